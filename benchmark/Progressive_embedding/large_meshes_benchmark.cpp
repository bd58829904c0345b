// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Benchmark driver (not run by ctest): the stages of `pe embed --no-optimize` on large disks, with the
// sparse solver of the Tutte map chosen among
//   default      what tutte_embedding() does without a solver: Eigen's LDLT below internal::cholmod_minimum_unknowns
//                unknowns, from internal::multigrid_minimum_unknowns on conjugate gradients with the multigrid
//                preconditioner (the direct solvers if they do not converge), on a matrix built in place
//   ldlt_amd     Eigen::SimplicialLDLT, approximate minimum degree ordering, given as CGAL solver traits (through
//                CGAL::Eigen_sparse_matrix: the package's default path before the solver was chosen by size)
//   llt_amd      Eigen::SimplicialLLT, approximate minimum degree ordering
//   ldlt_metis   Eigen::SimplicialLDLT, METIS nested dissection (Eigen/MetisSupport; built with PE_HAS_METIS)
//   cholmod      CHOLMOD's supernodal Cholesky (Eigen/CholmodSupport; when the package is built with CHOLMOD), its
//                default ordering (AMD, METIS when AMD fills much); cholmod_metis: METIS alone; cholmod_best: the
//                best of AMD, METIS and CHOLMOD's nested dissection
//   cg_ichol     conjugate gradients, incomplete Cholesky preconditioner, relative residual 1e-10
//   cg_jacobi    conjugate gradients, diagonal preconditioner, relative residual 1e-10
//   cg_amg       conjugate gradients, Smoothed_aggregation_preconditioner (algebraic multigrid V-cycle),
//                relative residual 1e-10
// Cases: `grid:N` (the N x N grid disk of `pe generate grid`) or a mesh file. Stages, each timed alone
// (wall clock): make (generate or read), tutte (tutte_embedding() with the solver, circle border, uniform
// weights), certificate (check_embedding()), repair (progressive_embedding() when the map is not valid),
// write (OBJ with uv, only with --write-dir DIR). Each run is a child process (fork), so that its peak
// resident memory (VmHWM) is its own.
//
//   large_meshes_benchmark OUT_PREFIX [--cases grid:128,grid:256,...,FILE.off] [--solvers ldlt_amd,cholmod,...]
//                          [--repeat R] [--time-limit S] [--memory-limit-mb M] [--write-dir DIR]
//   large_meshes_benchmark --list-solvers      (the solvers of this build)
//
// writes OUT_PREFIX.csv (one row per case and solver: medians of R runs) and OUT_PREFIX.md, with the
// growth per doubling of the vertex count between consecutive rows of one solver: (t2/t1)^(1/log2(n2/n1)).

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/IO/OBJ_with_uv.h>
#include <CGAL/Progressive_embedding/IO/read_polygon_mesh.h>
#include <CGAL/Progressive_embedding/internal/disk_generators.h>
#include <CGAL/Progressive_embedding/Smoothed_aggregation_preconditioner.h>
#include "process_memory.h"
#include "table_util.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Eigen_solver_traits.h>
#include <Eigen/IterativeLinearSolvers>
#ifdef PE_HAS_METIS
#include <Eigen/MetisSupport>
#endif

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace PE = CGAL::Progressive_embedding;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef CGAL::Eigen_sparse_matrix<double>::EigenType Sparse;

