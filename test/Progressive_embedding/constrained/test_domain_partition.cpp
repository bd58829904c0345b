// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// The target domain cut into convex polygons (partition_domain) and the placement of path vertices
// on its edges (place_path_vertices). Every property is checked independently of the package, with
// CGAL::orientation on exact rational points: strict convexity, tiling (exact areas, Euler, each
// polygon side once), targets as corners, rotation orders, error codes, bit-exact positions.

#include <CGAL/Progressive_embedding/internal/constrained/domain_partition.h>
#include <CGAL/Progressive_embedding/internal/constrained/trace_paths.h>
#include <CGAL/Progressive_embedding/triangulate_self_overlapping_polygon_2.h>

#include <CGAL/Polygon_2_algorithms.h>

#include "registry.h"
#include "polygon_fixtures.h"
#include "../test_util.h"

#include <algorithm>
#include <map>
#include <set>
#include <string>

namespace {

namespace I = CGAL::Progressive_embedding::internal;
using pe_test::hilbert_outline;

template <class P>
Kq::Point_2 qp(const P& p) { return Kq::Point_2(exact_rational(p.x()), exact_rational(p.y())); }

CGAL::Gmpq twice_area(const std::vector<Kq::Point_2>& P)
{
  CGAL::Gmpq s(0);
  for(std::size_t k = 0; k < P.size(); ++k)
  {
    const Kq::Point_2& a = P[k];
    const Kq::Point_2& b = P[(k + 1) % P.size()];
    s += a.x() * b.y() - a.y() * b.x();
  }
  return s;
}

// half-plane of a direction: [0, 180) degrees or [180, 360)
bool upper(const Kq::Vector_2& d) { return d.y() > 0 || (d.y() == 0 && d.x() > 0); }

// strictly inside a convex counterclockwise polygon, O(n), exact
bool strictly_inside(const std::vector<Kq::Point_2>& P, const Kq::Point_2& q)
{
  for(std::size_t k = 0; k < P.size(); ++k)
    if(CGAL::orientation(P[k], P[(k + 1) % P.size()], q) != CGAL::LEFT_TURN) return false;
  return true;
}

struct Stats { std::size_t edges = 0, chords = 0, polygons = 0; };

// The independent certificate of a partition. `flat_ok`: flat border vertices were allowed.
template <class P>
int check_partition(const std::vector<P>& border, const std::vector<P>& targets, const I::Domain_partition& dp,
                    bool expected_ccw, Stats& st, bool flat_ok = false, bool chords_ok = false)
{
  const std::size_t nb = border.size(), nt = targets.size(), nn = nb + nt;
  std::vector<Kq::Point_2> pt;
  for(const P& p : border) pt.push_back(qp(p));
  for(const P& p : targets) pt.push_back(qp(p));
  CHECK(dp.number_of_border_nodes == nb && dp.number_of_targets == nt, "node counts");
  CHECK(dp.counterclockwise == expected_ccw, "border orientation reported");
  CHECK(dp.rotation.size() == nn && dp.edge_polygons.size() == dp.edges.size(), "array sizes");
  const std::size_t E = dp.edges.size(), F = dp.polygons.size();
  auto ccw_next = [&](std::size_t i) { return expected_ccw ? (i + 1) % nb : (i + nb - 1) % nb; };
  auto ccw_prev = [&](std::size_t i) { return expected_ccw ? (i + nb - 1) % nb : (i + 1) % nb; };

  // edges: valid, unique, a target at one end at least
  std::set<std::pair<std::size_t, std::size_t> > edge_set;
  std::vector<std::vector<std::size_t> > incident(nn);
  st = Stats();
  for(std::size_t e = 0; e < E; ++e)
  {
    const std::size_t u = dp.edges[e][0], v = dp.edges[e][1];
    CHECK(u < v && v < nn, "edge " << e << " nodes " << u << " " << v);
    CHECK(edge_set.insert(std::make_pair(u, v)).second, "edge " << e << " repeated");
    CHECK(!(u < nb && v < nb && (v == u + 1 || (u == 0 && v == nb - 1))), "an interior edge is a border edge");
    if(v < nb) ++st.chords;
    incident[u].push_back(e); incident[v].push_back(e);
  }
  CHECK(chords_ok || st.chords == 0, st.chords << " interior edges join two border points");
  st.edges = E; st.polygons = F;

  // polygons: convex (strictly, except flat border nodes without interior edges), counterclockwise,
  // winding once, each directed side once overall
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> side_polygon;
  std::vector<std::size_t> corner_count(nn, 0);
  CGAL::Gmpq area_sum(0);
  for(std::size_t f = 0; f < F; ++f)
  {
    const std::vector<std::size_t>& poly = dp.polygons[f];
    const std::size_t m = poly.size();
    CHECK(m >= 3, "polygon " << f << " has " << m << " nodes");
    CHECK(*std::min_element(poly.begin(), poly.end()) == poly[0], "polygon starts at its smallest node");
    std::vector<Kq::Point_2> Q;
    std::size_t ups = 0;
    for(std::size_t k = 0; k < m; ++k)
    {
      CHECK(poly[k] < nn, "node index");
      Q.push_back(pt[poly[k]]);
      ++corner_count[poly[k]];
      CHECK(side_polygon.emplace(std::make_pair(poly[k], poly[(k + 1) % m]), f).second, "a polygon side appears twice");
    }
    for(std::size_t k = 0; k < m; ++k)
    {
      const Kq::Point_2& a = Q[(k + m - 1) % m];
      const Kq::Point_2& b = Q[k];
      const Kq::Point_2& c = Q[(k + 1) % m];
      const CGAL::Orientation o = CGAL::orientation(a, b, c);
      const std::size_t u = poly[k];
      const bool flat_allowed = flat_ok && u < nb && incident[u].empty() && o == CGAL::COLLINEAR
                                && CGAL::orientation(pt[ccw_prev(u)], pt[u], pt[ccw_next(u)]) == CGAL::COLLINEAR;
      CHECK(o == CGAL::LEFT_TURN || flat_allowed, "polygon " << f << " not strictly convex at node " << u);
      if(!upper(b - a) && upper(c - b)) ++ups;
    }
    CHECK(ups == 1, "polygon " << f << " winds " << ups << " times");
    const CGAL::Gmpq a2 = twice_area(Q);
    CHECK(a2 > 0, "polygon " << f << " area");
    area_sum += a2;
  }
  std::vector<Kq::Point_2> Bccw;
  for(std::size_t k = 0, i = 0; k < nb; ++k, i = ccw_next(i)) Bccw.push_back(pt[i]);
  CHECK(area_sum == twice_area(Bccw), "the polygons' areas do not sum exactly to the domain's");
  CHECK(side_polygon.size() == nb + 2 * E, "polygon sides: " << side_polygon.size() << " != " << nb + 2 * E);
  for(std::size_t i = 0; i < nb; ++i)
    CHECK(side_polygon.count(std::make_pair(i, ccw_next(i))) == 1, "border edge " << i << " not a polygon side");
  for(std::size_t e = 0; e < E; ++e)
  {
    const std::size_t u = dp.edges[e][0], v = dp.edges[e][1];
    const auto l = side_polygon.find(std::make_pair(u, v)), r = side_polygon.find(std::make_pair(v, u));
    CHECK(l != side_polygon.end() && r != side_polygon.end(), "edge " << e << " not a side of two polygons");
    CHECK(std::ptrdiff_t(l->second) == dp.edge_polygons[e][0] && std::ptrdiff_t(r->second) == dp.edge_polygons[e][1],
          "edge " << e << " left/right polygons");
  }
  const std::vector<std::vector<std::ptrdiff_t> > sides = I::polygon_side_edges(dp);
  CHECK(sides.size() == F, "polygon_side_edges size");
  for(std::size_t f = 0; f < F; ++f)
    for(std::size_t k = 0; k < dp.polygons[f].size(); ++k)
    {
      const std::size_t u = dp.polygons[f][k], v = dp.polygons[f][(k + 1) % dp.polygons[f].size()];
      const std::ptrdiff_t e = sides[f][k];
      if(e < 0) CHECK(u < nb && v == ccw_next(u), "polygon " << f << " side " << k << ": not a border edge");
      else CHECK((dp.edges[std::size_t(e)] == std::array<std::size_t, 2>{{ (std::min)(u, v), (std::max)(u, v) }}),
                 "polygon " << f << " side " << k << ": wrong edge");
    }
  CHECK(std::ptrdiff_t(nn) - std::ptrdiff_t(nb + E) + std::ptrdiff_t(F) == 1, "Euler: V - E + F != 1");
  for(std::size_t t = nb; t < nn; ++t) CHECK(corner_count[t] >= 3, "target " << t - nb << " is a corner of " << corner_count[t] << " polygons");

  // rotations: exactly the incident edges, counterclockwise
  for(std::size_t u = 0; u < nn; ++u)
  {
    const std::vector<std::size_t>& R = dp.rotation[u];
    std::vector<std::size_t> a = R, b = incident[u];
    std::sort(a.begin(), a.end()); std::sort(b.begin(), b.end());
    CHECK(a == b, "rotation of node " << u << " is not its set of edges");
    std::vector<Kq::Point_2> seq;
    if(u < nb) seq.push_back(pt[ccw_next(u)]);
    for(std::size_t e : R) seq.push_back(pt[dp.opposite(e, u)]);
    if(u < nb)
    {
      seq.push_back(pt[ccw_prev(u)]);
      for(std::size_t k = 0; k + 1 < seq.size(); ++k)
        CHECK(CGAL::orientation(pt[u], seq[k], seq[k + 1]) == CGAL::LEFT_TURN
              || (flat_ok && seq.size() == 2), "border node " << u << ": rotation not counterclockwise inside the domain");
    }
    else
    {
      CHECK(seq.size() >= 3, "target " << u - nb << " has " << seq.size() << " edges");
      std::size_t ups = 0;
      for(std::size_t k = 0; k < seq.size(); ++k)
      {
        const Kq::Point_2& p = seq[k];
        const Kq::Point_2& q = seq[(k + 1) % seq.size()];
        CHECK(CGAL::orientation(pt[u], p, q) == CGAL::LEFT_TURN, "target " << u - nb << ": rotation step not a left turn");
        if(!upper(p - pt[u]) && upper(q - pt[u])) ++ups;
      }
      CHECK(ups == 1, "target " << u - nb << ": rotation winds " << ups << " times");
    }
  }
  return EXIT_SUCCESS;
}

template <class K>
std::vector<typename K::Point_2> regular_polygon(int n, bool ccw = true)
{
  std::vector<typename K::Point_2> B;
  for(int i = 0; i < n; ++i)
  {
    const double a = 2 * CGAL_PI * i / n + 0.1;
    B.push_back(point<K>(std::cos(a), std::sin(a)));
  }
  if(!ccw) std::reverse(B.begin(), B.end());
  return B;
}

template <class K>
std::vector<typename K::Point_2> square(double h = 1)
{
  return { point<K>(-h, -h), point<K>(h, -h), point<K>(h, h), point<K>(-h, h) };
}

// seeded uniform targets in the disk of radius r
template <class K>
std::vector<typename K::Point_2> random_targets(std::size_t nt, double r, unsigned seed)
{
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> U(-r, r);
  std::vector<typename K::Point_2> T;
  for(std::size_t guard = 0; T.size() < nt && guard < 100 * nt + 100; ++guard)
  {
    const double x = U(g), y = U(g);
    if(x * x + y * y < r * r) T.push_back(point<K>(x, y));
  }
  return T;
}

// Places k path vertices on every interior edge and checks the guarantees independently.
template <class K>
int check_placement(const std::vector<typename K::Point_2>& border, const std::vector<typename K::Point_2>& targets,
                    const I::Domain_partition& dp, unsigned seed, std::size_t& collinear, std::size_t& off_line)
{
  typedef typename K::Point_2 P;
  constexpr bool exact = !std::is_floating_point<typename K::FT>::value;
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> U(0, 1);
  const std::size_t nb = border.size();
  auto qpt = [&](std::size_t n) { return n < nb ? qp(border[n]) : qp(targets[n - nb]); };
  for(std::size_t e = 0; e < dp.edges.size(); ++e)
  {
    const std::size_t k = 1 + (e * 7 + seed) % 20;
    std::vector<double> fr(k);
    for(double& f : fr) f = U(g);
    if(e % 3 == 1) { fr[0] = 0; fr[k - 1] = 1; if(k > 2) fr[1] = fr[0]; } // repeated and end fractions
    std::sort(fr.begin(), fr.end());
    std::vector<P> pos;
    std::vector<CGAL::Orientation> sides;
    CHECK(I::place_path_vertices(dp, border, targets, e, fr, pos, &sides) == PE::OK, "edge " << e);
    CHECK(pos.size() == k && sides.size() == k, "sizes");
    const Kq::Point_2 a = qpt(dp.edges[e][0]), b = qpt(dp.edges[e][1]);
    const bool x_major = CGAL::abs(b.x() - a.x()) >= CGAL::abs(b.y() - a.y());
    const CGAL::Gmpq d = x_major ? b.x() - a.x() : b.y() - a.y();
    std::vector<Kq::Point_2> L, R;
    for(std::size_t n : dp.polygons[std::size_t(dp.edge_polygons[e][0])]) L.push_back(qpt(n));
    for(std::size_t n : dp.polygons[std::size_t(dp.edge_polygons[e][1])]) R.push_back(qpt(n));
    CGAL::Gmpq last = x_major ? a.x() : a.y();
    for(std::size_t i = 0; i < k; ++i)
    {
      const Kq::Point_2 p = qp(pos[i]);
      const CGAL::Gmpq c = x_major ? p.x() : p.y();
      CHECK(d > 0 ? c > last : c < last, "edge " << e << " vertex " << i << ": not strictly monotone along the segment");
      last = c;
      const CGAL::Orientation s = CGAL::orientation(a, b, p);
      CHECK(s == sides[i], "reported side");
      if(s == CGAL::COLLINEAR) ++collinear;
      else
      {
        ++off_line;
        CHECK(strictly_inside(s == CGAL::LEFT_TURN ? L : R, p), "edge " << e << " vertex " << i << " outside its polygon");
      }
      if(exact)
      {
        CHECK(s == CGAL::COLLINEAR, "exact number type: not on the segment");
        // fractions strictly increasing in (0, 1): the exact point pa + t (pb - pa)
        bool strict = true;
        for(std::size_t j = 0; j < k; ++j) if(!(fr[j] > 0 && fr[j] < 1 && (j == 0 || fr[j] > fr[j - 1]))) strict = false;
        if(strict)
        {
          const CGAL::Gmpq t(fr[i]);
          CHECK(p == Kq::Point_2(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y())), "exact position");
        }
      }
    }
    const CGAL::Gmpq end = x_major ? b.x() : b.y();
    CHECK(d > 0 ? end > last : end < last, "edge " << e << ": last vertex not before the end");
  }
  return EXIT_SUCCESS;
}

} // namespace

