// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_COLLAPSE_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_COLLAPSE_H

// The simplification stage of progressive embedding: interior edges of invalid faces are
// collapsed under the link condition, in sweeps of independent collapses, growing the tagged
// region by one ring around the faces still invalid when nothing is left to collapse, until
// no face is invalid. Each collapse is recorded so that the insertion stage can undo it.

#include <CGAL/Progressive_embedding/internal/progressive_embedding/working_mesh.h>

#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <functional>
#include <iostream>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// How to undo one collapse (see Insertion_stage::split()).
template <class Vertex>
struct Collapse_record
{
  Vertex kept, vl, vr, a1;                  // a1: the removed vertex's neighbour after vl on its side (null if none)
  std::size_t removed_id = 0;              // index of the removed vertex in the input
  unsigned int degree_removed = 0, degree_kept = 0; // to check that the split restores the connectivity
};

template <class Traits>
class Collapse_stage
{
public:
  typedef Working_mesh<Traits>                                 WMesh;
  typedef typename WMesh::FT                                   FT;
  typedef typename WMesh::Point_2                              Point_2;
  typedef typename WMesh::Mesh                                 Mesh;
  typedef typename WMesh::vertex_descriptor                    vertex_descriptor;
  typedef typename WMesh::halfedge_descriptor                  halfedge_descriptor;
  typedef typename WMesh::face_descriptor                      face_descriptor;
  typedef Collapse_record<vertex_descriptor>                   Record;

private:
  WMesh& wm;
  Mesh& m;
  const Validity_criteria<Traits>& validity;
  Embedder_counters& counters;
  std::size_t expansion_budget;
  std::function<bool()> over_time;
  bool verbose;
  typename Mesh::template Property_map<face_descriptor, bool> ftag;       // tagged for collapse
  typename Mesh::template Property_map<vertex_descriptor, std::size_t> vtouched; // sweep of the last collapse nearby
  std::size_t sweep = 0;

public:
  Collapse_stage(WMesh& wm, const Validity_criteria<Traits>& validity, Embedder_counters& counters,
                 std::size_t expansion_budget, std::function<bool()> over_time, bool verbose)
    : wm(wm), m(wm.m), validity(validity), counters(counters), expansion_budget(expansion_budget),
      over_time(std::move(over_time)), verbose(verbose)
  {
    ftag = m.template add_property_map<face_descriptor, bool>("f:pe_tag", false).first;
    vtouched = m.template add_property_map<vertex_descriptor, std::size_t>("v:pe_touched", 0).first;
  }

  ~Collapse_stage()
  {
    m.remove_property_map(ftag);
    m.remove_property_map(vtouched);
  }

  bool face_invalid(face_descriptor f) const
  {
    const halfedge_descriptor h = m.halfedge(f);
    const vertex_descriptor a = m.source(h), b = m.target(h), c = m.target(m.next(h));
    return validity.face_invalid(m.point(a), m.point(b), m.point(c), wm.on_border(a), wm.on_border(b), wm.on_border(c));
  }

