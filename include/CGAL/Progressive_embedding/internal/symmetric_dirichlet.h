// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SYMMETRIC_DIRICHLET_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SYMMETRIC_DIRICHLET_H

// Symmetric Dirichlet energy E = |J|^2 (1 + det(J)^-2) of the affine map from a
// reference triangle to a uv triangle, written without square roots so that it
// evaluates in any field (double, Gmpq, Gmpfr):
//   |J|^2 = sum_i d_i |e_i|^2 / (4 A_r^2),  det(J) = A_t / A_r,
// where e_i is the uv edge opposite corner i, d_i the dot product of the two
// reference edges leaving corner i (= 2 A_r cot(angle_i)), A_r the reference area,
// A_t the signed uv area. The minimum, 4, is reached by isometries.

#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// A reference shape: the three corner dot products and the squared area.
template <class FT>
struct Reference_triangle
{
  std::array<FT, 3> dot; // dot[i]: dot product of the two reference edges at corner i
  FT area2;              // squared reference area
};

// equilateral reference of area `area`; `sqrt3` is passed in (it is irrational).
template <class FT>
Reference_triangle<FT> equilateral_reference(const FT& area, const FT& sqrt3)
{
  // side^2 = 4 A / sqrt3, and each corner's dot product is side^2 / 2
  const FT d = FT(2) * area / sqrt3;
  return Reference_triangle<FT>{ {d, d, d}, area * area };
}

// reference from three 2D or 3D corner positions, given as coordinates arrays
template <class FT, std::size_t D>
Reference_triangle<FT> reference_from_points(const std::array<FT, D>& a,
                                             const std::array<FT, D>& b,
                                             const std::array<FT, D>& c)
{
  auto dotp = [](const std::array<FT, D>& u, const std::array<FT, D>& v) {
    FT s(0); for(std::size_t k = 0; k < D; ++k) s += u[k] * v[k]; return s;
  };
  std::array<FT, D> ab, ac, bc;
  for(std::size_t k = 0; k < D; ++k) { ab[k] = b[k] - a[k]; ac[k] = c[k] - a[k]; bc[k] = c[k] - b[k]; }
  Reference_triangle<FT> r;
  r.dot[0] = dotp(ab, ac);
  r.dot[1] = - dotp(ab, bc);
  r.dot[2] = dotp(ac, bc);
  // |ab x ac|^2 from the cross product itself (Lagrange's identity cancels badly on slivers)
  FT cross2(0);
  if constexpr(D == 2)
  {
    const FT c = ab[0] * ac[1] - ab[1] * ac[0];
    cross2 = c * c;
  }
  else
  {
    static_assert(D == 3, "2D or 3D reference triangles only");
    const FT cx = ab[1] * ac[2] - ab[2] * ac[1], cy = ab[2] * ac[0] - ab[0] * ac[2], cz = ab[0] * ac[1] - ab[1] * ac[0];
    cross2 = cx * cx + cy * cy + cz * cz;
  }
  r.area2 = cross2 / FT(4);
  return r;
}

// |J|^2 for uv corners (x0,y0),(x1,y1),(x2,y2)
template <class FT>
FT dirichlet_term(const Reference_triangle<FT>& r,
                  const FT& x0, const FT& y0, const FT& x1, const FT& y1, const FT& x2, const FT& y2)
{
  const FT l0 = (x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1);
  const FT l1 = (x0 - x2) * (x0 - x2) + (y0 - y2) * (y0 - y2);
  const FT l2 = (x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0);
  return (r.dot[0] * l0 + r.dot[1] * l1 + r.dot[2] * l2) / (FT(4) * r.area2);
}

template <class FT>
FT signed_area(const FT& x0, const FT& y0, const FT& x1, const FT& y1, const FT& x2, const FT& y2)
{
  return ((x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)) / FT(2);
}

// Energy; `ok` is false when the uv area is zero (the energy is then infinite).
template <class FT>
FT symmetric_dirichlet(const Reference_triangle<FT>& r,
                       const FT& x0, const FT& y0, const FT& x1, const FT& y1, const FT& x2, const FT& y2,
                       bool& ok)
{
  const FT a = signed_area(x0, y0, x1, y1, x2, y2);
  if(a == FT(0)) { ok = false; return FT(0); }
  ok = true;
  return dirichlet_term(r, x0, y0, x1, y1, x2, y2) * (FT(1) + r.area2 / (a * a));
}

// For double coordinates: the sign of the determinant (a - x) x (b - x) when the static filter of
// CGAL's Epick Orientation_2 decides it (`decided`), with the determinant itself. The callers
// need the determinant for the energy anyway: the common case costs one determinant and no call.
inline CGAL::Orientation filtered_double_orientation(double xx, double xy, double ax, double ay, double bx, double by,
                                                     double& det, bool& decided)
{
  const double pqx = ax - xx, pqy = ay - xy, prx = bx - xx, pry = by - xy;
  det = pqx * pry - pqy * prx;
  double lo = (std::max)(std::abs(pqx), std::abs(prx)), hi = (std::max)(std::abs(pqy), std::abs(pry));
  if(lo > hi) std::swap(lo, hi);
  decided = false;
  if(lo < 1e-146 || !(hi < 1e153)) return CGAL::COLLINEAR; // outside the filter's range
  const double eps = 8.8872057372592798e-16 * lo * hi;
  if(det > eps) { decided = true; return CGAL::LEFT_TURN; }
  if(det < -eps) { decided = true; return CGAL::RIGHT_TURN; }
  return CGAL::COLLINEAR;
}

