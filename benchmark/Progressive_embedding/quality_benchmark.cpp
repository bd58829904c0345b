// Benchmark driver (not run by ctest): quality by default. For every run of the Tutte-failure
// corpus: double Tutte, the default repair (progressive_embedding with default parameters), then
// the default optimize_distortion; per run the mean and max symmetric Dirichlet energy before and
// after, time, iterations, status, and the stability check (ten times the iterations, tolerance 0,
// from the optimized map: how much more the mean drops).
//
//   quality_benchmark DATA_DIR CORPUS_TSV OUT_PREFIX [--only MESH SEED] [--no-stability] [--smoothing N]
//
// --smoothing N repairs with smoothing_iterations(N) instead of the default (to compare pipelines).
//
// Writes OUT_PREFIX.csv and OUT_PREFIX.md. Energies are the certificate's (`mean_energy_3d`, 4 for
// an isometry; libigl's SLIM reports half of it).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace PE = CGAL::Progressive_embedding;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> SM;

struct Run
{
  std::string mesh; unsigned seed = 0; std::size_t vertices = 0;
  double repair_seconds = 0, repaired_mean = 0, repaired_max = 0;
  std::string status; bool valid = false, border_exact = false; std::size_t iterations = 0;
  double seconds = 0, mean = 0, max = 0;
  bool stability_run = false; double stability_mean = 0; std::size_t stability_iterations = 0;
};

static std::string fmt(double x)
{
  std::ostringstream os;
  os << std::setprecision(4) << x;
  return os.str();
}

static int smoothing = -1; // --smoothing N

static bool run_one(const std::string& data, Run& r, bool stability)
{
  SM m;
  if(!CGAL::IO::read_polygon_mesh(data + "/meshes/" + r.mesh, m)) return false;
  std::array<SM::Vertex_index, 3> pinned;
  if(PE::internal::thingi_cut(m, r.seed, pinned) != PE::OK) return false;
  auto uv = m.add_property_map<SM::Vertex_index, K::Point_2>("v:uv", K::Point_2(0, 0)).first;
  uv[pinned[0]] = K::Point_2(0, 0); uv[pinned[1]] = K::Point_2(0.5, std::sqrt(3.) / 2); uv[pinned[2]] = K::Point_2(1, 0);
  r.vertices = m.number_of_vertices();
  if(PE::tutte_embedding(m, SM::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::FIXED)) != PE::OK) return false;
  CGAL::Real_timer t;
  t.start();
  PE::Progressive_embedding_statistics ps;
  const PE::Error_code rec = smoothing >= 0
    ? PE::progressive_embedding(m, uv, PE::parameters::smoothing_iterations(smoothing, PE::parameters::statistics(&ps)))
    : PE::progressive_embedding(m, uv, PE::parameters::statistics(&ps));
  if(rec != PE::OK) return false;
  r.repair_seconds = t.time();
  r.repaired_mean = ps.report.mean_energy_3d;
  r.repaired_max = ps.report.max_energy_3d;
  std::vector<K::Point_2> border;
  for(auto v : m.vertices()) if(m.is_border(v)) border.push_back(uv[v]);
  PE::Optimization_statistics os;
  const PE::Error_code ec = PE::optimize_distortion(m, uv, PE::parameters::optimization_statistics(&os));
  r.status = PE::get_error_name(ec);
  r.iterations = os.iterations;
  r.seconds = os.seconds;
  r.valid = os.report.is_valid();
  r.mean = os.report.mean_energy_3d;
  r.max = os.report.max_energy_3d;
  std::size_t k = 0; r.border_exact = true;
  for(auto v : m.vertices()) if(m.is_border(v) && !(uv[v] == border[k++])) r.border_exact = false;
  if(stability)
  {
    PE::Optimization_statistics more;
    PE::optimize_distortion(m, uv, PE::parameters::optimization_statistics(&more, PE::parameters::convergence_tolerance(0.,
                                     CGAL::parameters::number_of_iterations(10 * (std::max)(os.iterations, std::size_t(1))))));
    r.stability_run = true;
    r.stability_mean = more.report.mean_energy_3d;
    r.stability_iterations = more.iterations;
  }
  return true;
}

