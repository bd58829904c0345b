// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_PATH_NETWORK_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_PATH_NETWORK_H

// What both path tracers (trace_paths.h: shortest paths of mesh edges; trace_overlay.h: curves over
// the input edges) share, so that neither includes the other: the Steiner vertex record, the path
// network's vertex marks, the checks of their preconditions (a triangulated disk, a planar partition
// graph) and postconditions (check_traced_paths(), label_patches()), the chord splits, and the order
// in which the partition's edges are traced. The interface is described at the top of trace_paths.h.

#include <CGAL/Progressive_embedding/internal/length_3.h>
#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/constrained/refinement.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Kernel_traits.h>

#include <boost/functional/hash.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

/// A vertex added by refinement: `v` was inserted on the edge (`a`, `b`) (as it was when split) at
/// the 3D point `(1-t) a + t b`. `a` or `b` may themselves be earlier Steiner vertices.
template <class TriangleMesh>
struct Steiner_vertex
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  vertex_descriptor v, a, b;
  double t;
  /// whether the split also joined `v` to the opposite corners of the edge's faces (refinement.h);
  /// otherwise the faces were left as they were (several points inserted on one edge)
  bool join_faces = true;
  /// the edges added after this split, each across one face (refinement.h's connect_in_face())
  std::vector<std::pair<vertex_descriptor, vertex_descriptor> > diagonals;
};

/// A patch of the traced network: a connected set of faces bounded by paths and border sides. After a
/// successful `trace_paths()`, its `corners` are the nodes of one polygon of the partition in
/// counterclockwise order (every node on the polygon's boundary, straight angles included), so the
/// directed pair (`corners[0]`, `corners[1]`) identifies the polygon (the one on its left); the
/// side from `corners[k]` to `corners[k+1]` is `border[corner_positions[k]]` up to the halfedge before
/// `border[corner_positions[k+1]]` (cyclically): a path or a border side.
template <class TriangleMesh>
struct Traced_patch
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  std::vector<halfedge_descriptor> border; ///< the border cycle, the patch on the left; starts at a corner when there is one
  std::vector<std::size_t> corners;        ///< the nodes met along `border`, in order (node indices)
  std::vector<std::size_t> corner_positions; ///< `border[corner_positions[k]]` leaves `corners[k]`
  std::size_t number_of_faces = 0;
  bool is_disk = false;                    ///< one border cycle, simple, Euler characteristic 1
};

// ---- small graph helpers ----------------------------------------------------------------------

// next outgoing halfedge counterclockwise around source(g): across the face on the left of g
// (for the outgoing border halfedge of a border vertex it crosses the hole, which closes the cycle)
template <class TM>
typename boost::graph_traits<TM>::halfedge_descriptor
ccw_next_outgoing(typename boost::graph_traits<TM>::halfedge_descriptor g, const TM& tm)
{
  return opposite(prev(g, tm), tm);
}

// the outgoing halfedges of v in counterclockwise order (bounded by the number of halfedges)
template <class TM>
void outgoing_ccw(typename boost::graph_traits<TM>::vertex_descriptor v, const TM& tm,
                  std::vector<typename boost::graph_traits<TM>::halfedge_descriptor>& out)
{
  out.clear();
  const auto g0 = opposite(halfedge(v, tm), tm);
  auto g = g0;
  const std::size_t guard = num_halfedges(tm);
  do { out.push_back(g); g = ccw_next_outgoing(g, tm); } while(g != g0 && out.size() <= guard);
}

