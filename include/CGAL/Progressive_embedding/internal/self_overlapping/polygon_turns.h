// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SELF_OVERLAPPING_POLYGON_TURNS_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SELF_OVERLAPPING_POLYGON_TURNS_H

// Exact angular facts about a closed polygon, from the orientation predicate and coordinate
// comparisons only (no construction, so exact in every number type):
//  - the turn at a vertex and its signed crossing of the reference direction +x, whose sum over a
//    closed polygon is its rotation (turning) number, exactly;
//  - the open sector of a vertex (the angle inside the polygon, interior on the left) and whether a
//    direction lies in it;
//  - whether two directions of a fan around a reflex vertex "wrap" past the vertex's first edge.

#include <CGAL/enum.h>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {
namespace self_overlapping {

// direction p -> q in the half-open upper half [0, pi) of angles (else [pi, 2 pi)); p != q
template <class Point_2>
inline bool upper_direction(const Point_2& p, const Point_2& q)
{
  return p.y() < q.y() || (p.y() == q.y() && p.x() < q.x());
}

template <class Point_2>
inline bool same_point(const Point_2& p, const Point_2& q) { return p.x() == q.x() && p.y() == q.y(); }

// Turn a -> b -> c (a != b, b != c). Returns false for a reversal (c goes back towards a: a turn of
// exactly pi has no sign). Otherwise `crossing` receives +1 if the direction turns counterclockwise
// across (or onto) angle 0, -1 if it turns clockwise off or across it, 0 otherwise: with angles in
// [0, 2 pi), a left turn crosses iff the new angle is smaller, a right turn iff it is larger.
template <class Point_2, class Orientation_2>
inline bool turn_crossing(const Point_2& a, const Point_2& b, const Point_2& c, const Orientation_2& orient, int& crossing)
{
  crossing = 0;
  const CGAL::Orientation o = orient(a, b, c);
  const bool h1 = upper_direction(a, b), h2 = upper_direction(b, c);
  if(o == CGAL::COLLINEAR)
    return h1 == h2; // same half and collinear: same direction (no turn); else a reversal
  // angle(b - a) < angle(c - b) in [0, 2 pi): halves first, then the cross product inside a half
  const bool less = (h1 != h2) ? h1 : (o == CGAL::LEFT_TURN);
  if(o == CGAL::LEFT_TURN && !less) crossing = 1;
  if(o == CGAL::RIGHT_TURN && less) crossing = -1;
  return true;
}

// the direction o -> q is that of o -> p (o, p, q pairwise distinct): collinear and in the same half;
// a direction opposite to o -> p (an angle of pi) is not
template <class Point_2, class Orientation_2>
inline bool same_direction(const Point_2& o, const Point_2& p, const Point_2& q, const Orientation_2& orient)
{
  return orient(o, p, q) == CGAL::COLLINEAR && upper_direction(o, p) == upper_direction(o, q);
}

// Kind of the angle at a vertex, interior on the left of the polygon's direction.
enum class Corner_kind : unsigned char { CONVEX, FLAT, REFLEX };

// direction v -> x strictly inside the open sector of v: counterclockwise from v -> next to v -> prev
template <class Point_2, class Orientation_2>
inline bool in_open_sector(const Point_2& prev, const Point_2& v, const Point_2& next, Corner_kind kind,
                           const Point_2& x, const Orientation_2& orient)
{
  switch(kind)
  {
    case Corner_kind::CONVEX:
      return orient(v, next, x) == CGAL::LEFT_TURN && orient(v, x, prev) == CGAL::LEFT_TURN;
    case Corner_kind::FLAT:
      return orient(v, next, x) == CGAL::LEFT_TURN;
    case Corner_kind::REFLEX:
    default:
      // outside the closed complement cone [v -> prev, v -> next], which is convex (angle < pi);
      // x == v lies in it (both orientations are zero)
      return !(orient(v, prev, x) != CGAL::RIGHT_TURN && orient(v, x, next) != CGAL::RIGHT_TURN);
  }
}

// At a reflex vertex v whose fan meets x before y (the triangle (v, x, y) positive, both directions in
// the sector), the counterclockwise arc from x to y must not pass the first edge direction v -> next:
// otherwise the fan wraps around and covers more than the vertex's angle. Convex and flat vertices
// cannot wrap (the arc is shorter than pi, the complement of the sector at least pi).
template <class Point_2, class Orientation_2>
inline bool fan_wraps(const Point_2& v, const Point_2& next, const Point_2& x, const Point_2& y, const Orientation_2& orient)
{
  return orient(v, x, next) == CGAL::LEFT_TURN && orient(v, next, y) == CGAL::LEFT_TURN;
}

} // namespace self_overlapping
} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
