// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_HOLES_DOMAIN_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_HOLES_DOMAIN_H

// Multiply connected domains: a connected genus-0 triangle mesh with k >= 1 border loops.
//
//  - Indexed_domain / make_indexed_domain(): the Indexed_disk of such a mesh (vertices, faces)
//    with every border loop listed (interior of the mesh on the left of each loop, as
//    Indexed_disk::border), and one of them chosen as the outer loop (`set_outer`): then
//    `disk.border` is the outer loop and `disk.on_border` marks its vertices only, so that every
//    algorithm written for a disk sees the outer loop as "the border" and the hole vertices as
//    interior vertices. Validation: empty -> ERROR_EMPTY_MESH, not a valid polygon mesh or a
//    pinched border vertex -> ERROR_NON_MANIFOLD, a non-triangle -> ERROR_NON_TRIANGULAR_MESH,
//    no border, an isolated vertex, several components or an Euler characteristic other than
//    2 - k -> ERROR_NOT_GENUS_ZERO.
//  - count_loop_intersections(): exact count of intersecting pairs of edges among several closed
//    polygons: pairs within one loop (self-intersections, with the fold-back rule of adjacent
//    edges of border_polygon.h) and pairs from two loops (any contact, closed segments).
//  - loop_edges_clear(): the same, local: the two edges of one loop vertex against all loop edges
//    (after moving that vertex in a map whose loops were pairwise disjoint and simple).
//  - winding_number(): exact winding number of a closed polygon around a point not on it.
// Every sign is decided by the exact orientation functor passed in and exact coordinate
// comparisons; candidate pairs come from conservative boxes (valid at any magnitude).

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/exact_predicates.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

template <class TriangleMesh>
struct Indexed_domain
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  Indexed_disk<TriangleMesh> disk;                    // disk.border: the outer loop (after set_outer)
  std::vector<std::vector<std::size_t> > loops;       // every border loop, mesh interior on the left
  std::vector<halfedge_descriptor> loop_halfedge;     // a border halfedge (face null) of each loop
  std::vector<long> loop_of;                          // per vertex: its loop, or -1
  std::size_t outer = 0;                              // index of the outer loop in `loops`

  std::size_t number_of_loops() const { return loops.size(); }
  bool is_hole_vertex(std::size_t v) const { return loop_of[v] >= 0 && std::size_t(loop_of[v]) != outer; }

  void set_outer(std::size_t k)
  {
    outer = k;
    disk.border = loops[k];
    disk.on_border.assign(disk.vertices.size(), 0);
    for(std::size_t b : disk.border) disk.on_border[b] = 1;
  }
};

