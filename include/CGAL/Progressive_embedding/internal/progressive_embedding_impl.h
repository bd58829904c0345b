// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_IMPL_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_IMPL_H

// The body of progressive_embedding(): the options read from the named parameters, the repair of a
// disk map by the progressive embedder, and the certificate of what it writes.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/internal/check_embedding_impl.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_statistics.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/border_polygon.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Progressive_embedding/internal/scaling.h>
#include <CGAL/Progressive_embedding/internal/progressive_embedding/progressive_embedder.h>
#include <CGAL/Progressive_embedding/internal/patch_chords.h>

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
namespace internal {

// The embedder's options from the named parameters of progressive_embedding()
// (ERROR_WRONG_PARAMETER when one is out of range).
template <class Traits, class NamedParameters>
Error_code progressive_embedder_options(const NamedParameters& np, typename Progressive_embedder<Traits>::Options& opt)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  opt.energy_threshold = choose_parameter(get_parameter(np, internal_np::invalid_energy_threshold), 1e20);
  Insertion_options& iopt = opt.insertion;
  iopt.smoothing_iterations = choose_parameter(get_parameter(np, internal_np::smoothing_iterations),
                                               Traits::has_exact_constructions ? 0 : 10);
  iopt.retry_smoothing_iterations = choose_parameter(get_parameter(np, internal_np::retry_smoothing_iterations), 50);
  iopt.line_search_factor = choose_parameter(get_parameter(np, internal_np::line_search_factor), 0.8);
  iopt.line_search_steps = choose_parameter(get_parameter(np, internal_np::line_search_steps), 75);
  iopt.insertion_retries = choose_parameter(get_parameter(np, internal_np::insertion_retries), 20);
  opt.expansion_budget = choose_parameter(get_parameter(np, internal_np::collapse_budget), std::size_t(-1));
  opt.time_budget = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time), std::numeric_limits<double>::infinity());
  opt.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  opt.callback = choose_parameter(get_parameter(np, CGAL::internal_np::callback), std::function<bool(double)>());
  opt.initial_min_area_ratio = choose_parameter(get_parameter(np, internal_np::minimum_area_ratio), opt.initial_min_area_ratio);
  opt.min_area_ratio_given = !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::minimum_area_ratio_t>::value;
  if(!(iopt.line_search_factor > 0 && iopt.line_search_factor < 1) || iopt.line_search_steps < 1
     || iopt.smoothing_iterations < 0 || iopt.retry_smoothing_iterations < 0 || iopt.insertion_retries < 0
     || !(opt.energy_threshold > 0) || !(opt.initial_min_area_ratio >= 0 && opt.initial_min_area_ratio < 1))
    return ERROR_WRONG_PARAMETER;
  return OK;
}

