// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_CROSS_PARAMETERIZATION_H
#define CGAL_PROGRESSIVE_EMBEDDING_CROSS_PARAMETERIZATION_H

/// \file cross_parameterization.h
///
/// `cross_parameterization()`: a map between two triangulated disks A and B with matched landmarks,
/// through two certified planar maps of one unit square. The steps:
///  1. validation of both meshes (triangulated disks) and of the landmarks (vertices of their mesh, each used
///     once, both inside or both on their borders, the border ones in the same order along both borders),
///     nothing computed before it passes;
///  2. both borders on the unit square, matched by relative 3D arc length from a matched pair of
///     border vertices (internal/cross/common_border.h);
///  3. B's map: Tutte, repaired if needed and optimized (`parameterize_certified()`), certified; then,
///     with interior landmarks, made again by `constrained_embedding()` on a copy of B with B's landmarks
///     pinned where that map put them (the copy possibly refined), certified;
///  4. A's map on a refined copy of A: `constrained_embedding()` with every landmark of A pinned
///     bit-exactly at the uv of its partner in B's map, certified, then optimized for the composed map;
///  5. each vertex of A located in B's map (internal/cross/locate_in_map.h: exact orientations,
///     coordinates in exact rationals rounded once; on a refined copy of B, rounded once more), written to the
///     output map.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/certified_pipeline.h>
#include <CGAL/Progressive_embedding/constrained_embedding.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/Progressive_embedding/internal/parallel_for.h>
#include <CGAL/Progressive_embedding/internal/scaling.h>
#include <CGAL/Progressive_embedding/internal/cross/certify_overlay.h>
#include <CGAL/Progressive_embedding/internal/cross/common_border.h>
#include <CGAL/Progressive_embedding/internal/cross/composed_distortion.h>
#include <CGAL/Progressive_embedding/internal/cross/cut_border.h>
#include <CGAL/Progressive_embedding/internal/cross/cut_closed.h>
#include <CGAL/Progressive_embedding/internal/cross/cut_pair.h>
#include <CGAL/Progressive_embedding/internal/cross/failure_reason.h>
#include <CGAL/Progressive_embedding/internal/cross/locate_in_map.h>
#include <CGAL/Progressive_embedding/internal/cross/overlay_maps.h>
#include <CGAL/Progressive_embedding/internal/cross/weld_cut_overlay.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <boost/functional/hash.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

#ifndef DOXYGEN_RUNNING
// The parameters of cross_parameterization(): NAME(t) starts a pack of this package, NAME(t, pack) appends to
// any pack (CGAL's or this package's, taken as the CGAL pack it is), as the functions of parameters.h.
namespace internal_np {
enum border_vertex_pair_t { border_vertex_pair };
enum b_to_a_locations_t { b_to_a_locations };
enum compatible_meshes_t { compatible_meshes };
enum composed_distortion_t { composed_distortion };
enum matched_maps_t { matched_maps };
enum planar_maps_t { planar_maps };
} // namespace internal_np

