// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_CONSTRAINED_EMBEDDING_STATISTICS_H
#define CGAL_PROGRESSIVE_EMBEDDING_CONSTRAINED_EMBEDDING_STATISTICS_H

/// \file Constrained_embedding_statistics.h
///
/// What `constrained_embedding()` reports: `Constrained_embedding_statistics` and `Steiner_point`.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Embedding_report.h>
#include <CGAL/Progressive_embedding/Immersion_report.h>
#include <CGAL/Progressive_embedding/Optimization_statistics.h>

#include <array>
#include <cstddef>
#include <limits>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingReports
/// The phases of `constrained_embedding()`, in their order, as its `phase_callback` reports them.
enum class Constrained_embedding_phase
{
  VALIDATION,    ///< the mesh, the constraints and the border checked, the border placed
  PARTITION,     ///< the domain cut into convex polygons
  TRACING,       ///< the polygons' interior edges traced on the mesh as paths (the refinement)
  PATCHES,       ///< each patch mapped into its polygon
  CERTIFICATION, ///< the whole map certified (`check_embedding()`, or `check_immersion()`)
  OPTIMIZATION,  ///< `optimize_distortion()` with the border and the constraints fixed
  COARSENING,    ///< added vertices that the certified map can do without removed
  OUTPUT         ///< the refinement replayed on the caller's mesh, the uv map written
};

/// \ingroup PkgProgressiveEmbeddingReports
/// What the `phase_callback` of `constrained_embedding()` receives: at the start of each phase, and after each
/// iteration of the optimization (and of the optimization that follows the coarsening). Returning `false` stops
/// the call: before the map is certified with `ERROR_BUDGET_EXHAUSTED` (nothing written); in the optimization, the
/// optimization stops there with its certified map, and the coarsening and the output follow.
struct Constrained_embedding_progress
{
  /// the phase running
  Constrained_embedding_phase phase = Constrained_embedding_phase::VALIDATION;
  /// how much of the phase is done, in [0, 1]: 0 at its start; in the optimization, the fraction of its iteration budget
  double fraction = 0;
  /// seconds since the call started
  double seconds = 0;
  /// seconds left of `maximum_running_time` (infinite without)
  double seconds_left = std::numeric_limits<double>::infinity();
  /// in the optimization: seconds left of its own budget (`optimization_time_limit`, bounded by `maximum_running_time`);
  /// infinite elsewhere or without a budget
  double optimization_seconds_left = std::numeric_limits<double>::infinity();
  /// in the optimization: the mean symmetric Dirichlet energy of the current map (after the last iteration; NaN
  /// before the first one and in the other phases)
  double energy = std::numeric_limits<double>::quiet_NaN();
};

