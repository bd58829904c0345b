// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_PARAMETERS_H
#define CGAL_PROGRESSIVE_EMBEDDING_PARAMETERS_H

/// \file parameters.h
/// Named parameters specific to this package. CGAL 5.5's list of named parameters is
/// closed, so each one is a function `CGAL::Progressive_embedding::parameters::name(value)`
/// starting a `CGAL::Progressive_embedding::Named_function_parameters` pack (a CGAL pack whose
/// members chain this package's parameters and CGAL's in any order:
/// `PE::parameters::border_shape(s).weights(w).verbose(true)`), with an overload `name(value, pack)`
/// that appends to any pack, CGAL's own included.

#include <CGAL/Named_function_parameters.h>

#include <type_traits>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingEnums
/// How `tutte_embedding()` places the border vertices.
enum class Border_shape
{
  FIXED,    ///< keep the uv coordinates already in the uv map (checked to be convex, exactly)
  CIRCLE,   ///< unit circle, by arc length (positions rounded to the number type)
  SQUARE,   ///< unit square, by arc length; corners at the vertices closest to quarter lengths
  TRIANGLE  ///< a triangle by arc length; corners and their positions may be given
};

/// \ingroup PkgProgressiveEmbeddingEnums
/// The cost of a path traced on the mesh by `constrained_embedding()`.
enum class Path_metric
{
  EDGE_LENGTH, ///< sum of the 3D edge lengths
  HOP_COUNT    ///< number of edges
};

/// \ingroup PkgProgressiveEmbeddingEnums
/// Edge weights of the Tutte system.
enum class Weights
{
  UNIFORM,   ///< Tutte's barycentric mapping: every weight is 1 (symmetric system)
  MEAN_VALUE ///< Floater's mean value coordinates from the 3D geometry (non-symmetric system)
};

#ifndef DOXYGEN_RUNNING
// The package's parameters, as an X-macro list: one entry generates the tag above, the member function of
// the pack and the free functions below.
#define CGAL_PE_NAMED_PARAMETER_LIST(X) \
  X(border_shape) \
  X(triangle_corners) \
  X(triangle_corner_points) \
  X(weights) \
  X(invalid_energy_threshold) \
  X(smoothing_iterations) \
  X(retry_smoothing_iterations) \
  X(line_search_factor) \
  X(line_search_steps) \
  X(insertion_retries) \
  X(collapse_budget) \
  X(check_overlap) \
  X(statistics) \
  X(convergence_tolerance) \
  X(reuse_factorization) \
  X(minimum_area_ratio) \
  X(free_border) \
  X(constrained_vertices) \
  X(distortion_energy) \
  X(optimization_statistics) \
  X(optimize) \
  X(multiply_connected) \
  X(maximum_steiner_vertices) \
  X(split_penalty) \
  X(path_metric) \
  X(proximity_penalty) \
  X(steiner_points) \
  X(face_patch_map) \
  X(polygon_report) \
  X(rotation_indices) \
  X(vertex_rotation_index_map) \
  X(coarsen) \
  X(kinetic_tracing) \
  X(optimization_time_limit) \
  X(optimization_policy) \
  X(pipeline_statistics) \
  X(stage_callback) \
  X(phase_callback) \

namespace internal_np {
#define CGAL_PE_ADD_NAMED_PARAMETER(NAME) enum NAME##_t { NAME };
CGAL_PE_NAMED_PARAMETER_LIST(CGAL_PE_ADD_NAMED_PARAMETER)
#undef CGAL_PE_ADD_NAMED_PARAMETER

// CGAL's parameters whose function name is also one of this package's: in this package's pack and
// namespace the name means the package's parameter (CGAL's is not generated there, so that the call is
// not ambiguous). CGAL's face_patch_map (face_patch_t) is the face-to-patch map of Polygon_mesh_processing.
template <class CgalTag> struct Shadowed_by_package : std::false_type {};
template <> struct Shadowed_by_package<CGAL::internal_np::face_patch_t> : std::true_type {};
} // namespace internal_np
#endif

/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// The named-parameter pack of this package. It is a `CGAL::Named_function_parameters` (every function of this
/// package and of CGAL that takes CGAL's pack takes it) whose member functions append any parameter, this package's
/// as well as CGAL's, so that a chain may name them in any order:
/// `PE::parameters::border_shape(s).weights(w).vertex_point_map(vpm).statistics(&st)`.
/// The functions of `CGAL::Progressive_embedding::parameters` start such a chain; CGAL's own
/// `CGAL::parameters::` functions start a `CGAL::Named_function_parameters`, to which a parameter of this package is
/// appended by its two-argument form, e.g. `PE::parameters::weights(w, CGAL::parameters::vertex_point_map(vpm))`.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  /// the CGAL pack this pack is
  typedef CGAL::Named_function_parameters<T, Tag, Base> Cgal_pack;

  /// an empty pack (with the default `T` and `Tag`)
  Named_function_parameters() {}
  /// the pack of the one parameter `Tag` with value `v`
  explicit Named_function_parameters(const T& v) : Cgal_pack(v) {}
  /// the parameter `Tag` with value `v` appended to the pack `b`
  Named_function_parameters(const T& v, const Base& b) : Cgal_pack(v, b) {}

