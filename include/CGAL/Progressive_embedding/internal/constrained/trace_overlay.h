// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_TRACE_OVERLAY_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_TRACE_OVERLAY_H

// Phase 2 of constrained maps for partitions that wind around the constrained vertices (targets in
// an order unrelated to the surface): the partition edges are traced as curves on the *input* mesh,
// kept as the sequence of input edges each one crosses, and the mesh is refined once at the end.
//
// trace_paths() splits the edges a path needs as it goes: a later path squeezed between two earlier
// ones must then cross every edge that their vertices span, so nested paths grow with each one traced
// before them (measured: the path lengths grow geometrically with 30 and more random targets). Here a
// curve only crosses input edges: the k-th curve through a corridor crosses the same input edges as the
// first, at the next free slot along each. The curves are still shortest (3D length between the input
// edges' midpoints), non-crossing, in the right sectors at their nodes, traced in trace_paths()'s order.
//
//   Error_code trace_paths_overlay(tm, vpm, nodes, edges, rotation, paths, steiner, np)
//       The interface, preconditions, postconditions and errors of trace_paths() (trace_paths.h), for a
//       triangulated disk, except that the patches are not labelled before OK is returned (a full pass
//       over the refined mesh, which constrained_embedding() makes anyway): the caller checks them,
//       with label_patches() or check_traced_paths(); np: maximum_steiner_vertices (default overlay_tracing_budget, tracer_budgets.h),
//       CGAL::parameters::maximum_running_time, split_penalty (the cost of one crossing, in mean edge
//       lengths, added to the curve's 3D length between edge midpoints; default 4).
//
// State: per input edge, the curves crossing it in order along the edge (gap ids that survive later
// insertions: the first gap of an edge, or the gap after a crossing); per input face, its chords
// (curve pieces: corner node to crossing, or crossing to crossing on another edge). A search state is a
// gap of an input edge (between two consecutive crossings) with the face the curve enters; a move
// inside a face adds a chord that must cross none of the face's chords (chords of a triangle with their
// ends on its boundary cross iff their ends interleave along the boundary). A curve leaves its node
// through a corner, to a gap of the edge opposite it, and arrives likewise; the angular position of
// that gap around the node decides the sector (between the node's traced curves, in rotation order).
// A curve whose nodes are joined by an input edge runs along it instead, when no curve crosses that edge yet
// and the edge's direction lies in both sectors (no crossing; later curves do not cross the edge).
//
// Refinement: every input edge crossed k times gets k points by midpoint splits (the crossing of median
// rank at the midpoint, the others recursively on either side: the Steiner vertices stay at dyadic
// positions), the faces left as polygons; each chord becomes an edge across its face; then every face
// of more than three vertices is cut by ears whose new edge does not join two points of one input edge
// (no flat triangle in 3D). Every new face lies in one input face: the surface is unchanged. The splits
// and the added edges are recorded (Steiner_vertex::join_faces false, diagonals) for the replay.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/constrained/refinement.h>
#include <CGAL/Progressive_embedding/internal/constrained/tracer_budgets.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/internal/constrained/path_network.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

template <class TM, class VPM>
class Overlay_tracer
{
  typedef boost::graph_traits<TM> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  // a chord end: a corner (the input vertex) or a crossing (its id)
  struct End { bool corner; vertex_descriptor v; int crossing; };
  struct Chord { End a, b; };
  struct Crossing { std::size_t edge; };

public:
  Overlay_tracer(TM& tm, VPM vpm)
    : tm_(tm), vpm_(vpm),
      hid_(get(CGAL::dynamic_halfedge_property_t<int>(), tm)),
      fid_(get(CGAL::dynamic_face_property_t<int>(), tm))
  {
    for(auto e : edges(tm_))
    {
      const halfedge_descriptor h = halfedge(e, tm_);
      put(hid_, h, static_cast<int>(eh_.size()));
      put(hid_, opposite(h, tm_), static_cast<int>(eh_.size()));
      eh_.push_back(h);
      ends_.push_back({ { source(h, tm_), target(h, tm_) } });
      const auto p = get(vpm_, source(h, tm_)), q = get(vpm_, target(h, tm_));
      mid_.push_back({ { 0.5 * (CGAL::to_double(p.x()) + CGAL::to_double(q.x())),
                         0.5 * (CGAL::to_double(p.y()) + CGAL::to_double(q.y())),
                         0.5 * (CGAL::to_double(p.z()) + CGAL::to_double(q.z())) } });
    }
    cross_.resize(eh_.size());
    blocked_.assign(eh_.size(), 0);
    for(face_descriptor f : faces(tm_)) { put(fid_, f, static_cast<int>(fh_.size())); fh_.push_back(halfedge(f, tm_)); }
    chords_.resize(fh_.size());
    fdata_.resize(fh_.size());
    // what the search reads per state, gathered so that it touches no mesh record
    side_.resize(2 * eh_.size());
    for(std::size_t e = 0; e < eh_.size(); ++e)
      for(std::size_t side = 0; side < 2; ++side)
      {
        const halfedge_descriptor hf = side == 0 ? eh_[e] : opposite(eh_[e], tm_);
        Side& sd = side_[2 * e + side];
        if(is_border(hf, tm_)) continue;
        sd.face = get(fid_, face(hf, tm_));
        const halfedge_descriptor h0 = fh_[static_cast<std::size_t>(sd.face)];
        sd.k = hf == h0 ? 0 : (hf == next(h0, tm_) ? 1 : 2);
        sd.apex = target(next(hf, tm_), tm_);
      }
  }

  std::size_t crossings() const { return crossing_.size(); }
  // the crossings of the curves not taken out (remove())
  std::size_t live_crossings() const { return live_; }
  // the ends of curve c as traced (from, to)
  std::pair<vertex_descriptor, vertex_descriptor> curve_ends(int c) const { return curve_ends_.at(static_cast<std::size_t>(c)); }

  // the cost of a crossing: `w` mean edge lengths (each crossing is a Steiner vertex), added to the
  // 3D length between the crossed edges' midpoints
  void set_crossing_cost(double w)
  {
    double sum = 0;
    for(std::size_t e = 0; e < eh_.size(); ++e) sum += length(point(source(eh_[e], tm_)), point(target(eh_[e], tm_)));
    step_ = w * (eh_.empty() ? 1. : sum / double(eh_.size()));
  }

