// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_KINETIC_TRIANGULATION_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_KINETIC_TRIANGULATION_H

// The homeomorphism class of a constrained map, chosen by a motion of the targets.
//
// A constrained map must send each constrained vertex to its target; which way the map winds around
// the other constrained vertices is free. Tracing the partition of the targets greedily on the mesh
// picks a class that, for targets in an order unrelated to the surface, winds a lot (tens of thousands
// of Steiner vertices for 50 random targets on a 4k-vertex disk). Here the class is the one of a
// motion from where a plain Tutte map puts the constrained vertices (`start`) to their targets (`end`),
// on straight lines or through waypoints: a triangulation of the start positions and the fixed border
// is kept valid while the points move, an edge being flipped whenever a point crosses it (a kinetic
// triangulation). The edges of the start triangulation are short curves on the mesh; each flip
// replaces one curve by another inside the quadrilateral of its two triangles (trace_kinetic.h). The
// end triangulation is a triangulation of the targets, merged into convex polygons as
// partition_domain() does.
//
//   bool kinetic_triangulation(border, start, end, max_flips, out)
//   bool kinetic_triangulation(border, waypoints, max_flips, out)
//     border: the fixed border points, counterclockwise, convex; start/end: per moving point, strictly
//     inside; or waypoints: the positions at successive times (start first, end last), each point moving
//     on a straight line from one to the next (permutation_braid_waypoints() gives such a motion). Doubles: the motion is simulated in floating point (event times are roots of quadratics);
//     the caller checks the end triangulation exactly, and the certificate decides the map anyway.
//     Nodes 0..nb-1 are the border points, nb.. the moving points. Returns false when the start
//     triangulation cannot be built (a point not strictly inside, two equal points), when an event
//     cannot be resolved, or after max_flips flips.
//     out.initial: the start triangulation, counterclockwise triangles; out.edges: its interior edges
//     (ids are the positions); out.flips: in time order, edge id, the old pair (a, b) and the new (c, d),
//     with the ids of the edges (c,a), (c,b), (d,b), (d,a) at that time (-1: a border side) - the
//     new edge leaves c between the first two counterclockwise and arrives at d between the last two;
//     out.final: the end triangulation, out.final_edge_id: per final triangle corner, the id of the
//     edge opposite it (-1: border side).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

struct Kinetic_flip
{
  std::size_t edge;              // the id of the flipped edge (kept by the new one)
  std::size_t a, b, c, d;        // (a, b) becomes (c, d); triangles (a, b, c) and (b, a, d) before
  std::ptrdiff_t ca, cb, db, da; // ids of the quadrilateral's sides (-1: border side)
};

struct Kinetic_triangulation
{
  std::vector<std::array<std::size_t, 3> > initial, final_triangles;
  std::vector<std::array<std::size_t, 2> > edges;          // the initial interior edges
  std::vector<Kinetic_flip> flips;
  std::vector<std::array<std::ptrdiff_t, 3> > final_edge_id; // per final triangle, opposite each corner
};

