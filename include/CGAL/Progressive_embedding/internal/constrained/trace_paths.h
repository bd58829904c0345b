// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_TRACE_PATHS_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_TRACE_PATHS_H

// Phase 2 of constrained maps: the interior edges of a partition of the target domain into
// polygons are traced on a triangulated disk (or a disk with holes: a connected genus-0 surface with
// several border cycles) as non-crossing paths of mesh edges, so that the paths cut the mesh into
// one patch per polygon. The mesh is refined by edge splits (Steiner
// vertices at edge midpoints, the surface is unchanged) only where a path is blocked.
//
// Interface (everything in CGAL::Progressive_embedding::internal unless said otherwise):
//
//   Steiner_vertex<TriangleMesh>       { v; a; b; t; join_faces; diagonals }  v = (1-t) a + t b in 3D, a
//                                       and b the endpoints of the split edge as they were at split time
//                                       (either may be an earlier Steiner vertex); t is always 0.5 here;
//                                       join_faces and diagonals as in refinement.h (here always joined,
//                                       no diagonal; trace_overlay.h uses the others).
//   Error_code trace_paths(tm, vpm, nodes, edges, rotation, paths, steiner, np)
//       tm      : triangulated topological disk, or connected genus-0 surface with several border
//                 cycles (one of them the domain's outer border, the others its holes; the tracing
//                 does not need to know which), a MutableFaceGraph, refined in place;
//       vpm     : its vertex point map (read/write: Steiner vertices get their 3D point);
//       nodes   : mesh vertex of each node (the partition's corners); a node is a border node iff its
//                 vertex is a border vertex of tm; the border nodes, in mesh border order, are the
//                 corners of the domain border (the segments between consecutive ones on a border
//                 cycle are the domain's border sides); every border cycle needs at least one node
//                 (unless there is no node at all and tm is a disk: one patch, nothing to trace);
//       edges   : the partition's interior edges, as node pairs (no loop, no duplicate);
//       rotation: per node, its incident edges (indices into edges), each exactly once, in
//                 counterclockwise order around the node in the target domain (counterclockwise =
//                 the orientation of the mesh's faces, i.e. the orientation in which a valid map
//                 puts them); for a border node, in order from the next border side (towards the
//                 next border node along the border, interior on the left) to the previous one;
//       paths   : out, paths[i] runs from nodes[edges[i][0]] to nodes[edges[i][1]];
//       steiner : out (appended), the vertices added, in order of creation;
//       np      : maximum_steiner_vertices (std::size_t, default shortest_paths_default_budget: tracer_budgets.h),
//                 CGAL::parameters::maximum_running_time (double seconds, default none),
//                 path_metric (Path_metric, default EDGE_LENGTH), split_penalty (double, in mean
//                 edge lengths, or in hops for HOP_COUNT; default 4: a path may be this much longer
//                 to avoid one split), proximity_penalty (double, same unit, default 1: each vertex
//                 of a path costs this much divided by its hop distance to the traced network, so
//                 that paths keep apart and leave free vertices for the later ones; 0 gives plain
//                 shortest paths), guide_weight (double, same unit, default 0: off; guide_map.h: each
//                 vertex of a path costs this much per local unit of guide distance to the straight
//                 segment of its partition edge, so that the paths spread as the partition's edges do;
//                 on a mesh with several border cycles the guide is not computed and this is ignored),
//                 guide_disk_factor (double, default 0: compute_guide_map()'s disk factor),
//                 interior_edges_first (bool, default false: the order of the edges outside the tree, below).
//                 A negative or non-finite value gives ERROR_WRONG_PARAMETER.
//     Preconditions checked (ERROR_* and the mesh unchanged): triangle mesh (ERROR_NON_TRIANGULAR_MESH,
//     ERROR_EMPTY_MESH); connected, no isolated vertex, at least one border cycle, Euler characteristic
//     2 - number of border cycles (ERROR_NOT_A_DISK with one border cycle or none, ERROR_NOT_GENUS_ZERO
//     with several); no pinched border vertex (ERROR_NON_MANIFOLD); nodes distinct vertices of tm;
//     edges/rotation consistent; a node on every border cycle; partition graph (with the border
//     sides) connected and its rotation system planar, i.e. a partition of the domain exists with
//     this combinatorics (ERROR_WRONG_PARAMETER). Every such input
//     is traced (a path always exists once enough edges are split), so the remaining failures are
//     ERROR_BUDGET_EXHAUSTED (split or time budget) and ERROR_PATH_TRACING_FAILED (a postcondition
//     does not hold: would be a bug). On these two the mesh HAS BEEN REFINED (a valid mesh, the
//     Steiner vertices listed in `steiner`) and `paths` holds the paths traced so far (others empty).
//     Postconditions (checked by check_traced_paths() before OK is returned): every path is simple,
//     made of mesh edges, none a border edge; its interior vertices are interior, non-node vertices
//     on no other path; at each node the paths leave in the order of `rotation` (border node: between
//     its two border edges, in that order); the faces between the paths form one patch per polygon
//     (interior edges + border sides - nodes + 1 - holes of them), each a closed disk whose border is
//     a simple cycle (label_patches()).
//   Error_code check_traced_paths(tm, nodes, edges, rotation, paths, &number_of_patches)
//   Error_code label_patches(tm, nodes, paths, face_patch_map, patches): patch index of every face,
//       and per patch its border cycle (halfedges, patch on the left) and its corner nodes.
//   collect_chords(tm, paths, accept) / split_chords(tm, vpm, paths, steiner, accept): the non-path,
//       non-border edges joining two vertices of the path network (paths and mesh border); split_chords
//       splits those `accept(a, b)` accepts. Same_side_chord accepts only the edges whose endpoints
//       lie on one partition edge's path or one border side (the chords a convex-polygon Tutte map
//       cannot keep); splitting only those is the economical choice.
//
// Algorithm (Kraevoy et al. 2003, Praun et al. 2001): the nodes of one border cycle are connected
// from the start; a spanning tree of the partition graph is grown from them (Prim, 3D distance
// between nodes; reaching a node of another border cycle connects that whole cycle) and its edges
// are traced first: each joins the network to an isolated node or cycle, and the surface minus the
// border cycles and a tree joining them is one region, so no tree path can block a later one. Then the other edges, longest
// first (by 3D distance between their nodes; with interior_edges_first, those with an interior node before
// those between two border nodes: an interior node's last edges, traced late, must wind into a sector
// already walled in by the border-to-border paths, and on space-filling-curve borders they took the most
// splits): each closes a cycle and must run in the face of the traced network that contains the
// right sector at both ends. A path is a shortest path (Dijkstra; 3D length or hop count) that starts
// in the sector of its first node between the already traced paths there (in rotation order), goes
// through free vertices only (interior, no node, on no path), and ends in the right sector of its
// last node; staying on free vertices keeps it inside one face of the network, and the sectors select
// the face. The search also walks through "virtual" midpoints of chords (edges between two blocked
// vertices, not on a path, not on the border) at a penalty: after splitting every chord of a face its
// free vertices are connected and touch every corner, so a path always exists in this augmented
// graph; the chords the best path uses are split (Euler::split_edge, then split_face on both sides),
// and the search is repeated on the refined mesh until a path of mesh edges is found. Only chords on
// the chosen path are split: splits happen only where a path is blocked. Paths that hug each other
// leave no free vertex between them and force splits all along any later path that must pass there,
// hence the proximity penalty (hop distance to the network, updated incrementally).
//
// Figures (test_trace_paths, this machine, 8 border nodes, Delaunay partitions of random Tutte
// positions): 3, 10 and 50 interior nodes on 2.3k-13k-vertex disks take 4-65 ms and add 6-285
// Steiner vertices (tracing + same-side chords), 1069 over 18 runs, where splitting every chord of
// plain hop-count shortest paths (the authors' protocol) adds 13962 (62-1540 per run). Partitions
// whose interior nodes are mirrored relative to the surface force winding paths: 3 and 10 mirrored
// nodes on an 8k-vertex disk add 84 and 397 Steiner vertices, 50 mirrored nodes about 22k (0.15 s):
// the paths squeeze through corridors between earlier paths, one split per edge (the split budget
// turns it into ERROR_BUDGET_EXHAUSTED; trace_overlay.h traces such partitions without compounding). An 8k-vertex disk with two holes (every
// hole vertex a node) and 3, 10, 50 interior nodes: 46, 121 and 193 Steiner vertices, under 45 ms.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/constrained/refinement.h>
#include <CGAL/Progressive_embedding/internal/constrained/guide_map.h>
#include <CGAL/Progressive_embedding/internal/constrained/tracer_budgets.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Real_timer.h>

