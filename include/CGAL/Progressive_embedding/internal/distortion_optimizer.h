// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_DISTORTION_OPTIMIZER_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_DISTORTION_OPTIMIZER_H

// The engine of optimize_distortion(), as named steps:
//   initialize()        reference frames, fixed vertices, stars, colouring
//   global_step()       projected Newton: per-face Hessians projected to SPD with the analytic
//                       eigensystem of isotropic energies, one sparse solve
//   line_search()       flip-free bound, then backtracking; every candidate certified exactly
//   border barrier      free border of a disk: a term of the energy that grows without bound as a
//                       border vertex nears a border edge, and a bound of the step at the first
//                       contact, so that the line search sees the border closing before the exact
//                       test refuses it (see border_barrier_terms() in internal/newton_step.h)
//   vertex_sweep()      per-vertex projected Newton steps (border phase checked for simplicity)
// Multiply connected maps (several border loops, see internal/holes_domain.h): the
// outer loop is the border (fixed unless free_border), the hole vertices are free. A step that
// keeps every face positive could still make a hole loop self-intersect, touch another loop, or
// turn a hole inside out (its faces then cover a region twice around a vertex of angle 4 pi), so
// every candidate of the global line search is checked exactly for loop intersections (all
// loops, O(n log n)) and hole orientations, and each hole vertex moves alone in the sweeps with
// its two loop edges checked against every loop edge and its loop's orientation checked.
// Positive faces, simple and pairwise disjoint loops and clockwise holes (in the counterclockwise
// frame) make the map valid: the turning numbers of the loops sum to 2 - k + (the branching of
// interior vertices), which forces the branching to 0, and the degree of the map is then 1 in the
// domain and 0 in the holes; the final certificate checks all of it again.
//   certify()/write()   exact certificate of the result, written only if valid
// Directions are computed in double; positions are stored and certified in the uv number type.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Optimization_statistics.h>
#include <CGAL/Progressive_embedding/internal/check_embedding_impl.h>
#include <CGAL/Progressive_embedding/internal/check_immersion_impl.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/border_polygon.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Progressive_embedding/internal/newton_step.h>
#include <CGAL/Progressive_embedding/internal/holes_domain.h>
#include <CGAL/Progressive_embedding/internal/symmetric_dirichlet.h>
#include <CGAL/Progressive_embedding/internal/block_cg.h>
#include <CGAL/Progressive_embedding/internal/rotation_svd_2x2.h>
#include <CGAL/Progressive_embedding/internal/scaling.h>

#include <CGAL/Real_timer.h>
#include <CGAL/tags.h>
#include <CGAL/Dynamic_property_map.h>
#include <boost/property_map/function_property_map.hpp>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#include <tbb/blocked_range.h>
#endif

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// SVD-based quantities of one face's Jacobian for an isotropic energy psi(s1, s2):
// psi, its gradient (psi1, psi2) and the eigenvalues of its Hessian in F (scaling, twist, flip),
// clamped at zero (projected Newton).
struct Isotropic_terms
{
  double psi, d1, d2, scale1, scale2, twist, flip;
};

inline bool isotropic_terms(Distortion_energy e, double s1, double s2, Isotropic_terms& r)
{
  if(!(s1 > 0) || !(s2 > 0)) return false;
  if(e == Distortion_energy::SYMMETRIC_DIRICHLET)
  {
    const double i1 = 1 / s1, i2 = 1 / s2;
    const double i13 = i1 * i1 * i1, i23 = i2 * i2 * i2;
    r.psi = s1 * s1 + s2 * s2 + i1 * i1 + i2 * i2;
    r.d1 = 2 * s1 - 2 * i13;
    r.d2 = 2 * s2 - 2 * i23;
    r.scale1 = 2 + 6 * i1 * i1 * i1 * i1;
    r.scale2 = 2 + 6 * i2 * i2 * i2 * i2;
    // (psi1 + psi2) / (s1 + s2) and (psi1 - psi2) / (s1 - s2) in closed forms, stable for s1 ~ s2
    const double q = (s1 * s1 + s2 * s2) * i13 * i23;
    const double m = s1 * s2 * i13 * i23;
    r.twist = 2 - 2 * (q - m);
    r.flip = 2 + 2 * (q + m);
  }
  else
  {
    r.psi = (s1 - 1) * (s1 - 1) + (s2 - 1) * (s2 - 1);
    r.d1 = 2 * (s1 - 1);
    r.d2 = 2 * (s2 - 1);
    r.scale1 = r.scale2 = 2;
    r.twist = 2 - 4 / (s1 + s2);
    r.flip = 2;
  }
  r.twist = (std::max)(r.twist, 0.);
  return std::isfinite(r.psi) && std::isfinite(r.d1) && std::isfinite(r.d2) && std::isfinite(r.twist) && std::isfinite(r.flip);
}

// The 3D reference of each face as a 2x2 edge frame, scaled by k (on lengths): the one place where
// the optimizer's reference triangles are built (from reference_from_points).
struct Face_frame
{
  std::array<double, 6> G;           // gradient operator: J(r, c) = sum_a G[2a + c] * uv_r(a)
  Reference_triangle<double> ref;    // corner dot products and squared area (per-vertex steps)
  double weight = 0;                 // scaled 3D area (the weight of the face's energy)
};

inline Face_frame face_frame(const Reference_triangle<double>& ref)
{
  Face_frame fr;
  fr.ref = ref;
  const double area = std::sqrt(ref.area2);
  fr.weight = area;
  const double l2 = ref.dot[0] + ref.dot[1]; // |ab|^2
  const double lab = std::sqrt(l2);
  const double r11 = lab, r21 = 0, r12 = ref.dot[0] / lab, r22 = 2 * area / lab;
  const double det = r11 * r22 - r12 * r21;
  const double i11 = r22 / det, i12 = -r12 / det, i21 = -r21 / det, i22 = r11 / det;
  fr.G = {{ -i11 - i21, -i12 - i22, i11, i12, i21, i22 }};
  return fr;
}

// The reference of the 3D triangle (q0, q1, q2), its area2 set to 0 where it has no positive finite area (see
// scale_references())
inline Reference_triangle<double> reference_3d(const std::array<std::array<double, 3>, 3>& q)
{
  Reference_triangle<double> r = reference_from_points<double, 3>(q[0], q[1], q[2]);
  if(!(r.area2 > 0 && std::isfinite(r.area2) && r.dot[0] + r.dot[1] > 0)) r.area2 = 0;
  return r;
}

// The references of 3D triangles scaled (k2 on squared lengths) so that their total area is `target_area`: the
// optimizer measures a map against them, and the composed distortion measures B's map the same way
// (internal/cross/composed_distortion.h). In: `refs` from reference_3d(); those without an area get an equilateral
// reference of the mean area of the others. Nothing is changed when no triangle has an area
// (ERROR_DEGENERATE_3D_FACE) or the scale is not positive and finite (ERROR_DEGENERATE_BORDER).
inline Error_code scale_references(std::vector<Reference_triangle<double> >& refs, double target_area, double& k2)
{
  double total = 0;
  std::size_t good = 0;
  for(const Reference_triangle<double>& r : refs)
    if(r.area2 > 0) { total += std::sqrt(r.area2); ++good; }
  if(good == 0 || !(total > 0) || !std::isfinite(total)) return ERROR_DEGENERATE_3D_FACE;
  k2 = target_area / total;
  if(!(k2 > 0) || !std::isfinite(k2)) return ERROR_DEGENERATE_BORDER;
  const Reference_triangle<double> fallback = equilateral_reference(total / double(good), std::sqrt(3.));
  for(Reference_triangle<double>& r : refs)
  {
    if(!(r.area2 > 0)) r = fallback;
    for(double& d : r.dot) d *= k2;
    r.area2 *= k2 * k2;
  }
  return OK;
}

template <class TriangleMesh, class VertexUVMap, class VertexPointMap, class ConcurrencyTag,
          class Traits_ = typename Uv_map_types<VertexUVMap>::Traits>
class Distortion_optimizer
{
public:
  typedef boost::graph_traits<TriangleMesh>                          GT;
  typedef typename GT::vertex_descriptor                             vertex_descriptor;
  typedef typename Uv_map_types<VertexUVMap>::Point_2                Point_2;
  typedef Traits_                                                    Traits;
  typedef typename Uv_map_types<VertexUVMap>::FT                     FT;
  typedef Eigen::SparseMatrix<double>                                SpMat;

  struct Settings
  {
    std::size_t max_iterations = 1000;
    double tolerance = 1e-5;
    double time_budget = std::numeric_limits<double>::infinity();
    bool free_border = false;
    Distortion_energy energy = Distortion_energy::SYMMETRIC_DIRICHLET;
    bool verbose = false;
    std::function<bool(double)> callback;
    // reuse the last factorization of the Hessian while its steps gain enough (see run())
    bool reuse_factorization = true;
    // Optional: a 2x2 matrix per face (indexed as the disk's faces) applied on the left of the face's Jacobian,
    // computed from the positions (x, y) every time the energy or its derivatives are: the distortion is then that
    // of M J, e.g. of the map composed with the inverse of another map (M the inverse Jacobian of the other map where
    // the face lies). Its derivatives with respect to the positions are taken as zero (M piecewise constant);
    // the line search still compares true energies. Counterclockwise maps only; no per-vertex sweeps.
    std::function<void(const std::vector<double>&, const std::vector<double>&, std::vector<Eigen::Matrix2d>&)> face_metric;
  };

