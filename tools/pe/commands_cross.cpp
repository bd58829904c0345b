// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// pe cross: the location on B of every vertex of A through a cross-parameterization with matched
// landmarks (cross_parameterization()).

#include "cli.h"
#include "pe.h"

#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Progressive_embedding/cross_parameterization.h>
#include <CGAL/Progressive_embedding/IO/SVG.h>
#include <CGAL/IO/OBJ.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace pe_tool {

namespace {

typedef std::pair<vertex_descriptor, vertex_descriptor> Landmark;

// Reads `a_index b_index` lines (blank lines and `#` comments skipped); `lines[k]` is the line of landmark k.
int read_landmarks(Run& run, const std::string& filename, const Mesh& a, const Mesh& b,
                   std::vector<Landmark>& landmarks, std::vector<std::size_t>& lines)
{
  const std::string what = "cannot use the landmarks '" + filename + "'";
  const std::string problem = input_file_problem(filename);
  if(!problem.empty()) return run.fail(PE::ERROR_CANNOT_READ_FILE, what, problem);
  std::ifstream in(filename, std::ios::binary);
  const std::size_t na = a.number_of_vertices(), nb = b.number_of_vertices();
  std::string line;
  for(std::size_t lineno = 1; std::getline(in, line); ++lineno)
  {
    const std::string at = "line " + std::to_string(lineno) + ": ";
    if(line.size() > 4096) return run.fail(PE::ERROR_MALFORMED_FILE, what, at + "line too long");
    std::istringstream ls(line);
    std::vector<std::string> tokens;
    for(std::string t; tokens.size() < 3 && ls >> t; ) tokens.push_back(t);
    if(tokens.empty() || tokens[0][0] == '#') continue;
    std::string why;
    unsigned long long ia = 0, ib = 0;
    if(tokens.size() != 2) why = tokens.size() < 2 ? "one field" : "more than 2 fields";
    else if(!parse_count(tokens[0], 0, na - 1, ia, why)) why = "a_index " + why;
    else if(!parse_count(tokens[1], 0, nb - 1, ib, why)) why = "b_index " + why;
    if(!why.empty())
      return run.fail(PE::ERROR_MALFORMED_FILE, what, at + why + " (expected 'a_index b_index' with 0 <= a_index < " +
                      std::to_string(na) + " and 0 <= b_index < " + std::to_string(nb) + ")");
    landmarks.emplace_back(vertex_descriptor(static_cast<Mesh::size_type>(ia)), vertex_descriptor(static_cast<Mesh::size_type>(ib)));
    lines.push_back(lineno);
  }
  return EXIT_VALID;
}

// One panel of the picture: a planar map (a flat mesh, (u, v, 0)) drawn by write_SVG() with the certificate that
// cross_parameterization() made of it (the legend's counts; the map is not certified twice), its landmarks marked;
// its ids prefixed by `prefix` so that the two panels of one document keep them unique.
PE::Error_code cross_panel(Mesh& plane, const PE::Embedding_report& report, const std::vector<vertex_descriptor>& marked,
                           const std::string& title, const std::string& prefix, std::string& svg, double& width,
                           double& height)
{
  auto uv = plane.add_property_map<vertex_descriptor, Point_2>("v:pe_cross_picture", Point_2(0, 0)).first;
  for(vertex_descriptor v : plane.vertices()) uv[v] = Point_2(plane.point(v).x(), plane.point(v).y());
  PE::IO::SVG_options options;
  options.title = title;
  options.size = 700;
  std::ostringstream os;
  const PE::Error_code ec = PE::IO::write_SVG(os, plane, uv, report, options, PE::parameters::constrained_vertices(marked));
  if(ec != PE::OK) return ec;
  svg = os.str();
  svg.erase(0, svg.find("<svg")); // the XML declaration goes once, at the top of the document
  for(const std::string key : { "id=\"pe-", "url(#pe-" })
    for(std::size_t at = svg.find(key); at != std::string::npos; at = svg.find(key, at + key.size()))
      svg.insert(at + key.size(), prefix);
  auto attribute = [&](const std::string& name) {
    const std::size_t at = svg.find(" " + name + "=\"");
    if(at == std::string::npos) return 0.; // cannot happen: write_SVG() gives its size
    const std::size_t begin = at + name.size() + 3;
    return std::stod(svg.substr(begin, svg.find('"', begin) - begin));
  };
  width = attribute("width");
  height = attribute("height");
  return PE::OK;
}

// The picture of --svg: A's planar map on the left, B's on the right (both on the unit square), each drawn by
// write_SVG() with its certificate, the landmarks marked in both; `document` receives the SVG text.
int cross_picture(Run& run, const std::string& filename, Mesh& plane_a, Mesh& plane_b,
                  const PE::Cross_parameterization_statistics& st, const std::vector<Landmark>& landmarks,
                  const std::string& name_a, const std::string& name_b, std::string& document)
{
  std::vector<vertex_descriptor> marked_a, marked_b;
  for(const Landmark& l : landmarks) { marked_a.push_back(l.first); marked_b.push_back(l.second); }
  std::string panels[2];
  double w[2] = { 0, 0 }, h[2] = { 0, 0 };
  PE::Error_code ec = cross_panel(plane_a, st.report_a, marked_a, "A: " + name_a, "a-", panels[0], w[0], h[0]);
  if(ec == PE::OK) ec = cross_panel(plane_b, st.report_b, marked_b, "B: " + name_b, "b-", panels[1], w[1], h[1]);
  if(ec != PE::OK) return run.fail(ec, "cannot draw '" + filename + "'");
  panels[0].insert(4, " id=\"pe-cross-a\" x=\"0\" y=\"0\"");
  panels[1].insert(4, " id=\"pe-cross-b\" x=\"" + PE::IO::format_number(w[0], 10) + "\" y=\"0\"");
  const std::string width = PE::IO::format_number(w[0] + w[1], 10), height = PE::IO::format_number((std::max)(h[0], h[1]), 10);
  document = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
             "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + width + "\" height=\"" + height +
             "\" viewBox=\"0 0 " + width + ' ' + height + "\">\n" + panels[0] + panels[1] + "</svg>\n";
  return EXIT_VALID;
}

} // namespace

