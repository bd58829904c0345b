// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_PROGRESSIVE_EMBEDDING_H
#define CGAL_PROGRESSIVE_EMBEDDING_PROGRESSIVE_EMBEDDING_H

/// \file progressive_embedding.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/border_polygon.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Progressive_embedding/internal/symmetric_dirichlet.h>
#include <CGAL/Progressive_embedding/internal/local_smoothing.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Real_timer.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingReports
///
/// What `progressive_embedding()` did, filled when a pointer to it is passed with the
/// `statistics` named parameter.
struct Progressive_embedding_statistics
{
  /// faces invalid in the input map (orientation or energy)
  std::size_t invalid_faces_before = 0;
  /// edge collapses of the simplification stage (= vertex insertions of the second stage)
  std::size_t collapses = 0;
  /// tag-expansion rounds of the simplification stage
  std::size_t expansion_rounds = 0;
  /// interior vertices placed at the barycenter of their (border) neighbours
  std::size_t barycenter_placements = 0;
  /// vertices re-inserted
  std::size_t insertions = 0;
  /// restarts with a lower energy threshold after a failed insertion (floating point only)
  std::size_t restarts = 0;
  /// insertions that found no candidate at first and needed extra smoothing (0 in exact arithmetic, Lemma A.11)
  std::size_t insertions_with_extra_smoothing = 0;
  /// accepted smoothing steps
  std::size_t smoothing_steps = 0;
  /// seconds spent in the simplification stage
  double seconds_collapse = 0;
  /// seconds spent in the insertion stage
  double seconds_insertion = 0;
  /// total seconds, certification included
  double seconds_total = 0;
  /// the certificate of the output map
  Embedding_report report;
};

namespace internal {

template <class Traits>
class Progressive_embedder
{
public:
  typedef typename Traits::FT                                  FT;
  typedef typename Traits::Point_2                             Point_2;
  typedef CGAL::Surface_mesh<Point_2>                          Mesh;
  typedef typename Mesh::Vertex_index                          vertex_descriptor;
  typedef typename Mesh::Halfedge_index                        halfedge_descriptor;
  typedef typename Mesh::Face_index                            face_descriptor;

  struct Options
  {
    double energy_threshold = 1e20;
    int smoothing_iterations = 10;
    int retry_smoothing_iterations = 50;
    double line_search_factor = 0.8;
    int line_search_steps = 75;
    int insertion_retries = 20;
    std::size_t expansion_budget = std::size_t(-1);
    double time_budget = std::numeric_limits<double>::infinity();
    bool verbose = false;
    std::function<bool(double)> callback;
    int restarts = 4;
    double initial_min_area_ratio = 1e-12;
    bool min_area_ratio_given = false;
  };

private:
  struct Collapse_record
  {
    vertex_descriptor kept, vl, vr, a1; // a1: the removed vertex's neighbour after vl on its side (null if none)
    std::size_t removed_id;             // index of the removed vertex in the input
    std::size_t degree_removed, degree_kept; // to check the split restores the connectivity
  };

  Mesh m;
  Traits traits;
  typename Traits::Exact_orientation_2 orient;
  Options opt;
  Reference_triangle<FT> ref;
  FT total_area;
  FT min_face_area;       // faces smaller than this are collapsed (restarts only)
  double min_area_ratio = 0;
  typename Mesh::template Property_map<vertex_descriptor, std::size_t> oid;
  typename Mesh::template Property_map<vertex_descriptor, bool> vborder;
  typename Mesh::template Property_map<vertex_descriptor, std::size_t> vmark;
  typename Mesh::template Property_map<vertex_descriptor, std::size_t> vtouched;
  typename Mesh::template Property_map<face_descriptor, bool> ftag;
  std::size_t stamp = 0, sweep = 0;
  std::vector<Collapse_record> history;
  CGAL::Real_timer timer;

public:
  Progressive_embedding_statistics stats;

  Progressive_embedder(const Traits& traits, const Options& opt) : traits(traits), orient(traits.exact_orientation_2_object()), opt(opt) {}