  // A deadline for every later trace(): a search that runs past `max_seconds` on `timer` gives up (false,
  // and timed_out() then says why). One curve's search can take seconds on a mesh crowded with curves:
  // a check between curves alone let a budget be overrun by tens of seconds.
  void set_deadline(const CGAL::Real_timer& timer, double max_seconds) { timer_ = &timer; max_seconds_ = max_seconds; }
  bool timed_out() const { return timed_out_; }

  // One curve from node vertex u to node vertex v. Sectors: the curve must leave u strictly between
  // the curves `before_u` and `after_u` (curve indices, -1: none) counterclockwise, likewise at v;
  // `border_u` / `border_v` say whether the node is a border vertex (its sector is then bounded by
  // the border where a neighbour is missing). Returns false when no curve exists.
  bool trace(int curve, vertex_descriptor u, int before_u, int after_u,
             vertex_descriptor v, int before_v, int after_v)
  {
    // gap states: 2 * gap_id(e, i) + side, side 0 entering face(eh[e]), 1 entering the other face
    const std::size_t S = 2 * (eh_.size() + crossing_.size());
    if(label_.size() < S) label_.resize(S);
    if(++stamp_ == 0) // wrapped around: no label may look current
    {
      for(Label& l : label_) l.stamp = 0;
      stamp_ = 1;
    }
    typedef std::pair<double, std::int64_t> QE;
    std::priority_queue<QE, std::vector<QE>, std::greater<QE> > q;
    const Star su = star(u), sv = star(v);
    const Sector secu = sector(su, before_u, after_u), secv = sector(sv, before_v, after_v);
    if(trace_along_edge(curve, u, v, su, sv, secu, secv)) return true;
    const std::array<double, 3> pu = point(u), pv = point(v);
    // start: chords from the corner u to a gap of the opposite edge
    for(std::size_t j = 0; j < su.out.size(); ++j)
    {
      const halfedge_descriptor g = su.out[j];
      if(is_border(g, tm_)) continue;
      const halfedge_descriptor o = next(g, tm_); // the edge opposite u, from the vertex after u
      const std::size_t e = static_cast<std::size_t>(get(hid_, o));
      if(is_border(opposite(o, tm_), tm_) || blocked_[e]) continue; // a curve crosses neither the border nor an edge curve
      const Face_data& fd = face_data(static_cast<std::size_t>(get(fid_, face(g, tm_))));
      const std::size_t ku = fd.index(g), ko = fd.index(o);
      const std::int64_t cu = 2 * fd.off[ku];
      const std::size_t n = cross_[e].size();
      for(std::size_t i = 0; i <= n; ++i) // gap i along o
      {
        if(!secu.contains(j, 2 * static_cast<std::int64_t>(i))) continue;
        const std::int64_t gp = fd.gap_position(ko, i);
        if(crosses_any(fd.chords, cu, gp, fd.size)) continue;
        const std::size_t gi = (o == eh_[e]) ? i : n - i;
        const std::size_t state = 2 * gap_id(e, gi) + ((o == eh_[e]) ? 1 : 0); // enters the face beyond o
        relax(q, state, step_ + length(pu, mid_[e]), -2);
      }
    }
    double best = std::numeric_limits<double>::infinity();
    std::int64_t best_state = -1;
    std::size_t guard = 0;
    while(!q.empty() && ++guard <= 64 * S + 1000000)
    {
      // the clock every 4096 states (a state costs well under a microsecond: the check is free)
      if(timer_ != nullptr && guard % 4096 == 0 && timer_->time() > max_seconds_) { timed_out_ = true; return false; }
      const QE top = q.top(); q.pop();
      const double d = top.first;
      if(d >= best) break;
      const std::size_t s = static_cast<std::size_t>(top.second);
      if(d > label_[s].dist) continue; // stale (queued in this search: its label is current)
      const std::size_t side = s % 2;
      std::size_t e, i;
      decode_gap(s / 2, e, i);
      const Side& sd = side_[2 * e + side]; // e, seen from the face entered
      if(sd.face < 0) continue;
      const std::size_t n = cross_[e].size();
      const std::size_t ih = side == 0 ? i : n - i; // the gap's index along hf
      const Face_data& fd = face_data(static_cast<std::size_t>(sd.face));
      const std::size_t kf = sd.k;
      const std::int64_t gp = fd.gap_position(kf, ih);
      // arrival at v, the corner opposite e
      if(sd.apex == v)
      {
        const halfedge_descriptor hf = side == 0 ? eh_[e] : opposite(eh_[e], tm_);
        const halfedge_descriptor hv = next(hf, tm_); // from target(hf) to the opposite corner
        // v -> source(hf) leaves v in f, whose edge opposite v is hf: the gap's position along hf
        // is its angular position around v
        const std::size_t j = sv.index_of(next(hv, tm_));
        if(j != std::size_t(-1) && secv.contains(j, 2 * static_cast<std::int64_t>(ih)) &&
           !crosses_any(fd.chords, gp, 2 * fd.off[fd.index(next(hv, tm_))], fd.size))
        {
          const double total = d + length(mid_[e], pv);
          if(total < best) { best = total; best_state = static_cast<std::int64_t>(s); }
        }
      }
      // the gaps of the two other edges of f in the same piece of f (no chord between them)
      const std::size_t lf = static_cast<std::size_t>(fd.label[kf][ih]);
      for(int mi = fd.member_start[lf]; mi < fd.member_start[lf + 1]; ++mi)
      {
        const Member& m = fd.members[static_cast<std::size_t>(mi)];
        if(m.k == kf || m.state == no_state) continue; // the gap's own edge, or the border
        relax(q, m.state, d + step_ + fd.length[kf][m.k], static_cast<std::int64_t>(s));
      }
    }
    if(best_state < 0) return false;
    // the states, from u to v
    std::vector<std::size_t> states;
    for(std::int64_t s = best_state; s >= 0; s = label_[static_cast<std::size_t>(s)].pred)
    {
      states.push_back(static_cast<std::size_t>(s));
      if(states.size() > S) return false; // defensive: a cycle would be a bug
    }
    std::reverse(states.begin(), states.end());
    commit(curve, u, v, states);
    return true;
  }

