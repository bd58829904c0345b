// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// `pe check` and `pe svg`, and the certificate of the maps of every other command.

#include "pe.h"

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>

#include <CGAL/Progressive_embedding/check_immersion.h>

namespace pe_tool {

Map_certificate certify(const Input& in)
{
  Map_certificate c;
  c.report = PE::check_embedding(in.mesh, in.uv);
  c.of = &in;
  return c;
}

Map_certificate certified_in_place(const Input& in, const PE::Embedding_report& report)
{
  Map_certificate c;
  c.report = report;
  c.of = &in;
  return c;
}

void add_report(Result& r, const PE::Embedding_report& rep, const std::string& prefix)
{
  r.add(prefix + "valid", rep.is_valid());
  r.add(prefix + "flipped", rep.flipped);
  r.add(prefix + "degenerate", rep.degenerate);
  if(prefix.empty())
  {
    r.add("faces", rep.faces);
    r.add("vertices", rep.vertices);
    r.add("border_vertices", rep.border_vertices);
  }
  r.add(prefix + "non_finite", rep.non_finite);
  r.add(prefix + "border_simple", rep.border_simple);
  r.add(prefix + "overlapping_pairs", rep.overlapping_pairs);
  r.add(prefix + "clockwise", rep.clockwise);
  r.add(prefix + "min_signed_area", rep.min_signed_area);
  r.add(prefix + "max_energy_3d", rep.max_energy_3d);
  r.add(prefix + "mean_energy_3d", rep.mean_energy_3d);
  if(rep.status != PE::OK) r.add(prefix + "check_status", PE::get_error_name(rep.status));
}

std::string describe(const PE::Embedding_report& rep)
{
  std::ostringstream os;
  if(rep.status != PE::OK) { os << "not checked: " << PE::get_error_message(rep.status); return os.str(); }
  os << (rep.is_valid() ? "valid" : "INVALID") << ": faces " << rep.faces << ", flipped " << rep.flipped
     << ", degenerate " << rep.degenerate;
  if(rep.non_finite) os << ", non-finite vertices " << rep.non_finite;
  os << ", border " << (rep.border_simple ? "simple" : "self-intersecting");
  if(rep.overlap_checked)
    os << ", overlapping pairs " << rep.overlapping_pairs << (rep.overlapping_pairs >= rep.overlap_limit ? "+" : "");
  if(rep.clockwise) os << " (clockwise layout)";
  os << ", min area " << format_number(rep.min_signed_area);
  if(rep.has_3d_energy)
    os << ", sym. Dirichlet max " << format_number(rep.max_energy_3d) << " mean " << format_number(rep.mean_energy_3d);
  return os.str();
}

int map_status(const Input& in, const PE::Embedding_report& rep, PE::Error_code& code, std::string& why)
{
  why.clear();
  code = rep.status;
  if(rep.status != PE::OK) { why = PE::get_error_message(rep.status); return exit_status(rep.status); }
  if(!rep.is_valid()) return EXIT_INVALID;
  // A valid map has finite areas and distortions when its input has: a zero-area 3D face has no
  // distortion, and coordinates whose products overflow double have no finite measure.
  std::size_t index = 0;
  for(face_descriptor f : faces(in.mesh))
  {
    const auto h = halfedge(f, in.mesh);
    const Point_3& p = in.mesh.point(source(h, in.mesh));
    const Point_3& q = in.mesh.point(target(h, in.mesh));
    const Point_3& r = in.mesh.point(target(next(h, in.mesh), in.mesh));
    if(CGAL::collinear(p, q, r)) // exact
    {
      code = PE::ERROR_DEGENERATE_3D_FACE;
      why = "the map is valid but face " + std::to_string(index) + " has zero 3D area: its distortion is not finite";
      return exit_status(code);
    }
    if(!std::isfinite(CGAL::squared_area(p, q, r)))
    {
      code = PE::ERROR_NON_FINITE_COORDINATES;
      why = "the map is valid but the 3D coordinates are too large: the area of face " + std::to_string(index) +
            " is not finite in double, nor is its distortion";
      return exit_status(code);
    }
    ++index;
  }
  const bool finite = std::isfinite(rep.min_signed_area) && std::isfinite(rep.max_signed_area)
                   && (!rep.has_3d_energy || (std::isfinite(rep.max_energy_3d) && std::isfinite(rep.mean_energy_3d)));
  if(!finite)
  {
    code = PE::ERROR_NON_FINITE_COORDINATES;
    why = "the map is valid but its measures are not finite (min area " + format_number(rep.min_signed_area) +
          (rep.has_3d_energy ? ", sym. Dirichlet max " + format_number(rep.max_energy_3d) + " mean " +
                               format_number(rep.mean_energy_3d) : std::string()) +
          "): the uv coordinates are too large for double arithmetic";
    return exit_status(code);
  }
  return EXIT_VALID;
}

int finish_with_map_status(Run& run, const Input& in, const PE::Embedding_report& rep)
{
  PE::Error_code code = PE::OK;
  std::string why;
  const int status = map_status(in, rep, code, why);
  if(!why.empty())
  {
    std::cerr << "pe: " << why << " (" << PE::get_error_name(code) << ")" << std::endl;
    run.result.add("status", PE::get_error_name(code));
    run.result.add("message", why);
  }
  return run.finish(status);
}

int write_and_finish(Run& run, const Input& in, const std::string& obj, const Map_certificate& cert,
                     const std::string& svg, const Picture& picture)
{
  assert(cert.of == &in); // the certificate of what is written
  const PE::Embedding_report& rep = cert.report;
  add_report(run.result, rep);
  Picture drawn = picture;
  drawn.report = &rep; // the picture draws this certificate, not another one
  const int w = write_outputs(run, in, obj, svg, drawn);
  if(w != EXIT_VALID) return w;
  run.result.add("written", true);
  run.summary << describe(rep);
  return finish_with_map_status(run, in, rep);
}

namespace {

// the faces as lists of vertex indices, each rotated to start at its smallest index
std::vector<std::vector<std::size_t> > face_list(const Mesh& m)
{
  std::vector<std::vector<std::size_t> > F;
  for(face_descriptor f : faces(m))
  {
    std::vector<std::size_t> t;
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, m), m)) t.push_back(std::size_t(v));
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    F.push_back(t);
  }
  return F;
}

} // namespace

