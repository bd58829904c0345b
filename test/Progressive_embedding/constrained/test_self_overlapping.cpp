// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// triangulate_self_overlapping_polygon_2: simple polygons (the constrained Delaunay path and, forced,
// the dynamic program), weakly self-overlapping ones (spiral strips), runs of collinear vertices and
// vertices on diagonals (polyomino outlines at every start vertex), clockwise input, errors, budgets,
// exact number types. Every triangulation is certified here independently of the package, on exact
// rational points: n - 2 strictly positive triangles, each polygon edge in one triangle (in the
// polygon's direction), each diagonal in two (once each way), Euler characteristic 1, and around every
// vertex a fan that turns monotonically from its next edge to its previous edge (local injectivity).
// Polygons with rotation indices (angles beyond 2 pi): the fan of a vertex with index r wraps r more
// times, certified by the sum of its corner angles (the polygon's angle there plus 2 pi r, within 1e-9).

#include <CGAL/Progressive_embedding/triangulate_self_overlapping_polygon_2.h>

#include "registry.h"
#include "polygon_fixtures.h"
#include "../test_util.h"

#include <algorithm>
#include <list>
#include <map>
#include <set>
#include <sstream>
#include <utility>

namespace {

namespace SO = CGAL::Progressive_embedding::internal::self_overlapping;
typedef std::array<std::size_t, 3> Tri;

template <class P>
Kq::Point_2 exact_point(const P& p) { return Kq::Point_2(exact_rational(p.x()), exact_rational(p.y())); }

// position of direction v->d in [0, 2 pi) measured counterclockwise from v->a0: half, then cross product
bool upper_rel(const Kq::Point_2& v, const Kq::Point_2& a0, const Kq::Point_2& d)
{
  const CGAL::Orientation o = CGAL::orientation(v, a0, d);
  if(o != CGAL::COLLINEAR) return o == CGAL::LEFT_TURN;
  return (a0 - v) * (d - v) > 0; // same direction as a0: angle 0
}
bool angle_less(const Kq::Point_2& v, const Kq::Point_2& a0, const Kq::Point_2& a, const Kq::Point_2& b)
{
  const bool ua = upper_rel(v, a0, a), ub = upper_rel(v, a0, b);
  if(ua != ub) return ua;
  return CGAL::orientation(v, a, b) == CGAL::LEFT_TURN;
}

// The independent certificate, silent: an empty string when `T` triangulates an immersed disk bounded by
// the polygon `Q`, else why not. `ccw`: the polygon's orientation (its edges appear in triangles in this direction).
// `turns`: rotation indices (empty: all 0); the fan of a vertex with a positive index wraps around it, its
// angles are certified by angle_sum_failure below instead of the monotonic walk.
std::string immersion_failure(const std::vector<Kq::Point_2>& Q, const std::vector<Tri>& T, bool ccw,
                              const std::vector<int>& turns = std::vector<int>())
{
  const std::size_t n = Q.size();
  std::ostringstream why;
  if(T.size() + 2 != n) { why << T.size() << " triangles for " << n << " vertices"; return why.str(); }
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> directed; // directed edge -> triangle
  for(std::size_t t = 0; t < T.size(); ++t)
  {
    for(int c = 0; c < 3; ++c) if(T[t][c] >= n) return "index out of range";
    if(CGAL::orientation(Q[T[t][0]], Q[T[t][1]], Q[T[t][2]]) != CGAL::LEFT_TURN)
    { why << "triangle " << t << " (" << T[t][0] << "," << T[t][1] << "," << T[t][2] << ") not strictly positive"; return why.str(); }
    for(int c = 0; c < 3; ++c)
      if(!directed.emplace(std::make_pair(T[t][c], T[t][(c + 1) % 3]), t).second) return "a directed edge is used twice";
  }
  std::set<std::pair<std::size_t, std::size_t> > undirected;
  std::set<std::size_t> used;
  for(const auto& e : directed)
  {
    const std::size_t a = e.first.first, b = e.first.second;
    used.insert(a);
    undirected.insert(std::make_pair((std::min)(a, b), (std::max)(a, b)));
    const bool border_forward = ccw ? (b == (a + 1) % n) : (a == (b + 1) % n);
    const bool border_backward = ccw ? (a == (b + 1) % n) : (b == (a + 1) % n);
    if(border_backward) { why << "polygon edge " << a << "-" << b << " used against the polygon's direction"; return why.str(); }
    if(!border_forward && directed.count(std::make_pair(b, a)) != 1) { why << "diagonal " << a << "-" << b << " in one triangle only"; return why.str(); }
  }
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::size_t a = ccw ? k : (k + 1) % n, b = ccw ? (k + 1) % n : k;
    if(directed.count(std::make_pair(a, b)) != 1) { why << "polygon edge " << k << " not in exactly one triangle"; return why.str(); }
  }
  // Euler characteristic of the index triangulation
  const long V = long(used.size()), E = long(undirected.size()), F = long(T.size());
  if(V != long(n) || V - E + F != 1) { why << "V - E + F = " << V - E + F << " (V " << V << ")"; return why.str(); }

  // local injectivity at every vertex: walk the fan from the next polygon vertex to the previous one
  // (each triangle (v, a, b) counterclockwise leads from a to b) and check that the directions increase
  // strictly in [0, 2 pi) measured from the first edge: the fan covers exactly the vertex's angle.
  std::vector<std::map<std::size_t, std::size_t> > fan(n); // fan[v][a] = b
  for(const Tri& t : T)
    for(int c = 0; c < 3; ++c) fan[t[c]][t[(c + 1) % 3]] = t[(c + 2) % 3];
  for(std::size_t k = 0; k < n; ++k)
  {
    // in counterclockwise terms: first = next vertex, last = previous vertex
    const std::size_t first = ccw ? (k + 1) % n : (k + n - 1) % n, last = ccw ? (k + n - 1) % n : (k + 1) % n;
    std::size_t a = first, steps = 0;
    while(a != last)
    {
      if(fan[k].count(a) != 1 || ++steps > n) { why << "the fan of vertex " << k << " is broken"; return why.str(); }
      const std::size_t b = fan[k][a];
      // (a == first has angle 0: b must not leave along the first edge)
      if((turns.empty() || turns[k] == 0) && !angle_less(Q[k], Q[first], Q[a], Q[b])) { why << "the fan of vertex " << k << " does not turn monotonically"; return why.str(); }
      a = b;
    }
  }
  return std::string();
}