inline std::uint64_t vertex_pair_key(std::size_t a, std::size_t b)
{
  if(a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
}

// Vertex/edge status shared by the tracing, the checks and the chord splitting: path edges and the
// vertices of the network (border vertices, nodes, path vertices).
// The border cycles of tm (each walk bounded by the number of halfedges)
template <class TM>
std::size_t number_of_border_cycles(const TM& tm)
{
  typedef typename boost::graph_traits<TM>::halfedge_descriptor halfedge_descriptor;
  std::size_t cycles = 0;
  std::unordered_set<halfedge_descriptor, boost::hash<halfedge_descriptor> > seen;
  for(halfedge_descriptor h : halfedges(tm))
  {
    if(!CGAL::is_border(h, tm) || seen.count(h)) continue;
    ++cycles;
    halfedge_descriptor c = h;
    std::size_t guard = 0;
    do { seen.insert(c); c = next(c, tm); } while(c != h && ++guard <= num_halfedges(tm));
  }
  return cycles;
}

template <class TM>
struct Path_network
{
  typedef boost::graph_traits<TM> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_map<TM, CGAL::dynamic_vertex_property_t<int> >::type Vid;

  const TM& tm;
  Vid vid;
  std::vector<vertex_descriptor> vd;
  std::vector<char> border_vertex;
  std::vector<int> node_of;     // node index or -1
  std::vector<int> path_of;     // path whose interior holds the vertex, or -1
  // a path edge has an interior path vertex, whose two neighbours along its path are kept, or it is
  // a whole path of one edge (looked up by hashing: rare). The queries are the tracers' inner loop.
  std::vector<std::array<int, 2> > path_neighbours;
  std::unordered_set<std::uint64_t> one_edge_paths;

  explicit Path_network(TM& m) : tm(m), vid(get(CGAL::dynamic_vertex_property_t<int>(), m))
  {
    const std::size_t n = static_cast<std::size_t>(num_vertices(tm));
    vd.reserve(n); border_vertex.reserve(n); node_of.reserve(n); path_of.reserve(n); path_neighbours.reserve(n);
    for(vertex_descriptor v : vertices(tm)) add_vertex(v, false);
    // the border vertices from the border halfedges: one pass, not one turn around every vertex
    for(halfedge_descriptor h : halfedges(tm))
      if(CGAL::is_border(h, tm)) border_vertex[static_cast<std::size_t>(id(target(h, tm)))] = 1;
  }
  int add_vertex(vertex_descriptor v) { return add_vertex(v, CGAL::is_border(v, tm) != boost::none); }
  int add_vertex(vertex_descriptor v, bool on_border)
  {
    const int i = static_cast<int>(vd.size());
    put(vid, v, i);
    vd.push_back(v);
    border_vertex.push_back(on_border ? 1 : 0);
    node_of.push_back(-1);
    path_of.push_back(-1);
    path_neighbours.push_back(std::array<int, 2>{ { -1, -1 } });
    return i;
  }
  int id(vertex_descriptor v) const { return get(vid, v); }
  bool blocked(int i) const { return border_vertex[i] || node_of[i] >= 0 || path_of[i] >= 0; }
  bool is_path_edge(int a, int b) const
  {
    if(path_of[a] >= 0) return path_neighbours[a][0] == b || path_neighbours[a][1] == b;
    if(path_of[b] >= 0) return path_neighbours[b][0] == a || path_neighbours[b][1] == a;
    return !one_edge_paths.empty() && one_edge_paths.count(vertex_pair_key(a, b)) != 0;
  }
  void add_path(const std::vector<vertex_descriptor>& p, int index)
  {
    if(p.size() == 2) one_edge_paths.insert(vertex_pair_key(id(p[0]), id(p[1])));
    for(std::size_t k = 1; k + 1 < p.size(); ++k)
    {
      const int i = id(p[k]);
      path_of[i] = index;
      path_neighbours[i] = std::array<int, 2>{ { id(p[k - 1]), id(p[k + 1]) } };
    }
  }
  // a chord: an edge between two blocked vertices that is neither a path edge nor a border edge
  bool is_chord(halfedge_descriptor h) const
  {
    const int a = id(source(h, tm)), b = id(target(h, tm));
    return blocked(a) && blocked(b) && !is_path_edge(a, b) && !CGAL::is_border(edge(h, tm), tm);
  }
};

// ---- input checks -------------------------------------------------------------------------------

// triangle mesh, connected, genus 0 with at least one border cycle (Euler characteristic 2 minus
// the number of border cycles: 1 for a disk), border cycles through distinct vertices, no isolated vertex
template <class TM>
Error_code check_triangulated_disk(const TM& tm)
{
  typedef boost::graph_traits<TM> GT;
  std::size_t nv = 0, ne = 0, nf = 0;
  for(auto f : faces(tm))
  {
    ++nf;
    if(CGAL::halfedges_around_face(halfedge(f, tm), tm).size() != 3) return ERROR_NON_TRIANGULAR_MESH;
  }
  if(nf == 0) return ERROR_EMPTY_MESH;
  for(auto v : vertices(tm))
  {
    ++nv;
    if(halfedge(v, tm) == GT::null_halfedge()) return ERROR_NOT_A_DISK; // isolated vertex
  }
  for(auto e : edges(tm)) { (void)e; ++ne; }
  std::size_t cycles = 0, nb = 0;
  std::unordered_set<typename GT::halfedge_descriptor, boost::hash<typename GT::halfedge_descriptor> > seen;
  std::unordered_set<typename GT::vertex_descriptor, boost::hash<typename GT::vertex_descriptor> > border_targets;
  for(auto h : halfedges(tm))
  {
    if(!CGAL::is_border(h, tm)) continue;
    ++nb;
    if(!border_targets.insert(target(h, tm)).second) return ERROR_NON_MANIFOLD; // pinched border vertex
    if(seen.count(h)) continue;
    ++cycles;
    auto c = h;
    std::size_t guard = 0;
    do { seen.insert(c); c = next(c, tm); } while(c != h && ++guard <= num_halfedges(tm));
  }
  if(cycles == 0) return ERROR_NOT_A_DISK;
  if(nv + nf + cycles != ne + 2) return cycles == 1 ? ERROR_NOT_A_DISK : ERROR_NOT_GENUS_ZERO;
  // connected (checked directly: a closed component could balance the Euler characteristic)
  std::unordered_set<typename GT::face_descriptor, boost::hash<typename GT::face_descriptor> > reached;
  std::vector<typename GT::face_descriptor> stack(1, *faces(tm).begin());
  reached.insert(stack.back());
  while(!stack.empty())
  {
    const auto f = stack.back(); stack.pop_back();
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
    {
      const auto g = face(opposite(h, tm), tm);
      if(g != GT::null_face() && reached.insert(g).second) stack.push_back(g);
    }
  }
  if(reached.size() != nf) return ERROR_NOT_A_DISK;
  return OK;
}

// Border nodes in mesh border order (interior on the left), and the planarity of the rotation system
// made of the interior edges and the border sides: V - E + F == 2 for the connected graph.
template <class TM>
Error_code check_partition(const TM& tm, const Path_network<TM>& net,
                           const std::vector<typename boost::graph_traits<TM>::vertex_descriptor>& nodes,
                           const std::vector<std::array<std::size_t, 2> >& edges,
                           const std::vector<std::vector<std::size_t> >& rotation,
                           std::vector<std::size_t>& border_nodes,
                           std::vector<std::vector<std::size_t> >& loops)
{
  const std::size_t N = nodes.size(), E = edges.size();
  border_nodes.clear();
  loops.clear();
  if(rotation.size() != N) return ERROR_WRONG_PARAMETER;
  for(std::size_t e = 0; e < E; ++e)
    if(edges[e][0] >= N || edges[e][1] >= N || edges[e][0] == edges[e][1]) return ERROR_WRONG_PARAMETER;
  {
    std::unordered_set<std::uint64_t> pairs;
    for(std::size_t e = 0; e < E; ++e)
      if(!pairs.insert(vertex_pair_key(edges[e][0], edges[e][1])).second) return ERROR_WRONG_PARAMETER;
  }
  std::vector<std::size_t> degree(N, 0);
  for(std::size_t e = 0; e < E; ++e) { ++degree[edges[e][0]]; ++degree[edges[e][1]]; }
  for(std::size_t i = 0; i < N; ++i)
  {
    if(rotation[i].size() != degree[i]) return ERROR_WRONG_PARAMETER;
    std::unordered_set<std::size_t> seen;
    for(std::size_t e : rotation[i])
      if(e >= E || (edges[e][0] != i && edges[e][1] != i) || !seen.insert(e).second) return ERROR_WRONG_PARAMETER;
  }
  // border nodes along each border cycle (interior on the left); every cycle needs a node
  {
    std::unordered_set<typename boost::graph_traits<TM>::halfedge_descriptor,
                       boost::hash<typename boost::graph_traits<TM>::halfedge_descriptor> > seen;
    for(auto h0 : halfedges(tm))
    {
      if(!CGAL::is_border(h0, tm) || seen.count(h0)) continue;
      loops.emplace_back();
      // the border halfedges run clockwise (hole on their left): walk them backwards
      auto h = h0;
      std::size_t guard = 0;
      do
      {
        seen.insert(h);
        const int n = net.node_of[net.id(target(h, tm))];
        if(n >= 0) loops.back().push_back(static_cast<std::size_t>(n));
        h = prev(h, tm);
      } while(h != h0 && ++guard <= num_halfedges(tm));
      if(loops.back().empty() && (N > 0 || loops.size() > 1)) return ERROR_WRONG_PARAMETER;
    }
  }
  if(N == 0) return loops.size() == 1 ? OK : ERROR_WRONG_PARAMETER;
  for(const auto& L : loops) if(L.empty()) return ERROR_WRONG_PARAMETER;
  for(const auto& L : loops) border_nodes.insert(border_nodes.end(), L.begin(), L.end());
  const std::size_t B = border_nodes.size();
  // darts: 2e (edge e from edges[e][0]), 2e+1 (reverse); border side k: 2(E+k) from border_nodes[k] to
  // the next node of its cycle
  std::vector<std::vector<std::size_t> > full(N);
  std::vector<std::size_t> next_side(N, std::size_t(-1)), prev_side(N, std::size_t(-1));
  std::vector<std::vector<std::size_t> > adj(N);
  {
    std::size_t k = 0;
    for(const auto& L : loops)
      for(std::size_t j = 0; j < L.size(); ++j, ++k)
      {
        next_side[L[j]] = k;                                   // side k: L[j] -> L[j+1]
        prev_side[L[(j + 1) % L.size()]] = k;
        adj[L[j]].push_back(L[(j + 1) % L.size()]);
        adj[L[(j + 1) % L.size()]].push_back(L[j]);
      }
  }
  for(std::size_t i = 0; i < N; ++i)
  {
    if(next_side[i] != std::size_t(-1)) full[i].push_back(2 * (E + next_side[i]));
    for(std::size_t e : rotation[i]) full[i].push_back(edges[e][0] == i ? 2 * e : 2 * e + 1);
    if(prev_side[i] != std::size_t(-1)) full[i].push_back(2 * (E + prev_side[i]) + 1);
  }
  const std::size_t D = 2 * (E + B);
  std::vector<std::size_t> dart_node(D), dart_pos(D);
  for(std::size_t i = 0; i < N; ++i)
    for(std::size_t k = 0; k < full[i].size(); ++k) { dart_node[full[i][k]] = i; dart_pos[full[i][k]] = k; }
  // faces: the next dart after d = (x -> y) is the predecessor of (y -> x) in y's rotation
  std::vector<char> done(D, 0);
  std::size_t F = 0;
  for(std::size_t d0 = 0; d0 < D; ++d0)
  {
    if(done[d0]) continue;
    ++F;
    std::size_t d = d0, guard = 0;
    do
    {
      done[d] = 1;
      const std::size_t r = d ^ 1, y = dart_node[r];
      d = full[y][(dart_pos[r] + full[y].size() - 1) % full[y].size()];
    } while(d != d0 && ++guard <= D);
  }
  // connectivity (border sides included)
  for(std::size_t e = 0; e < E; ++e) { adj[edges[e][0]].push_back(edges[e][1]); adj[edges[e][1]].push_back(edges[e][0]); }
  std::vector<char> reached(N, 0);
  std::vector<std::size_t> stack(1, border_nodes.front());
  reached[border_nodes.front()] = 1;
  while(!stack.empty())
  {
    const std::size_t i = stack.back(); stack.pop_back();
    for(std::size_t j : adj[i]) if(!reached[j]) { reached[j] = 1; stack.push_back(j); }
  }
  for(std::size_t i = 0; i < N; ++i) if(!reached[i]) return ERROR_WRONG_PARAMETER;
  if(N + F != (E + B) + 2) return ERROR_WRONG_PARAMETER; // not planar: no partition of the disk has it
  return OK;
}

// ---- patches -------------------------------------------------------------------------------------

/// labels every face of `tm` with its patch (the faces connected across edges that are neither on a
/// path nor on the border) in `face_patch`, and describes each patch. Returns `OK` when every patch is
/// a disk (one border cycle, simple, Euler characteristic 1), `ERROR_PATH_TRACING_FAILED` otherwise.
template <class TM, class FacePatchMap>
Error_code label_patches(const TM& tm,
                         const std::vector<typename boost::graph_traits<TM>::vertex_descriptor>& nodes,
                         const std::vector<std::vector<typename boost::graph_traits<TM>::vertex_descriptor> >& paths,
                         FacePatchMap face_patch, std::vector<Traced_patch<TM> >& patches)
{
  typedef boost::graph_traits<TM> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  patches.clear();
  Path_network<TM> net(const_cast<TM&>(tm));
  for(std::size_t i = 0; i < nodes.size(); ++i) net.node_of[net.id(nodes[i])] = static_cast<int>(i);
  for(std::size_t p = 0; p < paths.size(); ++p) net.add_path(paths[p], static_cast<int>(p));
  auto cut = [&](halfedge_descriptor h)
  {
    return CGAL::is_border(edge(h, tm), tm) || net.is_path_edge(net.id(source(h, tm)), net.id(target(h, tm)));
  };
  const std::size_t none = std::size_t(-1);
  for(face_descriptor f : faces(tm)) put(face_patch, f, none);
  Error_code status = OK;
  // per vertex id: the last patch that counted it, the last patch whose border walk met it
  std::vector<std::size_t> counted(net.vd.size(), none), walked(net.vd.size(), none);
  for(face_descriptor f0 : faces(tm))
  {
    if(get(face_patch, f0) != none) continue;
    const std::size_t pi = patches.size();
    patches.emplace_back();
    Traced_patch<TM>& P = patches.back();
    std::vector<face_descriptor> stack(1, f0), members;
    put(face_patch, f0, pi);
    std::vector<halfedge_descriptor> bh;
    while(!stack.empty())
    {
      const face_descriptor f = stack.back(); stack.pop_back();
      members.push_back(f);
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      {
        if(cut(h)) { bh.push_back(h); continue; }
        const face_descriptor g = face(opposite(h, tm), tm);
        if(get(face_patch, g) == none) { put(face_patch, g, pi); stack.push_back(g); }
      }
    }
    P.number_of_faces = members.size();
    // vertices of the patch
    std::size_t nv = 0;
    for(face_descriptor f : members)
      for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm))
      {
        const std::size_t i = static_cast<std::size_t>(net.id(v));
        if(counted[i] != pi) { counted[i] = pi; ++nv; }
      }
    const std::size_t ne = (3 * members.size() + bh.size()) / 2;
    bool disk = (nv + members.size() == ne + 1) && !bh.empty();
    // the border cycle from a corner (or any border halfedge)
    if(disk)
    {
      halfedge_descriptor start = bh.front();
      for(halfedge_descriptor h : bh) if(net.node_of[net.id(source(h, tm))] >= 0) { start = h; break; }
      halfedge_descriptor h = start;
      std::size_t guard = 0;
      do
      {
        const std::size_t i = static_cast<std::size_t>(net.id(source(h, tm)));
        if(walked[i] == pi) { disk = false; break; }
        walked[i] = pi;
        const int n = net.node_of[i];
        if(n >= 0) { P.corners.push_back(static_cast<std::size_t>(n)); P.corner_positions.push_back(P.border.size()); }
        P.border.push_back(h);
        // next border halfedge of the patch: turn around target(h) inside the patch
        halfedge_descriptor g = next(h, tm);
        std::size_t turn = 0;
        while(!cut(g) && ++turn <= num_halfedges(tm)) g = next(opposite(g, tm), tm);
        h = g;
      } while(h != start && ++guard <= bh.size());
      if(P.border.size() != bh.size()) disk = false; // several border cycles
    }
    P.is_disk = disk;
    if(!disk) status = ERROR_PATH_TRACING_FAILED;
  }
  return status;
}

