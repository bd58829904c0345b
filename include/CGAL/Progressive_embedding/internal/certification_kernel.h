// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CERTIFICATION_KERNEL_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CERTIFICATION_KERNEL_H

// The kernel in which certificates are decided: Epick for double coordinates
// (its predicates are exact on doubles), exact rationals for everything else
// (MPFR and rational values convert exactly). The sign decisions themselves are in
// internal/exact_predicates.h; this kernel is for callers that hold converted points.

#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <type_traits>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

template <class FT, bool is_double = std::is_floating_point<FT>::value>
struct Certification_kernel
{
  static_assert(Check_number_type<FT>::value, "");
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
  template <class P>
  static typename Kernel::Point_2 convert(const P& p) { return typename Kernel::Point_2(double(p.x()), double(p.y())); }
};

template <class FT>
struct Certification_kernel<FT, false>
{
  typedef CGAL::Simple_cartesian<CGAL::Gmpq> Kernel;
  template <class P>
  static typename Kernel::Point_2 convert(const P& p) { return typename Kernel::Point_2(to_rational(p.x()), to_rational(p.y())); }
};

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
