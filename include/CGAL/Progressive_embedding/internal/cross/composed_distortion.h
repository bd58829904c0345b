// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_COMPOSED_DISTORTION_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_COMPOSED_DISTORTION_H

// The distortion of the composed map A -> B as the energy of A's map. After both maps are certified, A's map (its
// border and landmarks fixed) is optimized once more, each face of A measured against B's surface instead of the
// plane: the Jacobian J of A's map on a face is multiplied on the left by the inverse Jacobian of B's map on the face
// of B that holds the face's uv centroid, so that the symmetric Dirichlet energy is that of the composed map (4 for an
// isometry between the two surfaces). Why: two maps that each minimize the planar energy agree only as far as that
// energy is stiff; where it is flat (a part of the surface squeezed in the plane, far from landmarks) the two maps
// slide apart, and the composed energy pulls A's map onto B's.
// The face of B is found by a walk from the one found for the face before (B's map triangulates a convex domain),
// bounded, then a scan; in double: the metric is a weight, not a certificate. It is piecewise constant: the
// optimizer takes its derivatives as zero and its line search compares true energies, and every step is certified
// exactly like any other step of the optimizer.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Optimization_statistics.h>
#include <CGAL/Progressive_embedding/internal/distortion_optimizer.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/cross/overlay_maps.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// B's map as the composed energy needs it: per face, the inverse of the Jacobian of the map from its 3D triangle
// (scaled so that the 3D area is the map's area, as the optimizer scales A's) to the plane, and the neighbour
// across each edge (k, k+1)
struct Inverse_map_metric
{
  static constexpr std::size_t none = std::size_t(-1);
  std::vector<std::array<double, 2> > uv;                   // the map's points
  std::vector<std::array<std::size_t, 3> > faces;           // counterclockwise in the map
  std::vector<Eigen::Matrix2d> inverse_jacobian;
  std::vector<std::array<std::size_t, 3> > neighbour;

  // the face holding (x, y), walking from `start`; the last face reached if the point is outside the domain. The walk
  // never steps back into the face it came from: a point within rounding of an edge may test outside both faces of
  // the edge (each computes the orientation from its own corner), and either face is then right.
  std::size_t locate(double x, double y, std::size_t start) const
  {
    const std::size_t bound = faces.size() + 1;
    std::size_t g = start < faces.size() ? start : 0, from = none;
    for(std::size_t step = 0; step < bound; ++step)
    {
      int out = -1;
      for(int k = 0; k < 3 && out < 0; ++k)
      {
        const auto& p = uv[faces[g][k]];
        const auto& q = uv[faces[g][(k + 1) % 3]];
        const std::size_t n = neighbour[g][std::size_t(k)];
        if((q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0]) < 0 && n != none && n != from) out = k;
      }
      if(out < 0) return g;
      from = g;
      g = neighbour[g][std::size_t(out)];
    }
    // a walk in a triangulation that is not Delaunay may cycle: the faces in turn
    for(std::size_t f = 0; f < faces.size(); ++f)
    {
      bool inside = true;
      for(int k = 0; k < 3 && inside; ++k)
      {
        const auto& p = uv[faces[f][k]];
        const auto& q = uv[faces[f][(k + 1) % 3]];
        inside = (q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0]) >= 0;
      }
      if(inside) return f;
    }
    return g;
  }
};

