// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CHECK_PASSES_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CHECK_PASSES_H

// The passes of check_embedding(), each usable alone:
//  - sample_uv: the uv points, which ones are finite, their exact rationals, and doubles of the
//    coordinates scaled by one power of two (so that measures never overflow or underflow
//    because of the map's scale; every measure of the package is invariant under scaling);
//  - orientation_pass: exact orientation of every face and of the border polygon;
//  - area_pass: signed areas relative to the border orientation (double, exact where the
//    double evaluation is unreliable), in the map's units and scaled;
//  - border_pass: exact count of self-intersections of the border polygon;
//  - loop_areas / loops_pass: with several border loops (a multiply connected domain, see
//    internal/holes_domain.h), the exact signed area of every loop, the outer loop
//    (largest absolute area), and the exact counts of self-intersections, of contacts between two
//    loops, of holes not oriented opposite to the outer loop and of holes not inside it;
//  - overlap_pass: exact count of overlapping pairs of faces (conservative boxes + exact tests);
//  - equilateral_energy_pass: symmetric Dirichlet energy against equilateral triangles.
// Every sign is decided by the exact orientation functor passed in (the traits' one).

#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/exact_predicates.h>
#include <CGAL/Progressive_embedding/internal/border_polygon.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Progressive_embedding/internal/symmetric_dirichlet.h>
#include <CGAL/Progressive_embedding/internal/holes_domain.h>

#include <CGAL/box_intersection_d.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Gmpq.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

template <class Point_2>
struct Uv_samples
{
  typedef typename Point_ft<Point_2>::type FT;
  static constexpr bool floating = std::is_floating_point<FT>::value;

  std::vector<Point_2> P;
  std::vector<char> finite;
  std::size_t non_finite = 0;
  std::vector<CGAL::Gmpq> QX, QY; // exact values (not stored for floating-point coordinates)
  long shift = 0;                 // X, Y are the coordinates times 2^shift
  bool scaled_exactly = true;     // every X, Y is exactly the scaled coordinate
  std::vector<double> X, Y;

  CGAL::Gmpq qx(std::size_t i) const { if constexpr(floating) return CGAL::Gmpq(double(P[i].x())); else return QX[i]; }
  CGAL::Gmpq qy(std::size_t i) const { if constexpr(floating) return CGAL::Gmpq(double(P[i].y())); else return QY[i]; }
};

template <class TriangleMesh, class VertexUVMap, class Point_2>
void sample_uv(const Indexed_disk<TriangleMesh>& disk, VertexUVMap uvm, Uv_samples<Point_2>& s)
{
  const std::size_t nv = disk.number_of_vertices();
  s = Uv_samples<Point_2>();
  s.P.resize(nv);
  s.finite.assign(nv, 1);
  s.X.assign(nv, 0.); s.Y.assign(nv, 0.);
  for(std::size_t i = 0; i < nv; ++i)
  {
    s.P[i] = get(uvm, disk.vertices[i]);
    if(!is_finite_ft(s.P[i].x()) || !is_finite_ft(s.P[i].y())) { s.finite[i] = 0; ++s.non_finite; }
  }
  if constexpr(Uv_samples<Point_2>::floating)
  {
    std::vector<double> all;
    all.reserve(2 * nv);
    for(std::size_t i = 0; i < nv; ++i)
      if(s.finite[i]) { all.push_back(double(s.P[i].x())); all.push_back(double(s.P[i].y())); }
    s.shift = unit_shift(all);
    for(std::size_t i = 0; i < nv; ++i)
    {
      if(!s.finite[i]) continue;
      const double x = double(s.P[i].x()), y = double(s.P[i].y());
      s.X[i] = std::ldexp(x, int(s.shift)); s.Y[i] = std::ldexp(y, int(s.shift));
      if(std::ldexp(s.X[i], -int(s.shift)) != x || std::ldexp(s.Y[i], -int(s.shift)) != y) s.scaled_exactly = false;
    }
  }
  else
  {
    s.QX.resize(nv); s.QY.resize(nv);
    std::vector<CGAL::Gmpq> all;
    all.reserve(2 * nv);
    for(std::size_t i = 0; i < nv; ++i)
    {
      if(!s.finite[i]) continue;
      s.QX[i] = to_rational(s.P[i].x()); s.QY[i] = to_rational(s.P[i].y());
      all.push_back(s.QX[i]); all.push_back(s.QY[i]);
    }
    s.shift = unit_shift(all);
    s.scaled_exactly = false; // rounded to double: areas are computed exactly
    for(std::size_t i = 0; i < nv; ++i)
    {
      if(!s.finite[i]) continue;
      s.X[i] = CGAL::to_double(times_power_of_two(s.QX[i], s.shift));
      s.Y[i] = CGAL::to_double(times_power_of_two(s.QY[i], s.shift));
    }
  }
}

