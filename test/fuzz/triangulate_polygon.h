// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Fuzz target of triangulate_self_overlapping_polygon_2(): polygons of up to 8 vertices on a 5 x 5
// grid (collinear runs, repeated points, every kind of overlap) or anywhere the input says
// (extreme and non-finite values), some with rotation indices. The decision must equal the brute
// force over all triangulations of the n-gon, each certified independently of the package (the
// certificate of test/Progressive_embedding/constrained/test_self_overlapping.cpp, restated here
// so that this program does not depend on that test's sources), and an accepted triangulation
// must pass that certificate.

#ifndef PE_FUZZ_TRIANGULATE_POLYGON_H
#define PE_FUZZ_TRIANGULATE_POLYGON_H

#include "fuzz_util.h"

#include <CGAL/Progressive_embedding/triangulate_self_overlapping_polygon_2.h>
#include <CGAL/Simple_cartesian.h>

#include <iterator>
#include <set>

namespace pe_fuzz {

namespace polygon_oracle {

typedef CGAL::Simple_cartesian<CGAL::Gmpq> Kq;
typedef Kq::Point_2                        Qp;

// The polygon's points (exact) and the orientations of their triples, each computed once: the brute
// force tries up to 132 triangulations, twice, on the same few points.
class Polygon
{
  std::vector<Qp> P;
  mutable std::vector<signed char> memo; // by i n^2 + j n + k; 2: not computed yet
public:
  explicit Polygon(std::vector<Qp> points) : P(std::move(points)), memo(P.size() * P.size() * P.size(), 2) {}
  std::size_t size() const { return P.size(); }
  const Qp& operator[](std::size_t i) const { return P[i]; }
  CGAL::Orientation orientation(std::size_t i, std::size_t j, std::size_t k) const
  {
    signed char& o = memo[(i * P.size() + j) * P.size() + k];
    if(o == 2) o = static_cast<signed char>(CGAL::orientation(P[i], P[j], P[k]));
    return CGAL::Orientation(o);
  }
};

// position of the direction v->d in [0, 2 pi) counterclockwise from v->a0: the half-plane first,
// then the sign of the cross product
inline bool upper_rel(const Polygon& Q, std::size_t v, std::size_t a0, std::size_t d)
{
  const CGAL::Orientation o = Q.orientation(v, a0, d);
  if(o != CGAL::COLLINEAR) return o == CGAL::LEFT_TURN;
  return (Q[a0] - Q[v]) * (Q[d] - Q[v]) > 0; // the direction of a0: angle 0
}
inline bool angle_less(const Polygon& Q, std::size_t v, std::size_t a0, std::size_t a, std::size_t b)
{
  const bool ua = upper_rel(Q, v, a0, a), ub = upper_rel(Q, v, a0, b);
  if(ua != ub) return ua;
  return Q.orientation(v, a, b) == CGAL::LEFT_TURN;
}

// Empty if the index triangles T triangulate an immersed disk bounded by the polygon Q (edges in the
// direction given by `ccw`), else why not: n - 2 strictly positive triangles, each polygon edge in one
// triangle in the polygon's direction, each diagonal in two (once each way), Euler characteristic 1, and
// around every vertex a fan from its next edge to its previous edge that turns monotonically (vertices
// with a positive rotation index are certified by their angle sums instead, angle_sum_failure()).
inline std::string immersion_failure(const Polygon& Q, const std::vector<Tri>& T, bool ccw,
                                     const std::vector<int>& turns)
{
  const std::size_t n = Q.size();
  if(T.size() + 2 != n) return "wrong number of triangles";
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> directed;
  for(std::size_t t = 0; t < T.size(); ++t)
  {
    for(int c = 0; c < 3; ++c) if(T[t][c] >= n) return "index out of range";
    if(Q.orientation(T[t][0], T[t][1], T[t][2]) != CGAL::LEFT_TURN) return "a triangle not strictly positive";
    for(int c = 0; c < 3; ++c)
      if(!directed.emplace(std::make_pair(T[t][c], T[t][(c + 1) % 3]), t).second) return "a directed edge used twice";
  }
  std::set<std::pair<std::size_t, std::size_t> > undirected;
  std::set<std::size_t> used;
  for(const auto& e : directed)
  {
    const std::size_t a = e.first.first, b = e.first.second;
    used.insert(a);
    undirected.insert(std::make_pair((std::min)(a, b), (std::max)(a, b)));
    const bool forward = ccw ? (b == (a + 1) % n) : (a == (b + 1) % n);
    const bool backward = ccw ? (a == (b + 1) % n) : (b == (a + 1) % n);
    if(backward) return "a polygon edge against the polygon's direction";
    if(!forward && directed.count(std::make_pair(b, a)) != 1) return "a diagonal in one triangle only";
  }
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::size_t a = ccw ? k : (k + 1) % n, b = ccw ? (k + 1) % n : k;
    if(directed.count(std::make_pair(a, b)) != 1) return "a polygon edge not in exactly one triangle";
  }
  const long V = long(used.size()), E = long(undirected.size()), F = long(T.size());
  if(V != long(n) || V - E + F != 1) return "Euler characteristic";
  std::vector<std::map<std::size_t, std::size_t> > fan(n); // fan[v][a] = b: triangle (v, a, b)
  for(const Tri& t : T)
    for(int c = 0; c < 3; ++c) fan[t[c]][t[(c + 1) % 3]] = t[(c + 2) % 3];
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::size_t first = ccw ? (k + 1) % n : (k + n - 1) % n, last = ccw ? (k + n - 1) % n : (k + 1) % n;
    std::size_t a = first, steps = 0;
    while(a != last)
    {
      if(fan[k].count(a) != 1 || ++steps > n) return "a broken fan";
      const std::size_t b = fan[k][a];
      if((turns.empty() || turns[k] == 0) && !angle_less(Q, k, first, a, b)) return "a fan not turning monotonically";
      a = b;
    }
  }
  return std::string();
}

