// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_LOCATE_IN_MAP_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_LOCATE_IN_MAP_H

// Point location in a certified planar map (every face positively oriented, no overlap): for each
// query point, a closed face of the map containing it and its barycentric coordinates there.
// Candidates come from CGAL::box_intersection_d() on conservative boxes (a box never misses its
// point, whatever the number type); the containment is decided by exact orientations, and the
// coordinates are computed in exact rationals and rounded once to double, so that a point on an edge
// has exactly one zero coordinate and a point on a vertex the coordinates (1, 0, 0) up to their order.

#include <CGAL/Progressive_embedding/internal/exact_predicates.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/box_intersection_d.h>

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// where a query point lies in the map
struct Map_location
{
  static constexpr std::size_t none = std::size_t(-1);
  std::size_t face = none;               // index into the face list, `none` if not located
  std::array<double, 3> barycentric{{ 0, 0, 0 }}; // of the face's three vertices, in its order
  int zeros = 0;                         // exact zero coordinates: 0 in the face, 1 on an edge, 2 on a vertex
};

// `faces`: the map's triangles as indices into `uv` (each positively oriented); `queries`: the points
// to locate. A point on an edge or a vertex shared by several faces gets the face of smallest index.
// Returns the number of queries not located (outside every face).
template <class Point_2>
std::size_t locate_in_map(const std::vector<Point_2>& uv, const std::vector<std::array<std::size_t, 3> >& faces,
                          const std::vector<Point_2>& queries, std::vector<Map_location>& result)
{
  typedef CGAL::Box_intersection_d::Box_with_handle_d<double, 2, std::size_t,
                                                      CGAL::Box_intersection_d::ID_EXPLICIT> Box;
  // one common scale for the map's points and the queries: their boxes are compared with each other
  std::vector<Point_2> all(uv);
  all.insert(all.end(), queries.begin(), queries.end());
  Conservative_boxes<Point_2> cb;
  cb.build(all);
  std::vector<Box> face_boxes, query_boxes;
  face_boxes.reserve(faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f)
  {
    const std::array<double, 4> b = cb.hull(faces[f]);
    double lo[2] = { b[0], b[2] }, hi[2] = { b[1], b[3] };
    face_boxes.push_back(Box(lo, hi, f));
  }
  query_boxes.reserve(queries.size());
  for(std::size_t q = 0; q < queries.size(); ++q)
  {
    const std::array<double, 4>& b = cb.box[uv.size() + q];
    double lo[2] = { b[0], b[2] }, hi[2] = { b[1], b[3] };
    query_boxes.push_back(Box(lo, hi, q));
  }

  result.assign(queries.size(), Map_location());
  auto test = [&](const Box& fb, const Box& qb)
  {
    const std::size_t f = fb.handle(), q = qb.handle();
    Map_location& r = result[q];
    if(r.face != Map_location::none && r.face < f) return;
    const Point_2& x = queries[q];
    const std::array<std::size_t, 3>& t = faces[f];
    int zeros = 0;
    for(int i = 0; i < 3; ++i)
    {
      // the coordinate of corner i has the sign of the orientation of the opposite edge with x
      const CGAL::Orientation o = exact_orientation(uv[t[(i + 1) % 3]], uv[t[(i + 2) % 3]], x);
      if(o == CGAL::RIGHT_TURN) return;
      if(o == CGAL::COLLINEAR) ++zeros;
    }
    if(zeros == 3) return; // a degenerate face (not in a certified map)
    // exact coordinates, rounded once
    CGAL::Gmpq px[3], py[3];
    for(int i = 0; i < 3; ++i) { px[i] = to_rational(uv[t[i]].x()); py[i] = to_rational(uv[t[i]].y()); }
    const CGAL::Gmpq xx = to_rational(x.x()), xy = to_rational(x.y());
    const CGAL::Gmpq area = twice_signed_area(px[0], py[0], px[1], py[1], px[2], py[2]);
    r.face = f;
    r.zeros = zeros;
    for(int i = 0; i < 3; ++i)
      r.barycentric[i] = CGAL::to_double(twice_signed_area(px[(i + 1) % 3], py[(i + 1) % 3], px[(i + 2) % 3],
                                                           py[(i + 2) % 3], xx, xy) / area);
  };
  CGAL::box_intersection_d(face_boxes.begin(), face_boxes.end(), query_boxes.begin(), query_boxes.end(), test);

  std::size_t missed = 0;
  for(const Map_location& r : result) if(r.face == Map_location::none) ++missed;
  return missed;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_LOCATE_IN_MAP_H
