// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_OPTIMIZE_DISTORTION_H
#define CGAL_PROGRESSIVE_EMBEDDING_OPTIMIZE_DISTORTION_H

/// \file optimize_distortion.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/distortion.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/border_polygon.h>
#include <CGAL/Progressive_embedding/internal/certification_kernel.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Progressive_embedding/internal/local_smoothing.h>
#include <CGAL/Progressive_embedding/internal/symmetric_dirichlet.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Real_timer.h>

#include <CGAL/tags.h>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/blocked_range.h>
#endif

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SVD>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <type_traits>
#include <functional>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingEnums
/// The energy minimized by `optimize_distortion()`.
enum class Distortion_energy
{
  SYMMETRIC_DIRICHLET, ///< \f$\|J\|_F^2 + \|J^{-1}\|_F^2\f$, a barrier against degeneracy (SLIM proxy)
  ARAP                 ///< as-rigid-as-possible, \f$\|J - R\|_F^2\f$ with \f$R\f$ the closest rotation
};

/// \ingroup PkgProgressiveEmbeddingReports
/// What `optimize_distortion()` did, filled when a pointer to it is passed with the `statistics` named parameter.
struct Optimization_statistics
{
  /// iterations performed
  std::size_t iterations = 0;
  /// `true` if the relative energy decrease fell below the tolerance
  bool converged = false;
  /// area-weighted mean of the energy before (per unit reference area)
  double energy_before = 0;
  /// area-weighted mean of the energy after
  double energy_after = 0;
  /// seconds
  double seconds = 0;
  /// certificate of the output
  Embedding_report report;
};