#include <boost/functional/hash.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <type_traits>
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
  std::size_t cycles = 0;
  {
    std::unordered_set<halfedge_descriptor, boost::hash<halfedge_descriptor> > seen;
    for(halfedge_descriptor h : halfedges(tm))
    {
      if(!CGAL::is_border(h, tm) || seen.count(h)) continue;
      ++cycles;
      halfedge_descriptor c = h;
      std::size_t guard = 0;
      do { seen.insert(c); c = next(c, tm); } while(c != h && ++guard <= num_halfedges(tm));
    }
  }
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

// ---- tracing -------------------------------------------------------------------------------------

template <class TM, class VPM>
class Path_tracer
{
  typedef boost::graph_traits<TM> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  struct Midpoint { int a, b; std::array<double, 3> p; };

public:
  Path_tracer(TM& tm, VPM vpm, Path_network<TM>& net, Path_metric metric, double penalty)
    : tm_(tm), vpm_(vpm), net_(net), metric_(metric), penalty_(penalty)
  {
    for(std::size_t i = 0; i < net_.vd.size(); ++i) pos_.push_back(point(net_.vd[i]));
  }

  // Searches the best path from node vertex u (sector: halfedges `su`, corners `cu`) to v (sectors
  // given as vertex-id marks). Returns false when no path exists even with splits. `items` receives
  // the inner items (vertex id >= 0, or -1 - midpoint index); `splits` the number of midpoints.
  bool search(int u, const std::vector<halfedge_descriptor>& strict_u, const std::vector<halfedge_descriptor>& corners_u,
              int v, const std::vector<halfedge_descriptor>& strict_v, const std::vector<halfedge_descriptor>& corners_v,
              double penalty, std::vector<int>& items, std::size_t& splits)
  {
    const std::size_t nv = net_.vd.size();
    ++stamp_;
    if(mark_s_.size() < nv) { mark_s_.resize(nv, 0); mark_c_.resize(nv, 0); vstamp_.resize(nv, 0); dist_.resize(nv); pred_.resize(nv); }
    for(halfedge_descriptor g : strict_v) mark_s_[net_.id(target(g, tm_))] = stamp_;
    for(halfedge_descriptor g : corners_v) mark_c_[net_.id(target(g, tm_))] = stamp_;
    mids_.clear(); mid_index_.clear(); mdist_.clear(); mpred_.clear();
    typedef std::pair<double, int> QE; // item: vertex id >= 0, midpoint -1-k
    std::priority_queue<QE, std::vector<QE>, std::greater<QE> > q;
    const int START = std::numeric_limits<int>::min();
    double best = std::numeric_limits<double>::infinity();
    int best_item = START; // START with finite best: the direct edge
    auto relax = [&](int item, double d, int from)
    {
      if(item >= 0)
      {
        if(proximity_ > 0) d += proximity_ / double((std::max)(1, dnet_[static_cast<std::size_t>(item)]));
        if(guided_) d += guide_cost(guide_[static_cast<std::size_t>(item)], gscale_[static_cast<std::size_t>(item)]);
        if(vstamp_[item] == stamp_ && dist_[item] <= d) return;
        vstamp_[item] = stamp_; dist_[item] = d; pred_[item] = from;
      }
      else
      {
        const std::size_t k = static_cast<std::size_t>(-1 - item);
        if(guided_)
        {
          const Midpoint& M = mids_[k];
          const std::size_t a = static_cast<std::size_t>(M.a), b = static_cast<std::size_t>(M.b);
          d += guide_cost(Guide_point{ { 0.5 * (guide_[a][0] + guide_[b][0]), 0.5 * (guide_[a][1] + guide_[b][1]) } },
                          0.5 * (std::min)(gscale_[a], gscale_[b]));
        }
        if(mdist_[k] <= d) return;
        mdist_[k] = d; mpred_[k] = from;
      }
      q.push(QE(d, item));
    };
    // the target: strict halfedge v -> x, or a corner of v's sector
    // start items
    for(halfedge_descriptor g : strict_u)
    {
      const int y = net_.id(target(g, tm_));
      if(y == v)
      {
        if(mark_s_[u] == stamp_ && cost(u, v) < best) { best = cost(u, v); best_item = START; }
      }
      else if(!net_.blocked(y)) relax(y, cost(u, y), START);
      else if(net_.is_chord(g)) { const int m = midpoint(g); relax(m, mcost(u, m) + penalty, START); }
    }
    for(halfedge_descriptor g : corners_u)
    {
      if(CGAL::is_border(g, tm_)) continue;
      const halfedge_descriptor o = next(g, tm_); // the edge opposite u
      if(net_.is_chord(o)) { const int m = midpoint(o); relax(m, mcost(u, m) + penalty, START); }
    }
    std::size_t guard = 0;
    const std::size_t max_pops = 64 * (nv + 16) + 1000000;
    while(!q.empty() && ++guard <= max_pops)
    {
      const QE top = q.top(); q.pop();
      const double d = top.first;
      const int item = top.second;
      if(d >= best) break;
      if(item >= 0 ? (dist_[item] < d) : (mdist_[static_cast<std::size_t>(-1 - item)] < d)) continue; // stale
      if(item >= 0)
      {
        const halfedge_descriptor g0 = opposite(halfedge(net_.vd[item], tm_), tm_);
        halfedge_descriptor g = g0;
        std::size_t turn = 0;
        do
        {
          const int y = net_.id(target(g, tm_));
          if(y == v) { if(mark_s_[item] == stamp_ && d + cost(item, v) < best) { best = d + cost(item, v); best_item = item; } }
          else if(!net_.blocked(y)) relax(y, d + cost(item, y), item);
          if(!CGAL::is_border(g, tm_))
          {
            const halfedge_descriptor o = next(g, tm_);
            if(net_.is_chord(o)) { const int m = midpoint(o); relax(m, d + mcost(item, m) + penalty, item); }
          }
          g = ccw_next_outgoing(g, tm_);
        } while(g != g0 && ++turn <= num_halfedges(tm_));
      }
      else
      {
        const Midpoint M = mids_[static_cast<std::size_t>(-1 - item)];
        const halfedge_descriptor h = halfedge(net_.vd[M.a], net_.vd[M.b], tm_).first;
        if(M.a == v && mark_s_[M.b] == stamp_ && d + mcost(v, item) < best) { best = d + mcost(v, item); best_item = item; }
        if(M.b == v && mark_s_[M.a] == stamp_ && d + mcost(v, item) < best) { best = d + mcost(v, item); best_item = item; }
        for(halfedge_descriptor k : { h, opposite(h, tm_) })
        {
          if(CGAL::is_border(k, tm_)) continue; // a chord is not a border edge: defensive
          const halfedge_descriptor n1 = next(k, tm_), n2 = next(n1, tm_);
          const int c = net_.id(target(n1, tm_));
          if(c == v)
          {
            // the corner of v in this face starts with v -> source(k)
            if(mark_c_[net_.id(source(k, tm_))] == stamp_ && d + mcost(v, item) < best) { best = d + mcost(v, item); best_item = item; }
          }
          else if(!net_.blocked(c)) relax(c, d + mcost(c, item), item);
          if(net_.is_chord(n1)) { const int m = midpoint(n1); relax(m, d + mmcost(item, m) + penalty, item); }
          if(net_.is_chord(n2)) { const int m = midpoint(n2); relax(m, d + mmcost(item, m) + penalty, item); }
        }
      }
    }
    if(!(best < std::numeric_limits<double>::infinity())) return false;
    items.clear();
    splits = 0;
    for(int it = best_item; it != START; )
    {
      items.push_back(it);
      if(it < 0) ++splits;
      it = (it >= 0) ? pred_[it] : mpred_[static_cast<std::size_t>(-1 - it)];
      if(items.size() > nv + mids_.size() + 1) return false; // defensive: a cycle would be a bug
    }
    std::reverse(items.begin(), items.end());
    return true;
  }

