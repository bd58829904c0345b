// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Fuzz target of cross_parameterization(): two small disks, or two small closed genus-0 meshes (each a
// disk closed by a cone over its border), with 3D points in general position, or anywhere the input
// says (repeated, collinear, non-finite, extreme), possibly scaled and translated; 0 to 4 landmark
// pairs of any vertices (repeated, on a border, inside), optionally a border vertex pair, B's matched
// map and the composed step on or off, the compatible meshes asked or not. B's vertices are always
// located on A too.
//
// Whatever it returns, it must not crash or loop. OK requires every vertex of A located in a face of
// B (and every vertex of B in a face of A) with finite barycentric coordinates in [0, 1] summing to 1,
// each landmark bit-exactly on its partner, both maps certified, every 3D point finite, and the compatible
// meshes, when asked, of one connectivity and certified; an error requires that nothing was written. Two disks in general
// position (every 3D face of non-zero area, exactly), at least four border vertices each, distinct
// interior landmarks and no border pair must be mapped: OK, or the time budget (an edge of B that every
// placement of the square's corners leaves flat is split on a copy of B, not refused).
// Compiled with -DPE_FUZZ_CROSS_VERBOSE, it prints each input's decoded shape and result (to study a corpus).

#ifndef PE_FUZZ_CROSS_PARAMETERIZATION_H
#define PE_FUZZ_CROSS_PARAMETERIZATION_H

#include "fuzz_util.h"

#include <CGAL/Progressive_embedding/cross_parameterization.h>

#include <boost/property_map/property_map.hpp>

#include <set>

namespace pe_fuzz {

// A small mesh of the target: a disk, or the disk closed by a cone (one more vertex, the apex, joined to
// every border edge), with 3D points
struct Small_surface
{
  Small_disk disk;
  bool closed = false;
  std::size_t nv = 0;           // the disk's vertices, and the apex when closed
  std::vector<Tri> faces;
  std::vector<double> xyz;      // 3 per vertex
};

inline Small_surface small_surface(Bytes& b, bool closed)
{
  Small_surface s;
  s.disk = small_disk(b);
  s.closed = closed;
  s.faces = s.disk.faces;
  s.nv = s.disk.nv;
  if(closed)
  {
    const std::size_t apex = s.nv++;
    const std::size_t nb = s.disk.border.size();
    for(std::size_t k = 0; k < nb; ++k) s.faces.push_back(Tri{{ s.disk.border[(k + 1) % nb], s.disk.border[k], apex }});
  }
  s.xyz.assign(3 * s.nv, 0.);
  const int mode = b.u8() % 4;
  for(std::size_t i = 0; i < s.nv; ++i)
  {
    // general position: irrational-looking, pairwise distinct (the exact test below decides)
    const double t = double(i) + 1;
    s.xyz[3 * i] = std::sin(1.7 * t) + 0.1 * t;
    s.xyz[3 * i + 1] = std::cos(2.3 * t);
    s.xyz[3 * i + 2] = std::sin(0.37 * t + 1);
  }
  if(mode == 1) for(double& x : s.xyz) x = coordinate(b);                 // anything, everywhere
  if(mode == 2)                                                            // a few coordinates anything
  {
    const int changes = 1 + b.u8() % 3;
    for(int c = 0; c < changes; ++c)
    {
      const std::size_t at = b.u8() % s.xyz.size(); // read before the value (an assignment reads its right side first)
      s.xyz[at] = coordinate(b);
    }
  }
  transform(b, s.xyz);
  return s;
}

inline void build_surface(const Small_surface& s, Mesh& m)
{
  std::vector<vertex_descriptor> V;
  for(std::size_t i = 0; i < s.nv; ++i) V.push_back(m.add_vertex(Point_3(s.xyz[3 * i], s.xyz[3 * i + 1], s.xyz[3 * i + 2])));
  for(const Tri& t : s.faces)
    PE_FUZZ_CHECK(m.add_face(V[t[0]], V[t[1]], V[t[2]]) != Mesh::null_face(), "the fuzz decoder built a face that does not fit");
}

// every point finite, every coordinate 0 or within a factor 1e100 of the largest, and every 3D face of non-zero
// area (exact predicate). Any size: the pipeline brings the points near unit size by a power of two; only the
// spread within one mesh is bounded, so that the differences of its points stay normal doubles once normalized.
inline bool general_position(const Mesh& m)
{
  double largest = 0;
  for(vertex_descriptor v : vertices(m))
  {
    const Point_3& p = m.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) return false;
    for(int c = 0; c < 3; ++c) largest = (std::max)(largest, std::abs(p[c]));
  }
  for(vertex_descriptor v : vertices(m))
    for(int c = 0; c < 3; ++c)
    {
      const double x = std::abs(m.point(v)[c]);
      if(x != 0 && x < largest * 1e-100) return false;
    }
  for(face_descriptor f : faces(m))
  {
    const auto h = halfedge(f, m);
    if(CGAL::collinear(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m)))) return false;
  }
  return true;
}