namespace internal {

// Flip-free step bound: the smallest t in (0, 1] at which the signed area of a face with
// corners moving along d vanishes (a quadratic in t), times 0.8.
inline double max_flip_free_step(double x0, double y0, double x1, double y1, double x2, double y2,
                                 double dx0, double dy0, double dx1, double dy1, double dx2, double dy2)
{
  const double ex1 = x1 - x0, ey1 = y1 - y0, ex2 = x2 - x0, ey2 = y2 - y0;
  const double fx1 = dx1 - dx0, fy1 = dy1 - dy0, fx2 = dx2 - dx0, fy2 = dy2 - dy0;
  const double c = ex1 * ey2 - ey1 * ex2;
  const double b = ex1 * fy2 + fx1 * ey2 - ey1 * fx2 - fy1 * ex2;
  const double a = fx1 * fy2 - fy1 * fx2;
  double t = std::numeric_limits<double>::infinity();
  auto consider = [&](double r) { if(r > 0 && r < t) t = r; };
  if(std::abs(a) < 1e-300 * (std::abs(b) + std::abs(c)) || a == 0)
  { if(b != 0) consider(-c / b); }
  else
  {
    const double disc = b * b - 4 * a * c;
    if(disc >= 0)
    {
      const double sq = std::sqrt(disc);
      // numerically stable roots
      const double q = -0.5 * (b + (b >= 0 ? sq : -sq));
      if(q != 0) consider(c / q);
      consider(q / a);
    }
  }
  return t;
}

} // namespace internal

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// lowers the distortion of a valid planar map of a disk without ever leaving the set of valid maps:
/// every accepted step is certified (all faces positively oriented under the exact predicate and, with a
/// free border, the border polygon simple, also exactly). The minimized energy is the sum over faces of the
/// 3D area times the symmetric Dirichlet (or ARAP) energy against the 3D triangle, scaled so that the
/// total 3D area equals the area enclosed by the uv border. Iterations are SLIM-style local/global steps
/// (per-face SVD, then one sparse SPD solve: a sparse LDLT whose symbolic factorization is computed once, or, above
/// 50,000 free vertices, warm-started conjugate gradients, so that an iteration stays linear in the mesh size), followed by a
/// line search that starts below the first time any triangle would degenerate.
///
/// Vertices listed in `constrained_vertices` and, unless `free_border` is set, the border vertices keep their
/// uv coordinates bit-exactly. The input must be a valid map (`check_embedding()`), e.g. the output of
/// `progressive_embedding()`. The uv number type may be `double`, an exact rational or MPFR: directions are
/// computed in double and applied and certified in the uv number type.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`: with the latter (TBB linked, floating-point uv),
///         the per-vertex sweeps move the vertices of each colour of a greedy colouring in parallel
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexUVMap a model of `ReadWritePropertyMap` with `Point_2` values
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh, not modified
/// \param uvm the uv map, read and written (constrained vertices are not written)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the iteration budget; `ERROR_BUDGET_EXHAUSTED` (with a valid, improved map) when reached before convergence}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{200}
///   \cgalParamNEnd
///   \cgalParamNBegin{convergence_tolerance}
///     \cgalParamDescription{stop when an iteration lowers the energy by less than this fraction}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1e-4}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{time budget in seconds}
///     \cgalParamType{`double`}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{free_border}
///     \cgalParamDescription{let the border vertices move (the border stays a simple polygon)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{constrained_vertices}
///     \cgalParamDescription{vertices whose uv coordinates are hard constraints, kept bit-exactly}
///     \cgalParamType{a range of vertex descriptors, e.g. `std::vector<vertex_descriptor>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{distortion_energy}
///     \cgalParamDescription{the energy}
///     \cgalParamType{`Distortion_energy`}
///     \cgalParamDefault{`Distortion_energy::SYMMETRIC_DIRICHLET`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points}
///     \cgalParamType{a model of `ReadablePropertyMap` with `Point_3` values}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called after each iteration with the fraction of the iteration budget used; returning `false` stops (`ERROR_BUDGET_EXHAUSTED`)}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{verbose}
///     \cgalParamDescription{per-iteration energies on `std::cerr`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{optimization_statistics}
///     \cgalParamDescription{receives what the optimization did and the certificate}
///     \cgalParamType{`Optimization_statistics*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK` when converged; `ERROR_BUDGET_EXHAUSTED` when a budget ran out first (the map written is valid
///         and no worse than the input); `ERROR_INVALID_EMBEDDING` if the input map is not valid (nothing written);
///         the disk and parameter errors of `tutte_embedding()`.
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code optimize_distortion(const TriangleMesh& tm, VertexUVMap uvm,
                               const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh>                                GT;
  typedef typename GT::vertex_descriptor                                   vertex_descriptor;
  typedef typename internal::Uv_map_types<VertexUVMap>::Point_2           Point_2;
  typedef typename internal::Uv_map_types<VertexUVMap>::Traits            Traits;
  typedef typename internal::Uv_map_types<VertexUVMap>::FT                FT;
  typedef internal::Certification_kernel<FT>                              CK;

  CGAL::Real_timer timer;
  timer.start();
  Optimization_statistics local_stats;
  Optimization_statistics* stats_out =
    choose_parameter(get_parameter(np, internal_np::optimization_statistics), static_cast<Optimization_statistics*>(nullptr));
  Optimization_statistics& stats = stats_out ? *stats_out : local_stats;
  stats = Optimization_statistics();

  const std::size_t max_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), std::size_t(200));
  const double tolerance = choose_parameter(get_parameter(np, internal_np::convergence_tolerance), 1e-4);
  const double time_budget = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), std::numeric_limits<double>::infinity());
  const bool free_border = choose_parameter(get_parameter(np, internal_np::free_border), false);
  const Distortion_energy energy_type = choose_parameter(get_parameter(np, internal_np::distortion_energy), Distortion_energy::SYMMETRIC_DIRICHLET);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const std::function<bool(double)> callback = choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  if(!(tolerance >= 0)) return ERROR_WRONG_PARAMETER;

  internal::Indexed_disk<TriangleMesh> disk;
  Error_code ec = internal::make_indexed_disk(tm, GT::null_halfedge(), disk);
  if(ec != OK) return ec;
  const std::size_t nv = disk.number_of_vertices(), nf = disk.number_of_faces();

  // the input must be valid: the optimization never leaves the valid set
  const Embedding_report input_report = check_embedding(tm, uvm, CGAL::parameters::vertex_point_map(vpm));
  if(!input_report.is_valid()) { stats.report = input_report; return ERROR_INVALID_EMBEDDING; }
  const double sgn = input_report.clockwise ? -1. : 1.;          // work on the counterclockwise mirror image
  typename Traits::Exact_orientation_2 orient = Traits().exact_orientation_2_object();
  const CGAL::Orientation positive = input_report.clockwise ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN;

  // which vertices move
  std::vector<char> fixed(nv, 0);
  for(std::size_t i = 0; i < nv; ++i) if(disk.on_border[i] && !free_border) fixed[i] = 1;
  {
    std::vector<vertex_descriptor> constrained =
      choose_parameter(get_parameter(np, internal_np::constrained_vertices), std::vector<vertex_descriptor>());
    if(!constrained.empty())
    {
      auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
      for(std::size_t i = 0; i < nv; ++i) put(vid, disk.vertices[i], i);
      for(const vertex_descriptor& v : constrained) fixed[get(vid, v)] = 1;
    }
  }
  std::vector<long> var(nv, -1);
  long nfree = 0;
  for(std::size_t i = 0; i < nv; ++i) if(!fixed[i]) var[i] = nfree++;

  std::vector<Point_2> P(nv);
  for(std::size_t i = 0; i < nv; ++i) P[i] = get(uvm, disk.vertices[i]);
  std::vector<double> X(nv), Y(nv);
  auto refresh_doubles = [&]() {
    for(std::size_t i = 0; i < nv; ++i) { X[i] = CGAL::to_double(P[i].x()); Y[i] = sgn * CGAL::to_double(P[i].y()); }
  };
  refresh_doubles();

  // per-face reference frames: 3D triangles scaled to the border area; G = C R^-1 maps corner values to the gradient
  double total3d = 0;
  std::vector<std::array<double, 6> > G(nf); // row-major 3x2
  std::vector<double> W(nf);
  {
    std::vector<std::array<double, 4> > R(nf); // 2x2 reference edge matrices (columns r1, r2), unscaled
    for(std::size_t f = 0; f < nf; ++f)
    {
      const auto& t = disk.faces[f];
      const auto& a = get(vpm, disk.vertices[t[0]]);
      const auto& b = get(vpm, disk.vertices[t[1]]);
      const auto& c = get(vpm, disk.vertices[t[2]]);
      const double abx = CGAL::to_double(b.x() - a.x()), aby = CGAL::to_double(b.y() - a.y()), abz = CGAL::to_double(b.z() - a.z());
      const double acx = CGAL::to_double(c.x() - a.x()), acy = CGAL::to_double(c.y() - a.y()), acz = CGAL::to_double(c.z() - a.z());
      const double lab = std::sqrt(abx * abx + aby * aby + abz * abz);
      const double cx = aby * acz - abz * acy, cy = abz * acx - abx * acz, cz = abx * acy - aby * acx;
      const double cr = std::sqrt(cx * cx + cy * cy + cz * cz);
      W[f] = cr / 2;
      total3d += W[f];
      if(!(lab > 0) || !(cr > 0)) { R[f] = {{0, 0, 0, 0}}; continue; }
      R[f] = {{ lab, 0, (abx * acx + aby * acy + abz * acz) / lab, cr / lab }}; // r1 = (lab, 0), r2 = (..)
    }
    if(!(total3d > 0)) return ERROR_WRONG_PARAMETER; // no 3D geometry to measure against
    const double k = std::sqrt(input_report.border_area / total3d); // length scale
    for(std::size_t f = 0; f < nf; ++f)
    {
      W[f] *= k * k;
      const double r11 = R[f][0] * k, r21 = R[f][1] * k, r12 = R[f][2] * k, r22 = R[f][3] * k;
      const double det = r11 * r22 - r12 * r21;
      if(!(std::abs(det) > 0)) { G[f] = {{0, 0, 0, 0, 0, 0}}; W[f] = 0; continue; }
      // Rinv = [r22 -r12; -r21 r11] / det ; C = [-1 -1; 1 0; 0 1]
      const double i11 = r22 / det, i12 = -r12 / det, i21 = -r21 / det, i22 = r11 / det;
      G[f] = {{ -i11 - i21, -i12 - i22, i11, i12, i21, i22 }};
    }
  }

  // per-face references (corner dot products, squared area) for the per-vertex Newton sweeps,
  // and the faces around each vertex
  std::vector<internal::Reference_triangle<double> > refs(nf);
  std::vector<std::vector<std::pair<std::size_t, int> > > star(nv); // (face, corner)
  {
    const double k2 = input_report.border_area / total3d;
    for(std::size_t f = 0; f < nf; ++f)
    {
      const auto& t = disk.faces[f];
      std::array<std::array<double, 3>, 3> Q;
      for(int c = 0; c < 3; ++c)
      {
        const auto& q = get(vpm, disk.vertices[t[c]]);
        Q[c] = {{ CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()) }};
      }
      refs[f] = internal::reference_from_points<double, 3>(Q[0], Q[1], Q[2]);
      for(double& d : refs[f].dot) d *= k2;
      refs[f].area2 *= k2 * k2;
      for(int c = 0; c < 3; ++c) star[t[c]].push_back(std::make_pair(f, c));
    }
  }

  auto jacobian = [&](std::size_t f, const std::vector<double>& x, const std::vector<double>& y, Eigen::Matrix2d& J) {
    const auto& t = disk.faces[f];
    const auto& g = G[f];
    J(0, 0) = g[0] * x[t[0]] + g[2] * x[t[1]] + g[4] * x[t[2]];
    J(0, 1) = g[1] * x[t[0]] + g[3] * x[t[1]] + g[5] * x[t[2]];
    J(1, 0) = g[0] * y[t[0]] + g[2] * y[t[1]] + g[4] * y[t[2]];
    J(1, 1) = g[1] * y[t[0]] + g[3] * y[t[1]] + g[5] * y[t[2]];
  };
  const double total_w = std::accumulate(W.begin(), W.end(), 0.);
  auto energy = [&](const std::vector<double>& x, const std::vector<double>& y) {
    double e = 0;
    Eigen::Matrix2d J;
    for(std::size_t f = 0; f < nf; ++f)
    {
      if(W[f] == 0) continue;
      jacobian(f, x, y, J);
      const double det = J.determinant();
      if(!(det > 0)) return std::numeric_limits<double>::infinity();
      if(energy_type == Distortion_energy::SYMMETRIC_DIRICHLET)
        e += W[f] * J.squaredNorm() * (1 + 1 / (det * det));
      else
      {
        Eigen::JacobiSVD<Eigen::Matrix2d> svd(J);
        const Eigen::Vector2d s = svd.singularValues();
        e += W[f] * ((s(0) - 1) * (s(0) - 1) + (s(1) - 1) * (s(1) - 1));
      }
    }
    return e / total_w;
  };

  // One sweep of per-vertex Newton steps on the symmetric Dirichlet energy of each vertex's
  // star: robust where the global step is not (faces 1e-20 times smaller than others), and
  // certified like the global step (exact orientation of the star in the uv number type).
  // One Newton step on the symmetric Dirichlet energy of the star of vertex i: robust where the
  // global step is not (faces 1e-20 times smaller than others), and certified like the global
  // step (exact orientation of the star in the uv number type). Returns true if i moved.
  auto move_vertex = [&](std::size_t i) -> bool {
    double g[2] = {0, 0}, H[3] = {0, 0, 0}, E0 = 0;
    bool ok = true;
    auto corner_ref = [&](std::size_t f, int c) {
      internal::Reference_triangle<double> r = refs[f];
      r.dot = {{ refs[f].dot[c], refs[f].dot[(c + 1) % 3], refs[f].dot[(c + 2) % 3] }};
      return r;
    };
    for(const auto& fc : star[i])
    {
      if(W[fc.first] == 0) continue;
      const auto& t = disk.faces[fc.first];
      const std::size_t a = t[(fc.second + 1) % 3], b = t[(fc.second + 2) % 3];
      double Ef; std::array<double, 2> gf; std::array<double, 3> Hf;
      if(!internal::symmetric_dirichlet_local(corner_ref(fc.first, fc.second), X[i], Y[i], X[a], Y[a], X[b], Y[b], Ef, gf, Hf))
      { ok = false; break; }
      E0 += Ef * W[fc.first]; g[0] += gf[0] * W[fc.first]; g[1] += gf[1] * W[fc.first];
      H[0] += Hf[0] * W[fc.first]; H[1] += Hf[1] * W[fc.first]; H[2] += Hf[2] * W[fc.first];
    }
    double d[2];
    if(!ok || !internal::projected_newton_direction(g, H, d)) return false;
    double tmax = 1.0;
    for(const auto& fc : star[i])
    {
      const auto& t = disk.faces[fc.first];
      const std::size_t a = t[(fc.second + 1) % 3], b = t[(fc.second + 2) % 3];
      const double A0 = (X[a] - X[i]) * (Y[b] - Y[i]) - (Y[a] - Y[i]) * (X[b] - X[i]);
      const double dA = d[0] * (Y[a] - Y[b]) + d[1] * (X[b] - X[a]);
      if(dA < 0 && A0 > 0) tmax = (std::min)(tmax, 0.8 * (A0 / -dA));
    }
    for(double t = tmax; t > 1e-10 * tmax; t *= 0.5)
    {
      const double xi = X[i] + t * d[0], yi = Y[i] + t * d[1];
      double En = 0;
      bool valid = true;
      for(const auto& fc : star[i])
      {
        if(W[fc.first] == 0) continue;
        const auto& tr = disk.faces[fc.first];
        const std::size_t a = tr[(fc.second + 1) % 3], b = tr[(fc.second + 2) % 3];
        bool okf;
        const double e = internal::symmetric_dirichlet(corner_ref(fc.first, fc.second), xi, yi, X[a], Y[a], X[b], Y[b], okf);
        if(!okf || !(e >= 0)) { valid = false; break; }
        En += e * W[fc.first];
      }
      if(!valid || !(En < E0)) continue;
      const Point_2 old = P[i];
      P[i] = Point_2(old.x() + internal::make_ft<FT>(t * d[0]), old.y() + internal::make_ft<FT>(sgn * t * d[1]));
      for(const auto& fc : star[i])
      {
        const auto& tr = disk.faces[fc.first];
        if(orient(P[tr[0]], P[tr[1]], P[tr[2]]) != positive) { valid = false; break; }
      }
      if(!valid) { P[i] = old; continue; }
      X[i] = CGAL::to_double(P[i].x()); Y[i] = sgn * CGAL::to_double(P[i].y());
      return true;
    }
    return false;
  };
  // Sweeps over all free vertices. With Parallel_tag (and TBB, and a floating-point uv number type,
  // whose values are not shared handles), the vertices of one colour of a greedy colouring move in
  // parallel: two vertices of one colour share no face, so their steps are independent.
  std::vector<std::vector<std::size_t> > colour_classes;
  {
    std::vector<int> colour(nv, -1);
    for(std::size_t i = 0; i < nv; ++i)
    {
      if(var[i] < 0) continue;
      std::vector<char> used;
      for(const auto& fc : star[i])
        for(std::size_t j : disk.faces[fc.first])
          if(j != i && colour[j] >= 0)
          {
            if(used.size() <= std::size_t(colour[j])) used.resize(colour[j] + 1, 0);
            used[colour[j]] = 1;
          }
      int c = 0;
      while(c < int(used.size()) && used[c]) ++c;
      colour[i] = c;
      if(colour_classes.size() <= std::size_t(c)) colour_classes.resize(c + 1);
      colour_classes[c].push_back(i);
    }
  }
  auto local_sweep = [&]() {
    std::size_t moved = 0;
#ifdef CGAL_LINKED_WITH_TBB
    if(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value && std::is_floating_point<FT>::value)
    {
      for(const std::vector<std::size_t>& cls : colour_classes)
      {
        std::atomic<std::size_t> count(0);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cls.size(), 64), [&](const tbb::blocked_range<std::size_t>& range) {
          for(std::size_t k = range.begin(); k != range.end(); ++k)
            if(move_vertex(cls[k])) ++count;
        });
        moved += count;
      }
      return moved;
    }
