// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SELF_OVERLAPPING_TRIANGULATE_POLYGON_IMPL_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SELF_OVERLAPPING_TRIANGULATE_POLYGON_IMPL_H

// The body of triangulate_self_overlapping_polygon_2(): the exact checks of the input, then the
// simple path (constrained Delaunay), the Shor-Van Wyk program or the cuts at turned vertices.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Progressive_embedding/Polygon_triangulation_report.h>
#include <CGAL/Progressive_embedding/internal/self_overlapping/polygon_turns.h>
#include <CGAL/Progressive_embedding/internal/self_overlapping/shor_van_wyk.h>
#include <CGAL/Progressive_embedding/internal/self_overlapping/simple_polygon_cdt.h>
#include <CGAL/Progressive_embedding/internal/self_overlapping/turn_cuts.h>

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
namespace internal {

// the body of triangulate_self_overlapping_polygon_2() (see its documentation there)
template <typename PointRange, typename TriangleOutputIterator, typename CGAL_NP_TEMPLATE_PARAMETERS>
Error_code triangulate_self_overlapping_polygon_2_impl(const PointRange& points, TriangleOutputIterator triangles,
                                                       const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::range_value<PointRange>::type                                 Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel                                 Kernel;
  typedef Progressive_embedding_traits_2<Kernel>                                        Default_traits;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
            CGAL::internal_np::geom_traits_t, CGAL_NP_CLASS, Default_traits>::type      Traits;
  static_assert(std::is_same<Point_2, typename Traits::Point_2>::value,
                "the geom_traits' Point_2 must be the value type of the point range");
  typedef typename Traits::FT                                                           FT;
  typedef typename Traits::Exact_orientation_2                                          Orientation_2;
  namespace SO = internal::self_overlapping;

  CGAL::Real_timer timer;
  timer.start();
  Polygon_triangulation_report local_report;
  Polygon_triangulation_report* report_out =
    choose_parameter(get_parameter(np, internal_np::polygon_report), static_cast<Polygon_triangulation_report*>(nullptr));
  Polygon_triangulation_report& report = report_out ? *report_out : local_report;
  report = Polygon_triangulation_report();
  struct Stop_timer // the report's time on every return
  {
    Polygon_triangulation_report& r; CGAL::Real_timer& t;
    ~Stop_timer() { r.seconds = t.time(); }
  } stop_timer{report, timer};

  const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const Orientation_2 orient = traits.exact_orientation_2_object();
  const double max_seconds = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time),
                                              std::numeric_limits<double>::infinity());
  if(!(max_seconds >= 0)) return ERROR_WRONG_PARAMETER;

  try // only std::bad_alloc can come out of the containers below
  {
    std::vector<Point_2> P(std::begin(points), std::end(points));
    const std::size_t n = P.size();
    report.vertices = n;
    if(n < 3) return ERROR_BORDER_TOO_SHORT;
    if(n > std::size_t((std::numeric_limits<std::uint32_t>::max)())) return ERROR_WRONG_PARAMETER;
    for(const Point_2& p : P)
      if(!internal::is_finite_ft<FT>(p.x()) || !internal::is_finite_ft<FT>(p.y())) return ERROR_NON_FINITE_COORDINATES;

    // exact turns: no repeated consecutive point, no reversal, rotation number +1 or -1
    int rotation = 0;
    for(std::size_t v = 0; v < n; ++v)
    {
      const Point_2& a = P[(v + n - 1) % n];
      const Point_2& b = P[v];
      const Point_2& c = P[(v + 1) % n];
      if(SO::same_point(a, b)) return ERROR_NOT_SELF_OVERLAPPING; // no positive triangle has a zero-length edge
      int crossing = 0;
      if(!SO::turn_crossing(a, b, c, orient, crossing)) return ERROR_NOT_SELF_OVERLAPPING; // angle 0 or 2 pi
      rotation += crossing;
    }
    report.rotation_number = rotation;
    const std::vector<int> no_turns;
    const std::vector<int> turns = choose_parameter(get_parameter(np, internal_np::rotation_indices), no_turns);
    if(!turns.empty())
    {
      if(turns.size() != n) return ERROR_WRONG_PARAMETER;
      long long sum = 0;
      for(int t : turns) { if(t < 0) return ERROR_WRONG_PARAMETER; sum += t; }
      if(sum > 0)
      {
        report.turns = sum > (std::numeric_limits<int>::max)() ? (std::numeric_limits<int>::max)() : int(sum);
        if(rotation - sum != 1) return ERROR_NOT_SELF_OVERLAPPING;
        std::vector<std::size_t> idx(n);
        for(std::size_t t = 0; t < n; ++t) idx[t] = t;
        std::vector<std::array<std::size_t, 3> > T;
        report.dynamic_program = true;
        SO::Dp_statistics st;
        SO::Turn_cuts<Point_2, Orientation_2> cuts(P, orient, timer, max_seconds);
        const Error_code ec = cuts.solve(idx, turns, T, st);
        report.chords_tested = st.chords_tested;
        report.chords_stored = st.chords_valid;
        report.triangles_tested = st.triangles_tested;
        if(ec != OK) return ec;
        if(T.size() != n - 2) return ERROR_NOT_SELF_OVERLAPPING; // cannot happen: each cut adds up
        report.self_overlapping = true;
        for(const std::array<std::size_t, 3>& t : T) *triangles++ = t;
        return OK;
      }
    }
    if(rotation != 1 && rotation != -1) return ERROR_NOT_SELF_OVERLAPPING;
    report.clockwise = (rotation == -1);

    // the working polygon is counterclockwise: index t of Q is index of[t] of the input
    std::vector<std::size_t> of(n);
    for(std::size_t t = 0; t < n; ++t) of[t] = report.clockwise ? n - 1 - t : t;
    std::vector<Point_2> Q;
    Q.reserve(n);
    for(std::size_t t = 0; t < n; ++t) Q.push_back(P[of[t]]);
    std::vector<Point_2>().swap(P);

    std::vector<std::array<std::size_t, 3> > T;
    const SO::Cdt_result cdt = SO::cdt_triangulate_simple_polygon(Q, T);
    report.simple = (cdt != SO::Cdt_result::NOT_SIMPLE);
    if(timer.time() > max_seconds) return ERROR_BUDGET_EXHAUSTED;
    if(cdt != SO::Cdt_result::SIMPLE)
    {
      // not simple (or, defensively, a simple polygon whose triangulation came out wrong)
      report.dynamic_program = true;
      SO::Dp_statistics st;
      SO::Shor_van_wyk<Point_2, Orientation_2> dp(Q, orient);
      const Error_code ec = dp.run(timer, max_seconds, T, st);
      report.chords_tested = st.chords_tested;
      report.chords_stored = st.chords_valid;
      report.triangles_tested = st.triangles_tested;
      if(ec != OK) return ec;
    }
    if(timer.time() > max_seconds) return ERROR_BUDGET_EXHAUSTED;
    report.self_overlapping = true;
    for(const std::array<std::size_t, 3>& t : T)
      *triangles++ = std::array<std::size_t, 3>{{ of[t[0]], of[t[1]], of[t[2]] }};
    return OK;
  }
  catch(const std::bad_alloc&)
  {
    return ERROR_BUDGET_EXHAUSTED; // the memory ran out: a budget too
  }
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_SELF_OVERLAPPING_TRIANGULATE_POLYGON_IMPL_H