template <class P>
int certify(const std::vector<P>& pts, const std::vector<Tri>& T, bool ccw, const std::string& what)
{
  std::vector<Kq::Point_2> Q;
  for(const P& p : pts) Q.push_back(exact_point(p));
  const std::string why = immersion_failure(Q, T, ccw);
  CHECK(why.empty(), what << ": " << why);
  return EXIT_SUCCESS;
}

// The angle of the polygon at every vertex k (in (0, 2 pi), counterclockwise from k -> next to k -> prev,
// plus 2 pi turns[k]) against the sum of the corners of the triangles at k, in double: an empty string
// when they agree within `tol` everywhere. With positive triangles whose fans are connected (checked by
// immersion_failure) this is local injectivity at every vertex, wrapped ones included.
const double two_pi = 2 * 3.14159265358979323846;

// counterclockwise angle from o -> a to o -> b, in (-pi, pi] (double)
double corner_angle(const std::vector<Kq::Point_2>& Q, std::size_t o, std::size_t a, std::size_t b)
{
  const double ux = CGAL::to_double(Q[a].x() - Q[o].x()), uy = CGAL::to_double(Q[a].y() - Q[o].y());
  const double vx = CGAL::to_double(Q[b].x() - Q[o].x()), vy = CGAL::to_double(Q[b].y() - Q[o].y());
  return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}
// the polygon's angle at k in (0, 2 pi], without turns
double base_angle(const std::vector<Kq::Point_2>& Q, std::size_t k)
{
  const std::size_t n = Q.size();
  const double a = corner_angle(Q, k, (k + 1) % n, (k + n - 1) % n);
  return a <= 0 ? a + two_pi : a;
}
// the sum of the triangles' corners at every vertex
std::vector<double> corner_sums(const std::vector<Kq::Point_2>& Q, const std::vector<Tri>& T)
{
  std::vector<double> sum(Q.size(), 0.);
  for(const Tri& t : T)
    for(int c = 0; c < 3; ++c) sum[t[c]] += corner_angle(Q, t[c], t[(c + 1) % 3], t[(c + 2) % 3]);
  return sum;
}

std::string angle_sum_failure(const std::vector<Kq::Point_2>& Q, const std::vector<Tri>& T, const std::vector<int>& turns, double tol)
{
  const std::size_t n = Q.size();
  const std::vector<double> sum = corner_sums(Q, T);
  std::ostringstream why;
  for(std::size_t k = 0; k < n; ++k)
  {
    const double want = base_angle(Q, k) + two_pi * (turns.empty() ? 0 : turns[k]);
    if(!(std::abs(sum[k] - want) <= tol))
    { why << "vertex " << k << ": corners sum to " << sum[k] << ", the polygon's angle is " << want; return why.str(); }
  }
  return std::string();
}

// every triangulation of the n-gon (small n), as index triples (i, k, j), i < k < j
void all_triangulations(std::size_t i, std::size_t j, std::vector<std::vector<Tri> >& out)
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

template <class P>
int run_public(const std::vector<P>& pts, bool expect_simple, bool expect_ccw, const std::string& what,
               std::vector<Tri>* out = nullptr)
{
  std::vector<Tri> T;
  PE::Polygon_triangulation_report r;
  const PE::Error_code ec = PE::triangulate_self_overlapping_polygon_2(pts, std::back_inserter(T), PE::parameters::polygon_report(&r));
  CHECK(ec == PE::OK, what << ": " << PE::get_error_name(ec));
  CHECK(r.self_overlapping && r.simple == expect_simple && r.clockwise == !expect_ccw && r.dynamic_program == !expect_simple,
        what << ": report simple " << r.simple << " clockwise " << r.clockwise << " dp " << r.dynamic_program);
  CHECK(r.rotation_number == (expect_ccw ? 1 : -1), what << ": rotation number " << r.rotation_number);
  RUN(certify(pts, T, expect_ccw, what));
  if(out) *out = T;
  return EXIT_SUCCESS;
}

// the dynamic program alone, on a counterclockwise polygon (simple ones included)
template <class P>
int run_dp(const std::vector<P>& pts, const std::string& what, std::vector<Tri>* out = nullptr)
{
  typedef typename CGAL::Kernel_traits<P>::Kernel K;
  typedef typename PE::Progressive_embedding_traits_2<K>::Exact_orientation_2 O;
  SO::Shor_van_wyk<P, O> dp(pts, O());
  SO::Dp_statistics st;
  std::vector<Tri> T;
  CGAL::Real_timer timer; timer.start();
  const PE::Error_code ec = dp.run(timer, 1e9, T, st);
  CHECK(ec == PE::OK, what << " (dynamic program): " << PE::get_error_name(ec));
  RUN(certify(pts, T, true, what + " (dynamic program)"));
  if(out) *out = T;
  return EXIT_SUCCESS;
}

// ---- polygons --------------------------------------------------------------------------------

template <class K>
std::vector<typename K::Point_2> star(std::size_t tips, double r_in, double r_out)
{
  std::vector<typename K::Point_2> P;
  for(std::size_t k = 0; k < 2 * tips; ++k)
  {
    const double a = 3.14159265358979323846 * double(k) / double(tips), r = (k % 2) ? r_in : r_out;
    P.push_back(point<K>(r * std::cos(a), r * std::sin(a)));
  }
  return P;
}

// a strip around a spiral centerline r = 1 + pitch * t / (2 pi), t in [0, turns * 2 pi], width w > pitch:
// it overlaps itself. Outer side forward, inner side backward: counterclockwise, rotation number 1.
template <class K>
std::vector<typename K::Point_2> spiral_strip(std::size_t per_side, double turns, double pitch, double w)
{
  std::vector<typename K::Point_2> P;
  const double two_pi = 2 * 3.14159265358979323846;
  for(std::size_t k = 0; k < per_side; ++k)
  {
    const double t = turns * two_pi * double(k) / double(per_side - 1), r = 1 + pitch * t / two_pi + w;
    P.push_back(point<K>(r * std::cos(t), r * std::sin(t)));
  }
  for(std::size_t k = per_side; k-- > 0; )
  {
    const double t = turns * two_pi * double(k) / double(per_side - 1), r = 1 + pitch * t / two_pi;
    P.push_back(point<K>(r * std::cos(t), r * std::sin(t)));
  }
  return P;
}