// Regular polygons (4..2000 sides) and an axis-aligned square with 0, 1, 3, 10, 50 seeded targets,
// counterclockwise and clockwise; path vertices on every edge.
PE_TEST_GROUP(domain_partition)
{
  (void)data_dir;
  std::size_t total_collinear = 0, total_off = 0;
  for(int n : { 4, 5, 7, 16, 100, 2000 })
    for(std::size_t nt : { std::size_t(0), std::size_t(1), std::size_t(3), std::size_t(10), std::size_t(50) })
      for(bool ccw : { true, false })
      {
        std::size_t sum_edges = 0, sum_polys = 0, runs = 0;
        for(unsigned seed = 0; seed < (nt >= 10 && n >= 100 ? 3u : 5u); ++seed)
        {
          const std::vector<Epick::Point_2> B = regular_polygon<Epick>(n, ccw);
          const std::vector<Epick::Point_2> T = random_targets<Epick>(nt, 0.9 * std::cos(CGAL_PI / n), seed + 100 * n);
          I::Domain_partition dp;
          CHECK(I::partition_domain(B, T, dp) == PE::OK, n << "-gon, " << nt << " targets");
          Stats st;
          RUN(check_partition(B, T, dp, ccw, st));
          if(nt == 0) CHECK(dp.polygons.size() == 1 && dp.edges.empty(), "no target: the domain is one polygon");
          if(nt == 1) CHECK(dp.edges.size() == 3, "one target: 3 edges (the fewest possible)");
          CHECK(dp.edges.size() >= (3 * nt + 1) / 2, "fewer edges than targets allow");
          if(ccw && seed == 0) RUN(check_placement<Epick>(B, T, dp, seed, total_collinear, total_off));
          sum_edges += st.edges; sum_polys += st.polygons; ++runs;
        }
        if(ccw)
          std::cout << "regular " << n << "-gon, " << nt << " targets: " << double(sum_edges) / runs
                    << " interior edges, " << double(sum_polys) / runs << " polygons (mean of " << runs
                    << " seeds; 0 edges between two border points)" << std::endl;
      }
  for(std::size_t nt : { 1, 3, 10, 50 })
  {
    const std::vector<Epick::Point_2> B = square<Epick>();
    const std::vector<Epick::Point_2> T = random_targets<Epick>(nt, 0.95, unsigned(nt));
    I::Domain_partition dp;
    CHECK(I::partition_domain(B, T, dp) == PE::OK, "square");
    Stats st;
    RUN(check_partition(B, T, dp, true, st));
    RUN(check_placement<Epick>(B, T, dp, 7, total_collinear, total_off));
    std::cout << "square, " << nt << " targets: " << st.edges << " interior edges, " << st.polygons << " polygons" << std::endl;
  }
  std::cout << "path vertices (double): " << total_collinear << " exactly on their segment, " << total_off
            << " off it, strictly inside the polygon on their side" << std::endl;

  // the other merge orders give valid partitions too (and, measured here, no fewer edges)
  for(I::Domain_merge_order order : { I::Domain_merge_order::SHORTEST_FIRST, I::Domain_merge_order::TRIANGULATION_ORDER })
  {
    const std::vector<Epick::Point_2> B = regular_polygon<Epick>(100);
    const std::vector<Epick::Point_2> T = random_targets<Epick>(50, 0.9, 5);
    I::Domain_partition dp, dl;
    I::Domain_partition_options opt;
    opt.order = order;
    CHECK(I::partition_domain(B, T, dp, opt) == PE::OK && I::partition_domain(B, T, dl) == PE::OK, "orders");
    Stats st;
    RUN(check_partition(B, T, dp, true, st));
    std::cout << "100-gon, 50 targets: " << (order == I::Domain_merge_order::SHORTEST_FIRST ? "shortest first " : "triangulation order ")
              << st.edges << " edges, longest first " << dl.edges.size() << std::endl;
  }
  return EXIT_SUCCESS;
}

