// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_WORKING_MESH_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_WORKING_MESH_H

// The working copy of progressive embedding: a Surface_mesh whose points are the uv
// positions, each vertex knowing its index in the input and whether it is on the border,
// plus what the collapse and insertion stages share: the counters, the validity criteria
// of a face, and scratch marks for neighbourhood queries.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_statistics.h>
#include <CGAL/Progressive_embedding/internal/symmetric_dirichlet.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// What the stages did: they count straight into the public statistics.
typedef Progressive_embedding_statistics Embedder_counters;

template <class Traits>
class Working_mesh
{
public:
  typedef typename Traits::FT                                  FT;
  typedef typename Traits::Point_2                             Point_2;
  typedef CGAL::Surface_mesh<Point_2>                          Mesh;
  typedef typename Mesh::Vertex_index                          vertex_descriptor;
  typedef typename Mesh::Halfedge_index                        halfedge_descriptor;
  typedef typename Mesh::Face_index                            face_descriptor;

  Mesh m;

private:
  typename Mesh::template Property_map<vertex_descriptor, std::size_t> input_id_;
  typename Mesh::template Property_map<vertex_descriptor, bool> on_border_;
  typename Mesh::template Property_map<vertex_descriptor, std::size_t> mark_;
  std::size_t stamp_ = 0;

public:
  // positions: by input index; faces: triples of input indices; on_border: per input index
  template <class Face_range>
  Error_code build(const std::vector<Point_2>& positions, const Face_range& faces, const std::vector<char>& on_border)
  {
    const std::size_t nv = positions.size();
    m.clear();
    m.reserve(nv, nv + faces.size(), faces.size()); // a disk has V + F - 1 edges
    input_id_ = m.template add_property_map<vertex_descriptor, std::size_t>("v:pe_id", 0).first;
    on_border_ = m.template add_property_map<vertex_descriptor, bool>("v:pe_border", false).first;
    mark_ = m.template add_property_map<vertex_descriptor, std::size_t>("v:pe_mark", 0).first;
    stamp_ = 0;
    std::vector<vertex_descriptor> V(nv);
    for(std::size_t i = 0; i < nv; ++i)
    {
      V[i] = m.add_vertex(positions[i]);
      input_id_[V[i]] = i;
      on_border_[V[i]] = on_border[i] != 0;
    }
    for(const auto& t : faces)
      if(m.add_face(V[t[0]], V[t[1]], V[t[2]]) == Mesh::null_face())
        return ERROR_NON_MANIFOLD;
    return OK;
  }

  std::size_t input_id(vertex_descriptor v) const { return input_id_[v]; }
  void set_input_id(vertex_descriptor v, std::size_t id) { input_id_[v] = id; }
  bool on_border(vertex_descriptor v) const { return on_border_[v]; }
  void set_on_border(vertex_descriptor v, bool b) { on_border_[v] = b; }
  const Point_2& point(vertex_descriptor v) const { return m.point(v); }
  Point_2& point(vertex_descriptor v) { return m.point(v); }

  // link condition for the interior edge of h in O(degree): the two endpoints
  // share exactly the two neighbours opposite to the edge
  bool link_condition(halfedge_descriptor h)
  {
    const vertex_descriptor v0 = m.source(h), v1 = m.target(h);
    ++stamp_;
    for(vertex_descriptor w : CGAL::vertices_around_target(v0, m)) mark_[w] = stamp_;
    int common = 0;
    for(vertex_descriptor w : CGAL::vertices_around_target(v1, m))
      if(mark_[w] == stamp_ && ++common > 2) return false;
    return common == 2;
  }

  // v and its neighbours up to `rings` edges away, v first
  void collect_ring(vertex_descriptor v, int rings, std::vector<vertex_descriptor>& out)
  {
    ++stamp_;
    out.clear();
    out.push_back(v); mark_[v] = stamp_;
    std::size_t begin = 0;
    for(int r = 0; r < rings; ++r)
    {
      const std::size_t end = out.size();
      for(std::size_t i = begin; i < end; ++i)
        for(vertex_descriptor w : CGAL::vertices_around_target(out[i], m))
          if(mark_[w] != stamp_) { mark_[w] = stamp_; out.push_back(w); }
      begin = end;
    }
  }

  // the positions, by input index
  void write_positions(std::vector<Point_2>& positions) const
  {
    for(vertex_descriptor v : m.vertices())
      positions[input_id_[v]] = m.point(v);
  }

  // the faces as triples of input indices, each rotated to start at its smallest index, sorted:
  // equal to the input's (normalized the same way) when every collapse has been undone
  std::vector<std::array<std::size_t, 3> > input_faces() const
  {
    std::vector<std::array<std::size_t, 3> > F;
    F.reserve(m.number_of_faces());
    for(face_descriptor f : m.faces())
    {
      std::array<std::size_t, 3> t = { 0, 0, 0 };
      int k = 0;
      for(vertex_descriptor v : CGAL::vertices_around_face(m.halfedge(f), m)) { if(k < 3) t[k] = input_id_[v]; ++k; }
      F.push_back(normalized_face(t));
    }
    std::sort(F.begin(), F.end());
    return F;
  }