// A random polyomino of `cells` cells (4-connected growth, holes filled), its outline counterclockwise
// with a vertex at every unit step (runs of collinear vertices, vertices on diagonals). Empty if the
// outline touches itself at a vertex (two cells meeting at a corner only).
std::vector<Epick::Point_2> polyomino_outline(std::size_t cells, unsigned seed)
{
  const int S = 2 * int(cells) + 4;
  std::vector<char> g(S * S, 0);
  auto at = [&](int x, int y) -> char& { return g[y * S + x]; };
  std::mt19937 rng(seed);
  std::vector<std::pair<int, int> > cs(1, std::make_pair(S / 2, S / 2));
  at(S / 2, S / 2) = 1;
  const int dx[4] = { 1, 0, -1, 0 }, dy[4] = { 0, 1, 0, -1 };
  while(cs.size() < cells)
  {
    const std::pair<int, int> c = cs[rng() % cs.size()];
    const int d = int(rng() % 4), x = c.first + dx[d], y = c.second + dy[d];
    if(x < 1 || y < 1 || x >= S - 1 || y >= S - 1 || at(x, y)) continue;
    at(x, y) = 1; cs.push_back(std::make_pair(x, y));
  }
  // fill holes: flood the outside from the corner
  std::vector<char> out(S * S, 0);
  std::vector<std::pair<int, int> > st(1, std::make_pair(0, 0));
  out[0] = 1;
  while(!st.empty())
  {
    const std::pair<int, int> c = st.back(); st.pop_back();
    for(int d = 0; d < 4; ++d)
    {
      const int x = c.first + dx[d], y = c.second + dy[d];
      if(x < 0 || y < 0 || x >= S || y >= S || at(x, y) || out[y * S + x]) continue;
      out[y * S + x] = 1; st.push_back(std::make_pair(x, y));
    }
  }
  for(int k = 0; k < S * S; ++k) if(!out[k]) g[k] = 1;
  // directed border edges, the cell on their left
  std::map<std::pair<int, int>, std::vector<std::pair<int, int> > > next;
  std::size_t edges = 0;
  for(int y = 1; y < S - 1; ++y)
    for(int x = 1; x < S - 1; ++x)
    {
      if(!at(x, y)) continue;
      if(!at(x, y - 1)) { next[std::make_pair(x, y)].push_back(std::make_pair(x + 1, y)); ++edges; }
      if(!at(x + 1, y)) { next[std::make_pair(x + 1, y)].push_back(std::make_pair(x + 1, y + 1)); ++edges; }
      if(!at(x, y + 1)) { next[std::make_pair(x + 1, y + 1)].push_back(std::make_pair(x, y + 1)); ++edges; }
      if(!at(x - 1, y)) { next[std::make_pair(x, y + 1)].push_back(std::make_pair(x, y)); ++edges; }
    }
  for(const auto& e : next) if(e.second.size() != 1) return std::vector<Epick::Point_2>();
  std::vector<Epick::Point_2> P;
  std::pair<int, int> v = next.begin()->first;
  do { P.push_back(Epick::Point_2(v.first, v.second)); v = next[v][0]; } while(v != next.begin()->first && P.size() <= edges);
  if(P.size() != edges) return std::vector<Epick::Point_2>();
  return P;
}

template <class P>
std::vector<P> rotated(const std::vector<P>& v, std::size_t s)
{
  std::vector<P> r(v.begin() + s, v.end());
  r.insert(r.end(), v.begin(), v.begin() + s);
  return r;
}

// A rectilinear strip of width 2 w around a square spiral centerline (left turns, side lengths growing by
// `pitch` < 2 w every turn): integer coordinates, a vertex at every unit step. It overlaps itself.
std::vector<Epick::Point_2> square_spiral_strip(int L, int segments, int pitch, int w)
{
  std::vector<std::array<int, 2> > c(1, std::array<int, 2>{{ 0, 0 }});
  const int dx[4] = { 1, 0, -1, 0 }, dy[4] = { 0, 1, 0, -1 };
  for(int s = 0; s < segments; ++s)
  {
    const int len = L + pitch * (s / 2);
    c.push_back(std::array<int, 2>{{ c.back()[0] + len * dx[s % 4], c.back()[1] + len * dy[s % 4] }});
  }
  const int m = int(c.size());
  // right normal of direction d: (dy, -dx); offset of centerline point k
  auto offset = [&](int k, int side) {
    std::array<int, 2> o = {{ 0, 0 }};
    if(k > 0) { const int d = (k - 1) % 4; o[0] += dy[d]; o[1] += -dx[d]; }
    if(k < m - 1) { const int d = k % 4; o[0] += dy[d]; o[1] += -dx[d]; }
    if(k == 0 || k == m - 1) { o[0] *= 1; o[1] *= 1; }
    return std::array<int, 2>{{ c[k][0] + side * w * o[0], c[k][1] + side * w * o[1] }};
  };
  std::vector<std::array<int, 2> > corners;
  for(int k = 0; k < m; ++k) corners.push_back(offset(k, 1));      // right side, forward
  for(int k = m; k-- > 0; ) corners.push_back(offset(k, -1));      // left side, backward
  std::vector<Epick::Point_2> P;
  for(std::size_t k = 0; k < corners.size(); ++k)
  {
    const std::array<int, 2> a = corners[k], b = corners[(k + 1) % corners.size()];
    const int steps = (std::max)(std::abs(b[0] - a[0]), std::abs(b[1] - a[1]));
    for(int s = 0; s < steps; ++s)
      P.push_back(Epick::Point_2(a[0] + (b[0] - a[0]) * s / steps, a[1] + (b[1] - a[1]) * s / steps));
  }
  return P;
}

// ---- rotation indices ------------------------------------------------------------------------

template <class P>
std::vector<Kq::Point_2> to_q(const std::vector<P>& pts)
{
  std::vector<Kq::Point_2> Q;
  for(const P& p : pts) Q.push_back(exact_point(p));
  return Q;
}

