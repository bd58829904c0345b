// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Repairs a broken double-precision Tutte map with progressive embedding.
//
// The input is the Tutte-failure protocol of the package (the paper's Thingi10k test):
// a closed genus-0 mesh with its last face removed, that face's vertices pinned on a
// triangle, uniform Tutte in double. On libcgal-demo's bull.off the map has flipped and
// degenerate faces; progressive_embedding() makes it valid, keeping the border bit-exactly.
//
// Usage: progressive_embedding_example [closed_mesh.off [out.obj]]   (default: meshes/bull.off)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/IO/OBJ_with_uv.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace PE = CGAL::Progressive_embedding;

typedef CGAL::Exact_predicates_inexact_constructions_kernel   K;
typedef CGAL::Surface_mesh<K::Point_3>                        Mesh;
typedef Mesh::Vertex_index                                    vertex_descriptor;
typedef Mesh::Face_index                                      face_descriptor;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bull.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_closed(mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a closed triangle mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // cut the mesh open: remove its last face and pin that face's vertices (clockwise)
  const face_descriptor f = *std::prev(faces(mesh).end());
  std::vector<vertex_descriptor> pinned;
  for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, mesh), mesh)) pinned.push_back(v);
  CGAL::Euler::remove_face(halfedge(f, mesh), mesh);

  auto uvm = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  uvm[pinned[0]] = K::Point_2(0, 0);
  uvm[pinned[1]] = K::Point_2(0.5, std::sqrt(3.) / 2);
  uvm[pinned[2]] = K::Point_2(1, 0);

  // uniform Tutte in double, with the border as given in the uv map
  PE::Error_code ec = PE::tutte_embedding(mesh, Mesh::null_halfedge(), uvm,
                                          PE::parameters::border_shape(PE::Border_shape::FIXED));
  if(ec != PE::OK)
  {
    std::cerr << "tutte_embedding: " << PE::get_error_message(ec) << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "double Tutte map:      " << PE::check_embedding(mesh, uvm).summary() << std::endl;

  // repair it; the statistics receive what was done and the certificate of the output
  PE::Progressive_embedding_statistics stats;
  ec = PE::progressive_embedding(mesh, uvm, PE::parameters::statistics(&stats));
  std::cout << "progressive embedding: " << PE::get_error_message(ec) << " (invalid faces before " << stats.invalid_faces_before
            << ", collapses " << stats.collapses << ", " << stats.seconds_total << " s)" << std::endl;
  if(ec != PE::OK)
    return EXIT_FAILURE;
  std::cout << "repaired map:          " << stats.report.summary() << std::endl;

  if(argc > 2 && PE::IO::write_OBJ_with_uv(std::string(argv[2]), mesh, uvm) != PE::OK)
  {
    std::cerr << "cannot write " << argv[2] << std::endl;
    return EXIT_FAILURE;
  }
  return stats.report.is_valid() ? EXIT_SUCCESS : EXIT_FAILURE;
}