  // splits the midpoints among `items`, turning them into vertex ids
  void realize(std::vector<int>& items, std::vector<Steiner_vertex<TM> >& steiner)
  {
    for(int& it : items)
    {
      if(it >= 0) continue;
      const Midpoint M = mids_[static_cast<std::size_t>(-1 - it)];
      const vertex_descriptor m = split_at_midpoint(halfedge(net_.vd[M.a], net_.vd[M.b], tm_).first, tm_, vpm_, steiner);
      it = net_.add_vertex(m);
      pos_.push_back(point(m));
      if(guided_)
      {
        const std::size_t a = static_cast<std::size_t>(M.a), b = static_cast<std::size_t>(M.b);
        guide_.push_back(Guide_point{ { 0.5 * (guide_[a][0] + guide_[b][0]), 0.5 * (guide_[a][1] + guide_[b][1]) } });
        gscale_.push_back(0.5 * (std::min)(gscale_[a], gscale_[b]));
      }
      if(proximity_ > 0)
      {
        // the new vertex is next to the split edge's (blocked) endpoints; its new edges may shorten distances
        dnet_.push_back(1);
        update_distances(std::vector<int>(1, it));
      }
    }
  }

  double total_cost_bound() const
  {
    double s = 0;
    for(auto e : edges(tm_)) s += cost(net_.id(source(halfedge(e, tm_), tm_)), net_.id(target(halfedge(e, tm_), tm_)));
    return 2 * s + 1;
  }
  double mean_edge_cost() const
  {
    std::size_t n = 0;
    double s = 0;
    for(auto e : edges(tm_)) { ++n; s += cost(net_.id(source(halfedge(e, tm_), tm_)), net_.id(target(halfedge(e, tm_), tm_))); }
    return n ? s / double(n) : 1.;
  }

private:
  std::array<double, 3> point(vertex_descriptor v) const
  {
    const auto p = get(vpm_, v);
    return { { CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) } };
  }
  static double length(const std::array<double, 3>& p, const std::array<double, 3>& q)
  {
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  }
  double cost(int a, int b) const { return metric_ == Path_metric::HOP_COUNT ? 1. : length(pos_[a], pos_[b]); }
  double mcost(int a, int m) const
  {
    return metric_ == Path_metric::HOP_COUNT ? 1. : length(pos_[a], mids_[static_cast<std::size_t>(-1 - m)].p);
  }
  double mmcost(int m1, int m2) const
  {
    return metric_ == Path_metric::HOP_COUNT ? 1.
           : length(mids_[static_cast<std::size_t>(-1 - m1)].p, mids_[static_cast<std::size_t>(-1 - m2)].p);
  }
