// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_SOLVE_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_SOLVE_H

// Solvers of the Tutte system (internal/tutte_system.h) and the progress/time budget.
//  - solve_with_solver_traits: a model of SparseLinearAlgebraWithFactorTraits_d (the user's, or Eigen's
//    LU through CGAL::Eigen_solver_traits for a non-symmetric floating-point system). Its factorization
//    cannot be observed: progress is reported before and after, and the clock read there.
//  - solve_symmetric_default: a symmetric double system, Eigen's LDLT or, for large systems, conjugate gradients
//    with the multigrid preconditioner (a whole mesh's map) or CHOLMOD's supernodal Cholesky (a patch's, when
//    built with it), on an Eigen matrix built in place; progress as above (and per CG iteration).
//  - solve_by_elimination: sparse Gaussian elimination in the number type itself, in a
//    fill-reducing order (AMD on the symmetric pattern), for multiprecision and exact types
//    (for CGAL::Gmpq, the fallback of the p-adic solve of internal/tutte_p_adic.h). The pattern of
//    the factors comes first from the elimination tree (Symbolic_factorization, shared with the
//    p-adic solve); the rows are then computed one by one through a dense work row. MPFR at the
//    default precision works in place on raw mpfr_t numbers (same operations, same bits as
//    CGAL::Gmpfr's operators, without an allocation per operation).
//    No pivoting is needed: the Tutte matrix is a nonsingular M-matrix (weakly diagonally
//    dominant, strictly on rows next to the border, irreducible) and every Schur complement of
//    an M-matrix is one, so every pivot is positive. Progress is the fraction of the
//    elimination work done (from the symbolic pass), reported and checked against the clock
//    after each row.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/tutte_system.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Progressive_embedding/internal/mpfr_numbers.h>
#include <CGAL/Progressive_embedding/Smoothed_aggregation_preconditioner.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_vector.h>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <Eigen/SparseCholesky>
#include <Eigen/OrderingMethods>
#ifdef CGAL_PROGRESSIVE_EMBEDDING_CHOLMOD_ENABLED
#include <CGAL/Progressive_embedding/internal/cholmod_runtime.h>
#include <Eigen/CholmodSupport>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// The default solver in floating point: sparse LDLT for a symmetric system, sparse LU
// (COLAMD) otherwise -- LDLT instantiates sqrt and does not compile for rationals.
template <class FT, bool symmetric>
struct Default_tutte_solver
{
  typedef CGAL::Eigen_solver_traits<
            Eigen::SparseLU<typename CGAL::Eigen_sparse_matrix<FT>::EigenType, Eigen::COLAMDOrdering<int> > > type;
};
template <>
struct Default_tutte_solver<double, true>
{
  typedef CGAL::Eigen_solver_traits<
            Eigen::SimplicialLDLT<typename CGAL::Eigen_sparse_matrix<double>::EigenType> > type;
};

// CHOLMOD's supernodal Cholesky factorization (SuiteSparse, through Eigen's CholmodSupport) when the
// package is built with it (CMake defines CGAL_PROGRESSIVE_EMBEDDING_CHOLMOD_ENABLED where CHOLMOD is
// found): the default solver of a symmetric double system from `cholmod_minimum_unknowns` unknowns on.
// Below that size Eigen's simplicial LDLT is as fast, and keeping it there keeps the Tutte maps of the
// corpus and of the tests those of the solver they were measured with. The threshold comes from
// benchmark/results/large_meshes.md (grid disks: equal times at 65k unknowns, CHOLMOD ahead from 262k on).
constexpr std::size_t cholmod_minimum_unknowns = 100000;

// CHOLMOD's relaxed amalgamation of supernodes (cholmod_common::zrelax, for supernodes of fewer than 4,
// 16 and 48 columns): merging two supernodes into one larger dense block stores the zeros between them, and
// CHOLMOD's defaults {0.8, 0.1, 0.05} let the merged blocks be up to 80%, 10% and 5% zeros. At 1M unknowns
// (the grid disk) those zeros are about 92 MB of the 793 MB CHOLMOD uses, and the larger blocks did not make the
// factorization measurably faster (benchmark/results/large_meshes_memory.md): the package asks for
// {0, 0.05, 0.01}.
constexpr double cholmod_zrelax[3] = { 0, 0.05, 0.01 };

