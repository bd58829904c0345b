// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_P_ADIC_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_P_ADIC_H

// Exact rational solve of the Tutte system by p-adic lifting (Dixon 1982):
//  1. scale each row to integers (the solution does not change);
//  2. factor A modulo a word-size prime p once: sparse LU on the symbolic structure of
//     internal/tutte_solve.h (AMD order, elimination tree), row by row through a dense work row;
//  3. lift both coordinates together: x_t = A^-1 r_t mod p, r_{t+1} = (r_t - A x_t) / p, so that
//     sum_t x_t p^t is the solution modulo p^T. The residuals stay below a few times the row sums of
//     |A|, so rows with word-size entries keep them in 128-bit integers (the exact division by p is a
//     multiplication by its inverse modulo 2^128); the others in GMP integers;
//  4. stop at the number of steps T the solution's size needs: the denominator divides
//     beta * det(diag(lambda) A) (lambda: the rows' scales, beta: the common denominator of the scaled
//     right-hand sides) and |x| is at most the largest |b_r / g_r| (g_r: the weight of row r to the
//     border; Tutte's solution is a convex combination), so numerator and denominator are below sqrt(p^T / 2) once T
//     passes a bound computed from log |det A| -- taken from the same factorization in double (the
//     pivots of an M-matrix are positive and accurate) -- with a margin; the Hadamard bound, far
//     larger, is the fallback when the estimate is unavailable or wrong;
//  5. rational reconstruction with a common denominator d: an extended Euclid on a component finds
//     d, then a numerator is d x_c modulo p^(T/2) (half the digits, one product); the rows of an
//     independent set get theirs from their own equation (an exact division); verification
//     A x = b in integers (on failure: more steps, then the caller's rational elimination);
//     lowest terms with one product modulo d's large part per component instead of a gcd.
// The cost is about T * (fill + nnz) word operations plus a few products of T/2-word integers per
// component; T grows with the size of the exact solution (about 2 bits per vertex for numerator and
// denominator each), so the whole grows a little faster than the square of the size.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/tutte_system.h>
#include <CGAL/Progressive_embedding/internal/tutte_solve.h>

#include <CGAL/Gmpq.h>
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// The system with integer rows: row r (original numbering) times the lcm of its denominators.
struct Integer_system
{
  std::vector<std::vector<std::pair<std::size_t, mpz_class> > > rows; // the diagonal first, then S.off[r] in order
  std::vector<mpz_class> bu, bv;
  double log2_row_scales = 0;   // sum over the rows of log2 of the lcm of the matrix entries' denominators
  double log2_rhs_scale = 0;    // log2 of the common denominator of the right-hand sides so scaled
};

inline double log2_mpz(const mpz_class& z)
{
  if(z == 0) return -std::numeric_limits<double>::infinity();
  long e = 0;
  const double m = mpz_get_d_2exp(&e, z.get_mpz_t());
  return std::log2(std::abs(m)) + double(e);
}

inline void integer_system(const Tutte_system<CGAL::Gmpq>& S, Integer_system& I)
{
  const std::size_t n = S.n;
  I.rows.assign(n, {});
  I.bu.resize(n); I.bv.resize(n);
  I.log2_row_scales = 0;
  mpz_class beta = 1, lambda, L, g;
  for(std::size_t r = 0; r < n; ++r)
  {
    lambda = 1;
    auto take = [&](mpz_class& acc, const CGAL::Gmpq& q) { mpz_lcm(acc.get_mpz_t(), acc.get_mpz_t(), mpq_denref(q.mpq())); };
    take(lambda, S.diag[r]);
    for(const auto& e : S.off[r]) take(lambda, e.second);
    L = lambda;
    take(L, S.bu[r]); take(L, S.bv[r]);
    I.log2_row_scales += log2_mpz(lambda);
    // the denominator of lambda * b_r is den(b_r) / gcd(den(b_r), lambda)
    for(const CGAL::Gmpq* b : { &S.bu[r], &S.bv[r] })
    {
      mpz_gcd(g.get_mpz_t(), mpq_denref(b->mpq()), lambda.get_mpz_t());
      mpz_class d(mpq_denref(b->mpq()));
      mpz_divexact(d.get_mpz_t(), d.get_mpz_t(), g.get_mpz_t());
      mpz_lcm(beta.get_mpz_t(), beta.get_mpz_t(), d.get_mpz_t());
    }
    auto scaled = [&](const CGAL::Gmpq& q) {
      mpz_class z;
      mpz_divexact(z.get_mpz_t(), L.get_mpz_t(), mpq_denref(q.mpq()));
      z *= mpz_class(mpq_numref(q.mpq()));
      return z;
    };
    I.rows[r].reserve(S.off[r].size() + 1);
    I.rows[r].emplace_back(r, scaled(S.diag[r]));
    for(const auto& e : S.off[r]) I.rows[r].emplace_back(e.first, scaled(e.second));
    I.bu[r] = scaled(S.bu[r]);
    I.bv[r] = scaled(S.bv[r]);
  }
  I.log2_rhs_scale = log2_mpz(beta);
}

