// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_HOLES_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_HOLES_H

// Multiply connected domains (meshes with holes): the fill/unfill machinery and the embedding.
//
// A connected genus-0 triangle mesh with k >= 1 border loops is mapped with one loop, the OUTER
// one, on the (convex) domain border and every other loop (a HOLE) bounding an empty region of the
// plane. The map is certified by check_embedding(..., parameters::multiply_connected(true)), see
// check_embedding.h: every face strictly positive, every loop simple, no two loops touching, every
// hole oriented opposite to the outer loop and inside it, no overlap.
//
// ---- Interface ------------------------------------------------------------------------------
//
//  halfedge_descriptor longest_border_loop(tm, vpm)
//      a border halfedge of the border loop of largest 3D length (sum of its edge lengths in
//      double; the first such loop in halfedge order among equal ones); null if tm has no border.
//      The default outer loop everywhere below.
//
//  Error_code fill_holes(TriangleMesh& tm, halfedge_descriptor outer, VPM vpm, Filled_holes<TriangleMesh>& rec)
//      tm: a MutableFaceGraph, connected genus 0 with k >= 1 border loops; outer: a border halfedge of
//      the loop that stays open, or null_halfedge() for longest_border_loop(). Closes every other
//      loop by a fan around one new vertex (Euler::fill_hole then Euler::add_center_vertex), whose
//      3D point (written with `put(vpm, ...)`) is the centroid of the loop's vertices, computed in
//      the point's number type. The result is a topological disk whose border is the outer loop;
//      `rec` records what was added. Original vertices, halfedges and faces keep their
//      descriptors (only new elements are added).
//      Errors (tm untouched): ERROR_NOT_GENUS_ZERO (closed, disconnected, genus > 0), ERROR_EMPTY_MESH,
//      ERROR_NON_MANIFOLD, ERROR_NON_TRIANGULAR_MESH, ERROR_WRONG_PARAMETER (outer not a border halfedge).
//
//  Error_code unfill_holes(TriangleMesh& tm, Filled_holes<TriangleMesh>& rec)
//      undoes fill_holes exactly (Euler::remove_center_vertex then Euler::make_hole, then every
//      loop vertex gets back the `halfedge(v)` it had): same vertices, halfedges, faces, with the
//      same descriptors and the same incidences as before fill_holes. Precondition: the fans are
//      as fill_holes left them (no edge of a fan split or flipped); checked first for every fan
//      (ERROR_WRONG_PARAMETER, tm untouched). On Surface_mesh the removed elements are marked
//      removed (garbage), as every Euler removal does; `collect_garbage()` is left to the caller.
//      Property values of the original elements (e.g. uv) are not touched; `rec` is cleared.
//
//  Error_code embed_with_holes(const TriangleMesh& tm, halfedge_descriptor outer, VertexUVMap uvm,
//                              const NamedParameters& np, Embedding_report* report = nullptr)
//      the whole embedding: tm any FaceGraph (not modified: the work is done on a Surface_mesh copy,
//      which is simpler than filling the caller's mesh and guarantees it is never touched);
//      outer: a border halfedge of the outer loop or null_halfedge() (longest_border_loop()).
//      Steps: copy -> fill_holes -> tutte_embedding (outer loop: fixed from uvm, or a border shape)
//      -> progressive_embedding if the Tutte map is not certified -> the uv of the original
//      vertices read back (the holes opened) -> check_embedding(tm, ..., multiply_connected(true)).
//      Named parameters (the others are ignored): border_shape (default Border_shape::FIXED: the
//      outer loop's uv are read from uvm; it must be strictly convex), weights,
//      triangle_corner_points, vertex_point_map, maximum_running_time (given to each of the two
//      solvers). With k == 1 this is tutte_embedding + progressive_embedding of a disk.
//      On OK the uv of every vertex of tm is written (the outer loop bit-exactly unchanged with
//      Border_shape::FIXED: it is not written) and the map is certified valid; `*report` receives the
//      certificate of the result (also on ERROR_INVALID_EMBEDDING). On any error nothing is written.
//      Errors: those of fill_holes (ERROR_NOT_GENUS_ZERO, ...), of tutte_embedding
//      (ERROR_NON_CONVEX_BORDER, ERROR_BORDER_TOO_SHORT, ...) and of progressive_embedding, and
//      ERROR_INVALID_EMBEDDING if the final certificate fails.
//
// Why a fan around a new vertex: it keeps the closed mesh a triangulated disk with the outer loop as
// its only border, adds the fewest elements (one vertex, one face per hole edge), and in a valid map
// of the filled disk the hole is star-shaped around its vertex, so that the fan faces keep the hole
// empty and inside the outer loop; removing them leaves exactly the multiply connected map.
// The centroid as 3D point is used only by 3D-dependent choices (mean value weights, energies on
// the filled disk); it is a point "in the middle of" the hole for any reasonably shaped hole.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/internal/check_embedding_impl.h>
#include <CGAL/Progressive_embedding/internal/tutte_embedding_impl.h>
#include <CGAL/Progressive_embedding/internal/progressive_embedding_impl.h>
#include <CGAL/Progressive_embedding/internal/holes_domain.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh.h>
#include <boost/property_map/function_property_map.hpp>

