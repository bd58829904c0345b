// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_CHECK_EMBEDDING_H
#define CGAL_PROGRESSIVE_EMBEDDING_CHECK_EMBEDDING_H

/// \file check_embedding.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/certification_kernel.h>
#include <CGAL/Progressive_embedding/internal/border_polygon.h>
#include <CGAL/Progressive_embedding/internal/symmetric_dirichlet.h>
#include <CGAL/Progressive_embedding/distortion.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingReports
///
/// The exact validity certificate of a planar map of a disk, returned by `check_embedding()`.
/// Orientation-dependent counts are relative to the orientation of the border polygon:
/// a layout whose border and faces are all clockwise is valid (it is a mirror image).
struct Embedding_report
{
  /// `OK`, or why the mesh itself could not be checked (not a disk, empty, ...)
  Error_code status = OK;
  /// number of faces
  std::size_t faces = 0;
  /// number of vertices
  std::size_t vertices = 0;
  /// number of border vertices
  std::size_t border_vertices = 0;
  /// faces whose orientation is opposite to the border's (exact predicate)
  std::size_t flipped = 0;
  /// faces whose three uv corners are collinear (exact predicate)
  std::size_t degenerate = 0;
  /// vertices with a NaN or infinite uv coordinate
  std::size_t non_finite = 0;
  /// `true` if the border polygon is oriented clockwise (then faces are expected clockwise)
  bool clockwise = false;
  /// `true` if the border polygon has no self-intersection (exact)
  bool border_simple = true;
  /// number of intersecting pairs of non-adjacent border edges (counting stops at `overlap_limit`)
  std::size_t border_intersections = 0;
  /// `true` if global overlap was decided
  bool overlap_checked = false;
  /// `true` if no overlap was concluded without the box test, because all faces are positively
  /// oriented and the border is simple (then every point is covered at most once)
  bool overlap_by_degree_argument = false;
  /// pairs of faces whose interiors intersect (exact; counting stops at `overlap_limit`)
  std::size_t overlapping_pairs = 0;
  /// the cap on the two counts above
  std::size_t overlap_limit = 1000;
  /// smallest signed uv area, the sign taken relative to the border orientation (double)
  double min_signed_area = 0;
  /// largest signed uv area, relative to the border orientation (double)
  double max_signed_area = 0;
  /// area enclosed by the border polygon (absolute value, double)
  double border_area = 0;
  /// max symmetric Dirichlet energy against the 3D triangles scaled to the uv area (infinite if a face is flipped or degenerate)
  double max_energy_3d = 0;
  /// 3D-area-weighted mean of that energy
  double mean_energy_3d = 0;
  /// max symmetric Dirichlet energy against an equilateral triangle of area `border_area / faces`
  double max_energy_equilateral = 0;
  /// mean of that energy (all reference areas are equal)
  double mean_energy_equilateral = 0;
  /// faces whose equilateral energy is not finite or exceeds `energy_threshold`
  std::size_t high_energy_faces = 0;
  /// threshold used for `high_energy_faces` (the `invalid_energy_threshold` named parameter)
  double energy_threshold = 1e20;
  /// `true` if the 3D energies were computed (the mesh has 3D points of non-zero total area)
  bool has_3d_energy = false;
  /// all distortion measures against the 3D triangles (`max_energy_3d` and `mean_energy_3d` repeat two of them)
  Distortion_report distortion;

  /// returns `true` if the map is a valid embedding: no flipped, degenerate or non-finite
  /// element, a simple border and no overlap.
  bool is_valid() const
  {
    return status == OK && faces > 0 && flipped == 0 && degenerate == 0 && non_finite == 0
        && border_simple && overlapping_pairs == 0;
  }

  /// returns a one-line human-readable summary
  std::string summary() const
  {
    std::ostringstream os;
    if(status != OK) { os << "not checked: " << get_error_message(status); return os.str(); }
    os << (is_valid() ? "valid" : "INVALID") << ": faces " << faces << ", flipped " << flipped
       << ", degenerate " << degenerate;
    if(non_finite) os << ", non-finite vertices " << non_finite;
    os << ", border " << (border_simple ? "simple" : "self-intersecting");
    if(overlap_checked) os << ", overlapping pairs " << overlapping_pairs
                           << (overlapping_pairs >= overlap_limit ? "+" : "");
    if(clockwise) os << " (clockwise layout)";
    os << ", min area " << min_signed_area;
    if(has_3d_energy) os << ", sym. Dirichlet max " << max_energy_3d << " mean " << mean_energy_3d;
    return os.str();
  }
};

