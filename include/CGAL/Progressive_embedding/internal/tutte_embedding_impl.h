// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_EMBEDDING_IMPL_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_EMBEDDING_IMPL_H

// The body of tutte_embedding(): the border placement, the interior solve (by number type) and
// the named parameters that choose them.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Progressive_embedding/internal/tutte_border.h>
#include <CGAL/Progressive_embedding/internal/tutte_system.h>
#include <CGAL/Progressive_embedding/internal/tutte_solve.h>
#include <CGAL/Progressive_embedding/internal/tutte_p_adic.h>
#include <CGAL/Progressive_embedding/internal/tutte_refinement.h>
#include <CGAL/Progressive_embedding/internal/patch_chords.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Kernel_traits.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// Places the border vertices (`bpos`, in border order) as the named parameters ask.
template <class TriangleMesh, class VertexUVMap, class VPM, class Traits, class NamedParameters>
Error_code place_border(const Indexed_disk<TriangleMesh>& disk, VertexUVMap uvm, VPM vpm, const Traits& traits,
                        const NamedParameters& np, std::vector<typename Traits::Point_2>& bpos)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename Traits::Point_2 Point_2;
  typedef typename Traits::FT FT;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const Border_shape shape = choose_parameter(get_parameter(np, internal_np::border_shape), Border_shape::FIXED);
  if(shape == Border_shape::FIXED) return fixed_border(disk, uvm, traits, bpos);
  const std::vector<double> s = border_arc_length(disk, vpm);
  if(shape == Border_shape::CIRCLE) { circle_border<FT>(s, bpos); return OK; }
  if(shape == Border_shape::SQUARE) return square_border<FT>(s, bpos);
  std::vector<std::size_t> ci;
  if(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::triangle_corners_t>::value)
  {
    const std::array<vertex_descriptor, 3> corners =
      choose_parameter(get_parameter(np, internal_np::triangle_corners), std::array<vertex_descriptor, 3>());
    const Error_code ec = corner_positions(disk, corners, ci);
    if(ec != OK) return ec;
  }
  const std::array<Point_2, 3> cp = choose_parameter(get_parameter(np, internal_np::triangle_corner_points),
                                                     default_triangle_corner_points<Point_2>());
  return triangle_border<FT>(s, ci, cp, traits, bpos);
}

// Solves the system with the solver the named parameters give, or the default one for FT:
// Eigen (LDLT or LU) in floating point, p-adic lifting for Gmpq, iterative refinement from a double
// factorization for MPFR, the elimination in FT otherwise (and when those cannot conclude).
// `multigrid`: the default double solver may be the multigrid one for a large system (see
// default_tutte_solver_is_multigrid()); the patches of constrained maps always solve directly.
template <class ConcurrencyTag = CGAL::Sequential_tag, class FT, class NamedParameters>
Error_code solve_tutte_system(Tutte_system<FT>& S, bool symmetric, const NamedParameters& np,
                              Progress_budget& budget, std::vector<FT>& xu, std::vector<FT>& xv, bool multigrid = false)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename Default_tutte_solver<FT, std::is_same<FT, double>::value>::type Default_solver;
  // a non-symmetric system must not go to LDLT: LU for mean value weights in double too
  typedef typename Default_tutte_solver<FT, false>::type LU_solver;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::sparse_linear_solver_t>::value)
    return solve_with_solver_traits(S, choose_parameter(get_parameter(np, CGAL::internal_np::sparse_linear_solver),
                                                        Default_solver()), budget, xu, xv);
  else if constexpr(std::is_same<FT, double>::value)
    // symmetric: Eigen's LDLT, or for large systems the multigrid solve or CHOLMOD, on a matrix built in place
    return symmetric ? solve_symmetric_default(S, budget, xu, xv, multigrid) : solve_with_solver_traits(S, LU_solver(), budget, xu, xv);
  else if constexpr(std::is_floating_point<FT>::value)
    return symmetric ? solve_with_solver_traits(S, Default_solver(), budget, xu, xv)
                     : solve_with_solver_traits(S, LU_solver(), budget, xu, xv);
  else if constexpr(std::is_same<FT, CGAL::Gmpq>::value)
  {
    // p-adic lifting, verified; rational elimination when it cannot conclude
    const Error_code ec = solve_by_p_adic_lifting<ConcurrencyTag>(S, budget, xu, xv);
    return (ec == ERROR_CANNOT_SOLVE_LINEAR_SYSTEM) ? solve_by_elimination(S, budget, xu, xv) : ec;
  }
  else if constexpr(std::is_same<FT, CGAL::Gmpfr>::value)
  {
    // refined from a double factorization; the elimination in MPFR when the refinement cannot conclude
    const Error_code ec = solve_by_refinement(S, symmetric, budget, xu, xv);
    return (ec == ERROR_CANNOT_SOLVE_LINEAR_SYSTEM) ? solve_by_elimination(S, budget, xu, xv) : ec;
  }
  else
    return solve_by_elimination(S, budget, xu, xv);
}