const double two_pi = 2 * 3.14159265358979323846;

// counterclockwise angle from o->a to o->b in (-pi, pi] (double)
inline double corner_angle(const Polygon& Q, std::size_t o, std::size_t a, std::size_t b)
{
  const double ux = CGAL::to_double(Q[a].x() - Q[o].x()), uy = CGAL::to_double(Q[a].y() - Q[o].y());
  const double vx = CGAL::to_double(Q[b].x() - Q[o].x()), vy = CGAL::to_double(Q[b].y() - Q[o].y());
  return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}

// Empty if at every vertex k the triangles' corners sum to the polygon's angle (in (0, 2 pi), from
// k->next to k->prev) plus 2 pi turns[k], within `tol` (small integer coordinates only). A reversal
// (k->next and k->prev in the same direction: an angle of 0 or 2 pi) has no such angle; the
// function's contract refuses it, whatever the rotation index.
inline std::string angle_sum_failure(const Polygon& Q, const std::vector<Tri>& T, const std::vector<int>& turns, double tol)
{
  const std::size_t n = Q.size();
  std::vector<double> sum(n, 0.);
  for(const Tri& t : T)
    for(int c = 0; c < 3; ++c) sum[t[c]] += corner_angle(Q, t[c], t[(c + 1) % 3], t[(c + 2) % 3]);
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::size_t next = (k + 1) % n, prev = (k + n - 1) % n;
    if(Q.orientation(k, next, prev) == CGAL::COLLINEAR && (Q[next] - Q[k]) * (Q[prev] - Q[k]) > 0)
      return "vertex " + std::to_string(k) + ": a reversal";
    double base = corner_angle(Q, k, (k + 1) % n, (k + n - 1) % n);
    if(base <= 0) base += two_pi;
    if(!(std::abs(sum[k] - (base + two_pi * turns[k])) <= tol)) return "vertex " + std::to_string(k) + ": angle sum";
  }
  return std::string();
}

// every triangulation of the polygon i..j, as index triples
inline void all_triangulations(std::size_t i, std::size_t j, std::vector<std::vector<Tri> >& out)
{
  out.clear();
  if(j < i + 2) { out.push_back(std::vector<Tri>()); return; }
  for(std::size_t k = i + 1; k < j; ++k)
  {
    std::vector<std::vector<Tri> > L, R;
    all_triangulations(i, k, L);
    all_triangulations(k, j, R);
    for(const auto& l : L)
      for(const auto& r : R)
      {
        std::vector<Tri> t = l;
        t.insert(t.end(), r.begin(), r.end());
        t.push_back(Tri{{ i, k, j }});
        out.push_back(t);
      }
  }
}

// the triangulations of the n-gon, computed once per n
inline const std::vector<std::vector<Tri> >& triangulations(std::size_t n)
{
  static std::map<std::size_t, std::vector<std::vector<Tri> > > cache;
  auto it = cache.find(n);
  if(it == cache.end())
  {
    std::vector<std::vector<Tri> > all;
    all_triangulations(0, n - 1, all);
    it = cache.emplace(n, std::move(all)).first;
  }
  return it->second;
}

} // namespace polygon_oracle