// Arithmetic modulo a prime p < 2^31: Barrett reduction of 64-bit values (no division instruction).
struct Modulus
{
  std::uint64_t p = 0, barrett = 0, two64 = 0; // floor(2^64 / p), 2^64 mod p
  explicit Modulus(std::uint64_t prime = 2147483647ull)
    : p(prime), barrett(static_cast<std::uint64_t>((static_cast<unsigned __int128>(1) << 64) / prime)),
      two64(static_cast<std::uint64_t>((static_cast<unsigned __int128>(1) << 64) % prime)) { }
  std::uint64_t reduce(std::uint64_t x) const
  {
    const std::uint64_t q = static_cast<std::uint64_t>((static_cast<unsigned __int128>(x) * barrett) >> 64);
    std::uint64_t r = x - q * p;
    return r >= p ? r - p : r;
  }
  std::uint64_t reduce(unsigned __int128 x) const
  {
    const std::uint64_t hi = static_cast<std::uint64_t>(x >> 64), lo = static_cast<std::uint64_t>(x);
    return reduce(reduce(hi) * two64 + reduce(lo));
  }
  std::uint64_t reduce(__int128 x) const
  {
    if(x >= 0) return reduce(static_cast<unsigned __int128>(x));
    const std::uint64_t r = reduce(static_cast<unsigned __int128>(-x));
    return r ? p - r : 0;
  }
  std::uint64_t reduce(const mpz_class& z) const { return mpz_fdiv_ui(z.get_mpz_t(), static_cast<unsigned long>(p)); }
  std::uint64_t power(std::uint64_t a, std::uint64_t e) const
  {
    std::uint64_t r = 1;
    a = reduce(a);
    for(; e; e >>= 1) { if(e & 1) r = reduce(r * a); a = reduce(a * a); }
    return r;
  }
};

// Sparse LU of the integer matrix modulo p on the symbolic structure F; false on a zero pivot.
// Both right-hand sides are solved together (interleaved), sums accumulated in 128 bits and
// reduced once per row.
struct Modular_lu
{
  Modulus mod;
  const Symbolic_factorization* F = nullptr;
  std::vector<std::uint32_t> lval, uval, inv_pivot;

  bool factor(const Integer_system& I, const Symbolic_factorization& sf, std::uint64_t prime)
  {
    mod = Modulus(prime); F = &sf;
    const std::uint64_t p = mod.p;
    const std::size_t n = sf.n;
    lval.assign(sf.l_col.size(), 0); uval.assign(sf.u_col.size(), 0); inv_pivot.assign(n, 0);
    std::vector<std::uint64_t> w(n, 0);
    for(std::size_t k = 0; k < n; ++k)
    {
      const auto& row = I.rows[sf.order[k]];
      for(int e = sf.a_ptr[k]; e < sf.a_ptr[k + 1]; ++e)
        w[sf.a_col[e]] = mod.reduce(row[static_cast<std::size_t>(sf.a_src[e] + 1)].second);
      for(int e = sf.l_ptr[k]; e < sf.l_ptr[k + 1]; ++e)
      {
        const int j = sf.l_col[e];
        const std::uint64_t l = mod.reduce(w[j] * inv_pivot[j]);
        lval[e] = static_cast<std::uint32_t>(l);
        w[j] = 0;
        const std::uint64_t ml = l ? p - l : 0;
        for(int f = sf.u_ptr[j]; f < sf.u_ptr[j + 1]; ++f) w[sf.u_col[f]] = mod.reduce(w[sf.u_col[f]] + ml * uval[f]);
      }
      if(w[k] == 0) return false;
      inv_pivot[k] = static_cast<std::uint32_t>(mod.power(w[k], p - 2));
      w[k] = 0;
      for(int f = sf.u_ptr[k]; f < sf.u_ptr[k + 1]; ++f) { uval[f] = static_cast<std::uint32_t>(w[sf.u_col[f]]); w[sf.u_col[f]] = 0; }
    }
    return true;
  }

