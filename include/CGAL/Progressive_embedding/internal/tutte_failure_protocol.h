// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_FAILURE_PROTOCOL_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_FAILURE_PROTOCOL_H

// The Tutte-failure protocol (the paper's Thingi10k test) that `pe thingi`, the benchmarks and the
// tests run on closed genus-0 meshes: remove one face chosen by a seed, pin its three vertices; and
// the constrained-map protocol's wider cut around the same face.

#include <CGAL/Progressive_embedding/Error_code.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstddef>
#include <random>
#include <set>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// The face removed by the Tutte-failure protocol: seed 0 -> the last face, seed s > 0 ->
// uniform_int_distribution<size_t>(0, F-1) drawn once from mt19937(s).
inline std::size_t thingi_face_index(std::size_t number_of_faces, unsigned seed)
{
  if(seed == 0) return number_of_faces - 1;
  std::mt19937 gen(seed);
  std::uniform_int_distribution<std::size_t> dist(0, number_of_faces - 1);
  return dist(gen);
}

// Applies the Tutte-failure protocol's cut to a closed mesh: removes the face and
// returns its three vertices in the order of vertices_around_face(halfedge(f)),
// to be pinned at (0,0), (1/2, sqrt(3)/2), (1,0). The face index counts faces(m) in order.
template <class Mesh>
Error_code thingi_cut(Mesh& m, unsigned seed,
                      std::array<typename boost::graph_traits<Mesh>::vertex_descriptor, 3>& pinned)
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor fd;
  std::vector<fd> F(faces(m).first, faces(m).second);
  if(F.empty()) return ERROR_EMPTY_MESH;
  if(!CGAL::is_closed(m)) return ERROR_NOT_A_DISK; // the protocol needs a closed mesh
  if(!CGAL::is_triangle_mesh(m)) return ERROR_NON_TRIANGULAR_MESH;
  fd f = F[thingi_face_index(F.size(), seed)];
  int k = 0;
  for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) pinned[k++] = v;
  CGAL::Euler::remove_face(halfedge(f, m), m);
  return OK;
}

// The constrained-map protocol's cut of a closed mesh: removes the Tutte-failure protocol's face for
// `seed` and every face sharing a vertex with it (a wider hole than thingi_cut(): no border vertex
// of degree 2), then collects the garbage (a Surface_mesh).
template <class Mesh>
void remove_protocol_face_star(Mesh& m, unsigned seed)
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor fd;
  std::vector<fd> F(faces(m).first, faces(m).second);
  if(F.empty()) return;
  const fd f = F[thingi_face_index(F.size(), seed)];
  std::set<fd> doomed;
  for(auto v : CGAL::vertices_around_face(halfedge(f, m), m))
    for(fd g : CGAL::faces_around_target(halfedge(v, m), m))
      if(g != boost::graph_traits<Mesh>::null_face()) doomed.insert(g);
  for(fd g : doomed) CGAL::Euler::remove_face(halfedge(g, m), m);
  m.collect_garbage();
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_FAILURE_PROTOCOL_H
