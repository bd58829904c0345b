// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Reads an OBJ file with texture coordinates (the disk is the mesh of the `vt` entries:
// seams are borders), certifies its uv map, draws it as SVG and writes it back with
// its seams and original `v` list.
//
// Usage: read_write_obj [in.obj [out.obj [out.svg]]]
// Without arguments, a Tutte map of libcgal-demo's meshes/mushroom.off is written to
// mushroom_uv.obj first and then read back.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/IO/OBJ_with_uv.h>
#include <CGAL/Progressive_embedding/IO/SVG.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace PE = CGAL::Progressive_embedding;

typedef CGAL::Exact_predicates_inexact_constructions_kernel   K;
typedef CGAL::Surface_mesh<K::Point_3>                        Mesh;
typedef Mesh::Vertex_index                                    vertex_descriptor;

int main(int argc, char** argv)
{
  std::string in_obj = (argc > 1) ? argv[1] : std::string();
  const std::string out_obj = (argc > 2) ? argv[2] : "uv_copy.obj";
  const std::string out_svg = (argc > 3) ? argv[3] : "uv.svg";

  if(in_obj.empty())
  {
    // make an input: Tutte map of mushroom.off, written as OBJ with vt
    Mesh m;
    const std::string off = CGAL::data_file_path("meshes/mushroom.off");
    if(!CGAL::IO::read_polygon_mesh(off, m)) { std::cerr << "cannot read " << off << std::endl; return EXIT_FAILURE; }
    auto uv = m.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
    if(PE::tutte_embedding(m, Mesh::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE)) != PE::OK)
      return EXIT_FAILURE;
    in_obj = "mushroom_uv.obj";
    if(PE::IO::write_OBJ_with_uv(in_obj, m, uv) != PE::OK) { std::cerr << "cannot write " << in_obj << std::endl; return EXIT_FAILURE; }
  }

  Mesh mesh;
  auto uvm = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  std::vector<std::size_t> vt_to_v;        // the surface vertex of each uv vertex: the seams
  std::vector<K::Point_3> positions;       // the `v` list of the file
  const PE::IO::OBJ_read_result r = PE::IO::read_OBJ_with_uv(in_obj, mesh, uvm, &vt_to_v, &positions);
  if(!r)
  {
    // malformed files are reported with the offending line, never a crash
    std::cerr << in_obj << ":" << r.line << ": " << r.message << " (" << PE::get_error_name(r.status) << ")" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << in_obj << ": " << r.number_of_positions << " v, " << r.number_of_texture_coordinates << " vt, "
            << r.number_of_faces << " faces" << std::endl;

  const PE::Embedding_report report = PE::check_embedding(mesh, uvm);
  std::cout << "uv map: " << report.summary() << std::endl;

  // the picture draws the certificate just printed
  PE::IO::SVG_options svg;
  svg.title = in_obj;
  // written with 17 significant digits: doubles round-trip bit-exactly
  if(PE::IO::write_OBJ_with_uv(out_obj, mesh, uvm, &vt_to_v, &positions) != PE::OK
     || PE::IO::write_SVG(out_svg, mesh, uvm, report, svg) != PE::OK)
  {
    std::cerr << "cannot write " << out_obj << " or " << out_svg << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << out_obj << " and " << out_svg << std::endl;
  return report.is_valid() ? EXIT_SUCCESS : EXIT_FAILURE;
}
