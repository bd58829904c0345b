// Benchmark driver (not run by ctest): the Tutte-failure protocol over the corpus
// (benchmark/results/study_tutte_failures.tsv) and the random-init protocol over generated
// grid disks; writes CSV + Markdown tables.
//
//   pe_benchmark DATA_DIR CORPUS_TSV OUT_PREFIX [--quick] [--repeat N] [--optimize]
//                [--only MESH SEED] [--corpus-only] [--grids N,N,...] [--smoothing N]
// --only runs one corpus run and nothing else (for profiling); --grids replaces the list of grid
// sides of the random-init protocol (default 32,64,128,256,512,1024; --grids 1024 alone measures
// the 1M-vertex run in a process of its own, so that its peak RSS is its own).
// Repair time (pe_seconds) excludes the certificate, which is timed apart (cert_seconds).
// --optimize adds the quality pipeline: progressive_embedding with minimum_area_ratio(1e-3),
// then optimize_distortion (at most 300 iterations), from the same input map.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/internal/disk_generators.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <sys/resource.h>
#include <unistd.h>
#include <dirent.h>

#include <algorithm>
#include <ctime>
#include <thread>
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
  double tutte_seconds = 0, pe_seconds = 0, cert_seconds = 0, collapse_seconds = 0, insertion_seconds = 0, peak_mb = 0;
  std::string status; bool valid = false;
  double in_max = 0, in_mean = 0, out_max = 0, out_mean = 0;
  // quality pipeline: progressive embedding with minimum_area_ratio(1e-3), then optimize_distortion
  bool opt_run = false, opt_valid = false, opt_border_exact = false; std::string opt_status;
  std::size_t opt_iterations = 0; double opt_seconds = 0, opt_mean = 0, opt_max = 0, opt_per_iteration = 0;
};

static std::string load_average()
{
  std::ifstream f("/proc/loadavg");
  std::string a;
  return (f >> a) ? a : std::string("unknown");
}