  // Collapses until no face is invalid; `history` receives the collapses in order.
  Error_code run(std::vector<Record>& history)
  {
    std::vector<face_descriptor> queue, stuck;
    std::size_t last_collapse_count = std::size_t(-1);
    for(face_descriptor f : m.faces())
      if(face_invalid(f)) { ftag[f] = true; queue.push_back(f); ++counters.invalid_faces_before; }
    if(verbose) std::cerr << "[pe] invalid faces: " << counters.invalid_faces_before << "\n";

    while(!queue.empty())
    {
      if(over_time()) return ERROR_BUDGET_EXHAUSTED;
      collapse_sweeps(queue, stuck, history);
      // what is still invalid?
      std::vector<face_descriptor> bad;
      for(face_descriptor f : stuck)
        if(!m.is_removed(f) && ftag[f] && face_invalid(f)) bad.push_back(f);
      stuck.clear();
      // a face can be queued once per neighbour: without this, each round multiplied the copies
      // (about 19 times), and a patch whose faces stayed stuck for a few rounds filled gigabytes
      remove_duplicates(bad);
      if(bad.empty()) break;
      if(++counters.expansion_rounds > expansion_budget) return ERROR_BUDGET_EXHAUSTED;
      const std::size_t collapses_before = counters.collapses;
      const bool grew = expand(bad, queue);
      remove_duplicates(queue);
      if(!grew && collapses_before == last_collapse_count)
      {
        // Nothing left to collapse around these faces: their interior vertices have only
        // border neighbours, and go to the barycenter of those.
        const bool placed = place_at_border_barycenters(bad);
        queue.clear();
        for(face_descriptor f : bad)
          if(face_invalid(f)) queue.push_back(f);
        // What is left can neither collapse nor move. A positively oriented face there is held
        // only by the area floor or the energy threshold, which its border vertices do not
        // let it meet (e.g. an interior vertex inside a cluster of border vertices 1e-12 apart):
        // it stays, as the insertions need positive faces only.
        if(!placed)
        {
          queue.erase(std::remove_if(queue.begin(), queue.end(), [this](face_descriptor f) { return face_positive(f); }),
                      queue.end());
          if(!queue.empty()) return ERROR_COLLAPSE_FAILED;
        }
      }
      last_collapse_count = counters.collapses;
    }
    if(verbose)
      std::cerr << "[pe] collapses: " << counters.collapses << ", expansion rounds: " << counters.expansion_rounds
                << ", barycenter placements: " << counters.barycenter_placements << "\n";
    return OK;
  }

  bool face_positive(face_descriptor f) const
  {
    const halfedge_descriptor h = m.halfedge(f);
    return validity.orient(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h)))) == CGAL::LEFT_TURN;
  }

  // the collapsible interior edge of f (link condition) giving the smallest degree; null if none
  halfedge_descriptor best_edge(face_descriptor f)
  {
    halfedge_descriptor best = Mesh::null_halfedge();
    std::size_t best_degree = std::size_t(-1);
    for(halfedge_descriptor h : halfedges_around_face(m.halfedge(f), m))
    {
      if(wm.on_border(m.source(h)) || wm.on_border(m.target(h))) continue;
      const std::size_t d = m.degree(m.source(h)) + m.degree(m.target(h));
      if(d >= best_degree || !wm.link_condition(h)) continue;
      best = h; best_degree = d;
    }
    return best;
  }

  // collapses h (source removed, target kept) and records how to undo it
  vertex_descriptor collapse(halfedge_descriptor h, std::vector<Record>& history)
  {
    Record r;
    const vertex_descriptor v0 = m.source(h);
    r.kept = m.target(h);
    r.vl = m.target(m.next(h));
    r.vr = m.target(m.next(m.opposite(h)));
    r.removed_id = wm.input_id(v0);
    // the removed vertex's neighbour following vl on its side: the third vertex of the face
    // (v0, vl, x); the face (vl, v0, kept) is the one that disappears
    const halfedge_descriptor hv0vl = m.halfedge(v0, r.vl); // v0 -> vl
    const vertex_descriptor x = m.target(m.next(hv0vl));
    r.a1 = (x == r.vr) ? Mesh::null_vertex() : x;
    r.degree_removed = static_cast<unsigned int>(m.degree(v0));
    r.degree_kept = static_cast<unsigned int>(m.degree(r.kept));
    for(halfedge_descriptor hh : halfedges_around_face(h, m)) ftag[m.face(hh)] = false;
    for(halfedge_descriptor hh : halfedges_around_face(m.opposite(h), m)) ftag[m.face(hh)] = false;
    const vertex_descriptor kept = CGAL::Euler::collapse_edge(m.edge(h), m);
    CGAL_assertion(kept == r.kept);
    history.push_back(r);
    ++counters.collapses;
    return kept;
  }

