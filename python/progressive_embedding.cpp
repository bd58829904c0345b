// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// The Python module `progressive_embedding` (pybind11, NumPy): the package's functions on a disk given
// as NumPy arrays V (n x 3), F (m x 3) and UV (n x 2), in the style of libigl's Python bindings.
//
// Every function copies its arrays out of NumPy, validates them (ValueError), then releases the GIL
// while it builds a Surface_mesh (Epick) and runs the algorithm; a failure of the algorithm or of
// the data raises progressive_embedding.Error, whose `code` is the name of the Error_code.
// One translation unit: each algorithm template is instantiated once, at one call site.

#include <pybind11/pybind11.h>
#include <pybind11/numpy.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Real_timer.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/check_immersion.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/certified_pipeline.h>
#include <CGAL/Progressive_embedding/distortion.h>
#include <CGAL/Progressive_embedding/constrained_embedding.h>
#include <CGAL/Progressive_embedding/cross_parameterization.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#ifndef PE_PYTHON_VERSION
#define PE_PYTHON_VERSION "0.0.0"
#endif

namespace py = pybind11;
namespace PE = CGAL::Progressive_embedding;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2                                          Point_2;
typedef K::Point_3                                          Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Mesh;
typedef Mesh::Vertex_index                                  vertex_descriptor;
typedef Mesh::Face_index                                    face_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Point_2>      UV_map;

// ---- errors -------------------------------------------------------------------------------

// An algorithm or data failure; translated into progressive_embedding.Error (with `code`).
struct Pe_failure : std::exception
{
  PE::Error_code code;
  std::string message;
  Pe_failure(PE::Error_code c, const std::string& context)
    : code(c), message(std::string(PE::get_error_name(c)) + ": " + PE::get_error_message(c) +
                       (context.empty() ? std::string() : " (" + context + ")")) {}
  const char* what() const noexcept override { return message.c_str(); }
};

PyObject* error_type = nullptr; // progressive_embedding.Error, created at import, never released

void fail_if(PE::Error_code ec, const std::string& context)
{
  if(ec != PE::OK) throw Pe_failure(ec, context);
}

// ---- timing (for benchmarks: the C++ part of the last call in this thread) -----------------

struct Timing
{
  double native_seconds = 0;    // everything done without the GIL: mesh, algorithm, output copy
  double algorithm_seconds = 0; // the library calls only
};
thread_local Timing last_timing;

// ---- inputs, copied out of NumPy ----------------------------------------------------------

struct Disk_input
{
  std::size_t n = 0, m = 0;
  std::vector<double> V;       // 3n
  std::vector<std::size_t> F;  // 3m
};

py::array as_array(const py::handle& obj, const char* name)
{
  py::array a = py::array::ensure(obj);
  if(!a) throw py::value_error(std::string(name) + " must be a NumPy array or convertible to one");
  return a;
}

// a 2D array of `cols` columns of a real (float or integer) dtype, converted to float64
std::vector<double> real_matrix(const py::handle& obj, const char* name, py::ssize_t cols, std::size_t& rows)
{
  const py::array a = as_array(obj, name);
  const char kind = a.dtype().kind();
  if(kind != 'f' && kind != 'i' && kind != 'u')
    throw py::value_error(std::string(name) + " must have a real dtype (float64 expected), not " +
                          std::string(py::str(a.dtype())));
  if(a.ndim() != 2 || a.shape(1) != cols)
  {
    std::string shape = "(";
    for(py::ssize_t k = 0; k < a.ndim(); ++k) shape += (k ? ", " : "") + std::to_string(a.shape(k));
    throw py::value_error(std::string(name) + " must have shape (n, " + std::to_string(cols) + "), not " + shape + ")");
  }
  const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  if(!d) throw py::value_error(std::string(name) + " cannot be converted to float64");
  rows = static_cast<std::size_t>(d.shape(0));
  return std::vector<double>(d.data(), d.data() + d.size());
}

// an integer value read by integer_values() as written: a uint64 value beyond int64 became negative there
std::string integer_text(long long v, bool from_unsigned)
{
  return from_unsigned ? std::to_string(static_cast<unsigned long long>(v)) : std::to_string(v);
}

// an integer array (any integer dtype) of the given dimension, as int64 (the range is the caller's);
// `from_unsigned`, if given, says whether the dtype was unsigned (for integer_text())
std::vector<long long> integer_values(const py::handle& obj, const char* name, int ndim, py::ssize_t cols,
                                      std::size_t& rows, bool* from_unsigned = nullptr)
{
  const py::array a = as_array(obj, name);
  const char kind = a.dtype().kind();
  if(kind != 'i' && kind != 'u')
    throw py::value_error(std::string(name) + " must have an integer dtype, not " + std::string(py::str(a.dtype())));
  if(a.ndim() != ndim || (ndim == 2 && a.shape(1) != cols))
    throw py::value_error(std::string(name) + (ndim == 2 ? " must have shape (m, " + std::to_string(cols) + ")"
                                                         : std::string(" must be one-dimensional")));
  // unsigned values beyond int64 become negative here, and are refused with the others
  if(from_unsigned) *from_unsigned = (kind == 'u');
  const auto d = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(a);
  if(!d) throw py::value_error(std::string(name) + " cannot be converted to int64");
  rows = static_cast<std::size_t>(d.shape(0));
  return std::vector<long long>(d.data(), d.data() + d.size());
}

bool in_range(long long i, std::size_t bound) { return i >= 0 && static_cast<unsigned long long>(i) < bound; }

// an integer array (any integer dtype) of the given dimension, each value in [0, bound)
std::vector<std::size_t> index_array(const py::handle& obj, const char* name, int ndim, py::ssize_t cols,
                                     std::size_t bound, std::size_t& rows)
{
  bool from_unsigned = false;
  const std::vector<long long> values = integer_values(obj, name, ndim, cols, rows, &from_unsigned);
  std::vector<std::size_t> out(values.size());
  for(std::size_t k = 0; k < out.size(); ++k)
  {
    const long long i = values[k];
    if(!in_range(i, bound))
      throw py::value_error(std::string(name) + " holds the index " + integer_text(i, from_unsigned) + ", out of range for " +
                            std::to_string(bound) + " vertices");
    out[k] = static_cast<std::size_t>(i);
  }
  return out;
}

// `vname`, `fname`: the names of the arguments in the messages (two meshes: V_a, F_a, V_b, F_b)
Disk_input read_disk(const py::handle& V, const py::handle& F, const std::string& vname = "V",
                     const std::string& fname = "F")
{
  Disk_input in;
  in.V = real_matrix(V, vname.c_str(), 3, in.n);
  in.F = index_array(F, fname.c_str(), 2, 3, in.n, in.m);
  // the 3D points enter the border lengths and the distortion: NaN would go through silently
  for(std::size_t i = 0; i < in.n; ++i)
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(in.V[3 * i + c]))
        throw Pe_failure(PE::ERROR_NON_FINITE_COORDINATES, vname + "[" + std::to_string(i) + "] is not finite");
  return in;
}

std::vector<double> read_uv(const py::handle& UV, std::size_t n, const char* name = "UV")
{
  std::size_t rows = 0;
  std::vector<double> uv = real_matrix(UV, name, 2, rows);
  if(rows != n)
    throw py::value_error(std::string(name) + " must have one row per vertex: " + std::to_string(rows) + " rows for " +
                          std::to_string(n) + " vertices");
  return uv;
}