  // Takes curve `curve` out: its crossings and chords, its places at its two nodes. Later curves may
  // use the gaps it leaves (the kinetic tracing replaces flipped partition edges this way).
  void remove(int curve)
  {
    if(curve < 0 || static_cast<std::size_t>(curve) >= curve_crossings_.size()) return;
    std::vector<int>& xs = curve_crossings_[static_cast<std::size_t>(curve)];
    int& along = curve_edge_[static_cast<std::size_t>(curve)];
    if(along >= 0) { set_blocked(static_cast<std::size_t>(along), false); along = -1; } // a curve along an input edge
    else if(xs.empty()) return; // not traced, or taken out already
    else remove_crossings(xs);
    const auto& ends = curve_ends_[static_cast<std::size_t>(curve)];
    node_curves_.erase(std::make_pair(ends.first, curve));
    node_curves_.erase(std::make_pair(ends.second, curve));
  }
  // remove()'s part for a curve that crosses edges: its crossings and chords
  void remove_crossings(std::vector<int>& xs)
  {
    removed_.resize(crossing_.size(), 0);
    for(int x : xs) removed_[static_cast<std::size_t>(x)] = 1;
    auto gone = [&](const End& e) { return !e.corner && removed_[static_cast<std::size_t>(e.crossing)]; };
    std::vector<std::size_t> touched;
    for(int x : xs) touched.push_back(crossing_[static_cast<std::size_t>(x)].edge);
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    for(std::size_t e : touched)
    {
      for(halfedge_descriptor h : { eh_[e], opposite(eh_[e], tm_) })
      {
        if(is_border(h, tm_)) continue;
        const std::size_t f = static_cast<std::size_t>(get(fid_, face(h, tm_)));
        std::vector<Chord>& ch = chords_[f];
        ch.erase(std::remove_if(ch.begin(), ch.end(), [&](const Chord& c) { return gone(c.a) || gone(c.b); }), ch.end());
        fdata_[f].valid = false;
      }
      std::vector<int>& cr = cross_[e];
      cr.erase(std::remove_if(cr.begin(), cr.end(), [&](int x) { return removed_[static_cast<std::size_t>(x)] != 0; }), cr.end());
      for(std::size_t k = 0; k < cr.size(); ++k) cpos_[static_cast<std::size_t>(cr[k])] = static_cast<int>(k);
    }
    live_ -= xs.size();
    xs.clear();
  }

  // Refines tm: the crossings become vertices (midpoint splits), the chords edges, the faces
  // triangles. `paths[c]` receives curve c's vertices (node, crossings, node). Returns false when a
  // face cannot be cut into non-flat triangles (would be a bug).
  bool realize(const std::vector<std::pair<vertex_descriptor, vertex_descriptor> >& ends,
               std::vector<std::vector<vertex_descriptor> >& paths, std::vector<Steiner_vertex<TM> >& steiner)
  {
    std::vector<vertex_descriptor> cv(crossing_.size());
    // per crossing, the halfedge ending at its vertex along eh_[e] (in face(eh_[e])) and against it
    std::vector<halfedge_descriptor> in_along(crossing_.size()), in_against(crossing_.size());
    // input edge of every vertex added (-1: an input vertex)
    auto on_edge = get(CGAL::dynamic_vertex_property_t<int>(), tm_);
    for(vertex_descriptor w : vertices(tm_)) put(on_edge, w, -1);
    const std::size_t first = steiner.size();
    for(std::size_t e = 0; e < eh_.size(); ++e)
    {
      const std::vector<int>& xs = cross_[e];
      if(xs.empty()) continue;
      split_range(ends_[e][0], ends_[e][1], e, 0, xs.size(), cv, on_edge, steiner);
      vertex_descriptor p = ends_[e][0];
      for(std::size_t k = 0; k < xs.size(); ++k)
      {
        const vertex_descriptor x = cv[static_cast<std::size_t>(xs[k])];
        in_along[static_cast<std::size_t>(xs[k])] = halfedge(p, x, tm_).first;
        p = x;
      }
      p = ends_[e][1];
      for(std::size_t k = xs.size(); k-- > 0; )
      {
        const vertex_descriptor x = cv[static_cast<std::size_t>(xs[k])];
        in_against[static_cast<std::size_t>(xs[k])] = halfedge(p, x, tm_).first;
        p = x;
      }
    }
    if(steiner.size() == first) // every curve along an input edge (or none): nothing to refine
    {
      paths.assign(ends.size(), std::vector<vertex_descriptor>());
      for(std::size_t c = 0; c < ends.size(); ++c)
      {
        if(curve_crossings_.size() <= c || !curve_crossings_[c].empty()) return false;
        paths[c] = { ends[c].first, ends[c].second };
      }
      return true;
    }
    // Each chord becomes an edge across its face. Between two crossings, the halfedges ending at them
    // in that face are known: no walk around the face (as long as its crossings) to find them. From a
    // corner, which may have several chords in one face, the edge is found by a walk (connect_in_face()).
    std::vector<std::pair<vertex_descriptor, vertex_descriptor> > diagonals;
    for(std::size_t f = 0; f < chords_.size(); ++f)
      for(const Chord& c : chords_[f])
      {
        const vertex_descriptor a = c.a.corner ? c.a.v : cv[static_cast<std::size_t>(c.a.crossing)];
        const vertex_descriptor b = c.b.corner ? c.b.v : cv[static_cast<std::size_t>(c.b.crossing)];
        if(c.a.corner || c.b.corner)
        {
          if(!connect_in_face(a, b, tm_)) return false;
        }
        else
        {
          auto in_face = [&](int x)
          {
            const std::size_t e = crossing_[static_cast<std::size_t>(x)].edge;
            return side_[2 * e].face == static_cast<int>(f) ? in_along[static_cast<std::size_t>(x)]
                                                            : in_against[static_cast<std::size_t>(x)];
          };
          // as connect_in_face(a, b) would (the same refined mesh)
          const halfedge_descriptor h1 = in_face(c.a.crossing), h2 = in_face(c.b.crossing);
          if(face(h1, tm_) != face(h2, tm_) || next(h1, tm_) == h2 || next(h2, tm_) == h1) return false;
          CGAL::Euler::split_face(h1, h2, tm_);
        }
        diagonals.emplace_back(a, b);
      }
    // faces of more than three vertices: ears whose new edge does not lie along one input edge
    auto common_input_edge = [&](vertex_descriptor a, vertex_descriptor b) -> bool
    {
      const int ea = get(on_edge, a), eb = get(on_edge, b);
      if(ea >= 0 && eb >= 0) return ea == eb;
      if(ea < 0 && eb < 0) return true; // two corners of one input face: joined by an input edge
      const int ep = ea >= 0 ? ea : eb;
      const vertex_descriptor c = ea >= 0 ? b : a;
      return ends_[static_cast<std::size_t>(ep)][0] == c || ends_[static_cast<std::size_t>(ep)][1] == c;
    };
    std::vector<face_descriptor> work(faces(tm_).begin(), faces(tm_).end());
    std::size_t guard = 0;
    while(!work.empty())
    {
      if(++guard > 8 * num_faces(tm_) + 1000) return false;
      const face_descriptor f = work.back(); work.pop_back();
      std::vector<halfedge_descriptor> hs;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm_), tm_)) hs.push_back(h);
      if(hs.size() <= 3) continue;
      const std::size_t k = hs.size();
      bool cut = false;
      for(std::size_t i = 0; i < k && !cut; ++i)
      {
        // the ear at target(hs[i]): from target(hs[i-1]) to target(hs[i+1])
        const halfedge_descriptor h1 = hs[(i + k - 1) % k], h2 = hs[(i + 1) % k];
        const vertex_descriptor a = target(h1, tm_), b = target(h2, tm_);
        if(common_input_edge(a, b)) continue;
        const halfedge_descriptor hn = CGAL::Euler::split_face(h1, h2, tm_);
        diagonals.emplace_back(a, b);
        work.push_back(face(hn, tm_));
        work.push_back(face(opposite(hn, tm_), tm_));
        cut = true;
      }
      if(!cut) return false;
    }
    steiner.back().diagonals = std::move(diagonals);
    paths.assign(ends.size(), std::vector<vertex_descriptor>());
    for(std::size_t c = 0; c < ends.size(); ++c)
    {
      if(curve_crossings_.size() <= c) return false;
      paths[c].push_back(ends[c].first);
      for(int x : curve_crossings_[c]) paths[c].push_back(cv[static_cast<std::size_t>(x)]);
      paths[c].push_back(ends[c].second);
    }
    return true;
  }

