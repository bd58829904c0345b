// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Fuzz target of check_immersion(): the small maps of the check_embedding target, with rotation
// indices for some border vertices and, sometimes, a border polygon to compare with (one point
// moved by an ulp or not). The report must equal a brute-force certificate computed another way:
// the winding number of each interior one-ring by ray casting (signed crossings of the ray +x), and
// the full turns of each border fan as the number of times its faces sweep a fixed direction other
// than the package's, minus the times the border's angle alone sweeps it. A valid embedding must
// also be an immersion.

#ifndef PE_FUZZ_CHECK_IMMERSION_H
#define PE_FUZZ_CHECK_IMMERSION_H

#include "fuzz_util.h"
#include "check_embedding.h"

#include <CGAL/Progressive_embedding/check_immersion.h>

namespace pe_fuzz {

namespace immersion_oracle {

// A direction: from `from` to `to` (exact differences of doubles).
struct Dir { Qpoint from, to; };

// the exact sign of the cross product (dot product with `dot`) of two directions
inline int product_sign(const Dir& u, const Dir& v, bool dot)
{
  const double ux = u.to.x - u.from.x, uy = u.to.y - u.from.y, vx = v.to.x - v.from.x, vy = v.to.y - v.from.y;
  const double t1 = dot ? ux * vx : ux * vy, t2 = dot ? -uy * vy : uy * vx, e = t1 - t2;
  const double scale = std::abs(t1) + std::abs(t2);
  if(std::isfinite(e) && std::isfinite(scale) && scale > 1e-280 && std::abs(e) > 1e-14 * scale) return e > 0 ? 1 : -1;
  // ux vx + uy vy = ux vx - (-uy) vy: negation is exact
  const int s = dot ? exact_in_double_sign(u.from.x, u.to.x, v.from.x, v.to.x, -u.from.y, -u.to.y, v.from.y, v.to.y)
                    : exact_in_double_sign(u.from.x, u.to.x, v.from.y, v.to.y, u.from.y, u.to.y, v.from.x, v.to.x);
  if(s != 2) return s;
  const Q qux = Q(u.to.x) - Q(u.from.x), quy = Q(u.to.y) - Q(u.from.y), qvx = Q(v.to.x) - Q(v.from.x), qvy = Q(v.to.y) - Q(v.from.y);
  const Q q = dot ? qux * qvx + quy * qvy : qux * qvy - quy * qvx;
  return int(q.sign());
}
inline int cross_sign(const Dir& u, const Dir& v) { return product_sign(u, v, false); }
inline int dot_sign(const Dir& u, const Dir& v) { return product_sign(u, v, true); }

// the direction d lies in the counterclockwise sweep (u, w], of angle in (0, pi)
inline bool in_sweep(const Dir& u, const Dir& w, const Dir& d)
{
  const int cw = cross_sign(d, w);
  return cross_sign(u, d) > 0 && (cw > 0 || (cw == 0 && dot_sign(d, w) > 0));
}

// the direction d lies in the counterclockwise sweep (u, u + theta], theta in (0, 2 pi] the angle from u to w
inline bool in_wedge(const Dir& u, const Dir& w, const Dir& d)
{
  const int s = cross_sign(u, w);
  if(s == 0 && dot_sign(u, w) > 0) return true;                      // theta = 2 pi: every direction once
  if(s > 0) return in_sweep(u, w, d);                                // theta < pi
  if(s == 0)                                                         // theta = pi
  {
    const int cd = cross_sign(u, d);
    return cd > 0 || (cd == 0 && dot_sign(d, w) > 0);
  }
  return !in_sweep(w, u, d);                                         // theta > pi: the complement of (w, u]
}

} // namespace immersion_oracle

PE_FUZZ_TARGET_FUNCTION(check_immersion)
{
  using namespace immersion_oracle;
  Bytes b(data, size);
  Small_disk d;
  std::vector<double> xy;
  small_map(b, d, xy);
  const std::size_t nv = d.nv, nb = d.border.size(), nf = d.faces.size();
  // rotation indices: none, or per border vertex mostly 0, some 1 or 2, rarely a value never matched
  const int index_mode = b.u8() % 3;
  std::vector<int> index(nv, 0);
  if(index_mode != 0)
    for(std::size_t k = 0; k < nb; ++k)
    {
      const int t = b.u8();
      index[d.border[k]] = t < 180 ? 0 : (t < 230 ? 1 : (t < 250 ? 2 : (t < 253 ? -1 : 2000000)));
    }
  const int polygon_mode = b.u8() % 4; // 1: compare with the border polygon, 2: with one point moved by an ulp
  const std::size_t start = b.u8() % nb, moved = b.u8() % nb;

  Mesh m;
  std::vector<vertex_descriptor> V;
  build_mesh(d, m, V);
  Uv_map uv = m.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
  set_uv(V, xy, uv);
  auto rim = m.add_property_map<vertex_descriptor, int>("v:rotation_index", 0).first;
  for(std::size_t i = 0; i < nv; ++i) rim[V[i]] = index[i];

  // ---- the brute force ----
  std::vector<char> finite(nv);
  std::vector<Qpoint> P(nv);
  std::size_t non_finite = 0;
  for(std::size_t i = 0; i < nv; ++i)
  {
    finite[i] = std::isfinite(xy[2 * i]) && std::isfinite(xy[2 * i + 1]);
    if(!finite[i]) ++non_finite;
    P[i] = qpoint(xy[2 * i], xy[2 * i + 1]);
  }
  std::vector<int> fo(nf, 2); // 2: a non-finite corner
  std::size_t pos = 0, neg = 0, degenerate = 0;
  for(std::size_t f = 0; f < nf; ++f)
  {
    const Tri& t = d.faces[f];
    if(!finite[t[0]] || !finite[t[1]] || !finite[t[2]]) continue;
    fo[f] = orient(P[t[0]], P[t[1]], P[t[2]]);
    if(fo[f] > 0) ++pos; else if(fo[f] < 0) ++neg; else ++degenerate;
  }
  const bool clockwise = neg > pos;
  const int good = clockwise ? -1 : 1;
  // a clockwise map is checked as its mirror image
  if(clockwise) for(Qpoint& p : P) p.y = -p.y;
  std::vector<char> bad(nv, 0), on_border(nv, 0);
  for(std::size_t v : d.border) on_border[v] = 1;
  for(std::size_t f = 0; f < nf; ++f)
    if(fo[f] != good) for(std::size_t v : d.faces[f]) bad[v] = 1;

  // interior one-rings: winding number of the link around the vertex, by signed crossings of the ray +x
  std::size_t winding_errors = 0, unchecked = 0, max_winding = 0;
  std::vector<long> winding(nv, 0);
  for(const Tri& t : d.faces)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t c = t[k];
      const Qpoint &a = P[t[(k + 1) % 3]], &e = P[t[(k + 2) % 3]];
      if(on_border[c] || bad[c]) continue;
      if(a.y <= P[c].y && P[c].y < e.y && orient(a, e, P[c]) > 0) ++winding[c];
      else if(e.y <= P[c].y && P[c].y < a.y && orient(a, e, P[c]) < 0) --winding[c];
    }
  for(std::size_t v = 0; v < nv; ++v)
  {
    if(on_border[v]) continue;
    if(bad[v]) { ++unchecked; continue; }
    // the faces turn counterclockwise: the winding number is the number of turns, at least 1
    PE_FUZZ_CHECK(winding[v] >= 1, "brute force: an interior vertex with correct faces winds " << winding[v] << " times");
    max_winding = (std::max)(max_winding, std::size_t(winding[v]));
    if(winding[v] != 1) ++winding_errors;
  }
  // border fans: full turns = sweeps of a fixed direction by the faces minus sweeps by the border's angle
  std::size_t angle_errors = 0, max_turns = 0;
  for(std::size_t k = 0; k < nb; ++k)
  {
    const std::size_t c = d.border[k], n = d.border[(k + 1) % nb], p = d.border[(k + nb - 1) % nb];
    if(bad[c]) continue;
    // the fixed direction (-1, -3), not the package's (1, 0)
    const Dir dir{ Qpoint{ 0., 0. }, Qpoint{ -1., -3. } };
    long sweeps = 0;
    for(const Tri& t : d.faces)
      for(int j = 0; j < 3; ++j)
        if(t[j] == c && in_sweep(Dir{ P[c], P[t[(j + 1) % 3]] }, Dir{ P[c], P[t[(j + 2) % 3]] }, dir)) ++sweeps;
    const long rho = sweeps - (in_wedge(Dir{ P[c], P[n] }, Dir{ P[c], P[p] }, dir) ? 1 : 0);
    PE_FUZZ_CHECK(rho >= 0, "brute force: a border fan of correct faces turns less than the border's angle (" << rho << ")");
    const long want = index_mode ? index[c] : 0;
    if(rho != want || want < 0 || want > 1000000) ++angle_errors;
    if(rho > 0) max_turns = (std::max)(max_turns, std::size_t(rho));
  }
  const std::size_t flipped = clockwise ? pos : neg;