struct Face_orientations
{
  std::vector<CGAL::Orientation> fo;  // per face, exact
  std::vector<char> face_ok;          // its three corners are finite
  CGAL::Orientation border_sign = CGAL::COLLINEAR;
  bool border_finite = true;
  CGAL::Gmpq border_twice_area;       // exact, signed
  std::size_t flipped = 0, degenerate = 0;
};

// Exact orientations. The border orientation is the sign of its exact area; with a zero area,
// the majority orientation of the faces.
template <class TriangleMesh, class Point_2, class Orientation_2>
void orientation_pass(const Indexed_disk<TriangleMesh>& disk, const Uv_samples<Point_2>& s, const Orientation_2& orient,
                      Face_orientations& r)
{
  const std::size_t nf = disk.number_of_faces(), nb = disk.border.size();
  r = Face_orientations();
  for(std::size_t b : disk.border) if(!s.finite[b]) r.border_finite = false;
  if(r.border_finite)
  {
    std::vector<CGAL::Gmpq> bx(nb), by(nb);
    for(std::size_t k = 0; k < nb; ++k) { bx[k] = s.qx(disk.border[k]); by[k] = s.qy(disk.border[k]); }
    r.border_twice_area = twice_polygon_area(bx, by);
    r.border_sign = CGAL::Orientation(CGAL::sign(r.border_twice_area));
  }
  r.fo.assign(nf, CGAL::COLLINEAR);
  r.face_ok.assign(nf, 0);
  std::size_t npos = 0, nneg = 0;
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = disk.faces[f];
    if(!s.finite[t[0]] || !s.finite[t[1]] || !s.finite[t[2]]) continue;
    r.face_ok[f] = 1;
    r.fo[f] = orient(s.P[t[0]], s.P[t[1]], s.P[t[2]]);
    if(r.fo[f] == CGAL::LEFT_TURN) ++npos; else if(r.fo[f] == CGAL::RIGHT_TURN) ++nneg;
  }
  if(r.border_sign == CGAL::COLLINEAR)
    r.border_sign = (nneg > npos) ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN;
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(!r.face_ok[f]) continue;
    if(r.fo[f] == CGAL::COLLINEAR) ++r.degenerate;
    else if(r.fo[f] != r.border_sign) ++r.flipped;
  }
}

struct Face_areas
{
  std::vector<double> scaled;  // signed area relative to the border orientation, coordinates times 2^shift
  double min_area = 0, max_area = 0;                  // in the map's units (rounded; may be 0 or infinite)
  double border_area = 0, border_area_scaled = 0;     // absolute
};

