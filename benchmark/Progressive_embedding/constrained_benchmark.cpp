// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors
//
// constrained_embedding() under the MatchMaker++ protocol, on real meshes:
//   disks  : every disk of DATA_DIR/meshes (--min-vertices and more), as they are;
//   closed : every closed genus-0 mesh, cut open by removing the faces around one face (the face of the
//            Tutte-failure protocol for the seed, then every face sharing a vertex with it), so that the
//            border has about a dozen vertices and can be put on a square.
// Border: CGAL's square shape (3D arc length, corners closest to quarter lengths) scaled to
// [-1.5, 2.5]^2. Constraints (seeds 0..S-1): K distinct random interior vertices. K = 3: to (0,0), (1,0),
// (0,1) (`fixed`). K > 3, two target sets: `random` (distinct random points of [-1, 2]^2: an arbitrary
// layout, whose paths must wind around each other), `layout` (each vertex's place in the Tutte map on
// the same border) and `jittered` (there, moved by a random offset of at most --jitter in x and y, default
// 0.01). Per run: vertices in/out,
// Steiner vertices, paths, patches, time per phase, peak memory, certificate, constraint error,
// symmetric Dirichlet before and after the optimization, and the unconstrained optimized map on the
// same border (constrained_embedding() with no constraint) for comparison.
//
//   constrained_benchmark DATA_DIR OUT_PREFIX [--meshes a.off,b.off] [--seeds S] [--counts 3,10,50]
//        [--min-vertices N] [--max-vertices N] [--no-disks] [--no-closed] [--optimize-seeds K]
//        [--seeds-large S] [--budget SECONDS] [--max-steiner N] [--targets layout,jittered,random] [--jitter D]
//        [--sequential] [--repeat R] [--no-coarsen] [--no-kinetic]
//
// --repeat R: every constrained run R times, the row of the median time to the certified map kept (the
// host is shared and its timings noisy; the maps are the same, a failure in any repeat is kept).
// --seeds-large S: only seeds < S for K > 3 (default: all).
// --no-coarsen: the added vertices are all kept (constrained_embedding()'s coarsening off), for A/B runs.
// --no-kinetic: constrained_embedding()'s kinetic tracing off (the tracings before it), for A/B runs.
// Writes OUT_PREFIX.csv (one row per run) and OUT_PREFIX.md (per mesh and constraint count: medians
// over the seeds; totals). The optimization (and its unconstrained reference) runs on seeds < K
// (default 3); every run is certified before optimizing, and the time to the certified map is the sum
// of the phases before the optimization.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Progressive_embedding/constrained_embedding.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>
#include "process_memory.h"

#include <dirent.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace PE = CGAL::Progressive_embedding;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                        SM;
typedef boost::graph_traits<SM>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<SM>::face_descriptor              face_descriptor;
typedef SM::Property_map<vertex_descriptor, K::Point_2>       UV_map;

namespace {

using pe_bench::reset_peak_rss;
using pe_bench::peak_rss_mb;

bool is_disk(const SM& m)
{
  PE::internal::Indexed_disk<SM> disk;
  return PE::internal::make_indexed_disk(m, SM::null_halfedge(), disk) == PE::OK && disk.border.size() >= 3;
}

bool is_closed_genus_0(const SM& m)
{
  if(m.number_of_vertices() < 4 || !CGAL::is_closed(m) || !CGAL::is_triangle_mesh(m)) return false;
  const long chi = long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
  return chi == 2;
}

// removes the protocol's face for the seed and every face sharing a vertex with it
bool cut_open(SM& m, unsigned seed)
{
  PE::internal::remove_protocol_face_star(m, seed);
  return is_disk(m);
}

// the square border [-1.5, 2.5]^2 (4x - 1.5 of the unit square shape: the sides stay exactly straight)
bool square_border(const SM& m, UV_map uv)
{
  if(PE::tutte_embedding(m, SM::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::SQUARE)) != PE::OK) return false;
  for(vertex_descriptor v : vertices(m))
  {
    const K::Point_2 p = get(uv, v);
    put(uv, v, K::Point_2(4 * p.x() - 1.5, 4 * p.y() - 1.5));
  }
  return true;
}

