// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_BORDER_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_BORDER_H

// Border placement of tutte_embedding(): the border parameterization by 3D arc length, and
// the positions on a circle, a square or a triangle, or the fixed positions of the uv map
// (checked convex, exactly).

#include <CGAL/Progressive_embedding/internal/length_3.h>
#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/border_polygon.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// Cumulative parameters s[0] = 0 < s[1] < ... < s[nb] = 1 of the border edges from their
// lengths. Edges too short to separate their ends after normalization (zero-length edges,
// duplicated points, non-finite lengths) would put distinct border vertices on one point:
// each maximal run of such edges shares evenly the length of the run and of the next long
// edge; with no long edge at all, the spacing is even over the whole border.
inline std::vector<double> arc_length_parameters(const std::vector<double>& length)
{
  const std::size_t nb = length.size();
  std::vector<double> s(nb + 1, 0.);
  if(nb == 0) return s;
  double total = 0;
  for(double d : length) if(std::isfinite(d) && d > 0) total += d;
  // relative threshold: below it an edge would not move its parameter in double
  const double tiny = total * 1e-12;
  std::vector<char> is_long(nb, 0);
  std::size_t first_long = nb;
  for(std::size_t k = 0; k < nb; ++k)
  {
    is_long[k] = std::isfinite(length[k]) && length[k] > tiny && total > 0 && std::isfinite(total);
    if(is_long[k] && first_long == nb) first_long = k;
  }
  if(first_long == nb)
  {
    for(std::size_t k = 0; k <= nb; ++k) s[k] = double(k) / double(nb);
    return s;
  }
  // effective lengths: start after a long edge so that every run ends on a long edge
  std::vector<double> eff(nb, 0.);
  std::size_t k = (first_long + 1) % nb;
  for(std::size_t done = 0; done < nb; )
  {
    std::size_t run = 0; // short edges before the next long one
    while(!is_long[(k + run) % nb]) ++run; // bounded: edge first_long is long
    const double share = length[(k + run) % nb] / double(run + 1);
    for(std::size_t j = 0; j <= run; ++j) eff[(k + j) % nb] = share;
    done += run + 1;
    k = (k + run + 1) % nb;
  }
  double L = 0;
  for(std::size_t j = 0; j < nb; ++j) { L += eff[j]; s[j + 1] = L; }
  for(double& x : s) x /= L;
  s[nb] = 1;
  return s;
}

// border parameters from the 3D points
template <class TriangleMesh, class VPM>
std::vector<double> border_arc_length(const Indexed_disk<TriangleMesh>& disk, VPM vpm)
{
  const std::size_t nb = disk.border.size();
  std::vector<double> length(nb, 0.);
  for(std::size_t k = 0; k < nb; ++k)
  {
    const auto& p = get(vpm, disk.vertices[disk.border[k]]);
    const auto& q = get(vpm, disk.vertices[disk.border[(k + 1) % nb]]);
    length[k] = length_3(p, q);
  }
  return arc_length_parameters(length);
}

// Positions along a closed polyline through `corner_pts` (convex polygon, counterclockwise):
// border vertex k goes to the polygon at its parameter between the corner indices around it.
template <class FT, class Point_2>
void place_on_polygon(const std::vector<double>& s, const std::vector<std::size_t>& corner_idx,
                      const std::vector<Point_2>& corner_pts, std::vector<Point_2>& out)
{
  const std::size_t nb = s.size() - 1, nc = corner_idx.size();
  out.resize(nb);
  for(std::size_t c = 0; c < nc; ++c)
  {
    const std::size_t k0 = corner_idx[c], k1 = corner_idx[(c + 1) % nc];
    const Point_2& A = corner_pts[c];
    const Point_2& B = corner_pts[(c + 1) % nc];
    const double s0 = s[k0];
    const double len = (k1 > k0 ? s[k1] : 1.0 + s[k1]) - s0;
    std::size_t k = k0;
    do
    {
      const double sk = (k >= k0 ? s[k] : 1.0 + s[k]) - s0;
      const double t = (len > 0) ? sk / len : 0.;
      const FT ft = make_ft<FT>(t);
      out[k] = Point_2(A.x() + ft * (B.x() - A.x()), A.y() + ft * (B.y() - A.y()));
      k = (k + 1) % nb;
    } while(k != k1);
  }
}

// index of the border vertex whose parameter is closest to `target`
inline std::size_t closest_parameter(const std::vector<double>& s, double target)
{
  std::size_t best = 0;
  for(std::size_t k = 0; k + 1 < s.size(); ++k)
    if(std::abs(s[k] - target) < std::abs(s[best] - target)) best = k;
  return best;
}