  // positions: by input index; faces: input faces; on_border: per input index.
  // When an insertion fails in floating point (the map has clusters of valid faces too
  // small for the precision left), the run restarts from the input with a threshold
  // 10^4 times lower, so that those clusters are collapsed too (at most `restarts` times).
  template <class Face_range>
  Error_code run(std::vector<Point_2>& positions, const Face_range& faces_in,
                 const std::vector<char>& on_border, const FT& border_area)
  {
    timer.start();
    Error_code ec = ERROR_INSERTION_FAILED;
    // In floating point, faces below 1e-12 x the mean area leave too few bits for the
    // insertions around them: they are collapsed from the start (exact types: never).
    min_area_ratio = (Traits::has_exact_constructions && !opt.min_area_ratio_given) ? 0 : opt.initial_min_area_ratio;
    for(int attempt = 0; attempt <= opt.restarts; ++attempt)
    {
      ec = run_once(positions, faces_in, on_border, border_area);
      if(ec != ERROR_INSERTION_FAILED) break;
      min_area_ratio = (min_area_ratio == 0) ? 1e-16 : min_area_ratio * 1e4;
      if(min_area_ratio > 1e-3) break;
      ++stats.restarts;
      if(opt.verbose) std::cerr << "[pe] restart: faces of area below " << min_area_ratio << " x mean are collapsed too\n";
    }
    return ec;
  }

private:
  template <class Face_range>
  Error_code run_once(std::vector<Point_2>& positions, const Face_range& faces_in,
                      const std::vector<char>& on_border, const FT& border_area)
  {
    const std::size_t nv = positions.size();
    m.clear();
    history.clear();
    const std::size_t restarts = stats.restarts;
    stats = Progressive_embedding_statistics();
    stats.restarts = restarts;
    // the working mesh: a Surface_mesh whose points are the uv positions
    m.reserve(nv, 3 * faces_in.size() / 2 + nv, faces_in.size());
    oid = m.template add_property_map<vertex_descriptor, std::size_t>("v:pe_id", 0).first;
    vborder = m.template add_property_map<vertex_descriptor, bool>("v:pe_border", false).first;
    vmark = m.template add_property_map<vertex_descriptor, std::size_t>("v:pe_mark", 0).first;
    ftag = m.template add_property_map<face_descriptor, bool>("f:pe_tag", false).first;
    vtouched = m.template add_property_map<vertex_descriptor, std::size_t>("v:pe_touched", 0).first;
    stamp = 0; sweep = 0;
    std::vector<vertex_descriptor> V(nv);
    for(std::size_t i = 0; i < nv; ++i)
    {
      V[i] = m.add_vertex(positions[i]);
      oid[V[i]] = i;
      vborder[V[i]] = on_border[i] != 0;
    }
    for(const auto& t : faces_in)
      if(m.add_face(V[t[0]], V[t[1]], V[t[2]]) == Mesh::null_face())
        return ERROR_NON_MANIFOLD;

    total_area = border_area;
    const FT area_per_face = border_area / FT(double(faces_in.size()));
    min_face_area = area_per_face * make_ft<FT>(min_area_ratio);
    ref = equilateral_reference(area_per_face, make_ft<FT>(1.7320508075688772));

    const double t0 = timer.time();
    Error_code ec = simplify();
    stats.seconds_collapse = timer.time() - t0;
    if(ec != OK) return ec;
    const double t1 = timer.time();
    ec = reinsert();
    stats.seconds_insertion = timer.time() - t1;
    if(ec != OK) return ec;

    for(vertex_descriptor v : m.vertices())
      positions[oid[v]] = m.point(v);
    return OK;
  }

private:
  bool over_time() const { return timer.time() > opt.time_budget; }

  bool face_invalid(face_descriptor f) const
  {
    halfedge_descriptor h = m.halfedge(f);
    const Point_2& a = m.point(m.source(h));
    const Point_2& b = m.point(m.target(h));
    const Point_2& c = m.point(m.target(m.next(h)));
    if(orient(a, b, c) != CGAL::LEFT_TURN) return true;
    if(min_area_ratio > 0 && signed_area(a.x(), a.y(), b.x(), b.y(), c.x(), c.y()) < min_face_area) return true;
    bool ok;
    const FT e = symmetric_dirichlet(ref, a.x(), a.y(), b.x(), b.y(), c.x(), c.y(), ok);
    if(!ok) return true;
    const double ed = CGAL::to_double(e);
    return !(ed <= opt.energy_threshold);
  }