/// \ingroup PkgProgressiveEmbeddingReports
/// What `constrained_embedding()` did, filled when a pointer to it is passed with the `statistics` named parameter
/// (also on error, as far as the computation went).
struct Constrained_embedding_statistics
{
  /// on an error about one constraint (`ERROR_CONSTRAINT_ON_BORDER`, `ERROR_DUPLICATE_CONSTRAINT`,
  /// `ERROR_CONSTRAINT_OUTSIDE_DOMAIN`, `ERROR_NON_FINITE_COORDINATES` of a target, `ERROR_WRONG_PARAMETER`
  /// for a vertex not of the mesh): its position in the `constraints` range (for two equal vertices or
  /// targets, the later one); `std::size_t(-1)` otherwise
  std::size_t failed_constraint = std::size_t(-1);
  /// vertices of the input mesh
  std::size_t input_vertices = 0;
  /// vertices of the output mesh (input vertices first, then the Steiner vertices)
  std::size_t output_vertices = 0;
  /// vertices added by edge splits (path tracing and chord splits)
  std::size_t steiner_vertices = 0;
  /// vertices added by the refinement before the coarsening (`steiner_vertices` counts those kept)
  std::size_t steiner_vertices_inserted = 0;
  /// added vertices removed again by the coarsening (`coarsen` named parameter)
  std::size_t steiner_vertices_removed = 0;
  /// added vertices that the coarsening could have removed with every new face positive, kept because a new face
  /// that no later optimization can reshape (its three vertices on the border or constrained, or any face when the
  /// optimization does not run again) would have been more distorted (symmetric Dirichlet against its 3D triangle)
  /// than the worst face of the map before the coarsening
  std::size_t steiner_vertices_kept_for_distortion = 0;
  /// of which added to split chords after tracing: chords along one path or border side, and chords of
  /// faces whose three vertices are on the paths and which the rounding of the path vertices left flat
  std::size_t chord_splits = 0;
  /// whether the paths were traced a second time, guided by a drawing of the partition (after shortest
  /// paths ran out of their Steiner budget or added more than a tenth of the vertices)
  bool guided_tracing = false;
  /// whether the guided tracing's paths were kept (it succeeded with fewer Steiner vertices)
  bool guided_tracing_kept = false;
  /// whether the paths were traced as curves crossing the input edges, the mesh refined once at the end
  /// (after shortest paths ran out of their Steiner budget or added more than a tenth of the vertices;
  /// input meshes without holes)
  bool overlay_tracing = false;
  /// whether the overlay tracing's paths were kept (it succeeded with the fewest Steiner vertices)
  bool overlay_tracing_kept = false;
  /// whether the paths were traced in the homeomorphism class of a motion of the targets: from where a
  /// uniform Tutte map puts the constrained vertices to their targets, a triangulation kept valid by edge
  /// flips, each flip re-tracing one curve (after shortest paths ran out of their Steiner budget or added
  /// more than a tenth of the vertices; a convex border, no holes, at least one constraint). Five motions
  /// are simulated, the straight-line one and four whose crossings all have one sign (a permutation braid
  /// along the directions at 0, 90, 45 and 135 degrees); the one whose curves cross its own start
  /// triangulation least is traced on the mesh. Its partition replaces the Delaunay one when its paths are
  /// kept.
  bool kinetic_tracing = false;
  /// whether the kinetic tracing's paths (and partition) were kept (it succeeded with the fewest Steiner vertices)
  bool kinetic_tracing_kept = false;
  /// the motion whose paths were kept: 0 the straight-line motion, 1, 2, 3, 4 the permutation braid along
  /// the direction at 0, 90, 45, 135 degrees; -1 when no kinetic tracing was kept
  int kinetic_motion = -1;
  /// edge flips of the motion traced on the mesh (0 when the kinetic tracing did not run)
  std::size_t kinetic_flips = 0;
  /// paths traced (interior edges of the partition of the domain)
  std::size_t paths = 0;
  /// patches (convex polygons of the partition), each embedded separately
  std::size_t patches = 0;
  /// patches whose Tutte map needed the progressive embedding repair
  std::size_t repaired_patches = 0;
  /// patches mapped as one with neighbours, into the union of their polygons, the paths between them free: the
  /// fallback for a patch that could not be mapped into its polygon (a needle a few ulps wide holding many
  /// vertices, when targets lie within a few ulps of each other); counts the failed patches and their partners
  std::size_t merged_patches = 0;
  /// seconds spent validating the input and placing the border
  double seconds_validation = 0;
  /// seconds spent partitioning the target domain into convex polygons
  double seconds_partition = 0;
  /// seconds spent tracing the paths (chord splits included)
  double seconds_tracing = 0;
  /// seconds spent placing the path vertices and embedding the patches
  double seconds_patches = 0;
  /// seconds spent certifying the map
  double seconds_certification = 0;
  /// seconds spent optimizing the distortion
  double seconds_optimization = 0;
  /// seconds spent coarsening the certified map
  double seconds_coarsening = 0;
  /// seconds spent replaying the refinement on the input mesh and writing the uv map
  double seconds_output = 0;
  /// seconds in all
  double seconds_total = 0;
  /// the certificate of the map before the optimization (on the refined mesh)
  Embedding_report report_before_optimization;
  /// the certificate of the returned map
  Embedding_report report;
  /// whether `optimize_distortion()` ran
  bool optimized = false;
  /// what `optimize_distortion()` returned (`OK` or `ERROR_BUDGET_EXHAUSTED` keep its result; any other status
  /// keeps the map before the optimization)
  Error_code optimization_status = OK;
  /// what the optimization did
  Optimization_statistics optimization;
  /// whether the optimization ran again after the coarsening removed vertices (with what was left of its time)
  bool reoptimized = false;
  /// what that second optimization did
  Optimization_statistics reoptimization;
  /// `true` when the fixed border is not simple (weakly self-overlapping): the map is an immersion, certified by
  /// `check_immersion()` (`immersion_report`; `report` is then the embedding certificate, which fails on the border)
  bool immersion = false;
  /// the immersion certificate, when `immersion` is `true`
  Immersion_report immersion_report;
  /// largest distance between a constrained vertex's uv and its target (0: bit-exact; computed in double)
  double max_constraint_error = 0;
};

/// \ingroup PkgProgressiveEmbeddingReports
/// Where a vertex added by `constrained_embedding()` lies on the input surface: the convex combination
/// `sum weights[i] * point(corners[i])`, `i < size`, of at most three vertices of one input face (exact: the
/// weights are dyadic and computed exactly in `double`).
template <class VertexDescriptor>
struct Steiner_point
{
  /// the added vertex (a vertex of the output mesh)
  VertexDescriptor vertex;
  /// the input vertices of the combination (the first `size` are used)
  std::array<VertexDescriptor, 3> corners;
  /// their weights (positive, summing to 1)
  std::array<double, 3> weights;
  /// 1, 2 or 3
  std::size_t size = 0;
};

} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_CONSTRAINED_EMBEDDING_STATISTICS_H