// Targets nearly collinear, collinear, nearly on the border; flat border vertices.
PE_TEST_GROUP(domain_partition_degenerate)
{
  (void)data_dir;
  typedef Epick::Point_2 P;
  const std::vector<P> S = square<Epick>();
  const std::vector<std::vector<P> > cases = {
    { P(-0.5, 0), P(0, 1e-15), P(0.5, 0) },                       // nearly collinear
    { P(-0.5, 0), P(0, 0), P(0.5, 0) },                           // collinear
    { P(-0.5, 0), P(0, 0), P(0.5, 0), P(0.25, -1e-15), P(0, 1e-300) },
    { P(1 - 1e-15, 0.3), P(0.2, -1 + 1e-15), P(-1 + 1e-15, -1 + 1e-15), P(0, 0) }, // 1e-15 from the border
    { P(0.5, 0.5), P(0.5 + std::ldexp(1., -53), 0.5 + std::ldexp(1., -53)) }        // one ulp apart
  };
  for(std::size_t c = 0; c < cases.size(); ++c)
  {
    I::Domain_partition dp;
    CHECK(I::partition_domain(S, cases[c], dp) == PE::OK, "case " << c);
    Stats st;
    RUN(check_partition(S, cases[c], dp, true, st));
    std::size_t col = 0, off = 0;
    if(c + 1 < cases.size()) // the last case has an edge one ulp long: see domain_partition_errors
      RUN(check_placement<Epick>(S, cases[c], dp, unsigned(c), col, off));
    std::cout << "square, degenerate case " << c << ": " << st.edges << " interior edges" << std::endl;
  }
  // extreme magnitudes: a 16-gon and its targets scaled by 2^1000 and 2^-1000 (exactly)
  for(int e : { 1000, -1000 })
  {
    std::vector<P> B = regular_polygon<Epick>(16), T = random_targets<Epick>(10, 0.8, 9);
    for(P& p : B) p = P(std::ldexp(p.x(), e), std::ldexp(p.y(), e));
    for(P& p : T) p = P(std::ldexp(p.x(), e), std::ldexp(p.y(), e));
    I::Domain_partition dp, d1;
    CHECK(I::partition_domain(B, T, dp) == PE::OK, "scaled by 2^" << e);
    CHECK(I::partition_domain(regular_polygon<Epick>(16), random_targets<Epick>(10, 0.8, 9), d1) == PE::OK, "unscaled");
    CHECK(dp.edges == d1.edges && dp.polygons == d1.polygons, "a scaling by a power of two changes the partition");
    Stats st;
    RUN(check_partition(B, T, dp, true, st));
    std::size_t col = 0, off = 0;
    RUN(check_placement<Epick>(B, T, dp, 3, col, off));
  }
  // targets 1e-15 from a border edge of a 100-gon: the expected code decided independently
  {
    const std::vector<P> B = regular_polygon<Epick>(100);
    std::vector<Kq::Point_2> Bq;
    for(const P& p : B) Bq.push_back(qp(p));
    std::size_t inside = 0, outside = 0;
    for(std::size_t i = 0; i < 100; i += 7)
      for(double eps : { 1e-15, 0., -1e-15 })
      {
        const P& a = B[i];
        const P& b = B[(i + 1) % 100];
        const double mx = 0.5 * (a.x() + b.x()), my = 0.5 * (a.y() + b.y());
        const double r = std::sqrt(mx * mx + my * my);
        const P t(mx - eps * mx / r, my - eps * my / r);
        const bool in = strictly_inside(Bq, qp(t));
        I::Domain_partition dp;
        const PE::Error_code ec = I::partition_domain(B, std::vector<P>{ t, P(0, 0) }, dp);
        CHECK(ec == (in ? PE::OK : PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN), "edge " << i << " eps " << eps);
        if(in) { Stats st; RUN(check_partition(B, std::vector<P>{ t, P(0, 0) }, dp, true, st)); ++inside; }
        else ++outside;
      }
    std::cout << "targets near a 100-gon's border: " << inside << " inside, " << outside << " rejected" << std::endl;
    CHECK(inside > 0 && outside > 0, "both outcomes exercised");
  }
  // flat border vertices: a square with 4 points per side
  {
    std::vector<P> B;
    for(int k = 0; k < 4; ++k) B.push_back(P(-1 + 0.5 * k, -1));
    for(int k = 0; k < 4; ++k) B.push_back(P(1, -1 + 0.5 * k));
    for(int k = 0; k < 4; ++k) B.push_back(P(1 - 0.5 * k, 1));
    for(int k = 0; k < 4; ++k) B.push_back(P(-1, 1 - 0.5 * k));
    for(std::size_t nt : { 0, 1, 3, 10 })
    {
      const std::vector<P> T = random_targets<Epick>(nt, 0.9, unsigned(nt + 11));
      I::Domain_partition dp;
      CHECK(I::partition_domain(B, T, dp) == PE::ERROR_DEGENERATE_BORDER, "flat border vertices refused by default");
      I::Domain_partition_options opt;
      opt.allow_flat_border_vertices = true;
      CHECK(I::partition_domain(B, T, dp, opt) == PE::OK, "flat border vertices allowed");
      Stats st;
      RUN(check_partition(B, T, dp, true, st, true));
      std::vector<P> Bc(B.rbegin(), B.rend());
      CHECK(I::partition_domain(Bc, T, dp, opt) == PE::OK, "clockwise, flat");
      RUN(check_partition(Bc, T, dp, false, st, true));
      std::cout << "square with flat border vertices, " << nt << " targets: " << st.edges << " interior edges" << std::endl;
    }
  }
  return EXIT_SUCCESS;
}