private:
  // keeps the first copy of each face, in order
  void remove_duplicates(std::vector<face_descriptor>& faces) const
  {
    std::vector<char> seen(m.num_faces(), 0);
    std::size_t k = 0;
    for(face_descriptor f : faces)
    {
      const std::size_t i = static_cast<std::size_t>(f);
      if(i < seen.size() && seen[i]) continue;
      if(i < seen.size()) seen[i] = 1;
      faces[k++] = f;
    }
    faces.resize(k);
  }

  // Sweeps of independent collapses (no two in one sweep touch the same vertex star) build a
  // balanced hierarchy, like a progressive mesh: insertion then refines coarse-to-fine instead
  // of peeling one huge star vertex by vertex. Faces with no collapsible edge go to `stuck`.
  void collapse_sweeps(std::vector<face_descriptor>& queue, std::vector<face_descriptor>& stuck, std::vector<Record>& history)
  {
    std::vector<face_descriptor> next_queue;
    while(!queue.empty())
    {
      ++sweep;
      next_queue.clear();
      for(std::size_t qi = 0; qi < queue.size(); ++qi)
      {
        const face_descriptor f = queue[qi];
        if(m.is_removed(f) || !ftag[f]) continue;
        bool busy = false;
        for(vertex_descriptor v : CGAL::vertices_around_face(m.halfedge(f), m))
          if(vtouched[v] == sweep) busy = true;
        if(busy) { next_queue.push_back(f); continue; }
        const halfedge_descriptor best = best_edge(f);
        if(best == Mesh::null_halfedge()) { stuck.push_back(f); continue; }
        const vertex_descriptor kept = collapse(best, history);
        vtouched[kept] = sweep;
        for(vertex_descriptor w : CGAL::vertices_around_target(kept, m)) vtouched[w] = sweep;
        for(face_descriptor g : CGAL::faces_around_target(m.halfedge(kept), m))
          if(g != Mesh::null_face() && !ftag[g] && face_invalid(g)) { ftag[g] = true; next_queue.push_back(g); }
      }
      queue.swap(next_queue);
    }
  }

  // Grows the tagged region by one ring around the faces still invalid; faces tagged before but
  // dropped as stuck are queued again (a collapse nearby may have freed them). True if it grew.
  bool expand(const std::vector<face_descriptor>& bad, std::vector<face_descriptor>& queue)
  {
    bool grew = false;
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
    return grew;
  }

  // An interior vertex of a face in `bad` whose neighbours are all on the (convex) border goes
  // to their barycenter, which makes its star valid. True if a vertex moved.
  bool place_at_border_barycenters(const std::vector<face_descriptor>& bad)
  {
    bool placed = false;
    for(face_descriptor f : bad)
      for(vertex_descriptor v : CGAL::vertices_around_face(m.halfedge(f), m))
      {
        if(wm.on_border(v)) continue;
        bool all_border = true;
        FT sx(0), sy(0); std::size_t n = 0;
        for(vertex_descriptor w : CGAL::vertices_around_target(v, m))
        {
          if(!wm.on_border(w)) { all_border = false; break; }
          sx += m.point(w).x(); sy += m.point(w).y(); ++n;
        }
        if(!all_border || n == 0) continue;
        Point_2 b(sx / FT(double(n)), sy / FT(double(n)));
        // border coordinates near the largest double: their sum overflows, the sum of their n-ths
        // does not; a vertex whose barycenter is still not finite stays where it is
        if(!is_finite_ft(b.x()) || !is_finite_ft(b.y()))
        {
          FT qx(0), qy(0);
          for(vertex_descriptor w : CGAL::vertices_around_target(v, m))
          {
            qx += m.point(w).x() / FT(double(n));
            qy += m.point(w).y() / FT(double(n));
          }
          b = Point_2(qx, qy);
          if(!is_finite_ft(b.x()) || !is_finite_ft(b.y())) continue;
        }
        if(b.x() == m.point(v).x() && b.y() == m.point(v).y()) continue;
        m.point(v) = b;
        ++counters.barycenter_placements;
        placed = true;
      }
    return placed;
  }
};

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_COLLAPSE_H
