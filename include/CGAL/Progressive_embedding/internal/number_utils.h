// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_NUMBER_UTILS_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_NUMBER_UTILS_H

// Number-type plumbing shared by every algorithm: building FT values at the
// intended precision, exact conversion to rationals, finiteness tests.

#include <CGAL/number_utils.h>
#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Lazy_exact_nt.h>
#ifdef CGAL_USE_GMPXX
#include <CGAL/mpq_class.h>
#endif
#include <CGAL/Interval_nt.h>
#include <boost/multiprecision/number.hpp>

#include <cmath>
#include <type_traits>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

template <class FT>
struct Is_mpfr : std::false_type {};
template <>
struct Is_mpfr<CGAL::Gmpfr> : std::true_type {};

template <class FT>
struct Is_exact_ft
  : std::integral_constant<bool,
      std::is_same<typename CGAL::Algebraic_structure_traits<FT>::Is_exact, CGAL::Tag_true>::value> {};

// Number types the algorithms run on exactly. `long double` is refused: every exact test of the
// package goes through double (filtered predicates) or rationals, and a long double would be
// rounded to double there, silently. `CGAL::Mpzf` is a ring (no exact division); integers too.
template <class FT>
struct Is_supported_number_type
  : std::integral_constant<bool, !std::is_same<typename std::remove_cv<FT>::type, long double>::value
                              && !std::is_same<FT, CGAL::Mpzf>::value && !std::is_integral<FT>::value> {};

// Rejects, at compile time and with a message, the number types that cannot run the algorithms.
template <class FT>
struct Check_number_type
{
  static_assert(!std::is_same<typename std::remove_cv<FT>::type, long double>::value,
                "Progressive_embedding: long double is not supported (its values would be rounded to double by the "
                "exact predicates). Supported number types: float, double, CGAL::Gmpq, CGAL::Gmpfr (any precision), "
                "CGAL::Lazy_exact_nt, boost::multiprecision rationals");
  static_assert(!std::is_same<FT, CGAL::Mpzf>::value,
                "CGAL::Mpzf is a ring (no exact division): it cannot be the FT of a Progressive_embedding traits class");
  static_assert(!std::is_integral<FT>::value, "an integral FT cannot be used");
  static constexpr bool value = Is_supported_number_type<FT>::value;
};

// builds an FT from a double. MPFR values get the current default precision
// (CGAL::Gmpfr(double) alone would silently take 512 bits).
template <class FT>
inline FT make_ft(double d)
{
  if constexpr(Is_mpfr<FT>::value)
    return CGAL::Gmpfr(d, CGAL::Gmpfr::get_default_precision());
  else
    return FT(d);
}

template <class FT>
inline bool is_finite_ft(const FT& x)
{
  if constexpr(std::is_floating_point<FT>::value)
    return std::isfinite(x);
  else if constexpr(Is_mpfr<FT>::value)
    return x.is_number();
  else
    return true; // exact rationals are always finite
}

// whether every 3D point of `tm` (read through `vpm`) is finite: lengths, paths and distortions read them
template <class TriangleMesh, class VertexPointMap>
bool points_are_finite(const TriangleMesh& tm, VertexPointMap vpm)
{
  for(auto v : vertices(tm))
  {
    const auto& p = get(vpm, v);
    if(!is_finite_ft(p.x()) || !is_finite_ft(p.y()) || !is_finite_ft(p.z())) return false;
  }
  return true;
}

// exact conversion to a rational, for certification.
inline CGAL::Gmpq to_rational(double d) { return CGAL::Gmpq(d); }
inline CGAL::Gmpq to_rational(float d) { return CGAL::Gmpq(double(d)); }
inline const CGAL::Gmpq& to_rational(const CGAL::Gmpq& q) { return q; }
inline CGAL::Gmpq to_rational(const CGAL::Gmpfr& f) { return CGAL::Gmpq(f); }

template <class FT> struct Always_false : std::false_type {};

// Fallback: names the number type in the error rather than failing deep in a template.
template <class FT>
inline CGAL::Gmpq to_rational(const FT&)
{
  static_assert(Always_false<FT>::value,
                "Progressive_embedding: no exact conversion to rationals is known for this number type; "
                "supported: double, Gmpq, Gmpfr, Lazy_exact_nt, boost::multiprecision rationals");
  return CGAL::Gmpq();
}

template <class Backend, boost::multiprecision::expression_template_option Et>
inline CGAL::Gmpq to_rational(const boost::multiprecision::number<Backend, Et>& x)
{
  // mpq_rational and cpp_rational: numerator and denominator through strings (exact).
  return CGAL::Gmpq(x.str()); // "n/d" or "n": exact
}

#ifdef CGAL_USE_GMPXX
// Epeck's exact type when CGAL is configured with gmpxx
inline CGAL::Gmpq to_rational(const mpq_class& q) { return CGAL::Gmpq(q.get_mpq_t()); }
#endif

// after the overloads of the exact types it forwards to (two-phase lookup sees only those declared
// before; Epeck's exact type is a boost::multiprecision rational)
template <class ET>
inline CGAL::Gmpq to_rational(const CGAL::Lazy_exact_nt<ET>& x)
{
  return to_rational(x.exact());
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
