// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_INSERTION_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_INSERTION_H

// The insertion stage of progressive embedding: the collapses are undone in reverse order.
// Each undo splits the kept vertex back into two coincident vertices (`split`), moves one of
// them into its sector by a flip-free line search towards link vertices and link-edge
// midpoints (`place`, decided with the exact orientation predicate), and smooths the new
// 1-ring locally (internal/local_smoothing.h). In floating point, when no candidate is
// valid, the neighbourhood is smoothed and the placement retried.

#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Progressive_embedding/internal/progressive_embedding/working_mesh.h>
#include <CGAL/Progressive_embedding/internal/progressive_embedding/collapse.h>
#include <CGAL/Progressive_embedding/internal/local_smoothing.h>
#include <CGAL/Progressive_embedding/internal/newton_step.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <functional>
#include <iostream>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

struct Insertion_options
{
  int smoothing_iterations = 10;       // passes over the 1-ring after each insertion
  int retry_smoothing_iterations = 50; // passes before a failed placement is retried
  // Energy decrease (fraction) under which a smoothed vertex counts as converged. After an
  // insertion, 10%: smaller decreases cost many passes for little (the smoothing there only
  // keeps the new triangles in shape; distortion is optimize_distortion()'s job). Before a retry,
  // 0.1%: making room for a placement that failed is worth the time.
  double smoothing_tolerance = 0.1;
  double retry_smoothing_tolerance = 1e-3;
  int insertion_retries = 20;
  double line_search_factor = 0.8;
  int line_search_steps = 75;
};

template <class Traits>
class Insertion_stage
{
public:
  typedef Working_mesh<Traits>                                 WMesh;
  typedef typename WMesh::FT                                   FT;
  typedef typename WMesh::Point_2                              Point_2;
  typedef typename WMesh::Mesh                                 Mesh;
  typedef typename WMesh::vertex_descriptor                    vertex_descriptor;
  typedef typename WMesh::halfedge_descriptor                  halfedge_descriptor;
  typedef Collapse_record<vertex_descriptor>                   Record;

private:
  WMesh& wm;
  Mesh& m;
  const Traits& traits;
  Validity_criteria<Traits>& validity;
  Embedder_counters& counters;
  Insertion_options opt;
  std::function<bool()> over_time;
  std::function<bool(double)> callback;
  bool verbose;
  Local_smoother<Mesh, Traits> smoother;
  std::vector<vertex_descriptor> region, ring;
  std::vector<Point_2> targets;

public:
  Insertion_stage(WMesh& wm, const Traits& traits, Validity_criteria<Traits>& validity, Embedder_counters& counters,
                  const Insertion_options& opt, std::function<bool()> over_time, std::function<bool(double)> callback,
                  bool verbose)
    : wm(wm), m(wm.m), traits(traits), validity(validity), counters(counters), opt(opt),
      over_time(std::move(over_time)), callback(std::move(callback)), verbose(verbose),
      smoother(wm.m, traits, validity.ref)
  {}

  // Undoes the collapses of `history`, last first. `total_area`: the area inside the border.
  Error_code run(const std::vector<Record>& history, const FT& total_area)
  {
    const std::size_t total = history.size();
    Error_code ec = OK;
    for(std::size_t k = total; k-- > 0; )
    {
      if(over_time()) { ec = ERROR_BUDGET_EXHAUSTED; break; }
      if(callback && ((total - k) % 256 == 0) && !callback(double(total - k) / double(total)))
      { ec = ERROR_BUDGET_EXHAUSTED; break; }
      ec = insert(history[k], total_area);
      if(ec != OK)
      {
        if(verbose && ec == ERROR_INSERTION_FAILED) std::cerr << "[pe] insertion " << (total - k) << " of " << total << " failed\n";
        break;
      }
    }
    counters.smoothing_steps = smoother.steps_accepted;
    return ec;
  }

  // Undoes one collapse: split, place, smooth.
  Error_code insert(const Record& r, const FT& total_area)
  {
    bool new_side_cw = false;
    const vertex_descriptor vnew = split(r, new_side_cw);
    // The reference triangle has the mean area of the current mesh: early, coarse meshes
    // are not pushed towards the final, much smaller, triangles.
    validity.set_mean_area(total_area / FT(double(m.number_of_faces())));
    smoother.ref = validity.ref;
    ++counters.insertions;
    // Move the new vertex into its sector if that sector is convex (angle < pi), else move
    // the kept vertex into the other one (the paper's Fig. 5); decided with the exact predicate.
    vertex_descriptor mover = vnew, fixed = r.kept;
    const CGAL::Orientation o = validity.orient(m.point(r.kept), m.point(r.vl), m.point(r.vr));
    const bool new_side_convex = (o == CGAL::COLLINEAR) || (new_side_cw ? (o == CGAL::RIGHT_TURN) : (o == CGAL::LEFT_TURN));
    if(!new_side_convex) std::swap(mover, fixed);
    if(!place(mover, fixed))
    {
      ++counters.insertions_with_extra_smoothing;
      const Error_code ec = retry_with_smoothing(mover, fixed);
      if(ec != OK) return ec;
    }
    if(opt.smoothing_iterations > 0)
    {
      // the 1-rings of both split vertices
      wm.collect_ring(mover, 1, region);
      smooth(region, opt.smoothing_iterations, opt.smoothing_tolerance);
    }
    return OK;
  }