#ifdef CGAL_PROGRESSIVE_EMBEDDING_CHOLMOD_ENABLED
typedef CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<typename CGAL::Eigen_sparse_matrix<double>::EigenType> >
  Cholmod_tutte_solver;
#endif

// Conjugate gradients preconditioned by Smoothed_aggregation_preconditioner: the default solver of a whole
// mesh's symmetric double system from `multigrid_minimum_unknowns` unknowns on (where CHOLMOD took over from
// Eigen's LDLT before), to a relative residual of `multigrid_tolerance`, at most `multigrid_maximum_iterations`
// iterations per coordinate (then the direct solvers take over). Measured on grid disks of 262k, 1M and 4M
// vertices: 2.2-4x faster than CHOLMOD, about three quarters of its peak memory; on a 250k-vertex Tutte failure
// the same repair time (benchmark/results/large_meshes.md, large_meshes_memory.md). The patches of constrained maps, whose refined meshes
// have slivers, keep the direct solvers.
constexpr std::size_t multigrid_minimum_unknowns = 100000;
constexpr double multigrid_tolerance = 1e-10;
constexpr int multigrid_maximum_iterations = 500;

// true if the default solver of a symmetric double system of `unknowns` unknowns is the multigrid one
inline bool default_tutte_solver_is_multigrid(std::size_t unknowns) { return unknowns >= multigrid_minimum_unknowns; }

// true if the default solver of a symmetric double system of `unknowns` unknowns is CHOLMOD's, for a whole
// mesh's map (`whole_mesh`) or for a patch of a constrained map (solved directly at every size)
inline bool default_tutte_solver_is_cholmod(std::size_t unknowns, bool whole_mesh = true)
{
#ifdef CGAL_PROGRESSIVE_EMBEDDING_CHOLMOD_ENABLED
  return unknowns >= cholmod_minimum_unknowns && !(whole_mesh && default_tutte_solver_is_multigrid(unknowns));
#else
  (void)unknowns;
  (void)whole_mesh;
  return false;
#endif
}

// A progress callback and a running-time limit. `report(f)` calls the callback with the
// fraction f done (at most about every thousandth, and at 0 and 1) and returns false when the
// callback asks to stop or the time is over.
class Progress_budget
{
public:
  Progress_budget(std::function<bool(double)> callback = std::function<bool(double)>(),
                  double max_seconds = std::numeric_limits<double>::infinity())
    : m_callback(callback), m_max_seconds(max_seconds), m_start(std::chrono::steady_clock::now())
  { }

  bool has_callback() const { return static_cast<bool>(m_callback); }

  bool time_left() const
  {
    if(m_max_seconds == std::numeric_limits<double>::infinity()) return true;
    const std::chrono::duration<double> d = std::chrono::steady_clock::now() - m_start;
    return d.count() < m_max_seconds;
  }

  bool report(double fraction)
  {
    // never backwards (a solver that falls back on another one starts again from 0)
    if(m_callback && fraction >= m_last && (m_last < 0 || fraction >= 1 || fraction >= m_last + 1e-3) && m_last < 1)
    {
      m_last = fraction;
      if(!m_callback((std::min)(1., (std::max)(0., fraction)))) return false;
    }
    return time_left();
  }

private:
  std::function<bool(double)> m_callback;
  double m_max_seconds;
  std::chrono::steady_clock::time_point m_start;
  double m_last = -1;
};