PE::Border_shape parse_shape(const std::string& s)
{
  if(s == "circle") return PE::Border_shape::CIRCLE;
  if(s == "square") return PE::Border_shape::SQUARE;
  if(s == "triangle") return PE::Border_shape::TRIANGLE;
  throw py::value_error("border must be 'circle', 'square', 'triangle' or an (n, 2) array, not '" + s + "'");
}

// `border`: a shape name, or an (n, 2) array whose border rows are the fixed border
struct Border_choice
{
  PE::Border_shape shape = PE::Border_shape::CIRCLE;
  std::vector<double> uv; // with Border_shape::FIXED
};

Border_choice parse_border(const py::object& border, std::size_t n)
{
  Border_choice b;
  if(py::isinstance<py::str>(border)) b.shape = parse_shape(border.cast<std::string>());
  else
  {
    b.shape = PE::Border_shape::FIXED;
    b.uv = read_uv(border, n, "border");
  }
  return b;
}

PE::Weights parse_weights(const std::string& w)
{
  if(w == "uniform") return PE::Weights::UNIFORM;
  if(w == "mean_value" || w == "mean-value") return PE::Weights::MEAN_VALUE;
  throw py::value_error("weights must be 'uniform' or 'mean_value', not '" + w + "'");
}

// ---- the mesh (built without the GIL) -----------------------------------------------------

struct Work
{
  Mesh mesh;
  UV_map uv;
  std::vector<vertex_descriptor> vd;

  explicit Work(const Disk_input& in, const std::string& fname = "F")
  {
    mesh.reserve(static_cast<Mesh::size_type>(in.n), static_cast<Mesh::size_type>(3 * in.m / 2 + 3),
                 static_cast<Mesh::size_type>(in.m));
    vd.reserve(in.n);
    for(std::size_t i = 0; i < in.n; ++i)
      vd.push_back(mesh.add_vertex(Point_3(in.V[3 * i], in.V[3 * i + 1], in.V[3 * i + 2])));
    for(std::size_t j = 0; j < in.m; ++j)
    {
      const std::size_t a = in.F[3 * j], b = in.F[3 * j + 1], c = in.F[3 * j + 2];
      // Euler::add_face, as the package's readers: it refuses non-manifold and misoriented faces
      const std::array<vertex_descriptor, 3> t = {{ vd[a], vd[b], vd[c] }};
      if(a == b || b == c || c == a)
        throw Pe_failure(PE::ERROR_NON_MANIFOLD, face_name(fname, j, a, b, c) + " repeats a vertex");
      if(CGAL::Euler::add_face(t, mesh) == Mesh::null_face())
        throw Pe_failure(PE::ERROR_NON_MANIFOLD, face_name(fname, j, a, b, c) + " cannot be added: non-manifold or inconsistently oriented");
    }
    // a vertex in no face: the mesh is no disk (nor closed surface), and said so here rather than through a less
    // telling code from the algorithm
    for(std::size_t i = 0; i < in.n; ++i)
      if(mesh.is_isolated(vd[i]))
        throw Pe_failure(PE::ERROR_NOT_A_DISK, "vertex " + std::to_string(i) + " is in no face of " + fname +
                                               " (every vertex must be on a face)");
    uv = mesh.add_property_map<vertex_descriptor, Point_2>("v:uv", Point_2(0, 0)).first;
  }

  static std::string face_name(const std::string& fname, std::size_t j, std::size_t a, std::size_t b, std::size_t c)
  {
    return fname + "[" + std::to_string(j) + "] = (" + std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c) + ")";
  }

  void set_uv(const std::vector<double>& u, bool border_only = false)
  {
    for(std::size_t i = 0; i < vd.size(); ++i)
      uv[vd[i]] = (!border_only || CGAL::is_border(vd[i], mesh)) ? Point_2(u[2 * i], u[2 * i + 1]) : Point_2(0, 0);
  }

  std::vector<double> get_uv() const
  {
    std::vector<double> u;
    u.reserve(2 * vd.size());
    for(vertex_descriptor v : vd) { u.push_back(uv[v].x()); u.push_back(uv[v].y()); }
    return u;
  }
};

py::array_t<double> uv_array(const std::vector<double>& u)
{
  const py::ssize_t n = static_cast<py::ssize_t>(u.size() / 2);
  py::array_t<double> out({ n, py::ssize_t(2) });
  if(!u.empty()) std::memcpy(out.mutable_data(), u.data(), u.size() * sizeof(double));
  return out;
}

// ---- the algorithm steps (one call site per template) -------------------------------------

struct Stopwatch
{
  CGAL::Real_timer t;
  double& into;
  explicit Stopwatch(double& d) : into(d) { t.start(); }
  ~Stopwatch() { into += t.time(); }
};

PE::Error_code run_tutte(Work& w, PE::Border_shape shape, PE::Weights weights)
{
  Stopwatch s(last_timing.algorithm_seconds);
  return PE::tutte_embedding(w.mesh, Mesh::null_halfedge(), w.uv,
                             PE::parameters::weights(weights, PE::parameters::border_shape(shape)));
}

PE::Embedding_report run_check(const Work& w)
{
  Stopwatch s(last_timing.algorithm_seconds);
  return PE::check_embedding(w.mesh, w.uv);
}

bool run_immersion_check(const Work& w)
{
  Stopwatch s(last_timing.algorithm_seconds);
  return PE::check_immersion(w.mesh, w.uv).is_immersion();
}

struct Optimize_settings
{
  bool free_border = false;
  std::vector<vertex_descriptor> fixed;
  std::size_t iterations = 1000;
  double tolerance = 1e-5;
};

PE::Error_code run_optimize(Work& w, const Optimize_settings& o, PE::Optimization_statistics& os)
{
  Stopwatch s(last_timing.algorithm_seconds);
  return PE::optimize_distortion<CGAL::Parallel_tag>(w.mesh, w.uv, PE::parameters::free_border(o.free_border).constrained_vertices(o.fixed)
                                                  .convergence_tolerance(o.tolerance).optimization_statistics(&os)
                                                  .number_of_iterations(o.iterations));
}

// the library's repair-and-optimize policy (repair_and_optimize(), as `pe untangle` and `pe embed`): the repair
// if the map is not valid, then the optimization unless optimize=False; a map the optimizer cannot touch keeps
// its certified map
void repair_and_optimize(Work& w, bool optimize, const Optimize_settings& o)
{
  Stopwatch s(last_timing.algorithm_seconds);
  PE::Pipeline_statistics ps;
  const PE::Error_code ec = PE::repair_and_optimize<CGAL::Parallel_tag>(w.mesh, w.uv,
    PE::parameters::optimization_policy(optimize ? PE::Optimization_policy::ALWAYS : PE::Optimization_policy::NEVER)
                   .pipeline_statistics(&ps).convergence_tolerance(o.tolerance).number_of_iterations(o.iterations));
  fail_if(ec, ps.optimized ? "optimize_distortion after the repair" : "progressive_embedding");
}

