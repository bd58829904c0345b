// Benchmark driver (not run by ctest): the Tutte-failure protocol over the corpus
// (../shared/corpus/tutte_failures.tsv) and the random-init protocol over generated
// grid disks; writes CSV + Markdown tables.
//
//   pe_benchmark DATA_DIR CORPUS_TSV OUT_PREFIX [--quick] [--repeat N] [--optimize]
// --optimize adds the quality pipeline: progressive_embedding with minimum_area_ratio(1e-3),
// then optimize_distortion (at most 300 iterations), from the same input map.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/internal/protocols.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <sys/resource.h>
#include <dirent.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace PE = CGAL::Progressive_embedding;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef SM::Vertex_index vd;

struct Row
{
  std::string kind, mesh; unsigned seed = 0; std::size_t vertices = 0, faces = 0;
  std::size_t tutte_flipped = 0, tutte_degenerate = 0, invalid_before = 0, collapses = 0, restarts = 0;
  double tutte_seconds = 0, pe_seconds = 0, peak_mb = 0;
  std::string status; bool valid = false;
  double in_max = 0, in_mean = 0, out_max = 0, out_mean = 0;
  // quality pipeline: progressive embedding with minimum_area_ratio(1e-3), then optimize_distortion
  bool opt_run = false, opt_valid = false, opt_border_exact = false; std::string opt_status;
  std::size_t opt_iterations = 0; double opt_seconds = 0, opt_mean = 0, opt_max = 0, opt_per_iteration = 0;
};

static double median(std::vector<double> v) { std::sort(v.begin(), v.end()); return v.empty() ? 0 : v[v.size() / 2]; }

// runs progressive embedding `repeat` times from the same input map; median time
static bool optimize = false;

static void repair(SM& m, SM::Property_map<vd, K::Point_2> uv, Row& r, int repeat)
{
  std::vector<K::Point_2> input(m.number_of_vertices());
  for(vd v : m.vertices()) input[v] = uv[v];
  std::vector<double> times;
  PE::Progressive_embedding_statistics st;
  PE::Error_code ec = PE::OK;
  for(int k = 0; k < repeat; ++k)
  {
    for(vd v : m.vertices()) uv[v] = input[v];
    CGAL::Real_timer t; t.start();
    ec = PE::progressive_embedding(m, uv, PE::parameters::statistics(&st));
    times.push_back(t.time());
  }
  r.pe_seconds = median(times);
  r.status = PE::get_error_name(ec);
  r.valid = (ec == PE::OK) && st.report.is_valid();
  r.invalid_before = st.invalid_faces_before; r.collapses = st.collapses; r.restarts = st.restarts;
  r.out_max = st.report.max_energy_3d; r.out_mean = st.report.mean_energy_3d;
  struct rusage ru; getrusage(RUSAGE_SELF, &ru);
  r.peak_mb = ru.ru_maxrss / 1024.0; // peak of the process so far (Linux: KiB)
  if(!optimize) return;
  // quality pipeline from the same input map
  for(vd v : m.vertices()) uv[v] = input[v];
  CGAL::Real_timer t; t.start();
  PE::Error_code e1 = PE::progressive_embedding(m, uv, PE::parameters::minimum_area_ratio(1e-3));
  PE::Optimization_statistics os;
  PE::Error_code e2 = (e1 == PE::OK) ? PE::optimize_distortion(m, uv, PE::parameters::optimization_statistics(&os,
                                         CGAL::parameters::number_of_iterations(std::size_t(300)))) : e1;
  r.opt_run = true;
  r.opt_seconds = t.time();
  r.opt_status = PE::get_error_name(e2);
  r.opt_valid = (e1 == PE::OK) && os.report.is_valid();
  r.opt_iterations = os.iterations;
  r.opt_mean = os.report.mean_energy_3d; r.opt_max = os.report.max_energy_3d;
  r.opt_per_iteration = os.iterations ? os.seconds / double(os.iterations) : 0;
  r.opt_border_exact = true;
  for(vd v : m.vertices()) if(m.is_border(v) && !(uv[v] == input[v])) r.opt_border_exact = false;
}

