// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_LOWEST_TERMS_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_LOWEST_TERMS_H

// Exact fractions num[c] / d over a common denominator d, put in lowest terms (CGAL::Gmpq) without a
// gcd of full size per fraction: the exact Tutte solve (internal/tutte_p_adic.h) reconstructs its
// solution as integer numerators over one denominator.

#include <CGAL/Progressive_embedding/internal/tutte_solve.h>
#include <CGAL/Progressive_embedding/internal/parallel_for.h>

#include <CGAL/Gmpq.h>
#include <gmpxx.h>

#include <atomic>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// The fractions num[c] / d (d > 0) for c in [begin, end) in lowest terms, into xu (even c) and xv
// (odd c), both already of their size; num[c] is emptied on the way. A gcd per component costs
// several times a product, so the common denominator is split:
// d = s Q with s made of the primes below 2^16 (trial division) and Q free of them. Each numerator
// is reduced against s (a small gcd). Q is kept as pairwise coprime factors f, at first Q itself:
// for each numerator and factor f, f divides the numerator (f holds full powers of its primes in d),
// or the remainder joins a product modulo f, whose gcd with f is checked every `window` numerators
// (one product modulo Q per component and one gcd in the usual case, all numerators coprime to Q).
// When that gcd t is not 1, f splits into its t-part A and a rest coprime to the window's
// numerators, which get their gcds with A; a gcd that separates primes of A splits it further.
// (Symmetric meshes have many numerators sharing large factors with d: the factors soon become
// those that divide each numerator or not.) The caller gives s and Q; false when `report(c)`,
// called every 256 components, returns false.
template <class Report>
bool canonical_fractions_range(std::vector<mpz_class>& num, const mpz_class& d, const mpz_class& s, const mpz_class& Q,
                               std::size_t begin, std::size_t end, Report report,
                               std::vector<CGAL::Gmpq>& xu, std::vector<CGAL::Gmpq>& xv)
{
  mpz_class g, t, r, h;
  std::vector<mpz_class> part, chain; // pairwise coprime factors of Q, products of remainders modulo them
  // Products modulo a large factor f (odd) are Montgomery's: a b / 2^k mod f with 2^k > f, two
  // products instead of a division (about 20 % less at a few thousand bits); the powers of 2 do not
  // change the gcd with f. mont_bits[i]: k, 0 for a plain product and division; mont_inv[i]: -1/f mod 2^k.
  std::vector<std::size_t> mont_bits;
  std::vector<mpz_class> mont_inv;
  const std::size_t montgomery_from = 256 * GMP_NUMB_BITS;
  auto prepare = [&](std::size_t i) {
    mont_bits.resize(part.size(), 0); mont_inv.resize(part.size());
    const std::size_t bits = mpz_sizeinbase(part[i].get_mpz_t(), 2);
    mont_bits[i] = bits >= montgomery_from ? bits : 0;
    if(mont_bits[i] == 0) return;
    mpz_class R = 1;
    R <<= static_cast<mp_bitcnt_t>(bits);
    mpz_invert(mont_inv[i].get_mpz_t(), part[i].get_mpz_t(), R.get_mpz_t());
    mont_inv[i] = R - mont_inv[i];
  };
  if(Q > 1) { part.push_back(Q); chain.emplace_back(1); prepare(0); }
  // out = the part of x made of the primes of y (full powers), x = the rest; at most log2 x rounds
  auto split = [&](mpz_class& x, const mpz_class& y, mpz_class& out) {
    out = 1;
    for(std::size_t round = 0, rounds = mpz_sizeinbase(x.get_mpz_t(), 2); round <= rounds; ++round)
    {
      mpz_gcd(t.get_mpz_t(), x.get_mpz_t(), y.get_mpz_t());
      if(t == 1) break;
      mpz_divexact(x.get_mpz_t(), x.get_mpz_t(), t.get_mpz_t());
      out *= t;
    }
  };
  // part[i] = its y-part, and the rest (if any) a new factor; the product of remainders modulo part[i]
  // (if not checked yet) serves both: its gcd with either is that of the remainders modulo it
  auto separate = [&](std::size_t i, const mpz_class& y) {
    mpz_class rest = part[i], with_y;
    split(rest, y, with_y);
    if(rest == 1 || with_y == 1) return;
    part[i].swap(with_y);
    const mpz_class carried = chain[i];
    part.push_back(rest); chain.push_back(carried);
    prepare(i); prepare(part.size() - 1);
  };
  const std::size_t window = 256;
  std::vector<std::size_t> pending;     // numerators whose factors are not all known yet,
  std::vector<mpz_class> pending_gcd;   // and their common factor with d found so far
  std::vector<mpz_class> found;
  auto emit = [&](std::size_t c, const mpz_class& common) {
    CGAL::Gmpq q;
    if(num[c] != 0)
    {
      mpz_divexact(mpq_numref(q.mpq()), num[c].get_mpz_t(), common.get_mpz_t());
      mpz_divexact(mpq_denref(q.mpq()), d.get_mpz_t(), common.get_mpz_t());
    }
    ((c % 2) ? xv : xu)[c / 2] = q;
    mpz_class().swap(num[c]);
  };
  auto flush = [&]() {
    // (factors split off below are checked too; at most one split per prime of Q)
    for(std::size_t i = 0; i < part.size(); ++i)
    {
      mpz_gcd(t.get_mpz_t(), chain[i].get_mpz_t(), part[i].get_mpz_t());
      chain[i] = 1;
      if(t == 1) continue;
      // the rest of part[i] is coprime to the window's numerators that it does not divide
      const mpz_class whole = part[i], shared = t;
      separate(i, shared);
      const mpz_class f = part[i];
      found.clear();
      for(std::size_t k = 0; k < pending.size(); ++k)
      {
        mpz_tdiv_r(r.get_mpz_t(), num[pending[k]].get_mpz_t(), whole.get_mpz_t());
        if(r == 0) continue; // `whole` was counted
        mpz_gcd(h.get_mpz_t(), r.get_mpz_t(), f.get_mpz_t());
        if(h != 1) { pending_gcd[k] *= h; found.push_back(h); }
      }
      for(const mpz_class& common : found)
        for(std::size_t j = 0, size = part.size(); j < size; ++j)
        {
          mpz_gcd(h.get_mpz_t(), part[j].get_mpz_t(), common.get_mpz_t());
          if(h != 1 && h != part[j]) separate(j, h);
        }
    }
    for(std::size_t k = 0; k < pending.size(); ++k) emit(pending[k], pending_gcd[k]);
    pending.clear(); pending_gcd.clear();
  };
  for(std::size_t c = begin; c < end; ++c)
  {
    if(num[c] == 0) { emit(c, 1); continue; }
    mpz_gcd(g.get_mpz_t(), num[c].get_mpz_t(), s.get_mpz_t());
    for(std::size_t i = 0; i < part.size(); ++i)
    {
      mpz_tdiv_r(r.get_mpz_t(), num[c].get_mpz_t(), part[i].get_mpz_t());
      if(r == 0) { g *= part[i]; continue; }
      if(mont_bits[i] == 0)
      {
        mpz_mul(chain[i].get_mpz_t(), chain[i].get_mpz_t(), r.get_mpz_t());
        mpz_tdiv_r(chain[i].get_mpz_t(), chain[i].get_mpz_t(), part[i].get_mpz_t());
        continue;
      }
      // chain, |r| < f: t = chain |r| < f 2^k; t + m f with m = t (-1/f) mod 2^k is a multiple of 2^k
      mpz_abs(r.get_mpz_t(), r.get_mpz_t());
      mpz_mul(t.get_mpz_t(), chain[i].get_mpz_t(), r.get_mpz_t());
      mpz_tdiv_r_2exp(h.get_mpz_t(), t.get_mpz_t(), mont_bits[i]);
      mpz_mul(h.get_mpz_t(), h.get_mpz_t(), mont_inv[i].get_mpz_t());
      mpz_tdiv_r_2exp(h.get_mpz_t(), h.get_mpz_t(), mont_bits[i]);
      mpz_addmul(t.get_mpz_t(), h.get_mpz_t(), part[i].get_mpz_t());
      mpz_tdiv_q_2exp(chain[i].get_mpz_t(), t.get_mpz_t(), mont_bits[i]);
      if(chain[i] >= part[i]) chain[i] -= part[i];
    }
    pending.push_back(c); pending_gcd.push_back(g);
    if(pending.size() == window) flush();
    if((c & 255) == 0 && !report(c)) return false;
  }
  flush();
  return true;
}

