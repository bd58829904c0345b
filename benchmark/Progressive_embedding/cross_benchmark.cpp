// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors
//
// cross_parameterization() under the remeshed-pair protocol (internal/cross/remeshed_pair_protocol.h):
// A a libcgal-demo disk or closed genus-0 mesh, B its copy remeshed by CGAL's isotropic remeshing (target edge length 1.3
// times the mean), K landmarks (interior vertices of A spread out by farthest-point sampling, each
// matched to the nearest interior vertex of B). Per run: vertices of A and B, vertices added to A's
// copy, seconds (B's map, A's map, location, total), both certificates, landmarks exact, mean and max
// 3D distance between a vertex of A and its image on B relative to A's bounding-box diagonal (also split: at the
// landmarks, on the border, inside); the compatible
// meshes (the certified overlay of the two maps): their vertices, certificate and seconds (in the total); the
// process's peak resident memory during the call (Linux: reset before it, the two input meshes included); the
// distortion of the composed map sampled at A's vertices. Each pair also gets one row of the naive composition
// (Tutte's maps of both on one circle, no landmark, nothing repaired or optimized: see run_naive()), measured the
// same way.
//
//   cross_benchmark DATA_DIR OUT_PREFIX [--meshes a.off,b.off] [--counts 5,20,50] [--pairs A1:B1,A2:B2]
//                   [--composed on|off|both] [--matched on|off|both] [--parallel on|off|both]
//
// --composed: A's map optimized for the composed map's distortion (named parameter composed_distortion; on by
// default) or not; `both` runs every case without it, then with it (side by side in the tables). --matched: B's map
// made again with B's landmarks pinned, as A's is (named parameter matched_maps; on by default), or not; likewise.
// --parallel: cross_parameterization<CGAL::Parallel_tag>() (B's matched map and A's map made at the same time) or
// <CGAL::Sequential_tag>() (one after the other, as `pe cross` and the Python binding do; the default); the maps are
// the same either way, only the seconds and the memory differ.
//
// With --pairs, A and B are two given files (e.g. two resolutions of one surface: the true image of a vertex of
// A is then its own position, up to the distance between the two discretizations) instead of a mesh and its
// remeshed copy; K = 0 gives the map without landmarks (the borders matched by relative arc length only).
//
// Writes OUT_PREFIX.csv (one row per run) and OUT_PREFIX.md (the same as a table).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Progressive_embedding/cross_parameterization.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/internal/cross/common_border.h>
#include <CGAL/Progressive_embedding/internal/cross/locate_in_map.h>
#include <CGAL/Progressive_embedding/internal/cross/remeshed_pair_protocol.h>
#include <CGAL/Progressive_embedding/internal/symmetric_dirichlet.h>
#include <CGAL/Real_timer.h>

#include "orbifold_composition.h"
#include "process_memory.h"

#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace PE = CGAL::Progressive_embedding;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                        SM;