// the median: the middle value, or the mean of the two middle ones for an even count
static double median(std::vector<double> v)
{
  if(v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// runs progressive embedding `repeat` times from the same input map; median time
static bool optimize = false;
static int smoothing = -1; // --smoothing N: smoothing_iterations(N) instead of the default

static void repair(SM& m, SM::Property_map<vd, K::Point_2> uv, Row& r, int repeat)
{
  std::vector<K::Point_2> input(m.number_of_vertices());
  for(vd v : m.vertices()) input[v] = uv[v];
  std::vector<double> times, cert, col, ins;
  PE::Progressive_embedding_statistics st;
  PE::Error_code ec = PE::OK;
  for(int k = 0; k < repeat; ++k)
  {
    for(vd v : m.vertices()) uv[v] = input[v];
    CGAL::Real_timer t; t.start();
    ec = (smoothing >= 0) ? PE::progressive_embedding(m, uv, PE::parameters::smoothing_iterations(smoothing, PE::parameters::statistics(&st)))
                          : PE::progressive_embedding(m, uv, PE::parameters::statistics(&st));
    const double total = t.time();
    times.push_back(total - st.seconds_certification);
    cert.push_back(st.seconds_certification);
    col.push_back(st.seconds_collapse); ins.push_back(st.seconds_insertion);
  }
  r.pe_seconds = median(times); r.cert_seconds = median(cert);
  r.collapse_seconds = median(col); r.insertion_seconds = median(ins);
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
  std::string only_mesh; unsigned only_seed = 0; bool only = false, grids_given = false, corpus_only = false;
  std::vector<std::size_t> grid_sides;
  for(int i = 4; i < argc; ++i)
  {
    std::string a = argv[i];
    if(a == "--quick") quick = true;
    else if(a == "--repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else if(a == "--optimize") optimize = true;
    else if(a == "--smoothing" && i + 1 < argc) smoothing = std::max(0, std::atoi(argv[++i]));
    else if(a == "--corpus-only") corpus_only = true;
    else if(a == "--only" && i + 2 < argc) { only = true; only_mesh = argv[++i]; only_seed = unsigned(std::atoi(argv[++i])); }
    else if(a == "--grids" && i + 1 < argc)
    {
      grids_given = true;
      std::istringstream gs(argv[++i]); std::string tok;
      while(std::getline(gs, tok, ',')) if(std::atoi(tok.c_str()) >= 2) grid_sides.push_back(std::size_t(std::atoi(tok.c_str())));
    }
    else { std::cerr << "unknown argument " << a << "\n"; return 2; }
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
    if(grids_given) break;
    if(only && (r.mesh != only_mesh || r.seed != only_seed)) continue;
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
  // --- random init: the border on the unit circle by 3D arc length (as Tutte's CIRCLE border, without
  // solving for the interior: the protocol throws the interior away), interior vertices uniformly random
  // in a disk inside the border polygon
  auto random_init = [&](SM& m, SM::Property_map<vd, K::Point_2> uv, unsigned seed) -> bool {
    PE::internal::Indexed_disk<SM> disk;
    if(PE::internal::make_indexed_disk(m, SM::null_halfedge(), disk) != PE::OK || disk.border.size() < 3) return false;
    const std::vector<double> s = PE::internal::border_arc_length(disk, m.points());
    const std::size_t nb = disk.border.size();
    for(std::size_t k = 0; k < nb; ++k)
      uv[disk.vertices[disk.border[k]]] = K::Point_2(std::cos(2 * CGAL_PI * s[k]), std::sin(2 * CGAL_PI * s[k]));
    // the radius of the disk inscribed in the border polygon (smallest distance from the center to an edge)
    double r_in = 1;
    for(std::size_t k = 0; k < nb; ++k)
    {
      const K::Point_2 p = uv[disk.vertices[disk.border[k]]], q = uv[disk.vertices[disk.border[(k + 1) % nb]]];
      const double len = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
      if(len > 0) r_in = std::min(r_in, std::abs(p.x() * q.y() - p.y() * q.x()) / len);
    }
    r_in *= 0.999;
    std::mt19937 gen(seed); std::uniform_real_distribution<double> U(-1, 1);
    for(vd v : m.vertices())
      if(!m.is_border(v))
      {
        double x, y; do { x = U(gen); y = U(gen); } while(x * x + y * y > 1);
        uv[v] = K::Point_2(r_in * x, r_in * y);
      }
    return true;
  };
  auto random_init_run = [&](SM& m, const std::string& name, int reps) {
    Row r; r.kind = "random-init"; r.mesh = name; r.seed = 1;
    auto uv = m.add_property_map<vd, K::Point_2>("uv").first;
    if(!random_init(m, uv, 1)) return;
    r.vertices = m.number_of_vertices(); r.faces = m.number_of_faces();
    repair(m, uv, r, reps);
    std::cerr << r.mesh << ": " << r.status << " " << r.pe_seconds << " s (certificate " << r.cert_seconds << " s)\n";
    rows.push_back(r);
  };
  if(!only && !grids_given && !corpus_only)
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
  // --- random init on grid disks
  std::vector<std::size_t> sides = grids_given ? grid_sides
                                 : quick ? std::vector<std::size_t>{32, 64} : std::vector<std::size_t>{32, 64, 128, 256, 512, 1024};
  if(only || corpus_only) sides.clear();
  for(std::size_t n : sides)
  {
    SM m; PE::internal::make_grid_disk(n, m);
    random_init_run(m, "grid" + std::to_string(n) + "x" + std::to_string(n), n >= 256 ? 1 : repeat);
  }
  // --- tables
  std::ofstream csv(out + ".csv"), md(out + ".md");
  csv << "kind,mesh,seed,vertices,faces,tutte_flipped,tutte_degenerate,tutte_seconds,invalid_before,collapses,restarts,pe_seconds,collapse_seconds,insertion_seconds,certificate_seconds,ratio_pe_tutte,peak_rss_mb,status,certified,input_max_sd,input_mean_sd,output_max_sd,output_mean_sd,opt_status,opt_certified,opt_border_exact,opt_iterations,opt_seconds,opt_seconds_per_iteration,opt_max_sd,opt_mean_sd\n";
  {
    char host[256] = "unknown"; gethostname(host, sizeof(host) - 1);
    const std::time_t now = std::time(nullptr); char date[64]; std::strftime(date, sizeof(date), "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    md << "Generated by pe_benchmark on " << date << ", host " << host << " (" << std::thread::hardware_concurrency()
       << " hardware threads, shared; load average at the end " << load_average() << "), medians of " << repeat
       << " runs (1 run for grids of 256x256 and more). "
       << "PE s is the repair time without the certificate; certificate s is check_embedding on the output; "
       << "random-init runs place the border without solving Tutte (no Tutte column).\n\n";
  }
  md << "| kind | mesh | seed | #V | Tutte flipped | Tutte degenerate | invalid before | collapses | Tutte s | PE s | collapse s | insertion s | certificate s | PE/Tutte | peak RSS MB | certified | mean SD in | mean SD out | max SD out |" << (optimize ? " optimized: status | certified | border exact | iterations | s | s/iteration | mean SD | max SD |" : "") << "\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|" << (optimize ? "---|---|---|---|---|---|---|---|" : "") << "\n";
  std::size_t certified = 0; std::vector<double> ratios;
  for(const Row& r : rows)
  {
    const double ratio = r.tutte_seconds > 0 ? r.pe_seconds / r.tutte_seconds : 0;
    const bool corpus = r.kind == "corpus";
    if(corpus) ratios.push_back(ratio);
    certified += r.valid && (!optimize || (r.opt_valid && r.opt_border_exact));
    csv << r.kind << ',' << r.mesh << ',' << r.seed << ',' << r.vertices << ',' << r.faces << ',' << r.tutte_flipped << ','
        << r.tutte_degenerate << ',' << r.tutte_seconds << ',' << r.invalid_before << ',' << r.collapses << ',' << r.restarts << ','
        << r.pe_seconds << ',' << r.collapse_seconds << ',' << r.insertion_seconds << ',' << r.cert_seconds << ','
        << ratio << ',' << r.peak_mb << ',' << r.status << ',' << (r.valid ? 1 : 0) << ','
        << r.in_max << ',' << r.in_mean << ',' << r.out_max << ',' << r.out_mean << ','
        << (r.opt_run ? r.opt_status : "") << ',' << r.opt_valid << ',' << r.opt_border_exact << ',' << r.opt_iterations << ','
        << r.opt_seconds << ',' << r.opt_per_iteration << ',' << r.opt_max << ',' << r.opt_mean << '\n';
    auto opt_num = [&](double x) { std::ostringstream o; if(corpus) o << x; else o << "-"; return o.str(); };
    md << "| " << r.kind << " | " << r.mesh << " | " << r.seed << " | " << r.vertices << " | " << opt_num(double(r.tutte_flipped)) << " | "
       << opt_num(double(r.tutte_degenerate)) << " | " << r.invalid_before << " | " << r.collapses << " | " << opt_num(r.tutte_seconds) << " | "
       << r.pe_seconds << " | " << r.collapse_seconds << " | " << r.insertion_seconds << " | " << r.cert_seconds << " | " << opt_num(ratio) << " | "
       << r.peak_mb << " | " << (r.valid ? "yes" : "**NO**") << " | " << opt_num(r.in_mean) << " | " << r.out_mean << " | " << r.out_max << " |";
    if(optimize)
      md << " " << r.opt_status << " | " << (r.opt_valid ? "yes" : "**NO**") << " | " << (r.opt_border_exact ? "yes" : "**NO**") << " | "
         << r.opt_iterations << " | " << r.opt_seconds << " | " << r.opt_per_iteration << " | " << r.opt_mean << " | " << r.opt_max << " |";
    md << "\n";
  }
  md << "\nCertified: " << certified << " / " << rows.size() << "; median PE/Tutte time ratio over the corpus runs: " << median(ratios)
     << " (repair time without the certificate)\n";
  // random-init scaling on the grids: time factor per doubling of the vertex count
  {
    const Row* prev = nullptr;
    for(const Row& r : rows)
    {
      if(r.kind != "random-init" || r.mesh.compare(0, 4, "grid") != 0) continue;
      if(prev && prev->pe_seconds > 0 && r.vertices > prev->vertices)
        md << "\nRandom init " << prev->mesh << " -> " << r.mesh << ": x" << std::pow(r.pe_seconds / prev->pe_seconds,
                                                                                    std::log(2.) / std::log(double(r.vertices) / double(prev->vertices)))
           << " per doubling of the vertex count\n";
      prev = &r;
    }
  }
  std::cout << "certified " << certified << " / " << rows.size() << ", median corpus PE/Tutte ratio " << median(ratios) << "\n";
  return certified == rows.size() ? 0 : 1;
}
