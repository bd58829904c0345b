// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_P_ADIC_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_P_ADIC_H

// Exact rational solve of the Tutte system by p-adic lifting (Dixon 1982):
//  1. scale each row to integers (the solution does not change);
//  2. factor A modulo a prime p = 2^62 - c once (reductions fold the high bits, and a step yields 62
//     bits): sparse LU on the symbolic structure of internal/tutte_solve.h (AMD order, elimination
//     tree), row by row through a dense work row;
//  3. lift both coordinates together: x_t = A^-1 r_t mod p, r_{t+1} = (r_t - A x_t) / p, so that
//     sum_t x_t p^t is the solution modulo p^T. All in step numbering; each row of the triangular
//     solves is one sum of 128-bit products and one reduction. The residuals stay below the row sums
//     of |A| (plus |b| / p^t), so for rows with word-size entries 64-bit arithmetic modulo 2^64 gives
//     them exactly (the exact division by p is a product by its inverse modulo 2^64); the other rows
//     in GMP integers. Only the digits of the seeds (step 5) are kept;
//  4. stop at the number of steps T the solution's size needs: the denominator divides
//     beta * det(diag(lambda) A) (lambda: the rows' scales, beta: the common denominator of the scaled
//     right-hand sides) and |x| is at most the largest |b_r / g_r| (g_r: the weight of row r to the
//     border; Tutte's solution is a convex combination), so numerator and denominator are below sqrt(p^T / 2) once T
//     passes a bound computed from log |det A| -- taken from the same factorization in double (the
//     pivots of an M-matrix are positive and accurate) -- with a margin; the Hadamard bound, far
//     larger, is the fallback when the estimate is unavailable or wrong. The common denominator can be
//     far below that bound (symmetric meshes): a probe on one component tries earlier (Early_termination);
//  5. rational reconstruction with a common denominator d, num = d x: only the seeds of a peeling of
//     the pattern of A (Numerator_plan, about a tenth of the unknowns on irregular meshes, about
//     sqrt(n) on grids) come from their digits: an extended Euclid on a component finds d, then a
//     numerator is d x_c modulo p^(T/2) (half the digits, one product); every other numerator follows
//     from a row whose other unknowns are known (an exact division by a small entry);
//  6. verification A num = d b in integers of the rows that did not define a numerator (on failure:
//     more steps, then the caller's rational elimination), then lowest terms (internal/lowest_terms.h:
//     about one product modulo d's large part per component instead of a gcd).
// The cost is about T * (fill + nnz) word operations plus a product and a division of T/2-word
// integers per component (the lowest terms); T grows with the size of the exact solution (about 2 bits
// per vertex for numerator and denominator each), so the whole grows a little faster than the square
// of the size.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/tutte_system.h>
#include <CGAL/Progressive_embedding/internal/tutte_solve.h>
#include <CGAL/Progressive_embedding/internal/lowest_terms.h>
#include <CGAL/Progressive_embedding/internal/parallel_for.h>

#include <CGAL/Gmpq.h>
#include <gmpxx.h>

#include <algorithm>
#include <atomic>
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

// 64-bit values into and out of GMP integers (unsigned long may have 32 bits)
constexpr bool long_has_64_bits = sizeof(unsigned long) >= sizeof(std::uint64_t);

inline void set_uint64(mpz_class& z, std::uint64_t v)
{
  if constexpr(long_has_64_bits) { z = static_cast<unsigned long>(v); return; }
  z = static_cast<unsigned long>(v >> 32);
  z <<= 32;
  z += static_cast<unsigned long>(v & 0xffffffffu);
}

inline mpz_class mpz_from_uint64(std::uint64_t v) { mpz_class z; set_uint64(z, v); return z; }

// |z| modulo 2^64
inline std::uint64_t low_64_bits(const mpz_class& z)
{
  if constexpr(long_has_64_bits) return mpz_get_ui(z.get_mpz_t());
  const mpz_class a = abs(z), high = a >> 32;
  return (std::uint64_t(mpz_get_ui(high.get_mpz_t())) << 32) | (mpz_get_ui(a.get_mpz_t()) & 0xffffffffu);
}

