// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// The package on an OpenMesh mesh: OpenMesh reads the file, the map is computed on the mesh itself
// through CGAL's graph traits for OpenMesh (Tutte, certified; repaired by progressive embedding if
// invalid; optimized), stored in OpenMesh's own texture coordinates and written by OpenMesh.

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>

#include <cstdlib>
#include <iostream>
#include <string>

namespace PE = CGAL::Progressive_embedding;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

// double precision points and texture coordinates (OpenMesh's defaults are float)
struct Traits : public OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
  typedef OpenMesh::Vec2d TexCoord2D;
  VertexAttributes(OpenMesh::Attributes::TexCoord2D | OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::PrevHalfedge);
};
typedef OpenMesh::TriMesh_ArrayKernelT<Traits> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;

// OpenMesh's texture coordinates as the uv map of the package
struct Texcoord_map
{
  typedef vertex_descriptor key_type;
  typedef K::Point_2 value_type;
  typedef value_type reference;
  typedef boost::read_write_property_map_tag category;
  Mesh* mesh;
  friend value_type get(const Texcoord_map& m, key_type v)
  { const Mesh::TexCoord2D& t = m.mesh->texcoord2D(v); return value_type(t[0], t[1]); }
  friend void put(const Texcoord_map& m, key_type v, const value_type& p)
  { m.mesh->set_texcoord2D(v, Mesh::TexCoord2D(p.x(), p.y())); }
};

int main(int argc, char** argv)
{
  const std::string in = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/bull.off");
  const std::string out = (argc > 2) ? argv[2] : "openmesh_example.obj";
  Mesh mesh;
  if(!OpenMesh::IO::read_mesh(mesh, in) || mesh.n_faces() == 0)
  {
    std::cerr << "cannot read " << in << std::endl;
    return EXIT_FAILURE;
  }
  if(CGAL::is_closed(mesh)) // cut a closed mesh open by removing one face
  {
    CGAL::Euler::remove_face(halfedge(*faces(mesh).begin(), mesh), mesh);
    mesh.garbage_collection();
  }

  const Texcoord_map uvm{ &mesh };
  const auto no_border = boost::graph_traits<Mesh>::null_halfedge(); // the mesh's only border
  PE::Error_code ec = PE::tutte_embedding(mesh, no_border, uvm, PE::parameters::border_shape(PE::Border_shape::CIRCLE));
  if(ec != PE::OK)
  {
    std::cerr << "Tutte: " << PE::get_error_message(ec) << std::endl;
    return EXIT_FAILURE;
  }
  PE::Embedding_report report = PE::check_embedding(mesh, uvm);
  std::cout << mesh.n_vertices() << " vertices; Tutte map: " << report.summary() << std::endl;
  if(!report.is_valid() && (ec = PE::progressive_embedding(mesh, uvm)) != PE::OK)
  {
    std::cerr << "progressive embedding: " << PE::get_error_message(ec) << std::endl;
    return EXIT_FAILURE;
  }
  PE::Optimization_statistics stats;
  ec = PE::optimize_distortion(mesh, uvm, PE::parameters::optimization_statistics(&stats));
  report = PE::check_embedding(mesh, uvm);
  std::cout << "optimized (" << stats.iterations << " iterations): " << report.summary() << std::endl;

  if(!OpenMesh::IO::write_mesh(mesh, out, OpenMesh::IO::Options::VertexTexCoord, 17))
  {
    std::cerr << "cannot write " << out << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "written " << out << std::endl;
  return (ec == PE::OK || ec == PE::ERROR_BUDGET_EXHAUSTED) && report.is_valid() ? EXIT_SUCCESS : EXIT_FAILURE;
}