private:
  // the outgoing halfedges of a node vertex in counterclockwise order (a border vertex: from the one
  // after the border), and the index of each
  struct Star
  {
    std::vector<halfedge_descriptor> out;
    std::size_t index_of(halfedge_descriptor g) const
    {
      const auto it = std::find(out.begin(), out.end(), g);
      return it == out.end() ? std::size_t(-1) : static_cast<std::size_t>(it - out.begin());
    }
  };
  Star star(vertex_descriptor u) const
  {
    Star s;
    outgoing_ccw(u, tm_, s.out);
    // a border vertex: from the border edge towards the next border vertex (interior on its left)
    for(std::size_t k = 0; k < s.out.size(); ++k)
      if(!is_border(s.out[k], tm_) && is_border(opposite(s.out[k], tm_), tm_))
      {
        std::rotate(s.out.begin(), s.out.begin() + static_cast<std::ptrdiff_t>(k), s.out.end());
        break;
      }
    return s;
  }
  // angular keys around a node: (index of the face's outgoing halfedge, doubled position along the
  // opposite edge from the vertex after the node); the sector is the open interval between two keys
  struct Sector
  {
    bool all = true, border = false;
    std::int64_t lo = 0, hi = 0, M = 0; // keys j * W + p
    static constexpr std::int64_t W = std::int64_t(1) << 32;
    bool contains(std::size_t j, std::int64_t p) const { return contains_key(static_cast<std::int64_t>(j) * W + p); }
    bool contains_key(std::int64_t k) const
    {
      if(border) return k > lo && k < hi;
      if(all) return true;
      const std::int64_t x = ((k - lo) % M + M) % M, y = ((hi - lo) % M + M) % M;
      return x != 0 && (y == 0 ? true : x < y);
    }
  };
  Sector sector(const Star& s, int before, int after) const
  {
    Sector sec;
    sec.M = static_cast<std::int64_t>(s.out.size()) * Sector::W;
    const vertex_descriptor u = s.out.empty() ? GT::null_vertex() : source(s.out.front(), tm_);
    const bool bv = u != GT::null_vertex() && CGAL::is_border(u, tm_) != boost::none;
    auto key = [&](int c) -> std::int64_t
    {
      const auto& n = node_curves_.at(std::make_pair(u, c)); // (outgoing halfedge, crossing)
      const std::size_t j = s.index_of(n.first);
      if(n.second < 0) return edge_key(j); // a curve along the input edge n.first
      const halfedge_descriptor o = next(n.first, tm_);
      return static_cast<std::int64_t>(j) * Sector::W + 2 * (position_along(o, n.second) + 1) - 1;
    };
    if(bv)
    {
      sec.border = true;
      sec.lo = before >= 0 ? key(before) : -1;
      sec.hi = after >= 0 ? key(after) : sec.M;
      return sec;
    }
    if(before < 0 && after < 0) return sec;
    sec.all = false;
    sec.lo = key(before >= 0 ? before : after);
    sec.hi = key(after >= 0 ? after : before);
    return sec;
  }

  // The angular key of the direction of out[j] around a node: after every gap of the face before it, before
  // every gap of face(out[j]) (gap i of face j has key j * W + 2i).
  static std::int64_t edge_key(std::size_t j) { return static_cast<std::int64_t>(j) * Sector::W - 1; }
  // the cached pieces of the faces on either side of input edge e are stale
  void invalidate_faces(std::size_t e)
  {
    for(halfedge_descriptor h : { eh_[e], opposite(eh_[e], tm_) })
      if(!is_border(h, tm_)) fdata_[static_cast<std::size_t>(get(fid_, face(h, tm_)))].valid = false;
  }
  void set_blocked(std::size_t e, bool b) { blocked_[e] = b ? 1 : 0; invalidate_faces(e); }
  // the records of curve `curve` from u to v (along input edge `edge`, or -1), its crossings cleared
  void record_curve(int curve, vertex_descriptor u, vertex_descriptor v, int edge)
  {
    const std::size_t c = static_cast<std::size_t>(curve);
    if(curve_crossings_.size() <= c)
    {
      curve_crossings_.resize(c + 1);
      curve_ends_.resize(c + 1);
      curve_edge_.resize(c + 1, -1);
    }
    curve_ends_[c] = std::make_pair(u, v);
    curve_crossings_[c].clear();
    curve_edge_[c] = edge;
  }
  // A curve between two nodes joined by an interior input edge runs along that edge when no curve crosses
  // it and its direction lies in the curve's sectors at both ends: no crossing at all (the crossing
  // curves, which must leave a node towards the edge opposite it, find no room along such an edge: near
  // a border where every border vertex is a node, a chord between two of them had no curve). Later curves
  // do not cross it.
  bool trace_along_edge(int curve, vertex_descriptor u, vertex_descriptor v, const Star& su, const Star& sv,
                        const Sector& secu, const Sector& secv)
  {
    const auto hv = halfedge(u, v, tm_);
    if(!hv.second) return false;
    const halfedge_descriptor g = hv.first;
    if(is_border(g, tm_) || is_border(opposite(g, tm_), tm_)) return false;
    const std::size_t e = static_cast<std::size_t>(get(hid_, g));
    if(blocked_[e] || !cross_[e].empty()) return false;
    const std::size_t ju = su.index_of(g), jv = sv.index_of(opposite(g, tm_));
    if(ju == std::size_t(-1) || jv == std::size_t(-1)) return false;
    if(!secu.contains_key(edge_key(ju)) || !secv.contains_key(edge_key(jv))) return false;
    record_curve(curve, u, v, static_cast<int>(e));
    node_curves_[std::make_pair(u, curve)] = std::make_pair(g, -1);
    node_curves_[std::make_pair(v, curve)] = std::make_pair(opposite(g, tm_), -1);
    set_blocked(e, true);
    return true;
  }

  // Boundary positions in a face are doubled: point k at 2k, the gap after it at 2k+1. Points: corner
  // source(h0), crossings along h0, corner source(h1), ... with h0 = fh_[f] (Face_data::off).

  // Gaps have ids that stay valid while crossings are inserted: the first gap of input edge e (from
  // source(eh_[e])) is e, the gap after crossing x is E + x (E input edges).
  std::size_t gap_id(std::size_t e, std::size_t i) const
  {
    return i == 0 ? e : eh_.size() + static_cast<std::size_t>(cross_[e][i - 1]);
  }
  // the input edge of a gap and its index along eh_[e]
  void decode_gap(std::size_t g, std::size_t& e, std::size_t& i) const
  {
    if(g < eh_.size()) { e = g; i = 0; return; }
    const std::size_t x = g - eh_.size();
    e = crossing_[x].edge;
    i = static_cast<std::size_t>(cpos_[x]) + 1;
  }
  // index of crossing x along hk (from source(hk))
  std::int64_t position_along(halfedge_descriptor hk, int x) const
  {
    const std::size_t e = static_cast<std::size_t>(get(hid_, hk));
    const std::size_t k = static_cast<std::size_t>(cpos_[static_cast<std::size_t>(x)]);
    return (hk == eh_[e]) ? static_cast<std::int64_t>(k) : static_cast<std::int64_t>(cross_[e].size() - 1 - k);
  }
  // A face's chords as boundary positions, and its pieces: the label of every gap of its three edges
  // (gaps of one piece have one label) and the gaps of each label. The chords are a non-crossing
  // matching of the boundary once a corner with several chords is split into one point per chord
  // (ordered so that they do not cross); along the boundary, each chord's first end opens a piece and
  // its second closes it, like parentheses. Cached until a curve crosses one of the face's edges.
  static constexpr std::size_t no_state = std::size_t(-1);
  // a gap of a face's edge h[k]: k and the search state entering the face beyond it (no_state: beyond
  // is the border)
  struct Member { std::size_t k, state; };
  struct Face_data
  {
    bool valid = false;
    std::array<halfedge_descriptor, 3> h;
    std::array<std::size_t, 3> e;                       // the input edge of h[k]
    std::array<std::int64_t, 3> off;                    // undoubled position of the corner source(h[k])
    std::vector<std::array<std::int64_t, 2> > chords;
    std::int64_t size = 0;
    std::array<std::vector<int>, 3> label;             // per edge (in h's order), per gap along it
    std::vector<Member> members;                        // by label
    std::vector<int> member_start;                      // per label: its first entry in members
    std::array<std::array<double, 3>, 3> length;        // between the midpoints of the input edges h[k], h[m]
    std::size_t index(halfedge_descriptor g) const { return g == h[0] ? 0 : (g == h[1] ? 1 : 2); }
    // gap i along h[k] (between its i-th and (i+1)-th crossing from source(h[k]))
    std::int64_t gap_position(std::size_t k, std::size_t i) const { return 2 * (off[k] + static_cast<std::int64_t>(i)) + 1; }
  };
  std::int64_t end_position(const Face_data& fd, const End& x) const
  {
    if(x.corner)
    {
      for(std::size_t k = 0; k < 3; ++k) if(source(fd.h[k], tm_) == x.v) return 2 * fd.off[k];
      return -1;
    }
    const std::size_t e = crossing_[static_cast<std::size_t>(x.crossing)].edge;
    const std::size_t k = fd.e[0] == e ? 0 : (fd.e[1] == e ? 1 : 2);
    return 2 * (fd.off[k] + 1 + position_along(fd.h[k], x.crossing));
  }
  const Face_data& face_data(std::size_t fi)
  {
    Face_data& fd = fdata_[fi];
    if(fd.valid) return fd;
    fd.valid = true; // the vectors are refilled in place: their storage is kept
    fd.h[0] = fh_[fi]; fd.h[1] = next(fd.h[0], tm_); fd.h[2] = next(fd.h[1], tm_);
    for(std::size_t k = 0; k < 3; ++k) fd.e[k] = static_cast<std::size_t>(get(hid_, fd.h[k]));
    for(std::size_t k = 0; k < 3; ++k)
      for(std::size_t m = 0; m < 3; ++m) fd.length[k][m] = length(mid_[fd.e[k]], mid_[fd.e[m]]);
    std::int64_t p = 0;
    std::array<std::int64_t, 3>& off = fd.off;
    for(int k = 0; k < 3; ++k)
    {
      off[static_cast<std::size_t>(k)] = p;
      p += 1 + static_cast<std::int64_t>(cross_[fd.e[static_cast<std::size_t>(k)]].size());
    }
    fd.size = 2 * p;
    fd.chords.clear();
    for(const Chord& c : chords_[fi]) fd.chords.push_back({ { end_position(fd, c.a), end_position(fd, c.b) } });
    // chord ends by position: a crossing has one, a corner any number, split into sub-points in the
    // order of decreasing distance to their partners (so that they do not cross). Positions are
    // visited in order: linear in the face's crossings, no sort but the corners'.
    std::vector<int>& at = at_scratch_;
    at.assign(static_cast<std::size_t>(fd.size), -1);
    for(auto& cc : corner_scratch_) cc.clear();
    for(std::size_t c = 0; c < fd.chords.size(); ++c)
      for(std::size_t t = 0; t < 2; ++t)
      {
        const std::int64_t a = fd.chords[c][t], b = fd.chords[c][1 - t];
        const std::size_t k = (a == 2 * off[0]) ? 0 : (a == 2 * off[1]) ? 1 : (a == 2 * off[2]) ? 2 : 3;
        if(k < 3) corner_scratch_[k].push_back(std::make_pair(((b - a) % fd.size + fd.size) % fd.size, static_cast<int>(c)));
        else at[static_cast<std::size_t>(a)] = static_cast<int>(c);
      }
    std::vector<char>& opened = opened_scratch_;
    opened.assign(fd.chords.size(), 0);
    std::vector<int>& stack = stack_scratch_;
    stack.clear();
    int labels = 1;
    auto chord_end = [&](int c)
    {
      if(!opened[static_cast<std::size_t>(c)]) { opened[static_cast<std::size_t>(c)] = 1; stack.push_back(labels++); }
      else if(!stack.empty()) stack.pop_back();
    };
    std::vector<std::array<int, 3> >& gaps = gaps_scratch_; // (label, edge, gap), in boundary order
    gaps.clear();
    for(std::size_t k = 0; k < 3; ++k)
    {
      std::sort(corner_scratch_[k].begin(), corner_scratch_[k].end(),
                [](const std::pair<std::int64_t, int>& x, const std::pair<std::int64_t, int>& y) { return x.first > y.first; });
      for(const auto& x : corner_scratch_[k]) chord_end(x.second);
      const std::size_t m = cross_[fd.e[k]].size();
      fd.label[k].resize(m + 1);
      for(std::size_t i = 0; i <= m; ++i)
      {
        if(i > 0) // the i-th crossing along h[k]
        {
          const int c = at[static_cast<std::size_t>(2 * (off[k] + static_cast<std::int64_t>(i)))];
          if(c >= 0) chord_end(c);
        }
        const int l = stack.empty() ? 0 : stack.back();
        fd.label[k][i] = l;
        gaps.push_back(std::array<int, 3>{ { l, static_cast<int>(k), static_cast<int>(i) } });
      }
    }
    // the gaps of each label, contiguous (counting sort, stable)
    fd.member_start.assign(static_cast<std::size_t>(labels) + 1, 0);
    for(const auto& g : gaps) ++fd.member_start[static_cast<std::size_t>(g[0]) + 1];
    for(std::size_t l = 0; l < static_cast<std::size_t>(labels); ++l) fd.member_start[l + 1] += fd.member_start[l];
    fd.members.resize(gaps.size());
    std::vector<int>& fill = stack; // reused: the stack is empty once every chord is closed
    fill.assign(fd.member_start.begin(), fd.member_start.end() - 1);
    for(const auto& g : gaps)
    {
      const std::size_t k = static_cast<std::size_t>(g[1]), j = static_cast<std::size_t>(g[2]);
      const halfedge_descriptor hk = fd.h[k];
      std::size_t state = no_state;
      if(!is_border(opposite(hk, tm_), tm_) && !blocked_[fd.e[k]])
      {
        const std::size_t ek = fd.e[k];
        const bool along = hk == eh_[ek];
        state = 2 * gap_id(ek, along ? j : cross_[ek].size() - j) + (along ? 1 : 0);
      }
      fd.members[static_cast<std::size_t>(fill[static_cast<std::size_t>(g[0])]++)] = Member{ k, state };
    }
    return fd;
  }
  // whether the chord (a, b) crosses one of `ch` (positions on a cycle of length n): their ends
  // interleave; chords sharing an end do not cross
  static bool crosses_any(const std::vector<std::array<std::int64_t, 2> >& ch, std::int64_t a, std::int64_t b, std::int64_t n)
  {
    auto inside = [&](std::int64_t x) { const std::int64_t d = ((x - a) % n + n) % n, w = ((b - a) % n + n) % n; return d > 0 && d < w; };
    for(const auto& c : ch)
    {
      if(c[0] == a || c[0] == b || c[1] == a || c[1] == b) continue;
      if(inside(c[0]) != inside(c[1])) return true;
    }
    return false;
  }
  void relax(std::priority_queue<std::pair<double, std::int64_t>, std::vector<std::pair<double, std::int64_t> >,
                                 std::greater<std::pair<double, std::int64_t> > >& q,
             std::size_t s, double d, std::int64_t from)
  {
    Label& l = label_[s];
    if(l.stamp == stamp_ && !(d < l.dist)) return;
    l.dist = d; l.pred = from; l.stamp = stamp_;
    q.push(std::make_pair(d, static_cast<std::int64_t>(s)));
  }
  void commit(int curve, vertex_descriptor u, vertex_descriptor v, const std::vector<std::size_t>& states)
  {
    // decode the states: edge, gap index along eh, side
    struct G { std::size_t e, i, side; int id; };
    std::vector<G> gs;
    for(std::size_t s : states)
    {
      std::size_t e, i;
      decode_gap(s / 2, e, i);
      gs.push_back(G{ e, i, s % 2, -1 });
    }
    for(G& g : gs) { g.id = static_cast<int>(crossing_.size()); crossing_.push_back(Crossing{ g.e }); }
    // insert the crossings, each edge's in one merge: a curve may cross one edge thousands of times and an
    // edge hold thousands of crossings, where an insertion and a renumbering per crossing cost their product
    std::vector<std::size_t> order(gs.size());
    for(std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y)
              { return gs[x].e != gs[y].e ? gs[x].e < gs[y].e : gs[x].i < gs[y].i; });
    cpos_.resize(crossing_.size());
    std::vector<int>& merged = merge_scratch_;
    for(std::size_t a = 0; a < order.size(); )
    {
      const std::size_t e = gs[order[a]].e;
      std::size_t b = a;
      while(b < order.size() && gs[order[b]].e == e) ++b;
      // gap i of the old list: before its i-th crossing (a shortest curve passes a gap once)
      std::vector<int>& cr = cross_[e];
      merged.clear();
      merged.reserve(cr.size() + (b - a));
      std::size_t k = a;
      for(std::size_t j = 0; j <= cr.size(); ++j)
      {
        for(; k < b && gs[order[k]].i == j; ++k) merged.push_back(gs[order[k]].id);
        if(j < cr.size()) merged.push_back(cr[j]);
      }
      cr.swap(merged);
      for(std::size_t m = 0; m < cr.size(); ++m) cpos_[static_cast<std::size_t>(cr[m])] = static_cast<int>(m);
      invalidate_faces(e);
      a = b;
    }
    // chords: u to the first crossing (in the face before it), between consecutive crossings (in the
    // face the first enters), the last to v (in the face it enters)
    auto face_before = [&](const G& g) { const halfedge_descriptor h = g.side == 0 ? opposite(eh_[g.e], tm_) : eh_[g.e]; return face(h, tm_); };
    auto face_after = [&](const G& g) { const halfedge_descriptor h = g.side == 0 ? eh_[g.e] : opposite(eh_[g.e], tm_); return face(h, tm_); };
    auto add = [&](face_descriptor f, End a, End b) { chords_[static_cast<std::size_t>(get(fid_, f))].push_back(Chord{ a, b }); };
    const End eu{ true, u, -1 }, ev{ true, v, -1 };
    add(face_before(gs.front()), eu, End{ false, GT::null_vertex(), gs.front().id });
    for(std::size_t k = 0; k + 1 < gs.size(); ++k)
      add(face_after(gs[k]), End{ false, GT::null_vertex(), gs[k].id }, End{ false, GT::null_vertex(), gs[k + 1].id });
    add(face_after(gs.back()), End{ false, GT::null_vertex(), gs.back().id }, ev);
    // the curve at its nodes: the outgoing halfedge of the face it leaves (or enters) through
    {
      const face_descriptor f0 = face_before(gs.front());
      halfedge_descriptor g = GT::null_halfedge();
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f0, tm_), tm_)) if(source(h, tm_) == u) g = h;
      node_curves_[std::make_pair(u, curve)] = std::make_pair(g, gs.front().id);
      const face_descriptor f1 = face_after(gs.back());
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f1, tm_), tm_)) if(source(h, tm_) == v) g = h;
      node_curves_[std::make_pair(v, curve)] = std::make_pair(g, gs.back().id);
    }
    record_curve(curve, u, v, -1);
    for(const G& g : gs) curve_crossings_[static_cast<std::size_t>(curve)].push_back(g.id);
    live_ += gs.size();
  }
  // splits the edge (a, b), a piece of input edge e, at its midpoint for the crossing of median rank
  // among cross_[e][lo, hi), then the two halves for the others
  template <class OnEdge>
  void split_range(vertex_descriptor a, vertex_descriptor b, std::size_t e, std::size_t lo, std::size_t hi,
                   std::vector<vertex_descriptor>& cv, OnEdge& on_edge, std::vector<Steiner_vertex<TM> >& steiner)
  {
    if(lo >= hi) return;
    const std::size_t m = lo + (hi - lo) / 2;
    const auto pa = get(vpm_, a), pb = get(vpm_, b);
    typedef typename CGAL::Kernel_traits<typename std::decay<decltype(pa)>::type>::Kernel K;
    const halfedge_descriptor hn = CGAL::Euler::split_edge(halfedge(a, b, tm_).first, tm_);
    const vertex_descriptor x = target(hn, tm_);
    put(vpm_, x, K().construct_midpoint_3_object()(pa, pb));
    put(on_edge, x, static_cast<int>(e));
    Steiner_vertex<TM> sv{ x, a, b, 0.5 };
    sv.join_faces = false;
    steiner.push_back(std::move(sv));
    cv[static_cast<std::size_t>(cross_[e][m])] = x;
    split_range(a, x, e, lo, m, cv, on_edge, steiner);
    split_range(x, b, e, m + 1, hi, cv, on_edge, steiner);
  }
  std::array<double, 3> point(vertex_descriptor v) const
  {
    const auto p = get(vpm_, v);
    return { { CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) } };
  }
  static double length(const std::array<double, 3>& p, const std::array<double, 3>& q)
  {
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  }

  TM& tm_;
  VPM vpm_;
  typename boost::property_map<TM, CGAL::dynamic_halfedge_property_t<int> >::type hid_;
  typename boost::property_map<TM, CGAL::dynamic_face_property_t<int> >::type fid_;
  std::vector<halfedge_descriptor> eh_, fh_;
  std::vector<std::array<vertex_descriptor, 2> > ends_; // per input edge: source and target of eh_ (realize() splits eh_)
  std::vector<std::array<double, 3> > mid_;
  std::vector<std::vector<int> > cross_;      // per input edge: crossing ids from source(eh_) to target(eh_)
  std::vector<std::vector<Chord> > chords_;   // per input face
  std::vector<Crossing> crossing_;
  std::vector<int> cpos_;                     // per crossing: its index in cross_ of its edge
  std::vector<Face_data> fdata_;              // per input face, cached
  std::vector<std::vector<int> > curve_crossings_;
  std::vector<std::pair<vertex_descriptor, vertex_descriptor> > curve_ends_;
  std::vector<char> removed_;                 // per crossing: taken out with its curve
  std::map<std::pair<vertex_descriptor, int>, std::pair<halfedge_descriptor, int> > node_curves_;
  // per input edge e and side (0: seen from face(eh_[e]), 1: from the other face)
  struct Side { int face = -1; std::size_t k = 0; vertex_descriptor apex; }; // face index (-1: border), index of e in Face_data::h, corner opposite e
  std::vector<Side> side_;
  // search labels, current when `stamp` is the search's (no reset of every state per search)
  struct Label { double dist = 0; std::int64_t pred = -1; std::uint32_t stamp = 0; };
  std::vector<Label> label_;
  std::uint32_t stamp_ = 0;
  // face_data()'s scratch space
  std::vector<int> at_scratch_, stack_scratch_;
  std::array<std::vector<std::pair<std::int64_t, int> >, 3> corner_scratch_;
  std::vector<char> opened_scratch_;
  std::vector<std::array<int, 3> > gaps_scratch_;
  std::vector<int> merge_scratch_;            // commit()'s
  std::vector<char> blocked_;                 // per input edge: an edge curve runs along it (not to be crossed)
  std::vector<int> curve_edge_;               // per curve: the input edge it runs along, or -1 (it crosses edges)
  double step_ = 0;                           // the cost of one crossing
  std::size_t live_ = 0;                      // crossings of the curves not taken out
  const CGAL::Real_timer* timer_ = nullptr;   // set_deadline()
  double max_seconds_ = std::numeric_limits<double>::infinity();
  bool timed_out_ = false;
};

