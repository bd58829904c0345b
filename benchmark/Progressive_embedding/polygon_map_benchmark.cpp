// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors
//
// constrained_embedding() onto fixed borders that are not convex, on real disks:
//   hilbert : the outline of the thickened Hilbert curve (polygon_shapes.h) of order 3 (104 corners), on
//             every disk: a border with fewer vertices is refined first (its longest edge split at the 3D
//             midpoint until it has 104; these vertices count as added), with 3 constraints at random points
//             inside (the paper's space-filling-curve stress test); simple, not convex: an embedding;
//   star    : a star with min(8, nb / 4) tips (radii 1 and 0.4), 3 constraints inside: an embedding;
//   spiral  : a strip winding twice around a spiral (min(nb, 64) corners, overlapping itself), border only:
//             an immersion;
//   own     : (--obj inputs) the disk's own uv border, its rotation indices read from the own map
//             (border_rotation_indices()), 3 constraints inside if it is simple.
// The border vertices go onto the polygon by 3D arc length: each corner on the border vertex nearest to
// its perimeter fraction (distinct, in order), the vertices between two corners on the side between them.
// Constraints: 3 distinct random interior vertices to distinct random points strictly inside the border
// polygon. Each run is a child process (its peak memory is its own; a crash or an overrun is recorded, not
// fatal); the map is certified again on the output (check_embedding, or check_immersion with the border
// polygon), the border and the constraints compared bit-exactly, then the time, the vertices added and the
// symmetric Dirichlet energy before and after the optimization are recorded.
//
//   polygon_map_benchmark DATA_DIR OUT_PREFIX [--meshes a.off,b.off] [--obj FILE.obj]... [--seeds S]
//        [--shapes hilbert,star,spiral,own] [--min-vertices N] [--budget SECONDS] [--no-optimize] [--max-steiner N]
//
// Writes OUT_PREFIX.csv (one row per run) and OUT_PREFIX.md.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Progressive_embedding/constrained_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/check_immersion.h>
#include <CGAL/Progressive_embedding/IO/OBJ_with_uv.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include "polygon_shapes.h"
#include "process_memory.h"

#include <dirent.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace PE = CGAL::Progressive_embedding;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2                                            P2;
typedef CGAL::Surface_mesh<K::Point_3>                        SM;
typedef boost::graph_traits<SM>::vertex_descriptor            vertex_descriptor;
typedef SM::Property_map<vertex_descriptor, P2>               UV_map;
typedef pe_bench::Shapes<P2>                                  Shapes;

