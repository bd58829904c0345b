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
#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Progressive_embedding/Error_code.h>
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

/// \ingroup PkgProgressiveEmbeddingReports
///
/// What `triangulate_self_overlapping_polygon_2()` found, filled through its named parameter
/// `polygon_report` (also when it fails).
struct Polygon_triangulation_report
{
  /// number of polygon vertices
  std::size_t vertices = 0;
  /// rotation (turning) number of the polygon, computed exactly: +1 or -1 for a weakly self-overlapping
  /// polygon; 0 when not computed (fewer than 3 vertices, a non-finite coordinate, a repeated consecutive
  /// vertex or a reversal)
  int rotation_number = 0;
  /// `true` if the polygon is oriented clockwise (rotation number -1)
  bool clockwise = false;
  /// `true` if the polygon is simple (no two edges meet except consecutive ones at their common vertex;
  /// exact); decided only when the rotation number is +1 or -1
  bool simple = false;
  /// `true` if the polygon is weakly self-overlapping (simple polygons included) and was triangulated
  bool self_overlapping = false;
  /// sum of the rotation indices given (named parameter `rotation_indices`; 0 without them)
  int turns = 0;
  /// `true` if the triangulation came from the dynamic program (the polygon is not simple)
  bool dynamic_program = false;
  /// dynamic program: chords that passed the exact sector and rotation tests
  std::size_t chords_tested = 0;
  /// dynamic program: chords stored as valid (one 32-bit word each), edges included
  std::size_t chords_stored = 0;
  /// dynamic program: candidate triangles tested
  std::size_t triangles_tested = 0;
  /// wall-clock seconds of the call
  double seconds = 0;
};


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

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_TRIANGULATE_SELF_OVERLAPPING_POLYGON_2_H
