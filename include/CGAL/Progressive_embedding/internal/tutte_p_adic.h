// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_P_ADIC_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_P_ADIC_H

// Exact rational solve of the Tutte system by p-adic lifting (Dixon 1982):
//  1. scale each row to integers (the solution does not change);
//  2. factor A modulo a word-size prime p once (sparse LU in a fill-reducing order);
//  3. lift: x_t = A^-1 r_t mod p, r_{t+1} = (r_t - A x_t) / p, so that sum_t x_t p^t is the
//     solution modulo p^T, for T large enough that the Hadamard bound of the numerators and
//     the common denominator fits: 2 N D < p^T;
//  4. rational reconstruction of each component, with the denominator found so far;
//  5. verification A x = b in integers (on failure the caller falls back on rational elimination).
// Every step works on integers of the size of the result: the cost is about n * fill * T
// word operations plus the reconstruction, instead of rational arithmetic on growing entries.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/tutte_system.h>
#include <CGAL/Progressive_embedding/internal/tutte_solve.h>

#include <CGAL/Gmpq.h>
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// The system with integer rows: row r (original numbering) times the lcm of its denominators.
struct Integer_system
{
  std::vector<std::vector<std::pair<std::size_t, mpz_class> > > rows; // including the diagonal
  std::vector<mpz_class> bu, bv;
};

inline void integer_system(const Tutte_system<CGAL::Gmpq>& S, Integer_system& I)
{
  const std::size_t n = S.n;
  I.rows.assign(n, {});
  I.bu.resize(n); I.bv.resize(n);
  auto num = [](const CGAL::Gmpq& q) { return mpz_class(mpq_numref(q.mpq())); };
  auto den = [](const CGAL::Gmpq& q) { return mpz_class(mpq_denref(q.mpq())); };
  for(std::size_t r = 0; r < n; ++r)
  {
    mpz_class L = 1;
    auto take = [&](const CGAL::Gmpq& q) { mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), mpq_denref(q.mpq())); };
    take(S.diag[r]); take(S.bu[r]); take(S.bv[r]);
    for(const auto& e : S.off[r]) take(e.second);
    auto scaled = [&](const CGAL::Gmpq& q) { return mpz_class(num(q) * (L / den(q))); };
    I.rows[r].emplace_back(r, scaled(S.diag[r]));
    for(const auto& e : S.off[r]) I.rows[r].emplace_back(e.first, scaled(e.second));
    I.bu[r] = scaled(S.bu[r]);
    I.bv[r] = scaled(S.bv[r]);
  }
}

// Sparse LU of the integer matrix modulo p, in the elimination order `order`; false on a zero pivot.
struct Modular_lu
{
  std::uint64_t p = 0;
  std::vector<int> order, step;                                             // step[original] = position
  std::vector<std::vector<std::pair<int, std::uint64_t> > > U;              // row k: columns >= k, U[k][0] is the pivot
  std::vector<std::uint64_t> inv_pivot;
  std::vector<std::vector<std::pair<int, std::uint64_t> > > L;              // step k: (row i > k, multiplier)

  static std::uint64_t power(std::uint64_t a, std::uint64_t e, std::uint64_t p)
  {
    std::uint64_t r = 1;
    a %= p;
    for(; e; e >>= 1) { if(e & 1) r = r * a % p; a = a * a % p; }
    return r;
  }

  bool factor(const Integer_system& I, const std::vector<int>& ord, std::uint64_t prime)
  {
    p = prime; order = ord;
    const std::size_t n = I.rows.size();
    step.assign(n, 0);
    for(std::size_t k = 0; k < n; ++k) step[order[k]] = int(k);
    U.assign(n, {}); L.assign(n, {}); inv_pivot.assign(n, 0);
    for(std::size_t r = 0; r < n; ++r)
    {
      auto& row = U[step[r]];
      for(const auto& e : I.rows[r]) row.emplace_back(step[e.first], mpz_fdiv_ui(e.second.get_mpz_t(), p));
      std::sort(row.begin(), row.end());
    }
    std::vector<std::pair<int, std::uint64_t> > merged;
    for(std::size_t k = 0; k < n; ++k)
    {
      const auto& rk = U[k];
      if(rk.empty() || rk[0].first != int(k) || rk[0].second == 0) return false;
      inv_pivot[k] = power(rk[0].second, p - 2, p);
      for(std::size_t a = 1; a < rk.size(); ++a)
      {
        auto& ri = U[rk[a].first];
        auto it = std::lower_bound(ri.begin(), ri.end(), std::make_pair(int(k), std::uint64_t(0)));
        if(it == ri.end() || it->first != int(k)) return false;
        const std::uint64_t m = it->second * inv_pivot[k] % p;
        L[k].emplace_back(rk[a].first, m);
        merged.clear();
        auto P = ri.begin();
        auto Q = rk.begin() + 1;
        while(P != ri.end() || Q != rk.end())
        {
          if(P != ri.end() && P->first == int(k)) { ++P; continue; }
          if(Q == rk.end() || (P != ri.end() && P->first < Q->first)) { merged.push_back(*P); ++P; }
          else if(P == ri.end() || Q->first < P->first) { merged.emplace_back(Q->first, (p - m * Q->second % p) % p); ++Q; }
          else { merged.emplace_back(P->first, (P->second + p - m * Q->second % p) % p); ++P; ++Q; }
        }
        ri.swap(merged);
      }
    }
    return true;
  }