/// checks the postconditions of `trace_paths()`; `number_of_patches` (if not null) receives the count.
/// Without `check_patches`, only the paths and their rotations are checked, not the patches they bound
/// (a full labelling of the mesh, for callers that label the patches themselves).
template <class TM>
Error_code check_traced_paths(const TM& tm,
                              const std::vector<typename boost::graph_traits<TM>::vertex_descriptor>& nodes,
                              const std::vector<std::array<std::size_t, 2> >& edges,
                              const std::vector<std::vector<std::size_t> >& rotation,
                              const std::vector<std::vector<typename boost::graph_traits<TM>::vertex_descriptor> >& paths,
                              std::size_t* number_of_patches = nullptr, bool check_patches = true)
{
  typedef boost::graph_traits<TM> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  if(paths.size() != edges.size() || rotation.size() != nodes.size()) return ERROR_PATH_TRACING_FAILED;
  Path_network<TM> net(const_cast<TM&>(tm));
  for(std::size_t i = 0; i < nodes.size(); ++i) net.node_of[net.id(nodes[i])] = static_cast<int>(i);
  // first edge of each path at each node: outgoing halfedge -> edge index
  std::unordered_map<halfedge_descriptor, std::size_t, boost::hash<halfedge_descriptor> > leaving;
  for(std::size_t p = 0; p < paths.size(); ++p)
  {
    const auto& P = paths[p];
    if(P.size() < 2 || P.front() != nodes[edges[p][0]] || P.back() != nodes[edges[p][1]]) return ERROR_PATH_TRACING_FAILED;
    for(std::size_t k = 0; k + 1 < P.size(); ++k)
    {
      const auto hb = halfedge(P[k], P[k + 1], tm);
      if(!hb.second || CGAL::is_border(edge(hb.first, tm), tm)) return ERROR_PATH_TRACING_FAILED;
    }
    for(std::size_t k = 1; k + 1 < P.size(); ++k)
    {
      const int i = net.id(P[k]);
      if(net.border_vertex[i] || net.node_of[i] >= 0 || net.path_of[i] >= 0) return ERROR_PATH_TRACING_FAILED;
      net.path_of[i] = static_cast<int>(p);
    }
    if(!leaving.emplace(halfedge(P[0], P[1], tm).first, p).second) return ERROR_PATH_TRACING_FAILED;
    if(!leaving.emplace(halfedge(P.back(), P[P.size() - 2], tm).first, p).second) return ERROR_PATH_TRACING_FAILED;
  }
  // rotation at each node
  std::vector<halfedge_descriptor> out;
  for(std::size_t i = 0; i < nodes.size(); ++i)
  {
    outgoing_ccw(nodes[i], tm, out);
    std::vector<std::size_t> order;
    std::size_t start = 0;
    for(std::size_t k = 0; k < out.size(); ++k)
      if(CGAL::is_border(opposite(out[k], tm), tm)) start = k; // the next border side
    for(std::size_t k = 0; k < out.size(); ++k)
    {
      const auto it = leaving.find(out[(start + k) % out.size()]);
      if(it != leaving.end()) order.push_back(it->second);
    }
    if(order.size() != rotation[i].size()) return ERROR_PATH_TRACING_FAILED;
    if(order.empty()) continue;
    std::size_t shift = 0;
    if(!CGAL::is_border(nodes[i], tm)) // cyclic: align the first entries
      shift = static_cast<std::size_t>(std::find(order.begin(), order.end(), rotation[i][0]) - order.begin());
    for(std::size_t k = 0; k < order.size(); ++k)
      if(order[(shift + k) % order.size()] != rotation[i][k]) return ERROR_PATH_TRACING_FAILED;
  }
  if(!check_patches) return OK;
  // patches: disks, one per polygon (Euler: 1 - nodes + interior edges + border sides)
  std::size_t B = 0;
  for(std::size_t i = 0; i < nodes.size(); ++i) if(CGAL::is_border(nodes[i], tm)) ++B;
  auto fpm = get(CGAL::dynamic_face_property_t<std::size_t>(), const_cast<TM&>(tm));
  std::vector<Traced_patch<TM> > patches;
  if(label_patches(tm, nodes, paths, fpm, patches) != OK) return ERROR_PATH_TRACING_FAILED;
  if(number_of_patches) *number_of_patches = patches.size();
  const std::size_t cycles = number_of_border_cycles(tm);
  // Euler on the sphere: polygons = interior edges + border sides - nodes + 2 - outer face - holes
  const std::size_t expected = nodes.empty() ? 1 : 1 + edges.size() + B - nodes.size() - (cycles - 1);
  if(patches.size() != expected) return ERROR_PATH_TRACING_FAILED;
  return OK;
}