public:
  // Hop distance of every vertex to the network (blocked vertices), kept up to date as paths are
  // added and edges split: a path pays proximity / distance at each vertex, so that it keeps away
  // from the network when it can and leaves room (free vertices) for the paths traced after it.
  // The network only grows, so distances only decrease: each update is a BFS from the new sources
  // that stops where nothing improves.
  void update_distances(std::vector<int> sources)
  {
    if(dnet_.size() < net_.vd.size()) dnet_.resize(net_.vd.size(), far_);
    for(int s : sources) if(net_.blocked(s)) dnet_[static_cast<std::size_t>(s)] = 0;
    std::size_t head = 0;
    while(head < sources.size())
    {
      const int x = sources[head++];
      const int dx = dnet_[static_cast<std::size_t>(x)];
      for(vertex_descriptor w : CGAL::vertices_around_target(halfedge(net_.vd[static_cast<std::size_t>(x)], tm_), tm_))
      {
        const std::size_t y = static_cast<std::size_t>(net_.id(w));
        if(dnet_[y] > dx + 1) { dnet_[y] = dx + 1; sources.push_back(static_cast<int>(y)); }
      }
    }
  }
  void init_distances()
  {
    dnet_.assign(net_.vd.size(), far_);
    std::vector<int> s;
    for(std::size_t i = 0; i < net_.vd.size(); ++i) if(net_.blocked(static_cast<int>(i))) s.push_back(static_cast<int>(i));
    update_distances(s);
  }
  // the guide (guide_map.h): positions of the vertices in the unit disk, their local scale, and the
  // segment of the edge being traced; `weight` is in units of the path cost
  void set_guide(std::vector<Guide_point> guide, std::vector<double> scale, double weight)
  {
    guide_ = std::move(guide); gscale_ = std::move(scale); gweight_ = weight;
    guided_ = gweight_ > 0 && guide_.size() == net_.vd.size();
  }
  void set_segment(const Guide_point& a, const Guide_point& b) { seg_a_ = a; seg_b_ = b; }
  bool guided() const { return guided_; }