namespace {

struct Input
{
  std::string name;
  SM mesh;
  UV_map uv;            // the own uv map (OBJ inputs)
  bool has_uv = false;
};

// the border loop (interior on the left) of a disk, empty if it is not one
std::vector<vertex_descriptor> border_loop(const SM& m)
{
  PE::internal::Indexed_disk<SM> disk;
  std::vector<vertex_descriptor> b;
  if(PE::internal::make_indexed_disk(m, SM::null_halfedge(), disk) != PE::OK) return b;
  for(std::size_t i : disk.border) b.push_back(disk.vertices[i]);
  return b;
}

// the border vertices onto the polygon Q (corners) by 3D arc length; false if Q has more corners than
// the border has vertices
bool place_border(const SM& m, const std::vector<vertex_descriptor>& B, const std::vector<P2>& Q, UV_map uv)
{
  const std::size_t nb = B.size(), nq = Q.size();
  if(nq < 3 || nb < nq) return false;
  std::vector<double> s(nb + 1, 0.), t(nq + 1, 0.);
  for(std::size_t k = 0; k < nb; ++k) s[k + 1] = s[k] + std::sqrt(CGAL::squared_distance(m.point(B[k]), m.point(B[(k + 1) % nb])));
  for(std::size_t j = 0; j < nq; ++j) t[j + 1] = t[j] + std::sqrt(CGAL::squared_distance(Q[j], Q[(j + 1) % nq]));
  std::vector<std::size_t> at(nq + 1, 0);
  at[nq] = nb;
  for(std::size_t j = 1; j < nq; ++j)
  {
    // nearest to the perimeter fraction, after the previous corner, leaving one vertex for each later corner
    const double target = t[j] / t[nq] * s[nb];
    std::size_t best = at[j - 1] + 1;
    for(std::size_t k = best; k <= nb - (nq - j); ++k)
      if(std::abs(s[k] - target) < std::abs(s[best] - target)) best = k;
    at[j] = best;
  }
  for(std::size_t j = 0; j < nq; ++j)
  {
    const P2& a = Q[j];
    const P2& b = Q[(j + 1) % nq];
    const double len = s[at[j + 1]] - s[at[j]];
    put(uv, B[at[j]], a);
    for(std::size_t k = at[j] + 1; k < at[j + 1]; ++k)
    {
      const double f = len > 0 ? (s[k] - s[at[j]]) / len : double(k - at[j]) / double(at[j + 1] - at[j]);
      // an axis-parallel side keeps one coordinate exactly
      put(uv, B[k], P2(a.x() == b.x() ? a.x() : a.x() + f * (b.x() - a.x()), a.y() == b.y() ? a.y() : a.y() + f * (b.y() - a.y())));
    }
  }
  return true;
}

// splits the longest border edge (at its 3D midpoint, the incident face by the diagonal to its opposite
// corner: the surface is unchanged) until the border has at least n vertices, so that every disk takes the
// order-3 Hilbert outline (104 corners); returns the vertices added
std::size_t refine_border(SM& m, std::size_t n)
{
  std::size_t added = 0;
  for(std::vector<vertex_descriptor> B = border_loop(m); B.size() < n && B.size() >= 3; B = border_loop(m), ++added)
  {
    SM::Halfedge_index longest;
    double best = -1;
    for(SM::Halfedge_index h : m.halfedges())
    {
      if(!m.is_border(h)) continue;
      const double l = CGAL::squared_distance(m.point(m.source(h)), m.point(m.target(h)));
      if(l > best) { best = l; longest = h; }
    }
    const K::Point_3 mid = CGAL::midpoint(m.point(m.source(longest)), m.point(m.target(longest)));
    const SM::Halfedge_index inner = m.opposite(longest);
    const SM::Halfedge_index hnew = CGAL::Euler::split_edge(inner, m); // ends at the new vertex
    m.point(m.target(hnew)) = mid;
    CGAL::Euler::split_face(hnew, m.next(m.next(hnew)), m);
  }
  return added;
}

struct Row
{
  std::string mesh, shape, status = "CRASHED", certificate = "-", optimization = "-";
  unsigned seed = 0;
  int order = 0;
  std::size_t v_in = 0, border = 0, corners = 0, constraints = 0, v_out = 0, steiner = 0, paths = 0, patches = 0;
  bool border_exact = false, constraints_exact = false, optimized = false;
  double t_certified = 0, t_optimize = 0, t_total = 0, peak_mb = 0, sd_before = 0, sd_after = 0;
};

// the run, in the child process; the result as one line on `fd`
void run_child(const Input& in, const std::string& shape, unsigned seed, double budget, bool optimize, std::size_t max_steiner, int fd)
{
  Row r;
  SM m = in.mesh;
  UV_map uv = m.add_property_map<vertex_descriptor, P2>("v:bench_uv", P2(0, 0)).first;
  const std::size_t vertices_given = m.number_of_vertices();
  std::size_t border_added = 0;
  std::vector<P2> Q;
  if(shape == "hilbert")
  {
    // order 3 on every disk, as the authors' test: a border with fewer vertices than its 104 corners is
    // refined first (these splits count as vertices added)
    Q = Shapes::corners_only(Shapes::hilbert(3));
    r.order = 3;
    border_added = refine_border(m, Q.size());
  }
  const std::vector<vertex_descriptor> B = border_loop(m);
  std::size_t constraints = 3;
  if(shape == "star") Q = Shapes::star(2 * std::max<std::size_t>(3, std::min<std::size_t>(8, B.size() / 4)));
  else if(shape == "spiral") { Q = Shapes::spiral(std::min<std::size_t>(64, B.size() & ~std::size_t(1))); constraints = 0; }
  r.corners = shape == "own" ? B.size() : Q.size();
  bool placed = false;
  if(shape == "own")
  {
    for(vertex_descriptor v : vertices(m)) put(uv, v, get(in.uv, v));
    placed = in.has_uv;
  }
  else placed = place_border(m, B, Q, uv);
  std::vector<P2> border;
  for(vertex_descriptor v : B) border.push_back(get(uv, v));
  std::ostringstream os;
  if(!placed) r.status = "NOT_APPLICABLE";
  else
  {
    // constraints only on a simple border (a point of an overlapping domain may lie on several sheets)
    if(!CGAL::is_simple_2(border.begin(), border.end(), K())) constraints = 0;
    std::mt19937 rng(seed);
    std::vector<vertex_descriptor> interior;
    for(vertex_descriptor v : vertices(m)) if(!CGAL::is_border(v, m)) interior.push_back(v);
    std::shuffle(interior.begin(), interior.end(), rng);
    const CGAL::Bbox_2 box = CGAL::bbox_2(border.begin(), border.end());
    std::uniform_real_distribution<double> ux(box.xmin(), box.xmax()), uy(box.ymin(), box.ymax());
    std::vector<std::pair<vertex_descriptor, P2> > C;
    for(std::size_t tries = 0; C.size() < std::min(constraints, interior.size()) && tries < 100000; ++tries)
    {
      const P2 p(ux(rng), uy(rng));
      if(CGAL::bounded_side_2(border.begin(), border.end(), p, K()) != CGAL::ON_BOUNDED_SIDE) continue;
      bool distinct = true;
      for(const auto& c : C) if(c.second == p) distinct = false;
      if(distinct) C.emplace_back(interior[C.size()], p);
    }
    r.constraints = C.size();
    r.v_in = vertices_given;
    PE::Constrained_embedding_statistics st;
    // PE_VERBOSE=1 in the environment: constrained_embedding() reports its phases on std::cerr
    const bool verbose = std::getenv("PE_VERBOSE") != nullptr;
    const auto np = PE::parameters::statistics(&st).optimize(optimize).maximum_running_time(budget).verbose(verbose);
    // the own border may wrap around some of its vertices (a seamless map cut through cones): its turns
    // are read from the own map
    auto turns = m.add_property_map<vertex_descriptor, int>("v:bench_turns", 0).first;
    if(shape == "own") PE::border_rotation_indices(m, uv, turns);
    const auto npt = PE::parameters::vertex_rotation_index_map(turns, np);
    const PE::Error_code ec = max_steiner ? PE::constrained_embedding<CGAL::Parallel_if_available_tag>(m, C, uv, PE::parameters::maximum_steiner_vertices(max_steiner, npt))
                                          : PE::constrained_embedding<CGAL::Parallel_if_available_tag>(m, C, uv, npt);
    r.peak_mb = pe_bench::peak_rss_mb();
    r.status = PE::get_error_name(ec);
    r.v_out = m.number_of_vertices();
    r.steiner = st.steiner_vertices + border_added; r.paths = st.paths; r.patches = st.patches;
    r.t_total = st.seconds_total; r.t_optimize = st.seconds_optimization; r.t_certified = st.seconds_total - st.seconds_optimization - st.seconds_output;
    r.optimized = st.optimized;
    if(st.optimized) r.optimization = PE::get_error_name(st.optimization_status);
    r.sd_before = st.report_before_optimization.mean_energy_3d; r.sd_after = st.report.mean_energy_3d;
    if(ec == PE::OK)
    {
      // certified again on the output, border and constraints bit-exact
      r.border_exact = true;
      for(std::size_t k = 0; k < B.size(); ++k) if(!(get(uv, B[k]) == border[k])) r.border_exact = false;
      r.constraints_exact = true;
      for(const auto& c : C) if(!(get(uv, c.first) == c.second)) r.constraints_exact = false;
      if(st.immersion)
      {
        const PE::Immersion_report ir = PE::check_immersion(m, uv, B.front(), border);
        r.certificate = ir.is_immersion() && ir.border_mismatches == 0 ? "immersion" : "FAILED";
      }
      else r.certificate = PE::check_embedding(m, uv).is_valid() ? "embedding" : "FAILED";
    }
  }
  os << r.status << ' ' << r.certificate << ' ' << r.order << ' ' << r.v_in << ' ' << B.size() << ' ' << r.corners << ' '
     << r.constraints << ' ' << r.v_out << ' ' << r.steiner << ' ' << r.paths << ' ' << r.patches << ' ' << r.border_exact << ' '
     << r.constraints_exact << ' ' << r.optimized << ' ' << r.t_certified << ' ' << r.t_optimize << ' ' << r.t_total << ' '
     << r.peak_mb << ' ' << r.sd_before << ' ' << r.sd_after << ' ' << r.optimization << '\n';
  const std::string s = os.str();
  if(::write(fd, s.data(), s.size()) < 0) { }
}

// forks, runs, kills the child after `wall` seconds
Row run_one(const Input& in, const std::string& shape, unsigned seed, double budget, bool optimize, std::size_t max_steiner, double wall)
{
  Row r;
  r.mesh = in.name; r.shape = shape; r.seed = seed;
  int fds[2];
  if(pipe(fds) != 0) return r;
  std::cout.flush();
  const pid_t pid = fork();
  if(pid < 0) return r;
  if(pid == 0)
  {
    close(fds[0]);
    run_child(in, shape, seed, budget, optimize, max_steiner, fds[1]);
    close(fds[1]);
    _exit(0);
  }
  close(fds[1]);
  int status = 0;
  const auto start = std::chrono::steady_clock::now();
  bool killed = false;
  while(waitpid(pid, &status, WNOHANG) == 0)
  {
    if(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > wall)
    {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      killed = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::string out;
  char buf[1024];
  ssize_t k;
  while((k = read(fds[0], buf, sizeof buf)) > 0) out.append(buf, std::size_t(k));
  close(fds[0]);
  std::istringstream is(out);
  if(!(is >> r.status >> r.certificate >> r.order >> r.v_in >> r.border >> r.corners >> r.constraints >> r.v_out >> r.steiner
          >> r.paths >> r.patches >> r.border_exact >> r.constraints_exact >> r.optimized >> r.t_certified >> r.t_optimize
          >> r.t_total >> r.peak_mb >> r.sd_before >> r.sd_after >> r.optimization))
    r.status = killed ? "KILLED_AFTER_" + std::to_string(int(wall)) + "S" : "CRASHED";
  return r;
}

std::vector<std::string> split(const std::string& s, char sep)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  for(std::string t; std::getline(ss, t, sep); ) if(!t.empty()) out.push_back(t);
  return out;
}

std::string fmt(double x, int p = 3)
{
  std::ostringstream os;
  os << std::setprecision(p) << x;
  return os.str();
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " DATA_DIR OUT_PREFIX [--meshes a.off,b.off] [--obj FILE.obj]... [--seeds S]\n"
                 "       [--shapes hilbert,star,spiral,own] [--min-vertices N] [--budget SECONDS] [--no-optimize] [--max-steiner N]" << std::endl;
    return 2;
  }
  const std::string data = argv[1], out = argv[2];
  std::vector<std::string> only, objs, shapes = { "hilbert", "star", "spiral", "own" };
  unsigned seeds = 3;
  std::size_t min_vertices = 300;
  double budget = 60;
  bool optimize = true;
  std::size_t max_steiner = 0; // 0: constrained_embedding's default
  for(int i = 3; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool has = i + 1 < argc;
    if(a == "--meshes" && has) only = split(argv[++i], ',');
    else if(a == "--obj" && has) objs.push_back(argv[++i]);
    else if(a == "--seeds" && has) seeds = unsigned(std::atoi(argv[++i]));
    else if(a == "--shapes" && has) shapes = split(argv[++i], ',');
    else if(a == "--min-vertices" && has) min_vertices = std::stoul(argv[++i]);
    else if(a == "--budget" && has) budget = std::atof(argv[++i]);
    else if(a == "--no-optimize") optimize = false;
    else if(a == "--max-steiner" && has) max_steiner = std::stoul(argv[++i]);
    else { std::cerr << "unknown argument " << a << std::endl; return 2; }
  }

  // the disks: libcgal-demo meshes with one border loop (and --meshes), then the OBJ files' uv disks
  std::vector<Input> inputs;
  std::vector<std::string> names;
  if(DIR* d = opendir((data + "/meshes").c_str()))
  {
    while(dirent* e = readdir(d)) names.push_back(e->d_name);
    closedir(d);
  }
  std::sort(names.begin(), names.end());
  for(const std::string& name : names)
  {
    if(name.size() < 5 || name.substr(name.size() - 4) != ".off") continue;
    if(!only.empty() && std::find(only.begin(), only.end(), name) == only.end()) continue;
    Input in;
    in.name = name;
    if(!CGAL::IO::read_polygon_mesh(data + "/meshes/" + name, in.mesh) || !CGAL::is_triangle_mesh(in.mesh)) continue;
    if(in.mesh.number_of_vertices() < min_vertices || border_loop(in.mesh).size() < 3) continue;
    in.uv = in.mesh.add_property_map<vertex_descriptor, P2>("v:own_uv", P2(0, 0)).first;
    inputs.push_back(std::move(in));
  }
  for(const std::string& f : objs)
  {
    Input in;
    in.name = f.substr(f.find_last_of('/') + 1);
    in.uv = in.mesh.add_property_map<vertex_descriptor, P2>("v:own_uv", P2(0, 0)).first;
    std::ifstream is(f);
    const PE::IO::Read_result rr = PE::IO::read_OBJ_with_uv(is, in.mesh, in.uv);
    if(rr.status != PE::OK || border_loop(in.mesh).size() < 3) { std::cerr << f << ": not an OBJ disk with vt, skipped" << std::endl; continue; }
    in.has_uv = true;
    inputs.push_back(std::move(in));
  }

  std::vector<Row> rows;
  for(const Input& in : inputs)
    for(const std::string& shape : shapes)
    {
      if(shape == "own" && !in.has_uv) continue;
      for(unsigned seed = 0; seed < (shape == "spiral" ? 1u : seeds); ++seed)
      {
        Row r = run_one(in, shape, seed, budget, optimize, max_steiner, 3 * budget + 30);
        std::cout << r.mesh << " " << r.shape << (r.order ? " order " + std::to_string(r.order) : std::string()) << " seed " << seed
                  << ": " << r.status << ", " << r.certificate << ", vertices " << r.v_in << " -> " << r.v_out << " (border "
                  << r.border << ", corners " << r.corners << ", constraints " << r.constraints << "), certified map "
                  << fmt(r.t_certified) << " s, optimized " << fmt(r.t_optimize) << " s, peak " << fmt(r.peak_mb, 4)
                  << " MB, SD " << fmt(r.sd_before, 4) << " -> " << fmt(r.sd_after, 4) << " (optimization "
                  << r.optimization << ")" << std::endl;
        rows.push_back(r);
      }
    }

  std::ofstream csv(out + ".csv");
  csv << "mesh,shape,order,seed,status,certificate,vertices_in,border_vertices,polygon_corners,constraints,vertices_out,"
         "steiner,added_percent,paths,patches,border_exact,constraints_exact,optimized,certified_map_s,optimize_s,total_s,"
         "peak_mb,mean_sd_before_optimization,mean_sd_after,optimization_status\n";
  std::size_t ok = 0, certified = 0, exact = 0, applicable = 0;
  for(const Row& r : rows)
  {
    const double added = r.v_in ? 100. * double(r.v_out - r.v_in) / double(r.v_in) : 0.;
    csv << r.mesh << ',' << r.shape << ',' << r.order << ',' << r.seed << ',' << r.status << ',' << r.certificate << ','
        << r.v_in << ',' << r.border << ',' << r.corners << ',' << r.constraints << ',' << r.v_out << ',' << r.steiner << ','
        << added << ',' << r.paths << ',' << r.patches << ',' << r.border_exact << ',' << r.constraints_exact << ','
        << r.optimized << ',' << r.t_certified << ',' << r.t_optimize << ',' << r.t_total << ',' << r.peak_mb << ','
        << r.sd_before << ',' << r.sd_after << ',' << r.optimization << '\n';
    if(r.status != "NOT_APPLICABLE") ++applicable;
    if(r.status == "OK") ++ok;
    if(r.certificate == "embedding" || r.certificate == "immersion") ++certified;
    if(r.status == "OK" && r.border_exact && r.constraints_exact) ++exact;
  }

  std::ofstream md(out + ".md");
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  double load = 0;
  { std::ifstream f("/proc/loadavg"); f >> load; }
  md << "# constrained_embedding() onto non-convex and self-overlapping borders\n\n"
     << "Generated " << date << " by `polygon_map_benchmark` (2 cores; load average " << load << " at the end). "
     << "Disks of libcgal-demo with at least " << min_vertices << " vertices"
     << (objs.empty() ? std::string() : std::string(", and the uv disks of the OBJ files given")) << ". "
     << "Borders: `hilbert` the thickened Hilbert curve outline of order 3 (104 corners; a border with fewer vertices "
        "is refined first by splitting its longest edges, counted as added vertices), 3 constraints at random points "
        "inside; `star` "
        "min(8, nb/4) tips, 3 constraints; `spiral` a strip winding twice around a spiral (min(nb, 64) corners; "
        "weakly self-overlapping), border only; `own` the disk's own uv border (OBJ inputs; its rotation indices read from the own map, "
        "border_rotation_indices()), 3 constraints if simple. "
        "Border vertices onto the polygon by 3D arc length (one polygon vertex per border vertex, corners on border "
        "vertices). Each run in its own process; the output certified again (check_embedding, or check_immersion "
        "with the border polygon), border and constraints compared bit-exactly. Time to the certified map: "
        "everything before the optimization (which then runs with border and constraints fixed). Symmetric "
        "Dirichlet mean against the 3D triangles (an isometry scores 4).\n\n"
     << "- runs: " << rows.size() << "; applicable (enough border vertices for the polygon): " << applicable
     << "; OK: " << ok << "; certified again: " << certified << "; border and constraints bit-exact: " << exact << "\n\n"
     << "Per shape (medians over the runs that returned OK):\n\n"
     << "| shape | runs | OK | certified again | vertices added % (median) | (max) | certified map s (median) | (max) "
        "| mean SD after (median) |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const std::string& shape : shapes)
  {
    std::vector<double> added, seconds, sd;
    std::size_t runs = 0, good = 0;
    for(const Row& r : rows)
    {
      if(r.shape != shape) continue;
      ++runs;
      if(r.certificate == "embedding" || r.certificate == "immersion") ++good;
      if(r.status != "OK") continue;
      added.push_back(100. * double(r.v_out - r.v_in) / double(r.v_in));
      seconds.push_back(r.t_certified);
      sd.push_back(r.sd_after);
    }
    if(runs == 0) continue;
    auto median = [](std::vector<double> v) {
      if(v.empty()) return 0.;
      std::sort(v.begin(), v.end());
      const std::size_t n = v.size();
      return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]); // the mean of the two middle values for an even count
    };
    auto top = [](const std::vector<double>& v) { return v.empty() ? 0. : *std::max_element(v.begin(), v.end()); };
    md << "| " << shape << " | " << runs << " | " << added.size() << " | " << good << " | " << fmt(median(added)) << " | "
       << fmt(top(added)) << " | " << fmt(median(seconds)) << " | " << fmt(top(seconds)) << " | " << fmt(median(sd), 4) << " |\n";
  }
  md << "\nRuns that did not return OK:\n\n";
  std::size_t failures = 0;
  for(const Row& r : rows)
    if(r.status != "OK")
    {
      md << "- " << r.mesh << " " << r.shape << (r.order ? " order " + std::to_string(r.order) : std::string()) << " seed " << r.seed
         << ": " << r.status << " (vertices " << r.v_in << ", border " << r.border << ", corners " << r.corners
         << ", Steiner vertices when it stopped " << r.steiner << ")\n";
      ++failures;
    }
  if(failures == 0) md << "- none\n";
  md << "\nEvery run:\n\n"
     << "| mesh | shape | order | seed | status | certificate | vertices in | border | corners | K | vertices out | added % "
        "| patches | certified map s | optimize s | optimization | peak MB | mean SD before opt. | mean SD after |\n"
     << "|---|---|---:|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|\n";
  for(const Row& r : rows)
  {
    const double added = r.v_in ? 100. * double(r.v_out - r.v_in) / double(r.v_in) : 0.;
    md << "| " << r.mesh << " | " << r.shape << " | " << (r.order ? std::to_string(r.order) : std::string("-")) << " | "
       << r.seed << " | " << r.status << " | " << r.certificate << " | " << r.v_in << " | " << r.border << " | "
       << r.corners << " | " << r.constraints << " | " << r.v_out << " | " << fmt(added) << " | " << r.patches << " | "
       << fmt(r.t_certified) << " | " << fmt(r.t_optimize) << " | " << r.optimization << " | " << fmt(r.peak_mb, 4) << " | " << fmt(r.sd_before, 4)
       << " | " << fmt(r.sd_after, 4) << " |\n";
  }
  md << "\nCommand: `polygon_map_benchmark";
  for(int i = 1; i < argc; ++i) md << ' ' << argv[i];
  md << "`\n";
  std::cout << "runs " << rows.size() << ", applicable " << applicable << ", OK " << ok << ", certified " << certified
            << ", bit-exact " << exact << "; wrote " << out << ".csv and " << out << ".md" << std::endl;
  return 0;
}