// Solves with a model of SparseLinearAlgebraWithFactorTraits_d (square matrix constructor:
// CGAL 5.5's rectangular Eigen_sparse_matrix constructor reads a member before setting it).
template <class FT, class Solver>
Error_code solve_with_solver_traits(const Tutte_system<FT>& S, Solver solver, Progress_budget& budget,
                                    std::vector<FT>& xu, std::vector<FT>& xv)
{
  typedef typename Solver::Matrix Matrix;
  typedef typename Solver::Vector Vector;
  typedef typename Solver::Index Index;
  if(!budget.report(0)) return ERROR_BUDGET_EXHAUSTED;
  const std::size_t n = S.n;
  Matrix A(n);
  Vector Bu(static_cast<Index>(n)), Bv(static_cast<Index>(n)), Xu(static_cast<Index>(n)), Xv(static_cast<Index>(n));
  for(std::size_t r = 0; r < n; ++r)
  {
    Bu[static_cast<Index>(r)] = S.bu[r];
    Bv[static_cast<Index>(r)] = S.bv[r];
    for(const auto& e : S.off[r]) A.set_coef(r, e.first, e.second, true);
    A.set_coef(r, r, S.diag[r], true);
  }
  FT D = make_ft<FT>(1);
  if(!solver.factor(A, D)) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  if(!budget.report(0.5)) return ERROR_BUDGET_EXHAUSTED;
  if(!solver.linear_solver(Bu, Xu) || !solver.linear_solver(Bv, Xv)) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  xu.resize(n); xv.resize(n);
  for(std::size_t r = 0; r < n; ++r)
  {
    xu[r] = Xu[static_cast<Index>(r)] / D;
    xv[r] = Xv[static_cast<Index>(r)] / D;
  }
  if(!budget.report(1)) return ERROR_BUDGET_EXHAUSTED;
  return OK;
}

// The default double solvers of a symmetric system (Eigen's LDLT, CHOLMOD) on an Eigen matrix built in place:
// no triplet list and no second copy as through CGAL::Eigen_sparse_matrix (at 1M unknowns the triplets alone
// are 112 MB), and the rows of the system released once the matrix holds them. The matrix holds the lower
// triangle only, the one both solvers read (Eigen's LDLT and its AMD ordering through selfadjointView<Lower>,
// CHOLMOD as stype -1): the same entries there as the matrix solve_with_solver_traits() assembles, so Eigen's
// LDLT computes the same map, bit for bit, and the matrix is 4 entries per unknown instead of 7 (36 MB less
// at 1M unknowns, while the factor is being computed).
// `configure(solver)` runs before the factorization. The right-hand sides are given by their nonzeros
// (`b`: unknown, u, v), rows next to the border only, and made dense one at a time once the factor
// is computed: 16 MB less at 1M unknowns while it is.
template <class EigenSolver, class Configure>
Error_code solve_symmetric_with_eigen(const Eigen::SparseMatrix<double>& A,
                                      const std::vector<std::tuple<Eigen::Index, double, double> >& b,
                                      Progress_budget& budget, std::vector<double>& xu, std::vector<double>& xv,
                                      const Configure& configure)
{
  const Eigen::Index n = A.rows();
  EigenSolver solver;
  configure(solver);
  solver.compute(A);
  if(solver.info() != Eigen::Success) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  if(!budget.report(0.5)) return ERROR_BUDGET_EXHAUSTED;
  auto solve = [&](bool second, std::vector<double>& x) {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
    for(const auto& e : b) rhs[std::get<0>(e)] = second ? std::get<2>(e) : std::get<1>(e);
    const Eigen::VectorXd sol = solver.solve(rhs);
    if(solver.info() != Eigen::Success) return false;
    x.assign(sol.data(), sol.data() + n);
    return true;
  };
  if(!solve(false, xu) || !solve(true, xv)) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  if(!budget.report(1)) return ERROR_BUDGET_EXHAUSTED;
  return OK;
}

