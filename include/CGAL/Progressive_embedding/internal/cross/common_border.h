// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_COMMON_BORDER_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_COMMON_BORDER_H

// The borders of two disks placed on one unit square, matched by relative 3D arc length from a
// pair of matched border vertices (both at the corner (0, 0)). The square's other corners are the
// border vertices of the second disk (B) nearest to a quarter, a half and three quarters of its
// length, and those of the first (A) nearest to the relative lengths of B's corners; between corners
// each side is parametrized by arc length. Every border point then lies exactly on a side (one of its
// coordinates is 0 or 1) and both border polygons are the whole square: the images of A's vertices
// all lie in the closed domain of B's map. With border landmarks, A's border goes through their
// partners' points (common_square_border_through()); where an arc of A between them has no vertex for
// B's corner, all corners are chosen again among the places both borders have (corners_at_places()). B
// is mapped unchanged, so an interior edge of B joining two border vertices of one side would be flat in
// any map: B's corners are moved off the quarters where that is needed (separate_chords(); not after
// corners_at_places(), whose corners the caller's map of B on a split copy then handles).

#include <CGAL/Progressive_embedding/internal/length_3.h>
#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/tutte_border.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// The matched pair of border vertices when none is given: the first border vertex of A in the disk's vertex order
// (that of vertices(tm_a)) and the border vertex of B nearest to it in 3D; returned as positions on the two border
// cycles.
template <class MeshA, class VPMA, class MeshB, class VPMB>
std::pair<std::size_t, std::size_t> default_start_pair(const Indexed_disk<MeshA>& disk_a, VPMA vpm_a,
                                                       const Indexed_disk<MeshB>& disk_b, VPMB vpm_b)
{
  std::size_t first = 0;
  while(!disk_a.on_border[first]) ++first;
  const std::size_t start_a = std::size_t(std::find(disk_a.border.begin(), disk_a.border.end(), first) - disk_a.border.begin());
  const auto& p = get(vpm_a, disk_a.vertices[first]);
  // the differences in double (the points may have different kernels), squared after a power of two brings the
  // largest near 1 when they are far from unit size (the squares would overflow or underflow: no nearest vertex)
  std::vector<std::array<double, 3> > difference(disk_b.border.size());
  double largest = 0;
  for(std::size_t k = 0; k < disk_b.border.size(); ++k)
  {
    const auto& q = get(vpm_b, disk_b.vertices[disk_b.border[k]]);
    difference[k] = {{ CGAL::to_double(p.x()) - CGAL::to_double(q.x()), CGAL::to_double(p.y()) - CGAL::to_double(q.y()),
                       CGAL::to_double(p.z()) - CGAL::to_double(q.z()) }};
    for(double d : difference[k]) if(std::abs(d) > largest) largest = std::abs(d);
  }
  const int exponent = (std::isfinite(largest) && (largest > 0x1p100 || (largest > 0 && largest < 0x1p-100))) ? -std::ilogb(largest) : 0;
  std::size_t start_b = 0;
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t k = 0; k < difference.size(); ++k)
  {
    double d = 0;
    for(double x : difference[k]) { const double y = std::ldexp(x, exponent); d += y * y; }
    if(d < best) { best = d; start_b = k; }
  }
  return std::make_pair(start_a, start_b);
}

// the relative arc-length parameters of `disk`'s border from its position `start` on
// (s[k]: of the border vertex start + k, modulo the border size; s[nb] = 1)
template <class TriangleMesh, class VPM>
std::vector<double> border_parameters_from(const Indexed_disk<TriangleMesh>& disk, VPM vpm, std::size_t start)
{
  const std::size_t nb = disk.border.size();
  std::vector<double> length(nb, 0.);
  for(std::size_t k = 0; k < nb; ++k)
  {
    const auto& p = get(vpm, disk.vertices[disk.border[(start + k) % nb]]);
    const auto& q = get(vpm, disk.vertices[disk.border[(start + k + 1) % nb]]);
    length[k] = length_3(p, q);
  }
  return arc_length_parameters(length);
}