  Distortion_optimizer(const TriangleMesh& tm, VertexUVMap uvm, VertexPointMap vpm, const Settings& s,
                       const Traits& traits = Traits())
    : tm_(tm), uvm_(uvm), vpm_(vpm), s_(s), traits_(traits), orient_(traits.exact_orientation_2_object()),
      disk_(domain_.disk) {}

  // ---- set-up ------------------------------------------------------------------------------
  // `given`: the disk already indexed from the mesh (a pipeline indexes once), or null
  Error_code initialize(const std::vector<vertex_descriptor>& constrained, Optimization_statistics& stats,
                        const Indexed_disk<TriangleMesh>* given = nullptr)
  {
    if(!(s_.tolerance >= 0) || !(s_.time_budget >= 0)) return ERROR_WRONG_PARAMETER;
    if(s_.face_metric && s_.free_border) return ERROR_WRONG_PARAMETER;
    Error_code ec = OK;
    if(given) disk_ = *given;
    else ec = make_indexed_disk(tm_, GT::null_halfedge(), disk_);
    if(ec == ERROR_NOT_A_DISK)
    {
      // several border loops: a multiply connected domain (genus 0 and connected, or refused)
      const Error_code ed = make_indexed_domain(tm_, domain_);
      if(domain_.number_of_loops() < 2) return ec;
      if(ed != OK) return ed;
      holes_ = true;
      ec = OK;
    }
    if(ec != OK) return ec;
    nv_ = disk_.number_of_vertices(); nf_ = disk_.number_of_faces();

    // the input must be valid: the optimization never leaves the valid set
    stats.report = check_embedding_impl(tm_, uvm_, parameters::multiply_connected(holes_,
                                                CGAL::parameters::vertex_point_map(vpm_).geom_traits(traits_)),
                                        holes_ ? nullptr : &disk_);
    if(stats.report.status != OK) return stats.report.status;
    if(stats.report.non_finite > 0) return ERROR_NON_FINITE_COORDINATES;
    if(!stats.report.is_valid())
    {
      // A disk map whose faces are all positive but whose border overlaps itself may be an immersion
      // (a weakly self-overlapping border): with the border fixed, steps that keep every face positive
      // keep each one-ring's winding number (it varies continuously and is an integer), so the
      // optimization stays among immersions; check_immersion() certifies the input and the output.
      // The full turns of each border fan are kept too (same argument): the input's are measured here
      // and the output must make the same ones.
      if(holes_ || stats.report.border_simple || stats.report.flipped != 0 || stats.report.degenerate != 0)
        return ERROR_INVALID_EMBEDDING;
      check_immersion_of_disk(disk_, uvm_, orient_, std::vector<int>(), &border_turns_);
      stats.immersion_report = check_immersion_of_disk(disk_, uvm_, orient_, border_turns_);
      if(!stats.immersion_report.is_immersion()) return ERROR_INVALID_EMBEDDING;
      stats.immersion = immersion_ = true;
      if(s_.free_border) return ERROR_WRONG_PARAMETER; // a moving border could stop being self-overlapping
    }
    if(holes_)
    {
      // the outer loop as the certificate chose it (largest exact uv area): the border
      Uv_samples<Point_2> samples;
      sample_uv(disk_, uvm_, samples);
      std::vector<CGAL::Gmpq> twice_area;
      std::vector<char> finite;
      loop_areas(domain_, samples, twice_area, finite);
      domain_.set_outer(largest_loop(twice_area, finite));
    }
    sgn_ = stats.report.clockwise ? -1. : 1.;   // work on the counterclockwise mirror image
    positive_ = stats.report.clockwise ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN;
    if(s_.face_metric && stats.report.clockwise) return ERROR_WRONG_PARAMETER;

    ec = mark_fixed_vertices(constrained);
    if(ec != OK) return ec;
    P_.resize(nv_);
    for(std::size_t i = 0; i < nv_; ++i) P_[i] = get(uvm_, disk_.vertices[i]);
    X_.resize(nv_); Y_.resize(nv_);
    refresh_doubles();
    ec = build_frames(stats.report.border_area);
    if(ec != OK) return ec;
    build_stars_and_colours();
    build_border_barrier();
    return OK;
  }

  std::size_t number_of_free_vertices() const { return std::size_t(nfree_); }

  // ---- the loop ----------------------------------------------------------------------------
  Error_code run(Optimization_statistics& stats)
  {
    CGAL::Real_timer timer;
    timer.start();
    double E = objective(X_, Y_);
    stats.energy_current = reported_energy(E);
    if(s_.verbose) std::cerr << "[optimize] energy " << E << ", " << nfree_ << " free vertices\n";
    Error_code result = ERROR_BUDGET_EXHAUSTED;
    std::size_t quiet = 0; // consecutive iterations below the tolerance
    for(std::size_t it = 0; it < s_.max_iterations; ++it)
    {
      if(timer.time() > s_.time_budget) { stats.time_budget_reached = true; break; }
      if(scale_free_) { match_reference_area(); E = objective(X_, Y_); } // the same energy, up to rounding
      const double E0 = E;
      // A global step, then a sweep of per-vertex steps if the global step was held back by the
      // first face to degenerate (far from smooth: tiny faces), where each vertex fixes its own
      // star at O(n) cost per sweep.
      const bool global_ok = global_step(E);
      if(global_ok) ++stats.global_steps;
      const bool reused = global_ok && step_reused_;
      // the per-vertex steps know no face metric: no step lowers the energy, as far as the line search can tell
      if(s_.face_metric && !global_ok) { result = OK; stats.converged = true; break; }
      if(!s_.face_metric && (!global_ok || held_back_))
      {
        vertex_sweep();
        ++stats.vertex_sweeps;
        E = objective(X_, Y_);
      }
      ++stats.iterations;
      const double decrease = (E0 - E) / E0;
      // Reusing the factorization: a Newton step costs a factorization, a step with the last one only two
      // triangular solves, and it still descends (the old Hessian is positive definite). After a fresh
      // step, the next ones reuse its factorization as long as each gains at least half of what the fresh
      // one gained; a reused step whose line search fails is computed again at once with a fresh one
      // (global_step()). Only fresh steps decide convergence, so the stopping rule means what it did.
      if(reused) reuse_next_ = decrease >= reuse_gain_ratio * fresh_gain_ && decrease >= s_.tolerance;
      else
      {
        fresh_gain_ = decrease;
        reuse_next_ = global_ok && s_.reuse_factorization && direct_solve() && decrease > 0;
      }
      if(s_.verbose) std::cerr << "[optimize] iteration " << stats.iterations << ": energy " << E
                               << (global_ok ? "" : " (sweep only)") << "\n";
      stats.energy_current = reported_energy(E);
      if(s_.callback && !s_.callback(double(stats.iterations) / double(s_.max_iterations))) break;
      // converged: two consecutive iterations lower the energy by less than the tolerance
      // (a tolerance of 0 never converges: a step that gains nothing, or loses a rounding error, still
      // leaves the rest of the budget to run)
      if(!reused) quiet = (s_.tolerance > 0 && decrease < s_.tolerance) ? quiet + 1 : 0;
      if(quiet >= 2) { result = OK; stats.converged = true; break; }
    }
    stats.factorizations = factorizations_;
    stats.seconds = timer.time();
    return result;
  }

  // exact certificate of the current positions, without writing them
  Embedding_report certify() const
  {
    const auto vid = vertex_indices();
    return check_embedding_impl(tm_, current_uv(vid), parameters::multiply_connected(holes_,
                                           parameters::check_overlap(!immersion_,
                                             CGAL::parameters::vertex_point_map(vpm_).geom_traits(traits_))),
                                holes_ ? nullptr : &disk_);
  }

  bool immersion() const { return immersion_; }