// The budgets of a curve tracing (named parameters maximum_running_time, default none, and
// maximum_steiner_vertices, default overlay_tracing_budget), then the check that tm is a triangulated disk.
template <class TriangleMesh, class NamedParameters>
Error_code read_curve_tracing_budgets(const TriangleMesh& tm, const NamedParameters& np, double& max_seconds, std::size_t& max_splits)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  max_seconds = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), std::numeric_limits<double>::infinity());
  if(!(max_seconds >= 0)) return ERROR_WRONG_PARAMETER;
  max_splits = choose_parameter(get_parameter(np, internal_np::maximum_steiner_vertices),
                                overlay_tracing_budget.of(static_cast<std::size_t>(num_edges(tm))));
  return check_triangulated_disk(tm);
}

// Traces every edge of the partition (nodes, edges, rotation) with `tracer`, curve id = edge index, in
// tracing_order() (after the checks of mark_nodes_and_check_partition(); a disk only). ERROR_BUDGET_EXHAUSTED
// when the curves cross more than max_splits input edges or the timer passes max_seconds (checked inside each
// curve's search too: the tracer keeps that deadline for later curves).
template <class TriangleMesh, class VertexPointMap>
Error_code trace_partition_curves(TriangleMesh& tm, VertexPointMap vpm, Overlay_tracer<TriangleMesh, VertexPointMap>& tracer,
                                  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& nodes,
                                  const std::vector<std::array<std::size_t, 2> >& edges,
                                  const std::vector<std::vector<std::size_t> >& rotation,
                                  std::size_t max_splits, const CGAL::Real_timer& timer, double max_seconds)
{
  std::vector<std::size_t> order;
  {
    Path_network<TriangleMesh> net(tm);
    std::vector<std::vector<std::size_t> > loops;
    const Error_code status = mark_nodes_and_check_partition(tm, net, nodes, edges, rotation, loops);
    if(status != OK) return status;
    if(loops.size() != 1) return ERROR_WRONG_PARAMETER; // a disk only
    tracing_order(vpm, net, nodes, edges, loops, false, order);
  }
  tracer.set_deadline(timer, max_seconds);
  std::vector<char> traced(edges.size(), 0);
  auto neighbours = [&](std::size_t i, std::size_t e, int& before, int& after)
  {
    const std::vector<std::size_t>& r = rotation[i];
    const std::size_t k = static_cast<std::size_t>(std::find(r.begin(), r.end(), e) - r.begin());
    traced_neighbours(r, k, CGAL::is_border(nodes[i], tm) != boost::none, traced, before, after);
  };
  for(std::size_t e : order)
  {
    if(timer.time() > max_seconds) return ERROR_BUDGET_EXHAUSTED;
    const std::size_t a = edges[e][0], b = edges[e][1];
    int ba, aa, bb, ab;
    neighbours(a, e, ba, aa);
    neighbours(b, e, bb, ab);
    // at b the curve arrives: its counterclockwise order around b is the rotation's
    if(!tracer.trace(static_cast<int>(e), nodes[a], ba, aa, nodes[b], bb, ab))
      return tracer.timed_out() ? ERROR_BUDGET_EXHAUSTED : ERROR_PATH_TRACING_FAILED;
    traced[e] = 1;
    if(tracer.live_crossings() > max_splits) return ERROR_BUDGET_EXHAUSTED;
  }
  return OK;
}

