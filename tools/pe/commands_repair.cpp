// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// `pe untangle`, `pe embed`, `pe optimize`, and the repair and optimization steps of the other
// commands: the only file that instantiates progressive_embedding() and optimize_distortion(). The
// repair-and-optimize policy is the library's (repair_and_optimize()), not written here. All with
// CGAL::Parallel_tag: the optimizer's sweeps and its large Newton solves run on TBB, with results bit
// for bit those of a sequential run.

#include "pe.h"

#include <CGAL/Progressive_embedding/certified_pipeline.h>

#include <iostream>

namespace pe_tool {

namespace {

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
  s.seconds = a.real("--optimize-time", default_optimize_seconds);
  return s;
}

PE::Error_code run_repair(Input& in, bool will_optimize, const Budget& budget, PE::Progressive_embedding_statistics& st)
{
  Progress bar("progressive embedding", budget.progress());
  return PE::progressive_embedding<CGAL::Parallel_tag>(in.mesh, in.uv,
    PE::parameters::minimum_area_ratio(PE::internal::pipeline_minimum_area_ratio(will_optimize, false),
    PE::parameters::statistics(&st,
    CGAL::parameters::callback(bar.callback()).maximum_running_time(budget.remaining()))));
}

PE::Error_code run_optimize(Input& in, const Optimize_settings& s, const Budget& budget, PE::Optimization_statistics& os)
{
  Progress bar("optimization", budget.progress());
  return PE::optimize_distortion<CGAL::Parallel_tag>(in.mesh, in.uv,
    PE::parameters::free_border(s.free_border,
    PE::parameters::constrained_vertices(s.fixed,
    PE::parameters::convergence_tolerance(s.tolerance,
    PE::parameters::optimization_statistics(&os,
    CGAL::parameters::callback(bar.callback()).number_of_iterations(s.iterations)
                     .maximum_running_time((std::min)(budget.remaining(), s.seconds)))))));
}

namespace {
// the library's key-value list of a statistics structure, into the result
struct Add_to_result
{
  Result& r;
  template <class T> void operator()(const char* key, const T& value) const { r.add(key, value); }
};
} // namespace

void add_statistics(Result& r, const PE::Pipeline_statistics& s) { PE::for_each_statistic(s, Add_to_result{ r }); }
void add_statistics(Result& r, const PE::Progressive_embedding_statistics& st) { PE::for_each_statistic(st, Add_to_result{ r }); }

std::string statistics_summary(const PE::Progressive_embedding_statistics& st)
{
  std::ostringstream s;
  s << "invalid before " << st.invalid_faces_before << ", collapses " << st.collapses << ", insertions " << st.insertions;
  if(st.insertions_with_extra_smoothing) s << " (" << st.insertions_with_extra_smoothing << " with extra smoothing)";
  return s.str();
}

void add_optimization(Result& r, const PE::Optimization_statistics& os) { PE::for_each_statistic(os, Add_to_result{ r }); }

std::string optimization_summary(const PE::Optimization_statistics& os, PE::Error_code status)
{
  // the tool's callback never cancels: unconverged and out of budget, either the time or the iteration limit stopped it
  const char* end = os.converged ? " (converged)"
                  : status != PE::ERROR_BUDGET_EXHAUSTED ? ""
                  : os.time_budget_reached ? " (stopped at its time budget)" : " (stopped at its iteration limit)";
  return std::to_string(os.iterations) + " iterations" + end +
         ", mean sym. Dirichlet " + format_number(os.energy_before) + " -> " + format_number(os.energy_after);
}

namespace {

// The common end of untangle and embed: repair_and_optimize() (the optimization unless --no-optimize),
// then the output. With `tutte`, the map given is embed's Tutte map: its certificate, the one
// repair_and_optimize() takes first, is reported as the Tutte map's (no second pass over a large map).
// The output is certified by the pipeline's own last certificate of the map it leaves in in.uv: a
// second check of a 1M-vertex map would cost most of a second. (parameterize_certified() would also
// save the Tutte map's indexing of the mesh, but it keeps the indexing through the Tutte solve, whose
// own indexing is freed before the factorization: 48 MB more at the peak of a 1M-vertex disk.)
int repair_optimize_and_finish(Run& run, Input& in, const Arguments& a, const Budget& budget, bool tutte = false)
{
  const bool optimize = !a.has("--no-optimize");
  const Optimize_settings o = optimize_settings(a, 1000);
  PE::Pipeline_statistics ps;
  Progress bar("progressive embedding", budget.progress());
  const std::function<bool(PE::Pipeline_stage, double)> stage = [&bar](PE::Pipeline_stage st, double f) {
    bar.set_label(st == PE::Pipeline_stage::REPAIR ? "progressive embedding" : "optimization");
    return bar.update(f);
  };
  const PE::Error_code ec = PE::repair_and_optimize<CGAL::Parallel_tag>(in.mesh, in.uv,
    PE::parameters::optimization_policy(optimize ? PE::Optimization_policy::ALWAYS : PE::Optimization_policy::NEVER,
    PE::parameters::pipeline_statistics(&ps,
    PE::parameters::stage_callback(stage,
    PE::parameters::convergence_tolerance(o.tolerance,
    PE::parameters::optimization_time_limit(o.seconds,
    CGAL::parameters::number_of_iterations(o.iterations).maximum_running_time(budget.remaining())))))));
  bar.finish();
  if(tutte)
  {
    const PE::Embedding_report& tutte_report = ps.input_report;
    run.result.add("tutte_valid", tutte_report.is_valid());
    run.result.add("tutte_flipped", tutte_report.flipped);
    run.result.add("tutte_degenerate", tutte_report.degenerate);
    run.summary << "faces " << count_faces(in.mesh) << ", Tutte " << (tutte_report.is_valid() ? "valid" : "INVALID")
                << " (flipped " << tutte_report.flipped << ", degenerate " << tutte_report.degenerate << ")";
  }
  add_statistics(run.result, ps);
  if(ps.repaired) run.summary << ", progressive embedding: " << statistics_summary(ps.repair);
  if(ec != PE::OK)
  {
    run.summary << "; ";
    return run.fail(ec, (ps.optimized ? "optimization failed on '" : "progressive embedding failed on '") + in.filename + "'");
  }
  if(ps.optimized && ps.optimization_status != PE::OK && ps.optimization_status != PE::ERROR_BUDGET_EXHAUSTED)
    std::cerr << "pe: optimization skipped: " << PE::get_error_message(ps.optimization_status) << " ("
              << PE::get_error_name(ps.optimization_status) << ")" << std::endl;
  // a map the optimizer could not touch keeps its repaired map: optimized says whether it improved it
  run.result.add("optimized", ps.optimized && (ps.optimization_status == PE::OK || ps.optimization_status == PE::ERROR_BUDGET_EXHAUSTED));
  if(optimize) run.result.add("optimization_budget", o.seconds);
  if(ps.optimized && ps.optimization.iterations)
    run.summary << ", optimization: " << optimization_summary(ps.optimization, ps.optimization_status);
  run.result.add("status", "OK");
  run.result.add("seconds", run.timer.seconds());
  run.summary << ", " << seconds_string(run.timer.seconds()) << "; ";
  return write_and_finish(run, in, a.positional[1], certified_in_place(in, ps.report));
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
  Budget budget(a);
  run.summary << "faces " << count_faces(in.mesh);
  return repair_optimize_and_finish(run, in, a, budget);
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
  Budget budget(a);
  PE::Embedding_report unused;
  PE::Error_code ec = run_tutte(in, s, budget, unused);
  if(ec != PE::OK) return run.fail(ec, "Tutte failed on '" + in.filename + "'");
  return repair_optimize_and_finish(run, in, a, budget, true);
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
  run.result.add("optimization_budget", s.seconds);
  run.summary << "faces " << count_faces(in.mesh) << ", " << optimization_summary(os, ec) << ", "
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