#include <cmath>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// What fill_holes() added, for unfill_holes()
template <class TriangleMesh>
struct Filled_holes
{
  typedef boost::graph_traits<TriangleMesh>         GT;
  typedef typename GT::vertex_descriptor            vertex_descriptor;
  typedef typename GT::halfedge_descriptor          halfedge_descriptor;

  halfedge_descriptor outer = GT::null_halfedge();  // a border halfedge of the outer loop (the border of the filled disk)
  std::vector<vertex_descriptor> centers;           // per closed hole: its new vertex
  std::vector<halfedge_descriptor> loop_halfedges;  // per closed hole: the halfedge that was a border halfedge of the loop
  std::vector<std::size_t> loop_sizes;              // per closed hole: number of loop edges (= degree of the center)
  std::vector<std::vector<std::pair<vertex_descriptor, halfedge_descriptor> > > vertex_halfedges; // halfedge(v) before

  std::size_t number_of_holes() const { return centers.size(); }
  void clear() { *this = Filled_holes(); }
};

template <class TriangleMesh, class VertexPointMap>
typename boost::graph_traits<TriangleMesh>::halfedge_descriptor
longest_border_loop(const TriangleMesh& tm, VertexPointMap vpm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  auto seen = get(CGAL::dynamic_halfedge_property_t<bool>(), tm);
  for(halfedge_descriptor h : halfedges(tm)) put(seen, h, false);
  halfedge_descriptor best = GT::null_halfedge();
  double best_length = -1;
  const std::size_t nh = num_halfedges(tm);
  for(halfedge_descriptor h : halfedges(tm))
  {
    if(!is_border(h, tm) || get(seen, h)) continue;
    double length = 0;
    halfedge_descriptor c = h;
    std::size_t guard = 0;
    do
    {
      put(seen, c, true);
      const auto& p = get(vpm, source(c, tm));
      const auto& q = get(vpm, target(c, tm));
      const double dx = CGAL::to_double(q.x()) - CGAL::to_double(p.x()), dy = CGAL::to_double(q.y()) - CGAL::to_double(p.y()),
                   dz = CGAL::to_double(q.z()) - CGAL::to_double(p.z());
      const double l = std::sqrt(dx * dx + dy * dy + dz * dz);
      if(std::isfinite(l)) length += l;
      c = next(c, tm);
    } while(c != h && ++guard <= nh);
    if(length > best_length) { best_length = length; best = h; }
  }
  return best;
}

