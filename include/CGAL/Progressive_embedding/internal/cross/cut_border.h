// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CUT_BORDER_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CUT_BORDER_H

// The borders of two cut disks (two closed meshes cut along the same chain of landmarks, cut_closed.h) placed on
// the unit square so that both sides of every arc of the cut are placed alike: a vertex of A and a vertex of B come
// in the same order along both sides, and meet at one point on one side exactly when they do on the other. The
// overlay of the two maps then welds back into a closed surface along the cut (weld_cut_overlay.h). A placement
// by arc length around the whole border (common_border.h) does not give that: a corner of the square inside an arc
// on one side only, or rounding that orders two nearby points differently on the two sides, interleaves A and B
// differently.
//
// Every border vertex gets the relative 3D arc length t of its mesh vertex along its arc of the cut (from the
// arc's first landmark in chain order), the same number on both sides. With three landmarks or more (four copies
// or more on each border) the corners of the square are landmark copies (near the quarters of B's border, chosen to
// leave as few edges of B joining two border vertices on one side as can be),
// the other copies between them by B's arc length, and each arc's vertices of both meshes at `t` between its two
// landmark points, nudged by one unit in the last place where rounding would not keep the order of `t` strict (the
// same `t`, the same point). With two landmarks (the chain's ends at (0, 0) and (1, 1)), corners 1 and 3 are a vertex
// inside the cut and its copy (on B nearest to the middle of the cut, on A nearest to B's corner in t): the way there
// goes along the sides through (1, 0), and the way back is its mirror image in the diagonal (x and y exchanged,
// exact).

#include <CGAL/Progressive_embedding/internal/length_3.h>
#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/cross/common_border.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>

#include <CGAL/squared_distance_3.h>

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

// a border cycle read from one of its vertices
struct Cut_border_cycle
{
  std::vector<std::size_t> at;       // position from the start -> disk vertex
  std::vector<std::size_t> position; // disk vertex -> position from the start, or -1 inside
  std::vector<double> length;        // 3D length from the start to each position; one more entry: the whole border
};

template <class Disk, class VPM>
Cut_border_cycle cut_border_cycle(const Indexed_disk<Disk>& disk, VPM vpm, std::size_t start_vertex)
{
  Cut_border_cycle c;
  const std::size_t n = disk.border.size();
  c.position.assign(disk.number_of_vertices(), std::size_t(-1));
  const std::size_t first = std::size_t(std::find(disk.border.begin(), disk.border.end(), start_vertex) - disk.border.begin());
  c.length.assign(1, 0.);
  for(std::size_t k = 0; k < n; ++k)
  {
    c.at.push_back(disk.border[(first + k) % n]);
    c.position[c.at.back()] = k;
    const auto& p = get(vpm, disk.vertices[disk.border[(first + k) % n]]);
    const auto& q = get(vpm, disk.vertices[disk.border[(first + k + 1) % n]]);
    c.length.push_back(c.length.back() + length_3(p, q));
  }
  return c;
}

// the point at `f` in [0, 1] along side `q` of the counterclockwise unit square (side 0 from (0, 0) to (1, 0), ...)
inline std::pair<double, double> on_square_side(std::size_t q, double f)
{
  switch(q)
  {
    case 0: return { f, 0. };
    case 1: return { 1., f };
    case 2: return { 1. - f, 1. };
    default: return { 0., 1. - f };
  }
}

