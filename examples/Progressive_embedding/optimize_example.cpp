// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Random interior positions inside a circular border, repaired by progressive embedding,
// then optimized for symmetric Dirichlet distortion without ever leaving the valid maps.
// Usage: optimize_example [disk.off]   (default: libcgal-demo's meshes/mushroom.off)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>

#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

namespace PE = CGAL::Progressive_embedding;

typedef CGAL::Exact_predicates_inexact_constructions_kernel   K;
typedef CGAL::Surface_mesh<K::Point_3>                        Mesh;
typedef Mesh::Vertex_index                                    vertex_descriptor;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/mushroom.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh))
  {
    std::cerr << "cannot read " << filename << std::endl;
    return EXIT_FAILURE;
  }
  auto uvm = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;

  // border on the unit circle (Tutte places it), interior scrambled at random inside it
  if(PE::tutte_embedding(mesh, Mesh::null_halfedge(), uvm, PE::parameters::border_shape(PE::Border_shape::CIRCLE)) != PE::OK)
    return EXIT_FAILURE;
  std::mt19937 gen(1);
  std::uniform_real_distribution<double> U(-0.5, 0.5);
  for(vertex_descriptor v : mesh.vertices())
    if(!mesh.is_border(v)) uvm[v] = K::Point_2(U(gen), U(gen));

  PE::Progressive_embedding_statistics ps;
  const PE::Error_code e1 = PE::progressive_embedding(mesh, uvm, PE::parameters::statistics(&ps));
  std::cout << "progressive embedding: " << PE::get_error_message(e1) << "; " << ps.report.summary() << std::endl;
  if(e1 != PE::OK) return EXIT_FAILURE;

  // optimize: border fixed (bit-exact), every accepted step certified
  PE::Optimization_statistics os;
  const PE::Error_code e2 = PE::optimize_distortion(mesh, uvm, PE::parameters::optimization_statistics(&os));
  std::cout << "optimize_distortion: " << PE::get_error_message(e2) << " after " << os.iterations << " iterations ("
            << os.seconds << " s); mean symmetric Dirichlet " << os.energy_before << " -> " << os.energy_after
            << "; " << os.report.summary() << std::endl;
  return (e2 == PE::OK && os.report.is_valid()) ? EXIT_SUCCESS : EXIT_FAILURE;
}
