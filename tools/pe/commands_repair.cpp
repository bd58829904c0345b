// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// `pe untangle`, `pe embed`, `pe optimize`, and the repair and optimization steps of the other
// commands: the only file that instantiates progressive_embedding() and optimize_distortion().

#include "pe.h"

#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>

#include <iostream>

namespace pe_tool {

namespace {

// The one place where the repair parameters are chosen. Before an optimization, the repair
// also collapses and re-inserts the faces below 1e-3 x the mean area: the optimizer cannot grow
// faces 1e-20 times too small back in a useful number of iterations. Without an optimization,
// the library's default for double (1e-12).
double repair_minimum_area_ratio(bool will_optimize) { return will_optimize ? 1e-3 : 1e-12; }

// The optimizer's default convergence tolerance; passed explicitly so that the optimizer is
// instantiated once, with or without --tolerance.
const double default_tolerance = 1e-5; // optimize_distortion's default

} // namespace

Optimize_settings optimize_settings(const Arguments& a, std::size_t default_iterations)
{
  Optimize_settings s;
  s.free_border = a.has("--free-border");
  s.iterations = static_cast<std::size_t>(a.count("--iterations", default_iterations));
  s.tolerance = a.real("--tolerance", default_tolerance);
  return s;
}

PE::Error_code run_repair(Input& in, bool will_optimize, const Budget& budget, PE::Progressive_embedding_statistics& st)
{
  Progress bar("progressive embedding", budget.progress());
  return PE::progressive_embedding(in.mesh, in.uv,
    PE::parameters::minimum_area_ratio(repair_minimum_area_ratio(will_optimize),
    PE::parameters::statistics(&st,
    CGAL::parameters::callback(bar.callback()).maximum_running_time(budget.remaining()))));
}

PE::Error_code run_optimize(Input& in, const Optimize_settings& s, const Budget& budget, PE::Optimization_statistics& os)
{
  Progress bar("optimization", budget.progress());
  return PE::optimize_distortion(in.mesh, in.uv,
    PE::parameters::free_border(s.free_border,
    PE::parameters::constrained_vertices(s.fixed,
    PE::parameters::convergence_tolerance(s.tolerance,
    PE::parameters::optimization_statistics(&os,
    CGAL::parameters::callback(bar.callback()).number_of_iterations(s.iterations)
                     .maximum_running_time(budget.remaining()))))));
}

void add_statistics(Result& r, const PE::Progressive_embedding_statistics& st)
{
  r.add("invalid_before", st.invalid_faces_before);
  r.add("collapses", st.collapses);
  r.add("insertions", st.insertions);
  r.add("extra_smoothing", st.insertions_with_extra_smoothing);
  r.add("expansion_rounds", st.expansion_rounds);
  r.add("seconds_collapse", st.seconds_collapse);
  r.add("seconds_insertion", st.seconds_insertion);
}

std::string statistics_summary(const PE::Progressive_embedding_statistics& st)
{
  std::ostringstream s;
  s << "invalid before " << st.invalid_faces_before << ", collapses " << st.collapses << ", insertions " << st.insertions;
  if(st.insertions_with_extra_smoothing) s << " (" << st.insertions_with_extra_smoothing << " with extra smoothing)";
  return s.str();
}

void add_optimization(Result& r, const PE::Optimization_statistics& os)
{
  r.add("iterations", os.iterations);
  r.add("converged", os.converged);
  r.add("energy_before", os.energy_before);
  r.add("energy_after", os.energy_after);
  r.add("seconds_optimization", os.seconds);
}

std::string optimization_summary(const PE::Optimization_statistics& os)
{
  return std::to_string(os.iterations) + " iterations" + (os.converged ? " (converged)" : "") +
         ", mean sym. Dirichlet " + format_number(os.energy_before) + " -> " + format_number(os.energy_after);
}

namespace {

// The default optimization after a repair (untangle, embed). A mesh that cannot be optimized
// (no free vertex, zero-area 3D faces) keeps its repaired map: said on stderr, not an error here
// (map_status() reports the distortion that is not finite). Returns OK or the error to report.
PE::Error_code optimize_after_repair(Run& run, Input& in, const Budget& budget, PE::Optimization_statistics& os)
{
  const PE::Error_code eo = run_optimize(in, optimize_settings(run.args, 1000), budget, os);
  if(eo == PE::OK || eo == PE::ERROR_BUDGET_EXHAUSTED) // budget: the map is valid and improved
  {
    run.result.add("optimized", true);
    add_optimization(run.result, os);
    return PE::OK;
  }
  run.result.add("optimized", false);
  if(eo == PE::ERROR_NO_FREE_VERTEX || eo == PE::ERROR_DEGENERATE_3D_FACE)
  {
    std::cerr << "pe: optimization skipped: " << PE::get_error_message(eo) << " (" << PE::get_error_name(eo) << ")" << std::endl;
    run.result.add("optimization_status", PE::get_error_name(eo));
    return PE::OK;
  }
  return eo;
}

// The common end of untangle and embed: the optimization (unless --no-optimize), then the output.
int optimize_and_finish(Run& run, Input& in, const Arguments& a, const Budget& budget, bool optimize)
{
  PE::Optimization_statistics os;
  run.result.add("optimized", false);
  if(optimize)
  {
    const PE::Error_code ec = optimize_after_repair(run, in, budget, os);
    if(ec != PE::OK) { run.summary << "; "; return run.fail(ec, "optimization failed on '" + in.filename + "'"); }
    if(os.iterations) run.summary << ", optimization: " << optimization_summary(os);
  }
  run.result.add("status", "OK");
  run.result.add("seconds", run.timer.seconds());
  run.summary << ", " << seconds_string(run.timer.seconds()) << "; ";
  return write_and_finish(run, in, a.positional[1], certify(in));
}

} // namespace

int cmd_untangle(const Arguments& a)
{
  Run run(a);
  run.summary << "untangle " << a.positional[0] << ": ";
  Input in;
  const int status = read_input(run, a.positional[0], in, Uv_mode::REQUIRED);
  if(status != EXIT_VALID) return status;
  run.result.add("output", a.positional[1]);
  const bool optimize = !a.has("--no-optimize");
  Budget budget(a);
  PE::Progressive_embedding_statistics st;
  PE::Error_code ec = run_repair(in, optimize, budget, st);
  add_statistics(run.result, st);
  run.summary << "faces " << count_faces(in.mesh) << ", " << statistics_summary(st);
  if(ec != PE::OK) { run.summary << "; "; return run.fail(ec, "progressive embedding failed on '" + in.filename + "'"); }
  return optimize_and_finish(run, in, a, budget, optimize);
}

int cmd_embed(const Arguments& a)
{
  Run run(a);
  run.summary << "embed " << a.positional[0] << ": ";
  Input in;
  int status = read_input(run, a.positional[0], in, Uv_mode::OPTIONAL);
  if(status != EXIT_VALID) return status;
  Tutte_settings s;
  status = tutte_settings(run, in, s);
  if(status != EXIT_VALID) return status;
  run.result.add("output", a.positional[1]);
  const bool optimize = !a.has("--no-optimize");
  Budget budget(a);
  PE::Embedding_report unused;
  PE::Error_code ec = run_tutte(in, s, budget, unused);
  if(ec != PE::OK) return run.fail(ec, "Tutte failed on '" + in.filename + "'");
  const PE::Embedding_report tutte_report = certify(in).report;
  const bool repaired = !tutte_report.is_valid();
  run.result.add("tutte_valid", tutte_report.is_valid());
  run.result.add("tutte_flipped", tutte_report.flipped);
  run.result.add("tutte_degenerate", tutte_report.degenerate);
  run.result.add("repaired", repaired);
  run.summary << "faces " << count_faces(in.mesh) << ", Tutte " << (tutte_report.is_valid() ? "valid" : "INVALID")
              << " (flipped " << tutte_report.flipped << ", degenerate " << tutte_report.degenerate << ")";
  if(repaired)
  {
    PE::Progressive_embedding_statistics st;
    ec = run_repair(in, optimize, budget, st);
    add_statistics(run.result, st);
    run.summary << ", progressive embedding: " << statistics_summary(st);
    if(ec != PE::OK) { run.summary << "; "; return run.fail(ec, "progressive embedding failed on '" + in.filename + "'"); }
  }
  return optimize_and_finish(run, in, a, budget, optimize);
}

int cmd_optimize(const Arguments& a)
{
  Run run(a);
  run.summary << "optimize " << a.positional[0] << ": ";
  Input in;
  int status = read_input(run, a.positional[0], in, Uv_mode::REQUIRED);
  if(status != EXIT_VALID) return status;
  run.result.add("output", a.positional[1]);
  Optimize_settings s = optimize_settings(a, 1000);
  if(a.has("--fix"))
  {
    status = read_constraints(run, a.get("--fix"), in, s.fixed);
    if(status != EXIT_VALID) return status;
  }
  run.result.add("constrained", s.fixed.size());
  Budget budget(a);
  PE::Optimization_statistics os;
  const PE::Error_code ec = run_optimize(in, s, budget, os);
  add_optimization(run.result, os);
  run.summary << "faces " << count_faces(in.mesh) << ", " << optimization_summary(os) << ", "
              << seconds_string(run.timer.seconds()) << "; ";
  if(ec == PE::ERROR_INVALID_EMBEDDING)
  {
    add_report(run.result, os.report);
    return run.fail(ec, "cannot optimize '" + in.filename + "'",
                    std::string("the input map is not valid") + (s.fixed.empty() ? "" : " with the constraints of --fix") +
                    ": optimize needs a valid map (run pe untangle first)");
  }
  // a budget that runs out still leaves a valid, improved map: it is written
  if(ec != PE::OK && ec != PE::ERROR_BUDGET_EXHAUSTED) return run.fail(ec, "optimization failed on '" + in.filename + "'");
  run.result.add("status", PE::get_error_name(ec));
  run.result.add("seconds", run.timer.seconds());
  return write_and_finish(run, in, a.positional[1], certify(in));
}

} // namespace pe_tool