// `uv`: B's map (counterclockwise), `points`: B's 3D points, both indexed as `faces`
template <class Point_2, class Point_3>
Inverse_map_metric inverse_map_metric(const std::vector<Point_2>& uv, const std::vector<Point_3>& points,
                                      const std::vector<std::array<std::size_t, 3> >& faces)
{
  Inverse_map_metric m;
  m.faces = faces;
  m.uv.resize(uv.size());
  for(std::size_t i = 0; i < uv.size(); ++i) m.uv[i] = {{ CGAL::to_double(uv[i].x()), CGAL::to_double(uv[i].y()) }};
  std::vector<Reference_triangle<double> > refs(faces.size());
  double area2 = 0;
  for(std::size_t g = 0; g < faces.size(); ++g)
  {
    std::array<std::array<double, 3>, 3> q;
    for(int c = 0; c < 3; ++c)
    {
      const Point_3& p = points[faces[g][c]];
      q[c] = {{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }};
    }
    refs[g] = reference_3d(q);
    const auto& a = m.uv[faces[g][0]];
    const auto& b = m.uv[faces[g][1]];
    const auto& c = m.uv[faces[g][2]];
    area2 += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
  }
  // B's 3D triangles scaled as the optimizer scaled them when it optimized B's map (a degenerate one: an
  // equilateral triangle of the mean area); if that cannot be done, the faces are measured against the plane
  m.inverse_jacobian.assign(faces.size(), Eigen::Matrix2d::Identity());
  double k2 = 0;
  if(scale_references(refs, area2, k2) != OK) refs.clear();
  for(std::size_t g = 0; g < refs.size(); ++g)
  {
    const auto& G = face_frame(refs[g]).G;
    const auto& t = faces[g];
    Eigen::Matrix2d J;
    for(int row = 0; row < 2; ++row)
      for(int col = 0; col < 2; ++col)
        J(row, col) = G[col] * m.uv[t[0]][row] + G[2 + col] * m.uv[t[1]][row] + G[4 + col] * m.uv[t[2]][row];
    const Eigen::Matrix2d inverse = J.inverse();
    if(J.determinant() > 0 && inverse.allFinite()) m.inverse_jacobian[g] = inverse;
  }
  // the faces across the edges, as the overlay indexes them (B's map is certified: its faces are consistent)
  overlay_detail::Indexed_map indexed;
  if(indexed.build(m.faces, m.uv.size()) == OK) m.neighbour = std::move(indexed.across);
  else m.neighbour.assign(faces.size(), {{ Inverse_map_metric::none, Inverse_map_metric::none, Inverse_map_metric::none }});
  return m;
}

// Optimizes the certified map `uvm` of `tm` (a disk; `fixed` and the border kept bit-exactly) for the distortion of
// the map composed with the inverse of B's map `b`. Writes only a certified map (see optimize_distortion_impl()).
template <class TriangleMesh, class VertexUVMap, class Vertex>
Error_code optimize_composed_distortion(const TriangleMesh& tm, VertexUVMap uvm, const std::vector<Vertex>& fixed,
                                        const Inverse_map_metric& b, double seconds, Optimization_statistics& stats)
{
  auto vpm = get_const_property_map(CGAL::vertex_point, tm);
  typedef Distortion_optimizer<TriangleMesh, VertexUVMap, decltype(vpm), CGAL::Sequential_tag> Optimizer;
  Indexed_disk<TriangleMesh> disk;
  Error_code ec = make_indexed_disk(tm, boost::graph_traits<TriangleMesh>::null_halfedge(), disk);
  if(ec != OK) return ec;
  const std::size_t nf = disk.faces.size();
  // the face of B found last for each face, where its next walk starts (the first time: where the walk of the face
  // before ended, consecutive faces being mostly close)
  std::vector<std::size_t> last(nf, 0);
  bool first = true;
  typename Optimizer::Settings settings;
  settings.time_budget = seconds;
  settings.face_metric = [&b, &disk, &last, &first, nf](const std::vector<double>& x, const std::vector<double>& y,
                                                         std::vector<Eigen::Matrix2d>& M) {
    M.resize(nf);
    for(std::size_t f = 0; f < nf; ++f)
    {
      const auto& t = disk.faces[f];
      const std::size_t start = (first && f > 0) ? last[f - 1] : last[f];
      last[f] = b.locate((x[t[0]] + x[t[1]] + x[t[2]]) / 3, (y[t[0]] + y[t[1]] + y[t[2]]) / 3, start);
      M[f] = b.inverse_jacobian[last[f]];
    }
    first = false;
  };
  Optimizer optimizer(tm, uvm, vpm, settings);
  stats = Optimization_statistics();
  ec = optimizer.initialize(fixed, stats, &disk);
  stats.energy_before = stats.report.mean_energy_3d;
  if(ec != OK) return ec;
  if(optimizer.immersion()) return ERROR_INVALID_EMBEDDING; // not an embedding: nothing to compose with
  const Error_code result = optimizer.run(stats);
  stats.report = optimizer.certify();
  stats.energy_after = stats.report.mean_energy_3d;
  if(!stats.report.is_valid()) return ERROR_INVALID_EMBEDDING; // nothing written
  optimizer.write();
  return result;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_COMPOSED_DISTORTION_H