int main(int argc, char** argv)
{
  if(argc < 4) { std::cerr << "usage: pe_benchmark DATA_DIR CORPUS_TSV OUT_PREFIX [--quick] [--repeat N] [--optimize]\n"; return 2; }
  const std::string data = argv[1], tsv = argv[2], out = argv[3];
  bool quick = false; int repeat = 3;
  for(int i = 4; i < argc; ++i)
  {
    std::string a = argv[i];
    if(a == "--quick") quick = true;
    else if(a == "--repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else if(a == "--optimize") optimize = true;
  }
  std::vector<Row> rows;
  // --- corpus: Tutte-failure protocol
  std::ifstream in(tsv);
  if(!in) { std::cerr << "cannot read " << tsv << "\n"; return 1; }
  std::string line; std::getline(in, line);
  std::size_t count = 0;
  while(std::getline(in, line))
  {
    std::istringstream ls(line); Row r; r.kind = "corpus";
    ls >> r.mesh >> r.seed;
    if(quick && ++count > 4) break;
    SM m;
    if(!CGAL::IO::read_polygon_mesh(data + "/meshes/" + r.mesh, m)) { std::cerr << "cannot read " << r.mesh << "\n"; return 1; }
    std::array<vd, 3> pin;
    if(PE::internal::thingi_cut(m, r.seed, pin) != PE::OK) { std::cerr << "cut failed\n"; return 1; }
    auto uv = m.add_property_map<vd, K::Point_2>("uv").first;
    uv[pin[0]] = K::Point_2(0, 0); uv[pin[1]] = K::Point_2(0.5, std::sqrt(3.) / 2); uv[pin[2]] = K::Point_2(1, 0);
    std::vector<double> tt;
    for(int k = 0; k < repeat; ++k) { CGAL::Real_timer t; t.start(); PE::tutte_embedding(m, SM::null_halfedge(), uv); tt.push_back(t.time()); }
    r.tutte_seconds = median(tt);
    PE::Embedding_report rep = PE::check_embedding(m, uv);
    r.vertices = m.number_of_vertices(); r.faces = m.number_of_faces();
    r.tutte_flipped = rep.flipped; r.tutte_degenerate = rep.degenerate;
    r.in_max = rep.max_energy_3d; r.in_mean = rep.mean_energy_3d;
    repair(m, uv, r, repeat);
    std::cerr << r.mesh << " " << r.seed << ": " << r.status << " " << r.pe_seconds << " s (Tutte " << r.tutte_seconds << " s)\n";
    rows.push_back(r);
  }
  // --- random init on the disks of libcgal-demo
  auto random_init = [&](SM& m, SM::Property_map<vd, K::Point_2> uv, unsigned seed) {
    std::size_t nb = 0; for(vd v : m.vertices()) if(m.is_border(v)) ++nb;
    const double radius = std::cos(CGAL_PI / double(nb)) * 0.999; // inside the inscribed polygon
    std::mt19937 gen(seed); std::uniform_real_distribution<double> U(-1, 1);
    for(vd v : m.vertices())
      if(!m.is_border(v))
      {
        double x, y; do { x = U(gen); y = U(gen); } while(x * x + y * y > 1);
        uv[v] = K::Point_2(radius * x, radius * y);
      }
  };
  // Tutte on a circle (the reference distortion), then random interior positions, then the repair
  auto random_init_run = [&](SM& m, const std::string& name, int reps) {
    Row r; r.kind = "random-init"; r.mesh = name; r.seed = 1;
    auto uv = m.add_property_map<vd, K::Point_2>("uv").first;
    std::vector<double> tt;
    for(int k = 0; k < reps; ++k)
    { CGAL::Real_timer t; t.start(); PE::tutte_embedding(m, SM::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE)); tt.push_back(t.time()); }
    r.tutte_seconds = median(tt);
    PE::Embedding_report rep = PE::check_embedding(m, uv);
    r.in_max = rep.max_energy_3d; r.in_mean = rep.mean_energy_3d;
    r.tutte_flipped = rep.flipped; r.tutte_degenerate = rep.degenerate;
    random_init(m, uv, 1);
    r.vertices = m.number_of_vertices(); r.faces = m.number_of_faces();
    repair(m, uv, r, reps);
    std::cerr << r.mesh << ": " << r.status << " " << r.pe_seconds << " s\n";
    rows.push_back(r);
  };
  {
    std::vector<std::string> names;
    if(DIR* dir = opendir((data + "/meshes").c_str()))
    {
      while(dirent* e = readdir(dir)) { std::string n = e->d_name; if(n.size() > 4 && n.substr(n.size() - 4) == ".off") names.push_back(n); }
      closedir(dir);
    }
    std::sort(names.begin(), names.end());
    std::size_t ndisks = 0;
    for(const std::string& name : names)
    {
      SM m;
      if(!CGAL::IO::read_polygon_mesh(data + "/meshes/" + name, m) || !CGAL::is_triangle_mesh(m)) continue;
      PE::internal::Indexed_disk<SM> disk;
      if(PE::internal::make_indexed_disk(m, SM::null_halfedge(), disk) != PE::OK || disk.border.size() < 3) continue;
      if(quick && ++ndisks > 3) break;
      random_init_run(m, name, repeat);
    }
  }
  // --- random init on grid disks (circle border, interior uniformly random inside)
  std::vector<std::size_t> sides = quick ? std::vector<std::size_t>{32, 64} : std::vector<std::size_t>{32, 64, 128, 256, 512};
  for(std::size_t n : sides)
  {
    SM m; PE::internal::make_grid_disk(n, m);
    random_init_run(m, "grid" + std::to_string(n) + "x" + std::to_string(n), n >= 256 ? 1 : repeat);
  }
  // --- tables
  std::ofstream csv(out + ".csv"), md(out + ".md");
  csv << "kind,mesh,seed,vertices,faces,tutte_flipped,tutte_degenerate,tutte_seconds,invalid_before,collapses,restarts,pe_seconds,ratio_pe_tutte,peak_rss_mb,status,certified,input_max_sd,input_mean_sd,output_max_sd,output_mean_sd,opt_status,opt_certified,opt_border_exact,opt_iterations,opt_seconds,opt_seconds_per_iteration,opt_max_sd,opt_mean_sd\n";
  md << "| kind | mesh | seed | #V | Tutte flipped | Tutte degenerate | invalid before | collapses | Tutte s | PE s | PE/Tutte | peak RSS MB | certified | mean SD in | mean SD out | max SD out |" << (optimize ? " optimized: status | certified | border exact | iterations | s | s/iteration | mean SD | max SD |" : "") << "\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|" << (optimize ? "---|---|---|---|---|---|---|---|" : "") << "\n";
  std::size_t certified = 0; std::vector<double> ratios;
  for(const Row& r : rows)
  {
    const double ratio = r.tutte_seconds > 0 ? r.pe_seconds / r.tutte_seconds : 0;
    if(r.kind == "corpus") ratios.push_back(ratio);
    certified += r.valid && (!optimize || (r.opt_valid && r.opt_border_exact));
    csv << r.kind << ',' << r.mesh << ',' << r.seed << ',' << r.vertices << ',' << r.faces << ',' << r.tutte_flipped << ','
        << r.tutte_degenerate << ',' << r.tutte_seconds << ',' << r.invalid_before << ',' << r.collapses << ',' << r.restarts << ','
        << r.pe_seconds << ',' << ratio << ',' << r.peak_mb << ',' << r.status << ',' << (r.valid ? 1 : 0) << ','
        << r.in_max << ',' << r.in_mean << ',' << r.out_max << ',' << r.out_mean << ','
        << (r.opt_run ? r.opt_status : "") << ',' << r.opt_valid << ',' << r.opt_border_exact << ',' << r.opt_iterations << ','
        << r.opt_seconds << ',' << r.opt_per_iteration << ',' << r.opt_max << ',' << r.opt_mean << '\n';
    md << "| " << r.kind << " | " << r.mesh << " | " << r.seed << " | " << r.vertices << " | " << r.tutte_flipped << " | " << r.tutte_degenerate
       << " | " << r.invalid_before << " | " << r.collapses << " | " << r.tutte_seconds << " | " << r.pe_seconds << " | " << ratio << " | "
       << r.peak_mb << " | " << (r.valid ? "yes" : "**NO**") << " | " << r.in_mean << " | " << r.out_mean << " | " << r.out_max << " |";
    if(optimize)
      md << " " << r.opt_status << " | " << (r.opt_valid ? "yes" : "**NO**") << " | " << (r.opt_border_exact ? "yes" : "**NO**") << " | "
         << r.opt_iterations << " | " << r.opt_seconds << " | " << r.opt_per_iteration << " | " << r.opt_mean << " | " << r.opt_max << " |";
    md << "\n";
  }
  md << "\nCertified: " << certified << " / " << rows.size() << "; median PE/Tutte time ratio over the corpus runs: " << median(ratios) << "\n";
  std::cout << "certified " << certified << " / " << rows.size() << ", median corpus PE/Tutte ratio " << median(ratios) << "\n";
  return certified == rows.size() ? 0 : 1;
}