// ---- splits --------------------------------------------------------------------------------------

// splits the edge of h at its midpoint (refinement.h's split_edge_and_faces: the one split that
// constrained_embedding() replays on the caller's mesh) and records the Steiner vertex
template <class TM, class VPM>
typename boost::graph_traits<TM>::vertex_descriptor
split_at_midpoint(typename boost::graph_traits<TM>::halfedge_descriptor h, TM& tm, VPM vpm,
                  std::vector<Steiner_vertex<TM> >& steiner)
{
  const auto a = source(h, tm), b = target(h, tm);
  const auto pa = get(vpm, a), pb = get(vpm, b);
  typedef typename CGAL::Kernel_traits<typename std::decay<decltype(pa)>::type>::Kernel K;
  const auto m = target(split_edge_and_faces(h, K().construct_midpoint_3_object()(pa, pb), tm, vpm), tm);
  steiner.push_back(Steiner_vertex<TM>{ m, a, b, 0.5 });
  return m;
}

/// accepts every chord
struct Accept_every_chord
{
  template <class V> bool operator()(const V&, const V&) const { return true; }
};

/// accepts the chords whose two endpoints lie on one path (its end nodes included) or on one border
/// side (the border between two consecutive border nodes, those included): in a patch mapped to a
/// convex polygon these would join two points of one straight side.
template <class TM>
class Same_side_chord
{
  typedef typename boost::graph_traits<TM>::vertex_descriptor vertex_descriptor;
  std::unordered_map<vertex_descriptor, std::vector<std::size_t>, boost::hash<vertex_descriptor> > sides_;
public:
  Same_side_chord(const TM& tm, const std::vector<vertex_descriptor>& nodes,
                  const std::vector<std::vector<vertex_descriptor> >& paths)
  {
    for(std::size_t p = 0; p < paths.size(); ++p)
      for(vertex_descriptor v : paths[p]) sides_[v].push_back(p);
    std::unordered_set<vertex_descriptor, boost::hash<vertex_descriptor> > node_set(nodes.begin(), nodes.end());
    typedef typename boost::graph_traits<TM>::halfedge_descriptor halfedge_descriptor;
    std::unordered_set<halfedge_descriptor, boost::hash<halfedge_descriptor> > seen;
    // border sides, numbered after the paths; on each border cycle a node closes one side and opens the next
    std::size_t side = paths.size();
    for(halfedge_descriptor b : halfedges(tm))
    {
      if(!CGAL::is_border(b, tm) || seen.count(b)) continue;
      halfedge_descriptor h0 = b; // start after a node when the cycle has one
      {
        halfedge_descriptor c = b;
        std::size_t guard = 0;
        do { if(node_set.count(target(c, tm))) { h0 = c; break; } c = next(c, tm); } while(c != b && ++guard <= num_halfedges(tm));
      }
      const std::size_t first = ++side;
      halfedge_descriptor h = next(h0, tm);
      sides_[target(h0, tm)].push_back(first);
      std::size_t guard = 0;
      do
      {
        seen.insert(h);
        sides_[target(h, tm)].push_back(side);
        if(node_set.count(target(h, tm)) && h != h0) { ++side; sides_[target(h, tm)].push_back(side); }
        h = next(h, tm);
      } while(h != next(h0, tm) && ++guard <= num_halfedges(tm));
    }
  }
  bool operator()(vertex_descriptor a, vertex_descriptor b) const
  {
    const auto ia = sides_.find(a), ib = sides_.find(b);
    if(ia == sides_.end() || ib == sides_.end()) return false;
    for(std::size_t x : ia->second)
      if(std::find(ib->second.begin(), ib->second.end(), x) != ib->second.end()) return true;
    return false;
  }
};

