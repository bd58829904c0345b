// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Built against the installed package by the find_package test: the Tutte map of a
// generated disk (a polar grid), certified.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>

#include <cmath>
#include <cstdlib>
#include <vector>
#include <iostream>

namespace PE = CGAL::Progressive_embedding;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef Mesh::Vertex_index                                  vertex_descriptor;

int main()
{
  // a polar grid: a center vertex and 4 rings of 12 vertices on a paraboloid
  Mesh m;
  const int rings = 4, n = 12;
  std::vector<std::vector<vertex_descriptor> > R(rings + 1);
  const vertex_descriptor center = m.add_vertex(K::Point_3(0, 0, 0));
  for(int r = 1; r <= rings; ++r)
    for(int k = 0; k < n; ++k)
    {
      const double t = 2 * CGAL_PI * (k + 0.5 * r) / n;
      R[r].push_back(m.add_vertex(K::Point_3(r * std::cos(t), r * std::sin(t), 0.1 * r * r)));
    }
  for(int k = 0; k < n; ++k)
    m.add_face(center, R[1][k], R[1][(k + 1) % n]);
  for(int r = 1; r < rings; ++r)
    for(int k = 0; k < n; ++k)
    {
      m.add_face(R[r][k], R[r + 1][k], R[r + 1][(k + 1) % n]);
      m.add_face(R[r][k], R[r + 1][(k + 1) % n], R[r][(k + 1) % n]);
    }
  auto uv = m.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  const PE::Error_code ec = PE::tutte_embedding(m, Mesh::null_halfedge(), uv,
                                                PE::parameters::border_shape(PE::Border_shape::CIRCLE));
  const PE::Embedding_report report = PE::check_embedding(m, uv);
  std::cout << "consumer: " << m.number_of_vertices() << " vertices, " << m.number_of_faces() << " faces; tutte_embedding: "
            << PE::get_error_name(ec) << "; " << report.summary() << std::endl;
  if(ec == PE::OK && report.is_valid())
    std::cout << "consumer: certified valid" << std::endl;
  return (ec == PE::OK && report.is_valid()) ? EXIT_SUCCESS : EXIT_FAILURE;
}
