// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_REFINEMENT_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_REFINEMENT_H

// The Tutte system in MPFR by mixed-precision iterative refinement: the matrix is factored once in
// double (Eigen's LDLT when symmetric, its LU otherwise), and the solution is refined in MPFR,
//   r = b - A x   (MPFR, with 64 guard bits: the residual cancels),
//   d = A^-1 r    (double, r scaled by a power of two into double's range, d scaled back exactly),
//   x = x + d     (MPFR),
// so the work in MPFR is a few sparse products instead of an elimination with fill: each step gains
// about 53 - log2(cond A) bits (cond A grows like the number of vertices for a Tutte matrix), so a
// few steps reach the precision. It stops when the correction is down to the last bits of the largest
// coordinate (normwise: 2^-(precision - 4) of it), and gives up -- ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, the
// caller then runs the elimination in MPFR -- when a step does not halve the correction, when a value
// leaves double's range, or when the double factorization fails. The result is at least as accurate
// as the elimination's (whose error grows with the fill), but not bit for bit the same.
//
//   Error_code solve_by_refinement(S, symmetric, budget, xu, xv): S a Tutte_system<CGAL::Gmpfr> whose
//   entries have at most the default precision.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/tutte_system.h>
#include <CGAL/Progressive_embedding/internal/tutte_solve.h>
#include <CGAL/Progressive_embedding/internal/mpfr_numbers.h>

#include <CGAL/Gmpfr.h>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <Eigen/OrderingMethods>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// the value of x times 2^-e as a double (underflows to 0 far below the largest value, as it should)
inline double mpfr_get_d_2exp_scaled(mpfr_srcptr x, mpfr_exp_t e)
{
  if(mpfr_zero_p(x)) return 0.;
  long ex = 0;
  const double m = mpfr_get_d_2exp(&ex, x, MPFR_RNDN);  // x = m 2^ex, 0.5 <= |m| < 1
  return std::ldexp(m, static_cast<int>(ex - e));
}

// the largest exponent among the non-zero values of x: false if all are zero (then `e` is 0)
inline bool largest_exponent(const Mpfr_numbers& x, std::size_t n, mpfr_exp_t& e)
{
  bool any = false;
  e = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    if(mpfr_zero_p(x[i])) continue;
    const mpfr_exp_t ei = mpfr_get_exp(x[i]);
    if(!any || ei > e) e = ei;
    any = true;
  }
  return any;
}

// x (in MPFR) scaled by 2^-e into double, e its largest exponent: false if all are zero (then `e` is 0
// and d all zero)
inline bool scaled_to_double(const Mpfr_numbers& x, std::size_t n, mpfr_exp_t& e, Eigen::VectorXd& d)
{
  const bool any = largest_exponent(x, n, e);
  d.resize(static_cast<Eigen::Index>(n));
  for(std::size_t i = 0; i < n; ++i)
    d[static_cast<Eigen::Index>(i)] = any ? mpfr_get_d_2exp_scaled(x[i], e) : 0.;
  return any;
}