// Arithmetic modulo a prime p = 2^62 - c, c < 2^8: 2^62 = c (mod p) and 2^64 = 4c, so a value reduces
// by folding its high bits onto its low ones (no division, no precomputed reciprocal).
struct Modulus
{
  static constexpr std::uint64_t mask62 = (std::uint64_t(1) << 62) - 1;
  std::uint64_t p = 0, c = 0, c4 = 0;
  explicit Modulus(std::uint64_t prime = mask62 - 56)
    : p(prime), c(mask62 + 1 - prime), c4(4 * (mask62 + 1 - prime)) { }
  std::uint64_t reduce(std::uint64_t x) const
  {
    x = (x & mask62) + (x >> 62) * c; // below p + 4c
    return x >= p ? x - p : x;
  }
  // x = h 2^64 + l = 4c h + l (below 2^75) = 4c h' + l' (below 2^64 + 2^21)
  std::uint64_t reduce(std::uint64_t high, std::uint64_t low) const
  {
    const unsigned __int128 t = static_cast<unsigned __int128>(high) * c4;
    std::uint64_t l, r;
    const std::uint64_t h = static_cast<std::uint64_t>(t >> 64) + __builtin_add_overflow(static_cast<std::uint64_t>(t), low, &l);
    if(__builtin_add_overflow(l, h * c4, &r)) r += c4; // r - 2^64 + 4c, below 2^22
    return reduce(r);
  }
  std::uint64_t reduce(unsigned __int128 x) const { return reduce(static_cast<std::uint64_t>(x >> 64), static_cast<std::uint64_t>(x)); }
  // |x| < 2^63
  std::uint64_t reduce(std::int64_t x) const
  {
    if(x >= 0) return reduce(static_cast<std::uint64_t>(x));
    const std::uint64_t r = reduce(std::uint64_t(0) - static_cast<std::uint64_t>(x));
    return r ? p - r : 0;
  }
  std::uint64_t reduce(const mpz_class& z) const
  {
    if constexpr(long_has_64_bits) return mpz_fdiv_ui(z.get_mpz_t(), static_cast<unsigned long>(p));
    mpz_class r;
    mpz_fdiv_r(r.get_mpz_t(), z.get_mpz_t(), mpz_from_uint64(p).get_mpz_t());
    return low_64_bits(r);
  }
  std::uint64_t add(std::uint64_t a, std::uint64_t b) const { const std::uint64_t s = a + b; return s >= p ? s - p : s; }
  std::uint64_t mul(std::uint64_t a, std::uint64_t b) const { return reduce(static_cast<unsigned __int128>(a) * b); }
  std::uint64_t power(std::uint64_t a, std::uint64_t e) const
  {
    std::uint64_t r = 1;
    a = reduce(a);
    for(; e; e >>= 1) { if(e & 1) r = mul(r, a); a = mul(a, a); }
    return r;
  }
};

// Sparse LU of the integer matrix modulo p on the symbolic structure F; false on a zero pivot.
// For the solves the factors are kept as columns and values in step numbering, one stream per
// triangle, with the signs and pivots folded in: row k of L holds -L_kj, row k of U holds
// -U_kc / U_kk, so that each row of a solve is one sum of products.
struct Modular_lu
{
  Modulus mod;
  const Symbolic_factorization* F = nullptr;
  std::vector<std::uint32_t> l_col, u_col;
  std::vector<std::uint64_t> l_val, u_val, inv_pivot;

  bool factor(const Integer_system& I, const Symbolic_factorization& sf, std::uint64_t prime)
  {
    mod = Modulus(prime); F = &sf;
    const std::uint64_t p = mod.p;
    const std::size_t n = sf.n;
    l_col.assign(sf.l_col.begin(), sf.l_col.end()); u_col.assign(sf.u_col.begin(), sf.u_col.end());
    l_val.assign(sf.l_col.size(), 0); u_val.assign(sf.u_col.size(), 0); inv_pivot.assign(n, 0);
    std::vector<std::uint64_t> w(n, 0);
    for(std::size_t k = 0; k < n; ++k)
    {
      const auto& row = I.rows[sf.order[k]];
      for(int e = sf.a_ptr[k]; e < sf.a_ptr[k + 1]; ++e)
        w[sf.a_col[e]] = mod.reduce(row[static_cast<std::size_t>(sf.a_src[e] + 1)].second);
      for(int e = sf.l_ptr[k]; e < sf.l_ptr[k + 1]; ++e)
      {
        const int j = sf.l_col[e];
        const std::uint64_t lv = mod.mul(w[j], inv_pivot[j]);
        const std::uint64_t ml = lv ? p - lv : 0;
        l_val[e] = ml;
        w[j] = 0;
        for(int f = sf.u_ptr[j]; f < sf.u_ptr[j + 1]; ++f)
          w[u_col[f]] = mod.reduce(static_cast<unsigned __int128>(ml) * u_val[f] + w[u_col[f]]);
      }
      if(w[k] == 0) return false;
      inv_pivot[k] = mod.power(w[k], p - 2);
      w[k] = 0;
      for(int f = sf.u_ptr[k]; f < sf.u_ptr[k + 1]; ++f) { u_val[f] = w[u_col[f]]; w[u_col[f]] = 0; }
    }
    for(std::size_t k = 0; k < n; ++k)
      for(int f = sf.u_ptr[k]; f < sf.u_ptr[k + 1]; ++f)
      {
        const std::uint64_t v = mod.mul(u_val[f], inv_pivot[k]);
        u_val[f] = v ? p - v : 0;
      }
    return true;
  }

