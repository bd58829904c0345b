// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SELF_OVERLAPPING_SIMPLE_POLYGON_CDT_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SELF_OVERLAPPING_SIMPLE_POLYGON_CDT_H

// The fast path for simple polygons: CGAL's constrained Delaunay triangulation of the polygon's edges,
// inside faces only. It is also the exact simplicity test (O(n log n) in practice, where a box test
// is quadratic on long thin edges such as a star's): the polygon is simple iff the triangulation has
// exactly the n points as vertices (a repeated point merges two), no two edges cross and every polygon
// edge is an edge of it (a vertex lying on a polygon edge splits it). These decisions use the exact
// predicates only: a crossing, which would need an intersection point constructed (in double, not
// even finite for coordinates near the largest double), is refused by the triangulation's
// No_constraint_intersection_requiring_constructions_tag with an exception, which means "not
// simple". A triangulation's faces are never flat, so every triangle is strictly positive
// even along runs of collinear vertices, and a vertex lying on a would-be diagonal simply becomes a
// vertex of the triangulation; with no interior vertex there are exactly n - 2 inside faces.
// Predicates: Epick (exact, filtered) for float and double coordinates, which convert exactly; exact
// rationals for every other number type (CGAL::Gmpq values of the coordinates, exact conversions).

#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {
namespace self_overlapping {

enum class Cdt_result { SIMPLE, NOT_SIMPLE, WRONG_COUNT };

template <class K>
Cdt_result cdt_triangulate_simple_polygon_in_kernel(const std::vector<typename K::Point_2>& Q,
                                              std::vector<std::array<std::size_t, 3> >& triangles)
{
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>           Vb;
  typedef CGAL::Constrained_triangulation_face_base_2<K>                         Cfb;
  typedef CGAL::Triangulation_face_base_with_info_2<int, K, Cfb>                 Fb; // -1 unvisited, 0 outside, 1 inside
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb>                           Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds,
                                                     CGAL::No_constraint_intersection_requiring_constructions_tag> CDT;

  const std::size_t n = Q.size();
  triangles.clear();
  std::vector<std::pair<typename K::Point_2, std::size_t> > pts;
  pts.reserve(n);
  for(std::size_t k = 0; k < n; ++k) pts.push_back(std::make_pair(Q[k], k));
  CDT cdt;
  cdt.insert(pts.begin(), pts.end()); // spatially sorted insertion
  if(cdt.number_of_vertices() != n) return Cdt_result::NOT_SIMPLE; // a repeated point
  std::vector<typename CDT::Vertex_handle> vh(n);
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) vh[v->info()] = v;
  try
  {
    for(std::size_t k = 0; k < n; ++k) cdt.insert_constraint(vh[k], vh[(k + 1) % n]);
  }
  catch(const typename CDT::Intersection_of_constraints_exception&)
  {
    return Cdt_result::NOT_SIMPLE; // two edges cross
  }
  for(std::size_t k = 0; k < n; ++k)
    if(!cdt.is_edge(vh[k], vh[(k + 1) % n])) return Cdt_result::NOT_SIMPLE; // a vertex on an edge, or an overlap

  // inside/outside by a flood fill from the infinite face, crossing constrained edges flips the side
  for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::vector<typename CDT::Face_handle> stack(1, cdt.infinite_face());
  cdt.infinite_face()->info() = 0;
  while(!stack.empty()) // every face is pushed once
  {
    const typename CDT::Face_handle f = stack.back();
    stack.pop_back();
    for(int e = 0; e < 3; ++e)
    {
      const typename CDT::Face_handle g = f->neighbor(e);
      if(g->info() != -1) continue;
      g->info() = cdt.is_constrained(typename CDT::Edge(f, e)) ? 1 - f->info() : f->info();
      stack.push_back(g);
    }
  }
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if(f->info() == 1)
      triangles.push_back(std::array<std::size_t, 3>{{ f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info() }});
  return triangles.size() + 2 == n ? Cdt_result::SIMPLE : Cdt_result::WRONG_COUNT;
}

// Q: a polygon (either orientation, no repeated consecutive point); `triangles`: counterclockwise index
// triples into Q when SIMPLE, unspecified otherwise. WRONG_COUNT (a simple polygon without n - 2 inside
// faces) cannot happen; the caller falls back on the dynamic program then.
template <class Point_2>
Cdt_result cdt_triangulate_simple_polygon(const std::vector<Point_2>& Q, std::vector<std::array<std::size_t, 3> >& triangles)
{
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel::FT FT;
  if constexpr(std::is_floating_point<FT>::value)
  {
    typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
    std::vector<Epick::Point_2> E;
    E.reserve(Q.size());
    for(const Point_2& p : Q) E.push_back(Epick::Point_2(double(p.x()), double(p.y())));
    return cdt_triangulate_simple_polygon_in_kernel<Epick>(E, triangles);
  }
  else
  {
    typedef CGAL::Simple_cartesian<CGAL::Gmpq> Kq;
    std::vector<Kq::Point_2> E;
    E.reserve(Q.size());
    for(const Point_2& p : Q) E.push_back(Kq::Point_2(to_rational(p.x()), to_rational(p.y())));
    return cdt_triangulate_simple_polygon_in_kernel<Kq>(E, triangles);
  }
}

} // namespace self_overlapping
} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
