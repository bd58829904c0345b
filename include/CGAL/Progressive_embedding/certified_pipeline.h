// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_CERTIFIED_PIPELINE_H
#define CGAL_PROGRESSIVE_EMBEDDING_CERTIFIED_PIPELINE_H

/// \file certified_pipeline.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>

#include <cstddef>
#include <functional>
#include <limits>
#include <string>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingEnums
/// When `repair_and_optimize()` and `parameterize_certified()` run `optimize_distortion()`.
enum class Optimization_policy
{
  NEVER,         ///< never: the map is the valid one (as given, or as repaired)
  WHEN_REPAIRED, ///< only when the map given was not valid and was repaired (its distortion is then far from optimal)
  ALWAYS         ///< always
};

/// \ingroup PkgProgressiveEmbeddingEnums
/// The stage that a `stage_callback` reports on.
enum class Pipeline_stage
{
  REPAIR,      ///< `progressive_embedding()`
  OPTIMIZATION ///< `optimize_distortion()`
};

/// \ingroup PkgProgressiveEmbeddingReports
///
/// What `repair_and_optimize()` and `parameterize_certified()` did, filled through the named parameter
/// `pipeline_statistics` (also when they fail). `for_each_statistic()` lists its fields as key-value pairs.
struct Pipeline_statistics
{
  /// the certificate of the map given to `repair_and_optimize()` (of the Tutte map for `parameterize_certified()`)
  Embedding_report input_report;
  /// `true` if `progressive_embedding()` ran: the map given was not valid
  bool repaired = false;
  /// the statistics of `progressive_embedding()` when it ran
  Progressive_embedding_statistics repair;
  /// `true` if `optimize_distortion()` ran
  bool optimized = false;
  /// what `optimize_distortion()` returned when it ran (`OK` otherwise)
  Error_code optimization_status = OK;
  /// the statistics of `optimize_distortion()` when it ran
  Optimization_statistics optimization;
  /// the certificate of the map the call ends with (the map left in the uv map)
  Embedding_report report;
  /// seconds of the Tutte map (`parameterize_certified()` only)
  double seconds_tutte = 0;
  /// seconds of the whole call
  double seconds_total = 0;
};

/// \ingroup PkgProgressiveEmbeddingReports
///
/// calls `f(key, value)` for every statistic of the repair `s`, in a fixed order, with the keys of `pe --json`:
/// `invalid_before`, `collapses`, `insertions`, `extra_smoothing`, `expansion_rounds`, `seconds_collapse`,
/// `seconds_insertion`. The value is a `std::size_t`, a `double`, a `bool` or a `std::string` (`f` is a generic
/// callable). A statistic added here reaches the command-line tool and the Python module at once.
template <class Function>
void for_each_statistic(const Progressive_embedding_statistics& s, Function&& f)
{
  f("invalid_before", s.invalid_faces_before);
  f("collapses", s.collapses);
  f("insertions", s.insertions);
  f("extra_smoothing", s.insertions_with_extra_smoothing);
  f("expansion_rounds", s.expansion_rounds);
  f("seconds_collapse", s.seconds_collapse);
  f("seconds_insertion", s.seconds_insertion);
}

/// \ingroup PkgProgressiveEmbeddingReports
///
/// calls `f(key, value)` for every statistic of the optimization `s`, as the overload for a repair does:
/// `iterations`, `converged`, `energy_before`, `energy_after`, `seconds_optimization`.
template <class Function>
void for_each_statistic(const Optimization_statistics& s, Function&& f)
{
  f("iterations", s.iterations);
  f("converged", s.converged);
  f("energy_before", s.energy_before);
  f("energy_after", s.energy_after);
  f("seconds_optimization", s.seconds);
}

/// \ingroup PkgProgressiveEmbeddingReports
///
/// calls `f(key, value)` for every statistic of the pipeline `s`: `repaired`, the repair's (overload above; zeros
/// when it did not run), `optimized`, `optimization_status` (the name of the `Error_code`), the optimization's.
template <class Function>
void for_each_statistic(const Pipeline_statistics& s, Function&& f)
{
  f("repaired", s.repaired);
  for_each_statistic(s.repair, f);
  f("optimized", s.optimized);
  f("optimization_status", std::string(get_error_name(s.optimization_status)));
  for_each_statistic(s.optimization, f);
}