// a location: a face of `m` with finite weights in [0, 1] summing to 1 (up to rounding)
inline bool plausible(const PE::Cross_location<Mesh>& l, const Mesh& m)
{
  if(std::size_t(l.first) >= m.number_of_faces()) return false;
  double sum = 0;
  for(double w : l.second)
  {
    if(!std::isfinite(w) || w < 0 || w > 1) return false;
    sum += w;
  }
  return std::abs(sum - 1) <= 1e-12;
}

// the weight of `l` at the vertex `v` (0 if `v` is not a corner of its face)
inline double weight_at(const PE::Cross_location<Mesh>& l, const Mesh& m, vertex_descriptor v)
{
  const auto h = halfedge(l.first, m);
  const vertex_descriptor corner[3] = { source(h, m), target(h, m), target(next(h, m), m) };
  double w = 0;
  for(int k = 0; k < 3; ++k) if(corner[k] == v) w += l.second[k];
  return w;
}

PE_FUZZ_TARGET_FUNCTION(cross_parameterization)
{
  Bytes b(data, size);
  const int flags = b.u8();
  const bool closed = (flags & 3) == 3;          // a quarter of the inputs: two closed meshes
  const bool matched = flags & 4, composed = flags & 8, compatible = flags & 16, pair_given = flags & 32;
  const bool mixed = !closed && (flags & 192) == 192; // one closed mesh against a disk (refused)
  const Small_surface sa = small_surface(b, closed || mixed);
  const Small_surface sb = small_surface(b, closed);
  Mesh a, bm;
  build_surface(sa, a);
  build_surface(sb, bm);
  typedef std::pair<vertex_descriptor, vertex_descriptor> Landmark;
  std::vector<Landmark> landmarks;
  const int count = b.u8() % 5;
  for(int k = 0; k < count; ++k)
  {
    const std::size_t ia = b.u8() % sa.nv, ib = b.u8() % sb.nv;
    landmarks.emplace_back(vertex_descriptor(Mesh::size_type(ia)), vertex_descriptor(Mesh::size_type(ib)));
  }
  const Landmark pair(vertex_descriptor(Mesh::size_type(b.u8() % sa.nv)), vertex_descriptor(Mesh::size_type(b.u8() % sb.nv)));

  // what has been written is recognizable: every location starts at an impossible face
  const PE::Cross_location<Mesh> unwritten(Mesh::null_face(), {{ -1., -1., -1. }});
  std::vector<PE::Cross_location<Mesh> > on_b(a.number_of_vertices(), unwritten), on_a(bm.number_of_vertices(), unwritten);
  auto out = boost::make_iterator_property_map(on_b.begin(), get(CGAL::vertex_index, a));
  auto out_back = boost::make_iterator_property_map(on_a.begin(), get(CGAL::vertex_index, bm));
  Mesh compatible_a, compatible_b;
  PE::Cross_parameterization_statistics st;
  // Small budgets: the meshes have at most 17 vertices; the time budget only bounds what the counts do
  // not, and libFuzzer's timeout catches a loop that ignores both.
  const auto np = PE::parameters::b_to_a_locations(out_back,
    PE::parameters::compatible_meshes(compatible ? std::make_pair(&compatible_a, &compatible_b) : std::pair<Mesh*, Mesh*>(nullptr, nullptr),
      PE::parameters::matched_maps(matched, PE::parameters::composed_distortion(composed,
        PE::parameters::statistics(&st, PE::parameters::optimization_time_limit(0.05, CGAL::parameters::maximum_running_time(0.5)))))));
  PE::Error_code ec;
  {
    const Silence quiet;
    ec = pair_given ? PE::cross_parameterization(a, bm, landmarks, out, PE::parameters::border_vertex_pair(pair, np))
                    : PE::cross_parameterization(a, bm, landmarks, out, np);
  }

#ifdef PE_FUZZ_CROSS_VERBOSE
  std::cerr << "closed " << closed << " mixed " << mixed << " pair " << pair_given << " landmarks " << landmarks.size()
            << " A " << sa.nv << "/" << sa.disk.border.size() << " B " << sb.nv << "/" << sb.disk.border.size()
            << ": " << PE::get_error_name(ec) << " (mesh " << st.failed_mesh << ")" << std::endl;
#endif
  if(ec != PE::OK)
  {
    for(const auto& l : on_b) PE_FUZZ_CHECK(l.first == Mesh::null_face(), "a location written on " << PE::get_error_name(ec));
    for(const auto& l : on_a) PE_FUZZ_CHECK(l.first == Mesh::null_face(), "a location of B written on " << PE::get_error_name(ec));
    PE_FUZZ_CHECK(compatible_a.number_of_vertices() == 0 && compatible_b.number_of_vertices() == 0,
                  "compatible meshes written on " << PE::get_error_name(ec));
    // the inputs that must be mapped
    std::set<std::size_t> seen_a, seen_b;
    bool interior = true;
    for(const Landmark& l : landmarks)
    {
      interior = interior && !is_border(l.first, a) && !is_border(l.second, bm);
      seen_a.insert(std::size_t(l.first));
      seen_b.insert(std::size_t(l.second));
    }
    const bool distinct = seen_a.size() == landmarks.size() && seen_b.size() == landmarks.size();
    const bool must_map = !closed && !mixed && !pair_given && interior && distinct && sa.disk.border.size() >= 4
                          && sb.disk.border.size() >= 4 && general_position(a) && general_position(bm);
    PE_FUZZ_CHECK(!must_map || ec == PE::ERROR_BUDGET_EXHAUSTED,
                  "two disks in general position with distinct interior landmarks refused: " << PE::get_error_name(ec)
                  << " (failed mesh " << st.failed_mesh << ")");
    return 0;
  }
  PE_FUZZ_CHECK(!mixed, "OK for a closed mesh against a disk");
  for(double x : sa.xyz) PE_FUZZ_CHECK(std::isfinite(x), "OK with a non-finite 3D point in A");
  for(double x : sb.xyz) PE_FUZZ_CHECK(std::isfinite(x), "OK with a non-finite 3D point in B");
  PE_FUZZ_CHECK(st.report_a.is_valid() && st.report_b.is_valid() && st.landmarks_exact, "OK with a map whose certificate fails");
  for(vertex_descriptor v : vertices(a))
    PE_FUZZ_CHECK(plausible(on_b[std::size_t(v)], bm), "vertex " << std::size_t(v) << " of A: no location on B");
  for(vertex_descriptor v : vertices(bm))
    PE_FUZZ_CHECK(plausible(on_a[std::size_t(v)], a), "vertex " << std::size_t(v) << " of B: no location on A");
  for(const Landmark& l : landmarks)
  {
    PE_FUZZ_CHECK(weight_at(on_b[std::size_t(l.first)], bm, l.second) == 1.,
                  "landmark " << std::size_t(l.first) << " of A not exactly on its partner " << std::size_t(l.second));
    PE_FUZZ_CHECK(weight_at(on_a[std::size_t(l.second)], a, l.first) == 1.,
                  "landmark " << std::size_t(l.second) << " of B not exactly on its partner " << std::size_t(l.first));
  }
  if(compatible)
  {
    PE_FUZZ_CHECK(compatible_a.number_of_vertices() == compatible_b.number_of_vertices()
                  && compatible_a.number_of_faces() == compatible_b.number_of_faces() && compatible_a.number_of_faces() > 0,
                  "compatible meshes of different sizes: " << compatible_a.number_of_faces() << " and "
                  << compatible_b.number_of_faces() << " faces");
    for(face_descriptor f : faces(compatible_a))
    {
      const auto ha = halfedge(f, compatible_a), hb = halfedge(f, compatible_b);
      PE_FUZZ_CHECK(std::size_t(source(ha, compatible_a)) == std::size_t(source(hb, compatible_b))
                    && std::size_t(target(ha, compatible_a)) == std::size_t(target(hb, compatible_b)),
                    "compatible meshes of different connectivity at face " << std::size_t(f));
    }
    if(!closed) PE_FUZZ_CHECK(st.report_compatible.is_valid(), "compatible meshes whose certificate fails");
  }
  else PE_FUZZ_CHECK(compatible_a.number_of_vertices() == 0, "compatible meshes written without being asked");
  return 0;
}

} // namespace pe_fuzz

#endif // PE_FUZZ_CROSS_PARAMETERIZATION_H