namespace parameters {
template <typename T> Named_function_parameters<T, internal_np::border_vertex_pair_t> border_vertex_pair(const T& t)
{ return Named_function_parameters<T, internal_np::border_vertex_pair_t>(t); }
template <typename T, typename P, typename G, typename B>
Named_function_parameters<T, internal_np::border_vertex_pair_t, CGAL::Named_function_parameters<P, G, B> >
border_vertex_pair(const T& t, const CGAL::Named_function_parameters<P, G, B>& np) { return { t, np }; }

template <typename T> Named_function_parameters<T, internal_np::b_to_a_locations_t> b_to_a_locations(const T& t)
{ return Named_function_parameters<T, internal_np::b_to_a_locations_t>(t); }
template <typename T, typename P, typename G, typename B>
Named_function_parameters<T, internal_np::b_to_a_locations_t, CGAL::Named_function_parameters<P, G, B> >
b_to_a_locations(const T& t, const CGAL::Named_function_parameters<P, G, B>& np) { return { t, np }; }

template <typename T> Named_function_parameters<T, internal_np::compatible_meshes_t> compatible_meshes(const T& t)
{ return Named_function_parameters<T, internal_np::compatible_meshes_t>(t); }
template <typename T, typename P, typename G, typename B>
Named_function_parameters<T, internal_np::compatible_meshes_t, CGAL::Named_function_parameters<P, G, B> >
compatible_meshes(const T& t, const CGAL::Named_function_parameters<P, G, B>& np) { return { t, np }; }

template <typename T> Named_function_parameters<T, internal_np::composed_distortion_t> composed_distortion(const T& t)
{ return Named_function_parameters<T, internal_np::composed_distortion_t>(t); }
template <typename T, typename P, typename G, typename B>
Named_function_parameters<T, internal_np::composed_distortion_t, CGAL::Named_function_parameters<P, G, B> >
composed_distortion(const T& t, const CGAL::Named_function_parameters<P, G, B>& np) { return { t, np }; }

template <typename T> Named_function_parameters<T, internal_np::matched_maps_t> matched_maps(const T& t)
{ return Named_function_parameters<T, internal_np::matched_maps_t>(t); }
template <typename T, typename P, typename G, typename B>
Named_function_parameters<T, internal_np::matched_maps_t, CGAL::Named_function_parameters<P, G, B> >
matched_maps(const T& t, const CGAL::Named_function_parameters<P, G, B>& np) { return { t, np }; }

template <typename T> Named_function_parameters<T, internal_np::planar_maps_t> planar_maps(const T& t)
{ return Named_function_parameters<T, internal_np::planar_maps_t>(t); }
template <typename T, typename P, typename G, typename B>
Named_function_parameters<T, internal_np::planar_maps_t, CGAL::Named_function_parameters<P, G, B> >
planar_maps(const T& t, const CGAL::Named_function_parameters<P, G, B>& np) { return { t, np }; }
} // namespace parameters
#else
namespace parameters {
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the matched pair of border vertices of `cross_parameterization()` (a `std::pair` of a vertex of A and a vertex
/// of B, both on their border); `border_vertex_pair(t, np)` appends it to the pack `np` (this package's or CGAL's)
template <typename T> unspecified_type border_vertex_pair(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// a writable property map from the vertices of B to `Cross_location<TriangleMeshA>` that receives, from
/// `cross_parameterization()`, the location on A of every vertex of B (the other direction);
/// `b_to_a_locations(t, np)` appends it to the pack `np`
template <typename T> unspecified_type b_to_a_locations(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the named parameter `compatible_meshes` of `cross_parameterization()`: a `std::pair` of pointers to the two
/// output meshes; `compatible_meshes(t, np)` appends it to the pack `np`
template <typename T> unspecified_type compatible_meshes(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the named parameter `composed_distortion` of `cross_parameterization()`: a `bool`, whether A's map is optimized
/// once more for the distortion of the composed map; `composed_distortion(t, np)` appends it to the pack `np`
template <typename T> unspecified_type composed_distortion(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the named parameter `matched_maps` of `cross_parameterization()`: a `bool`, whether B's map is made again the way
/// A's is, by `constrained_embedding()` with B's landmarks pinned; `matched_maps(t, np)` appends it to the pack `np`
template <typename T> unspecified_type matched_maps(const T& t);
/// \ingroup PkgProgressiveEmbeddingNamedParameters
/// the named parameter `planar_maps` of `cross_parameterization()`: a `std::pair` of pointers to two output meshes
/// that receive the certified planar maps of A and B; `planar_maps(t, np)` appends it to the pack `np`
template <typename T> unspecified_type planar_maps(const T& t);
} // namespace parameters
#endif

/// \ingroup PkgProgressiveEmbeddingReports
/// What `cross_parameterization()` did, filled when a pointer to it is passed with the `statistics` named parameter
/// (also on error, as far as the computation went).
struct Cross_parameterization_statistics
{
  /// on an error about one landmark (`ERROR_WRONG_PARAMETER`: a vertex not of its mesh; `ERROR_LANDMARK_ORDER`: a
  /// border landmark out of the order of the others along B's border; `ERROR_CONSTRAINT_ON_BORDER`; `ERROR_DUPLICATE_CONSTRAINT`: a vertex of
  /// A or of B used twice, the later one, or a border landmark that gives a vertex of `border_vertex_pair` another
  /// partner; `ERROR_BORDER_TOO_SHORT`: the border landmark at the end of the first arc of A's border found with too few
  /// vertices for the corners of the square that B's arc holds, when no other place holds them,
  /// `std::size_t(-1)` when that arc ends at `border_vertex_pair`;
  /// for closed meshes `ERROR_PATH_TRACING_FAILED`: the landmark the
  /// cut cannot reach from the one before it on the cut, and `ERROR_NOT_A_DISK`: the second of two landmarks joined by
  /// an edge): its position in the `landmarks` range; `std::size_t(-1)` otherwise
  std::size_t failed_landmark = std::size_t(-1);
  /// the mesh an error is about: 0 for A, 1 for B, -1 for none (a mesh that is not a disk or has fewer than four
  /// border vertices, a landmark vertex, a border vertex of `border_vertex_pair`, a map that failed)
  int failed_mesh = -1;
  /// vertices of A (as given)
  std::size_t vertices_a = 0;
  /// faces of A (as given)
  std::size_t faces_a = 0;
  /// vertices of B
  std::size_t vertices_b = 0;
  /// faces of B
  std::size_t faces_b = 0;
  /// landmark pairs (interior and border)
  std::size_t landmarks = 0;
  /// landmark pairs on the borders
  std::size_t border_landmarks = 0;
  /// vertices added to A's copy by `constrained_embedding()` (kept after its coarsening); they are not reported
  std::size_t vertices_added_a = 0;
  /// vertices of A located inside a face of B (decided exactly)
  std::size_t located_in_face = 0;
  /// vertices of A located on an edge of B (decided exactly)
  std::size_t located_on_edge = 0;
  /// vertices of A located on a vertex of B (decided exactly)
  std::size_t located_on_vertex = 0;
  /// vertices of A not located in B's map (0 unless a certificate is wrong: the call then fails)
  std::size_t unlocated = 0;
  /// whether every landmark of A is located exactly on its partner (barycentric coordinate 1 there)
  bool landmarks_exact = false;
  /// with `b_to_a_locations`: vertices of B located on A (all of them on success)
  std::size_t located_b_on_a = 0;
  /// seconds spent validating the input and placing the borders
  double seconds_validation = 0;
  /// seconds spent mapping B
  double seconds_map_b = 0;
  /// seconds spent mapping A
  double seconds_map_a = 0;
  /// seconds spent locating the vertices
  double seconds_location = 0;
  /// with `compatible_meshes`: faces of the overlay of the two maps (each the intersection of a face of A's refined
  /// copy and a face of B, a convex polygon)
  std::size_t overlay_cells = 0;
  /// with `compatible_meshes`: vertices of the overlay where an edge of one map crosses an edge of the other
  std::size_t overlay_crossings = 0;
  /// with `compatible_meshes`: vertices added inside cells that no fan from a corner triangulates without a flat triangle
  std::size_t overlay_centers = 0;
  /// with `compatible_meshes`: vertices of each compatible mesh
  std::size_t compatible_vertices = 0;
  /// with `compatible_meshes`: faces of each compatible mesh
  std::size_t compatible_faces = 0;
  /// with `compatible_meshes`: seconds spent on the overlay, its certificate and the two meshes
  double seconds_compatible = 0;
  /// whether both meshes were closed (genus 0) and cut into disks along a chain of landmarks; the counts and
  /// certificates above are then those of the cut disks (`landmarks` is then the number of landmark pairs given)
  bool closed = false;
  /// closed meshes: landmarks on the cut, its two ends and the landmarks between them (2 unless no pair of
  /// landmarks cuts both meshes, see `cross_parameterization()`); the other landmarks are inside the cut disks
  std::size_t cut_landmarks = 0;
  /// closed meshes: edges of A on the cut (each becomes two border edges of the cut disk)
  std::size_t cut_edges_a = 0;
  /// closed meshes: edges of B on the cut
  std::size_t cut_edges_b = 0;
  /// closed meshes: edges of B's cut disk joining two of its border vertices (where two paths of the cut run side by
  /// side) split at their midpoints, when B's map had failed with `ERROR_DEGENERATE_CHORD`; two disks: edges of B
  /// joining two border vertices of one side of the square, split by B's first map made on a copy of B
  /// (`constrained_embedding()`), when B itself had no valid map (`ERROR_DEGENERATE_CHORD`); 0 otherwise
  std::size_t chords_split_b = 0;
  /// closed meshes with `compatible_meshes`: vertices of the cut disks' overlay on the cut, joined two by two (the
  /// same vertex of A or of B on both sides of the cut) into one vertex of the compatible meshes
  std::size_t cut_vertices_welded = 0;
  /// with `compatible_meshes`: the certificate of the triangulated overlay in exact coordinates (`CGAL::Epeck`
  /// points): a triangulated disk, every triangle counterclockwise, the border simple and counterclockwise, decided
  /// by filtered exact predicates; its areas are those of the points rounded to double and its energies are not
  /// computed. Should any of these fail, it is the report of `check_embedding()` on those points.
  Embedding_report report_compatible;
  /// seconds in all
  double seconds_total = 0;
  /// the certificate of B's map (`check_embedding()`)
  Embedding_report report_b;
  /// the certificate of A's map, on A's refined copy (`check_embedding()`)
  Embedding_report report_a;
  /// what `parameterize_certified()` did for B's map (when it failed with `ERROR_DEGENERATE_CHORD`, B's first map
  /// was made on a refined copy instead: `chords_split_b`)
  Pipeline_statistics map_b;
  /// what `constrained_embedding()` did for A's map
  Constrained_embedding_statistics map_a;
  /// with `composed_distortion` (the default): the optimization of A's map for the distortion of the composed map;
  /// `energy_current` is that distortion (area-weighted mean symmetric Dirichlet energy of the composed map, 4 for an
  /// isometry), `energy_before` and `energy_after` are A's map's own (`check_embedding()`'s `mean_energy_3d`)
  Optimization_statistics composed;
  /// the status of that optimization: `OK` (converged, or no step lowers the energy), `ERROR_BUDGET_EXHAUSTED` (stopped
  /// by its time or iteration budget: A's map is the last certified one; or not run at all because
  /// `maximum_running_time` was already spent: `seconds_composed` is then 0), another error (A's map is kept as
  /// `constrained_embedding()` left it).
  Error_code composed_status = OK;
  /// seconds spent on that optimization (part of `seconds_map_a`)
  double seconds_composed = 0;
  /// with `matched_maps` (the default) and interior landmarks: whether B's map is the one made the way A's is
  /// (`constrained_embedding()` on a copy of B with B's landmarks pinned where B's first map put them); `false` when
  /// that map failed or was not made (B's first map is then kept)
  bool matched_b = false;
  /// what `constrained_embedding()` did for that map of B (`Constrained_embedding_statistics::optimization` is its
  /// optimization)
  Constrained_embedding_statistics map_b_matched;
  /// the status of `constrained_embedding()` for that map (`OK` when it was not asked for: `matched_maps` false or no
  /// interior landmark; `ERROR_BUDGET_EXHAUSTED` also when it was not made because `maximum_running_time` was already
  /// spent); on another status, or when its map is not certified (`ERROR_INVALID_EMBEDDING`), B's first map is kept
  Error_code matched_status = OK;
  /// `true` when that map was made and certified but its mean distortion energy (`Embedding_report::mean_energy_3d`)
  /// is more than 5% above that of B's first map, which has the same border and the same landmark positions, and more
  /// than 5% above that of A's map, made the same way: it went around the landmarks another way than A's, and B's
  /// first map is kept (`matched_b` is then `false`)
  bool matched_more_distorted = false;
  /// vertices added to B's copy by that `constrained_embedding()` and kept after its coarsening (or, when B's first
  /// map is kept and was made on a refined copy, `chords_split_b`, the vertices added to that copy): B's map is then
  /// on the refined copy, whose added vertices lie on B's faces (B itself is not changed; its vertices are still
  /// located in A's map and every location is written in B's faces)
  std::size_t vertices_added_b = 0;
};

/// \ingroup PkgProgressiveEmbeddingMainFunctions
/// The location of a point of A on B: a face of B and the barycentric coordinates of the point with respect to
/// `source(halfedge(f))`, `target(halfedge(f))` and `target(next(halfedge(f)))` (the convention of
/// `CGAL::Polygon_mesh_processing::Face_location`, so that `CGAL::Polygon_mesh_processing::construct_point()` gives
/// its 3D point on B).
template <class TriangleMeshB>
using Cross_location = CGAL::Polygon_mesh_processing::Face_location<TriangleMeshB, double>;

namespace internal {

// whether B's matched map may replace its first map: both certified, with the same border and landmark positions;
// the matched map's mean energy at most 5% above the first's, or (`a`: A's constrained map, made the same way) at most
// 5% above A's map's: a matched map that goes around the landmarks as A's does keeps the two maps alike (reports
// without 3D energies are not compared)
inline bool matched_map_acceptable(const Embedding_report& first, const Embedding_report& matched,
                                   const Embedding_report* a = nullptr)
{
  if(!first.has_3d_energy || !matched.has_3d_energy || !std::isfinite(first.mean_energy_3d)) return true;
  if(matched.mean_energy_3d <= 1.05 * first.mean_energy_3d) return true;
  return a != nullptr && a->has_3d_energy && matched.mean_energy_3d <= 1.05 * a->mean_energy_3d;
}

// What the function on two closed meshes asks of the one on their cut disks (Cross_settings::cut):
// the borders placed on the square (internal/cross/cut_border.h), and with `compatible` the triangulated overlay as
// soups with, for each of its points, the vertex of each disk it is (indices in `vertices(tm)` order, or -1).
struct Cut_request
{
  std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_2> border_uv_a, border_uv_b; // per disk vertex
  bool compatible = false;
  std::vector<std::array<double, 3> > on_a, on_b;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::array<std::size_t, 2> > origins;
};

// the convex combination of three values: numbers, std::array of numbers, CGAL points and colours
template <class T>
T weighted_sum(const std::array<T, 3>& v, const std::array<double, 3>& w)
{
  if constexpr(std::is_arithmetic<T>::value)
    return static_cast<T>(w[0] * v[0] + w[1] * v[1] + w[2] * v[2]);
  else if constexpr(std::is_same<T, CGAL::IO::Color>::value)
  {
    auto mix = [&](int c) {
      const double x = w[0] * v[0][c] + w[1] * v[1][c] + w[2] * v[2][c];
      return static_cast<unsigned char>((std::min)(255., (std::max)(0., std::round(x))));
    };
    return T(mix(0), mix(1), mix(2), mix(3));
  }
  else
    return CGAL::barycenter(v[0], w[0], v[1], w[1], v[2], w[2]);
}

template <class T, std::size_t N>
std::array<T, N> weighted_sum(const std::array<std::array<T, N>, 3>& v, const std::array<double, 3>& w)
{
  std::array<T, N> r;
  for(std::size_t i = 0; i < N; ++i) r[i] = static_cast<T>(w[0] * v[0][i] + w[1] * v[1][i] + w[2] * v[2][i]);
  return r;
}

// The points `queries` (uv in the map of `work`, the refined copy of A) located on the faces of A: each
// located in the refined map, then written in the face of A holding the refined face (every vertex of
// `work` is a vertex of A or a Steiner point, a combination of the vertices of one face of A).
// ERROR_INVALID_EMBEDDING if a point is outside the map (cannot happen with two certified maps of one domain).
// The common refinement of A's refined map (`work`, `uv`) and B's map (`map_b` on `disk_b`'s faces),
// triangulated: the points of each vertex on A's surface and on B's, and the triangles. The overlay
// is certified in exact coordinates (`stats.report_compatible`).
template <class Work, class UVMap, class TriangleMeshB, class Point_2>
Error_code compatible_soups(const Work& work, UVMap uv, const TriangleMeshB& tm_b, const Indexed_disk<TriangleMeshB>& disk_b,
                            const std::vector<Point_2>& map_b, Cross_parameterization_statistics& stats,
                            std::vector<std::array<double, 3> >& on_a, std::vector<std::array<double, 3> >& on_b,
                            std::vector<std::array<std::size_t, 3> >& triangles,
                            std::vector<std::array<std::size_t, 2> >* origins = nullptr,
                            const std::vector<typename boost::graph_traits<Work>::vertex_descriptor>* disk_a_in_work = nullptr,
                            const std::vector<std::size_t>* b_in_disk = nullptr)
{
  typedef typename boost::graph_traits<Work>::vertex_descriptor wvertex;
  typedef CGAL::Epeck EK;
  std::vector<Point_2> map_a;
  std::vector<std::array<double, 3> > points_a;
  std::unordered_map<wvertex, std::size_t> index;
  const auto vpm_work = get(CGAL::vertex_point, work);
  for(wvertex v : vertices(work))
  {
    index.emplace(v, map_a.size());
    map_a.push_back(get(uv, v));
    const auto& p = get(vpm_work, v);
    points_a.push_back({{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }});
  }
  std::vector<std::array<std::size_t, 3> > faces_a;
  for(auto f : faces(work))
  {
    const auto h = halfedge(f, work);
    faces_a.push_back({{ index.at(source(h, work)), index.at(target(h, work)), index.at(target(next(h, work), work)) }});
  }
  const auto vpm_b = get(CGAL::vertex_point, tm_b);
  std::vector<std::array<double, 3> > points_b;
  for(auto v : disk_b.vertices)
  {
    const auto& p = get(vpm_b, v);
    points_b.push_back({{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }});
  }
  Map_overlay overlay;
  Error_code ec = overlay_maps(map_a, faces_a, map_b, disk_b.faces, overlay);
  if(ec != OK) return ec;
  stats.overlay_cells = overlay.cells;
  stats.overlay_crossings = overlay.crossings;
  stats.overlay_centers = overlay.centers;

  // the certificate of the triangulated overlay, in its exact coordinates
  stats.report_compatible = certify_overlay(overlay.points, overlay.triangles);
  if(!stats.report_compatible.is_valid()) return ERROR_INVALID_EMBEDDING;

  // Each vertex on both surfaces, from where it lies in each map: a map vertex gets its own point bit for bit;
  // a point inside an edge, the point at its parameter along the edge; a point inside a face, its barycentric
  // coordinates there. Parameters and coordinates come from the interval approximation of the point (exact
  // points would cost an exact evaluation of every crossing).
  auto place = [](const EK::Point_2& q, const Map_feature& feature, const std::array<std::size_t, 3>& face,
                  const std::vector<Point_2>& map, const std::vector<std::array<double, 3> >& points) {
    constexpr std::size_t none = std::size_t(-1);
    if(feature[0] != none && feature[1] == none) return points[feature[0]];
    const double qx = CGAL::to_double(q.x()), qy = CGAL::to_double(q.y());
    std::array<std::size_t, 3> corner = face;
    double w[3] = { 0, 0, 0 };
    if(feature[0] != none)
    {
      const Point_2& u = map[feature[0]];
      const Point_2& v = map[feature[1]];
      const double dx = v.x() - u.x(), dy = v.y() - u.y();
      const double t = (std::min)(1., (std::max)(0., ((qx - u.x()) * dx + (qy - u.y()) * dy) / (dx * dx + dy * dy)));
      corner = {{ feature[0], feature[1], feature[1] }};
      w[0] = 1 - t;
      w[1] = t;
    }
    else
    {
      const Point_2 &c0 = map[face[0]], &c1 = map[face[1]], &c2 = map[face[2]];
      auto twice_area = [](double ax, double ay, double bx, double by, double cx, double cy) {
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
      };
      w[0] = (std::max)(0., twice_area(qx, qy, c1.x(), c1.y(), c2.x(), c2.y()));
      w[1] = (std::max)(0., twice_area(c0.x(), c0.y(), qx, qy, c2.x(), c2.y()));
      w[2] = (std::max)(0., twice_area(c0.x(), c0.y(), c1.x(), c1.y(), qx, qy));
      const double sum = w[0] + w[1] + w[2];
      for(double& x : w) x /= sum;
    }
    std::array<double, 3> r{{ 0, 0, 0 }};
    for(int k = 0; k < 3; ++k)
      for(int d = 0; d < 3; ++d) r[d] += w[k] * points[corner[k]][d];
    return r;
  };
  on_a.assign(overlay.points.size(), std::array<double, 3>());
  on_b.assign(overlay.points.size(), std::array<double, 3>());
  std::vector<bool> placed(overlay.points.size(), false);
  for(std::size_t t = 0; t < overlay.triangles.size(); ++t)
    for(std::size_t i : overlay.triangles[t])
      if(!placed[i])
      {
        placed[i] = true;
        on_a[i] = place(overlay.points[i], overlay.features[i][0], faces_a[overlay.cell_faces[t][0]], map_a, points_a);
        on_b[i] = place(overlay.points[i], overlay.features[i][1], disk_b.faces[overlay.cell_faces[t][1]], map_b, points_b);
      }
  // the vertex of each map that a point is: of A, its index in A's disk (`disk_a_in_work`: the vertex of the copy
  // of each), -1 for a Steiner vertex; of B, its index in `disk_b`, or, B's map on a refined copy (`disk_b` is then
  // the copy's), in B's own disk (`b_in_disk`, -1 for a Steiner vertex)
  if(origins != nullptr && disk_a_in_work != nullptr)
  {
    constexpr std::size_t none = std::size_t(-1);
    std::vector<std::size_t> disk_index(map_a.size(), none);
    for(std::size_t i = 0; i < disk_a_in_work->size(); ++i) disk_index[index.at((*disk_a_in_work)[i])] = i;
    origins->assign(overlay.points.size(), {{ none, none }});
    for(std::size_t i = 0; i < overlay.points.size(); ++i)
    {
      const Map_feature& fa = overlay.features[i][0];
      const Map_feature& fb = overlay.features[i][1];
      if(fa[0] != none && fa[1] == none) (*origins)[i][0] = disk_index[fa[0]];
      if(fb[0] != none && fb[1] == none) (*origins)[i][1] = b_in_disk != nullptr ? (*b_in_disk)[fb[0]] : fb[0];
    }
  }
  triangles.swap(overlay.triangles);
  stats.compatible_vertices = overlay.points.size();
  stats.compatible_faces = triangles.size();
  return OK;
}

// `out` cleared and made of `points` and `triangles`, its vertices and faces in their order
template <class Mesh>
void write_soup(const std::vector<std::array<double, 3> >& points, const std::vector<std::array<std::size_t, 3> >& triangles,
                Mesh& out)
{
  typedef typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point_3;
  std::vector<Point_3> p;
  p.reserve(points.size());
  for(const auto& q : points) p.emplace_back(q[0], q[1], q[2]);
  clear(out);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(p, triangles, out);
}

// A planar map as a soup of points (u, v, 0): first the vertices of `work` standing for the mesh's own vertices, in
// the order of `first`, then the other vertices of `work` (those added to a refined copy) in the order of
// vertices(work); the faces of `work`, each from its halfedge (counterclockwise in a valid map).
template <class Work, class UVMap>
void planar_soup(const Work& work, UVMap uv, const std::vector<typename boost::graph_traits<Work>::vertex_descriptor>& first,
                 std::vector<std::array<double, 3> >& points, std::vector<std::array<std::size_t, 3> >& triangles)
{
  typedef typename boost::graph_traits<Work>::vertex_descriptor wvertex;
  std::unordered_map<wvertex, std::size_t, boost::hash<wvertex> > index;
  points.clear();
  triangles.clear();
  auto add = [&](wvertex v) {
    if(!index.emplace(v, points.size()).second) return;
    const auto& p = get(uv, v);
    points.push_back({{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), 0. }});
  };
  for(wvertex v : first) add(v);
  for(wvertex v : vertices(work)) add(v);
  for(auto f : faces(work))
  {
    const auto h = halfedge(f, work);
    triangles.push_back({{ index.at(source(h, work)), index.at(target(h, work)), index.at(target(next(h, work), work)) }});
  }
}

template <class TriangleMeshA, class Work, class UVMap, class ToWork, class SteinerPoints, class Point_2>
Error_code locate_on_refined_copy(const TriangleMeshA& tm_a, const Indexed_disk<TriangleMeshA>& disk_a, const Work& work,
                                  UVMap uv, const ToWork& to_work, const SteinerPoints& steiner,
                                  const std::vector<Point_2>& queries,
                                  std::vector<CGAL::Polygon_mesh_processing::Face_location<TriangleMeshA, double> >& result,
                                  std::size_t* unlocated = nullptr)
{
  typedef typename boost::graph_traits<Work>::vertex_descriptor wvertex;
  typedef typename boost::graph_traits<TriangleMeshA>::vertex_descriptor vertex_a;
  // each vertex of the copy as a combination of at most three vertices of A (indices into disk_a)
  typedef std::vector<std::pair<std::size_t, double> > Combination;
  std::unordered_map<wvertex, Combination> combination;
  std::unordered_map<wvertex, std::size_t> copy_index;
  for(std::size_t i = 0; i < disk_a.vertices.size(); ++i)
  {
    const wvertex w = to_work.at(disk_a.vertices[i]);
    combination[w] = Combination(1, std::make_pair(i, 1.));
    copy_index[w] = i;
  }
  for(const auto& sp : steiner)
  {
    Combination c;
    for(std::size_t k = 0; k < sp.size; ++k) c.emplace_back(copy_index.at(sp.corners[k]), sp.weights[k]);
    combination[sp.vertex] = c;
  }
  std::unordered_map<wvertex, std::size_t> index;
  std::vector<Point_2> map_uv;
  std::vector<wvertex> wv;
  for(wvertex v : vertices(work)) { index[v] = map_uv.size(); map_uv.push_back(get(uv, v)); wv.push_back(v); }
  std::vector<std::array<std::size_t, 3> > wfaces;
  for(auto f : faces(work))
  {
    const auto h = halfedge(f, work);
    wfaces.push_back({{ index[source(h, work)], index[target(h, work)], index[target(next(h, work), work)] }});
  }
  std::vector<Map_location> located;
  const std::size_t outside = locate_in_map(map_uv, wfaces, queries, located);
  if(unlocated != nullptr) *unlocated = outside;
  if(outside > 0) return ERROR_INVALID_EMBEDDING;
  result.resize(queries.size());
  for(std::size_t q = 0; q < queries.size(); ++q)
  {
    std::map<std::size_t, double> w; // vertex of A -> weight
    for(int i = 0; i < 3; ++i)
    {
      const double l = located[q].barycentric[i];
      if(l == 0) continue;
      for(const auto& c : combination.at(wv[wfaces[located[q].face][i]])) w[c.first] += l * c.second;
    }
    // the face of A around the first vertex that holds every vertex of the combination
    const vertex_a v0 = disk_a.vertices[w.begin()->first];
    bool found = false;
    for(auto h : halfedges_around_target(halfedge(v0, tm_a), tm_a))
    {
      if(is_border(h, tm_a)) continue;
      const auto g = halfedge(face(h, tm_a), tm_a);
      const std::array<vertex_a, 3> corners{{ source(g, tm_a), target(g, tm_a), target(next(g, tm_a), tm_a) }};
      std::array<double, 3> b{{ 0, 0, 0 }};
      std::size_t matched = 0;
      for(const auto& e : w)
        for(int i = 0; i < 3; ++i)
          if(corners[i] == disk_a.vertices[e.first]) { b[i] = e.second; ++matched; }
      if(matched != w.size()) continue;
      result[q] = CGAL::Polygon_mesh_processing::Face_location<TriangleMeshA, double>(face(h, tm_a), b);
      found = true;
      break;
    }
    if(!found) return ERROR_INVALID_EMBEDDING; // a refined face not inside one face of A: cannot happen
  }
  return OK;
}

} // namespace internal

#ifndef DOXYGEN_RUNNING
namespace internal {

// whether the mesh-pair parameter `tag` (compatible_meshes, planar_maps) is given with a pointer that is not null:
// two null pointers ask for nothing, so that a caller deciding at run time (a binding) can pass the parameter always
template <class Tag, class NamedParameters>
bool asks_for_meshes(const NamedParameters& np, Tag tag)
{
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, Tag>::value) return false;
  else
  {
    const auto meshes = CGAL::parameters::get_parameter(np, tag);
    return meshes.first != nullptr || meshes.second != nullptr;
  }
}

// The named parameters of cross_parameterization(), read once by it: the computation below is a template of the two
// meshes only, so that calls with different parameter packs (and with different location maps) share one
// instantiation of it; what it computes comes back in a Cross_output, written by the caller once all is certified.
// the landmarks as (vertex of A, vertex of B) pairs
template <class TriangleMeshA, class TriangleMeshB>
using Landmark_pairs = std::vector<std::pair<typename boost::graph_traits<TriangleMeshA>::vertex_descriptor,
                                             typename boost::graph_traits<TriangleMeshB>::vertex_descriptor> >;

template <class TriangleMeshA, class TriangleMeshB>
struct Cross_settings
{
  Cross_parameterization_statistics* statistics = nullptr;
  double max_seconds = std::numeric_limits<double>::infinity();
  double optimization_seconds = 30;
  bool has_border_vertex_pair = false;
  std::pair<typename boost::graph_traits<TriangleMeshA>::vertex_descriptor,
            typename boost::graph_traits<TriangleMeshB>::vertex_descriptor> border_vertex_pair;
  bool matched_maps = true;
  bool composed_distortion = true;
  bool b_to_a = false;            // b_to_a_locations given
  bool compatible_meshes = false; // compatible_meshes given with a mesh to write
  bool planar_maps = false;       // planar_maps given with a mesh to write
  Cut_request* cut = nullptr;     // set by the function on two closed meshes for their cut disks
};

template <class TriangleMeshA, class TriangleMeshB>
struct Cross_output
{
  std::vector<typename boost::graph_traits<TriangleMeshA>::vertex_descriptor> vertices_a;
  std::vector<Cross_location<TriangleMeshB> > locations;   // of vertices_a[i]
  std::vector<typename boost::graph_traits<TriangleMeshB>::vertex_descriptor> vertices_b;
  std::vector<Cross_location<TriangleMeshA> > locations_b; // of vertices_b[i], with b_to_a
  std::vector<std::array<double, 3> > compatible_a, compatible_b; // the compatible meshes: points on A, on B
  std::vector<std::array<std::size_t, 3> > compatible_triangles;
  std::vector<std::array<double, 3> > plane_a, plane_b;    // the planar maps
  std::vector<std::array<std::size_t, 3> > plane_faces_a, plane_faces_b;
};

template <class TriangleMeshA, class TriangleMeshB, class NamedParameters>
void read_cross_settings(const NamedParameters& np, Cross_settings<TriangleMeshA, TriangleMeshB>& s)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  s.statistics = choose_parameter(get_parameter(np, internal_np::statistics), static_cast<Cross_parameterization_statistics*>(nullptr));
  s.max_seconds = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time),
                                   std::numeric_limits<double>::infinity());
  s.optimization_seconds = choose_parameter(get_parameter(np, internal_np::optimization_time_limit), 30.);
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::border_vertex_pair_t>::value)
  {
    s.has_border_vertex_pair = true;
    s.border_vertex_pair = get_parameter(np, internal_np::border_vertex_pair);
  }
  s.matched_maps = choose_parameter(get_parameter(np, internal_np::matched_maps), true);
  s.composed_distortion = choose_parameter(get_parameter(np, internal_np::composed_distortion), true);
  s.b_to_a = !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::b_to_a_locations_t>::value;
  s.compatible_meshes = asks_for_meshes(np, internal_np::compatible_meshes);
  s.planar_maps = asks_for_meshes(np, internal_np::planar_maps);
}