#ifndef DOXYGEN_RUNNING
  // CGAL's parameters (the list CGAL's own pack is generated from), returning this package's pack
#define CGAL_add_named_parameter(X, Y, Z)                                                      \
  template <typename K, typename Tag_ = CGAL::internal_np::X,                                   \
            std::enable_if_t<!internal_np::Shadowed_by_package<Tag_>::value, int> = 0>          \
  Named_function_parameters<K, Tag_, Cgal_pack> Z(const K& k) const                             \
  { return Named_function_parameters<K, Tag_, Cgal_pack>(k, *this); }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define CGAL_PE_NAMED_PARAMETER_MEMBER(NAME)                                                   \
  template <typename K>                                                                        \
  Named_function_parameters<K, internal_np::NAME##_t, Cgal_pack> NAME(const K& k) const         \
  { return Named_function_parameters<K, internal_np::NAME##_t, Cgal_pack>(k, *this); }
  CGAL_PE_NAMED_PARAMETER_LIST(CGAL_PE_NAMED_PARAMETER_MEMBER)
#undef CGAL_PE_NAMED_PARAMETER_MEMBER
#endif
};

namespace parameters {

/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// an empty pack of this package, to start a chain: `PE::parameters::default_values().weights(w)`
inline Named_function_parameters<bool, CGAL::internal_np::all_default_t> default_values()
{ return Named_function_parameters<bool, CGAL::internal_np::all_default_t>(); }

#ifndef DOXYGEN_RUNNING
// CGAL's parameters start a chain of this package's pack too: PE::parameters::vertex_point_map(vpm).weights(w)
#define CGAL_add_named_parameter(X, Y, Z)                                                      \
  template <typename K, typename Tag_ = CGAL::internal_np::X,                                   \
            std::enable_if_t<!internal_np::Shadowed_by_package<Tag_>::value, int> = 0>          \
  Named_function_parameters<K, Tag_> Z(const K& k)                                              \
  { return Named_function_parameters<K, Tag_>(k); }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

// NAME(t) starts a chain; NAME(t, pack) appends to any pack (CGAL's or this package's).
#define CGAL_PE_NAMED_PARAMETER_FUNCTIONS(NAME)                                             \
  template <typename T>                                                                     \
  Named_function_parameters<T, internal_np::NAME##_t>                                       \
  NAME(const T& t)                                                                          \
  { return Named_function_parameters<T, internal_np::NAME##_t>(t); }                        \
  template <typename T, typename NP_T, typename NP_Tag, typename NP_Base>                   \
  Named_function_parameters<T, internal_np::NAME##_t,                                       \
                            CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base> >         \
  NAME(const T& t, const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& np)        \
  { return Named_function_parameters<T, internal_np::NAME##_t,                              \
             CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base> >(t, np); }
CGAL_PE_NAMED_PARAMETER_LIST(CGAL_PE_NAMED_PARAMETER_FUNCTIONS)
#undef CGAL_PE_NAMED_PARAMETER_FUNCTIONS
#else
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the largest number of Steiner vertices path tracing may add (`std::size_t`; default 4 times the number of edges plus 1000)
template <typename T> unspecified_type maximum_steiner_vertices(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// how much longer a traced path may be to avoid one edge split (`double`, in mean edge lengths, or hops with
/// `Path_metric::HOP_COUNT`; default 4)
template <typename T> unspecified_type split_penalty(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the cost of traced paths (a `Path_metric`; default `Path_metric::EDGE_LENGTH`)
template <typename T> unspecified_type path_metric(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the extra cost of a traced path at each vertex, divided by the vertex's hop distance to the already traced
/// network (`double`, in mean edge lengths, or hops with `Path_metric::HOP_COUNT`; default 1; 0: plain shortest paths)
template <typename T> unspecified_type proximity_penalty(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// receives, for `constrained_embedding()`, the position on the input surface of every vertex it adds
/// (`std::vector<Steiner_point<vertex_descriptor> >*`)
template <typename T> unspecified_type steiner_points(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// a face property map (integral values) that receives, for `constrained_embedding()`, the index of the patch of every
/// face of the output mesh, and from which `IO::write_SVG()` colors the faces by patch and draws the patch borders
template <typename T> unspecified_type face_patch_map(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// receives what `triangulate_self_overlapping_polygon_2()` found (a `Polygon_triangulation_report*`; default none)
template <typename T> unspecified_type polygon_report(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the rotation index of every polygon vertex for `triangulate_self_overlapping_polygon_2()`: full turns added to its
/// angle (a `std::vector<int>`; default all 0)
template <typename T> unspecified_type rotation_indices(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the rotation index of every border vertex for `constrained_embedding()` onto a fixed border: full turns added to
/// the border's angle there (a readable vertex property map with `int` values; default all 0)
template <typename T> unspecified_type vertex_rotation_index_map(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// whether `check_embedding()` accepts a connected genus-0 mesh with several border cycles (`bool`, default `false`:
/// such a mesh is refused with `ERROR_NOT_A_DISK`, as a mesh that is not a disk)
template <typename T> unspecified_type multiply_connected(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// selects the border shape of `tutte_embedding()` (a `Border_shape`; default `Border_shape::FIXED`)
template <typename T> unspecified_type border_shape(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the three border vertices that become the corners of a `Border_shape::TRIANGLE` border (a `std::array` of three vertex descriptors)
template <typename T> unspecified_type triangle_corners(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the positions of the three triangle corners (a `std::array` of three `Traits::Point_2`; default (0,0), (1,0), (1/2, sqrt(3)/2))
template <typename T> unspecified_type triangle_corner_points(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the Tutte weights (a `Weights`; default `Weights::UNIFORM`)
template <typename T> unspecified_type weights(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// faces whose symmetric Dirichlet energy (equilateral reference) is above this `double` count as invalid (default 1e20)
template <typename T> unspecified_type invalid_energy_threshold(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// local smoothing iterations after each insertion (`int`, default 10 in floating point, 0 in exact arithmetic)
template <typename T> unspecified_type smoothing_iterations(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// smoothing iterations before retrying an insertion that found no candidate (`int`, default 50)
template <typename T> unspecified_type retry_smoothing_iterations(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// backtracking factor of the flip-free line search (`double` in (0,1), default 0.8)
template <typename T> unspecified_type line_search_factor(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// maximal number of backtracking steps (`int`, default 75)
template <typename T> unspecified_type line_search_steps(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// how many times a failed insertion is retried after extra smoothing (`int`, default 20)
template <typename T> unspecified_type insertion_retries(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// maximal number of tag-expansion rounds of the simplification stage (`int`, default: unbounded by the mesh size)
template <typename T> unspecified_type collapse_budget(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// whether `check_embedding()` runs the global overlap test (`bool`, default `true`)
template <typename T> unspecified_type check_overlap(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// a pointer to a `Progressive_embedding_statistics` filled by `progressive_embedding()`
template <typename T> unspecified_type statistics(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// `progressive_embedding()` also collapses (and re-inserts) faces whose area is below this fraction of the mean face
/// area (`double`; default 1e-12 in floating point, 0 in exact arithmetic)
template <typename T> unspecified_type minimum_area_ratio(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// `optimize_distortion()` has converged when two consecutive iterations each lower the energy by less than this fraction (`double`, default 1e-5)
template <typename T> unspecified_type convergence_tolerance(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// whether `optimize_distortion()`'s Newton steps may reuse the last factorization of the Hessian while the steps made
/// with it gain at least half of what the step that made it gained (`bool`, default `true`; only fresh steps decide
/// convergence)
template <typename T> unspecified_type reuse_factorization(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// whether `optimize_distortion()` may move the border vertices (`bool`, default `false`); the border stays simple
template <typename T> unspecified_type free_border(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// vertices whose uv coordinates `optimize_distortion()` keeps bit-exactly (a `std::vector` of vertex descriptors)
template <typename T> unspecified_type constrained_vertices(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the energy of `optimize_distortion()` (a `Distortion_energy`; default `Distortion_energy::SYMMETRIC_DIRICHLET`)
template <typename T> unspecified_type distortion_energy(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// a pointer to an `Optimization_statistics` filled by `optimize_distortion()`
template <typename T> unspecified_type optimization_statistics(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// whether a repaired map is then passed to `optimize_distortion()` (`bool`; see the function's default)
template <typename T> unspecified_type optimize(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// whether `constrained_embedding()` removes, after the optimization, the added vertices that the certified map can
/// do without (`bool`; default `true`)
template <typename T> unspecified_type coarsen(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// seconds that the optimization of `constrained_embedding()`, `repair_and_optimize()` and `parameterize_certified()`
/// may take (`double`; default: what is left of `maximum_running_time`)
template <typename T> unspecified_type optimization_time_limit(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// when `repair_and_optimize()` and `parameterize_certified()` run the optimization (an `Optimization_policy`;
/// default `Optimization_policy::WHEN_REPAIRED`)
template <typename T> unspecified_type optimization_policy(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// receives what `repair_and_optimize()` and `parameterize_certified()` did (a `Pipeline_statistics*`; default none)
template <typename T> unspecified_type pipeline_statistics(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// called by `repair_and_optimize()` with the stage and its progress in [0, 1]; `false` stops the call
/// (`std::function<bool(Pipeline_stage, double)>`; default none)
template <typename T> unspecified_type stage_callback(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// called by `constrained_embedding()` at the start of each phase and after each iteration of its optimization, with a
/// `Constrained_embedding_progress`; `false` stops the call (`std::function<bool(const Constrained_embedding_progress&)>`;
/// default none)
template <typename T> unspecified_type phase_callback(const T& t);
#endif

} // namespace parameters
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_PARAMETERS_H
