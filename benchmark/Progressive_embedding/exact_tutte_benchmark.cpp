// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Benchmark driver (not run by ctest): tutte_embedding() in exact rationals (CGAL::Gmpq, p-adic
// lifting) and in MPFR (CGAL::Gmpfr at 256 bits, iterative refinement from a double factorization),
// uniform weights (`exact:parallel`: with CGAL::Parallel_tag, both cores), on
//  - thingi:MESH:SEED  the Tutte-failure protocol on DATA_DIR/meshes/MESH.off (one face removed, its
//                      three vertices pinned at (0,0), (1/2, sqrt(3)/2), (1,0), as `pe thingi` does);
//  - grid:N            the N x N grid disk of `pe generate grid`, border on the circle by arc length.
// Each run is a child process (fork) so that its peak resident memory (VmHWM) is its own; its time is
// the wall clock of the tutte_embedding() call alone; then check_embedding() certifies the map in its number
// type (timed apart). The digest is a hash of the solution's exact
// values (MPFR values converted exactly to rationals): two builds that give the same digest computed
// the same map, bit for bit.
//
//   exact_tutte_benchmark DATA_DIR OUT_PREFIX [--cases thingi:dino:8,grid:141] [--types exact,mpfr:256]
//                         [--repeat R] [--single-run-seconds S1] [--time-limit S] [--memory-limit-mb M]
//                         [--before BEFORE.csv]...
//
// writes OUT_PREFIX.csv (one row per case and number type: medians of the successful runs among R; a
// run longer than S1 seconds (default 60) or a time-out or failure in the first run is not repeated) and OUT_PREFIX.md. With --before (repeatable,
// later files replacing the rows of earlier ones), the rows of an earlier run of this driver (built against older headers, same CSV) are set side
// by side: time and memory before and after, the speed-up, and whether the digests agree. The growth
// per doubling of the vertex count is the ratio of times between consecutive rows of one family (the
// thingi meshes, the grids), scaled to a doubling: (t2/t1)^(1/log2(n2/n1)).
//
// Standalone build (CGAL 5.5 headers, GMP, MPFR, Eigen), from the repository root (the "before" columns:
// the same command with -I pointing at an older checkout's include/ instead of -Iinclude):
//   g++ -std=c++17 -O2 -DNDEBUG -frounding-math -DCGAL_EIGEN3_ENABLED -DCGAL_USE_GMPXX=1 -DCGAL_LINKED_WITH_TBB -Iinclude
//       -I/usr/include/eigen3 benchmark/Progressive_embedding/exact_tutte_benchmark.cpp -lgmpxx -lgmp -lmpfr -ltbb
//       -o exact_tutte_benchmark
// The tables of benchmark/results/exact_tutte.{csv,md}:
//   exact_tutte_benchmark DATA_DIR before --time-limit 120 --memory-limit-mb 12000     (built on the old headers)
//   exact_tutte_benchmark DATA_DIR benchmark/results/exact_tutte --time-limit 240 --memory-limit-mb 12000
//       --before before.csv

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>
#include <CGAL/Progressive_embedding/internal/disk_generators.h>
#include "process_memory.h"
#include "table_util.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace PE = CGAL::Progressive_embedding;
typedef CGAL::Simple_cartesian<double> K3;
typedef CGAL::Surface_mesh<K3::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;