PE_FUZZ_TARGET_FUNCTION(triangulate_polygon)
{
  using namespace polygon_oracle;
  Bytes b(data, size);
  const std::size_t n = 1 + b.u8() % 8;
  const int mode = b.u8() % 4;
  const bool lattice = mode != 3;
  std::vector<double> xy(2 * n);
  for(double& x : xy) x = lattice ? double(b.u8() % 5) : coordinate(b);
  if(!lattice) transform(b, xy);
  // rotation indices (on lattice polygons only: their angle sums are certified in double)
  std::vector<int> turns;
  if(lattice && mode == 2)
    for(std::size_t k = 0; k < n; ++k) { const int t = b.u8(); turns.push_back(t < 200 ? 0 : (t < 250 ? 1 : 2)); }
  bool any_turn = false;
  for(int t : turns) any_turn = any_turn || t > 0;

  std::vector<Point_2> P;
  bool finite = true;
  for(std::size_t k = 0; k < n; ++k)
  {
    P.push_back(Point_2(xy[2 * k], xy[2 * k + 1]));
    finite = finite && std::isfinite(xy[2 * k]) && std::isfinite(xy[2 * k + 1]);
  }
  const std::vector<Tri> sentinel(1, Tri{{ 7, 7, 7 }});
  std::vector<Tri> T = sentinel;
  PE::Polygon_triangulation_report rep;
  const PE::Error_code ec = turns.empty()
    ? PE::triangulate_self_overlapping_polygon_2(P, std::back_inserter(T), PE::parameters::polygon_report(&rep))
    : PE::triangulate_self_overlapping_polygon_2(P, std::back_inserter(T), PE::parameters::rotation_indices(turns).polygon_report(&rep));
  if(ec != PE::OK) PE_FUZZ_CHECK(T == sentinel, "the output was written on " << PE::get_error_name(ec));
  else T.erase(T.begin()); // the triangles follow the sentinel
  if(n < 3) { PE_FUZZ_CHECK(ec == PE::ERROR_BORDER_TOO_SHORT, "a polygon of " << n << " points: " << PE::get_error_name(ec)); return 0; }
  if(!finite) { PE_FUZZ_CHECK(ec == PE::ERROR_NON_FINITE_COORDINATES, "non-finite coordinates: " << PE::get_error_name(ec)); return 0; }

  std::vector<Qp> points;
  for(std::size_t k = 0; k < n; ++k) points.push_back(Qp(CGAL::Gmpq(xy[2 * k]), CGAL::Gmpq(xy[2 * k + 1])));
  const Polygon Qr(std::vector<Qp>(points.rbegin(), points.rend()));
  const Polygon Q(std::move(points));
  const std::vector<int> no_turns(n, 0);
  const std::vector<int>& r = turns.empty() ? no_turns : turns;
  bool exists = false;
  for(const std::vector<Tri>& t : triangulations(n))
  {
    if(any_turn) exists = immersion_failure(Q, t, true, r).empty() && angle_sum_failure(Q, t, r, 1e-9).empty();
    else exists = immersion_failure(Q, t, true, r).empty() || immersion_failure(Qr, t, true, r).empty();
    if(exists) break;
  }
  if(!exists)
  {
    PE_FUZZ_CHECK(ec == PE::ERROR_NOT_SELF_OVERLAPPING || (any_turn && ec == PE::ERROR_WRONG_PARAMETER),
                  "the brute force finds no immersed disk, the function says " << PE::get_error_name(ec));
    return 0;
  }
  PE_FUZZ_CHECK(ec == PE::OK, "the brute force finds an immersed disk, the function says " << PE::get_error_name(ec));
  PE_FUZZ_CHECK(rep.self_overlapping && rep.vertices == n, "report of an accepted polygon");
  const std::string why = immersion_failure(Q, T, !rep.clockwise, r);
  PE_FUZZ_CHECK(why.empty(), "the triangulation returned fails the certificate: " << why);
  if(any_turn)
  {
    PE_FUZZ_CHECK(!rep.clockwise, "a clockwise polygon accepted with rotation indices");
    const std::string angles = angle_sum_failure(Q, T, r, 1e-9);
    PE_FUZZ_CHECK(angles.empty(), "the triangulation returned fails the angle sums: " << angles);
  }
  return 0;
}

} // namespace pe_fuzz

#endif // PE_FUZZ_TRIANGULATE_POLYGON_H
