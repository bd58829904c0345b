// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_BORDER_POLYGON_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_BORDER_POLYGON_H

// Exact classification of a border polygon: strictly convex, convex (some
// collinear vertices), non-convex (including winding more than once), or degenerate.
// Only the exact orientation predicate and coordinate comparisons are used.

#include <CGAL/enum.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/number_utils.h>
#include <cmath>
#include <type_traits>
#include <vector>
#include <cstddef>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

enum class Polygon_class { STRICTLY_CONVEX, CONVEX, NON_CONVEX, DEGENERATE };

// `orientation` receives +1 (counterclockwise) or -1 (clockwise) when convex.
template <class Point_2, class ExactOrientation>
Polygon_class classify_convex_polygon(const std::vector<Point_2>& P, ExactOrientation orient, int& orientation)
{
  orientation = 0;
  const std::size_t n = P.size();
  if(n < 3) return Polygon_class::DEGENERATE;
  for(std::size_t i = 0; i < n; ++i)
    if(P[i].x() == P[(i + 1) % n].x() && P[i].y() == P[(i + 1) % n].y())
      return Polygon_class::DEGENERATE;

  // all turns first: a polygon with no turn at all is degenerate, not a spike
  bool has_pos = false, has_neg = false, has_col = false, has_spike = false;
  for(std::size_t i = 0; i < n; ++i)
  {
    const Point_2& a = P[(i + n - 1) % n];
    const Point_2& b = P[i];
    const Point_2& c = P[(i + 1) % n];
    CGAL::Orientation o = orient(a, b, c);
    if(o == CGAL::LEFT_TURN) has_pos = true;
    else if(o == CGAL::RIGHT_TURN) has_neg = true;
    else
    {
      has_col = true;
      // collinear: a spike (c goes back towards a) is not convex
      const bool xdiff = !(a.x() == b.x());
      const bool back = xdiff ? ((a.x() < b.x()) != (b.x() < c.x()))
                              : ((a.y() < b.y()) != (b.y() < c.y()));
      if(back) has_spike = true;
    }
  }
  if(!has_pos && !has_neg) return Polygon_class::DEGENERATE;
  if((has_pos && has_neg) || has_spike) return Polygon_class::NON_CONVEX;
  orientation = has_pos ? 1 : -1;

  // winding number of the edge directions: exactly one full turn
  auto upper = [&](std::size_t i) {
    const Point_2& a = P[i];
    const Point_2& b = P[(i + 1) % n];
    return (a.y() < b.y()) || (a.y() == b.y() && a.x() < b.x());
  };
  std::size_t turns = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const bool u0 = upper(i), u1 = upper((i + 1) % n);
    if(orientation > 0 ? (!u0 && u1) : (u0 && !u1)) ++turns;
  }
  if(turns != 1) return Polygon_class::NON_CONVEX;
  return has_col ? Polygon_class::CONVEX : Polygon_class::STRICTLY_CONVEX;
}

struct Count_limit_reached {};

// Number of intersecting pairs of border edges of the closed polygon P (exact predicates of
// the kernel EK; adjacent edges count only if they fold back onto each other). Counting stops
// at `limit`. Boxes come from double approximations, enlarged when EK is not on doubles.
template <class EK>
std::size_t count_border_intersections(const std::vector<typename EK::Point_2>& P, std::size_t limit)
{
  typedef typename EK::Point_2 EPoint;
  typedef typename EK::FT EFT;
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t> Box;
  const std::size_t nb = P.size();
  if(nb < 3) return 0;
  std::vector<Box> boxes;
  boxes.reserve(nb);
  for(std::size_t k = 0; k < nb; ++k)
  {
    const EPoint& a = P[k];
    const EPoint& b = P[(k + 1) % nb];
    double x0 = CGAL::to_double(a.x()), y0 = CGAL::to_double(a.y()), x1 = CGAL::to_double(b.x()), y1 = CGAL::to_double(b.y());
    double xmin = (std::min)(x0, x1), xmax = (std::max)(x0, x1), ymin = (std::min)(y0, y1), ymax = (std::max)(y0, y1);
    if(!std::is_floating_point<EFT>::value)
    {
      const double e = 1e-12 * (std::abs(xmin) + std::abs(xmax) + std::abs(ymin) + std::abs(ymax)) + 1e-300;
      xmin -= e; ymin -= e; xmax += e; ymax += e;
    }
    boxes.push_back(Box(CGAL::Bbox_2(xmin, ymin, xmax, ymax), k));
  }
  typename EK::Orientation_2 orient;
  typename EK::Do_intersect_2 do_intersect;
  std::size_t count = 0;
  auto cb = [&](const Box& b1, const Box& b2) {
    std::size_t i = b1.info(), j = b2.info();
    if(i > j) std::swap(i, j);
    const EPoint& p0 = P[i]; const EPoint& p1 = P[(i + 1) % nb];
    const EPoint& q0 = P[j]; const EPoint& q1 = P[(j + 1) % nb];
    bool bad = false;
    if(j == i + 1 || (i == 0 && j == nb - 1))
    {
      const EPoint& s = (j == i + 1) ? p1 : p0;        // shared vertex
      const EPoint& u = (j == i + 1) ? p0 : p1;        // other end of edge i
      const EPoint& w = (j == i + 1) ? q1 : q0;        // other end of edge j
      if(orient(u, s, w) == CGAL::COLLINEAR)
        bad = (CGAL::compare_xy(u, s) == CGAL::compare_xy(w, s)); // both on the same side of s
    }
    else
      bad = do_intersect(typename EK::Segment_2(p0, p1), typename EK::Segment_2(q0, q1));
    if(bad && ++count >= limit) throw Count_limit_reached();
  };
  try { CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), cb); }
  catch(const Count_limit_reached&) { }
  return count;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
