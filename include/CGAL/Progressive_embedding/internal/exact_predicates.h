// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_EXACT_PREDICATES_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_EXACT_PREDICATES_H

// The one place where the package decides geometric signs exactly, for every supported
// number type of uv coordinates:
//  - orientation of three points (double: Epick's filtered predicate; other types: an interval
//    filter built with CGAL::to_interval, used only when every bound is finite, then exact
//    arithmetic: the number type itself when it is exact, rationals otherwise);
//  - closed segment intersection and triangle interior intersection, from orientations and
//    coordinate comparisons only (both exact in every supported number type);
//  - exact (rational) twice signed areas of triangles and polygons;
//  - conservative double boxes of points whose coordinates may lie outside double range:
//    the coordinates are first scaled exactly by one power of two chosen from their exponents,
//    then enclosed by CGAL::to_interval (a box never misses a point, whatever its magnitude).

#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Gmpq.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <gmp.h>
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

template <class Point_2>
struct Point_ft { typedef typename CGAL::Kernel_traits<Point_2>::Kernel::FT type; };

// ---- orientation ---------------------------------------------------------------------------

// Interval filter: the sign of the determinant when the intervals decide it, COLLINEAR
// with `decided == false` otherwise. Bounds that are not finite (a rational beyond double
// range converts to an infinite bound) never decide.
template <class FT>
CGAL::Orientation filtered_orientation(const FT& px, const FT& py, const FT& qx, const FT& qy,
                                       const FT& rx, const FT& ry, bool& decided)
{
  typedef CGAL::Interval_nt<false> I;
  typename I::Protector protector;
  decided = false;
  const I ix[3] = { I(CGAL::to_interval(px)), I(CGAL::to_interval(qx)), I(CGAL::to_interval(rx)) };
  const I iy[3] = { I(CGAL::to_interval(py)), I(CGAL::to_interval(qy)), I(CGAL::to_interval(ry)) };
  for(int k = 0; k < 3; ++k)
    if(!std::isfinite(ix[k].inf()) || !std::isfinite(ix[k].sup()) || !std::isfinite(iy[k].inf()) || !std::isfinite(iy[k].sup()))
      return CGAL::COLLINEAR;
  // finite inputs: overflow in the products gives infinite but still enclosing bounds
  const I det = (ix[1] - ix[0]) * (iy[2] - iy[0]) - (iy[1] - iy[0]) * (ix[2] - ix[0]);
  if(det.inf() > 0) { decided = true; return CGAL::LEFT_TURN; }
  if(det.sup() < 0) { decided = true; return CGAL::RIGHT_TURN; }
  return CGAL::COLLINEAR;
}

// a - b as num / den, not in lowest terms, when that needs no product of two long integers: (na - nb) / d
// when da = db = d, over the larger denominator when one divides the other (the coordinates of an exact
// Tutte map are mostly over one common denominator or its divisors, the quotients small); false otherwise
inline bool cheap_rational_difference(const CGAL::Gmpq& a, const CGAL::Gmpq& b, mpz_class& num, mpz_class& den)
{
  const mpz_srcptr na = mpq_numref(a.mpq()), da = mpq_denref(a.mpq()), nb = mpq_numref(b.mpq()), db = mpq_denref(b.mpq());
  const int c = mpz_cmp(da, db);
  if(c == 0) { mpz_sub(num.get_mpz_t(), na, nb); mpz_set(den.get_mpz_t(), da); return true; }
  if(c < 0 && mpz_divisible_p(db, da))
  {
    mpz_divexact(den.get_mpz_t(), db, da); // the quotient, for a moment
    mpz_mul(num.get_mpz_t(), na, den.get_mpz_t());
    mpz_sub(num.get_mpz_t(), num.get_mpz_t(), nb);
    mpz_set(den.get_mpz_t(), db);
    return true;
  }
  if(c > 0 && mpz_divisible_p(da, db))
  {
    mpz_divexact(den.get_mpz_t(), da, db);
    mpz_mul(num.get_mpz_t(), nb, den.get_mpz_t());
    mpz_sub(num.get_mpz_t(), na, num.get_mpz_t());
    mpz_set(den.get_mpz_t(), da);
    return true;
  }
  return false;
}

