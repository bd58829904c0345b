// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Fuzz targets of the mesh readers: read_polygon_mesh() in each of its four formats and
// read_OBJ_with_uv(). Any input must give either a failure with a message and an empty mesh, or
// a valid triangle mesh with finite points whose counts agree with the result; nothing may throw,
// crash, leak or allocate beyond what the input holds (libFuzzer's malloc limit). An OBJ with uv
// read successfully is also written and read back, and must come back bit-exactly.

#ifndef PE_FUZZ_READERS_H
#define PE_FUZZ_READERS_H

#include "fuzz_util.h"

#include <CGAL/Progressive_embedding/IO/OBJ_with_uv.h>
#include <CGAL/Progressive_embedding/IO/read_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>

namespace pe_fuzz {

inline std::size_t count_faces(const Mesh& m) { return std::size_t(std::distance(faces(m).begin(), faces(m).end())); }
inline std::size_t count_vertices(const Mesh& m) { return std::size_t(std::distance(vertices(m).begin(), vertices(m).end())); }

inline bool finite_point(const Point_3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

// what every successful read must give
inline void check_mesh_read(const Mesh& m, const PE::IO::Read_result& r, const char* format)
{
  if(!r)
  {
    PE_FUZZ_CHECK(count_vertices(m) == 0 && count_faces(m) == 0, format << ": the mesh is not empty after a failure");
    PE_FUZZ_CHECK(!r.message.empty(), format << ": a failure without a message (" << PE::get_error_name(r.status) << ")");
    return;
  }
  PE_FUZZ_CHECK(CGAL::is_valid_polygon_mesh(m) && CGAL::is_triangle_mesh(m), format << ": success with an invalid mesh");
  PE_FUZZ_CHECK(count_faces(m) == r.number_of_faces && count_faces(m) > 0,
                format << ": " << count_faces(m) << " faces, the result says " << r.number_of_faces);
  for(vertex_descriptor v : vertices(m))
  {
    PE_FUZZ_CHECK(finite_point(m.point(v)), format << ": a non-finite point read");
    PE_FUZZ_CHECK(!m.is_isolated(v), format << ": a vertex in no face");
  }
}

inline int read_mesh(const std::uint8_t* data, std::size_t size, const char* format)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  Mesh m;
  const PE::IO::Read_result r = PE::IO::read_polygon_mesh(in, format, m);
  check_mesh_read(m, r, format);
  if(r)
    PE_FUZZ_CHECK(count_vertices(m) + r.number_of_unreferenced_vertices == r.number_of_positions,
                  format << ": " << count_vertices(m) << " vertices + " << r.number_of_unreferenced_vertices
                  << " unreferenced != " << r.number_of_positions << " positions");
  return 0;
}

PE_FUZZ_TARGET_FUNCTION(read_off) { return read_mesh(data, size, "off"); }
PE_FUZZ_TARGET_FUNCTION(read_obj) { return read_mesh(data, size, "obj"); }
PE_FUZZ_TARGET_FUNCTION(read_ply) { return read_mesh(data, size, "ply"); }
PE_FUZZ_TARGET_FUNCTION(read_stl) { return read_mesh(data, size, "stl"); }

PE_FUZZ_TARGET_FUNCTION(read_obj_uv)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  Mesh m;
  Uv_map uv = m.add_property_map<vertex_descriptor, Point_2>("v:uv", Point_2(0, 0)).first;
  std::vector<std::size_t> vt_to_v;
  std::vector<Point_3> positions;
  const PE::IO::Read_result r = PE::IO::read_OBJ_with_uv(in, m, uv, &vt_to_v, &positions);
  check_mesh_read(m, r, "obj with uv");
  if(!r) return 0;
  PE_FUZZ_CHECK(count_vertices(m) + r.number_of_unreferenced_vertices == r.number_of_texture_coordinates,
                "obj with uv: " << count_vertices(m) << " vertices + " << r.number_of_unreferenced_vertices
                << " unreferenced != " << r.number_of_texture_coordinates << " vt");
  PE_FUZZ_CHECK(vt_to_v.size() == count_vertices(m) && positions.size() == r.number_of_positions,
                "obj with uv: vt_to_v or positions of the wrong size");
  for(vertex_descriptor v : vertices(m))
    PE_FUZZ_CHECK(std::isfinite(uv[v].x()) && std::isfinite(uv[v].y()), "obj with uv: a non-finite uv read");

  // written back with its seams and v list, it reads back to the same mesh, bit-exactly
  std::ostringstream out;
  const PE::Error_code wec = PE::IO::write_OBJ_with_uv(out, m, uv, &vt_to_v, &positions);
  PE_FUZZ_CHECK(wec == PE::OK, "obj with uv: writing what was read fails: " << PE::get_error_name(wec));
  std::istringstream in2(out.str());
  Mesh m2;
  Uv_map uv2 = m2.add_property_map<vertex_descriptor, Point_2>("v:uv", Point_2(0, 0)).first;
  std::vector<std::size_t> vt_to_v2;
  std::vector<Point_3> positions2;
  const PE::IO::Read_result r2 = PE::IO::read_OBJ_with_uv(in2, m2, uv2, &vt_to_v2, &positions2);
  PE_FUZZ_CHECK(r2, "obj with uv: what was written does not read back: " << r2.message << "\n" << out.str());
  PE_FUZZ_CHECK(count_vertices(m2) == count_vertices(m) && count_faces(m2) == count_faces(m) && vt_to_v2 == vt_to_v
                && positions2.size() == positions.size(), "obj with uv: the round trip changes the mesh");
  const auto bits = [](double x) { std::uint64_t b; std::memcpy(&b, &x, sizeof b); return b; };
  for(std::size_t i = 0; i < positions.size(); ++i)
    PE_FUZZ_CHECK(bits(positions[i].x()) == bits(positions2[i].x()) && bits(positions[i].y()) == bits(positions2[i].y())
                  && bits(positions[i].z()) == bits(positions2[i].z()), "obj with uv: a position changes in the round trip");
  auto v1 = vertices(m).begin();
  for(vertex_descriptor v : vertices(m2))
  {
    PE_FUZZ_CHECK(bits(uv[*v1].x()) == bits(uv2[v].x()) && bits(uv[*v1].y()) == bits(uv2[v].y()),
                  "obj with uv: a uv changes in the round trip");
    PE_FUZZ_CHECK(m.point(*v1) == m2.point(v), "obj with uv: a point changes in the round trip");
    ++v1;
  }
  return 0;
}

} // namespace pe_fuzz

#endif // PE_FUZZ_READERS_H
