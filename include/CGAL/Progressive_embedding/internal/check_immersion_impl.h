// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CHECK_IMMERSION_IMPL_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CHECK_IMMERSION_IMPL_H

// The certificate of an immersion on an indexed disk (orientations, interior windings, border fans
// with their rotation indices) and the body of check_immersion().

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/Immersion_report.h>
#include <CGAL/Progressive_embedding/internal/distortion_measures.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <iterator>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// 0 if the direction from c to p points into the half-open upper half-plane [0, pi), 1 into [pi, 2 pi)
// (exact: coordinate comparisons only)
template <class Point_2>
int direction_half(const Point_2& c, const Point_2& p)
{
  const CGAL::Comparison_result cy = CGAL::compare(p.y(), c.y());
  if(cy == CGAL::LARGER) return 0;
  if(cy == CGAL::SMALLER) return 1;
  return CGAL::compare(p.x(), c.x()) == CGAL::LARGER ? 0 : 1;
}


// the rotation index of v in the user's map (any integral value type); -1 for a value no mesh border can
// turn (negative, or beyond a million turns)
template <class Map, class Vertex>
int read_rotation_index(const Map& m, Vertex v)
{
  const auto r = get(m, v);
  if(r < 0) return -1;
  if(r > 1000000) return -1;
  return static_cast<int>(r);
}

// true if the direction from c to b is after the direction from c to a in the order of angles in [0, 2 pi)
// from (1, 0) (the half-planes of direction_half; exact)
template <class Point_2, class Orientation_2>
bool direction_after(const Point_2& c, const Point_2& a, const Point_2& b, const Orientation_2& orient)
{
  const int ha = direction_half(c, a), hb = direction_half(c, b);
  if(ha != hb) return hb > ha;
  return orient(c, a, b) == CGAL::POSITIVE; // within a half-plane the turn is below pi
}

// the certificate of check_immersion() on a disk already indexed (its border order is the one the
// border-polygon overload compares with). rotation_indices: per border position k (disk.border[k]), the full
// turns expected beyond the border's angle (empty: all 0). measured_indices (if given): per border position, the
// full turns the fan makes beyond the border's angle, -1 where not decided (a face there not correctly
// oriented or not finite).
template <class TriangleMesh, class VertexUVMap, class Orientation_2>
Immersion_report check_immersion_of_disk(const Indexed_disk<TriangleMesh>& disk, VertexUVMap uvm,
                                         const Orientation_2& orient,
                                         const std::vector<int>& rotation_indices = std::vector<int>(),
                                         std::vector<int>* measured_indices = nullptr)
{
  typedef typename Uv_map_types<VertexUVMap>::Point_2 Point_2;
  Immersion_report r;
  const std::size_t nv = disk.number_of_vertices(), nf = disk.number_of_faces();
  r.faces = nf;
  r.vertices = nv;
  r.border_vertices = disk.border.size();

  std::vector<Point_2> P(nv);
  std::vector<char> finite(nv, 1);
  for(std::size_t i = 0; i < nv; ++i)
  {
    P[i] = get(uvm, disk.vertices[i]);
    if(!is_finite_ft(P[i].x()) || !is_finite_ft(P[i].y())) { finite[i] = 0; ++r.non_finite; }
  }

  // face orientations; the map's orientation is the majority one (a mirror image is an immersion too)
  std::vector<signed char> sign(nf, 0);
  std::size_t positive = 0, negative = 0;
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = disk.faces[f];
    if(!finite[t[0]] || !finite[t[1]] || !finite[t[2]]) { sign[f] = 2; continue; } // not decided
    const CGAL::Orientation o = orient(P[t[0]], P[t[1]], P[t[2]]);
    sign[f] = static_cast<signed char>(o == CGAL::POSITIVE ? 1 : o == CGAL::NEGATIVE ? -1 : 0);
    if(o == CGAL::POSITIVE) ++positive;
    else if(o == CGAL::NEGATIVE) ++negative;
    else ++r.degenerate;
  }
  r.clockwise = negative > positive;
  const signed char good = r.clockwise ? -1 : 1;
  r.flipped = r.clockwise ? positive : negative;

  // winding of each interior one-ring: a correctly oriented face (c, a, b) turns the direction from c by an
  // angle in (0, pi) counterclockwise (clockwise for a mirror image); the turn passes the direction (1, 0) iff
  // it goes from the lower half-open half-plane to the upper one (the reverse for a mirror image). Border
  // vertices are counted the same way, over their fan.
  std::vector<std::size_t> turns(nv, 0);
  std::vector<char> bad(nv, 0);
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = disk.faces[f];
    const bool ok = sign[f] == good;
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t c = t[k], a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      if(!ok) { bad[c] = 1; continue; }
      const int ha = direction_half(P[c], P[a]), hb = direction_half(P[c], P[b]);
      if(r.clockwise ? (ha == 0 && hb == 1) : (ha == 1 && hb == 0)) ++turns[c];
    }
  }
  for(std::size_t i = 0; i < nv; ++i)
  {
    if(disk.on_border[i]) continue;
    if(bad[i]) { ++r.unchecked_vertices; continue; }
    r.max_winding = (std::max)(r.max_winding, turns[i]);
    if(turns[i] != 1) ++r.winding_errors;
  }

  // border fans: the fan of c = border[k] turns (mesh order) from c -> border[k+1] to c -> border[k-1], by the
  // border polygon's angle theta in (0, 2 pi] (pi for a flat vertex, 2 pi for a reversal) plus 2 pi rho, rho its
  // rotation index. Counterclockwise, starting at the angle s of c -> next, it passes the direction (1, 0)
  // floor((s + theta) / 2 pi) + rho times: 1 + rho if c -> prev is not after c -> next (theta reaches 2 pi),
  // rho otherwise. A mirror image turns clockwise: 1 + rho if c -> prev is not before c -> next.
  const std::size_t nb = disk.border.size();
  if(measured_indices) measured_indices->assign(nb, -1);
  for(std::size_t k = 0; k < nb; ++k)
  {
    const std::size_t c = disk.border[k], n = disk.border[(k + 1) % nb], p = disk.border[(k + nb - 1) % nb];
    if(bad[c] || !finite[c] || !finite[n] || !finite[p]) continue; // a face there is already counted as wrong
    const bool wraps = r.clockwise ? !direction_after(P[c], P[p], P[n], orient)
                                   : !direction_after(P[c], P[n], P[p], orient);
    const long long rho = static_cast<long long>(turns[c]) - (wraps ? 1 : 0);
    if(measured_indices) (*measured_indices)[k] = static_cast<int>((std::max)(rho, -1LL));
    const long long expected = rotation_indices.empty() ? 0 : rotation_indices[k];
    if(rho != expected) ++r.border_angle_errors;
    if(rho > 0) r.max_border_turns = (std::max)(r.max_border_turns, static_cast<std::size_t>(rho));
  }
  return r;
}

