// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_CONSTRAINED_EMBEDDING_H
#define CGAL_PROGRESSIVE_EMBEDDING_CONSTRAINED_EMBEDDING_H

/// \file constrained_embedding.h
///
/// `constrained_embedding()`: a certified planar map of a disk-topology triangle mesh in which
/// chosen interior vertices land exactly on given points (MatchMaker++). The pipeline:
///  1. validation on the caller's mesh (a triangulated disk; constraints interior, distinct,
///     finite), border uv (fixed from the uv map, or a border shape);
///  2. the domain cut into convex polygons whose corners are border points and targets
///     (internal::partition_domain); a clockwise border is mirrored (x -> -x, exact) so that the
///     polygons' counterclockwise order is the orientation of the mesh faces, and mirrored back;
///  3. on a Surface_mesh copy, the polygons' interior edges traced as paths of mesh edges
///     (internal::trace_paths, edge splits where blocked; when that runs out of its budget, as curves
///     over the input edges refined once, internal::trace_paths_overlay), then the chords along one
///     path or one straight border side split (no map into a convex polygon keeps them);
///  4. path vertices placed on their segments by 3D arc length (internal::place_path_vertices):
///     in floating point they are only within an ulp of the segment, so each patch border is a
///     simple polygon convex up to rounding; a face whose three vertices are on the path network and
///     which rounding left flat or negative (at a corner sharper than an ulp allows) gets its chord
///     split (an interior vertex that the patch map can place); each patch is embedded by
///     internal::embed_patch_impl(..., simple_border = true) (Tutte + repair, every face certified
///     strictly positive, border simple and unchanged);
///  5. the whole map certified by check_embedding() (positive faces + simple fixed border: one-to-
///     one), then optimize_distortion() with border and constrained vertices fixed, certified again;
///     then the coarsening (internal/constrained/coarsen.h): each added vertex, latest first, is
///     removed into an end of the edge it split wherever every face of the fan is strictly positive
///     (exact), and the map is certified again;
///  6. the edge splits replayed on the caller's mesh (internal::replay_splits; same split
///     convention), then the coarsening's removals (internal::replay_removals), the uv of every
///     vertex written.
/// Holes: filled with fans on the copy (internal::fill_holes), the regions the fans became removed
/// after step 5's first certificate (tracked through the splits), then certified multiply connected.
/// Nothing of the caller's mesh or uv map is touched before step 6, which cannot fail. Each step is a method of
/// internal::Constrained_embedder (internal/constrained/constrained_embedder.h), which times itself into the statistics.

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Constrained_embedding_statistics.h>
// the certificates a caller runs on the map (its statistics hold their reports)
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/check_immersion.h>
#include <CGAL/Progressive_embedding/internal/constrained/constrained_embedder.h>

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// computes a certified planar map of a disk-topology triangle mesh in which every constrained interior vertex
/// lands bit-exactly on its target point, refining the mesh where needed (MatchMaker++).
///
/// The domain (the border polygon, fixed from `uvm` or given by a border shape) is cut into convex polygons
/// whose corners are the border points and the targets; their interior edges are traced on the mesh as
/// non-crossing paths of edges between the corresponding vertices (edges are split at their midpoints where a path
/// is blocked, and where an edge joins two vertices of one path or of one straight border side); the path
/// vertices are placed on their segments by 3D arc length; each patch is mapped into its polygon (Tutte's map,
/// repaired by the progressive embedding when not valid in floating point). A patch that cannot be mapped so (its
/// polygon a needle too thin for its vertices in floating point, when targets lie within a few ulps of each other)
/// is mapped together with neighbouring patches into the union of their polygons, the paths between them free
/// and every constrained vertex still on the union's border. The whole map is then certified by
/// `check_embedding()` and its distortion optimized (`optimize_distortion()`) with the border and the constrained
/// vertices fixed, and certified again. Last, the <b>coarsening</b> removes the added vertices that the map can do
/// without: each one, latest first, is removed and its star replaced by the fan from an end of the edge it split,
/// wherever every face of that fan is strictly positive (exact orientation); nothing else moves, so the border and
/// the constraints stay bit-exact, and the whole map is certified again (`Constrained_embedding_statistics` counts the
/// vertices inserted, removed and kept). Each face of such a fan lies in an input face, so the output is still a
/// refinement of the input surface. When vertices were removed and the map is optimized, the optimization runs again
/// on the coarser mesh with what is left of its time (the fans are shaped by the removal only), and the map is
/// certified again.
///
/// The computation runs on a `Surface_mesh` copy: on any error `tm` and `uvm` are left exactly as they were. On
/// success the edge splits are replayed on `tm` (`Euler::split_edge` at the midpoint, then `Euler::split_face`
/// joining the new vertex to the opposite corner of each incident face; or, when the paths were traced as curves
/// over the input edges, several midpoint splits along one input edge followed by `Euler::split_face` across the
/// faces), then the coarsening's removals (`Euler::remove_center_vertex`, then `Euler::split_face` for the fan; a
/// `Surface_mesh` keeps the removed vertices as garbage until `collect_garbage()`): the input vertices keep their
/// descriptors and 3D points and come first in the vertex order, the new vertices (at edge midpoints, so on the
/// input surface) follow; the uv of every vertex is written. The map is certified by `check_embedding()`, every
/// constrained vertex is bit-exactly at its target and, with `Border_shape::FIXED`, the border bit-exactly
/// unchanged. A clockwise border gives a clockwise map (the mirror image of a valid one).
///
/// <b>Holes</b>: a connected genus-0 mesh with several border cycles is accepted. Its outer cycle (the longest in
/// 3D) gets the border (fixed from `uvm` or the shape); every other cycle (a hole) is closed on the working copy by
/// a fan around a new vertex, the disk is mapped as above, and once that map is certified the faces that the fans
/// became (after the splits) are removed: the restriction of a one-to-one map is one-to-one, each hole is the image
/// of a disk bounded by its loop. The result is certified by `check_embedding()` with `multiply_connected(true)`
/// and optimized with the hole loops free. Steiner vertices inside a hole are removed with it; those on a hole loop
/// (an edge of the loop split) are kept (they lie on the input surface's boundary).
///
/// <b>Non-convex borders</b> (`Border_shape::FIXED` only): a simple non-convex border polygon is cut into convex
/// polygons the same way (its reflex corners keep interior edges, some of them between two border points); the
/// result is an embedding, certified and optimized as above. A border polygon that is not simple but weakly
/// self-overlapping (it bounds an immersed disk: `triangulate_self_overlapping_polygon_2()`) is cut along its
/// Shor-Van Wyk triangulation, merged into convex pieces; the map is then an immersion (locally injective,
/// overlapping itself), certified by `check_immersion()` with the border bit-exactly the given polygon
/// (`Constrained_embedding_statistics::immersion` and `immersion_report`), then optimized as an immersion (border
/// fixed, every step keeping every face positive, the output certified again by `check_immersion()`: see
/// `optimize_distortion()`). Constraints need a simple border (a target of an overlapping domain could lie
/// on several sheets): with a self-overlapping border they give `ERROR_CONSTRAINT_OUTSIDE_DOMAIN`; a border that is
/// not even weakly self-overlapping gives `ERROR_NOT_SELF_OVERLAPPING`; holes need a simple outer border
/// (`ERROR_NOT_A_DISK` otherwise).
///
/// <b>Borders that wrap around a vertex</b>: the border of an immersed disk may turn around one of its vertices
/// more than once (the disk's angle there exceeds 2 pi: a border vertex of a seamless parametrization cut through
/// a cone, for instance). The uv positions give the angle only modulo 2 pi: `vertex_rotation_index_map` gives the
/// full turns to add (for a given valid map, the sum of its face angles at the vertex divided by 2 pi, rounded
/// down; `pe constrain` reads them so from its input). The border is then triangulated with these
/// `rotation_indices` and the map is an immersion as above.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (`CGAL::Parallel_if_available_tag` picks
///         the latter when TBB is linked): with `CGAL::Parallel_tag` and a floating-point uv number type the path
///         vertices are placed and the patches mapped in parallel (they are independent: the certified map before the
///         optimization is bit-for-bit the sequential one), and `optimize_distortion()` runs with the same tag (it
///         moves the vertices of one colour class at a time, which share no face: the same sweeps as in sequence).
///         Exact number types always run sequentially.
/// \tparam TriangleMesh a model of `MutableFaceGraph` (triangles)
/// \tparam ConstraintRange a range of `std::pair<vertex_descriptor, Point_2>` (`Point_2` the uv map's value type)
/// \tparam VertexUVMap a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type; its kernel's `FT` is the number type of the computation
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh, refined on success
/// \param constraints the constrained interior vertices of `tm` and their targets, strictly inside the domain
/// \param uvm the uv map: read on the border with `Border_shape::FIXED`, written on every vertex on success
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{border_shape}
///     \cgalParamDescription{the border: fixed from `uvm` (convex, flat vertices allowed; or non-convex, see above), or a shape as in `tutte_embedding()`}
///     \cgalParamType{`Border_shape`}
///     \cgalParamDefault{`Border_shape::FIXED`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_rotation_index_map}
///     \cgalParamDescription{with `Border_shape::FIXED`: the rotation index of every border vertex, the full turns
///                           (multiples of 2 pi) to add to the border's angle there, for a border that wraps around
///                           some of its vertices (see above); read at border vertices only}
///     \cgalParamType{a readable vertex property map with integral values, each at least 0 (else `ERROR_WRONG_PARAMETER`)}
///     \cgalParamDefault{all 0}
///   \cgalParamNEnd
///   \cgalParamNBegin{triangle_corner_points}
///     \cgalParamDescription{the corners of `Border_shape::TRIANGLE`, as in `tutte_embedding()`}
///     \cgalParamType{`std::array<Point_2, 3>`}
///     \cgalParamDefault{as in `tutte_embedding()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{weights}
///     \cgalParamDescription{the weights of the Tutte map of each patch}
///     \cgalParamType{`Weights`}
///     \cgalParamDefault{`Weights::UNIFORM`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points (read; written on the added vertices)}
///     \cgalParamType{a model of `ReadWritePropertyMap` with `Point_3` values}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{seconds (wall clock) for the whole computation; `ERROR_BUDGET_EXHAUSTED` when exceeded
///                           before the map is certified (the optimization gets what is left and stops early)}
///     \cgalParamType{`double` (negative or NaN: `ERROR_WRONG_PARAMETER`)}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_steiner_vertices}
///     \cgalParamDescription{the largest number of vertices path tracing may add. The paths are traced as
///                           shortest paths first; when these exceed their budget or add more than a tenth of the
///                           vertices, they are traced again as curves over the input edges (meshes without holes),
///                           then guided by a drawing of the partition (unless the curves added more than 4 times
///                           the mesh's vertices), and the result with the fewest Steiner vertices is kept. A value
///                           given here bounds every tracing}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{shortest paths: 2 times the number of vertices plus 1000; curves over the input edges: 128 times
///                       the number of edges plus 10000; guided paths: 32 times the number of edges plus 10000}
///   \cgalParamNEnd
///   \cgalParamNBegin{optimize}
///     \cgalParamDescription{whether to optimize the distortion of the certified map (border and constraints fixed)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{optimization_time_limit}
///     \cgalParamDescription{seconds (wall clock) for the optimization: it stops there with its certified, improved map
///                           (`Constrained_embedding_statistics::optimization_status` is then `ERROR_BUDGET_EXHAUSTED`,
///                           and `optimization` says how far it went); the call still returns `OK`}
///     \cgalParamType{`double` (negative or NaN: `ERROR_WRONG_PARAMETER`)}
///     \cgalParamDefault{what is left of `maximum_running_time`}
///   \cgalParamNEnd
///   \cgalParamNBegin{coarsen}
///     \cgalParamDescription{whether to remove, after the optimization, the added vertices that the certified map can
///                           do without (see above)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{kinetic_tracing}
///     \cgalParamDescription{whether to trace the paths also in the class of a motion of the targets (the
///                           straight-line motion or a permutation braid, the one that winds least) when shortest
///                           paths add many vertices (see above); `false` keeps the other tracings only}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{statistics}
///     \cgalParamDescription{receives counts, times and certificates}
///     \cgalParamType{`Constrained_embedding_statistics*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{steiner_points}
///     \cgalParamDescription{receives (on success) the position on the input surface of every added vertex, in creation order}
///     \cgalParamType{`std::vector<Steiner_point<vertex_descriptor> >*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_patch_map}
///     \cgalParamDescription{receives (on success) for every face of the refined `tm` the index of its patch: the convex
///                           polygon of the partition of the domain into which the face was mapped, from 0 to
///                           `Constrained_embedding_statistics::patches` - 1. Faces created by the refinement get the
///                           patch they lie in (the labels are taken from the refined working copy, whose faces are
///                           those of the refined `tm`); the optimization changes no label. Two faces sharing an edge
///                           have different patches only if the edge is on a traced path; with holes, a patch
///                           that lay inside a hole has no face. The faces of patches mapped as one with their
///                           neighbours (`Constrained_embedding_statistics::merged_patches`) keep their labels but lie
///                           in the union of the polygons. The coarsening deflects the paths through the vertices it keeps: each face of a
///                           fan takes the patch of the face it replaces, so a patch may then fall into several pieces
///                           (`coarsen(false)` keeps the patches as traced). Nothing is written on error.}
///     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as
///                    key type and an integral value type (the index is converted by `static_cast`); it must accept the
///                    faces the refinement adds to `tm` (a `Surface_mesh` property map, a dynamic property map)}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{phase_callback}
///     \cgalParamDescription{called at the start of each phase and after each iteration of the optimization with a
///                           `Constrained_embedding_progress`: the phase, its progress, the time left, and in the
///                           optimization the current energy and the time left of its budget. Returning `false` before
///                           the map is certified stops the call (`ERROR_BUDGET_EXHAUSTED`, nothing written); in the
///                           optimization it stops the optimization (its certified map is kept; the coarsening and the
///                           output follow)}
///     \cgalParamType{`std::function<bool(const Constrained_embedding_progress&)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits whose exact orientation predicate decides every sign of the uv map (patch maps,
///                           certificates, optimization, coarsening); the partition of the domain decides in its own exact
///                           kernel}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2` whose `Point_2` is the uv map's value type}
///     \cgalParamDefault{`Progressive_embedding_traits_2` of the uv map's kernel}
///   \cgalParamNEnd
///   \cgalParamNBegin{verbose}
///     \cgalParamDescription{progress messages on `std::cerr`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK` only if the map is certified and every constraint met exactly; otherwise, with `tm` and `uvm`
///         unchanged: the mesh errors of `tutte_embedding()` (`ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`,
///         `ERROR_NON_MANIFOLD`, `ERROR_NOT_A_DISK` (closed mesh), `ERROR_NOT_GENUS_ZERO` (a border, but not a
///         connected genus-0 surface), `ERROR_BORDER_TOO_SHORT`), the border errors (`ERROR_NON_CONVEX_BORDER` for a
///         border shape, `ERROR_NOT_SELF_OVERLAPPING`, `ERROR_DEGENERATE_BORDER`), `ERROR_WRONG_PARAMETER` (a constrained vertex that is not a vertex of `tm`, a
///         named parameter out of range), `ERROR_NON_FINITE_COORDINATES` (a 3D point, a target or a fixed border
///         position NaN or infinite), `ERROR_CONSTRAINT_ON_BORDER`,
///         `ERROR_DUPLICATE_CONSTRAINT` (a vertex or a target given twice), `ERROR_CONSTRAINT_OUTSIDE_DOMAIN`,
///         `ERROR_BUDGET_EXHAUSTED` (time or Steiner budget), `ERROR_PATH_TRACING_FAILED`, the errors of the patch
///         embeddings (`ERROR_DEGENERATE_CHORD`, `ERROR_COLLAPSE_FAILED`, `ERROR_INSERTION_FAILED`, ...), or
///         `ERROR_INVALID_EMBEDDING` when a certificate fails.
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class ConstraintRange, class VertexUVMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code constrained_embedding(TriangleMesh& tm, const ConstraintRange& constraints, VertexUVMap uvm,
                                 const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::Constrained_embedder_for<ConcurrencyTag, TriangleMesh, VertexUVMap, NamedParameters> embedder(tm, uvm, np);
  return embedder.run(constraints);
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_CONSTRAINED_EMBEDDING_H
