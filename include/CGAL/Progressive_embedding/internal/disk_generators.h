// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_DISK_GENERATORS_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_DISK_GENERATORS_H

// Disks built from a size alone, for `pe generate`, the benchmarks and the tests: the deep stacked
// triangulation (a Tutte map that double precision breaks) and the grid disk.

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
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

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_DISK_GENERATORS_H