// Conjugate gradients preconditioned by one multigrid V-cycle, on the whole symmetric matrix `A`, for each
// right-hand side (given by its nonzeros, as above), from zero to a relative residual of `tolerance`. The clock
// and the callback are read at every iteration. ERROR_CANNOT_SOLVE_LINEAR_SYSTEM if the preconditioner refuses
// the matrix or an iteration budget runs out (the caller then solves directly).
inline Error_code solve_symmetric_with_multigrid(const Eigen::SparseMatrix<double>& A,
                                                 const std::vector<std::tuple<Eigen::Index, double, double> >& b,
                                                 Progress_budget& budget, std::vector<double>& xu, std::vector<double>& xv,
                                                 double tolerance, int maximum_iterations)
{
  typedef Eigen::VectorXd Vector;
  const Eigen::Index n = A.rows();
  const Smoothed_aggregation_preconditioner<double> M(A);
  if(M.info() != Eigen::Success) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  if(!budget.report(0.2)) return ERROR_BUDGET_EXHAUSTED;
  Error_code status = OK;
  auto solve = [&](bool second, std::vector<double>& out) {
    Vector r = Vector::Zero(n);
    for(const auto& e : b) r[std::get<0>(e)] = second ? std::get<2>(e) : std::get<1>(e);
    Vector x = Vector::Zero(n);
    const double bound = tolerance * r.norm();
    Vector z = M.solve(r), p = z, Ap(n);
    double rz = r.dot(z);
    for(int k = 0;; ++k)
    {
      const double residual = r.norm();
      if(!(residual > bound))
      {
        if(std::isfinite(residual)) break;
        status = ERROR_CANNOT_SOLVE_LINEAR_SYSTEM; // not a number: the direct solvers decide
        return false;
      }
      if(k == maximum_iterations) { status = ERROR_CANNOT_SOLVE_LINEAR_SYSTEM; return false; }
      if(!budget.report((second ? 0.6 : 0.2) + 0.4 * double(k) / maximum_iterations)) { status = ERROR_BUDGET_EXHAUSTED; return false; }
      Ap.noalias() = A * p;
      const double alpha = rz / p.dot(Ap);
      x += alpha * p;
      r -= alpha * Ap;
      z = M.solve(r);
      const double rz_next = r.dot(z);
      p = z + (rz_next / rz) * p;
      rz = rz_next;
    }
    out.assign(x.data(), x.data() + n);
    return true;
  };
  if(!solve(false, xu) || !solve(true, xv)) return status;
  if(!budget.report(1)) return ERROR_BUDGET_EXHAUSTED;
  return OK;
}

// Solves a symmetric double system with the default solver for its size (the multigrid solve only where
// `allow_multigrid`); the system's vectors are released on the way (once the matrix holds them).
inline Error_code solve_symmetric_default(Tutte_system<double>& S, Progress_budget& budget,
                                          std::vector<double>& xu, std::vector<double>& xv, bool allow_multigrid = false)
{
  if(!budget.report(0)) return ERROR_BUDGET_EXHAUSTED;
  const Eigen::Index n = static_cast<Eigen::Index>(S.n);
  const bool multigrid = allow_multigrid && default_tutte_solver_is_multigrid(S.n);
  // the direct solvers read the entries below the diagonal (column r holds those of row r), the multigrid
  // solve the whole matrix
  auto kept = [multigrid](std::size_t c, Eigen::Index r) { return multigrid || static_cast<Eigen::Index>(c) > r; };
  Eigen::SparseMatrix<double> A(n, n);
  {
    Eigen::VectorXi sizes(n);
    for(Eigen::Index r = 0; r < n; ++r)
    {
      sizes[r] = 1;
      for(const auto& e : S.off[static_cast<std::size_t>(r)]) sizes[r] += kept(e.first, r) ? 1 : 0;
    }
    A.reserve(sizes);
  }
  for(Eigen::Index r = 0; r < n; ++r)
  {
    A.insert(r, r) = S.diag[static_cast<std::size_t>(r)];
    for(const auto& e : S.off[static_cast<std::size_t>(r)])
      if(kept(e.first, r)) A.insert(static_cast<Eigen::Index>(e.first), r) = e.second;
  }
  A.makeCompressed();
  std::vector<std::vector<std::pair<std::size_t, double> > >().swap(S.off);
  std::vector<double>().swap(S.diag);
  std::vector<std::tuple<Eigen::Index, double, double> > b;
  for(std::size_t r = 0; r < S.n; ++r)
    if(S.bu[r] != 0 || S.bv[r] != 0 || std::signbit(S.bu[r]) || std::signbit(S.bv[r])) // -0 kept: same bits
      b.emplace_back(static_cast<Eigen::Index>(r), S.bu[r], S.bv[r]);
  std::vector<double>().swap(S.bu);
  std::vector<double>().swap(S.bv);
  if(multigrid)
  {
    const Error_code ec = solve_symmetric_with_multigrid(A, b, budget, xu, xv, multigrid_tolerance, multigrid_maximum_iterations);
    if(ec != ERROR_CANNOT_SOLVE_LINEAR_SYSTEM) return ec;
    A = Eigen::SparseMatrix<double>(A.triangularView<Eigen::Lower>()); // the direct solvers take over
  }
#ifdef CGAL_PROGRESSIVE_EMBEDDING_CHOLMOD_ENABLED
  // CHOLMOD for large systems; Eigen's LDLT if it refuses the matrix
  if(S.n >= cholmod_minimum_unknowns)
  {
    use_huge_pages_for_cholmod();
    release_free_heap_memory();
    const Cholmod_dynamic_threads threads;
    typedef Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double> > Cholmod;
    const Error_code ec = solve_symmetric_with_eigen<Cholmod>(A, b, budget, xu, xv, [](Cholmod& c) {
      for(int k = 0; k < 3; ++k) c.cholmod().zrelax[k] = cholmod_zrelax[k];
    });
    if(ec != ERROR_CANNOT_SOLVE_LINEAR_SYSTEM) return ec;
  }
#endif
  typedef Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > Ldlt;
  return solve_symmetric_with_eigen<Ldlt>(A, b, budget, xu, xv, [](Ldlt&) { });
}

