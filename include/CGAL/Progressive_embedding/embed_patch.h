// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_EMBED_PATCH_H
#define CGAL_PROGRESSIVE_EMBEDDING_EMBED_PATCH_H

/// \file embed_patch.h
///
/// `embed_patch()`: a certified map of one patch of a mesh -- a range of its faces forming a
/// topological disk -- into the convex polygon that the patch's border vertices already have in
/// the uv map. This is the building block of constrained maps: the mesh is cut into patches by
/// traced paths, the path vertices are placed along the sides of convex polygons (so several
/// border vertices of a patch are collinear), and every patch is embedded in its polygon.
///
/// What the caller gives and gets:
///  - the patch: faces of `tm` (a disk: connected through its interior edges, not pinched at a
///    vertex, one border cycle, Euler characteristic 1). Its border may run along border edges
///    of `tm` and along interior edges of `tm` alike;
///  - the uv of the patch border vertices, read (never written) from the uv map: a convex
///    polygon traversed once, counterclockwise or clockwise, with strictly convex corners and any
///    number of vertices on the straight sides between them (no spike, no repeated point).
///    Everything is decided with the exact orientation predicate;
///  - the uv of the patch's interior vertices, written (and nothing else) on success: a map in
///    which every patch face is strictly positively oriented relative to the border, certified
///    exactly. On any error the uv map is left exactly as it was. Vertices that are not on the
///    patch are neither read nor written.
///  - a patch with a "flat chord" -- an interior edge joining two border vertices of one side,
///    which every map would flatten onto that side -- is refused with `ERROR_DEGENERATE_CHORD`;
///    `internal::find_flat_chords()` (internal/patch_chords.h) lists those edges so
///    that the caller can split them first. Without flat chord a valid map always exists.
///
/// How: the Tutte map (uniform weights, or the `weights` named parameter) with the border fixed,
/// solved in the uv number type (relative to a border vertex when that translation is exact on the
/// border: a small patch far from the origin keeps its digits); when it is not valid (floating point), the progressive embedding
/// of `progressive_embedding()` repairs it; the result is certified on the patch.
///
/// Internal variant for the constrained pipeline: internal::embed_patch_impl(tm, faces, uvm, np,
/// simple_border = true) accepts a border that is only a simple polygon (no repeated point, no two
/// edges touching), e.g. convex up to the rounding of path vertices placed on straight segments in
/// double (internal::place_path_vertices cannot put them exactly on their segments). No convexity
/// and no flat-chord test then: the caller splits the chords along one side beforehand
/// (internal::split_chords with Same_side_chord). Tutte and the repair run as usual and the same
/// exact certificate -- every face strictly oriented like the border, the border unchanged and
/// simple -- proves the patch map one-to-one (the degree argument needs a simple border only).
/// Errors as embed_patch(), with ERROR_NON_CONVEX_BORDER meaning "not simple".

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_statistics.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/internal/embed_patch_impl.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>

