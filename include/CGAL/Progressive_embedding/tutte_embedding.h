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
#include <CGAL/Progressive_embedding/internal/tutte_embedding_impl.h>

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

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// computes Tutte's barycentric embedding (or Floater's mean value embedding) of a triangulated
/// topological disk into the plane, in the number type of the uv map. The border is taken from
/// the uv map as given (it must be convex, which is checked exactly, see below) or placed on a
/// circle, a square or a triangle by 3D arc length (runs of zero-length border edges share the length of the next
/// edge evenly, and a border of zero total length is spaced evenly, so that distinct border vertices
/// never get the same position). The same code runs with `double`, exact rationals and MPFR.
///
/// The linear system is solved by sparse LDLT (`double`, uniform weights) or sparse LU (`double`,
/// mean value weights) from Eigen. With `CGAL::Gmpq` it is solved exactly by p-adic lifting (Dixon):
/// one sparse LU factorization modulo a 62-bit prime in a fill-reducing order, lifting steps in
/// word-size integers for both coordinates at once, as many as a bound on the solution's size asks
/// (from the determinant, estimated by the same factorization in double; fewer when a probe finds the
/// common denominator earlier), rational reconstruction with a common denominator for a few seed
/// unknowns, the other numerators propagated through the rows by exact divisions, and an exact
/// verification of the solution (if it cannot conclude, a sparse Gaussian elimination in rationals
/// takes over). With `CGAL::Gmpfr` it is solved by iterative
/// refinement: the matrix is factored once in `double` (Eigen's LDLT, or its LU for mean value weights), and
/// the solution refined in MPFR (residual in MPFR with 64 guard bits, correction from the `double`
/// factors) until the correction is down to the last bits of the largest coordinate: a few steps, each
/// gaining about 53 - log2(cond A) bits, so that the work in MPFR is a few sparse products (0.32 s for
/// the 17,495 vertices of `man.off` at 256 bits, where the elimination in MPFR took 2.2 s in the same
/// run; 1.2 s against 21 s for a 50k-vertex grid). When the refinement cannot conclude (a value
/// beyond `double`'s range, no progress, entries more precise than the default precision), the sparse
/// Gaussian elimination in MPFR takes over, in place on MPFR numbers. In any other number type (other exact types) the system is solved by that sparse Gaussian
/// elimination in the number type itself.
/// These solvers report their progress to `callback` and stop at `maximum_running_time`. Another
/// solver can be given with `sparse_linear_solver` (then progress is reported only before and after
/// its factorization).
///
/// <b>Cost of exact arithmetic.</b> The rational solution has numerators and denominators of about
/// two bits per vertex each (8,108 bits for the 3,916 vertices of `dino.off` cut by the Tutte-failure
/// protocol, 40,441 bits for the 17,495 of `man.off`), so the exact map alone takes memory about
/// quadratic in the number of vertices (about 350 MB at 17,500 vertices) and its time grows faster
/// than that: the lifting takes a number of steps proportional to n (each gives 62 bits of the
/// solution), each a sparse triangular solve modulo p, and each of the 2n coordinates needs a product
/// and a division of integers of that size (its lowest terms). Certify such a map with `check_embedding()`
/// directly on the rationals: its predicates work on numerators and denominators, without the gcd that each
/// `CGAL::Gmpq` operation costs (about a second for `man.off`, where arithmetic in `CGAL::Gmpq` takes minutes).
/// The measured times and memory of the exact and MPFR maps and of their certificates from 4k to 100k vertices
/// are in `benchmark/results/exact_tutte.md`. Eigen's sparse LU over `CGAL::Gmpq`, for comparison, takes
/// 0.03 s for 100 unknowns, 1.35 s for 400 and 22.6 s for 1024 (time about cubic). Use `callback`
/// to show progress and `maximum_running_time` to bound the time.
///
/// A fixed border may be weakly convex: strictly convex corners with any number of border vertices
/// on the straight sides between them (a polygon traversed once, counterclockwise or clockwise, no
/// spike, no repeated point; decided exactly). Then an interior edge joining two border vertices
/// of one side (a "flat chord"; a face with its three vertices on one side has one) would
/// be flattened onto that side in every map: the function refuses it with `ERROR_DEGENERATE_CHORD`
/// (splitting such an edge at an interior point removes it). On a strictly convex border there is
/// never a flat chord. The borders placed by
/// `Border_shape::SQUARE` and `Border_shape::TRIANGLE` are not checked for flat chords: a border
/// vertex of degree 2 off a corner (an ear) gets a degenerate face there.
///
/// In exact arithmetic the result is a valid embedding when the border is strictly convex
/// (Tutte's theorem), or weakly convex without flat chord (Floater, 2003: no dividing edge);
/// in floating point it may be invalid: certify it with `check_embedding()`.
/// The function does not certify its output; `progressive_embedding()` repairs it.
/// On every error, the uv map is left unchanged.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`: with the latter (TBB linked) and
///         `CGAL::Gmpq` coordinates, the p-adic solve lifts the two coordinates on two threads and reconstructs
///         the fractions in two halves at the same time (about 1.8 times faster on two cores); the result is
///         the same. Other number types ignore it
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
///     \cgalParamDefault{`CGAL::Eigen_solver_traits` over `Eigen::SimplicialLDLT` (double, uniform weights) or
///                      `Eigen::SparseLU` with COLAMD ordering (double, mean value weights); with uniform weights in
///                      double and 100,000 interior vertices or more, conjugate gradients preconditioned by
///                      `Smoothed_aggregation_preconditioner` to a relative residual of \f$10^{-10}\f$ (see the manual's
///                      section "The Linear Solver and Large Meshes"); with `CGAL::Gmpq`, the package's p-adic solve; with
///                      `CGAL::Gmpfr`, the package's iterative refinement; in other number types, the package's sparse
///                      elimination}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits class whose exact orientation predicate checks the border and the triangle
///                           corners; its `Point_2` is the uv map's value type}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2`}
///     \cgalParamDefault{`Progressive_embedding_traits_2<K>`, `K` the kernel of the uv map's point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called during the solve with the fraction of the work done, in [0,1] and non-decreasing
///                           (at 0, at most about every thousandth, and at 1); returning `false` stops the
///                           computation with `ERROR_BUDGET_EXHAUSTED`}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{the solve stops with `ERROR_BUDGET_EXHAUSTED` once this many seconds (wall clock, from the
///                           call) have passed; checked at every row update of the elimination, and before and after
///                           the factorization of the floating-point solvers (which cannot be interrupted)}
///     \cgalParamType{`double` (a negative value or NaN gives `ERROR_WRONG_PARAMETER`)}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK`, `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`, `ERROR_NON_MANIFOLD`, `ERROR_NOT_A_DISK`,
///         `ERROR_BORDER_TOO_SHORT`, `ERROR_NON_FINITE_COORDINATES`, `ERROR_NON_CONVEX_BORDER`,
///         `ERROR_DEGENERATE_BORDER`, `ERROR_DEGENERATE_CHORD` (fixed border only), `ERROR_WRONG_PARAMETER`,
///         `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM` or `ERROR_BUDGET_EXHAUSTED` (the uv map is then unchanged)
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh, typename VertexUVMap,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code tutte_embedding(const TriangleMesh& tm,
                           typename boost::graph_traits<TriangleMesh>::halfedge_descriptor bhd,
                           VertexUVMap uvm,
                           const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  return internal::tutte_embedding_impl<ConcurrencyTag>(tm, bhd, uvm, np);
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_TUTTE_EMBEDDING_H
