// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SCALING_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SCALING_H

// Power-of-two normalization of a planar map. The algorithms square areas and lengths
// (energies, gradients, Hessians): in double, uv coordinates beyond about 1e77 or below
// 1e-77 overflow or underflow there, and exact types lose the double conversions used for
// search directions. Multiplying by 2^k is exact in binary floating point, Gmpq and Gmpfr
// (unless it overflows or underflows), so a map is scaled by the power of two that brings
// its border's bounding box to about 1 (when it is beyond 2^+-32), worked on, and scaled back;
// `Power_of_two_scaling` checks that the border round-trips bit-exactly and otherwise scales by 1.

#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// 2^k in FT, exact: ldexp for built-in floating point (0 or inf when out of range),
// binary powering otherwise (powers of two are exact in Gmpq and Gmpfr).
template <class FT>
FT power_of_two(long k)
{
  if constexpr(std::is_floating_point<FT>::value)
    return std::ldexp(FT(1), int((std::max)(long(std::numeric_limits<int>::min() / 2),
                                            (std::min)(k, long(std::numeric_limits<int>::max() / 2)))));
  else
  {
    FT result = make_ft<FT>(1), base = make_ft<FT>(2);
    unsigned long e = (k < 0) ? static_cast<unsigned long>(-(k + 1)) + 1 : static_cast<unsigned long>(k);
    for(int bit = 0; e != 0 && bit < 64; ++bit, e >>= 1) // bounded: one pass per bit of |k|
    {
      if(e & 1ul) result = result * base;
      if(e > 1) base = base * base;
    }
    return (k < 0) ? make_ft<FT>(1) / result : result;
  }
}

// The exponent e of std::frexp: 2^(e-1) <= |x| < 2^e (|x| > 0 and finite; one more when a
// non-double x rounds up to a power of two in double), without converting an out-of-range
// value to double.
template <class FT>
long frexp_exponent(const FT& x)
{
  if constexpr(std::is_floating_point<FT>::value)
  {
    int e = 0;
    std::frexp(x, &e);
    return e;
  }
  else
  {
    const double d = std::abs(CGAL::to_double(x));
    if(std::isfinite(d) && d >= 0x1p-1000 && d <= 0x1p+1000)
    {
      int e = 0;
      std::frexp(d, &e);
      return e;
    }
    // outside double range: exponential then binary search with exact comparisons
    const bool small = CGAL::abs(x) < make_ft<FT>(1);
    const FT a = small ? make_ft<FT>(1) / CGAL::abs(x) : FT(CGAL::abs(x));
    long hi = 1;
    FT p = make_ft<FT>(2); // 2^hi
    for(int guard = 0; !(a < p) && guard < 62; ++guard) { hi *= 2; p = p * p; }
    long lo = hi / 2; // 2^lo <= a < 2^hi
    for(int guard = 0; hi - lo > 1 && guard < 64; ++guard)
    {
      const long mid = lo + (hi - lo) / 2;
      if(a < power_of_two<FT>(mid)) hi = mid; else lo = mid;
    }
    return small ? 1 - hi : hi;
  }
}

template <class FT>
bool same_value(const FT& a, const FT& b)
{
  if constexpr(std::is_floating_point<FT>::value)
    return std::memcmp(&a, &b, sizeof(FT)) == 0; // also tells -0 from +0
  else
    return a == b;
}

// x * 2^k with the power prepared once. `exponent() == 0` is the identity.
template <class FT>
class Power_of_two_scaling
{
  long k_ = 0;
  FT up_, down_;

public:
  Power_of_two_scaling() : up_(make_ft<FT>(1)), down_(make_ft<FT>(1)) {}

  explicit Power_of_two_scaling(long k) : k_(k), up_(power_of_two<FT>(k)), down_(power_of_two<FT>(-k)) {}

  long exponent() const { return k_; }

  FT forward(const FT& x) const
  {
    if(k_ == 0) return x;
    if constexpr(std::is_floating_point<FT>::value) return std::ldexp(x, int(k_));
    else return x * up_;
  }

  FT backward(const FT& x) const
  {
    if(k_ == 0) return x;
    if constexpr(std::is_floating_point<FT>::value) return std::ldexp(x, int(-k_));
    else return x * down_;
  }

  // true if x * 2^k is finite and comes back to x bit-exactly
  bool round_trips(const FT& x) const
  {
    const FT y = forward(x);
    return is_finite_ft(y) && same_value(backward(y), x);
  }

