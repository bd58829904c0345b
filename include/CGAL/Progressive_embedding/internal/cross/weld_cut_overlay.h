// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_WELD_CUT_OVERLAY_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_WELD_CUT_OVERLAY_H

// The triangulated overlay of the maps of two cut disks welded back into a closed surface. Every point on the
// overlay's border is a vertex of A's disk or of B's (the two borders run along the same sides of the square), and
// each such vertex is a vertex of a closed mesh seen from one side of the cut: the points on the border that are
// the same vertex of A and the same vertex of B (or -1 for both) are one vertex of the welded surface. That the
// two sides of every cut arc hold the same sequence is not assumed: the welded triangles are certified to form a
// closed, connected, consistently oriented 2-manifold of Euler characteristic 2 (every edge in exactly two
// triangles, once each way; the triangles around every vertex one cycle), else ERROR_INVALID_EMBEDDING and nothing
// changed.

#include <CGAL/Progressive_embedding/Error_code.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// whether `triangles` on `points` (every point used) form a closed, connected, oriented 2-manifold of Euler
// characteristic 2: PMP's test that the soup is a polygon mesh (every edge in at most two triangles, once each way;
// no pinched vertex), then the mesh it makes closed, of one component, with V - E + F = 2
inline bool is_closed_genus_zero_soup(const std::vector<std::array<double, 3> >& points,
                                      const std::vector<std::array<std::size_t, 3> >& triangles)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef CGAL::Simple_cartesian<double>::Point_3 Point_3;
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  for(const auto& t : triangles)
    for(std::size_t i : t) if(i >= points.size()) return false;
  if(triangles.empty() || !PMP::is_polygon_soup_a_polygon_mesh(triangles)) return false;
  std::vector<Point_3> p;
  p.reserve(points.size());
  for(const auto& q : points) p.emplace_back(q[0], q[1], q[2]);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(p, triangles, mesh);
  if(num_vertices(mesh) != points.size() || !CGAL::is_closed(mesh)) return false;
  for(auto v : vertices(mesh)) if(mesh.is_isolated(v)) return false;
  auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:component", 0).first;
  if(PMP::connected_components(mesh, component) != 1) return false;
  return long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh)) == 2;
}

// `origin[i]`: the vertex of the closed mesh A and of B that point i is (-1 when it is none). The points on the
// border of `triangles` with the same origin become one (the first of them keeps its place on both surfaces);
// `on_a`, `on_b` and `triangles` are renumbered, `welded` counts the points removed.
inline Error_code weld_cut_overlay(std::vector<std::array<double, 3> >& on_a, std::vector<std::array<double, 3> >& on_b,
                                   std::vector<std::array<std::size_t, 3> >& triangles,
                                   const std::vector<std::array<std::size_t, 2> >& origin, std::size_t& welded)
{
  typedef std::pair<std::size_t, std::size_t> Edge;
  const std::size_t n = on_a.size(), none = std::size_t(-1);
  welded = 0;
  if(on_b.size() != n || origin.size() != n) return ERROR_INVALID_EMBEDDING;
  // the border: edges in one triangle
  std::map<Edge, int> count;
  for(const auto& t : triangles)
    for(int k = 0; k < 3; ++k)
    {
      std::size_t u = t[k], v = t[(k + 1) % 3];
      if(u > v) std::swap(u, v);
      ++count[Edge(u, v)];
    }
  std::vector<char> on_border(n, 0);
  for(const auto& e : count)
    if(e.second == 1) on_border[e.first.first] = on_border[e.first.second] = 1;
  // one point per origin on the border
  std::vector<std::size_t> target(n, none);
  std::map<Edge, std::size_t> first_with;
  std::size_t next = 0;
  std::vector<std::size_t> kept;
  for(std::size_t i = 0; i < n; ++i)
  {
    if(on_border[i])
    {
      if(origin[i][0] == none && origin[i][1] == none) return ERROR_INVALID_EMBEDDING; // a border point of neither map
      const auto found = first_with.emplace(Edge(origin[i][0], origin[i][1]), next);
      if(!found.second) { target[i] = found.first->second; ++welded; continue; }
    }
    target[i] = next++;
    kept.push_back(i);
  }
  std::vector<std::array<std::size_t, 3> > welded_triangles(triangles.size());
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int k = 0; k < 3; ++k) welded_triangles[t][k] = target[triangles[t][k]];
  std::vector<std::array<double, 3> > a(next), b(next);
  for(std::size_t j = 0; j < next; ++j) { a[j] = on_a[kept[j]]; b[j] = on_b[kept[j]]; }
  if(!is_closed_genus_zero_soup(a, welded_triangles)) { welded = 0; return ERROR_INVALID_EMBEDDING; }
  on_a.swap(a);
  on_b.swap(b);
  triangles.swap(welded_triangles);
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_WELD_CUT_OVERLAY_H
