// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Test meshes shared by the constrained-map tests: a polar annulus, a grid with holes (a grid disk
// when none is removed), holes cut around chosen vertices, far-apart vertices, two counts, and a fan whose
// uv map wraps around a border vertex.
// Templated on the mesh (any MutableFaceGraph: Surface_mesh, Polyhedron_3).

#ifndef CGAL_PROGRESSIVE_EMBEDDING_TEST_CONSTRAINED_MESH_FIXTURES_H
#define CGAL_PROGRESSIVE_EMBEDDING_TEST_CONSTRAINED_MESH_FIXTURES_H

#include "../test_util.h"

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace pe_test {

template <class Mesh>
using Mesh_point_3 = typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;

// A polar annulus: `rings` circles of radii 1 .. 2 with `sectors` vertices each, a bump in z.
template <class Mesh>
void make_annulus(Mesh& m, std::size_t rings, std::size_t sectors, double z_bump = 0.3)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  typedef Mesh_point_3<Mesh> P3;
  auto vpm = get(CGAL::vertex_point, m);
  std::vector<vd> V;
  for(std::size_t i = 0; i < rings; ++i)
    for(std::size_t j = 0; j < sectors; ++j)
    {
      const double r = 1 + double(i) / double(rings - 1), t = 2 * CGAL_PI * double(j) / double(sectors);
      V.push_back(add_vertex(m));
      put(vpm, V.back(), P3(r * std::cos(t), r * std::sin(t), z_bump * std::sin(2 * t) * (r - 1)));
    }
  auto id = [&](std::size_t i, std::size_t j) { return V[i * sectors + (j % sectors)]; };
  for(std::size_t i = 0; i + 1 < rings; ++i)
    for(std::size_t j = 0; j < sectors; ++j)
    {
      CGAL::Euler::add_face(std::vector<vd>{ id(i, j), id(i + 1, j + 1), id(i, j + 1) }, m);
      CGAL::Euler::add_face(std::vector<vd>{ id(i, j), id(i + 1, j), id(i + 1, j + 1) }, m);
    }
}

// A grid of nx x ny unit cells without the cells listed in `removed`; 3D point (x, y, x y / 10).
// Vertex (x, y) is the (y (nx + 1) + x)-th vertex added.
template <class Mesh>
void make_grid_with_holes(Mesh& m, int nx, int ny, const std::set<std::pair<int, int> >& removed)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  typedef Mesh_point_3<Mesh> P3;
  auto vpm = get(CGAL::vertex_point, m);
  std::vector<vd> V;
  for(int y = 0; y <= ny; ++y)
    for(int x = 0; x <= nx; ++x) { V.push_back(add_vertex(m)); put(vpm, V.back(), P3(x, y, 0.1 * x * y)); }
  auto id = [&](int x, int y) { return V[std::size_t(y * (nx + 1) + x)]; };
  for(int y = 0; y < ny; ++y)
    for(int x = 0; x < nx; ++x)
    {
      if(removed.count(std::make_pair(x, y))) continue;
      CGAL::Euler::add_face(std::vector<vd>{ id(x, y), id(x + 1, y), id(x + 1, y + 1) }, m);
      CGAL::Euler::add_face(std::vector<vd>{ id(x, y), id(x + 1, y + 1), id(x, y + 1) }, m);
    }
}

// Removes the faces around each of `centers` (their 1-rings): one hole per center.
template <class Mesh>
void cut_one_rings(Mesh& m, const std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& centers)
{
  for(auto c : centers)
  {
    std::vector<typename boost::graph_traits<Mesh>::face_descriptor> ring;
    for(auto f : CGAL::faces_around_target(halfedge(c, m), m)) if(f != boost::graph_traits<Mesh>::null_face()) ring.push_back(f);
    for(auto f : ring) CGAL::Euler::remove_face(halfedge(f, m), m);
  }
}