#endif
    for(const std::vector<std::size_t>& cls : colour_classes)
      for(std::size_t i : cls)
        if(move_vertex(i)) ++moved;
    return moved;
  };

  // sparsity pattern: one 2x2 block per pair of free vertices sharing a face
  typedef Eigen::SparseMatrix<double> SpMat;
  const long n2 = 2 * nfree;
  Eigen::SimplicialLDLT<SpMat> solver;
  bool analyzed = false;
  const long direct_solver_limit = 100000; // unknowns (2 per free vertex)
  Eigen::ConjugateGradient<SpMat, Eigen::Lower | Eigen::Upper, Eigen::DiagonalPreconditioner<double> > iterative;
  double E = energy(X, Y);
  stats.energy_before = E;
  if(verbose) std::cerr << "[optimize] energy " << E << ", " << nfree << " free vertices\n";

  Error_code result = ERROR_BUDGET_EXHAUSTED;
  std::vector<double> nx(nv), ny(nv);
  if(nfree == 0) result = OK;
  for(std::size_t it = 0; it < max_iterations && nfree > 0; ++it)
  {
    if(timer.time() > time_budget) break;
    // local step: per-face rotation and (SLIM) weights
    std::vector<Eigen::Triplet<double> > trip;
    trip.reserve(nf * 36);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n2);
    Eigen::Matrix2d J;
    for(std::size_t f = 0; f < nf; ++f)
    {
      if(W[f] == 0) continue;
      jacobian(f, X, Y, J);
      Eigen::JacobiSVD<Eigen::Matrix2d> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
      Eigen::Matrix2d U = svd.matrixU(), V = svd.matrixV();
      Eigen::Vector2d s = svd.singularValues();
      if(U.determinant() * V.determinant() < 0) { U.col(1) *= -1; s(1) = -s(1); }
      const Eigen::Matrix2d Rot = U * V.transpose();
      Eigen::Vector2d w2;
      for(int k = 0; k < 2; ++k)
      {
        if(energy_type == Distortion_energy::ARAP) { w2(k) = 1; continue; }
        const double sk = (std::max)(s(k), 1e-12);
        w2(k) = (std::abs(sk - 1) < 1e-8) ? 4. : (sk - 1 / (sk * sk * sk)) / (sk - 1);
        if(!std::isfinite(w2(k)) || w2(k) <= 0) w2(k) = 1;
        w2(k) = (std::min)(w2(k), 1e12);
      }
      const Eigen::Matrix2d S = U * w2.asDiagonal() * U.transpose(); // W^T W
      const auto& t = disk.faces[f];
      const auto& g = G[f];
      // Q = G G^T (3x3); per face: W_f * [S11 Q, S12 Q; S21 Q, S22 Q] in (u, v) blocks
      double Qm[3][3];
      for(int a = 0; a < 3; ++a) for(int b = 0; b < 3; ++b) Qm[a][b] = g[2 * a] * g[2 * b] + g[2 * a + 1] * g[2 * b + 1];
      // rhs: W_f * sum_j [B_j^T 0; 0 B_j^T] S r_j, r_j = column j of Rot
      for(int a = 0; a < 3; ++a)
      {
        const std::size_t ia = t[a];
        double ru = 0, rv = 0;
        for(int j = 0; j < 2; ++j)
        {
          const Eigen::Vector2d Sr = S * Rot.col(j);
          ru += g[2 * a + j] * Sr(0);
          rv += g[2 * a + j] * Sr(1);
        }
        ru *= W[f]; rv *= W[f];
        if(var[ia] >= 0) { rhs(2 * var[ia]) += ru; rhs(2 * var[ia] + 1) += rv; }
        for(int b = 0; b < 3; ++b)
        {
          const std::size_t ib = t[b];
          const double q = W[f] * Qm[a][b];
          const double huu = S(0, 0) * q, huv = S(0, 1) * q, hvu = S(1, 0) * q, hvv = S(1, 1) * q;
          if(var[ia] < 0) continue;
          if(var[ib] >= 0)
          {
            trip.emplace_back(2 * var[ia], 2 * var[ib], huu);
            trip.emplace_back(2 * var[ia], 2 * var[ib] + 1, huv);
            trip.emplace_back(2 * var[ia] + 1, 2 * var[ib], hvu);
            trip.emplace_back(2 * var[ia] + 1, 2 * var[ib] + 1, hvv);
          }
          else
          {
            // fixed neighbour: move its contribution to the right-hand side
            rhs(2 * var[ia]) -= huu * X[ib] + huv * Y[ib];
            rhs(2 * var[ia] + 1) -= hvu * X[ib] + hvv * Y[ib];
          }
        }
      }
    }
    SpMat H(n2, n2);
    H.setFromTriplets(trip.begin(), trip.end());
    // a small proximal term keeps the system definite (free border: translations and rotations)
    const double lambda = 1e-9 * H.diagonal().cwiseAbs().maxCoeff() + 1e-300;
    for(long i = 0; i < nfree * 2; ++i)
    {
      H.coeffRef(i, i) += lambda;
    }
    for(std::size_t i = 0; i < nv; ++i)
      if(var[i] >= 0) { rhs(2 * var[i]) += lambda * X[i]; rhs(2 * var[i] + 1) += lambda * Y[i]; }
    Eigen::VectorXd sol;
    if(n2 <= direct_solver_limit)
    {
      if(!analyzed) { solver.analyzePattern(H); analyzed = true; } // the pattern never changes
      solver.factorize(H);
      if(solver.info() != Eigen::Success) { result = ERROR_CANNOT_SOLVE_LINEAR_SYSTEM; break; }
      sol = solver.solve(rhs);
      if(solver.info() != Eigen::Success || !sol.allFinite()) { result = ERROR_CANNOT_SOLVE_LINEAR_SYSTEM; break; }
    }
    else
    {
      // Large meshes: a sparse factorization of a 2D mesh costs O(n^1.5); conjugate gradients,
      // warm-started at the current positions with a bounded iteration count, keep an iteration
      // linear in the mesh size. The direction needs no more accuracy: the line search decides.
      Eigen::VectorXd x0(n2);
      for(std::size_t i = 0; i < nv; ++i) if(var[i] >= 0) { x0(2 * var[i]) = X[i]; x0(2 * var[i] + 1) = Y[i]; }
      iterative.setMaxIterations(200);
      iterative.setTolerance(1e-8);
      iterative.compute(H);
      sol = iterative.solveWithGuess(rhs, x0);
      if(!sol.allFinite()) { result = ERROR_CANNOT_SOLVE_LINEAR_SYSTEM; break; }
    }

    // direction and flip-free bound
    std::vector<double> dx(nv, 0.), dy(nv, 0.);
    for(std::size_t i = 0; i < nv; ++i)
      if(var[i] >= 0) { dx[i] = sol(2 * var[i]) - X[i]; dy[i] = sol(2 * var[i] + 1) - Y[i]; }
    double tmax = 1.0;
    for(std::size_t f = 0; f < nf; ++f)
    {
      const auto& t = disk.faces[f];
      const double r = internal::max_flip_free_step(X[t[0]], Y[t[0]], X[t[1]], Y[t[1]], X[t[2]], Y[t[2]],
                                                    dx[t[0]], dy[t[0]], dx[t[1]], dy[t[1]], dx[t[2]], dy[t[2]]);
      tmax = (std::min)(tmax, 0.8 * r);
    }
    // backtracking: energy decrease, then exact certification of the candidate in FT
    bool accepted = false;
    double Enew = E;
    std::vector<Point_2> Pn(P);
    for(double t = tmax; t > 1e-12 && !accepted; t *= 0.5)
    {
      for(std::size_t i = 0; i < nv; ++i) { nx[i] = X[i] + t * dx[i]; ny[i] = Y[i] + t * dy[i]; }
      Enew = energy(nx, ny);
      if(!(Enew < E)) continue;
      for(std::size_t i = 0; i < nv; ++i)
        if(var[i] >= 0)
          Pn[i] = Point_2(P[i].x() + internal::make_ft<FT>(t * dx[i]), P[i].y() + internal::make_ft<FT>(sgn * t * dy[i]));
      bool ok = true;
      for(std::size_t f = 0; f < nf && ok; ++f)
      {
        const auto& tr = disk.faces[f];
        if(var[tr[0]] < 0 && var[tr[1]] < 0 && var[tr[2]] < 0) continue;
        if(orient(Pn[tr[0]], Pn[tr[1]], Pn[tr[2]]) != positive) ok = false;
      }
      if(ok && free_border)
      {
        std::vector<typename CK::Kernel::Point_2> B;
        B.reserve(disk.border.size());
        for(std::size_t b : disk.border) B.push_back(CK::convert(Pn[b]));
        ok = (internal::count_border_intersections<typename CK::Kernel>(B, 1) == 0);
      }
      accepted = ok;
    }
    double decrease = 0;
    if(accepted)
    {
      P.swap(Pn);
      refresh_doubles();
      const double E1 = energy(X, Y);
      decrease = (E - E1) / E;
      E = E1;
    }
    if(!accepted || decrease < tolerance)
    {
      // the global step stalls: sweep vertex by vertex
      const double E0 = E;
      const std::size_t moved = local_sweep();
      E = energy(X, Y);
      const double local_decrease = (E0 - E) / E0;
      if(verbose) std::cerr << "[optimize] local sweep: " << moved << " vertices moved, energy " << E << "\n";
      decrease = (std::max)(decrease, local_decrease);
    }
    ++stats.iterations;
    if(verbose) std::cerr << "[optimize] iteration " << stats.iterations << ": energy " << E << "\n";
    if(callback && !callback(double(stats.iterations) / double(max_iterations))) break;
    if(!(decrease >= tolerance)) { result = OK; stats.converged = true; break; }
  }

  // write the free vertices; certify what was written
  for(std::size_t i = 0; i < nv; ++i)
    if(var[i] >= 0) put(uvm, disk.vertices[i], P[i]);
  stats.energy_after = E;
  stats.report = check_embedding(tm, uvm, CGAL::parameters::vertex_point_map(vpm));
  stats.seconds = timer.time();
  if(!stats.report.is_valid()) return ERROR_INVALID_EMBEDDING; // cannot happen: every step was certified
  return result;
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_OPTIMIZE_DISTORTION_H