template <class TriangleMesh, class VertexPointMap>
Error_code fill_holes(TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor outer,
                      VertexPointMap vpm, Filled_holes<TriangleMesh>& rec)
{
  typedef boost::graph_traits<TriangleMesh>                     GT;
  typedef typename GT::vertex_descriptor                        vertex_descriptor;
  typedef typename GT::halfedge_descriptor                      halfedge_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel::FT     FT3;

  rec.clear();
  Indexed_domain<TriangleMesh> d;
  const Error_code ec = make_indexed_domain(tm, d);
  if(ec != OK) return ec;
  if(outer == GT::null_halfedge()) outer = longest_border_loop(tm, vpm);
  else
  {
    bool found = false; // a border halfedge of tm (checked without trusting the descriptor)
    for(halfedge_descriptor h : d.loop_halfedge)
    {
      halfedge_descriptor c = h;
      std::size_t guard = 0;
      do { if(c == outer) found = true; c = next(c, tm); } while(c != h && ++guard <= num_halfedges(tm));
    }
    if(!found) return ERROR_WRONG_PARAMETER;
  }
  rec.outer = outer;
  auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  for(std::size_t i = 0; i < d.disk.vertices.size(); ++i) put(vid, d.disk.vertices[i], i);
  const long outer_loop = d.loop_of[get(vid, target(outer, tm))];

  for(std::size_t l = 0; l < d.number_of_loops(); ++l)
  {
    if(long(l) == outer_loop) continue;
    const halfedge_descriptor h = d.loop_halfedge[l];
    std::vector<std::pair<vertex_descriptor, halfedge_descriptor> > vh;
    FT3 x(0), y(0), z(0);
    for(std::size_t v : d.loops[l])
    {
      const vertex_descriptor vd = d.disk.vertices[v];
      vh.emplace_back(vd, halfedge(vd, tm));
      const Point_3& p = get(vpm, vd);
      x += p.x(); y += p.y(); z += p.z();
    }
    const FT3 n(static_cast<int>(d.loops[l].size()));
    CGAL::Euler::fill_hole(h, tm);
    const halfedge_descriptor hc = CGAL::Euler::add_center_vertex(h, tm);
    const vertex_descriptor c = target(hc, tm);
    put(vpm, c, Point_3(x / n, y / n, z / n));
    rec.centers.push_back(c);
    rec.loop_halfedges.push_back(h);
    rec.loop_sizes.push_back(d.loops[l].size());
    rec.vertex_halfedges.push_back(vh);
  }
  return OK;
}

template <class TriangleMesh>
Error_code unfill_holes(TriangleMesh& tm, Filled_holes<TriangleMesh>& rec)
{
  typedef boost::graph_traits<TriangleMesh>  GT;
  typedef typename GT::halfedge_descriptor   halfedge_descriptor;
  // every fan first: all or nothing
  for(std::size_t i = 0; i < rec.number_of_holes(); ++i)
  {
    const halfedge_descriptor h = rec.loop_halfedges[i];
    if(is_border(h, tm) || target(next(h, tm), tm) != rec.centers[i]) return ERROR_WRONG_PARAMETER;
    std::size_t degree = 0;
    const halfedge_descriptor start = halfedge(rec.centers[i], tm);
    halfedge_descriptor c = start;
    do
    {
      // a triangle of the fan: no spoke split or flipped
      if(is_border(c, tm) || ++degree > rec.loop_sizes[i] || next(next(next(c, tm), tm), tm) != c) return ERROR_WRONG_PARAMETER;
      c = opposite(next(c, tm), tm);
    } while(c != start);
    if(degree != rec.loop_sizes[i]) return ERROR_WRONG_PARAMETER;
  }
  for(std::size_t i = rec.number_of_holes(); i-- > 0; )
  {
    const halfedge_descriptor h = rec.loop_halfedges[i];
    CGAL::Euler::remove_center_vertex(next(h, tm), tm); // the fan becomes one face, h on it
    CGAL::Euler::make_hole(h, tm);                       // and the face is removed: h is a border halfedge again
    for(const auto& vh : rec.vertex_halfedges[i]) set_halfedge(vh.first, vh.second, tm);
  }
  rec.clear();
  return OK;
}