namespace kinetic_detail {

typedef std::array<double, 2> P2;

inline double orient(const P2& a, const P2& b, const P2& c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// The first time in (t0, 1] at which the orientation of three linearly moving points, a quadratic
// A + B t + C t^2 (positive at t0, up to rounding), reaches zero; infinity when it does not.
inline double first_zero(double A, double B, double C, double t0)
{
  const double inf = std::numeric_limits<double>::infinity();
  auto value = [&](double t) { return A + t * (B + t * C); };
  std::array<double, 2> roots{ { inf, inf } };
  const double scale = std::abs(A) + std::abs(B) + std::abs(C);
  if(!(scale > 0)) return inf;
  if(std::abs(C) <= 1e-14 * scale)
  {
    if(B != 0) roots[0] = -A / B;
  }
  else
  {
    const double disc = B * B - 4 * A * C;
    if(disc < 0) return inf;
    const double s = std::sqrt(disc);
    const double q = -0.5 * (B + (B >= 0 ? s : -s));
    roots[0] = q / C;
    roots[1] = q != 0 ? A / q : inf;
  }
  std::sort(roots.begin(), roots.end());
  for(double r : roots)
    if(r > t0 && r <= 1) return r;
  // rounding: negative already at t0 (an event at t0 missed by the roots) or at the end
  if(value(t0) < 0) return t0;
  return inf;
}

} // namespace kinetic_detail

inline bool kinetic_triangulation(const std::vector<std::array<double, 2> >& border,
                                  const std::vector<std::vector<std::array<double, 2> > >& waypoints,
                                  std::size_t max_flips, Kinetic_triangulation& out)
{
  using namespace kinetic_detail;
  out = Kinetic_triangulation();
  if(waypoints.size() < 2) return false;
  const std::vector<P2>& start = waypoints.front();
  const std::size_t nb = border.size(), nt = start.size(), nn = nb + nt;
  const std::ptrdiff_t none = -1;
  if(nb < 3) return false;
  for(const P2& p : border) if(!std::isfinite(p[0]) || !std::isfinite(p[1])) return false;
  for(const std::vector<P2>& w : waypoints)
  {
    if(w.size() != nt) return false;
    for(const P2& p : w) if(!std::isfinite(p[0]) || !std::isfinite(p[1])) return false;
  }
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  // strictly inside the (convex, counterclockwise) border, exactly, at every waypoint (and so on the
  // segments between them)
  for(const std::vector<P2>& w : waypoints)
    for(std::size_t i = 0; i < nt; ++i)
      for(std::size_t k = 0; k < nb; ++k)
      {
        const K::Point_2 a(border[k][0], border[k][1]), b(border[(k + 1) % nb][0], border[(k + 1) % nb][1]);
        if(CGAL::orientation(a, b, K::Point_2(w[i][0], w[i][1])) != CGAL::LEFT_TURN) return false;
      }

  // ---- the start triangulation: constrained Delaunay of the border and the start positions ----
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K> Vb;
  typedef CGAL::Triangulation_face_base_with_info_2<std::size_t, K> Fbb;
  typedef CGAL::Constrained_triangulation_face_base_2<K, Fbb> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag> CDT;
  auto pos0 = [&](std::size_t n) -> const P2& { return n < nb ? border[n] : start[n - nb]; };
  CDT cdt;
  {
    std::vector<std::pair<K::Point_2, std::size_t> > pts;
    for(std::size_t n = 0; n < nn; ++n) pts.emplace_back(K::Point_2(pos0(n)[0], pos0(n)[1]), n);
    cdt.insert(pts.begin(), pts.end());
  }
  if(cdt.number_of_vertices() != nn || cdt.dimension() != 2) return false;
  {
    std::vector<CDT::Vertex_handle> vh(nn);
    for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) vh[v->info()] = v;
    for(std::size_t i = 0; i < nb; ++i) cdt.insert_constraint(vh[i], vh[(i + 1) % nb]);
    if(cdt.number_of_vertices() != nn) return false;
  }
  // faces: tri[f] counterclockwise, nbr[f][i] across the edge opposite tri[f][i], eid[f][i] its id
  std::vector<std::array<std::size_t, 3> > tri;
  std::vector<std::array<std::ptrdiff_t, 3> > nbr, eid;
  {
    std::size_t nf = 0;
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) f->info() = nf++;
    tri.resize(nf); nbr.resize(nf); eid.assign(nf, std::array<std::ptrdiff_t, 3>{ { none, none, none } });
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    {
      const std::size_t id = f->info();
      for(int i = 0; i < 3; ++i)
      {
        tri[id][i] = f->vertex(i)->info();
        const auto g = f->neighbor(i);
        nbr[id][i] = (cdt.is_infinite(g) || f->is_constrained(i)) ? none : std::ptrdiff_t(g->info());
      }
    }
    // the border's constraints are the convex hull: no finite face lies outside it
    if(nf != 2 * nn - nb - 2) return false;
    for(std::size_t f = 0; f < nf; ++f)
      for(int i = 0; i < 3; ++i)
      {
        if(nbr[f][i] == none || eid[f][i] != none) continue;
        const std::size_t g = static_cast<std::size_t>(nbr[f][i]);
        const std::ptrdiff_t id = static_cast<std::ptrdiff_t>(out.edges.size());
        const std::size_t u = tri[f][(i + 1) % 3], v = tri[f][(i + 2) % 3];
        out.edges.push_back({ { u, v } });
        eid[f][i] = id;
        for(int j = 0; j < 3; ++j) if(nbr[g][j] == std::ptrdiff_t(f)) eid[g][j] = id;
      }
    out.initial = tri;
  }

  // ---- the motion: straight lines from each waypoint to the next ------------------------------
  auto corner = [&](std::size_t f, std::size_t v) { for(int i = 0; i < 3; ++i) if(tri[f][i] == v) return i; return -1; };
  for(std::size_t stage = 0; stage + 1 < waypoints.size(); ++stage)
  {
    const std::vector<P2>& start = waypoints[stage];
    const std::vector<P2>& end = waypoints[stage + 1];
    auto at = [&](std::size_t n, double t) -> P2 {
      if(n < nb) return border[n];
      const P2& p = start[n - nb];
      const P2& r = end[n - nb];
      return { { p[0] + t * (r[0] - p[0]), p[1] + t * (r[1] - p[1]) } };
    };
    auto vel = [&](std::size_t n) -> P2 {
      if(n < nb) return { { 0., 0. } };
      return { { end[n - nb][0] - start[n - nb][0], end[n - nb][1] - start[n - nb][1] } };
    };
    // the orientation of face f is A + B t + C t^2: its first zero after t0
    auto event_time = [&](std::size_t f, double t0) {
      const std::size_t a = tri[f][0], b = tri[f][1], c = tri[f][2];
      if(a < nb && b < nb && c < nb) return std::numeric_limits<double>::infinity();
      const P2 pa = at(a, 0), pb = at(b, 0), pc = at(c, 0), va = vel(a), vb = vel(b), vc = vel(c);
      const double ux = pb[0] - pa[0], uy = pb[1] - pa[1], wx = pc[0] - pa[0], wy = pc[1] - pa[1];
      const double dux = vb[0] - va[0], duy = vb[1] - va[1], dwx = vc[0] - va[0], dwy = vc[1] - va[1];
      const double A = ux * wy - uy * wx;
      const double B = ux * dwy + dux * wy - uy * dwx - duy * wx;
      const double C = dux * dwy - duy * dwx;
      return first_zero(A, B, C, t0);
    };
    typedef std::pair<double, std::pair<std::size_t, std::size_t> > Event; // time, (face, stamp)
    std::priority_queue<Event, std::vector<Event>, std::greater<Event> > q;
    std::vector<std::size_t> stamp(tri.size(), 0);
    auto schedule = [&](std::size_t f, double t0) {
      ++stamp[f];
      const double t = event_time(f, t0);
      if(t <= 1) q.push(Event(t, std::make_pair(f, stamp[f])));
    };
    for(std::size_t f = 0; f < tri.size(); ++f) schedule(f, 0.);
    while(!q.empty())
    {
      const Event ev = q.top(); q.pop();
      const std::size_t f = ev.second.first;
      if(ev.second.second != stamp[f]) continue;
      const double t = ev.first;
      if(out.flips.size() >= max_flips) return false;
      // the corner between the two others at t: opposite the longest side
      int m = 0;
      double longest = -1;
      for(int i = 0; i < 3; ++i)
      {
        const P2 u = at(tri[f][(i + 1) % 3], t), v = at(tri[f][(i + 2) % 3], t);
        const double l = (u[0] - v[0]) * (u[0] - v[0]) + (u[1] - v[1]) * (u[1] - v[1]);
        if(l > longest) { longest = l; m = i; }
      }
      if(nbr[f][m] == none) return false; // a point crossing the border: cannot happen for points inside
      const std::size_t g = static_cast<std::size_t>(nbr[f][m]);
      const std::size_t c = tri[f][m], a = tri[f][(m + 1) % 3], b = tri[f][(m + 2) % 3];
      const int ga = corner(g, a), gb = corner(g, b);
      if(ga < 0 || gb < 0) return false;
      const int gd = 3 - ga - gb;
      const std::size_t d = tri[g][gd];
      Kinetic_flip fl;
      fl.edge = static_cast<std::size_t>(eid[f][m]);
      fl.a = a; fl.b = b; fl.c = c; fl.d = d;
      fl.ca = eid[f][(m + 2) % 3]; // opposite b
      fl.cb = eid[f][(m + 1) % 3]; // opposite a
      fl.db = eid[g][ga];
      fl.da = eid[g][gb];
      const std::ptrdiff_t nfa = nbr[f][(m + 1) % 3], nfb = nbr[f][(m + 2) % 3], nga = nbr[g][ga], ngb = nbr[g][gb];
      // new faces: f = (a, d, c), g = (c, d, b)
      tri[f] = { { a, d, c } };
      nbr[f] = { { std::ptrdiff_t(g), nfb, ngb } };
      eid[f] = { { std::ptrdiff_t(fl.edge), fl.ca, fl.da } };
      tri[g] = { { c, d, b } };
      nbr[g] = { { nga, nfa, std::ptrdiff_t(f) } };
      eid[g] = { { fl.db, fl.cb, std::ptrdiff_t(fl.edge) } };
      auto relink = [&](std::ptrdiff_t h, std::size_t from, std::size_t to) {
        if(h == none) return;
        for(int i = 0; i < 3; ++i) if(nbr[static_cast<std::size_t>(h)][i] == std::ptrdiff_t(from)) nbr[static_cast<std::size_t>(h)][i] = std::ptrdiff_t(to);
      };
      relink(ngb, g, f); // (a, d) was g's, now f's
      relink(nfa, f, g); // (b, c) was f's, now g's
      out.flips.push_back(fl);
      schedule(f, t);
      schedule(g, t);
    }
    // at the waypoint, in floating point, every triangle counterclockwise (the caller checks the last exactly)
    for(const auto& tr : tri)
      if(!(orient(at(tr[0], 1), at(tr[1], 1), at(tr[2], 1)) > 0)) return false;
  }
  out.final_triangles = tri;
  out.final_edge_id = eid;
  return true;
}