int main(int argc, char** argv)
{
  if(argc < 4)
  {
    std::cerr << "usage: quality_benchmark DATA_DIR CORPUS_TSV OUT_PREFIX [--only MESH SEED] [--no-stability] [--smoothing N]\n";
    return 2;
  }
  const std::string data = argv[1], corpus = argv[2], out = argv[3];
  std::string only_mesh; long only_seed = -1; bool stability = true;
  for(int i = 4; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--only" && i + 2 < argc) { only_mesh = argv[++i]; only_seed = std::atol(argv[++i]); }
    else if(a == "--no-stability") stability = false;
    else if(a == "--smoothing" && i + 1 < argc) smoothing = std::max(0, std::atoi(argv[++i]));
    else { std::cerr << "quality_benchmark: unknown option " << a << "\n"; return 2; }
  }
  std::ifstream in(corpus);
  if(!in) { std::cerr << "quality_benchmark: cannot read " << corpus << "\n"; return 3; }
  std::vector<Run> runs;
  std::string line;
  while(std::getline(in, line))
  {
    if(line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    Run r; long seed;
    if(!(ls >> r.mesh >> seed)) continue; // the header line
    r.seed = unsigned(seed);
    if(!only_mesh.empty() && (r.mesh != only_mesh || seed != only_seed)) continue;
    runs.push_back(r);
  }
  std::size_t failed = 0;
  for(Run& r : runs)
  {
    if(!run_one(data, r, stability)) { r.status = "SETUP_FAILED"; ++failed; }
    std::cout << r.mesh << " seed " << r.seed << ": " << r.status << ", " << r.iterations << " iterations, "
              << fmt(r.seconds) << " s, mean " << fmt(r.repaired_mean) << " -> " << fmt(r.mean)
              << (r.stability_run ? " (10x iterations: " + fmt(r.stability_mean) + ")" : std::string()) << std::endl;
  }
  std::ofstream csv(out + ".csv");
  csv << "mesh,seed,vertices,repair_seconds,repaired_mean,repaired_max,status,valid,border_exact,iterations,seconds,mean,max,"
         "stability_iterations,stability_mean\n";
  for(const Run& r : runs)
    csv << r.mesh << ',' << r.seed << ',' << r.vertices << ',' << r.repair_seconds << ',' << r.repaired_mean << ','
        << r.repaired_max << ',' << r.status << ',' << r.valid << ',' << r.border_exact << ',' << r.iterations << ','
        << r.seconds << ',' << r.mean << ',' << r.max << ',' << r.stability_iterations << ',' << r.stability_mean << '\n';
  std::size_t ok = 0, valid = 0, exact = 0, stable = 0;
  std::vector<double> secs;
  for(const Run& r : runs)
  {
    ok += (r.status == "OK"); valid += r.valid; exact += r.border_exact;
    stable += (r.stability_run && r.stability_mean > 0.95 * r.mean);
    secs.push_back(r.seconds);
  }
  std::sort(secs.begin(), secs.end());
  std::ofstream md(out + ".md");
  const std::time_t now = std::time(nullptr);
  md << "# Quality by default: the default repair, then the default optimize_distortion\n\n"
     << "Generated " << std::put_time(std::gmtime(&now), "%Y-%m-%d") << " by `quality_benchmark` on the Tutte-failure corpus "
     << "(2 shared cores). Energies: area-weighted mean and max symmetric Dirichlet energy against the 3D triangles, "
     << "as `check_embedding()` reports them (an isometry scores 4).\n\n"
     << "- runs: " << runs.size() << "; converged (`OK`): " << ok << "; certified valid: " << valid
     << "; border bit-exact: " << exact << "\n";
  if(stability)
    md << "- stable (ten times the iterations lower the mean by less than 5%): " << stable << " of " << runs.size() << "\n";
  if(!secs.empty())
    md << "- optimization time: median "
       << fmt(secs.size() % 2 ? secs[secs.size() / 2] : 0.5 * (secs[secs.size() / 2 - 1] + secs[secs.size() / 2]))
       << " s, max " << fmt(secs.back()) << " s\n";
  md << "\n| mesh | seed | vertices | repaired mean | repaired max | status | iterations | seconds | mean | max |"
     << (stability ? " 10x iterations: mean |" : "") << "\n|---|---|---|---|---|---|---|---|---|---|" << (stability ? "---|" : "") << "\n";
  for(const Run& r : runs)
  {
    md << "| " << r.mesh << " | " << r.seed << " | " << r.vertices << " | " << fmt(r.repaired_mean) << " | " << fmt(r.repaired_max)
       << " | " << r.status << (r.valid ? "" : " INVALID") << " | " << r.iterations << " | " << fmt(r.seconds) << " | "
       << fmt(r.mean) << " | " << fmt(r.max) << " |";
    if(stability) md << " " << fmt(r.stability_mean) << " |";
    md << "\n";
  }
  std::cout << runs.size() << " runs, " << ok << " converged, " << valid << " valid, " << failed << " failed to set up\n";
  return (failed == 0 && valid == runs.size()) ? 0 : 1;
}