  // y (step numbering, interleaved u, v) = A^-1 y mod p
  void solve(std::vector<std::uint64_t>& y) const
  {
    const Symbolic_factorization& sf = *F;
    const std::size_t n = sf.n;
    // y_k -= sum_e val[e] y_col[e] over row k of a factor, both coordinates
    auto subtract_row = [&](const std::vector<int>& ptr, const std::vector<int>& col, const std::vector<std::uint32_t>& val, std::size_t k) {
      unsigned __int128 su = 0, sv = 0;
      for(int e = ptr[k]; e < ptr[k + 1]; ++e)
      {
        const std::uint64_t a = val[e];
        const std::size_t j = static_cast<std::size_t>(col[e]);
        su += a * y[2 * j]; sv += a * y[2 * j + 1];
      }
      const std::uint64_t ru = mod.reduce(su), rv = mod.reduce(sv);
      y[2 * k] = y[2 * k] >= ru ? y[2 * k] - ru : y[2 * k] + mod.p - ru;
      y[2 * k + 1] = y[2 * k + 1] >= rv ? y[2 * k + 1] - rv : y[2 * k + 1] + mod.p - rv;
    };
    for(std::size_t k = 0; k < n; ++k) subtract_row(sf.l_ptr, sf.l_col, lval, k);
    for(std::size_t k = n; k-- > 0; )
    {
      subtract_row(sf.u_ptr, sf.u_col, uval, k);
      y[2 * k] = mod.reduce(y[2 * k] * inv_pivot[k]);
      y[2 * k + 1] = mod.reduce(y[2 * k + 1] * inv_pivot[k]);
    }
  }
};

// log2 |det A| from the factorization of A in double on the same structure; NaN unless every
// pivot is positive and finite (an M-matrix: then the pivots are computed accurately).
inline double log2_determinant(const Tutte_system<CGAL::Gmpq>& S, const Symbolic_factorization& F)
{
  const std::size_t n = F.n;
  std::vector<double> w(n, 0.), uval(F.u_col.size(), 0.), pivot(n, 0.);
  double sum = 0;
  for(std::size_t k = 0; k < n; ++k)
  {
    for(int e = F.a_ptr[k]; e < F.a_ptr[k + 1]; ++e) w[F.a_col[e]] = CGAL::to_double(system_entry(S, F, k, e));
    for(int e = F.l_ptr[k]; e < F.l_ptr[k + 1]; ++e)
    {
      const int j = F.l_col[e];
      const double l = w[j] / pivot[j];
      w[j] = 0;
      for(int f = F.u_ptr[j]; f < F.u_ptr[j + 1]; ++f) w[F.u_col[f]] -= l * uval[f];
    }
    pivot[k] = w[k]; w[k] = 0;
    if(!(pivot[k] > 0) || !std::isfinite(pivot[k])) return std::numeric_limits<double>::quiet_NaN();
    for(int f = F.u_ptr[k]; f < F.u_ptr[k + 1]; ++f) { uval[f] = w[F.u_col[f]]; w[F.u_col[f]] = 0; }
    sum += std::log2(pivot[k]);
  }
  return sum;
}

