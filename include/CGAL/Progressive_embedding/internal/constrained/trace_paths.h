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
// Partitions whose interior nodes lie in another order than on the surface force winding paths that
// squeeze through corridors between earlier paths, one split per edge (the split budget turns it into
// ERROR_BUDGET_EXHAUSTED; trace_overlay.h traces such partitions without compounding). Figures:
// benchmark/results/constrained_design_measurements.md.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/constrained/path_network.h>
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