// Border_shape::FIXED: the uv map's border, which must be finite and convex (exact test)
template <class TriangleMesh, class VertexUVMap, class Traits, class Point_2>
Error_code fixed_border(const Indexed_disk<TriangleMesh>& disk, VertexUVMap uvm, const Traits& traits,
                        std::vector<Point_2>& bpos)
{
  const std::size_t nb = disk.border.size();
  bpos.resize(nb);
  for(std::size_t k = 0; k < nb; ++k)
  {
    bpos[k] = get(uvm, disk.vertices[disk.border[k]]);
    if(!is_finite_ft(bpos[k].x()) || !is_finite_ft(bpos[k].y()))
      return ERROR_NON_FINITE_COORDINATES;
  }
  int orientation = 0;
  const Polygon_class pc = classify_convex_polygon(bpos, traits.exact_orientation_2_object(), orientation);
  if(pc == Polygon_class::DEGENERATE) return ERROR_DEGENERATE_BORDER;
  if(pc == Polygon_class::NON_CONVEX) return ERROR_NON_CONVEX_BORDER;
  return OK;
}

template <class FT, class Point_2>
void circle_border(const std::vector<double>& s, std::vector<Point_2>& bpos)
{
  const std::size_t nb = s.size() - 1;
  const double two_pi = 2 * CGAL_PI;
  bpos.resize(nb);
  for(std::size_t k = 0; k < nb; ++k)
    bpos[k] = Point_2(make_ft<FT>(std::cos(two_pi * s[k])), make_ft<FT>(std::sin(two_pi * s[k])));
}

template <class FT, class Point_2>
Error_code square_border(const std::vector<double>& s, std::vector<Point_2>& bpos)
{
  const std::size_t nb = s.size() - 1;
  if(nb < 4) return ERROR_BORDER_TOO_SHORT;
  std::vector<std::size_t> ci(1, 0);
  for(int c = 1; c < 4; ++c)
  {
    std::size_t k = closest_parameter(s, c / 4.0);
    if(k <= ci.back()) k = ci.back() + 1;
    if(k + (4 - c) > nb) return ERROR_BORDER_TOO_SHORT;
    ci.push_back(k);
  }
  const FT zero = make_ft<FT>(0), one = make_ft<FT>(1);
  const std::vector<Point_2> cp = { Point_2(zero, zero), Point_2(one, zero), Point_2(one, one), Point_2(zero, one) };
  place_on_polygon<FT>(s, ci, cp, bpos);
  return OK;
}

// `corner_pos`: the border positions of the given corners (empty: chosen by arc length);
// `cp`: the corner points, checked strictly convex
template <class FT, class Point_2, class Traits>
Error_code triangle_border(const std::vector<double>& s, std::vector<std::size_t> ci,
                           const std::array<Point_2, 3>& cp, const Traits& traits, std::vector<Point_2>& bpos)
{
  const std::size_t nb = s.size() - 1;
  if(!ci.empty())
  {
    // rotate so that the corners appear in border order
    const std::size_t first = std::min_element(ci.begin(), ci.end()) - ci.begin();
    std::rotate(ci.begin(), ci.begin() + first, ci.end());
    if(!(ci[0] < ci[1] && ci[1] < ci[2])) return ERROR_WRONG_PARAMETER; // not in border order
  }
  else
  {
    ci.push_back(0);
    const std::size_t k1 = (std::max)(std::size_t(1), closest_parameter(s, 1 / 3.0));
    const std::size_t k2 = (std::max)(k1 + 1, closest_parameter(s, 2 / 3.0));
    if(k2 >= nb) return ERROR_BORDER_TOO_SHORT;
    ci.push_back(k1); ci.push_back(k2);
  }
  const std::vector<Point_2> cpv(cp.begin(), cp.end());
  int orientation = 0;
  if(classify_convex_polygon(cpv, traits.exact_orientation_2_object(), orientation) != Polygon_class::STRICTLY_CONVEX)
    return ERROR_DEGENERATE_BORDER;
  place_on_polygon<FT>(s, ci, cpv, bpos);
  return OK;
}

template <class Point_2>
std::array<Point_2, 3> default_triangle_corner_points()
{
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel::FT FT;
  return {{ Point_2(make_ft<FT>(0), make_ft<FT>(0)), Point_2(make_ft<FT>(1), make_ft<FT>(0)),
            Point_2(make_ft<FT>(0.5), make_ft<FT>(std::sqrt(3.) / 2)) }};
}

// positions of the given corner vertices on the border (ERROR_WRONG_PARAMETER if one is not on it)
template <class TriangleMesh, class VD>
Error_code corner_positions(const Indexed_disk<TriangleMesh>& disk, const std::array<VD, 3>& corners,
                            std::vector<std::size_t>& ci)
{
  const std::size_t nb = disk.border.size();
  ci.clear();
  for(const VD& c : corners)
  {
    std::size_t pos = nb;
    for(std::size_t k = 0; k < nb; ++k) if(disk.vertices[disk.border[k]] == c) pos = k;
    if(pos == nb) return ERROR_WRONG_PARAMETER;
    ci.push_back(pos);
  }
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_BORDER_H
