// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// pe polygon: is a polygon simple, weakly self-overlapping or neither, and its triangulation
// (triangulate_self_overlapping_polygon_2()).

#include "cli.h"
#include "pe.h"

#include <CGAL/Progressive_embedding/check_immersion.h>
#include <CGAL/Progressive_embedding/triangulate_self_overlapping_polygon_2.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <array>
#include <iterator>
#include <vector>

namespace pe_tool {

int cmd_polygon(const Arguments& a)
{
  Run run(a);
  run.summary << "polygon " << a.positional[0] << ": ";
  std::vector<Point_2> points;
  int status = read_polygon(run, a.positional[0], points);
  if(status != EXIT_VALID) return status;
  run.result.add("output", a.positional[1]);
  run.result.add("vertices", points.size());
  run.summary << points.size() << " vertices, ";

  const Budget budget(a);
  PE::Polygon_triangulation_report rep;
  std::vector<std::array<std::size_t, 3> > triangles;
  const PE::Error_code ec = PE::triangulate_self_overlapping_polygon_2(points, std::back_inserter(triangles),
    PE::parameters::polygon_report(&rep, CGAL::parameters::maximum_running_time(budget.remaining())));
  // what the polygon is, also when it is refused
  const char* kind = ec == PE::OK ? (rep.simple ? "simple" : "weakly self-overlapping")
                   : ec == PE::ERROR_NOT_SELF_OVERLAPPING ? "neither simple nor weakly self-overlapping" : "unknown";
  run.result.add("kind", kind);
  run.result.add("rotation_number", static_cast<double>(rep.rotation_number));
  run.result.add("clockwise", rep.clockwise);
  run.result.add("simple", ec == PE::OK && rep.simple);
  run.result.add("self_overlapping", ec == PE::OK);
  run.result.add("path", ec != PE::OK ? "none" : rep.dynamic_program ? "shor-van-wyk" : "cdt");
  run.result.add("chords_stored", rep.chords_stored);
  run.result.add("triangulation_seconds", rep.seconds);
  if(ec != PE::OK)
  {
    std::string detail;
    if(ec == PE::ERROR_NOT_SELF_OVERLAPPING)
      detail = rep.rotation_number != 1 && rep.rotation_number != -1 && rep.rotation_number != 0
             ? "the polygon turns " + std::to_string(rep.rotation_number) + " times: it bounds no immersed disk "
               "(neither simple nor weakly self-overlapping)"
             : "the polygon is neither simple nor weakly self-overlapping: no immersed disk has it as border "
               "(a repeated consecutive vertex, a reversal, a figure-eight, ...)";
    if(ec == PE::ERROR_BORDER_TOO_SHORT)
      detail = "a polygon needs at least 3 vertices, the file has " + std::to_string(points.size());
    return run.fail(ec, "cannot triangulate '" + a.positional[0] + "'", detail);
  }
  run.summary << kind << (rep.clockwise ? " (clockwise)" : "") << ", " << triangles.size() << " triangles ("
              << (rep.dynamic_program ? "Shor-Van Wyk" : "constrained Delaunay") << ", "
              << seconds_string(rep.seconds) << "); ";

  // the triangulated disk as a mesh whose vertex i is point i (z = 0), its uv map the points themselves
  Input in;
  in.filename = a.positional[0];
  std::vector<Point_3> positions;
  positions.reserve(points.size());
  for(const Point_2& p : points) positions.emplace_back(p.x(), p.y(), 0);
  std::vector<std::vector<std::size_t> > faces;
  faces.reserve(triangles.size());
  for(const auto& t : triangles) faces.push_back({ t[0], t[1], t[2] });
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(positions, faces, in.mesh);
  in.uv = in.mesh.add_property_map<vertex_descriptor, Point_2>("v:pe_uv", Point_2(0, 0)).first;
  for(vertex_descriptor v : vertices(in.mesh)) in.uv[v] = points[std::size_t(v)];

  Picture picture;
  picture.color_by_distortion = false;
  picture.title = in.filename + ": " + kind + ", " + std::to_string(points.size()) + " vertices, "
                + std::to_string(triangles.size()) + " triangles";
  if(rep.simple)
  {
    run.result.add("immersion", false);
    return write_and_finish(run, in, a.positional[1], certify(in), a.get("--svg"), picture);
  }
  // not simple: the triangles overlap, the certificate is the immersion one, with the border
  // bit-exactly the polygon (walked counterclockwise, so backwards from point 0 if it is clockwise)
  std::vector<Point_2> border;
  const std::size_t n = points.size();
  for(std::size_t k = 0; k < n; ++k) border.push_back(points[rep.clockwise ? (n - k) % n : k]);
  const PE::Immersion_report ir = PE::check_immersion(in.mesh, in.uv, vertex_descriptor(0), border);
  run.result.add("immersion", ir.is_immersion());
  run.result.add("valid", false);
  run.result.add("flipped", ir.flipped);
  run.result.add("degenerate", ir.degenerate);
  run.result.add("winding_errors", ir.winding_errors);
  run.result.add("border_mismatches", ir.border_mismatches);
  run.result.add("border_angle_errors", ir.border_angle_errors);
  const int w = write_outputs(run, in, a.positional[1], a.get("--svg"), picture);
  if(w != EXIT_VALID) return w;
  run.result.add("written", true);
  run.summary << ir.summary() << ", border bit-exact " << (ir.border_mismatches == 0 ? "yes" : "NO");
  return run.finish(ir.is_immersion() && ir.border_mismatches == 0 ? EXIT_VALID : EXIT_INVALID);
}

} // namespace pe_tool