// a - b = (na db - nb da) / (da db) otherwise
inline void rational_difference(const CGAL::Gmpq& a, const CGAL::Gmpq& b, mpz_class& num, mpz_class& den)
{
  if(cheap_rational_difference(a, b, num, den)) return;
  const mpz_srcptr na = mpq_numref(a.mpq()), da = mpq_denref(a.mpq()), nb = mpq_numref(b.mpq()), db = mpq_denref(b.mpq());
  mpz_mul(num.get_mpz_t(), na, db);
  mpz_submul(num.get_mpz_t(), nb, da);
  mpz_mul(den.get_mpz_t(), da, db);
}

// Leading bits of rationals: the second filter of rational_twice_area(), between the double one and exact
// products. The coordinates of an exact Tutte map are fractions of tens of thousands of bits, and where
// its faces are slivers (the maps of Tutte failures), the double filter rarely decides: the exact products
// then cost about as much as the Tutte solve. Their leading bits decide nearly always.
constexpr long twice_area_filter_bits = 512;

// n / d (d > 0) as M 2^E with |M 2^E - n / d| <= 2^-(P-2) |n / d|: n and d cut to their P + 2 leading bits
// (a relative error below 2^-(P+1) each), then a quotient of P + 1 bits or more (truncated: the same bound).
inline void leading_bits_quotient(mpz_srcptr n, mpz_srcptr d, long P, mpz_class& M, long& E)
{
  if(mpz_sgn(n) == 0) { M = 0; E = 0; return; }
  mpz_class a, b;
  const long cn = (std::max)(long(mpz_sizeinbase(n, 2)) - P - 2, 0L);
  const long cd = (std::max)(long(mpz_sizeinbase(d, 2)) - P - 2, 0L);
  mpz_tdiv_q_2exp(a.get_mpz_t(), n, static_cast<mp_bitcnt_t>(cn));
  mpz_tdiv_q_2exp(b.get_mpz_t(), d, static_cast<mp_bitcnt_t>(cd));
  // a 2^s / b >= 2^(P+1): s = bits(b) - bits(a) + P + 2 >= 1
  const long s = long(mpz_sizeinbase(b.get_mpz_t(), 2)) - long(mpz_sizeinbase(a.get_mpz_t(), 2)) + P + 2;
  mpz_mul_2exp(a.get_mpz_t(), a.get_mpz_t(), static_cast<mp_bitcnt_t>(s));
  mpz_tdiv_q(M.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  E = cn - cd - s;
}

// x 2^ex - y 2^ey, exactly, as D 2^E
inline void shifted_difference(const mpz_class& x, long ex, const mpz_class& y, long ey, mpz_class& D, long& E)
{
  E = (std::min)(ex, ey);
  mpz_class a = x, b = y;
  mpz_mul_2exp(a.get_mpz_t(), a.get_mpz_t(), static_cast<mp_bitcnt_t>(ex - E));
  mpz_mul_2exp(b.get_mpz_t(), b.get_mpz_t(), static_cast<mp_bitcnt_t>(ey - E));
  D = a - b;
}

// log2 |z 2^e| as a double (-infinity for z = 0)
inline double log2_magnitude(const mpz_class& z, long e)
{
  if(z == 0) return -std::numeric_limits<double>::infinity();
  long k = 0;
  const double f = mpz_get_d_2exp(&k, z.get_mpz_t());
  return std::log2(std::abs(f)) + double(k + e);
}

// The second filter (see above) of rational_twice_area() for the differences (qx - px, ry - py, qy - py,
// rx - px) of `terms`, `n[k] / d[k]` where `integral[k]` (exact already). True, with m 2^e, if it decides:
// a relative error below 2^-40 (the sign only with `sign_only`).
inline bool leading_bits_twice_area(const CGAL::Gmpq* const terms[4][2], const mpz_class n[4], const mpz_class d[4],
                                    const bool integral[4], bool sign_only, double& m, long& e)
{
  const long P = twice_area_filter_bits;
  const double unit = double(2 - P); // log2 of the relative error of one quotient
  mpz_class v[4];
  long x[4];
  double rel[4]; // log2 of the relative error of v[k] 2^x[k]
  for(int k = 0; k < 4; ++k)
  {
    if(integral[k])
    {
      leading_bits_quotient(n[k].get_mpz_t(), d[k].get_mpz_t(), P, v[k], x[k]);
      rel[k] = unit;
      continue;
    }
    mpz_class a, b;
    long ea = 0, eb = 0;
    leading_bits_quotient(mpq_numref(terms[k][0]->mpq()), mpq_denref(terms[k][0]->mpq()), P, a, ea);
    leading_bits_quotient(mpq_numref(terms[k][1]->mpq()), mpq_denref(terms[k][1]->mpq()), P, b, eb);
    shifted_difference(a, ea, b, eb, v[k], x[k]);
    if(v[k] == 0) return false; // the two coordinates agree to P bits: undecided
    // (|a| + |b|) 2^(2-P) / |a - b|, in log2 (the larger of |a|, |b| counted twice: an upper bound); relative
    // to the exact difference, at most 1.001 times that while it is below 2^-10 (counted in the bound below)
    rel[k] = unit + 1 + (std::max)(log2_magnitude(a, ea), log2_magnitude(b, eb)) - log2_magnitude(v[k], x[k]);
  }
  // the products, exact, and their difference, exact; the error of the approximations bounds the error
  const mpz_class p1 = v[0] * v[1], p2 = v[2] * v[3];
  const long e1 = x[0] + x[1], e2 = x[2] + x[3];
  mpz_class diff;
  long ed = 0;
  shifted_difference(p1, e1, p2, e2, diff, ed);
  if(diff == 0) return false;
  // the error, |P1| (r0 + r1 + r0 r1) + |P2| (r2 + r3 + r2 r3) with P1, P2 the exact products, is below
  // 2.01 (|p1| max(r0, r1) + |p2| max(r2, r3)) <= 5 max(|p1| max(r0, r1), |p2| max(r2, r3)) with p1, p2 the
  // approximations, while every r is below 2^-10
  for(int k = 0; k < 4; ++k) if(!(rel[k] < -10)) return false;
  const double err = std::log2(5.) + (std::max)(log2_magnitude(p1, e1) + (std::max)(rel[0], rel[1]),
                                               log2_magnitude(p2, e2) + (std::max)(rel[2], rel[3]));
  if(!(log2_magnitude(diff, ed) > err + (sign_only ? 1 : 41))) return false;
  long k = 0;
  m = mpz_get_d_2exp(&k, diff.get_mpz_t());
  e = k + ed;
  return true;
}

// Twice the signed area of (p, q, r) as m 2^e with a relative error below 2^-40 (m = 0 for a zero area;
// the sign is exact). Each of the four coordinate differences is in double with a bound on its relative
// error: a few units in the last place where it is an exact integer over a denominator
// (cheap_rational_difference()), the difference of the two rounded coordinates otherwise (as accurate as
// they are far apart). Where the determinant in double is not that accurate (its two products nearly
// cancel, or two coordinates nearly agree), it is computed again from the leading bits of the fractions
// (leading_bits_twice_area()), and exactly from integer products where that does not decide either. With
// `sign_only`, m is accurate enough for its sign only.
inline void rational_twice_area(const CGAL::Gmpq& px, const CGAL::Gmpq& py, const CGAL::Gmpq& qx,
                                const CGAL::Gmpq& qy, const CGAL::Gmpq& rx, const CGAL::Gmpq& ry, double& m, long& e,
                                bool sign_only = false)
{
  const CGAL::Gmpq* const terms[4][2] = { { &qx, &px }, { &ry, &py }, { &qy, &py }, { &rx, &px } };
  mpz_class n[4], d[4];
  bool integral[4];
  // an integer z as f 2^k with 1/2 <= |f| < 1 (truncated: relative error below 2^-53)
  auto split = [](mpz_srcptr z, double& f, long& k) { f = mpz_get_d_2exp(&k, z); };
  const double ulp = std::ldexp(1., -53), inexact = std::ldexp(1., -20);
  double v[4], rel[4];
  long x[4];
  bool filter = true;
  for(int k = 0; k < 4; ++k)
  {
    double fn, fd;
    long kn, kd;
    integral[k] = cheap_rational_difference(*terms[k][0], *terms[k][1], n[k], d[k]);
    if(integral[k])
    {
      split(n[k].get_mpz_t(), fn, kn); split(d[k].get_mpz_t(), fd, kd);
      v[k] = fn / fd; x[k] = kn - kd; rel[k] = 3 * ulp;
      continue;
    }
    // both coordinates rounded (relative error below 3 2^-53 each), then subtracted
    double f[2];
    long kk[2];
    for(int i = 0; i < 2; ++i)
    {
      split(mpq_numref(terms[k][i]->mpq()), fn, kn); split(mpq_denref(terms[k][i]->mpq()), fd, kd);
      f[i] = fn / fd; kk[i] = kn - kd;
    }
    x[k] = (std::max)(f[0] == 0 ? kk[1] : kk[0], f[1] == 0 ? kk[0] : kk[1]);
    const double a = std::ldexp(f[0], int((std::max)(kk[0] - x[k], -1100L))), b = std::ldexp(f[1], int((std::max)(kk[1] - x[k], -1100L)));
    v[k] = a - b;
    rel[k] = v[k] == 0 ? 1. : 3 * ulp * (std::abs(a) + std::abs(b)) / std::abs(v[k]) + ulp;
    if(rel[k] > inexact) filter = false;
  }
  if(filter)
  {
    const bool zero1 = v[0] == 0 || v[1] == 0, zero2 = v[2] == 0 || v[3] == 0; // exact zeros (integral)
    if(zero1 && zero2) { m = 0; e = 0; return; }
    const long e1 = x[0] + x[1], e2 = x[2] + x[3];
    e = zero1 ? e2 : (zero2 ? e1 : (std::max)(e1, e2));
    // the products scaled by 2^-e (at most 4 in absolute value, exact scaling unless below 2^-1000)
    const double p1 = zero1 ? 0. : std::ldexp(v[0] * v[1], int((std::max)(e1 - e, -1100L)));
    const double p2 = zero2 ? 0. : std::ldexp(v[2] * v[3], int((std::max)(e2 - e, -1100L)));
    m = p1 - p2;
    const double bound = std::abs(p1) * (rel[0] + rel[1] + rel[0] * rel[1] + 4 * ulp)
                       + std::abs(p2) * (rel[2] + rel[3] + rel[2] * rel[3] + 4 * ulp) + 2 * ulp * std::abs(m);
    if(std::abs(m) > (sign_only ? bound : std::ldexp(bound, 40))) return;
  }
  if(leading_bits_twice_area(terms, n, d, integral, sign_only, m, e)) return;
  // exactly
  for(int k = 0; k < 4; ++k) if(!integral[k]) rational_difference(*terms[k][0], *terms[k][1], n[k], d[k]);
  mpz_class num = n[0] * n[1], right = n[2] * n[3], den;
  if((d[0] == d[2] && d[1] == d[3]) || (d[0] == d[3] && d[1] == d[2])) den = d[0] * d[1];
  else
  {
    num *= d[2] * d[3];
    right *= d[0] * d[1];
    den = d[0] * d[1] * d[2] * d[3];
  }
  num -= right;
  if(num == 0) { m = 0; e = 0; return; }
  double fn, fd;
  long kn, kd;
  split(num.get_mpz_t(), fn, kn); split(den.get_mpz_t(), fd, kd);
  m = fn / fd; e = kn - kd;
}

// The orientation of three points with rational coordinates, from their numerators and denominators:
// the sign of (qx - px)(ry - py) - (qy - py)(rx - px) = n0 n1 / (d0 d1) - n2 n3 / (d2 d3) (denominators
// positive), in double where that decides, with two products of integers otherwise. CGAL::Gmpq's
// operators put every intermediate result in lowest terms, a gcd per operation: on the fractions of an
// exact Tutte map (tens of thousands of bits over one common denominator) the gcds cost about a hundred
// times the products.
inline CGAL::Orientation rational_orientation(const CGAL::Gmpq& px, const CGAL::Gmpq& py, const CGAL::Gmpq& qx,
                                              const CGAL::Gmpq& qy, const CGAL::Gmpq& rx, const CGAL::Gmpq& ry)
{
  double m = 0;
  long e = 0;
  rational_twice_area(px, py, qx, qy, rx, ry, m, e, true);
  return m > 0 ? CGAL::LEFT_TURN : (m < 0 ? CGAL::RIGHT_TURN : CGAL::COLLINEAR);
}

// exact orientation of coordinates in any supported number type
template <class FT>
CGAL::Orientation exact_orientation_ft(const FT& px, const FT& py, const FT& qx, const FT& qy, const FT& rx, const FT& ry)
{
  static_assert(Check_number_type<FT>::value, "");
  if constexpr(std::is_floating_point<FT>::value)
  {
    typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
    // float and double convert exactly to double (long double is rejected by Check_number_type)
    return Epick::Orientation_2()(Epick::Point_2(double(px), double(py)), Epick::Point_2(double(qx), double(qy)),
                                  Epick::Point_2(double(rx), double(ry)));
  }
  else
  {
    bool decided = false;
    const CGAL::Orientation o = filtered_orientation(px, py, qx, qy, rx, ry, decided);
    if(decided) return o;
    if constexpr(std::is_same<FT, CGAL::Gmpq>::value)
      return rational_orientation(px, py, qx, qy, rx, ry);
    else if constexpr(Is_exact_ft<FT>::value)
      return CGAL::Orientation(CGAL::sign((qx - px) * (ry - py) - (qy - py) * (rx - px)));
    else
      // MPFR and other rounded types: their values are rationals, decide there
      return rational_orientation(to_rational(px), to_rational(py), to_rational(qx), to_rational(qy), to_rational(rx),
                                  to_rational(ry));
  }
}

template <class Point_2>
CGAL::Orientation exact_orientation(const Point_2& p, const Point_2& q, const Point_2& r)
{
  return exact_orientation_ft(p.x(), p.y(), q.x(), q.y(), r.x(), r.y());
}

// the orientation functor of the default traits
template <class Point_2>
struct Exact_orientation_2
{
  typedef CGAL::Orientation result_type;
  CGAL::Orientation operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
  { return exact_orientation(p, q, r); }
};

// ---- segments and triangles -------------------------------------------------------------------

// lexicographic comparison of (x, y): exact in every supported number type
template <class Point_2>
CGAL::Comparison_result exact_compare_xy(const Point_2& p, const Point_2& q)
{
  if(p.x() < q.x()) return CGAL::SMALLER;
  if(q.x() < p.x()) return CGAL::LARGER;
  if(p.y() < q.y()) return CGAL::SMALLER;
  if(q.y() < p.y()) return CGAL::LARGER;
  return CGAL::EQUAL;
}

// `c`, collinear with `a` and `b`, lies on the closed segment [a, b] (coordinate comparisons are exact)
template <class Point_2>
bool collinear_point_on_segment(const Point_2& a, const Point_2& b, const Point_2& c)
{
  const bool in_x = (a.x() < b.x()) ? !(c.x() < a.x()) && !(b.x() < c.x()) : !(c.x() < b.x()) && !(a.x() < c.x());
  const bool in_y = (a.y() < b.y()) ? !(c.y() < a.y()) && !(b.y() < c.y()) : !(c.y() < b.y()) && !(a.y() < c.y());
  return in_x && in_y;
}

// the closed segments [p0, p1] and [q0, q1] intersect
template <class Point_2, class Orientation_2>
bool closed_segments_intersect(const Point_2& p0, const Point_2& p1, const Point_2& q0, const Point_2& q1,
                               const Orientation_2& orient)
{
  const CGAL::Orientation o1 = orient(p0, p1, q0), o2 = orient(p0, p1, q1);
  if(o1 != CGAL::COLLINEAR && o1 == o2) return false;
  const CGAL::Orientation o3 = orient(q0, q1, p0), o4 = orient(q0, q1, p1);
  if(o3 != CGAL::COLLINEAR && o3 == o4) return false;
  if(o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR && o3 != CGAL::COLLINEAR && o4 != CGAL::COLLINEAR)
    return true; // proper crossing
  return (o1 == CGAL::COLLINEAR && collinear_point_on_segment(p0, p1, q0))
      || (o2 == CGAL::COLLINEAR && collinear_point_on_segment(p0, p1, q1))
      || (o3 == CGAL::COLLINEAR && collinear_point_on_segment(q0, q1, p0))
      || (o4 == CGAL::COLLINEAR && collinear_point_on_segment(q0, q1, p1));
}

// Interiors of two non-degenerate triangles, both with orientation `s`, intersect iff no
// edge line of either one weakly separates them (separating axis theorem).
template <class Point_2, class Orientation_2>
bool triangle_interiors_intersect(const Point_2* t1, const Point_2* t2, CGAL::Orientation s, const Orientation_2& orient)
{
  auto separated_by_edges_of = [&](const Point_2* a, const Point_2* b) {
    for(int i = 0; i < 3; ++i)
    {
      bool all_outside = true;
      for(int j = 0; j < 3 && all_outside; ++j)
        if(orient(a[i], a[(i + 1) % 3], b[j]) == s) all_outside = false; // strictly on the interior side
      if(all_outside) return true;
    }
    return false;
  };
  return !separated_by_edges_of(t1, t2) && !separated_by_edges_of(t2, t1);
}

// ---- exact areas --------------------------------------------------------------------------------

inline CGAL::Gmpq twice_signed_area(const CGAL::Gmpq& x0, const CGAL::Gmpq& y0, const CGAL::Gmpq& x1, const CGAL::Gmpq& y1,
                                    const CGAL::Gmpq& x2, const CGAL::Gmpq& y2)
{
  return (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0);
}

// twice the signed area of the closed polygon (x[k], y[k]) (shoelace formula, exact)
inline CGAL::Gmpq twice_polygon_area(const std::vector<CGAL::Gmpq>& x, const std::vector<CGAL::Gmpq>& y)
{
  CGAL::Gmpq s(0);
  const std::size_t n = x.size();
  for(std::size_t k = 0; k < n; ++k)
    s += x[k] * y[(k + 1) % n] - y[k] * x[(k + 1) % n];
  return s;
}

// ---- powers of two -------------------------------------------------------------------------------

// an exponent e with 2^(e-1) <= |q| < 2^(e+1) (q != 0)
inline long binary_exponent(const CGAL::Gmpq& q)
{
  return long(mpz_sizeinbase(mpq_numref(q.mpq()), 2)) - long(mpz_sizeinbase(mpq_denref(q.mpq()), 2));
}

// q * 2^e, exactly
inline CGAL::Gmpq times_power_of_two(const CGAL::Gmpq& q, long e)
{
  CGAL::Gmpq r;
  if(e >= 0) mpq_mul_2exp(r.mpq(), q.mpq(), static_cast<mp_bitcnt_t>(e));
  else mpq_div_2exp(r.mpq(), q.mpq(), static_cast<mp_bitcnt_t>(-e));
  return r;
}

// The shift s such that 2^s * max|q| is about 1 (0 when every value is zero).
inline long unit_shift(const std::vector<CGAL::Gmpq>& values)
{
  bool any = false;
  long emax = 0;
  for(const CGAL::Gmpq& q : values)
  {
    if(CGAL::is_zero(q)) continue;
    const long e = binary_exponent(q);
    if(!any || e > emax) emax = e;
    any = true;
  }
  return any ? -emax : 0;
}

// the same for doubles (finite values only)
inline long unit_shift(const std::vector<double>& values)
{
  double m = 0;
  for(double d : values) if(std::isfinite(d)) m = (std::max)(m, std::abs(d));
  return (m > 0) ? -long(std::ilogb(m)) : 0;
}

// ---- conservative boxes -------------------------------------------------------------------------

// An interval enclosing x * 2^shift (x given exactly as a rational)
inline std::pair<double, double> scaled_interval(const CGAL::Gmpq& x, long shift)
{
  return CGAL::to_interval(shift == 0 ? x : times_power_of_two(x, shift));
}

// Conservative boxes of points: for each point with `use[i]` (all when `use` is empty), an
// enclosing interval of each coordinate times 2^shift, for one shift chosen from all the points
// (a uniform positive scaling keeps every box intersection). Doubles are used as they are
// (shift 0; they are exact); other number types go through exact rationals. Bounds at the ends
// of the double range are moved one ulp inside (see `inside_limits`).
template <class Point_2>
struct Conservative_boxes
{
  typedef typename Point_ft<Point_2>::type FT;
  std::vector<std::array<double, 4> > box; // per point: xmin, xmax, ymin, ymax

  // CGAL::box_intersection_d() splits [-DBL_MAX, DBL_MAX) and loses the boxes that reach DBL_MAX
  // (or start at -DBL_MAX), so a point there would never be paired. Clamping every bound one ulp
  // inside is a monotone map of the bounds: it keeps every intersection of boxes, and the pairs it
  // adds are decided by the exact tests anyway.
  static double inside_limits(double x)
  {
    const double m = std::nextafter((std::numeric_limits<double>::max)(), 0.);
    return (std::max)(-m, (std::min)(m, x));
  }
  long shift = 0;

  void build(const std::vector<Point_2>& P, const std::vector<char>& use = std::vector<char>())
  {
    const std::size_t n = P.size();
    box.assign(n, std::array<double, 4>{{0, 0, 0, 0}});
    auto used = [&](std::size_t i) { return use.empty() || use[i]; };
    if constexpr(std::is_floating_point<FT>::value)
    {
      shift = 0;
      for(std::size_t i = 0; i < n; ++i)
        if(used(i))
        {
          const double x = inside_limits(double(P[i].x())), y = inside_limits(double(P[i].y()));
          box[i] = {{ x, x, y, y }};
        }
    }
    else
    {
      std::vector<CGAL::Gmpq> q;
      q.reserve(2 * n);
      for(std::size_t i = 0; i < n; ++i)
        if(used(i)) { q.push_back(to_rational(P[i].x())); q.push_back(to_rational(P[i].y())); }
      shift = unit_shift(q);
      std::size_t k = 0;
      for(std::size_t i = 0; i < n; ++i)
      {
        if(!used(i)) continue;
        const std::pair<double, double> ix = scaled_interval(q[k++], shift), iy = scaled_interval(q[k++], shift);
        box[i] = {{ inside_limits(ix.first), inside_limits(ix.second), inside_limits(iy.first), inside_limits(iy.second) }};
      }
    }
  }

  // the box of several points
  template <class Indices>
  std::array<double, 4> hull(const Indices& ids) const
  {
    std::array<double, 4> b = box[ids[0]];
    for(std::size_t k = 1; k < ids.size(); ++k)
    {
      const std::array<double, 4>& c = box[ids[k]];
      b[0] = (std::min)(b[0], c[0]); b[1] = (std::max)(b[1], c[1]);
      b[2] = (std::min)(b[2], c[2]); b[3] = (std::max)(b[3], c[3]);
    }
    return b;
  }
};

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_EXACT_PREDICATES_H