// corners (positions from the start) at the parameters nearest to `targets`, strictly increasing;
// ERROR_BORDER_TOO_SHORT when the border has fewer than four vertices
inline Error_code square_corners(const std::vector<double>& s, const std::vector<double>& targets,
                                 std::vector<std::size_t>& corners)
{
  const std::size_t nb = s.size() - 1;
  if(nb < 4) return ERROR_BORDER_TOO_SHORT;
  corners.assign(1, 0);
  for(std::size_t c = 1; c < 4; ++c)
  {
    std::size_t k = closest_parameter(s, targets[c]);
    if(k <= corners.back()) k = corners.back() + 1;
    if(k + (4 - c) > nb) k = nb - (4 - c);
    corners.push_back(k);
  }
  return OK;
}

// the positions (from `start`, the smaller first) of the end points of the interior edges of `disk` that
// join two border vertices
template <class TriangleMesh>
std::vector<std::pair<std::size_t, std::size_t> > border_chords(const Indexed_disk<TriangleMesh>& disk, std::size_t start)
{
  const std::size_t nb = disk.border.size();
  std::vector<std::size_t> position(disk.number_of_vertices(), std::size_t(-1));
  for(std::size_t k = 0; k < nb; ++k) position[disk.border[(start + k) % nb]] = k;
  std::vector<std::pair<std::size_t, std::size_t> > chords;
  for(const auto& f : disk.faces)
    for(int i = 0; i < 3; ++i)
    {
      std::size_t u = position[f[i]], v = position[f[(i + 1) % 3]];
      if(u == std::size_t(-1) || v == std::size_t(-1)) continue;
      if(u > v) std::swap(u, v);
      if(v - u == 1 || (u == 0 && v + 1 == nb)) continue; // a border edge
      chords.emplace_back(u, v);
    }
  std::sort(chords.begin(), chords.end());
  chords.erase(std::unique(chords.begin(), chords.end()), chords.end());
  return chords;
}

// Moves corners 1 to 3 (positions on a border of `nb` vertices, corner 0 at position 0) so that no chord has
// both end points on one side of the square: the corner at the end of the side that holds a chord goes to
// the vertex just inside the chord (a chord is not a border edge, so there is one). Bounded: a few passes
// over the chords; a chord that no move separates is left (the map then reports ERROR_DEGENERATE_CHORD).
inline void separate_chords(const std::vector<std::pair<std::size_t, std::size_t> >& chords, std::size_t nb,
                            std::vector<std::size_t>& corners)
{
  for(int pass = 0; pass < 8; ++pass)
  {
    bool moved = false;
    for(const auto& c : chords)
      for(std::size_t j = 0; j < 4; ++j)
      {
        const std::size_t lo = corners[j], hi = j < 3 ? corners[j + 1] : nb;
        // the start vertex is position 0 and position nb, the end of the last side
        const std::size_t u = (c.first == 0 && j == 3) ? c.second : c.first;
        const std::size_t v = (c.first == 0 && j == 3) ? nb : c.second;
        if(!(lo <= u && v <= hi)) continue;
        if(j < 3 && v - 1 > u) { corners[j + 1] = v - 1; moved = true; }
        else if(j == 3 && u + 1 < v) { corners[3] = u + 1; moved = true; }
        break;
      }
    if(!moved) return;
  }
}

template <class Point_2>
std::vector<Point_2> unit_square()
{
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel::FT FT;
  const FT zero = make_ft<FT>(0), one = make_ft<FT>(1);
  return { Point_2(zero, zero), Point_2(one, zero), Point_2(one, one), Point_2(zero, one) };
}