// log2 of a bound on |x_i| for every component of the solution: Tutte's system is
// diag_r x_r = sum_j w_rj x_j + b_r with w >= 0 and diag_r = sum_j w_rj + g_r, g_r >= 0, so x_r is
// a convex combination of its neighbours and of b_r / g_r: |x| <= max |b_r / g_r| over g_r > 0.
// NaN if the signs are not those of such a system.
inline double log2_solution_bound(const Tutte_system<CGAL::Gmpq>& S)
{
  double bound = -std::numeric_limits<double>::infinity();
  CGAL::Gmpq g;
  auto log2_upper = [](const CGAL::Gmpq& q) { // an upper bound on log2 |q|, q != 0
    return double(mpz_sizeinbase(mpq_numref(q.mpq()), 2)) - double(mpz_sizeinbase(mpq_denref(q.mpq()), 2)) + 1;
  };
  for(std::size_t r = 0; r < S.n; ++r)
  {
    g = S.diag[r];
    for(const auto& e : S.off[r])
    {
      if(CGAL::is_positive(e.second)) return std::numeric_limits<double>::quiet_NaN();
      g += e.second;
    }
    if(CGAL::is_negative(g)) return std::numeric_limits<double>::quiet_NaN();
    for(const CGAL::Gmpq* b : { &S.bu[r], &S.bv[r] })
    {
      if(CGAL::is_zero(*b)) continue;
      if(CGAL::is_zero(g)) return std::numeric_limits<double>::quiet_NaN();
      bound = (std::max)(bound, log2_upper(*b) - log2_upper(g) + 2);
    }
  }
  return (std::max)(bound, 0.);
}

// a/b = u mod M with |a|, b below `bound` (about sqrt(M/2)); false if there is none
inline bool rational_reconstruction(const mpz_class& u, const mpz_class& M, const mpz_class& bound, mpz_class& a, mpz_class& b)
{
  mpz_class r0 = M, r1 = u, t0 = 0, t1 = 1, q, tmp;
  while(r1 >= bound)
  {
    mpz_fdiv_qr(q.get_mpz_t(), tmp.get_mpz_t(), r0.get_mpz_t(), r1.get_mpz_t());
    r0.swap(r1); r1.swap(tmp);
    tmp = t0 - q * t1; t0.swap(t1); t1.swap(tmp);
  }
  a = r1; b = t1;
  if(b < 0) { a = -a; b = -b; }
  if(b == 0 || b >= bound) return false;
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  return g == 1;
}

// sum_t digits[t * stride + offset] p^t for t < T, by pairing with the powers p^(2^j) in `powers`
// (subquadratic with GMP's multiplication); `v` is scratch space
inline void combine_digits(const std::vector<std::uint32_t>& digits, std::size_t stride, std::size_t offset, std::size_t T,
                           const std::vector<mpz_class>& powers, std::vector<mpz_class>& v, mpz_class& out)
{
  v.resize(T);
  for(std::size_t t = 0; t < T; ++t) v[t] = static_cast<unsigned long>(digits[t * stride + offset]);
  std::size_t size = T;
  for(std::size_t level = 0; size > 1; ++level)
  {
    const std::size_t half = (size + 1) / 2;
    for(std::size_t i = 0; i < half; ++i)
    {
      if(2 * i + 1 < size) { mpz_mul(v[2 * i + 1].get_mpz_t(), v[2 * i + 1].get_mpz_t(), powers[level].get_mpz_t()); mpz_add(v[i].get_mpz_t(), v[2 * i].get_mpz_t(), v[2 * i + 1].get_mpz_t()); }
      else if(i != 2 * i) v[i].swap(v[2 * i]);
    }
    size = half;
  }
  if(T == 0) out = 0; else out.swap(v[0]);
}