namespace {

using pe_bench::split;
using pe_bench::median;
using pe_bench::fixed;

// FNV-1a over the limbs of a rational (numerator, then denominator, signs included)
struct Digest
{
  std::uint64_t h = 1469598103934665603ull;
  void byte(unsigned char b) { h ^= b; h *= 1099511628211ull; }
  void word(std::uint64_t w) { for(int k = 0; k < 8; ++k) byte(static_cast<unsigned char>(w >> (8 * k))); }
  void integer(mpz_srcptr z)
  {
    word(static_cast<std::uint64_t>(static_cast<std::int64_t>(z->_mp_size)));
    for(int k = 0; k < std::abs(z->_mp_size); ++k) word(static_cast<std::uint64_t>(z->_mp_d[k]));
  }
  void rational(const CGAL::Gmpq& q) { integer(mpq_numref(q.mpq())); integer(mpq_denref(q.mpq())); }
};

struct Result
{
  std::string status = "CRASHED";
  std::size_t vertices = 0, unknowns = 0;
  double seconds = 0, peak_mb = 0;
  std::string digest = "-";
  double certificate_seconds = 0;  // check_embedding() in the number type, after the solve
  std::string certified = "-";
};

// the input of one case, its border placed in double (the thingi pins) or by the circle shape
bool make_case(const std::string& data, const std::string& name, Mesh& m, std::vector<std::pair<vertex_descriptor, std::array<double, 2> > >& pins)
{
  const std::vector<std::string> f = split(name, ':');
  if(f.size() == 2 && f[0] == "grid") { PE::internal::make_grid_disk(std::size_t(std::atol(f[1].c_str())), m); return true; }
  if(f.size() != 3 || f[0] != "thingi") return false;
  if(!CGAL::IO::read_polygon_mesh(data + "/meshes/" + f[1] + ".off", m)) return false;
  std::array<vertex_descriptor, 3> pinned;
  if(PE::internal::thingi_cut(m, unsigned(std::atol(f[2].c_str())), pinned) != PE::OK) return false;
  pins = { { pinned[0], {{ 0., 0. }} }, { pinned[1], {{ 0.5, std::sqrt(3.) / 2 }} }, { pinned[2], {{ 1., 0. }} } };
  return true;
}

template <class FT>
FT from_double(double d)
{
  if constexpr(std::is_same<FT, CGAL::Gmpfr>::value) return CGAL::Gmpfr(d, CGAL::Gmpfr::get_default_precision());
  else return FT(d);
}

template <class FT, class ConcurrencyTag = CGAL::Sequential_tag>
void run_in(Mesh& m, const std::vector<std::pair<vertex_descriptor, std::array<double, 2> > >& pins, double limit, Result& r)
{
  typedef typename CGAL::Simple_cartesian<FT>::Point_2 P2;
  auto uv = m.add_property_map<vertex_descriptor, P2>("v:uv", P2(from_double<FT>(0), from_double<FT>(0))).first;
  for(const auto& p : pins) uv[p.first] = P2(from_double<FT>(p.second[0]), from_double<FT>(p.second[1]));
  const PE::Border_shape shape = pins.empty() ? PE::Border_shape::CIRCLE : PE::Border_shape::FIXED;
  const auto t0 = std::chrono::steady_clock::now();
  const PE::Error_code ec = PE::tutte_embedding<ConcurrencyTag>(m, Mesh::null_halfedge(), uv,
                              PE::parameters::border_shape(shape, CGAL::parameters::maximum_running_time(limit)));
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.peak_mb = pe_bench::peak_rss_mb();
  r.status = ec == PE::OK ? "OK" : (ec == PE::ERROR_BUDGET_EXHAUSTED ? "TIMEOUT" : PE::get_error_name(ec));
  r.vertices = num_vertices(m);
  std::size_t border = 0;
  for(auto h : halfedges(m)) if(is_border(h, m)) ++border;
  r.unknowns = r.vertices - border;
  if(ec != PE::OK) return;
  Digest d;
  for(vertex_descriptor v : vertices(m))
  {
    d.rational(PE::internal::to_rational(uv[v].x()));
    d.rational(PE::internal::to_rational(uv[v].y()));
  }
  std::ostringstream os;
  os << std::hex << std::setw(16) << std::setfill('0') << d.h;
  r.digest = os.str();
  const auto t1 = std::chrono::steady_clock::now();
  const PE::Embedding_report report = PE::check_embedding(m, uv);
  r.certificate_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  r.certified = report.is_valid() ? "valid" : "INVALID";
}

void run_child(const std::string& data, const std::string& name, const std::string& type, double limit, int fd)
{
  Result r;
  Mesh m;
  std::vector<std::pair<vertex_descriptor, std::array<double, 2> > > pins;
  if(!make_case(data, name, m, pins)) r.status = "NO_INPUT";
  else if(type == "exact") run_in<CGAL::Gmpq>(m, pins, limit, r);
  else if(type == "exact:parallel") run_in<CGAL::Gmpq, CGAL::Parallel_tag>(m, pins, limit, r);
  else
  {
    CGAL::Gmpfr::set_default_precision(std::atol(type.substr(5).c_str()));
    run_in<CGAL::Gmpfr>(m, pins, limit, r);
  }
  std::ostringstream os;
  os << r.status << ' ' << r.vertices << ' ' << r.unknowns << ' ' << r.seconds << ' ' << r.peak_mb << ' ' << r.digest << ' '
     << r.certificate_seconds << ' ' << r.certified << '\n';
  const std::string s = os.str();
  if(::write(fd, s.data(), s.size()) < 0) { }
}

Result run_one(const std::string& data, const std::string& name, const std::string& type, double limit, double memory_mb)
{
  Result r;
  int status = 0;
  const std::string out = pe_bench::run_in_child([&](int fd) { run_child(data, name, type, limit, fd); }, memory_mb, status);
  if(status == -1) return r;
  std::istringstream is(out);
  Result got;
  if(is >> got.status >> got.vertices >> got.unknowns >> got.seconds >> got.peak_mb >> got.digest >> got.certificate_seconds
        >> got.certified) return got;
  r.status = (WIFSIGNALED(status) || memory_mb > 0) ? "FAILED(memory?)" : "CRASHED";
  return r;
}

struct Row
{
  std::string name, type, status, digest, certified = "-";
  std::size_t vertices = 0, unknowns = 0, runs = 0;
  double seconds = 0, peak_mb = 0, certificate_seconds = 0;
};

const char* csv_header = "case,number_type,vertices,unknowns,status,runs,median_seconds,peak_rss_mb,digest,"
                         "certificate_seconds,certified";

std::string csv_row(const Row& r)
{
  std::ostringstream os;
  os << r.name << ',' << r.type << ',' << r.vertices << ',' << r.unknowns << ',' << r.status << ',' << r.runs << ','
     << r.seconds << ',' << r.peak_mb << ',' << r.digest << ',' << r.certificate_seconds << ',' << r.certified;
  return os.str();
}

std::map<std::string, Row> read_rows(const std::string& file)
{
  std::map<std::string, Row> rows;
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  while(std::getline(in, line))
  {
    const std::vector<std::string> f = split(line, ',');
    if(f.size() < 9) continue;
    Row r;
    r.name = f[0]; r.type = f[1]; r.vertices = std::size_t(std::atol(f[2].c_str())); r.unknowns = std::size_t(std::atol(f[3].c_str()));
    r.status = f[4]; r.runs = std::size_t(std::atol(f[5].c_str())); r.seconds = std::atof(f[6].c_str()); r.peak_mb = std::atof(f[7].c_str());
    r.digest = f[8];
    rows[r.name + "|" + r.type] = r;
  }
  return rows;
}

std::string family(const std::string& name) { return split(name, ':')[0]; }

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " DATA_DIR OUT_PREFIX [--cases a,b] [--types exact,mpfr:256] [--repeat R]"
                 " [--time-limit S] [--memory-limit-mb M] [--before BEFORE.csv]" << std::endl;
    return 1;
  }
  const std::string data = argv[1], prefix = argv[2];
  std::string cases = "thingi:dino:8,thingi:man:4,grid:141,grid:224,grid:316", types = "exact,mpfr:256";
  std::vector<std::string> before_files; // rows of later files replace those of earlier ones
  int repeat = 3;
  double limit = 600, memory_mb = 16000, single_run_seconds = 60;
  for(int a = 3; a + 1 < argc; a += 2)
  {
    const std::string o = argv[a], v = argv[a + 1];
    if(o == "--cases") cases = v;
    else if(o == "--types") types = v;
    else if(o == "--repeat") repeat = std::max(1, std::atoi(v.c_str()));
    else if(o == "--time-limit") limit = std::atof(v.c_str());
    else if(o == "--memory-limit-mb") memory_mb = std::atof(v.c_str());
    else if(o == "--single-run-seconds") single_run_seconds = std::atof(v.c_str());
    else if(o == "--before") before_files.push_back(v);
    else { std::cerr << "unknown option " << o << std::endl; return 1; }
  }
  std::vector<Row> rows;
  for(const std::string& name : split(cases, ','))
    for(const std::string& type : split(types, ','))
    {
      Row row;
      row.name = name; row.type = type;
      // the median of the successful runs; a row without one reports its first failure
      std::vector<double> secs, mem, certs;
      for(int k = 0; k < repeat; ++k)
      {
        const Result r = run_one(data, name, type, limit, memory_mb);
        std::cerr << name << ' ' << type << " run " << k + 1 << ": " << r.status << ' ' << r.seconds << " s, " << r.peak_mb << " MB" << std::endl;
        if(r.vertices) { row.vertices = r.vertices; row.unknowns = r.unknowns; }
        if(r.status == "OK")
        {
          if(row.status == "OK" && row.digest != r.digest) row.digest = "DIFFERS";
          else row.digest = r.digest;
          row.status = "OK";
          secs.push_back(r.seconds); mem.push_back(r.peak_mb); certs.push_back(r.certificate_seconds);
          if(row.certified != "INVALID") row.certified = r.certified;
          if(r.seconds > single_run_seconds) break; // slow: one run
        }
        else if(secs.empty())
        {
          row.status = r.status; row.seconds = r.seconds; row.peak_mb = r.peak_mb;
          break; // a time-out or a failure first: not repeated
        }
      }
      row.runs = secs.size();
      if(!secs.empty())
      {
        row.seconds = median(secs);
        row.certificate_seconds = median(certs);
        row.peak_mb = *std::max_element(mem.begin(), mem.end());
      }
      rows.push_back(row);
    }

  std::ofstream csv(prefix + ".csv");
  std::map<std::string, Row> before;
  for(const std::string& f : before_files)
    for(const auto& r : read_rows(f)) before[r.first] = r.second;
  csv << csv_header;
  if(!before.empty()) csv << ",before_status,before_median_seconds,before_peak_rss_mb,before_digest,speedup,same_result";
  csv << ",growth_per_doubling\n";
  std::ofstream md(prefix + ".md");
  char host[256] = "?";
  gethostname(host, sizeof host);
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  md << "# Exact and MPFR Tutte maps: time and memory\n\n"
     << "`tutte_embedding()`, uniform weights, in `CGAL::Gmpq` (exact; `exact:parallel`: `tutte_embedding<CGAL::Parallel_tag>()`,\n"
     << "two threads) and `CGAL::Gmpfr` (`mpfr:BITS`); `thingi:MESH:SEED`: the\n"
     << "Tutte-failure protocol on libcgal-demo's MESH.off, `grid:N`: the N x N grid disk, circle border. Times: wall clock of the\n"
     << "call, median of up to " << repeat << " runs (one when a run takes over " << single_run_seconds << " s; each in its own process); peak: the\n"
     << "process's VmHWM (MB); certificate: `check_embedding()` of the map in its number type after the call (what\n"
     << "`pe tutte --number-type` runs before rounding), its time and verdict. Growth per doubling (of the call):\n"
     << "(t2/t1)^(1/log2(n2/n1)) between consecutive rows of one family. Date " << date << ", host " << host
     << ", time limit " << limit << " s per run.\n\n";
  md << "| case | number type | vertices | unknowns | status | seconds | peak MB | certificate s | certified |";
  if(!before.empty()) md << " before: status | before: seconds | before: peak MB | speed-up | same result |";
  md << " growth per doubling |\n|---|---|---|---|---|---|---|---|---|";
  if(!before.empty()) md << "---|---|---|---|---|";
  md << "---|\n";
  for(std::size_t i = 0; i < rows.size(); ++i)
  {
    const Row& r = rows[i];
    // growth against the previous row of the same family and number type
    std::string growth = "";
    for(std::size_t j = i; j-- > 0; )
      if(rows[j].type == r.type && family(rows[j].name) == family(r.name))
      {
        if(rows[j].status == "OK" && r.status == "OK" && r.vertices > rows[j].vertices && rows[j].seconds > 0)
          growth = fixed(std::pow(r.seconds / rows[j].seconds, 1. / std::log2(double(r.vertices) / double(rows[j].vertices))), 2);
        break;
      }
    csv << csv_row(r);
    md << "| " << r.name << " | " << r.type << " | " << r.vertices << " | " << r.unknowns << " | " << r.status << " | "
       << fixed(r.seconds, 3) << " | " << fixed(r.peak_mb, 0) << " | " << (r.status == "OK" ? fixed(r.certificate_seconds, 3) : "")
       << " | " << r.certified << " |";
    if(!before.empty())
    {
      auto it = before.find(r.name + "|" + r.type);
      if(it == before.end()) { csv << ",,,,,,"; md << " | | | | |"; }
      else
      {
        const Row& b = it->second;
        const bool both = b.status == "OK" && r.status == "OK";
        const std::string speedup = both && r.seconds > 0 ? fixed(b.seconds / r.seconds, 1) : (r.status == "OK" ? "> " + fixed(b.seconds / r.seconds, 1) : "");
        const std::string same = both ? (b.digest == r.digest ? "yes" : "NO") : "";
        csv << ',' << b.status << ',' << b.seconds << ',' << b.peak_mb << ',' << b.digest << ',' << speedup << ',' << same;
        md << ' ' << b.status << " | " << fixed(b.seconds, 3) << " | " << fixed(b.peak_mb, 0) << " | " << speedup << " | " << same << " |";
      }
    }
    csv << ',' << growth << '\n';
    md << ' ' << growth << " |\n";
  }
  std::cerr << "wrote " << prefix << ".csv and " << prefix << ".md" << std::endl;
  return 0;
}