// The fractions num[c] / d (d > 0) in lowest terms, into xu (even c) and xv (odd c); num is emptied on
// the way. With CGAL::Parallel_tag (and TBB), the two halves of the components at the same time.
// false if the budget stops it.
template <class ConcurrencyTag = CGAL::Sequential_tag>
bool canonical_fractions(std::vector<mpz_class>& num, const mpz_class& d, Progress_budget& budget, double progress_from,
                         std::vector<CGAL::Gmpq>& xu, std::vector<CGAL::Gmpq>& xv)
{
  const std::size_t m = num.size(), n = m / 2;
  mpz_class s = 1, Q = d;
  for(unsigned long q = 2; q < 65536 && Q > 1; q += (q == 2 ? 1 : 2))
  {
    bool prime = true;
    for(unsigned long f = 3; f * f <= q && prime; f += 2) if(q % f == 0) prime = false;
    if(!prime) continue;
    while(mpz_divisible_ui_p(Q.get_mpz_t(), q)) { mpz_divexact_ui(Q.get_mpz_t(), Q.get_mpz_t(), q); s *= q; }
  }
  xu.resize(n); xv.resize(n);
  auto progress = [&](std::size_t done) { return budget.report(progress_from + (1 - progress_from) * double(done) / double(m)); };
  if(!pair_is_parallel<ConcurrencyTag>() || m < 512)
    return canonical_fractions_range(num, d, s, Q, 0, m, progress, xu, xv);
  // the first half reports the progress (twice its own) and the budget; the second one stops with it
  const std::size_t half = 2 * (n / 2);
  std::atomic<bool> stop(false);
  bool ok0 = true, ok1 = true;
  run_pair<ConcurrencyTag>(
    [&] { ok0 = canonical_fractions_range(num, d, s, Q, 0, half, [&](std::size_t c) {
            if(!progress(2 * c)) { stop = true; return false; }
            return !stop.load(); }, xu, xv);
          if(!ok0) stop = true; },
    [&] { ok1 = canonical_fractions_range(num, d, s, Q, half, m, [&](std::size_t) {
            if(stop.load() || !budget.time_left()) { stop = true; return false; }
            return true; }, xu, xv);
          if(!ok1) stop = true; });
  return ok0 && ok1;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_LOWEST_TERMS_H
