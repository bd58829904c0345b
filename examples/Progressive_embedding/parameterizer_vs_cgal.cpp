// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// The drop-in parameterizer next to CGAL's own Barycentric_mapping_parameterizer_3 on the
// Tutte-failure protocol's bull.off seed 0 (a closed mesh with its last face removed):
// CGAL returns OK on a map with flipped faces; Progressive_embedding_parameterizer_3
// returns OK only with a certified map.
// Usage: parameterizer_vs_cgal [closed_mesh.off]   (default: libcgal-demo's meshes/bull.off)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>

#include <CGAL/Progressive_embedding/Progressive_embedding_parameterizer_3.h>
#include <CGAL/Progressive_embedding/check_embedding.h>

#include <cstdlib>
#include <iostream>
#include <string>

namespace PE = CGAL::Progressive_embedding;
namespace SMP = CGAL::Surface_mesh_parameterization;

typedef CGAL::Exact_predicates_inexact_constructions_kernel   K;
typedef CGAL::Surface_mesh<K::Point_3>                        Mesh;
typedef Mesh::Vertex_index                                    vertex_descriptor;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bull.off");
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || !CGAL::is_closed(mesh))
  {
    std::cerr << "cannot read a closed mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  // cut the closed mesh open: remove its last face (the protocol's seed 0)
  Mesh::Face_index last;
  for(Mesh::Face_index f : mesh.faces()) last = f;
  CGAL::Euler::remove_face(mesh.halfedge(last), mesh);
  const auto bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  auto uvm = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;

  // CGAL's Tutte parameterizer (circular border by arc length)
  const SMP::Error_code e1 = SMP::parameterize(mesh, SMP::Barycentric_mapping_parameterizer_3<Mesh>(), bhd, uvm);
  const PE::Embedding_report r1 = PE::check_embedding(mesh, uvm);
  std::cout << "CGAL Barycentric_mapping_parameterizer_3: " << SMP::get_error_message(e1) << "; certificate: " << r1.summary() << std::endl;

  // the drop-in replacement: same border, Tutte, then progressive embedding when needed
  PE::Progressive_embedding_parameterizer_3<Mesh> parameterizer;
  const SMP::Error_code e2 = SMP::parameterize(mesh, parameterizer, bhd, uvm);
  const PE::Embedding_report r2 = PE::check_embedding(mesh, uvm);
  std::cout << "Progressive_embedding_parameterizer_3:    " << SMP::get_error_message(e2)
            << (parameterizer.repaired() ? " (Tutte map repaired" : " (Tutte map already valid")
            << (parameterizer.optimized() ? ", then optimized)" : ")")
            << "; certificate: " << r2.summary() << std::endl;

  // ours says OK only with a certified map
  return (e2 == SMP::OK && r2.is_valid()) ? EXIT_SUCCESS : EXIT_FAILURE;
}