  // Splits `r.kept` back into kept + a new vertex (at the same position); returns the new vertex.
  // `new_side_cw` tells whether the new vertex's neighbours follow vl clockwise around `kept`.
  vertex_descriptor split(const Record& r, bool& new_side_cw)
  {
    const halfedge_descriptor hL = m.halfedge(r.vl, r.kept), hR = m.halfedge(r.vr, r.kept);
    CGAL_assertion(hL != Mesh::null_halfedge() && hR != Mesh::null_halfedge());
    vertex_descriptor vnew;
    if(r.a1 == Mesh::null_vertex())
    {
      // the removed vertex had degree 3: it sat inside the face (kept, vl, vr)
      halfedge_descriptor h = (m.target(m.next(hL)) == r.vr) ? hL : m.opposite(hL);
      CGAL_assertion(!m.is_border(h));
      new_side_cw = (h == hL); // face (vl, kept, vr): vr precedes vl counterclockwise
      halfedge_descriptor hc = CGAL::Euler::add_center_vertex(h, m);
      vnew = m.target(hc);
    }
    else
    {
      // In the counterclockwise face (vl, kept, a1), a1 precedes vl counterclockwise around kept.
      new_side_cw = (m.target(m.next(hL)) == r.a1);
      // split_vertex(h1, h2) gives the new vertex the fan after h2 up to and including h1
      const halfedge_descriptor h1 = new_side_cw ? hL : hR, h2 = new_side_cw ? hR : hL;
      const vertex_descriptor s1 = m.source(h1), s2 = m.source(h2);
      const halfedge_descriptor hnew = CGAL::Euler::split_vertex(h1, h2, m);
      vnew = (m.target(hnew) == r.kept) ? m.source(hnew) : m.target(hnew);
      // The two faces along the new edge are quads; the missing edges are s1-vnew and s2-kept.
      // A quad may contain all four of kept, vnew, vl, vr (when one side has no vertex): it then
      // admits both diagonals, so the quad with a single choice is cut first.
      // (at most two candidate diagonals per quad)
      struct Diagonals { std::pair<halfedge_descriptor, halfedge_descriptor> d[2]; std::size_t n = 0;
                         void push_back(const std::pair<halfedge_descriptor, halfedge_descriptor>& x) { if(n < 2) d[n++] = x; }
                         std::size_t size() const { return n; } bool empty() const { return n == 0; }
                         const std::pair<halfedge_descriptor, halfedge_descriptor>& front() const { return d[0]; } };
      auto diagonals = [&](halfedge_descriptor hq, Diagonals& out) {
        out.n = 0;
        if(m.is_border(hq)) return;
        halfedge_descriptor hs[4];
        std::size_t n = 0;
        for(halfedge_descriptor x : halfedges_around_face(hq, m)) { if(n < 4) hs[n] = x; ++n; }
        if(n != 4) return;
        for(std::size_t i = 0; i < 4; ++i)
        {
          const vertex_descriptor x = m.target(hs[i]), y = m.target(hs[(i + 2) % 4]);
          if(((x == s1 && y == vnew) || (x == s2 && y == r.kept)) && m.halfedge(x, y) == Mesh::null_halfedge())
            out.push_back(std::make_pair(hs[i], hs[(i + 2) % 4]));
        }
      };
      Diagonals d1, d2;
      halfedge_descriptor q1 = hnew, q2 = m.opposite(hnew);
      diagonals(q1, d1); diagonals(q2, d2);
      if(d1.size() > d2.size()) { std::swap(q1, q2); std::swap(d1, d2); }
      if(!d1.empty()) CGAL::Euler::split_face(d1.front().first, d1.front().second, m);
      diagonals(q2, d2);
      if(!d2.empty()) CGAL::Euler::split_face(d2.front().first, d2.front().second, m);
    }
    CGAL_assertion(m.degree(vnew) == r.degree_removed && m.degree(r.kept) == r.degree_kept);
    wm.set_input_id(vnew, r.removed_id);
    wm.set_on_border(vnew, false);
    m.point(vnew) = m.point(r.kept);
    return vnew;
  }