// (x, a, b) is positively oriented under the exact predicate `orient` (filtered inline for double)
template <class Point_2, class Orientation_2>
bool positively_oriented(const Orientation_2& orient, const Point_2& x, const Point_2& a, const Point_2& b)
{
  if constexpr(std::is_same<typename std::decay<decltype(x.x())>::type, double>::value)
  {
    double det; bool decided;
    const CGAL::Orientation o = filtered_double_orientation(x.x(), x.y(), a.x(), a.y(), b.x(), b.y(), det, decided);
    if(decided) return o == CGAL::LEFT_TURN;
  }
  return orient(x, a, b) == CGAL::LEFT_TURN;
}

// The energy `e` of the face (x, a, b) if it is positively oriented under the exact predicate
// `orient`; false otherwise. Same value as symmetric_dirichlet().
template <class FT, class Point_2, class Orientation_2>
bool positive_face_energy(const Reference_triangle<FT>& r, const Orientation_2& orient,
                          const Point_2& x, const Point_2& a, const Point_2& b, FT& e)
{
  if constexpr(std::is_same<FT, double>::value)
  {
    double det; bool decided;
    const CGAL::Orientation o = filtered_double_orientation(x.x(), x.y(), a.x(), a.y(), b.x(), b.y(), det, decided);
    if(decided)
    {
      if(o != CGAL::LEFT_TURN) return false;
      const double A = det / 2; // bit-identical to signed_area()
      e = dirichlet_term(r, x.x(), x.y(), a.x(), a.y(), b.x(), b.y()) * (1 + r.area2 / (A * A));
      return true;
    }
  }
  if(orient(x, a, b) != CGAL::LEFT_TURN) return false;
  bool ok;
  e = symmetric_dirichlet(r, x.x(), x.y(), a.x(), a.y(), b.x(), b.y(), ok);
  return ok;
}

// Energy of one face as a function of its corner 0 at (x,y), with its gradient
// and Hessian in (x,y). Corners 1 and 2 are fixed. Returns false if the area is zero.
template <class FT>
bool symmetric_dirichlet_local(const Reference_triangle<FT>& r,
                               const FT& x, const FT& y,
                               const FT& x1, const FT& y1, const FT& x2, const FT& y2,
                               FT& E, std::array<FT, 2>& g, std::array<FT, 3>& H /* hxx, hxy, hyy */)
{
  const FT A = signed_area(x, y, x1, y1, x2, y2);
  if(A == FT(0)) return false;
  const FT s = FT(1) / (FT(4) * r.area2);
  // |J|^2 = s * sum_i d_i |e_i|^2, with s computed once (divisions dominate this function)
  const FT l0 = (x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1);
  const FT l1 = (x - x2) * (x - x2) + (y - y2) * (y - y2);
  const FT l2 = (x1 - x) * (x1 - x) + (y1 - y) * (y1 - y);
  const FT a = s * (r.dot[0] * l0 + r.dot[1] * l1 + r.dot[2] * l2);
  // grad |J|^2 = s * (2 d1 (p - p2) + 2 d2 (p - p1)); its Hessian is 2 s (d1 + d2) I
  const FT ga_x = s * (FT(2) * r.dot[1] * (x - x2) + FT(2) * r.dot[2] * (x - x1));
  const FT ga_y = s * (FT(2) * r.dot[1] * (y - y2) + FT(2) * r.dot[2] * (y - y1));
  const FT ha = FT(2) * s * (r.dot[1] + r.dot[2]);
  // A = (cross(p1,p2) + cross(p, p1 - p2)) / 2  =>  grad A = ((y1 - y2), -(x1 - x2)) / 2
  const FT gA_x = (y1 - y2) / FT(2);
  const FT gA_y = (x2 - x1) / FT(2);
  const FT q = r.area2;
  const FT iA = FT(1) / A;
  const FT iA2 = iA * iA;
  const FT f = FT(1) + q * iA2;              // 1 + q/A^2
  const FT c1 = FT(-2) * q * iA2 * iA;       // d f / d A
  const FT c2 = FT(6) * q * iA2 * iA2;       // d^2 f / d A^2
  E = a * f;
  g[0] = ga_x * f + a * c1 * gA_x;
  g[1] = ga_y * f + a * c1 * gA_y;
  H[0] = ha * f + c1 * (FT(2) * ga_x * gA_x) + a * c2 * gA_x * gA_x;
  H[1] = c1 * (ga_x * gA_y + ga_y * gA_x) + a * c2 * gA_x * gA_y;
  H[2] = ha * f + c1 * (FT(2) * ga_y * gA_y) + a * c2 * gA_y * gA_y;
  return true;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
