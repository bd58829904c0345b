// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_OVERLAY_MAPS_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_OVERLAY_MAPS_H

// The common refinement of two valid planar maps A and B of one domain, triangulated. Each cell is the
// intersection of a triangle of A and a triangle of B, a convex polygon: every triangle of A is clipped
// by the triangles of B it overlaps (found by a walk to its centroid, then across the edges of B from
// cell to cell), with exact predicates (CGAL::Epeck: filtered, exact only where the interval sign is
// uncertain). Each point of a cell is named by what it is, a vertex of A, a vertex of B (one point where
// both have the same coordinates) or the crossing of an edge of A and an edge of B, so that the cells
// share their points and every point on a cell's border is listed (no T-junction); a crossing is
// constructed once. This is linear in the size of the overlay, where a general overlay of two
// arrangements (CGAL's, internal/cross/overlay_by_arrangement.h, the reference of the tests) sweeps.
// A cell is fanned from a corner whose two neighbours are corners too (then no fan triangle is flat); a
// cell without one gets a vertex at the mean of its corners and is fanned from it. Every point records
// where it lies in each map (a vertex, an edge, a face): a caller places the points on the surfaces from
// that, without evaluating the constructed points exactly.

#include <CGAL/Progressive_embedding/Error_code.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <CGAL/version.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// Where an overlay vertex lies in one map: at the map vertex `{v, none}`, inside the edge `{u, v}`, or
// inside a face `{none, none}` (the face of any triangle of the overlay that has the vertex).
typedef std::array<std::size_t, 2> Map_feature;

// The triangulated overlay: exact points, counterclockwise triangles, and for each triangle the
// triangle of each map that holds it.
struct Map_overlay
{
  typedef CGAL::Epeck::Point_2 Point_2;
  std::vector<Point_2> points;
  std::vector<std::array<Map_feature, 2> > features; // per point: where it lies in map A and in map B
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::array<std::size_t, 2> > cell_faces; // per triangle: face of map A, face of map B
  std::size_t cells = 0;     // faces of the overlay
  std::size_t crossings = 0; // overlay vertices that are a vertex of neither map
  std::size_t centers = 0;   // vertices added at the mean of a cell's corners
};

// The convex cell `cell` (points of `out`, counterclockwise, `corner[i]` when point i is a strict left
// turn) triangulated into `out`, its triangles tagged with the map faces `faces`.
inline void triangulate_cell(const std::vector<std::size_t>& cell, const std::vector<bool>& corner,
                             const std::array<std::size_t, 2>& faces, Map_overlay& out)
{
  const std::size_t m = cell.size(), none = std::size_t(-1);
  std::size_t apex = none;
  for(std::size_t i = 0; i < m && apex == none; ++i)
    if(corner[i] && corner[(i + m - 1) % m] && corner[(i + 1) % m]) apex = i;
  if(apex != none)
  {
    for(std::size_t k = 1; k + 1 < m; ++k)
    {
      out.triangles.push_back({{ cell[apex], cell[(apex + k) % m], cell[(apex + k + 1) % m] }});
      out.cell_faces.push_back(faces);
    }
    return;
  }
  CGAL::Epeck::FT x(0), y(0);
  int corners = 0;
  for(std::size_t i = 0; i < m; ++i)
    if(corner[i]) { x += out.points[cell[i]].x(); y += out.points[cell[i]].y(); ++corners; }
  const std::size_t center = out.points.size();
  out.points.emplace_back(x / corners, y / corners);
  out.features.push_back({{ Map_feature{{ none, none }}, Map_feature{{ none, none }} }});
  ++out.centers;
  for(std::size_t i = 0; i < m; ++i)
  {
    out.triangles.push_back({{ center, cell[i], cell[(i + 1) % m] }});
    out.cell_faces.push_back(faces);
  }
}

namespace overlay_detail {

constexpr std::size_t none = std::size_t(-1);
typedef CGAL::Epeck K;

// One triangulated map: its points, faces, the edge ids of each face (edge k from corner k to k + 1) and
// the face across each of them (none on the border).
struct Indexed_map
{
  std::vector<K::Point_2> p;
  const std::vector<std::array<std::size_t, 3> >* faces = nullptr;
  std::vector<std::array<std::size_t, 3> > edge, across;
  std::vector<std::array<std::size_t, 2> > ends; // per edge id