// the settings of an optimization from the Python arguments, checked
Optimize_settings optimize_settings(long long iterations, double tolerance, bool free_border = false)
{
  if(iterations < 0) throw py::value_error("iterations must be non-negative, not " + std::to_string(iterations));
  if(!(tolerance >= 0)) throw py::value_error("tolerance must be a non-negative number");
  Optimize_settings o;
  o.free_border = free_border;
  o.iterations = static_cast<std::size_t>(iterations);
  o.tolerance = tolerance;
  return o;
}

// ---- reports as dicts ---------------------------------------------------------------------

// the keys of `pe check --json` (add_report in tools/pe), and a few more fields of the certificate
py::dict report_dict(const PE::Embedding_report& rep)
{
  py::dict d;
  d["status"] = PE::get_error_name(rep.status);
  d["valid"] = rep.is_valid();
  d["flipped"] = rep.flipped;
  d["degenerate"] = rep.degenerate;
  d["faces"] = rep.faces;
  d["vertices"] = rep.vertices;
  d["border_vertices"] = rep.border_vertices;
  d["non_finite"] = rep.non_finite;
  d["border_simple"] = rep.border_simple;
  d["border_intersections"] = rep.border_intersections;
  d["overlapping_pairs"] = rep.overlapping_pairs;
  d["overlap_checked"] = rep.overlap_checked;
  d["clockwise"] = rep.clockwise;
  d["min_signed_area"] = rep.min_signed_area;
  d["max_signed_area"] = rep.max_signed_area;
  d["border_area"] = rep.border_area;
  d["max_energy_3d"] = rep.max_energy_3d;
  d["mean_energy_3d"] = rep.mean_energy_3d;
  d["high_energy_faces"] = rep.high_energy_faces;
  d["has_3d_energy"] = rep.has_3d_energy;
  return d;
}

// ---- the functions ------------------------------------------------------------------------

py::array_t<double> py_tutte(const py::object& V, const py::object& F, const py::object& border,
                             const std::string& weights)
{
  const Disk_input in = read_disk(V, F);
  const Border_choice b = parse_border(border, in.n);
  const PE::Weights wts = parse_weights(weights);
  std::vector<double> uv;
  last_timing = Timing();
  {
    py::gil_scoped_release release;
    Stopwatch s(last_timing.native_seconds);
    Work w(in);
    if(b.shape == PE::Border_shape::FIXED) w.set_uv(b.uv);
    fail_if(run_tutte(w, b.shape, wts), "tutte_embedding");
    uv = w.get_uv();
  }
  return uv_array(uv);
}

py::dict py_check(const py::object& V, const py::object& F, const py::object& UV)
{
  const Disk_input in = read_disk(V, F);
  const std::vector<double> u = read_uv(UV, in.n);
  PE::Embedding_report rep;
  bool immersion = false;
  last_timing = Timing();
  {
    py::gil_scoped_release release;
    Stopwatch s(last_timing.native_seconds);
    Work w(in);
    w.set_uv(u);
    rep = run_check(w);
    fail_if(rep.status, "check_embedding");
    // a map that is not an embedding may still be an immersion (locally injective, overlapping itself)
    immersion = run_immersion_check(w);
  }
  py::dict d = report_dict(rep);
  d["immersion"] = immersion;
  return d;
}

py::array_t<double> py_untangle(const py::object& V, const py::object& F, const py::object& UV, bool optimize,
                                long long iterations, double tolerance)
{
  const Disk_input in = read_disk(V, F);
  const std::vector<double> u = read_uv(UV, in.n);
  const Optimize_settings o = optimize_settings(iterations, tolerance);
  std::vector<double> out;
  last_timing = Timing();
  {
    py::gil_scoped_release release;
    Stopwatch s(last_timing.native_seconds);
    Work w(in);
    w.set_uv(u);
    repair_and_optimize(w, optimize, o);
    out = w.get_uv();
  }
  return uv_array(out);
}

py::array_t<double> py_embed(const py::object& V, const py::object& F, const py::object& border,
                             const std::string& weights, bool optimize, long long iterations, double tolerance)
{
  const Disk_input in = read_disk(V, F);
  const Border_choice b = parse_border(border, in.n);
  const PE::Weights wts = parse_weights(weights);
  const Optimize_settings o = optimize_settings(iterations, tolerance);
  std::vector<double> out;
  last_timing = Timing();
  {
    py::gil_scoped_release release;
    Stopwatch s(last_timing.native_seconds);
    Work w(in);
    if(b.shape == PE::Border_shape::FIXED) w.set_uv(b.uv);
    fail_if(run_tutte(w, b.shape, wts), "tutte_embedding");
    repair_and_optimize(w, optimize, o);
    out = w.get_uv();
  }
  return uv_array(out);
}

py::array_t<double> py_optimize(const py::object& V, const py::object& F, const py::object& UV,
                                const py::object& fixed, bool free_border, long long iterations, double tolerance)
{
  const Disk_input in = read_disk(V, F);
  const std::vector<double> u = read_uv(UV, in.n);
  Optimize_settings o = optimize_settings(iterations, tolerance, free_border);
  std::vector<std::size_t> fixed_idx;
  if(!fixed.is_none())
  {
    std::size_t k = 0;
    fixed_idx = index_array(fixed, "fixed", 1, 0, in.n, k);
  }
  std::vector<double> out;
  last_timing = Timing();
  {
    py::gil_scoped_release release;
    Stopwatch s(last_timing.native_seconds);
    Work w(in);
    w.set_uv(u);
    for(std::size_t i : fixed_idx) o.fixed.push_back(w.vd[i]);
    PE::Optimization_statistics os;
    const PE::Error_code ec = run_optimize(w, o, os);
    // a budget that runs out still leaves a valid, improved map
    if(ec != PE::ERROR_BUDGET_EXHAUSTED)
      fail_if(ec, ec == PE::ERROR_INVALID_EMBEDDING ? "optimize_distortion needs a valid map: run untangle() first"
                                                     : "optimize_distortion");
    out = w.get_uv();
  }
  return uv_array(out);
}

py::dict py_measure(const py::object& V, const py::object& F, const py::object& UV)
{
  const Disk_input in = read_disk(V, F);
  const std::vector<double> u = read_uv(UV, in.n);
  PE::Distortion_report r;
  last_timing = Timing();
  {
    py::gil_scoped_release release;
    Stopwatch s(last_timing.native_seconds);
    Work w(in);
    w.set_uv(u);
    {
      Stopwatch a(last_timing.algorithm_seconds);
      r = PE::measure_distortion(w.mesh, w.uv);
    }
    fail_if(r.status, "measure_distortion");
  }
  py::dict d;
  d["status"] = PE::get_error_name(r.status);
  d["faces"] = r.faces;
  d["max_symmetric_dirichlet"] = r.max_symmetric_dirichlet;
  d["mean_symmetric_dirichlet"] = r.mean_symmetric_dirichlet;
  d["symmetric_dirichlet_median"] = r.symmetric_dirichlet_quantiles[0];
  d["symmetric_dirichlet_p90"] = r.symmetric_dirichlet_quantiles[1];
  d["symmetric_dirichlet_p99"] = r.symmetric_dirichlet_quantiles[2];
  d["max_conformal"] = r.max_conformal;
  d["mean_conformal"] = r.mean_conformal;
  d["max_area"] = r.max_area;
  d["mean_area"] = r.mean_area;
  // the names `pe --json` gives the symmetric Dirichlet energy
  d["max_energy_3d"] = r.max_symmetric_dirichlet;
  d["mean_energy_3d"] = r.mean_symmetric_dirichlet;
  return d;
}