  // x = A^-1 b mod p, b and x in the original numbering (b is overwritten)
  void solve(std::vector<std::uint64_t>& b, std::vector<std::uint64_t>& x) const
  {
    const std::size_t n = U.size();
    std::vector<std::uint64_t> y(n);
    for(std::size_t k = 0; k < n; ++k) y[k] = b[order[k]];
    for(std::size_t k = 0; k < n; ++k)
      for(const auto& e : L[k]) y[e.first] = (y[e.first] + p - e.second * y[k] % p) % p;
    for(std::size_t k = n; k-- > 0; )
    {
      std::uint64_t s = y[k];
      for(std::size_t a = 1; a < U[k].size(); ++a) s = (s + p - U[k][a].second * y[U[k][a].first] % p) % p;
      y[k] = s * inv_pivot[k] % p;
    }
    x.resize(n);
    for(std::size_t k = 0; k < n; ++k) x[order[k]] = y[k];
  }
};

// a/b = u mod M with |a|, b below sqrt(M/2); false if there is none
inline bool rational_reconstruction(const mpz_class& u, const mpz_class& M, const mpz_class& bound, mpz_class& a, mpz_class& b)
{
  mpz_class r0 = M, r1 = u, t0 = 0, t1 = 1, q, tmp;
  while(r1 >= bound)
  {
    mpz_fdiv_q(q.get_mpz_t(), r0.get_mpz_t(), r1.get_mpz_t());
    tmp = r0 - q * r1; r0 = r1; r1 = tmp;
    tmp = t0 - q * t1; t0 = t1; t1 = tmp;
  }
  a = r1; b = t1;
  if(b < 0) { a = -a; b = -b; }
  if(b == 0 || b >= bound) return false;
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  return g == 1;
}

// sum_t digits[t] p^t, by pairing (subquadratic with GMP's multiplication)
inline mpz_class combine_digits(const std::vector<std::uint32_t>& digits, std::size_t stride, std::size_t offset,
                                std::size_t T, std::uint64_t p)
{
  std::vector<mpz_class> v(T);
  for(std::size_t t = 0; t < T; ++t) v[t] = static_cast<unsigned long>(digits[t * stride + offset]);
  mpz_class P = static_cast<unsigned long>(p);
  while(v.size() > 1)
  {
    std::vector<mpz_class> w((v.size() + 1) / 2);
    for(std::size_t i = 0; i < w.size(); ++i)
      w[i] = (2 * i + 1 < v.size()) ? mpz_class(v[2 * i] + P * v[2 * i + 1]) : v[2 * i];
    v.swap(w);
    P = P * P;
  }
  return v.empty() ? mpz_class(0) : v[0];
}

// From the p-adic digits of the first T steps, the rational solution, verified exactly
// (A x = b in integers); false if the digits do not determine it yet.
inline bool reconstruct_solution(const Integer_system& I, const std::vector<std::uint32_t>& digits, std::size_t T,
                                 std::uint64_t p, std::vector<CGAL::Gmpq>& xu, std::vector<CGAL::Gmpq>& xv)
{
  const std::size_t n = I.rows.size();
  mpz_class M;
  mpz_ui_pow_ui(M.get_mpz_t(), static_cast<unsigned long>(p), static_cast<unsigned long>(T));
  const mpz_class half = M / 2;
  mpz_class bound;
  mpz_sqrt(bound.get_mpz_t(), half.get_mpz_t());
  // x_i = num[i] / den[i], every den[i] divides d
  mpz_class d = 1;
  std::vector<mpz_class> num(2 * n), den(2 * n);
  for(std::size_t c = 0; c < 2 * n; ++c)
  {
    const mpz_class X = combine_digits(digits, 2 * n, c, T, p);
    mpz_class y = (X * d) % M;
    if(y < 0) y += M;
    if(y > half) y -= M; // symmetric residue
    if(abs(y) < bound) { num[c] = y; den[c] = d; continue; }
    if(y < 0) y += M;
    mpz_class a, bb;
    if(!rational_reconstruction(y, M, bound, a, bb)) return false;
    d *= bb;
    num[c] = a; den[c] = d;
  }
  // verification in integers: sum_j A_rj X_j = b_r d with X_j = num_j d / den_j
  std::vector<mpz_class> X(2 * n);
  for(std::size_t c = 0; c < 2 * n; ++c) X[c] = num[c] * (d / den[c]);
  mpz_class s;
  for(std::size_t r = 0; r < n; ++r)
    for(int side = 0; side < 2; ++side)
    {
      s = (side ? I.bv[r] : I.bu[r]) * d;
      for(const auto& e : I.rows[r]) mpz_submul(s.get_mpz_t(), e.second.get_mpz_t(), X[2 * e.first + side].get_mpz_t());
      if(s != 0) return false;
    }
  xu.resize(n); xv.resize(n);
  for(std::size_t c = 0; c < 2 * n; ++c)
  {
    CGAL::Gmpq q;
    mpq_set_num(q.mpq(), num[c].get_mpz_t()); mpq_set_den(q.mpq(), den[c].get_mpz_t()); mpq_canonicalize(q.mpq());
    ((c % 2) ? xv : xu)[c / 2] = q;
  }
  return true;
}