namespace {

struct Row
{
  std::string mesh;
  std::string method = "cross"; // or "naive Tutte": Tutte's map of both, no landmark, no optimization
  // the distortion of the composed map sampled at A's vertices: per face of A, the affine map onto the triangle of
  // its vertices' images on B, its symmetric Dirichlet energy (4 for an isometry), the mean weighted by A's areas;
  // faces whose image is degenerate (infinite energy) are counted apart
  double distortion = 0;
  std::size_t degenerate_images = 0;
  std::size_t unlocated = 0;        // naive: vertices of A outside every positively oriented face of B's map
  std::size_t bad_faces = 0;        // naive: flipped or degenerate faces of the two Tutte maps
  std::size_t tiles = 0;            // Orbifold Tutte: copies of B's tile A's vertices were located among
  std::size_t cone_orders_rejected = 0; // Orbifold Tutte: orders of the cones whose shortest paths made no chain
  bool composed = true, matched = true, matched_b = false, parallel = false;
  bool matched_more_distorted = false; // B's matched map made, but more than 5% above the first map's energy
  bool closed = false; // two closed meshes, cut into disks
  std::size_t added_b = 0;
  std::size_t count = 0, landmarks = 0, va = 0, vb = 0, added = 0, vc = 0;
  std::string status;
  bool valid_a = false, valid_b = false, exact = false, valid_c = false;
  // the mean error split: at A's landmark vertices, at A's border vertices, at the other vertices (what the
  // landmarks and the border rule cannot fix: a landmark pair of two discretizations is apart by the distance between
  // the two vertices, and the border is matched by relative arc length, not by position)
  double error_landmarks = -1, error_border = -1, error_inside = -1; // -1: no such vertex measured
  double peak_mb = 0; // the process's peak resident memory during the call
  double mean_error = 0, max_error = 0, t_b = 0, t_a = 0, t_composed = 0, t_location = 0, t_compatible = 0, t_total = 0;
};

std::vector<std::string> split(const std::string& s, char separator = ',')
{
  std::vector<std::string> r;
  std::stringstream ss(s);
  for(std::string t; std::getline(ss, t, separator); ) if(!t.empty()) r.push_back(t);
  return r;
}

std::string base_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

// `file_b` empty: B is A remeshed
bool read_pair(const std::string& file_a, const std::string& file_b, SM& a, SM& b)
{
  if(!CGAL::IO::read_polygon_mesh(file_a, a) || !CGAL::IO::read_polygon_mesh(file_b.empty() ? file_a : file_b, b))
    return false;
  if(file_b.empty())
  {
    PE::internal::remesh_isotropically(b);
    b.collect_garbage();
  }
  return true;
}

// the symmetric Dirichlet energy of the affine map from the triangle p to the triangle q (both in 3D): q laid out in
// its own plane, measured against p by the optimizer's energy (internal/symmetric_dirichlet.h); infinite when q is
// degenerate
double triangle_map_energy(const std::array<K::Point_3, 3>& p, const std::array<K::Point_3, 3>& q)
{
  auto coords = [](const K::Point_3& x) { return std::array<double, 3>{{ x.x(), x.y(), x.z() }}; };
  const PE::internal::Reference_triangle<double> ref =
    PE::internal::reference_from_points<double, 3>(coords(p[0]), coords(p[1]), coords(p[2]));
  const K::Vector_3 e1 = q[1] - q[0], e2 = q[2] - q[0];
  const double l1 = std::sqrt(e1.squared_length());
  if(!(l1 > 0) || !(ref.area2 > 0)) return std::numeric_limits<double>::infinity();
  const double x2 = (e1 * e2) / l1, y2 = std::sqrt(CGAL::cross_product(e1, e2).squared_length()) / l1;
  bool ok = false;
  const double e = PE::internal::symmetric_dirichlet(ref, 0., 0., l1, 0., x2, y2, ok);
  return ok && std::isfinite(e) ? e : std::numeric_limits<double>::infinity();
}

// the composed map's distortion sampled at A's vertices (see Row)
// (over the faces of A whose three vertices are `located`)
template <class LocationMap>
void sampled_distortion(const SM& a, const SM& b, LocationMap loc, const std::vector<char>& located, Row& r)
{
  double sum = 0, area = 0;
  for(SM::Face_index f : faces(a))
  {
    std::array<K::Point_3, 3> p, q;
    int k = 0;
    bool all = true;
    for(SM::Vertex_index v : CGAL::vertices_around_face(a.halfedge(f), a)) all = all && located[std::size_t(v)];
    if(!all) continue;
    for(SM::Vertex_index v : CGAL::vertices_around_face(a.halfedge(f), a))
    {
      p[k] = a.point(v);
      q[k] = CGAL::Polygon_mesh_processing::construct_point(get(loc, v), b);
      ++k;
    }
    const double e = triangle_map_energy(p, q);
    if(!std::isfinite(e)) { ++r.degenerate_images; continue; }
    const double w = std::sqrt(CGAL::squared_area(p[0], p[1], p[2]));
    sum += w * e;
    area += w;
  }
  r.distortion = area > 0 ? sum / area : 0;
}

// the errors of the located vertices of A (the mean and max, split as in Row)
template <class LocationMap>
void measure_errors(const SM& a, const SM& b, LocationMap loc, const std::vector<char>& landmark, const std::vector<char>& located,
                    Row& r)
{
  const std::vector<double> errors = PE::internal::correspondence_errors(a, b, loc);
  std::array<double, 3> sum = {{ 0, 0, 0 }};
  std::array<std::size_t, 3> n = {{ 0, 0, 0 }};
  std::size_t i = 0;
  for(SM::Vertex_index v : vertices(a))
  {
    const double e = errors[i++];
    if(!located[std::size_t(v)]) continue;
    const int c = landmark[std::size_t(v)] ? 0 : CGAL::is_border(v, a) ? 1 : 2;
    sum[c] += e;
    ++n[c];
    r.max_error = (std::max)(r.max_error, e);
  }
  const std::size_t all = n[0] + n[1] + n[2];
  if(all != 0) r.mean_error = (sum[0] + sum[1] + sum[2]) / double(all);
  if(n[0] != 0) r.error_landmarks = sum[0] / double(n[0]);
  if(n[1] != 0) r.error_border = sum[1] / double(n[1]);
  if(n[2] != 0) r.error_inside = sum[2] / double(n[2]);
}

// The naive composition: Tutte's map (uniform weights) of A and of B onto the unit circle, each border by relative
// arc length from the start pair that cross_parameterization() chooses, nothing repaired or optimized, and each vertex of A
// located in B's map by the same exact point location. A vertex of A may fall outside every positively oriented
// face of B: near the border, outside the polygon inscribed in the circle by B's border vertices, and anywhere
// where a map is not valid in floating point (flipped or degenerate faces); it is counted (`unlocated`), and its
// error and the faces of A around it are left out.
Row run_naive(const std::string& file_a, const std::string& file_b, const std::string& name)
{
  Row r;
  r.mesh = name;
  r.method = "naive Tutte";
  r.composed = r.matched = false;
  SM a, b;
  if(!read_pair(file_a, file_b, a, b)) { r.status = "unreadable"; return r; }
  CGAL::Real_timer timer;
  timer.start();
  pe_bench::reset_peak_rss();
  typedef PE::internal::Indexed_disk<SM> Disk;
  Disk disk_a, disk_b;
  PE::Error_code ec = PE::internal::make_indexed_disk(a, SM::null_halfedge(), disk_a);
  if(ec == PE::OK) ec = PE::internal::make_indexed_disk(b, SM::null_halfedge(), disk_b);
  if(ec != PE::OK) { r.status = PE::get_error_name(ec); return r; }
  r.va = disk_a.number_of_vertices();
  r.vb = disk_b.number_of_vertices();
  // the start pair as cross_parameterization() chooses it
  const std::pair<std::size_t, std::size_t> start = PE::internal::default_start_pair(disk_a, a.points(), disk_b, b.points());
  const std::size_t start_a = start.first, start_b = start.second;
  // both borders on the unit circle by relative arc length from the start pair (on the square, an edge inside a
  // mesh joining two border vertices of one side would be flat, and Tutte's map refuses it)
  auto on_circle = [](const Disk& disk, const SM& m, std::size_t start) {
    const std::vector<double> t = PE::internal::border_parameters_from(disk, m.points(), start);
    std::vector<K::Point_2> p, uv;
    for(std::size_t k = 0; k + 1 < t.size(); ++k)
      p.emplace_back(std::cos(2 * CGAL_PI * t[k]), std::sin(2 * CGAL_PI * t[k]));
    PE::internal::rotate_from_start(p, start, uv);
    return uv;
  };
  const std::vector<K::Point_2> border_a = on_circle(disk_a, a, start_a), border_b = on_circle(disk_b, b, start_b);
  auto uv_a = a.add_property_map<SM::Vertex_index, K::Point_2>("v:naive_uv", K::Point_2(0, 0)).first;
  auto uv_b = b.add_property_map<SM::Vertex_index, K::Point_2>("v:naive_uv", K::Point_2(0, 0)).first;
  for(std::size_t k = 0; k < border_a.size(); ++k) uv_a[disk_a.vertices[disk_a.border[k]]] = border_a[k];
  for(std::size_t k = 0; k < border_b.size(); ++k) uv_b[disk_b.vertices[disk_b.border[k]]] = border_b[k];
  ec = PE::tutte_embedding(a, SM::null_halfedge(), uv_a, PE::parameters::border_shape(PE::Border_shape::FIXED));
  if(ec == PE::OK) ec = PE::tutte_embedding(b, SM::null_halfedge(), uv_b, PE::parameters::border_shape(PE::Border_shape::FIXED));
  if(ec != PE::OK) { r.status = PE::get_error_name(ec); return r; }
  const PE::Embedding_report report_a = PE::check_embedding(a, uv_a), report_b = PE::check_embedding(b, uv_b);
  r.valid_a = report_a.is_valid();
  r.valid_b = report_b.is_valid();
  r.bad_faces = report_a.flipped + report_a.degenerate + report_b.flipped + report_b.degenerate;
  r.exact = true; // no landmark
  std::vector<K::Point_2> map_b, queries;
  for(SM::Vertex_index v : disk_b.vertices) map_b.push_back(uv_b[v]);
  for(SM::Vertex_index v : disk_a.vertices) queries.push_back(uv_a[v]);
  std::vector<PE::internal::Map_location> located;
  r.unlocated = PE::internal::locate_in_map(map_b, disk_b.faces, queries, located);
  std::vector<SM::Face_index> faces_b(faces(b).begin(), faces(b).end());
  auto loc = a.add_property_map<SM::Vertex_index, PE::Cross_location<SM> >("v:cross").first;
  std::vector<char> is_located(a.num_vertices(), 0);
  for(std::size_t i = 0; i < located.size(); ++i)
    if(located[i].face != PE::internal::Map_location::none)
    {
      loc[disk_a.vertices[i]] = PE::Cross_location<SM>(faces_b[located[i].face], located[i].barycentric);
      is_located[std::size_t(disk_a.vertices[i])] = 1;
    }
    else loc[disk_a.vertices[i]] = PE::Cross_location<SM>(faces_b.front(), {{ 1., 0., 0. }}); // not measured
  r.t_total = timer.time();
  r.peak_mb = pe_bench::peak_rss_mb();
  r.status = "OK";
  measure_errors(a, b, loc, std::vector<char>(a.num_vertices(), 0), is_located, r);
  // the distortion on the faces whose three vertices were located
  sampled_distortion(a, b, loc, is_located, r);
  return r;
}

// the landmarks spread over the coarser mesh, each matched to the nearest vertex of the finer one (the other
// way round, a landmark would be moved by up to half an edge of the coarser mesh)
std::vector<std::pair<SM::Vertex_index, SM::Vertex_index> > protocol_landmarks(const SM& a, const SM& b, std::size_t count)
{
  if(b.number_of_vertices() >= a.number_of_vertices())
    return PE::internal::nearest_vertex_landmarks(a, b, PE::internal::spread_interior_vertices(a, count));
  std::vector<std::pair<SM::Vertex_index, SM::Vertex_index> > landmarks;
  for(const auto& p : PE::internal::nearest_vertex_landmarks(b, a, PE::internal::spread_interior_vertices(b, count)))
    landmarks.emplace_back(p.second, p.first);
  return landmarks;
}

// CGAL's Orbifold Tutte embedding of two closed genus-0 meshes with the first 3 (or 4, parallelogram) landmarks of
// the protocol as cones, composed (orbifold_composition.h): measured as the naive row, vertices of A in no positively
// oriented face of B's tiling counted as unlocated and left out
Row run_orbifold(const std::string& file_a, const std::string& file_b, const std::string& name,
                 CGAL::Surface_mesh_parameterization::Orbifold_type type)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  Row r;
  r.mesh = name;
  r.method = std::string("Orbifold Tutte (") + SMP::get_orbifold_type(type) + ")";
  r.composed = r.matched = false;
  r.closed = true;
  r.count = type == SMP::Parallelogram ? 4 : 3;
  SM a, b;
  if(!read_pair(file_a, file_b, a, b)) { r.status = "unreadable"; return r; }
  const std::vector<std::pair<SM::Vertex_index, SM::Vertex_index> > landmarks = protocol_landmarks(a, b, r.count);
  r.landmarks = landmarks.size();
  r.va = a.number_of_vertices();
  r.vb = b.number_of_vertices();
  std::vector<SM::Vertex_index> cones_a, cones_b;
  for(const auto& p : landmarks) { cones_a.push_back(p.first); cones_b.push_back(p.second); }
  CGAL::Real_timer timer;
  timer.start();
  pe_bench::reset_peak_rss();
  pe_bench::Orbifold_map<K> map_a, map_b;
  // the cones in their order, else the first other order in which CGAL's shortest paths make a chain on both meshes
  std::vector<std::size_t> order(landmarks.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  int ec = SMP::ERROR_WRONG_PARAMETER;
  do
  {
    std::vector<SM::Vertex_index> ca, cb;
    for(std::size_t i : order) { ca.push_back(cones_a[i]); cb.push_back(cones_b[i]); }
    const double t0 = timer.time();
    ec = pe_bench::orbifold_map(b, cb, type, map_b);
    const double t1 = timer.time();
    if(ec == SMP::OK) ec = pe_bench::orbifold_map(a, ca, type, map_a);
    r.t_b += t1 - t0;
    r.t_a += timer.time() - t1;
    if(ec != SMP::ERROR_WRONG_PARAMETER) break;
    ++r.cone_orders_rejected;
  }
  while(std::next_permutation(order.begin(), order.end()));
  if(ec == SMP::ERROR_WRONG_PARAMETER && r.cone_orders_rejected > 0)
  {
    r.status = "no chain of shortest paths"; // in any order of the cones, on A or on B
    return r;
  }
  if(ec == SMP::OK && map_a.mirrored != map_b.mirrored)
  {
    r.status = "maps of opposite orientations"; // the tiles could not be compared
    return r;
  }
  if(ec != SMP::OK)
  {
    // CGAL's get_error_message() misses a message and returns null for the last code
    static const char* names[] = { "OK", "ERROR_EMPTY_MESH", "ERROR_NON_TRIANGULAR_MESH", "ERROR_NO_TOPOLOGICAL_DISC",
                                   "ERROR_NO_TOPOLOGICAL_BALL", "ERROR_BORDER_TOO_SHORT", "ERROR_NON_CONVEX_BORDER",
                                   "ERROR_CANNOT_SOLVE_LINEAR_SYSTEM", "ERROR_NO_1_TO_1_MAPPING", "ERROR_WRONG_PARAMETER" };
    r.status = std::string("CGAL ") + (ec >= 0 && ec <= SMP::ERROR_WRONG_PARAMETER ? names[ec] : "unknown error");
    return r;
  }
  std::vector<std::pair<std::size_t, std::array<double, 3> > > located;
  r.unlocated = pe_bench::locate_in_tiling(map_a, map_b, 3, located, r.tiles);
  r.t_total = timer.time();
  r.t_location = r.t_total - r.t_a - r.t_b;
  r.peak_mb = pe_bench::peak_rss_mb();
  r.bad_faces = map_a.flipped + map_a.degenerate + map_b.flipped + map_b.degenerate;
  r.valid_a = map_a.flipped + map_a.degenerate == 0;
  r.valid_b = map_b.flipped + map_b.degenerate == 0;
  r.status = "OK";
  std::vector<SM::Face_index> faces_b(faces(b).begin(), faces(b).end());
  auto loc = a.add_property_map<SM::Vertex_index, PE::Cross_location<SM> >("v:cross").first;
  std::vector<char> is_located(a.num_vertices(), 0), landmark(a.num_vertices(), 0);
  for(SM::Vertex_index v : vertices(a))
  {
    const auto& l = located[std::size_t(v)];
    if(l.first == std::size_t(-1)) { loc[v] = PE::Cross_location<SM>(faces_b.front(), {{ 1., 0., 0. }}); continue; } // not measured
    loc[v] = PE::Cross_location<SM>(faces_b[l.first], l.second);
    is_located[std::size_t(v)] = 1;
  }
  // a cone is exact when it is located at its partner with coordinate 1 there
  r.exact = true;
  for(const auto& p : landmarks)
  {
    landmark[std::size_t(p.first)] = 1;
    const PE::Cross_location<SM>& l = loc[p.first];
    bool at_partner = false;
    int k = 0;
    for(SM::Vertex_index w : CGAL::vertices_around_face(b.halfedge(l.first), b))
    {
      // vertices_around_face starts at target(halfedge(f)): coordinate (k + 1) % 3
      if(w == p.second && l.second[std::size_t((k + 1) % 3)] == 1.) at_partner = true;
      ++k;
    }
    r.exact = r.exact && is_located[std::size_t(p.first)] && at_partner;
  }
  measure_errors(a, b, loc, landmark, is_located, r);
  sampled_distortion(a, b, loc, is_located, r);
  return r;
}

Row run(const std::string& file_a, const std::string& file_b, const std::string& name, std::size_t count, bool composed,
        bool matched, bool parallel)
{
  Row r;
  r.parallel = parallel;
  r.mesh = name;
  r.count = count;
  r.composed = composed;
  r.matched = matched;
  SM a, b;
  if(!read_pair(file_a, file_b, a, b)) { r.status = "unreadable"; return r; }
  const std::vector<std::pair<SM::Vertex_index, SM::Vertex_index> > landmarks = protocol_landmarks(a, b, count);
  r.landmarks = landmarks.size();
  SM::Property_map<SM::Vertex_index, PE::Cross_location<SM> > loc =
    a.add_property_map<SM::Vertex_index, PE::Cross_location<SM> >("v:cross").first;
  PE::Cross_parameterization_statistics st;
  SM compatible_a, compatible_b;
  pe_bench::reset_peak_rss();
  const auto np = PE::parameters::compatible_meshes(std::make_pair(&compatible_a, &compatible_b),
      PE::parameters::composed_distortion(composed, PE::parameters::matched_maps(matched, PE::parameters::statistics(&st))));
  const PE::Error_code ec = parallel ? PE::cross_parameterization<CGAL::Parallel_tag>(a, b, landmarks, loc, np)
                                     : PE::cross_parameterization<CGAL::Sequential_tag>(a, b, landmarks, loc, np);
  r.peak_mb = pe_bench::peak_rss_mb();
  r.status = PE::get_error_name(ec);
  r.va = st.vertices_a;
  r.vb = st.vertices_b;
  r.added = st.vertices_added_a;
  r.matched_b = st.matched_b;
  r.matched_more_distorted = st.matched_more_distorted;
  r.closed = st.closed;
  r.added_b = st.vertices_added_b;
  r.valid_a = st.report_a.is_valid();
  r.valid_b = st.report_b.is_valid();
  r.exact = st.landmarks_exact;
  r.t_b = st.seconds_map_b;
  r.t_a = st.seconds_map_a;
  r.t_composed = st.seconds_composed;
  r.t_location = st.seconds_location;
  r.vc = st.compatible_vertices;
  r.valid_c = st.report_compatible.is_valid();
  r.t_compatible = st.seconds_compatible;
  r.t_total = st.seconds_total;
  if(ec != PE::OK) return r;
  std::vector<char> landmark(a.num_vertices(), 0);
  for(const auto& p : landmarks) landmark[std::size_t(p.first)] = 1;
  measure_errors(a, b, loc, landmark, std::vector<char>(a.num_vertices(), 1), r);
  sampled_distortion(a, b, loc, std::vector<char>(a.num_vertices(), 1), r);
  return r;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: cross_benchmark DATA_DIR OUT_PREFIX [--meshes a.off,b.off] [--counts 5,20,50] [--pairs A:B,...]"
                 " [--composed on|off|both] [--matched on|off|both] [--parallel on|off|both]\n";
    return 2;
  }
  const std::string dir = argv[1], out = argv[2];
  std::vector<std::string> meshes = { "mushroom.off", "lion-head.off" };
  std::vector<std::size_t> counts = { 5, 20, 50 };
  std::vector<std::pair<std::string, std::string> > pairs;
  std::vector<bool> composed = { true }, matched = { true }, parallel = { false };
  for(int i = 3; i + 1 < argc; i += 2)
  {
    const std::string o = argv[i], v = argv[i + 1];
    if(o == "--meshes") meshes = split(v);
    else if(o == "--counts") { counts.clear(); for(const std::string& c : split(v)) counts.push_back(std::stoul(c)); }
    else if(o == "--pairs")
    {
      for(const std::string& p : split(v))
      {
        const std::vector<std::string> ab = split(p, ':');
        if(ab.size() != 2) { std::cerr << "--pairs: expected A:B, got " << p << "\n"; return 2; }
        pairs.emplace_back(ab[0], ab[1]);
      }
      meshes.clear();
    }
    else if(o == "--composed")
    {
      if(v == "on") composed = { true };
      else if(v == "off") composed = { false };
      else if(v == "both") composed = { false, true };
      else { std::cerr << "--composed: expected on, off or both, got " << v << "\n"; return 2; }
    }
    else if(o == "--matched")
    {
      if(v == "on") matched = { true };
      else if(v == "off") matched = { false };
      else if(v == "both") matched = { false, true };
      else { std::cerr << "--matched: expected on, off or both, got " << v << "\n"; return 2; }
    }
    else if(o == "--parallel")
    {
      if(v == "on") parallel = { true };
      else if(v == "off") parallel = { false };
      else if(v == "both") parallel = { false, true };
      else { std::cerr << "--parallel: expected on, off or both, got " << v << "\n"; return 2; }
    }
    else { std::cerr << "unknown option " << o << "\n"; return 2; }
  }
  std::vector<std::array<std::string, 3> > jobs; // A file, B file (empty: A remeshed), name
  for(const std::string& m : meshes) jobs.push_back({{ dir + "/meshes/" + m, std::string(), m }});
  for(const auto& p : pairs) jobs.push_back({{ p.first, p.second, base_name(p.first) + " -> " + base_name(p.second) }});
  std::vector<Row> rows;
  for(const auto& job : jobs)
  {
    rows.push_back(run_naive(job[0], job[1], job[2]));
    const Row& n = rows.back();
    if(n.status == PE::get_error_name(PE::ERROR_NOT_A_DISK))
    {
      rows.pop_back(); // a closed mesh: no Tutte map of its own, but CGAL's Orbifold Tutte maps
      for(auto type : { CGAL::Surface_mesh_parameterization::Square, CGAL::Surface_mesh_parameterization::Parallelogram })
      {
        rows.push_back(run_orbifold(job[0], job[1], job[2], type));
        const Row& o = rows.back();
        std::cout << job[2] << ' ' << o.method << ": " << o.status << ", faces flipped or degenerate " << o.bad_faces
                  << ", unlocated " << o.unlocated << " (" << o.tiles << " copies of B's tile; cone orders rejected "
                  << o.cone_orders_rejected << "), mean error " << o.mean_error
                  << ", max " << o.max_error << ", distortion " << o.distortion << ", " << o.t_total << " s" << std::endl;
      }
    }
    else std::cout << job[2] << " naive Tutte: " << n.status << ", faces flipped or degenerate " << n.bad_faces << ", unlocated "
              << n.unlocated << ", mean error " << n.mean_error << ", max " << n.max_error << ", distortion " << n.distortion
              << ", " << n.t_total << " s" << std::endl;
    for(std::size_t k : counts)
      for(bool mt : matched)
      for(bool c : composed)
      for(bool par : parallel)
      {
        const std::string& m = job[2];
        rows.push_back(run(job[0], job[1], m, k, c, mt, par));
        const Row& r = rows.back();
        std::cout << m << " K=" << k << (mt ? " matched" : "") << (c ? " composed" : "") << (par ? " parallel" : " sequential") << ": " << r.status << ", mean error " << r.mean_error
                  << ", max " << r.max_error << ", added " << r.added << ", compatible " << r.vc
                  << " vertices (" << r.t_compatible << " s), distortion " << r.distortion << ", " << r.t_total << " s" << std::endl;
      }
  }

