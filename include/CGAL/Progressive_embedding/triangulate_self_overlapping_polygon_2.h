// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_TRIANGULATE_SELF_OVERLAPPING_POLYGON_2_H
#define CGAL_PROGRESSIVE_EMBEDDING_TRIANGULATE_SELF_OVERLAPPING_POLYGON_2_H

/// \file triangulate_self_overlapping_polygon_2.h
/// Triangulation of simple and weakly self-overlapping polygons (the border of an immersed disk),
/// with the polygon's vertices only: `triangulate_self_overlapping_polygon_2()`.

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Polygon_triangulation_report.h>
#include <CGAL/Progressive_embedding/internal/self_overlapping/triangulate_polygon_impl.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Real_timer.h>
#include <boost/range/value_type.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <type_traits>
#include <limits>
#include <new>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// triangulates a closed polygon that is simple or weakly self-overlapping, using its vertices only.
///
/// The polygon is `points` in order, the last point joined to the first. It is *weakly self-overlapping*
/// when it is the border of an immersed disk: a disk mapped into the plane by a locally injective map,
/// which may cover some regions several times (Shor and Van Wyk 1992; Weber and Zorin 2014). Simple
/// polygons are the special case of an embedded disk. The function decides this exactly and, if so,
/// writes a triangulation of that disk: exactly `n - 2` index triples into `points` (`n` its size), each
/// a triangle that is strictly counterclockwise under the traits' exact orientation predicate; every
/// polygon edge belongs to exactly one triangle, every other pair used (a diagonal) to exactly two, and
/// the triangles glued along the diagonals form a disk whose border is the polygon and which the
/// positions of `points` map locally injectively into the plane. Collinear consecutive vertices (flat
/// angles) and vertices lying exactly on a diagonal are allowed; a triangle never has three collinear
/// corners.
///
/// A clockwise polygon (rotation number -1) is accepted: it is the same polygon traversed the other way,
/// and its triangles are still written counterclockwise (so each of them lists its polygon edges in the
/// order opposite to the input's); `Polygon_triangulation_report::clockwise` says so.
///
/// Algorithm: exact checks of the input (repeated consecutive points, reversals, rotation number +1 or
/// -1), then CGAL's `Constrained_Delaunay_triangulation_2` of the polygon's edges (exact predicates), which is
/// also the exact simplicity test: a simple polygon is triangulated by its inside faces, in O(n log n) in
/// practice. Any other polygon (including one that touches itself at a vertex) goes through the Shor-Van
/// Wyk dynamic program over the chords (i, j), with every triangle and every fan around a vertex tested
/// exactly, pruned by exact necessary conditions (a chord must leave both ends inside the polygon's angle
/// there and cut off a sub-polygon of rotation number 1): O(n^2) chord tests plus O(n) per chord that
/// passes them, so O(n^3) time in the worst case; no recursion. Some polygons bound several different
/// immersed disks: the triangulation is then one of them. Whatever the start vertex, the decision is the same.
///
/// <b>Angles beyond a full turn.</b> The border of an immersed disk may wrap around one of its vertices more
/// than once: the disk's angle there exceeds 2 pi (a border vertex of a seamless parametrization cut through
/// a cone, for instance). The positions give each angle only modulo 2 pi, so such a polygon needs its
/// *rotation indices*: `r[v]` full turns added to the angle at `v` (its angle in (0, 2 pi), counterclockwise
/// from `v -> next` to `v -> prev`). With any index positive the polygon must be counterclockwise and its rotation number
/// minus the sum of the indices must be 1; the disk is then found by cutting at a vertex with a positive index
/// along every chord and lift in turn (complete; exponential in the number of such vertices in the worst case,
/// bounded by `maximum_running_time`). Every triangle is still strictly positive, and the fan at `v` covers
/// exactly its angle, so the fan of a vertex with index `r[v]` wraps `r[v]` more times around it.
///
/// Memory: O(n) words plus one 32-bit word per chord found valid by the dynamic program (at most
/// n(n-1)/2 of them, so at most about 2 n^2 bytes, 4 n^2 with the vectors' growth; the report's
/// `chords_stored`) and a byte per vertex; the simple path stores a triangulation of the n points.
/// For instance a strip of 16000 vertices winding twice around a spiral stores 3.1 10^7 chords (160 MB
/// peak, about 10 s on one core); simple polygons of 16000 vertices take under 0.1 s and 5 MB.
///
/// \tparam PointRange a model of `ConstRange` whose value type is the traits' `Point_2`
/// \tparam TriangleOutputIterator a model of `OutputIterator` accepting `std::array<std::size_t, 3>`
/// \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
///
/// \param points the polygon's vertices in order
/// \param triangles receives the `n - 2` triangles on success, nothing otherwise
/// \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits class whose exact orientation predicate decides every sign}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2` whose `Point_2` is the value type of `points`}
///     \cgalParamDefault{`Progressive_embedding_traits_2<K>`, `K` the kernel of the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{seconds (wall clock, from the call) for the whole computation;
///                           `ERROR_BUDGET_EXHAUSTED` when exceeded (checked at least every 2^20 elementary steps)}
///     \cgalParamType{`double` (a negative value or NaN gives `ERROR_WRONG_PARAMETER`)}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{rotation_indices}
///     \cgalParamDescription{the rotation index of every vertex, in the order of `points`: full turns added to its angle}
///     \cgalParamType{`std::vector<int>`, of the size of `points`, every entry at least 0 (else `ERROR_WRONG_PARAMETER`)}
///     \cgalParamDefault{all 0: every angle in (0, 2 pi)}
///   \cgalParamNEnd
///   \cgalParamNBegin{polygon_report}
///     \cgalParamDescription{receives the rotation number, orientation, simplicity, which path was taken and the
///                           dynamic program's counts}
///     \cgalParamType{`Polygon_triangulation_report*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK` with the triangles written; otherwise nothing is written and the result is
///         `ERROR_BORDER_TOO_SHORT` (fewer than 3 points), `ERROR_NON_FINITE_COORDINATES`,
///         `ERROR_NOT_SELF_OVERLAPPING` (the polygon is neither simple nor weakly self-overlapping; this includes
///         repeated consecutive points, a reversal (an angle of 0 or 2 pi), a rotation number other than +1 or -1,
///         a figure-eight), `ERROR_BUDGET_EXHAUSTED` (the time budget, or the memory, ran out), or `ERROR_WRONG_PARAMETER`
///         (a negative or NaN time budget, more than 2^32 - 1 points).
template <typename PointRange, typename TriangleOutputIterator, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code triangulate_self_overlapping_polygon_2(const PointRange& points, TriangleOutputIterator triangles,
                                                  const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  return internal::triangulate_self_overlapping_polygon_2_impl(points, triangles, np);
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_TRIANGULATE_SELF_OVERLAPPING_POLYGON_2_H