// Progressive embedding of the positions `P` (by vertex index of `disk`, all finite) whose
// border polygon `B` (in border order) is convex -- strictly, or weakly without flat chord
// (the callers check both exactly) -- and oriented as `orientation` says (+1 counterclockwise,
// -1 clockwise). On OK, `P` holds the repaired map, its border bit-exactly unchanged; the
// map is not certified here. On error `P` is unchanged. `stats` receives the counters.
template <class Traits, class TriangleMesh>
Error_code repair_disk_map(const Indexed_disk<TriangleMesh>& disk, const std::vector<typename Traits::Point_2>& B,
                           int orientation, const Traits& traits, const typename Progressive_embedder<Traits>::Options& opt,
                           std::vector<typename Traits::Point_2>& P, Progressive_embedding_statistics& stats)
{
  typedef typename Traits::Point_2 Point_2;
  typedef typename Traits::FT      FT;
  const std::size_t nv = disk.number_of_vertices(), nb = disk.border.size();
  std::vector<Point_2> W(P);
  // a clockwise layout is repaired as its mirror image (negation is exact, so the border round-trips bit-exactly)
  const bool mirrored = orientation < 0;
  if(mirrored)
    for(Point_2& p : W) p = Point_2(p.x(), -p.y());
  // Work on the map scaled by the power of two that brings the border's bounding box to about 1:
  // squared areas and energies stay in range at any scale, and the border is bit-exact (checked).
  const Power_of_two_scaling<FT> scaling = Power_of_two_scaling<FT>::normalizing(B);
  if(scaling.exponent() != 0)
    for(std::size_t i = 0; i < nv; ++i)
    {
      Point_2& p = W[i];
      p = Point_2(scaling.forward(p.x()), scaling.forward(p.y()));
      // an interior vertex far outside a tiny border may overflow: any finite place will do, its faces are invalid
      if(!is_finite_ft(p.x()) || !is_finite_ft(p.y()))
        p = Point_2(scaling.forward(B[0].x()), mirrored ? -scaling.forward(B[0].y()) : scaling.forward(B[0].y()));
    }
  // faces with three border vertices cannot move: they must already be positive
  typename Traits::Exact_orientation_2 orient = traits.exact_orientation_2_object();
  for(const auto& t : disk.faces)
    if(disk.on_border[t[0]] && disk.on_border[t[1]] && disk.on_border[t[2]]
       && orient(W[t[0]], W[t[1]], W[t[2]]) != CGAL::LEFT_TURN)
      return ERROR_DEGENERATE_BORDER;
  // The area inside the border (it sets the reference triangle and the area floor), summed
  // relative to a border vertex: the shoelace sum on absolute coordinates cancels down to the
  // rounding of its terms, which are as large as the coordinates squared -- for a patch 1e-9
  // across at 0.36 that noise is 1000 times the area, and of either sign.
  FT twice_area(0);
  const Point_2& o = W[disk.border[0]];
  for(std::size_t k = 1; k + 1 < nb; ++k)
  {
    const Point_2& a = W[disk.border[k]];
    const Point_2& b = W[disk.border[k + 1]];
    twice_area += (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  }
  Error_code ec;
  {
    // the embedder (its working mesh and collapse history) is gone before the caller certifies
    Progressive_embedder<Traits> pe(traits, opt);
    ec = pe.run(W, disk.faces, disk.on_border, twice_area / FT(2));
    stats = pe.counters; // the stages count into the public statistics; timings and report follow
  }
  if(ec != OK) return ec;
  for(std::size_t i = 0; i < nv; ++i)
  {
    if(disk.on_border[i]) continue;
    const FT x = scaling.backward(W[i].x()), y = scaling.backward(W[i].y());
    P[i] = Point_2(x, mirrored ? -y : y);
  }
  return OK;
}

// the body of progressive_embedding() (see its documentation there); `given`: the disk already indexed from
// `tm` by the caller (a pipeline indexes once), or null
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code progressive_embedding_impl(const TriangleMesh& tm, VertexUVMap uvm,
                                      const CGAL_NP_CLASS& np = CGAL::parameters::default_values(),
                                      const Indexed_disk<TriangleMesh>* given = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh>                                GT;
  typedef typename internal::Uv_map_types<VertexUVMap>::Point_2           Point_2;
  typedef typename internal::Check_traits<VertexUVMap, CGAL_NP_CLASS>::type Traits;

  CGAL::Real_timer timer;
  timer.start();
  Progressive_embedding_statistics local_stats;
  Progressive_embedding_statistics* stats_out =
    choose_parameter(get_parameter(np, internal_np::statistics), static_cast<Progressive_embedding_statistics*>(nullptr));
  Progressive_embedding_statistics& stats = stats_out ? *stats_out : local_stats;
  stats = Progressive_embedding_statistics();

  typename internal::Progressive_embedder<Traits>::Options opt;
  Error_code ec = internal::progressive_embedder_options<Traits>(np, opt);
  if(ec != OK) return ec;

  internal::Indexed_disk<TriangleMesh> own;
  ec = given ? OK : internal::make_indexed_disk(tm, GT::null_halfedge(), own);
  if(ec != OK) return ec;
  const internal::Indexed_disk<TriangleMesh>& disk = given ? *given : own;
  const std::size_t nv = disk.number_of_vertices(), nb = disk.border.size();
  if(nb < 3) return ERROR_BORDER_TOO_SHORT;

  std::vector<Point_2> P(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    P[i] = get(uvm, disk.vertices[i]);
    if(!internal::is_finite_ft(P[i].x()) || !internal::is_finite_ft(P[i].y()))
      return ERROR_NON_FINITE_COORDINATES;
  }
  std::vector<Point_2> B(nb);
  for(std::size_t k = 0; k < nb; ++k) B[k] = P[disk.border[k]];
  int orientation = 0;
  const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const internal::Polygon_class pc = internal::classify_convex_polygon(B, traits.exact_orientation_2_object(), orientation);
  if(pc == internal::Polygon_class::DEGENERATE) return ERROR_DEGENERATE_BORDER;
  if(pc == internal::Polygon_class::NON_CONVEX) return ERROR_NON_CONVEX_BORDER;
  if(pc == internal::Polygon_class::CONVEX)
  {
    // weakly convex: an interior edge along a side cannot be made valid
    std::vector<std::pair<std::size_t, std::size_t> > chords;
    internal::flat_chords(disk, B, traits.exact_orientation_2_object(), chords);
    if(!chords.empty()) return ERROR_DEGENERATE_CHORD;
  }
  ec = internal::repair_disk_map(disk, B, orientation, traits, opt, P, stats);
  if(ec != OK) { stats.seconds_total = timer.time(); return ec; }
  // write back (interior only: the border is untouched), keeping the old values in P for a
  // rollback, and certify what was written
  for(std::size_t i = 0; i < nv; ++i)
  {
    if(disk.on_border[i]) continue;
    const Point_2 old = get(uvm, disk.vertices[i]);
    put(uvm, disk.vertices[i], P[i]);
    P[i] = old;
  }
  const double t_certificate = timer.time();
  stats.report = check_embedding_impl(tm, uvm, CGAL::parameters::vertex_point_map(
                   choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm)))
                   .geom_traits(traits), &disk);
  stats.seconds_total = timer.time();
  stats.seconds_certification = stats.seconds_total - t_certificate;
  if(!stats.report.is_valid())
  {
    for(std::size_t i = 0; i < nv; ++i)
      if(!disk.on_border[i]) put(uvm, disk.vertices[i], P[i]);
    return ERROR_INVALID_EMBEDDING;
  }
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PROGRESSIVE_EMBEDDING_IMPL_H