  // link condition for the interior edge of h in O(degree): the two endpoints
  // share exactly the two neighbours opposite to the edge
  bool link_condition(halfedge_descriptor h)
  {
    const vertex_descriptor v0 = m.source(h), v1 = m.target(h);
    ++stamp;
    for(vertex_descriptor w : CGAL::vertices_around_target(v0, m)) vmark[w] = stamp;
    int common = 0;
    for(vertex_descriptor w : CGAL::vertices_around_target(v1, m))
      if(vmark[w] == stamp && ++common > 2) return false;
    return common == 2;
  }

  void tag(face_descriptor f, std::vector<face_descriptor>& queue)
  {
    if(!ftag[f]) { ftag[f] = true; queue.push_back(f); }
  }

  // collapses h (source removed, target kept) and records how to undo it
  vertex_descriptor collapse(halfedge_descriptor h)
  {
    Collapse_record r;
    const vertex_descriptor v0 = m.source(h);
    r.kept = m.target(h);
    r.vl = m.target(m.next(h));
    r.vr = m.target(m.next(m.opposite(h)));
    r.removed_id = oid[v0];
    // the removed vertex's neighbour following vl on its side: the third vertex of the face
    // (v0, vl, x); the face (vl, v0, kept) is the one that disappears
    halfedge_descriptor hv0vl = m.halfedge(v0, r.vl); // v0 -> vl
    const vertex_descriptor x = m.target(m.next(hv0vl));
    r.a1 = (x == r.vr) ? Mesh::null_vertex() : x;
    r.degree_removed = m.degree(v0);
    r.degree_kept = m.degree(r.kept);
    for(halfedge_descriptor hh : halfedges_around_face(h, m)) ftag[m.face(hh)] = false;
    for(halfedge_descriptor hh : halfedges_around_face(m.opposite(h), m)) ftag[m.face(hh)] = false;
    const vertex_descriptor kept = CGAL::Euler::collapse_edge(m.edge(h), m);
    CGAL_assertion(kept == r.kept);
    history.push_back(r);
    ++stats.collapses;
    return kept;
  }