// A fill-reducing elimination order of the system's (symmetric) pattern: order[k] is the
// unknown eliminated at step k (approximate minimum degree).
template <class FT>
std::vector<int> fill_reducing_order(const Tutte_system<FT>& S)
{
  const int n = static_cast<int>(S.n);
  std::vector<Eigen::Triplet<double, int> > trip;
  for(int r = 0; r < n; ++r)
  {
    trip.emplace_back(r, r, 1.);
    for(const auto& e : S.off[r]) trip.emplace_back(r, static_cast<int>(e.first), 1.);
  }
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> pattern(n, n);
  pattern.setFromTriplets(trip.begin(), trip.end());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> perm;
  Eigen::AMDOrdering<int> amd;
  amd(pattern, perm);
  std::vector<int> order(perm.indices().data(), perm.indices().data() + perm.indices().size());
  // a permutation of 0..n-1 is expected; anything else falls back on the natural order
  std::vector<char> seen(n, 0);
  bool ok = static_cast<int>(order.size()) == n;
  for(int k = 0; ok && k < n; ++k)
  {
    if(order[k] < 0 || order[k] >= n || seen[order[k]]) ok = false;
    else seen[order[k]] = 1;
  }
  if(!ok) { order.resize(n); for(int k = 0; k < n; ++k) order[k] = k; }
  return order;
}

// The symbolic factorization of the system's (structurally symmetric) pattern in an elimination
// order: the elimination tree gives the pattern of every row of L (its reach in the tree) and, by
// symmetry, of every row of U, before any arithmetic. The numeric factorizations (modular for the
// p-adic solve, in FT for the elimination) then run row by row ("up-looking") through a dense work
// row, with no merge of sparse rows and no allocation per update.
struct Symbolic_factorization
{
  std::size_t n = 0;
  std::vector<int> order, step;        // order[k]: unknown eliminated at step k; step[order[k]] == k
  std::vector<int> a_ptr, a_col, a_src; // A in step numbering, row k sorted; a_src: -1 the diagonal, else index in S.off[order[k]]
  std::vector<int> l_ptr, l_col;       // row k of L: columns j < k, increasing
  std::vector<int> u_ptr, u_col;       // row k of U: columns c > k, increasing (the diagonal apart)
  double flops = 0;                    // multiply-adds of the numeric factorization

