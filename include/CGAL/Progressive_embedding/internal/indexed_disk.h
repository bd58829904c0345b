// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_INDEXED_DISK_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_INDEXED_DISK_H

// The compact structure every algorithm starts from: vertices numbered 0..n-1,
// faces as index triples, and the border cycle with the interior on its left.
// Building it also validates the input: empty, not triangulated, not manifold,
// not a disk -> specific Error_code.

#include <CGAL/Progressive_embedding/Error_code.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>

#include <array>
#include <vector>
#include <cstddef>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

template <class TriangleMesh>
struct Indexed_disk
{
  typedef boost::graph_traits<TriangleMesh>                  GT;
  typedef typename GT::vertex_descriptor                     vertex_descriptor;
  typedef typename GT::halfedge_descriptor                   halfedge_descriptor;
  typedef typename GT::face_descriptor                       face_descriptor;

  std::vector<vertex_descriptor> vertices;           // index -> descriptor
  std::vector<std::array<std::size_t, 3> > faces;    // in the mesh's face orientation
  std::vector<std::size_t> border;                   // border cycle, mesh interior on the left
  std::vector<char> on_border;                       // per vertex

  std::size_t number_of_vertices() const { return vertices.size(); }
  std::size_t number_of_faces() const { return faces.size(); }
  std::size_t number_of_interior_vertices() const { return vertices.size() - border.size(); }
};

// Fills `disk` from `tm`. `bhd` may be a border halfedge or `null_halfedge()`
// (then the mesh's unique border cycle is used). `vertex_index` is any function
// vertex_descriptor -> index in [0, num_vertices); a dynamic map is used.
template <class TriangleMesh>
Error_code make_indexed_disk(const TriangleMesh& tm,
                             typename boost::graph_traits<TriangleMesh>::halfedge_descriptor bhd,
                             Indexed_disk<TriangleMesh>& disk)
{
  typedef boost::graph_traits<TriangleMesh>                  GT;
  typedef typename GT::vertex_descriptor                     vertex_descriptor;
  typedef typename GT::halfedge_descriptor                   halfedge_descriptor;
  typedef typename GT::face_descriptor                       face_descriptor;

  disk = Indexed_disk<TriangleMesh>();
  if(faces(tm).first == faces(tm).second)
    return ERROR_EMPTY_MESH;
  if(!CGAL::is_valid_polygon_mesh(tm))
    return ERROR_NON_MANIFOLD;
  if(!CGAL::is_triangle_mesh(tm))
    return ERROR_NON_TRIANGULAR_MESH;

  auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  const std::size_t none = std::size_t(-1);
  for(vertex_descriptor v : vertices(tm))
  {
    put(vid, v, disk.vertices.size());
    disk.vertices.push_back(v);
  }
  const std::size_t nv = disk.vertices.size();
  disk.on_border.assign(nv, 0);

  for(face_descriptor f : faces(tm))
  {
    halfedge_descriptor h = halfedge(f, tm);
    disk.faces.push_back({ get(vid, source(h, tm)), get(vid, target(h, tm)), get(vid, target(next(h, tm), tm)) });
  }

  // Border cycles; a vertex with two incoming border halfedges is a pinched (non-manifold) vertex.
  std::vector<char> border_seen(nv, 0);
  std::size_t n_border_cycles = 0, n_border_halfedges = 0;
  halfedge_descriptor first_border = GT::null_halfedge();
  for(halfedge_descriptor h : halfedges(tm))
  {
    if(!is_border(h, tm)) continue;
    ++n_border_halfedges;
    const std::size_t t = get(vid, target(h, tm));
    if(border_seen[t]) return ERROR_NON_MANIFOLD;
    border_seen[t] = 1;
    if(first_border == GT::null_halfedge()) first_border = h;
  }
  if(n_border_halfedges == 0)
    return ERROR_NOT_A_DISK; // closed
  {
    // count cycles
    std::vector<char> visited(nv, 0);
    for(halfedge_descriptor h : halfedges(tm))
    {
      if(!is_border(h, tm)) continue;
      const std::size_t t = get(vid, target(h, tm));
      if(visited[t]) continue;
      ++n_border_cycles;
      halfedge_descriptor c = h;
      std::size_t guard = 0;
      do { visited[get(vid, target(c, tm))] = 1; c = next(c, tm); } while(c != h && ++guard <= n_border_halfedges);
    }
  }
  if(n_border_cycles != 1)
    return ERROR_NOT_A_DISK;

  if(bhd == GT::null_halfedge())
    bhd = first_border;
  else if(!is_border(bhd, tm))
    return ERROR_WRONG_PARAMETER;

  // isolated vertices and connectivity (BFS over faces)
  for(vertex_descriptor v : vertices(tm))
    if(halfedge(v, tm) == GT::null_halfedge())
      return ERROR_NOT_A_DISK;
  {
    std::size_t nf = disk.faces.size();
    auto fseen = get(CGAL::dynamic_face_property_t<bool>(), tm);
    for(face_descriptor f : faces(tm)) put(fseen, f, false);
    std::vector<face_descriptor> stack(1, *faces(tm).first);
    put(fseen, stack.back(), true);
    std::size_t reached = 1;
    while(!stack.empty())
    {
      face_descriptor f = stack.back(); stack.pop_back();
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
      {
        halfedge_descriptor o = opposite(h, tm);
        if(is_border(o, tm)) continue;
        face_descriptor g = face(o, tm);
        if(!get(fseen, g)) { put(fseen, g, true); ++reached; stack.push_back(g); }
      }
    }
    if(reached != nf)
      return ERROR_NOT_A_DISK;
    // Euler characteristic of a disk is 1
    const long ne = static_cast<long>(num_halfedges(tm) / 2);
    if(static_cast<long>(nv) - ne + static_cast<long>(nf) != 1)
      return ERROR_NOT_A_DISK;
  }

  // border with the interior on the left: walk the border halfedges backwards
  std::vector<std::size_t> cyc;
  halfedge_descriptor c = bhd;
  do { cyc.push_back(get(vid, target(c, tm))); c = next(c, tm); } while(c != bhd);
  disk.border.assign(cyc.rbegin(), cyc.rend());
  for(std::size_t b : disk.border) disk.on_border[b] = 1;
  (void)none;
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