#include <functional>
#include <iostream>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// computes a certified planar map of a patch of a triangle mesh -- a range of its faces forming a
/// topological disk -- into the convex polygon given by the uv coordinates of the patch's border
/// vertices, writing the uv coordinates of the patch's interior vertices only.
///
/// The patch border may contain border edges of `tm` as well as interior edges of `tm`; its
/// vertices keep their uv bit-exactly. Their polygon must be convex and traversed once,
/// counterclockwise or clockwise (a clockwise polygon gives a clockwise map, the mirror image of a
/// valid one), with strictly convex corners and any number of collinear vertices along the sides,
/// no spike and no repeated point; all of it is decided with the exact orientation predicate. A
/// valid map with this border exists if and only if no interior edge of the patch joins two border
/// vertices on one straight side (a "flat chord": the part of the patch it cuts off would have
/// zero area; a face whose three vertices are on one side has such an edge). Such a patch is
/// refused with `ERROR_DEGENERATE_CHORD`; `internal::find_flat_chords()` lists the edges, which the
/// caller splits beforehand.
///
/// The interior vertices get the Tutte map of the patch with the border fixed (uniform weights,
/// or Floater's mean value weights, solved in the uv number type as by `tutte_embedding()`); when it
/// is not valid (in floating point), the progressive embedding of `progressive_embedding()` repairs
/// it (if the floating-point solve fails, the repair starts from every interior vertex at the
/// border's centroid). The result is certified on the patch, exactly: every patch face is strictly
/// oriented like the border polygon and the border is unchanged; with a simple, fixed border,
/// positive faces imply that the map is one-to-one (each point of the polygon is covered once).
///
/// Vertices of `tm` that are not on the patch are neither read nor written; border vertices of the
/// patch are only read. On any error the uv map is left exactly as it was.
///
/// \tparam TriangleMesh a model of `FaceGraph` (the patch faces must be triangles)
/// \tparam FaceRange a range of `boost::graph_traits<TriangleMesh>::%face_descriptor`
/// \tparam VertexUVMap a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type; its kernel's `FT` is the number type of the computation
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh, not modified
/// \param patch_faces the faces of the patch, each once
/// \param uvm the uv map: read on the patch border vertices, written on the patch interior vertices
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{weights}
///     \cgalParamDescription{the weights of the Tutte map}
///     \cgalParamType{`Weights`}
///     \cgalParamDefault{`Weights::UNIFORM`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points (mean value weights, distortion in the statistics), read on the patch only}
///     \cgalParamType{a model of `ReadablePropertyMap` with `Point_3` values}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{sparse_linear_solver}
///     \cgalParamDescription{the solver of the Tutte system, as in `tutte_embedding()`}
///     \cgalParamType{a class model of `SparseLinearAlgebraWithFactorTraits_d`}
///     \cgalParamDefault{as in `tutte_embedding()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits class whose exact orientation predicate decides every sign}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2` whose `Point_2` is the uv map's value type}
///     \cgalParamDefault{`Progressive_embedding_traits_2<K>`, `K` the kernel of the uv map's point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{seconds (wall clock, from the call) for the whole computation: the Tutte solve
///                           gets all of it, the repair what is left; `ERROR_BUDGET_EXHAUSTED` when exceeded}
///     \cgalParamType{`double` (a negative value or NaN gives `ERROR_WRONG_PARAMETER`)}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{invalid_energy_threshold, smoothing_iterations, retry_smoothing_iterations, insertion_retries,
///                    line_search_factor, line_search_steps, minimum_area_ratio, collapse_budget}
///     \cgalParamDescription{the settings of the repair, as in `progressive_embedding()`}
///     \cgalParamType{as in `progressive_embedding()`}
///     \cgalParamDefault{as in `progressive_embedding()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{verbose}
///     \cgalParamDescription{progress messages on `std::cerr`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{statistics}
///     \cgalParamDescription{receives what the repair did (all counts zero when the Tutte map was valid), the
///                           times, and in `report` the certificate of the patch's map (counts of the patch's faces
///                           and vertices; the overlap is decided by the degree argument)}
///     \cgalParamType{`Progressive_embedding_statistics*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK` only if the patch's map is certified; otherwise, with the uv map unchanged:
///         `ERROR_EMPTY_MESH` (no face), `ERROR_WRONG_PARAMETER` (a null or repeated face, or a named parameter
///         out of range), `ERROR_NON_TRIANGULAR_MESH`, `ERROR_NOT_A_DISK`, `ERROR_BORDER_TOO_SHORT`,
///         `ERROR_NON_FINITE_COORDINATES` (on the border), `ERROR_NON_CONVEX_BORDER` (including a spike or a
///         polygon winding more than once), `ERROR_DEGENERATE_BORDER` (repeated consecutive points, zero area),
///         `ERROR_DEGENERATE_CHORD`, `ERROR_BUDGET_EXHAUSTED`, `ERROR_COLLAPSE_FAILED`, `ERROR_INSERTION_FAILED`
///         or `ERROR_INVALID_EMBEDDING` (the repaired map failed the certificate)
template <typename TriangleMesh, typename FaceRange, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code embed_patch(const TriangleMesh& tm, const FaceRange& patch_faces, VertexUVMap uvm,
                       const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  return internal::embed_patch_impl(tm, patch_faces, uvm, np, false);
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_EMBED_PATCH_H