// Solves S in rationals by p-adic lifting. Returns ERROR_CANNOT_SOLVE_LINEAR_SYSTEM when it
// cannot conclude (unlucky primes, failed verification): the caller then eliminates in rationals.
// The solution is tried (and verified) after 16, 32, 64, ... steps and at the Hadamard bound,
// so that the number of steps follows the actual size of the solution.
inline Error_code solve_by_p_adic_lifting(const Tutte_system<CGAL::Gmpq>& S, Progress_budget& budget,
                                          std::vector<CGAL::Gmpq>& xu, std::vector<CGAL::Gmpq>& xv)
{
  const std::size_t n = S.n;
  if(!budget.report(0)) return ERROR_BUDGET_EXHAUSTED;
  Integer_system I;
  integer_system(S, I);

  // Hadamard bound H >= |det A| and >= |det A_j(b)| for both right-hand sides (Cramer): log2 H
  double log2_H = 0;
  for(std::size_t r = 0; r < n; ++r)
  {
    double bits = 0;
    for(const auto& e : I.rows[r]) bits = (std::max)(bits, double(mpz_sizeinbase(e.second.get_mpz_t(), 2)));
    bits += 0.5 * std::log2(double(I.rows[r].size()));
    const double bb = double((std::max)(mpz_sizeinbase(I.bu[r].get_mpz_t(), 2), mpz_sizeinbase(I.bv[r].get_mpz_t(), 2)));
    log2_H += (std::max)(bits, bb) + 1;
  }

  const std::vector<int> order = fill_reducing_order(S);
  const std::uint64_t primes[] = { 2147483647ull, 2147483629ull, 2147483587ull, 2147483579ull };
  Modular_lu lu;
  bool factored = false;
  for(std::uint64_t p : primes) if(lu.factor(I, order, p)) { factored = true; break; }
  if(!factored) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  const std::uint64_t p = lu.p;
  // p^T > 2 N D with N, D <= H, and some margin
  const std::size_t T = static_cast<std::size_t>(std::ceil((2 * log2_H + 2) / std::log2(double(p)))) + 2;

  std::vector<mpz_class> ru = I.bu, rv = I.bv;
  std::vector<std::uint32_t> digits;
  digits.reserve(2 * n * (std::min)(T, std::size_t(64)));
  std::vector<std::uint64_t> b(n), x(n);
  std::size_t next_try = 16;
  for(std::size_t t = 0; t < T; ++t)
  {
    digits.resize(2 * n * (t + 1));
    for(int side = 0; side < 2; ++side)
    {
      std::vector<mpz_class>& r = side ? rv : ru;
      for(std::size_t i = 0; i < n; ++i) b[i] = mpz_fdiv_ui(r[i].get_mpz_t(), p);
      lu.solve(b, x);
      for(std::size_t i = 0; i < n; ++i) digits[(t * n + i) * 2 + side] = static_cast<std::uint32_t>(x[i]);
      // r = (r - A x) / p, exact
      for(std::size_t i = 0; i < n; ++i)
      {
        for(const auto& e : I.rows[i])
          if(x[e.first]) mpz_submul_ui(r[i].get_mpz_t(), e.second.get_mpz_t(), static_cast<unsigned long>(x[e.first]));
        mpz_divexact_ui(r[i].get_mpz_t(), r[i].get_mpz_t(), static_cast<unsigned long>(p));
      }
    }
    // progress against the bound (the early tries may end sooner)
    if(!budget.report(double(t + 1) / double(T))) return ERROR_BUDGET_EXHAUSTED;
    if(t + 1 == next_try || t + 1 == T)
    {
      if(reconstruct_solution(I, digits, t + 1, p, xu, xv)) return budget.report(1) ? OK : ERROR_BUDGET_EXHAUSTED;
      next_try *= 2;
      if(!budget.time_left()) return ERROR_BUDGET_EXHAUSTED;
    }
  }
  return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_P_ADIC_H