private:
  double guide_cost(const Guide_point& p, double scale) const
  {
    // linear in the distance: measured against its square on Hilbert-curve borders, no better
    return gweight_ * guide_segment_distance(p, seg_a_, seg_b_) / scale;
  }
  int midpoint(halfedge_descriptor h)
  {
    const int a = net_.id(source(h, tm_)), b = net_.id(target(h, tm_));
    const auto it = mid_index_.find(vertex_pair_key(a, b));
    if(it != mid_index_.end()) return it->second;
    Midpoint M{ a, b, { { 0.5 * (pos_[a][0] + pos_[b][0]), 0.5 * (pos_[a][1] + pos_[b][1]), 0.5 * (pos_[a][2] + pos_[b][2]) } } };
    mids_.push_back(M);
    mdist_.push_back(std::numeric_limits<double>::infinity());
    mpred_.push_back(0);
    const int item = -static_cast<int>(mids_.size());
    mid_index_.emplace(vertex_pair_key(a, b), item);
    return item;
  }

  TM& tm_;
  VPM vpm_;
  Path_network<TM>& net_;
  Path_metric metric_;
  double penalty_;
public:
  double proximity_ = 0;
private:
  std::vector<std::array<double, 3> > pos_;
  std::vector<Guide_point> guide_;
  std::vector<double> gscale_;
  Guide_point seg_a_{ { 0., 0. } }, seg_b_{ { 0., 0. } };
  double gweight_ = 0;
  bool guided_ = false;
  std::vector<int> dnet_;
  static constexpr int far_ = (std::numeric_limits<int>::max)() / 4; // "unreached": no overflow in far_ + 1
  std::vector<unsigned> mark_s_, mark_c_, vstamp_;
  unsigned stamp_ = 0;
  std::vector<double> dist_;
  std::vector<int> pred_;
  std::vector<Midpoint> mids_;
  std::unordered_map<std::uint64_t, int> mid_index_;
  std::vector<double> mdist_;
  std::vector<int> mpred_;
};

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
    const auto p = get(vpm, nodes[edges[e][0]]), q = get(vpm, nodes[edges[e][1]]);
    typedef typename CGAL::Kernel_traits<typename std::decay<decltype(p)>::type>::Kernel K;
    return std::sqrt(CGAL::to_double(K().compute_squared_distance_3_object()(p, q)));
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