  // Moves `mover` (at the position of `fixed`) to the best valid candidate: a line search from its
  // position towards each link vertex and link-edge midpoint of its sector keeps the first valid
  // point; the candidate of lowest maximal energy wins. False (and nothing moved) if none is valid.
  bool place(vertex_descriptor mover, vertex_descriptor fixed)
  {
    const Point_2 p = m.point(mover);
    ring.clear();
    for(vertex_descriptor w : CGAL::vertices_around_target(mover, m)) ring.push_back(w);
    targets.clear();
    const std::size_t n = ring.size();
    std::size_t fi = 0;
    while(fi < n && ring[fi] != fixed) ++fi;
    // ring in cyclic order starting after `fixed`: vl|vr, a_1..a_k, vr|vl
    for(std::size_t k = 1; k < n; ++k)
    {
      const vertex_descriptor u = ring[(fi + k) % n];
      if(k > 1 && k < n - 1) targets.push_back(m.point(u));
      if(k + 1 < n)
      {
        const vertex_descriptor w = ring[(fi + k + 1) % n];
        targets.push_back(traits.construct_midpoint_2_object()(m.point(u), m.point(w)));
      }
    }
    bool found = false;
    double best = std::numeric_limits<double>::infinity();
    Point_2 best_p = p;
    const FT factor = make_ft<FT>(opt.line_search_factor);
    const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y());
    for(const Point_2& c : targets)
    {
      const FT dx = c.x() - p.x(), dy = c.y() - p.y();
      // The steps t = factor^s at or beyond the flip-free bound along the direction (computed in
      // double, a hint only: every candidate is checked exactly) flip a face: they are skipped.
      // A direction that leaves the sector is skipped entirely.
      double bound = 1;
      if(!flip_free_bound(mover, px, py, CGAL::to_double(dx), CGAL::to_double(dy), bound)) continue;
      FT t = make_ft<FT>(1);
      int s = 0;
      for(double td = 1; s < opt.line_search_steps && td > bound * (1 + 1e-6); ++s, td *= opt.line_search_factor)
        t = t * factor;
      for(; s < opt.line_search_steps; ++s, t = t * factor)
      {
        m.point(mover) = Point_2(p.x() + t * dx, p.y() + t * dy);
        // near the largest doubles a midpoint or a step overflows: no exact predicate takes infinity
        if(!is_finite_ft(m.point(mover).x()) || !is_finite_ft(m.point(mover).y())) continue;
        double e;
        if(validity.star_ok(m, mover, [this](vertex_descriptor w) { return wm.on_border(w); }, e))
        {
          if(e < best || !found) { best = e; best_p = m.point(mover); found = true; }
          break;
        }
      }
    }
    m.point(mover) = found ? best_p : p;
    return found;
  }

  // The first t at which a positive face of the star of `mover` (at (px, py)) degenerates when it
  // moves along (dx, dy) (+infinity if none does). False if a face degenerate at t = 0 (the two
  // split vertices coincide) gets a negative area along the direction: no t is valid then.
  bool flip_free_bound(vertex_descriptor mover, double px, double py, double dx, double dy, double& bound) const
  {
    bound = std::numeric_limits<double>::infinity();
    for(halfedge_descriptor h : halfedges_around_target(mover, m))
    {
      if(m.is_border(h)) continue;
      const Point_2& a = m.point(m.target(m.next(h)));
      const Point_2& b = m.point(m.source(h));
      const double ax = CGAL::to_double(a.x()), ay = CGAL::to_double(a.y());
      const double bx = CGAL::to_double(b.x()), by = CGAL::to_double(b.y());
      const double A0 = (ax - px) * (by - py) - (ay - py) * (bx - px); // twice the area at t = 0
      if(A0 == 0)
      {
        if(dx * (ay - by) + dy * (bx - ax) < 0) return false; // its derivative in t
      }
      else
        bound = (std::min)(bound, vertex_degeneration_time(px, py, dx, dy, ax, ay, bx, by));
    }
    return true;
  }

  // at most `passes` smoothing passes over the interior vertices of `vs` (see Local_smoother::smooth())
  void smooth(const std::vector<vertex_descriptor>& vs, int passes, double tolerance)
  {
    smoother.smooth(vs, passes, [&](vertex_descriptor v) { return wm.on_border(v); }, tolerance);
  }

private:
  // The valid positions are too thin for the number type: smooth around the two coincident
  // vertices (which stay where they are), on a growing region, and retry.
  Error_code retry_with_smoothing(vertex_descriptor mover, vertex_descriptor fixed)
  {
    for(int retry = 0; retry < opt.insertion_retries; ++retry)
    {
      wm.collect_ring(fixed, 2 + retry / 4, region);
      region.erase(std::remove_if(region.begin(), region.end(),
                                  [&](vertex_descriptor v) { return v == mover || v == fixed; }), region.end());
      smooth(region, opt.retry_smoothing_iterations, opt.retry_smoothing_tolerance);
      if(place(mover, fixed) || place(fixed, mover)) return OK;
      if(over_time()) return ERROR_BUDGET_EXHAUSTED;
    }
    return ERROR_INSERTION_FAILED;
  }
};

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_INSERTION_H