  Error_code simplify()
  {
    std::vector<face_descriptor> queue, stuck;
    std::size_t last_collapse_count = std::size_t(-1);
    for(face_descriptor f : m.faces())
      if(face_invalid(f)) { ftag[f] = true; queue.push_back(f); ++stats.invalid_faces_before; }
    if(opt.verbose) std::cerr << "[pe] invalid faces: " << stats.invalid_faces_before << "\n";

    while(!queue.empty())
    {
      if(over_time()) return ERROR_BUDGET_EXHAUSTED;
      // Sweeps of independent collapses (no two in one sweep touch the same vertex star) build a
      // balanced hierarchy, like a progressive mesh: reinsertion then refines coarse-to-fine
      // instead of peeling one huge star vertex by vertex.
      while(!queue.empty())
      {
        ++sweep;
        std::vector<face_descriptor> next_queue;
        for(std::size_t qi = 0; qi < queue.size(); ++qi)
        {
          const face_descriptor f = queue[qi];
          if(m.is_removed(f) || !ftag[f]) continue;
          bool busy = false;
          for(vertex_descriptor v : CGAL::vertices_around_face(m.halfedge(f), m))
            if(vtouched[v] == sweep) busy = true;
          if(busy) { next_queue.push_back(f); continue; }
          // the collapsible interior edge of f giving the smallest degree
          halfedge_descriptor best = Mesh::null_halfedge();
          std::size_t best_degree = std::size_t(-1);
          for(halfedge_descriptor h : halfedges_around_face(m.halfedge(f), m))
          {
            if(vborder[m.source(h)] || vborder[m.target(h)]) continue;
            const std::size_t d = m.degree(m.source(h)) + m.degree(m.target(h));
            if(d >= best_degree || !link_condition(h)) continue;
            best = h; best_degree = d;
          }
          if(best == Mesh::null_halfedge()) { stuck.push_back(f); continue; }
          const vertex_descriptor kept = collapse(best);
          vtouched[kept] = sweep;
          for(vertex_descriptor w : CGAL::vertices_around_target(kept, m)) vtouched[w] = sweep;
          for(face_descriptor g : CGAL::faces_around_target(m.halfedge(kept), m))
            if(g != Mesh::null_face() && !ftag[g] && face_invalid(g)) tag(g, next_queue);
        }
        queue.swap(next_queue);
      }
      // what is still invalid?
      std::vector<face_descriptor> bad;
      for(face_descriptor f : stuck)
        if(!m.is_removed(f) && ftag[f] && face_invalid(f)) bad.push_back(f);
      stuck.clear();
      if(bad.empty()) break;
      if(++stats.expansion_rounds > opt.expansion_budget) return ERROR_BUDGET_EXHAUSTED;
      // grow the tagged region by one ring around the faces still invalid; faces tagged
      // before but dropped as stuck are queued again (a collapse nearby may have freed them)
      bool grew = false;
      const std::size_t collapses_before = stats.collapses;
      for(face_descriptor f : bad)
      {
        queue.push_back(f);
        for(halfedge_descriptor h : halfedges_around_face(m.halfedge(f), m))
          for(face_descriptor g : CGAL::faces_around_target(h, m))
            if(g != Mesh::null_face() && g != f)
            {
              if(!ftag[g]) { ftag[g] = true; grew = true; }
              queue.push_back(g);
            }
      }
      if(!grew && collapses_before == last_collapse_count)
      {
        // Nothing left to collapse around these faces: their interior vertices have only
        // border neighbours. Such a vertex goes to the barycenter of its neighbours, which
        // lie on a convex polygon, so its star becomes valid.
        bool placed = false;
        for(face_descriptor f : bad)
          for(vertex_descriptor v : CGAL::vertices_around_face(m.halfedge(f), m))
          {
            if(vborder[v]) continue;
            bool all_border = true;
            FT sx(0), sy(0); std::size_t n = 0;
            for(vertex_descriptor w : CGAL::vertices_around_target(v, m))
            {
              if(!vborder[w]) { all_border = false; break; }
              sx += m.point(w).x(); sy += m.point(w).y(); ++n;
            }
            if(!all_border || n == 0) continue;
            const Point_2 b(sx / FT(double(n)), sy / FT(double(n)));
            if(b.x() == m.point(v).x() && b.y() == m.point(v).y()) continue;
            m.point(v) = b;
            ++stats.barycenter_placements;
            placed = true;
          }
        queue.clear();
        for(face_descriptor f : bad)
          if(face_invalid(f)) queue.push_back(f);
        if(!placed && !queue.empty())
          return ERROR_COLLAPSE_FAILED;
      }
      last_collapse_count = stats.collapses;
    }
    if(opt.verbose)
      std::cerr << "[pe] collapses: " << stats.collapses << ", expansion rounds: " << stats.expansion_rounds
                << ", barycenter placements: " << stats.barycenter_placements << "\n";
    return OK;
  }