template <class ConcurrencyTag, class TriangleMeshA, class TriangleMeshB>
Error_code cross_parameterization_closed(
  const TriangleMeshA& tm_a, const TriangleMeshB& tm_b,
  const Landmark_pairs<TriangleMeshA, TriangleMeshB>& landmarks,
  const Cross_settings<TriangleMeshA, TriangleMeshB>& settings, Cross_output<TriangleMeshA, TriangleMeshB>& output);

// cross_parameterization() of two disks (or, both closed, through cross_parameterization_closed())
template <class ConcurrencyTag, class TriangleMeshA, class TriangleMeshB>
Error_code cross_parameterization_disks(
  const TriangleMeshA& tm_a, const TriangleMeshB& tm_b,
  const Landmark_pairs<TriangleMeshA, TriangleMeshB>& landmarks,
  const Cross_settings<TriangleMeshA, TriangleMeshB>& settings, Cross_output<TriangleMeshA, TriangleMeshB>& output)
{
  typedef boost::graph_traits<TriangleMeshA>                         GTA;
  typedef boost::graph_traits<TriangleMeshB>                         GTB;
  typedef typename GTA::vertex_descriptor                            vertex_a;
  typedef typename GTB::vertex_descriptor                            vertex_b;
  typedef typename GTB::face_descriptor                              face_b;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel        K2;
  typedef K2::Point_2                                                Point_2;
  typedef typename boost::property_map<TriangleMeshA, CGAL::vertex_point_t>::const_type VPMA;
  typedef typename boost::property_traits<VPMA>::value_type          Point_3a;
  typedef CGAL::Surface_mesh<Point_3a>                               Work;
  typedef typename boost::graph_traits<Work>::vertex_descriptor      wvertex;
  typedef typename boost::property_map<TriangleMeshB, CGAL::vertex_point_t>::const_type VPMB;
  typedef typename boost::property_traits<VPMB>::value_type          Point_3b;
  typedef CGAL::Surface_mesh<Point_3b>                               Work_b;
  typedef typename boost::graph_traits<Work_b>::vertex_descriptor    wbvertex;

  CGAL::Real_timer timer;
  timer.start();
  Cross_parameterization_statistics local_stats;
  Cross_parameterization_statistics& stats = settings.statistics ? *settings.statistics : local_stats;
  stats = Cross_parameterization_statistics();
  auto finish = [&](Error_code ec) { stats.seconds_total = timer.time(); return ec; };
  const double max_seconds = settings.max_seconds;
  const double optimization_seconds = settings.optimization_seconds;
  if(!(max_seconds >= 0) || !(optimization_seconds >= 0)) return finish(ERROR_WRONG_PARAMETER);

  // ---- 1. validation -----------------------------------------------------------------------
  // an empty mesh is neither closed nor a disk: said so before the two kinds are compared
  if(faces(tm_a).empty()) { stats.failed_mesh = 0; return finish(ERROR_EMPTY_MESH); }
  if(faces(tm_b).empty()) { stats.failed_mesh = 1; return finish(ERROR_EMPTY_MESH); }
  // two closed surfaces: cut into disks between two landmarks (or along the chain of all)
  const bool closed_a = internal::is_closed_mesh(tm_a), closed_b = internal::is_closed_mesh(tm_b);
  if(closed_a && closed_b) return internal::cross_parameterization_closed<ConcurrencyTag>(tm_a, tm_b, landmarks, settings, output);
  if(closed_a || closed_b) { stats.failed_mesh = closed_a ? 0 : 1; return finish(ERROR_NOT_A_DISK); }
  const auto vpm_a = get(CGAL::vertex_point, tm_a);
  const auto vpm_b = get(CGAL::vertex_point, tm_b);
  internal::Indexed_disk<TriangleMeshA> disk_a;
  internal::Indexed_disk<TriangleMeshB> disk_b;
  Error_code ec = internal::make_indexed_disk(tm_a, GTA::null_halfedge(), disk_a);
  if(ec != OK) { stats.failed_mesh = 0; return finish(ec); }
  ec = internal::make_indexed_disk(tm_b, GTB::null_halfedge(), disk_b);
  if(ec != OK) { stats.failed_mesh = 1; return finish(ec); }
  stats.vertices_a = disk_a.number_of_vertices();
  stats.faces_a = disk_a.number_of_faces();
  stats.vertices_b = disk_b.number_of_vertices();
  stats.faces_b = disk_b.number_of_faces();
  if(!internal::points_are_finite(tm_a, get(CGAL::vertex_point, tm_a))) { stats.failed_mesh = 0; return finish(ERROR_NON_FINITE_COORDINATES); }
  if(!internal::points_are_finite(tm_b, get(CGAL::vertex_point, tm_b))) { stats.failed_mesh = 1; return finish(ERROR_NON_FINITE_COORDINATES); }
  std::unordered_map<vertex_a, std::size_t, boost::hash<vertex_a> > index_a;
  std::unordered_map<vertex_b, std::size_t, boost::hash<vertex_b> > index_b;
  for(std::size_t i = 0; i < disk_a.vertices.size(); ++i) index_a.emplace(disk_a.vertices[i], i);
  for(std::size_t i = 0; i < disk_b.vertices.size(); ++i) index_b.emplace(disk_b.vertices[i], i);

  std::vector<std::pair<std::size_t, std::size_t> > pairs; // interior landmarks as indices into disk_a, disk_b
  std::vector<std::pair<std::size_t, std::size_t> > border_pairs; // border landmarks, likewise
  std::vector<std::size_t> border_pair_input; // the position in `landmarks` of each border landmark
  {
    std::unordered_set<std::size_t> seen_a, seen_b;
    std::size_t position = 0;
    for(const auto& l : landmarks)
    {
      stats.failed_landmark = position;
      const auto ia = index_a.find(l.first);
      if(ia == index_a.end()) { stats.failed_mesh = 0; return finish(ERROR_WRONG_PARAMETER); }
      const auto ib = index_b.find(l.second);
      if(ib == index_b.end()) { stats.failed_mesh = 1; return finish(ERROR_WRONG_PARAMETER); }
      // a border landmark needs a partner on the other border
      const bool border_a = disk_a.on_border[ia->second], border_b = disk_b.on_border[ib->second];
      if(border_a != border_b) { stats.failed_mesh = border_a ? 0 : 1; return finish(ERROR_CONSTRAINT_ON_BORDER); }
      if(!seen_a.insert(ia->second).second) { stats.failed_mesh = 0; return finish(ERROR_DUPLICATE_CONSTRAINT); }
      if(!seen_b.insert(ib->second).second) { stats.failed_mesh = 1; return finish(ERROR_DUPLICATE_CONSTRAINT); }
      if(border_a) { border_pairs.emplace_back(ia->second, ib->second); border_pair_input.push_back(position); }
      else pairs.emplace_back(ia->second, ib->second);
      ++position;
    }
    stats.failed_landmark = std::size_t(-1);
    stats.landmarks = pairs.size() + border_pairs.size();
    stats.border_landmarks = border_pairs.size();
  }

  // ---- 2. the common border ------------------------------------------------------------------
  // positions of the matched vertices on their border cycles
  std::vector<std::size_t> border_pos_a(disk_a.number_of_vertices(), std::size_t(-1));
  std::vector<std::size_t> border_pos_b(disk_b.number_of_vertices(), std::size_t(-1));
  for(std::size_t k = 0; k < disk_a.border.size(); ++k) border_pos_a[disk_a.border[k]] = k;
  for(std::size_t k = 0; k < disk_b.border.size(); ++k) border_pos_b[disk_b.border[k]] = k;
  std::size_t start_a = 0, start_b = 0;
  typedef std::pair<vertex_a, vertex_b> Vertex_pair;
  if(settings.has_border_vertex_pair)
  {
    const Vertex_pair given = settings.border_vertex_pair;
    const auto ia = index_a.find(given.first);
    if(ia == index_a.end() || border_pos_a[ia->second] == std::size_t(-1)) { stats.failed_mesh = 0; return finish(ERROR_WRONG_PARAMETER); }
    const auto ib = index_b.find(given.second);
    if(ib == index_b.end() || border_pos_b[ib->second] == std::size_t(-1)) { stats.failed_mesh = 1; return finish(ERROR_WRONG_PARAMETER); }
    start_a = border_pos_a[ia->second];
    start_b = border_pos_b[ib->second];
    // the pair is matched like a border landmark; a vertex of it in another landmark must have the same partner
    bool listed = false;
    for(std::size_t k = 0; k < border_pairs.size(); ++k)
    {
      const auto& bp = border_pairs[k];
      if(bp.first == ia->second && bp.second == ib->second) listed = true;
      else if(bp.first == ia->second || bp.second == ib->second)
      {
        // the landmark that gives one of the pair's vertices another partner
        stats.failed_landmark = border_pair_input[k];
        stats.failed_mesh = bp.first == ia->second ? 0 : 1;
        return finish(ERROR_DUPLICATE_CONSTRAINT);
      }
    }
    if(!listed && !border_pairs.empty())
    {
      border_pairs.emplace_back(ia->second, ib->second);
      border_pair_input.push_back(std::size_t(-1));
    }
  }
  else if(!border_pairs.empty())
  {
    // the first border landmark at the corner (0,0)
    start_a = border_pos_a[border_pairs.front().first];
    start_b = border_pos_b[border_pairs.front().second];
  }
  else
  {
    const std::pair<std::size_t, std::size_t> start = internal::default_start_pair(disk_a, vpm_a, disk_b, vpm_b);
    start_a = start.first;
    start_b = start.second;
  }
  // a square needs four border vertices on each mesh: say which one has fewer
  if(disk_a.border.size() < 4) { stats.failed_mesh = 0; return finish(ERROR_BORDER_TOO_SHORT); }
  if(disk_b.border.size() < 4) { stats.failed_mesh = 1; return finish(ERROR_BORDER_TOO_SHORT); }
  std::vector<Point_2> border_uv_a, border_uv_b;
  if(border_pairs.size() < 2)
    ec = internal::common_square_border(disk_a, vpm_a, start_a, disk_b, vpm_b, start_b, border_uv_a, border_uv_b);
  else
  {
    // border landmarks: in the same order along both borders (each counterclockwise, from the start pair)
    const std::size_t na = disk_a.border.size(), nb = disk_b.border.size();
    std::vector<std::pair<std::size_t, std::size_t> > matched; // positions from the start
    for(const auto& bp : border_pairs)
      matched.emplace_back((border_pos_a[bp.first] + na - start_a) % na, (border_pos_b[bp.second] + nb - start_b) % nb);
    std::vector<std::size_t> order(matched.size());
    for(std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return matched[x].first < matched[y].first; });
    std::vector<std::pair<std::size_t, std::size_t> > sorted;
    for(std::size_t k : order)
    {
      if(!sorted.empty() && matched[k].second <= sorted.back().second)
      {
        stats.failed_landmark = border_pair_input[k]; // -1 for border_vertex_pair
        stats.failed_mesh = 1;
        return finish(ERROR_LANDMARK_ORDER); // not in A's order along B's border
      }
      sorted.push_back(matched[k]);
    }
    // the cut disks of two closed meshes come with their borders placed
    if(settings.cut != nullptr)
    {
      const internal::Cut_request* request = settings.cut;
      if(request->border_uv_a.size() != disk_a.number_of_vertices() || request->border_uv_b.size() != disk_b.number_of_vertices())
        return finish(ERROR_WRONG_PARAMETER);
      border_uv_a.resize(na);
      border_uv_b.resize(nb);
      for(std::size_t k = 0; k < na; ++k) border_uv_a[k] = request->border_uv_a[disk_a.border[k]];
      for(std::size_t k = 0; k < nb; ++k) border_uv_b[k] = request->border_uv_b[disk_b.border[k]];
    }
    else
    {
      std::size_t arc = std::size_t(-1);
      ec = internal::common_square_border_through(disk_a, vpm_a, start_a, disk_b, vpm_b, start_b, sorted,
                                                  border_uv_a, border_uv_b, &arc);
      // the border landmark that ends the arc of A with too few vertices for B's corners (-1 for border_vertex_pair)
      if(ec == ERROR_BORDER_TOO_SHORT && arc < order.size()) stats.failed_landmark = border_pair_input[order[arc]];
    }
    if(ec == ERROR_BORDER_TOO_SHORT) stats.failed_mesh = 0;
  }
  if(ec != OK) return finish(ec);
  stats.seconds_validation = timer.time();
  auto remaining = [&]() { const double r = max_seconds - timer.time(); return r > 0 ? r : 0.; };

  // ---- 3. B's map -------------------------------------------------------------------------------
  std::unordered_map<vertex_b, Point_2, boost::hash<vertex_b> > uv_b_storage;
  for(std::size_t i = 0; i < disk_b.vertices.size(); ++i) uv_b_storage[disk_b.vertices[i]] = Point_2(0, 0);
  boost::associative_property_map<std::unordered_map<vertex_b, Point_2, boost::hash<vertex_b> > > uv_b(uv_b_storage);
  for(std::size_t k = 0; k < disk_b.border.size(); ++k) put(uv_b, disk_b.vertices[disk_b.border[k]], border_uv_b[k]);
  ec = parameterize_certified(tm_b, GTB::null_halfedge(), uv_b,
    parameters::border_shape(Border_shape::FIXED,
      parameters::optimization_policy(Optimization_policy::ALWAYS,
        parameters::pipeline_statistics(&stats.map_b,
          CGAL::parameters::maximum_running_time(remaining())))));
  // An interior edge of B joining two border vertices of one side of the square (no placement of the corners kept
  // it off) is flat in every map of B itself: B's first map is then made on a copy of B by constrained_embedding()
  // without landmarks, which splits such edges at Steiner vertices. The cut disks of two closed meshes split them
  // their own way (cross_parameterization_closed()).
  Work_b first_b;
  std::unordered_map<vertex_b, wbvertex, boost::hash<vertex_b> > to_first_b;
  auto uv_first_b = first_b.template add_property_map<wbvertex, Point_2>("v:pe_cross_uv_first_b", Point_2(0, 0)).first;
  std::vector<Steiner_point<wbvertex> > steiner_first_b;
  bool first_refined = false;
  const bool cut_disks = settings.cut != nullptr;
  if(ec == ERROR_DEGENERATE_CHORD && !cut_disks)
  {
    std::vector<std::pair<vertex_b, wbvertex> > v2v_first;
    CGAL::copy_face_graph(tm_b, first_b, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v_first)));
    to_first_b.insert(v2v_first.begin(), v2v_first.end());
    for(std::size_t k = 0; k < disk_b.border.size(); ++k) uv_first_b[to_first_b.at(disk_b.vertices[disk_b.border[k]])] = border_uv_b[k];
    Constrained_embedding_statistics first_stats;
    ec = constrained_embedding(first_b, std::vector<std::pair<wbvertex, Point_2> >(), uv_first_b,
      parameters::steiner_points(&steiner_first_b,
      parameters::border_shape(Border_shape::FIXED,
        parameters::optimization_time_limit((std::min)(optimization_seconds, remaining()),
          parameters::statistics(&first_stats,
            CGAL::parameters::maximum_running_time(remaining()))))));
    first_refined = true;
    stats.chords_split_b = first_stats.chord_splits;
  }
  stats.report_b = first_refined ? check_embedding(first_b, uv_first_b) : check_embedding(tm_b, uv_b);
  // the uv of vertex `i` of disk_b in B's first map
  auto first_uv = [&](std::size_t i) {
    return first_refined ? uv_first_b[to_first_b.at(disk_b.vertices[i])] : get(uv_b, disk_b.vertices[i]);
  };
  if(ec != OK || !stats.report_b.is_valid())
  {
    stats.seconds_map_b = timer.time() - stats.seconds_validation;
    stats.failed_mesh = 1;
    return finish(ec != OK ? ec : ERROR_INVALID_EMBEDDING);
  }
  const double seconds_first_b = timer.time() - stats.seconds_validation;
  // ---- 4. B's map made again the way A's is made, and A's map ---------------------------------------
  // B's matched map: constrained_embedding() on a copy of B, B's landmarks pinned where the first map put them. A's
  // map starts from the same kind of map with the same pins and is optimized the same way, so that the two maps
  // settle at the same place where the energy is flat (see the documentation). The copy may be refined by Steiner
  // vertices (on B's faces) that the coarsening could not remove: B's map is then on the copy.
  // A's map: constrained_embedding() on a copy of A, A's landmarks pinned at the uv of their partners in B's first
  // map (the same points). The two do not depend on each other: with CGAL::Parallel_tag they run side by side.
  Work_b work_b;
  std::vector<std::pair<vertex_b, wbvertex> > v2v_b;
  std::unordered_map<vertex_b, wbvertex, boost::hash<vertex_b> > to_work_b;
  auto uv_wb = work_b.template add_property_map<wbvertex, Point_2>("v:pe_cross_uv_b", Point_2(0, 0)).first;
  std::vector<Steiner_point<wbvertex> > steiner_b;
  Embedding_report matched_report;
  const bool make_matched = !pairs.empty() && settings.matched_maps;
  std::vector<std::pair<wbvertex, Point_2> > pins;
  if(make_matched)
  {
    CGAL::copy_face_graph(tm_b, work_b, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v_b)));
    to_work_b.insert(v2v_b.begin(), v2v_b.end());
    for(std::size_t k = 0; k < disk_b.border.size(); ++k) uv_wb[to_work_b[disk_b.vertices[disk_b.border[k]]]] = border_uv_b[k];
    for(const auto& p : pairs) pins.emplace_back(to_work_b[disk_b.vertices[p.second]], first_uv(p.second));
  }
  Work work;
  std::vector<std::pair<vertex_a, wvertex> > v2v;
  CGAL::copy_face_graph(tm_a, work, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v)));
  std::unordered_map<vertex_a, wvertex, boost::hash<vertex_a> > to_work(v2v.begin(), v2v.end());
  // A's copy brought near unit size by an exact power of two when it is beyond 2^+-100 (its squared areas would
  // overflow or underflow in the composed distortion); its points are scaled back where they are output
  const auto scaling_a = internal::normalize_points_3(work);
  auto uv_a = work.template add_property_map<wvertex, Point_2>("v:pe_cross_uv", Point_2(0, 0)).first;
  for(std::size_t k = 0; k < disk_a.border.size(); ++k) uv_a[to_work[disk_a.vertices[disk_a.border[k]]]] = border_uv_a[k];
  std::vector<std::pair<wvertex, Point_2> > constraints;
  for(const auto& p : pairs)
    constraints.emplace_back(to_work[disk_a.vertices[p.first]], first_uv(p.second));
  std::vector<Steiner_point<wvertex> > steiner;
  double seconds_matched = 0, seconds_constrained_a = 0;
  // each task writes only its own copy, uv map, Steiner list and statistics
  bool matched_ran = false;
  auto matched_task = [&]() {
    if(!make_matched) return;
    if(!(remaining() > 0)) { stats.matched_status = ERROR_BUDGET_EXHAUSTED; return; } // not made: no time left
    matched_ran = true;
    const double t0 = timer.time();
    stats.matched_status = constrained_embedding(work_b, pins, uv_wb,
      parameters::steiner_points(&steiner_b,
      parameters::border_shape(Border_shape::FIXED,
        parameters::optimization_time_limit((std::min)(optimization_seconds, remaining()),
          parameters::statistics(&stats.map_b_matched,
            CGAL::parameters::maximum_running_time(remaining()))))));
    if(stats.matched_status == OK)
    {
      matched_report = check_embedding(work_b, uv_wb);
      if(!matched_report.is_valid()) stats.matched_status = ERROR_INVALID_EMBEDDING;
    }
    seconds_matched = timer.time() - t0;
  };
  Error_code ec_a = OK;
  auto a_task = [&]() {
    const double t0 = timer.time();
    ec_a = constrained_embedding(work, constraints, uv_a,
      parameters::steiner_points(&steiner,
      parameters::border_shape(Border_shape::FIXED,
        parameters::optimization_time_limit((std::min)(optimization_seconds, remaining()),
          parameters::statistics(&stats.map_a,
            CGAL::parameters::maximum_running_time(remaining()))))));
    seconds_constrained_a = timer.time() - t0;
  };
  // A's map first when they run one after the other: it is needed, B's matched map is not (under a time budget, what
  // is left after A's map goes to it)
  internal::run_pair<ConcurrencyTag>(a_task, matched_task);
  const double after_tasks = timer.time();
  ec = ec_a;
  // B's matched map, made and certified, replaces the first one, unless it is more distorted: the first map has the
  // same border and the same pins, so a matched map well above its energy went around the landmarks another way (a
  // region wound around them), which A's map need not follow: the composition would carry a gross error there (seen
  // on two meshes of one statue with 50 landmarks: 2.5% of the diagonal on average, 26% at most). Unless A's map,
  // made the same way, is as distorted: it then went around them the same way (two copies of one surface: the two
  // maps are one computation), and B's first map would be the one A's does not follow.
  bool acceptable = true;
  if(matched_ran && stats.matched_status == OK && !internal::matched_map_acceptable(stats.report_b, matched_report))
  {
    const Embedding_report report_a = ec_a == OK ? check_embedding(work, uv_a) : Embedding_report();
    acceptable = ec_a == OK && internal::matched_map_acceptable(stats.report_b, matched_report, &report_a);
  }
  if(!acceptable)
    stats.matched_more_distorted = true;
  else if(matched_ran && stats.matched_status == OK)
  {
    stats.matched_b = true;
    stats.vertices_added_b = work_b.number_of_vertices() - disk_b.number_of_vertices();
    if(stats.vertices_added_b == 0)
    {
      // the same map on B itself (certified again there; should that fail, B's first map is kept)
      std::vector<Point_2> first(v2v_b.size());
      for(std::size_t i = 0; i < v2v_b.size(); ++i)
      {
        first[i] = get(uv_b, v2v_b[i].first);
        put(uv_b, v2v_b[i].first, uv_wb[v2v_b[i].second]);
      }
      const Embedding_report report = check_embedding(tm_b, uv_b);
      if(report.is_valid()) stats.report_b = report;
      else
      {
        for(std::size_t i = 0; i < v2v_b.size(); ++i) put(uv_b, v2v_b[i].first, first[i]);
        stats.matched_b = false;
        stats.matched_status = ERROR_INVALID_EMBEDDING;
      }
    }
    else stats.report_b = matched_report;
  }
  // B's first map, when it is kept and was made on a refined copy, is B's map from here on
  const bool first_copy_kept = first_refined && !stats.matched_b;
  if(first_copy_kept) stats.vertices_added_b = first_b.number_of_vertices() - disk_b.number_of_vertices();
  const bool refined_b = (stats.matched_b && stats.vertices_added_b > 0) || first_copy_kept;
  const Work_b& refined_mesh_b = first_copy_kept ? first_b : work_b;
  const auto& refined_uv_b = first_copy_kept ? uv_first_b : uv_wb;
  const auto& to_refined_b = first_copy_kept ? to_first_b : to_work_b;
  const auto& refined_steiner_b = first_copy_kept ? steiner_first_b : steiner_b;
  // B's map as the rest uses it: on B, or on its refined copy (vertices, 3D points and faces in `side_b`'s order)
  internal::Indexed_disk<Work_b> side_b;
  std::vector<Point_2> side_uv;
  std::vector<Point_3b> side_points;
  if(refined_b)
  {
    const Error_code es = internal::make_indexed_disk(refined_mesh_b, boost::graph_traits<Work_b>::null_halfedge(), side_b);
    if(es != OK) { stats.failed_mesh = 1; return finish(es); } // cannot happen: a refined disk
    for(wbvertex v : side_b.vertices) { side_uv.push_back(refined_uv_b[v]); side_points.push_back(refined_mesh_b.point(v)); }
  }
  else
    for(vertex_b v : disk_b.vertices) { side_uv.push_back(get(uv_b, v)); side_points.push_back(get(vpm_b, v)); }
  const std::vector<std::array<std::size_t, 3> >& side_faces = refined_b ? side_b.faces : disk_b.faces;
  stats.seconds_map_b = seconds_first_b + seconds_matched;
  // no collect_garbage(): the descriptors of `steiner` stay valid (number_of_vertices() skips the removed ones)
  stats.vertices_added_a = work.number_of_vertices() - disk_a.number_of_vertices();
  // A's map measured against B's surface rather than the plane (internal/cross/composed_distortion.h); on failure
  // the map stays as constrained_embedding() left it
  if(ec == OK && settings.composed_distortion && remaining() > 0)
  {
    const double before_composed = timer.time();
    std::vector<wvertex> fixed;
    for(const auto& c : constraints) fixed.push_back(c.first);
    // B's points for its metric only, near unit size like A's (the metric is the same up to rounding)
    std::vector<Point_3b> metric_points(side_points);
    internal::normalize_points_3(metric_points);
    stats.composed_status = internal::optimize_composed_distortion(work, uv_a, fixed,
                              internal::inverse_map_metric(side_uv, metric_points, side_faces),
                              (std::min)(optimization_seconds, remaining()), stats.composed);
    stats.seconds_composed = timer.time() - before_composed;
  }
  else if(ec == OK && settings.composed_distortion) stats.composed_status = ERROR_BUDGET_EXHAUSTED; // not run: no time left
  if(ec == OK) stats.report_a = check_embedding(work, uv_a);
  stats.seconds_map_a = seconds_constrained_a + (timer.time() - after_tasks);
  if(ec != OK) { stats.failed_mesh = 0; return finish(ec); }
  if(!stats.report_a.is_valid()) { stats.failed_mesh = 0; return finish(ERROR_INVALID_EMBEDDING); }

  // ---- 5. every vertex of A located in B's map -------------------------------------------------
  const double before_location = timer.time();
  std::vector<Point_2> map_b(disk_b.number_of_vertices()), queries(disk_a.number_of_vertices());
  for(std::size_t i = 0; i < map_b.size(); ++i)
    map_b[i] = refined_b ? refined_uv_b[to_refined_b.at(disk_b.vertices[i])] : get(uv_b, disk_b.vertices[i]);
  for(std::size_t i = 0; i < queries.size(); ++i) queries[i] = uv_a[to_work[disk_a.vertices[i]]];
  std::vector<face_b> faces_b;
  faces_b.reserve(disk_b.number_of_faces());
  for(face_b f : faces(tm_b)) faces_b.push_back(f);
  std::vector<Cross_location<TriangleMeshB> > locations;
  if(refined_b)
  {
    // located in the refined copy's map, then written in the face of B holding the refined face
    ec = internal::locate_on_refined_copy(tm_b, disk_b, refined_mesh_b, refined_uv_b, to_refined_b, refined_steiner_b, queries, locations,
                                          &stats.unlocated);
    if(ec != OK) return finish(ec);
  }
  else
  {
    std::vector<internal::Map_location> located;
    stats.unlocated = internal::locate_in_map(map_b, disk_b.faces, queries, located);
    if(stats.unlocated > 0) return finish(ERROR_INVALID_EMBEDDING);
    for(const internal::Map_location& l : located) locations.emplace_back(faces_b[l.face], l.barycentric);
  }
  for(const auto& l : locations)
  {
    const int zeros = int(l.second[0] == 0) + int(l.second[1] == 0) + int(l.second[2] == 0);
    if(zeros == 2) ++stats.located_on_vertex;
    else if(zeros == 1) ++stats.located_on_edge;
    else ++stats.located_in_face;
  }
  stats.landmarks_exact = true;
  std::vector<std::pair<std::size_t, std::size_t> > all_pairs(pairs);
  all_pairs.insert(all_pairs.end(), border_pairs.begin(), border_pairs.end());
  for(const auto& p : all_pairs)
  {
    const auto& l = locations[p.first];
    const auto h = halfedge(l.first, tm_b);
    const std::array<vertex_b, 3> corners{{ source(h, tm_b), target(h, tm_b), target(next(h, tm_b), tm_b) }};
    bool at_partner = false;
    for(int i = 0; i < 3; ++i)
      if(corners[i] == disk_b.vertices[p.second] && l.second[i] == 1.) at_partner = true;
    if(!at_partner) stats.landmarks_exact = false;
  }
  if(!stats.landmarks_exact) return finish(ERROR_INVALID_EMBEDDING);
  // the other direction: B's vertices located on A's refined copy, then on A's faces
  const bool backwards = settings.b_to_a;
  std::vector<Cross_location<TriangleMeshA> > back;
  if(backwards)
  {
    ec = internal::locate_on_refined_copy(tm_a, disk_a, work, uv_a, to_work, steiner, map_b, back);
    if(ec != OK) return finish(ec);
    stats.located_b_on_a = back.size();
  }
  stats.seconds_location = timer.time() - before_location;

  // ---- 6. the compatible meshes: the overlay of the two maps, triangulated and certified ----------
  internal::Cut_request* request = settings.cut;
  const bool compatible = settings.compatible_meshes || (request && request->compatible);
  std::vector<std::array<double, 3> > on_a, on_b;
  std::vector<std::array<std::size_t, 3> > triangles;
  if(compatible)
  {
    const double before_overlay = timer.time();
    // for the join along the cut of two cut disks: the vertex of each disk that an overlay point is (Steiner
    // vertices of either refined copy are none)
    std::vector<std::array<std::size_t, 2> >* origins = request && request->compatible ? &request->origins : nullptr;
    std::vector<wvertex> disk_a_in_work;
    std::vector<std::size_t> b_in_disk;
    if(origins != nullptr)
    {
      for(vertex_a v : disk_a.vertices) disk_a_in_work.push_back(to_work[v]);
      if(refined_b)
      {
        std::unordered_map<wbvertex, std::size_t, boost::hash<wbvertex> > disk_index;
        for(std::size_t i = 0; i < disk_b.vertices.size(); ++i) disk_index.emplace(to_refined_b.at(disk_b.vertices[i]), i);
        for(wbvertex v : side_b.vertices)
        {
          const auto it = disk_index.find(v);
          b_in_disk.push_back(it == disk_index.end() ? std::size_t(-1) : it->second);
        }
      }
    }
    ec = refined_b ? internal::compatible_soups(work, uv_a, refined_mesh_b, side_b, side_uv, stats, on_a, on_b, triangles,
                                                origins, &disk_a_in_work, &b_in_disk)
                   : internal::compatible_soups(work, uv_a, tm_b, disk_b, map_b, stats, on_a, on_b, triangles, origins,
                                                &disk_a_in_work);
    stats.seconds_compatible = timer.time() - before_overlay;
    if(ec != OK) return finish(ec);
    if(scaling_a.exponent() != 0)
      for(auto& p : on_a) for(double& x : p) x = std::ldexp(x, int(-scaling_a.exponent()));
  }

  // the planar maps as flat soups, A's vertices (then B's) first in their meshes' order
  const bool planar = settings.planar_maps;
  std::vector<std::array<double, 3> > plane_a, plane_b;
  std::vector<std::array<std::size_t, 3> > plane_faces_a, plane_faces_b;
  if(planar)
  {
    std::vector<wvertex> first_a;
    for(vertex_a v : disk_a.vertices) first_a.push_back(to_work[v]);
    internal::planar_soup(work, uv_a, first_a, plane_a, plane_faces_a);
    if(refined_b)
    {
      std::vector<wbvertex> order_b;
      for(vertex_b v : disk_b.vertices) order_b.push_back(to_refined_b.at(v));
      internal::planar_soup(refined_mesh_b, refined_uv_b, order_b, plane_b, plane_faces_b);
    }
    else
      internal::planar_soup(tm_b, uv_b, disk_b.vertices, plane_b, plane_faces_b);
  }

  // ---- 7. the output, handed to the caller (who writes it) only now that everything is certified ---------
  output.vertices_a = disk_a.vertices;
  output.locations.swap(locations);
  if(backwards)
  {
    output.vertices_b = disk_b.vertices;
    output.locations_b.swap(back);
  }
  if(request && request->compatible)
  {
    request->on_a.swap(on_a);
    request->on_b.swap(on_b);
    request->triangles.swap(triangles);
  }
  else
  {
    output.compatible_a.swap(on_a);
    output.compatible_b.swap(on_b);
    output.compatible_triangles.swap(triangles);
  }
  output.plane_a.swap(plane_a);
  output.plane_b.swap(plane_b);
  output.plane_faces_a.swap(plane_faces_a);
  output.plane_faces_b.swap(plane_faces_b);
  return finish(OK);
}

} // namespace internal
#endif