  // ---- the function ----
  PE::Immersion_report r;
  std::size_t mismatches = 0;
  bool border_finite = true;
  for(std::size_t v : d.border) border_finite = border_finite && finite[v];
  if(polygon_mode != 0 && border_finite)
  {
    std::vector<Point_2> B;
    for(std::size_t k = 0; k < nb; ++k) B.push_back(uv[V[d.border[(start + k) % nb]]]);
    if(polygon_mode == 2)
    {
      B[moved] = Point_2(std::nextafter(B[moved].x(), std::numeric_limits<double>::infinity()), B[moved].y());
      mismatches = 1;
    }
    r = index_mode ? PE::check_immersion(m, uv, V[d.border[start]], B, PE::parameters::vertex_rotation_index_map(rim))
                   : PE::check_immersion(m, uv, V[d.border[start]], B);
  }
  else
    r = index_mode ? PE::check_immersion(m, uv, PE::parameters::vertex_rotation_index_map(rim)) : PE::check_immersion(m, uv);

  PE_FUZZ_CHECK(r.status == PE::OK, "a disk refused: " << PE::get_error_name(r.status));
  PE_FUZZ_CHECK(r.faces == nf && r.vertices == nv && r.border_vertices == nb, "wrong counts");
  PE_FUZZ_CHECK(r.non_finite == non_finite, "non-finite " << r.non_finite << ", brute force " << non_finite);
  PE_FUZZ_CHECK(r.clockwise == clockwise, "clockwise " << r.clockwise << ", brute force " << clockwise);
  PE_FUZZ_CHECK(r.flipped == flipped, "flipped " << r.flipped << ", brute force " << flipped);
  PE_FUZZ_CHECK(r.degenerate == degenerate, "degenerate " << r.degenerate << ", brute force " << degenerate);
  PE_FUZZ_CHECK(r.unchecked_vertices == unchecked, "unchecked vertices " << r.unchecked_vertices << ", brute force " << unchecked);
  PE_FUZZ_CHECK(r.winding_errors == winding_errors, "winding errors " << r.winding_errors << ", brute force " << winding_errors);
  PE_FUZZ_CHECK(r.max_winding == max_winding, "max winding " << r.max_winding << ", brute force " << max_winding);
  PE_FUZZ_CHECK(r.border_angle_errors == angle_errors, "border angle errors " << r.border_angle_errors << ", brute force " << angle_errors);
  PE_FUZZ_CHECK(r.max_border_turns == max_turns, "max border turns " << r.max_border_turns << ", brute force " << max_turns);
  PE_FUZZ_CHECK(r.border_mismatches == mismatches, "border mismatches " << r.border_mismatches << ", expected " << mismatches);
  const bool immersion = flipped == 0 && degenerate == 0 && non_finite == 0 && winding_errors == 0 && unchecked == 0
                         && angle_errors == 0 && mismatches == 0;
  PE_FUZZ_CHECK(r.is_immersion() == immersion, "is_immersion() " << r.is_immersion() << ", brute force " << immersion);

  // an embedding is an immersion whose border fans turn by the border's angle alone
  if(index_mode == 0 && PE::check_embedding(m, uv).is_valid())
    PE_FUZZ_CHECK(r.is_immersion() || mismatches > 0, "a valid embedding that is not an immersion: " << r.summary());
  return 0;
}

} // namespace pe_fuzz

#endif // PE_FUZZ_CHECK_IMMERSION_H
