// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_OPTIMIZE_DISTORTION_H
#define CGAL_PROGRESSIVE_EMBEDDING_OPTIMIZE_DISTORTION_H

/// \file optimize_distortion.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/distortion.h>
#include <CGAL/Progressive_embedding/internal/optimize_distortion_impl.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>

#include <functional>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// lowers the distortion of a valid planar map of a disk without ever leaving the set of valid maps:
/// every accepted step is certified (all faces positively oriented under the exact predicate and, with a
/// free border, the border polygon simple, also exactly; together they make the map injective). The minimized
/// energy is the sum over faces of the 3D area times the symmetric Dirichlet (or ARAP) energy against the 3D
/// triangle, the 3D mesh scaled so that its total area equals the area enclosed by the uv border. With a free
/// border, which changes that area, the symmetric Dirichlet energy is that of the map scaled uniformly to the 3D
/// area at every step, the measure `check_embedding()` reports: each iteration rescales the
/// 3D triangles to the map's current area and adds the derivative of that scale to the gradient (an energy against
/// triangles of a fixed area prefers a scale of its own, and the reported energy could rise). Without the barrier
/// term below, `Optimization_statistics::energy_after` is then below `energy_before` whenever a step was taken, up
/// to rounding. ARAP, which measures the scale too, keeps the 3D triangles at the input's area, and so do free hole
/// loops inside a fixed border (they change the area a little; the reported energy may then rise slightly).
///
/// An iteration is a projected Newton step: per-face Hessians projected to positive semi-definite matrices with
/// the closed-form eigensystem of isotropic energies, one sparse solve (a sparse LDLT whose symbolic factorization
/// is computed once, or, above 50,000 free vertices, bounded conjugate gradients, so that an iteration stays linear
/// in the mesh size), and a line search that starts below the first time any triangle would degenerate. When that
/// step gains little, or at the first iteration of a map whose faces are far from their 3D shape (e.g. the
/// \f$10^{-20}\f$-area faces that a repaired Tutte map keeps), a sweep of per-vertex Newton steps follows: each vertex
/// moves within its own star, so a single tiny face does not hold back the whole map. With a free border, the
/// border vertices of a sweep move first and are put back together unless the border stays simple and the energy
/// of the whole map falls.
///
/// <b>Free border.</b> Where the border closes on itself (e.g. the two sides of a cut at a cone whose angle exceeds
/// \f$2\pi\f$), a yes-or-no test of simplicity would let each step bring the two sides closer until the line search
/// stalls with them a few ulps apart. The minimized energy of a disk with a free border therefore has a barrier term:
/// each border vertex closer to a border edge (not its own) than half the shorter of their 3D edge lengths adds
/// \f$-w (1 - x)^2 \ln x\f$, \f$x\f$ the distance over that reach and \f$w\f$ the edge's squared 3D length (a vertex
/// one border vertex away from the edge only when the angle between them is reflex); its gradient and the
/// diagonal blocks of its Gauss-Newton Hessian enter the Newton step and the per-vertex steps, and every step is also
/// bounded by the first time a border vertex would reach a border edge. The line search thus sees the border
/// closing before the exact test refuses it; the exact tests and the certificate are unchanged. The reaches follow
/// the 3D triangles when they are rescaled to the map's area, the weights do not. The reported energies
/// (`Optimization_statistics`) are the certificate's, without the barrier: where the barrier acts, the minimized
/// sum may trade some of the reported energy for distance between the border's parts.
///
/// <b>Multiply connected maps.</b> The mesh may also be a connected genus-0 mesh with several border cycles, mapped
/// validly in the sense of `check_embedding()` with `multiply_connected(true)` (e.g. by the hole-filling embedding):
/// the outer cycle (largest uv area) is the border, fixed unless `free_border` is set, and the vertices of the holes
/// are free. Every accepted step keeps every face positive, every cycle simple and no two cycles touching (decided
/// exactly: all cycles against each other in the global line search, the two cycle edges of a moved hole vertex
/// against every cycle edge in the per-vertex sweeps), which makes the map valid again; the output is certified with
/// the multiply connected certificate. A mesh with several border cycles that is not connected or not of genus 0
/// gives `ERROR_NOT_GENUS_ZERO`.
///
/// <b>Immersions.</b> A map of a disk whose faces are all positive and whose border polygon overlaps itself (a map onto
/// a weakly self-overlapping polygon, as `constrained_embedding()` computes) is not valid, but it may be an immersion
/// (`check_immersion()`). Such a map is optimized as an immersion, with its border fixed: a step that keeps every
/// face positive keeps the winding number of every one-ring (an integer that varies continuously), so every accepted
/// step stays an immersion, and the output is certified by `check_immersion()` with its border compared bit-exactly
/// with the input's and every border fan wrapping around its vertex as many times as in the input (`Optimization_statistics::immersion` and `immersion_report`; `report` then holds the energies).
///
/// <b>Convergence criterion:</b> the function returns `OK` when two consecutive iterations each lower the mean
/// energy by less than `convergence_tolerance` (relative). On the repaired Tutte maps of real meshes this happens
/// after 100 to 500 iterations, at a point where ten times more iterations lower the energy by less than 5%.
///
/// Vertices listed in `constrained_vertices` and, unless `free_border` is set, the border vertices keep their
/// uv coordinates bit-exactly. The input must be a valid map (`check_embedding()`), e.g. the output of
/// `progressive_embedding()`. The uv number type may be `double`, an exact rational or MPFR: directions are
/// computed in double and applied and certified in the uv number type. On any error the uv map is left exactly as
/// it was; the output is written only once it is certified.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`: with the latter (TBB linked, floating-point uv),
///         the per-vertex sweeps move the vertices of each colour of a greedy colouring in parallel, and above
///         50,000 free vertices the conjugate gradients of the Newton steps run their products and sums in parallel
///         over fixed chunks of rows. The sequential sweeps visit the same colour classes in the same order, the
///         vertices of a class share no face, and the chunks' partial sums are added in the same order either way,
///         so the result is the sequential one bit for bit (tested)
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexUVMap a model of `ReadWritePropertyMap` with `Point_2` values
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh, not modified
/// \param uvm the uv map, read and written (constrained vertices are not written)
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the iteration budget; `ERROR_BUDGET_EXHAUSTED` (with a valid, improved map) when reached before convergence}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{1000}
///   \cgalParamNEnd
///   \cgalParamNBegin{convergence_tolerance}
///     \cgalParamDescription{converged when two consecutive iterations each lower the mean energy by less than this fraction; 0 runs the whole budget}
///     \cgalParamType{`double`, non-negative}
///     \cgalParamDefault{1e-5}
///   \cgalParamNEnd
///   \cgalParamNBegin{reuse_factorization}
///     \cgalParamDescription{whether a Newton step may reuse the factorization of the Hessian made by an earlier step
///                           (two triangular solves instead of a factorization): after a step with a fresh
///                           factorization, the next ones reuse it as long as each lowers the energy by at least half
///                           of what that step did; a reused step that fails its line search is made again at once
///                           with a fresh factorization, and only steps with a fresh one decide convergence.
///                           Maps of more than 50,000 free vertices use an iterative solver, where this does not apply.}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{time budget in seconds}
///     \cgalParamType{`double`}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{free_border}
///     \cgalParamDescription{let the border vertices move (the border stays a simple polygon, decided exactly; a barrier
///                           term of the energy keeps the border's parts apart where it closes on itself; the symmetric
///                           Dirichlet energy is measured at the 3D area, as the certificate does; see above)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{constrained_vertices}
///     \cgalParamDescription{vertices whose uv coordinates are hard constraints, kept bit-exactly (precondition: vertices of `tm`)}
///     \cgalParamType{a range of vertex descriptors, e.g. `std::vector<vertex_descriptor>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{distortion_energy}
///     \cgalParamDescription{the energy}
///     \cgalParamType{`Distortion_energy`}
///     \cgalParamDefault{`Distortion_energy::SYMMETRIC_DIRICHLET`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits class whose exact orientation predicate certifies every step}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2` whose `Point_2` is the uv map's value type}
///     \cgalParamDefault{`Progressive_embedding_traits_2<K>`, `K` the kernel of the uv map's point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points}
///     \cgalParamType{a model of `ReadablePropertyMap` with `Point_3` values}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called after each iteration with the fraction of the iteration budget used; returning `false` stops (`ERROR_BUDGET_EXHAUSTED`)}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{verbose}
///     \cgalParamDescription{per-iteration energies on `std::cerr`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{optimization_statistics}
///     \cgalParamDescription{receives what the optimization did and the certificate}
///     \cgalParamType{`Optimization_statistics*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK` when converged. `ERROR_BUDGET_EXHAUSTED` when a budget ran out first: the one status other than `OK`
///         with which a map is written, because it is certified valid and no worse than the input.
///         Nothing is written with any other status:
///         `ERROR_INVALID_EMBEDDING` if the input map is neither valid nor an immersion of a disk (its certificate is in
///         the statistics);
///         `ERROR_NON_FINITE_COORDINATES` if a uv or 3D coordinate is NaN or infinite;
///         `ERROR_NO_FREE_VERTEX` if every vertex is fixed (border and constraints);
///         `ERROR_DEGENERATE_3D_FACE` if the 3D faces have no area at all (faces of zero 3D area among others get an
///         equilateral reference of the mean area);
///         `ERROR_WRONG_PARAMETER` for a negative tolerance or time budget, or `free_border` on an immersion;
///         `ERROR_NOT_GENUS_ZERO` for several border cycles on a mesh that is not a connected genus-0 surface;
///         the disk errors of `check_embedding()` (`ERROR_NOT_A_DISK`, `ERROR_NON_MANIFOLD`, ...).
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code optimize_distortion(const TriangleMesh& tm, VertexUVMap uvm,
                               const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  return internal::optimize_distortion_impl<ConcurrencyTag>(tm, uvm, np);
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_OPTIMIZE_DISTORTION_H
