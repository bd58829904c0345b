// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_CHECK_IMMERSION_H
#define CGAL_PROGRESSIVE_EMBEDDING_CHECK_IMMERSION_H

/// \file check_immersion.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/distortion.h>
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

/// \ingroup PkgProgressiveEmbeddingReports
///
/// The exact certificate of a locally injective map (an immersion) of a disk into the plane, returned by
/// `check_immersion()`. An immersion may overlap itself (a map onto a weakly self-overlapping border polygon
/// does), so it is certified locally: every face has the orientation of the map, and the one-ring of every
/// interior vertex winds exactly once around it. A valid embedding (`check_embedding()`) is an immersion; an
/// immersion is an embedding when moreover its border is simple.
struct Immersion_report
{
  /// `OK` when the map could be checked; otherwise why not (`ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`,
  /// `ERROR_NON_MANIFOLD`, `ERROR_NOT_A_DISK`, or `ERROR_WRONG_PARAMETER` for a border polygon of the wrong size)
  Error_code status = OK;
  /// number of faces
  std::size_t faces = 0;
  /// number of vertices
  std::size_t vertices = 0;
  /// number of border vertices
  std::size_t border_vertices = 0;
  /// `true` if the faces are clockwise (the mirror image of a counterclockwise map: then the counts below are
  /// relative to that orientation)
  bool clockwise = false;
  /// faces oriented against the map (the minority orientation)
  std::size_t flipped = 0;
  /// faces of zero area (exact predicate)
  std::size_t degenerate = 0;
  /// vertices with a non-finite coordinate
  std::size_t non_finite = 0;
  /// interior vertices whose one-ring winds a number of times other than once around them (among the interior
  /// vertices whose incident faces are all correctly oriented)
  std::size_t winding_errors = 0;
  /// largest number of turns of the one-ring of an interior vertex (1 for an immersion)
  std::size_t max_winding = 0;
  /// interior vertices not checked because an incident face is flipped, degenerate or not finite
  std::size_t unchecked_vertices = 0;
  /// with a `border_polygon`: the number of border vertices whose uv differs from the polygon's point (compared
  /// by value (`==`: in floating point -0 equals 0), the polygon's first point at the border vertex
  /// `border_polygon_start`)
  std::size_t border_mismatches = 0;
  /// border vertices (among those whose incident faces are all correctly oriented) whose fan of faces does not
  /// turn by the border polygon's angle there plus 2 pi times the vertex's rotation index (index 0 unless the
  /// named parameter `vertex_rotation_index_map` gives one)
  std::size_t border_angle_errors = 0;
  /// largest number of full turns that the fan of a border vertex makes beyond the border polygon's angle there
  /// (0 when no border fan wraps around its vertex)
  std::size_t max_border_turns = 0;

  /// returns `true` if the map is an immersion: no flipped, degenerate or non-finite element, every interior
  /// one-ring winding once, every border fan turning by the border's angle plus its rotation index's full turns,
  /// and (with a border polygon) the border bit-exactly the polygon
  bool is_immersion() const
  {
    return status == OK && faces > 0 && flipped == 0 && degenerate == 0 && non_finite == 0 && winding_errors == 0
        && unchecked_vertices == 0 && border_mismatches == 0 && border_angle_errors == 0;
  }

