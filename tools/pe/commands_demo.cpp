// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// `pe demo`, the README's main job: the Tutte-failure protocol on dino.off seed 8, the repair by
// progressive embedding and the optimized map, each certified, written and drawn. Every number
// of a picture (the counts and energies of its legend) is printed with it.

#include "pe.h"

#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>

#include <cstdlib>
#include <fstream>
#include <iostream>

#ifndef PE_DEFAULT_DATA_DIR
#define PE_DEFAULT_DATA_DIR ""
#endif
#ifndef PE_DEFAULT_OUTPUT_DIR
#define PE_DEFAULT_OUTPUT_DIR "."
#endif

namespace pe_tool {

namespace {

// The numbers of the legend of the picture `svg`, as drawn: the text of the elements with the
// ids pe-energy-min, -median, -mean and -max (write_SVG() formats them itself), and the zoom of
// the inset; empty if there is no legend.
std::string legend_numbers(const std::string& svg)
{
  std::ifstream in(svg, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  std::string out;
  for(const char* id : { "pe-energy-min", "pe-energy-median", "pe-energy-mean", "pe-energy-max" })
  {
    const std::size_t at = s.find(std::string("id=\"") + id + "\"");
    if(at == std::string::npos) return std::string();
    const std::size_t open = s.find('>', at), close = s.find('<', at);
    if(open == std::string::npos || close == std::string::npos || close < open) return std::string();
    out += (out.empty() ? "" : ", ") + s.substr(open + 1, close - open - 1);
  }
  // the magnification of the inset, when there is one
  const std::string zoom = "zoom &#215;";
  const std::size_t z = s.find(zoom);
  if(z != std::string::npos)
  {
    const std::size_t end = s.find(' ', z + zoom.size());
    if(end != std::string::npos) out += "; inset zoom x" + s.substr(z + zoom.size(), end - z - zoom.size());
  }
  return out;
}

// writes the map and the picture of one stage and prints what the picture shows
int write_stage(Run& run, const Input& in, const std::string& base, const std::string& stage, const std::string& caption,
                const PE::Embedding_report& rep, bool inset)
{
  const std::string svg = base + "_" + stage + ".svg", obj = base + "_" + stage + ".obj";
  Picture picture;
  picture.title = caption + ": " + (rep.is_valid() ? "valid" : "INVALID"); // the numbers are in the legend
  picture.inset = inset;
  picture.has_3d_energy = rep.has_3d_energy;
  const int w = write_outputs(run, in, obj, svg, picture);
  if(w != EXIT_VALID) return w;
  run.result.add("svg_" + stage, svg);
  const std::string legend = legend_numbers(svg);
  if(!legend.empty()) run.result.add("legend_" + stage, legend);
  if(!run.args.json)
    std::cout << "      " << describe(rep) << "\n"
              << (legend.empty() ? std::string() : "      sym. Dirichlet energy per face (the legend): " + legend + "\n")
              << "      wrote " << svg << " and " << obj << std::endl;
  return EXIT_VALID;
}

} // namespace

int cmd_demo(const Arguments& a)
{
  Run run(a);
  std::string data = a.positional.empty() ? std::string(PE_DEFAULT_DATA_DIR) : a.positional[0];
  if(a.positional.empty() && data.empty() && std::getenv("CGAL_DATA_DIR")) data = std::getenv("CGAL_DATA_DIR");
  const std::string mesh_name = a.get("--mesh", "dino.off");
  const unsigned long long seed = a.count("--seed", 8);
  const std::string out_dir = a.get("--out-dir", PE_DEFAULT_OUTPUT_DIR);
  std::string stem = mesh_name.substr(0, mesh_name.find_last_of('.'));
  stem = stem.substr(stem.find_last_of('/') + 1) + "_seed" + std::to_string(seed);
  const std::string base = out_dir + "/" + stem;
  const std::string name = mesh_name + " seed " + std::to_string(seed);
  run.summary << "demo " << name << ": ";
  run.result.add("seed", static_cast<std::size_t>(seed));

  Input in;
  const std::string path = data + "/meshes/" + mesh_name;
  int status = read_input(run, path, in, Uv_mode::IGNORED, Shape::CLOSED_SPHERE);
  if(status != EXIT_VALID)
  {
    if(status == EXIT_INPUT && !input_file_problem(path).empty())
      std::cerr << "pe: the demo needs libcgal-demo's meshes: install the Debian package libcgal-demo and configure with cmake,\n"
                   "    or give the folder that contains meshes/ (e.g. the data folder of /usr/share/doc/libcgal-demo/data.tar.gz)"
                << std::endl;
    return status;
  }
  const std::size_t nv = num_vertices(in.mesh), nf = count_faces(in.mesh);
  Budget budget(a);

  // [1/3] the Tutte map of the protocol: the failure region is small, hence the inset
  Timer step;
  PE::Error_code ec = thingi_protocol(in, static_cast<unsigned>(seed), budget);
  const double t_tutte = step.seconds();
  if(ec != PE::OK) return run.fail(ec, "the Tutte-failure protocol failed on '" + path + "'");
  const PE::Embedding_report tutte = certify(in).report;
  add_report(run.result, tutte, "tutte_");
  run.result.add("seconds_tutte", t_tutte);
  if(!a.json)
    std::cout << "[1/3] " << mesh_name << " (" << nv << " vertices, " << nf << " faces), Tutte-failure protocol seed " << seed
              << ", double Tutte map (" << seconds_string(t_tutte) << "):" << std::endl;
  status = write_stage(run, in, base, "tutte", name + ", double Tutte map", tutte, !tutte.is_valid());
  if(status != EXIT_VALID) return status;

  // [2/3] the repair, with the parameters chosen for an optimization
  step.restart();
  PE::Progressive_embedding_statistics st;
  ec = run_repair(in, true, budget, st);
  const double t_repair = step.seconds();
  add_statistics(run.result, st);
  run.result.add("seconds_repair", t_repair);
  if(!a.json)
    std::cout << "[2/3] progressive embedding (" << statistics_summary(st) << ", " << seconds_string(t_repair) << "):" << std::endl;
  if(ec != PE::OK) return run.fail(ec, "progressive embedding failed");
  const PE::Embedding_report repaired = certify(in).report; // the map written, not the library's copy
  add_report(run.result, repaired, "repaired_");
  status = write_stage(run, in, base, "repaired", name + ", after progressive embedding", repaired, false);
  if(status != EXIT_VALID) return status;

  // [3/3] the distortion optimization of the repaired map
  step.restart();
  PE::Optimization_statistics os;
  Optimize_settings settings = optimize_settings(a, 300);
  ec = run_optimize(in, settings, budget, os);
  const double t_optimize = step.seconds();
  if(!a.json)
    std::cout << "[3/3] distortion optimization (" << optimization_summary(os) << ", " << seconds_string(t_optimize) << "):"
              << std::endl;
  if(ec != PE::OK && ec != PE::ERROR_BUDGET_EXHAUSTED) return run.fail(ec, "the optimization failed");
  add_optimization(run.result, os);
  const PE::Embedding_report optimized = certify(in).report;
  add_report(run.result, optimized);
  status = write_stage(run, in, base, "optimized", name + ", optimized", optimized, false);
  if(status != EXIT_VALID) return status;

  run.result.add("status", "OK");
  run.result.add("written", true);
  run.summary.str("");
  run.summary << "demo " << name << ": Tutte " << (tutte.is_valid() ? "valid" : "INVALID") << " (flipped " << tutte.flipped
              << ", degenerate " << tutte.degenerate << "), repaired " << (repaired.is_valid() ? "valid" : "INVALID")
              << ", optimized " << describe(optimized) << "; " << seconds_string(run.timer.seconds());
  return finish_with_map_status(run, in, optimized);
}

} // namespace pe_tool