  // (ru, rv) += sum_e val[e] (y[2 col[e]], y[2 col[e] + 1]) over e < count, modulo p. Values and y
  // are below p < 2^62: sixteen products fit in 128 bits, kept as two words (the compiler keeps
  // unsigned __int128 accumulators in memory), reduced once per sixteen.
  void row_sum(const std::uint32_t* col, const std::uint64_t* val, std::size_t count, const std::uint64_t* y,
               std::uint64_t& ru, std::uint64_t& rv) const
  {
    for(std::size_t first = 0; first < count; first += 16)
    {
      const std::size_t end = (std::min)(count, first + 16);
      std::uint64_t ul = 0, uh = 0, vl = 0, vh = 0;
      for(std::size_t e = first; e < end; ++e)
      {
        const std::uint64_t a = val[e];
        const std::uint64_t* yj = y + 2 * std::size_t(col[e]);
        const unsigned __int128 pu = static_cast<unsigned __int128>(a) * yj[0], pv = static_cast<unsigned __int128>(a) * yj[1];
        const std::uint64_t pul = static_cast<std::uint64_t>(pu), puh = static_cast<std::uint64_t>(pu >> 64);
        const std::uint64_t pvl = static_cast<std::uint64_t>(pv), pvh = static_cast<std::uint64_t>(pv >> 64);
        ul += pul; uh += puh + (ul < pul);
        vl += pvl; vh += pvh + (vl < pvl);
      }
      ru = mod.add(ru, mod.reduce(uh, ul));
      rv = mod.add(rv, mod.reduce(vh, vl));
    }
  }

  // r += sum_e val[e] y[col[e]] over e < count, modulo p (row_sum for one coordinate)
  void row_sum_one(const std::uint32_t* col, const std::uint64_t* val, std::size_t count, const std::uint64_t* y,
                   std::uint64_t& r) const
  {
    for(std::size_t first = 0; first < count; first += 16)
    {
      const std::size_t end = (std::min)(count, first + 16);
      std::uint64_t lo = 0, hi = 0;
      for(std::size_t e = first; e < end; ++e)
      {
        const unsigned __int128 pr = static_cast<unsigned __int128>(val[e]) * y[col[e]];
        const std::uint64_t pl = static_cast<std::uint64_t>(pr);
        lo += pl; hi += static_cast<std::uint64_t>(pr >> 64) + (lo < pl);
      }
      r = mod.add(r, mod.reduce(hi, lo));
    }
  }

  // y = A^-1 y mod p for one coordinate (step numbering): the two coordinates in arrays of their own
  // can be solved at the same time
  void solve_one(std::vector<std::uint64_t>& yv) const
  {
    const std::size_t n = F->n;
    const int* lp = F->l_ptr.data();
    const int* up = F->u_ptr.data();
    std::uint64_t* y = yv.data();
    for(std::size_t k = 0; k < n; ++k)
      row_sum_one(l_col.data() + lp[k], l_val.data() + lp[k], std::size_t(lp[k + 1] - lp[k]), y, y[k]);
    for(std::size_t k = n; k-- > 0; )
    {
      std::uint64_t r = mod.mul(y[k], inv_pivot[k]);
      row_sum_one(u_col.data() + up[k], u_val.data() + up[k], std::size_t(up[k + 1] - up[k]), y, r);
      y[k] = r;
    }
  }