py::tuple py_constrain(const py::object& V, const py::object& F, const py::object& UV, const py::object& border,
                       const py::object& constraints, const std::string& weights, bool optimize)
{
  const Disk_input in = read_disk(V, F);
  // the targets are points of the domain: its border must be given, not guessed (as in `pe constrain`)
  if(UV.is_none() == border.is_none())
    throw py::value_error("constrain needs exactly one of UV (the fixed border) and border ('circle', 'square', 'triangle')");
  PE::Border_shape shape = PE::Border_shape::FIXED;
  std::vector<double> u;
  if(!UV.is_none()) u = read_uv(UV, in.n);
  else
  {
    if(!py::isinstance<py::str>(border)) throw py::value_error("border must be 'circle', 'square' or 'triangle' (a fixed border is given as UV)");
    shape = parse_shape(border.cast<std::string>());
  }
  const PE::Weights wts = parse_weights(weights);
  std::vector<std::size_t> idx;
  std::vector<double> targets;
  if(!constraints.is_none())
  {
    if(!py::isinstance<py::sequence>(constraints) || py::len(constraints) != 2)
      throw py::value_error("constraints must be a pair (indices, targets): an integer array of k vertices and a (k, 2) array");
    const py::sequence c = constraints.cast<py::sequence>();
    std::size_t k = 0, kt = 0;
    idx = index_array(c[0], "constraints[0] (indices)", 1, 0, in.n, k);
    targets = real_matrix(c[1], "constraints[1] (targets)", 2, kt);
    if(k != kt)
      throw py::value_error("constraints: " + std::to_string(k) + " indices but " + std::to_string(kt) + " targets");
  }

  std::vector<double> V2, U2;
  std::vector<long long> F2, s_index, s_corner;
  std::vector<double> s_weight;
  PE::Constrained_embedding_statistics st;
  double error = 0;
  bool exact = true;
  last_timing = Timing();
  {
    py::gil_scoped_release release;
    Stopwatch s(last_timing.native_seconds);
    Work w(in);
    if(shape == PE::Border_shape::FIXED) w.set_uv(u, true); // interior values are ignored
    std::vector<std::pair<vertex_descriptor, Point_2> > cons;
    for(std::size_t k = 0; k < idx.size(); ++k)
      cons.emplace_back(w.vd[idx[k]], Point_2(targets[2 * k], targets[2 * k + 1]));
    std::vector<PE::Steiner_point<vertex_descriptor> > steiner;
    PE::Error_code ec;
    {
      Stopwatch a(last_timing.algorithm_seconds);
      ec = PE::constrained_embedding<CGAL::Parallel_if_available_tag>(w.mesh, cons, w.uv,
        PE::parameters::border_shape(shape,
        PE::parameters::weights(wts,
        PE::parameters::optimize(optimize,
        PE::parameters::statistics(&st,
        PE::parameters::steiner_points(&steiner))))));
    }
    fail_if(ec, "constrained_embedding");
    // the refined mesh: input vertices first, in their order, then the Steiner vertices
    auto index = w.mesh.add_property_map<vertex_descriptor, long long>("v:py_index", -1).first;
    long long next = 0;
    for(vertex_descriptor v : w.mesh.vertices())
    {
      index[v] = next++;
      const Point_3& p = w.mesh.point(v);
      V2.insert(V2.end(), { p.x(), p.y(), p.z() });
      U2.insert(U2.end(), { w.uv[v].x(), w.uv[v].y() });
    }
    for(face_descriptor f : w.mesh.faces())
      for(vertex_descriptor v : CGAL::vertices_around_face(w.mesh.halfedge(f), w.mesh)) F2.push_back(index[v]);
    for(const auto& sp : steiner)
    {
      s_index.push_back(index[sp.vertex]);
      for(std::size_t k = 0; k < 3; ++k)
      {
        s_corner.push_back(k < sp.size ? index[sp.corners[k]] : -1);
        s_weight.push_back(k < sp.size ? sp.weights[k] : 0.);
      }
    }
    for(const auto& c : cons)
    {
      const Point_2 p = w.uv[c.first];
      if(p.x() != c.second.x() || p.y() != c.second.y()) exact = false;
      error = (std::max)(error, std::hypot(p.x() - c.second.x(), p.y() - c.second.y()));
    }
  }
  const py::ssize_t nv = static_cast<py::ssize_t>(V2.size() / 3), nf = static_cast<py::ssize_t>(F2.size() / 3),
                    ns = static_cast<py::ssize_t>(s_index.size());
  py::array_t<double> V2a({ nv, py::ssize_t(3) });
  if(nv) std::memcpy(V2a.mutable_data(), V2.data(), V2.size() * sizeof(double));
  py::array_t<long long> F2a({ nf, py::ssize_t(3) });
  if(nf) std::memcpy(F2a.mutable_data(), F2.data(), F2.size() * sizeof(long long));
  py::array_t<long long> si(ns), sc({ ns, py::ssize_t(3) });
  py::array_t<double> sw({ ns, py::ssize_t(3) });
  if(ns)
  {
    std::memcpy(si.mutable_data(), s_index.data(), s_index.size() * sizeof(long long));
    std::memcpy(sc.mutable_data(), s_corner.data(), s_corner.size() * sizeof(long long));
    std::memcpy(sw.mutable_data(), s_weight.data(), s_weight.size() * sizeof(double));
  }
  py::dict info = report_dict(st.report);
  info["steiner_vertices"] = st.steiner_vertices;
  info["paths"] = st.paths;
  info["patches"] = st.patches;
  info["repaired_patches"] = st.repaired_patches;
  info["optimized"] = st.optimized;
  info["optimization_status"] = PE::get_error_name(st.optimization_status);
  info["immersion"] = st.immersion && st.immersion_report.is_immersion();
  info["constraint_error"] = error;
  info["constraints_exact"] = exact;
  info["steiner_indices"] = si;
  info["steiner_corners"] = sc;
  info["steiner_weights"] = sw;
  return py::make_tuple(V2a, F2a, uv_array(U2), info);
}

// ---- cross-parameterization ----------------------------------------------------------------

// a CGAL Face_location on `m` (a face and the coordinates of source(halfedge(f)), target(halfedge(f)),
// target(next(halfedge(f)))) as the row of F and the coordinates in the order of that row's columns; `m`
// was built from `in` (Work): vertex i and face j are the i-th vertex and the j-th row of F
void location_to_row(const Mesh& m, const Disk_input& in, const PE::Cross_location<Mesh>& l, long long& face, double* b)
{
  const std::size_t j = static_cast<std::size_t>(l.first);
  const Mesh::Halfedge_index h = m.halfedge(l.first);
  const std::array<std::size_t, 3> corners = {{ std::size_t(m.source(h)), std::size_t(m.target(h)),
                                                std::size_t(m.target(m.next(h))) }};
  for(int c = 0; c < 3; ++c)
    for(int k = 0; k < 3; ++k)
      if(in.F[3 * j + k] == corners[c]) b[k] = l.second[c];
  face = static_cast<long long>(j);
}