  template <class FT>
  void analyze(const Tutte_system<FT>& S, const std::vector<int>& elimination_order)
  {
    n = S.n;
    order = elimination_order;
    step.assign(n, 0);
    for(std::size_t k = 0; k < n; ++k) step[order[k]] = static_cast<int>(k);
    a_ptr.assign(n + 1, 0);
    for(std::size_t k = 0; k < n; ++k) a_ptr[k + 1] = a_ptr[k] + 1 + static_cast<int>(S.off[order[k]].size());
    a_col.resize(a_ptr[n]); a_src.resize(a_ptr[n]);
    std::vector<std::pair<int, int> > row;
    for(std::size_t k = 0; k < n; ++k)
    {
      const auto& off = S.off[order[k]];
      row.clear();
      row.emplace_back(static_cast<int>(k), -1);
      for(std::size_t e = 0; e < off.size(); ++e) row.emplace_back(step[off[e].first], static_cast<int>(e));
      std::sort(row.begin(), row.end());
      for(std::size_t e = 0; e < row.size(); ++e) { a_col[a_ptr[k] + e] = row[e].first; a_src[a_ptr[k] + e] = row[e].second; }
    }
    // elimination tree (path compression through `ancestor`), on the pattern made symmetric
    std::vector<int> parent(n, -1), ancestor(n, -1);
    for(std::size_t k = 0; k < n; ++k)
      for(int e = a_ptr[k]; e < a_ptr[k + 1]; ++e)
        for(int j = a_col[e]; j != -1 && j < static_cast<int>(k); )
        {
          const int next = ancestor[j];
          ancestor[j] = static_cast<int>(k);
          if(next == -1) { parent[j] = static_cast<int>(k); break; }
          j = next;
        }
    // row k of L: the nodes met climbing the tree from each j < k of row k of A up to k
    std::vector<int> mark(n, -1);
    l_ptr.assign(n + 1, 0);
    l_col.clear();
    std::vector<int> u_count(n, 0);
    for(std::size_t k = 0; k < n; ++k)
    {
      mark[k] = static_cast<int>(k);
      const std::size_t first = l_col.size();
      for(int e = a_ptr[k]; e < a_ptr[k + 1]; ++e)
        for(int j = a_col[e]; j < static_cast<int>(k) && mark[j] != static_cast<int>(k); j = parent[j])
        {
          mark[j] = static_cast<int>(k);
          l_col.push_back(j);
        }
      std::sort(l_col.begin() + first, l_col.end());
      for(std::size_t e = first; e < l_col.size(); ++e) ++u_count[l_col[e]];
      l_ptr[k + 1] = static_cast<int>(l_col.size());
    }
    // the pattern is symmetric: column k of L is row k of U
    u_ptr.assign(n + 1, 0);
    for(std::size_t k = 0; k < n; ++k) u_ptr[k + 1] = u_ptr[k] + u_count[k];
    u_col.resize(u_ptr[n]);
    std::vector<int> fill(u_ptr.begin(), u_ptr.end() - 1);
    for(std::size_t k = 0; k < n; ++k)
      for(int e = l_ptr[k]; e < l_ptr[k + 1]; ++e) u_col[fill[l_col[e]]++] = static_cast<int>(k);
    flops = 0;
    for(std::size_t k = 0; k < n; ++k)
      for(int e = l_ptr[k]; e < l_ptr[k + 1]; ++e) flops += double(u_ptr[l_col[e] + 1] - u_ptr[l_col[e]]) + 1;
  }
};

// The value of entry `e` of row k of the symbolic structure (a_src: -1 the diagonal).
template <class FT>
const FT& system_entry(const Tutte_system<FT>& S, const Symbolic_factorization& F, std::size_t k, int e)
{
  const std::size_t r = static_cast<std::size_t>(F.order[k]);
  return F.a_src[e] < 0 ? S.diag[r] : S.off[r][static_cast<std::size_t>(F.a_src[e])].second;
}