namespace internal {

struct Overlap_limit_reached {};

// Interiors of two non-degenerate triangles (both with orientation `s`) intersect
// iff no edge line of either one weakly separates them (separating axis theorem).
template <class Orientation_2, class Point_2>
bool triangle_interiors_intersect(const Point_2* t1, const Point_2* t2, CGAL::Orientation s, const Orientation_2& orient)
{
  auto separated_by_edges_of = [&](const Point_2* a, const Point_2* b) {
    for(int i = 0; i < 3; ++i)
    {
      const Point_2& p = a[i];
      const Point_2& q = a[(i + 1) % 3];
      bool all_outside = true;
      for(int j = 0; j < 3 && all_outside; ++j)
      {
        CGAL::Orientation o = orient(p, q, b[j]);
        if(o == s) all_outside = false; // strictly on the interior side
      }
      if(all_outside) return true;
    }
    return false;
  };
  return !separated_by_edges_of(t1, t2) && !separated_by_edges_of(t2, t1);
}

} // namespace internal

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// certifies a planar map of a triangulated topological disk with exact predicates, whatever
/// the number type of the uv coordinates: doubles are tested with the filtered exact predicates
/// of `Exact_predicates_inexact_constructions_kernel`; other number types (MPFR, rationals) are
/// converted exactly to `CGAL::Gmpq`. The function never throws: a mesh that is not a disk is
/// reported in `Embedding_report::status`.
///
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param uvm the uv coordinates
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points, used for the distortion statistics}
///     \cgalParamType{a model of `ReadablePropertyMap` with `Point_3` values}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{check_overlap}
///     \cgalParamDescription{whether to run the global face-overlap test (box intersection and exact triangle tests)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_number}
///     \cgalParamDescription{the cap on the number of overlapping pairs and border intersections counted}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{1000}
///   \cgalParamNEnd
///   \cgalParamNBegin{invalid_energy_threshold}
///     \cgalParamDescription{faces whose equilateral-reference energy exceeds it are counted in `high_energy_faces`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1e20}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the report; the map is a valid embedding iff `Embedding_report::is_valid()`
template <typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Embedding_report check_embedding(const TriangleMesh& tm, VertexUVMap uvm,
                                 const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh>                                GT;
  typedef typename boost::property_traits<VertexUVMap>::value_type         UV_point;
  typedef typename CGAL::Kernel_traits<UV_point>::Kernel                   UV_kernel;
  typedef typename UV_kernel::FT                                           UV_FT;
  typedef internal::Certification_kernel<UV_FT>                            CK;
  typedef typename CK::Kernel                                              EK;
  typedef typename EK::Point_2                                             EPoint;

  Embedding_report r;
  r.overlap_limit = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_number), std::size_t(1000));
  r.energy_threshold = choose_parameter(get_parameter(np, internal_np::invalid_energy_threshold), 1e20);
  const bool do_overlap = choose_parameter(get_parameter(np, internal_np::check_overlap), true);

  internal::Indexed_disk<TriangleMesh> disk;
  r.status = internal::make_indexed_disk(tm, GT::null_halfedge(), disk);
  if(r.status != OK)
    return r;
  const std::size_t nv = disk.number_of_vertices(), nf = disk.number_of_faces();
  r.faces = nf; r.vertices = nv; r.border_vertices = disk.border.size();

  // exact points; non-finite coordinates are recorded and those vertices excluded
  std::vector<EPoint> P(nv);
  std::vector<char> finite(nv, 1);
  std::vector<double> X(nv), Y(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    const UV_point& p = get(uvm, disk.vertices[i]);
    if(!internal::is_finite_ft(p.x()) || !internal::is_finite_ft(p.y())) { finite[i] = 0; ++r.non_finite; continue; }
    P[i] = CK::convert(p);
    X[i] = CGAL::to_double(p.x()); Y[i] = CGAL::to_double(p.y());
  }
  typename EK::Orientation_2 orient = EK().orientation_2_object();

  // border orientation: sign of the exact signed area
  CGAL::Orientation border_sign = CGAL::COLLINEAR;
  bool border_finite = true;
  for(std::size_t b : disk.border) if(!finite[b]) border_finite = false;
  if(border_finite)
  {
    CGAL::Gmpq twice_area(0);
    const std::size_t nb = disk.border.size();
    for(std::size_t k = 0; k < nb; ++k)
    {
      const EPoint& a = P[disk.border[k]];
      const EPoint& b = P[disk.border[(k + 1) % nb]];
      twice_area += internal::to_rational(a.x()) * internal::to_rational(b.y())
                  - internal::to_rational(a.y()) * internal::to_rational(b.x());
    }
    border_sign = CGAL::Orientation(CGAL::sign(twice_area));
    r.border_area = std::abs(CGAL::to_double(twice_area)) / 2;
  }
  // Zero border area: fall back on the majority orientation of the faces.
  std::vector<CGAL::Orientation> fo(nf, CGAL::COLLINEAR);
  std::vector<char> face_ok(nf, 0);
  std::size_t npos = 0, nneg = 0;
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = disk.faces[f];
    if(!finite[t[0]] || !finite[t[1]] || !finite[t[2]]) continue;
    face_ok[f] = 1;
    fo[f] = orient(P[t[0]], P[t[1]], P[t[2]]);
    if(fo[f] == CGAL::LEFT_TURN) ++npos; else if(fo[f] == CGAL::RIGHT_TURN) ++nneg;
  }
  if(border_sign == CGAL::COLLINEAR)
    border_sign = (nneg > npos) ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN;
  r.clockwise = (border_sign == CGAL::RIGHT_TURN);
  const double sgn = r.clockwise ? -1. : 1.;

  // Signed areas relative to the border orientation. Evaluated in double, and again
  // exactly (rationals) where cancellation makes the double value unreliable.
  std::vector<double> area(nf, 0.);
  r.min_signed_area = std::numeric_limits<double>::infinity();
  r.max_signed_area = -std::numeric_limits<double>::infinity();
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(!face_ok[f]) continue;
    if(fo[f] == CGAL::COLLINEAR) ++r.degenerate;
    else if(fo[f] != border_sign) ++r.flipped;
    const auto& t = disk.faces[f];
    // a forward error bound on the double determinant; beyond it the value is used as is
    const double dx1 = X[t[1]] - X[t[0]], dy1 = Y[t[1]] - Y[t[0]], dx2 = X[t[2]] - X[t[0]], dy2 = Y[t[2]] - Y[t[0]];
    double a = (dx1 * dy2 - dy1 * dx2) / 2;
    // (each difference of doubles is correctly rounded, so the error is relative to the products)
    const double bound = 1e-14 * (std::abs(dx1 * dy2) + std::abs(dy1 * dx2));
    if(!(std::abs(a) > bound) || CGAL::sign(a) != CGAL::Sign(fo[f]) || !std::is_floating_point<UV_FT>::value)
    {
      const CGAL::Gmpq x0 = internal::to_rational(P[t[0]].x()), y0 = internal::to_rational(P[t[0]].y());
      const CGAL::Gmpq x1 = internal::to_rational(P[t[1]].x()), y1 = internal::to_rational(P[t[1]].y());
      const CGAL::Gmpq x2 = internal::to_rational(P[t[2]].x()), y2 = internal::to_rational(P[t[2]].y());
      a = CGAL::to_double(internal::signed_area(x0, y0, x1, y1, x2, y2));
    }
    area[f] = sgn * a;
    r.min_signed_area = (std::min)(r.min_signed_area, area[f]);
    r.max_signed_area = (std::max)(r.max_signed_area, area[f]);
  }

  // border simplicity: box intersection of border edges + exact segment tests
  if(border_finite)
  {
    std::vector<EPoint> BP;
    BP.reserve(disk.border.size());
    for(std::size_t b : disk.border) BP.push_back(P[b]);
    r.border_intersections = internal::count_border_intersections<EK>(BP, r.overlap_limit);
  }
  r.border_simple = border_finite && r.border_intersections == 0;

  // Global overlap of face interiors. When every face is positively oriented and the border
  // is simple (both decided exactly), the map has degree one over the region the border
  // encloses (each point is covered as many times as the border winds around it): no overlap
  // is possible and the box test is skipped.
  if(do_overlap && r.flipped == 0 && r.degenerate == 0 && r.non_finite == 0 && r.border_simple)
  {
    r.overlap_checked = true;
    r.overlap_by_degree_argument = true;
  }
  else if(do_overlap)
  {
    r.overlap_checked = true;
    typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t> Box;
    std::vector<Box> boxes;
    boxes.reserve(nf);
    for(std::size_t f = 0; f < nf; ++f)
    {
      if(!face_ok[f] || fo[f] == CGAL::COLLINEAR) continue;
      const auto& t = disk.faces[f];
      double xmin = (std::min)({X[t[0]], X[t[1]], X[t[2]]}), xmax = (std::max)({X[t[0]], X[t[1]], X[t[2]]});
      double ymin = (std::min)({Y[t[0]], Y[t[1]], Y[t[2]]}), ymax = (std::max)({Y[t[0]], Y[t[1]], Y[t[2]]});
      if(!std::is_floating_point<UV_FT>::value)
      {
        const double e = 1e-12 * (std::abs(xmin) + std::abs(xmax) + std::abs(ymin) + std::abs(ymax)) + 1e-300;
        xmin -= e; ymin -= e; xmax += e; ymax += e;
      }
      boxes.push_back(Box(CGAL::Bbox_2(xmin, ymin, xmax, ymax), f));
    }
    std::size_t examined = 0;
    const std::size_t max_examined = 200 * (nf + 10);
    auto cb = [&](const Box& b1, const Box& b2) {
      if(++examined > max_examined) throw internal::Overlap_limit_reached();
      const auto& t1 = disk.faces[b1.info()];
      const auto& t2 = disk.faces[b2.info()];
      // two correctly oriented faces sharing an edge lie on both sides of it: no overlap
      if(fo[b1.info()] == border_sign && fo[b2.info()] == border_sign)
      {
        int shared = 0;
        for(int i = 0; i < 3; ++i) for(int j = 0; j < 3; ++j) shared += (t1[i] == t2[j]);
        if(shared >= 2) return;
      }
      // faces with the wrong orientation are already counted as flipped; compare each in its own orientation
      EPoint a[3] = { P[t1[0]], P[t1[1]], P[t1[2]] };
      EPoint b[3] = { P[t2[0]], P[t2[1]], P[t2[2]] };
      if(fo[b1.info()] != border_sign) std::swap(a[1], a[2]);
      if(fo[b2.info()] != border_sign) std::swap(b[1], b[2]);
      if(internal::triangle_interiors_intersect(a, b, border_sign, orient))
        if(++r.overlapping_pairs >= r.overlap_limit) throw internal::Overlap_limit_reached();
    };
    try { CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), cb); }
    catch(const internal::Overlap_limit_reached&)
    {
      if(r.overlapping_pairs == 0 && examined > max_examined) r.overlap_checked = false; // inconclusive
    }
  }

  // distortion statistics, in double
  {
    const double inf = std::numeric_limits<double>::infinity();
    const double sqrt3 = std::sqrt(3.);
    const double ref_area = r.border_area / double(nf);
    const internal::Reference_triangle<double> eq = internal::equilateral_reference(ref_area, sqrt3);
    auto face_energy = [&](const internal::Reference_triangle<double>& ref, std::size_t f) {
      const auto& t = disk.faces[f];
      const double a = area[f];
      if(!(a > 0)) return inf;
      const double e = internal::dirichlet_term(ref, X[t[0]], Y[t[0]], X[t[1]], Y[t[1]], X[t[2]], Y[t[2]]) * (1 + ref.area2 / (a * a));
      return std::isfinite(e) ? e : inf;
    };
    double sum_eq = 0; std::size_t n_eq = 0;
    for(std::size_t f = 0; f < nf; ++f)
    {
      double e = inf;
      if(face_ok[f] && fo[f] == border_sign && ref_area > 0)
        e = face_energy(eq, f);
      if(!(e <= r.energy_threshold)) ++r.high_energy_faces;
      r.max_energy_equilateral = (std::max)(r.max_energy_equilateral, e);
      sum_eq += e; ++n_eq;
    }
    r.mean_energy_equilateral = n_eq ? sum_eq / double(n_eq) : 0;

    // 3D reference, scaled so that the total 3D area equals the border area (distortion.h)
    auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
    std::vector<double> rel_area(nf, 0.);
    for(std::size_t f = 0; f < nf; ++f)
      rel_area[f] = (face_ok[f] && fo[f] == border_sign) ? area[f] : 0.;
    const std::vector<internal::Face_distortion> fds = internal::face_distortions(disk, vpm, X, Y, sgn, rel_area, r.border_area);
    internal::aggregate_distortion(fds, r.distortion);
    double wsum = 0;
    for(const auto& fd : fds) wsum += fd.weight;
    r.has_3d_energy = wsum > 0 && r.border_area > 0;
    if(r.has_3d_energy)
    {
      r.max_energy_3d = r.distortion.max_symmetric_dirichlet;
      r.mean_energy_3d = r.distortion.mean_symmetric_dirichlet;
    }
  }
  return r;
}

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// measures the distortion of the uv map `uvm` of the disk `tm` against its 3D triangles (see
/// `Distortion_report`). The values are the ones `check_embedding()` reports (one implementation).
///
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexUVMap a model of `ReadablePropertyMap` with `Point_2` values
/// \tparam NamedParameters a sequence of named parameters
/// \param tm the mesh \param uvm the uv map
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points}
///     \cgalParamType{a model of `ReadablePropertyMap` with `Point_3` values}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Distortion_report measure_distortion(const TriangleMesh& tm, VertexUVMap uvm,
                                     const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Embedding_report r = check_embedding(tm, uvm, CGAL::parameters::vertex_point_map(
    choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm))));
  r.distortion.status = r.status;
  return r.distortion;
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_CHECK_EMBEDDING_H