// The fractions num[c] / d in lowest terms, into xu (even c) and xv (odd c). A gcd per component
// costs several times the products of the reconstruction, so the common denominator is split:
// d = s Q with s made of the primes below 2^16 (trial division) and Q free of them. Each numerator
// is reduced against s (a small gcd); Q shares no factor with any numerator when
// gcd(Q, prod_c num[c] mod Q) = 1 (one product modulo Q per component, one gcd). Otherwise
// (it may happen, rarely) every fraction is reduced by its own gcd. false if the budget stops it.
inline bool canonical_fractions(std::vector<mpz_class>& num, const mpz_class& d, Progress_budget& budget, double progress_from,
                                std::vector<CGAL::Gmpq>& xu, std::vector<CGAL::Gmpq>& xv)
{
  const std::size_t m = num.size(), n = m / 2;
  mpz_class s = 1, Q = d, P = 1, g;
  for(unsigned long q = 2; q < 65536 && Q > 1; q += (q == 2 ? 1 : 2))
  {
    bool prime = true;
    for(unsigned long f = 3; f * f <= q && prime; f += 2) if(q % f == 0) prime = false;
    if(!prime) continue;
    while(mpz_divisible_ui_p(Q.get_mpz_t(), q)) { mpz_divexact_ui(Q.get_mpz_t(), Q.get_mpz_t(), q); s *= q; }
  }
  bool coprime = true;
  if(Q > 1)
  {
    for(std::size_t c = 0; c < m; ++c)
    {
      if(num[c] == 0) continue;
      mpz_mul(P.get_mpz_t(), P.get_mpz_t(), num[c].get_mpz_t());
      mpz_fdiv_r(P.get_mpz_t(), P.get_mpz_t(), Q.get_mpz_t());
      if((c & 255) == 0 && !budget.report(progress_from + 0.5 * (1 - progress_from) * double(c) / double(m))) return false;
    }
    mpz_gcd(g.get_mpz_t(), P.get_mpz_t(), Q.get_mpz_t());
    coprime = (g == 1);
  }
  xu.resize(n); xv.resize(n);
  for(std::size_t c = 0; c < m; ++c)
  {
    CGAL::Gmpq q;
    if(num[c] != 0)
    {
      if(coprime)
      {
        mpz_gcd(g.get_mpz_t(), num[c].get_mpz_t(), s.get_mpz_t());
        mpz_divexact(mpq_numref(q.mpq()), num[c].get_mpz_t(), g.get_mpz_t());
        mpz_divexact(mpq_denref(q.mpq()), d.get_mpz_t(), g.get_mpz_t());
      }
      else
      {
        mpq_set_num(q.mpq(), num[c].get_mpz_t()); mpq_set_den(q.mpq(), d.get_mpz_t()); mpq_canonicalize(q.mpq());
      }
    }
    ((c % 2) ? xv : xu)[c / 2] = q;
    mpz_class().swap(num[c]);
    if((c & 255) == 0 && !budget.report(progress_from + (1 - progress_from) * (0.5 + 0.5 * double(c) / double(m)))) return false;
  }
  return true;
}