// Sparse Gaussian elimination in FT, row by row on the symbolic structure (entries that cancel are
// kept), with both right-hand sides, then back substitution. Every entry receives the updates of
// the earlier pivots in increasing order, each rounded as `a - (a_ik / a_kk) * a_kj`: the
// operations of a right-looking elimination in the same order, so the same values.
template <class FT>
Error_code solve_by_elimination_generic(const Tutte_system<FT>& S, const Symbolic_factorization& F, Progress_budget& budget,
                                        std::vector<FT>& xu, std::vector<FT>& xv)
{
  const std::size_t n = S.n;
  const FT zero = make_ft<FT>(0);
  std::vector<FT> uval(F.u_col.size()), pivot(n), bu(n), bv(n), w(n, zero);
  double done = 0;
  for(std::size_t k = 0; k < n; ++k)
  {
    for(int e = F.a_ptr[k]; e < F.a_ptr[k + 1]; ++e) w[F.a_col[e]] = system_entry(S, F, k, e);
    FT su = S.bu[F.order[k]], sv = S.bv[F.order[k]];
    for(int e = F.l_ptr[k]; e < F.l_ptr[k + 1]; ++e)
    {
      const int j = F.l_col[e];
      if(CGAL::is_zero(pivot[j])) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      const FT m = w[j] / pivot[j];
      w[j] = zero;
      for(int f = F.u_ptr[j]; f < F.u_ptr[j + 1]; ++f) w[F.u_col[f]] -= m * uval[f];
      su -= m * bu[j];
      sv -= m * bv[j];
      done += double(F.u_ptr[j + 1] - F.u_ptr[j]) + 1;
    }
    pivot[k] = w[k]; w[k] = zero;
    if(CGAL::is_zero(pivot[k])) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    for(int f = F.u_ptr[k]; f < F.u_ptr[k + 1]; ++f) { uval[f] = w[F.u_col[f]]; w[F.u_col[f]] = zero; }
    bu[k] = su; bv[k] = sv;
    if(!budget.report(F.flops > 0 ? done / F.flops : 1.)) return ERROR_BUDGET_EXHAUSTED;
  }
  std::vector<FT> yu(n, zero), yv(n, zero);
  for(std::size_t kk = n; kk-- > 0; )
  {
    FT su = bu[kk], sv = bv[kk];
    for(int f = F.u_ptr[kk]; f < F.u_ptr[kk + 1]; ++f)
    {
      su -= uval[f] * yu[F.u_col[f]];
      sv -= uval[f] * yv[F.u_col[f]];
    }
    yu[kk] = su / pivot[kk];
    yv[kk] = sv / pivot[kk];
  }
  xu.resize(n); xv.resize(n);
  for(std::size_t k = 0; k < n; ++k) { xu[F.order[k]] = yu[k]; xv[F.order[k]] = yv[k]; }
  return budget.report(1) ? OK : ERROR_BUDGET_EXHAUSTED;
}