// Fills `d` from `tm` (see the header comment); the outer loop is loop 0 until set_outer().
template <class TriangleMesh>
Error_code make_indexed_domain(const TriangleMesh& tm, Indexed_domain<TriangleMesh>& d)
{
  typedef boost::graph_traits<TriangleMesh>                  GT;
  typedef typename GT::vertex_descriptor                     vertex_descriptor;
  typedef typename GT::halfedge_descriptor                   halfedge_descriptor;
  typedef typename GT::face_descriptor                       face_descriptor;

  CGAL_PROGRESSIVE_EMBEDDING_COUNT_ONE_INDEXING();
  d = Indexed_domain<TriangleMesh>();
  Indexed_disk<TriangleMesh>& disk = d.disk;
  if(faces(tm).first == faces(tm).second) return ERROR_EMPTY_MESH;
  if(!CGAL::is_valid_polygon_mesh(tm)) return ERROR_NON_MANIFOLD;
  if(!CGAL::is_triangle_mesh(tm)) return ERROR_NON_TRIANGULAR_MESH;

  auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  for(vertex_descriptor v : vertices(tm))
  {
    if(halfedge(v, tm) == GT::null_halfedge()) return ERROR_NOT_GENUS_ZERO; // isolated vertex: not connected
    put(vid, v, disk.vertices.size());
    disk.vertices.push_back(v);
  }
  const std::size_t nv = disk.vertices.size();
  for(face_descriptor f : faces(tm))
  {
    const halfedge_descriptor h = halfedge(f, tm);
    disk.faces.push_back({ get(vid, source(h, tm)), get(vid, target(h, tm)), get(vid, target(next(h, tm), tm)) });
  }

  // border loops; a vertex with two incoming border halfedges is pinched (non-manifold)
  d.loop_of.assign(nv, -1);
  std::vector<char> seen(nv, 0);
  std::size_t n_border_halfedges = 0;
  for(halfedge_descriptor h : halfedges(tm))
  {
    if(!is_border(h, tm)) continue;
    ++n_border_halfedges;
    const std::size_t t = get(vid, target(h, tm));
    if(seen[t]) return ERROR_NON_MANIFOLD;
    seen[t] = 1;
  }
  if(n_border_halfedges == 0) return ERROR_NOT_GENUS_ZERO; // closed
  for(halfedge_descriptor h : halfedges(tm))
  {
    if(!is_border(h, tm) || d.loop_of[get(vid, target(h, tm))] >= 0) continue;
    const long k = long(d.loops.size());
    std::vector<std::size_t> cyc;
    halfedge_descriptor c = h;
    std::size_t guard = 0; // a valid polygon mesh closes every cycle; the guard bounds the walk anyway
    do { cyc.push_back(get(vid, target(c, tm))); d.loop_of[cyc.back()] = k; c = next(c, tm); }
    while(c != h && ++guard <= n_border_halfedges);
    if(c != h) return ERROR_NON_MANIFOLD;
    d.loops.emplace_back(cyc.rbegin(), cyc.rend()); // interior on the left, as Indexed_disk::border
    d.loop_halfedge.push_back(h);
  }

  // connected (faces reached from the first one across interior edges) and genus 0
  {
    auto fseen = get(CGAL::dynamic_face_property_t<bool>(), tm);
    for(face_descriptor f : faces(tm)) put(fseen, f, false);
    std::vector<face_descriptor> stack(1, *faces(tm).first);
    put(fseen, stack.back(), true);
    std::size_t reached = 1;
    while(!stack.empty())
    {
      const face_descriptor f = stack.back(); stack.pop_back();
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
      {
        const halfedge_descriptor o = opposite(h, tm);
        if(is_border(o, tm)) continue;
        const face_descriptor g = face(o, tm);
        if(!get(fseen, g)) { put(fseen, g, true); ++reached; stack.push_back(g); }
      }
    }
    if(reached != disk.faces.size()) return ERROR_NOT_GENUS_ZERO;
  }
  // halfedges counted by iteration: num_halfedges() of a Surface_mesh includes removed ones
  long nh = 0;
  for(halfedge_descriptor h : halfedges(tm)) { (void)h; ++nh; }
  const long ne = nh / 2;
  if(static_cast<long>(nv) - ne + static_cast<long>(disk.faces.size()) != 2 - static_cast<long>(d.loops.size()))
    return ERROR_NOT_GENUS_ZERO;
  d.set_outer(0);
  return OK;
}

struct Loop_count_limit_reached {};

// Intersecting pairs of edges among the closed polygons `loops` (vertex indices into P):
// `self` counts pairs within one loop (non-adjacent edges that touch, adjacent edges that fold
// back onto each other; a loop of fewer than 3 vertices counts once), `crossing` pairs from two
// different loops (closed segments touching). Counting stops when self + crossing reaches `limit`.
// With `pairs`, the vertices (indices into P) of the two edges of each pair counted are appended to it.
template <class Point_2, class Orientation_2>
void count_loop_intersections(const std::vector<Point_2>& P, const std::vector<std::vector<std::size_t> >& loops,
                              const Orientation_2& orient, std::size_t limit, std::size_t& self, std::size_t& crossing,
                              std::vector<std::array<std::size_t, 4> >* pairs = nullptr)
{
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::pair<std::size_t, std::size_t> > Box;
  self = crossing = 0;
  if(limit == 0) return;
  for(const std::vector<std::size_t>& L : loops)
    if(L.size() < 3 && ++self >= limit) return;
  std::vector<Point_2> Q; // the loop points, in loop order
  std::vector<std::size_t> first(loops.size() + 1, 0);
  for(std::size_t l = 0; l < loops.size(); ++l)
  {
    first[l] = Q.size();
    for(std::size_t v : loops[l]) Q.push_back(P[v]);
  }
  first[loops.size()] = Q.size();
  Conservative_boxes<Point_2> cb;
  cb.build(Q);
  std::vector<Box> boxes;
  boxes.reserve(Q.size());
  for(std::size_t l = 0; l < loops.size(); ++l)
  {
    const std::size_t n = loops[l].size();
    if(n < 3) continue;
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::array<std::size_t, 2> ends = {{ first[l] + k, first[l] + (k + 1) % n }};
      const std::array<double, 4> b = cb.hull(ends);
      boxes.push_back(Box(CGAL::Bbox_2(b[0], b[2], b[1], b[3]), std::make_pair(l, k)));
    }
  }
  auto report = [&](const Box& b1, const Box& b2) {
    std::size_t l1 = b1.info().first, i = b1.info().second, l2 = b2.info().first, j = b2.info().second;
    const std::size_t n1 = loops[l1].size(), n2 = loops[l2].size();
    const Point_2& p0 = Q[first[l1] + i]; const Point_2& p1 = Q[first[l1] + (i + 1) % n1];
    const Point_2& q0 = Q[first[l2] + j]; const Point_2& q1 = Q[first[l2] + (j + 1) % n2];
    const auto record = [&]() {
      if(pairs) pairs->push_back({{ loops[l1][i], loops[l1][(i + 1) % n1], loops[l2][j], loops[l2][(j + 1) % n2] }});
    };
    if(l1 != l2)
    {
      if(closed_segments_intersect(p0, p1, q0, q1, orient))
      {
        record();
        if(++crossing + self >= limit) throw Loop_count_limit_reached();
      }
      return;
    }
    bool bad = false;
    const std::size_t n = n1;
    if(i > j) std::swap(i, j);
    const Point_2& a0 = Q[first[l1] + i]; const Point_2& a1 = Q[first[l1] + (i + 1) % n];
    const Point_2& c0 = Q[first[l1] + j]; const Point_2& c1 = Q[first[l1] + (j + 1) % n];
    if(j == i + 1 || (i == 0 && j == n - 1))
    {
      const Point_2& s = (j == i + 1) ? a1 : a0;   // shared vertex
      const Point_2& u = (j == i + 1) ? a0 : a1;   // other end of edge i
      const Point_2& w = (j == i + 1) ? c1 : c0;   // other end of edge j
      if(orient(u, s, w) == CGAL::COLLINEAR)
        bad = (exact_compare_xy(u, s) == exact_compare_xy(w, s)); // both on the same side of s
    }
    else
      bad = closed_segments_intersect(a0, a1, c0, c1, orient);
    if(bad)
    {
      record();
      if(++self + crossing >= limit) throw Loop_count_limit_reached();
    }
  };
  try { CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), report); }
  catch(const Loop_count_limit_reached&) { }
}

