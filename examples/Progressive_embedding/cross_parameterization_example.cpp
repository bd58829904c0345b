// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// A map between two triangulations of one disk-shaped surface with matched landmarks: every vertex of A
// located on B (a face of B and barycentric coordinates), B's colors carried over to A, and the two certified
// planar maps written as OFF files (z = 0).
//
// Usage: cross_parameterization_example [A.off [B.off]]; without B, B is A remeshed isotropically (another
// triangulation of the same surface), so that the error of the map can be measured.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Progressive_embedding/cross_parameterization.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace PE = CGAL::Progressive_embedding;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef CGAL::Exact_predicates_inexact_constructions_kernel   K;
typedef CGAL::Surface_mesh<K::Point_3>                        Mesh;
typedef Mesh::Vertex_index                                    Vertex;

int main(int argc, char** argv)
{
  const std::string file_a = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/mushroom.off");
  Mesh a, b;
  if(!CGAL::IO::read_polygon_mesh(file_a, a) || is_empty(a))
  {
    std::cerr << "cannot read " << file_a << std::endl;
    return EXIT_FAILURE;
  }
  if(argc > 2)
  {
    if(!CGAL::IO::read_polygon_mesh(argv[2], b) || is_empty(b))
    {
      std::cerr << "cannot read " << argv[2] << std::endl;
      return EXIT_FAILURE;
    }
  }
  else
  {
    b = a;
    double mean = 0;
    for(auto e : edges(b)) mean += PMP::edge_length(e, b);
    PMP::isotropic_remeshing(faces(b), 1.3 * mean / double(num_edges(b)), b, CGAL::parameters::number_of_iterations(3));
    b.collect_garbage();
  }

  // five landmarks: interior vertices of A spread along its vertex list, each with the nearest vertex of B
  std::vector<Vertex> interior_a;
  for(Vertex v : a.vertices()) if(!a.is_border(v)) interior_a.push_back(v);
  std::vector<std::pair<Vertex, Vertex> > landmarks;
  for(std::size_t k = 1; k <= 5 && !interior_a.empty(); ++k)
  {
    const Vertex va = interior_a[k * interior_a.size() / 6];
    Vertex best;
    double d = std::numeric_limits<double>::infinity();
    for(Vertex vb : b.vertices())
      if(!b.is_border(vb) && CGAL::squared_distance(a.point(va), b.point(vb)) < d)
      {
        d = CGAL::squared_distance(a.point(va), b.point(vb));
        best = vb;
      }
    landmarks.emplace_back(va, best);
  }

  // the map: where each vertex of A lies on B, and the two planar maps it is made of
  auto location = a.add_property_map<Vertex, PE::Cross_location<Mesh> >("v:cross_location").first;
  Mesh plane_a, plane_b;
  PE::Cross_parameterization_statistics stats;
  const PE::Error_code ec = PE::cross_parameterization(a, b, landmarks, location,
                              PE::parameters::planar_maps(std::make_pair(&plane_a, &plane_b),
                                PE::parameters::statistics(&stats)));
  if(ec != PE::OK)
  {
    std::cerr << "cross_parameterization: " << PE::get_error_message(ec) << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "A: " << num_vertices(a) << " vertices, B: " << num_vertices(b) << " vertices, " << landmarks.size()
            << " landmarks, each exactly on its partner: " << (stats.landmarks_exact ? "yes" : "no") << "\n"
            << "A's map: " << stats.report_a.summary() << "\nB's map: " << stats.report_b.summary() << "\n";

  // B's colors (red to blue along x) carried over to A through the map
  const CGAL::Bbox_3 box = PMP::bbox(b);
  auto color_b = b.add_property_map<Vertex, CGAL::IO::Color>("v:color").first;
  for(Vertex v : b.vertices())
  {
    const double t = (b.point(v).x() - box.xmin()) / (box.xmax() - box.xmin());
    color_b[v] = CGAL::IO::Color((unsigned char)(255 * (1 - t)), 0, (unsigned char)(255 * t));
  }
  auto color_a = a.add_property_map<Vertex, CGAL::IO::Color>("v:color").first;
  PE::transfer_vertex_property(a, b, location, color_b, color_a);

  // when B is another triangulation of A's surface: how far each vertex of A lands from where it is
  const CGAL::Bbox_3 box_a = PMP::bbox(a);
  const double diagonal = std::sqrt(CGAL::square(box_a.xmax() - box_a.xmin()) + CGAL::square(box_a.ymax() - box_a.ymin()) +
                                    CGAL::square(box_a.zmax() - box_a.zmin()));
  double sum = 0;
  for(Vertex v : a.vertices())
    sum += std::sqrt(CGAL::squared_distance(a.point(v), PMP::construct_point(location[v], b))) / diagonal;
  std::cout << "mean distance between a vertex of A and its image on B: " << 100 * sum / double(num_vertices(a))
            << "% of the bounding-box diagonal\n";

  const bool written = CGAL::IO::write_polygon_mesh("cross_a_colored.off", a,
                                                    CGAL::parameters::vertex_color_map(color_a).stream_precision(17)) &&
                       CGAL::IO::write_polygon_mesh("cross_map_a.off", plane_a, CGAL::parameters::stream_precision(17)) &&
                       CGAL::IO::write_polygon_mesh("cross_map_b.off", plane_b, CGAL::parameters::stream_precision(17));
  std::cout << (written ? "wrote cross_a_colored.off, cross_map_a.off and cross_map_b.off"
                        : "cannot write the output files") << std::endl;
  return (written && stats.report_a.is_valid() && stats.report_b.is_valid()) ? EXIT_SUCCESS : EXIT_FAILURE;
}