// Signed areas relative to the border orientation. Evaluated in double on the scaled
// coordinates, and exactly where the double value is unreliable; for exact and MPFR types from the
// rationals, to a relative 2^-40 (rational_twice_area(): exact coordinate differences, products in
// double unless they nearly cancel, then on the fractions' leading bits, exact as a last resort),
// without a gcd per operation on the long fractions of exact Tutte maps.
template <class TriangleMesh, class Point_2>
void area_pass(const Indexed_disk<TriangleMesh>& disk, const Uv_samples<Point_2>& s, const Face_orientations& o, Face_areas& r)
{
  const std::size_t nf = disk.number_of_faces();
  const double sgn = (o.border_sign == CGAL::RIGHT_TURN) ? -1. : 1.;
  const int back = -2 * int(s.shift); // from scaled areas to the map's units
  r = Face_areas();
  r.scaled.assign(nf, 0.);
  if(o.border_finite)
  {
    r.border_area = std::abs(CGAL::to_double(times_power_of_two(o.border_twice_area, -1)));
    r.border_area_scaled = std::abs(CGAL::to_double(times_power_of_two(o.border_twice_area, 2 * s.shift - 1)));
  }
  r.min_area = std::numeric_limits<double>::infinity();
  r.max_area = -std::numeric_limits<double>::infinity();
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(!o.face_ok[f]) continue;
    const auto& t = disk.faces[f];
    double a = 0, a_map = 0;
    bool exact = !s.scaled_exactly;
    if(!exact)
    {
      const double dx1 = s.X[t[1]] - s.X[t[0]], dy1 = s.Y[t[1]] - s.Y[t[0]];
      const double dx2 = s.X[t[2]] - s.X[t[0]], dy2 = s.Y[t[2]] - s.Y[t[0]];
      a = (dx1 * dy2 - dy1 * dx2) / 2;
      // each difference of doubles is correctly rounded, so the error is relative to the products
      const double bound = 1e-14 * (std::abs(dx1 * dy2) + std::abs(dy1 * dx2));
      exact = !(std::abs(a) > bound) || CGAL::sign(a) != CGAL::Sign(o.fo[f]);
      a_map = std::ldexp(a, back);
    }
    if(exact)
    {
      if constexpr(Uv_samples<Point_2>::floating)
      {
        const CGAL::Gmpq a2 = twice_signed_area(s.qx(t[0]), s.qy(t[0]), s.qx(t[1]), s.qy(t[1]), s.qx(t[2]), s.qy(t[2]));
        a = CGAL::to_double(times_power_of_two(a2, 2 * s.shift - 1));
        a_map = CGAL::to_double(times_power_of_two(a2, -1));
      }
      else
      {
        double m = 0;
        long e = 0;
        rational_twice_area(s.QX[t[0]], s.QY[t[0]], s.QX[t[1]], s.QY[t[1]], s.QX[t[2]], s.QY[t[2]], m, e);
        a = std::ldexp(m, int((std::max)((std::min)(e + 2 * s.shift - 1, 4000L), -4000L)));
        a_map = std::ldexp(m, int((std::max)((std::min)(e - 1, 4000L), -4000L)));
      }
    }
    r.scaled[f] = sgn * a;
    r.min_area = (std::min)(r.min_area, sgn * a_map);
    r.max_area = (std::max)(r.max_area, sgn * a_map);
  }
}

// Exact number of self-intersections of the border polygon (counting stops at `limit`)
template <class TriangleMesh, class Point_2, class Orientation_2>
std::size_t border_pass(const Indexed_disk<TriangleMesh>& disk, const Uv_samples<Point_2>& s, const Orientation_2& orient,
                        std::size_t limit)
{
  std::vector<Point_2> B;
  B.reserve(disk.border.size());
  for(std::size_t b : disk.border) B.push_back(s.P[b]);
  return count_polygon_self_intersections(B, orient, limit);
}

// Exact twice signed area of every loop of `d` (zero for a loop with a non-finite vertex, whose
// `finite` flag is then 0).
template <class TriangleMesh, class Point_2>
void loop_areas(const Indexed_domain<TriangleMesh>& d, const Uv_samples<Point_2>& s,
                std::vector<CGAL::Gmpq>& twice_area, std::vector<char>& finite)
{
  const std::size_t k = d.number_of_loops();
  twice_area.assign(k, CGAL::Gmpq(0));
  finite.assign(k, 1);
  for(std::size_t l = 0; l < k; ++l)
  {
    const std::vector<std::size_t>& L = d.loops[l];
    for(std::size_t v : L) if(!s.finite[v]) finite[l] = 0;
    if(!finite[l]) continue;
    std::vector<CGAL::Gmpq> bx(L.size()), by(L.size());
    for(std::size_t i = 0; i < L.size(); ++i) { bx[i] = s.qx(L[i]); by[i] = s.qy(L[i]); }
    twice_area[l] = twice_polygon_area(bx, by);
  }
}