// B's border on the unit square, as both functions below place it: `sb` its relative arc-length parameters and
// `cb` its corners (positions from `start_b`; at the quarters, moved around chords), `pb` the points
template <class Point_2, class MeshB, class VPMB>
Error_code place_b_on_square(const Indexed_disk<MeshB>& disk_b, VPMB vpm_b, std::size_t start_b,
                             std::vector<double>& sb, std::vector<std::size_t>& cb, std::vector<Point_2>& pb)
{
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel::FT FT;
  sb = border_parameters_from(disk_b, vpm_b, start_b);
  const Error_code ec = square_corners(sb, { 0., 0.25, 0.5, 0.75 }, cb);
  if(ec != OK) return ec;
  separate_chords(border_chords(disk_b, start_b), disk_b.border.size(), cb);
  place_on_polygon<FT>(sb, cb, unit_square<Point_2>(), pb);
  return OK;
}

// `uv[k]` for the border vertex at position k of the border cycle, from `p` given from position `start`
template <class Point_2>
void rotate_from_start(const std::vector<Point_2>& p, std::size_t start, std::vector<Point_2>& uv)
{
  const std::size_t n = p.size();
  uv.resize(n);
  for(std::size_t k = 0; k < n; ++k) uv[(start + k) % n] = p[k];
}

// The uv of the border vertices of B (`disk_b` from `start_b`) and A on the unit square: `uv_b[k]`,
// `uv_a[k]` for the border vertex at position k of each disk's border cycle.
template <class Point_2, class MeshA, class VPMA, class MeshB, class VPMB>
Error_code common_square_border(const Indexed_disk<MeshA>& disk_a, VPMA vpm_a, std::size_t start_a,
                                const Indexed_disk<MeshB>& disk_b, VPMB vpm_b, std::size_t start_b,
                                std::vector<Point_2>& uv_a, std::vector<Point_2>& uv_b)
{
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel::FT FT;
  std::vector<double> sb;
  std::vector<std::size_t> ca, cb;
  std::vector<Point_2> pa, pb;
  Error_code ec = place_b_on_square(disk_b, vpm_b, start_b, sb, cb, pb);
  if(ec != OK) return ec;
  const std::vector<double> sa = border_parameters_from(disk_a, vpm_a, start_a);
  ec = square_corners(sa, { 0., sb[cb[1]], sb[cb[2]], sb[cb[3]] }, ca);
  if(ec != OK) return ec;
  place_on_polygon<FT>(sa, ca, unit_square<Point_2>(), pa);
  rotate_from_start(pa, start_a, uv_a);
  rotate_from_start(pb, start_b, uv_b);
  return OK;
}

// the position in [lo, hi) whose parameter is nearest to `target` (the first of equals; lo when the range is empty)
inline std::size_t nearest_in(const std::vector<double>& s, double target, std::size_t lo, std::size_t hi)
{
  std::size_t best = lo;
  for(std::size_t k = lo + 1; k < hi; ++k) if(std::abs(s[k] - target) < std::abs(s[best] - target)) best = k;
  return best;
}

