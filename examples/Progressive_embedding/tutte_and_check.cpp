// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Tutte's embedding of a disk mesh, then its exact validity certificate.
// Usage: tutte_and_check [mesh.off]   (default: libcgal-demo's meshes/mushroom.off)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>

#include <cstdlib>
#include <iostream>
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

  // the uv map: any read-write property map whose value type is a Point_2;
  // its kernel's number type (here double) is the number type of the computation
  auto uvm = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;

  // border on the unit circle by arc length, uniform (Tutte) weights
  const PE::Error_code ec = PE::tutte_embedding(mesh, Mesh::null_halfedge(), uvm,
                                                PE::parameters::border_shape(PE::Border_shape::CIRCLE));
  if(ec != PE::OK)
  {
    std::cerr << "tutte_embedding: " << PE::get_error_message(ec) << std::endl;
    return EXIT_FAILURE;
  }

  // Tutte's theorem holds in exact arithmetic only: certify the double map with exact predicates
  const PE::Embedding_report report = PE::check_embedding(mesh, uvm);
  std::cout << filename << ": " << report.summary() << std::endl;
  return report.is_valid() ? EXIT_SUCCESS : EXIT_FAILURE;
}