/// the chords of the traced network (edges that are neither path nor border edges and join two
/// vertices of paths or of the border) that `accept(a, b)` accepts, as vertex pairs
template <class TM, class EdgePredicate = Accept_every_chord>
std::vector<std::pair<typename boost::graph_traits<TM>::vertex_descriptor, typename boost::graph_traits<TM>::vertex_descriptor> >
collect_chords(const TM& tm,
               const std::vector<std::vector<typename boost::graph_traits<TM>::vertex_descriptor> >& paths,
               const EdgePredicate& accept = EdgePredicate())
{
  Path_network<TM> net(const_cast<TM&>(tm));
  for(std::size_t p = 0; p < paths.size(); ++p)
  {
    net.add_path(paths[p], static_cast<int>(p));
    if(!paths[p].empty()) { net.node_of[net.id(paths[p].front())] = 0; net.node_of[net.id(paths[p].back())] = 0; }
  }
  std::vector<std::pair<typename boost::graph_traits<TM>::vertex_descriptor, typename boost::graph_traits<TM>::vertex_descriptor> > out;
  for(auto e : edges(tm))
  {
    const auto h = halfedge(e, tm);
    if(net.is_chord(h) && accept(source(h, tm), target(h, tm))) out.emplace_back(source(h, tm), target(h, tm));
  }
  return out;
}

