// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_REFINEMENT_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_REFINEMENT_H

// Constrained maps refine a working copy of the user's mesh (so that a failure leaves the user's
// mesh untouched), then replay the refinement on the user's mesh. The refinement is a sequence of
// edge splits at a parameter t. Usually each is followed by the split of each (now quadrilateral)
// incident face by the one diagonal that joins the new vertex to the opposite corner; a split can
// instead leave the faces as they are (`join_faces` false: several points inserted on one edge)
// and name the diagonals to add after it (`diagonals`, each between two vertices of one face). The
// result is determined by the split edges and the diagonals, so replaying them in the same order on
// a mesh with the same connectivity gives the same mesh. Every new face lies in one face of the
// mesh before the split, so the surface is unchanged.
//
// Each vertex of a refined mesh lies on the input surface: it is a convex combination of at most
// three input vertices of one input face (an input vertex is itself, a point on an input edge a
// combination of the edge's two endpoints). Surface_position keeps that combination, so that
// attributes can be interpolated.

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstddef>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// a convex combination of at most three input vertices
template <class Vertex, class FT>
struct Surface_position
{
  std::array<Vertex, 3> corners;
  std::array<FT, 3> weights;
  std::size_t size = 0;

  static Surface_position vertex(Vertex v)
  {
    Surface_position p;
    p.corners[0] = v; p.weights[0] = FT(1); p.size = 1;
    return p;
  }

  // (1 - t) a + t b, merging equal corners; false if the support exceeds three vertices
  // (the two points are not on one input face: the caller split an edge that crosses input faces)
  static bool combine(const Surface_position& a, const Surface_position& b, const FT& t, Surface_position& out)
  {
    out = Surface_position();
    auto add = [&out](Vertex v, const FT& w) -> bool {
      for(std::size_t i = 0; i < out.size; ++i)
        if(out.corners[i] == v) { out.weights[i] += w; return true; }
      if(out.size == 3) return false;
      out.corners[out.size] = v; out.weights[out.size] = w; ++out.size;
      return true;
    };
    const FT s = FT(1) - t;
    for(std::size_t i = 0; i < a.size; ++i) if(!add(a.corners[i], s * a.weights[i])) return false;
    for(std::size_t i = 0; i < b.size; ++i) if(!add(b.corners[i], t * b.weights[i])) return false;
    return true;
  }
};

// One edge split of a refinement: the edge (a, b) as it was when split, the parameter t of the
// new vertex (position (1 - t) a + t b), and the new vertex.
template <class Vertex, class FT>
struct Edge_split
{
  Vertex a, b, v;
  FT t;
  bool join_faces = true;                          // split the incident faces to the opposite corners
  std::vector<std::pair<Vertex, Vertex> > diagonals; // then add these edges, in order
};

// Adds the edge (u, w) across the face that has both on its border (split_face). Returns false when no
// face has both, or when they are adjacent along that face.
template <class TriangleMesh>
bool connect_in_face(typename boost::graph_traits<TriangleMesh>::vertex_descriptor u,
                     typename boost::graph_traits<TriangleMesh>::vertex_descriptor w, TriangleMesh& tm)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  for(halfedge_descriptor hu : CGAL::halfedges_around_target(u, tm))
  {
    if(is_border(hu, tm)) continue;
    // walk the face of hu from u: its other halfedges, each once
    for(halfedge_descriptor hw = next(hu, tm); hw != hu; hw = next(hw, tm))
    {
      if(target(hw, tm) != w) continue;
      if(next(hu, tm) == hw || next(hw, tm) == hu) return false; // already an edge of that face
      CGAL::Euler::split_face(hu, hw, tm);
      return true;
    }
  }
  return false;
}

// Splits the edge of halfedge h at `point` (the new vertex's point), then splits each incident
// quadrilateral face by the diagonal from the new vertex to its opposite corner. Returns a halfedge
// whose target is the new vertex.
template <class TriangleMesh, class VertexPointMap, class Point>
typename boost::graph_traits<TriangleMesh>::halfedge_descriptor
split_edge_and_faces(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, const Point& point,
                     TriangleMesh& tm, VertexPointMap vpm)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  // split_edge(h) inserts the new vertex before target(h): the returned halfedge ends at it
  const halfedge_descriptor hnew = CGAL::Euler::split_edge(h, tm);
  put(vpm, target(hnew, tm), point);
  // the two faces of the new vertex's edges are quadrilaterals (unless border)
  for(halfedge_descriptor hs : { hnew, opposite(next(hnew, tm), tm) })
  {
    if(is_border(hs, tm)) continue;
    // hs ends at the new vertex; next(next(hs)) ends at the corner opposite to it
    CGAL::Euler::split_face(hs, next(next(hs, tm), tm), tm);
  }
  return hnew;
}

// Replays `splits` (made on a copy whose vertex `copy_to_mesh` maps to the user's mesh) on `tm`:
// each split edge is found by its two endpoints. `copy_to_mesh` receives the new vertices.
// ERROR_WRONG_PARAMETER if an edge is missing (the meshes did not have the same connectivity).
// Surface_mesh reuses the slots of removed elements: vertices added to a mesh that still holds removed
// ones would come before the input's. The guard turns the reuse off for its lifetime (other meshes append).
template <class TriangleMesh>
struct No_recycling_guard
{
  explicit No_recycling_guard(TriangleMesh&) {}
};

template <class P>
struct No_recycling_guard<CGAL::Surface_mesh<P> >
{
  CGAL::Surface_mesh<P>& mesh;
  const bool recycled;
  explicit No_recycling_guard(CGAL::Surface_mesh<P>& m) : mesh(m), recycled(m.does_recycle_garbage())
  { m.set_recycle_garbage(false); }
  ~No_recycling_guard() { mesh.set_recycle_garbage(recycled); }
  No_recycling_guard(const No_recycling_guard&) = delete;
  No_recycling_guard& operator=(const No_recycling_guard&) = delete;
};

template <class TriangleMesh, class VertexPointMap, class CopyVertex, class FT, class Point_of_split>
Error_code replay_splits(const std::vector<Edge_split<CopyVertex, FT> >& splits, TriangleMesh& tm, VertexPointMap vpm,
                         std::unordered_map<CopyVertex, typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& copy_to_mesh,
                         const Point_of_split& point_of_split)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  for(const Edge_split<CopyVertex, FT>& s : splits)
  {
    const auto ia = copy_to_mesh.find(s.a), ib = copy_to_mesh.find(s.b);
    if(ia == copy_to_mesh.end() || ib == copy_to_mesh.end()) return ERROR_WRONG_PARAMETER;
    const std::pair<halfedge_descriptor, bool> h = halfedge(ia->second, ib->second, tm);
    if(!h.second) return ERROR_WRONG_PARAMETER;
    const auto point = point_of_split(get(vpm, ia->second), get(vpm, ib->second), s.t);
    halfedge_descriptor hn;
    if(s.join_faces) hn = split_edge_and_faces(h.first, point, tm, vpm);
    else
    {
      hn = CGAL::Euler::split_edge(h.first, tm);
      put(vpm, target(hn, tm), point);
    }
    copy_to_mesh[s.v] = target(hn, tm);
    for(const auto& d : s.diagonals)
    {
      const auto iu = copy_to_mesh.find(d.first), iw = copy_to_mesh.find(d.second);
      if(iu == copy_to_mesh.end() || iw == copy_to_mesh.end()) return ERROR_WRONG_PARAMETER;
      if(!connect_in_face(iu->second, iw->second, tm)) return ERROR_WRONG_PARAMETER;
    }
  }
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_REFINEMENT_H