inline bool kinetic_triangulation(const std::vector<std::array<double, 2> >& border,
                                  const std::vector<std::array<double, 2> >& start,
                                  const std::vector<std::array<double, 2> >& end,
                                  std::size_t max_flips, Kinetic_triangulation& out)
{
  return kinetic_triangulation(border, std::vector<std::vector<std::array<double, 2> > >{ start, end }, max_flips, out);
}

// The waypoints of a motion from `start` to `end` in the class of a positive permutation braid along the
// direction at angle `theta`: with u the coordinate along it and w across, the points first move to a
// band across the border's centre, each at a height w given by the rank of its start u and at its start
// u scaled (u order kept: no two points pass each other along u), then along the band to their end u
// scaled the same way (each pair whose u order is reversed passes once, the one that starts before the
// other below it: every crossing of one sign), then to their ends (u order kept). A random target
// order costs the straight-line motion crossings of both signs, whose curves grow exponentially with the
// flips (constrained_design_measurements.md). Empty when the border is degenerate.
inline std::vector<std::vector<std::array<double, 2> > >
permutation_braid_waypoints(const std::vector<std::array<double, 2> >& border,
                            const std::vector<std::array<double, 2> >& start,
                            const std::vector<std::array<double, 2> >& end, double theta)
{
  typedef std::array<double, 2> P2;
  const std::size_t nb = border.size(), nt = start.size();
  std::vector<std::vector<P2> > none;
  if(nb < 3 || end.size() != nt) return none;
  double cx = 0, cy = 0;
  for(const P2& p : border) { cx += p[0]; cy += p[1]; }
  cx /= double(nb); cy /= double(nb);
  // the largest disk about the centroid inside the (convex) border
  double r = std::numeric_limits<double>::infinity();
  for(std::size_t k = 0; k < nb; ++k)
  {
    const P2& a = border[k];
    const P2& b = border[(k + 1) % nb];
    const double ex = b[0] - a[0], ey = b[1] - a[1], l = std::sqrt(ex * ex + ey * ey);
    if(!(l > 0)) continue;
    r = (std::min)(r, std::abs((cx - a[0]) * ey - (cy - a[1]) * ex) / l);
  }
  if(!(r > 0) || !std::isfinite(r)) return none;
  const double ux = std::cos(theta), uy = std::sin(theta), wx = -uy, wy = ux;
  auto along = [&](const P2& p) { return (p[0] - cx) * ux + (p[1] - cy) * uy; };
  std::vector<std::size_t> order(nt);
  for(std::size_t i = 0; i < nt; ++i) order[i] = i;
  // two points at the same u at the start or the end would pass through each other on the way to
  // or from the band: no motion along this direction then (the start last: its order gives the heights)
  for(const std::vector<P2>* at : { &end, &start })
  {
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return along((*at)[a]) < along((*at)[b]); });
    for(std::size_t k = 1; k < nt; ++k)
      if(!(along((*at)[order[k - 1]]) < along((*at)[order[k]]))) return none;
  }
  // heights in [-r/4, r/4], u in [-0.8 r, 0.8 r]: inside the disk of radius 0.84 r
  std::vector<double> height(nt, 0.);
  for(std::size_t k = 0; k < nt; ++k) height[order[k]] = nt > 1 ? 0.5 * r * (double(k) / double(nt - 1) - 0.5) : 0.;
  double ms = 0, me = 0;
  for(std::size_t i = 0; i < nt; ++i)
  {
    ms = (std::max)(ms, std::abs(along(start[i])));
    me = (std::max)(me, std::abs(along(end[i])));
  }
  const double ss = ms > 0 ? 0.8 * r / ms : 0., se = me > 0 ? 0.8 * r / me : 0.;
  std::vector<P2> m1(nt), m2(nt);
  for(std::size_t i = 0; i < nt; ++i)
  {
    const double u1 = along(start[i]) * ss, u2 = along(end[i]) * se;
    m1[i] = { { cx + u1 * ux + height[i] * wx, cy + u1 * uy + height[i] * wy } };
    m2[i] = { { cx + u2 * ux + height[i] * wx, cy + u2 * uy + height[i] * wy } };
  }
  return { start, m1, m2, end };
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_KINETIC_TRIANGULATION_H