struct Row
{
  std::string kind, mesh, targets;
  unsigned seed = 0;
  std::size_t count = 0, v_in = 0, v_out = 0, steiner = 0, chord_splits = 0, paths = 0, patches = 0, repaired = 0;
  std::size_t inserted = 0, removed = 0; // added vertices before the coarsening, and removed by it (steiner: kept)
  std::string status;
  bool certified = false, optimized = false;
  double constraint_error = 0;
  double t_validation = 0, t_partition = 0, t_tracing = 0, t_patches = 0, t_certification = 0, t_certified = 0,
         t_optimization = 0, t_coarsening = 0, t_output = 0, t_total = 0, peak_mb = 0;
  double mean_before = 0, max_before = 0, mean_after = 0, max_after = 0;
  std::size_t iterations = 0;
  std::string optimization_status;
  std::string tracing = "-"; // the tracing whose paths were kept: shortest, kinetic, overlay, guided
  int kinetic_motion = -1;   // the motion the kinetic tracing kept (Constrained_embedding_statistics::kinetic_motion)
  double unconstrained_mean = -1; // optimized, same border, no constraint (-1: not run)
};

template <class T> double median(std::vector<T> v)
{
  if(v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? double(v[n / 2]) : 0.5 * (double(v[n / 2 - 1]) + double(v[n / 2]));
}

std::vector<std::string> split(const std::string& s, char c)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string x;
  while(std::getline(ss, x, c)) if(!x.empty()) out.push_back(x);
  return out;
}

std::string fmt(double x, int prec = 3)
{
  if(std::isnan(x)) return "-";
  std::ostringstream o;
  o << std::setprecision(prec) << x;
  return o.str();
}

// --sequential: constrained_embedding<CGAL::Sequential_tag> (the patches one after the other)
bool sequential = false;
// --repeat R: each constrained run R times (the median time kept)
int repeat = 1;
// --no-coarsen: constrained_embedding()'s coarsening off
bool coarsen = true;
// --no-kinetic: constrained_embedding()'s kinetic tracing off (kinetic_tracing(false))
bool kinetic = true;