// Every error code, and the output left unchanged on error.
PE_TEST_GROUP(domain_partition_errors)
{
  (void)data_dir;
  typedef Epick::Point_2 P;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::vector<P> S = square<Epick>(), none;
  I::Domain_partition dp;
  CHECK(I::partition_domain(S, std::vector<P>{ P(0.1, 0.2) }, dp) == PE::OK, "valid");
  const std::size_t edges_before = dp.edges.size();
  auto code = [&](const std::vector<P>& B, const std::vector<P>& T) { return I::partition_domain(B, T, dp); };
  CHECK(code({ P(-1, -1), P(1, -1), P(nan, 1), P(-1, 1) }, none) == PE::ERROR_NON_FINITE_COORDINATES, "NaN border");
  CHECK(code(S, { P(0, 0), P(inf, 0) }) == PE::ERROR_NON_FINITE_COORDINATES, "infinite target");
  CHECK(code(S, { P(0, -inf) }) == PE::ERROR_NON_FINITE_COORDINATES, "infinite target");
  CHECK(code({ P(0, 0), P(1, 0) }, none) == PE::ERROR_DEGENERATE_BORDER, "2 points");
  CHECK(code(none, none) == PE::ERROR_DEGENERATE_BORDER, "empty border");
  CHECK(code({ P(-1, -1), P(1, -1), P(1, -1), P(1, 1), P(-1, 1) }, none) == PE::ERROR_DEGENERATE_BORDER, "repeated point");
  CHECK(code({ P(0, 0), P(1, 1), P(2, 2), P(3, 3) }, none) == PE::ERROR_DEGENERATE_BORDER, "collinear points");
  CHECK(code({ P(-1, -1), P(0, -1), P(1, -1), P(1, 1), P(-1, 1) }, none) == PE::ERROR_DEGENERATE_BORDER, "flat vertex");
  CHECK(code({ P(-1, -1), P(1, -1), P(0, 0), P(1, 1), P(-1, 1) }, none) == PE::ERROR_NON_CONVEX_BORDER, "reflex vertex");
  CHECK(code({ P(-1, -1), P(1, -1), P(1, 1), P(2, 1), P(-1, 1) }, none) == PE::ERROR_NON_CONVEX_BORDER, "spike");
  {
    std::vector<P> star; // a pentagram: every turn left, winds twice
    for(int i = 0; i < 5; ++i) star.push_back(P(std::cos(4 * CGAL_PI * i / 5), std::sin(4 * CGAL_PI * i / 5)));
    CHECK(code(star, none) == PE::ERROR_NON_CONVEX_BORDER, "pentagram");
  }
  CHECK(code(S, { P(0, 0), P(2, 0) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "outside");
  CHECK(code(S, { P(0, 0), P(1, 0.5) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "on a border edge");
  CHECK(code(S, { P(1, 1) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "on a border point");
  CHECK(code(S, { P(-1, -1) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "on the first border point");
  CHECK(code(S, { P(-1, 0) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "on the last border edge");
  CHECK(code(S, { P(1 + 1e-15, 0) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "1e-15 outside");
  CHECK(code(S, { P(0.3, 0.2), P(0, 0), P(0.3, 0.2) }) == PE::ERROR_DUPLICATE_CONSTRAINT, "duplicate");
  CHECK(code(S, { P(0.3, 0.2), P(0.3, 0.2 + 1e-17) }) == PE::ERROR_DUPLICATE_CONSTRAINT, "duplicate after rounding");
  CHECK(dp.edges.size() == edges_before && dp.number_of_targets == 1, "output changed on error");

  // place_path_vertices: wrong parameters and impossible placements
  std::vector<P> pos;
  CHECK(I::place_path_vertices(dp, S, std::vector<P>{ P(0.1, 0.2) }, dp.edges.size(), std::vector<double>{ 0.5 }, pos) == PE::ERROR_WRONG_PARAMETER, "edge index");
  CHECK(I::place_path_vertices(dp, S, std::vector<P>{ P(0.1, 0.2) }, 0, std::vector<double>{ 0.6, 0.5 }, pos) == PE::ERROR_WRONG_PARAMETER, "decreasing fractions");
  CHECK(I::place_path_vertices(dp, S, std::vector<P>{ P(0.1, 0.2) }, 0, std::vector<double>{ 1.5 }, pos) == PE::ERROR_WRONG_PARAMETER, "fraction > 1");
  CHECK(I::place_path_vertices(dp, S, std::vector<P>{ P(0.1, 0.2) }, 0, std::vector<double>{ nan }, pos) == PE::ERROR_WRONG_PARAMETER, "NaN fraction");
  CHECK(I::place_path_vertices(dp, S, none, 0, std::vector<double>{ 0.5 }, pos) == PE::ERROR_WRONG_PARAMETER, "other targets");
  {
    // two targets 1 and 2 ulps apart (diagonally): no double between them for 1, resp. 2 vertices
    for(int ulps : { 1, 2 })
    {
      const double u = std::ldexp(1., -53);
      const std::vector<P> T = { P(0.5, 0.5), P(0.5 + ulps * u, 0.5 + ulps * u) };
      CHECK(I::partition_domain(S, T, dp) == PE::OK, "close targets");
      std::size_t e = dp.edges.size();
      for(std::size_t i = 0; i < dp.edges.size(); ++i) if(dp.edges[i][0] == 4 && dp.edges[i][1] == 5) e = i;
      CHECK(e < dp.edges.size(), "the short edge is kept (a target keeps 3 edges)");
      std::vector<CGAL::Orientation> sides;
      const PE::Error_code one = I::place_path_vertices(dp, S, T, e, std::vector<double>{ 0.5 }, pos, &sides);
      CHECK(one == (ulps == 1 ? PE::ERROR_PATH_TRACING_FAILED : PE::OK), ulps << " ulps, 1 vertex");
      if(ulps == 2)
      {
        CHECK(same_bits(pos[0].x(), 0.5 + u) && same_bits(pos[0].y(), 0.5 + u) && sides[0] == CGAL::COLLINEAR, "the one double between");
        CHECK(I::place_path_vertices(dp, S, T, e, std::vector<double>{ 0.4, 0.6 }, pos) == PE::ERROR_PATH_TRACING_FAILED, "2 vertices");
      }
    }
  }
  return EXIT_SUCCESS;
}

// Exact number types: Gmpq (rational targets included) and Gmpfr; bit-exact placements in double.
PE_TEST_GROUP(domain_partition_exact)
{
  (void)data_dir;
  {
    typedef Kq::Point_2 P;
    std::vector<P> B = regular_polygon<Kq>(7);
    std::vector<P> T = random_targets<Kq>(10, 0.8, 3);
    T.push_back(P(CGAL::Gmpq(1, 3), CGAL::Gmpq(-1, 7)));
    T.push_back(P(CGAL::Gmpq(1, 3) + CGAL::Gmpq(1, 1000000007), CGAL::Gmpq(-1, 7))); // very close, not dyadic
    I::Domain_partition dp;
    CHECK(I::partition_domain(B, T, dp) == PE::OK, "Gmpq");
    Stats st;
    RUN(check_partition(B, T, dp, true, st));
    std::size_t col = 0, off = 0;
    RUN(check_placement<Kq>(B, T, dp, 1, col, off));
    CHECK(off == 0, "Gmpq: every path vertex on its segment");
    // the same doubles give the same partition in double and in Gmpq
    const std::vector<Epick::Point_2> Bd = regular_polygon<Epick>(7);
    const std::vector<Epick::Point_2> Td = random_targets<Epick>(10, 0.8, 3);
    I::Domain_partition dd, dq;
    CHECK(I::partition_domain(Bd, Td, dd) == PE::OK, "double");
    CHECK(I::partition_domain(B, std::vector<P>(T.begin(), T.begin() + 10), dq) == PE::OK, "Gmpq");
    CHECK(dd.edges == dq.edges && dd.polygons == dq.polygons, "double and Gmpq partitions differ");
    // beyond double range: the same partition after a scaling by 2^5000 (and 2^-5000)
    for(long e : { 5000L, -5000L })
    {
      std::vector<P> Bs, Ts;
      for(const Epick::Point_2& p : Bd) Bs.push_back(P(scaled_ft<CGAL::Gmpq>(p.x(), e), scaled_ft<CGAL::Gmpq>(p.y(), e)));
      for(const Epick::Point_2& p : Td) Ts.push_back(P(scaled_ft<CGAL::Gmpq>(p.x(), e), scaled_ft<CGAL::Gmpq>(p.y(), e)));
      I::Domain_partition ds;
      CHECK(I::partition_domain(Bs, Ts, ds) == PE::OK, "Gmpq scaled by 2^" << e);
      CHECK(ds.edges == dq.edges && ds.polygons == dq.polygons, "scaling by 2^" << e << " changes the partition");
      Stats ss;
      RUN(check_partition(Bs, Ts, ds, true, ss));
      std::size_t c2 = 0, o2 = 0;
      RUN(check_placement<Kq>(Bs, Ts, ds, 4, c2, o2));
    }
    std::cout << "Gmpq 7-gon, 12 targets: " << st.edges << " interior edges, " << col << " path vertices on their segments" << std::endl;
    CHECK(I::partition_domain(B, std::vector<P>{ T[0], P(CGAL::Gmpq(2), CGAL::Gmpq(0)) }, dp) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "Gmpq outside");
    CHECK(I::partition_domain(B, std::vector<P>{ T[10], T[0], T[10] }, dp) == PE::ERROR_DUPLICATE_CONSTRAINT, "Gmpq duplicate");
    // a target exactly on a border edge, with rational coordinates
    const P mid((B[2].x() + B[3].x()) / 2, (B[2].y() + B[3].y()) / 2);
    CHECK(I::partition_domain(B, std::vector<P>{ mid }, dp) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "Gmpq on the border");
  }
  {
    typedef Kfr::Point_2 P;
    const std::vector<P> B = square<Kfr>();
    const std::vector<P> T = random_targets<Kfr>(5, 0.9, 4);
    I::Domain_partition dp;
    CHECK(I::partition_domain(B, T, dp) == PE::OK, "Gmpfr");
    Stats st;
    RUN(check_partition(B, T, dp, true, st));
    std::size_t col = 0, off = 0;
    RUN(check_placement<Kfr>(B, T, dp, 2, col, off));
    CHECK(off == 0, "Gmpfr: every path vertex on its segment (exact dyadic values)");
    CHECK(I::partition_domain(B, std::vector<P>{ point<Kfr>(1, 0) }, dp) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "Gmpfr on the border");
    std::cout << "Gmpfr square, 5 targets: " << st.edges << " interior edges" << std::endl;
  }
  {
    // double, bit-exact: one target at the center of a square, paths along the diagonals
    typedef Epick::Point_2 P;
    const std::vector<P> S = square<Epick>();
    const std::vector<P> T = { P(0, 0) };
    I::Domain_partition dp;
    CHECK(I::partition_domain(S, T, dp) == PE::OK, "square + center");
    CHECK(dp.edges.size() == 4, "4 edges: dropping one would leave a flat angle at the center");
    for(std::size_t e = 0; e < 4; ++e)
    {
      const std::size_t corner = dp.edges[e][0]; // border node first (smaller index), then the target
      std::vector<P> pos;
      std::vector<CGAL::Orientation> sides;
      CHECK(I::place_path_vertices(dp, S, T, e, std::vector<double>{ 0.25, 0.5, 0.75 }, pos, &sides) == PE::OK, "diagonal");
      for(int i = 0; i < 3; ++i)
      {
        const double f = 1 - 0.25 * (i + 1);
        CHECK(same_bits(pos[i].x(), f * S[corner].x()) && same_bits(pos[i].y(), f * S[corner].y()), "bit-exact diagonal point");
        CHECK(sides[i] == CGAL::COLLINEAR, "on the diagonal");
      }
      // repeated fractions (zero-length 3D edges) and the ends: blended, still strictly inside
      CHECK(I::place_path_vertices(dp, S, T, e, std::vector<double>{ 0, 0, 0.5, 0.5, 1 }, pos, &sides) == PE::OK, "blended");
      for(int i = 0; i < 5; ++i) CHECK(sides[i] == CGAL::COLLINEAR, "blended on the diagonal");
      CHECK(I::place_path_vertices(dp, S, T, e, std::vector<double>(), pos) == PE::OK && pos.empty(), "no vertex");
    }
  }
  return EXIT_SUCCESS;
}

// ---- non-convex simple borders and weakly self-overlapping (immersed) borders ----------------------

namespace {

// exact point-in-polygon of the test (CGAL's, on rational points)
template <class P>
CGAL::Bounded_side exact_side(const std::vector<P>& border, const P& q)
{
  std::vector<Kq::Point_2> B;
  for(const P& p : border) B.push_back(qp(p));
  return CGAL::bounded_side_2(B.begin(), B.end(), qp(q), Kq());
}

// seeded targets strictly inside a simple polygon (rejection in its bounding box, exact test)
template <class K>
std::vector<typename K::Point_2> random_targets_in(const std::vector<typename K::Point_2>& border, std::size_t nt, unsigned seed)
{
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for(const auto& p : border)
  {
    x0 = (std::min)(x0, CGAL::to_double(p.x())); x1 = (std::max)(x1, CGAL::to_double(p.x()));
    y0 = (std::min)(y0, CGAL::to_double(p.y())); y1 = (std::max)(y1, CGAL::to_double(p.y()));
  }
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> X(x0, x1), Y(y0, y1);
  std::vector<typename K::Point_2> T;
  for(std::size_t guard = 0; T.size() < nt && guard < 1000 * nt + 100; ++guard)
  {
    const typename K::Point_2 p = point<K>(X(g), Y(g));
    if(exact_side(border, p) == CGAL::ON_BOUNDED_SIDE) T.push_back(p);
  }
  return T;
}

template <class K>
std::vector<typename K::Point_2> l_shape()
{
  return { point<K>(0, 0), point<K>(2, 0), point<K>(2, 1), point<K>(1, 1), point<K>(1, 2), point<K>(0, 2) };
}

// a star with `points` spikes: radii 1 and 0.4 alternating, counterclockwise
template <class K>
std::vector<typename K::Point_2> star(int points)
{
  std::vector<typename K::Point_2> B;
  for(int i = 0; i < 2 * points; ++i)
  {
    const double a = CGAL_PI * i / points + 0.05, r = (i % 2 == 0) ? 1 : 0.4;
    B.push_back(point<K>(r * std::cos(a), r * std::sin(a)));
  }
  return B;
}

// a comb of k teeth of width 1 and height 4 on a base of height 1, gaps of width 1, counterclockwise
template <class K>
std::vector<typename K::Point_2> comb(int k)
{
  std::vector<typename K::Point_2> B = { point<K>(0, 0), point<K>(2 * k - 1, 0) };
  for(int i = k - 1; i >= 0; --i)
  {
    B.push_back(point<K>(2 * i + 1, 4)); B.push_back(point<K>(2 * i, 4));
    if(i > 0) { B.push_back(point<K>(2 * i, 1)); B.push_back(point<K>(2 * i - 1, 1)); }
  }
  return B;
}


// a strip around the spiral r = 1 + pitch t / (2 pi), t in [0, turns 2 pi], of width w > pitch: it
// overlaps itself; counterclockwise
template <class K>
std::vector<typename K::Point_2> spiral(std::size_t per_side, double turns, double pitch, double w)
{
  std::vector<typename K::Point_2> P;
  for(std::size_t k = 0; k < per_side; ++k)
  {
    const double t = turns * 2 * CGAL_PI * double(k) / double(per_side - 1), r = 1 + pitch * t / (2 * CGAL_PI) + w;
    P.push_back(point<K>(r * std::cos(t), r * std::sin(t)));
  }
  for(std::size_t k = per_side; k-- > 0; )
  {
    const double t = turns * 2 * CGAL_PI * double(k) / double(per_side - 1), r = 1 + pitch * t / (2 * CGAL_PI);
    P.push_back(point<K>(r * std::cos(t), r * std::sin(t)));
  }
  return P;
}

// a piece of a doubly covered annulus: radii 1 and 2, angles 0 .. 2 pi (2m - 1) / m in m steps per turn;
// the points of angles a and a + 2 pi are the same doubles (different sheets)
template <class K>
std::vector<typename K::Point_2> double_annulus(int m)
{
  std::vector<typename K::Point_2> P;
  for(int k = 0; k < 2 * m; ++k)
  {
    const double a = 2 * CGAL_PI * (k % m) / m;
    P.push_back(point<K>(2 * std::cos(a), 2 * std::sin(a)));
  }
  for(int k = 2 * m; k-- > 0; )
  {
    const double a = 2 * CGAL_PI * (k % m) / m;
    P.push_back(point<K>(std::cos(a), std::sin(a)));
  }
  return P;
}

template <class P>
std::vector<P> reversed(const std::vector<P>& v) { return std::vector<P>(v.rbegin(), v.rend()); }

bool same_partition(const I::Domain_partition& a, const I::Domain_partition& b)
{
  return a.number_of_border_nodes == b.number_of_border_nodes && a.number_of_targets == b.number_of_targets
      && a.counterclockwise == b.counterclockwise && a.edges == b.edges && a.polygons == b.polygons
      && a.edge_polygons == b.edge_polygons && a.rotation == b.rotation;
}

// Every triangle in exactly one polygon: the triangles glued across the diagonals the partition
// dropped form one group per polygon, whose outer sides are that polygon's sides, with polygon size
// - 2 triangles and the polygon's exact area.
template <class P>
int check_triangles_in_polygons(const std::vector<P>& border, const std::vector<std::array<std::size_t, 3> >& tris,
                                const I::Domain_partition& dp)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> side_polygon;
  for(std::size_t f = 0; f < dp.polygons.size(); ++f)
    for(std::size_t k = 0; k < dp.polygons[f].size(); ++k)
      side_polygon[std::make_pair(dp.polygons[f][k], dp.polygons[f][(k + 1) % dp.polygons[f].size()])] = f;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> tri_of_side;
  for(std::size_t t = 0; t < tris.size(); ++t)
    for(int i = 0; i < 3; ++i) tri_of_side[std::make_pair(tris[t][i], tris[t][(i + 1) % 3])] = t;
  std::vector<std::size_t> group(tris.size(), std::size_t(-1));
  std::vector<std::ptrdiff_t> poly_of_group;
  for(std::size_t t0 = 0; t0 < tris.size(); ++t0)
  {
    if(group[t0] != std::size_t(-1)) continue;
    const std::size_t gid = poly_of_group.size();
    poly_of_group.push_back(-1);
    std::vector<std::size_t> stack(1, t0), members;
    group[t0] = gid;
    std::set<std::pair<std::size_t, std::size_t> > outer;
    while(!stack.empty())
    {
      const std::size_t t = stack.back(); stack.pop_back();
      members.push_back(t);
      for(int i = 0; i < 3; ++i)
      {
        const std::pair<std::size_t, std::size_t> s(tris[t][i], tris[t][(i + 1) % 3]);
        const auto ps = side_polygon.find(s);
        if(ps != side_polygon.end())
        {
          CHECK(poly_of_group[gid] < 0 || poly_of_group[gid] == std::ptrdiff_t(ps->second), "a triangle group touches two polygons from inside");
          poly_of_group[gid] = std::ptrdiff_t(ps->second);
          outer.insert(s);
          continue;
        }
        const auto o = tri_of_side.find(std::make_pair(s.second, s.first));
        CHECK(o != tri_of_side.end(), "a dropped side has no triangle behind it");
        if(group[o->second] == std::size_t(-1)) { group[o->second] = gid; stack.push_back(o->second); }
        CHECK(group[o->second] == gid, "groups");
      }
    }
    CHECK(poly_of_group[gid] >= 0, "a triangle group has no polygon side");
    const std::vector<std::size_t>& poly = dp.polygons[std::size_t(poly_of_group[gid])];
    CHECK(members.size() + 2 == poly.size(), "polygon with " << poly.size() << " corners holds " << members.size() << " triangles");
    CHECK(outer.size() == poly.size(), "the group's outer sides are not the polygon's sides");
    CGAL::Gmpq a(0), b(0);
    for(std::size_t t : members)
    {
      std::vector<Kq::Point_2> T;
      for(int i = 0; i < 3; ++i) T.push_back(qp(border[tris[t][i]]));
      a += twice_area(T);
    }
    std::vector<Kq::Point_2> Q;
    for(std::size_t n : poly) Q.push_back(qp(border[n]));
    CHECK(a == twice_area(Q), "triangle areas != polygon area");
  }
  std::set<std::ptrdiff_t> used(poly_of_group.begin(), poly_of_group.end());
  CHECK(used.size() == poly_of_group.size() && used.size() == dp.polygons.size(), "not one triangle group per polygon");
  return EXIT_SUCCESS;
}

// Triangulates an immersed polygon, partitions it, checks everything; returns the partition.
template <class K>
int run_immersed(const std::vector<typename K::Point_2>& B, bool ccw, bool flat, const std::string& name,
                 I::Domain_partition& dp, std::vector<std::array<std::size_t, 3> >* triangles_out = nullptr)
{
  std::vector<std::array<std::size_t, 3> > tris;
  PE::Polygon_triangulation_report rep;
  CHECK(PE::triangulate_self_overlapping_polygon_2(B, std::back_inserter(tris), PE::parameters::polygon_report(&rep)) == PE::OK, name << ": triangulation");
  I::Domain_partition_options o;
  o.allow_flat_border_vertices = flat;
  const PE::Error_code ec = I::partition_immersed_domain(B, tris, dp, o);
  CHECK(ec == PE::OK, name << ": " << PE::get_error_name(ec));
  Stats st;
  RUN(check_partition(B, std::vector<typename K::Point_2>(), dp, ccw, st, flat, true));
  RUN(check_triangles_in_polygons(B, tris, dp));
  // path vertices on every interior edge (between two border nodes), in the two adjacent polygons
  std::size_t col = 0, off = 0;
  RUN(check_placement<K>(B, std::vector<typename K::Point_2>(), dp, 3, col, off));
  std::cout << name << " (" << nt_name<K>() << ", " << B.size() << " vertices, " << (rep.simple ? "simple" : "self-overlapping")
            << "): " << dp.edges.size() << " interior edges, " << dp.polygons.size() << " convex polygons" << std::endl;
  if(triangles_out) *triangles_out = tris;
  return EXIT_SUCCESS;
}

template <class K>
int run_simple(const std::vector<typename K::Point_2>& B, const std::vector<typename K::Point_2>& T, bool ccw, bool flat,
               const std::string& name, I::Domain_partition& dp)
{
  I::Domain_partition_options o;
  o.allow_non_convex_border = true;
  o.allow_flat_border_vertices = flat;
  const PE::Error_code ec = I::partition_domain(B, T, dp, o);
  CHECK(ec == PE::OK, name << ": " << PE::get_error_name(ec));
  Stats st;
  RUN(check_partition(B, T, dp, ccw, st, flat, true));
  // a reflex border node keeps an interior edge (no polygon can have a reflex corner)
  const std::size_t nb = B.size();
  for(std::size_t i = 0; i < nb; ++i)
  {
    const CGAL::Orientation o2 = CGAL::orientation(qp(B[(i + nb - 1) % nb]), qp(B[i]), qp(B[(i + 1) % nb]));
    if(o2 == (ccw ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN)) CHECK(!dp.rotation[i].empty(), name << ": reflex node " << i << " without edge");
  }
  // path vertices on every interior edge, chords between border nodes included
  std::size_t col = 0, off = 0;
  RUN(check_placement<K>(B, T, dp, 5, col, off));
  // without the option: refused as before
  I::Domain_partition other;
  o.allow_non_convex_border = false;
  CHECK(I::partition_domain(B, T, other, o) == PE::ERROR_NON_CONVEX_BORDER, name << ": accepted without the option");
  std::cout << name << " (" << nt_name<K>() << ", " << nb << " vertices, " << T.size() << " targets): " << st.edges
            << " interior edges (" << st.chords << " between border points), " << st.polygons << " polygons" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

// Simple non-convex borders (option allow_non_convex_border): L shape, 12-point star, Hilbert-curve
// outline of order 3 (flat vertices), comb; 0, 3 and 10 targets, both orientations; Gmpq on the L and
// the comb; convex borders give the same output with the option on.
PE_TEST_GROUP(domain_partition_non_convex)
{
  (void)data_dir;
  typedef Epick::Point_2 P;
  const std::vector<std::pair<std::string, std::vector<P> > > shapes = {
    { "L shape", l_shape<Epick>() }, { "star 12", star<Epick>(12) }, { "Hilbert outline 3", hilbert_outline(3) },
    { "comb 6", comb<Epick>(6) } };
  CHECK(shapes[2].second.size() == 256, "Hilbert outline: " << shapes[2].second.size() << " vertices");
  for(const auto& s : shapes)
  {
    const bool flat = s.first.compare(0, 7, "Hilbert") == 0;
    for(std::size_t nt : { std::size_t(0), std::size_t(3), std::size_t(10) })
      for(bool ccw : { true, false })
      {
        const std::vector<P> B = ccw ? s.second : reversed(s.second);
        const std::vector<P> T = random_targets_in<Epick>(B, nt, unsigned(17 * nt + B.size()));
        CHECK(T.size() == nt, "targets");
        I::Domain_partition dp;
        RUN(run_simple<Epick>(B, T, ccw, flat, s.first + (ccw ? "" : " clockwise"), dp));
        if(nt == 0) CHECK(std::all_of(dp.edges.begin(), dp.edges.end(), [&](const std::array<std::size_t, 2>& e) { return e[1] < B.size(); }), "no target");
        if(nt == 0 && s.first == "L shape") CHECK(dp.edges.size() == 1 && dp.polygons.size() == 2, "the L is two rectangles");
        if(flat)
        {
          // without flat vertices allowed: refused as degenerate
          I::Domain_partition_options o;
          o.allow_non_convex_border = true;
          CHECK(I::partition_domain(B, T, dp, o) == PE::ERROR_DEGENERATE_BORDER, "flat vertices without the option");
        }
      }
  }
  // the 10-target L and comb in Gmpq, with rational targets: the same partition as in double
  for(const std::vector<P>& Bd : { l_shape<Epick>(), comb<Epick>(6) })
  {
    const std::vector<P> Td = random_targets_in<Epick>(Bd, 10, 5);
    std::vector<Kq::Point_2> Bq, Tq;
    for(const P& p : Bd) Bq.push_back(qp(p));
    for(const P& p : Td) Tq.push_back(qp(p));
    I::Domain_partition dd, dq;
    RUN(run_simple<Epick>(Bd, Td, true, false, "double", dd));
    RUN(run_simple<Kq>(Bq, Tq, true, false, "Gmpq", dq));
    CHECK(same_partition(dd, dq), "double and Gmpq partitions differ");
    Tq.push_back(Kq::Point_2(CGAL::Gmpq(1, 3), CGAL::Gmpq(1, 7)));
    RUN(run_simple<Kq>(Bq, Tq, true, false, "Gmpq + a rational target", dq));
  }
  // convex borders: the same output with the option on
  for(int n : { 4, 7, 100 })
    for(std::size_t nt : { std::size_t(0), std::size_t(3), std::size_t(10) })
      for(bool ccw : { true, false })
      {
        const std::vector<P> B = regular_polygon<Epick>(n, ccw);
        const std::vector<P> T = random_targets<Epick>(nt, 0.9 * std::cos(CGAL_PI / n), unsigned(n + nt));
        I::Domain_partition off, on;
        I::Domain_partition_options o;
        CHECK(I::partition_domain(B, T, off, o) == PE::OK, "convex, option off");
        o.allow_non_convex_border = true;
        CHECK(I::partition_domain(B, T, on, o) == PE::OK, "convex, option on");
        CHECK(same_partition(off, on), "convex " << n << "-gon: the option changes the output");
      }
  {
    // a square with flat vertices (4 per side)
    std::vector<P> B;
    for(int i = 0; i < 4; ++i) B.push_back(P(i, 0));
    for(int i = 0; i < 4; ++i) B.push_back(P(4, i));
    for(int i = 0; i < 4; ++i) B.push_back(P(4 - i, 4));
    for(int i = 0; i < 4; ++i) B.push_back(P(0, 4 - i));
    const std::vector<P> T = { P(1.5, 2.5), P(3, 1) };
    I::Domain_partition off, on;
    I::Domain_partition_options o;
    o.allow_flat_border_vertices = true;
    CHECK(I::partition_domain(B, T, off, o) == PE::OK, "flat square, option off");
    o.allow_non_convex_border = true;
    CHECK(I::partition_domain(B, T, on, o) == PE::OK, "flat square, option on");
    CHECK(same_partition(off, on), "flat square: the option changes the output");
  }
  return EXIT_SUCCESS;
}

// Errors of the non-convex path: targets in a reflex notch, on the border, on a reflex vertex,
// duplicated; self-intersecting borders; flat vertices without their option; output unchanged.
PE_TEST_GROUP(domain_partition_non_convex_errors)
{
  (void)data_dir;
  typedef Epick::Point_2 P;
  I::Domain_partition_options o;
  o.allow_non_convex_border = true;
  const std::vector<P> L = l_shape<Epick>();
  I::Domain_partition dp;
  CHECK(I::partition_domain(L, std::vector<P>{ P(0.5, 0.5) }, dp, o) == PE::OK, "L");
  const I::Domain_partition before = dp;
  auto code = [&](const std::vector<P>& B, const std::vector<P>& T) { return I::partition_domain(B, T, dp, o); };
  CHECK(code(L, { P(0.5, 0.5), P(1.5, 1.5) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "target in the reflex notch");
  CHECK(code(L, { P(1.5, 1.5), P(1.5, 1.5) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "outside before duplicate");
  CHECK(code(L, { P(1, 1) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "target on the reflex vertex");
  CHECK(code(L, { P(1.5, 1) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "target on a border edge next to the notch");
  CHECK(code(L, { P(1, 1.5) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "target on the other notch edge");
  CHECK(code(L, { P(0, 0.5) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "target on an outer edge");
  CHECK(code(L, { P(3, 3) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "target far outside");
  CHECK(code(L, { P(0.5, 0.5), P(0.2, 1.5), P(0.5, 0.5) }) == PE::ERROR_DUPLICATE_CONSTRAINT, "duplicate targets");
  CHECK(code(L, { P(0.5, 1.0 + std::ldexp(1., -52)) }) == PE::OK, "one ulp inside near the notch edge's line");
  CHECK(code(comb<Epick>(4), { P(1.5, 2) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "target between two teeth");
  CHECK(code(star<Epick>(12), { P(0.9 * std::cos(CGAL_PI / 12 + 0.05), 0.9 * std::sin(CGAL_PI / 12 + 0.05)) }) == PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "target between two spikes");
  dp = before;
  // non-simple borders: not convex (the code for a non-simple border)
  CHECK(code({ P(0, 0), P(1, 0), P(0, 1), P(1, 1) }, {}) == PE::ERROR_NON_CONVEX_BORDER, "bowtie");
  CHECK(code({ P(0, 0), P(2, 0), P(2, 2), P(1, 2), P(1, -1), P(0, -1) }, {}) == PE::ERROR_NON_CONVEX_BORDER, "crossing edges");
  CHECK(code({ P(0, 0), P(2, 0), P(1, 1), P(2, 2), P(0, 2), P(1, 1) }, {}) == PE::ERROR_NON_CONVEX_BORDER, "touching itself at a vertex");
  CHECK(code({ P(0, 0), P(2, 0), P(2, 2), P(1, 0), P(0, 2) }, {}) == PE::ERROR_NON_CONVEX_BORDER, "a vertex on another edge");
  CHECK(code({ P(0, 0), P(2, 0), P(2, 1), P(3, 1), P(1, 1), P(0, 2) }, {}) == PE::ERROR_NON_CONVEX_BORDER, "a spike (overlapping edges)");
  {
    // winding twice around (every turn to the left, a pentagram-like double loop)
    std::vector<P> W;
    for(int i = 0; i < 11; ++i) W.push_back(P(std::cos(4 * CGAL_PI * i / 11 + 0.1), std::sin(4 * CGAL_PI * i / 11 + 0.1)));
    CHECK(code(W, {}) == PE::ERROR_NON_CONVEX_BORDER, "winding twice");
    std::vector<P> S;
    for(int i = 0; i < 5; ++i) S.push_back(P(std::cos(4 * CGAL_PI * i / 5 + 0.1), std::sin(4 * CGAL_PI * i / 5 + 0.1)));
    CHECK(code(S, {}) == PE::ERROR_NON_CONVEX_BORDER, "pentagram");
  }
  // flat vertices without allow_flat_border_vertices, degenerate borders
  CHECK(code({ P(0, 0), P(1, 0), P(2, 0), P(2, 1), P(1, 1), P(1, 2), P(0, 2) }, {}) == PE::ERROR_DEGENERATE_BORDER, "flat vertex");
  CHECK(code({ P(0, 0), P(2, 0), P(2, 1), P(1, 1), P(1, 1), P(1, 2), P(0, 2) }, {}) == PE::ERROR_DEGENERATE_BORDER, "repeated point");
  CHECK(code({ P(0, 0), P(1, 0) }, {}) == PE::ERROR_DEGENERATE_BORDER, "two points");
  CHECK(code({ P(0, 0), P(2, 0), P(2, 1), P(1, std::nan("")), P(1, 2), P(0, 2) }, {}) == PE::ERROR_NON_FINITE_COORDINATES, "NaN");
  CHECK(code(L, { P(0.5, std::numeric_limits<double>::infinity()) }) == PE::ERROR_NON_FINITE_COORDINATES, "infinite target");
  CHECK(same_partition(dp, before), "output changed on error");
  // without the option: the codes of the convex contract
  o.allow_non_convex_border = false;
  CHECK(code(L, {}) == PE::ERROR_NON_CONVEX_BORDER, "L without the option");
  CHECK(code({ P(0, 0), P(1, 0), P(0, 1), P(1, 1) }, {}) == PE::ERROR_NON_CONVEX_BORDER, "bowtie without the option");
  return EXIT_SUCCESS;
}

// Weakly self-overlapping borders: partition of the immersed disk given by
// triangulate_self_overlapping_polygon_2(): spiral strips winding twice, a doubly covered annulus piece
// (vertices at equal positions on two sheets), a rectilinear spiral with flat vertices, simple
// polygons; both orientations; Gmpq; errors on inconsistent triangles.
PE_TEST_GROUP(domain_partition_immersed)
{
  (void)data_dir;
  typedef Epick::Point_2 P;
  I::Domain_partition dp;
  for(bool ccw : { true, false })
  {
    const std::string o = ccw ? "" : " clockwise";
    const std::vector<P> sp = spiral<Epick>(30, 2.0, 0.3, 0.6);
    RUN(run_immersed<Epick>(ccw ? sp : reversed(sp), ccw, false, "spiral strip" + o, dp));
    const std::vector<P> big = spiral<Epick>(200, 3.0, 0.25, 0.5);
    RUN(run_immersed<Epick>(ccw ? big : reversed(big), ccw, false, "spiral strip 3 turns" + o, dp));
    const std::vector<P> da = double_annulus<Epick>(12);
    RUN(run_immersed<Epick>(ccw ? da : reversed(da), ccw, false, "doubly covered annulus piece" + o, dp));
    RUN(run_immersed<Epick>(ccw ? star<Epick>(12) : reversed(star<Epick>(12)), ccw, false, "star 12 (simple)" + o, dp));
    const std::vector<P> h = hilbert_outline(3);
    RUN(run_immersed<Epick>(ccw ? h : reversed(h), ccw, true, "Hilbert outline 3 (simple)" + o, dp));
  }
  {
    // equal positions on two sheets: some polygon corners coincide in the plane, never in one polygon
    const std::vector<P> da = double_annulus<Epick>(12);
    RUN(run_immersed<Epick>(da, true, false, "doubly covered annulus piece", dp));
    for(const std::vector<std::size_t>& poly : dp.polygons)
      for(std::size_t a = 0; a < poly.size(); ++a)
        for(std::size_t b = a + 1; b < poly.size(); ++b)
          CHECK(!(da[poly[a]] == da[poly[b]]), "two corners of one polygon coincide");
  }
  {
    // a rectilinear spiral strip with a vertex at every unit step: flat vertices (180 degrees) and
    // collinear vertices of total angle 540 degrees on the inner side
    std::vector<std::array<int, 2> > c = { {{ 0, 0 }} };
    const int dx[4] = { 1, 0, -1, 0 }, dy[4] = { 0, 1, 0, -1 };
    for(int s = 0; s < 8; ++s) c.push_back({{ c.back()[0] + 6 * dx[s % 4], c.back()[1] + 6 * dy[s % 4] }});
    // strip of half-width 1 around the centerline (right side forward, left side backward)
    std::vector<std::array<int, 2> > corners;
    const int m = int(c.size());
    for(int side : { 1, -1 })
      for(int j = 0; j < m; ++j)
      {
        const int k = side == 1 ? j : m - 1 - j;
        int ox = 0, oy = 0;
        if(k > 0) { ox += dy[(k - 1) % 4]; oy -= dx[(k - 1) % 4]; }
        if(k < m - 1) { ox += dy[k % 4]; oy -= dx[k % 4]; }
        if(k == 0 || k == m - 1) { ox *= 1; oy *= 1; }
        corners.push_back({{ c[k][0] + side * ox, c[k][1] + side * oy }});
      }
    std::vector<P> R;
    for(std::size_t k = 0; k < corners.size(); ++k)
    {
      const std::array<int, 2> a = corners[k], b = corners[(k + 1) % corners.size()];
      const int steps = (std::max)(std::abs(b[0] - a[0]), std::abs(b[1] - a[1]));
      for(int s = 0; s < steps; ++s) R.push_back(P(a[0] + (b[0] - a[0]) * s / steps, a[1] + (b[1] - a[1]) * s / steps));
    }
    std::vector<std::array<std::size_t, 3> > tris;
    RUN(run_immersed<Epick>(R, true, true, "rectilinear spiral strip", dp, &tris));
    I::Domain_partition_options no_flat;
    CHECK(I::partition_immersed_domain(R, tris, dp, no_flat) == PE::ERROR_DEGENERATE_BORDER, "flat vertices without their option");
  }
  {
    // Gmpq: the same partition as in double, from the same triangles
    const std::vector<P> sp = spiral<Epick>(20, 2.0, 0.3, 0.6);
    std::vector<Kq::Point_2> spq;
    for(const P& p : sp) spq.push_back(qp(p));
    I::Domain_partition dd, dq;
    std::vector<std::array<std::size_t, 3> > td, tq;
    RUN(run_immersed<Epick>(sp, true, false, "spiral strip 40", dd, &td));
    RUN(run_immersed<Kq>(spq, true, false, "spiral strip 40", dq, &tq));
    CHECK(td == tq, "double and Gmpq triangulations differ");
    CHECK(same_partition(dd, dq), "double and Gmpq partitions differ");
    const std::vector<Kq::Point_2> daq = double_annulus<Kq>(8);
    RUN(run_immersed<Kq>(daq, true, false, "doubly covered annulus piece", dq));
  }
  {
    // inconsistent triangles: wrong parameter, output unchanged
    const std::vector<P> sp = spiral<Epick>(12, 2.0, 0.3, 0.6);
    std::vector<std::array<std::size_t, 3> > tris;
    CHECK(PE::triangulate_self_overlapping_polygon_2(sp, std::back_inserter(tris)) == PE::OK, "spiral 24");
    CHECK(I::partition_immersed_domain(sp, tris, dp) == PE::OK, "spiral 24");
    const I::Domain_partition before = dp;
    auto code = [&](const std::vector<std::array<std::size_t, 3> >& t) { return I::partition_immersed_domain(sp, t, dp); };
    std::vector<std::array<std::size_t, 3> > t = tris;
    t.pop_back();
    CHECK(code(t) == PE::ERROR_WRONG_PARAMETER, "a triangle missing");
    t = tris; std::swap(t[3][0], t[3][1]);
    CHECK(code(t) == PE::ERROR_WRONG_PARAMETER, "a clockwise triangle");
    t = tris; t[2][1] = sp.size();
    CHECK(code(t) == PE::ERROR_WRONG_PARAMETER, "index out of range");
    t = tris; t[2][1] = t[2][0];
    CHECK(code(t) == PE::ERROR_WRONG_PARAMETER, "repeated index");
    t = tris; t.push_back(t[0]); t.erase(t.begin() + 1);
    CHECK(code(t) == PE::ERROR_WRONG_PARAMETER, "a repeated triangle");
    {
      // the triangles of another polygon with the same vertex count
      std::vector<P> other = sp;
      std::rotate(other.begin(), other.begin() + 1, other.end());
      CHECK(code(std::vector<std::array<std::size_t, 3> >(tris)) == PE::OK, "the right triangles");
      std::vector<std::array<std::size_t, 3> > to;
      CHECK(PE::triangulate_self_overlapping_polygon_2(other, std::back_inserter(to)) == PE::OK, "rotated spiral");
      CHECK(code(to) == PE::ERROR_WRONG_PARAMETER, "the triangles of the rotated polygon");
    }
    dp = before;
    std::vector<P> bad = sp;
    bad[3] = P(std::nan(""), 0);
    CHECK(I::partition_immersed_domain(bad, tris, dp) == PE::ERROR_NON_FINITE_COORDINATES, "NaN");
    bad = sp; bad[4] = bad[3];
    CHECK(I::partition_immersed_domain(bad, tris, dp) == PE::ERROR_DEGENERATE_BORDER, "repeated consecutive point");
    CHECK(I::partition_immersed_domain(std::vector<P>{ P(0, 0), P(1, 0) }, std::vector<std::array<std::size_t, 3> >(), dp) == PE::ERROR_DEGENERATE_BORDER, "two points");
    CHECK(same_partition(dp, before), "output changed on error");
  }
  return EXIT_SUCCESS;
}

// trace_paths on a partition of a non-convex border: a planar grid mesh of an L shape whose border
// vertices are the border nodes (flat ones included), 0 and 3 interior vertices as targets. The
// partitions have interior edges between two border nodes (from the reflex corner).
PE_TEST_GROUP(domain_partition_non_convex_tracing)
{
  (void)data_dir;
  typedef boost::graph_traits<Surface_mesh>::vertex_descriptor vertex_descriptor;
  typedef Epick::Point_2 P;
  const int n = 8; // grid steps per unit
  for(std::size_t nt : { std::size_t(0), std::size_t(3) })
  {
    Surface_mesh m;
    std::map<std::pair<int, int>, vertex_descriptor> grid;
    auto in_l = [&](int i, int j) { return i >= 0 && j >= 0 && i < 2 * n && j < 2 * n && (i < n || j < n); }; // cells
    auto vertex_at = [&](int i, int j) {
      const auto it = grid.find(std::make_pair(i, j));
      if(it != grid.end()) return it->second;
      const vertex_descriptor v = m.add_vertex(Epick::Point_3(double(i) / n, double(j) / n, 0));
      grid.emplace(std::make_pair(i, j), v);
      return v;
    };
    for(int j = 0; j < 2 * n; ++j)
      for(int i = 0; i < 2 * n; ++i)
      {
        if(!in_l(i, j)) continue;
        const vertex_descriptor a = vertex_at(i, j), b = vertex_at(i + 1, j), c = vertex_at(i + 1, j + 1), d = vertex_at(i, j + 1);
        CHECK(m.add_face(a, b, c) != Surface_mesh::null_face() && m.add_face(a, c, d) != Surface_mesh::null_face(), "grid face");
      }
    // border vertices counterclockwise (the faces' orientation): against the border halfedges
    boost::graph_traits<Surface_mesh>::halfedge_descriptor hb = Surface_mesh::null_halfedge();
    for(auto h : halfedges(m)) if(CGAL::is_border(h, m)) { hb = h; break; }
    std::vector<vertex_descriptor> nodes;
    for(auto h : CGAL::halfedges_around_face(hb, m)) nodes.push_back(source(h, m));
    std::reverse(nodes.begin(), nodes.end());
    std::vector<P> B, T;
    for(vertex_descriptor v : nodes) B.push_back(P(m.point(v).x(), m.point(v).y()));
    const std::array<std::array<int, 2>, 3> tv = {{ {{ n / 2, n / 2 }}, {{ 3 * n / 2, n / 2 }}, {{ n / 2, 3 * n / 2 }} }};
    for(std::size_t t = 0; t < nt; ++t)
    {
      nodes.push_back(grid.at(std::make_pair(tv[t][0], tv[t][1])));
      T.push_back(P(double(tv[t][0]) / n, double(tv[t][1]) / n));
    }
    I::Domain_partition dp;
    RUN(run_simple<Epick>(B, T, true, true, "L grid border", dp));
    std::size_t chords = 0;
    for(const std::array<std::size_t, 2>& e : dp.edges) if(e[1] < B.size()) ++chords;
    CHECK(chords >= 1 || nt > 0, "the L needs an edge between border nodes");
    std::vector<std::vector<vertex_descriptor> > paths;
    std::vector<I::Steiner_vertex<Surface_mesh> > steiner;
    const PE::Error_code ec = I::trace_paths(m, get(CGAL::vertex_point, m), nodes, dp.edges, dp.rotation, paths, steiner);
    CHECK(ec == PE::OK, "trace_paths: " << PE::get_error_name(ec));
    std::size_t patches = 0;
    CHECK(I::check_traced_paths(m, nodes, dp.edges, dp.rotation, paths, &patches) == PE::OK, "traced paths certificate");
    CHECK(patches == dp.polygons.size(), patches << " patches for " << dp.polygons.size() << " polygons");
    std::cout << "L grid (" << num_vertices(m) << " vertices, " << nt << " targets): " << dp.edges.size() << " paths ("
              << chords << " between border nodes), " << patches << " patches, " << steiner.size() << " Steiner vertices" << std::endl;
  }
  {
    // a rectangular grid strip (W x H cells) whose border goes onto a spiral strip polygon winding
    // twice (outer side = bottom row, inner side = top row, the caps = the short sides): the immersed
    // partition's rotation system traced on the planar mesh
    const int W = 39, H = 3;
    std::vector<P> S;
    const double turns = 2, pitch = 0.3, w = 0.6, tmax = turns * 2 * CGAL_PI;
    auto at = [&](double t, double f) { const double r = 1 + pitch * t / (2 * CGAL_PI) + w * f; return P(r * std::cos(t), r * std::sin(t)); };
    for(int k = 0; k <= W; ++k) S.push_back(at(tmax * k / W, 1));
    for(int k = 1; k < H; ++k) S.push_back(at(tmax, 1 - double(k) / H));
    for(int k = W; k >= 0; --k) S.push_back(at(tmax * k / W, 0));
    for(int k = 1; k < H; ++k) S.push_back(at(0, double(k) / H));
    Surface_mesh m;
    std::vector<vertex_descriptor> g((W + 1) * (H + 1));
    for(int j = 0; j <= H; ++j)
      for(int i = 0; i <= W; ++i) g[j * (W + 1) + i] = m.add_vertex(Epick::Point_3(i, j, 0));
    for(int j = 0; j < H; ++j)
      for(int i = 0; i < W; ++i)
      {
        const vertex_descriptor a = g[j * (W + 1) + i], b = g[j * (W + 1) + i + 1], c = g[(j + 1) * (W + 1) + i + 1], d = g[(j + 1) * (W + 1) + i];
        m.add_face(a, b, c); m.add_face(a, c, d);
      }
    std::vector<vertex_descriptor> nodes;
    for(int i = 0; i <= W; ++i) nodes.push_back(g[i]);
    for(int j = 1; j < H; ++j) nodes.push_back(g[j * (W + 1) + W]);
    for(int i = W; i >= 0; --i) nodes.push_back(g[H * (W + 1) + i]);
    for(int j = H - 1; j >= 1; --j) nodes.push_back(g[j * (W + 1)]);
    CHECK(nodes.size() == S.size(), "border sizes");
    I::Domain_partition dp;
    RUN(run_immersed<Epick>(S, true, true, "spiral strip for tracing", dp)); // the cap at angle 0 is flat (y = 0)
    std::vector<std::vector<vertex_descriptor> > paths;
    std::vector<I::Steiner_vertex<Surface_mesh> > steiner;
    const PE::Error_code ec = I::trace_paths(m, get(CGAL::vertex_point, m), nodes, dp.edges, dp.rotation, paths, steiner);
    CHECK(ec == PE::OK, "trace_paths on the immersed partition: " << PE::get_error_name(ec));
    std::size_t patches = 0;
    CHECK(I::check_traced_paths(m, nodes, dp.edges, dp.rotation, paths, &patches) == PE::OK, "traced paths certificate");
    CHECK(patches == dp.polygons.size(), patches << " patches for " << dp.polygons.size() << " polygons");
    std::cout << "grid strip (" << num_vertices(m) << " vertices) onto a spiral strip: " << dp.edges.size() << " paths, "
              << patches << " patches, " << steiner.size() << " Steiner vertices" << std::endl;
  }
  return EXIT_SUCCESS;
}