#ifndef DOXYGEN_RUNNING
namespace internal {

// A location on a cut disk brought back to the closed mesh it was cut from: the corners of the disk's face, in the
// order of the location, as vertices of the mesh (a point `i >= cut.vertices.size()`, the midpoint of a split chord
// `(*midpoint)[i - cut.vertices.size()]`, gives half its weight to each end), in the mesh's face that holds the disk's
// face (`(*face)[disk face]` indexes `cut.faces`). Null `face` and `midpoint`: the disk is the cut itself (its faces
// in `cut.faces` order, no chord split).
template <class TriangleMesh, class Disk>
Cross_location<TriangleMesh> location_on_closed_mesh(const TriangleMesh& tm, const Cut_disk<TriangleMesh>& cut,
                                                     const std::vector<std::size_t>* face,
                                                     const std::vector<std::array<std::size_t, 2> >* midpoint,
                                                     const Disk& disk, const Cross_location<Disk>& l)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex;
  const std::size_t n_cut = cut.vertices.size();
  const std::size_t disk_face = std::size_t(l.first);
  const auto f = cut.faces[face != nullptr ? (*face)[disk_face] : disk_face];
  const auto hc = halfedge(l.first, disk);
  const std::size_t cut_corner[3] = { std::size_t(source(hc, disk)), std::size_t(target(hc, disk)),
                                      std::size_t(target(next(hc, disk), disk)) };
  const auto h = halfedge(f, tm);
  const vertex corner[3] = { source(h, tm), target(h, tm), target(next(h, tm), tm) };
  std::array<double, 3> w{{ 0, 0, 0 }};
  auto add = [&](std::size_t point, double weight) {
    for(int j = 0; j < 3; ++j)
      if(corner[j] == cut.vertices[point]) w[j] += weight;
  };
  for(int k = 0; k < 3; ++k)
  {
    if(cut_corner[k] < n_cut) { add(cut_corner[k], l.second[k]); continue; }
    CGAL_assertion(midpoint != nullptr);
    const auto& m = (*midpoint)[cut_corner[k] - n_cut];
    add(m[0], l.second[k] / 2);
    add(m[1], l.second[k] / 2);
  }
  return Cross_location<TriangleMesh>(f, w);
}