// From the p-adic digits of the first T steps, the rational solution, verified exactly
// (A x = b in integers); false if the digits do not determine it yet.
inline bool reconstruct_solution(const Integer_system& I, const std::vector<std::uint32_t>& digits, std::size_t T,
                                 std::uint64_t p, Progress_budget& budget, double progress_from,
                                 std::vector<CGAL::Gmpq>& xu, std::vector<CGAL::Gmpq>& xv, bool& stopped)
{
  stopped = false;
  const std::size_t n = I.rows.size();
  std::vector<mpz_class> powers(1, mpz_class(static_cast<unsigned long>(p)));
  while((std::size_t(1) << powers.size()) < T) powers.push_back(powers.back() * powers.back());
  mpz_class M;
  mpz_ui_pow_ui(M.get_mpz_t(), static_cast<unsigned long>(p), static_cast<unsigned long>(T));
  const mpz_class half = M / 2;
  mpz_class bound;
  mpz_sqrt(bound.get_mpz_t(), half.get_mpz_t());
  // two digits more than half of them: a component that is not over d passes the test |y| < bound
  // by chance with a probability below 1/p^2 (and then fails the verification)
  const std::size_t T2 = (std::min)(T, (T + 1) / 2 + 2);
  mpz_class M2, d_low, d_low_of = 0;
  mpz_ui_pow_ui(M2.get_mpz_t(), static_cast<unsigned long>(p), static_cast<unsigned long>(T2));
  const mpz_class half2 = M2 / 2;
  // x_c = num[c] / d over the common denominator d: an extended Euclid finds d (or a new factor
  // of it) on a component that is not over the d known so far; every other component needs one
  // product (its numerator is d x_c mod M, small)
  mpz_class d = 1, X, y, s;
  std::vector<mpz_class> num(2 * n), scratch;
  // rows of an independent set of the system's graph get their numerators from their own equation,
  // A_rr num_r = d b_r - sum_j A_rj num_j, an exact division (a linear cost instead of a product):
  // the others are reconstructed first
  std::vector<char> in_set(n, 0);
  for(std::size_t r = 1; r < n; ++r)
  {
    bool free = true;
    for(std::size_t e = 1; e < I.rows[r].size() && free; ++e) if(in_set[I.rows[r][e].first]) free = false;
    in_set[r] = free;
  }
  // (a pattern that is not symmetric could put a row and a later neighbour in the set)
  for(std::size_t r = 0; r < n; ++r)
    for(std::size_t e = 1; e < I.rows[r].size() && in_set[r]; ++e) if(in_set[I.rows[r][e].first]) in_set[r] = 0;
  std::vector<std::size_t> first;
  for(std::size_t r = 0; r < n; ++r) if(!in_set[r]) { first.push_back(2 * r); first.push_back(2 * r + 1); }
  std::vector<mpz_class> d_growth;  // the factors of d, in the order found,
  std::vector<std::size_t> grew_at; // and the position (in `first`) where each was found
  const double share = (1 - progress_from) / 2;
  for(std::size_t i = 0; i < first.size(); ++i)
  {
    const std::size_t c = first[i];
    // |numerator| < bound < p^T2 / 2: it is d x_c modulo p^T2, from the first T2 digits only
    if(d_low_of != d) { mpz_fdiv_r(d_low.get_mpz_t(), d.get_mpz_t(), M2.get_mpz_t()); d_low_of = d; }
    combine_digits(digits, 2 * n, c, T2, powers, scratch, X);
    mpz_mul(y.get_mpz_t(), X.get_mpz_t(), d_low.get_mpz_t());
    mpz_fdiv_r(y.get_mpz_t(), y.get_mpz_t(), M2.get_mpz_t());
    if(y > half2) y -= M2;
    if(abs(y) >= bound)
    {
      // not over d (or not determined yet): all T digits
      combine_digits(digits, 2 * n, c, T, powers, scratch, X);
      mpz_mul(y.get_mpz_t(), X.get_mpz_t(), d.get_mpz_t());
      mpz_fdiv_r(y.get_mpz_t(), y.get_mpz_t(), M.get_mpz_t());
      if(y > half) y -= M; // symmetric residue
    }
    if(abs(y) < bound) { num[c].swap(y); }
    else
    {
      if(y < 0) y += M;
      mpz_class a, bb;
      if(!rational_reconstruction(y, M, bound, a, bb)) return false;
      d *= bb;
      // the earlier numerators were over the old d: they get the factor bb below
      d_growth.push_back(bb); grew_at.push_back(i);
      num[c].swap(a);
    }
    if((i & 255) == 0 && !budget.report(progress_from + share * double(i) / double(first.size()))) { stopped = true; return false; }
  }
  // numerators over the final d: the one at position i was over the product of the factors found up to i
  if(!d_growth.empty())
  {
    mpz_class f = 1;
    std::size_t h = d_growth.size();
    for(std::size_t i = first.size(); i-- > 0; )
    {
      while(h > 0 && grew_at[h - 1] > i) { f *= d_growth[h - 1]; --h; }
      if(f != 1) num[first[i]] *= f;
    }
  }
  for(std::size_t r = 0; r < n; ++r)
  {
    if(!in_set[r]) continue;
    const mpz_class& diag = I.rows[r][0].second;
    for(int side = 0; side < 2; ++side)
    {
      mpz_mul(s.get_mpz_t(), (side ? I.bv[r] : I.bu[r]).get_mpz_t(), d.get_mpz_t());
      for(std::size_t e = 1; e < I.rows[r].size(); ++e)
        mpz_submul(s.get_mpz_t(), I.rows[r][e].second.get_mpz_t(), num[2 * I.rows[r][e].first + side].get_mpz_t());
      if(diag == 0 || !mpz_divisible_p(s.get_mpz_t(), diag.get_mpz_t())) return false;
      mpz_divexact(num[2 * r + side].get_mpz_t(), s.get_mpz_t(), diag.get_mpz_t());
    }
  }
  // verification in integers: sum_j A_rj num_j = b_r d (the rows of the independent set hold by construction)
  for(std::size_t r = 0; r < n; ++r)
    if(!in_set[r])
    for(int side = 0; side < 2; ++side)
    {
      mpz_mul(s.get_mpz_t(), (side ? I.bv[r] : I.bu[r]).get_mpz_t(), d.get_mpz_t());
      for(const auto& e : I.rows[r]) mpz_submul(s.get_mpz_t(), e.second.get_mpz_t(), num[2 * e.first + side].get_mpz_t());
      if(s != 0) return false;
    }
  if(!budget.report(progress_from + share)) { stopped = true; return false; }
  if(!canonical_fractions(num, d, budget, progress_from + share, xu, xv)) { stopped = true; return false; }
  return true;
}

