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
// all lie in the closed domain of B's map.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/tutte_border.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

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
    length[k] = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
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

// The uv of the border vertices of B (`disk_b` from `start_b`) and A on the unit square: `uv_b[k]`,
// `uv_a[k]` for the border vertex at position k of each disk's border cycle.
template <class Point_2, class MeshA, class VPMA, class MeshB, class VPMB>
Error_code common_square_border(const Indexed_disk<MeshA>& disk_a, VPMA vpm_a, std::size_t start_a,
                                const Indexed_disk<MeshB>& disk_b, VPMB vpm_b, std::size_t start_b,
                                std::vector<Point_2>& uv_a, std::vector<Point_2>& uv_b)
{
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel::FT FT;
  const std::vector<double> sa = border_parameters_from(disk_a, vpm_a, start_a);
  const std::vector<double> sb = border_parameters_from(disk_b, vpm_b, start_b);
  std::vector<std::size_t> ca, cb;
  Error_code ec = square_corners(sb, { 0., 0.25, 0.5, 0.75 }, cb);
  if(ec != OK) return ec;
  ec = square_corners(sa, { 0., sb[cb[1]], sb[cb[2]], sb[cb[3]] }, ca);
  if(ec != OK) return ec;
  const FT zero = make_ft<FT>(0), one = make_ft<FT>(1);
  const std::vector<Point_2> square = { Point_2(zero, zero), Point_2(one, zero), Point_2(one, one), Point_2(zero, one) };
  std::vector<Point_2> pa, pb;
  place_on_polygon<FT>(sa, ca, square, pa);
  place_on_polygon<FT>(sb, cb, square, pb);
  const std::size_t na = disk_a.border.size(), nb = disk_b.border.size();
  uv_a.resize(na);
  uv_b.resize(nb);
  for(std::size_t k = 0; k < na; ++k) uv_a[(start_a + k) % na] = pa[k];
  for(std::size_t k = 0; k < nb; ++k) uv_b[(start_b + k) % nb] = pb[k];
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_COMMON_BORDER_H