  Error_code build(const std::vector<std::array<std::size_t, 3> >& f, std::size_t vertices)
  {
    faces = &f;
    for(const auto& t : f)
      for(int k = 0; k < 3; ++k)
        if(t[k] >= vertices || t[k] == t[(k + 1) % 3]) return ERROR_INVALID_EMBEDDING; // not a triangle of the points
    edge.assign(f.size(), {{ none, none, none }});
    across.assign(f.size(), {{ none, none, none }});
    std::unordered_map<std::uint64_t, std::pair<std::size_t, std::size_t> > first; // edge -> (face, k)
    first.reserve(2 * f.size());
    for(std::size_t t = 0; t < f.size(); ++t)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t u = f[t][k], v = f[t][(k + 1) % 3];
        const std::uint64_t key = std::uint64_t((std::min)(u, v)) << 32 | std::uint64_t((std::max)(u, v));
        const auto it = first.find(key);
        if(it == first.end())
        {
          first.emplace(key, std::make_pair(t, std::size_t(k)));
          edge[t][k] = ends.size();
          ends.push_back({{ u, v }});
          continue;
        }
        const std::size_t s = it->second.first, j = it->second.second;
        if(across[s][j] != none || (*faces)[s][j] != v) return ERROR_INVALID_EMBEDDING; // not a consistent surface
        edge[t][k] = edge[s][j];
        across[t][k] = s;
        across[s][j] = t;
      }
    return OK;
  }
  const K::Point_2& corner(std::size_t t, int k) const { return p[(*faces)[t][k]]; }
};

// A point of a clipped polygon: what it is (a vertex of A or of B, or the crossing of an edge of A with
// the line of an edge of B), its point, and the support of the polygon's edge that leaves it: an edge of
// A (`support_a`) or of B, by its edge id. A point becomes a point of the overlay only once it is in a
// cell: a crossing with the line of an edge may lie beyond the edge, and a later line removes it.
struct Clip_point
{
  enum Kind { A_VERTEX, B_VERTEX, CROSSING } kind;
  std::size_t id;     // the vertex (A_VERTEX, B_VERTEX) or the edge of A (CROSSING)
  std::size_t edge_b; // CROSSING: the edge of B
  K::Point_2 point;
  bool support_a;
  std::size_t support;
};

} // namespace overlay_detail

