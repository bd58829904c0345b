// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_SYSTEM_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_SYSTEM_H

// Assembly of the Tutte system of tutte_embedding(): one unknown per interior vertex,
//   sum_j w_ij (x_i - x_j) = 0,
// with the border positions moved to the right-hand sides. The weights are computed in
// double (uniform or mean value) and converted to the number type; the diagonal is the sum
// of the converted weights, computed in the number type, so that an exact solution is
// exactly a convex combination of its neighbours (Tutte's theorem applies).

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Progressive_embedding/internal/scaling.h>

#include <CGAL/Kernel_traits.h>
#include <boost/property_map/property_map.hpp>

#include <CGAL/number_utils.h>

#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

template <class FT>
struct Tutte_system
{
  std::size_t n = 0;                                           // unknowns
  std::vector<long> row;                                       // vertex -> unknown, -1 on the border
  std::vector<std::vector<std::pair<std::size_t, FT> > > off;  // per unknown: (unknown, -w) off the diagonal
  std::vector<FT> diag;                                        // per unknown: sum of its weights
  std::vector<FT> bu, bv;                                      // right-hand sides
};

// Directed weights w(i -> j) of every vertex, in double, accumulated per face corner.
template <class TriangleMesh, class VPM>
Error_code tutte_weights(const Indexed_disk<TriangleMesh>& disk, VPM vpm, Weights wts,
                         std::vector<std::vector<std::pair<std::size_t, double> > >& adj)
{
  adj.assign(disk.number_of_vertices(), std::vector<std::pair<std::size_t, double> >());
  auto add = [&](std::size_t i, std::size_t j, double w) {
    for(auto& e : adj[i]) if(e.first == j) { e.second += w; return; }
    adj[i].push_back(std::make_pair(j, w));
  };
  // Mean value weights square 3D lengths: for a mesh far from unit size, the differences are brought near it by the
  // power of two that normalizes the points (exact; every weight is then scaled by one power of two, which does not
  // change the solution).
  typedef typename boost::property_traits<VPM>::value_type Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel::FT FT3;
  Power_of_two_scaling<FT3> scaling;
  if(wts != Weights::UNIFORM)
  {
    std::vector<Point_3> points;
    points.reserve(disk.number_of_vertices());
    for(std::size_t i = 0; i < disk.number_of_vertices(); ++i) points.push_back(get(vpm, disk.vertices[i]));
    scaling = Power_of_two_scaling<FT3>::normalizing_3(points);
  }
  auto scaled = [&scaling](const FT3& d) { return CGAL::to_double(scaling.forward(d)); };
  for(const auto& t : disk.faces)
  {
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t i = t[c], j = t[(c + 1) % 3], k = t[(c + 2) % 3];
      if(wts == Weights::UNIFORM)
      {
        // each interior edge is seen from its two faces: weight 1/2 per face and direction
        add(i, j, 0.5); add(i, k, 0.5);
        continue;
      }
      // mean value: tan(alpha/2) / |p_i - p_j| for the angle alpha at i in this face, for both edges at i
      const auto& P = get(vpm, disk.vertices[i]);
      const auto& Q = get(vpm, disk.vertices[j]);
      const auto& R = get(vpm, disk.vertices[k]);
      const double ax = scaled(Q.x() - P.x()), ay = scaled(Q.y() - P.y()), az = scaled(Q.z() - P.z());
      const double bx = scaled(R.x() - P.x()), by = scaled(R.y() - P.y()), bz = scaled(R.z() - P.z());
      const double la = std::sqrt(ax * ax + ay * ay + az * az), lb = std::sqrt(bx * bx + by * by + bz * bz);
      const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
      const double cr = std::sqrt(cx * cx + cy * cy + cz * cz), dt = ax * bx + ay * by + az * bz;
      const double tan_half = (cr > 0) ? (la * lb - dt) / cr : 0.;
      if(!(la > 0) || !(lb > 0) || !std::isfinite(tan_half)) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      add(i, j, tan_half / la); add(i, k, tan_half / lb);
    }
  }
  return OK;
}

// The system for the given weights and border positions (`pos` holds the border vertices' uv).
template <class FT, class TriangleMesh, class Point_2>
void assemble_tutte_system(const Indexed_disk<TriangleMesh>& disk,
                           const std::vector<std::vector<std::pair<std::size_t, double> > >& adj,
                           const std::vector<Point_2>& pos, Tutte_system<FT>& S)
{
  const std::size_t nv = disk.number_of_vertices();
  S = Tutte_system<FT>();
  S.row.assign(nv, -1);
  for(std::size_t i = 0; i < nv; ++i) if(!disk.on_border[i]) S.row[i] = static_cast<long>(S.n++);
  S.off.resize(S.n);
  S.diag.assign(S.n, make_ft<FT>(0));
  S.bu.assign(S.n, make_ft<FT>(0));
  S.bv.assign(S.n, make_ft<FT>(0));
  for(std::size_t i = 0; i < nv; ++i)
  {
    if(S.row[i] < 0) continue;
    const std::size_t r = static_cast<std::size_t>(S.row[i]);
    S.off[r].reserve(adj[i].size());
    for(const auto& e : adj[i])
    {
      const FT w = make_ft<FT>(e.second);
      S.diag[r] += w;
      if(S.row[e.first] >= 0)
        S.off[r].push_back(std::make_pair(static_cast<std::size_t>(S.row[e.first]), FT(-w)));
      else
      {
        S.bu[r] += w * pos[e.first].x();
        S.bv[r] += w * pos[e.first].y();
      }
    }
  }
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_SYSTEM_H