// constrained_embedding() on a copy of `m0`, whose "v:uv" property holds the border
Row run(const SM& m0, const std::vector<std::pair<vertex_descriptor, K::Point_2> >& constraints,
        bool optimize, double budget, std::size_t max_steiner)
{
  SM m = m0; // the property maps are copied with the mesh
  UV_map uv = m.property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  PE::Constrained_embedding_statistics st;
  reset_peak_rss();
  // max_steiner 0: constrained_embedding()'s default budgets
  // PE_VERBOSE=1 in the environment: constrained_embedding() reports its phases on std::cerr
  const bool verbose = std::getenv("PE_VERBOSE") != nullptr;
  const auto np = PE::parameters::optimize(optimize, PE::parameters::coarsen(coarsen, PE::parameters::kinetic_tracing(kinetic,
                   PE::parameters::statistics(&st, CGAL::parameters::maximum_running_time(budget).verbose(verbose)))));
  auto call = [&](auto tag, const auto& params) {
    return max_steiner ? PE::constrained_embedding<decltype(tag)>(m, constraints, uv, PE::parameters::maximum_steiner_vertices(max_steiner, params))
                       : PE::constrained_embedding<decltype(tag)>(m, constraints, uv, params);
  };
  const PE::Error_code ec = sequential ? call(CGAL::Sequential_tag(), np) : call(CGAL::Parallel_if_available_tag(), np);
  Row r;
  r.peak_mb = peak_rss_mb();
  r.status = PE::get_error_name(ec);
  r.count = constraints.size();
  r.v_in = st.input_vertices; r.v_out = st.output_vertices; r.steiner = st.steiner_vertices;
  r.inserted = st.steiner_vertices_inserted; r.removed = st.steiner_vertices_removed;
  r.chord_splits = st.chord_splits; r.paths = st.paths; r.patches = st.patches; r.repaired = st.repaired_patches;
  r.t_validation = st.seconds_validation; r.t_partition = st.seconds_partition; r.t_tracing = st.seconds_tracing;
  r.t_patches = st.seconds_patches; r.t_certification = st.seconds_certification;
  r.t_certified = r.t_validation + r.t_partition + r.t_tracing + r.t_patches + r.t_certification;
  r.t_optimization = st.seconds_optimization; r.t_coarsening = st.seconds_coarsening; r.t_output = st.seconds_output; r.t_total = st.seconds_total;
  r.optimized = st.optimized;
  r.tracing = st.kinetic_tracing_kept ? "kinetic" : st.overlay_tracing_kept ? "overlay" : st.guided_tracing_kept ? "guided" : "shortest";
  r.kinetic_motion = st.kinetic_motion;
  r.optimization_status = st.optimized ? PE::get_error_name(st.optimization_status) : "-";
  r.iterations = st.optimization.iterations;
  r.mean_before = st.report_before_optimization.mean_energy_3d;
  r.max_before = st.report_before_optimization.max_energy_3d;
  r.mean_after = st.report.mean_energy_3d;
  r.max_after = st.report.max_energy_3d;
  // the certificate and the constraints, checked again here on the caller's mesh
  if(ec == PE::OK)
  {
    const PE::Embedding_report rep = PE::check_embedding(m, uv);
    // the whole certificate: positive faces, finite, simple border, no overlapping pair
    r.certified = rep.is_valid();
    double err = 0;
    for(const auto& c : constraints)
    {
      const K::Point_2 p = get(uv, c.first);
      err = std::max(err, std::max(std::abs(p.x() - c.second.x()), std::abs(p.y() - c.second.y())));
    }
    r.constraint_error = err;
  }
  return r;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: constrained_benchmark DATA_DIR OUT_PREFIX [--meshes a.off,b.off] [--seeds S] [--counts 3,10,50]\n"
                 "       [--min-vertices N] [--max-vertices N] [--no-disks] [--no-closed] [--optimize-seeds K] [--seeds-large S] [--budget S]\n"
                 "       [--max-steiner N] [--targets layout,jittered,random] [--jitter D] [--sequential] [--repeat R] [--no-coarsen] [--no-kinetic]\n"
                 "  --sequential: patches embedded one after the other (default: in parallel, CGAL::Parallel_if_available_tag)\n"
                 "  --repeat R: each run R times, the one of median time to the certified map kept (default 1)\n";
    return 2;
  }
  const std::string data = argv[1], out = argv[2];
  std::vector<std::string> only;
  unsigned seeds = 10, optimize_seeds = 3, seeds_large = 10;
  bool seeds_large_given = false;
  std::vector<std::size_t> counts = {3, 10, 50};
  std::size_t min_vertices = 500, max_vertices = 30000;
  bool disks = true, closed = true;
  double budget = 300;
  std::vector<std::string> target_kinds = {"layout", "jittered", "random"};
  double jitter = 0.01;
  std::size_t max_steiner = 0; // 0: the default of constrained_embedding()
  for(int i = 3; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool has = i + 1 < argc;
    if(a == "--meshes" && has) only = split(argv[++i], ',');
    else if(a == "--seeds" && has) seeds = unsigned(std::atoi(argv[++i]));
    else if(a == "--seeds-large" && has) { seeds_large = unsigned(std::atoi(argv[++i])); seeds_large_given = true; }
    else if(a == "--optimize-seeds" && has) optimize_seeds = unsigned(std::atoi(argv[++i]));
    else if(a == "--counts" && has) { counts.clear(); for(auto& c : split(argv[++i], ',')) counts.push_back(std::stoul(c)); }
    else if(a == "--min-vertices" && has) min_vertices = std::stoul(argv[++i]);
    else if(a == "--max-vertices" && has) max_vertices = std::stoul(argv[++i]);
    else if(a == "--budget" && has) budget = std::atof(argv[++i]);
    else if(a == "--targets" && has) target_kinds = split(argv[++i], ',');
    else if(a == "--jitter" && has) jitter = std::atof(argv[++i]);
    else if(a == "--max-steiner" && has) max_steiner = std::stoul(argv[++i]);
    else if(a == "--no-disks") disks = false;
    else if(a == "--sequential") sequential = true;
    else if(a == "--no-coarsen") coarsen = false;
    else if(a == "--no-kinetic") kinetic = false;
    else if(a == "--repeat" && has) repeat = std::max(1, std::atoi(argv[++i]));
    else if(a == "--no-closed") closed = false;
    else { std::cerr << "constrained_benchmark: unknown option " << a << "\n"; return 2; }
  }

  if(!seeds_large_given) seeds_large = seeds;
  // the meshes, sorted by name
  std::vector<std::string> names;
  const std::string dir = data + "/meshes";
  if(DIR* d = opendir(dir.c_str()))
  {
    while(dirent* e = readdir(d))
    {
      const std::string n = e->d_name;
      if(n.size() > 4 && n.compare(n.size() - 4, 4, ".off") == 0) names.push_back(n);
    }
    closedir(d);
  }
  else { std::cerr << "constrained_benchmark: cannot read " << dir << "\n"; return 3; }
  std::sort(names.begin(), names.end());

  std::vector<Row> rows;
  for(const std::string& name : names)
  {
    if(!only.empty() && std::find(only.begin(), only.end(), name) == only.end()) continue;
    SM input;
    if(!CGAL::IO::read_polygon_mesh(dir + "/" + name, input) || !CGAL::is_triangle_mesh(input)) continue;
    if(input.number_of_vertices() < min_vertices || input.number_of_vertices() > max_vertices) continue;
    const bool disk = is_disk(input);
    const bool sphere = !disk && is_closed_genus_0(input);
    if((disk && !disks) || (sphere && !closed) || (!disk && !sphere)) continue;
    for(unsigned seed = 0; seed < seeds; ++seed)
    {
      SM m = input;
      if(sphere && !cut_open(m, seed)) { std::cerr << name << " seed " << seed << ": the cut is not a disk, skipped\n"; continue; }
      UV_map uv = m.add_property_map<vertex_descriptor, K::Point_2>("v:uv", K::Point_2(0, 0)).first;
      if(!square_border(m, uv)) { std::cerr << name << ": no square border, skipped\n"; continue; }
      std::vector<vertex_descriptor> interior;
      for(vertex_descriptor v : vertices(m)) if(!CGAL::is_border(v, m)) interior.push_back(v);
      const bool optimize = seed < optimize_seeds;
      double unconstrained = -1;
      if(optimize)
      {
        const Row u = run(m, {}, true, budget, max_steiner);
        if(u.status == "OK") unconstrained = u.mean_after;
      }
      for(std::size_t count : counts)
      for(const std::string& targets : (count <= 3 ? std::vector<std::string>{"fixed"} : target_kinds))
      {
        if(count > interior.size() || (count > 3 && seed >= seeds_large)) continue;
        std::mt19937 gen(seed * 1000u + unsigned(count));
        std::vector<vertex_descriptor> pick = interior;
        std::shuffle(pick.begin(), pick.end(), gen);
        std::uniform_real_distribution<double> U(-1, 2), J(-jitter, jitter);
        std::vector<std::pair<vertex_descriptor, K::Point_2> > constraints;
        std::set<std::pair<double, double> > used;
        const K::Point_2 corners[3] = {K::Point_2(0, 0), K::Point_2(1, 0), K::Point_2(0, 1)};
        auto inside = [](double x) { return std::min(2.4, std::max(-1.4, x)); };
        auto draw = [&](vertex_descriptor v) {
          if(targets == "random") return K::Point_2(U(gen), U(gen));
          // layout: the vertex's place in the Tutte map on the same border; jittered: moved a little
          const K::Point_2 p = get(uv, v);
          if(targets == "layout") return K::Point_2(inside(p.x()), inside(p.y()));
          return K::Point_2(inside(p.x() + J(gen)), inside(p.y() + J(gen)));
        };
        // distinct targets: a vertex whose target is taken is skipped (bounded by the interior vertices)
        for(std::size_t j = 0; j < pick.size() && constraints.size() < count; ++j)
        {
          const std::size_t k = constraints.size();
          const K::Point_2 t = targets == "fixed" ? corners[k] : draw(pick[j]);
          if(used.insert({t.x(), t.y()}).second) constraints.emplace_back(pick[j], t);
        }
        if(constraints.size() < count) continue;
        std::vector<Row> tries;
        for(int t = 0; t < repeat; ++t)
        {
          tries.push_back(run(m, constraints, optimize, budget, max_steiner));
          if(tries.back().status != "OK" || !tries.back().certified) break; // a failure is the result
        }
        std::sort(tries.begin(), tries.end(), [](const Row& x, const Row& y) {
          const bool fx = x.status != "OK" || !x.certified, fy = y.status != "OK" || !y.certified;
          return fx != fy ? fx : x.t_certified < y.t_certified; });
        if(tries.front().status == "OK" && tries.front().certified)
          for(const Row& t : tries)
            if(t.steiner != tries.front().steiner)
              std::cerr << name << " seed " << seed << ": repeats differ (" << t.steiner << " vs " << tries.front().steiner << " Steiner vertices)\n";
        Row r = tries.front().status != "OK" || !tries.front().certified ? tries.front() : tries[(tries.size() - 1) / 2];
        r.kind = disk ? "disk" : "closed";
        r.targets = targets;
        r.mesh = name; r.seed = seed;
        r.unconstrained_mean = unconstrained;
        std::cerr << name << " seed " << seed << " K=" << count << " " << targets << ": " << r.status << ", " << r.v_in << " -> " << r.v_out
                  << " (+" << r.steiner << "), " << r.paths << " paths, " << r.patches << " patches, certified map "
                  << fmt(r.t_certified) << " s, total " << fmt(r.t_total) << " s, peak " << fmt(r.peak_mb, 4)
                  << " MB, error " << r.constraint_error
                  << (r.optimized ? ", mean SD " + fmt(r.mean_after, 4) + " (unconstrained " + fmt(unconstrained, 4) + ")" : "")
                  << "\n";
        rows.push_back(r);
      }
    }
  }

  std::ofstream csv(out + ".csv");
  csv << "kind,mesh,seed,constraints,targets,vertices_in,vertices_out,steiner,added_percent,chord_splits,paths,patches,"
         "repaired_patches,status,certified,constraint_error,s_validation,s_partition,s_tracing,s_patches,"
         "s_certification,s_certified_map,s_optimization,s_output,s_total,peak_rss_mb,optimized,optimization_status,"
         "iterations,mean_sd_before,max_sd_before,mean_sd_after,max_sd_after,unconstrained_mean_sd,steiner_inserted,"
         "steiner_removed,s_coarsening,tracing,kinetic_motion\n";
  csv << std::setprecision(6);
  for(const Row& r : rows)
    csv << r.kind << ',' << r.mesh << ',' << r.seed << ',' << r.count << ',' << r.targets << ',' << r.v_in << ',' << r.v_out << ','
        << r.steiner << ',' << (r.v_in ? 100.0 * double(r.steiner) / double(r.v_in) : 0) << ',' << r.chord_splits << ','
        << r.paths << ',' << r.patches << ',' << r.repaired << ',' << r.status << ',' << (r.certified ? 1 : 0) << ','
        << r.constraint_error << ',' << r.t_validation << ',' << r.t_partition << ',' << r.t_tracing << ','
        << r.t_patches << ',' << r.t_certification << ',' << r.t_certified << ',' << r.t_optimization << ','
        << r.t_output << ',' << r.t_total << ',' << r.peak_mb << ',' << (r.optimized ? 1 : 0) << ','
        << r.optimization_status << ',' << r.iterations << ',' << r.mean_before << ',' << r.max_before << ','
        << r.mean_after << ',' << r.max_after << ',' << r.unconstrained_mean << ',' << r.inserted << ',' << r.removed << ','
        << r.t_coarsening << ',' << r.tracing << ',' << r.kinetic_motion << '\n';

  // Markdown: per (mesh, count) medians over the seeds
  std::size_t ok = 0, certified = 0, exact = 0;
  for(const Row& r : rows) { ok += r.status == "OK"; certified += r.certified; exact += r.status == "OK" && r.constraint_error == 0; }
  char host[256] = {0};
  gethostname(host, sizeof host - 1);
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  double load[3] = {0, 0, 0};
  if(FILE* f = std::fopen("/proc/loadavg", "r")) { if(std::fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3) load[0] = -1; std::fclose(f); }
  std::ofstream md(out + ".md");
  md << "# constrained_embedding(): the MatchMaker++ protocol on libcgal-demo meshes\n\n"
     << "Generated " << date << " by `constrained_benchmark` (" << sysconf(_SC_NPROCESSORS_ONLN)
     << " cores; load average " << load[0] << " at the end; patches embedded "
     << (sequential ? "sequentially" : "in parallel")
     << (repeat > 1 ? "; each run " + std::to_string(repeat) + " times, the one of median time to the certified map kept" : std::string())
     << "). Disks as they are; closed genus-0 meshes cut open around "
        "the Tutte-failure protocol's face for the seed. Border: the square [-1.5, 2.5]^2 by 3D arc length. K "
        "constraints: K random interior vertices, the first three at (0,0), (1,0), (0,1) (targets `fixed`, K = 3); for K > 3 "
        "either at random points of [-1, 2]^2 (`random`: an arbitrary layout, the paths must wind), at their places "
        "in the Tutte map on the same border (`layout`: the surface's own layout, as feature alignment gives), or there "
        "moved by up to " << jitter << " in x and y (`jittered`: nearby constraints may swap, which the Tutte map's "
        "compressed regions make frequent). Time to the certified map: validation, partition, path tracing, patch embeddings and the "
        "certificate (before the optimization). Added vertices: inserted by the refinement, removed again by the "
        "coarsening after the optimization (" << (coarsen ? "on" : "off: `--no-coarsen`") << "), kept in the output. Path tracings: "
        "shortest paths, then, when they add many vertices, the kinetic tracing (" << (kinetic ? "on" : "off: `--no-kinetic`") <<
        "), the overlay and the guided ones, the one with the fewest added vertices kept (column `tracing`; CSV column `kinetic_motion`: the motion kept, 0 the straight line, 1-4 the braids at 0, 90, 45, 135 degrees, -1 none). Symmetric Dirichlet energies against the 3D triangles (an isometry "
        "scores 4), optimized with border and constraints fixed, next to the optimized map with no constraint on the "
        "same border.\n\n"
     << "- runs: " << rows.size() << "; OK: " << ok << "; certified again by check_embedding(): " << certified
     << "; every constraint bit-exact: " << exact << "\n\n"
     << "Per mesh and constraint count, medians over the seeds (optimization: the seeds where it ran).\n\n"
     << "| mesh | kind | K | targets | vertices in | seeds OK | inserted | removed | kept | added % | vertices out | paths | patches | certified map s | peak MB | optimize s | mean SD after | unconstrained mean SD |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::map<std::tuple<std::string, std::size_t, std::string>, std::vector<const Row*> > groups;
  std::vector<std::tuple<std::string, std::size_t, std::string> > order;
  for(const Row& r : rows)
  {
    auto key = std::make_tuple(r.mesh, r.count, r.targets);
    if(!groups.count(key)) order.push_back(key);
    groups[key].push_back(&r);
  }
  for(const auto& key : order)
  {
    const auto& g = groups[key];
    std::vector<double> steiner, inserted, removed, vout, added, paths, patches, tcert, peak, topt, mean, umean;
    std::size_t good = 0;
    for(const Row* r : g)
    {
      if(r->status != "OK") continue;
      ++good;
      steiner.push_back(double(r->steiner)); inserted.push_back(double(r->inserted)); removed.push_back(double(r->removed));
      vout.push_back(double(r->v_out)); added.push_back(100.0 * double(r->steiner) / double(r->v_in));
      paths.push_back(double(r->paths)); patches.push_back(double(r->patches));
      tcert.push_back(r->t_certified); peak.push_back(r->peak_mb);
      if(r->optimized) { topt.push_back(r->t_optimization); mean.push_back(r->mean_after); }
      if(r->unconstrained_mean >= 0) umean.push_back(r->unconstrained_mean);
    }
    md << "| " << std::get<0>(key) << " | " << g.front()->kind << " | " << std::get<1>(key) << " | " << std::get<2>(key) << " | " << g.front()->v_in << " | " << good
       << "/" << g.size() << " | " << fmt(median(inserted), 4) << " | " << fmt(median(removed), 4) << " | "
       << fmt(median(steiner), 4) << " | " << fmt(median(added)) << " | " << fmt(median(vout), 6) << " | " << fmt(median(paths))
       << " | " << fmt(median(patches)) << " | " << fmt(median(tcert)) << " | " << fmt(median(peak), 4) << " | "
       << fmt(median(topt)) << " | " << fmt(median(mean), 4) << " | " << fmt(median(umean), 4) << " |\n";
  }
  md << "\nRuns that did not return OK:\n\n";
  std::size_t bad = 0;
  for(const Row& r : rows)
    if(r.status != "OK") { md << "- " << r.mesh << " seed " << r.seed << " K=" << r.count << " " << r.targets << ": " << r.status << " (" << r.steiner << " Steiner vertices when it stopped)" << "\n"; ++bad; }
  if(!bad) md << "- none\n";
  md << "\nCommand: `constrained_benchmark";
  for(int i = 1; i < argc; ++i) md << ' ' << argv[i];
  md << "` (" << host << ")\n";
  std::cerr << rows.size() << " runs, " << ok << " OK, " << certified << " certified, " << exact << " bit-exact; wrote "
            << out << ".{csv,md}\n";
  return ok == rows.size() && certified == rows.size() && exact == rows.size() ? 0 : 1;
}
