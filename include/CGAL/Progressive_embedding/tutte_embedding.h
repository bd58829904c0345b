// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_TUTTE_EMBEDDING_H
#define CGAL_PROGRESSIVE_EMBEDDING_TUTTE_EMBEDDING_H

/// \file tutte_embedding.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/border_polygon.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_vector.h>
#include <Eigen/SparseLU>
#include <Eigen/SparseCholesky>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

namespace internal {

// The default solver: sparse LDLT for a symmetric double system, sparse LU
// (COLAMD) otherwise -- LDLT instantiates sqrt and does not compile for rationals.
template <class FT, bool symmetric>
struct Default_tutte_solver
{
  typedef CGAL::Eigen_solver_traits<
            Eigen::SparseLU<typename CGAL::Eigen_sparse_matrix<FT>::EigenType, Eigen::COLAMDOrdering<int> > > type;
};
template <>
struct Default_tutte_solver<double, true>
{
  typedef CGAL::Eigen_solver_traits<
            Eigen::SimplicialLDLT<typename CGAL::Eigen_sparse_matrix<double>::EigenType> > type;
};

// cumulative 3D arc length along the border, normalized to [0,1)
template <class TriangleMesh, class VPM>
std::vector<double> border_arc_length(const Indexed_disk<TriangleMesh>& disk, VPM vpm)
{
  const std::size_t nb = disk.border.size();
  std::vector<double> s(nb + 1, 0.);
  for(std::size_t k = 0; k < nb; ++k)
  {
    const auto& p = get(vpm, disk.vertices[disk.border[k]]);
    const auto& q = get(vpm, disk.vertices[disk.border[(k + 1) % nb]]);
    const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
    s[k + 1] = s[k] + ((std::isfinite(d) && d > 0) ? d : 0.);
  }
  const double L = s[nb];
  for(double& x : s) x = (L > 0) ? x / L : 0.;
  // a zero-length border: fall back on uniform spacing
  if(!(L > 0)) for(std::size_t k = 0; k <= nb; ++k) s[k] = double(k) / double(nb);
  return s;
}

// Positions along a closed polyline through `corners` (convex polygon, counterclockwise),
// border vertex k goes to the corner polygon at parameter in [0,1) between corner indices.
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
    double len = (k1 > k0 ? s[k1] : 1.0 + s[k1]) - s0;
    std::size_t k = k0;
    do
    {
      double sk = (k >= k0 ? s[k] : 1.0 + s[k]) - s0;
      double t = (len > 0) ? sk / len : 0.;
      const FT ft = make_ft<FT>(t);
      out[k] = Point_2(A.x() + ft * (B.x() - A.x()), A.y() + ft * (B.y() - A.y()));
      k = (k + 1) % nb;
    } while(k != k1);
  }
}