/// traces the interior edges of a partition of the target domain on `tm` as non-crossing paths; see
/// the comment at the top of this file for the parameters, pre- and postconditions and error codes.
template <class TriangleMesh, class VertexPointMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code trace_paths(TriangleMesh& tm, VertexPointMap vpm,
                       const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& nodes,
                       const std::vector<std::array<std::size_t, 2> >& edges,
                       const std::vector<std::vector<std::size_t> >& rotation,
                       std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >& paths,
                       std::vector<Steiner_vertex<TriangleMesh> >& steiner,
                       const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef TriangleMesh TM;
  typedef boost::graph_traits<TM> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  const double max_seconds = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time),
                                              std::numeric_limits<double>::infinity());
  const Path_metric metric = choose_parameter(get_parameter(np, internal_np::path_metric), Path_metric::EDGE_LENGTH);
  const double penalty_units = choose_parameter(get_parameter(np, internal_np::split_penalty), 4.);
  const double proximity_units = choose_parameter(get_parameter(np, internal_np::proximity_penalty), 1.);
  const double guide_units = choose_parameter(get_parameter(np, internal_np::guide_weight), 0.);
  const double disk_factor = choose_parameter(get_parameter(np, internal_np::guide_disk_factor), 0.);
  const bool interior_first = choose_parameter(get_parameter(np, internal_np::interior_edges_first), false);
  if(!(max_seconds >= 0) || !(penalty_units >= 0) || !std::isfinite(penalty_units) ||
     !(proximity_units >= 0) || !std::isfinite(proximity_units) ||
     !(guide_units >= 0) || !std::isfinite(guide_units) ||
     !(disk_factor >= 0) || !std::isfinite(disk_factor)) return ERROR_WRONG_PARAMETER;
  CGAL::Real_timer timer;
  timer.start();

  paths.assign(edges.size(), std::vector<vertex_descriptor>());
  Error_code status = check_triangulated_disk(tm);
  if(status != OK) return status;
  const std::size_t max_splits = choose_parameter(get_parameter(np, internal_np::maximum_steiner_vertices),
                                                  shortest_paths_default_budget.of(static_cast<std::size_t>(num_edges(tm))));
  Path_network<TM> net(tm);
  std::vector<std::vector<std::size_t> > loops;
  status = mark_nodes_and_check_partition(tm, net, nodes, edges, rotation, loops);
  if(status != OK) return status;
  const std::size_t N = nodes.size(), E = edges.size();

  // tracing order: Prim's tree from the border nodes, then the other edges
  std::vector<std::size_t> order;
  tracing_order(vpm, net, nodes, edges, loops, interior_first, order);

  Path_tracer<TM, VertexPointMap> tracer(tm, vpm, net, metric, penalty_units);
  const double unit = (metric == Path_metric::HOP_COUNT) ? 1. : tracer.mean_edge_cost();
  const double penalty = penalty_units * unit;
  tracer.proximity_ = proximity_units * unit;
  if(tracer.proximity_ > 0) tracer.init_distances();
  std::vector<Guide_point> node_guide;
  if(guide_units > 0)
  {
    std::vector<Guide_point> vg;
    std::vector<double> vs;
    auto vid = [&](vertex_descriptor v) { return static_cast<std::size_t>(net.id(v)); };
    const bool ok = compute_guide_map(tm, vpm, vid, net.vd.size(), nodes, edges, node_guide, vg, vs, disk_factor);
    if(ok) tracer.set_guide(std::move(vg), std::move(vs), guide_units * unit);
  }
  std::vector<char> traced(E, 0);
  const std::size_t first_steiner = steiner.size();

  // the sector of node i for edge e: outgoing halfedges strictly inside it and the corners (the
  // halfedge starting each triangle corner inside it)
  std::vector<halfedge_descriptor> out;
  auto sector = [&](std::size_t i, std::size_t e, std::vector<halfedge_descriptor>& strict, std::vector<halfedge_descriptor>& corners)
  {
    const vertex_descriptor u = nodes[i];
    const std::vector<std::size_t>& r = rotation[i];
    const std::size_t k = static_cast<std::size_t>(std::find(r.begin(), r.end(), e) - r.begin());
    const bool border = net.border_vertex[net.id(u)] != 0;
    auto leaving = [&](std::size_t p) // halfedge of traced path p at u
    {
      const auto& P = paths[p];
      return halfedge(u, (edges[p][0] == i) ? P[1] : P[P.size() - 2], tm).first;
    };
    outgoing_ccw(u, tm, out);
    halfedge_descriptor hp = GT::null_halfedge(), hs = GT::null_halfedge();
    if(border)
      for(halfedge_descriptor g : out)
      {
        if(CGAL::is_border(opposite(g, tm), tm)) hp = g;
        if(CGAL::is_border(g, tm)) hs = g;
      }
    int before, after;
    traced_neighbours(r, k, border, traced, before, after);
    if(before >= 0) hp = leaving(static_cast<std::size_t>(before));
    if(after >= 0) hs = leaving(static_cast<std::size_t>(after));
    strict.clear(); corners.clear();
    if(hp == GT::null_halfedge()) { strict = out; corners = out; return; }
    const std::size_t s0 = static_cast<std::size_t>(std::find(out.begin(), out.end(), hp) - out.begin());
    for(std::size_t j = 0; j < out.size(); ++j)
    {
      const halfedge_descriptor g = out[(s0 + j) % out.size()];
      if(j > 0 && g == hs) break;
      if(j > 0) strict.push_back(g);
      corners.push_back(g);
    }
  };

  std::vector<halfedge_descriptor> su, cu, sv, cv;
  std::vector<int> items;
  const double lexicographic = tracer.total_cost_bound();
  for(std::size_t e : order)
  {
    const std::size_t a = edges[e][0], b = edges[e][1];
    const int ia = net.id(nodes[a]), ib = net.id(nodes[b]);
    if(tracer.guided()) tracer.set_segment(node_guide[a], node_guide[b]);
    std::size_t rounds = 0;
    for(;;)
    {
      if(timer.time() > max_seconds) return ERROR_BUDGET_EXHAUSTED;
      sector(a, e, su, cu);
      sector(b, e, sv, cv);
      std::size_t splits = 0;
      if(!tracer.search(ia, su, cu, ib, sv, cv, penalty, items, splits)) return ERROR_PATH_TRACING_FAILED;
      const std::size_t left = max_splits - (std::min)(max_splits, steiner.size() - first_steiner);
      if(splits > left) // the fewest splits possible
      {
        if(!tracer.search(ia, su, cu, ib, sv, cv, lexicographic, items, splits)) return ERROR_PATH_TRACING_FAILED;
        if(splits > left) return ERROR_BUDGET_EXHAUSTED;
      }
      if(splits == 0) break;
      tracer.realize(items, steiner);
      // the split vertices are free now: search again on the refined mesh (each round splits one
      // edge at least, so the split budget bounds the rounds)
      if(++rounds > max_splits + 1) return ERROR_BUDGET_EXHAUSTED;
    }
    std::vector<vertex_descriptor>& P = paths[e];
    P.clear();
    P.push_back(nodes[a]);
    for(int it : items) P.push_back(net.vd[static_cast<std::size_t>(it)]);
    P.push_back(nodes[b]);
    net.add_path(P, static_cast<int>(e));
    traced[e] = 1;
    if(tracer.proximity_ > 0)
    {
      std::vector<int> inner;
      for(std::size_t k = 1; k + 1 < P.size(); ++k) inner.push_back(net.id(P[k]));
      tracer.update_distances(inner);
    }
  }
  if(check_traced_paths(tm, nodes, edges, rotation, paths) != OK) return ERROR_PATH_TRACING_FAILED;
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_TRACE_PATHS_H