// The same elimination on raw MPFR numbers at the default precision, in place: CGAL::Gmpfr's
// operators allocate a reference-counted result for every operation, which costs far more than the
// operation at a few hundred bits. Taken when no entry of the system is more precise than the default
// precision: then every value of the generic elimination has the default precision and the default
// rounding, so both give the same bits.
inline Error_code solve_by_elimination_mpfr(const Tutte_system<CGAL::Gmpfr>& S, const Symbolic_factorization& F, Progress_budget& budget,
                                            std::vector<CGAL::Gmpfr>& xu, std::vector<CGAL::Gmpfr>& xv)
{
  const std::size_t n = S.n;
  const mpfr_prec_t prec = static_cast<mpfr_prec_t>(CGAL::Gmpfr::get_default_precision());
  const mpfr_rnd_t rnd = mpfr_get_default_rounding_mode();
  Mpfr_numbers uval(F.u_col.size(), prec), pivot(n, prec), bu(n, prec), bv(n, prec), w(n, prec), tmp(3, prec);
  mpfr_ptr m = tmp[0], t = tmp[1];
  double done = 0;
  for(std::size_t k = 0; k < n; ++k)
  {
    for(int e = F.a_ptr[k]; e < F.a_ptr[k + 1]; ++e) mpfr_set(w[F.a_col[e]], system_entry(S, F, k, e).fr(), rnd);
    mpfr_set(bu[k], S.bu[F.order[k]].fr(), rnd);
    mpfr_set(bv[k], S.bv[F.order[k]].fr(), rnd);
    for(int e = F.l_ptr[k]; e < F.l_ptr[k + 1]; ++e)
    {
      const int j = F.l_col[e];
      if(mpfr_zero_p(pivot[j])) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      mpfr_div(m, w[j], pivot[j], rnd);
      mpfr_set_zero(w[j], 1);
      for(int f = F.u_ptr[j]; f < F.u_ptr[j + 1]; ++f)
      {
        mpfr_mul(t, m, uval[f], rnd);
        mpfr_sub(w[F.u_col[f]], w[F.u_col[f]], t, rnd);
      }
      mpfr_mul(t, m, bu[j], rnd); mpfr_sub(bu[k], bu[k], t, rnd);
      mpfr_mul(t, m, bv[j], rnd); mpfr_sub(bv[k], bv[k], t, rnd);
      done += double(F.u_ptr[j + 1] - F.u_ptr[j]) + 1;
    }
    mpfr_swap(pivot[k], w[k]);
    mpfr_set_zero(w[k], 1);
    if(mpfr_zero_p(pivot[k])) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    for(int f = F.u_ptr[k]; f < F.u_ptr[k + 1]; ++f) { mpfr_swap(uval[f], w[F.u_col[f]]); mpfr_set_zero(w[F.u_col[f]], 1); }
    if(!budget.report(F.flops > 0 ? done / F.flops : 1.)) return ERROR_BUDGET_EXHAUSTED;
  }
  // back substitution into bu, bv (row k is final once the rows after it are)
  for(std::size_t kk = n; kk-- > 0; )
  {
    for(int f = F.u_ptr[kk]; f < F.u_ptr[kk + 1]; ++f)
    {
      mpfr_mul(t, uval[f], bu[F.u_col[f]], rnd); mpfr_sub(bu[kk], bu[kk], t, rnd);
      mpfr_mul(t, uval[f], bv[F.u_col[f]], rnd); mpfr_sub(bv[kk], bv[kk], t, rnd);
    }
    mpfr_div(bu[kk], bu[kk], pivot[kk], rnd);
    mpfr_div(bv[kk], bv[kk], pivot[kk], rnd);
  }
  xu.resize(n); xv.resize(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    xu[F.order[k]] = to_gmpfr(bu[k], prec);
    xv[F.order[k]] = to_gmpfr(bv[k], prec);
  }
  return budget.report(1) ? OK : ERROR_BUDGET_EXHAUSTED;
}

// Sparse Gaussian elimination in FT in a fill-reducing order (AMD), with both right-hand sides,
// for multiprecision and exact types. MPFR systems at the default precision take the in-place path.
template <class FT>
Error_code solve_by_elimination(const Tutte_system<FT>& S, Progress_budget& budget, std::vector<FT>& xu, std::vector<FT>& xv)
{
  if(!budget.report(0)) return ERROR_BUDGET_EXHAUSTED;
  Symbolic_factorization F;
  F.analyze(S, fill_reducing_order(S));
  if constexpr(std::is_same<FT, CGAL::Gmpfr>::value)
  {
    const CGAL::Gmpfr::Precision_type p = CGAL::Gmpfr::get_default_precision();
    bool uniform = true;
    auto check = [&](const CGAL::Gmpfr& x) { if(x.get_precision() > p) uniform = false; };
    for(std::size_t r = 0; r < S.n && uniform; ++r)
    {
      check(S.diag[r]); check(S.bu[r]); check(S.bv[r]);
      for(const auto& e : S.off[r]) check(e.second);
    }
    if(uniform) return solve_by_elimination_mpfr(S, F, budget, xu, xv);
  }
  return solve_by_elimination_generic(S, F, budget, xu, xv);
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_SOLVE_H