int cmd_check(const Arguments& a)
{
  Run run(a);
  run.summary << "check " << a.positional[0] << ": ";
  Input in;
  int status = read_input(run, a.positional[0], in, Uv_mode::REQUIRED);
  if(status != EXIT_VALID) return status;
  const PE::Embedding_report report = certify(in).report;
  run.result.add("status", PE::get_error_name(report.status));
  add_report(run.result, report);
  run.result.add("seconds", run.timer.seconds());
  run.summary << describe(report);
  if(a.positional.size() == 2)
  {
    Input ref;
    Run ref_run(a); // a failure to read REF ends the command with its own report
    ref_run.result = run.result;
    ref_run.summary << run.summary.str() << "; reference " << a.positional[1] << ": ";
    const int rs = read_input(ref_run, a.positional[1], ref, Uv_mode::REQUIRED, Shape::DISK, "reference");
    if(rs != EXIT_VALID) return rs;
    // the same faces: same vertex count and, face by face, the same vertex indices (up to rotation);
    // the mesh read has no removed element, so vertex indices are positions in the file
    const bool same_faces = in.mesh.number_of_vertices() == ref.mesh.number_of_vertices() && face_list(in.mesh) == face_list(ref.mesh);
    std::size_t border_differing = 0, border_count = 0;
    if(same_faces)
      for(vertex_descriptor v : vertices(ref.mesh))
        if(CGAL::is_border(v, ref.mesh))
        {
          ++border_count;
          if(!same_bits(in.uv[v].x(), ref.uv[v].x()) || !same_bits(in.uv[v].y(), ref.uv[v].y())) ++border_differing;
        }
    const bool border_exact = same_faces && border_differing == 0;
    run.result.add("reference", ref.filename);
    run.result.add("same_faces", same_faces);
    run.result.add("border_exact", border_exact);
    run.result.add("border_vertices_differing", border_differing);
    run.summary << "; against " << ref.filename << ": " << (same_faces ? "same faces" : "DIFFERENT faces");
    if(same_faces)
      run.summary << ", border " << (border_exact ? "bit-exact" : "CHANGED") << " (" << border_differing << " of "
                  << border_count << " border vertices differ)";
    if(!border_exact)
    {
      run.result.add("ok", false);
      return run.finish(EXIT_INVALID);
    }
  }
  // a map that is not an embedding may still be an immersion (locally injective, overlapping itself). Its
  // border fans turn by the border's angle alone, or (--turns-from MAP) by that plus the full turns that MAP's
  // border makes at the vertex of the same index (pe constrain's outputs keep the input's vertices first)
  auto turns = in.mesh.add_property_map<vertex_descriptor, int>("v:pe_rotation_index", 0).first;
  if(a.has("--turns-from"))
  {
    Input tin;
    Run trun(a); // a failure to read MAP ends the command with its own report
    trun.result = run.result;
    trun.summary << run.summary.str() << "; border turns from " << a.get("--turns-from") << ": ";
    const int ts = read_input(trun, a.get("--turns-from"), tin, Uv_mode::REQUIRED, Shape::DISK, "border turns map");
    if(ts != EXIT_VALID) return ts;
    auto tturns = tin.mesh.add_property_map<vertex_descriptor, int>("v:pe_rotation_index", 0).first;
    const int total = PE::border_rotation_indices(tin.mesh, tin.uv, tturns);
    for(vertex_descriptor v : vertices(in.mesh))
      if(std::size_t(v) < tin.mesh.number_of_vertices()) turns[v] = tturns[v];
    run.result.add("border_turns", static_cast<std::size_t>(total));
  }
  const PE::Immersion_report immersion = PE::check_immersion(in.mesh, in.uv, PE::parameters::vertex_rotation_index_map(turns));
  run.result.add("immersion", immersion.is_immersion());
  run.result.add("border_angle_errors", immersion.border_angle_errors);
  if(!report.is_valid() && !immersion.is_immersion() && immersion.border_angle_errors > 0)
    run.summary << "; not an immersion: " << immersion.border_angle_errors << " border fans turn by another angle than "
                << "the border's" << (a.has("--turns-from") ? " plus the turns of --turns-from" : " (--turns-from gives wrapping borders)");
  if(!report.is_valid() && immersion.is_immersion())
    run.summary << "; an immersion: locally injective, the border overlapping itself";
  run.result.add("ok", report.is_valid());
  return finish_with_map_status(run, in, report);
}

int cmd_svg(const Arguments& a)
{
  Run run(a);
  run.summary << "svg " << a.positional[0] << ": ";
  Input in;
  const int status = read_input(run, a.positional[0], in, Uv_mode::REQUIRED);
  if(status != EXIT_VALID) return status;
  const PE::Embedding_report report = certify(in).report;
  run.result.add("output", a.positional[1]);
  run.result.add("status", PE::get_error_name(report.status));
  add_report(run.result, report);
  Picture picture;
  picture.title = in.filename + ": " + (report.is_valid() ? "valid" : "INVALID"); // the numbers are in the legend
  picture.inset = !report.is_valid();
  picture.has_3d_energy = report.has_3d_energy;
  picture.report = &report;
  const int w = write_picture(run, in, a.positional[1], picture);
  if(w != EXIT_VALID) return w;
  run.result.add("written", true);
  run.summary.str("");
  run.summary << "svg " << in.filename << " -> " << a.positional[1] << ": " << describe(report);
  return run.finish(EXIT_VALID);
}

} // namespace pe_tool