// two closed genus-0 meshes: both cut between two landmarks near each other (cut_pair.h), or along the chain of all
// landmarks where no pair cuts both (cut_closed.h), the cut disks mapped with every landmark copy on the
// cut a border landmark and the other landmarks inside, the locations brought back to the vertices and faces of the
// meshes
template <class ConcurrencyTag, class TriangleMeshA, class TriangleMeshB>
Error_code cross_parameterization_closed(
  const TriangleMeshA& tm_a, const TriangleMeshB& tm_b,
  const Landmark_pairs<TriangleMeshA, TriangleMeshB>& landmarks,
  const Cross_settings<TriangleMeshA, TriangleMeshB>& settings, Cross_output<TriangleMeshA, TriangleMeshB>& output)
{
  typedef typename boost::graph_traits<TriangleMeshA>::vertex_descriptor vertex_a;
  typedef typename boost::graph_traits<TriangleMeshB>::vertex_descriptor vertex_b;
  typedef typename boost::property_traits<typename boost::property_map<TriangleMeshA, CGAL::vertex_point_t>::const_type>::value_type Point_a;
  typedef typename boost::property_traits<typename boost::property_map<TriangleMeshB, CGAL::vertex_point_t>::const_type>::value_type Point_b;
  typedef CGAL::Surface_mesh<Point_a> Disk_a;
  typedef CGAL::Surface_mesh<Point_b> Disk_b;
  Cross_parameterization_statistics local_stats;
  Cross_parameterization_statistics& stats = settings.statistics ? *settings.statistics : local_stats;
  stats = Cross_parameterization_statistics();
  stats.closed = true;
  // a closed mesh has no border: a border pair does not apply. The planar maps are those of the cut disks; the
  // compatible meshes are their overlay welded along the cut; B's vertices are located on A's cut disk.
  if(settings.has_border_vertex_pair) return ERROR_WRONG_PARAMETER;
  const bool backwards = settings.b_to_a;
  const bool compatible = settings.compatible_meshes;

  if(!points_are_finite(tm_a, get(CGAL::vertex_point, tm_a))) { stats.failed_mesh = 0; return ERROR_NON_FINITE_COORDINATES; }
  if(!points_are_finite(tm_b, get(CGAL::vertex_point, tm_b))) { stats.failed_mesh = 1; return ERROR_NON_FINITE_COORDINATES; }
  // the chain: the landmarks in their order, each vertex once
  std::vector<vertex_a> chain_a;
  std::vector<vertex_b> chain_b;
  {
    std::unordered_set<vertex_a, boost::hash<vertex_a> > seen_a;
    std::unordered_set<vertex_b, boost::hash<vertex_b> > seen_b;
    std::unordered_set<vertex_a, boost::hash<vertex_a> > all_a(vertices(tm_a).begin(), vertices(tm_a).end());
    std::unordered_set<vertex_b, boost::hash<vertex_b> > all_b(vertices(tm_b).begin(), vertices(tm_b).end());
    for(const auto& l : landmarks)
    {
      stats.failed_landmark = chain_a.size();
      if(all_a.count(l.first) == 0) { stats.failed_mesh = 0; return ERROR_WRONG_PARAMETER; }
      if(all_b.count(l.second) == 0) { stats.failed_mesh = 1; return ERROR_WRONG_PARAMETER; }
      if(!seen_a.insert(l.first).second) { stats.failed_mesh = 0; return ERROR_DUPLICATE_CONSTRAINT; }
      if(!seen_b.insert(l.second).second) { stats.failed_mesh = 1; return ERROR_DUPLICATE_CONSTRAINT; }
      chain_a.push_back(l.first);
      chain_b.push_back(l.second);
    }
    stats.failed_landmark = std::size_t(-1);
    stats.landmarks = chain_a.size();
    if(chain_a.size() < 2) return ERROR_WRONG_PARAMETER; // a cut needs two landmarks
  }
  // With three landmarks or more, the cut joins two landmarks near each other (cut_pair.h: the candidate pairs of A,
  // nearest first; a pair is taken when both meshes cut between it, each avoiding the other landmarks and the edge
  // joining the two, at most `tries` pairs tried) and the others stay inside the cut disks; where no pair cuts both,
  // the chain goes through all of them in their order. `chain_landmark`: the position in `landmarks` of each chain
  // vertex; `inside_landmark`: of each landmark left inside.
  std::vector<std::size_t> chain_landmark, inside_landmark;
  for(std::size_t k = 0; k < chain_a.size(); ++k) chain_landmark.push_back(k);
  std::vector<vertex_a> inside_a;
  std::vector<vertex_b> inside_b;
  Cut_disk<TriangleMeshA> cut_a;
  Cut_disk<TriangleMeshB> cut_b;
  std::size_t failed = std::size_t(-1);
  bool cut_done = false;
  if(chain_a.size() > 2)
  {
    constexpr std::size_t tries = 8;
    const auto candidates = landmark_pairs_to_cut(tm_a, get(CGAL::vertex_point, tm_a), chain_a);
    for(std::size_t c = 0; c < candidates.size() && c < tries && !cut_done; ++c)
    {
      const std::size_t first = candidates[c].second.first, second = candidates[c].second.second;
      std::vector<vertex_a> in_a;
      std::vector<vertex_b> in_b;
      std::vector<std::size_t> in_landmark;
      for(std::size_t k = 0; k < chain_a.size(); ++k)
        if(k != first && k != second) { in_a.push_back(chain_a[k]); in_b.push_back(chain_b[k]); in_landmark.push_back(k); }
      const std::vector<vertex_a> pair_a = { chain_a[first], chain_a[second] };
      const std::vector<vertex_b> pair_b = { chain_b[first], chain_b[second] };
      // a fault of a mesh (not genus 0, not triangulated) is the same for every pair: the chain below reports it
      const Error_code ea = cut_along_chain(tm_a, get(CGAL::vertex_point, tm_a), pair_a, cut_a, failed, in_a, true);
      if(ea != OK && ea != ERROR_PATH_TRACING_FAILED) break;
      if(ea != OK) continue;
      const Error_code eb = cut_along_chain(tm_b, get(CGAL::vertex_point, tm_b), pair_b, cut_b, failed, in_b, true);
      if(eb != OK && eb != ERROR_PATH_TRACING_FAILED) break;
      if(eb != OK) continue;
      cut_done = true;
      chain_a = pair_a;
      chain_b = pair_b;
      inside_a.swap(in_a);
      inside_b.swap(in_b);
      inside_landmark.swap(in_landmark);
      chain_landmark = { first, second };
    }
  }
  stats.cut_landmarks = chain_a.size();
  Error_code ec = OK;
  if(!cut_done)
  {
    // (a chain position is a position in `landmarks`: the chain is all of them, in their order)
    ec = cut_along_chain(tm_a, get(CGAL::vertex_point, tm_a), chain_a, cut_a, failed);
    if(ec != OK) { stats.failed_mesh = 0; stats.failed_landmark = failed; return ec; }
    ec = cut_along_chain(tm_b, get(CGAL::vertex_point, tm_b), chain_b, cut_b, failed);
    if(ec != OK) { stats.failed_mesh = 1; stats.failed_landmark = failed; return ec; }
  }
  Disk_a disk_a;
  {
    std::vector<Point_a> pa;
    for(vertex_a v : cut_a.vertices) pa.push_back(get(CGAL::vertex_point, tm_a, v));
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pa, cut_a.triangles, disk_a);
  }
  // B's cut disk as cut, or with its chords split (see below)
  Disk_b disk_b;
  Split_soup soup_b;
  std::size_t chords_b = 0;
  auto build_b = [&](bool split) {
    std::vector<Point_b> pb;
    for(vertex_b v : cut_b.vertices) pb.push_back(get(CGAL::vertex_point, tm_b, v));
    if(split) chords_b = split_chords(cut_b, soup_b);
    else
    {
      soup_b.triangles = cut_b.triangles;
      soup_b.face.resize(cut_b.triangles.size());
      for(std::size_t t = 0; t < soup_b.face.size(); ++t) soup_b.face[t] = t;
      soup_b.midpoint.clear();
    }
    for(const auto& m : soup_b.midpoint) pb.push_back(CGAL::midpoint(pb[m[0]], pb[m[1]]));
    disk_b.clear();
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pb, soup_b.triangles, disk_b);
  };
  build_b(false);
  // every landmark on the cut a border landmark of the cut disks, each copy matched to the copy on the same side
  std::unordered_map<vertex_a, std::size_t, boost::hash<vertex_a> > index_a;
  std::unordered_map<vertex_b, std::size_t, boost::hash<vertex_b> > index_b;
  for(std::size_t i = 0; i < cut_a.copy.size(); ++i) index_a.emplace(cut_a.vertices[i], i);
  for(std::size_t i = 0; i < cut_b.copy.size(); ++i) index_b.emplace(cut_b.vertices[i], i);
  typedef typename Disk_a::Vertex_index dva;
  typedef typename Disk_b::Vertex_index dvb;
  std::vector<std::pair<dva, dvb> > pairs;
  std::vector<std::size_t> pair_landmark;
  for(std::size_t k = 0; k < chain_a.size(); ++k)
  {
    const std::size_t ia = index_a.at(chain_a[k]), ib = index_b.at(chain_b[k]);
    pairs.emplace_back(dva(ia), dvb(ib));
    pair_landmark.push_back(chain_landmark[k]);
    if(cut_a.copy[ia] != std::size_t(-1) && cut_b.copy[ib] != std::size_t(-1))
    {
      pairs.emplace_back(dva(cut_a.copy[ia]), dvb(cut_b.copy[ib]));
      pair_landmark.push_back(chain_landmark[k]);
    }
  }
  // the landmarks inside the cut disks (a vertex off the cut keeps its index there)
  const std::size_t border_pair_count = pairs.size();
  for(std::size_t k = 0; k < inside_a.size(); ++k)
  {
    pairs.emplace_back(dva(index_a.at(inside_a[k])), dvb(index_b.at(inside_b[k])));
    pair_landmark.push_back(inside_landmark[k]);
  }
  std::vector<Cross_location<Disk_b> > located(disk_a.number_of_vertices());
  std::vector<Cross_location<Disk_a> > located_b; // B's cut disk's vertices on A's, with b_to_a_locations
  Cross_output<Disk_a, Disk_b> inner_output;
  Cross_parameterization_statistics inner;
  const double max_seconds = settings.max_seconds;
  CGAL::Real_timer timer;
  timer.start();
  // both borders placed so that the two sides of the cut are placed alike (internal/cross/cut_border.h)
  Cut_request request;
  request.compatible = compatible;
  std::vector<std::pair<std::size_t, std::size_t> > pair_indices;
  for(std::size_t k = 0; k < border_pair_count; ++k) pair_indices.emplace_back(std::size_t(pairs[k].first), std::size_t(pairs[k].second));
  auto place_borders = [&]() {
    Indexed_disk<Disk_a> indexed_a;
    Indexed_disk<Disk_b> indexed_b;
    Error_code e = make_indexed_disk(disk_a, boost::graph_traits<Disk_a>::null_halfedge(), indexed_a);
    if(e != OK) { stats.failed_mesh = 0; return e; }
    e = make_indexed_disk(disk_b, boost::graph_traits<Disk_b>::null_halfedge(), indexed_b);
    if(e != OK) { stats.failed_mesh = 1; return e; }
    std::size_t failed_mesh = std::size_t(-1);
    e = cut_border_on_square(indexed_a, get(CGAL::vertex_point, disk_a), indexed_b, get(CGAL::vertex_point, disk_b),
                             pair_indices, cut_twins(cut_a, disk_a.number_of_vertices()),
                             cut_twins(cut_b, disk_b.number_of_vertices()), request.border_uv_a, request.border_uv_b,
                             failed_mesh);
    if(e != OK) stats.failed_mesh = failed_mesh;
    return e;
  };
  auto map_disks = [&]() {
    Cross_settings<Disk_a, Disk_b> disk_settings;
    disk_settings.cut = &request;
    disk_settings.statistics = &inner;
    disk_settings.composed_distortion = settings.composed_distortion;
    // B's map made again as A's is, as for disks: on two copies of one surface, the two maps are then one
    // computation, and the composition the identity (with B's first map, A's map settles elsewhere where the energy
    // is flat: up to a third of the diagonal away on hand.off against itself with 20 landmarks)
    disk_settings.matched_maps = settings.matched_maps;
    disk_settings.optimization_seconds = settings.optimization_seconds;
    disk_settings.max_seconds = (std::max)(0., max_seconds - timer.time());
    disk_settings.b_to_a = backwards;
    // the planar maps are those of the cut disks (the points of a cut disk: the mesh's vertices in their order,
    // then the copies on the cut, then B's chord midpoints)
    disk_settings.planar_maps = settings.planar_maps;
    inner_output = Cross_output<Disk_a, Disk_b>();
    const Error_code e = cross_parameterization_disks<ConcurrencyTag>(disk_a, disk_b, pairs, disk_settings, inner_output);
    if(e != OK) return e;
    for(std::size_t i = 0; i < inner_output.vertices_a.size(); ++i)
      located[std::size_t(inner_output.vertices_a[i])] = inner_output.locations[i];
    if(backwards)
    {
      located_b.assign(disk_b.number_of_vertices(), Cross_location<Disk_a>());
      for(std::size_t i = 0; i < inner_output.vertices_b.size(); ++i)
        located_b[std::size_t(inner_output.vertices_b[i])] = inner_output.locations_b[i];
    }
    return OK;
  };
  ec = place_borders();
  if(ec != OK) return ec;
  ec = map_disks();
  // Where two paths of the cut run side by side (up and down a limb to a landmark at its tip), the edges
  // across them join two border vertices of B's disk, and where both ends lie on one side of the square, B's
  // map would flatten them: then B's disk is mapped again with those edges split
  // at their midpoints (only then, so that the map of a disk that needs no split is the disk's own)
  if(ec == ERROR_DEGENERATE_CHORD && inner.failed_mesh == 1)
  {
    build_b(true);
    if(chords_b > 0)
    {
      ec = place_borders(); // the same borders, B's midpoints added inside
      if(ec == OK) ec = map_disks();
    }
  }
  const std::size_t inner_failed = inner.failed_landmark;
  stats = inner;
  stats.closed = true;
  stats.landmarks = landmarks.size();
  stats.cut_landmarks = chain_a.size();
  stats.cut_edges_a = cut_a.path_edges;
  stats.cut_edges_b = cut_b.path_edges;
  stats.chords_split_b = chords_b;
  stats.failed_landmark = inner_failed < pair_landmark.size() ? pair_landmark[inner_failed] : std::size_t(-1);
  if(ec != OK) return ec;
  // the compatible meshes: the overlay of the cut disks' maps welded along the cut (every border point of it is a
  // vertex of A's or B's disk, named by the vertex of the closed mesh it is a copy of), then certified closed genus 0
  std::vector<std::array<double, 3> > on_a, on_b;
  std::vector<std::array<std::size_t, 3> > triangles;
  if(compatible)
  {
    CGAL::Real_timer weld_timer;
    weld_timer.start();
    std::vector<std::size_t> mesh_a(cut_a.vertices.size()), mesh_b(cut_b.vertices.size());
    for(std::size_t i = 0; i < mesh_a.size(); ++i) mesh_a[i] = index_a.at(cut_a.vertices[i]);
    for(std::size_t i = 0; i < mesh_b.size(); ++i) mesh_b[i] = index_b.at(cut_b.vertices[i]);
    std::vector<std::array<std::size_t, 2> > origin(request.origins.size(), {{ std::size_t(-1), std::size_t(-1) }});
    for(std::size_t i = 0; i < origin.size(); ++i)
    {
      const std::array<std::size_t, 2>& o = request.origins[i];
      if(o[0] < mesh_a.size()) origin[i][0] = mesh_a[o[0]];
      if(o[1] < mesh_b.size()) origin[i][1] = mesh_b[o[1]]; // B's chord midpoints are inside: no origin
    }
    on_a.swap(request.on_a);
    on_b.swap(request.on_b);
    triangles.swap(request.triangles);
    ec = weld_cut_overlay(on_a, on_b, triangles, origin, stats.cut_vertices_welded);
    stats.seconds_compatible += weld_timer.time();
    if(ec != OK) return ec;
    stats.compatible_vertices = on_a.size();
    stats.compatible_faces = triangles.size();
  }
  // back to the faces of the closed meshes (A's cut disk has no midpoint and its faces are the cut's)
  for(vertex_a v : vertices(tm_a))
  {
    output.vertices_a.push_back(v);
    output.locations.push_back(location_on_closed_mesh(tm_b, cut_b, &soup_b.face, &soup_b.midpoint, disk_b,
                                                       located[index_a.at(v)]));
  }
  if(backwards)
  {
    for(vertex_b v : vertices(tm_b))
    {
      output.vertices_b.push_back(v);
      output.locations_b.push_back(location_on_closed_mesh(tm_a, cut_a, nullptr, nullptr, disk_a, located_b[index_b.at(v)]));
    }
    stats.located_b_on_a = num_vertices(tm_b);
  }
  output.compatible_a.swap(on_a);
  output.compatible_b.swap(on_b);
  output.compatible_triangles.swap(triangles);
  output.plane_a.swap(inner_output.plane_a);
  output.plane_b.swap(inner_output.plane_b);
  output.plane_faces_a.swap(inner_output.plane_faces_a);
  output.plane_faces_b.swap(inner_output.plane_faces_b);
  return OK;
}

} // namespace internal
#endif

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// computes a bijective map between two triangulated disks `tm_a` (A) and `tm_b` (B) in which every landmark vertex
/// of A lands exactly on its partner in B, and reports for every vertex of A the face of B containing its image and
/// its barycentric coordinates there.
///
/// Both meshes are mapped onto the unit square [0,1]²: its corner (0,0) gets a matched pair of border vertices
/// (`border_vertex_pair`, else the first border landmark); B's border vertices nearest to a quarter, a half and three
/// quarters of its 3D length get the other corners, counterclockwise (the mesh interior on the left of the border;
/// a corner moves to the vertex just inside an interior edge of B that joins two border vertices, when both would
/// otherwise lie on one side: B is mapped unchanged, and such an edge would be flat), and A's border vertices nearest to the relative lengths of B's corners get the same corners; between corners each
/// side is parametrized by 3D arc length. The borders are thus matched by relative arc length up to the corners (each
/// corner moves by at most half a border edge), and every border point lies exactly on a side of the square.
///
/// Landmarks on the borders (both vertices on their border, in the same counterclockwise order along both borders)
/// fix the border correspondence: each border landmark of A is placed at the uv of its partner, bit for bit; the
/// relative arc lengths are then matched between consecutive border landmarks (A's corners are the vertices nearest
/// to the relative positions of B's corners within the arcs between border landmarks).
///
/// B is mapped first, unchanged: Tutte's map of the square border, repaired by progressive embedding if it is not
/// valid in floating point, then optimized (`parameterize_certified()` with `Optimization_policy::ALWAYS`). Where no
/// placement of the corners keeps every such edge of B off the sides (e.g. five ears, the edge around each tip
/// needing a corner at the tip), B itself has no valid map (`ERROR_DEGENERATE_CHORD`): B's first map is then made
/// on a `Surface_mesh` copy of B by `constrained_embedding()` without landmarks, which splits the flat edges at
/// Steiner vertices (`Cross_parameterization_statistics::chords_split_b`), and B's map is on that refined copy as
/// below (`Cross_parameterization_statistics::vertices_added_b`). The uv of
/// B's landmarks are the targets of A's map: a `Surface_mesh` copy of A is mapped by `constrained_embedding()` with
/// each landmark of A pinned bit-exactly at the uv of its partner; the copy is refined by Steiner vertices where the
/// landmark paths need them (`Cross_parameterization_statistics::vertices_added_a`), A itself is not changed.
/// Unless `matched_maps` is `false`, and when there are interior landmarks, B's map is first made again the same way:
/// `constrained_embedding()` on a `Surface_mesh` copy of B, B's border as before and B's landmarks pinned where B's
/// first map put them. The two maps then come from the same kind of start (each patch between the landmark paths
/// mapped by Tutte's method), with the same pins, and are optimized alike: where the planar energy is flat they settle
/// at the same place, where two maps made differently (B's from Tutte's map without pins) drift apart; on two meshes
/// of one surface this lowers the correspondence error (see the user manual). If Steiner vertices remain in B's copy
/// after the coarsening (`Cross_parameterization_statistics::vertices_added_b`), B's map is on the refined copy: the
/// vertices of A are located in it and their locations written in the faces of B holding the refined faces. If that
/// map fails (`Cross_parameterization_statistics::matched_status`), or if its mean distortion energy is more than 5%
/// above the first map's (which has the same border and pins: the matched map then went around the landmarks another
/// way) and more than 5% above A's map's (which would then not have gone that way too;
/// `Cross_parameterization_statistics::matched_more_distorted`), B's first map is kept. Then,
/// unless `composed_distortion` is `false`, A's map is optimized once more (border and landmarks fixed) for the
/// distortion of the composed map: each face of A's copy is measured against B's surface instead of the plane, through
/// the inverse Jacobian of B's map on the face of B that holds the face's uv centroid, so that the energy is the
/// symmetric Dirichlet energy of the map from A's surface to B's (4 for an isometry). Two maps that each minimize the
/// planar energy agree only where that energy is stiff; where it is flat (parts of the surface squeezed in the plane,
/// far from landmarks) they slide apart, and this step pulls A's map onto B's: on two meshes of one surface it lowers
/// the correspondence error (see the user manual). Every step of it is certified like any step of the optimizer. Both
/// maps are certified by `check_embedding()` (the reports are in the statistics). Each vertex of A is then located
/// in B's map: the face is decided by exact orientations (a point on an edge or a vertex of B gets the incident face
/// of B listed first in `faces(tm_b)`, with exact zero coordinates), the barycentric coordinates are computed in
/// exact rationals and rounded once to double (they sum to 1 up to that rounding). When B's map is on a refined copy
/// of B (`Cross_parameterization_statistics::vertices_added_b` > 0), the point is located in the refined copy that
/// way and expressed in a face of B that contains the refined face (for a point on an edge or a vertex of B, the first
/// such face found around one of its vertices), each vertex added to the copy being a combination of the vertices of
/// one face of B: these coordinates are sums of products in double, rounded once more. A landmark of A gets the
/// coordinate 1 exactly at its partner.
///
/// Two closed genus-0 meshes (no border) are first cut into disks. With three landmarks or more, each mesh is cut
/// along its shortest edge path (3D edge lengths, through no other landmark and not along an edge joining the two)
/// between two landmarks near each other: the nearest pair on A that both meshes can join so (see the user manual,
/// section Closed Surfaces), and the other landmarks stay inside the cut disks, pinned as on two disks; with two
/// landmarks, or where no pair cuts both meshes, the cut is the chain through all landmarks in their order: the
/// shortest edge path from each landmark to the next, avoiding the earlier paths and the other landmarks
/// (`Cross_parameterization_statistics::cut_landmarks`). Every landmark copy on the cut is a border landmark, and both
/// borders are placed on the square so that the two sides of every arc of the cut are placed alike (see the user
/// manual, section Closed Surfaces); B's map of its cut disk is made again as for disks (`matched_maps`). They need at
/// least two landmarks; `border_vertex_pair` does not apply to them (they have no border: `ERROR_WRONG_PARAMETER`);
/// `planar_maps` receives the maps of the cut disks, `compatible_meshes` the overlay of the cut disks' maps
/// joined along the cut into two closed meshes, and `b_to_a_locations` the locations of B's vertices on A's faces
/// (a vertex of B on the cut is located from its first copy, its place in the cut disk's order).
///
/// Since both maps are one-to-one onto the same square, the composition (A's map, then the inverse of B's) is a
/// bijection between the two surfaces, piecewise linear on A's refined copy; the output samples it at A's vertices.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`: with `CGAL::Parallel_tag` (and TBB), B's
///         matched map and A's constrained map, which do not depend on each other, are made side by side (the
///         result is the same unless a time budget stops one of them; `seconds_map_b` and `seconds_map_a` then
///         overlap); one after the other, A's map is made first
/// \tparam TriangleMeshA a model of `FaceGraph` (triangles), with 3D points
/// \tparam TriangleMeshB a model of `FaceGraph` (triangles), with 3D points
/// \tparam LandmarkRange a range of `std::pair<vertex_descriptor of A, vertex_descriptor of B>`
/// \tparam LocationMap a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMeshA>::%vertex_descriptor`
///         as key type and `Cross_location<TriangleMeshB>` as value type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm_a the mesh whose vertices are located (not modified)
/// \param tm_b the mesh in which they are located (not modified)
/// \param landmarks the matched vertices, interior or both on their borders (none is allowed: only the border is
///        then matched)
/// \param out receives, on success only, the location on B of every vertex of A
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{border_vertex_pair}
///     \cgalParamDescription{the border vertex of A and the border vertex of B that are matched (both at the
///                           corner (0,0) of the square); a vertex not on its mesh's border gives
///                           `ERROR_WRONG_PARAMETER`}
///     \cgalParamType{`std::pair<vertex_descriptor of A, vertex_descriptor of B>`}
///     \cgalParamDefault{the first border vertex of A in `vertices(tm_a)` and the border vertex of B nearest to it in
///                       3D (right for two meshes of one surface in one frame; give the pair otherwise)}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_running_time}
///     \cgalParamDescription{seconds (wall clock) for the whole call, counted from its start (for two closed meshes
///                           from the end of the cut along the landmarks, which is not interrupted): each map and each
///                           optimization gets what is left; `ERROR_BUDGET_EXHAUSTED` when a certified map of A or
///                           of B cannot be made within it (an optimization cut short keeps the certified map it
///                           has, and the steps not started are skipped: the composed distortion, B's matched map,
///                           whose statuses in the statistics are then `ERROR_BUDGET_EXHAUSTED`).
///                           The location and the compatible meshes, whose time is bounded by the sizes of the
///                           meshes and of the overlay, are not interrupted: the call may end after the budget, with
///                           `OK`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{no limit}
///   \cgalParamNEnd
///   \cgalParamNBegin{optimization_time_limit}
///     \cgalParamDescription{seconds for the optimization of A's map (see `constrained_embedding()`), and as many for
///                           its optimization for the composed distortion (`composed_distortion`) and for the
///                           optimization of B's matched map (`matched_maps`)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{30}
///   \cgalParamNEnd
///   \cgalParamNBegin{composed_distortion}
///     \cgalParamDescription{whether A's map is optimized for the distortion of the composed map after
///                           `constrained_embedding()` (see above), for at most `optimization_time_limit` seconds}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{matched_maps}
///     \cgalParamDescription{whether B's map is made again by `constrained_embedding()` with B's landmarks pinned, as
///                           A's is (see above), when there are interior landmarks (for closed surfaces, the
///                           map of B's cut disk); its optimization has at most
///                           `optimization_time_limit` seconds, and it gets what A's map leaves of
///                           `maximum_running_time`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{b_to_a_locations}
///     \cgalParamDescription{receives, on success, the location on A of every vertex of B (the inverse map): each
///                           vertex of B is located in A's map on the refined copy (exact orientations, as above),
///                           and the point is expressed in the face of A that contains the refined face (each
///                           vertex added to the copy is a combination of the vertices of one face of A: the
///                           `steiner_points` of `constrained_embedding()`; these coordinates are rounded once more);
///                           a landmark of B gets the coordinate 1 exactly at its partner}
///     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMeshB>::%vertex_descriptor` as
///                    key type and `Cross_location<TriangleMeshA>` as value type}
///     \cgalParamDefault{none: only the locations of A's vertices are computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{compatible_meshes}
///     \cgalParamDescription{receives, on success, two meshes with one connectivity, the first on A's surface and the
///                           second on B's, in correspondence through the map: the common refinement of the two maps.
///                           Each face of A's refined map is clipped by the faces of B's map it overlaps, in exact
///                           arithmetic (`CGAL::Epeck` points, filtered predicates); each cell of the overlay, the
///                           intersection of a face of each map, is a convex polygon, triangulated by a fan from a
///                           corner (or from the mean of its corners when every fan from a corner would have a flat
///                           triangle). Each
///                           vertex is placed on A from where it lies in A's refined map: a vertex of the map at its
///                           own point, a point inside an edge at its parameter along it, a point inside a face at its
///                           barycentric coordinates (in double, from the interval approximation of the exact point);
///                           on B likewise; both meshes list their vertices and faces in the same order, so that
///                           `(1-t) A' + t B'` is a morph. The triangulated overlay is certified in exact
///                           coordinates (`Cross_parameterization_statistics::report_compatible`); since both maps are
///                           certified, the composed map is affine and orientation-preserving on every triangle.
///                           For two closed meshes, the overlay of the maps of the cut disks, whose points on the cut
///                           (each a vertex of A or of B, met once on each side) are joined two by two
///                           (`Cross_parameterization_statistics::cut_vertices_welded`): the joined triangles are
///                           certified to form two closed, connected, consistently oriented surfaces of Euler
///                           characteristic 2 (every edge in two triangles, the triangles around every vertex one
///                           cycle), else `ERROR_INVALID_EMBEDDING`.
///                           Either pointer may be null; with both null no overlay is computed, as without the
///                           parameter}
///     \cgalParamType{`std::pair<OutputMeshA*, OutputMeshB*>`, each a model of `MutableFaceGraph` whose point type
///                    is constructible from three `double`; the meshes are cleared first}
///     \cgalParamDefault{none: no overlay is computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{planar_maps}
///     \cgalParamDescription{receives, on success, the two certified maps onto the unit square as flat meshes (each
///                           vertex at (u, v, 0)): first A's map, on A's copy as `constrained_embedding()` refined it
///                           (`Cross_parameterization_statistics::vertices_added_a`) and as the composed distortion
///                           left it, then B's map (on B, or on B's refined copy:
///                           `Cross_parameterization_statistics::vertices_added_b`). Each lists first the vertices of
///                           its mesh in the order of `vertices(tm)`, then the vertices added to its copy; its faces
///                           are counterclockwise. These are the maps that `check_embedding()` certified
///                           (`Cross_parameterization_statistics::report_a` and `report_b`): no face flipped or
///                           degenerate in floating point, the landmarks of A at the same points as their partners.
///                           For two closed meshes, the maps of the two cut disks: each lists first the vertices of
///                           its mesh in the order of `vertices(tm)`, then the copies of the vertices inside the cut
///                           (the cut's border runs through both copies of each), then for B the midpoints of the chords
///                           it split (`Cross_parameterization_statistics::chords_split_b`), then the vertices added
///                           to the copies. Either pointer may be null; both null ask for nothing}
///     \cgalParamType{`std::pair<OutputMeshA*, OutputMeshB*>`, each a model of `MutableFaceGraph` whose point type
///                    is constructible from three `double`; the meshes are cleared first}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{statistics}
///     \cgalParamDescription{receives counts, times and both certificates}
///     \cgalParamType{`Cross_parameterization_statistics*`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// Both meshes use their internal vertex points (`boost::get(CGAL::vertex_point, tm)`).
///
/// \return `OK` with every vertex of A located and both maps certified; otherwise, with nothing written to `out`:
///         the mesh errors of `tutte_embedding()` for either mesh (`ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`,
///         `ERROR_NON_MANIFOLD`, `ERROR_NOT_A_DISK`, also for a closed mesh against a disk;
///         `Cross_parameterization_statistics::failed_mesh` says which), `ERROR_NON_FINITE_COORDINATES` (a NaN or
///         infinite 3D point; `failed_mesh` says which mesh), for closed meshes `ERROR_NOT_GENUS_ZERO`
///         and `ERROR_PATH_TRACING_FAILED` (no pair of landmarks cuts both meshes and the chain through all cannot
///         go on without crossing itself or a landmark; with `failed_landmark`), `ERROR_WRONG_PARAMETER` for two closed meshes with fewer than two landmarks,
///         `ERROR_BORDER_TOO_SHORT` (fewer than four border vertices; `failed_mesh` says which mesh), `ERROR_WRONG_PARAMETER` (a landmark vertex
///         not of its mesh, a `border_vertex_pair` vertex not on its border), `ERROR_LANDMARK_ORDER` (border landmarks
///         not in the same counterclockwise order along both borders, `border_vertex_pair` counted as the first:
///         no orientation-preserving bijection matches them; the first landmark out of order along B's border),
///         `ERROR_CONSTRAINT_ON_BORDER` (a landmark with one vertex on its border and the other
///         inside), `ERROR_DUPLICATE_CONSTRAINT` (a vertex used by two landmarks, or by a landmark and
///         `border_vertex_pair` with another partner) -- these four with
///         `Cross_parameterization_statistics::failed_landmark` --, `ERROR_BORDER_TOO_SHORT` also when the border
///         landmarks leave fewer than three places for the corners of the square besides the first (the first border
///         landmark, or `border_vertex_pair`; each corner needs a vertex at the same place along both borders: a
///         border landmark, or vertices inside an arc between two matched border vertices on both borders; with
///         `failed_landmark`: the border landmark at the end of the first arc of A found too short for the corners
///         that B's arc holds, counterclockwise, unless that is `border_vertex_pair`), the
///         errors of `parameterize_certified()` on B and of `constrained_embedding()` on A, or
///         `ERROR_INVALID_EMBEDDING` when a certificate fails (of either map, of the location, or with `compatible_meshes` of
///         the triangulated overlay, for closed meshes also of the overlay joined along the cut), for closed meshes
///         `ERROR_NOT_A_DISK` when the cut is a single edge (two landmarks joined by an edge: the cut opens nothing;
///         with `failed_landmark`, the second landmark) and
///         `ERROR_DEGENERATE_BORDER` when two points of an arc of the cut cannot be kept apart in double.
template <typename ConcurrencyTag = CGAL::Sequential_tag, class TriangleMeshA, class TriangleMeshB,
          class LandmarkRange, class LocationMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code cross_parameterization(const TriangleMeshA& tm_a, const TriangleMeshB& tm_b, const LandmarkRange& landmarks,
                                  LocationMap out, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::get_parameter;
  CGAL::Real_timer timer;
  timer.start();
  internal::Cross_settings<TriangleMeshA, TriangleMeshB> settings;
  internal::read_cross_settings(np, settings);
  internal::Landmark_pairs<TriangleMeshA, TriangleMeshB> pairs;
  for(const auto& l : landmarks) pairs.emplace_back(l.first, l.second);
  internal::Cross_output<TriangleMeshA, TriangleMeshB> output;
  const Error_code ec = internal::cross_parameterization_disks<ConcurrencyTag>(tm_a, tm_b, pairs, settings, output);
  if(ec != OK) return ec;
  // the output, written only now that everything is certified
  const double before_write = timer.time();
  for(std::size_t i = 0; i < output.vertices_a.size(); ++i) put(out, output.vertices_a[i], output.locations[i]);
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::b_to_a_locations_t>::value)
  {
    auto out_b = get_parameter(np, internal_np::b_to_a_locations);
    for(std::size_t i = 0; i < output.vertices_b.size(); ++i) put(out_b, output.vertices_b[i], output.locations_b[i]);
  }
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::compatible_meshes_t>::value)
  {
    const auto meshes = get_parameter(np, internal_np::compatible_meshes);
    if(meshes.first != nullptr) internal::write_soup(output.compatible_a, output.compatible_triangles, *meshes.first);
    if(meshes.second != nullptr) internal::write_soup(output.compatible_b, output.compatible_triangles, *meshes.second);
  }
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::planar_maps_t>::value)
  {
    const auto maps = get_parameter(np, internal_np::planar_maps);
    if(maps.first != nullptr) internal::write_soup(output.plane_a, output.plane_faces_a, *maps.first);
    if(maps.second != nullptr) internal::write_soup(output.plane_b, output.plane_faces_b, *maps.second);
  }
  if(settings.statistics != nullptr)
  {
    const double written = timer.time() - before_write;
    if(settings.compatible_meshes) settings.statistics->seconds_compatible += written;
    settings.statistics->seconds_total += written;
  }
  return OK;
}


