// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_OVERLAY_BY_ARRANGEMENT_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_OVERLAY_BY_ARRANGEMENT_H

// The overlay of two valid planar maps of one domain by CGAL's arrangements: each map's edges make a
// CGAL arrangement whose faces carry the index of the map's triangle; CGAL's overlay (a sweep in exact
// arithmetic: Epeck) gives the cells. The reference that overlay_maps() (internal/cross/overlay_maps.h,
// the one cross_parameterization() uses, by clipping the triangles of one map by those of the other) is
// tested against: the same cells, crossings and triangles. The overlay traits record where each overlay
// vertex lies in each map (a vertex, an edge, a face).

#include <CGAL/Progressive_embedding/internal/cross/overlay_maps.h>

#include <CGAL/Arr_default_overlay_traits.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_overlay_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

namespace arrangement_overlay_detail {

constexpr std::size_t no_face = std::size_t(-1);
typedef CGAL::Epeck K;
typedef CGAL::Arr_segment_traits_2<K> Traits;
// vertices carry their map vertex, faces their map triangle
typedef CGAL::Arrangement_2<Traits, CGAL::Arr_extended_dcel<Traits, std::size_t, char, std::size_t> > Map_arrangement;
typedef CGAL::Arrangement_2<Traits, CGAL::Arr_extended_dcel<Traits, std::array<Map_feature, 2>, char,
                                                            std::array<std::size_t, 2> > > Overlay_arrangement;

// records, for every cell, the triangle of each map, and for every vertex, the feature of each map it is on
class Origin_overlay_traits
  : public CGAL::_Arr_default_overlay_traits_base<Map_arrangement, Map_arrangement, Overlay_arrangement>
{
  typedef CGAL::_Arr_default_overlay_traits_base<Map_arrangement, Map_arrangement, Overlay_arrangement> Base;
  static Map_feature at(Map_arrangement::Vertex_const_handle v) { return {{ v->data(), no_face }}; }
  static Map_feature at(Map_arrangement::Halfedge_const_handle e) { return {{ e->source()->data(), e->target()->data() }}; }
  static Map_feature at(Map_arrangement::Face_const_handle) { return {{ no_face, no_face }}; }
  template <class X, class Y>
  static void set(X x, Y y, Base::Vertex_handle_R v) { v->set_data({{ at(x), at(y) }}); }

public:
  void create_vertex(Base::Vertex_handle_A x, Base::Vertex_handle_B y, Base::Vertex_handle_R v) const override { set(x, y, v); }
  void create_vertex(Base::Vertex_handle_A x, Base::Halfedge_handle_B y, Base::Vertex_handle_R v) const override { set(x, y, v); }
  void create_vertex(Base::Vertex_handle_A x, Base::Face_handle_B y, Base::Vertex_handle_R v) const override { set(x, y, v); }
  void create_vertex(Base::Halfedge_handle_A x, Base::Vertex_handle_B y, Base::Vertex_handle_R v) const override { set(x, y, v); }
  void create_vertex(Base::Face_handle_A x, Base::Vertex_handle_B y, Base::Vertex_handle_R v) const override { set(x, y, v); }
  void create_vertex(Base::Halfedge_handle_A x, Base::Halfedge_handle_B y, Base::Vertex_handle_R v) const override { set(x, y, v); }
  void create_face(Base::Face_handle_A x, Base::Face_handle_B y, Base::Face_handle_R f) const override
  {
    f->set_data({{ x->data(), y->data() }});
  }
};

// The arrangement of a map's edges, each bounded face tagged with its triangle. Fails if a triangle
// is not a face of the arrangement on its left (a map that is not valid).
template <class Point_2>
Error_code map_arrangement(const std::vector<Point_2>& uv, const std::vector<std::array<std::size_t, 3> >& faces,
                           Map_arrangement& arr)
{
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  edges.reserve(3 * faces.size());
  for(const auto& f : faces)
    for(int i = 0; i < 3; ++i) edges.emplace_back((std::min)(f[i], f[(i + 1) % 3]), (std::max)(f[i], f[(i + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<K::Point_2> p;
  p.reserve(uv.size());
  for(const Point_2& q : uv) p.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
  std::vector<Traits::X_monotone_curve_2> segments;
  segments.reserve(edges.size());
  for(const auto& e : edges)
  {
    if(p[e.first] == p[e.second]) return ERROR_INVALID_EMBEDDING; // a collapsed edge
    segments.emplace_back(p[e.first], p[e.second]);
  }
  // the edges of a valid map meet only at common end points
  CGAL::insert_non_intersecting_curves(arr, segments.begin(), segments.end());
  for(auto f = arr.faces_begin(); f != arr.faces_end(); ++f) f->set_data(no_face);
  // the arrangement's vertex at each map vertex (the points are doubles: their conversion is exact)
  std::map<std::pair<double, double>, Map_arrangement::Vertex_handle> at;
  for(auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v)
  {
    v->set_data(no_face);
    at.emplace(std::make_pair(CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())), v);
  }
  std::vector<Map_arrangement::Vertex_handle> vh(uv.size());
  for(std::size_t i = 0; i < uv.size(); ++i)
  {
    const auto it = at.find(std::make_pair(CGAL::to_double(p[i].x()), CGAL::to_double(p[i].y())));
    if(it == at.end()) return ERROR_INVALID_EMBEDDING; // a vertex in no edge
    vh[i] = it->second;
    vh[i]->set_data(i);
  }
  for(std::size_t t = 0; t < faces.size(); ++t)
  {
    // the halfedge from f[0] to f[1]: its face, on its left, is the triangle if the map is valid
    const auto from = vh[faces[t][0]], to = vh[faces[t][1]];
    auto c = to->incident_halfedges(), done = c;
    Map_arrangement::Face_handle face;
    bool found = false;
    do
    {
      if(c->source() == from) { face = c->face(); found = true; break; }
    } while(++c != done);
    if(!found || face->is_unbounded() || face->data() != no_face) return ERROR_INVALID_EMBEDDING;
    face->set_data(t);
  }
  return OK;
}

} // namespace arrangement_overlay_detail

// overlay_maps()'s contract, by CGAL's arrangements
template <class Point_2>
Error_code overlay_maps_by_arrangement(const std::vector<Point_2>& uv_a, const std::vector<std::array<std::size_t, 3> >& faces_a,
                                       const std::vector<Point_2>& uv_b, const std::vector<std::array<std::size_t, 3> >& faces_b,
                                       Map_overlay& out)
{
  using namespace arrangement_overlay_detail;
  out = Map_overlay();
  Map_arrangement arr_a, arr_b;
  Error_code ec = map_arrangement(uv_a, faces_a, arr_a);
  if(ec != OK) return ec;
  ec = map_arrangement(uv_b, faces_b, arr_b);
  if(ec != OK) return ec;
  Overlay_arrangement arr;
  Origin_overlay_traits traits;
  CGAL::overlay(arr_a, arr_b, arr, traits);

  std::unordered_map<const void*, std::size_t> index;
  out.points.reserve(arr.number_of_vertices());
  out.features.reserve(arr.number_of_vertices());
  for(auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v)
  {
    index.emplace(&*v, out.points.size());
    out.points.push_back(v->point());
    out.features.push_back(v->data());
    // inside an edge of each map
    if(v->data()[0][1] != no_face && v->data()[1][1] != no_face) ++out.crossings;
  }
  std::vector<std::size_t> cell;
  for(auto f = arr.faces_begin(); f != arr.faces_end(); ++f)
  {
    const std::array<std::size_t, 2> d = f->data();
    if(f->is_unbounded())
    {
      if(f->number_of_inner_ccbs() != 1) return ERROR_INVALID_EMBEDDING; // two domains side by side
      continue;
    }
    // a bounded cell outside either domain, or a cell with a hole: the maps do not cover one domain
    if(d[0] == no_face || d[1] == no_face || f->number_of_inner_ccbs() != 0) return ERROR_INVALID_EMBEDDING;
    ++out.cells;
    cell.clear();
    auto c = f->outer_ccb(), done = c;
    do cell.push_back(index.at(&*c->target())); while(++c != done);
    const std::size_t m = cell.size();
    // corners: left turns; a right turn means the cell is not convex (not an intersection of triangles)
    std::vector<bool> corner(m);
    for(std::size_t i = 0; i < m; ++i)
    {
      const CGAL::Orientation o = CGAL::orientation(out.points[cell[(i + m - 1) % m]], out.points[cell[i]],
                                                    out.points[cell[(i + 1) % m]]);
      if(o == CGAL::RIGHT_TURN) return ERROR_INVALID_EMBEDDING;
      corner[i] = (o == CGAL::LEFT_TURN);
    }
    triangulate_cell(cell, corner, d, out);
  }
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_OVERLAY_BY_ARRANGEMENT_H