  std::ofstream csv(out + ".csv");
  csv << "mesh,method,landmarks_requested,landmarks,matched_maps,matched_b,vertices_added_b,composed_distortion,vertices_a,vertices_b,vertices_added_a,status,valid_a,valid_b,"
         "landmarks_exact,mean_error,max_error,mean_error_landmarks,mean_error_border,mean_error_inside,seconds_map_b,seconds_map_a,seconds_composed,seconds_location,"
         "compatible_vertices,compatible_certified,seconds_compatible,seconds_total,peak_rss_mb,"
         "distortion,degenerate_images,unlocated,faces_flipped_or_degenerate,parallel,closed,orbifold_tiles,orbifold_cone_orders_rejected,matched_more_distorted\n";
  csv << std::setprecision(6);
  for(const Row& r : rows)
  {
    csv << r.mesh << ',' << r.method << ',' << r.count << ',' << r.landmarks << ',' << r.matched << ',' << r.matched_b << ',' << r.added_b << ','
        << r.composed << ',' << r.va << ',' << r.vb << ',' << r.added << ','
        << r.status << ',' << r.valid_a << ',' << r.valid_b << ',' << r.exact << ',' << r.mean_error << ','
        << r.max_error << ',';
    if(r.error_landmarks >= 0) csv << r.error_landmarks; // empty without landmarks
    csv << ',';
    if(r.error_border >= 0) csv << r.error_border;
    csv << ',';
    if(r.error_inside >= 0) csv << r.error_inside;
    csv << ','
        << r.t_b << ',' << r.t_a << ',' << r.t_composed << ',' << r.t_location << ',' << r.vc << ',' << r.valid_c << ','
        << r.t_compatible << ',' << r.t_total << ',' << r.peak_mb << ',' << r.distortion << ',' << r.degenerate_images << ','
        << r.unlocated << ',' << r.bad_faces << ',' << r.parallel << ',' << r.closed << ',' << r.tiles << ',' << r.cone_orders_rejected << ',' << r.matched_more_distorted << '\n';
  }