// `pairs`: every landmark copy as (disk vertex of A, disk vertex of B), the first at (0, 0); `twin_a`, `twin_b`: per
// disk vertex its copy on the other side of the cut (cut_twins()). Writes `uv_a`, `uv_b` for the border vertices (per
// disk vertex). ERROR_BORDER_TOO_SHORT (`failed_mesh` 0 or 1) when a mesh has fewer than four border vertices or,
// with two landmarks, no vertex inside the cut; ERROR_WRONG_PARAMETER when the copies are not in one order on both
// borders or a border is not a cut along the chain; ERROR_DEGENERATE_BORDER when two points of an arc cannot be
// kept apart in double (an arc shorter than a few units in the last place).
template <class Point_2, class DiskA, class VPMA, class DiskB, class VPMB>
Error_code cut_border_on_square(const Indexed_disk<DiskA>& disk_a, VPMA vpm_a, const Indexed_disk<DiskB>& disk_b, VPMB vpm_b,
                                const std::vector<std::pair<std::size_t, std::size_t> >& pairs,
                                const std::vector<std::size_t>& twin_a, const std::vector<std::size_t>& twin_b,
                                std::vector<Point_2>& uv_a, std::vector<Point_2>& uv_b, std::size_t& failed_mesh)
{
  constexpr std::size_t none = std::size_t(-1);
  failed_mesh = disk_a.border.size() < 4 ? 0 : 1;
  if(disk_a.border.size() < 4 || disk_b.border.size() < 4 || pairs.size() < 2) return ERROR_BORDER_TOO_SHORT;
  failed_mesh = none;
  const Cut_border_cycle ca = cut_border_cycle(disk_a, vpm_a, pairs.front().first);
  const Cut_border_cycle cb = cut_border_cycle(disk_b, vpm_b, pairs.front().second);
  const Cut_border_cycle* cycle[2] = { &ca, &cb };
  const std::vector<std::size_t>* twin[2] = { &twin_a, &twin_b };
  // the copies, in border order (positions on A's and B's border)
  std::vector<std::array<std::size_t, 2> > anchor;
  for(const auto& p : pairs)
  {
    if(ca.position[p.first] == none || cb.position[p.second] == none) return ERROR_WRONG_PARAMETER;
    anchor.push_back({{ ca.position[p.first], cb.position[p.second] }});
  }
  std::sort(anchor.begin(), anchor.end(), [](const auto& x, const auto& y) { return x[1] < y[1]; });
  const std::size_t m = anchor.size();
  for(std::size_t j = 1; j < m; ++j) if(anchor[j][0] <= anchor[j - 1][0]) return ERROR_WRONG_PARAMETER;
  // the chain's far end: the copy without a twin; the way there is arcs 0 to h - 1, the way back arcs h to m - 1
  const std::size_t h = m / 2;
  if(m % 2 != 0 || (*twin[0])[ca.at[anchor[h][0]]] != none || (*twin[1])[cb.at[anchor[h][1]]] != none) return ERROR_WRONG_PARAMETER;
  auto end_position = [&](std::size_t j, int mesh) { return j < m ? anchor[j][mesh] : cycle[mesh]->at.size(); };

  // t per disk vertex of each mesh and the arc of the way there it belongs to
  std::vector<double> t[2];
  for(int mesh = 0; mesh < 2; ++mesh)
  {
    const Cut_border_cycle& c = *cycle[mesh];
    t[mesh].assign(c.position.size(), std::numeric_limits<double>::quiet_NaN());
    for(std::size_t j = 0; j < h; ++j)
    {
      const std::size_t p0 = anchor[j][mesh], p1 = anchor[j + 1][mesh];
      const double total = c.length[p1] - c.length[p0];
      if(!(total > 0)) { failed_mesh = std::size_t(mesh); return ERROR_DEGENERATE_BORDER; }
      for(std::size_t p = p0 + 1; p < p1; ++p) t[mesh][c.at[p]] = (c.length[p] - c.length[p0]) / total;
    }
    // the way back: each vertex its twin's t
    for(std::size_t p = anchor[h][mesh] + 1; p < c.at.size(); ++p)
    {
      const std::size_t v = c.at[p], w = (*twin[mesh])[v];
      if(w == none || c.position[w] == none || c.position[w] >= anchor[h][mesh]) return ERROR_WRONG_PARAMETER;
      if(std::isnan(t[mesh][v])) t[mesh][v] = t[mesh][w];
    }
  }
  uv_a.assign(ca.position.size(), Point_2(0, 0));
  uv_b.assign(cb.position.size(), Point_2(0, 0));
  auto put_uv = [&](int mesh, std::size_t v, double x, double y) {
    (mesh == 0 ? uv_a : uv_b)[v] = Point_2(x, y);
  };

  if(m == 2)
  {
    // two landmarks: the way there through the corner (1, 0), the way back its mirror image
    double corner_t[2];
    std::size_t corner_v[2];
    for(int mesh = 1; mesh >= 0; --mesh)
    {
      const Cut_border_cycle& c = *cycle[mesh];
      const double target = mesh == 1 ? 0.5 : corner_t[1];
      corner_v[mesh] = none;
      for(std::size_t p = 1; p < anchor[1][mesh]; ++p)
        if(corner_v[mesh] == none || std::abs(t[mesh][c.at[p]] - target) < std::abs(corner_t[mesh] - target))
        { corner_v[mesh] = c.at[p]; corner_t[mesh] = t[mesh][c.at[p]]; }
      if(corner_v[mesh] == none) { failed_mesh = std::size_t(mesh); return ERROR_BORDER_TOO_SHORT; }
    }
    for(int mesh = 0; mesh < 2; ++mesh)
    {
      const Cut_border_cycle& c = *cycle[mesh];
      const double ts = corner_t[mesh];
      put_uv(mesh, c.at[0], 0, 0);
      put_uv(mesh, c.at[anchor[1][mesh]], 1, 1);
      for(std::size_t p = 1; p < anchor[1][mesh]; ++p)
      {
        const std::size_t v = c.at[p];
        const double tv = t[mesh][v];
        const double x = tv <= ts ? tv / ts : 1., y = tv <= ts ? 0. : (tv - ts) / (1. - ts);
        put_uv(mesh, v, x, y);
        put_uv(mesh, (*twin[mesh])[v], y, x);
      }
    }
    return OK;
  }

  // three landmarks or more: the corners at copies. B's map would flatten an edge joining two of its border
  // vertices on one side of the square (where two arcs of the cut run side by side), which then has to be split:
  // among the copies nearest to the quarters of B's border (8 candidates per corner), the corners leaving the fewest
  // such edges on one side, then the nearest to the quarters.
  const double whole = cb.length.back();
  auto sb = [&](std::size_t j) { return j < m ? cb.length[anchor[j][1]] / whole : 1.; };
  const std::size_t start_b = std::size_t(std::find(disk_b.border.begin(), disk_b.border.end(), cb.at[0]) - disk_b.border.begin());
  const std::vector<std::pair<std::size_t, std::size_t> > chords = border_chords(disk_b, start_b);
  std::vector<std::size_t> candidates[4];
  for(std::size_t q = 1; q < 4; ++q)
  {
    for(std::size_t j = 1; j < m; ++j) candidates[q].push_back(j);
    const double target = 0.25 * double(q);
    std::stable_sort(candidates[q].begin(), candidates[q].end(),
                     [&](std::size_t x, std::size_t y) { return std::abs(sb(x) - target) < std::abs(sb(y) - target); });
    if(candidates[q].size() > 8) candidates[q].resize(8);
  }
  auto flat_chords = [&](const std::size_t* c) {
    std::size_t flat = 0;
    const std::size_t nb = cb.at.size();
    for(const auto& e : chords)
      for(std::size_t q = 0; q < 4; ++q)
      {
        const std::size_t lo = anchor[c[q]][1], hi = q < 3 ? anchor[c[q + 1]][1] : nb;
        const std::size_t u = (e.first == 0 && q == 3) ? e.second : e.first, v = (e.first == 0 && q == 3) ? nb : e.second;
        if(lo <= u && v <= hi) { ++flat; break; }
      }
    return flat;
  };
  std::size_t corner[5] = { 0, 0, 0, 0, m };
  std::size_t best_flat = none;
  double best_deviation = 0;
  for(std::size_t j1 : candidates[1])
    for(std::size_t j2 : candidates[2])
      for(std::size_t j3 : candidates[3])
      {
        if(!(j1 < j2 && j2 < j3)) continue;
        const std::size_t c[4] = { 0, j1, j2, j3 };
        const std::size_t flat = flat_chords(c);
        const double deviation = std::abs(sb(j1) - 0.25) + std::abs(sb(j2) - 0.5) + std::abs(sb(j3) - 0.75);
        if(best_flat == none || flat < best_flat || (flat == best_flat && deviation < best_deviation))
        {
          best_flat = flat;
          best_deviation = deviation;
          corner[1] = j1; corner[2] = j2; corner[3] = j3;
        }
      }
  if(best_flat == none)
  {
    // no ordered choice among the candidates (cannot happen with four copies or more: the nearest ones in order)
    corner[1] = 1; corner[2] = 2; corner[3] = 3;
  }
  // the copies' points and sides
  std::vector<std::pair<double, double> > anchor_uv(m + 1);
  std::vector<std::size_t> side(m);
  for(std::size_t q = 0; q < 4; ++q)
    for(std::size_t j = corner[q]; j < corner[q + 1]; ++j)
    {
      const double span = sb(corner[q + 1]) - sb(corner[q]);
      if(!(span > 0)) { failed_mesh = 1; return ERROR_DEGENERATE_BORDER; }
      anchor_uv[j] = on_square_side(q, j == corner[q] ? 0. : (sb(j) - sb(corner[q])) / span);
      side[j] = q;
    }
  anchor_uv[m] = anchor_uv[0];
  for(std::size_t j = 0; j < m; ++j)
  {
    put_uv(0, ca.at[anchor[j][0]], anchor_uv[j].first, anchor_uv[j].second);
    put_uv(1, cb.at[anchor[j][1]], anchor_uv[j].first, anchor_uv[j].second);
  }
  // each arc: the points of both meshes in the order of t, from the arc's first landmark in chain order (the
  // start of the arc on the way there, its end on the way back)
  struct Item { double t; int mesh; std::size_t v; };
  for(std::size_t j = 0; j < m; ++j)
  {
    const bool back = j >= h;
    const std::pair<double, double> e0 = back ? anchor_uv[j + 1] : anchor_uv[j], e1 = back ? anchor_uv[j] : anchor_uv[j + 1];
    const bool along_x = side[j] % 2 == 0;
    const double c0 = along_x ? e0.first : e0.second, c1 = along_x ? e1.first : e1.second;
    const double fixed = along_x ? e0.second : e0.first;
    if(!(c0 != c1)) { failed_mesh = 1; return ERROR_DEGENERATE_BORDER; }
    const double toward = c1 > c0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    std::vector<Item> items;
    for(int mesh = 0; mesh < 2; ++mesh)
      for(std::size_t p = anchor[j][mesh] + 1; p < end_position(j + 1, mesh); ++p)
        items.push_back({ t[mesh][cycle[mesh]->at[p]], mesh, cycle[mesh]->at[p] });
    std::sort(items.begin(), items.end(), [](const Item& x, const Item& y) { return x.t < y.t; });
    double last = c0, last_t = -1;
    for(const Item& it : items)
    {
      if(!(it.t >= 0 && it.t <= 1)) return ERROR_WRONG_PARAMETER;
      if(it.t != last_t)
      {
        double c = c0 + it.t * (c1 - c0);
        if(!((c1 > c0) ? c > last : c < last)) c = std::nextafter(last, toward);
        if(!((c1 > c0) ? c < c1 : c > c1)) { failed_mesh = std::size_t(it.mesh); return ERROR_DEGENERATE_BORDER; }
        last = c;
        last_t = it.t;
      }
      put_uv(it.mesh, it.v, along_x ? last : fixed, along_x ? fixed : last);
    }
  }
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CUT_BORDER_H
