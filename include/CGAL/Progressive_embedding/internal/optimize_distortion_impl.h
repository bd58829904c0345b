// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_OPTIMIZE_DISTORTION_IMPL_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_OPTIMIZE_DISTORTION_IMPL_H

// The body of optimize_distortion(): the named parameters read and handed to the optimizer engine
// of internal/distortion_optimizer.h.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/Optimization_statistics.h>
#include <CGAL/Progressive_embedding/internal/check_embedding_impl.h>
#include <CGAL/Progressive_embedding/internal/distortion_measures.h>
#include <CGAL/Progressive_embedding/internal/distortion_optimizer.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>

#include <functional>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// the body of optimize_distortion() (see its documentation there); `given`: the disk already indexed from
// `tm` by the caller (a pipeline indexes once), or null
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code optimize_distortion_impl(const TriangleMesh& tm, VertexUVMap uvm,
                                    const CGAL_NP_CLASS& np = CGAL::parameters::default_values(),
                                    const Indexed_disk<TriangleMesh>* given = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor    vertex_descriptor;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  typedef typename internal::Check_traits<VertexUVMap, CGAL_NP_CLASS>::type Traits;
  typedef internal::Distortion_optimizer<TriangleMesh, VertexUVMap, decltype(vpm), ConcurrencyTag, Traits> Optimizer;
  const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));

  Optimization_statistics local_stats;
  Optimization_statistics* stats_out =
    choose_parameter(get_parameter(np, internal_np::optimization_statistics), static_cast<Optimization_statistics*>(nullptr));
  Optimization_statistics& stats = stats_out ? *stats_out : local_stats;
  stats = Optimization_statistics();

  typename Optimizer::Settings settings;
  settings.max_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), settings.max_iterations);
  settings.tolerance = choose_parameter(get_parameter(np, internal_np::convergence_tolerance), settings.tolerance);
  settings.time_budget = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), settings.time_budget);
  settings.free_border = choose_parameter(get_parameter(np, internal_np::free_border), false);
  settings.energy = choose_parameter(get_parameter(np, internal_np::distortion_energy), Distortion_energy::SYMMETRIC_DIRICHLET);
  settings.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  settings.callback = choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  settings.reuse_factorization = choose_parameter(get_parameter(np, internal_np::reuse_factorization), settings.reuse_factorization);
  const std::vector<vertex_descriptor> constrained =
    choose_parameter(get_parameter(np, internal_np::constrained_vertices), std::vector<vertex_descriptor>());

  Optimizer optimizer(tm, uvm, vpm, settings, traits);
  Error_code ec = optimizer.initialize(constrained, stats, given);
  stats.energy_before = stats.report.mean_energy_3d;
  if(ec != OK) return ec;                                   // nothing written
  const Error_code result = optimizer.run(stats);
  // every accepted step was certified; the certificate of the whole map is the last guard,
  // taken before anything is written
  stats.report = optimizer.certify();
  stats.energy_after = stats.report.mean_energy_3d;
  if(optimizer.immersion())
  {
    stats.immersion_report = optimizer.certify_immersion();
    if(!stats.immersion_report.is_immersion() || stats.immersion_report.border_mismatches != 0)
      return ERROR_INVALID_EMBEDDING;                       // nothing written
  }
  else if(!stats.report.is_valid()) return ERROR_INVALID_EMBEDDING;  // nothing written
  optimizer.write();
  return result;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_OPTIMIZE_DISTORTION_IMPL_H