// The function with rotation indices `r`: OK, the report's counts, n - 2 triangles certified (exact
// orientation and gluing, angle sums at every vertex within 1e-9)
template <class P>
int run_turns(const std::vector<P>& pts, const std::vector<int>& r, const std::string& what, std::vector<Tri>* out = nullptr)
{
  std::vector<Tri> T;
  PE::Polygon_triangulation_report rep;
  const PE::Error_code ec = PE::triangulate_self_overlapping_polygon_2(pts, std::back_inserter(T),
                              PE::parameters::rotation_indices(r).polygon_report(&rep));
  CHECK(ec == PE::OK, what << ": " << PE::get_error_name(ec));
  int sum = 0;
  for(int t : r) sum += t;
  CHECK(rep.self_overlapping && !rep.clockwise && rep.turns == sum && rep.rotation_number == sum + 1 && rep.vertices == pts.size(),
        what << ": report turns " << rep.turns << ", rotation number " << rep.rotation_number);
  CHECK(T.size() + 2 == pts.size(), what << ": " << T.size() << " triangles for " << pts.size() << " vertices");
  const std::vector<Kq::Point_2> Q = to_q(pts);
  std::string why = immersion_failure(Q, T, true, r);
  CHECK(why.empty(), what << ": " << why);
  why = angle_sum_failure(Q, T, r, 1e-9);
  CHECK(why.empty(), what << ": " << why);
  if(out) *out = T;
  return EXIT_SUCCESS;
}

// the rotation indices read from a triangulation: (corner sum - polygon angle) / 2 pi, rounded
std::vector<int> turns_of(const std::vector<Kq::Point_2>& Q, const std::vector<Tri>& T)
{
  const std::vector<double> sum = corner_sums(Q, T);
  std::vector<int> r(Q.size());
  for(std::size_t k = 0; k < Q.size(); ++k) r[k] = int(std::floor((sum[k] - base_angle(Q, k)) / two_pi + 0.5));
  return r;
}

// Two wrapped fans glued along an edge: fan A around a = (0, 0) (wrapped_fan_polygon, 2.5 pi, m steps: a, then
// A_0 .. A_m) and fan B around c = A_m, winding 2.5 pi too, whose last spoke goes back to a, so that B's last
// triangle (c, B_{m-1}, a) and A's last triangle (a, A_{m-1}, c) share the edge a c. The polygon is a, A_0 .. A_m,
// B_0 .. B_{m-1} (2 m + 2 vertices); `T` receives the two fans (2 m triangles). Both a and c wrap once.
std::vector<Epick::Point_2> glued_fans(std::size_t m, std::vector<Tri>& T)
{
  std::vector<Epick::Point_2> P = pe_test::wrapped_fan_polygon(2.5 * 3.14159265358979323846, m);
  const std::size_t c = m + 1;
  T.clear();
  for(std::size_t k = 1; k <= m; ++k) T.push_back(Tri{{ 0, k, k + 1 }});
  const double end = std::atan2(-P[c].y(), -P[c].x()); // the direction from c to a
  for(std::size_t j = 0; j < m; ++j)
  {
    const double phi = end - 2.5 * 3.14159265358979323846 * double(m - j) / double(m), rho = 0.6 + 0.05 * double(j);
    P.push_back(Epick::Point_2(P[c].x() + rho * std::cos(phi), P[c].y() + rho * std::sin(phi)));
  }
  for(std::size_t j = 0; j < m; ++j) T.push_back(Tri{{ c, c + 1 + j, j + 1 < m ? c + 2 + j : 0 }});
  return P;
}

} // namespace

