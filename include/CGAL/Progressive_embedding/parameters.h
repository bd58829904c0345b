// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_PARAMETERS_H
#define CGAL_PROGRESSIVE_EMBEDDING_PARAMETERS_H

/// \file parameters.h
/// Named parameters specific to this package. CGAL 5.5's list of named parameters is
/// closed, so each one is a free function `CGAL::Progressive_embedding::parameters::name(value)`
/// returning a `CGAL::Named_function_parameters` pack, with an overload `name(value, pack)`
/// that appends to an existing pack. CGAL's own parameters chain after it:
/// `PE::parameters::invalid_energy_threshold(1e20).verbose(true)`.

#include <CGAL/Named_function_parameters.h>

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
namespace internal_np {
#define CGAL_PE_ADD_NAMED_PARAMETER(NAME) enum NAME##_t { NAME };
CGAL_PE_ADD_NAMED_PARAMETER(border_shape)
CGAL_PE_ADD_NAMED_PARAMETER(triangle_corners)
CGAL_PE_ADD_NAMED_PARAMETER(triangle_corner_points)
CGAL_PE_ADD_NAMED_PARAMETER(weights)
CGAL_PE_ADD_NAMED_PARAMETER(invalid_energy_threshold)
CGAL_PE_ADD_NAMED_PARAMETER(smoothing_iterations)
CGAL_PE_ADD_NAMED_PARAMETER(retry_smoothing_iterations)
CGAL_PE_ADD_NAMED_PARAMETER(line_search_factor)
CGAL_PE_ADD_NAMED_PARAMETER(line_search_steps)
CGAL_PE_ADD_NAMED_PARAMETER(insertion_retries)
CGAL_PE_ADD_NAMED_PARAMETER(collapse_budget)
CGAL_PE_ADD_NAMED_PARAMETER(check_overlap)
CGAL_PE_ADD_NAMED_PARAMETER(statistics)
CGAL_PE_ADD_NAMED_PARAMETER(convergence_tolerance)
CGAL_PE_ADD_NAMED_PARAMETER(minimum_area_ratio)
CGAL_PE_ADD_NAMED_PARAMETER(free_border)
CGAL_PE_ADD_NAMED_PARAMETER(constrained_vertices)
CGAL_PE_ADD_NAMED_PARAMETER(distortion_energy)
CGAL_PE_ADD_NAMED_PARAMETER(optimization_statistics)
CGAL_PE_ADD_NAMED_PARAMETER(optimize)
CGAL_PE_ADD_NAMED_PARAMETER(multiply_connected)
CGAL_PE_ADD_NAMED_PARAMETER(maximum_steiner_vertices)
CGAL_PE_ADD_NAMED_PARAMETER(split_penalty)
CGAL_PE_ADD_NAMED_PARAMETER(path_metric)
CGAL_PE_ADD_NAMED_PARAMETER(proximity_penalty)
CGAL_PE_ADD_NAMED_PARAMETER(steiner_points)
CGAL_PE_ADD_NAMED_PARAMETER(face_patch_map)
#undef CGAL_PE_ADD_NAMED_PARAMETER
} // namespace internal_np
#endif

namespace parameters {

#ifndef DOXYGEN_RUNNING
#define CGAL_PE_NAMED_PARAMETER_FUNCTIONS(NAME)                                             \
  template <typename T>                                                                     \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t>                                 \
  NAME(const T& t)                                                                          \
  { return CGAL::Named_function_parameters<T, internal_np::NAME##_t>(t); }                  \
  template <typename T, typename NP_T, typename NP_Tag, typename NP_Base>                   \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t,                                 \
                                  CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base> >   \
  NAME(const T& t, const CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base>& np)        \
  { return CGAL::Named_function_parameters<T, internal_np::NAME##_t,                        \
             CGAL::Named_function_parameters<NP_T, NP_Tag, NP_Base> >(t, np); }

CGAL_PE_NAMED_PARAMETER_FUNCTIONS(border_shape)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(triangle_corners)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(triangle_corner_points)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(weights)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(invalid_energy_threshold)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(smoothing_iterations)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(retry_smoothing_iterations)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(line_search_factor)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(line_search_steps)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(insertion_retries)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(collapse_budget)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(check_overlap)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(statistics)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(convergence_tolerance)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(minimum_area_ratio)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(free_border)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(constrained_vertices)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(distortion_energy)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(optimization_statistics)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(optimize)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(multiply_connected)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(maximum_steiner_vertices)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(split_penalty)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(path_metric)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(proximity_penalty)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(steiner_points)
CGAL_PE_NAMED_PARAMETER_FUNCTIONS(face_patch_map)
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
#endif

} // namespace parameters
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_PARAMETERS_H
