// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_PROGRESSIVE_EMBEDDING_H
#define CGAL_PROGRESSIVE_EMBEDDING_PROGRESSIVE_EMBEDDING_H

/// \file progressive_embedding.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_statistics.h>
#include <CGAL/Progressive_embedding/internal/progressive_embedding_impl.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Real_timer.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// repairs a planar map of a triangulated topological disk whose border is fixed on a convex
/// polygon and whose interior may be anything (a broken Tutte map, random points, all interior
/// vertices at one point): the result is certified valid by `check_embedding()`, the border is
/// bit-exactly unchanged, and so is the connectivity. The caller's mesh is not modified.
///
/// The border polygon may be weakly convex: strictly convex corners with any number of border
/// vertices on the straight sides between them (traversed once, no spike, no repeated point;
/// decided exactly). A valid map then exists unless an interior edge joins two border vertices
/// of one side (a "flat chord"; a face with its three vertices on one side has one), which is
/// refused with `ERROR_DEGENERATE_CHORD`. On a strictly convex border there is never a flat chord.
///
/// The algorithm is the one of Shen, Jiang, Zorin and Panozzo, *Progressive Embedding*
/// (SIGGRAPH 2019), section 3.2: interior edges of invalid faces (exact orientation not positive,
/// or symmetric Dirichlet energy not finite or above a threshold) are collapsed under the link
/// condition, growing the tagged region when stuck, until no face is invalid; then the collapses
/// are undone in reverse order, each new vertex placed by a flip-free line search towards link
/// vertices and link-edge midpoints of the valid sector (decided with exact predicates), followed by
/// local Newton smoothing that never lets a face flip. All work is local to the touched
/// neighbourhood. A consistently clockwise layout is handled as its mirror image.
///
/// Every decision is exact or relative to the map's own size (energies against a reference
/// triangle of the mean face area, area floors as fractions of it; the area summed relative to a
/// border vertex, so a small map far from the origin gets its own), so the function works at any
/// scale the number type represents. Where the border forces faces smaller than the mean -- an
/// edge between two border vertices much shorter than the reference side -- the threshold and the
/// floor of the faces on that edge are scaled by the squared ratio of the two lengths (the energy of
/// such a face is at least the inverse of that ratio wherever it is placed); a face with three border
/// vertices only needs to be positive, and so does a face that nothing can collapse or move any
/// more. A map whose border's bounding box is far from 1 (beyond
/// 2^32 or 2^-32) is worked on scaled by the power of two that brings that box to about 1 --
/// exact in binary floating point, `Gmpq` and `Gmpfr` -- and scaled back; the scaling is used only
/// if every border coordinate round-trips bit-exactly, so the border is never changed.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`; the present implementation
///         is sequential whatever the tag
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexUVMap a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type; its kernel's `FT` is the number type of the computation
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh, not modified
/// \param uvm the uv map: read everywhere, written on interior vertices
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits class whose exact predicates decide every sign of the repair and of its
///                           final certificate}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2` whose `Point_2` is the uv map's value type}
///     \cgalParamDefault{`Progressive_embedding_traits_2<K>`, `K` the kernel of the uv map's point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{invalid_energy_threshold}
///     \cgalParamDescription{faces whose symmetric Dirichlet energy against an equilateral triangle of the mean area exceeds it are invalid
///       (for a face on an edge between two border vertices shorter than that triangle's side, the threshold is divided by
///       their squared length ratio)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1e20}
///   \cgalParamNEnd
///   \cgalParamNBegin{smoothing_iterations}
///     \cgalParamDescription{maximal number of local smoothing passes over the 1-ring after each insertion; after the
///       first pass, only vertices whose neighbourhood still decreased its energy by more than 10% are stepped again}
///     \cgalParamType{`int`}
///     \cgalParamDefault{10 in floating point, 0 with an exact number type}
///   \cgalParamNEnd
///   \cgalParamNBegin{retry_smoothing_iterations}
///     \cgalParamDescription{maximal number of smoothing passes (down to a 0.1% energy decrease) before an insertion
///       that found no candidate is retried}
///     \cgalParamType{`int`}
///     \cgalParamDefault{50}
///   \cgalParamNEnd
///   \cgalParamNBegin{insertion_retries}
///     \cgalParamDescription{how often a failed insertion is retried before `ERROR_INSERTION_FAILED`}
///     \cgalParamType{`int`}
///     \cgalParamDefault{20}
///   \cgalParamNEnd
///   \cgalParamNBegin{line_search_factor}
///     \cgalParamDescription{backtracking factor of the candidate line search}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.8}
///   \cgalParamNEnd
///   \cgalParamNBegin{line_search_steps}
///     \cgalParamDescription{maximal backtracking steps per candidate}
///     \cgalParamType{`int`}
///     \cgalParamDefault{75}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_area_ratio}
///     \cgalParamDescription{faces whose area is below this fraction of the mean face area are collapsed too: in floating point
///       they leave too few bits for insertions nearby; larger values trade speed for quality (scaled like the energy
///       threshold on short edges between border vertices). When an insertion fails in floating point, the run
///       restarts with a higher floor (10^4 times higher up to 1e-4, then 1e-3, 1e-2 and 0.1)}
///     \cgalParamType{`double` in [0, 1)}
///     \cgalParamDefault{1e-12 in floating point, 0 with an exact number type}
///   \cgalParamNEnd
///   \cgalParamNBegin{collapse_budget}
///     \cgalParamDescription{maximal number of tag-expansion rounds of the simplification}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{unbounded (the mesh size bounds it)}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{time budget in seconds; `ERROR_BUDGET_EXHAUSTED` when exceeded}
///     \cgalParamType{`double`}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called during the insertion stage with the fraction done; returning `false` cancels (`ERROR_BUDGET_EXHAUSTED`)}
///     \cgalParamType{`std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{verbose}
///     \cgalParamDescription{progress messages on `std::cerr`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{statistics}
///     \cgalParamDescription{receives what the algorithm did and the certificate}
///     \cgalParamType{`Progressive_embedding_statistics*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK` only if the output is certified valid; otherwise `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`,
///         `ERROR_NON_MANIFOLD`, `ERROR_NOT_A_DISK`, `ERROR_NON_FINITE_COORDINATES`, `ERROR_NON_CONVEX_BORDER`,
///         `ERROR_DEGENERATE_BORDER`, `ERROR_DEGENERATE_CHORD`, `ERROR_WRONG_PARAMETER`, `ERROR_COLLAPSE_FAILED`, `ERROR_INSERTION_FAILED`, `ERROR_BUDGET_EXHAUSTED`
///         or `ERROR_INVALID_EMBEDDING`; the uv map is left unchanged on error.
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code progressive_embedding(const TriangleMesh& tm, VertexUVMap uvm,
                                 const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  return internal::progressive_embedding_impl<ConcurrencyTag>(tm, uvm, np);
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_PROGRESSIVE_EMBEDDING_H