// The outer loop of a map: the finite loop of largest absolute area (exact; the first of equal
// ones in the order of `d.loops`); loop 0 if no loop is finite.
inline std::size_t largest_loop(const std::vector<CGAL::Gmpq>& twice_area, const std::vector<char>& finite)
{
  std::size_t best = 0;
  bool found = false;
  for(std::size_t l = 0; l < twice_area.size(); ++l)
  {
    if(!finite[l]) continue;
    if(!found || CGAL::abs(twice_area[best]) < CGAL::abs(twice_area[l])) best = l;
    found = true;
  }
  return best;
}

struct Loops_result
{
  std::size_t self_intersections = 0; // pairs of edges of one loop (summed over the loops)
  std::size_t crossings = 0;          // pairs of edges of two loops that touch
  std::size_t misoriented_holes = 0;  // holes whose exact area is zero or has the outer loop's sign
  std::size_t holes_outside = 0;      // holes with a vertex outside the outer loop (exact winding number 0)
};

// The loop tests of a multiply connected map whose loops are all finite; `outer_sign` is the
// orientation of the outer loop (`d.outer`). Intersection counting stops at `limit`.
template <class TriangleMesh, class Point_2, class Orientation_2>
Loops_result loops_pass(const Indexed_domain<TriangleMesh>& d, const Uv_samples<Point_2>& s, const Orientation_2& orient,
                        const std::vector<CGAL::Gmpq>& twice_area, CGAL::Orientation outer_sign, std::size_t limit)
{
  Loops_result r;
  count_loop_intersections(s.P, d.loops, orient, limit, r.self_intersections, r.crossings);
  for(std::size_t l = 0; l < d.number_of_loops(); ++l)
  {
    if(l == d.outer) continue;
    const CGAL::Sign sg = CGAL::sign(twice_area[l]);
    if(sg == CGAL::ZERO || sg == CGAL::Sign(outer_sign)) ++r.misoriented_holes;
    // One vertex decides for the whole loop when no two loops touch. Otherwise every vertex of the
    // hole is tested (within a budget of tests: the map is invalid anyway). A vertex on the outer
    // loop is not counted here (it is a contact, counted in `crossings`); the winding number of a
    // point on an outer edge is only used when the contact is already counted.
    const std::vector<std::size_t>& H = d.loops[l];
    const std::vector<std::size_t>& O = d.loops[d.outer];
    const std::size_t tested = (r.crossings == 0 || H.size() * O.size() > 10000000) ? 1 : H.size();
    for(std::size_t i = 0; i < tested; ++i)
    {
      const Point_2& p = s.P[H[i]];
      bool on_outer = false;
      for(std::size_t b : O) if(exact_compare_xy(s.P[b], p) == CGAL::EQUAL) on_outer = true;
      if(!on_outer && winding_number(s.P, O, p, orient) == 0) { ++r.holes_outside; break; }
    }
  }
  return r;
}

struct Overlap_limit_reached {};

struct Overlap_result
{
  bool checked = false;          // decided (false when the examined-pair budget ran out with no overlap found)
  std::size_t overlapping_pairs = 0;
};