  /// returns a one-line human-readable summary
  std::string summary() const
  {
    std::ostringstream os;
    if(status != OK) { os << "not checked: " << get_error_message(status); return os.str(); }
    os << (is_immersion() ? "immersion" : "NOT AN IMMERSION") << ": faces " << faces << ", flipped " << flipped
       << ", degenerate " << degenerate;
    if(non_finite) os << ", non-finite vertices " << non_finite;
    os << ", interior one-rings not winding once " << winding_errors << " (max turns " << max_winding << ")";
    if(unchecked_vertices) os << ", unchecked vertices " << unchecked_vertices;
    if(border_angle_errors) os << ", border fans not turning by the border's angle plus their full turns " << border_angle_errors;
    if(max_border_turns) os << ", border fans wrapping up to " << max_border_turns << " extra turn(s)";
    if(border_mismatches) os << ", border vertices off the polygon " << border_mismatches;
    return os.str();
  }
};

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

} // namespace internal

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// certifies exactly that the uv map `uvm` of the disk `tm` is an immersion (a locally injective map): every face
/// strictly oriented like the map (counterclockwise, or every face clockwise for a mirror image), and the one-ring
/// of every interior vertex winding exactly once around it, and the fan of every border vertex turning by the
/// border polygon's angle there plus 2 pi times the vertex's rotation index. The winding is counted exactly: with
/// every incident face correctly oriented, each face turns the direction from the vertex by an angle in (0, pi),
/// and the number of turns is the number of faces whose turn passes the direction (1, 0) (coordinate comparisons
/// and the exact orientation predicate only: exact in every number type, at every scale). Never throws on data.
///
/// <b>Border angles.</b> The border polygon's angle at a border vertex, in (0, 2 pi], is the angle from the
/// direction of the next border vertex to that of the previous one, in the map's orientation (pi at a flat vertex,
/// 2 pi where the border turns back on itself). The uv positions give it only modulo 2 pi, while the fan of
/// faces may wrap around the vertex several times (a border that winds around its vertex, as at a cone of a
/// seamless map cut open): `vertex_rotation_index_map` says how many full turns each border vertex adds, and
/// without it every fan must turn by the border's angle alone. The full turns found are in
/// `Immersion_report::max_border_turns`; `border_rotation_indices()` reads them from a map taken as the reference.
///
/// Overlaps between faces far apart are allowed (a map onto a weakly self-overlapping border has them): use
/// `check_embedding()` for a one-to-one map.
///
/// \tparam TriangleMesh a model of `FaceListGraph` (triangles)
/// \tparam VertexUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type
/// \tparam PointRange a range of the uv map's `Point_2` (only for the second overload)
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh, a triangulated topological disk
/// \param uvm the uv map
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits class whose exact orientation predicate decides every sign}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2` whose `Point_2` is the uv map's value type}
///     \cgalParamDefault{`Progressive_embedding_traits_2<K>`, `K` the kernel of the uv map's point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_rotation_index_map}
///     \cgalParamDescription{the rotation index of every border vertex: the full turns its fan adds to the border's
///                           angle there (a negative value, or one above a million, never matches)}
///     \cgalParamType{a model of `ReadablePropertyMap` with the vertex descriptor as key type and an integral value
///                    type}
///     \cgalParamDefault{all 0: every border fan turns by the border's angle alone}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the report; the map is an immersion iff `Immersion_report::is_immersion()`
template <typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Immersion_report check_immersion(const TriangleMesh& tm, VertexUVMap uvm,
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


/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// certifies that the uv map `uvm` of the disk `tm` is an immersion (as the first overload) whose border is
/// bit-exactly the polygon `border`: the border vertex `start` at `border[0]`, and the next ones along the border
/// (mesh interior on the left) at the next points. A polygon whose size is not the number of border vertices, or a
/// `start` that is not a border vertex, gives `ERROR_WRONG_PARAMETER` in the report's status.
///
/// \param tm the mesh, a triangulated topological disk
/// \param uvm the uv map
/// \param start a border vertex of `tm`
/// \param border the expected uv of the border vertices, from `start` on
/// \param np the named parameters of the first overload (`geom_traits`, `vertex_rotation_index_map`)
template <typename TriangleMesh, typename VertexUVMap, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
Immersion_report check_immersion(const TriangleMesh& tm, VertexUVMap uvm,
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

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// reads, from a map `uvm` of the disk `tm`, how many full turns its border makes around each border vertex beyond
/// its angle in (0, 2 pi]: the rotation index that `constrained_embedding()` takes as `vertex_rotation_index_map` to
/// map onto the same border, and that `check_immersion()` takes to certify such a map. The turns are counted
/// exactly, as `check_immersion()` counts them (coordinate comparisons and the exact orientation predicate, at
/// every scale): the number of times the fan of the vertex passes a fixed direction, minus the times the border's
/// angle alone passes it. A border vertex with a face that is not strictly oriented like the map (or a non-finite
/// point) gets 0, and so does every border vertex when `tm` is not a triangulated disk. Vertices that are not on the
/// border are not written.
///
/// \tparam TriangleMesh a model of `FaceListGraph` (triangles)
/// \tparam VertexUVMap a readable vertex property map whose values are points of a CGAL kernel
/// \tparam VertexIndexMap a writable vertex property map with `int` values
/// \return the sum of the indices written
template <class TriangleMesh, class VertexUVMap, class VertexIndexMap>
int border_rotation_indices(const TriangleMesh& tm, VertexUVMap uvm, VertexIndexMap rotation_index_map)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename internal::Check_traits<VertexUVMap, CGAL::parameters::Default_named_parameters>::type Traits;
  for(halfedge_descriptor h : halfedges(tm))
    if(CGAL::is_border(h, tm)) put(rotation_index_map, target(h, tm), 0);
  internal::Indexed_disk<TriangleMesh> disk;
  if(internal::make_indexed_disk(tm, boost::graph_traits<TriangleMesh>::null_halfedge(), disk) != OK) return 0;
  std::vector<int> measured;
  internal::check_immersion_of_disk(disk, uvm, Traits().exact_orientation_2_object(), std::vector<int>(), &measured);
  int total = 0;
  for(std::size_t k = 0; k < disk.border.size(); ++k)
  {
    const int r = measured[k] > 0 ? measured[k] : 0;
    put(rotation_index_map, disk.vertices[disk.border[k]], r);
    total += r;
  }
  return total;
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_CHECK_IMMERSION_H