template <class TriangleMesh, class VertexUVMap, class NamedParameters>
Error_code embed_with_holes(const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor outer,
                            VertexUVMap uvm, const NamedParameters& np, Embedding_report* report = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh>                                GT;
  typedef typename GT::vertex_descriptor                                   vertex_descriptor;
  typedef typename GT::halfedge_descriptor                                 halfedge_descriptor;
  typedef typename Uv_map_types<VertexUVMap>::Point_2                      Point_2;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  typedef typename boost::property_traits<decltype(vpm)>::value_type       Point_3;
  typedef CGAL::Surface_mesh<Point_3>                                      Work;
  typedef boost::graph_traits<Work>                                        WGT;
  typedef typename WGT::vertex_descriptor                                  wvertex;
  typedef typename WGT::halfedge_descriptor                                whalfedge;

  const Border_shape shape = choose_parameter(get_parameter(np, internal_np::border_shape), Border_shape::FIXED);
  const Weights wts = choose_parameter(get_parameter(np, internal_np::weights), Weights::UNIFORM);
  const std::array<Point_2, 3> corners = choose_parameter(get_parameter(np, internal_np::triangle_corner_points),
                                                          default_triangle_corner_points<Point_2>());
  const double max_seconds = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time),
                                              std::numeric_limits<double>::infinity());
  if(!(max_seconds >= 0)) return ERROR_WRONG_PARAMETER;

  Indexed_domain<TriangleMesh> d;
  Error_code ec = make_indexed_domain(tm, d);
  if(ec != OK) return ec;
  if(outer == GT::null_halfedge()) outer = longest_border_loop(tm, vpm);
  else if(!is_border(outer, tm)) return ERROR_WRONG_PARAMETER;

  // the work copy, with its own uv (the caller's values copied: the outer loop for FIXED)
  Work work;
  std::vector<std::pair<vertex_descriptor, wvertex> > v2v;
  std::vector<std::pair<halfedge_descriptor, whalfedge> > h2h;
  CGAL::copy_face_graph(tm, work, CGAL::parameters::vertex_point_map(vpm)
                                    .vertex_to_vertex_output_iterator(std::back_inserter(v2v))
                                    .halfedge_to_halfedge_output_iterator(std::back_inserter(h2h)));
  whalfedge wouter = WGT::null_halfedge();
  for(const auto& hh : h2h) if(hh.first == outer) wouter = hh.second;
  if(wouter == WGT::null_halfedge() || !is_border(wouter, work)) return ERROR_WRONG_PARAMETER;
  auto wuv = work.template add_property_map<wvertex, Point_2>("v:pe_holes_uv", Point_2()).first;
  for(const auto& vv : v2v) put(wuv, vv.second, get(uvm, vv.first));

  Filled_holes<Work> rec;
  ec = fill_holes(work, wouter, get(CGAL::vertex_point, work), rec);
  if(ec != OK) return ec;
  ec = tutte_embedding_impl(work, wouter, wuv, CGAL::Progressive_embedding::parameters::border_shape(shape,
                         CGAL::Progressive_embedding::parameters::weights(wts,
                         CGAL::Progressive_embedding::parameters::triangle_corner_points(corners,
                         CGAL::parameters::maximum_running_time(max_seconds)))));
  if(ec != OK) return ec;
  if(!check_embedding_impl(work, wuv).is_valid())
  {
    ec = progressive_embedding_impl(work, wuv, CGAL::parameters::maximum_running_time(max_seconds));
    if(ec != OK) return ec;
  }
  // the holes opened: the uv of the original vertices, certified on the caller's mesh before writing
  auto wv = get(CGAL::dynamic_vertex_property_t<wvertex>(), tm);
  for(const auto& vv : v2v) put(wv, vv.first, vv.second);
  auto result = boost::make_function_property_map<vertex_descriptor, Point_2>(
    [&](vertex_descriptor v) -> Point_2 { return get(wuv, get(wv, v)); });
  const Embedding_report r = check_embedding_impl(tm, result, CGAL::Progressive_embedding::parameters::multiply_connected(true,
                                                           CGAL::parameters::vertex_point_map(vpm)));
  if(report) *report = r;
  if(!r.is_valid()) return ERROR_INVALID_EMBEDDING;
  auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  for(std::size_t i = 0; i < d.disk.vertices.size(); ++i) put(vid, d.disk.vertices[i], i);
  const long outer_loop = d.loop_of[get(vid, target(outer, tm))];
  for(const auto& vv : v2v)
    if(shape != Border_shape::FIXED || d.loop_of[get(vid, vv.first)] != outer_loop)
      put(uvm, vv.first, get(wuv, vv.second));
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_HOLES_H