  char host[256] = {0};
  gethostname(host, sizeof host - 1);
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  std::ofstream md(out + ".md");
  md << std::setprecision(3)
     << (pairs.empty() ? "# cross_parameterization(): libcgal-demo meshes against their remeshed copies\n\n"
                       : "# cross_parameterization(): pairs of meshes of one surface\n\n")
     << "Generated " << date << " by `cross_benchmark` (" << sysconf(_SC_NPROCESSORS_ONLN) << " cores). "
     << (pairs.empty() ? "A: the mesh as it is; B: its copy remeshed by CGAL's isotropic remeshing (target edge length "
                         "1.3 times the mean edge length, 3 iterations). "
                       : "A and B: two given meshes of one surface (command line below). ")
     << "K landmarks: interior vertices of the coarser mesh spread out by farthest-point "
        "sampling, each matched to the nearest interior vertex of the other. Error: the 3D distance between the point "
        "of B at the location of a vertex of A and the point of B nearest to that vertex, relative to the diagonal of "
        "A's bounding box. Vertices added: Steiner vertices of A's "
        "refined copy (A itself is not changed). Compatible meshes: the overlay of the two maps triangulated "
        "(`compatible_meshes`), certified in exact coordinates (filtered exact predicates: a triangulated disk, every "
        "triangle and the border counterclockwise, the border simple); its seconds are part of the total. Peak MB: the "
        "process's peak resident memory during the call (reset before it; the two input meshes and the program "
        "included). K = 0: no landmark, the borders matched by "
        "relative arc length only. Distortion: the composed map sampled at A's vertices, per face of A the affine map "
        "onto the triangle of its vertices' images on B, its symmetric Dirichlet energy (4 for an isometry), the mean "
        "weighted by A's face areas (faces with a degenerate image counted apart: none in these tables unless said). "
        "Naive Tutte: the composition a user would write by hand, Tutte's map (uniform weights) of A and of B on the "
        "unit circle (each border by relative arc length from the same start pair as above), no landmark, nothing repaired or optimized, A's vertices located in B's map by the same "
        "exact point location; vertices of A outside every positively oriented face of B (near the border: outside the "
        "polygon of B's border vertices inscribed in the circle; or where a map is not valid in floating point) are "
        "counted (unlocated) and left out of the errors, and the faces around them out of the distortion. "
        "Closed genus-0 meshes (with `--meshes`, or two closed files with `--pairs`) are cut into disks by `cross_parameterization()` itself, between "
        "two landmarks near each other (the others inside the cut disks; their vertex counts are those of the "
        "cut disks, a vertex inside the cut counted twice); they have no naive row (Tutte's "
        "map needs a disk); instead, CGAL's Orbifold Tutte embedding (Aigerman and Lipman: each mesh cut along CGAL's "
        "shortest paths between consecutive cones and mapped, with mean value weights, onto one tile of a periodic "
        "tiling of the plane, the cones at the same points in both maps), with the first 3 landmarks as cones "
        "(`Square`) or the first 4 (`Parallelogram`), the same landmarks as the first of the K; composed as the naive "
        "maps are, each vertex of A located in double precision among the copies of B's tile under the motions of the "
        "tiling's group (read off B's map across its seam; products of up to three) that reach A's tile; faces of "
        "either map flipped or degenerate under the exact orientation test and vertices of A in no positively oriented "
        "copied face of B are counted as for the naive maps (both maps certified: no such face; landmarks exact: each "
        "cone located at its partner with coordinate 1); B's map s and A's map s are the two Orbifold Tutte maps. "
        "CGAL's shortest paths between consecutive cones may cross or overlap (the seam is then not a chain through "
        "the cones, which its parameterizer needs): the cones are then taken in the next order that gives a chain on "
        "both meshes (`orbifold_cone_orders_rejected` in the CSV), status `no chain of shortest paths` when none does. "
        "(It does not apply to two disks.) The Orbifold rows count the vertices of the closed meshes, the rows "
        "of this function those of the cut disks. Composed: A's map optimized once more for the distortion of the composed map "
        "(`composed_distortion`, the default); its seconds (composed s) are part of A's map's. Matched: B's map made "
        "again by `constrained_embedding()` with B's landmarks pinned where its first map put them, as A's is "
        "(`matched_maps`, the default; with landmarks only; its seconds are part of B's map's); vertices added to "
        "B: Steiner vertices left in B's copy (B's map is then on that refined copy); `more distorted`: the matched map "
        "made but more than 5% above the first map's distortion energy, the first map kept (`failed`: not made). "
        "Parallel: "
        "`cross_parameterization<CGAL::Parallel_tag>()`, B's matched map and A's map made at the same time, or "
        "`<CGAL::Sequential_tag>()`, one after the other (as `pe cross` and the Python binding do): the same maps, only "
        "the seconds and the memory differ (with Parallel_tag, B's map s and A's map s overlap). "
        "The mean error is also given "
        "at A's landmark vertices (each lands on its partner, a vertex of the other discretization, so its error is "
        "about the distance between the two: the landmarks cannot bring the error below it), at A's other border "
        "vertices (placed by relative arc length, not by position) and at the other vertices.\n\n"
     << "| mesh | method | K | matched | vertices added to B | composed | parallel | vertices A | vertices B | status | both maps certified | landmarks exact | vertices added to A "
        "| mean error | max error | mean error at landmarks | mean error on the border | mean error inside | B's map s "
        "| A's map s | composed s | location s | compatible vertices | compatible certified "
        "| compatible s | total s | peak MB | distortion | naive, Orbifold: unlocated | naive, Orbifold: faces flipped or degenerate |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for(const Row& r : rows)
  {
    md << "| " << r.mesh << " | " << r.method << " | " << r.landmarks << " | " << (r.matched_b ? "yes" : r.method != "cross" ? "-" : r.matched_more_distorted ? "more distorted" : r.matched && r.landmarks > 0 ? "failed" : "no")
       << " | " << r.added_b << " | " << (r.composed ? "yes" : "no") << " | "
       << (r.method != "cross" ? "-" : r.parallel ? "yes" : "no") << " | " << r.va << " | " << r.vb << " | " << r.status << " | "
       << (r.valid_a && r.valid_b ? "yes" : "no") << " | " << (r.exact ? "yes" : "no") << " | " << r.added << " | "
       << r.mean_error << " | " << r.max_error << " | ";
    if(r.error_landmarks < 0) md << "-";
    else md << r.error_landmarks;
    for(double e : { r.error_border, r.error_inside })
    {
      md << " | ";
      if(e < 0) md << "-";
      else md << e;
    }
    md << " | ";
    if(r.method == "cross")
      md << r.t_b << " | " << r.t_a << " | " << r.t_composed << " | " << r.t_location << " | " << r.vc << " | "
         << (r.valid_c ? "yes" : "no") << " | " << r.t_compatible << " | ";
    else if(r.method != "naive Tutte")
      md << r.t_b << " | " << r.t_a << " | - | " << r.t_location << " | - | - | - | "; // Orbifold Tutte: no overlay
    else md << "- | - | - | - | - | - | - | "; // the naive maps: total only, no overlay
    md << r.t_total << " | " << std::setprecision(4) << r.peak_mb << std::setprecision(3) << " | " << r.distortion << " | ";
    if(r.method == "cross") md << "- | - |\n";
    else md << r.unlocated << " | " << r.bad_faces << " |\n";
  }
  std::string command = "cross_benchmark";
  for(int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
  md << "\nMachine: " << host << ". Command: `" << command << "`.\n";
  return 0;
}