template <class DoubleSolver>
Error_code refine_tutte_solution(const Tutte_system<CGAL::Gmpfr>& S, const DoubleSolver& solver, Progress_budget& budget,
                                 const std::vector<CGAL::Gmpfr>& b, std::vector<CGAL::Gmpfr>& x_out, double progress_from,
                                 double progress_to)
{
  const std::size_t n = S.n;
  const mpfr_prec_t prec = static_cast<mpfr_prec_t>(CGAL::Gmpfr::get_default_precision());
  const mpfr_prec_t rprec = prec + 64;
  Mpfr_numbers x(n, prec), r(n, rprec), dx(n, prec), t(1, rprec);
  Eigen::VectorXd rd, d;
  // at most one step per 8 bits gained, plus a margin: the precision is reached in far fewer
  const int max_steps = static_cast<int>(prec / 8) + 8;
  double last = std::numeric_limits<double>::infinity(); // the previous correction, relative to max |x|
  for(int step = 0; step <= max_steps; ++step)
  {
    // r = b - A x
    for(std::size_t i = 0; i < n; ++i)
    {
      mpfr_set(r[i], b[i].fr(), MPFR_RNDN);
      mpfr_mul(t[0], S.diag[i].fr(), x[i], MPFR_RNDN);
      mpfr_sub(r[i], r[i], t[0], MPFR_RNDN);
      for(const auto& e : S.off[i])
      {
        mpfr_mul(t[0], e.second.fr(), x[e.first], MPFR_RNDN);
        mpfr_sub(r[i], r[i], t[0], MPFR_RNDN);
      }
    }
    mpfr_exp_t er = 0;
    if(!scaled_to_double(r, n, er, rd)) break; // the residual is exactly zero
    d = solver.solve(rd);
    if(!d.allFinite()) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    // x += d 2^er; the correction's size against the largest coordinate decides convergence
    double dmax = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      mpfr_set_d(dx[i], d[static_cast<Eigen::Index>(i)], MPFR_RNDN);
      mpfr_mul_2si(dx[i], dx[i], er, MPFR_RNDN);
      mpfr_add(x[i], x[i], dx[i], MPFR_RNDN);
      dmax = (std::max)(dmax, std::abs(d[static_cast<Eigen::Index>(i)]));
    }
    mpfr_exp_t ex = 0;
    if(!largest_exponent(x, n, ex)) break;  // x = 0 and a zero correction
    // |d|_max / |x|_max as a power of two (|x|_max in [2^(ex-1), 2^ex))
    const double rel_log2 = (dmax > 0 ? std::log2(dmax) : -std::numeric_limits<double>::infinity()) + double(er - ex) + 1;
    if(!budget.report(progress_from + (progress_to - progress_from) * (std::min)(1., double(step + 1) / 8)))
      return ERROR_BUDGET_EXHAUSTED;
    // converged: the correction is within the last 4 bits of the largest coordinate (a solution rounded to
    // the precision leaves a correction of about its last bit: x is then as accurate as it can be)
    if(rel_log2 <= 4 - double(prec)) break;
    if(step > 0 && !(rel_log2 < last - 1)) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM; // less than a bit per step
    if(step == max_steps) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    last = rel_log2;
  }
  x_out.resize(n);
  for(std::size_t i = 0; i < n; ++i) x_out[i] = to_gmpfr(x[i], prec);
  return OK;
}

inline Error_code solve_by_refinement(const Tutte_system<CGAL::Gmpfr>& S, bool symmetric, Progress_budget& budget,
                                      std::vector<CGAL::Gmpfr>& xu, std::vector<CGAL::Gmpfr>& xv)
{
  const std::size_t n = S.n;
  if(n == 0) { xu.clear(); xv.clear(); return OK; }
  const CGAL::Gmpfr::Precision_type p = CGAL::Gmpfr::get_default_precision();
  std::vector<Eigen::Triplet<double> > T;
  T.reserve(n * 7);
  for(std::size_t i = 0; i < n; ++i)
  {
    if(S.diag[i].get_precision() > p || S.bu[i].get_precision() > p || S.bv[i].get_precision() > p)
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    const double di = CGAL::to_double(S.diag[i]);
    if(!std::isfinite(di)) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    T.emplace_back(Eigen::Index(i), Eigen::Index(i), di);
    for(const auto& e : S.off[i])
    {
      if(e.second.get_precision() > p) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      const double w = CGAL::to_double(e.second);
      if(!std::isfinite(w)) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      T.emplace_back(Eigen::Index(i), Eigen::Index(e.first), w);
    }
  }
  Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  A.setFromTriplets(T.begin(), T.end());
  std::vector<Eigen::Triplet<double> >().swap(T);
  if(!budget.report(0)) return ERROR_BUDGET_EXHAUSTED;
  auto run = [&](const auto& solver) -> Error_code {
    if(solver.info() != Eigen::Success) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    if(!budget.report(0.2)) return ERROR_BUDGET_EXHAUSTED;
    const Error_code e1 = refine_tutte_solution(S, solver, budget, S.bu, xu, 0.2, 0.6);
    if(e1 != OK) return e1;
    const Error_code e2 = refine_tutte_solution(S, solver, budget, S.bv, xv, 0.6, 1.);
    if(e2 != OK) return e2;
    return budget.report(1) ? OK : ERROR_BUDGET_EXHAUSTED;
  };
  if(symmetric)
  {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > ldlt(A);
    return run(ldlt);
  }
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int> > lu;
  lu.analyzePattern(A);
  lu.factorize(A);
  return run(lu);
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_REFINEMENT_H
