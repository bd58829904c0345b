// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_BORDER_POLYGON_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_BORDER_POLYGON_H

// Exact classification of a border polygon: strictly convex, convex (some
// collinear vertices), non-convex (including winding more than once), or degenerate.
// Only the exact orientation predicate and coordinate comparisons are used.

#include <CGAL/enum.h>
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

  bool has_pos = false, has_neg = false, has_col = false;
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
      if(back) return Polygon_class::NON_CONVEX;
    }
  }
  if(!has_pos && !has_neg) return Polygon_class::DEGENERATE;
  if(has_pos && has_neg) return Polygon_class::NON_CONVEX;
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

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