std::string landmark_name(std::size_t k, const std::vector<long long>& pairs, bool from_unsigned)
{
  return "landmarks[" + std::to_string(k) + "] = (" + integer_text(pairs[2 * k], from_unsigned) + ", " +
         integer_text(pairs[2 * k + 1], from_unsigned) + ")";
}

// a mesh that cross_parameterization() wrote (vertices in order, triangles) as arrays: points (n, dim), faces (f, 3)
std::pair<py::array_t<double>, py::array_t<long long> > mesh_arrays(const Mesh& m, int dim)
{
  py::array_t<double> P({ static_cast<py::ssize_t>(m.number_of_vertices()), py::ssize_t(dim) });
  py::array_t<long long> T({ static_cast<py::ssize_t>(m.number_of_faces()), py::ssize_t(3) });
  double* p = P.mutable_data();
  for(vertex_descriptor v : m.vertices())
    for(int c = 0; c < dim; ++c) *p++ = CGAL::to_double(m.point(v)[c]);
  long long* t = T.mutable_data();
  for(face_descriptor f : m.faces())
    for(vertex_descriptor v : CGAL::vertices_around_face(m.halfedge(f), m)) *t++ = static_cast<long long>(v);
  return { P, T };
}

py::tuple py_cross(const py::object& V_a, const py::object& F_a, const py::object& V_b, const py::object& F_b,
                   const py::object& landmarks, const py::object& border_vertex_pair, bool b_to_a,
                   const py::object& time_limit, double optimization_time_limit, bool composed, bool matched,
                   bool compatible, bool planar_maps)
{
  const Disk_input in_a = read_disk(V_a, F_a, "V_a", "F_a");
  const Disk_input in_b = read_disk(V_b, F_b, "V_b", "F_b");
  // landmarks: (k, 2) integers; None or empty (e.g. []): only the borders are matched
  std::vector<long long> pairs;
  std::size_t k = 0;
  bool landmarks_unsigned = false;
  if(!landmarks.is_none())
  {
    const py::array l = as_array(landmarks, "landmarks");
    if(!(l.size() == 0 && (l.ndim() == 1 || (l.ndim() == 2 && l.shape(1) == 2))))
      pairs = integer_values(l, "landmarks", 2, 2, k, &landmarks_unsigned);
  }
  // an index that is no vertex is the C++ function's ERROR_WRONG_PARAMETER (it cannot be a descriptor here)
  for(std::size_t r = 0; r < k; ++r)
    for(int c = 0; c < 2; ++c)
      if(!in_range(pairs[2 * r + c], c == 0 ? in_a.n : in_b.n))
        throw Pe_failure(PE::ERROR_WRONG_PARAMETER, landmark_name(r, pairs, landmarks_unsigned) + ": " +
                         integer_text(pairs[2 * r + c], landmarks_unsigned) +
                         " is not a vertex of " + (c == 0 ? "A (" + std::to_string(in_a.n) : "B (" + std::to_string(in_b.n)) +
                         " vertices)");
  const bool has_pair = !border_vertex_pair.is_none();
  std::vector<long long> pair;
  if(has_pair)
  {
    std::size_t rows = 0;
    bool pair_unsigned = false;
    pair = integer_values(border_vertex_pair, "border_vertex_pair", 1, 0, rows, &pair_unsigned);
    if(pair.size() != 2) throw py::value_error("border_vertex_pair must be a pair (border vertex of A, border vertex of B)");
    for(int c = 0; c < 2; ++c)
      if(!in_range(pair[c], c == 0 ? in_a.n : in_b.n))
        throw Pe_failure(PE::ERROR_WRONG_PARAMETER, "border_vertex_pair: " + integer_text(pair[c], pair_unsigned) + " is not a vertex of " +
                         (c == 0 ? "A (" + std::to_string(in_a.n) : "B (" + std::to_string(in_b.n)) + " vertices)");
  }
  double seconds = std::numeric_limits<double>::infinity();
  if(!time_limit.is_none())
  {
    try { seconds = time_limit.cast<double>(); }
    catch(const py::cast_error&) { throw py::value_error("time_limit must be a number of seconds or None"); }
    if(!(seconds >= 0)) throw py::value_error("time_limit must be non-negative");
  }
  if(!(optimization_time_limit >= 0)) throw py::value_error("optimization_time_limit must be non-negative");

  std::vector<long long> faces(in_a.n), back_faces(b_to_a ? in_b.n : 0);
  std::vector<double> bary(3 * in_a.n), back_bary(3 * back_faces.size());
  PE::Cross_parameterization_statistics st;
  // the optional meshes (written by the C++ function: the null pointers ask for nothing, so that one call
  // serves every combination)
  Mesh compatible_a, compatible_b, plane_a, plane_b;
  last_timing = Timing();
  {
    py::gil_scoped_release release;
    Stopwatch s(last_timing.native_seconds);
    const Work wa(in_a, "F_a"), wb(in_b, "F_b");
    std::vector<std::pair<vertex_descriptor, vertex_descriptor> > lm;
    for(std::size_t r = 0; r < k; ++r) lm.emplace_back(wa.vd[pairs[2 * r]], wb.vd[pairs[2 * r + 1]]);
    const std::pair<vertex_descriptor, vertex_descriptor> vp =
      has_pair ? std::make_pair(wa.vd[pair[0]], wb.vd[pair[1]]) : std::make_pair(Mesh::null_vertex(), Mesh::null_vertex());
    std::vector<PE::Cross_location<Mesh> > located(in_a.n), back(back_faces.size());
    auto out = boost::make_iterator_property_map(located.begin(), get(CGAL::vertex_index, wa.mesh));
    auto out_back = boost::make_iterator_property_map(back.begin(), get(CGAL::vertex_index, wb.mesh));
    const auto np = PE::parameters::composed_distortion(composed, PE::parameters::matched_maps(matched,
                      PE::parameters::compatible_meshes(std::make_pair(compatible ? &compatible_a : nullptr,
                                                                       compatible ? &compatible_b : nullptr),
                      PE::parameters::planar_maps(std::make_pair(planar_maps ? &plane_a : nullptr,
                                                                 planar_maps ? &plane_b : nullptr),
                      PE::parameters::statistics(&st).maximum_running_time(seconds)
                                                     .optimization_time_limit(optimization_time_limit)))));
    PE::Error_code ec;
    {
      Stopwatch a(last_timing.algorithm_seconds);
      // the function tests at compile time whether these two parameters are given (without a pair it
      // chooses its own): one call per combination
      if(has_pair && b_to_a)
        ec = PE::cross_parameterization(wa.mesh, wb.mesh, lm, out,
               PE::parameters::border_vertex_pair(vp, PE::parameters::b_to_a_locations(out_back, np)));
      else if(has_pair)
        ec = PE::cross_parameterization(wa.mesh, wb.mesh, lm, out, PE::parameters::border_vertex_pair(vp, np));
      else if(b_to_a)
        ec = PE::cross_parameterization(wa.mesh, wb.mesh, lm, out, PE::parameters::b_to_a_locations(out_back, np));
      else
        ec = PE::cross_parameterization(wa.mesh, wb.mesh, lm, out, np);
    }
    if(ec != PE::OK)
    {
      // name what the statistics point at: a landmark (its row), the border pair, or a mesh; the words of the fault
      // are those of `pe cross`
      const std::string mesh = st.failed_mesh == 0 ? "A" : "B";
      std::string context = "cross_parameterization";
      if(st.failed_landmark < k)
        context = landmark_name(st.failed_landmark, pairs, landmarks_unsigned) + ": the vertex " +
                  std::to_string(pairs[2 * st.failed_landmark + (st.failed_mesh == 0 ? 0 : 1)]) + " of " + mesh + " " +
                  PE::internal::cross_landmark_fault(ec, st.closed, has_pair);
      else if(ec == PE::ERROR_WRONG_PARAMETER && has_pair && st.failed_mesh >= 0 &&
              !CGAL::is_border(st.failed_mesh == 0 ? vp.first : vp.second, st.failed_mesh == 0 ? wa.mesh : wb.mesh))
        context = "border_vertex_pair: the vertex " + std::to_string(pair[st.failed_mesh]) + " of " + mesh +
                  " is not on its border";
      else if(st.failed_mesh >= 0)
      {
        context += st.failed_mesh == 0 ? ", mesh A (V_a, F_a)" : ", mesh B (V_b, F_b)";
        const std::string why = PE::internal::cross_mesh_fault(ec, st.border_landmarks,
                                  !st.closed && CGAL::is_closed(st.failed_mesh == 0 ? wa.mesh : wb.mesh));
        if(!why.empty()) context += ": " + why;
      }
      else if(st.closed && ec == PE::ERROR_WRONG_PARAMETER)
        context += ": closed meshes need at least two landmarks (the cut runs between two of them), and "
                   "border_vertex_pair does not apply to them (no border)";
      throw Pe_failure(ec, context);
    }
    for(std::size_t i = 0; i < in_a.n; ++i) location_to_row(wb.mesh, in_b, located[i], faces[i], &bary[3 * i]);
    for(std::size_t i = 0; i < back.size(); ++i) location_to_row(wa.mesh, in_a, back[i], back_faces[i], &back_bary[3 * i]);
  }
  auto int_array = [](const std::vector<long long>& v) {
    py::array_t<long long> a(static_cast<py::ssize_t>(v.size()));
    if(!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(long long));
    return a;
  };
  auto coordinates = [](const std::vector<double>& v) {
    py::array_t<double> a({ static_cast<py::ssize_t>(v.size() / 3), py::ssize_t(3) });
    if(!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(double));
    return a;
  };
  // the keys of `pe cross --json` where it has them
  py::dict info;
  info["status"] = PE::get_error_name(PE::OK);
  info["valid"] = st.report_a.is_valid() && st.report_b.is_valid();
  info["valid_a"] = st.report_a.is_valid();
  info["valid_b"] = st.report_b.is_valid();
  info["landmarks_exact"] = st.landmarks_exact;
  info["landmarks"] = st.landmarks;
  info["border_landmarks"] = st.border_landmarks;
  info["vertices_a"] = st.vertices_a;
  info["faces_a"] = st.faces_a;
  info["vertices_b"] = st.vertices_b;
  info["faces_b"] = st.faces_b;
  info["vertices_added_a"] = st.vertices_added_a;
  info["closed"] = st.closed;
  info["cut_landmarks"] = st.cut_landmarks;
  info["cut_edges_a"] = st.cut_edges_a;
  info["cut_edges_b"] = st.cut_edges_b;
  info["chords_split_b"] = st.chords_split_b;
  info["in_face"] = st.located_in_face;
  info["on_edge"] = st.located_on_edge;
  info["on_vertex"] = st.located_on_vertex;
  info["seconds_validation"] = st.seconds_validation;
  info["seconds_map_b"] = st.seconds_map_b;
  info["seconds_map_a"] = st.seconds_map_a;
  info["seconds_location"] = st.seconds_location;
  info["composed"] = composed;
  if(composed)
  {
    info["composed_status"] = PE::get_error_name(st.composed_status);
    info["composed_iterations"] = st.composed.iterations;
    info["composed_energy"] = st.composed.energy_current;
    info["seconds_composed"] = st.seconds_composed;
  }
  if(compatible)
  {
    // the keys of `pe cross --compatible --json`, and the two meshes
    info["valid_compatible"] = st.report_compatible.is_valid();
    info["certificate_compatible"] = report_dict(st.report_compatible);
    info["overlay_cells"] = st.overlay_cells;
    info["overlay_crossings"] = st.overlay_crossings;
    info["compatible_vertices"] = st.compatible_vertices;
    info["compatible_faces"] = st.compatible_faces;
    if(st.closed) info["cut_vertices_welded"] = st.cut_vertices_welded;
    info["seconds_compatible"] = st.seconds_compatible;
    const auto on_a = mesh_arrays(compatible_a, 3), on_b = mesh_arrays(compatible_b, 3);
    info["compatible_V_a"] = on_a.first;
    info["compatible_V_b"] = on_b.first;
    info["compatible_F"] = on_a.second;
  }
  if(planar_maps)
  {
    const auto map_a = mesh_arrays(plane_a, 2), map_b = mesh_arrays(plane_b, 2);
    info["planar_uv_a"] = map_a.first;
    info["planar_F_a"] = map_a.second;
    info["planar_uv_b"] = map_b.first;
    info["planar_F_b"] = map_b.second;
  }
  info["matched_b"] = st.matched_b;
  info["matched_status"] = PE::get_error_name(st.matched_status);
  info["matched_more_distorted"] = st.matched_more_distorted;
  info["vertices_added_b"] = st.vertices_added_b;
  info["seconds_total"] = st.seconds_total;
  info["certificate_a"] = report_dict(st.report_a);
  info["certificate_b"] = report_dict(st.report_b);
  py::dict map_b;
  PE::for_each_statistic(st.map_b, [&](const char* key, const auto& value) { map_b[key] = value; });
  info["map_b"] = map_b;
  py::dict map_a;
  map_a["steiner_vertices"] = st.map_a.steiner_vertices;
  map_a["paths"] = st.map_a.paths;
  map_a["patches"] = st.map_a.patches;
  map_a["repaired_patches"] = st.map_a.repaired_patches;
  map_a["optimized"] = st.map_a.optimized;
  map_a["optimization_status"] = PE::get_error_name(st.map_a.optimization_status);
  info["map_a"] = map_a;
  if(b_to_a)
  {
    info["located_b_on_a"] = st.located_b_on_a;
    info["b_to_a_faces"] = int_array(back_faces);
    info["b_to_a_barycentric"] = coordinates(back_bary);
  }
  return py::make_tuple(int_array(faces), coordinates(bary), info);
}