namespace {

using pe_bench::split;
using pe_bench::median;
using pe_bench::fixed;

double now_s()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Result
{
  std::string status = "CRASHED";
  std::size_t vertices = 0;
  double make = 0, tutte = 0, certificate = 0, repair = 0, write = 0, peak_mb = 0, mesh_mb = 0, tutte_peak_mb = 0;
  std::size_t flipped = 0;   // flipped + degenerate faces of the Tutte map
  bool valid = false;        // the final certificate
};

template <class Solver>
PE::Error_code tutte_with(Mesh& m, Mesh::Property_map<vertex_descriptor, K::Point_2> uv, double limit, Solver solver)
{
  return PE::tutte_embedding(m, Mesh::null_halfedge(), uv,
                             PE::parameters::border_shape(PE::Border_shape::CIRCLE,
                               CGAL::parameters::maximum_running_time(limit).sparse_linear_solver(solver)));
}

template <class EigenCG>
CGAL::Eigen_solver_traits<EigenCG> cg_traits()
{
  CGAL::Eigen_solver_traits<EigenCG> s;
  s.solver().setTolerance(1e-10);
  s.solver().setMaxIterations(100000);
  return s;
}

PE::Error_code run_solver(const std::string& solver, Mesh& m, Mesh::Property_map<vertex_descriptor, K::Point_2> uv, double limit)
{
  if(solver == "ldlt_amd") return tutte_with(m, uv, limit, CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Sparse> >());
  if(solver == "default")
    return PE::tutte_embedding(m, Mesh::null_halfedge(), uv,
                               PE::parameters::border_shape(PE::Border_shape::CIRCLE, CGAL::parameters::maximum_running_time(limit)));
  if(solver == "llt_amd") return tutte_with(m, uv, limit, CGAL::Eigen_solver_traits<Eigen::SimplicialLLT<Sparse> >());
#ifdef PE_HAS_METIS
  if(solver == "ldlt_metis")
    return tutte_with(m, uv, limit, CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Sparse, Eigen::Lower, Eigen::MetisOrdering<int> > >());
#endif
#ifdef CGAL_PROGRESSIVE_EMBEDDING_CHOLMOD_ENABLED
  if(solver == "cholmod") return tutte_with(m, uv, limit, PE::internal::Cholmod_tutte_solver());
  if(solver == "cholmod_metis" || solver == "cholmod_best")
  {
    // METIS nested dissection alone, or CHOLMOD's best of AMD, METIS and its own nested dissection
    PE::internal::Cholmod_tutte_solver s;
    if(solver == "cholmod_metis") { s.solver().cholmod().nmethods = 1; s.solver().cholmod().method[0].ordering = CHOLMOD_METIS; }
    else s.solver().cholmod().nmethods = 3;
    return tutte_with(m, uv, limit, s);
  }
#endif
  if(solver == "cg_ichol")
    return tutte_with(m, uv, limit, cg_traits<Eigen::ConjugateGradient<Sparse, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double> > >());
  if(solver == "cg_jacobi")
    return tutte_with(m, uv, limit, cg_traits<Eigen::ConjugateGradient<Sparse, Eigen::Lower | Eigen::Upper> >());
  if(solver == "cg_amg")
    return tutte_with(m, uv, limit,
                      cg_traits<Eigen::ConjugateGradient<Sparse, Eigen::Lower | Eigen::Upper, PE::Smoothed_aggregation_preconditioner<double> > >());
  return PE::ERROR_WRONG_PARAMETER;
}

void run_child(const std::string& name, const std::string& solver, double limit, const std::string& write_dir, int fd)
{
  Result r;
  Mesh m;
  double t = now_s();
  const std::vector<std::string> f = split(name, ':');
  if(f.size() == 2 && f[0] == "grid") PE::internal::make_grid_disk(std::size_t(std::atol(f[1].c_str())), m);
  else if(PE::IO::read_polygon_mesh(name, m).status != PE::OK) r.status = "NO_INPUT";
  r.make = now_s() - t;
  r.vertices = num_vertices(m);
  // the mesh alone (after reading), then the peak of the Tutte stage alone
  r.mesh_mb = pe_bench::current_rss_mb();
  const double make_peak_mb = pe_bench::peak_rss_mb();
  const bool peak_reset = pe_bench::reset_peak_rss();
  if(r.status != "NO_INPUT")
  {
    auto uv = m.add_property_map<vertex_descriptor, K::Point_2>("v:uv", K::Point_2(0, 0)).first;
    t = now_s();
    PE::Error_code ec = run_solver(solver, m, uv, limit);
    r.tutte = now_s() - t;
    r.tutte_peak_mb = peak_reset ? pe_bench::peak_rss_mb() : 0;
    if(ec == PE::OK)
    {
      t = now_s();
      PE::Embedding_report rep = PE::check_embedding(m, uv);
      r.certificate = now_s() - t;
      r.flipped = rep.flipped + rep.degenerate;
      if(!rep.is_valid())
      {
        t = now_s();
        ec = PE::progressive_embedding(m, uv, CGAL::parameters::maximum_running_time(limit));
        r.repair = now_s() - t;
        if(ec == PE::OK) rep = PE::check_embedding(m, uv);
      }
      r.valid = ec == PE::OK && rep.is_valid();
      if(ec == PE::OK && !write_dir.empty())
      {
        t = now_s();
        std::ofstream out(write_dir + "/large_meshes_out.obj");
        ec = PE::IO::write_OBJ_with_uv(out, m, uv);
        r.write = now_s() - t;
      }
    }
    r.status = ec == PE::OK ? "OK" : (ec == PE::ERROR_BUDGET_EXHAUSTED ? "TIMEOUT" : PE::get_error_name(ec));
  }
  r.peak_mb = (std::max)(make_peak_mb, pe_bench::peak_rss_mb());
  std::ostringstream os;
  os << std::setprecision(9) << r.status << ' ' << r.vertices << ' ' << r.make << ' ' << r.tutte << ' ' << r.certificate << ' '
     << r.repair << ' ' << r.write << ' ' << r.peak_mb << ' ' << r.flipped << ' ' << r.valid << ' ' << r.mesh_mb << ' '
     << r.tutte_peak_mb << '\n';
  const std::string s = os.str();
  if(::write(fd, s.data(), s.size()) < 0) { }
}

Result run_one(const std::string& name, const std::string& solver, double limit, double memory_mb, const std::string& write_dir)
{
  Result r;
  int status = 0;
  const std::string out = pe_bench::run_in_child([&](int fd) { run_child(name, solver, limit, write_dir, fd); }, memory_mb, status);
  std::istringstream is(out);
  Result got;
  if(is >> got.status >> got.vertices >> got.make >> got.tutte >> got.certificate >> got.repair >> got.write >> got.peak_mb
        >> got.flipped >> got.valid >> got.mesh_mb >> got.tutte_peak_mb) return got;
  if(status != -1 && memory_mb > 0) r.status = "FAILED(memory?)";
  return r;
}

// the BLAS this process runs on (CHOLMOD's supernodal factorization calls it): from the mapped libraries
std::string blas_in_use()
{
  // libblas.so.3 is the library the symbols come from: Debian's reference one (blas/), or OpenBLAS's
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while(std::getline(maps, line))
  {
    if(line.find("libblas.so") == std::string::npos) continue;
    for(const char* kind : { "openblas-serial", "openblas-pthread", "openblas-openmp" })
      if(line.find(kind) != std::string::npos) return kind;
    if(line.find("/blas/libblas.so") != std::string::npos) return "reference";
    return "other";
  }
  return "none";
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " OUT_PREFIX [--cases grid:256,FILE.off] [--solvers ldlt_amd,cholmod] [--repeat R]"
                 " [--time-limit S] [--memory-limit-mb M] [--write-dir DIR]" << std::endl;
    return 1;
  }
  const std::string prefix = argv[1];
  std::string cases = "grid:128,grid:256,grid:512,grid:1024", solvers = "default,ldlt_amd,llt_amd,cg_ichol,cg_jacobi,cg_amg", write_dir;
#ifdef PE_HAS_METIS
  solvers += ",ldlt_metis";
#endif
#ifdef CGAL_PROGRESSIVE_EMBEDDING_CHOLMOD_ENABLED
  solvers += ",cholmod,cholmod_metis,cholmod_best";
#endif
  if(prefix == "--list-solvers") { std::cout << solvers << std::endl; return 0; }
  int repeat = 3;
  double limit = 600, memory_mb = 20000;
  for(int a = 2; a + 1 < argc; a += 2)
  {
    const std::string o = argv[a], v = argv[a + 1];
    if(o == "--cases") cases = v;
    else if(o == "--solvers") solvers = v;
    else if(o == "--repeat") repeat = std::max(1, std::atoi(v.c_str()));
    else if(o == "--time-limit") limit = std::atof(v.c_str());
    else if(o == "--memory-limit-mb") memory_mb = std::atof(v.c_str());
    else if(o == "--write-dir") write_dir = v;
    else { std::cerr << "unknown option " << o << std::endl; return 1; }
  }
  struct Row { std::string name, solver; Result r; int runs = 0; };
  std::vector<Row> rows;
  for(const std::string& name : split(cases, ','))
    for(const std::string& solver : split(solvers, ','))
    {
      Row row;
      row.name = name; row.solver = solver;
      std::vector<double> make, tutte, cert, repair, write, mem;
      for(int k = 0; k < repeat; ++k)
      {
        const Result r = run_one(name, solver, limit, memory_mb, write_dir);
        std::cerr << name << ' ' << solver << " run " << k + 1 << ": " << r.status << " tutte " << r.tutte << " s, certificate "
                  << r.certificate << " s, flipped " << r.flipped << ", repair " << r.repair << " s, " << r.peak_mb << " MB" << std::endl;
        row.r.status = r.status; row.r.vertices = r.vertices; row.r.flipped = r.flipped; row.r.valid = r.valid;
        row.r.mesh_mb = (std::max)(row.r.mesh_mb, r.mesh_mb); row.r.tutte_peak_mb = (std::max)(row.r.tutte_peak_mb, r.tutte_peak_mb);
        if(r.status != "OK") break;
        make.push_back(r.make); tutte.push_back(r.tutte); cert.push_back(r.certificate); repair.push_back(r.repair);
        write.push_back(r.write); mem.push_back(r.peak_mb);
      }
      row.runs = int(tutte.size());
      row.r.make = median(make); row.r.tutte = median(tutte); row.r.certificate = median(cert); row.r.repair = median(repair);
      row.r.write = median(write); row.r.peak_mb = mem.empty() ? 0 : *std::max_element(mem.begin(), mem.end());
      rows.push_back(row);
    }

