// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_BORDER_POLYGON_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_BORDER_POLYGON_H

// Exact classification of a border polygon: strictly convex, convex (some
// collinear vertices), non-convex (including winding more than once), or degenerate.
// Only the exact orientation predicate and coordinate comparisons are used. Also the exact
// count of self-intersections of a closed polygon (border simplicity).

#include <CGAL/Progressive_embedding/internal/exact_predicates.h>

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

// Number of intersecting pairs of edges of the closed polygon P, decided with the exact
// orientation `orient` and coordinate comparisons; adjacent edges count only if they fold back
// onto each other. Counting stops at `limit`. Candidate pairs come from conservative boxes
// (internal/exact_predicates.h), valid at any magnitude of the coordinates.
template <class Point_2, class Orientation_2>
std::size_t count_polygon_self_intersections(const std::vector<Point_2>& P, const Orientation_2& orient, std::size_t limit)
{
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t> Box;
  const std::size_t nb = P.size();
  if(nb < 3 || limit == 0) return 0;
  Conservative_boxes<Point_2> cb;
  cb.build(P);
  std::vector<Box> boxes;
  boxes.reserve(nb);
  for(std::size_t k = 0; k < nb; ++k)
  {
    const std::array<std::size_t, 2> ends = {{ k, (k + 1) % nb }};
    const std::array<double, 4> b = cb.hull(ends);
    boxes.push_back(Box(CGAL::Bbox_2(b[0], b[2], b[1], b[3]), k));
  }
  std::size_t count = 0;
  auto report = [&](const Box& b1, const Box& b2) {
    std::size_t i = b1.info(), j = b2.info();
    if(i > j) std::swap(i, j);
    const Point_2& p0 = P[i]; const Point_2& p1 = P[(i + 1) % nb];
    const Point_2& q0 = P[j]; const Point_2& q1 = P[(j + 1) % nb];
    bool bad = false;
    if(j == i + 1 || (i == 0 && j == nb - 1))
    {
      const Point_2& s = (j == i + 1) ? p1 : p0;        // shared vertex
      const Point_2& u = (j == i + 1) ? p0 : p1;        // other end of edge i
      const Point_2& w = (j == i + 1) ? q1 : q0;        // other end of edge j
      if(orient(u, s, w) == CGAL::COLLINEAR)
        bad = (exact_compare_xy(u, s) == exact_compare_xy(w, s)); // both on the same side of s
    }
    else
      bad = closed_segments_intersect(p0, p1, q0, q1, orient);
    if(bad && ++count >= limit) throw Count_limit_reached();
  };
  try { CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), report); }
  catch(const Count_limit_reached&) { }
  return count;
}

// The same for the points of a kernel EK whose Orientation_2 is exact (Epick, or a kernel on an
// exact number type): kept for the callers that certify in such a kernel.
template <class EK>
std::size_t count_border_intersections(const std::vector<typename EK::Point_2>& P, std::size_t limit)
{
  return count_polygon_self_intersections(P, Exact_orientation_2<typename EK::Point_2>(), limit);
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