  // y = A^-1 y mod p (step numbering, interleaved u, v)
  void solve(std::vector<std::uint64_t>& yv) const
  {
    const std::size_t n = F->n;
    const int* lp = F->l_ptr.data();
    const int* up = F->u_ptr.data();
    std::uint64_t* y = yv.data();
    for(std::size_t k = 0; k < n; ++k)
    {
      std::uint64_t ru = y[2 * k], rv = y[2 * k + 1];
      row_sum(l_col.data() + lp[k], l_val.data() + lp[k], std::size_t(lp[k + 1] - lp[k]), y, ru, rv);
      y[2 * k] = ru; y[2 * k + 1] = rv;
    }
    for(std::size_t k = n; k-- > 0; )
    {
      std::uint64_t ru = mod.mul(y[2 * k], inv_pivot[k]), rv = mod.mul(y[2 * k + 1], inv_pivot[k]);
      row_sum(u_col.data() + up[k], u_val.data() + up[k], std::size_t(up[k + 1] - up[k]), y, ru, rv);
      y[2 * k] = ru; y[2 * k + 1] = rv;
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
inline void combine_digits(const std::vector<std::uint64_t>& digits, std::size_t stride, std::size_t offset, std::size_t T,
                           const std::vector<mpz_class>& powers, std::vector<mpz_class>& v, mpz_class& out)
{
  v.resize(T);
  for(std::size_t t = 0; t < T; ++t) set_uint64(v[t], digits[t * stride + offset]);
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

// Which unknowns the reconstruction takes from their p-adic digits (the seeds), and which follow
// from a row of A N = d b whose other unknowns are known (one exact division by a small entry instead
// of the products of a reconstruction): a peeling of the pattern of A. A row whose unknowns are all
// known but one defines it; when none is left, a seed is taken in a row with the fewest unknowns
// left, the one that completes the most rows with two.
struct Numerator_plan
{
  std::vector<std::size_t> seeds;                          // in the order taken
  std::vector<std::pair<std::size_t, std::size_t> > steps; // (row, unknown it defines), in order
  std::vector<char> defining;                              // rows that hold by construction
};

inline void plan_numerators(const Integer_system& I, Numerator_plan& plan)
{
  const std::size_t n = I.rows.size();
  plan.seeds.clear(); plan.steps.clear(); plan.defining.assign(n, 0);
  // the rows of each unknown
  std::vector<std::size_t> cptr(n + 1, 0), crow;
  for(std::size_t r = 0; r < n; ++r) for(const auto& e : I.rows[r]) ++cptr[e.first + 1];
  for(std::size_t j = 0; j < n; ++j) cptr[j + 1] += cptr[j];
  crow.resize(cptr[n]);
  {
    std::vector<std::size_t> fill(cptr.begin(), cptr.end() - 1);
    for(std::size_t r = 0; r < n; ++r) for(const auto& e : I.rows[r]) crow[fill[e.first]++] = r;
  }
  std::vector<std::size_t> left(n);   // unknowns of each row not known yet
  std::size_t longest = 0;
  for(std::size_t r = 0; r < n; ++r) { left[r] = I.rows[r].size(); longest = (std::max)(longest, left[r]); }
  std::vector<char> known(n, 0);
  std::vector<std::vector<std::size_t> > bucket(longest + 1); // rows by `left` (stale entries skipped)
  for(std::size_t r = 0; r < n; ++r) bucket[left[r]].push_back(r);
  std::size_t lowest = 0, unknown = n;
  auto learn = [&](std::size_t j) {
    known[j] = 1; --unknown;
    for(std::size_t e = cptr[j]; e < cptr[j + 1]; ++e)
    {
      const std::size_t r = crow[e];
      --left[r];
      if(!plan.defining[r]) { bucket[left[r]].push_back(r); lowest = (std::min)(lowest, left[r]); }
    }
  };
  // each pass defines an unknown or takes a seed: at most n passes, plus the stale bucket entries
  for(std::size_t guard = 0; unknown > 0 && guard < n + cptr[n] + longest + 2; ++guard)
  {
    while(lowest <= longest && (bucket[lowest].empty() || lowest == 0))
    {
      if(lowest == 0) { bucket[0].clear(); ++lowest; continue; }
      ++lowest;
    }
    if(lowest > longest) break;
    const std::size_t r = bucket[lowest].back();
    bucket[lowest].pop_back();
    if(plan.defining[r] || left[r] != lowest) continue; // stale
    // the unknowns of row r not known yet
    if(lowest == 1)
    {
      for(const auto& e : I.rows[r])
        if(!known[e.first])
        {
          if(e.second != 0) { plan.defining[r] = 1; plan.steps.emplace_back(r, e.first); learn(e.first); }
          break;
        }
      continue;
    }
    // a seed in row r: the unknown that completes the most rows with two unknowns left
    std::size_t best = n, best_score = 0;
    for(const auto& e : I.rows[r])
    {
      if(known[e.first]) continue;
      std::size_t score = 1;
      for(std::size_t f = cptr[e.first]; f < cptr[e.first + 1]; ++f) if(!plan.defining[crow[f]] && left[crow[f]] == 2) ++score;
      if(score > best_score) { best = e.first; best_score = score; }
    }
    bucket[lowest].push_back(r); // r is still to be used
    plan.seeds.push_back(best);
    learn(best);
  }
  // (an unknown no row could define, its last row's entry zero: a seed too)
  for(std::size_t j = 0; j < n; ++j) if(!known[j]) { plan.seeds.push_back(j); known[j] = 1; }
}

// From the p-adic digits of the seeds over the first T steps (digits[t * 2 * seeds + 2 * i + side]),
// the rational solution, verified exactly (A x = b in integers); false if the digits do not
// determine it yet. With CGAL::Parallel_tag (and TBB), the seeds' numerators over the d of the first
// seed, the verification and the lowest terms in two halves at the same time.
template <class ConcurrencyTag = CGAL::Sequential_tag>
bool reconstruct_solution(const Integer_system& I, const Numerator_plan& plan, const std::vector<std::uint64_t>& digits,
                                 std::size_t T, std::uint64_t p, Progress_budget& budget, double progress_from,
                                 std::vector<CGAL::Gmpq>& xu, std::vector<CGAL::Gmpq>& xv, bool& stopped)
{
  stopped = false;
  const std::size_t n = I.rows.size(), m = 2 * plan.seeds.size();
  std::vector<mpz_class> powers(1, mpz_from_uint64(p));
  while((std::size_t(1) << powers.size()) < T) powers.push_back(powers.back() * powers.back());
  mpz_class M;
  mpz_pow_ui(M.get_mpz_t(), powers[0].get_mpz_t(), static_cast<unsigned long>(T));
  const mpz_class half = M / 2;
  mpz_class bound;
  mpz_sqrt(bound.get_mpz_t(), half.get_mpz_t());
  // two digits more than half of them: a component that is not over d passes the test |y| < bound
  // by chance with a probability below 1/p^2 (and then fails the verification)
  const std::size_t T2 = (std::min)(T, (T + 1) / 2 + 2);
  mpz_class M2, d_low, d_low_of = 0;
  mpz_pow_ui(M2.get_mpz_t(), powers[0].get_mpz_t(), static_cast<unsigned long>(T2));
  const mpz_class half2 = M2 / 2;
  // the seeds: x_c = num[c] / d over the common denominator d; an extended Euclid finds d (or a new
  // factor of it) on a component that is not over the d known so far; every other seed needs one
  // product (its numerator is d x_c mod M, small)
  mpz_class d = 1, X, y, s;
  std::vector<mpz_class> num(2 * n), scratch;
  std::vector<mpz_class> d_growth;  // the factors of d, in the order found,
  std::vector<std::size_t> grew_at; // and the seed component where each was found
  const double share = (1 - progress_from) / 2;
  const bool parallel = pair_is_parallel<ConcurrencyTag>();
  // In parallel: X d mod p^T2 for the seeds ahead, beforehand, over the d known after the first two
  // seed components (usually all of it); when d has grown since by a factor f, such a value times f.
  std::vector<mpz_class> early(parallel ? m : 0);
  std::vector<char> early_ok(parallel ? m : 0, 0);
  mpz_class early_d = 0, early_f, early_f_of = 0;
  auto precompute = [&](std::size_t from) {
    early_d = d;
    mpz_class low;
    mpz_fdiv_r(low.get_mpz_t(), d.get_mpz_t(), M2.get_mpz_t());
    std::atomic<bool> stop(false);
    auto range = [&](std::size_t begin, std::size_t end) {
      std::vector<mpz_class> work;
      mpz_class Xi;
      for(std::size_t i = begin; i < end && !stop.load(); ++i)
      {
        combine_digits(digits, m, i, T2, powers, work, Xi);
        mpz_mul(early[i].get_mpz_t(), Xi.get_mpz_t(), low.get_mpz_t());
        mpz_fdiv_r(early[i].get_mpz_t(), early[i].get_mpz_t(), M2.get_mpz_t());
        early_ok[i] = 1;
        if((i & 63) == 0 && !budget.time_left()) stop = true;
      }
    };
    const std::size_t mid = from + (m - from) / 2;
    run_pair<ConcurrencyTag>([&] { range(from, mid); }, [&] { range(mid, m); });
  };
  for(std::size_t i = 0; i < m; ++i)
  {
    const std::size_t c = 2 * plan.seeds[i / 2] + i % 2;
    if(parallel && i == 2 && m > 64) precompute(i);
    if(parallel && early_ok[i])
    {
      if(d != early_d)
      {
        if(early_f_of != d) { mpz_divexact(early_f.get_mpz_t(), d.get_mpz_t(), early_d.get_mpz_t()); early_f_of = d; }
        early[i] *= early_f;
        mpz_fdiv_r(early[i].get_mpz_t(), early[i].get_mpz_t(), M2.get_mpz_t());
      }
      if(early[i] > half2) early[i] -= M2;
      const bool over_d = abs(early[i]) < bound;
      if(over_d) num[c].swap(early[i]);
      mpz_class().swap(early[i]);
      if(over_d)
      {
        if((i & 63) == 0 && !budget.report(progress_from + share * double(i) / double(m + n))) { stopped = true; return false; }
        continue;
      }
      // not over d: the way below
    }
    if(d_low_of != d) { mpz_fdiv_r(d_low.get_mpz_t(), d.get_mpz_t(), M2.get_mpz_t()); d_low_of = d; }
    combine_digits(digits, m, i, T2, powers, scratch, X);
    mpz_mul(y.get_mpz_t(), X.get_mpz_t(), d_low.get_mpz_t());
    mpz_fdiv_r(y.get_mpz_t(), y.get_mpz_t(), M2.get_mpz_t());
    if(y > half2) y -= M2;
    if(abs(y) >= bound)
    {
      // not over d (or not determined yet): all T digits
      combine_digits(digits, m, i, T, powers, scratch, X);
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
    if((i & 63) == 0 && !budget.report(progress_from + share * double(i) / double(m + n))) { stopped = true; return false; }
  }
  // numerators over the final d: the one of seed component i was over the product of the factors found up to i
  if(!d_growth.empty())
  {
    mpz_class f = 1;
    std::size_t h = d_growth.size();
    for(std::size_t i = m; i-- > 0; )
    {
      while(h > 0 && grew_at[h - 1] > i) { f *= d_growth[h - 1]; --h; }
      if(f != 1) num[2 * plan.seeds[i / 2] + i % 2] *= f;
    }
  }
  // the other unknowns, each from its row: A_rj num_j = d b_r - sum_k A_rk num_k, an exact division
  // unless x_j has a denominator that does not divide d (then d grows by the missing factor)
  std::vector<std::size_t> known; // the components known, for such a growth
  known.reserve(2 * n);
  for(std::size_t i = 0; i < m; ++i) known.push_back(2 * plan.seeds[i / 2] + i % 2);
  mpz_class g;
  for(std::size_t q = 0; q < plan.steps.size(); ++q)
  {
    const std::size_t r = plan.steps[q].first, j = plan.steps[q].second;
    const mpz_class* a_rj = nullptr;
    for(const auto& e : I.rows[r]) if(e.first == j) a_rj = &e.second;
    if(a_rj == nullptr || *a_rj == 0) return false;
    for(int side = 0; side < 2; ++side)
    {
      mpz_mul(s.get_mpz_t(), (side ? I.bv[r] : I.bu[r]).get_mpz_t(), d.get_mpz_t());
      for(const auto& e : I.rows[r])
        if(e.first != j) mpz_submul(s.get_mpz_t(), e.second.get_mpz_t(), num[2 * e.first + side].get_mpz_t());
      mpz_class& out = num[2 * j + side];
      if(mpz_divisible_p(s.get_mpz_t(), a_rj->get_mpz_t())) mpz_divexact(out.get_mpz_t(), s.get_mpz_t(), a_rj->get_mpz_t());
      else
      {
        mpz_gcd(g.get_mpz_t(), s.get_mpz_t(), a_rj->get_mpz_t());
        mpz_class f = abs(*a_rj) / g; // x_j = s / (a_rj d) = (s / (a_rj / f)) / (f d)
        for(std::size_t c : known) num[c] *= f;
        d *= f;
        mpz_divexact(out.get_mpz_t(), s.get_mpz_t(), mpz_class(*a_rj / f).get_mpz_t());
      }
      known.push_back(2 * j + side);
    }
    if((q & 255) == 0 && !budget.report(progress_from + share * double(m + q) / double(m + n))) { stopped = true; return false; }
  }
  // verification in integers: sum_j A_rj num_j = b_r d (the rows that defined an unknown hold by construction)
  std::atomic<bool> wrong(false);
  auto verify = [&](std::size_t begin, std::size_t end) {
    mpz_class sum;
    for(std::size_t r = begin; r < end && !wrong.load(); ++r)
      if(!plan.defining[r])
      for(int side = 0; side < 2; ++side)
      {
        mpz_mul(sum.get_mpz_t(), (side ? I.bv[r] : I.bu[r]).get_mpz_t(), d.get_mpz_t());
        for(const auto& e : I.rows[r]) mpz_submul(sum.get_mpz_t(), e.second.get_mpz_t(), num[2 * e.first + side].get_mpz_t());
        if(sum != 0) { wrong = true; return; }
      }
  };
  run_pair<ConcurrencyTag>([&] { verify(0, n / 2); }, [&] { verify(n / 2, n); });
  if(wrong.load()) return false;
  if(!budget.report(progress_from + share)) { stopped = true; return false; }
  if(!canonical_fractions<ConcurrencyTag>(num, d, budget, progress_from + share, xu, xv)) { stopped = true; return false; }
  return true;
}

// When to try the reconstruction before the estimated number of steps: the common denominator d can
// be far below the bound from the determinant (on symmetric meshes, factors of det A cancel with every
// numerator). A probe reconstructs the first seed's u-coordinate alone (an extended Euclid, from half
// the estimated steps on, every eighth of them); while later digits agree with that fraction (one
// product every 64th), the digits likely determine it, and the whole solution is tried (verified
// as at the estimate); after a failed try, not again before another sixteenth of the steps.
class Early_termination
{
public:
  explicit Early_termination(std::size_t T_goal)
    : m_goal(T_goal), m_check((std::max)(std::size_t(1), T_goal / 64)), m_next_euclid(T_goal / 2), m_not_before(0) { }

  // true if the solution is worth trying after t steps (digits of the seeds, `m` per step)
  bool ready(const std::vector<std::uint64_t>& digits, std::size_t m, std::size_t t, std::uint64_t p)
  {
    if(m_have && t % m_check == 0)
    {
      value(digits, m, t, p);
      mpz_mul(m_y.get_mpz_t(), m_x.get_mpz_t(), m_b.get_mpz_t());
      m_y -= m_a;
      mpz_fdiv_r(m_y.get_mpz_t(), m_y.get_mpz_t(), m_modulus.get_mpz_t());
      if(m_y != 0) m_have = false;
      else if(t >= m_since + 2 * m_check && t >= m_not_before) return true;
    }
    if(!m_have && t >= m_next_euclid)
    {
      m_next_euclid = t + (std::max)(std::size_t(1), m_goal / 8);
      value(digits, m, t, p);
      mpz_class half = m_modulus / 2, bound;
      mpz_sqrt(bound.get_mpz_t(), half.get_mpz_t());
      m_have = rational_reconstruction(m_x, m_modulus, bound, m_a, m_b);
      m_since = t;
    }
    return false;
  }

  void failed(std::size_t t) { m_not_before = t + (std::max)(std::size_t(1), m_goal / 16); }

private:
  // m_x = the first seed's u-coordinate modulo m_modulus = p^t
  void value(const std::vector<std::uint64_t>& digits, std::size_t m, std::size_t t, std::uint64_t p)
  {
    if(m_powers.empty()) m_powers.push_back(mpz_from_uint64(p));
    while((std::size_t(1) << m_powers.size()) < t) m_powers.push_back(m_powers.back() * m_powers.back());
    combine_digits(digits, m, 0, t, m_powers, m_scratch, m_x);
    mpz_pow_ui(m_modulus.get_mpz_t(), m_powers[0].get_mpz_t(), static_cast<unsigned long>(t));
  }

  std::size_t m_goal, m_check, m_next_euclid, m_not_before, m_since = 0;
  bool m_have = false;
  mpz_class m_a, m_b, m_x, m_y, m_modulus;
  std::vector<mpz_class> m_powers, m_scratch;
};

// Solves S in rationals by p-adic lifting. Returns ERROR_CANNOT_SOLVE_LINEAR_SYSTEM when it
// cannot conclude (unlucky primes, failed verification): the caller then eliminates in rationals.
// The solution is tried at the estimated number of steps (then every quarter of it more, up to
// the Hadamard bound); without an estimate after 16, 32, 64, ... steps and at the Hadamard bound.
// With CGAL::Parallel_tag (and TBB), the two coordinates are lifted at the same time, and the
// reconstruction runs in two halves (reconstruct_solution()); the result is the same.
template <class ConcurrencyTag = CGAL::Sequential_tag>
Error_code solve_by_p_adic_lifting(const Tutte_system<CGAL::Gmpq>& S, Progress_budget& budget,
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
  // primes 2^62 - c (Modulus)
  const std::uint64_t primes[] = { (std::uint64_t(1) << 62) - 57, (std::uint64_t(1) << 62) - 87,
                                   (std::uint64_t(1) << 62) - 117, (std::uint64_t(1) << 62) - 143 };
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
  Numerator_plan plan;
  plan_numerators(I, plan);
  const std::size_t m = 2 * plan.seeds.size();

  // The residuals, in step numbering. |r_{t+1}| <= |r_t| / p + sum|A_rj|: for a row whose entries fit
  // in 64 bits with sum|A_rj| < 2^59 and |b| < 2^120, the quotients (r_t - A x_t) / p stay below 2^62,
  // so that 64-bit arithmetic modulo 2^64 gives them exactly (a division by p is a product by its
  // inverse modulo 2^64): r_0 = b is kept modulo 2^64 only. The other rows in GMP integers.
  std::vector<char> big(n, 0);
  std::vector<std::int64_t> aval;
  std::vector<std::uint32_t> acol;
  std::vector<std::size_t> aptr(n + 1, 0);
  std::vector<std::uint64_t> ru64(n, 0), rv64(n, 0); // two's complement
  std::vector<mpz_class> ru(n), rv(n);
  std::vector<std::uint64_t> y(2 * n), y_next(2 * n);
  auto low_word = [](const mpz_class& z) { // z modulo 2^64
    const std::uint64_t v = low_64_bits(z);
    return z < 0 ? std::uint64_t(0) - v : v;
  };
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::size_t r = static_cast<std::size_t>(F.order[k]);
    double sum = 0;
    for(const auto& e : I.rows[r])
    {
      if(mpz_sizeinbase(e.second.get_mpz_t(), 2) > 62) big[k] = 1;
      sum += std::abs(mpz_get_d(e.second.get_mpz_t()));
    }
    if(sum >= std::ldexp(1., 59) || mpz_sizeinbase(I.bu[r].get_mpz_t(), 2) > 119 || mpz_sizeinbase(I.bv[r].get_mpz_t(), 2) > 119) big[k] = 1;
    if(!big[k])
    {
      for(int e = F.a_ptr[k]; e < F.a_ptr[k + 1]; ++e)
      {
        const mpz_class& a = I.rows[r][static_cast<std::size_t>(F.a_src[e] + 1)].second;
        acol.push_back(static_cast<std::uint32_t>(F.a_col[e]));
        aval.push_back(static_cast<std::int64_t>(low_word(a)));
      }
      ru64[k] = low_word(I.bu[r]); rv64[k] = low_word(I.bv[r]);
    }
    else { ru[k] = I.bu[r]; rv[k] = I.bv[r]; }
    y[2 * k] = lu.mod.reduce(I.bu[r]); y[2 * k + 1] = lu.mod.reduce(I.bv[r]);
    aptr[k + 1] = acol.size();
  }
  // 1/p modulo 2^64 (Newton: each step doubles the correct low bits)
  std::uint64_t pinv = p;
  for(int k = 0; k < 6; ++k) pinv *= 2 - p * pinv;
  const mpz_class p_mpz = mpz_from_uint64(p);
  mpz_class x_mpz;

  std::vector<std::uint64_t> digits; // the seeds' digits of every step
  digits.reserve(m * (std::min)(T_goal ? T_goal : T_max, std::size_t(1) << 20));
  std::vector<std::size_t> seed_step(plan.seeds.size());
  for(std::size_t i = 0; i < plan.seeds.size(); ++i) seed_step[i] = static_cast<std::size_t>(F.step[plan.seeds[i]]);
  Early_termination early(T_goal);
  const bool parallel = pair_is_parallel<ConcurrencyTag>();
  // one coordinate of a step: x_t = A^-1 r_t mod p, r_{t+1} = (r_t - A x_t) / p and its residues,
  // in arrays of that coordinate only (two threads write no common cache line)
  std::vector<std::uint64_t> ys[2], ys_next[2];
  if(parallel)
    for(std::size_t side = 0; side < 2; ++side)
    {
      ys[side].resize(n); ys_next[side].resize(n);
      for(std::size_t k = 0; k < n; ++k) ys[side][k] = y[2 * k + side];
    }
  auto lift_side = [&](std::size_t side, mpz_class& x_side) {
    std::vector<std::uint64_t>& xs = ys[side];
    std::vector<std::uint64_t>& next = ys_next[side];
    lu.solve_one(xs);
    std::vector<std::uint64_t>& r64 = side ? rv64 : ru64;
    std::vector<mpz_class>& rbig = side ? rv : ru;
    for(std::size_t k = 0; k < n; ++k)
    {
      if(!big[k])
      {
        std::uint64_t sum = r64[k];
        for(std::size_t e = aptr[k]; e < aptr[k + 1]; ++e) sum -= static_cast<std::uint64_t>(aval[e]) * xs[acol[e]];
        r64[k] = sum * pinv;
        next[k] = lu.mod.reduce(static_cast<std::int64_t>(r64[k]));
        continue;
      }
      const std::size_t r = static_cast<std::size_t>(F.order[k]);
      for(const auto& e : I.rows[r])
      {
        const std::uint64_t xj = xs[static_cast<std::size_t>(F.step[e.first])];
        if(xj) { set_uint64(x_side, xj); mpz_submul(rbig[k].get_mpz_t(), e.second.get_mpz_t(), x_side.get_mpz_t()); }
      }
      mpz_divexact(rbig[k].get_mpz_t(), rbig[k].get_mpz_t(), p_mpz.get_mpz_t());
      next[k] = lu.mod.reduce(rbig[k]);
    }
  };
  mpz_class x_v;
  for(std::size_t t = 0; t < T_max; ++t)
  {
    if(parallel)
    {
      run_pair<ConcurrencyTag>([&] { lift_side(0, x_mpz); }, [&] { lift_side(1, x_v); });
      for(std::size_t i = 0; i < seed_step.size(); ++i)
      {
        digits.push_back(ys[0][seed_step[i]]);
        digits.push_back(ys[1][seed_step[i]]);
      }
      ys[0].swap(ys_next[0]); ys[1].swap(ys_next[1]);
    }
    else
    {
    lu.solve(y); // x_t = A^-1 r_t mod p
    const std::uint64_t* x = y.data();
    for(std::size_t i = 0; i < seed_step.size(); ++i)
    {
      digits.push_back(x[2 * seed_step[i]]);
      digits.push_back(x[2 * seed_step[i] + 1]);
    }
    // r_{t+1} = (r_t - A x_t) / p, exact, and its residues for the next step
    for(std::size_t k = 0; k < n; ++k)
    {
      if(!big[k])
      {
        std::uint64_t su = ru64[k], sv = rv64[k];
        for(std::size_t e = aptr[k]; e < aptr[k + 1]; ++e)
        {
          const std::uint64_t a = static_cast<std::uint64_t>(aval[e]);
          const std::uint64_t* xj = x + 2 * std::size_t(acol[e]);
          su -= a * xj[0]; sv -= a * xj[1];
        }
        ru64[k] = su * pinv; rv64[k] = sv * pinv;
        y_next[2 * k] = lu.mod.reduce(static_cast<std::int64_t>(ru64[k]));
        y_next[2 * k + 1] = lu.mod.reduce(static_cast<std::int64_t>(rv64[k]));
        continue;
      }
      const std::size_t r = static_cast<std::size_t>(F.order[k]);
      for(const auto& e : I.rows[r])
      {
        const std::uint64_t* xj = x + 2 * std::size_t(F.step[e.first]);
        if(xj[0]) { set_uint64(x_mpz, xj[0]); mpz_submul(ru[k].get_mpz_t(), e.second.get_mpz_t(), x_mpz.get_mpz_t()); }
        if(xj[1]) { set_uint64(x_mpz, xj[1]); mpz_submul(rv[k].get_mpz_t(), e.second.get_mpz_t(), x_mpz.get_mpz_t()); }
      }
      mpz_divexact(ru[k].get_mpz_t(), ru[k].get_mpz_t(), p_mpz.get_mpz_t());
      mpz_divexact(rv[k].get_mpz_t(), rv[k].get_mpz_t(), p_mpz.get_mpz_t());
      y_next[2 * k] = lu.mod.reduce(ru[k]); y_next[2 * k + 1] = lu.mod.reduce(rv[k]);
    }
    y.swap(y_next);
    }
    // progress: the lifting is the first half of the work when the number of steps is known
    const double lifted = double(t + 1) / double(T_goal ? T_goal : T_max);
    if(!budget.report(0.5 * (std::min)(1., lifted))) return ERROR_BUDGET_EXHAUSTED;
    bool attempt = (t + 1 == next_try || t + 1 == T_max);
    if(!attempt && T_goal && m > 0 && t + 1 < next_try)
      attempt = early.ready(digits, m, t + 1, p);
    if(attempt)
    {
      bool stopped = false;
      if(reconstruct_solution<ConcurrencyTag>(I, plan, digits, t + 1, p, budget, 0.5, xu, xv, stopped)) return budget.report(1) ? OK : ERROR_BUDGET_EXHAUSTED;
      if(stopped) return ERROR_BUDGET_EXHAUSTED;
      if(t + 1 < next_try) { early.failed(t + 1); continue; }
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