  std::ofstream csv(prefix + ".csv");
  std::ofstream md(prefix + ".md");
  char host[256] = "?";
  gethostname(host, sizeof host);
  const std::time_t t = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  const std::string blas = blas_in_use();
  csv << "case,solver,blas,vertices,status,runs,make_s,tutte_s,certificate_s,repair_s,write_s,total_s,peak_rss_mb,mesh_rss_mb,tutte_peak_rss_mb,tutte_flipped_or_degenerate,valid,tutte_growth_per_doubling,date,host\n";
  md << "# Large disks: the stages of a certified Tutte map, by sparse solver\n\n"
     << "`large_meshes_benchmark`, date " << date << ", host " << host << ", BLAS " << blas << ". `grid:N`: the N x N grid disk; the Tutte map has the circle\n"
     << "border and uniform weights. Seconds: wall clock of each stage, median of " << repeat << " runs (each in its own process);\n"
     << "peak: the process's VmHWM (MB); mesh: the resident size once the mesh is made or read; tutte peak: the VmHWM of\n"
     << "the Tutte stage alone (reset before it); flipped: flipped or degenerate faces of the Tutte map (then repaired); total: make +\n"
     << "tutte + certificate + repair + write. Growth per doubling of the Tutte stage: (t2/t1)^(1/log2(n2/n1)) against the\n"
     << "previous case with the same solver.\n\n"
     << "| case | solver | vertices | status | make s | tutte s | certificate s | repair s | write s | total s | peak MB | mesh MB | tutte peak MB | flipped | valid | tutte growth per doubling |\n"
     << "|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|\n";
  for(std::size_t i = 0; i < rows.size(); ++i)
  {
    const Row& row = rows[i];
    const Result& r = row.r;
    std::string growth;
    for(std::size_t j = i; j-- > 0;)
      if(rows[j].solver == row.solver)
      {
        if(rows[j].r.status == "OK" && r.status == "OK" && r.vertices > rows[j].r.vertices && rows[j].r.tutte > 0)
          growth = fixed(std::pow(r.tutte / rows[j].r.tutte, 1. / std::log2(double(r.vertices) / double(rows[j].r.vertices))), 2);
        break;
      }
    const double total = r.make + r.tutte + r.certificate + r.repair + r.write;
    csv << row.name << ',' << row.solver << ',' << blas << ',' << r.vertices << ',' << r.status << ',' << row.runs << ',' << r.make << ',' << r.tutte << ','
        << r.certificate << ',' << r.repair << ',' << r.write << ',' << total << ',' << r.peak_mb << ',' << r.mesh_mb << ',' << r.tutte_peak_mb << ',' << r.flipped << ','
        << (r.valid ? "true" : "false") << ',' << growth << ',' << date << ',' << host << '\n';
    md << "| " << row.name << " | " << row.solver << " | " << r.vertices << " | " << r.status << " | " << fixed(r.make, 2) << " | "
       << fixed(r.tutte, 2) << " | " << fixed(r.certificate, 2) << " | " << fixed(r.repair, 2) << " | " << fixed(r.write, 2) << " | "
       << fixed(total, 2) << " | " << fixed(r.peak_mb, 0) << " | " << fixed(r.mesh_mb, 0) << " | " << fixed(r.tutte_peak_mb, 0) << " | " << r.flipped << " | " << (r.valid ? "yes" : "no") << " | " << growth << " |\n";
  }
  std::cerr << "wrote " << prefix << ".csv and " << prefix << ".md" << std::endl;
  return 0;
}