/// splits at their midpoints the chords `collect_chords()` returns (each is an interior edge of one
/// patch: splitting it keeps the paths and the patches, and the new vertex is an interior vertex of
/// that patch); the new vertices are appended to `steiner`. Returns the number of splits.
template <class TM, class VPM, class EdgePredicate = Accept_every_chord>
std::size_t split_chords(TM& tm, VPM vpm,
                         const std::vector<std::vector<typename boost::graph_traits<TM>::vertex_descriptor> >& paths,
                         std::vector<Steiner_vertex<TM> >& steiner, const EdgePredicate& accept = EdgePredicate())
{
  const auto chords = collect_chords(tm, paths, accept);
  // splitting one chord adds edges from the new (free) vertex only: the others stay edges
  for(const auto& c : chords) split_at_midpoint(halfedge(c.first, c.second, tm).first, tm, vpm, steiner);
  return chords.size();
}

// Marks the nodes in `net` (ERROR_WRONG_PARAMETER for a vertex not of tm or given twice), then
// check_partition(): `loops` receives the border nodes of each border cycle.
template <class TM>
Error_code mark_nodes_and_check_partition(const TM& tm, Path_network<TM>& net,
                                          const std::vector<typename boost::graph_traits<TM>::vertex_descriptor>& nodes,
                                          const std::vector<std::array<std::size_t, 2> >& edges,
                                          const std::vector<std::vector<std::size_t> >& rotation,
                                          std::vector<std::vector<std::size_t> >& loops)
{
  typedef typename boost::graph_traits<TM>::vertex_descriptor vertex_descriptor;
  std::unordered_set<vertex_descriptor, boost::hash<vertex_descriptor> > valid(vertices(tm).begin(), vertices(tm).end());
  for(std::size_t i = 0; i < nodes.size(); ++i)
  {
    if(!valid.count(nodes[i])) return ERROR_WRONG_PARAMETER;
    int& n = net.node_of[net.id(nodes[i])];
    if(n >= 0) return ERROR_WRONG_PARAMETER;
    n = static_cast<int>(i);
  }
  std::vector<std::size_t> border_nodes;
  return check_partition(tm, net, nodes, edges, rotation, border_nodes, loops);
}