// The interior positions of the Tutte map of `disk` (weights, solver, callback and time as the
// named parameters of tutte_embedding() say), given the border positions in `pos` (by vertex
// index); `pos` is written on the interior vertices only (the solution; on failure, (0, 0) or part
// of the solution). `faces_to_release`: the faces of a disk that only this solve needs (those of
// `disk` itself, at the caller's choice), released once the system is assembled, before the
// factorization, whose peak they would add to (50 MB at 1M vertices). `multigrid`: as in solve_tutte_system().
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class VPM, class Point_2, class NamedParameters>
Error_code tutte_interior(const Indexed_disk<TriangleMesh>& disk, VPM vpm, const NamedParameters& np,
                          Progress_budget& budget, std::vector<Point_2>& pos,
                          std::vector<std::array<std::size_t, 3> >* faces_to_release = nullptr, bool multigrid = false)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel::FT FT;
  if(disk.number_of_interior_vertices() == 0) return OK;
  const Weights wts = choose_parameter(get_parameter(np, internal_np::weights), Weights::UNIFORM);
  Tutte_system<FT> S;
  {
    std::vector<std::vector<std::pair<std::size_t, double> > > adj;
    const Error_code status = tutte_weights(disk, vpm, wts, adj);
    if(status != OK) return status;
    assemble_tutte_system(disk, adj, pos, S);
  } // the weights are released before the solve
  // what the solve does not read is released before its peak: the faces (at the caller's choice), the
  // vertex -> unknown map (the unknowns are the interior vertices in index order) and `pos` (16 MB at 1M
  // vertices in double), its border entries kept aside
  if(faces_to_release != nullptr) std::vector<std::array<std::size_t, 3> >().swap(*faces_to_release);
  std::vector<long>().swap(S.row);
  const std::size_t nv = disk.number_of_vertices();
  std::vector<std::pair<std::size_t, Point_2> > fixed;
  fixed.reserve(nv - S.n);
  for(std::size_t i = 0; i < nv; ++i)
    if(disk.on_border[i]) fixed.emplace_back(i, pos[i]);
  std::vector<Point_2>().swap(pos);
  std::vector<FT> xu, xv;
  const Error_code status = solve_tutte_system<ConcurrencyTag>(S, wts == Weights::UNIFORM, np, budget, xu, xv, multigrid);
  pos.assign(nv, Point_2(0, 0));
  for(const auto& f : fixed) pos[f.first] = f.second;
  if(status != OK) return status;
  for(std::size_t i = 0, r = 0; i < nv; ++i)
  {
    if(disk.on_border[i]) continue;
    pos[i] = Point_2(xu[r], xv[r]);
    ++r;
    if(!is_finite_ft(pos[i].x()) || !is_finite_ft(pos[i].y()))
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  }
  return OK;
}

// the body of tutte_embedding() (see its documentation there); `given`: the disk already indexed from `tm`
// with the border cycle of `bhd` by the caller (a pipeline indexes once), or null
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh, typename VertexUVMap,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code tutte_embedding_impl(const TriangleMesh& tm,
                                typename boost::graph_traits<TriangleMesh>::halfedge_descriptor bhd,
                                VertexUVMap uvm,
                                const CGAL_NP_CLASS& np = CGAL::parameters::default_values(),
                                const Indexed_disk<TriangleMesh>* given = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename internal::Uv_map_types<VertexUVMap>::Traits                    Default_traits;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
            CGAL::internal_np::geom_traits_t, CGAL_NP_CLASS, Default_traits>::type  Traits;
  typedef typename Traits::Point_2                                                Point_2;
  static_assert(std::is_same<Point_2, typename internal::Uv_map_types<VertexUVMap>::Point_2>::value,
                "the geom_traits' Point_2 must be the value type of the uv map");

  const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const Border_shape shape = choose_parameter(get_parameter(np, internal_np::border_shape), Border_shape::FIXED);
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  const double max_seconds = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time),
                                              std::numeric_limits<double>::infinity());
  if(!(max_seconds >= 0)) return ERROR_WRONG_PARAMETER;

  internal::Indexed_disk<TriangleMesh> own;
  Error_code status = given ? OK : internal::make_indexed_disk(tm, bhd, own);
  if(status != OK) return status;
  const internal::Indexed_disk<TriangleMesh>& disk = given ? *given : own;
  const std::size_t nv = disk.number_of_vertices(), nb = disk.border.size();
  if(nb < 3) return ERROR_BORDER_TOO_SHORT;

  std::vector<Point_2> bpos;
  status = internal::place_border(disk, uvm, vpm, traits, np, bpos);
  if(status != OK) return status;
  std::vector<Point_2> pos(nv);
  for(std::size_t k = 0; k < nb; ++k) pos[disk.border[k]] = bpos[k];

  if(shape == Border_shape::FIXED)
  {
    // a weakly convex border: an interior edge along one of its sides would be flattened
    std::vector<std::pair<std::size_t, std::size_t> > chords;
    internal::flat_chords(disk, bpos, traits.exact_orientation_2_object(), chords);
    if(!chords.empty()) return ERROR_DEGENERATE_CHORD;
  }

  internal::Progress_budget budget(callback, max_seconds);
  // the disk indexed here is not needed after the solve but for its vertices: its faces go before the factorization
  // a whole mesh's map, certified (and repaired) after: a large system may be solved by the multigrid solve
  status = internal::tutte_interior<ConcurrencyTag>(disk, vpm, np, budget, pos, given ? nullptr : &own.faces, true);
  if(status != OK) return status;

  // written only now: on every error the uv map is left as it was
  for(std::size_t i = 0; i < nv; ++i)
    if(!disk.on_border[i] || shape != Border_shape::FIXED)
      put(uvm, disk.vertices[i], pos[i]);
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_TUTTE_EMBEDDING_IMPL_H