// The corners of the square through matched border vertices when B's corners leave an arc of A without a vertex
// for one of them. A corner needs a vertex on both borders, in the same place along them: a matched pair after the
// first, or an inside vertex of an arc of B (between consecutive matched pairs; the last arc ends at the start
// again) with the inside vertex of A's arc at the same relative arc length. Corners 1 to 3 are chosen in order, each
// the place nearest to B's corner `cb[c]` in B's relative arc length (`sb`), after the corner before it on both
// borders, leaving places for the corners still to come. `matched`, `sa`, `sb`, `na`, `nb` as in
// common_square_border_through(); `ca` and `cb` get the four corners (positions from the start, the first 0).
// False, with `ca` and `cb` unchanged, when the borders have fewer than three places in order: no square with its
// corners at vertices of both borders matches the landmarks. O(3 (na + nb)).
inline bool corners_at_places(const std::vector<double>& sa, const std::vector<double>& sb,
                              const std::vector<std::pair<std::size_t, std::size_t> >& matched,
                              std::size_t na, std::size_t nb, std::vector<std::size_t>& ca, std::vector<std::size_t>& cb)
{
  const std::size_t nm = matched.size();
  auto a_end = [&](std::size_t j) { return j + 1 < nm ? matched[j + 1].first : na; };
  auto b_end = [&](std::size_t j) { return j + 1 < nm ? matched[j + 1].second : nb; };
  // inside places of arc j, and the places from the matched pair j (the start excluded) on
  std::vector<std::size_t> inside(nm), from(nm + 1, 0);
  for(std::size_t j = nm; j-- > 0;)
  {
    inside[j] = (std::min)(a_end(j) - matched[j].first - 1, b_end(j) - matched[j].second - 1);
    from[j] = from[j + 1] + inside[j] + (j > 0 ? 1 : 0);
  }
  if(from[0] < 3) return false;
  std::vector<std::size_t> qa(1, 0), qb(1, 0);
  for(std::size_t c = 1; c < 4; ++c)
  {
    const std::size_t need = 3 - c; // corners after this one
    const double target = sb[cb[c]];
    double best = std::numeric_limits<double>::infinity();
    std::size_t best_a = 0, best_b = 0;
    for(std::size_t j = 0; j < nm; ++j)
    {
      if(b_end(j) <= qb.back() || a_end(j) <= qa.back()) continue; // arc j and its matched pair before the last corner
      if(j > 0 && matched[j].first > qa.back() && matched[j].second > qb.back() && inside[j] + from[j + 1] >= need)
      {
        const double d = std::abs(sb[matched[j].second] - target);
        if(d < best) { best = d; best_a = matched[j].first; best_b = matched[j].second; }
      }
      // inside vertices of the arc, leaving the corners after this one the room they need here
      const std::size_t in_arc = need > from[j + 1] ? need - from[j + 1] : 0;
      const std::size_t a0 = matched[j].first, b0 = matched[j].second, a1 = a_end(j), b1 = b_end(j);
      const std::size_t a_lo = (std::max)(a0, qa.back()) + 1, b_lo = (std::max)(b0, qb.back()) + 1;
      if(a1 < in_arc + 1 || b1 < in_arc + 1) continue;
      const std::size_t a_hi = a1 - 1 - in_arc, b_hi = b1 - 1 - in_arc; // last usable positions
      if(a_lo > a_hi || b_lo > b_hi) continue;
      const std::size_t k = nearest_in(sb, target, b_lo, b_hi + 1);
      const double d = std::abs(sb[k] - target);
      if(d < best)
      {
        const double r = (sb[b1] > sb[b0]) ? (sb[k] - sb[b0]) / (sb[b1] - sb[b0]) : 0.5;
        best = d; best_b = k;
        best_a = nearest_in(sa, sa[a0] + r * (sa[a1] - sa[a0]), a_lo, a_hi + 1);
      }
    }
    if(!(best < std::numeric_limits<double>::infinity())) return false;
    qa.push_back(best_a);
    qb.push_back(best_b);
  }
  ca.swap(qa);
  cb.swap(qb);
  return true;
}

