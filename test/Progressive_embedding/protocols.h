// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef PROGRESSIVE_EMBEDDING_TEST_PROTOCOLS_H
#define PROGRESSIVE_EMBEDDING_TEST_PROTOCOLS_H

// Test fixtures (not part of the installed package), shared by the tests, the `pe` tool and the
// benchmarks: the deep stacked triangulation, grid disks, the Tutte-failure protocol on closed
// genus-0 meshes (remove one face, pin its three vertices), and random initialization of a disk.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <random>
#include <set>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// Stacked triangulation of depth d: 3 + d vertices; the outer triangle is the border.
// Returns the three border vertices in the order of the initial face.
template <class Mesh>
std::array<typename boost::graph_traits<Mesh>::vertex_descriptor, 3>
make_stacked_triangulation(std::size_t depth, Mesh& m)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor hd;
  typedef typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point_3;
  auto vpm = get(CGAL::vertex_point, m);
  vd a = add_vertex(m), b = add_vertex(m), c = add_vertex(m);
  put(vpm, a, Point_3(0, 0, 0)); put(vpm, b, Point_3(1, 0, 0)); put(vpm, c, Point_3(0.5, 0.8, 0));
  std::vector<vd> tri = { a, b, c };
  auto f = CGAL::Euler::add_face(tri, m);
  hd h = halfedge(f, m);
  for(std::size_t k = 0; k < depth; ++k)
  {
    const Point_3 p = get(vpm, source(h, m)), q = get(vpm, target(h, m)), r = get(vpm, target(next(h, m), m));
    hd hc = CGAL::Euler::add_center_vertex(h, m); // hc points to the new center vertex
    put(vpm, target(hc, m), Point_3((p.x() + q.x() + r.x()) / 3, (p.y() + q.y() + r.y()) / 3, (p.z() + q.z() + r.z()) / 3));
    // The three children are the faces of the original edges h, e1, e2 (in face order);
    // descend into h, e2, e1, h, ... keeping h on the child's original (outer) edge.
    // With the corners pinned as in the Tutte-failure protocol, double Tutte flips
    // 3 faces at depth 40 and 49 at depth 80.
    (void)hc;
    const hd e1 = next(opposite(next(h, m), m), m);
    const hd e2 = next(opposite(next(e1, m), m), m);
    h = (k % 3 == 0) ? h : (k % 3 == 1 ? e2 : e1);
  }
  return { a, b, c };
}

// n x n grid of vertices on [0,1]^2 (z = 0), each square split along a diagonal.
template <class Mesh>
void make_grid_disk(std::size_t n, Mesh& m)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  typedef typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point_3;
  auto vpm = get(CGAL::vertex_point, m);
  std::vector<vd> V(n * n);
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
    {
      V[j * n + i] = add_vertex(m);
      put(vpm, V[j * n + i], Point_3(double(i) / (n - 1), double(j) / (n - 1), 0));
    }
  for(std::size_t j = 0; j + 1 < n; ++j)
    for(std::size_t i = 0; i + 1 < n; ++i)
    {
      vd a = V[j * n + i], b = V[j * n + i + 1], c = V[(j + 1) * n + i + 1], d = V[(j + 1) * n + i];
      std::vector<vd> t1 = { a, b, c }, t2 = { a, c, d };
      CGAL::Euler::add_face(t1, m);
      CGAL::Euler::add_face(t2, m);
    }
}

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

#endif