// `count` vertices far apart: the first one, then each time the farthest from those chosen.
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> far_apart_vertices(const Mesh& m, int count)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  std::vector<vd> c(1, *vertices(m).begin());
  for(int k = 1; k < count; ++k)
  {
    vd best = c[0];
    double bd = -1;
    for(vd v : vertices(m))
    {
      double d = std::numeric_limits<double>::infinity();
      for(vd w : c) d = (std::min)(d, CGAL::to_double(CGAL::squared_distance(get(CGAL::vertex_point, m, v), get(CGAL::vertex_point, m, w))));
      if(d > bd) { bd = d; best = v; }
    }
    c.push_back(best);
  }
  return c;
}

// The triangle fan of pe_test::wrapped_fan_polygon(angle, steps) (polygon_fixtures.h: the center (0, 0), then the
// points at angles t_k = angle k / steps on the spiral of radius 1 + t / 10), refined by `rings` rings: the
// center, then on every spoke k the points i / rings of the way out (i = 1 .. rings); the faces (center, ring 1)
// and two triangles per quad between rings. Returns the uv of the vertices in the order they were added (the
// center first): the fan itself, a map that is locally injective and whose border winds `angle` around the center,
// a border vertex. The 3D point is (u, v, t i / (5 rings)): lifted with the angle, so that the surface does not
// overlap itself in 3D.
template <class Mesh>
std::vector<std::array<double, 2> > make_wrapped_fan_mesh(Mesh& m, double angle, std::size_t steps, std::size_t rings)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  typedef Mesh_point_3<Mesh> P3;
  auto vpm = get(CGAL::vertex_point, m);
  std::vector<std::array<double, 2> > uv;
  std::vector<vd> V;
  V.push_back(add_vertex(m));
  put(vpm, V.back(), P3(0, 0, 0));
  uv.push_back(std::array<double, 2>{{ 0., 0. }});
  for(std::size_t i = 1; i <= rings; ++i)
    for(std::size_t k = 0; k <= steps; ++k)
    {
      const double t = angle * double(k) / double(steps), r = 1 + t / 10, f = double(i) / double(rings);
      const double x = f * (r * std::cos(t)), y = f * (r * std::sin(t)); // the outer ring: the polygon's points exactly
      V.push_back(add_vertex(m));
      put(vpm, V.back(), P3(x, y, t * f / 5));
      uv.push_back(std::array<double, 2>{{ x, y }});
    }
  auto id = [&](std::size_t i, std::size_t k) { return i == 0 ? V[0] : V[1 + (i - 1) * (steps + 1) + k]; };
  for(std::size_t k = 0; k < steps; ++k)
  {
    CGAL::Euler::add_face(std::vector<vd>{ id(0, 0), id(1, k), id(1, k + 1) }, m);
    for(std::size_t i = 1; i < rings; ++i)
    {
      CGAL::Euler::add_face(std::vector<vd>{ id(i, k), id(i + 1, k), id(i + 1, k + 1) }, m);
      CGAL::Euler::add_face(std::vector<vd>{ id(i, k), id(i + 1, k + 1), id(i, k + 1) }, m);
    }
  }
  return uv;
}

// by iteration (num_vertices of a Surface_mesh counts removed vertices)
template <class Mesh>
std::size_t count_vertices(const Mesh& m) { return static_cast<std::size_t>(std::distance(vertices(m).begin(), vertices(m).end())); }

template <class Mesh>
std::size_t count_border_cycles(const Mesh& m)
{
  std::set<typename boost::graph_traits<Mesh>::halfedge_descriptor> seen;
  std::size_t k = 0;
  for(auto h : halfedges(m))
  {
    if(!is_border(h, m) || seen.count(h)) continue;
    ++k;
    for(auto g : CGAL::halfedges_around_face(h, m)) seen.insert(g);
  }
  return k;
}

} // namespace pe_test

#endif // CGAL_PROGRESSIVE_EMBEDDING_TEST_CONSTRAINED_MESH_FIXTURES_H
