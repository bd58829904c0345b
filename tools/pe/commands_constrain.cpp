// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// pe constrain: a map with hard positional constraints (constrained_embedding()).

#include "cli.h"
#include "pe.h"

#include <CGAL/Progressive_embedding/check_immersion.h>

#include <CGAL/Progressive_embedding/constrained_embedding.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace pe_tool {

int cmd_constrain(const Arguments& a)
{
  Run run(a);
  run.summary << "constrain " << a.positional[0] << ": ";
  Input in;
  int status = read_input(run, a.positional[0], in, Uv_mode::OPTIONAL);
  if(status != EXIT_VALID) return status;
  // the targets are points of the domain: its border must be known, not guessed
  if(!in.has_uv && !a.has("--border"))
    return usage("constrain needs a border: an input OBJ with texture coordinates (vt), or --border circle|square|triangle");
  Tutte_settings s;
  status = tutte_settings(run, in, s);
  if(status != EXIT_VALID) return status;
  run.result.add("output", a.positional[1]);
  // a border from the input's map may wrap around some of its vertices (a seamless map cut through
  // cones): the input's faces say how many times, read before the targets overwrite uv
  auto turns = in.mesh.add_property_map<vertex_descriptor, int>("v:pe_rotation_index", 0).first;
  int border_turns = 0;
  if(in.has_uv && s.border == PE::Border_shape::FIXED) border_turns = PE::border_rotation_indices(in.mesh, in.uv, turns);
  run.result.add("border_turns", static_cast<std::size_t>(border_turns));
  // the targets: read_constraints() writes them into in.uv; they are taken from there
  std::vector<vertex_descriptor> fixed;
  if(a.has("--fix"))
  {
    status = read_constraints(run, a.get("--fix"), in, fixed);
    if(status != EXIT_VALID) return status;
  }
  std::vector<std::pair<vertex_descriptor, Point_2> > constraints;
  for(vertex_descriptor v : fixed) constraints.emplace_back(v, in.uv[v]);
  run.result.add("constrained", constraints.size());
  // the faults constrained_embedding() refuses, said with the vertex (read_constraints() keeps the
  // last target of a vertex given twice, so a repeated vertex is found here, not by its targets)
  {
    const std::string what = "cannot use --fix '" + a.get("--fix") + "'";
    std::set<std::size_t> vertex_seen;
    std::map<std::pair<double, double>, std::size_t> target_seen;
    for(vertex_descriptor v : fixed)
    {
      const std::string name = "vertex " + std::to_string(std::size_t(v));
      if(CGAL::is_border(v, in.mesh))
        return run.fail(PE::ERROR_CONSTRAINT_ON_BORDER, what, name + " is on the border: only interior vertices can be constrained");
      if(!vertex_seen.insert(std::size_t(v)).second)
        return run.fail(PE::ERROR_DUPLICATE_CONSTRAINT, what, name + " is constrained twice");
      const Point_2& t = in.uv[v];
      const auto other = target_seen.emplace(std::make_pair(t.x() == 0 ? 0. : t.x(), t.y() == 0 ? 0. : t.y()), std::size_t(v));
      if(!other.second)
        return run.fail(PE::ERROR_DUPLICATE_CONSTRAINT, what, name + " and vertex " + std::to_string(other.first->second) +
                        " have the same target (" + format_number(t.x()) + ", " + format_number(t.y()) + ")");
    }
  }
  const std::size_t vertices_in = in.mesh.number_of_vertices();

  const Budget budget(a);
  // the optimization of a heavily refined map can run for a long time: it gets a budget of its own
  const double optimize_seconds = a.real("--optimize-time", default_constrain_optimize_seconds);
  PE::Constrained_embedding_statistics st;
  Picture picture;
  picture.has_patches = true;
  picture.patches = in.mesh.add_property_map<face_descriptor, int>("f:pe_patch", -1).first;
  // the bar says the phase running; in the optimization, the energy and the time left of its budget
  Progress bar("validation", budget.progress());
  const std::function<bool(const PE::Constrained_embedding_progress&)> phase = [&bar](const PE::Constrained_embedding_progress& p) {
    static const char* const names[] = { "validation", "partition", "path tracing", "patch maps", "certificate",
                                         "optimization", "coarsening", "output" };
    std::string label = names[static_cast<int>(p.phase)];
    if(p.phase == PE::Constrained_embedding_phase::OPTIMIZATION && p.energy == p.energy)
    {
      label += ": energy " + format_number(p.energy);
      if(p.optimization_seconds_left < std::numeric_limits<double>::infinity())
        label += ", " + seconds_string(p.optimization_seconds_left) + " left";
    }
    bar.set_label(label);
    return bar.update(p.fraction);
  };
  const PE::Error_code ec = PE::constrained_embedding<CGAL::Parallel_if_available_tag>(in.mesh, constraints, in.uv,
    PE::parameters::phase_callback(phase,
    PE::parameters::border_shape(s.border,
      PE::parameters::weights(s.weights,
        PE::parameters::optimize(!a.has("--no-optimize"),
        PE::parameters::optimization_time_limit(optimize_seconds,
          PE::parameters::statistics(&st,
            PE::parameters::face_patch_map(picture.patches,
              PE::parameters::vertex_rotation_index_map(turns,
                CGAL::parameters::maximum_running_time(budget.remaining()))))))))));
  bar.finish();
  // the coarsening removes added vertices again: compact the mesh so that vertex indices follow the
  // output order (the input vertices, never removed, keep theirs)
  if(ec == PE::OK && in.mesh.has_garbage()) in.mesh.collect_garbage();
  run.result.add("steiner_vertices", st.steiner_vertices);
  run.result.add("steiner_vertices_inserted", st.steiner_vertices_inserted);
  run.result.add("steiner_vertices_removed", st.steiner_vertices_removed);
  run.result.add("steiner_vertices_kept_for_distortion", st.steiner_vertices_kept_for_distortion);
  run.result.add("paths", st.paths);
  run.result.add("patches", st.patches);
  // which tracing's paths were kept, and with the kinetic tracing, which motion of the targets
  run.result.add("tracing", std::string(st.kinetic_tracing_kept ? "kinetic" : st.overlay_tracing_kept ? "overlay"
                                        : st.guided_tracing_kept ? "guided" : "shortest"));
  run.result.add("kinetic_motion", static_cast<double>(st.kinetic_motion));
  run.summary << "vertices " << vertices_in << " -> " << in.mesh.number_of_vertices() << " (" << st.steiner_vertices
              << " Steiner";
  if(st.steiner_vertices_removed > 0)
    run.summary << ", " << st.steiner_vertices_inserted << " inserted, " << st.steiner_vertices_removed << " removed by the coarsening";
  run.summary << "), " << st.paths << " paths, " << st.patches << " patches";
  if(ec != PE::OK)
  {
    run.summary << "; ";
    std::string detail;
    if(st.failed_constraint < constraints.size())
    {
      const auto& c = constraints[st.failed_constraint];
      detail = "vertex " + std::to_string(std::size_t(c.first)) + " -> (" + format_number(c.second.x()) + ", " +
               format_number(c.second.y()) + ")";
      if(ec == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN)
        detail += border_turns > 0 ? ": a border that wraps around its vertices takes no constraint"
                                   : " is not strictly inside the border";
      run.result.add("failed_vertex", std::size_t(c.first));
    }
    return run.fail(ec, "constrained embedding failed on '" + in.filename + "'", detail);
  }

  // every constraint bit-exact (the function guarantees it; the tool says it from the map it writes)
  double error = 0;
  bool exact = true;
  for(const auto& c : constraints)
  {
    const Point_2 p = in.uv[c.first];
    if(!same_bits(p.x(), c.second.x()) || !same_bits(p.y(), c.second.y())) exact = false;
    error = (std::max)(error, std::hypot(p.x() - c.second.x(), p.y() - c.second.y()));
  }
  run.result.add("constraint_error", error);
  run.result.add("constraints_exact", exact);
  // the new vertices are interior (border edges are never split): one `v` line each after the input's
  // (without a seam map, each vertex is its own `v` line already)
  if(in.has_uv && !in.vt_to_v.empty())
    for(vertex_descriptor v : in.mesh.vertices())
      if(std::size_t(v) >= in.vt_to_v.size())
      {
        in.positions.push_back(in.mesh.point(v));
        in.vt_to_v.push_back(in.positions.size() - 1);
      }
  run.result.add("optimized", st.optimized);
  if(st.optimized)
  {
    // both runs when the optimization ran again after the coarsening: the iterations add up, the last one converged or not
    const PE::Optimization_statistics& last = st.reoptimized ? st.reoptimization : st.optimization;
    const bool stopped = st.optimization_status == PE::ERROR_BUDGET_EXHAUSTED;
    run.result.add("optimization_budget", optimize_seconds);
    run.result.add("optimization_seconds", st.seconds_optimization);
    run.result.add("optimization_iterations", st.optimization.iterations + (st.reoptimized ? st.reoptimization.iterations : 0));
    run.result.add("optimization_converged", last.converged);
    run.summary << ", optimized in " << seconds_string(st.seconds_optimization) << " ("
                << (last.converged ? "converged" : stopped ? "stopped at its budget" : "not converged")
                << ", mean symmetric Dirichlet " << format_number(st.report_before_optimization.mean_energy_3d) << " -> "
                << format_number(st.report.mean_energy_3d) << ")";
  }
  run.result.add("status", "OK");
  run.result.add("seconds", run.timer.seconds());
  run.summary << ", constraint error " << format_number(error) << ", " << seconds_string(run.timer.seconds()) << "; ";
  if(!exact) return run.fail(PE::ERROR_INVALID_EMBEDDING, "constrained embedding of '" + in.filename + "'",
                             "a constrained vertex is not bit-exactly at its target");
  picture.constrained = fixed;
  picture.color_by_distortion = false;
  picture.title = in.filename + ": " + std::to_string(fixed.size()) + " constrained vertices, " + std::to_string(st.patches)
                + " patches, " + std::to_string(st.steiner_vertices) + " Steiner vertices, "
                + (st.immersion ? (st.immersion_report.is_immersion() ? "immersion" : "NOT AN IMMERSION")
                                : (st.report.is_valid() ? "valid" : "INVALID"));
  run.result.add("immersion", st.immersion && st.immersion_report.is_immersion());
  // the map written is certified, not the library's working copy (st.report)
  if(!st.immersion) return write_and_finish(run, in, a.positional[1], certify(in), a.get("--svg"), picture);
  // a weakly self-overlapping border: the map is an immersion, certified by check_immersion() on the map written,
  // with the border fans wrapping as in the input's
  add_report(run.result, certify(in).report);
  const PE::Immersion_report ir = PE::check_immersion(in.mesh, in.uv, PE::parameters::vertex_rotation_index_map(turns));
  const int w = write_outputs(run, in, a.positional[1], a.get("--svg"), picture);
  if(w != EXIT_VALID) return w;
  run.result.add("written", true);
  run.summary << ir.summary() << " (the border overlaps itself: not an embedding)";
  return run.finish(ir.is_immersion() ? EXIT_VALID : EXIT_INVALID);
}

} // namespace pe_tool
