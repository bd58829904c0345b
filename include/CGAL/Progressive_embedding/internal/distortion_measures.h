// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_DISTORTION_MEASURES_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_DISTORTION_MEASURES_H

// The distortion measures of measure_distortion() and check_embedding(): per-face symmetric Dirichlet,
// conformal and area distortions against the scaled 3D triangles, their aggregation, and the traits
// that the certificates use (the geom_traits named parameter or the uv map's kernel).

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/symmetric_dirichlet.h>
#include <CGAL/Progressive_embedding/internal/check_passes.h>
#include <CGAL/Progressive_embedding/internal/scaling.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/Distortion_report.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// Per-face distortion of uv triangles against their 3D triangles scaled by one factor k2
// (on squared lengths). Orientation sign `sgn` (+1 or -1) mirrors a clockwise layout.
struct Face_distortion
{
  double symmetric_dirichlet, conformal, area, weight;
};

inline Face_distortion face_distortion(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                       const std::array<double, 3>& c, double k2,
                                       double x0, double y0, double x1, double y1, double x2, double y2,
                                       double uv_area /* signed, relative to the border orientation */)
{
  const double inf = std::numeric_limits<double>::infinity();
  Reference_triangle<double> ref = reference_from_points<double, 3>(a, b, c);
  for(double& d : ref.dot) d *= k2;
  ref.area2 *= k2 * k2;
  Face_distortion fd;
  fd.weight = std::sqrt((std::max)(0., ref.area2));
  if(!(uv_area > 0) || !(ref.area2 > 0)) { fd.symmetric_dirichlet = fd.conformal = fd.area = inf; return fd; }
  const double n2 = dirichlet_term(ref, x0, y0, x1, y1, x2, y2);  // |J|^2 = s1^2 + s2^2
  const double det = uv_area / fd.weight;                          // s1 s2
  fd.symmetric_dirichlet = n2 * (1 + 1 / (det * det));
  fd.conformal = n2 / det;                                         // (s1^2 + s2^2) / (s1 s2)
  fd.area = (std::max)(det, 1 / det);
  if(!std::isfinite(fd.symmetric_dirichlet)) fd.symmetric_dirichlet = inf;
  if(!std::isfinite(fd.conformal)) fd.conformal = inf;
  if(!std::isfinite(fd.area)) fd.area = inf;
  return fd;
}

// Aggregates per-face values into a report (the single implementation shared with check_embedding()).
inline void aggregate_distortion(const std::vector<Face_distortion>& fds, Distortion_report& r)
{
  r.faces = fds.size();
  double ws = 0, sd = 0, cf = 0, ar = 0;
  std::vector<double> sds;
  sds.reserve(fds.size());
  for(const Face_distortion& f : fds)
  {
    r.max_symmetric_dirichlet = (std::max)(r.max_symmetric_dirichlet, f.symmetric_dirichlet);
    r.max_conformal = (std::max)(r.max_conformal, f.conformal);
    r.max_area = (std::max)(r.max_area, f.area);
    sds.push_back(f.symmetric_dirichlet);
    if(f.weight > 0) { ws += f.weight; sd += f.weight * f.symmetric_dirichlet; cf += f.weight * f.conformal; ar += f.weight * f.area; }
  }
  const double inf = std::numeric_limits<double>::infinity();
  r.mean_symmetric_dirichlet = ws > 0 ? sd / ws : inf;
  r.mean_conformal = ws > 0 ? cf / ws : inf;
  r.mean_area = ws > 0 ? ar / ws : inf;
  if(!sds.empty())
  {
    const double q[3] = {0.5, 0.9, 0.99};
    for(int i = 0; i < 3; ++i)
    {
      std::size_t k = std::min(sds.size() - 1, static_cast<std::size_t>(q[i] * double(sds.size())));
      std::nth_element(sds.begin(), sds.begin() + k, sds.end());
      r.symmetric_dirichlet_quantiles[i] = sds[k];
    }
  }
}

// Per-face distortions of a disk given double uv coordinates and signed areas (relative to the
// border orientation, `area` computed robustly by the caller) and the 3D points.
template <class TriangleMesh, class VPM>
std::vector<Face_distortion> face_distortions(const Indexed_disk<TriangleMesh>& disk, VPM vpm,
                                              const std::vector<double>& X, const std::vector<double>& Y,
                                              double sgn, const std::vector<double>& area, double border_area)
{
  const std::size_t nv = disk.number_of_vertices(), nf = disk.number_of_faces();
  std::vector<std::array<double, 3> > Q(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    const auto& q = get(vpm, disk.vertices[i]);
    Q[i] = {{ CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()) }};
  }
  normalize_coordinates_3(Q); // near unit size: squared 3D areas neither overflow nor underflow
  double total3d = 0;
  for(const auto& t : disk.faces)
    total3d += std::sqrt((std::max)(0., reference_from_points<double, 3>(Q[t[0]], Q[t[1]], Q[t[2]]).area2));
  const double k2 = (total3d > 0 && border_area > 0) ? border_area / total3d : 0.;
  std::vector<Face_distortion> out(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = disk.faces[f];
    out[f] = face_distortion(Q[t[0]], Q[t[1]], Q[t[2]], k2, X[t[0]], sgn * Y[t[0]], X[t[1]], sgn * Y[t[1]],
                             X[t[2]], sgn * Y[t[2]], area[f]);
  }
  return out;
}

// Distortion pass: the distortion of every correctly oriented face against its 3D triangle,
// aggregated. Computed on the scaled coordinates (the measures are scale invariant).
// `has_3d` receives whether the 3D triangles have a positive total area and the border encloses some.
template <class TriangleMesh, class VPM, class Point_2>
Distortion_report distortion_pass(const Indexed_disk<TriangleMesh>& disk, VPM vpm, const Uv_samples<Point_2>& s,
                                  const Face_orientations& o, const Face_areas& a, bool& has_3d)
{
  const std::size_t nf = disk.number_of_faces();
  const double sgn = (o.border_sign == CGAL::RIGHT_TURN) ? -1. : 1.;
  std::vector<double> rel_area(nf, 0.);
  for(std::size_t f = 0; f < nf; ++f)
    rel_area[f] = (o.face_ok[f] && o.fo[f] == o.border_sign) ? a.scaled[f] : 0.;
  const std::vector<Face_distortion> fds = face_distortions(disk, vpm, s.X, s.Y, sgn, rel_area, a.border_area_scaled);
  Distortion_report r;
  aggregate_distortion(fds, r);
  double wsum = 0;
  for(const Face_distortion& fd : fds) wsum += fd.weight;
  has_3d = wsum > 0 && a.border_area_scaled > 0;
  return r;
}

// The traits named by `geom_traits`, or the default traits of the uv map's point type.
template <class VertexUVMap, class NamedParameters>
struct Check_traits
{
  typedef typename Uv_map_types<VertexUVMap>::Traits                              Default_traits;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
            CGAL::internal_np::geom_traits_t, NamedParameters, Default_traits>::type type;
  static_assert(std::is_same<typename type::Point_2, typename Uv_map_types<VertexUVMap>::Point_2>::value,
                "the geom_traits' Point_2 must be the value type of the uv map");
};

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_DISTORTION_MEASURES_H
