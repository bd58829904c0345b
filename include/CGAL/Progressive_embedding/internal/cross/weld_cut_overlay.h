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

#include <array>
#include <cstddef>
#include <map>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// whether `triangles` (on `n` points, every point used) form a closed, connected, oriented 2-manifold of Euler
// characteristic 2
inline bool is_closed_genus_zero_soup(std::size_t n, const std::vector<std::array<std::size_t, 3> >& triangles)
{
  typedef std::pair<std::size_t, std::size_t> Edge;
  std::map<Edge, std::size_t> triangle_of; // directed edge -> the triangle that has it
  std::vector<std::size_t> out_degree(n, 0);
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t u = triangles[t][k], v = triangles[t][(k + 1) % 3];
      if(u >= n || v >= n || u == v) return false;
      if(!triangle_of.emplace(Edge(u, v), t).second) return false; // an edge twice the same way
      ++out_degree[u];
    }
  for(const auto& e : triangle_of)
    if(triangle_of.count(Edge(e.first.second, e.first.first)) == 0) return false; // a border edge
  // the triangles around each vertex one cycle: from the edge u -> v of a triangle (u, v, w), the next edge out of
  // u is u -> w
  std::vector<char> seen_vertex(n, 0);
  for(const auto& e : triangle_of)
  {
    const std::size_t u = e.first.first;
    if(seen_vertex[u]) continue;
    seen_vertex[u] = 1;
    std::size_t v = e.first.second, steps = 0;
    do
    {
      const std::array<std::size_t, 3>& t = triangles[triangle_of.at(Edge(u, v))];
      int k = 0;
      while(t[k] != u) ++k;
      v = t[(k + 2) % 3];
      ++steps;
    } while(v != e.first.second && steps <= out_degree[u]);
    if(steps != out_degree[u]) return false; // a pinched vertex
  }
  for(std::size_t i = 0; i < n; ++i) if(!seen_vertex[i]) return false; // a point in no triangle
  // connected
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t x) { while(parent[x] != x) x = parent[x] = parent[parent[x]]; return x; };
  std::size_t components = n;
  for(const auto& t : triangles)
    for(int k = 1; k < 3; ++k)
    {
      const std::size_t a = find(t[0]), b = find(t[k]);
      if(a != b) { parent[a] = b; --components; }
    }
  if(components != 1) return false;
  const long chi = long(n) - long(triangle_of.size() / 2) + long(triangles.size());
  return chi == 2;
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
  if(!is_closed_genus_zero_soup(next, welded_triangles)) { welded = 0; return ERROR_INVALID_EMBEDDING; }
  std::vector<std::array<double, 3> > a(next), b(next);
  for(std::size_t j = 0; j < next; ++j) { a[j] = on_a[kept[j]]; b[j] = on_b[kept[j]]; }
  on_a.swap(a);
  on_b.swap(b);
  triangles.swap(welded_triangles);
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_WELD_CUT_OVERLAY_H