// Pairs of non-degenerate faces whose interiors intersect: candidates from conservative boxes,
// decided exactly. Counting stops at `limit`; at most 200 (faces + 10) candidate pairs are examined.
template <class TriangleMesh, class Point_2, class Orientation_2>
Overlap_result overlap_pass(const Indexed_disk<TriangleMesh>& disk, const Uv_samples<Point_2>& s,
                            const Face_orientations& o, const Orientation_2& orient, std::size_t limit)
{
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t> Box;
  const std::size_t nf = disk.number_of_faces();
  Overlap_result r;
  r.checked = true;
  if(limit == 0) return r;
  Conservative_boxes<Point_2> cb;
  cb.build(s.P, s.finite);
  std::vector<Box> boxes;
  boxes.reserve(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(!o.face_ok[f] || o.fo[f] == CGAL::COLLINEAR) continue;
    const std::array<double, 4> b = cb.hull(disk.faces[f]);
    boxes.push_back(Box(CGAL::Bbox_2(b[0], b[2], b[1], b[3]), f));
  }
  std::size_t examined = 0;
  const std::size_t max_examined = 200 * (nf + 10);
  auto report = [&](const Box& b1, const Box& b2) {
    if(++examined > max_examined) throw Overlap_limit_reached();
    const auto& t1 = disk.faces[b1.info()];
    const auto& t2 = disk.faces[b2.info()];
    const bool ok1 = o.fo[b1.info()] == o.border_sign, ok2 = o.fo[b2.info()] == o.border_sign;
    // two correctly oriented faces sharing an edge lie on both sides of it: no overlap
    if(ok1 && ok2)
    {
      int shared = 0;
      for(int i = 0; i < 3; ++i) for(int j = 0; j < 3; ++j) shared += (t1[i] == t2[j]);
      if(shared >= 2) return;
    }
    // faces with the wrong orientation are already counted as flipped; compare each in its own orientation
    Point_2 a[3] = { s.P[t1[0]], s.P[t1[1]], s.P[t1[2]] };
    Point_2 b[3] = { s.P[t2[0]], s.P[t2[1]], s.P[t2[2]] };
    if(!ok1) std::swap(a[1], a[2]);
    if(!ok2) std::swap(b[1], b[2]);
    if(triangle_interiors_intersect(a, b, o.border_sign, orient))
      if(++r.overlapping_pairs >= limit) throw Overlap_limit_reached();
  };
  try { CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), report); }
  catch(const Overlap_limit_reached&)
  {
    if(r.overlapping_pairs == 0 && examined > max_examined) r.checked = false; // inconclusive
  }
  return r;
}

struct Equilateral_energies
{
  double max_energy = 0, mean_energy = 0;
  std::size_t high_energy_faces = 0;
};

// Symmetric Dirichlet energy of every face against an equilateral triangle of area
// border_area / faces (scale invariant: computed on the scaled coordinates); faces that are not
// correctly oriented, or whose energy is not finite, have an infinite energy.
template <class TriangleMesh, class Point_2>
Equilateral_energies equilateral_energy_pass(const Indexed_disk<TriangleMesh>& disk, const Uv_samples<Point_2>& s,
                                             const Face_orientations& o, const Face_areas& a, double threshold)
{
  const std::size_t nf = disk.number_of_faces();
  const double inf = std::numeric_limits<double>::infinity();
  const double ref_area = a.border_area_scaled / double(nf);
  const Reference_triangle<double> eq = equilateral_reference(ref_area, std::sqrt(3.));
  Equilateral_energies r;
  double sum = 0;
  for(std::size_t f = 0; f < nf; ++f)
  {
    double e = inf;
    const double af = a.scaled[f];
    if(o.face_ok[f] && o.fo[f] == o.border_sign && ref_area > 0 && af > 0)
    {
      const auto& t = disk.faces[f];
      e = dirichlet_term(eq, s.X[t[0]], s.Y[t[0]], s.X[t[1]], s.Y[t[1]], s.X[t[2]], s.Y[t[2]]) * (1 + eq.area2 / (af * af));
      if(!std::isfinite(e)) e = inf;
    }
    if(!(e <= threshold)) ++r.high_energy_faces;
    r.max_energy = (std::max)(r.max_energy, e);
    sum += e;
  }
  r.mean_energy = nf ? sum / double(nf) : 0;
  return r;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CHECK_PASSES_H