// `uv_a`/`faces_a` and `uv_b`/`faces_b`: two valid maps (counterclockwise triangles, coordinates in
// double, every vertex in a face) of one convex domain, each certified by the caller. Returns
// ERROR_INVALID_EMBEDDING if a face is not a triangle of the points, if the faces do not make a consistent
// surface, or if the maps do not cover the same domain (a face or a vertex of one outside the other's).
template <class Point_2>
Error_code overlay_maps(const std::vector<Point_2>& uv_a, const std::vector<std::array<std::size_t, 3> >& faces_a,
                        const std::vector<Point_2>& uv_b, const std::vector<std::array<std::size_t, 3> >& faces_b,
                        Map_overlay& out)
{
  using namespace overlay_detail;
  out = Map_overlay();
  if(faces_a.empty() || faces_b.empty()) return ERROR_INVALID_EMBEDDING;
  Indexed_map A, B;
  if(A.build(faces_a, uv_a.size()) != OK || B.build(faces_b, uv_b.size()) != OK) return ERROR_INVALID_EMBEDDING;
  for(const Point_2& q : uv_a) A.p.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
  for(const Point_2& q : uv_b) B.p.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
  const K::Orientation_2 orientation = K().orientation_2_object();

  // the overlay's point of each vertex of A and of B; a vertex of A at the coordinates of a vertex of B is the same
  std::vector<std::size_t> of_a(uv_a.size(), none), of_b(uv_b.size(), none), same_b(uv_a.size(), none);
  {
    std::map<std::pair<double, double>, std::size_t> at;
    for(std::size_t j = 0; j < uv_b.size(); ++j)
      if(!at.emplace(std::make_pair(CGAL::to_double(uv_b[j].x()), CGAL::to_double(uv_b[j].y())), j).second)
        return ERROR_INVALID_EMBEDDING; // two vertices of B at one point
    std::vector<char> taken(uv_b.size(), 0);
    for(std::size_t i = 0; i < uv_a.size(); ++i)
    {
      const auto it = at.find(std::make_pair(CGAL::to_double(uv_a[i].x()), CGAL::to_double(uv_a[i].y())));
      if(it == at.end()) continue;
      if(taken[it->second]) return ERROR_INVALID_EMBEDDING; // two vertices of A at one point
      taken[it->second] = 1;
      same_b[i] = it->second;
    }
  }
  std::unordered_map<std::uint64_t, std::size_t> crossing; // edge of A * edges of B + edge of B -> point
  const std::uint64_t nb_edges = B.ends.size();

  // where point q lies in triangle t of map M (a vertex, on an edge, inside), q known to be in the closed triangle
  auto feature_in = [&](const Indexed_map& M, std::size_t t, const K::Point_2& q) -> Map_feature {
    std::size_t on = none;
    int zeros = 0;
    for(int k = 0; k < 3; ++k)
      if(orientation(M.corner(t, k), M.corner(t, (k + 1) % 3), q) == CGAL::COLLINEAR) { on = std::size_t(k); ++zeros; }
    if(zeros == 0) return {{ none, none }};
    if(zeros == 1) return {{ (*M.faces)[t][on], (*M.faces)[t][(on + 1) % 3] }};
    // on two edge lines: their common corner (a vertex of the other map at a vertex of M was merged before)
    for(int k = 0; k < 3; ++k) if(M.corner(t, k) == q) return {{ (*M.faces)[t][k], none }};
    return {{ none, none }};
  };
  auto add_point = [&](const K::Point_2& q, const Map_feature& fa, const Map_feature& fb) {
    out.points.push_back(q);
    out.features.push_back({{ fa, fb }});
    return out.points.size() - 1;
  };
  // the overlay point of vertex i of A, in the closed triangle tb of B
  auto point_of_a = [&](std::size_t i, std::size_t tb) {
    if(of_a[i] != none) return of_a[i];
    const std::size_t j = same_b[i];
    if(j != none) of_a[i] = of_b[j] = add_point(A.p[i], {{ i, none }}, {{ j, none }});
    else of_a[i] = add_point(A.p[i], {{ i, none }}, feature_in(B, tb, A.p[i]));
    return of_a[i];
  };
  std::vector<std::size_t> a_of_b(uv_b.size(), none);
  for(std::size_t i = 0; i < uv_a.size(); ++i) if(same_b[i] != none) a_of_b[same_b[i]] = i;
  auto point_of_b = [&](std::size_t j, std::size_t ta) {
    if(of_b[j] != none) return of_b[j];
    const std::size_t i = a_of_b[j];
    if(i != none) of_a[i] = of_b[j] = add_point(B.p[j], {{ i, none }}, {{ j, none }});
    else of_b[j] = add_point(B.p[j], feature_in(A, ta, B.p[j]), {{ j, none }});
    return of_b[j];
  };
  // the point where edge ea of A (between the two sides of the line of edge eb of B) meets that line
  auto cross = [&](std::size_t ea, std::size_t eb) -> Clip_point {
    const auto& a = A.ends[ea];
    const auto& b = B.ends[eb];
    for(std::size_t j : b)
      if(orientation(A.p[a[0]], A.p[a[1]], B.p[j]) == CGAL::COLLINEAR) return { Clip_point::B_VERTEX, j, none, B.p[j], true, none };
    const auto it = crossing.find(std::uint64_t(ea) * nb_edges + eb);
    if(it != crossing.end()) return { Clip_point::CROSSING, ea, eb, out.points[it->second], true, none };
    const auto x = CGAL::intersection(K::Line_2(A.p[a[0]], A.p[a[1]]), K::Line_2(B.p[b[0]], B.p[b[1]]));
#if CGAL_VERSION_NR >= 1060000000
    const K::Point_2* q = x ? std::get_if<K::Point_2>(&*x) : nullptr;
#else
    const K::Point_2* q = x ? boost::get<K::Point_2>(&*x) : nullptr;
#endif
    if(q == nullptr) return { Clip_point::CROSSING, none, none, K::Point_2(), true, none }; // parallel: cannot happen
    return { Clip_point::CROSSING, ea, eb, *q, true, none };
  };
  // the overlay point of a point of the cell (ta, tb)
  auto materialize = [&](const Clip_point& c, std::size_t ta, std::size_t tb) {
    if(c.kind == Clip_point::A_VERTEX) return point_of_a(c.id, tb);
    if(c.kind == Clip_point::B_VERTEX) return point_of_b(c.id, ta);
    const std::uint64_t key = std::uint64_t(c.id) * nb_edges + c.edge_b;
    const auto it = crossing.find(key);
    if(it != crossing.end()) return it->second;
    const auto& a = A.ends[c.id];
    const auto& b = B.ends[c.edge_b];
    const std::size_t id = add_point(c.point, {{ a[0], a[1] }}, {{ b[0], b[1] }});
    ++out.crossings;
    crossing.emplace(key, id);
    return id;
  };
  auto common_vertex = [&](std::size_t e, std::size_t g) {
    for(std::size_t u : B.ends[e]) for(std::size_t v : B.ends[g]) if(u == v) return u;
    return none;
  };

  std::vector<Clip_point> poly, next;
  std::vector<CGAL::Orientation> side;
  std::vector<std::size_t> cell;
  std::vector<bool> corner, cell_corner; // kept across cells: no allocation per cell
  // the cell of ta and tb, appended to `out`; false if the two triangles overlap in no area
  bool failed = false;
  auto clip = [&](std::size_t ta, std::size_t tb) {
    poly.clear();
    for(int k = 0; k < 3; ++k)
      poly.push_back({ Clip_point::A_VERTEX, faces_a[ta][k], none, A.corner(ta, k), true, A.edge[ta][k] });
    for(int k = 0; k < 3 && !poly.empty(); ++k)
    {
      const K::Point_2 &b0 = B.corner(tb, k), &b1 = B.corner(tb, (k + 1) % 3);
      const std::size_t g = B.edge[tb][k];
      side.clear();
      bool any_out = false;
      for(const Clip_point& c : poly)
      {
        side.push_back(orientation(b0, b1, c.point));
        if(side.back() == CGAL::RIGHT_TURN) any_out = true;
      }
      if(!any_out) continue;
      // where the polygon's edge from p crosses the line of g: on an edge of A, a crossing; on an edge of B
      // (the line of an earlier edge of tb), the corner of tb the two share
      auto meet = [&](const Clip_point& p) -> Clip_point {
        if(p.support_a) return cross(p.support, g);
        const std::size_t j = common_vertex(p.support, g);
        return { Clip_point::B_VERTEX, j, none, B.p[j], true, none };
      };
      next.clear();
      const std::size_t m = poly.size();
      for(std::size_t i = 0; i < m; ++i)
      {
        const Clip_point& p = poly[i];
        const CGAL::Orientation sp = side[i], sq = side[(i + 1) % m];
        if(sp != CGAL::RIGHT_TURN)
        {
          next.push_back(p);
          if(sq == CGAL::RIGHT_TURN)
          {
            // leaving: along the line of g from p (on it) or from the crossing
            if(sp == CGAL::COLLINEAR) { next.back().support_a = false; next.back().support = g; }
            else
            {
              next.push_back(meet(p));
              next.back().support_a = false;
              next.back().support = g;
            }
          }
        }
        else if(sq == CGAL::LEFT_TURN)
        {
          // entering: from the crossing along the edge p was on
          next.push_back(meet(p));
          next.back().support_a = p.support_a;
          next.back().support = p.support;
        }
      }
      for(const Clip_point& c : next)
        if(c.kind == Clip_point::CROSSING && c.id == none) { failed = true; return false; }
      poly.swap(next);
    }
    if(poly.size() < 3) return false;
    // no area unless some point is a strict left turn (two pieces of one edge make no corner)
    const std::size_t n = poly.size();
    corner.assign(n, false);
    bool any = false;
    for(std::size_t i = 0; i < n; ++i)
    {
      const Clip_point &p = poly[(i + n - 1) % n], &c = poly[i], &q = poly[(i + 1) % n];
      if(p.support_a == c.support_a && p.support == c.support) continue;
      const CGAL::Orientation o = orientation(p.point, c.point, q.point);
      if(o == CGAL::RIGHT_TURN) { failed = true; return false; } // not convex: cannot happen
      corner[i] = (o == CGAL::LEFT_TURN);
      any = any || corner[i];
    }
    if(!any) return false;
    // the points of the overlay, the same point twice in a row (a crossing at a point already listed) once
    cell.clear();
    cell_corner.clear();
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t id = materialize(poly[i], ta, tb);
      if(!cell.empty() && cell.back() == id) { cell_corner.back() = cell_corner.back() || corner[i]; continue; }
      cell.push_back(id);
      cell_corner.push_back(corner[i]);
    }
    while(cell.size() > 1 && cell.front() == cell.back())
    {
      cell_corner.front() = cell_corner.front() || cell_corner.back();
      cell.pop_back();
      cell_corner.pop_back();
    }
    if(cell.size() < 3) { failed = true; return false; } // a corner lost: cannot happen
    ++out.cells;
    triangulate_cell(cell, cell_corner, {{ ta, tb }}, out);
    return true;
  };

  // the faces of A in breadth-first order, each started from the face of B found for the one before it
  std::vector<std::size_t> seed(faces_a.size(), none), stamp(faces_b.size(), none), cells_of_b(faces_b.size(), 0);
  std::vector<char> queued_a(faces_a.size(), 0);
  std::deque<std::size_t> order{ 0 };
  queued_a[0] = 1;
  seed[0] = 0;
  std::deque<std::size_t> queue;
  std::size_t walk_state = 0;
  while(!order.empty())
  {
    const std::size_t ta = order.front();
    order.pop_front();
    // the face of B holding the centroid of ta (strictly inside ta): a walk towards it, bounded
    const K::Point_2 c = CGAL::centroid(A.corner(ta, 0), A.corner(ta, 1), A.corner(ta, 2));
    std::size_t tb = seed[ta];
    auto holds = [&](std::size_t t) {
      for(int k = 0; k < 3; ++k)
        if(orientation(B.corner(t, k), B.corner(t, (k + 1) % 3), c) == CGAL::RIGHT_TURN) return false;
      return true;
    };
    for(std::size_t steps = 0;; ++steps)
    {
      if(steps > 2 * faces_b.size() + 8)
      {
        // a visibility walk in a triangulation that is not Delaunay may take long: the faces of B in turn
        tb = none;
        for(std::size_t t = 0; t < faces_b.size() && tb == none; ++t) if(holds(t)) tb = t;
        if(tb == none) return ERROR_INVALID_EMBEDDING; // a point of A outside B's domain
        break;
      }
      // the edges tried from a varying first one: a walk that cannot cycle for ever
      walk_state = walk_state * 1103515245u + 12345u;
      const int first = int((walk_state >> 16) % 3);
      std::size_t to = none;
      bool outside = false;
      for(int d = 0; d < 3 && to == none && !outside; ++d)
      {
        const int k = (first + d) % 3;
        if(orientation(B.corner(tb, k), B.corner(tb, (k + 1) % 3), c) != CGAL::RIGHT_TURN) continue;
        if(B.across[tb][k] == none) outside = true;
        else to = B.across[tb][k];
      }
      if(outside) return ERROR_INVALID_EMBEDDING; // a point of A outside B's domain
      if(to == none) break;
      tb = to;
    }
    // the faces of B overlapping ta: from tb, across the edges of B from cell to cell
    std::size_t found = 0;
    queue.assign(1, tb);
    stamp[tb] = ta;
    while(!queue.empty())
    {
      const std::size_t t = queue.front();
      queue.pop_front();
      if(!clip(ta, t)) { if(failed) return ERROR_INVALID_EMBEDDING; continue; }
      ++found;
      ++cells_of_b[t];
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t u = B.across[t][k];
        if(u != none && stamp[u] != ta) { stamp[u] = ta; queue.push_back(u); }
      }
    }
    if(found == 0) return ERROR_INVALID_EMBEDDING;
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t u = A.across[ta][k];
      if(u != none && !queued_a[u]) { queued_a[u] = 1; seed[u] = tb; order.push_back(u); }
    }
  }
  // every face of A reached (A connected), every face of B and every vertex of either map in the overlay
  for(char q : queued_a) if(!q) return ERROR_INVALID_EMBEDDING;
  for(std::size_t n : cells_of_b) if(n == 0) return ERROR_INVALID_EMBEDDING;
  for(std::size_t i : of_a) if(i == none) return ERROR_INVALID_EMBEDDING;
  for(std::size_t j : of_b) if(j == none) return ERROR_INVALID_EMBEDDING;
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_OVERLAY_MAPS_H