  // The power of two that brings the bounding box of `border` (points with x(), y()) to an extent in [1/2, 1) when
  // it is outside [2^-32, 2^32], if every border coordinate round-trips exactly; the identity otherwise (empty,
  // degenerate or non-finite border).
  template <class PointRange>
  static Power_of_two_scaling normalizing(const PointRange& border)
  {
    return normalizing_box(border, [](const auto& p) { return std::array<FT, 2>{{ FT(p.x()), FT(p.y()) }}; }, 32);
  }

  // The same for 3D points (x(), y(), z()) whose lengths are squared, and areas squared again, in double: the power
  // of two that brings the bounding box to an extent in [1/2, 1) when it is outside [2^-100, 2^100] (beyond, a
  // squared area overflows or underflows), if every coordinate round-trips exactly; the identity otherwise.
  template <class PointRange>
  static Power_of_two_scaling normalizing_3(const PointRange& points)
  {
    return normalizing_box(points, [](const auto& p) { return std::array<FT, 3>{{ FT(p.x()), FT(p.y()), FT(p.z()) }}; }, 100);
  }

  // the same for coordinate triples
  static Power_of_two_scaling normalizing_coordinates_3(const std::vector<std::array<FT, 3> >& points)
  {
    return normalizing_box(points, [](const std::array<FT, 3>& p) { return p; }, 100);
  }

private:
  // The power of two that brings the bounding box of the points (`coordinates(p)`: a std::array of FT) to an extent
  // in [1/2, 1) when it is outside [2^-limit, 2^limit], if every coordinate round-trips exactly; the identity
  // otherwise (no point, a zero extent or a coordinate that is not finite).
  template <class PointRange, class Coordinates>
  static Power_of_two_scaling normalizing_box(const PointRange& points, Coordinates coordinates, long limit)
  {
    typedef decltype(coordinates(*std::begin(points))) Array;
    bool first = true;
    Array lo, hi;
    for(const auto& p : points)
    {
      const Array c = coordinates(p);
      for(std::size_t i = 0; i < c.size(); ++i)
      {
        if(!is_finite_ft(c[i])) return Power_of_two_scaling();
        if(first || c[i] < lo[i]) lo[i] = c[i];
        if(first || hi[i] < c[i]) hi[i] = c[i];
      }
      first = false;
    }
    if(first) return Power_of_two_scaling();
    // the largest extent, halved first so that it cannot overflow in floating point
    const FT half = make_ft<FT>(0.5);
    FT e = make_ft<FT>(0);
    for(std::size_t i = 0; i < lo.size(); ++i)
    {
      const FT ei = hi[i] * half - lo[i] * half;
      if(e < ei) e = ei;
    }
    if(!(e > make_ft<FT>(0)) || !is_finite_ft(e)) return Power_of_two_scaling();
    const long k = -(frexp_exponent(e) + 1); // the halving above: extent = 2 e
    // ordinary scales need nothing (and then give the same results as without this normalization)
    if(k >= -limit && k <= limit) return Power_of_two_scaling();
    const Power_of_two_scaling s(k);
    for(const auto& p : points)
      for(const FT& x : coordinates(p))
        if(!s.round_trips(x)) return Power_of_two_scaling();
    return s;
  }
};

// Brings the 3D points of a Surface_mesh, or of a vector, near unit size (Power_of_two_scaling::normalizing_3) and
// returns the scaling (the identity for sizes within 2^+-100): exact, so the geometry is the same up to that factor.
template <class Point_3>
Power_of_two_scaling<typename CGAL::Kernel_traits<Point_3>::Kernel::FT> normalize_points_3(std::vector<Point_3>& points)
{
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel::FT FT;
  const auto scaling = Power_of_two_scaling<FT>::normalizing_3(points);
  if(scaling.exponent() != 0)
    for(Point_3& p : points)
      p = Point_3(scaling.forward(FT(p.x())), scaling.forward(FT(p.y())), scaling.forward(FT(p.z())));
  return scaling;
}

// The same for coordinate triples in double, e.g. the 3D points a distortion measure reads.
inline void normalize_coordinates_3(std::vector<std::array<double, 3> >& points)
{
  const auto scaling = Power_of_two_scaling<double>::normalizing_coordinates_3(points);
  if(scaling.exponent() != 0)
    for(std::array<double, 3>& p : points)
      for(double& x : p) x = scaling.forward(x);
}

template <class Mesh>
auto normalize_points_3(Mesh& mesh) -> decltype(normalize_points_3(std::declval<std::vector<typename Mesh::Point>&>()))
{
  std::vector<typename Mesh::Point> points;
  for(auto v : vertices(mesh)) points.push_back(mesh.point(v));
  const auto scaling = normalize_points_3(points);
  if(scaling.exponent() != 0)
  {
    std::size_t i = 0;
    for(auto v : vertices(mesh)) mesh.point(v) = points[i++];
  }
  return scaling;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SCALING_H