// After moving vertex v (on loop `loops[l]` at position k) in a map whose loops were simple and
// pairwise disjoint: true if its two loop edges touch no other loop edge (exact, O(loop edges)).
template <class Point_2, class Orientation_2>
bool loop_edges_clear(const std::vector<Point_2>& P, const std::vector<std::vector<std::size_t> >& loops,
                      std::size_t l, std::size_t k, const Orientation_2& orient)
{
  const std::vector<std::size_t>& L = loops[l];
  const std::size_t n = L.size();
  if(n < 3) return false;
  const std::size_t prev = L[(k + n - 1) % n], v = L[k], next = L[(k + 1) % n];
  // the two edges themselves must not fold back onto each other
  if(orient(P[prev], P[v], P[next]) == CGAL::COLLINEAR
     && exact_compare_xy(P[prev], P[v]) == exact_compare_xy(P[next], P[v]))
    return false;
  for(std::size_t m = 0; m < loops.size(); ++m)
  {
    const std::vector<std::size_t>& M = loops[m];
    const std::size_t nm = M.size();
    for(std::size_t e = 0; e < nm; ++e)
    {
      const std::size_t a = M[e], b = M[(e + 1) % nm];
      for(int side = 0; side < 2; ++side)
      {
        const std::size_t x = side == 0 ? prev : v, y = side == 0 ? v : next;
        if(a == x || a == y || b == x || b == y)
        {
          // an edge adjacent to this one in the same loop: fold-back only
          if(m != l) continue;
          if((a == x && b == y) || (a == y && b == x)) continue; // itself
          const std::size_t s = (a == x || b == x) ? x : y;     // shared vertex
          const std::size_t u = (s == x) ? y : x, w = (a == s) ? b : a;
          if(u == w) continue; // the pair of edges at v, checked above
          if(orient(P[u], P[s], P[w]) == CGAL::COLLINEAR && exact_compare_xy(P[u], P[s]) == exact_compare_xy(P[w], P[s]))
            return false;
          continue;
        }
        if(closed_segments_intersect(P[x], P[y], P[a], P[b], orient)) return false;
      }
    }
  }
  return true;
}

// Exact winding number of the closed polygon (indices `L` into P) around p, p not on it.
template <class Point_2, class Orientation_2>
long winding_number(const std::vector<Point_2>& P, const std::vector<std::size_t>& L, const Point_2& p,
                    const Orientation_2& orient)
{
  long w = 0;
  const std::size_t n = L.size();
  for(std::size_t k = 0; k < n; ++k)
  {
    const Point_2& a = P[L[k]];
    const Point_2& b = P[L[(k + 1) % n]];
    if(!(p.y() < a.y()))      // a.y <= p.y
    {
      if(p.y() < b.y() && orient(a, b, p) == CGAL::LEFT_TURN) ++w;   // upward crossing, p on the left
    }
    else if(!(p.y() < b.y())) // b.y <= p.y < a.y
    {
      if(orient(a, b, p) == CGAL::RIGHT_TURN) --w;                   // downward crossing, p on the right
    }
  }
  return w;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_HOLES_DOMAIN_H