// index of the border vertex whose arc-length parameter is closest to `target`
inline std::size_t closest_parameter(const std::vector<double>& s, double target)
{
  std::size_t best = 0;
  for(std::size_t k = 0; k + 1 < s.size(); ++k)
    if(std::abs(s[k] - target) < std::abs(s[best] - target)) best = k;
  return best;
}

} // namespace internal

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// computes Tutte's barycentric embedding (or Floater's mean value embedding) of a triangulated
/// topological disk into the plane, in the number type of the uv map. The border is taken from
/// the uv map as given (it must be convex, which is checked exactly) or placed on a circle, a square
/// or a triangle. The same code runs with `double`, exact rationals and MPFR; the sparse solver is
/// chosen from the number type (sparse LDLT for a symmetric `double` system, sparse LU otherwise)
/// and can be replaced with the `sparse_linear_solver` named parameter.
///
/// In exact arithmetic the result is a valid embedding when the border is strictly convex
/// (Tutte's theorem); in floating point it may be invalid: certify it with `check_embedding()`.
/// The function does not certify its output; `progressive_embedding()` repairs it.
///
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexUVMap a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type; its kernel's `FT` is the number type of the computation
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh, not modified
/// \param bhd a border halfedge of `tm`, or `boost::graph_traits<TriangleMesh>::null_halfedge()` for the unique border
/// \param uvm the uv map: read on the border for `Border_shape::FIXED`, written everywhere else
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{border_shape}
///     \cgalParamDescription{how the border is placed}
///     \cgalParamType{`Border_shape`}
///     \cgalParamDefault{`Border_shape::FIXED`}
///   \cgalParamNEnd
///   \cgalParamNBegin{triangle_corners}
///     \cgalParamDescription{with `Border_shape::TRIANGLE`, the three border vertices placed at the corners, in border order}
///     \cgalParamType{`std::array<vertex_descriptor, 3>`}
///     \cgalParamDefault{the vertices closest to one third and two thirds of the border length, and the first one}
///   \cgalParamNEnd
///   \cgalParamNBegin{triangle_corner_points}
///     \cgalParamDescription{with `Border_shape::TRIANGLE`, the positions of the corners}
///     \cgalParamType{`std::array<Point_2, 3>`}
///     \cgalParamDefault{(0,0), (1,0), (1/2, sqrt(3)/2)}
///   \cgalParamNEnd
///   \cgalParamNBegin{weights}
///     \cgalParamDescription{the edge weights}
///     \cgalParamType{`Weights`}
///     \cgalParamDefault{`Weights::UNIFORM`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points (border arc length, mean value weights)}
///     \cgalParamType{a model of `ReadablePropertyMap` with `Point_3` values}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{sparse_linear_solver}
///     \cgalParamDescription{the solver, a model of `SparseLinearAlgebraWithFactorTraits_d` whose scalar is the uv `FT`}
///     \cgalParamType{a class model of `SparseLinearAlgebraWithFactorTraits_d`}
///     \cgalParamDefault{`CGAL::Eigen_solver_traits` over `Eigen::SimplicialLDLT` (double, uniform weights) or `Eigen::SparseLU` with COLAMD ordering}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK`, `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`, `ERROR_NON_MANIFOLD`, `ERROR_NOT_A_DISK`,
///         `ERROR_BORDER_TOO_SHORT`, `ERROR_NON_FINITE_COORDINATES`, `ERROR_NON_CONVEX_BORDER`,
///         `ERROR_DEGENERATE_BORDER`, `ERROR_WRONG_PARAMETER` or `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`
template <typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code tutte_embedding(const TriangleMesh& tm,
                           typename boost::graph_traits<TriangleMesh>::halfedge_descriptor bhd,
                           VertexUVMap uvm,
                           const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  typedef boost::graph_traits<TriangleMesh>                                GT;
  typedef typename GT::vertex_descriptor                                   vertex_descriptor;
  typedef typename internal::Uv_map_types<VertexUVMap>::Point_2           Point_2;
  typedef typename internal::Uv_map_types<VertexUVMap>::Traits            Traits;
  typedef typename internal::Uv_map_types<VertexUVMap>::FT                FT;

  const Border_shape shape = choose_parameter(get_parameter(np, internal_np::border_shape), Border_shape::FIXED);
  const Weights wts = choose_parameter(get_parameter(np, internal_np::weights), Weights::UNIFORM);
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));

  internal::Indexed_disk<TriangleMesh> disk;
  Error_code status = internal::make_indexed_disk(tm, bhd, disk);
  if(status != OK) return status;
  const std::size_t nv = disk.number_of_vertices(), nb = disk.border.size();
  if(nb < 3) return ERROR_BORDER_TOO_SHORT;

  // ---- border ------------------------------------------------------------------
  std::vector<Point_2> bpos(nb);
  if(shape == Border_shape::FIXED)
  {
    for(std::size_t k = 0; k < nb; ++k)
    {
      bpos[k] = get(uvm, disk.vertices[disk.border[k]]);
      if(!internal::is_finite_ft(bpos[k].x()) || !internal::is_finite_ft(bpos[k].y()))
        return ERROR_NON_FINITE_COORDINATES;
    }
    int orientation = 0;
    internal::Polygon_class pc = internal::classify_convex_polygon(bpos, Traits().exact_orientation_2_object(), orientation);
    if(pc == internal::Polygon_class::DEGENERATE) return ERROR_DEGENERATE_BORDER;
    if(pc == internal::Polygon_class::NON_CONVEX) return ERROR_NON_CONVEX_BORDER;
  }
  else
  {
    const std::vector<double> s = internal::border_arc_length(disk, vpm);
    if(shape == Border_shape::CIRCLE)
    {
      const double two_pi = 2 * CGAL_PI;
      for(std::size_t k = 0; k < nb; ++k)
        bpos[k] = Point_2(internal::make_ft<FT>(std::cos(two_pi * s[k])), internal::make_ft<FT>(std::sin(two_pi * s[k])));
    }
    else if(shape == Border_shape::SQUARE)
    {
      if(nb < 4) return ERROR_BORDER_TOO_SHORT;
      std::vector<std::size_t> ci(1, 0);
      for(int c = 1; c < 4; ++c)
      {
        std::size_t k = internal::closest_parameter(s, c / 4.0);
        if(k <= ci.back()) k = ci.back() + 1;
        if(k + (4 - c) > nb) return ERROR_BORDER_TOO_SHORT;
        ci.push_back(k);
      }
      const FT zero = internal::make_ft<FT>(0), one = internal::make_ft<FT>(1);
      std::vector<Point_2> cp = { Point_2(zero, zero), Point_2(one, zero), Point_2(one, one), Point_2(zero, one) };
      internal::place_on_polygon<FT>(s, ci, cp, bpos);
    }
    else // TRIANGLE
    {
      std::vector<std::size_t> ci;
      if(!is_default_parameter<CGAL_NP_CLASS, internal_np::triangle_corners_t>::value)
      {
        std::array<vertex_descriptor, 3> corners =
          choose_parameter(get_parameter(np, internal_np::triangle_corners), std::array<vertex_descriptor, 3>());
        for(const vertex_descriptor& c : corners)
        {
          std::size_t pos = nb;
          for(std::size_t k = 0; k < nb; ++k) if(disk.vertices[disk.border[k]] == c) pos = k;
          if(pos == nb) return ERROR_WRONG_PARAMETER; // not a border vertex
          ci.push_back(pos);
        }
        // rotate so that the corners appear in border order
        std::size_t first = std::min_element(ci.begin(), ci.end()) - ci.begin();
        std::rotate(ci.begin(), ci.begin() + first, ci.end());
        if(!(ci[0] < ci[1] && ci[1] < ci[2])) return ERROR_WRONG_PARAMETER; // corners not in border order
      }
      else
      {
        ci.push_back(0);
        std::size_t k1 = (std::max)(std::size_t(1), internal::closest_parameter(s, 1 / 3.0));
        std::size_t k2 = (std::max)(k1 + 1, internal::closest_parameter(s, 2 / 3.0));
        if(k2 >= nb) return ERROR_BORDER_TOO_SHORT;
        ci.push_back(k1); ci.push_back(k2);
      }
      std::array<Point_2, 3> cp_default = { Point_2(internal::make_ft<FT>(0), internal::make_ft<FT>(0)),
                                            Point_2(internal::make_ft<FT>(1), internal::make_ft<FT>(0)),
                                            Point_2(internal::make_ft<FT>(0.5), internal::make_ft<FT>(std::sqrt(3.) / 2)) };
      std::array<Point_2, 3> cp = choose_parameter(get_parameter(np, internal_np::triangle_corner_points), cp_default);
      std::vector<Point_2> cpv(cp.begin(), cp.end());
      int orientation = 0;
      if(internal::classify_convex_polygon(cpv, Traits().exact_orientation_2_object(), orientation)
           != internal::Polygon_class::STRICTLY_CONVEX)
        return ERROR_DEGENERATE_BORDER;
      internal::place_on_polygon<FT>(s, ci, cpv, bpos);
    }
  }

  // ---- interior system -------------------------------------------------------------
  std::vector<long> row(nv, -1);
  long n_int = 0;
  for(std::size_t i = 0; i < nv; ++i) if(!disk.on_border[i]) row[i] = n_int++;
  std::vector<Point_2> pos(nv);
  for(std::size_t k = 0; k < nb; ++k) pos[disk.border[k]] = bpos[k];

  if(n_int > 0)
  {
    // directed weights w(i -> j), accumulated per face corner
    std::vector<std::vector<std::pair<std::size_t, double> > > adj(nv);
    auto add = [&](std::size_t i, std::size_t j, double w) {
      for(auto& e : adj[i]) if(e.first == j) { e.second += w; return; }
      adj[i].push_back(std::make_pair(j, w));
    };
    for(const auto& t : disk.faces)
    {
      for(int c = 0; c < 3; ++c)
      {
        const std::size_t i = t[c], j = t[(c + 1) % 3], k = t[(c + 2) % 3];
        if(wts == Weights::UNIFORM)
        {
          // each interior edge is seen from its two faces: weight 1/2 per face and direction
          add(i, j, 0.5); add(i, k, 0.5);
        }
        else
        {
          // mean value: tan(alpha/2) / |p_i - p_j| for the angle alpha at i in this face, for both edges at i
          const auto& P = get(vpm, disk.vertices[i]);
          const auto& Q = get(vpm, disk.vertices[j]);
          const auto& R = get(vpm, disk.vertices[k]);
          const double ax = CGAL::to_double(Q.x() - P.x()), ay = CGAL::to_double(Q.y() - P.y()), az = CGAL::to_double(Q.z() - P.z());
          const double bx = CGAL::to_double(R.x() - P.x()), by = CGAL::to_double(R.y() - P.y()), bz = CGAL::to_double(R.z() - P.z());
          const double la = std::sqrt(ax * ax + ay * ay + az * az), lb = std::sqrt(bx * bx + by * by + bz * bz);
          const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
          const double cr = std::sqrt(cx * cx + cy * cy + cz * cz), dt = ax * bx + ay * by + az * bz;
          const double tan_half = (cr > 0) ? (la * lb - dt) / cr : 0.;
          if(!(la > 0) || !(lb > 0) || !std::isfinite(tan_half)) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
          add(i, j, tan_half / la); add(i, k, tan_half / lb);
        }
      }
    }

    const bool symmetric = (wts == Weights::UNIFORM);
    typedef typename internal::Default_tutte_solver<FT, std::is_same<FT, double>::value>::type Default_solver;
    // a non-symmetric system must not go to LDLT: LU for mean value weights in double too
    typedef typename internal::Default_tutte_solver<FT, false>::type LU_solver;

    auto solve = [&](auto solver) -> Error_code {
      typedef decltype(solver) Solver;
      typedef typename Solver::Matrix Matrix;
      typedef typename Solver::Vector Vector;
      typedef typename Solver::Index Index;
      Matrix A(static_cast<std::size_t>(n_int), static_cast<std::size_t>(n_int));
      Vector Bu(static_cast<Index>(n_int)), Bv(static_cast<Index>(n_int)), Xu(static_cast<Index>(n_int)), Xv(static_cast<Index>(n_int));
      for(long r = 0; r < n_int; ++r) { Bu[r] = internal::make_ft<FT>(0); Bv[r] = internal::make_ft<FT>(0); }
      for(std::size_t i = 0; i < nv; ++i)
      {
        if(row[i] < 0) continue;
        double diag = 0;
        for(const auto& e : adj[i])
        {
          diag += e.second;
          const FT w = internal::make_ft<FT>(e.second);
          if(row[e.first] >= 0)
            A.set_coef(row[i], row[e.first], -w, true);
          else
          {
            Bu[row[i]] += w * pos[e.first].x();
            Bv[row[i]] += w * pos[e.first].y();
          }
        }
        A.set_coef(row[i], row[i], internal::make_ft<FT>(diag), true);
      }
      FT D = internal::make_ft<FT>(1);
      if(!solver.factor(A, D)) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      if(!solver.linear_solver(Bu, Xu) || !solver.linear_solver(Bv, Xv)) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      for(std::size_t i = 0; i < nv; ++i)
        if(row[i] >= 0)
          pos[i] = Point_2(Xu[row[i]] / D, Xv[row[i]] / D);
      return OK;
    };

    Error_code sc;
    if constexpr(!CGAL::parameters::is_default_parameter<CGAL_NP_CLASS, CGAL::internal_np::sparse_linear_solver_t>::value)
      sc = solve(choose_parameter(get_parameter(np, CGAL::internal_np::sparse_linear_solver), Default_solver()));
    else if(symmetric)
      sc = solve(Default_solver());
    else
      sc = solve(LU_solver());
    if(sc != OK) return sc;
    for(std::size_t i = 0; i < nv; ++i)
      if(row[i] >= 0 && (!internal::is_finite_ft(pos[i].x()) || !internal::is_finite_ft(pos[i].y())))
        return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  }

  for(std::size_t i = 0; i < nv; ++i)
    if(!disk.on_border[i] || shape != Border_shape::FIXED)
      put(uvm, disk.vertices[i], pos[i]);
  return OK;
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_TUTTE_EMBEDDING_H