// Solves S in rationals by p-adic lifting. Returns ERROR_CANNOT_SOLVE_LINEAR_SYSTEM when it
// cannot conclude (unlucky primes, failed verification): the caller then eliminates in rationals.
// The solution is tried at the estimated number of steps (then every quarter of it more, up to
// the Hadamard bound); without an estimate after 16, 32, 64, ... steps and at the Hadamard bound.
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

  Symbolic_factorization F;
  F.analyze(S, fill_reducing_order(S));
  const std::uint64_t primes[] = { 2147483647ull, 2147483629ull, 2147483587ull, 2147483579ull };
  Modular_lu lu;
  bool factored = false;
  for(std::uint64_t prime : primes) if(lu.factor(I, F, prime)) { factored = true; break; }
  if(!factored) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  const std::uint64_t p = lu.mod.p;
  const double log2_p = std::log2(double(p));
  // p^T > 2 N D with N, D <= H, and some margin
  const std::size_t T_max = static_cast<std::size_t>(std::ceil((2 * log2_H + 2) / log2_p)) + 2;
  // the estimate: D <= beta det(diag(lambda) A), N <= D max|x|, with a margin for the rounding of log det
  std::size_t T_goal = 0;
  {
    const double log2_det = log2_determinant(S, F), log2_x = log2_solution_bound(S);
    if(std::isfinite(log2_det) && std::isfinite(log2_x))
    {
      const double log2_D = I.log2_rhs_scale + I.log2_row_scales + log2_det;
      // the reconstruction bounds numerator and denominator both by sqrt(p^T / 2)
      const double bits = 1 + 2 * (log2_D + log2_x) + 64 + 1e-6 * std::abs(log2_det) + 1e-9 * double(n);
      T_goal = (std::min)(T_max, static_cast<std::size_t>(std::ceil(bits / log2_p)) + 1);
    }
  }
  std::size_t next_try = T_goal ? T_goal : (std::min)(std::size_t(16), T_max);

  // rows whose entries fit in 62 bits with a small row sum keep their residuals in 128 bits:
  // |r_t| <= max(|b|, 2 sum|A_rj|) and |r_t - A x_t| < 2^127 when |b| < 2^120 and sum|A_rj| < 2^90
  std::vector<char> small(n, 1);
  std::vector<std::int64_t> aval;
  std::vector<std::size_t> acol, aptr(n + 1, 0);
  std::vector<__int128> ru128(n, 0), rv128(n, 0);
  std::vector<mpz_class> ru(n), rv(n);
  for(std::size_t r = 0; r < n; ++r)
  {
    double sum = 0;
    for(const auto& e : I.rows[r])
    {
      if(!mpz_fits_slong_p(e.second.get_mpz_t()) || mpz_sizeinbase(e.second.get_mpz_t(), 2) > 62) small[r] = 0;
      sum += std::abs(mpz_get_d(e.second.get_mpz_t()));
    }
    if(sum >= std::ldexp(1., 89) || mpz_sizeinbase(I.bu[r].get_mpz_t(), 2) > 119 || mpz_sizeinbase(I.bv[r].get_mpz_t(), 2) > 119) small[r] = 0;
    if(small[r])
    {
      for(const auto& e : I.rows[r]) { acol.push_back(e.first); aval.push_back(mpz_get_si(e.second.get_mpz_t())); }
      auto to128 = [](const mpz_class& z) {
        mpz_class a = abs(z), hi = a >> 64, lo = a - (hi << 64);
        const unsigned __int128 u = (static_cast<unsigned __int128>(mpz_get_ui(hi.get_mpz_t())) << 64) | mpz_get_ui(lo.get_mpz_t());
        return z < 0 ? -static_cast<__int128>(u) : static_cast<__int128>(u);
      };
      ru128[r] = to128(I.bu[r]); rv128[r] = to128(I.bv[r]);
    }
    else { ru[r] = I.bu[r]; rv[r] = I.bv[r]; }
    aptr[r + 1] = acol.size();
  }
  // 1/p modulo 2^128 (Newton: each step doubles the correct low bits)
  unsigned __int128 pinv = p;
  for(int k = 0; k < 7; ++k) pinv *= 2 - static_cast<unsigned __int128>(p) * pinv;

  std::vector<std::uint32_t> digits;
  digits.reserve(2 * n * (std::min)(T_goal ? T_goal : T_max, std::size_t(1) << 20));
  std::vector<std::uint64_t> y(2 * n);
  const std::vector<int>& step = F.step;
  for(std::size_t t = 0; t < T_max; ++t)
  {
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t k = static_cast<std::size_t>(step[i]);
      y[2 * k] = small[i] ? lu.mod.reduce(ru128[i]) : lu.mod.reduce(ru[i]);
      y[2 * k + 1] = small[i] ? lu.mod.reduce(rv128[i]) : lu.mod.reduce(rv[i]);
    }
    lu.solve(y);
    digits.resize(2 * n * (t + 1));
    std::uint32_t* xt = digits.data() + 2 * n * t; // x_t in the original numbering, interleaved
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t k = static_cast<std::size_t>(step[i]);
      xt[2 * i] = static_cast<std::uint32_t>(y[2 * k]);
      xt[2 * i + 1] = static_cast<std::uint32_t>(y[2 * k + 1]);
    }
    // r = (r - A x) / p, exact
    for(std::size_t i = 0; i < n; ++i)
    {
      if(small[i])
      {
        __int128 su = ru128[i], sv = rv128[i];
        for(std::size_t e = aptr[i]; e < aptr[i + 1]; ++e)
        {
          const __int128 a = aval[e];
          su -= a * static_cast<__int128>(xt[2 * acol[e]]);
          sv -= a * static_cast<__int128>(xt[2 * acol[e] + 1]);
        }
        ru128[i] = static_cast<__int128>(static_cast<unsigned __int128>(su) * pinv);
        rv128[i] = static_cast<__int128>(static_cast<unsigned __int128>(sv) * pinv);
      }
      else
      {
        for(const auto& e : I.rows[i])
        {
          if(xt[2 * e.first]) mpz_submul_ui(ru[i].get_mpz_t(), e.second.get_mpz_t(), static_cast<unsigned long>(xt[2 * e.first]));
          if(xt[2 * e.first + 1]) mpz_submul_ui(rv[i].get_mpz_t(), e.second.get_mpz_t(), static_cast<unsigned long>(xt[2 * e.first + 1]));
        }
        mpz_divexact_ui(ru[i].get_mpz_t(), ru[i].get_mpz_t(), static_cast<unsigned long>(p));
        mpz_divexact_ui(rv[i].get_mpz_t(), rv[i].get_mpz_t(), static_cast<unsigned long>(p));
      }
    }
    // progress: the lifting is the first half of the work when the number of steps is known
    const double lifted = double(t + 1) / double(T_goal ? T_goal : T_max);
    if(!budget.report(0.5 * (std::min)(1., lifted))) return ERROR_BUDGET_EXHAUSTED;
    if(t + 1 == next_try || t + 1 == T_max)
    {
      bool stopped = false;
      if(reconstruct_solution(I, digits, t + 1, p, budget, 0.5, xu, xv, stopped)) return budget.report(1) ? OK : ERROR_BUDGET_EXHAUSTED;
      if(stopped) return ERROR_BUDGET_EXHAUSTED;
      next_try = T_goal ? (std::min)(T_max, next_try + (std::max)(std::size_t(1), next_try / 4)) : 2 * next_try;
      if(!budget.time_left()) return ERROR_BUDGET_EXHAUSTED;
    }
  }
  return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_P_ADIC_H