/// traces the partition edges as curves crossing the input edges, then refines the mesh once (see above)
template <class TriangleMesh, class VertexPointMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code trace_paths_overlay(TriangleMesh& tm, VertexPointMap vpm,
                               const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& nodes,
                               const std::vector<std::array<std::size_t, 2> >& edges,
                               const std::vector<std::vector<std::size_t> >& rotation,
                               std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >& paths,
                               std::vector<Steiner_vertex<TriangleMesh> >& steiner,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  CGAL::Real_timer timer;
  timer.start();
  paths.assign(edges.size(), std::vector<vertex_descriptor>());
  double max_seconds = 0;
  std::size_t max_splits = 0;
  Error_code status = read_curve_tracing_budgets(tm, np, max_seconds, max_splits);
  if(status != OK) return status;
  const double penalty_units = choose_parameter(get_parameter(np, internal_np::split_penalty), 4.);
  if(!(penalty_units >= 0) || !std::isfinite(penalty_units)) return ERROR_WRONG_PARAMETER;
  Overlay_tracer<TriangleMesh, VertexPointMap> tracer(tm, vpm);
  tracer.set_crossing_cost(penalty_units);
  status = trace_partition_curves(tm, vpm, tracer, nodes, edges, rotation, max_splits, timer, max_seconds);
  if(status != OK) return status;
  std::vector<std::pair<vertex_descriptor, vertex_descriptor> > ends;
  for(const auto& e : edges) ends.emplace_back(nodes[e[0]], nodes[e[1]]);
  if(!edges.empty() && !tracer.realize(ends, paths, steiner)) return ERROR_PATH_TRACING_FAILED;
  if(check_traced_paths(tm, nodes, edges, rotation, paths, nullptr, false) != OK) return ERROR_PATH_TRACING_FAILED;
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_TRACE_OVERLAY_H