  static std::array<std::size_t, 3> normalized_face(std::array<std::size_t, 3> t)
  {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  }
};

// When a face is invalid (it must be collapsed) and when a star is acceptable (an insertion
// may stop there). Energies are against an equilateral reference of the mean face area, so
// they are scale-free; the area floor is a fraction of the mean face area.
//
// Both are relative to the mean face, which the border may not allow: an edge joining two
// border vertices keeps its length e, and a face on it has an energy of at least s^2 / e^2
// (s: the reference side; the reference edge mapped onto it gives a singular value of at most
// e / s), and an area that its place cannot raise much above e^2 where the border is crowded.
// So, for a face with such a "fixed" edge shorter than s, the floor is scaled by e^2 / s^2 and
// the threshold divided by it: the criteria ask as much relative to the scale the border
// forces there as they ask elsewhere relative to the mean face, and a fixed edge alone can
// never make a face invalid wherever its other corner goes. A face with three border vertices
// cannot change at all: it is judged by its orientation only.
template <class Traits>
struct Validity_criteria
{
  typedef typename Traits::FT                                  FT;
  typedef typename Traits::Point_2                             Point_2;

  Reference_triangle<FT> ref;
  double energy_threshold = 1e20;
  FT min_face_area = FT(0);   // faces smaller than this are invalid, when `use_min_area`
  bool use_min_area = false;
  typename Traits::Exact_orientation_2 orient;

  // the reference triangle for a mean face area `a`
  void set_mean_area(const FT& a)
  {
    ref = equilateral_reference(a, make_ft<FT>(1.7320508075688772));
  }

  // min(1, e^2 / s^2) for the fixed edge (p, q) (1 if it is not fixed): the scale of a face on it
  double fixed_edge_scale(const Point_2& p, const Point_2& q, bool fixed) const
  {
    if(!fixed) return 1;
    const FT dx = q.x() - p.x(), dy = q.y() - p.y();
    // s^2 = 2 x the reference's corner dot product (the equilateral reference: side^2 / 2)
    const double r = CGAL::to_double((dx * dx + dy * dy) / (FT(2) * ref.dot[0]));
    return (r > 0 && r < 1) ? r : 1; // NaN or <= 0 (a degenerate reference) counts as 1: the criteria as before
  }

  // a, b, c counterclockwise; ba, bb, bc: whether each is a border vertex
  bool face_invalid(const Point_2& a, const Point_2& b, const Point_2& c, bool ba, bool bb, bool bc) const
  {
    FT e;
    if(!positive_face_energy(ref, orient, a, b, c, e)) return true;
    if(ba && bb && bc) return false; // fixed: positive is all it can be
    const double scale = (std::min)(fixed_edge_scale(a, b, ba && bb),
                         (std::min)(fixed_edge_scale(b, c, bb && bc), fixed_edge_scale(c, a, bc && ba)));
    if(use_min_area && signed_area(a.x(), a.y(), b.x(), b.y(), c.x(), c.y()) < min_face_area * make_ft<FT>(scale))
      return true;
    return !(CGAL::to_double(e) * scale <= energy_threshold);
  }

  // all faces around v (an interior vertex) positively oriented and (in floating point) of
  // acceptable energy, its threshold scaled for a fixed edge as in face_invalid();
  // `max_energy` is the largest energy of those faces, scaled the same way
  template <class Mesh, class OnBorder>
  bool star_ok(const Mesh& m, typename Mesh::Vertex_index v, const OnBorder& on_border, double& max_energy) const
  {
    max_energy = 0;
    const Point_2& x = m.point(v);
    if(!is_finite_ft(x.x()) || !is_finite_ft(x.y())) return false; // no exact predicate takes infinity
    // orientations first: most rejected candidates fail there, and energies cost more
    for(typename Mesh::Halfedge_index h : halfedges_around_target(v, m))
      if(!m.is_border(h) && !positively_oriented(orient, x, m.point(m.target(m.next(h))), m.point(m.source(h))))
        return false;
    for(typename Mesh::Halfedge_index h : halfedges_around_target(v, m))
    {
      if(m.is_border(h)) continue;
      const Point_2& a = m.point(m.target(m.next(h)));
      const Point_2& b = m.point(m.source(h));
      FT e;
      if(!positive_face_energy(ref, orient, x, a, b, e)) return false;
      const double ed = CGAL::to_double(e)
                        * fixed_edge_scale(a, b, on_border(m.target(m.next(h))) && on_border(m.source(h)));
      if(!Traits::has_exact_constructions && !(ed <= energy_threshold)) return false;
      max_energy = (std::max)(max_energy, std::isfinite(ed) ? ed : std::numeric_limits<double>::max());
    }
    return true;
  }
};

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_WORKING_MESH_H