int cmd_cross(const Arguments& a)
{
  Run run(a);
  run.summary << "cross " << a.positional[0] << " -> " << a.positional[1] << ": ";
  Input in_a, in_b;
  // two disks, or two closed genus-0 meshes (cut between two landmarks)
  int status = read_input(run, a.positional[0], in_a, Uv_mode::IGNORED, Shape::DISK_OR_SPHERE, "A");
  if(status != EXIT_VALID) return status;
  status = read_input(run, a.positional[1], in_b, Uv_mode::IGNORED, Shape::DISK_OR_SPHERE, "B");
  if(status != EXIT_VALID) return status;
  status = require_file_vertex_order(run, in_a, "the vertex indices of LANDMARKS and the lines of OUT.txt");
  if(status == EXIT_VALID) status = require_file_vertex_order(run, in_b, "the vertex indices of LANDMARKS");
  if(status != EXIT_VALID) return status;
  std::vector<Landmark> landmarks;
  std::vector<std::size_t> lines;
  status = read_landmarks(run, a.positional[2], in_a.mesh, in_b.mesh, landmarks, lines);
  if(status != EXIT_VALID) return status;
  status = check_output_path(run, a.positional[3]);
  if(status != EXIT_VALID) return status;
  run.result.add("output", a.positional[3]);
  run.result.add("landmarks", landmarks.size());

  const Budget budget(a);
  std::vector<PE::Cross_location<Mesh> > located(in_a.mesh.number_of_vertices());
  auto out = boost::make_iterator_property_map(located.begin(), get(CGAL::vertex_index, in_a.mesh));
  PE::Cross_parameterization_statistics st;
  const bool compatible = a.has("--compatible");
  const bool picture = a.has("--svg");
  Mesh compatible_a, compatible_b, plane_a, plane_b;
  const auto np = PE::parameters::composed_distortion(!a.has("--no-composed"), PE::parameters::matched_maps(!a.has("--no-matched"),
                    PE::parameters::statistics(&st, CGAL::parameters::maximum_running_time(budget.remaining()))));
  auto cross = [&](const auto& with) {
    return compatible ? PE::cross_parameterization(in_a.mesh, in_b.mesh, landmarks, out,
                          PE::parameters::compatible_meshes(std::make_pair(&compatible_a, &compatible_b), with))
                      : PE::cross_parameterization(in_a.mesh, in_b.mesh, landmarks, out, with);
  };
  const PE::Error_code ec = picture ? cross(PE::parameters::planar_maps(std::make_pair(&plane_a, &plane_b), np)) : cross(np);
  // the meshes as read (for closed meshes, the statistics count the cut disks)
  run.result.add("vertices_a", std::size_t(in_a.mesh.number_of_vertices()));
  run.result.add("vertices_b", std::size_t(in_b.mesh.number_of_vertices()));
  run.result.add("border_landmarks", st.border_landmarks);
  run.result.add("vertices_added_a", st.vertices_added_a);
  run.result.add("closed", st.closed);
  if(st.closed)
  {
    run.result.add("cut_landmarks", st.cut_landmarks);
    run.result.add("cut_edges_a", st.cut_edges_a);
    run.result.add("cut_edges_b", st.cut_edges_b);
  }
  run.result.add("chords_split_b", st.chords_split_b);
  if(ec != PE::OK)
  {
    std::string detail;
    // a landmark named by the function is a fault of the landmark file (exit 3), whatever the error code (an index
    // that is no vertex comes as ERROR_WRONG_PARAMETER, like a misuse of the function); so are too few landmarks for
    // two closed meshes
    const bool landmark_fault = st.failed_landmark < landmarks.size();
    const bool too_few = st.closed && st.failed_mesh < 0 && ec == PE::ERROR_WRONG_PARAMETER;
    if(landmark_fault)
    {
      const Landmark& l = landmarks[st.failed_landmark];
      detail = "'" + a.positional[2] + "' line " + std::to_string(lines[st.failed_landmark]) + ": landmark " +
               std::to_string(std::size_t(l.first)) + " " + std::to_string(std::size_t(l.second)) + ": " +
               (st.failed_mesh == 0 ? "the vertex of A " : "the vertex of B ") +
               PE::internal::cross_landmark_fault(ec, st.closed, false);
      run.result.add("failed_landmark_line", lines[st.failed_landmark]);
    }
    else if(st.failed_mesh >= 0)
    {
      const std::string why = PE::internal::cross_mesh_fault(ec, st.border_landmarks,
                                !st.closed && CGAL::is_closed(st.failed_mesh == 0 ? in_a.mesh : in_b.mesh));
      detail = std::string(st.failed_mesh == 0 ? "A" : "B") + ": " + (why.empty() ? std::string(PE::get_error_message(ec)) : why);
    }
    else if(too_few)
      detail = "'" + a.positional[2] + "': closed meshes need at least two landmarks (the cut runs between two of them)";
    return run.fail(ec, "cross-parameterization of '" + in_a.filename + "' and '" + in_b.filename + "' failed", detail,
                    landmark_fault || too_few ? EXIT_INPUT : -1);
  }
  run.result.add("valid_a", st.report_a.is_valid());
  run.result.add("valid_b", st.report_b.is_valid());
  run.result.add("landmarks_exact", st.landmarks_exact);
  run.result.add("on_vertex", st.located_on_vertex);
  run.result.add("on_edge", st.located_on_edge);
  run.result.add("in_face", st.located_in_face);
  run.result.add("seconds_map_b", st.seconds_map_b);
  run.result.add("seconds_map_a", st.seconds_map_a);
  run.result.add("composed", !a.has("--no-composed"));
  if(!a.has("--no-composed"))
  {
    run.result.add("composed_status", PE::get_error_name(st.composed_status));
    run.result.add("composed_iterations", st.composed.iterations);
    run.result.add("composed_energy", st.composed.energy_current);
    run.result.add("seconds_composed", st.seconds_composed);
  }
  run.result.add("matched_b", st.matched_b);
  run.result.add("matched_status", PE::get_error_name(st.matched_status));
  run.result.add("matched_more_distorted", st.matched_more_distorted);
  run.result.add("vertices_added_b", st.vertices_added_b);
  run.result.add("seconds_location", st.seconds_location);

  // the outputs all or none (write_files_together()): B's faces in file order (the reader adds them in order, no
  // face removed), the coordinates in the order the face lists its vertices in B's file (vertices_around_face
  // starts at target(halfedge(f)))
  std::vector<Output_file> outputs;
  outputs.push_back({ a.positional[3], [&](std::ostream& os) {
    os << std::setprecision(17);
    for(vertex_descriptor v : in_a.mesh.vertices())
    {
      const PE::Cross_location<Mesh>& l = located[std::size_t(v)];
      // PMP order: source(h), target(h), target(next(h)); file order: target(h), target(next(h)), source(h)
      os << std::size_t(l.first) << ' ' << l.second[1] << ' ' << l.second[2] << ' ' << l.second[0] << '\n';
    }
    return os ? PE::OK : PE::ERROR_CANNOT_WRITE_FILE;
  } });
  const std::string files[2] = { compatible ? a.get("--compatible") : std::string(),
                                 compatible ? a.second_values.at("--compatible") : std::string() };
  const Mesh* meshes[2] = { &compatible_a, &compatible_b };
  if(compatible)
    for(int k = 0; k < 2; ++k)
      outputs.push_back({ files[k], [&, k](std::ostream& os) {
        return CGAL::IO::write_OBJ(os, *meshes[k], CGAL::parameters::stream_precision(17)) && os ? PE::OK
                                                                                                 : PE::ERROR_CANNOT_WRITE_FILE;
      } });
  std::string picture_text;
  if(picture)
  {
    const int ps = cross_picture(run, a.get("--svg"), plane_a, plane_b, st, landmarks, in_a.filename, in_b.filename,
                                 picture_text);
    if(ps != EXIT_VALID) return ps;
    outputs.push_back({ a.get("--svg"), [&](std::ostream& os) {
      os << picture_text;
      return os ? PE::OK : PE::ERROR_CANNOT_WRITE_FILE;
    } });
  }
  const int ws = write_files_together(run, outputs);
  if(ws != EXIT_VALID) return ws;
  if(compatible)
  {
    run.result.add("valid_compatible", st.report_compatible.is_valid());
    run.result.add("overlay_cells", st.overlay_cells);
    run.result.add("overlay_crossings", st.overlay_crossings);
    run.result.add("compatible_vertices", st.compatible_vertices);
    run.result.add("compatible_faces", st.compatible_faces);
    if(st.closed) run.result.add("cut_vertices_welded", st.cut_vertices_welded);
    run.result.add("seconds_compatible", st.seconds_compatible);
    run.result.add("compatible_a", files[0]);
    run.result.add("compatible_b", files[1]);
  }
  if(picture) run.result.add("svg", a.get("--svg"));
  run.result.add("written", true);
  run.result.add("valid", true);
  run.result.add("status", "OK");
  run.result.add("seconds", run.timer.seconds());
  run.summary << in_a.mesh.number_of_vertices() << " vertices of A located on B (" << st.located_on_vertex << " on vertices, "
              << st.located_on_edge << " on edges), " << landmarks.size() << " landmarks exact, both maps valid, "
              << st.vertices_added_a << " vertices added to A's copy, ";
  if(compatible)
    run.summary << "compatible meshes of " << st.compatible_vertices << " vertices and " << st.compatible_faces
                << " faces (overlay certified), ";
  run.summary << seconds_string(run.timer.seconds());
  return run.finish(EXIT_VALID);
}

} // namespace pe_tool