/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// interpolates a per-vertex property of `tm_b` onto the vertices of `tm_a` through the locations computed by
/// `cross_parameterization()`: the value at a vertex of A is the convex combination of the values at the three
/// vertices of its face of B, with its barycentric coordinates as weights.
///
/// \tparam TriangleMeshA a model of `FaceGraph`
/// \tparam TriangleMeshB a model of `FaceGraph`
/// \tparam LocationMap a model of `ReadablePropertyMap` from the vertices of `tm_a` to `Cross_location<TriangleMeshB>`
/// \tparam VertexValueMapB a model of `ReadablePropertyMap` from the vertices of `tm_b` to a value: an arithmetic type
///         (a scalar), a `std::array` of numbers, a CGAL `Point_2` or `Point_3` (a uv, a position) or a
///         `CGAL::IO::Color` (rounded to the nearest)
/// \tparam VertexValueMapA a model of `WritablePropertyMap` from the vertices of `tm_a` to the same value type
///
/// \param tm_a the mesh whose vertices receive the values
/// \param tm_b the mesh whose property is transferred
/// \param locations the location on `tm_b` of every vertex of `tm_a`
/// \param from_b the property of `tm_b`
/// \param to_a receives the interpolated property
template <class TriangleMeshA, class TriangleMeshB, class LocationMap, class VertexValueMapB, class VertexValueMapA>
void transfer_vertex_property(const TriangleMeshA& tm_a, const TriangleMeshB& tm_b, LocationMap locations,
                              VertexValueMapB from_b, VertexValueMapA to_a)
{
  typedef typename boost::property_traits<VertexValueMapB>::value_type Value;
  for(auto v : vertices(tm_a))
  {
    const Cross_location<TriangleMeshB> loc = get(locations, v);
    const auto h = halfedge(loc.first, tm_b);
    const std::array<Value, 3> values{{ Value(get(from_b, source(h, tm_b))), Value(get(from_b, target(h, tm_b))),
                                        Value(get(from_b, target(next(h, tm_b), tm_b))) }};
    put(to_a, v, internal::weighted_sum(values, loc.second));
  }
}

} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_CROSS_PARAMETERIZATION_H
