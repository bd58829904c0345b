// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_LENGTH_3_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_LENGTH_3_H

// The length of a 3D segment in double, for arc lengths and path costs. The usual sqrt of the
// squared distance overflows for points beyond about 1e154 apart and loses everything below about
// 1e-154; only then is it computed again from the coordinate differences scaled by a power of two
// (so that a segment scaled by 2^k gets 2^k times the length, bit for bit), and every other length is
// the usual value bit for bit.

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

template <class Point_3>
double length_3(const Point_3& p, const Point_3& q)
{
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel K;
  const double squared = CGAL::to_double(K().compute_squared_distance_3_object()(p, q));
  if(squared >= (std::numeric_limits<double>::min)() && squared <= (std::numeric_limits<double>::max)())
    return std::sqrt(squared);
  const double d[3] = { CGAL::to_double(q.x() - p.x()), CGAL::to_double(q.y() - p.y()), CGAL::to_double(q.z() - p.z()) };
  const double m = (std::max)({ std::abs(d[0]), std::abs(d[1]), std::abs(d[2]) });
  if(!(m > 0) || !std::isfinite(m)) return std::sqrt(squared); // 0, or not finite: as it is
  // scaled by a power of two (exact), so that the length is 2^e times that of the segment scaled by 2^-e, bit for bit
  const int e = std::ilogb(m);
  const double x = std::ldexp(d[0], -e), y = std::ldexp(d[1], -e), z = std::ldexp(d[2], -e);
  return std::ldexp(std::sqrt(x * x + y * y + z * z), e);
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_LENGTH_3_H
