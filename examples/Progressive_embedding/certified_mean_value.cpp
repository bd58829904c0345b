// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// The two-line swap in a CGAL program: the user's mean value parameterizer is wrapped by
// Certified_parameterizer_3, which keeps its map when it is certified and repairs it otherwise.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Progressive_embedding/Certified_parameterizer_3.h>   // swap, line 1
#include <CGAL/Progressive_embedding/check_embedding.h>

#include <cstdlib>
#include <iostream>
#include <string>

namespace PE = CGAL::Progressive_embedding;
namespace SMP = CGAL::Surface_mesh_parameterization;

typedef CGAL::Exact_predicates_inexact_constructions_kernel   K;
typedef CGAL::Surface_mesh<K::Point_3>                        Mesh;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bull.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh))
  {
    std::cerr << "cannot read " << filename << std::endl;
    return EXIT_FAILURE;
  }
  if(CGAL::is_closed(mesh)) // cut a closed mesh open by removing one face
    CGAL::Euler::remove_face(halfedge(*faces(mesh).begin(), mesh), mesh);
  const auto bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  auto uvm = mesh.add_property_map<Mesh::Vertex_index, K::Point_2>("v:uv").first;

  // before: SMP::Mean_value_coordinates_parameterizer_3<Mesh> parameterizer;
  PE::Certified_parameterizer_3<Mesh, SMP::Mean_value_coordinates_parameterizer_3<Mesh> > parameterizer; // swap, line 2
  const SMP::Error_code status = SMP::parameterize(mesh, parameterizer, bhd, uvm);

  const PE::Embedding_report report = PE::check_embedding(mesh, uvm);
  std::cout << SMP::get_error_message(status)
            << (parameterizer.repaired() ? " (mean value map repaired)" : " (mean value map kept)")
            << "; certificate: " << report.summary() << std::endl;
  return (status == SMP::OK && report.is_valid()) ? EXIT_SUCCESS : EXIT_FAILURE;
}