py::dict py_last_timing()
{
  py::dict d;
  d["native_seconds"] = last_timing.native_seconds;
  d["algorithm_seconds"] = last_timing.algorithm_seconds;
  return d;
}

} // namespace

PYBIND11_MODULE(progressive_embedding, m)
{
  m.doc() =
    "Planar parametrizations of triangulated disks that are valid in floating point.\n\n"
    "Bindings of the C++ package Progressive_embedding (CGAL style). A mesh is a topological disk given\n"
    "by V (n x 3 float64 vertex positions) and F (m x 3 integer faces indexing V, no seams); a map is UV\n"
    "(n x 2 float64, one row per vertex). Wrong shapes, dtypes or indices raise ValueError; a failure of\n"
    "the algorithm or of the data raises progressive_embedding.Error, whose attribute `code` is the name\n"
    "of the package's Error_code (e.g. 'ERROR_NOT_A_DISK'). The GIL is released during the computation.";
  m.attr("__version__") = PE_PYTHON_VERSION;

  error_type = PyErr_NewExceptionWithDoc(
    "progressive_embedding.Error",
    "A failure of an algorithm or of the input data (not a disk, non-manifold, NaN coordinates, a map that\n"
    "cannot be repaired, ...). `code` is the name of the Error_code, e.g. 'ERROR_NOT_A_DISK'; the message\n"
    "starts with it.", PyExc_RuntimeError, nullptr);
  if(!error_type) throw py::error_already_set();
  py::handle(error_type).attr("code") = py::none();
  m.add_object("Error", py::handle(error_type));
  py::register_exception_translator([](std::exception_ptr p) {
    try { if(p) std::rethrow_exception(p); }
    catch(const Pe_failure& e)
    {
      py::object type = py::reinterpret_borrow<py::object>(error_type);
      py::object instance = type(py::str(e.message));
      instance.attr("code") = py::str(PE::get_error_name(e.code));
      PyErr_SetObject(error_type, instance.ptr());
    }
  });

  m.def("tutte", &py_tutte, py::arg("V"), py::arg("F"), py::arg("border") = "circle", py::arg("weights") = "uniform",
    "tutte(V, F, border='circle', weights='uniform') -> UV\n\n"
    "Tutte's barycentric map (weights='uniform') or Floater's mean value map (weights='mean_value') of the\n"
    "disk (V, F), solved in double precision. border: 'circle', 'square' or 'triangle' (placed by 3D arc\n"
    "length), or an (n, 2) array whose border rows give a fixed convex border (its interior rows are\n"
    "ignored). The map is not certified: in double it may have flipped faces (see check(), untangle()).\n"
    "Returns UV, an (n, 2) float64 array.");
  m.def("check", &py_check, py::arg("V"), py::arg("F"), py::arg("UV"),
    "check(V, F, UV) -> dict\n\n"
    "The exact certificate of the map UV of the disk (V, F), with the keys of `pe check --json`: 'valid',\n"
    "'flipped', 'degenerate', 'faces', 'vertices', 'border_vertices', 'non_finite', 'border_simple',\n"
    "'overlapping_pairs', 'clockwise', 'min_signed_area', 'max_energy_3d', 'mean_energy_3d', 'immersion',\n"
    "and 'status', 'border_intersections', 'overlap_checked', 'max_signed_area', 'border_area',\n"
    "'high_energy_faces', 'has_3d_energy'. Every sign is decided exactly; 'valid' is True iff no face is\n"
    "flipped or degenerate, no coordinate is NaN, the border is simple and no two faces overlap;\n"
    "'immersion' is True iff the map is locally injective and every border fan turns by the border's angle\n"
    "alone (a border wrapping around a vertex is not taken: the C++ check_immersion() takes rotation indices).");
  m.def("untangle", &py_untangle, py::arg("V"), py::arg("F"), py::arg("UV"), py::arg("optimize") = true,
    py::arg("iterations") = 1000, py::arg("tolerance") = 1e-5,
    "untangle(V, F, UV, optimize=True, iterations=1000, tolerance=1e-5) -> UV\n\n"
    "Repairs the map UV by progressive embedding (Shen et al. 2019): its border (convex) is kept\n"
    "bit-exactly, its interior may be anything. The result is certified valid; then, unless\n"
    "optimize=False, its symmetric Dirichlet distortion is lowered by optimize() (border fixed), as\n"
    "`pe untangle` does. Raises Error if the map cannot be repaired (e.g. ERROR_NON_CONVEX_BORDER).");
  m.def("embed", &py_embed, py::arg("V"), py::arg("F"), py::arg("border") = "circle", py::arg("weights") = "uniform",
    py::arg("optimize") = true, py::arg("iterations") = 1000, py::arg("tolerance") = 1e-5,
    "embed(V, F, border='circle', weights='uniform', optimize=True, iterations=1000, tolerance=1e-5) -> UV\n\n"
    "A certified map of the disk (V, F), as `pe embed`: Tutte's map (border as in tutte()), repaired by\n"
    "progressive embedding only if it is invalid, then (unless optimize=False) optimized.");
  m.def("optimize", &py_optimize, py::arg("V"), py::arg("F"), py::arg("UV"), py::arg("fixed") = py::none(),
    py::arg("free_border") = false, py::arg("iterations") = 1000, py::arg("tolerance") = 1e-5,
    "optimize(V, F, UV, fixed=None, free_border=False, iterations=1000, tolerance=1e-5) -> UV\n\n"
    "Lowers the symmetric Dirichlet distortion of the valid map UV without ever leaving the valid maps\n"
    "(every step certified). The vertices of `fixed` (an integer array of vertex indices) and, unless\n"
    "free_border=True, the border vertices keep their uv bit-exactly. Stops when two consecutive\n"
    "iterations each gain less than `tolerance` (relative) or after `iterations` iterations (the map is\n"
    "then still valid and improved). Raises Error ERROR_INVALID_EMBEDDING if UV is not a valid map.");
  m.def("measure", &py_measure, py::arg("V"), py::arg("F"), py::arg("UV"),
    "measure(V, F, UV) -> dict\n\n"
    "The distortion of the map UV against the 3D triangles (scaled to the uv area): 'faces',\n"
    "'max_symmetric_dirichlet', 'mean_symmetric_dirichlet' (area-weighted; 4 for an isometry),\n"
    "'symmetric_dirichlet_median', '_p90', '_p99', 'max_conformal', 'mean_conformal', 'max_area',\n"
    "'mean_area', and 'max_energy_3d', 'mean_energy_3d' (the names `pe --json` gives the symmetric\n"
    "Dirichlet energy). Flipped or degenerate faces have infinite distortion.");
  m.def("constrain", &py_constrain, py::arg("V"), py::arg("F"), py::arg("UV") = py::none(),
    py::arg("border") = py::none(), py::arg("constraints") = py::none(), py::arg("weights") = "uniform",
    py::arg("optimize") = true,
    "constrain(V, F, UV=None, border=None, constraints=None, weights='uniform', optimize=True)\n"
    "    -> (V2, F2, UV2, info)\n\n"
    "A map with hard positional constraints (MatchMaker++): constraints=(idx, targets), idx an integer\n"
    "array of k interior vertices and targets a (k, 2) array; each vertex lands bit-exactly on its target.\n"
    "The border is the one of UV (its border rows; interior rows are ignored) or border='circle', 'square'\n"
    "or 'triangle' (exactly one of the two). The mesh is refined by Steiner vertices on its edges where\n"
    "needed, so new arrays are returned: V2, F2 (int64) and UV2 with the original vertices first, in their\n"
    "order. info holds the certificate (the keys of check()), 'steiner_vertices', 'paths', 'patches',\n"
    "'repaired_patches', 'optimized', 'optimization_status', 'immersion', 'constraint_error',\n"
    "'constraints_exact', and where each Steiner vertex lies on the input surface: 'steiner_indices' (rows\n"
    "of V2), 'steiner_corners' (s x 3 input vertex indices, -1 unused) and 'steiner_weights' (s x 3).");
  m.def("cross_parameterization", &py_cross, py::arg("V_a"), py::arg("F_a"), py::arg("V_b"), py::arg("F_b"),
    py::arg("landmarks") = py::none(), py::arg("border_vertex_pair") = py::none(), py::arg("b_to_a") = false,
    py::arg("time_limit") = py::none(), py::arg("optimization_time_limit") = 30.0, py::arg("composed") = true,
    py::arg("matched") = true, py::arg("compatible") = false, py::arg("planar_maps") = false,
    "cross_parameterization(V_a, F_a, V_b, F_b, landmarks=None, border_vertex_pair=None, b_to_a=False,\n"
    "                       time_limit=None, optimization_time_limit=30.0, composed=True, matched=True,\n"
    "                       compatible=False, planar_maps=False)\n"
    "    -> (faces, barycentric, info)\n\n"
    "A certified map between two disks A = (V_a, F_a) and B = (V_b, F_b) taking every landmark of A exactly\n"
    "onto its partner in B, as `pe cross`: both disks are mapped onto the unit square, B by the certified\n"
    "pipeline, then (matched=True, with interior landmarks) again with its landmarks pinned where that map\n"
    "put them, as A's is (info 'matched_b', 'matched_status', 'matched_more_distorted': kept only if its mean\n"
    "energy is at most 5% above the first map's or A's map's, 'vertices_added_b': B's map is then on a copy of\n"
    "B refined by that many vertices, the locations still in B's faces), A with its landmarks pinned at\n"
    "their partners' uv (constrained_embedding(), on a refined copy\n"
    "of A), then (composed=True) optimized for the distortion of the composed map A -> B (info 'composed_status',\n"
    "'composed_iterations', 'composed_energy', 'seconds_composed'); both maps are certified. landmarks: a (k, 2) integer array of (vertex of A, vertex of B) pairs,\n"
    "each vertex used once, both interior or both on their borders (border landmarks fix the border\n"
    "correspondence; None or empty: only the borders are matched). The borders are matched by relative 3D\n"
    "arc length between the border landmarks, from border_vertex_pair = (border vertex of A, border vertex of B);\n"
    "by default the first border landmark, or without one the first border vertex of A and the border vertex\n"
    "of B nearest to it in 3D (right for two meshes in one frame). Returns, per vertex of A, the row of F_b holding its image (faces, int64, (n_a,))\n"
    "and its barycentric coordinates in the order of that row's columns (barycentric, (n_a, 3) float64,\n"
    "computed exactly and rounded once: they sum to 1 up to one rounding, or to a few when B's map is on a\n"
    "refined copy, info 'vertices_added_b' > 0; a landmark gets exactly 1 at its partner). Two closed genus-0 meshes are first cut into disks (at\n"
    "least two landmarks): each along its shortest edge path between two landmarks near each other on A (the\n"
    "nearest pair that both meshes can join; their partners on B), the others staying inside the cut disks (where\n"
    "no pair does, e.g. every vertex a landmark, along a chain through all of them in their order); matched\n"
    "applies to B's cut disk; info 'closed', 'cut_landmarks', 'cut_edges_a', 'cut_edges_b',\n"
    "'chords_split_b'; vertex and face counts are\n"
    "then those of the cut disks; border_vertex_pair does not apply to them (no border): ERROR_WRONG_PARAMETER;\n"
    "planar_maps gives the maps of the cut disks, the rows of V first, then the copies of the vertices inside\n"
    "the cut, then (B) the midpoints of the split chords and the vertices added to the copies; compatible gives two closed meshes, the cut disks' overlay joined along the cut, certified closed\n"
    "with Euler characteristic 2, info 'cut_vertices_welded'). info: 'valid', 'valid_a', 'valid_b', 'landmarks_exact', 'landmarks', 'vertices_a',\n"
    "'faces_a', 'vertices_b', 'faces_b', 'vertices_added_a', 'in_face', 'on_edge', 'on_vertex' (where A's\n"
    "vertices landed, decided exactly), 'seconds_validation', 'seconds_map_b', 'seconds_map_a',\n"
    "'seconds_location', 'seconds_total', 'certificate_a' (of A's map, on its refined copy) and\n"
    "'certificate_b' (the keys of check()), 'map_b' (the pipeline's statistics) and 'map_a'. With\n"
    "b_to_a=True also the other direction, each vertex of B on A: 'b_to_a_faces' (rows of F_a, (n_b,)),\n"
    "'b_to_a_barycentric' ((n_b, 3), columns of F_a) and 'located_b_on_a'. With compatible=True the common\n"
    "refinement of the two maps, triangulated and certified in exact coordinates: one connectivity\n"
    "'compatible_F' ((f, 3) int64) for 'compatible_V_a' ((m, 3), on A's surface) and 'compatible_V_b' ((m, 3),\n"
    "on B's), so that (1 - t) * V_a' + t * V_b' is a morph; every vertex of A (of B) is a vertex of\n"
    "compatible_V_a (compatible_V_b), landmarks at the same row; 'valid_compatible', 'certificate_compatible',\n"
    "'overlay_cells', 'overlay_crossings', 'compatible_vertices', 'compatible_faces', 'seconds_compatible'.\n"
    "With planar_maps=True the two certified maps onto the unit square: 'planar_uv_a' ((n_a + vertices_added_a,\n"
    "2): the rows of V_a first, then the vertices added to A's copy) with its faces 'planar_F_a', and\n"
    "'planar_uv_b', 'planar_F_b' (B's map, on B or its refined copy: rows of V_b first); faces counterclockwise,\n"
    "a landmark of A at exactly the uv of its partner. time_limit: seconds in all (ERROR_BUDGET_EXHAUSTED\n"
    "when a certified map of A or B cannot be made within it; an optimization cut short keeps its certified\n"
    "map; the location and the compatible meshes run to their end, and for closed meshes the cut, so the\n"
    "call may end after it);\n"
    "optimization_time_limit: seconds for the optimization of A's map.\n"
    "Raises Error with ERROR_WRONG_PARAMETER for a landmark or border_vertex_pair index that is no vertex\n"
    "(as the C++ function, not ValueError) or a border_vertex_pair vertex off its border,\n"
    "ERROR_LANDMARK_ORDER for border landmarks not in the same order along both borders, ERROR_CONSTRAINT_ON_BORDER for a landmark\n"
    "with one vertex on its border and the other inside, ERROR_DUPLICATE_CONSTRAINT for a\n"
    "vertex used twice, ERROR_NOT_A_DISK, ERROR_BORDER_TOO_SHORT (fewer than 4 border vertices, or border\n"
    "landmarks that leave fewer than 3 places for the corners of the square after the first: a border\n"
    "landmark, or vertices inside an arc between two matched border vertices on both borders), ...; the\n"
    "message names the landmark (its row) or the mesh.");
  m.def("last_timing", &py_last_timing,
    "last_timing() -> dict\n\n"
    "Seconds spent in C++ by the last call of this thread: 'native_seconds' (everything done without the\n"
    "GIL: building the mesh, the algorithm, copying the result) and 'algorithm_seconds' (the package's\n"
    "functions alone). For benchmarks: the difference to the call's wall time is the Python overhead.");
}