// As common_square_border(), through matched pairs of border vertices (border landmarks): B is placed as
// there; on A, each matched vertex goes to the uv of its partner (bit for bit), each corner of the square
// to the vertex of A, strictly between the matched vertices around B's corner, whose relative arc length
// between them is nearest to that of B's corner (or to the matched vertex when B's corner is one), and the
// other vertices by arc length between these anchors. Consecutive anchors lie on one side of the square,
// so every border point of A lies exactly on a side too. `matched`: (position on A's border from
// start_a, position on B's border from start_b), the first (0, 0), both positions strictly increasing.
// When an arc of A (between two consecutive matched vertices) has too few vertices for the corners that B's arc
// holds, the three corners after the start are chosen again (corners_at_places()), B's among them: the square
// then has corners at matched vertices or in arcs with room on both borders. ERROR_BORDER_TOO_SHORT when no such
// choice exists; `failed_arc`, if given, is then the index in `matched` of the pair that ends the first arc of A
// found too short (0 when it ends at the start), and std::size_t(-1) on any other outcome.
template <class Point_2, class MeshA, class VPMA, class MeshB, class VPMB>
Error_code common_square_border_through(const Indexed_disk<MeshA>& disk_a, VPMA vpm_a, std::size_t start_a,
                                        const Indexed_disk<MeshB>& disk_b, VPMB vpm_b, std::size_t start_b,
                                        const std::vector<std::pair<std::size_t, std::size_t> >& matched,
                                        std::vector<Point_2>& uv_a, std::vector<Point_2>& uv_b,
                                        std::size_t* failed_arc = nullptr)
{
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel::FT FT;
  CGAL_precondition(!matched.empty() && matched.front().first == 0 && matched.front().second == 0);
  if(failed_arc != nullptr) *failed_arc = std::size_t(-1);
  const std::size_t na = disk_a.border.size(), nb = disk_b.border.size(), nm = matched.size();
  std::vector<double> sb;
  std::vector<std::size_t> cb;
  std::vector<Point_2> pb;
  Error_code ec = place_b_on_square(disk_b, vpm_b, start_b, sb, cb, pb);
  if(ec != OK) return ec;
  if(na < 4) return ERROR_BORDER_TOO_SHORT;
  const std::vector<double> sa = border_parameters_from(disk_a, vpm_a, start_a);
  const std::vector<Point_2> square = unit_square<Point_2>();

  // A's corners
  std::vector<std::size_t> ca(1, 0);
  std::size_t short_arc = std::size_t(-1); // the pair ending the first arc of A found too short
  for(std::size_t c = 1; c < 4 && short_arc == std::size_t(-1); ++c)
  {
    const std::size_t kb = cb[c];
    std::size_t i = 0; // the last matched pair at or before B's corner
    while(i + 1 < nm && matched[i + 1].second <= kb) ++i;
    std::size_t ka = matched[i].first;
    if(matched[i].second != kb)
    {
      const std::size_t a0 = matched[i].first, a1 = (i + 1 < nm) ? matched[i + 1].first : na;
      const std::size_t b0 = matched[i].second, b1 = (i + 1 < nm) ? matched[i + 1].second : nb;
      const double r = (sb[b1] > sb[b0]) ? (sb[kb] - sb[b0]) / (sb[b1] - sb[b0]) : 0.5;
      ka = (std::max)(nearest_in(sa, sa[a0] + r * (sa[a1] - sa[a0]), a0 + 1, a1), ca.back() + 1);
    }
    if(ka <= ca.back() || (matched[i].second != kb && ka >= ((i + 1 < nm) ? matched[i + 1].first : na)))
      short_arc = (i + 1 < nm) ? i + 1 : 0;
    else ca.push_back(ka);
  }
  if(short_arc != std::size_t(-1))
  {
    if(!corners_at_places(sa, sb, matched, na, nb, ca, cb))
    {
      if(failed_arc != nullptr) *failed_arc = short_arc;
      return ERROR_BORDER_TOO_SHORT;
    }
    place_on_polygon<FT>(sb, cb, square, pb);
  }
  // the anchors of A, in border order: the matched vertices and the corners (a corner that is a matched
  // vertex once: its partner is B's corner, at the corner point exactly)
  std::vector<std::pair<std::size_t, Point_2> > anchors;
  for(const auto& m : matched) anchors.emplace_back(m.first, pb[m.second]);
  for(std::size_t c = 0; c < 4; ++c) anchors.emplace_back(ca[c], square[c]);
  std::stable_sort(anchors.begin(), anchors.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::size_t> idx;
  std::vector<Point_2> pts;
  for(const auto& a : anchors)
  {
    if(!idx.empty() && idx.back() == a.first) continue;
    idx.push_back(a.first);
    pts.push_back(a.second);
  }
  std::vector<Point_2> pa;
  place_on_polygon<FT>(sa, idx, pts, pa);
  rotate_from_start(pa, start_a, uv_a);
  rotate_from_start(pb, start_b, uv_b);
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_COMMON_BORDER_H
