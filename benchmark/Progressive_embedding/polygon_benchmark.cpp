// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Benchmark driver (not run by ctest): triangulate_self_overlapping_polygon_2 on generated polygons of
// 100 to 16000 vertices, writing OUT_PREFIX.csv and OUT_PREFIX.md:
//  - convex: regular n-gon (the constrained Delaunay path);
//  - star: n/2 tips, radii 1 and 0.4 (the constrained Delaunay path);
//  - hilbert: outline of the Hilbert curve of order k thickened into a polyomino (cells at even grid
//    positions and their connectors), a vertex at every unit step: long runs of collinear vertices and
//    vertices on diagonals (the constrained Delaunay path);
//  - spiral: a strip of width 0.6 around the spiral r = 1 + 0.3 t / (2 pi), t in [0, 4 pi], n/2 vertices
//    per side: it winds twice and overlaps itself (the Shor-Van Wyk dynamic program).
// Each run is a child process (fork), so that its peak resident memory (VmHWM) is its own; the driver
// waits for it and records its time (the function's wall clock, from its report), peak memory, the path
// taken, the dynamic program's counts and an exact check of the result (n - 2 strictly positive triangles,
// each polygon edge in exactly one).
//
//   polygon_benchmark OUT_PREFIX [--max N] [--shapes convex,star,hilbert,spiral] [--budget SECONDS]
//
// Standalone build (CGAL 5.5 headers, GMP, MPFR), from the repository root:
//   g++ -std=c++17 -O2 -DNDEBUG -frounding-math -Iinclude benchmark/Progressive_embedding/polygon_benchmark.cpp \
//       -lgmp -lmpfr -o polygon_benchmark

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Progressive_embedding/triangulate_self_overlapping_polygon_2.h>
#include "polygon_shapes.h"
#include "process_memory.h"

#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace PE = CGAL::Progressive_embedding;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;

typedef pe_bench::Shapes<Point> Shapes;

struct Row
{
  std::string shape, result, path;
  std::size_t n = 0, triangles = 0, chords_tested = 0, chords_stored = 0;
  double seconds = 0, peak_mb = 0, extra_mb = 0;
  bool certified = false;
};

// in the child: generate, triangulate, check; one line on `fd`
static void run_child(const std::string& shape, std::size_t size, double budget, int fd)
{
  std::vector<Point> P = shape == "convex" ? Shapes::convex(size) : shape == "star" ? Shapes::star(size)
                       : shape == "spiral" ? Shapes::spiral(size) : Shapes::hilbert(int(size));
  pe_bench::reset_peak_rss(); // the peak from the current size on
  const double base = pe_bench::current_rss_mb();
  std::vector<std::array<std::size_t, 3> > T;
  PE::Polygon_triangulation_report r;
  const PE::Error_code ec = PE::triangulate_self_overlapping_polygon_2(P, std::back_inserter(T),
                              PE::parameters::polygon_report(&r).maximum_running_time(budget));
  const double peak = pe_bench::peak_rss_mb();
  // exact check: n - 2 strictly positive triangles, each polygon edge (in its direction) in exactly one
  bool ok = (ec == PE::OK && T.size() + 2 == P.size());
  std::vector<int> edge_use(P.size(), 0);
  const std::size_t n = P.size();
  for(const auto& t : T)
  {
    if(K::Orientation_2()(P[t[0]], P[t[1]], P[t[2]]) != CGAL::LEFT_TURN) ok = false;
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t a = t[c], b = t[(c + 1) % 3];
      if(b == (a + 1) % n) ++edge_use[a];
    }
  }
  for(int u : edge_use) if(u != 1) ok = false;
  std::ostringstream os;
  os << shape << ' ' << n << ' ' << PE::get_error_name(ec) << ' ' << (r.dynamic_program ? "dp" : "cdt") << ' '
     << T.size() << ' ' << r.chords_tested << ' ' << r.chords_stored << ' ' << r.seconds << ' ' << peak << ' '
     << (peak - base) << ' ' << (ok ? 1 : 0) << '\n';
  const std::string s = os.str();
  if(::write(fd, s.data(), s.size()) < 0) { }
}