// the rotation indices of the named parameters, per border position of the disk (empty without them)
template <class TriangleMesh, class NamedParameters>
std::vector<int> named_rotation_indices(const Indexed_disk<TriangleMesh>& disk, const NamedParameters& np)
{
  typedef typename CGAL::internal_np::Lookup_named_param_def<internal_np::vertex_rotation_index_map_t, NamedParameters,
                                                             CGAL::internal_np::Param_not_found>::type Map;
  std::vector<int> r;
  if constexpr(!std::is_same<Map, CGAL::internal_np::Param_not_found>::value)
  {
    const Map m = CGAL::parameters::get_parameter(np, internal_np::vertex_rotation_index_map);
    for(std::size_t b : disk.border) r.push_back(read_rotation_index(m, disk.vertices[b]));
  }
  return r;
}

// the body of check_immersion() (see its documentation there)
template <typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Immersion_report check_immersion_impl(const TriangleMesh& tm, VertexUVMap uvm,
                                      const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename internal::Check_traits<VertexUVMap, CGAL_NP_CLASS>::type Traits;
  const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const typename Traits::Exact_orientation_2 orient = traits.exact_orientation_2_object();

  internal::Indexed_disk<TriangleMesh> disk;
  const Error_code ec = internal::make_indexed_disk(tm, boost::graph_traits<TriangleMesh>::null_halfedge(), disk);
  if(ec != OK) { Immersion_report r; r.status = ec; return r; }
  return internal::check_immersion_of_disk(disk, uvm, orient, internal::named_rotation_indices(disk, np));
}

// the body of check_immersion() (see its documentation there)
template <typename TriangleMesh, typename VertexUVMap, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
Immersion_report check_immersion_impl(const TriangleMesh& tm, VertexUVMap uvm,
                                      typename boost::graph_traits<TriangleMesh>::vertex_descriptor start,
                                      const PointRange& border,
                                      const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename internal::Check_traits<VertexUVMap, CGAL_NP_CLASS>::type Traits;
  const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  internal::Indexed_disk<TriangleMesh> disk;
  const Error_code ec = internal::make_indexed_disk(tm, boost::graph_traits<TriangleMesh>::null_halfedge(), disk);
  if(ec != OK) { Immersion_report r; r.status = ec; return r; }
  Immersion_report r = internal::check_immersion_of_disk(disk, uvm, traits.exact_orientation_2_object(),
                                                         internal::named_rotation_indices(disk, np));
  const std::size_t n = disk.border.size();
  if(static_cast<std::size_t>(std::distance(std::begin(border), std::end(border))) != n)
  {
    r.status = ERROR_WRONG_PARAMETER;
    return r;
  }
  std::size_t first = n;
  for(std::size_t k = 0; k < n; ++k) if(disk.vertices[disk.border[k]] == start) { first = k; break; }
  if(first == n) { r.status = ERROR_WRONG_PARAMETER; return r; }
  std::size_t k = 0;
  for(const auto& p : border)
  {
    const auto q = get(uvm, disk.vertices[disk.border[(first + k) % n]]);
    // bit-exact: equal values (and for floating point the same zero sign does not matter to the map)
    if(!(q.x() == p.x() && q.y() == p.y())) ++r.border_mismatches;
    ++k;
  }
  return r;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CHECK_IMMERSION_IMPL_H
