// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_TRAITS_2_H
#define CGAL_PROGRESSIVE_EMBEDDING_TRAITS_2_H

/// \file Progressive_embedding_traits_2.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Progressive_embedding/internal/exact_predicates.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/enum.h>
#include <boost/property_map/property_map.hpp>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingTraitsClasses
///
/// The default model of `ProgressiveEmbeddingTraits_2`. It inherits every type and
/// functor of the kernel `K` and adds `Exact_orientation_2`, an orientation
/// predicate that is exact for every supported number type: with `double`
/// it is the filtered predicate of `Exact_predicates_inexact_constructions_kernel`;
/// with exact rationals it is `K::Orientation_2`; with `CGAL::Gmpfr`, whose
/// kernel predicates round, it is an interval filter with an exact fallback on
/// rationals (an MPFR value converts exactly to a `CGAL::Gmpq`).
///
/// \tparam K a model of `Kernel` whose `FT` is `float`, `double`, an exact field number type
///           (`CGAL::Gmpq`, `CGAL::Lazy_exact_nt`, `boost::multiprecision` rationals) or `CGAL::Gmpfr`.
///           Other number types are rejected at compile time with a message naming the supported ones:
///           `long double` (the exact predicates would round it to double), `CGAL::Mpzf` (a ring)
///           and integral types.
///
/// \cgalModels `ProgressiveEmbeddingTraits_2`
template <class K>
class Progressive_embedding_traits_2
  : public K
{
  static_assert(internal::Check_number_type<typename K::FT>::value, "");

public:
  /// the kernel
  typedef K                          Kernel;
  /// the field number type
  typedef typename K::FT             FT;
  /// point type
  typedef typename K::Point_2        Point_2;
  /// vector type
  typedef typename K::Vector_2       Vector_2;

  /// `true` when `FT` computes exactly (then no smoothing is needed for insertion, Lemma A.11)
  static constexpr bool has_exact_constructions = internal::Is_exact_ft<FT>::value;

  /// Orientation predicate, exact whatever the number type (`internal/exact_predicates.h`:
  /// an interval filter used only on finite bounds, then exact arithmetic).
  struct Exact_orientation_2
  {
    /// the result type
    typedef CGAL::Orientation result_type;

    /// returns the orientation of the triangle `(p, q, r)`, exactly
    CGAL::Orientation operator()(const Point_2& p, const Point_2& q, const Point_2& r) const
    {
      return internal::exact_orientation(p, q, r);
    }
  };

  /// constructs the traits from a kernel instance
  Progressive_embedding_traits_2(const K& k = K()) : K(k) { }

  /// returns the exact orientation predicate
  Exact_orientation_2 exact_orientation_2_object() const { return Exact_orientation_2(); }
};

#ifndef DOXYGEN_RUNNING
namespace internal {

// Wraps a kernel into the default traits unless it already is a traits model.
template <class K>
struct Get_pe_traits { typedef Progressive_embedding_traits_2<K> type; };
template <class K>
struct Get_pe_traits<Progressive_embedding_traits_2<K> > { typedef Progressive_embedding_traits_2<K> type; };

// The computation types of a uv map: its point type decides the kernel and the number type.
template <class VertexUVMap>
struct Uv_map_types
{
  typedef typename boost::property_traits<VertexUVMap>::value_type  Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel             Kernel;
  typedef typename Get_pe_traits<Kernel>::type                      Traits;
  typedef typename Traits::FT                                       FT;
  static_assert(Check_number_type<FT>::value, "");
};

} // namespace internal
#endif

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_TRAITS_2_H