static bool run_one(const std::string& shape, std::size_t size, double budget, Row& row)
{
  int status = 0;
  const std::string out = pe_bench::run_in_child([&](int fd) { run_child(shape, size, budget, fd); }, 0., status);
  if(status == -1) return false;
  std::istringstream is(out);
  int ok = 0;
  row.shape = shape;
  if(!(is >> row.shape >> row.n >> row.result >> row.path >> row.triangles >> row.chords_tested >> row.chords_stored
          >> row.seconds >> row.peak_mb >> row.extra_mb >> ok))
  {
    row.result = "CRASHED";
    return true;
  }
  row.certified = (ok == 1);
  return true;
}

int main(int argc, char** argv)
{
  if(argc < 2) { std::cerr << "usage: " << argv[0] << " OUT_PREFIX [--max N] [--shapes a,b] [--budget S]" << std::endl; return 1; }
  const std::string prefix = argv[1];
  std::size_t max_n = 16000;
  double budget = 300;
  std::string shapes = "convex,star,hilbert,spiral";
  for(int a = 2; a + 1 < argc; a += 2)
  {
    const std::string o = argv[a];
    if(o == "--max") max_n = std::size_t(std::atol(argv[a + 1]));
    else if(o == "--shapes") shapes = argv[a + 1];
    else if(o == "--budget") budget = std::atof(argv[a + 1]);
    else { std::cerr << "unknown option " << o << std::endl; return 1; }
  }
  const std::vector<std::size_t> sizes = { 100, 250, 500, 1000, 2000, 4000, 8000, 16000 };
  std::vector<Row> rows;
  std::stringstream ss(shapes);
  std::string shape;
  while(std::getline(ss, shape, ','))
  {
    std::vector<std::size_t> params;
    if(shape == "hilbert") { for(int order = 2; order <= 6; ++order) params.push_back(std::size_t(order)); }
    else for(std::size_t n : sizes) if(n <= max_n) params.push_back(n);
    for(std::size_t p : params)
    {
      Row row;
      if(!run_one(shape, p, budget, row)) { std::cerr << "fork failed" << std::endl; return 1; }
      if(shape == "hilbert" && double(row.n) > 1.1 * double(max_n)) break; // order 6 has 16384 vertices
      std::cerr << row.shape << " " << row.n << ": " << row.result << " " << row.path << " " << row.seconds << " s, "
                << row.peak_mb << " MB peak (" << row.extra_mb << " MB in the call), certified " << row.certified << std::endl;
      rows.push_back(row);
    }
  }
  std::ofstream csv(prefix + ".csv"), md(prefix + ".md");
  csv << "shape,vertices,result,path,triangles,chords_tested,chords_stored,seconds,peak_rss_mb,call_mb,certified\n";
  md << "| shape | vertices | result | path | seconds | peak RSS (MB) | in the call (MB) | chords stored | certified |\n"
     << "|---|---:|---|---|---:|---:|---:|---:|---|\n";
  for(const Row& r : rows)
  {
    csv << r.shape << ',' << r.n << ',' << r.result << ',' << r.path << ',' << r.triangles << ',' << r.chords_tested << ','
        << r.chords_stored << ',' << r.seconds << ',' << r.peak_mb << ',' << r.extra_mb << ',' << (r.certified ? "yes" : "no") << '\n';
    char sec[32], pk[32], ex[32];
    std::snprintf(sec, sizeof sec, "%.4f", r.seconds);
    std::snprintf(pk, sizeof pk, "%.1f", r.peak_mb);
    std::snprintf(ex, sizeof ex, "%.1f", r.extra_mb);
    md << "| " << r.shape << " | " << r.n << " | " << r.result << " | " << r.path << " | " << sec << " | " << pk << " | " << ex
       << " | " << r.chords_stored << " | " << (r.certified ? "yes" : "no") << " |\n";
  }
  std::cout << "wrote " << prefix << ".csv and " << prefix << ".md" << std::endl;
  return 0;
}