  // splits `kept` back into kept + a new vertex (at the same position); returns the new vertex.
  // `new_side_cw` tells whether the new vertex's neighbours follow vl clockwise around `kept`.
  vertex_descriptor split(const Collapse_record& r, bool& new_side_cw)
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
      auto diagonals = [&](halfedge_descriptor hq, std::vector<std::pair<halfedge_descriptor, halfedge_descriptor> >& out) {
        out.clear();
        if(m.is_border(hq)) return;
        std::vector<halfedge_descriptor> hs;
        for(halfedge_descriptor x : halfedges_around_face(hq, m)) hs.push_back(x);
        if(hs.size() != 4) return;
        for(std::size_t i = 0; i < 4; ++i)
        {
          const vertex_descriptor x = m.target(hs[i]), y = m.target(hs[(i + 2) % 4]);
          if(((x == s1 && y == vnew) || (x == s2 && y == r.kept)) && m.halfedge(x, y) == Mesh::null_halfedge())
            out.push_back(std::make_pair(hs[i], hs[(i + 2) % 4]));
        }
      };
      std::vector<std::pair<halfedge_descriptor, halfedge_descriptor> > d1, d2;
      halfedge_descriptor q1 = hnew, q2 = m.opposite(hnew);
      diagonals(q1, d1); diagonals(q2, d2);
      if(d1.size() > d2.size()) { std::swap(q1, q2); std::swap(d1, d2); }
      if(!d1.empty()) CGAL::Euler::split_face(d1.front().first, d1.front().second, m);
      diagonals(q2, d2);
      if(!d2.empty()) CGAL::Euler::split_face(d2.front().first, d2.front().second, m);
    }
    CGAL_assertion(m.degree(vnew) == r.degree_removed && m.degree(r.kept) == r.degree_kept);
    oid[vnew] = r.removed_id;
    vborder[vnew] = false;
    m.point(vnew) = m.point(r.kept);
    return vnew;
  }

  // all faces around v positively oriented and (in floating point) of acceptable energy
  bool star_ok(vertex_descriptor v, double& max_energy) const
  {
    max_energy = 0;
    for(halfedge_descriptor h : halfedges_around_target(v, m))
    {
      if(m.is_border(h)) continue;
      const Point_2& x = m.point(v);
      const Point_2& a = m.point(m.target(m.next(h)));
      const Point_2& b = m.point(m.source(h));
      if(orient(x, a, b) != CGAL::LEFT_TURN) return false;
      bool ok;
      const FT e = symmetric_dirichlet(ref, x.x(), x.y(), a.x(), a.y(), b.x(), b.y(), ok);
      if(!ok) return false;
      const double ed = CGAL::to_double(e);
      if(!Traits::has_exact_constructions && !(ed <= opt.energy_threshold)) return false;
      max_energy = (std::max)(max_energy, std::isfinite(ed) ? ed : std::numeric_limits<double>::max());
    }
    return true;
  }

  // candidate placement of `mover` (currently at the same position as `fixed`)
  bool place(vertex_descriptor mover, vertex_descriptor fixed)
  {
    const Point_2 p = m.point(mover);
    std::vector<vertex_descriptor> ring;
    for(vertex_descriptor w : CGAL::vertices_around_target(mover, m)) ring.push_back(w);
    std::vector<Point_2> targets;
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
    for(const Point_2& c : targets)
    {
      FT t = make_ft<FT>(1);
      const FT dx = c.x() - p.x(), dy = c.y() - p.y();
      for(int s = 0; s < opt.line_search_steps; ++s, t = t * factor)
      {
        m.point(mover) = Point_2(p.x() + t * dx, p.y() + t * dy);
        double e;
        if(star_ok(mover, e))
        {
          if(e < best || !found) { best = e; best_p = m.point(mover); found = true; }
          break;
        }
      }
    }
    m.point(mover) = found ? best_p : p;
    return found;
  }

  void collect_ring(vertex_descriptor v, int rings, std::vector<vertex_descriptor>& out)
  {
    ++stamp;
    out.clear();
    out.push_back(v); vmark[v] = stamp;
    std::size_t begin = 0;
    for(int r = 0; r < rings; ++r)
    {
      const std::size_t end = out.size();
      for(std::size_t i = begin; i < end; ++i)
        for(vertex_descriptor w : CGAL::vertices_around_target(out[i], m))
          if(vmark[w] != stamp) { vmark[w] = stamp; out.push_back(w); }
      begin = end;
    }
  }

  void smooth(const std::vector<vertex_descriptor>& vs, int iterations, Local_smoother<Mesh, Traits>& sm)
  {
    for(int it = 0; it < iterations; ++it)
    {
      bool moved = false;
      for(vertex_descriptor v : vs)
        if(!vborder[v] && sm.step(v)) moved = true;
      if(!moved) break;
    }
  }

  Error_code reinsert()
  {
    Local_smoother<Mesh, Traits> sm(m, traits, ref);
    std::vector<vertex_descriptor> region;
    const std::size_t total = history.size();
    for(std::size_t k = total; k-- > 0; )
    {
      if(over_time()) return ERROR_BUDGET_EXHAUSTED;
      if(opt.callback && ((total - k) % 256 == 0) && !opt.callback(double(total - k) / double(total)))
        return ERROR_BUDGET_EXHAUSTED;
      const Collapse_record& r = history[k];
      bool new_side_cw = false;
      const vertex_descriptor vnew = split(r, new_side_cw);
      // The reference triangle has the mean area of the current mesh: early, coarse meshes
      // are not pushed towards the final, much smaller, triangles.
      ref = equilateral_reference(total_area / FT(double(m.number_of_faces())), make_ft<FT>(1.7320508075688772));
      sm.ref = ref;
      ++stats.insertions;
      // Move the new vertex into its sector if that sector is convex (angle < pi), else move
      // the kept vertex into the other one (the paper's Fig. 5); decided with the exact predicate.
      vertex_descriptor mover = vnew, fixed = r.kept;
      const CGAL::Orientation o = orient(m.point(r.kept), m.point(r.vl), m.point(r.vr));
      const bool new_side_convex = (o == CGAL::COLLINEAR) || (new_side_cw ? (o == CGAL::RIGHT_TURN) : (o == CGAL::LEFT_TURN));
      if(!new_side_convex) std::swap(mover, fixed);
      bool ok = place(mover, fixed);
      if(!ok)
      {
        // the valid positions are too thin for the number type: improve the neighbourhood and retry
        ++stats.insertions_with_extra_smoothing;
        for(int retry = 0; retry < opt.insertion_retries && !ok; ++retry)
        {
          // smooth around the two coincident vertices, which stay where they are
          collect_ring(fixed, 2 + retry / 4, region);
          region.erase(std::remove_if(region.begin(), region.end(),
                                      [&](vertex_descriptor v) { return v == mover || v == fixed; }), region.end());
          smooth(region, opt.retry_smoothing_iterations, sm);
          ok = place(mover, fixed) || place(fixed, mover);
          if(over_time()) return ERROR_BUDGET_EXHAUSTED;
        }
        if(!ok)
        {
          stats.smoothing_steps = sm.steps_accepted;
          if(opt.verbose) std::cerr << "[pe] insertion " << (total - k) << " of " << total << " failed\n";
          return ERROR_INSERTION_FAILED;
        }
      }
      if(opt.smoothing_iterations > 0)
      {
        // the 1-rings of both split vertices
        collect_ring(mover, 1, region);
        smooth(region, opt.smoothing_iterations, sm);
      }
    }
    stats.smoothing_steps = sm.steps_accepted;
    return OK;
  }
};

} // namespace internal

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// repairs a planar map of a triangulated topological disk whose border is fixed on a convex
/// polygon and whose interior may be anything (a broken Tutte map, random points, all interior
/// vertices at one point): the result is certified valid by `check_embedding()`, the border is
/// bit-exactly unchanged, and so is the connectivity. The caller's mesh is not modified.
///
/// The algorithm is the one of Shen, Jiang, Zorin and Panozzo, *Progressive Embedding*
/// (SIGGRAPH 2019), section 3.2: interior edges of invalid faces (exact orientation not positive,
/// or symmetric Dirichlet energy not finite or above a threshold) are collapsed under the link
/// condition, growing the tagged region when stuck, until no face is invalid; then the collapses
/// are undone in reverse order, each new vertex placed by a flip-free line search towards link
/// vertices and link-edge midpoints of the valid sector (decided with exact predicates), followed by
/// local Newton smoothing that never lets a face flip. All work is local to the touched
/// neighbourhood. A consistently clockwise layout is handled as its mirror image.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`; the present implementation
///         is sequential whatever the tag
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexUVMap a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type; its kernel's `FT` is the number type of the computation
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh, not modified
/// \param uvm the uv map: read everywhere, written on interior vertices
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{invalid_energy_threshold}
///     \cgalParamDescription{faces whose symmetric Dirichlet energy against an equilateral triangle of the mean area exceeds it are invalid}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1e20}
///   \cgalParamNEnd
///   \cgalParamNBegin{smoothing_iterations}
///     \cgalParamDescription{local smoothing sweeps over the 1-ring after each insertion}
///     \cgalParamType{`int`}
///     \cgalParamDefault{10 in floating point, 0 with an exact number type}
///   \cgalParamNEnd
///   \cgalParamNBegin{retry_smoothing_iterations}
///     \cgalParamDescription{smoothing sweeps before an insertion that found no candidate is retried}
///     \cgalParamType{`int`}
///     \cgalParamDefault{50}
///   \cgalParamNEnd
///   \cgalParamNBegin{insertion_retries}
///     \cgalParamDescription{how often a failed insertion is retried before `ERROR_INSERTION_FAILED`}
///     \cgalParamType{`int`}
///     \cgalParamDefault{20}
///   \cgalParamNEnd
///   \cgalParamNBegin{line_search_factor}
///     \cgalParamDescription{backtracking factor of the candidate line search}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.8}
///   \cgalParamNEnd
///   \cgalParamNBegin{line_search_steps}
///     \cgalParamDescription{maximal backtracking steps per candidate}
///     \cgalParamType{`int`}
///     \cgalParamDefault{75}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_area_ratio}
///     \cgalParamDescription{faces whose area is below this fraction of the mean face area are collapsed too: in floating point
///       they leave too few bits for insertions nearby; larger values trade speed for quality}
///     \cgalParamType{`double` in [0, 1)}
///     \cgalParamDefault{1e-12 in floating point, 0 with an exact number type}
///   \cgalParamNEnd
///   \cgalParamNBegin{collapse_budget}
///     \cgalParamDescription{maximal number of tag-expansion rounds of the simplification}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{unbounded (the mesh size bounds it)}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{time budget in seconds; `ERROR_BUDGET_EXHAUSTED` when exceeded}
///     \cgalParamType{`double`}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called during the insertion stage with the fraction done; returning `false` cancels (`ERROR_BUDGET_EXHAUSTED`)}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{verbose}
///     \cgalParamDescription{progress messages on `std::cerr`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{statistics}
///     \cgalParamDescription{receives what the algorithm did and the certificate}
///     \cgalParamType{`Progressive_embedding_statistics*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK` only if the output is certified valid; otherwise `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`,
///         `ERROR_NON_MANIFOLD`, `ERROR_NOT_A_DISK`, `ERROR_NON_FINITE_COORDINATES`, `ERROR_NON_CONVEX_BORDER`,
///         `ERROR_DEGENERATE_BORDER`, `ERROR_COLLAPSE_FAILED`, `ERROR_INSERTION_FAILED`, `ERROR_BUDGET_EXHAUSTED`
///         or `ERROR_INVALID_EMBEDDING`; the uv map is left unchanged on error.
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code progressive_embedding(const TriangleMesh& tm, VertexUVMap uvm,
                                 const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh>                                GT;
  typedef typename internal::Uv_map_types<VertexUVMap>::Point_2           Point_2;
  typedef typename internal::Uv_map_types<VertexUVMap>::Traits            Traits;
  typedef typename internal::Uv_map_types<VertexUVMap>::FT                FT;

  CGAL::Real_timer timer;
  timer.start();
  Progressive_embedding_statistics local_stats;
  Progressive_embedding_statistics* stats_out =
    choose_parameter(get_parameter(np, internal_np::statistics), static_cast<Progressive_embedding_statistics*>(nullptr));
  Progressive_embedding_statistics& stats = stats_out ? *stats_out : local_stats;
  stats = Progressive_embedding_statistics();

  typename internal::Progressive_embedder<Traits>::Options opt;
  opt.energy_threshold = choose_parameter(get_parameter(np, internal_np::invalid_energy_threshold), 1e20);
  opt.smoothing_iterations = choose_parameter(get_parameter(np, internal_np::smoothing_iterations),
                                              Traits::has_exact_constructions ? 0 : 10);
  opt.retry_smoothing_iterations = choose_parameter(get_parameter(np, internal_np::retry_smoothing_iterations), 50);
  opt.line_search_factor = choose_parameter(get_parameter(np, internal_np::line_search_factor), 0.8);
  opt.line_search_steps = choose_parameter(get_parameter(np, internal_np::line_search_steps), 75);
  opt.insertion_retries = choose_parameter(get_parameter(np, internal_np::insertion_retries), 20);
  opt.expansion_budget = choose_parameter(get_parameter(np, internal_np::collapse_budget), std::size_t(-1));
  opt.time_budget = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), std::numeric_limits<double>::infinity());
  opt.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  opt.callback = choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  opt.initial_min_area_ratio = choose_parameter(get_parameter(np, internal_np::minimum_area_ratio), opt.initial_min_area_ratio);
  opt.min_area_ratio_given = !CGAL::parameters::is_default_parameter<CGAL_NP_CLASS, internal_np::minimum_area_ratio_t>::value;
  if(!(opt.line_search_factor > 0 && opt.line_search_factor < 1) || opt.line_search_steps < 1
     || opt.smoothing_iterations < 0 || opt.retry_smoothing_iterations < 0 || opt.insertion_retries < 0
     || !(opt.energy_threshold > 0) || !(opt.initial_min_area_ratio >= 0 && opt.initial_min_area_ratio < 1))
    return ERROR_WRONG_PARAMETER;

  internal::Indexed_disk<TriangleMesh> disk;
  Error_code ec = internal::make_indexed_disk(tm, GT::null_halfedge(), disk);
  if(ec != OK) return ec;
  const std::size_t nv = disk.number_of_vertices(), nb = disk.border.size();
  if(nb < 3) return ERROR_BORDER_TOO_SHORT;

  std::vector<Point_2> P(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    P[i] = get(uvm, disk.vertices[i]);
    if(!internal::is_finite_ft(P[i].x()) || !internal::is_finite_ft(P[i].y()))
      return ERROR_NON_FINITE_COORDINATES;
  }
  std::vector<Point_2> B(nb);
  for(std::size_t k = 0; k < nb; ++k) B[k] = P[disk.border[k]];
  int orientation = 0;
  const Traits traits;
  const internal::Polygon_class pc = internal::classify_convex_polygon(B, traits.exact_orientation_2_object(), orientation);
  if(pc == internal::Polygon_class::DEGENERATE) return ERROR_DEGENERATE_BORDER;
  if(pc == internal::Polygon_class::NON_CONVEX) return ERROR_NON_CONVEX_BORDER;
  // a clockwise layout is repaired as its mirror image (negation is exact, so the border round-trips bit-exactly)
  const bool mirrored = orientation < 0;
  if(mirrored)
    for(Point_2& p : P) p = Point_2(p.x(), -p.y());
  // faces with three border vertices cannot move: they must already be positive
  typename Traits::Exact_orientation_2 orient = traits.exact_orientation_2_object();
  for(const auto& t : disk.faces)
    if(disk.on_border[t[0]] && disk.on_border[t[1]] && disk.on_border[t[2]]
       && orient(P[t[0]], P[t[1]], P[t[2]]) != CGAL::LEFT_TURN)
      return ERROR_DEGENERATE_BORDER;
  FT twice_area(0);
  for(std::size_t k = 0; k < nb; ++k)
  {
    const Point_2& a = P[disk.border[k]];
    const Point_2& b = P[disk.border[(k + 1) % nb]];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }

  internal::Progressive_embedder<Traits> pe(traits, opt);
  ec = pe.run(P, disk.faces, disk.on_border, twice_area / FT(2));
  stats = pe.stats;
  if(ec != OK) { stats.seconds_total = timer.time(); return ec; }

  // write back (interior only: the border is untouched) and certify what was written
  std::vector<Point_2> old(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    if(disk.on_border[i]) continue;
    old[i] = get(uvm, disk.vertices[i]);
    put(uvm, disk.vertices[i], mirrored ? Point_2(P[i].x(), -P[i].y()) : P[i]);
  }
  stats.report = check_embedding(tm, uvm, CGAL::parameters::vertex_point_map(
                   choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm))));
  stats.seconds_total = timer.time();
  if(!stats.report.is_valid())
  {
    for(std::size_t i = 0; i < nv; ++i)
      if(!disk.on_border[i]) put(uvm, disk.vertices[i], old[i]);
    return ERROR_INVALID_EMBEDDING;
  }
  return OK;
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_PROGRESSIVE_EMBEDDING_H