// The traced edges next to position k of a node's rotation r: the previous and the next one (-1: none).
// A border node's rotation is a sequence (from the next border side to the previous one), an interior
// node's a cycle.
inline void traced_neighbours(const std::vector<std::size_t>& r, std::size_t k, bool border,
                              const std::vector<char>& traced, int& before, int& after)
{
  before = after = -1;
  if(border)
  {
    for(std::size_t j = k; j-- > 0; ) if(traced[r[j]]) { before = static_cast<int>(r[j]); break; }
    for(std::size_t j = k + 1; j < r.size(); ++j) if(traced[r[j]]) { after = static_cast<int>(r[j]); break; }
    return;
  }
  for(std::size_t j = 1; j < r.size(); ++j)
    if(traced[r[(k + r.size() - j) % r.size()]]) { before = static_cast<int>(r[(k + r.size() - j) % r.size()]); break; }
  for(std::size_t j = 1; j < r.size(); ++j)
    if(traced[r[(k + j) % r.size()]]) { after = static_cast<int>(r[(k + j) % r.size()]); break; }
}

// The order in which trace_paths() traces the partition edges: a spanning tree grown from the
// border nodes first (Prim, 3D distance between the nodes; each tree edge joins the network to an
// isolated node or border cycle, so no tree path can block a later one), then the other edges,
// longest first (with interior_first, those with an interior node before those between two border nodes).
template <class TM, class VertexPointMap>
void tracing_order(VertexPointMap vpm, const Path_network<TM>& net,
                   const std::vector<typename boost::graph_traits<TM>::vertex_descriptor>& nodes,
                   const std::vector<std::array<std::size_t, 2> >& edges,
                   const std::vector<std::vector<std::size_t> >& loops, bool interior_first,
                   std::vector<std::size_t>& order)
{
  const std::size_t N = nodes.size(), E = edges.size();
  auto node_distance = [&](std::size_t e)
  {
    return length_3(get(vpm, nodes[edges[e][0]]), get(vpm, nodes[edges[e][1]]));
  };
  order.clear();
  // the first border cycle (with its sides) is connected from the start; reaching a node of
  // another border cycle connects that whole cycle
  std::vector<char> in_tree(N, 0), used(E, 0);
  std::vector<std::size_t> loop_of(N, std::size_t(-1));
  for(std::size_t l = 0; l < loops.size(); ++l) for(std::size_t b : loops[l]) loop_of[b] = l;
  std::vector<std::vector<std::size_t> > inc(N);
  for(std::size_t e = 0; e < E; ++e) { inc[edges[e][0]].push_back(e); inc[edges[e][1]].push_back(e); }
  typedef std::pair<double, std::size_t> QE;
  std::priority_queue<QE, std::vector<QE>, std::greater<QE> > q;
  auto join = [&](std::size_t n)
  {
    const std::vector<std::size_t> one(1, n);
    for(std::size_t m : (loop_of[n] == std::size_t(-1) ? one : loops[loop_of[n]]))
    {
      in_tree[m] = 1;
      for(std::size_t f : inc[m]) if(!used[f]) q.push(QE(node_distance(f), f));
    }
  };
  if(!loops.empty() && !loops[0].empty()) join(loops[0].front());
  while(!q.empty())
  {
    const std::size_t e = q.top().second; q.pop();
    const std::size_t a = edges[e][0], b = edges[e][1];
    if(in_tree[a] && in_tree[b]) continue;
    used[e] = 1; order.push_back(e);
    join(in_tree[a] ? b : a);
  }
  std::vector<std::size_t> rest;
  for(std::size_t e = 0; e < E; ++e) if(!used[e]) rest.push_back(e);
  // longest first: measured on the test partitions, fewer splits than shortest first (the long
  // paths take the direct routes, the short ones fit between them locally)
  std::stable_sort(rest.begin(), rest.end(), [&](std::size_t x, std::size_t y) { return node_distance(x) > node_distance(y); });
  if(interior_first)
    std::stable_partition(rest.begin(), rest.end(), [&](std::size_t x)
                          { return !net.border_vertex[net.id(nodes[edges[x][0]])] || !net.border_vertex[net.id(nodes[edges[x][1]])]; });
  order.insert(order.end(), rest.begin(), rest.end());
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_PATH_NETWORK_H