// Polygons whose angle exceeds 2 pi at some vertices (named parameter rotation_indices): a border winding
// 1.25 and 2.25 turns around its vertex 0, at every start vertex, two wrapped vertices, exact rationals, errors.
PE_TEST_GROUP(self_overlapping_rotation_indices)
{
  (void)data_dir;
  const double pi = 3.14159265358979323846;
  // 1.25 turns around vertex 0: angle 2.5 pi there, rotation number 2, r[0] = 1
  const std::vector<Epick::Point_2> fan = pe_test::wrapped_fan_polygon(2.5 * pi, 10);
  const std::size_t n = fan.size();
  CHECK(n == 12, "12 vertices");
  std::vector<int> r(n, 0);
  r[0] = 1;
  {
    // the construction's own fan is the immersed disk these indices describe
    std::vector<Tri> F;
    for(std::size_t k = 1; k + 1 < n; ++k) F.push_back(Tri{{ 0, k, k + 1 }});
    CHECK(turns_of(to_q(fan), F) == r, "the fan's corner sums give r[0] = 1 and 0 elsewhere");
    CHECK(immersion_failure(to_q(fan), F, true, r).empty() && angle_sum_failure(to_q(fan), F, r, 1e-9).empty(), "the fan certified");
    // the certificate is not vacuous: without the indices the wrapped fan is refused at vertex 0
    CHECK(!angle_sum_failure(to_q(fan), F, std::vector<int>(), 1e-9).empty(), "the angle sums see the wrap");
  }
  std::vector<Tri> Td;
  RUN(run_turns(fan, r, "1.25 turns", &Td));
  CHECK(std::abs(corner_sums(to_q(fan), Td)[0] - 2.5 * pi) < 1e-9, "angle 2.5 pi at vertex 0: " << corner_sums(to_q(fan), Td)[0]);
  for(std::size_t s = 0; s < n; ++s)
    RUN(run_turns(rotated(fan, s), rotated(r, s), "1.25 turns, start " + std::to_string(s)));

  // 2.25 turns: angle 4.5 pi, r[0] = 2, rotation number 3
  const std::vector<Epick::Point_2> fan2 = pe_test::wrapped_fan_polygon(4.5 * pi, 18);
  std::vector<int> r2(fan2.size(), 0);
  r2[0] = 2;
  std::vector<Tri> T2;
  RUN(run_turns(fan2, r2, "2.25 turns", &T2));
  CHECK(std::abs(corner_sums(to_q(fan2), T2)[0] - 4.5 * pi) < 1e-9, "angle 4.5 pi at vertex 0: " << corner_sums(to_q(fan2), T2)[0]);
  for(std::size_t s = 0; s < fan2.size(); ++s)
    RUN(run_turns(rotated(fan2, s), rotated(r2, s), "2.25 turns, start " + std::to_string(s)));

  // two wrapped vertices: the glued fans, indices read from the construction
  std::vector<Tri> G;
  const std::vector<Epick::Point_2> glued = glued_fans(8, G);
  const std::vector<int> rg = turns_of(to_q(glued), G);
  std::vector<int> rg_want(glued.size(), 0);
  rg_want[0] = 1; rg_want[9] = 1;
  CHECK(rg == rg_want, "the glued fans wrap once around vertices 0 and 9 only");
  CHECK(immersion_failure(to_q(glued), G, true, rg).empty() && angle_sum_failure(to_q(glued), G, rg, 1e-9).empty(),
        "the glued fans certified");
  std::vector<Tri> TG;
  RUN(run_turns(glued, rg, "two wrapped vertices", &TG));
  const std::vector<double> gs = corner_sums(to_q(glued), TG), gs_want = corner_sums(to_q(glued), G);
  CHECK(std::abs(gs[0] - gs_want[0]) < 1e-9 && std::abs(gs[9] - gs_want[9]) < 1e-9 && gs[0] > 2 * pi && gs[9] > 2 * pi,
        "angles " << gs[0] << " and " << gs[9] << " at the wrapped vertices");
  for(std::size_t s = 0; s < glued.size(); s += 3)
    RUN(run_turns(rotated(glued, s), rotated(rg, s), "two wrapped vertices, start " + std::to_string(s)));

  // Every chord at the wrapped vertex lies along or against one of its edges: (3, 1) sees its neighbours
  // (1, 3) and (0, 3) again at positions 6 and 7, and the chords to (4, 0) and (3, 3) point against an
  // edge at one end (an angle of pi on one side, which is allowed; along an edge is not)
  const std::vector<Epick::Point_2> against = { Epick::Point_2(3, 1), Epick::Point_2(1, 3), Epick::Point_2(0, 3),
    Epick::Point_2(4, 0), Epick::Point_2(3, 4), Epick::Point_2(3, 3), Epick::Point_2(1, 3), Epick::Point_2(0, 3) };
  std::vector<int> ra(against.size(), 0);
  ra[0] = 1;
  for(std::size_t s = 0; s < against.size(); ++s)
    RUN(run_turns(rotated(against, s), rotated(ra, s), "chords against an edge, start " + std::to_string(s)));
  RUN(run_turns(to_q(against), ra, "chords against an edge, Gmpq"));

  // exact rationals: the same decisions, the same triangles
  std::vector<Kq::Point_2> fanq = to_q(fan);
  std::vector<Tri> Tq;
  RUN(run_turns(fanq, r, "1.25 turns, Gmpq", &Tq));
  CHECK(Tq == Td, "double and Gmpq triangulations differ");

  // errors, the output untouched
  const std::vector<Tri> sentinel(1, Tri{{ 7, 7, 7 }});
  auto expect = [&](const std::vector<Epick::Point_2>& P, const std::vector<int>* turns, PE::Error_code want, const std::string& what) {
    std::vector<Tri> T = sentinel;
    PE::Polygon_triangulation_report rep;
    const PE::Error_code ec = turns
      ? PE::triangulate_self_overlapping_polygon_2(P, std::back_inserter(T), PE::parameters::rotation_indices(*turns).polygon_report(&rep))
      : PE::triangulate_self_overlapping_polygon_2(P, std::back_inserter(T), PE::parameters::polygon_report(&rep));
    CHECK(ec == want, what << ": " << PE::get_error_name(ec) << " (" << int(ec) << ")");
    CHECK(T == sentinel, what << ": the output was touched");
    CHECK(!rep.self_overlapping, what << ": reported self-overlapping");
    return EXIT_SUCCESS;
  };
  RUN(expect(fan, nullptr, PE::ERROR_NOT_SELF_OVERLAPPING, "1.25 turns without indices"));
  const std::vector<int> zeros(n, 0);
  RUN(expect(fan, &zeros, PE::ERROR_NOT_SELF_OVERLAPPING, "1.25 turns with all indices 0"));
  RUN(expect(glued, nullptr, PE::ERROR_NOT_SELF_OVERLAPPING, "two wrapped vertices without indices"));
  std::vector<int> one_of_two = rg; one_of_two[9] = 0;
  RUN(expect(glued, &one_of_two, PE::ERROR_NOT_SELF_OVERLAPPING, "two wrapped vertices, one index only"));
  const std::vector<int> short_r(n - 1, 0), long_r(n + 1, 0);
  RUN(expect(fan, &short_r, PE::ERROR_WRONG_PARAMETER, "one index too few"));
  RUN(expect(fan, &long_r, PE::ERROR_WRONG_PARAMETER, "one index too many"));
  std::vector<int> negative = r; negative[3] = -1;
  RUN(expect(fan, &negative, PE::ERROR_WRONG_PARAMETER, "a negative index"));
  std::vector<int> too_many = r; too_many[0] = 2; // rotation number 2 minus 2 turns: 0
  RUN(expect(fan, &too_many, PE::ERROR_NOT_SELF_OVERLAPPING, "indices summing to the rotation number"));
  std::vector<int> too_few = r2; too_few[0] = 1; // rotation number 3 minus 1 turn: 2
  RUN(expect(fan2, &too_few, PE::ERROR_NOT_SELF_OVERLAPPING, "2.25 turns with one index"));
  std::vector<int> misplaced(n, 0); misplaced[5] = 1; // the sum adds up, but vertex 5 is not wrapped
  RUN(expect(fan, &misplaced, PE::ERROR_NOT_SELF_OVERLAPPING, "the index on another vertex"));
  // counterclockwise only: the clockwise fan (rotation number -2) with the index
  const std::vector<Epick::Point_2> cw(fan.rbegin(), fan.rend());
  std::vector<int> rcw(r.rbegin(), r.rend());
  RUN(expect(cw, &rcw, PE::ERROR_NOT_SELF_OVERLAPPING, "clockwise with an index"));
  // a simple polygon with an index: rotation number 1 minus 1 turn
  const std::vector<Epick::Point_2> sq = { Epick::Point_2(0, 0), Epick::Point_2(1, 0), Epick::Point_2(1, 1), Epick::Point_2(0, 1) };
  const std::vector<int> rsq = { 1, 0, 0, 0 };
  RUN(expect(sq, &rsq, PE::ERROR_NOT_SELF_OVERLAPPING, "a square with an index"));
  // all-zero indices leave a simple polygon as it was
  const std::vector<int> zsq(4, 0);
  std::vector<Tri> Tsq;
  CHECK(PE::triangulate_self_overlapping_polygon_2(sq, std::back_inserter(Tsq), PE::parameters::rotation_indices(zsq)) == PE::OK
        && Tsq.size() == 2, "a square with zero indices");
  RUN(certify(sq, Tsq, true, "a square with zero indices"));
  std::cout << "wrapped fans (1.25 and 2.25 turns, every start vertex), two wrapped vertices, chords against an edge, Gmpq: certified; 12 errors as expected" << std::endl;
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(self_overlapping_simple)
{
  (void)data_dir;
  // convex
  std::vector<Epick::Point_2> convex;
  for(int k = 0; k < 50; ++k) convex.push_back(point<Epick>(std::cos(k * 0.12566370614359174), std::sin(k * 0.12566370614359174)));
  RUN(run_public(convex, true, true, "convex 50"));
  RUN(run_dp(convex, "convex 50"));
  // star, both orientations; the dynamic program too
  const std::vector<Epick::Point_2> st = star<Epick>(12, 0.3, 1.0);
  RUN(run_public(st, true, true, "star 24"));
  RUN(run_dp(st, "star 24"));
  std::vector<Epick::Point_2> cw(st.rbegin(), st.rend());
  RUN(run_public(cw, true, false, "clockwise star 24"));
  // a clockwise self-overlapping polygon
  const std::vector<Epick::Point_2> sp = spiral_strip<Epick>(30, 2.0, 0.3, 0.6);
  RUN(run_public(std::vector<Epick::Point_2>(sp.rbegin(), sp.rend()), false, false, "clockwise spiral strip"));
  // a triangle
  std::vector<Epick::Point_2> tri = { point<Epick>(0, 0), point<Epick>(1, 0), point<Epick>(0, 1) };
  RUN(run_public(tri, true, true, "triangle"));
  // any range of points: a std::list
  const std::list<Epick::Point_2> lst(st.begin(), st.end());
  std::vector<Tri> T;
  CHECK(PE::triangulate_self_overlapping_polygon_2(lst, std::back_inserter(T)) == PE::OK, "std::list");
  RUN(certify(st, T, true, "std::list"));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(self_overlapping_polyomino)
{
  (void)data_dir;
  std::size_t shapes = 0, rotations = 0;
  for(unsigned seed = 1; shapes < 6 && seed < 200; ++seed)
  {
    const std::vector<Epick::Point_2> P = polyomino_outline(40, seed);
    if(P.empty()) continue;
    ++shapes;
    for(std::size_t s = 0; s < P.size(); ++s, ++rotations)
    {
      const std::vector<Epick::Point_2> R = rotated(P, s);
      const std::string what = "polyomino seed " + std::to_string(seed) + " start " + std::to_string(s);
      RUN(run_public(R, true, true, what));
      RUN(run_dp(R, what));
    }
  }
  CHECK(shapes == 6, "only " << shapes << " polyominoes");
  std::cout << shapes << " polyomino outlines, " << rotations << " start rotations, both paths certified" << std::endl;
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(self_overlapping_spiral)
{
  (void)data_dir;
  // a spiral strip that winds twice and overlaps itself (width 0.6 > pitch 0.3)
  const std::vector<Epick::Point_2> sp = spiral_strip<Epick>(60, 2.0, 0.3, 0.6);
  RUN(run_public(sp, false, true, "spiral strip 120"));
  // every start vertex on a smaller one
  const std::vector<Epick::Point_2> small = spiral_strip<Epick>(25, 2.0, 0.3, 0.6);
  for(std::size_t s = 0; s < small.size(); ++s)
    RUN(run_public(rotated(small, s), false, true, "spiral strip 50 start " + std::to_string(s)));
  // three turns, larger
  PE::Polygon_triangulation_report r;
  std::vector<Tri> T;
  const std::vector<Epick::Point_2> big = spiral_strip<Epick>(300, 3.0, 0.25, 0.5);
  CHECK(PE::triangulate_self_overlapping_polygon_2(big, std::back_inserter(T), PE::parameters::polygon_report(&r)) == PE::OK, "spiral 600");
  RUN(certify(big, T, true, "spiral strip 600"));
  std::cout << "spiral strip 600: " << r.chords_tested << " chords tested, " << r.chords_stored << " stored, "
            << r.triangles_tested << " triangles tested, " << r.seconds << " s" << std::endl;
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(self_overlapping_collinear)
{
  (void)data_dir;
  // a rectangle with runs of collinear vertices on every side
  std::vector<Epick::Point_2> rect;
  for(int x = 0; x < 8; ++x) rect.push_back(point<Epick>(x, 0));
  for(int y = 0; y < 3; ++y) rect.push_back(point<Epick>(8, y));
  for(int x = 8; x > 0; --x) rect.push_back(point<Epick>(x, 3));
  for(int y = 3; y > 0; --y) rect.push_back(point<Epick>(0, y));
  RUN(run_public(rect, true, true, "rectangle with runs"));
  RUN(run_dp(rect, "rectangle with runs"));
  // a rectilinear strip around a square spiral: overlapping itself, collinear runs, vertices on diagonals
  const std::vector<Epick::Point_2> sq = square_spiral_strip(12, 8, 2, 2);
  RUN(run_public(sq, false, true, "square spiral strip " + std::to_string(sq.size())));
  for(std::size_t s = 0; s < sq.size(); s += 7)
    RUN(run_public(rotated(sq, s), false, true, "square spiral strip start " + std::to_string(s)));
  // no pitch: the second turn lies exactly on the first (coincident vertices and overlapping edges of two sheets)
  RUN(run_public(square_spiral_strip(12, 8, 0, 2), false, true, "square strip wound twice on itself"));
  // one closed turn: the end cap lies on the start cap, the polygon runs along that segment both ways
  RUN(run_public(square_spiral_strip(12, 4, 0, 2), false, true, "square annulus cut open"));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(self_overlapping_errors)
{
  (void)data_dir;
  const std::vector<Tri> sentinel(1, Tri{{ 7, 7, 7 }});
  auto expect = [&](const std::vector<Epick::Point_2>& P, PE::Error_code want, const char* what) {
    std::vector<Tri> T = sentinel;
    const PE::Error_code ec = PE::triangulate_self_overlapping_polygon_2(P, std::back_inserter(T));
    CHECK(ec == want, what << ": " << PE::get_error_name(ec) << " (" << int(ec) << ")");
    CHECK(T == sentinel, what << ": the output was touched");
    return EXIT_SUCCESS;
  };
  // figure-eight: rotation number 0
  std::vector<Epick::Point_2> eight = { point<Epick>(0, 0), point<Epick>(2, 2), point<Epick>(2, 0), point<Epick>(0, 2) };
  RUN(expect(eight, PE::ERROR_NOT_SELF_OVERLAPPING, "figure-eight"));
  // a convex polygon wound twice: rotation number 2
  std::vector<Epick::Point_2> twice;
  for(int k = 0; k < 10; ++k) twice.push_back(point<Epick>(std::cos(k * 1.2566370614359172), std::sin(k * 1.2566370614359172) + 0.01 * k));
  RUN(expect(twice, PE::ERROR_NOT_SELF_OVERLAPPING, "wound twice"));
  // rotation number 1, but a clockwise kink encloses a region of winding number -1 (and a counterclockwise one elsewhere)
  std::vector<Epick::Point_2> kinks = {
    point<Epick>(0, 0), point<Epick>(3, 0), point<Epick>(5, 0), point<Epick>(5, -1), point<Epick>(4, -1), point<Epick>(4, 1),
    point<Epick>(10, 1), point<Epick>(10, 10), point<Epick>(6, 10), point<Epick>(5, 10), point<Epick>(5, 11), point<Epick>(4, 11),
    point<Epick>(4, 9), point<Epick>(0, 9) };
  RUN(expect(kinks, PE::ERROR_NOT_SELF_OVERLAPPING, "kinks"));
  // two squares touching at a corner: rotation number 1, but the disk would be pinched there
  std::vector<Epick::Point_2> pinch = { point<Epick>(0, 0), point<Epick>(1, 0), point<Epick>(1, 1), point<Epick>(2, 1),
                                        point<Epick>(2, 2), point<Epick>(1, 2), point<Epick>(1, 1), point<Epick>(0, 1) };
  RUN(expect(pinch, PE::ERROR_NOT_SELF_OVERLAPPING, "pinched"));
  // spike (reversal), repeated point, too short, non-finite
  std::vector<Epick::Point_2> spike = { point<Epick>(0, 0), point<Epick>(2, 0), point<Epick>(1, 0), point<Epick>(1, 1) };
  RUN(expect(spike, PE::ERROR_NOT_SELF_OVERLAPPING, "spike"));
  std::vector<Epick::Point_2> rep = { point<Epick>(0, 0), point<Epick>(1, 0), point<Epick>(1, 0), point<Epick>(0, 1) };
  RUN(expect(rep, PE::ERROR_NOT_SELF_OVERLAPPING, "repeated point"));
  RUN(expect(std::vector<Epick::Point_2>(eight.begin(), eight.begin() + 2), PE::ERROR_BORDER_TOO_SHORT, "two points"));
  std::vector<Epick::Point_2> nan = eight; nan[1] = Epick::Point_2(std::nan(""), 1);
  RUN(expect(nan, PE::ERROR_NON_FINITE_COORDINATES, "NaN"));
  // budgets: a tiny time budget on the dynamic program and on the simple path; a negative one
  const std::vector<Epick::Point_2> sp = spiral_strip<Epick>(400, 2.0, 0.3, 0.6);
  for(const std::vector<Epick::Point_2>* P : { &sp })
  {
    std::vector<Tri> T = sentinel;
    CHECK(PE::triangulate_self_overlapping_polygon_2(*P, std::back_inserter(T), CGAL::parameters::maximum_running_time(1e-9))
          == PE::ERROR_BUDGET_EXHAUSTED && T == sentinel, "tiny budget");
    CHECK(PE::triangulate_self_overlapping_polygon_2(*P, std::back_inserter(T), CGAL::parameters::maximum_running_time(-1.))
          == PE::ERROR_WRONG_PARAMETER && T == sentinel, "negative budget");
  }
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(self_overlapping_exact)
{
  (void)data_dir;
  // the same decisions in double and in exact rationals (the coordinates convert exactly): same triangles
  const std::vector<Epick::Point_2> sp = spiral_strip<Epick>(20, 2.0, 0.3, 0.6);
  std::vector<Kq::Point_2> spq;
  for(const auto& p : sp) spq.push_back(Kq::Point_2(CGAL::Gmpq(p.x()), CGAL::Gmpq(p.y())));
  std::vector<Tri> Td, Tq;
  RUN(run_public(sp, false, true, "spiral 40 double", &Td));
  RUN(run_public(spq, false, true, "spiral 40 Gmpq", &Tq));
  CHECK(Td == Tq, "double and Gmpq triangulations differ");
  // the simple path in Gmpq and Gmpfr, and a polygon whose points need more than double precision
  const std::vector<Kq::Point_2> stq = star<Kq>(6, 0.25, 1.0);
  RUN(run_public(stq, true, true, "star Gmpq"));
  const std::vector<Kfr::Point_2> stf = star<Kfr>(6, 0.25, 1.0);
  RUN(run_public(stf, true, true, "star Gmpfr"));
  std::vector<Kfr::Point_2> spf;
  for(const auto& p : sp) spf.push_back(Kfr::Point_2(ft<CGAL::Gmpfr>(p.x()), ft<CGAL::Gmpfr>(p.y())));
  std::vector<Tri> Tf;
  RUN(run_public(spf, false, true, "spiral 40 Gmpfr", &Tf));
  CHECK(Td == Tf, "double and Gmpfr triangulations differ");
  // a flat vertex a third of the way between two others, in rationals: (0,0) (1/3,0) (1,0) (1,1) (0,1)
  std::vector<Kq::Point_2> third = { Kq::Point_2(0, 0), Kq::Point_2(CGAL::Gmpq(1, 3), 0), Kq::Point_2(1, 0), Kq::Point_2(1, 1), Kq::Point_2(0, 1) };
  RUN(run_public(third, true, true, "flat vertex at 1/3"));
  RUN(run_dp(third, "flat vertex at 1/3"));
  return EXIT_SUCCESS;
}

// Small random polygons on a 5 x 5 grid (collinear runs, points on diagonals, repeated points, every
// kind of overlap): the function's decision equals the brute force over all triangulations of the n-gon
// with the independent certificate, and every triangulation it returns is certified.
PE_TEST_GROUP(self_overlapping_brute_force)
{
  (void)data_dir;
  std::mt19937 rng(12345);
  std::size_t accepted = 0, rejected = 0, simple = 0;
  for(int trial = 0; trial < 3000; ++trial)
  {
    const std::size_t n = (trial % 2 == 0) ? 4 + std::size_t(trial % 5) : 6 + std::size_t(trial % 4); // 4..8, 6..9
    std::vector<Epick::Point_2> P;
    if(trial % 2 == 0)
      for(std::size_t k = 0; k < n; ++k) P.push_back(Epick::Point_2(double(rng() % 5), double(rng() % 5)));
    else
    {
      // triangles glued one by one on a border edge, each positive: often an immersed disk that overlaps itself
      P = { Epick::Point_2(0, 0), Epick::Point_2(1, 0), Epick::Point_2(0, 1) };
      for(int tries = 0; P.size() < n && tries < 200; ++tries)
      {
        const std::size_t e = rng() % P.size();
        const Epick::Point_2 x(double(rng() % 9) - 4, double(rng() % 9) - 4);
        if(CGAL::orientation(P[(e + 1) % P.size()], P[e], x) != CGAL::LEFT_TURN) continue; // outside edge e
        P.insert(P.begin() + std::ptrdiff_t(e + 1), x);
      }
      if(P.size() != n) continue;
    }
    std::vector<Kq::Point_2> Q, Qr;
    for(const auto& p : P) Q.push_back(exact_point(p));
    Qr.assign(Q.rbegin(), Q.rend());
    std::vector<std::vector<Tri> > all;
    all_triangulations(0, n - 1, all);
    bool exists = false;
    for(const auto& t : all) if(immersion_failure(Q, t, true).empty() || immersion_failure(Qr, t, true).empty()) { exists = true; break; }
    std::vector<Tri> T;
    PE::Polygon_triangulation_report r;
    const PE::Error_code ec = PE::triangulate_self_overlapping_polygon_2(P, std::back_inserter(T), PE::parameters::polygon_report(&r));
    CHECK(ec == PE::OK || ec == PE::ERROR_NOT_SELF_OVERLAPPING, "trial " << trial << ": " << PE::get_error_name(ec));
    CHECK((ec == PE::OK) == exists, "trial " << trial << ": the function says " << PE::get_error_name(ec)
          << ", the brute force " << (exists ? "self-overlapping" : "not self-overlapping"));
    if(ec == PE::OK)
    {
      RUN(certify(P, T, !r.clockwise, "trial " + std::to_string(trial)));
      ++accepted;
      if(r.simple) ++simple;
    }
    else ++rejected;
  }
  CHECK(accepted > 300 && rejected > 300 && accepted - simple >= 30, accepted << " accepted (" << simple << " simple), " << rejected << " rejected");
  std::cout << accepted << " accepted (" << simple << " simple), " << rejected << " rejected, all as the brute force" << std::endl;
  return EXIT_SUCCESS;
}

// The certificate of these tests is not vacuous: it rejects broken triangulations of each kind.
PE_TEST_GROUP(self_overlapping_certificate)
{
  (void)data_dir;
  const double d2r = 3.14159265358979323846 / 180;
  // a fan of four positive triangles around vertex 0 turning 400 degrees: a disk, every triangle positive,
  // but not locally injective at vertex 0
  std::vector<Kq::Point_2> Q = { Kq::Point_2(0, 0) };
  const double ang[5] = { 0, 100, 200, 300, 400 }, rad[5] = { 2, 2, 2, 2, 1 };
  for(int k = 0; k < 5; ++k) Q.push_back(exact_point(point<Epick>(rad[k] * std::cos(ang[k] * d2r), rad[k] * std::sin(ang[k] * d2r))));
  const std::vector<Tri> wrap = { Tri{{ 0, 1, 2 }}, Tri{{ 0, 2, 3 }}, Tri{{ 0, 3, 4 }}, Tri{{ 0, 4, 5 }} };
  const std::string why = immersion_failure(Q, wrap, true);
  CHECK(why.find("monotonically") != std::string::npos, "the 400-degree fan: '" << why << "'");
  // the same triangles, one of them listed clockwise; one missing; a polygon edge twice
  std::vector<Tri> flipped = wrap; std::swap(flipped[1][1], flipped[1][2]);
  CHECK(immersion_failure(Q, flipped, true).find("positive") != std::string::npos, "flipped triangle");
  CHECK(!immersion_failure(Q, std::vector<Tri>(wrap.begin(), wrap.end() - 1), true).empty(), "missing triangle");
  // a square triangulated along both diagonals' halves (4 triangles around no vertex) is refused by the count;
  // the square with a repeated triangle is refused by the directed edges
  std::vector<Kq::Point_2> sq = { Kq::Point_2(0, 0), Kq::Point_2(1, 0), Kq::Point_2(1, 1), Kq::Point_2(0, 1) };
  CHECK(immersion_failure(sq, { Tri{{ 0, 1, 2 }}, Tri{{ 0, 2, 3 }} }, true).empty(), "the valid square");
  CHECK(!immersion_failure(sq, { Tri{{ 0, 1, 2 }}, Tri{{ 0, 1, 2 }} }, true).empty(), "repeated triangle");
  CHECK(!immersion_failure(sq, { Tri{{ 0, 1, 2 }}, Tri{{ 0, 2, 3 }} }, false).empty(), "wrong orientation");
  return EXIT_SUCCESS;
}