namespace internal {

// The policy's one choice of the repair's area threshold: before an optimization, faces below 1e-3 times
// the mean area are collapsed and re-inserted too (the optimizer cannot grow faces 1e-20 times too small
// back in a useful number of iterations); without one, progressive_embedding()'s own default (1e-12 in
// floating point, 0 with exact constructions), passed explicitly so that one instantiation serves both.
inline double pipeline_minimum_area_ratio(bool will_optimize, bool exact_constructions)
{
  return will_optimize ? 1e-3 : exact_constructions ? 0. : 1e-12;
}

// the optimizer's results that leave a certified map the pipeline keeps: improved (OK, or stopped by its
// budget), or not optimizable (no free vertex; a zero-area 3D face makes the energy infinite) and kept as is
inline bool tolerated_optimization_status(Error_code ec)
{
  return ec == OK || ec == ERROR_BUDGET_EXHAUSTED || ec == ERROR_NO_FREE_VERTEX || ec == ERROR_DEGENERATE_3D_FACE;
}

// the body of repair_and_optimize() (see its documentation there); `given`: the disk already indexed from `tm`
// (with the default border start, see start_border_as_default()) by the caller, or null
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code repair_and_optimize_impl(const TriangleMesh& tm, VertexUVMap uvm, const CGAL_NP_CLASS& np,
                                   const Indexed_disk<TriangleMesh>* given = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef std::function<bool(Pipeline_stage, double)> Stage_callback;

  CGAL::Real_timer timer;
  timer.start();
  Pipeline_statistics local;
  Pipeline_statistics* out = choose_parameter(get_parameter(np, internal_np::pipeline_statistics),
                                              static_cast<Pipeline_statistics*>(nullptr));
  Pipeline_statistics& s = out ? *out : local;
  s = Pipeline_statistics();
  auto finish = [&](Error_code ec) { s.seconds_total = timer.time(); return ec; };

  const Optimization_policy policy = choose_parameter(get_parameter(np, internal_np::optimization_policy),
                                                      Optimization_policy::WHEN_REPAIRED);
  const Stage_callback callback = choose_parameter(get_parameter(np, internal_np::stage_callback), Stage_callback());
  const double max_seconds = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time),
                                              std::numeric_limits<double>::infinity());
  const double optimization_seconds = choose_parameter(get_parameter(np, internal_np::optimization_time_limit),
                                                       std::numeric_limits<double>::infinity());
  if(!(max_seconds >= 0) || !(optimization_seconds >= 0)) return finish(ERROR_WRONG_PARAMETER);
  auto remaining = [&]() { const double r = max_seconds - timer.time(); return r > 0 ? r : 0.; };
  auto stage = [&](Pipeline_stage st) {
    return std::function<bool(double)>(callback ? [callback, st](double x) { return callback(st, x); }
                                                : std::function<bool(double)>());
  };

  // every stage decides its signs with the caller's traits and reads the caller's 3D positions
  typedef typename Check_traits<VertexUVMap, CGAL_NP_CLASS>::type Traits;
  const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const auto common = CGAL::parameters::geom_traits(traits).vertex_point_map(vpm);

  // the stages share one indexed disk: the mesh is indexed once
  Indexed_disk<TriangleMesh> own;
  const Indexed_disk<TriangleMesh>* disk = given;
  if(!disk && make_indexed_disk(tm, boost::graph_traits<TriangleMesh>::null_halfedge(), own) == OK) disk = &own;
  s.input_report = check_embedding_impl(tm, uvm, common, disk);
  s.report = s.input_report;
  if(s.input_report.status != OK) return finish(s.input_report.status);
  if(s.input_report.non_finite > 0) return finish(ERROR_NON_FINITE_COORDINATES);

  const bool invalid = !s.input_report.is_valid();
  const bool optimize = policy == Optimization_policy::ALWAYS || (invalid && policy == Optimization_policy::WHEN_REPAIRED);
  if(invalid)
  {
    s.repaired = true;
    const double ratio = pipeline_minimum_area_ratio(optimize, Traits::has_exact_constructions);
    const Error_code ec = progressive_embedding_impl<ConcurrencyTag>(tm, uvm,
      parameters::minimum_area_ratio(ratio,
      parameters::statistics(&s.repair,
      common.callback(stage(Pipeline_stage::REPAIR)).maximum_running_time(remaining()))), disk);
    if(ec != OK) return finish(ec);
    s.report = s.repair.report;
  }
  if(optimize)
  {
    s.optimized = true;
    const std::size_t iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations),
                                                    std::size_t(1000));
    const double tolerance = choose_parameter(get_parameter(np, internal_np::convergence_tolerance), 1e-5);
    s.optimization_status = optimize_distortion_impl<ConcurrencyTag>(tm, uvm,
      parameters::convergence_tolerance(tolerance,
      parameters::optimization_statistics(&s.optimization,
      common.callback(stage(Pipeline_stage::OPTIMIZATION)).number_of_iterations(iterations)
            .maximum_running_time((std::min)(remaining(), optimization_seconds)))), disk);
    // the optimizer certifies the map it writes, and writes nothing otherwise: no second certificate
    if(s.optimization_status == OK || s.optimization_status == ERROR_BUDGET_EXHAUSTED) s.report = s.optimization.report;
    if(!tolerated_optimization_status(s.optimization_status)) return finish(s.optimization_status);
  }
  return finish(s.report.is_valid() ? OK : ERROR_INVALID_EMBEDDING);
}

} // namespace internal

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// the package's one policy for turning a map of a disk into a certified map of good quality, as `pe untangle`,
/// `pe embed`, the Python module and both parameterizers apply it:
/// 1. certify the map with `check_embedding()`;
/// 2. if it is not valid, repair it with `progressive_embedding()` (when an optimization follows, the repair also
///    collapses and re-inserts the faces below \f$ 10^{-3} \f$ times the mean area, which the optimizer could not
///    grow back in a useful number of iterations; otherwise `progressive_embedding()`'s own threshold);
/// 3. optimize it with `optimize_distortion()` as the `optimization_policy` says; the optimizer writes only
///    certified maps, and a map it cannot optimize (no free vertex, or a zero-area 3D face) keeps its valid map;
/// 4. certify the map it ends with (`Pipeline_statistics::report`).
///
/// The border is fixed throughout. The uv map is changed only by a stage that succeeds.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`, passed to each stage (see
///         `optimize_distortion()`: the result is the same bit for bit)
/// \tparam TriangleMesh a model of `FaceListGraph` (triangles)
/// \tparam VertexUVMap a model of `ReadWritePropertyMap` with the vertex descriptor as key type and a CGAL `Point_2`
///         as value type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh, a triangulated topological disk
/// \param uvm the uv map: the input map (its border strictly convex, as `progressive_embedding()` needs when it is
///        not valid); the output map on success
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{optimization_policy}
///     \cgalParamDescription{when the optimization runs}
///     \cgalParamType{`Optimization_policy`}
///     \cgalParamDefault{`Optimization_policy::WHEN_REPAIRED`}
///   \cgalParamNEnd
///   \cgalParamNBegin{pipeline_statistics}
///     \cgalParamDescription{receives what the call did}
///     \cgalParamType{`Pipeline_statistics*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{stage_callback}
///     \cgalParamDescription{called with the stage and its progress in [0, 1]; returning `false` stops the call
///                           (`ERROR_BUDGET_EXHAUSTED` in the repair; in the optimization, its certified map is kept)}
///     \cgalParamType{`std::function<bool(Pipeline_stage, double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{seconds (wall clock) for the whole call, shared by the stages in order}
///     \cgalParamType{`double`}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the optimization's maximum number of iterations}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`optimize_distortion()`'s default}
///   \cgalParamNEnd
///   \cgalParamNBegin{convergence_tolerance}
///     \cgalParamDescription{the optimization's convergence criterion}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`optimize_distortion()`'s default}
///   \cgalParamNEnd
///   \cgalParamNBegin{optimization_time_limit}
///     \cgalParamDescription{seconds (wall clock) for the optimization: it stops there with its certified, improved map
///                           (`Pipeline_statistics::optimization_status` is then `ERROR_BUDGET_EXHAUSTED`, and
///                           `Pipeline_statistics::optimization` says how far it went); the call still returns `OK`}
///     \cgalParamType{`double` (negative or NaN: `ERROR_WRONG_PARAMETER`)}
///     \cgalParamDefault{what is left of `maximum_running_time`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits class whose exact predicates decide every sign, in every stage}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2` whose `Point_2` is the uv map's value type}
///     \cgalParamDefault{`Progressive_embedding_traits_2<K>`, `K` the kernel of the uv map's point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D positions, for the distortion (all stages)}
///     \cgalParamType{a readable vertex property map with 3D points as values}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK` with a certified map (`Pipeline_statistics::report` valid); otherwise the error of the first stage
///         that failed: those of `check_embedding()` (a mesh that is not a disk, ...), of `progressive_embedding()`
///         (the uv map is then unchanged), or of `optimize_distortion()` other than the ones the policy tolerates
///         (the uv map then holds the certified repaired map).
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code repair_and_optimize(const TriangleMesh& tm, VertexUVMap uvm,
                               const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  return internal::repair_and_optimize_impl<ConcurrencyTag>(tm, uvm, np);
}

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// a certified parameterization of the disk `tm`: its Tutte map (`tutte_embedding()` with the named parameters given,
/// e.g. `border_shape` and `weights`), then `repair_and_optimize()` (the same named parameters; the optimization
/// policy defaults to `Optimization_policy::WHEN_REPAIRED`). `Pipeline_statistics::seconds_tutte` times the Tutte
/// map and `Pipeline_statistics::input_report` certifies it.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`, passed to each stage (the result is the
///         same bit for bit)
/// \tparam TriangleMesh a model of `FaceListGraph` (triangles)
/// \tparam VertexUVMap a model of `ReadWritePropertyMap` with the vertex descriptor as key type and a CGAL `Point_2`
///         as value type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh, a triangulated topological disk
/// \param bhd a border halfedge of `tm`, or the null halfedge (the longest border cycle's)
/// \param uvm the uv map: with `Border_shape::FIXED`, the border's positions; the certified map on success
/// \param np the named parameters of `tutte_embedding()` and `repair_and_optimize()`
///
/// \return `OK` with a certified map, the error of `tutte_embedding()` (nothing written), or that of
///         `repair_and_optimize()`
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code parameterize_certified(const TriangleMesh& tm,
                                  typename boost::graph_traits<TriangleMesh>::halfedge_descriptor bhd,
                                  VertexUVMap uvm, const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  CGAL::Real_timer timer;
  timer.start();
  Pipeline_statistics local;
  Pipeline_statistics* out = choose_parameter(get_parameter(np, internal_np::pipeline_statistics),
                                              static_cast<Pipeline_statistics*>(nullptr));
  Pipeline_statistics& s = out ? *out : local;
  s = Pipeline_statistics();
  // one indexed disk for every stage
  internal::Indexed_disk<TriangleMesh> disk;
  const bool indexed = internal::make_indexed_disk(tm, bhd, disk) == OK;
  const Error_code ec = internal::tutte_embedding_impl<ConcurrencyTag>(tm, bhd, uvm, np, indexed ? &disk : nullptr);
  const double tutte_seconds = timer.time();
  if(ec != OK) { s.seconds_tutte = s.seconds_total = tutte_seconds; return ec; }
  const double max_seconds = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time),
                                              std::numeric_limits<double>::infinity());
  const double left = max_seconds - timer.time();
  internal::start_border_as_default(tm, disk);
  const Error_code er = internal::repair_and_optimize_impl<ConcurrencyTag>(tm, uvm, parameters::pipeline_statistics(&s,
                                                           np.maximum_running_time(left > 0 ? left : 0.)), &disk);
  s.seconds_tutte = tutte_seconds;
  s.seconds_total = timer.time();
  return er;
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_CERTIFIED_PIPELINE_H