  // the index of each vertex in disk_, and the current positions as a uv map (for the certificates)
  auto vertex_indices() const
  {
    auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm_);
    for(std::size_t i = 0; i < nv_; ++i) put(vid, disk_.vertices[i], i);
    return vid;
  }
  template <class VertexIndexMap>
  auto current_uv(const VertexIndexMap& vid) const
  {
    return boost::make_function_property_map<vertex_descriptor, Point_2>(
      [this, &vid](vertex_descriptor v) -> Point_2 { return P_[get(vid, v)]; });
  }

  // with an immersion: its exact certificate for the current positions, the border compared
  // bit-exactly with the input's (it is fixed)
  Immersion_report certify_immersion() const
  {
    const auto vid = vertex_indices();
    Immersion_report r = check_immersion_of_disk(disk_, current_uv(vid), orient_, border_turns_);
    for(std::size_t b : disk_.border)
    {
      const Point_2 q = get(uvm_, disk_.vertices[b]);
      if(!(q.x() == P_[b].x() && q.y() == P_[b].y())) ++r.border_mismatches;
    }
    return r;
  }

  void write() const
  {
    for(std::size_t i = 0; i < nv_; ++i)
      if(var_[i] >= 0) put(uvm_, disk_.vertices[i], P_[i]);
  }

  // ---- named steps -------------------------------------------------------------------------
  // Area-weighted mean energy; +inf if a face is not positively oriented (in double). With a free border, the
  // energy of the map scaled uniformly to the references' area (scale_free_). `certificate_faces`: the mean over the
  // faces that have a 3D area only, as check_embedding() measures it (the others' stand-in references shape them
  // but are no part of the surface's distortion).
  double energy(const std::vector<double>& x, const std::vector<double>& y, bool certificate_faces = false) const
  {
    double e = 0;
    Isotropic_terms it;
    if(s_.face_metric) s_.face_metric(x, y, metric_);
    double k = 1;
    if(scale_free_)
    {
      const double area = uv_area(x, y);
      if(!(area > 0)) return std::numeric_limits<double>::infinity();
      k = std::sqrt(reference_area_ / area);
    }
    for(std::size_t f = 0; f < nf_; ++f)
    {
      double s1, s2;
      if(!singular_values(f, x, y, s1, s2)) return std::numeric_limits<double>::infinity();
      if(!isotropic_terms(s_.energy, k * s1, k * s2, it)) return std::numeric_limits<double>::infinity();
      if(!(certificate_faces && stand_in_[f])) e += frames_[f].weight * it.psi;
    }
    return e / (certificate_faces ? certificate_weight_ : total_weight_);
  }

  // `energy_current`: the objective `E` at the current positions, or with faces of no 3D area the same measure
  // over the others, as the certificate's mean (one more pass, only then). Not with a face metric: its hook keeps
  // state (where each face's walk in the other map starts), which a pass outside the optimization would change; the
  // composed distortion is no certificate's measure anyway.
  double reported_energy(double E) const
  {
    if(!has_stand_ins_ || s_.face_metric || !std::isfinite(E)) return E;
    const double barrier = barrier_ ? barrier_energy(X_, Y_) / total_weight_ : 0.; // as objective() has it
    return energy(X_, Y_, true) + barrier;
  }

  // The area of the map (the sum of its faces' signed areas, in the counterclockwise frame, in double)
  double uv_area(const std::vector<double>& x, const std::vector<double>& y) const
  {
    double a = 0;
    for(const auto& t : disk_.faces) a += signed_area(x[t[0]], y[t[0]], x[t[1]], y[t[1]], x[t[2]], y[t[2]]);
    return a;
  }

  // A free border lets the map's area change, and the energy against fixed references
  // prefers a scale of its own (for the symmetric Dirichlet energy, the one that balances the map's stretched
  // and shrunk faces), while check_embedding() measures the map scaled to the references' area. The optimizer
  // minimizes the latter: the energy of the map scaled by k = sqrt(reference_area_ / uv_area), which no uniform scaling
  // changes. Each iteration first scales the references to the map's current area (k = 1 there), so that
  // the per-face derivatives are those at the current scale, and the gradient gains the term of k
  // (add_scale_term()); the line search compares the scaled energies, so every accepted step lowers the
  // energy reported.
  void match_reference_area()
  {
    if(!scale_free_) return;
    const double area = uv_area(X_, Y_);
    if(!(area > 0) || !std::isfinite(area) || area == reference_area_) return;
    const double c = area / reference_area_, r = std::sqrt(c), inv = 1 / r; // c on areas, r on lengths
    if(!(c > 0) || !std::isfinite(c * c) || !(c * c > 0) || !std::isfinite(inv)) return;
    for(Face_frame& fr : frames_)
    {
      for(double& g : fr.G) g *= inv;
      for(double& d : fr.ref.dot) d *= c;
      fr.ref.area2 *= c * c;
    }
    reference_area_ = area;
    reach_scale_ *= r;
    max_reach_ *= r;
  }

  // At k = 1: the derivative of the energy in k is D = sum over faces of weight * (s1 dpsi/ds1 + s2 dpsi/ds2),
  // and k = sqrt(reference_area_ / uv_area) varies by -k / (2 uv_area) times the derivative of the area, which
  // only the vertices of the loops change (an interior vertex's faces keep their total area). The Hessian stays
  // that of the energy at the fixed scale, positive definite: the steps still descend, and the line search
  // decides.
  bool add_scale_term(Eigen::VectorXd& grad) const
  {
    double D = 0;
    Isotropic_terms it;
    for(std::size_t f = 0; f < nf_; ++f)
    {
      double s1, s2;
      if(!singular_values(f, X_, Y_, s1, s2) || !isotropic_terms(s_.energy, s1, s2, it)) return false;
      D += frames_[f].weight * (s1 * it.d1 + s2 * it.d2);
    }
    const double area = uv_area(X_, Y_);
    if(!(area > 0)) return false;
    const double c = -D / (2 * area);
    for(const auto& t : disk_.faces)
      for(int a = 0; a < 3; ++a)
      {
        const long v = var_[t[a]];
        if(v < 0) continue;
        const std::size_t b = t[(a + 1) % 3], d = t[(a + 2) % 3];
        // the derivative of the face's area in the position of corner a
        grad(2 * v) += c * 0.5 * (Y_[b] - Y_[d]);
        grad(2 * v + 1) += c * 0.5 * (X_[d] - X_[b]);
      }
    return std::isfinite(D) && grad.allFinite();
  }

  // The minimized energy: energy() plus, with a free disk border, the border barrier (same scale)
  double objective(const std::vector<double>& x, const std::vector<double>& y) const
  {
    const double e = energy(x, y);
    if(!barrier_ || !std::isfinite(e)) return e;
    return e + barrier_energy(x, y) / total_weight_;
  }

  // One projected Newton step of the whole map; lowers E (mean energy) and returns true if a
  // step was accepted.
  // With holes, the loops are free and nothing keeps them apart but the line search: where a hole
  // has pinched itself (or touches another loop) to a gap below any step, every step fails there.
  // The vertices of the touching edges are then held for the global steps (an active set; the
  // per-vertex steps still move them, each checked exactly) and the step is computed again.
  bool global_step(double& E)
  {
    for(int attempt = 0; ; ++attempt)
    {
      // a step with the last factorization needs the gradient only
      const bool reuse = reuse_next_ && factor_ready_ && !holding_;
      step_reused_ = reuse;
      Eigen::VectorXd grad;
      if(!assemble(grad, !reuse)) return false;
      Eigen::VectorXd d;
      if(!solve(grad, d, reuse))
      {
        if(!reuse) return false;
        reuse_next_ = false; --attempt; continue; // once: fresh at once
      }
      std::vector<double> dx(nv_, 0.), dy(nv_, 0.);
      for(std::size_t i = 0; i < nv_; ++i)
        if(var_[i] >= 0 && !held_[i]) { dx[i] = d(2 * var_[i]); dy[i] = d(2 * var_[i] + 1); }
      if(line_search(dx, dy, E)) return true;
      if(reuse) { reuse_next_ = false; --attempt; continue; } // the old factorization's step failed: a fresh one
      if(!holes_ || contact_.empty() || attempt + 1 >= max_hold_attempts) return false;
      std::size_t added = 0;
      for(const std::array<std::size_t, 4>& pair : contact_)
        for(std::size_t v : pair)
          if(var_[v] >= 0 && !held_[v]) { held_[v] = 1; ++added; }
      if(added == 0) return false;
      holding_ = true;
    }
  }

  // Backtracking from the flip-free bound: accepts the first t whose energy is lower and whose
  // positions, rounded to the uv number type, pass the exact test (faces positive; with a free
  // border, the border simple).
  bool line_search(const std::vector<double>& dx, const std::vector<double>& dy, double& E)
  {
    double tmax = 1.0;
    for(std::size_t f = 0; f < nf_; ++f)
    {
      const auto& t = disk_.faces[f];
      if(var_[t[0]] < 0 && var_[t[1]] < 0 && var_[t[2]] < 0) continue;
      tmax = (std::min)(tmax, 0.8 * triangle_degeneration_time(X_[t[0]], Y_[t[0]], X_[t[1]], Y_[t[1]], X_[t[2]], Y_[t[2]],
                                                               dx[t[0]], dy[t[0]], dx[t[1]], dy[t[1]], dx[t[2]], dy[t[2]]));
    }
    if(barrier_) tmax = (std::min)(tmax, 0.8 * border_contact_time(dx, dy, tmax));
    held_back_ = tmax < 1;
    contact_.clear();
    std::vector<double> nx(X_), ny(Y_);
    std::vector<Point_2> Pn(P_);
    bool loops_failed = false; // the last t tried failed on the loops only
    for(double t = tmax; t > 1e-12 * tmax; t *= 0.5)
    {
      loops_failed = false;
      for(std::size_t i = 0; i < nv_; ++i)
        if(var_[i] >= 0) { nx[i] = X_[i] + t * dx[i]; ny[i] = Y_[i] + t * dy[i]; }
      const double En = objective(nx, ny);
      if(!(En < E)) continue;
      for(std::size_t i = 0; i < nv_; ++i)
        if(var_[i] >= 0)
          Pn[i] = Point_2(P_[i].x() + make_ft<FT>(t * dx[i]), P_[i].y() + make_ft<FT>(sgn_ * t * dy[i]));
      if(!faces_positive(Pn) || (s_.free_border && !border_simple(Pn))) continue;
      if(holes_ && !(loops_disjoint(Pn) && holes_oriented(Pn))) { loops_failed = true; continue; }
      P_.swap(Pn);
      refresh_doubles();
      E = objective(X_, Y_);
      return true;
    }
    // even the shortest step makes loops touch: the edges that touch then (for global_step())
    if(loops_failed)
    {
      std::size_t self = 0, crossing = 0;
      count_loop_intersections(Pn, domain_.loops, orient_, 64, self, crossing, &contact_);
    }
    return false;
  }

  // Per-vertex projected Newton steps over all free vertices. With a free border, the border
  // vertices move first, alone, and their moves are undone together unless the border stays
  // simple (decided exactly); then the interior vertices move, colour by colour.
  std::size_t vertex_sweep()
  {
    std::size_t moved = 0;
    // the stars' energies below are at the references' scale: that of the current area (a global step may have
    // changed it)
    match_reference_area();
    if(s_.free_border && !border_free_.empty())
    {
      // each border vertex lowers the energy of its star at the current scale; the scale follows the area they
      // change, so the energy of the whole map decides too
      const std::vector<Point_2> saved(P_);
      const double before = scale_free_ ? objective(X_, Y_) : 0.;
      std::size_t m = 0;
      for(std::size_t i : border_free_) if(move_vertex(i)) ++m;
      if(m > 0 && (!border_simple(P_) || (holes_ && !(loops_disjoint(P_) && holes_oriented(P_)))
                   || (scale_free_ && !(objective(X_, Y_) < before)))) { P_ = saved; refresh_doubles(); m = 0; }
      if(m > 0) match_reference_area(); // the interior steps below keep the area: their scale is this one
      moved += m;
    }
    // hole vertices one at a time, each checked against every loop edge (sequential: the check
    // reads the other loops)
    if(!hole_free_.empty())
    {
      // with a free border, the hole vertices change the area too: checked and rescaled as the border's
      const std::vector<Point_2> saved(scale_free_ ? P_ : std::vector<Point_2>());
      const double before = scale_free_ ? objective(X_, Y_) : 0.;
      std::size_t m = 0;
      for(std::size_t i : hole_free_) if(move_vertex(i)) ++m;
      if(scale_free_ && m > 0)
      {
        if(objective(X_, Y_) < before) match_reference_area();
        else { P_ = saved; refresh_doubles(); m = 0; }
      }
      moved += m;
    }
#ifdef CGAL_LINKED_WITH_TBB
    if(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value && std::is_floating_point<FT>::value)
    {
      for(const std::vector<std::size_t>& cls : colours_)
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
    for(const std::vector<std::size_t>& cls : colours_)
      for(std::size_t i : cls)
        if(move_vertex(i)) ++moved;
    return moved;
  }

  // One Newton step on the energy of the star of vertex i, certified exactly; true if i moved.
  bool move_vertex(std::size_t i)
  {
    double g[2] = {0, 0}, H[3] = {0, 0, 0}, E0 = 0;
    for(const auto& fc : star_[i])
    {
      const std::size_t a = corner(fc, 1), b = corner(fc, 2);
      double Ef; std::array<double, 2> gf; std::array<double, 3> Hf;
      if(!star_face_terms(fc, X_[i], Y_[i], X_[a], Y_[a], X_[b], Y_[b], Ef, gf, Hf)) return false;
      const double w = frames_[fc.first].weight;
      E0 += Ef * w; g[0] += gf[0] * w; g[1] += gf[1] * w;
      H[0] += Hf[0] * w; H[1] += Hf[1] * w; H[2] += Hf[2] * w;
    }
    const bool barrier = barrier_ && border_pos_[i] >= 0;
    std::vector<Barrier_pair> near; // border vertices move one at a time: no sharing
    if(barrier)
    {
      double Eb = 0;
      pairs_of(i, 0., near);
      if(!vertex_barrier(i, X_[i], Y_[i], near, Eb, g, H)) return false;
      E0 += Eb;
    }
    double d[2];
    if(!projected_newton_direction(g, H, d)) return false;
    double tmax = 1.0;
    for(const auto& fc : star_[i])
    {
      const std::size_t a = corner(fc, 1), b = corner(fc, 2);
      tmax = (std::min)(tmax, 0.8 * vertex_degeneration_time(X_[i], Y_[i], d[0], d[1], X_[a], Y_[a], X_[b], Y_[b]));
    }
    if(barrier)
    {
      // every pair that a step of at most tmax can bring within reach or into contact
      pairs_of(i, tmax * std::sqrt(d[0] * d[0] + d[1] * d[1]), near);
      tmax = (std::min)(tmax, 0.8 * vertex_contact_time(d, near));
    }
    double t = tmax;
    for(int k = 0; k < 16; ++k, t *= 0.5) // a vertex that cannot move now may move in a later sweep
    {
      const double xi = X_[i] + t * d[0], yi = Y_[i] + t * d[1];
      double En = 0;
      bool valid = true;
      for(const auto& fc : star_[i])
      {
        const std::size_t a = corner(fc, 1), b = corner(fc, 2);
        const double e = star_face_energy(fc, xi, yi, X_[a], Y_[a], X_[b], Y_[b]);
        if(!(e >= 0)) { valid = false; break; }
        En += e * frames_[fc.first].weight;
      }
      if(valid && barrier)
      {
        double Eb = 0, gb[2] = {0, 0}, Hb[3] = {0, 0, 0};
        valid = vertex_barrier(i, xi, yi, near, Eb, gb, Hb);
        En += Eb;
      }
      if(!valid || !(En < E0)) continue;
      const Point_2 old = P_[i];
      P_[i] = Point_2(old.x() + make_ft<FT>(t * d[0]), old.y() + make_ft<FT>(sgn_ * t * d[1]));
      for(const auto& fc : star_[i])
      {
        const auto& tr = disk_.faces[fc.first];
        if(orient_(P_[tr[0]], P_[tr[1]], P_[tr[2]]) != positive_) { valid = false; break; }
      }
      if(valid && holes_ && domain_.is_hole_vertex(i))
        valid = loop_edges_clear(P_, domain_.loops, std::size_t(domain_.loop_of[i]), hole_position_[i], orient_)
             && hole_sign(P_, std::size_t(domain_.loop_of[i])) == CGAL::NEGATIVE;
      if(!valid) { P_[i] = old; continue; }
      X_[i] = CGAL::to_double(P_[i].x()); Y_[i] = sgn_ * CGAL::to_double(P_[i].y());
      return true;
    }
    return false;
  }

private:
  typedef std::pair<std::size_t, int> Face_corner;

  std::size_t corner(const Face_corner& fc, int k) const { return disk_.faces[fc.first][(fc.second + k) % 3]; }

  void refresh_doubles()
  {
    for(std::size_t i = 0; i < nv_; ++i) { X_[i] = CGAL::to_double(P_[i].x()); Y_[i] = sgn_ * CGAL::to_double(P_[i].y()); }
  }

  Error_code mark_fixed_vertices(const std::vector<vertex_descriptor>& constrained)
  {
    std::vector<char> fixed(nv_, 0);
    for(std::size_t i = 0; i < nv_; ++i) if(disk_.on_border[i] && !s_.free_border) fixed[i] = 1;
    if(!constrained.empty())
    {
      auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm_);
      for(std::size_t i = 0; i < nv_; ++i) put(vid, disk_.vertices[i], i);
      for(const vertex_descriptor& v : constrained) fixed[get(vid, v)] = 1; // a vertex of tm: precondition
    }
    var_.assign(nv_, -1);
    held_.assign(nv_, 0);
    nfree_ = 0;
    for(std::size_t i = 0; i < nv_; ++i) if(!fixed[i]) var_[i] = nfree_++;
    border_free_.clear();
    for(std::size_t b : disk_.border) if(var_[b] >= 0) border_free_.push_back(b);
    hole_free_.clear();
    hole_position_.assign(nv_, 0);
    if(holes_)
      for(std::size_t l = 0; l < domain_.number_of_loops(); ++l)
      {
        if(l == domain_.outer) continue;
        for(std::size_t k = 0; k < domain_.loops[l].size(); ++k)
        {
          const std::size_t v = domain_.loops[l][k];
          hole_position_[v] = k;
          if(var_[v] >= 0) hole_free_.push_back(v);
        }
      }
    return nfree_ > 0 ? OK : ERROR_NO_FREE_VERTEX;
  }

  // 3D triangles scaled so that the total 3D area equals the area enclosed by the uv border.
  // Faces with a zero 3D area get an equilateral reference of the mean area (they must still be
  // shaped by something); a mesh with no 3D area at all, or non-finite points, is refused.
  Error_code build_frames(double border_area)
  {
    // the 3D points in double, brought near unit size by a power of two when they are far from it (squared areas
    // would overflow or underflow); the references are scaled to the uv area below anyway
    points_3_.resize(nv_);
    for(std::size_t i = 0; i < nv_; ++i)
    {
      const auto& q = get(vpm_, disk_.vertices[i]);
      points_3_[i] = {{ CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()) }};
      for(double x : points_3_[i]) if(!std::isfinite(x)) return ERROR_NON_FINITE_COORDINATES; // every vertex is in a face
    }
    normalize_coordinates_3(points_3_);
    std::vector<Reference_triangle<double> > refs(nf_);
    for(std::size_t f = 0; f < nf_; ++f)
    {
      const auto& t = disk_.faces[f];
      refs[f] = reference_3d({{ points_3_[t[0]], points_3_[t[1]], points_3_[t[2]] }});
    }
    stand_in_.assign(nf_, 0);
    for(std::size_t f = 0; f < nf_; ++f) stand_in_[f] = !(refs[f].area2 > 0); // given a stand-in below
    has_stand_ins_ = std::find(stand_in_.begin(), stand_in_.end(), char(1)) != stand_in_.end();
    double k2 = 0;
    const Error_code ec = scale_references(refs, border_area, k2);
    if(ec != OK) return ec;
    reference_scale_ = std::sqrt(k2);
    frames_.resize(nf_);
    total_weight_ = 0;
    certificate_weight_ = 0;
    for(std::size_t f = 0; f < nf_; ++f)
    {
      frames_[f] = face_frame(refs[f]);
      total_weight_ += frames_[f].weight;
      if(!stand_in_[f]) certificate_weight_ += frames_[f].weight;
    }
    // the symmetric Dirichlet energy (the certificate's) with a moving border, which changes the map's area. ARAP
    // measures the scale too: its references keep the input's area. Free hole loops inside a fixed border change
    // the area too, but little, and there the Hessian without the scale's terms left the constrained maps with
    // holes unconverged after 1000 iterations: their references keep the input's area as well.
    scale_free_ = s_.free_border && s_.energy == Distortion_energy::SYMMETRIC_DIRICHLET;
    reference_area_ = border_area; // that of the faces with a 3D area (the others have stand-ins, see scale_references())
    return OK;
  }

  void build_stars_and_colours()
  {
    star_.assign(nv_, std::vector<Face_corner>());
    for(std::size_t f = 0; f < nf_; ++f)
      for(int c = 0; c < 3; ++c) star_[disk_.faces[f][c]].push_back(Face_corner(f, c));
    // greedy colouring of the free interior vertices: two vertices of one colour share no face,
    // so their steps are independent (parallel sweeps)
    colours_.clear();
    std::vector<int> colour(nv_, -1);
    for(std::size_t i = 0; i < nv_; ++i)
    {
      if(var_[i] < 0 || disk_.on_border[i] || (holes_ && domain_.is_hole_vertex(i))) continue;
      std::vector<char> used;
      for(const auto& fc : star_[i])
        for(std::size_t j : disk_.faces[fc.first])
          if(j != i && colour[j] >= 0)
          {
            if(used.size() <= std::size_t(colour[j])) used.resize(colour[j] + 1, 0);
            used[colour[j]] = 1;
          }
      int c = 0;
      while(c < int(used.size()) && used[c]) ++c;
      colour[i] = c;
      if(colours_.size() <= std::size_t(c)) colours_.resize(c + 1);
      colours_[c].push_back(i);
    }
  }

  void jacobian(std::size_t f, const std::vector<double>& x, const std::vector<double>& y, Eigen::Matrix2d& J) const
  {
    const auto& t = disk_.faces[f];
    const auto& g = frames_[f].G;
    J(0, 0) = g[0] * x[t[0]] + g[2] * x[t[1]] + g[4] * x[t[2]];
    J(0, 1) = g[1] * x[t[0]] + g[3] * x[t[1]] + g[5] * x[t[2]];
    J(1, 0) = g[0] * y[t[0]] + g[2] * y[t[1]] + g[4] * y[t[2]];
    J(1, 1) = g[1] * y[t[0]] + g[3] * y[t[1]] + g[5] * y[t[2]];
    if(s_.face_metric) J = (metric_[f] * J).eval();
  }

  // singular values of the Jacobian of face f (s1 >= s2 > 0), false if the face is not positive
  bool singular_values(std::size_t f, const std::vector<double>& x, const std::vector<double>& y, double& s1, double& s2) const
  {
    Eigen::Matrix2d J;
    jacobian(f, x, y, J);
    const double det = J.determinant();
    if(!(det > 0)) return false;
    // closed form: s1,2 = (sqrt(|J|^2 + 2 det) +- sqrt(|J|^2 - 2 det)) / 2
    const double n2 = J.squaredNorm();
    const double a = std::sqrt(n2 + 2 * det), b = std::sqrt((std::max)(0., n2 - 2 * det));
    s1 = 0.5 * (a + b);
    s2 = det / s1; // stable for the small one
    return s2 > 0 && std::isfinite(s1);
  }

  // The Hessian's sparsity pattern, built once from the stars: columns 2j and 2j + 1 of free vertex j
  // both hold the rows 2i and 2i + 1 of every free vertex i that shares a face with j (j included),
  // sorted. Written straight into H_'s compressed storage (per-face triplets would take 36 entries
  // of 16 bytes per face: over 1 GB at a million vertices), with the position of each face's 3x3
  // vertex blocks in it, so that the assembly adds into place.
  void build_pattern()
  {
    const long n2 = 2 * nfree_;
    std::vector<std::size_t> free_vertex(static_cast<std::size_t>(nfree_));
    for(std::size_t i = 0; i < nv_; ++i) if(var_[i] >= 0) free_vertex[std::size_t(var_[i])] = i;
    std::vector<long> around;
    auto neighbours = [&](long j) {
      around.clear();
      for(const auto& fc : star_[free_vertex[std::size_t(j)]])
        for(std::size_t v : disk_.faces[fc.first]) if(var_[v] >= 0) around.push_back(var_[v]);
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
    };
    std::vector<int> outer(std::size_t(n2) + 1, 0);
    for(long j = 0; j < nfree_; ++j)
    {
      neighbours(j);
      const int count = int(2 * around.size());
      outer[std::size_t(2 * j + 1)] = outer[std::size_t(2 * j)] + count;
      outer[std::size_t(2 * j + 2)] = outer[std::size_t(2 * j + 1)] + count;
    }
    H_.resize(n2, n2);
    H_.resizeNonZeros(outer.back());
    std::copy(outer.begin(), outer.end(), H_.outerIndexPtr());
    int* inner = H_.innerIndexPtr();
    for(long j = 0; j < nfree_; ++j)
    {
      neighbours(j);
      for(int c = 0; c < 2; ++c)
        for(long i : around) { *inner++ = int(2 * i); *inner++ = int(2 * i + 1); }
    }
    face_slots_.assign(nf_, std::array<int, 9>());
    for(std::size_t f = 0; f < nf_; ++f)
      for(int a = 0; a < 3; ++a)
        for(int b = 0; b < 3; ++b)
        {
          const long va = var_[disk_.faces[f][a]], vb = var_[disk_.faces[f][b]];
          face_slots_[f][3 * a + b] = (va >= 0 && vb >= 0) ? slot(2 * va, 2 * vb) : -1;
        }
    diagonal_slots_.resize(std::size_t(n2));
    for(long i = 0; i < n2; ++i) diagonal_slots_[std::size_t(i)] = std::size_t(slot(i, i));
  }

  // position of entry (r, c) in H_'s compressed storage (the entry must be in the pattern)
  int slot(long r, long c) const
  {
    return int(std::lower_bound(H_.innerIndexPtr() + H_.outerIndexPtr()[c],
                                H_.innerIndexPtr() + H_.outerIndexPtr()[c + 1], int(r)) - H_.innerIndexPtr());
  }

  // Gradient and projected Hessian of the whole energy (sum of weight * psi), Hessian into H_
  bool assemble(Eigen::VectorXd& grad, bool hessian = true)
  {
    const long n2 = 2 * nfree_;
    grad = Eigen::VectorXd::Zero(n2);
    if(face_slots_.empty()) build_pattern();
    if(hessian) std::fill(H_.valuePtr(), H_.valuePtr() + H_.nonZeros(), 0.);
    if(s_.face_metric) s_.face_metric(X_, Y_, metric_);
    double* const values = H_.valuePtr();
    const int* const outer = H_.outerIndexPtr();
    for(std::size_t f = 0; f < nf_; ++f)
    {
      const auto& t = disk_.faces[f];
      if(var_[t[0]] < 0 && var_[t[1]] < 0 && var_[t[2]] < 0) continue;
      Eigen::Matrix2d J;
      jacobian(f, X_, Y_, J);
      if(!(J.determinant() > 0)) return false;
      Eigen::Matrix2d U, V;
      Eigen::Vector2d s;
      if(!rotation_svd_2x2(J, U, s, V)) return false;
      Isotropic_terms it;
      if(!isotropic_terms(s_.energy, s(0), s(1), it)) return false;
      const double w = frames_[f].weight;
      const auto& g = frames_[f].G;
      // D^T vec(Q) for a 2x2 Q: per corner a, (g_a0 Q00 + g_a1 Q01, g_a0 Q10 + g_a1 Q11)
      // with a face metric M, the derivative of psi(M J) with respect to J is M^T Q
      auto pull = [&](const Eigen::Matrix2d& Q0, std::array<double, 6>& out) {
        const Eigen::Matrix2d Q = s_.face_metric ? (metric_[f].transpose() * Q0).eval() : Q0;
        for(int a = 0; a < 3; ++a)
        {
          out[2 * a] = g[2 * a] * Q(0, 0) + g[2 * a + 1] * Q(0, 1);
          out[2 * a + 1] = g[2 * a] * Q(1, 0) + g[2 * a + 1] * Q(1, 1);
        }
      };
      const Eigen::Vector2d u1 = U.col(0), u2 = U.col(1), v1 = V.col(0), v2 = V.col(1);
      std::array<double, 6> gr;
      pull(U * Eigen::Vector2d(it.d1, it.d2).asDiagonal() * V.transpose(), gr);
      if(!hessian)
      {
        for(int a = 0; a < 3; ++a)
          if(var_[t[a]] >= 0) { grad(2 * var_[t[a]]) += w * gr[2 * a]; grad(2 * var_[t[a]] + 1) += w * gr[2 * a + 1]; }
        continue;
      }
      std::array<std::array<double, 6>, 4> modes;
      const double r2 = std::sqrt(0.5);
      pull(u1 * v1.transpose(), modes[0]);
      pull(u2 * v2.transpose(), modes[1]);
      pull(r2 * (u2 * v1.transpose() - u1 * v2.transpose()), modes[2]);
      pull(r2 * (u1 * v2.transpose() + u2 * v1.transpose()), modes[3]);
      const double lambda[4] = { it.scale1, it.scale2, it.twist, it.flip };
      const std::array<int, 9>& slots = face_slots_[f];
      for(int a = 0; a < 3; ++a)
      {
        const long va = var_[t[a]];
        if(va < 0) continue;
        grad(2 * va) += w * gr[2 * a];
        grad(2 * va + 1) += w * gr[2 * a + 1];
        for(int b = 0; b < 3; ++b)
        {
          const long vb = var_[t[b]];
          if(vb < 0) continue;
          // the 2x2 block (rows of a, columns of b): column 2 vb + 1 holds the same rows as column 2 vb
          const int base = slots[3 * a + b], len = outer[2 * vb + 1] - outer[2 * vb];
          for(int i = 0; i < 2; ++i)
            for(int j = 0; j < 2; ++j)
            {
              const int p = 2 * a + i, q = 2 * b + j;
              double h = 0;
              for(int k = 0; k < 4; ++k) h += lambda[k] * modes[k][p] * modes[k][q];
              values[base + i + j * len] += w * h;
            }
        }
      }
    }
    if(scale_free_ && !add_scale_term(grad)) return false;
    if(barrier_ && !add_barrier_derivatives(grad)) return false;
    if(holding_) hold_rows(grad);
    return grad.allFinite();
  }

  // the rows and columns of the held vertices replaced by the identity's, their gradient by 0: the
  // same sparsity pattern (its analysis is kept), and a zero step for them
  void hold_rows(Eigen::VectorXd& grad)
  {
    std::vector<char> row_held(std::size_t(H_.rows()), 0);
    for(std::size_t i = 0; i < nv_; ++i)
      if(var_[i] >= 0 && held_[i]) row_held[std::size_t(2 * var_[i])] = row_held[std::size_t(2 * var_[i] + 1)] = 1;
    for(long c = 0; c < H_.outerSize(); ++c)
      for(typename SpMat::InnerIterator it(H_, c); it; ++it)
        if(row_held[std::size_t(it.row())] || row_held[std::size_t(c)]) it.valueRef() = (it.row() == c) ? 1. : 0.;
    for(long r = 0; r < grad.size(); ++r) if(row_held[std::size_t(r)]) grad(r) = 0;
  }

  // d = -H^-1 grad; a small relative shift keeps H definite (a free border leaves translations free)
  // whether the Newton steps use the direct solver (whose factorization may be reused)
  bool direct_solve() const { return 2 * long(nfree_) <= direct_solver_limit; }

  // reuse: solve with the factorization of an earlier iteration (the direct solver only)
  bool solve(const Eigen::VectorXd& grad, Eigen::VectorXd& d, bool reuse = false)
  {
    if(reuse)
    {
      d = ldlt_.solve(-grad);
      return ldlt_.info() == Eigen::Success && d.allFinite() && grad.dot(d) < 0;
    }
    const long n2 = H_.rows();
    Eigen::VectorXd diag = H_.diagonal();
    if(!diag.allFinite()) return false;
    std::vector<double> dv(diag.data(), diag.data() + n2);
    std::nth_element(dv.begin(), dv.begin() + n2 / 2, dv.end());
    const double shift = 1e-10 * dv[n2 / 2] + std::numeric_limits<double>::min();
    for(long i = 0; i < n2; ++i) H_.valuePtr()[diagonal_slots_[std::size_t(i)]] += shift;
    if(n2 <= direct_solver_limit)
    {
      if(!analyzed_) { ldlt_.analyzePattern(H_); analyzed_ = true; } // the pattern never changes
      factor_ready_ = false;
      ldlt_.factorize(H_);
      ++factorizations_;
      if(ldlt_.info() != Eigen::Success) return false;
      factor_ready_ = true;
      d = ldlt_.solve(-grad);
      if(ldlt_.info() != Eigen::Success) return false;
    }
    else
    {
      // large meshes: a sparse factorization costs O(n^1.5) on 2D meshes; bounded conjugate
      // gradients keep an iteration linear (the line search decides anyway)
      if(!cg_ready_) { cg_.set_pattern(H_); cg_ready_ = true; } // the pattern never changes
      cg_.set_values(H_);
      cg_.solve(-grad, d, cg_iterations, cg_tolerance);
    }
    return d.allFinite() && grad.dot(d) < 0;
  }

  bool faces_positive(const std::vector<Point_2>& P) const
  {
    for(std::size_t f = 0; f < nf_; ++f)
    {
      const auto& tr = disk_.faces[f];
      if(var_[tr[0]] < 0 && var_[tr[1]] < 0 && var_[tr[2]] < 0) continue;
      if(orient_(P[tr[0]], P[tr[1]], P[tr[2]]) != positive_) return false;
    }
    return true;
  }

  bool border_simple(const std::vector<Point_2>& P) const
  {
    std::vector<Point_2> B;
    B.reserve(disk_.border.size());
    for(std::size_t b : disk_.border) B.push_back(P[b]);
    return count_polygon_self_intersections(B, orient_, 1) == 0;
  }

  // no two loops touch and every loop is simple (exact; multiply connected maps)
  bool loops_disjoint(const std::vector<Point_2>& P) const
  {
    std::size_t self = 0, crossing = 0;
    count_loop_intersections(P, domain_.loops, orient_, 1, self, crossing);
    return self == 0 && crossing == 0;
  }

  // every hole clockwise in the counterclockwise working frame (exact)
  bool holes_oriented(const std::vector<Point_2>& P) const
  {
    for(std::size_t l = 0; l < domain_.number_of_loops(); ++l)
      if(l != domain_.outer && hole_sign(P, l) != CGAL::NEGATIVE) return false;
    return true;
  }

  // exact sign of the area of loop l in the working frame (y times sgn_): a double evaluation
  // when its error bound decides, exact rationals otherwise
  CGAL::Sign hole_sign(const std::vector<Point_2>& P, std::size_t l) const
  {
    const std::vector<std::size_t>& L = domain_.loops[l];
    const std::size_t n = L.size();
    if constexpr(std::is_floating_point<FT>::value)
    {
      double sum = 0, mag = 0;
      for(std::size_t k = 0; k < n; ++k)
      {
        const Point_2& a = P[L[k]];
        const Point_2& b = P[L[(k + 1) % n]];
        const double t1 = double(a.x()) * double(b.y()), t2 = double(a.y()) * double(b.x());
        sum += t1 - t2;
        mag += std::abs(t1) + std::abs(t2);
      }
      // rounding of n products and 2n sums, and underflow of the products
      const double bound = 4. * double(n + 2) * (std::numeric_limits<double>::epsilon() * mag + std::numeric_limits<double>::min());
      if(std::isfinite(sum) && std::isfinite(mag) && std::abs(sum) > bound)
        return (sum > 0) == (sgn_ > 0) ? CGAL::POSITIVE : CGAL::NEGATIVE;
    }
    std::vector<CGAL::Gmpq> x(n), y(n);
    for(std::size_t k = 0; k < n; ++k) { x[k] = to_rational(P[L[k]].x()); y[k] = to_rational(P[L[k]].y()); }
    const CGAL::Sign sg = CGAL::sign(twice_polygon_area(x, y));
    return sgn_ > 0 ? sg : CGAL::Sign(-int(sg));
  }

  // energy of star face fc with its corner 0 at (x, y): psi * weight is summed by the caller
  bool star_face_terms(const Face_corner& fc, double x, double y, double ax, double ay, double bx, double by,
                       double& E, std::array<double, 2>& g, std::array<double, 3>& H) const
  {
    if(s_.energy == Distortion_energy::SYMMETRIC_DIRICHLET)
    {
      const bool ok = symmetric_dirichlet_local(corner_reference(fc), x, y, ax, ay, bx, by, E, g, H);
      return ok && std::isfinite(E);
    }
    // ARAP: central differences (a diagonal model of the star's Hessian is enough for a descent step)
    const double h = 1e-7 * (std::abs(x) + std::abs(y) + std::abs(ax - bx) + std::abs(ay - by));
    E = star_face_energy(fc, x, y, ax, ay, bx, by);
    const double ex = star_face_energy(fc, x + h, y, ax, ay, bx, by), ey = star_face_energy(fc, x, y + h, ax, ay, bx, by);
    const double exm = star_face_energy(fc, x - h, y, ax, ay, bx, by), eym = star_face_energy(fc, x, y - h, ax, ay, bx, by);
    g = {{ (ex - exm) / (2 * h), (ey - eym) / (2 * h) }};
    H = {{ (ex - 2 * E + exm) / (h * h), 0., (ey - 2 * E + eym) / (h * h) }};
    return std::isfinite(E) && std::isfinite(g[0]) && std::isfinite(g[1]);
  }

  double star_face_energy(const Face_corner& fc, double x, double y, double ax, double ay, double bx, double by) const
  {
    const Reference_triangle<double> r = corner_reference(fc);
    if(s_.energy == Distortion_energy::SYMMETRIC_DIRICHLET)
    {
      bool ok;
      const double e = symmetric_dirichlet(r, x, y, ax, ay, bx, by, ok);
      // a pre-filter only: accepted positions are then certified with the exact predicate
      return (ok && signed_area(x, y, ax, ay, bx, by) > 0 && std::isfinite(e)) ? e : -1;
    }
    // ARAP from the singular values: |J|^2 and det J
    const double A = signed_area(x, y, ax, ay, bx, by);
    if(!(A > 0)) return -1;
    const double n2 = dirichlet_term(r, x, y, ax, ay, bx, by), det = A / std::sqrt(r.area2);
    const double a = std::sqrt(n2 + 2 * det), b = std::sqrt((std::max)(0., n2 - 2 * det));
    const double s1 = 0.5 * (a + b), s2 = det / s1;
    return (s1 - 1) * (s1 - 1) + (s2 - 1) * (s2 - 1);
  }

  // the face's reference with its corners rotated so that corner 0 is the star's centre
  Reference_triangle<double> corner_reference(const Face_corner& fc) const
  {
    Reference_triangle<double> r = frames_[fc.first].ref;
    const auto& d = frames_[fc.first].ref.dot;
    r.dot = {{ d[fc.second], d[(fc.second + 1) % 3], d[(fc.second + 2) % 3] }};
    return r;
  }

  // ---- border barrier ------------------------------------------------------------------------
  // Free border of a disk: for a border vertex v and a border edge e not incident to v, the reach
  // h = barrier_reach * min(reference length of e, reference lengths of v's two border edges) and
  // the weight k = (reference length of e)^2, so that a pair at a tenth of its reach weighs about as
  // much as one face of the border. The lengths are those of the scaled 3D triangles; the reaches follow
  // the references when they take the map's area (reach_scale_, match_reference_area()), the weights, like
  // the faces', do not: a uniform scaling of the map then changes neither the energy nor the barrier.
  void build_border_barrier()
  {
    barrier_ = s_.free_border && !holes_ && !immersion_ && disk_.border.size() >= 4;
    if(!barrier_) return;
    const std::size_t n = disk_.border.size();
    border_pos_.assign(nv_, -1);
    for(std::size_t k = 0; k < n; ++k) border_pos_[disk_.border[k]] = long(k);
    edge_length_.resize(n);
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::array<double, 3>& p = points_3_[disk_.border[k]];
      const std::array<double, 3>& q = points_3_[disk_.border[(k + 1) % n]];
      const double ex = q[0] - p[0], ey = q[1] - p[1], ez = q[2] - p[2];
      edge_length_[k] = reference_scale_ * std::sqrt(ex * ex + ey * ey + ez * ez);
    }
    // a border edge of zero 3D length: the mean length instead (its reach must not vanish)
    double mean = 0;
    for(double l : edge_length_) mean += l;
    mean /= double(n);
    if(!(mean > 0) || !std::isfinite(mean)) { barrier_ = false; return; }
    for(double& l : edge_length_) if(!(l > 0) || !std::isfinite(l)) l = mean;
    vertex_length_.resize(n);
    max_reach_ = 0;
    for(std::size_t k = 0; k < n; ++k)
    {
      vertex_length_[k] = (std::min)(edge_length_[k], edge_length_[(k + n - 1) % n]);
      max_reach_ = (std::max)(max_reach_, barrier_reach_ * edge_length_[k]);
    }
  }

  // a pair that involves one moving vertex: border positions of the vertex and of the edge's first
  // vertex, and which of the pair's three corners moves (0: the vertex, 1, 2: the edge's ends)
  struct Barrier_pair { std::size_t k, e; int c; };

  // the pairs (border position of the vertex, border position of the edge's first vertex)
  // that the barrier considers: the edge is not incident to the vertex
  bool barrier_pair(std::size_t k, std::size_t e) const
  {
    const std::size_t n = disk_.border.size();
    return e != k && (e + 1) % n != k;
  }

  double barrier_reach(std::size_t k, std::size_t e) const
  {
    return barrier_reach_ * reach_scale_ * (std::min)(edge_length_[e], vertex_length_[k]);
  }

  // f(k, e) for the pairs whose vertex lies within max_reach_ of the edge's x-range: the others
  // are beyond their reach (broad phase: the vertices sorted by x)
  template <class F>
  void for_each_near_pair(const std::vector<double>& x, const F& f) const
  {
    const std::size_t n = disk_.border.size();
    std::vector<std::pair<double, std::size_t> > xs(n);
    for(std::size_t k = 0; k < n; ++k) xs[k] = std::make_pair(x[disk_.border[k]], k);
    std::sort(xs.begin(), xs.end());
    for(std::size_t e = 0; e < n; ++e)
    {
      const double xa = x[disk_.border[e]], xb = x[disk_.border[(e + 1) % n]];
      const double lo = (std::min)(xa, xb) - max_reach_, hi = (std::max)(xa, xb) + max_reach_;
      auto it = std::lower_bound(xs.begin(), xs.end(), std::make_pair(lo, std::size_t(0)));
      for(; it != xs.end() && it->first <= hi; ++it)
        if(barrier_pair(it->second, e)) f(it->second, e);
    }
  }

  // One pair: its energy k * b(d / h) added to E; its distance gradient and the first and second
  // derivatives of the energy in d in g, e1, e2; false if the vertex touches the segment.
  // Nothing is added when the pair is beyond its reach (active is then false).
  // Vertex `moved` (none by default) is taken at (mx, my) instead of its place in (x, y).
  bool barrier_pair_terms(std::size_t k, std::size_t e, const std::vector<double>& x, const std::vector<double>& y,
                          double& E, double g[6], double& e1, double& e2, bool& active,
                          std::size_t moved = std::size_t(-1), double mx = 0, double my = 0) const
  {
    const std::size_t n = disk_.border.size();
    const std::size_t v = disk_.border[k], a = disk_.border[e], b = disk_.border[(e + 1) % n];
    const double vx = v == moved ? mx : x[v], vy = v == moved ? my : y[v];
    const double ax = a == moved ? mx : x[a], ay = a == moved ? my : y[a];
    const double bx = b == moved ? mx : x[b], by = b == moved ? my : y[b];
    const double h = barrier_reach(k, e);
    active = false;
    // cheap rejection: v outside the edge's box grown by h
    if(vx < (std::min)(ax, bx) - h || vx > (std::max)(ax, bx) + h ||
       vy < (std::min)(ay, by) - h || vy > (std::max)(ay, by) + h) return true;
    // a vertex next to the edge (one border vertex between them) measures the angle there: only a
    // reflex angle closing to 2 pi (the vertex outside the edge's line) is kept open; a sharp convex
    // corner is the faces' business
    if((k + 1) % n == e || (e + 2) % n == k)
      if(!((bx - ax) * (vy - ay) - (by - ay) * (vx - ax) < 0)) return true;
    double d;
    if(!point_segment_distance(vx, vy, ax, ay, bx, by, d, g)) return false;
    if(!(d < h)) return true;
    double b0, b1, b2;
    border_barrier_terms(d / h, b0, b1, b2);
    const double w = edge_length_[e] * edge_length_[e];
    E += w * b0;
    e1 = w * b1 / h;
    e2 = w * b2 / (h * h);
    active = true;
    return std::isfinite(E);
  }

  // the barrier's energy (not divided by the total weight); +inf if a vertex touches an edge
  double barrier_energy(const std::vector<double>& x, const std::vector<double>& y) const
  {
    double E = 0, g[6], e1, e2;
    bool active, ok = true;
    for_each_near_pair(x, [&](std::size_t k, std::size_t e) {
      if(ok && !barrier_pair_terms(k, e, x, y, E, g, e1, e2, active)) ok = false;
    });
    return ok ? E : std::numeric_limits<double>::infinity();
  }

  // Adds the barrier's gradient to grad and a positive semi-definite part of its Hessian to H_:
  // the Gauss-Newton term e2 * g g^T reduced to its 2x2 diagonal blocks (a principal part of a
  // positive semi-definite matrix is one), which fit the Hessian's fixed pattern.
  bool add_barrier_derivatives(Eigen::VectorXd& grad)
  {
    const std::size_t n = disk_.border.size();
    if(block_slots_.empty())
    {
      block_slots_.resize(std::size_t(nfree_));
      for(long i = 0; i < nfree_; ++i)
        block_slots_[std::size_t(i)] = {{ std::size_t(slot(2 * i, 2 * i)), std::size_t(slot(2 * i + 1, 2 * i)),
                                          std::size_t(slot(2 * i, 2 * i + 1)), std::size_t(slot(2 * i + 1, 2 * i + 1)) }};
    }
    double E = 0, g[6], e1 = 0, e2 = 0;
    bool active, ok = true;
    for_each_near_pair(X_, [&](std::size_t k, std::size_t e) {
        if(!ok) return;
        if(!barrier_pair_terms(k, e, X_, Y_, E, g, e1, e2, active)) { ok = false; return; }
        if(!active) return;
        const std::size_t corners[3] = { disk_.border[k], disk_.border[e], disk_.border[(e + 1) % n] };
        for(int c = 0; c < 3; ++c)
        {
          const long vi = var_[corners[c]];
          if(vi < 0) continue;
          const double gx = g[2 * c], gy = g[2 * c + 1];
          grad(2 * vi) += e1 * gx;
          grad(2 * vi + 1) += e1 * gy;
          const auto& sl = block_slots_[std::size_t(vi)];
          H_.valuePtr()[sl[0]] += e2 * gx * gx;
          H_.valuePtr()[sl[1]] += e2 * gx * gy;
          H_.valuePtr()[sl[2]] += e2 * gx * gy;
          H_.valuePtr()[sl[3]] += e2 * gy * gy;
        }
    });
    return ok;
  }

  // First time (up to `limit`) at which a border vertex would reach a border edge along the
  // direction (dx, dy) of every vertex
  double border_contact_time(const std::vector<double>& dx, const std::vector<double>& dy, double limit) const
  {
    const std::size_t n = disk_.border.size();
    double t = std::numeric_limits<double>::infinity();
    // swept boxes over [0, limit]
    std::vector<std::array<double, 4> > box(n);
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::size_t v = disk_.border[k];
      const double x1 = X_[v] + limit * dx[v], y1 = Y_[v] + limit * dy[v];
      box[k] = {{ (std::min)(X_[v], x1), (std::max)(X_[v], x1), (std::min)(Y_[v], y1), (std::max)(Y_[v], y1) }};
    }
    for(std::size_t e = 0; e < n; ++e)
    {
      const std::size_t e2 = (e + 1) % n, a = disk_.border[e], b = disk_.border[e2];
      const double xlo = (std::min)(box[e][0], box[e2][0]), xhi = (std::max)(box[e][1], box[e2][1]);
      const double ylo = (std::min)(box[e][2], box[e2][2]), yhi = (std::max)(box[e][3], box[e2][3]);
      for(std::size_t k = 0; k < n; ++k)
      {
        if(!barrier_pair(k, e)) continue;
        if(box[k][1] < xlo || box[k][0] > xhi || box[k][3] < ylo || box[k][2] > yhi) continue;
        const std::size_t v = disk_.border[k];
        t = (std::min)(t, vertex_segment_contact_time(X_[v], Y_[v], X_[a], Y_[a], X_[b], Y_[b],
                                                      dx[v], dy[v], dx[a], dy[a], dx[b], dy[b]));
      }
    }
    return t;
  }

  // f(k, e, c) for every pair that involves border vertex i: as the vertex (c = 0), or as the
  // first (c = 1) or second (c = 2) end of the edge
  template <class F>
  void for_each_pair_of(std::size_t i, const F& f) const
  {
    const std::size_t n = disk_.border.size(), k = std::size_t(border_pos_[i]);
    const std::size_t prev = (k + n - 1) % n;
    for(std::size_t e = 0; e < n; ++e) if(barrier_pair(k, e)) f(k, e, 0);          // i is the vertex
    for(std::size_t j = 0; j < n; ++j)
    {
      if(barrier_pair(j, k)) f(j, k, 1);       // i is the first end of edge k
      if(barrier_pair(j, prev)) f(j, prev, 2); // i is the second end of edge prev
    }
  }

  // the pairs that involve border vertex i and may be within their reach after i moves by up to
  // `radius` (current positions)
  void pairs_of(std::size_t i, double radius, std::vector<Barrier_pair>& out) const
  {
    const std::size_t n = disk_.border.size();
    out.clear();
    for_each_pair_of(i, [&](std::size_t k, std::size_t e, int c) {
      const std::size_t v = disk_.border[k], a = disk_.border[e], b = disk_.border[(e + 1) % n];
      const double r = barrier_reach(k, e) + radius;
      if(X_[v] < (std::min)(X_[a], X_[b]) - r || X_[v] > (std::max)(X_[a], X_[b]) + r ||
         Y_[v] < (std::min)(Y_[a], Y_[b]) - r || Y_[v] > (std::max)(Y_[a], Y_[b]) + r) return;
      out.push_back(Barrier_pair{ k, e, c });
    });
  }

  // The pairs of `pairs` (pairs_of(i)), with i at (xi, yi): their energy added to E, gradient to g
  // and Gauss-Newton Hessian to H (in i's two coordinates); false if i touches an edge or an edge
  // of i touches a vertex.
  bool vertex_barrier(std::size_t i, double xi, double yi, const std::vector<Barrier_pair>& pairs,
                      double& E, double g[2], double H[3]) const
  {
    for(const Barrier_pair& p : pairs)
    {
      double gp[6], e1 = 0, e2 = 0;
      bool active;
      if(!barrier_pair_terms(p.k, p.e, X_, Y_, E, gp, e1, e2, active, i, xi, yi)) return false;
      if(!active) continue;
      const double gx = gp[2 * p.c], gy = gp[2 * p.c + 1];
      g[0] += e1 * gx; g[1] += e1 * gy;
      H[0] += e2 * gx * gx; H[1] += e2 * gx * gy; H[2] += e2 * gy * gy;
    }
    return std::isfinite(E);
  }

  // first time at which border vertex i, moving alone along d, makes a pair of `pairs` touch
  double vertex_contact_time(const double d[2], const std::vector<Barrier_pair>& pairs) const
  {
    const std::size_t n = disk_.border.size();
    double t = std::numeric_limits<double>::infinity();
    for(const Barrier_pair& p : pairs)
    {
      const std::size_t v = disk_.border[p.k], a = disk_.border[p.e], b = disk_.border[(p.e + 1) % n];
      const double dv[2] = { p.c == 0 ? d[0] : 0., p.c == 0 ? d[1] : 0. };
      const double da[2] = { p.c == 1 ? d[0] : 0., p.c == 1 ? d[1] : 0. };
      const double db[2] = { p.c == 2 ? d[0] : 0., p.c == 2 ? d[1] : 0. };
      t = (std::min)(t, vertex_segment_contact_time(X_[v], Y_[v], X_[a], Y_[a], X_[b], Y_[b],
                                                    dv[0], dv[1], da[0], da[1], db[0], db[1]));
    }
    return t;
  }

  static constexpr long direct_solver_limit = 100000; // unknowns (2 per free vertex)
  static constexpr int cg_iterations = 200;            // per Newton step, above the direct solver's limit
  static constexpr double cg_tolerance = 1e-6;         // relative residual

  const TriangleMesh& tm_;
  VertexUVMap uvm_;
  VertexPointMap vpm_;
  Settings s_;
  Traits traits_;
  typename Traits::Exact_orientation_2 orient_;
  Indexed_domain<TriangleMesh> domain_;  // the loops of a multiply connected map (domain_.disk: faces, outer loop)
  Indexed_disk<TriangleMesh>& disk_;
  bool holes_ = false;                   // several border loops
  bool immersion_ = false;               // the map is an immersion (border fixed, overlapping itself)
  std::vector<int> border_turns_;        // an immersion: the input's full turns per border fan, kept
  std::vector<std::size_t> hole_free_;   // free vertices of the hole loops
  std::vector<std::size_t> hole_position_; // per hole vertex: its position in its loop
  std::size_t nv_ = 0, nf_ = 0;
  double sgn_ = 1;
  CGAL::Orientation positive_ = CGAL::LEFT_TURN;
  std::vector<long> var_;
  long nfree_ = 0;
  std::vector<std::size_t> border_free_;
  std::vector<Point_2> P_;
  std::vector<double> X_, Y_;
  std::vector<Face_frame> frames_;
  mutable std::vector<Eigen::Matrix2d> metric_;       // the face metric at the positions last evaluated
  double total_weight_ = 1;
  double certificate_weight_ = 1;   // the weights of the faces with a 3D area (see energy())
  std::vector<char> stand_in_;      // per face: its reference is a stand-in (no 3D area)
  bool has_stand_ins_ = false;
  bool scale_free_ = false;     // the energy of the map scaled to the references' area (match_reference_area())
  double reference_area_ = 1;   // the total area of the references (frames_) as last scaled
  std::vector<std::vector<Face_corner> > star_;
  std::vector<std::vector<std::size_t> > colours_;
  std::vector<std::array<int, 9> > face_slots_; // per face: where its 3x3 vertex blocks start in H_'s storage
  std::vector<std::size_t> diagonal_slots_;      // where the diagonal entries are in H_'s storage
  SpMat H_;
  Eigen::SimplicialLDLT<SpMat> ldlt_;
  bool analyzed_ = false;
  // reuse of the factorization (run()): ldlt_ holds one, the next step may use it, the relative
  // decrease of the last step with a fresh one, and the factorizations made
  bool factor_ready_ = false;
  bool reuse_next_ = false;
  bool step_reused_ = false; // the last global step used the last factorization
  double fresh_gain_ = 0;
  std::size_t factorizations_ = 0;
  static constexpr double reuse_gain_ratio = 0.5;
  bool held_back_ = false; // the last global step was limited by the flip-free (or border contact) bound
  // vertices held still by the global steps (loops in contact, see global_step()); holding_: any
  std::vector<char> held_;
  bool holding_ = false;
  std::vector<std::array<std::size_t, 4> > contact_; // the loop edges touching at the last failed line search
  static constexpr int max_hold_attempts = 4;
  bool barrier_ = false;   // the border barrier is on (free border of a disk)
  double barrier_reach_ = 0.5;           // reach of a pair, relative to the shortest reference edge length
  std::vector<std::array<double, 3> > points_3_; // the 3D points, normalized (build_frames())
  double reference_scale_ = 1;           // the scale of the reference triangles (on lengths) when they were built
  std::vector<long> border_pos_;         // per vertex: its position on the border, -1 inside
  std::vector<double> edge_length_;      // per border edge (from border position k to k + 1): its reference length
  std::vector<double> vertex_length_;    // per border vertex: the shorter reference length of its two border edges
  double max_reach_ = 0;                 // the largest reach of a pair (reach_scale_ included)
  double reach_scale_ = 1;               // the references' lengths against those the barrier was built with
  std::vector<std::array<std::size_t, 4> > block_slots_; // per free vertex: its 2x2 block of H_
  Block_cg<ConcurrencyTag> cg_;
  bool cg_ready_ = false;
};

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_DISTORTION_OPTIMIZER_H
