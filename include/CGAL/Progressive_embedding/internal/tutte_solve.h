// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_SOLVE_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_SOLVE_H

// Solvers of the Tutte system (internal/tutte_system.h) and the progress/time budget.
//  - solve_with_solver_traits: a model of SparseLinearAlgebraWithFactorTraits_d (Eigen's LDLT
//    or LU through CGAL::Eigen_solver_traits by default in floating point). Its factorization
//    cannot be observed: progress is reported before and after, and the clock read there.
//  - solve_by_elimination: sparse Gaussian elimination in the number type itself, in a
//    fill-reducing order (AMD on the symmetric pattern), for multiprecision and exact types
//    (for CGAL::Gmpq, the fallback of the p-adic solve of internal/tutte_p_adic.h).
//    No pivoting is needed: the Tutte matrix is a nonsingular M-matrix (weakly diagonally
//    dominant, strictly on rows next to the border, irreducible) and every Schur complement of
//    an M-matrix is one, so every pivot is positive. Progress is the fraction of the
//    elimination work done (from a symbolic pass), reported and checked against the clock
//    after each updated row.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/tutte_system.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_vector.h>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <Eigen/SparseCholesky>
#include <Eigen/OrderingMethods>

#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>
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

// The rows of the system in elimination order (columns renumbered), sorted by column.
template <class FT>
void permuted_rows(const Tutte_system<FT>& S, const std::vector<int>& order,
                   std::vector<std::vector<std::pair<int, FT> > >& rows, std::vector<FT>& bu, std::vector<FT>& bv)
{
  const std::size_t n = S.n;
  std::vector<int> step(n);
  for(std::size_t k = 0; k < n; ++k) step[order[k]] = static_cast<int>(k);
  rows.assign(n, std::vector<std::pair<int, FT> >());
  bu.resize(n); bv.resize(n);
  for(std::size_t r = 0; r < n; ++r)
  {
    auto& row = rows[step[r]];
    row.reserve(S.off[r].size() + 1);
    row.emplace_back(step[r], S.diag[r]);
    for(const auto& e : S.off[r]) row.emplace_back(step[e.first], e.second);
    std::sort(row.begin(), row.end(), [](const std::pair<int, FT>& a, const std::pair<int, FT>& b) { return a.first < b.first; });
    bu[step[r]] = S.bu[r];
    bv[step[r]] = S.bv[r];
  }
}

// Symbolic elimination: the work of each step (entries updated), for progress fractions.
template <class FT>
std::vector<double> elimination_work(const std::vector<std::vector<std::pair<int, FT> > >& rows)
{
  const std::size_t n = rows.size();
  std::vector<std::vector<int> > pat(n);
  for(std::size_t k = 0; k < n; ++k)
    for(const auto& e : rows[k]) if(e.first >= int(k)) pat[k].push_back(e.first);
  std::vector<double> work(n, 0.);
  std::vector<int> merged;
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::vector<int>& pk = pat[k]; // columns >= k, pk[0] == k
    work[k] = double(pk.size()) * double(pk.size());
    for(std::size_t a = 1; a < pk.size(); ++a)
    {
      std::vector<int>& pi = pat[pk[a]];
      merged.clear();
      std::set_union(pi.begin(), pi.end(), pk.begin() + 1, pk.end(), std::back_inserter(merged));
      merged.erase(std::remove(merged.begin(), merged.end(), int(k)), merged.end());
      pi.swap(merged);
    }
    std::vector<int>().swap(pat[k]);
  }
  return work;
}

// Right-looking sparse Gaussian elimination in FT with both right-hand sides, then back
// substitution. Entries that cancel are kept, so the pattern stays structurally symmetric
// and the rows to update at step k are the columns of row k after k.
template <class FT>
Error_code solve_by_elimination(const Tutte_system<FT>& S, Progress_budget& budget, std::vector<FT>& xu, std::vector<FT>& xv)
{
  typedef std::pair<int, FT> Entry;
  const std::size_t n = S.n;
  if(!budget.report(0)) return ERROR_BUDGET_EXHAUSTED;
  const std::vector<int> order = fill_reducing_order(S);
  std::vector<std::vector<Entry> > rows;
  std::vector<FT> bu, bv;
  permuted_rows(S, order, rows, bu, bv);
  const std::vector<double> work = elimination_work(rows);
  double total = 0, done = 0;
  for(double w : work) total += w;
  const FT zero = make_ft<FT>(0);

  std::vector<Entry> merged;
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::vector<Entry>& rk = rows[k]; // columns >= k: the earlier ones were eliminated
    if(rk.empty() || rk[0].first != int(k) || CGAL::is_zero(rk[0].second)) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    const FT& pivot = rk[0].second;
    for(std::size_t a = 1; a < rk.size(); ++a)
    {
      std::vector<Entry>& ri = rows[rk[a].first];
      // ri holds column k (structural symmetry); it is eliminated
      auto it = std::lower_bound(ri.begin(), ri.end(), int(k), [](const Entry& e, int c) { return e.first < c; });
      if(it == ri.end() || it->first != int(k)) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      const FT m = it->second / pivot;
      merged.clear();
      merged.reserve(ri.size() + rk.size());
      auto p = ri.begin();
      auto q = rk.begin() + 1;
      while(p != ri.end() || q != rk.end())
      {
        if(p != ri.end() && p->first == int(k)) { ++p; continue; }
        if(q == rk.end() || (p != ri.end() && p->first < q->first)) { merged.push_back(*p); ++p; }
        else if(p == ri.end() || q->first < p->first) { merged.emplace_back(q->first, FT(zero - m * q->second)); ++q; }
        else { merged.emplace_back(p->first, FT(p->second - m * q->second)); ++p; ++q; }
      }
      ri.swap(merged);
      bu[rk[a].first] -= m * bu[k];
      bv[rk[a].first] -= m * bv[k];
      if(!budget.time_left()) return ERROR_BUDGET_EXHAUSTED;
    }
    done += work[k];
    if(!budget.report(total > 0 ? done / total : 1.)) return ERROR_BUDGET_EXHAUSTED;
  }
  // back substitution; rows[k] is the final row k of the upper triangular factor
  std::vector<FT> yu(n, zero), yv(n, zero);
  for(std::size_t kk = n; kk-- > 0; )
  {
    FT su = bu[kk], sv = bv[kk];
    const std::vector<Entry>& rk = rows[kk];
    for(std::size_t a = 1; a < rk.size(); ++a)
    {
      su -= rk[a].second * yu[rk[a].first];
      sv -= rk[a].second * yv[rk[a].first];
    }
    yu[kk] = su / rk[0].second;
    yv[kk] = sv / rk[0].second;
  }
  xu.resize(n); xv.resize(n);
  for(std::size_t k = 0; k < n; ++k) { xu[order[k]] = yu[k]; xv[order[k]] = yv[k]; }
  if(!budget.report(1)) return ERROR_BUDGET_EXHAUSTED;
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_SOLVE_H
