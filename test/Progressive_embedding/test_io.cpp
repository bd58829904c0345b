// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

// Tests of the I/O layer: IO/OBJ_with_uv.h, IO/read_polygon_mesh.h (validating OFF/OBJ/PLY/STL
// readers with bounded memory), the writers' no-partial-file guarantee, and IO/SVG.h.
// Usage: test_io DATA_DIR   (DATA_DIR contains libcgal-demo's meshes/; required: without it the test fails)

#include <CGAL/Progressive_embedding/IO/OBJ_with_uv.h>
#include <CGAL/Progressive_embedding/IO/SVG.h>
#include <CGAL/Progressive_embedding/IO/read_polygon_mesh.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/parameters.h> // its namespaces must not shadow CGAL's in the IO headers

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Unique_hash_map.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/property_map/property_map.hpp>

#include <CGAL/boost/graph/Euler_operations.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace PE = CGAL::Progressive_embedding;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2                                          Point_2;
typedef K::Point_3                                          Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Mesh;
typedef Mesh::Vertex_index                                  vertex_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Point_2>      UV_map;
typedef CGAL::Polyhedron_3<K>                               Polyhedron;

#define CHECK(cond, msg)                                                                   \
  do {                                                                                     \
    if(!(cond)) {                                                                          \
      std::cerr << "FAILED " << __FILE__ << ":" << __LINE__ << ": " << #cond << " -- " << msg << std::endl; \
      return EXIT_FAILURE;                                                                 \
    }                                                                                      \
  } while(0)

#define RUN(f) do { if(f != EXIT_SUCCESS) return EXIT_FAILURE; } while(0)

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

std::string describe(const PE::IO::OBJ_read_result& r)
{
  return std::string(PE::get_error_name(r.status)) + " line " + std::to_string(r.line) + ": " + r.message;
}

// ---------------------------------------------------------------------------
// A cylinder cut along a seam: R rows x C columns of `v`, the last column of `vt`
// duplicates the first column of `v`. One unused `vt` is inserted after the first few.

struct Seam_grid
{
  static const int R = 4, C = 4;
  std::string text;
  std::size_t nv = R * C, nvt_file = R * (C + 1) + 1, nvt_used = R * (C + 1), nf = 2 * (R - 1) * C;
  std::vector<std::size_t> expected_vt_to_v;     // per mesh vertex
  std::vector<std::array<double, 2> > expected_uv; // per mesh vertex
};

Seam_grid make_seam_grid()
{
  Seam_grid g;
  const int R = Seam_grid::R, C = Seam_grid::C;
  std::ostringstream s;
  s.precision(17);
  s << "# seam grid\nmtllib none.mtl\no grid\n\n";
  for(int r = 0; r < R; ++r)
    for(int c = 0; c < C; ++c)
      s << "v " << std::cos(2 * M_PI * c / C) << ' ' << std::sin(2 * M_PI * c / C) << ' ' << r / 3.0 << '\n';
  s << "vn 0 0 1\n";
  const int unused_at = 7; // file vt index (0-based) of the unused vt
  int written = 0;
  for(int r = 0; r < R; ++r)
    for(int c = 0; c <= C; ++c)
    {
      if(written == unused_at) { s << "vt 0.123 0.456   # unused\n"; ++written; }
      const double u = c / double(C) + (r * 0.1) / 7.0, v = r / 3.0 + 1e-300 * c;
      s << "vt " << u << ' ' << v << '\n';
      g.expected_uv.push_back({u, v});
      g.expected_vt_to_v.push_back(std::size_t(r * C + (c % C)));
      ++written;
    }
  s << "g faces\ns 1\nusemtl m\n";
  auto vt_index = [&](int r, int c) { int k = r * (C + 1) + c; return k + (k >= unused_at ? 2 : 1); };
  auto v_index = [&](int r, int c) { return r * C + (c % C) + 1; };
  int face = 0;
  for(int r = 0; r + 1 < R; ++r)
    for(int c = 0; c < C; ++c)
    {
      const int a = v_index(r, c), b = v_index(r, c + 1), cc = v_index(r + 1, c + 1), d = v_index(r + 1, c);
      const int ta = vt_index(r, c), tb = vt_index(r, c + 1), tc = vt_index(r + 1, c + 1), td = vt_index(r + 1, c);
      if(face % 3 == 0)      // plain
        s << "f " << a << '/' << ta << ' ' << b << '/' << tb << ' ' << cc << '/' << tc << '\n';
      else if(face % 3 == 1) // with a normal
        s << "f " << a << '/' << ta << "/1 " << b << '/' << tb << "/1 " << cc << '/' << tc << "/1\n";
      else                   // relative indices
        s << "f " << a - int(g.nv) - 1 << '/' << ta - int(g.nvt_file) - 1 << ' ' << b << '/' << tb << ' '
          << cc << '/' << tc << "  # relative\n";
      s << "f " << a << '/' << ta << ' ' << cc << '/' << tc << ' ' << d << '/' << td << '\n';
      ++face;
    }
  g.text = s.str();
  return g;
}

template <class TM, class UVM>
std::vector<std::array<std::size_t, 3> > face_list(const TM& tm, UVM)
{
  std::map<typename boost::graph_traits<TM>::vertex_descriptor, std::size_t> id;
  std::size_t i = 0;
  for(auto v : vertices(tm)) id[v] = i++;
  std::vector<std::array<std::size_t, 3> > F;
  for(auto f : faces(tm))
  {
    std::array<std::size_t, 3> t; int k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) t[k++ % 3] = id[target(h, tm)];
    F.push_back(t);
  }
  return F;
}

// ---------------------------------------------------------------------------

int test_round_trip_surface_mesh(const Seam_grid& g)
{
  Mesh m;
  UV_map uvm = m.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
  std::vector<std::size_t> vt_to_v;
  std::vector<Point_3> positions;
  std::istringstream in(g.text);
  PE::IO::OBJ_read_result r = PE::IO::read_OBJ_with_uv(in, m, uvm, &vt_to_v, &positions);
  CHECK(r.status == PE::OK, describe(r));
  CHECK(r.number_of_positions == g.nv && r.number_of_texture_coordinates == g.nvt_file && r.number_of_faces == g.nf, "counts");
  CHECK(num_vertices(m) == g.nvt_used && num_faces(m) == g.nf, num_vertices(m) << " " << num_faces(m));
  CHECK(positions.size() == g.nv, "positions");
  CHECK(vt_to_v == g.expected_vt_to_v, "vt_to_v");
  CHECK(CGAL::is_valid_polygon_mesh(m) && CGAL::is_triangle_mesh(m), "valid");
  {
    std::size_t i = 0, nb = 0;
    for(vertex_descriptor v : vertices(m))
    {
      CHECK(same_bits(uvm[v].x(), g.expected_uv[i][0]) && same_bits(uvm[v].y(), g.expected_uv[i][1]), "uv " << i);
      CHECK(m.point(v) == positions[vt_to_v[i]], "point " << i);
      if(CGAL::is_border(v, m)) ++nb;
      ++i;
    }
    // a cut cylinder is a disk: one border cycle, Euler characteristic 1
    CHECK(num_vertices(m) - num_edges(m) + num_faces(m) == 1, "disk");
    CHECK(nb == num_vertices(m) - (Seam_grid::R - 2) * (Seam_grid::C - 1), "border size " << nb);
  }
  const auto F0 = face_list(m, uvm);

  // (a) write back with the original v list and the seams
  std::ostringstream out;
  CHECK(PE::IO::write_OBJ_with_uv(out, m, uvm, &vt_to_v, &positions) == PE::OK, "write");
  {
    Mesh m2;
    UV_map uvm2 = m2.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
    std::vector<std::size_t> vt_to_v2;
    std::vector<Point_3> positions2;
    std::istringstream in2(out.str());
    PE::IO::OBJ_read_result r2 = PE::IO::read_OBJ_with_uv(in2, m2, uvm2, &vt_to_v2, &positions2);
    CHECK(r2.status == PE::OK, describe(r2));
    CHECK(r2.number_of_positions == g.nv && r2.number_of_texture_coordinates == g.nvt_used, "counts after write");
    CHECK(vt_to_v2 == vt_to_v && face_list(m2, uvm2) == F0, "topology after write");
    CHECK(positions2.size() == positions.size(), "positions");
    for(std::size_t i = 0; i < positions.size(); ++i)
      CHECK(same_bits(positions[i].x(), positions2[i].x()) && same_bits(positions[i].z(), positions2[i].z()), "position bits");
    auto it = vertices(m).begin();
    for(vertex_descriptor v : vertices(m2))
    {
      CHECK(same_bits(uvm2[v].x(), uvm[*it].x()) && same_bits(uvm2[v].y(), uvm[*it].y()), "uv bits");
      ++it;
    }
    // writing again gives the same text
    std::ostringstream out2;
    CHECK(PE::IO::write_OBJ_with_uv(out2, m2, uvm2, &vt_to_v2, &positions2) == PE::OK, "write 2");
    CHECK(out2.str() == out.str(), "second write differs");
  }
  // named parameters
  {
    std::ostringstream o1, o2;
    CHECK(PE::IO::write_OBJ_with_uv(o1, m, uvm, &vt_to_v, &positions, CGAL::parameters::stream_precision(17)) == PE::OK, "np");
    CHECK(o1.str() == out.str(), "stream_precision(17) is the default");
    CHECK(PE::IO::write_OBJ_with_uv(o2, m, uvm, nullptr, nullptr,
                                    CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, m))) == PE::OK, "vpm");
    std::ostringstream s1, s2;
    CHECK(PE::IO::write_SVG(s1, m, uvm, "t") == PE::OK, "svg");
    CHECK(PE::IO::write_SVG(s2, m, uvm, "t", CGAL::parameters::geom_traits(PE::Progressive_embedding_traits_2<K>()))
            == PE::OK, "svg geom_traits");
    CHECK(s1.str() == s2.str(), "geom_traits");
    Mesh m3;
    UV_map uvm3 = m3.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
    auto vpm3 = m3.add_property_map<vertex_descriptor, Point_3>("v:other").first;
    std::istringstream i3(g.text);
    CHECK(PE::IO::read_OBJ_with_uv(i3, m3, uvm3, nullptr, nullptr, CGAL::parameters::vertex_point_map(vpm3)).status
            == PE::OK, "read with vertex_point_map");
    auto it3 = vertices(m).begin();
    for(vertex_descriptor v : vertices(m3)) { CHECK(vpm3[v] == m.point(*it3), "vertex_point_map"); ++it3; }
  }
  // vt_to_v without positions: the used v, compacted (here all of them)
  {
    std::ostringstream out3;
    CHECK(PE::IO::write_OBJ_with_uv(out3, m, uvm, &vt_to_v) == PE::OK, "write 3");
    CHECK(out3.str() == out.str(), "v list rebuilt from the mesh differs");
  }
  // (b) plain: one v per vertex
  {
    std::ostringstream out4;
    CHECK(PE::IO::write_OBJ_with_uv(out4, m, uvm) == PE::OK, "write plain");
    Mesh m4;
    UV_map uvm4 = m4.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
    std::vector<std::size_t> vt_to_v4;
    std::istringstream in4(out4.str());
    PE::IO::OBJ_read_result r4 = PE::IO::read_OBJ_with_uv(in4, m4, uvm4, &vt_to_v4);
    CHECK(r4.status == PE::OK, describe(r4));
    CHECK(r4.number_of_positions == g.nvt_used && r4.number_of_texture_coordinates == g.nvt_used, "plain counts");
    for(std::size_t i = 0; i < vt_to_v4.size(); ++i) CHECK(vt_to_v4[i] == i, "plain vt_to_v");
    CHECK(face_list(m4, uvm4) == F0, "plain faces");
  }
  // wrong parameters
  {
    std::ostringstream o;
    std::vector<std::size_t> bad(vt_to_v.begin(), vt_to_v.end() - 1);
    CHECK(PE::IO::write_OBJ_with_uv(o, m, uvm, &bad) == PE::ERROR_WRONG_PARAMETER, "short vt_to_v");
    CHECK(PE::IO::write_OBJ_with_uv(o, m, uvm, nullptr, &positions) == PE::ERROR_WRONG_PARAMETER, "positions alone");
    std::vector<Point_3> few(positions.begin(), positions.begin() + 3);
    CHECK(PE::IO::write_OBJ_with_uv(o, m, uvm, &vt_to_v, &few) == PE::ERROR_WRONG_PARAMETER, "index past positions");
    CHECK(o.str().empty(), "nothing written on error");
    Mesh mc = m;
    UV_map uvc = mc.property_map<vertex_descriptor, Point_2>("h:uv").first;
    uvc[*vertices(mc).begin()] = Point_2(std::nan(""), 0);
    CHECK(PE::IO::write_OBJ_with_uv(o, mc, uvc) == PE::ERROR_NON_FINITE_COORDINATES, "nan uv");
  }
  // file overloads
  {
    const std::filesystem::path dir = std::filesystem::temp_directory_path();
    const std::string fname = (dir / ("pe_test_io_" + std::to_string(std::random_device()()) + ".obj")).string();
    CHECK(PE::IO::write_OBJ_with_uv(fname, m, uvm, &vt_to_v, &positions) == PE::OK, "write file");
    Mesh m5;
    UV_map uvm5 = m5.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
    PE::IO::OBJ_read_result r5 = PE::IO::read_OBJ_with_uv(fname, m5, uvm5);
    CHECK(r5.status == PE::OK && num_vertices(m5) == g.nvt_used, describe(r5));
    std::remove(fname.c_str());
    r5 = PE::IO::read_OBJ_with_uv(fname, m5, uvm5);
    CHECK(r5.status == PE::ERROR_CANNOT_READ_FILE && num_vertices(m5) == 0, describe(r5));
    CHECK(PE::IO::write_OBJ_with_uv((dir / "no_such_dir_pe" / "x.obj").string(), m, uvm) == PE::ERROR_CANNOT_WRITE_FILE,
          "write to a missing directory");
  }
  std::cout << "round trip Surface_mesh<Epick>: OK (" << num_vertices(m) << " vertices, " << num_faces(m) << " faces)" << std::endl;
  return EXIT_SUCCESS;
}

int test_round_trip_polyhedron(const Seam_grid& g)
{
  typedef boost::graph_traits<Polyhedron>::vertex_descriptor pvd;
  typedef CGAL::Unique_hash_map<pvd, Point_2> UV_hmap;
  typedef boost::associative_property_map<UV_hmap> UV_pmap;
  Polyhedron P;
  UV_hmap uvh;
  UV_pmap uvm(uvh);
  std::vector<std::size_t> vt_to_v;
  std::vector<Point_3> positions;
  std::istringstream in(g.text);
  PE::IO::OBJ_read_result r = PE::IO::read_OBJ_with_uv(in, P, uvm, &vt_to_v, &positions);
  CHECK(r.status == PE::OK, describe(r));
  CHECK(num_vertices(P) == g.nvt_used && num_faces(P) == g.nf && P.is_valid(), "polyhedron counts");
  CHECK(vt_to_v == g.expected_vt_to_v, "polyhedron vt_to_v");
  std::size_t i = 0;
  for(pvd v : vertices(P))
  {
    CHECK(same_bits(get(uvm, v).x(), g.expected_uv[i][0]) && same_bits(get(uvm, v).y(), g.expected_uv[i][1]), "uv");
    ++i;
  }
  std::ostringstream out;
  CHECK(PE::IO::write_OBJ_with_uv(out, P, uvm, &vt_to_v, &positions) == PE::OK, "write");
  // same text as with Surface_mesh
  Mesh m;
  UV_map uvs = m.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
  std::vector<std::size_t> vt_to_v_sm;
  std::vector<Point_3> positions_sm;
  std::istringstream in2(g.text);
  CHECK(PE::IO::read_OBJ_with_uv(in2, m, uvs, &vt_to_v_sm, &positions_sm).status == PE::OK, "sm");
  std::ostringstream out2;
  CHECK(PE::IO::write_OBJ_with_uv(out2, m, uvs, &vt_to_v_sm, &positions_sm) == PE::OK, "sm write");
  CHECK(out.str() == out2.str(), "Polyhedron and Surface_mesh write different files");
  // re-reading into a non-empty polyhedron replaces its content
  std::istringstream in3(out.str());
  r = PE::IO::read_OBJ_with_uv(in3, P, uvm);
  CHECK(r.status == PE::OK && num_vertices(P) == g.nvt_used, describe(r));
  // SVG
  std::ostringstream svg;
  CHECK(PE::IO::write_SVG(svg, P, uvm, "polyhedron") == PE::OK, "svg");
  CHECK(svg.str().find("flipped: 0<") != std::string::npos, "svg counts");
  std::cout << "round trip Polyhedron_3<Epick> (Unique_hash_map uv): OK" << std::endl;
  return EXIT_SUCCESS;
}

int test_exact_uv(const Seam_grid& g)
{
  {
    typedef CGAL::Simple_cartesian<CGAL::Gmpq>::Point_2 QPoint_2;
    Mesh m;
    auto uvm = m.add_property_map<vertex_descriptor, QPoint_2>("h:uvq").first;
    std::vector<std::size_t> vt_to_v;
    std::vector<Point_3> positions;
    std::istringstream in(g.text);
    PE::IO::OBJ_read_result r = PE::IO::read_OBJ_with_uv(in, m, uvm, &vt_to_v, &positions);
    CHECK(r.status == PE::OK, describe(r));
    std::size_t i = 0;
    for(vertex_descriptor v : vertices(m))
    {
      CHECK(uvm[v].x() == CGAL::Gmpq(g.expected_uv[i][0]) && uvm[v].y() == CGAL::Gmpq(g.expected_uv[i][1]), "gmpq uv");
      ++i;
    }
    std::ostringstream out;
    CHECK(PE::IO::write_OBJ_with_uv(out, m, uvm, &vt_to_v, &positions) == PE::OK, "gmpq write");
    Mesh m2;
    UV_map uvd = m2.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
    std::istringstream in2(out.str());
    CHECK(PE::IO::read_OBJ_with_uv(in2, m2, uvd).status == PE::OK, "gmpq reread");
    i = 0;
    for(vertex_descriptor v : vertices(m2))
    {
      CHECK(same_bits(uvd[v].x(), g.expected_uv[i][0]) && same_bits(uvd[v].y(), g.expected_uv[i][1]), "gmpq bits");
      ++i;
    }
    std::ostringstream svg;
    CHECK(PE::IO::write_SVG(svg, m, uvm) == PE::OK, "gmpq svg");
    {
      // distortion colors in an exact number type: the legend is the report's
      const PE::Embedding_report rep = PE::check_embedding(m, uvm);
      PE::IO::SVG_options so;
      so.color_by_distortion = true;
      so.inset = true;
      std::ostringstream svg2;
      CHECK(rep.status == PE::OK && PE::IO::write_SVG(svg2, m, uvm, so) == PE::OK, "gmpq svg with distortion");
      CHECK(svg2.str().find(">mean " + PE::IO::format_number(rep.mean_energy_3d) + "</text>") != std::string::npos
            && svg2.str().find(">flipped: " + std::to_string(rep.flipped) + "</text>") != std::string::npos, "gmpq legend");
    }
  }
  {
    typedef CGAL::Simple_cartesian<CGAL::Gmpfr>::Point_2 FPoint_2;
    const auto old = CGAL::Gmpfr::get_default_precision();
    CGAL::Gmpfr::set_default_precision(80);
    Mesh m;
    auto uvm = m.add_property_map<vertex_descriptor, FPoint_2>("h:uvf").first;
    std::istringstream in(g.text);
    PE::IO::OBJ_read_result r = PE::IO::read_OBJ_with_uv(in, m, uvm);
    CHECK(r.status == PE::OK, describe(r));
    std::size_t i = 0;
    for(vertex_descriptor v : vertices(m))
    {
      CHECK(uvm[v].x().get_precision() == 80 && uvm[v].x() == CGAL::Gmpfr(g.expected_uv[i][0]), "gmpfr uv");
      ++i;
    }
    std::ostringstream svg;
    CHECK(PE::IO::write_SVG(svg, m, uvm) == PE::OK, "gmpfr svg");
    {
      // distortion colors in an exact number type: the legend is the report's
      const PE::Embedding_report rep = PE::check_embedding(m, uvm);
      PE::IO::SVG_options so;
      so.color_by_distortion = true;
      so.inset = true;
      std::ostringstream svg2;
      CHECK(rep.status == PE::OK && PE::IO::write_SVG(svg2, m, uvm, so) == PE::OK, "gmpfr svg with distortion");
      CHECK(svg2.str().find(">mean " + PE::IO::format_number(rep.mean_energy_3d) + "</text>") != std::string::npos
            && svg2.str().find(">flipped: " + std::to_string(rep.flipped) + "</text>") != std::string::npos, "gmpfr legend");
    }
    CGAL::Gmpfr::set_default_precision(old);
  }
  std::cout << "uv in Simple_cartesian<Gmpq> and <Gmpfr>: OK" << std::endl;
  return EXIT_SUCCESS;
}

int test_mushroom(const std::string& data_dir)
{
  Mesh m;
  const std::string fname = data_dir + "/meshes/mushroom.off";
  CHECK(CGAL::IO::read_polygon_mesh(fname, m), "cannot read " << fname);
  UV_map uvm = m.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
  for(vertex_descriptor v : vertices(m)) uvm[v] = Point_2(m.point(v).x(), m.point(v).y());
  std::ostringstream out;
  CHECK(PE::IO::write_OBJ_with_uv(out, m, uvm) == PE::OK, "write mushroom");
  Mesh m2;
  UV_map uvm2 = m2.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
  std::vector<std::size_t> vt_to_v;
  std::istringstream in(out.str());
  PE::IO::OBJ_read_result r = PE::IO::read_OBJ_with_uv(in, m2, uvm2, &vt_to_v);
  CHECK(r.status == PE::OK, describe(r));
  CHECK(num_vertices(m2) == num_vertices(m) && num_faces(m2) == num_faces(m), "mushroom counts");
  CHECK(face_list(m2, uvm2) == face_list(m, uvm), "mushroom faces");
  auto it = vertices(m).begin();
  for(vertex_descriptor v : vertices(m2))
  {
    CHECK(uvm2[v] == uvm[*it] && m2.point(v) == m.point(*it), "mushroom coordinates");
    CHECK(same_bits(uvm2[v].x(), uvm[*it].x()) && same_bits(m2.point(v).z(), m.point(*it).z()), "mushroom bits");
    ++it;
  }
  std::ostringstream svg;
  CHECK(PE::IO::write_SVG(svg, m2, uvm2, "mushroom, uv = (x, y)") == PE::OK, "mushroom svg");
  std::cout << "mushroom.off round trip: OK (" << num_vertices(m2) << " vertices, " << num_faces(m2)
            << " faces, SVG " << svg.str().size() / 1024 << " KiB)" << std::endl;
  return EXIT_SUCCESS;
}

// every call returns; failures leave the mesh empty and give a line within the file
int check_robust_read(const std::string& text, Mesh& m, UV_map uvm, std::size_t& n_ok, std::size_t& n_fail)
{
  std::vector<std::size_t> vt_to_v;
  std::vector<Point_3> positions;
  std::istringstream in(text);
  PE::IO::OBJ_read_result r;
  try { r = PE::IO::read_OBJ_with_uv(in, m, uvm, &vt_to_v, &positions); }
  catch(...) { CHECK(false, "exception escaped"); }
  std::size_t nlines = 0;
  for(char c : text) if(c == '\n') ++nlines;
  ++nlines;
  if(r.status == PE::OK)
  {
    ++n_ok;
    CHECK(num_faces(m) == r.number_of_faces && num_faces(m) > 0, "faces");
    CHECK(CGAL::is_valid_polygon_mesh(m) && CGAL::is_triangle_mesh(m), "invalid mesh accepted");
    CHECK(vt_to_v.size() == num_vertices(m), "vt_to_v size");
    for(std::size_t k : vt_to_v) CHECK(k < positions.size(), "vt_to_v range");
    for(vertex_descriptor v : vertices(m)) CHECK(std::isfinite(uvm[v].x()) && std::isfinite(uvm[v].y()), "finite");
    // and what was read can be written and read again
    std::ostringstream out;
    CHECK(PE::IO::write_OBJ_with_uv(out, m, uvm, &vt_to_v, &positions) == PE::OK, "rewrite");
    Mesh m2;
    UV_map uvm2 = m2.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
    std::istringstream in2(out.str());
    PE::IO::OBJ_read_result r2 = PE::IO::read_OBJ_with_uv(in2, m2, uvm2);
    CHECK(r2.status == PE::OK && num_faces(m2) == num_faces(m), describe(r2));
  }
  else
  {
    ++n_fail;
    CHECK(num_vertices(m) == 0 && num_faces(m) == 0, "mesh not emptied after " << describe(r));
    CHECK(vt_to_v.empty() && positions.empty(), "outputs not emptied");
    CHECK(!r.message.empty(), "no message");
    CHECK(r.line <= nlines, "line " << r.line << " past the end");
    CHECK(r.status == PE::ERROR_EMPTY_MESH || r.line > 0, "no line for " << describe(r));
    CHECK(r.status == PE::ERROR_EMPTY_MESH || r.status == PE::ERROR_MALFORMED_FILE
          || r.status == PE::ERROR_NON_TRIANGULAR_MESH || r.status == PE::ERROR_NON_MANIFOLD
          || r.status == PE::ERROR_NON_FINITE_COORDINATES, "unexpected status " << describe(r));
  }
  return EXIT_SUCCESS;
}

int test_fuzz(const Seam_grid& g)
{
  Mesh m;
  UV_map uvm = m.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
  std::size_t n_ok = 0, n_fail = 0;
  const std::string& text = g.text;
  // (a) truncations
  const std::size_t step = text.size() > 2000 ? 7 : 1;
  for(std::size_t k = 0; k <= text.size(); k += step)
    RUN(check_robust_read(text.substr(0, k), m, uvm, n_ok, n_fail));
  std::cout << "fuzz truncations (" << text.size() / step + 1 << "): OK (" << n_ok << " accepted, " << n_fail << " rejected)" << std::endl;
  // (b) random single-character replacements, then a few multi-character ones
  n_ok = n_fail = 0;
  std::mt19937 rng(12345);
  const std::string alphabet = "0123456789/-x\n .e#+\t\rfv";
  std::uniform_int_distribution<std::size_t> pos(0, text.size() - 1);
  std::uniform_int_distribution<int> pick(0, int(alphabet.size()) + 3);
  std::uniform_int_distribution<int> byte(0, 255);
  for(int k = 0; k < 2400; ++k)
  {
    std::string t = text;
    const int n_changes = (k < 2000) ? 1 : 1 + k % 4;
    for(int c = 0; c < n_changes; ++c)
    {
      const int a = pick(rng);
      t[pos(rng)] = (a < int(alphabet.size())) ? alphabet[std::size_t(a)] : char(byte(rng));
    }
    RUN(check_robust_read(t, m, uvm, n_ok, n_fail));
  }
  std::cout << "fuzz replacements (2400): OK (" << n_ok << " accepted, " << n_fail << " rejected)" << std::endl;
  return EXIT_SUCCESS;
}

int test_malformed()
{
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"; // lines 1-6
  const std::string quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"; // lines 1-8
  const std::string five = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 1 1 1\nvt 0 0\nvt 1 0\nvt 0 1\nvt 0 -1\nvt 1 1\n"; // 1-10
  struct Case { std::string name, text; PE::Error_code code; std::size_t line; };
  const std::vector<Case> cases = {
    { "index 0", tri + "f 0/1 2/2 3/3\n", PE::ERROR_MALFORMED_FILE, 7 },
    { "v index out of range", tri + "f 1/1 2/2 4/3\n", PE::ERROR_MALFORMED_FILE, 7 },
    { "vt index out of range", tri + "f 1/1 2/2 3/4\n", PE::ERROR_MALFORMED_FILE, 7 },
    { "relative index too far back", tri + "f -4/1 2/2 3/3\n", PE::ERROR_MALFORMED_FILE, 7 },
    { "normal index out of range", tri + "f 1/1/1 2/2/1 3/3/1\n", PE::ERROR_MALFORMED_FILE, 7 },
    { "two corners", tri + "f 1/1 2/2\n", PE::ERROR_NON_TRIANGULAR_MESH, 7 },
    { "quad", quad + "f 1/1 2/2 3/3 4/4\n", PE::ERROR_NON_TRIANGULAR_MESH, 9 },
    { "vt nan", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt nan 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n", PE::ERROR_NON_FINITE_COORDINATES, 4 },
    { "v inf", "v 0 0 0\nv 1 -inf 0\n", PE::ERROR_NON_FINITE_COORDINATES, 2 },
    { "v overflow", "v 0 0 1e400\n", PE::ERROR_NON_FINITE_COORDINATES, 1 },
    { "v with 2 coordinates", "v 1 2\n", PE::ERROR_MALFORMED_FILE, 1 },
    { "vt with 1 coordinate", "v 1 2 3\nvt 1\n", PE::ERROR_MALFORMED_FILE, 2 },
    { "not a number", "v 1 2 3x\n", PE::ERROR_MALFORMED_FILE, 1 },
    { "hexadecimal", "v 1 2 0x3\n", PE::ERROR_MALFORMED_FILE, 1 },
    { "face without vt", tri + "f 1 2 3\n", PE::ERROR_MALFORMED_FILE, 7 },
    { "face with normals but no vt", tri + "f 1//1 2//1 3//1\n", PE::ERROR_MALFORMED_FILE, 7 },
    { "empty third index", tri + "f 1/1/ 2/2 3/3\n", PE::ERROR_MALFORMED_FILE, 7 },
    { "four indices", tri + "f 1/1/1/1 2/2 3/3\n", PE::ERROR_MALFORMED_FILE, 7 },
    { "empty face", tri + "f\n", PE::ERROR_MALFORMED_FILE, 7 },
    { "vt paired with two v", five + "f 1/1 2/2 3/3\nf 1/1 4/4 2/2\nf 2/3 5/5 3/2\n", PE::ERROR_MALFORMED_FILE, 13 },
    { "repeated vertex", tri + "f 1/1 2/2 1/1\n", PE::ERROR_NON_MANIFOLD, 7 },
    { "edge of three faces", five + "f 1/1 2/2 3/3\nf 2/2 1/1 4/4\nf 1/1 2/2 5/5\n", PE::ERROR_NON_MANIFOLD, 13 },
    { "edge of three faces (other direction)", five + "f 1/1 2/2 3/3\nf 2/2 1/1 4/4\nf 2/2 1/1 5/5\n", PE::ERROR_NON_MANIFOLD, 13 },
    { "inconsistent orientation", quad + "f 1/1 2/2 3/3\n\n# x\nf 1/1 2/2 4/4\n", PE::ERROR_NON_MANIFOLD, 12 },
    { "unsupported statement", tri + "l 1 2\nf 1/1 2/2 3/3\n", PE::ERROR_MALFORMED_FILE, 7 },
    { "empty file", "", PE::ERROR_EMPTY_MESH, 0 },
    { "comments only", "# nothing\n\n   \n", PE::ERROR_EMPTY_MESH, 0 },
    { "no face", tri, PE::ERROR_EMPTY_MESH, 0 },
  };
  Mesh m;
  UV_map uvm = m.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
  for(const Case& c : cases)
  {
    std::istringstream in(c.text);
    PE::IO::OBJ_read_result r = PE::IO::read_OBJ_with_uv(in, m, uvm);
    CHECK(r.status == c.code && r.line == c.line,
          c.name << ": expected " << PE::get_error_name(c.code) << " line " << c.line << ", got " << describe(r));
    CHECK(num_vertices(m) == 0 && !r.message.empty(), c.name);
  }
  std::cout << "malformed files (" << cases.size() << "): OK" << std::endl;

  // valid variants
  const std::vector<std::pair<std::string, std::string> > valid = {
    { "CRLF, tabs, trailing comment", "v 0 0 0\r\nv\t1 0 0\r\nv 0 1 0 # c\r\nvt 0 0\r\nvt 1 0\r\nvt 0 1\r\nf 1/1 2/2 3/3\r\n" },
    { "relative indices", tri + "f -3/-3 -2/-2 -1/-1\n" },
    { "forward references", "f 1/1 2/2 3/3\n" + tri },
    { "w coordinates and colours, plus signs", "v 0 0 0 1\nv +1 0 0 1 0.5 0.5\nv 0 1 0\nvt 0 0 0\nvt +1e0 0\nvt 0 1\nf 1/1 2/2 3/3\n" },
    { "underflow to zero", "v 0 0 1e-400\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 -1e-999\nvt 0 1\nf 1/1 2/2 3/3\n" },
    { "no final newline", tri + "f 1/1 2/2 3/3" },
  };
  for(const auto& c : valid)
  {
    std::istringstream in(c.second);
    PE::IO::OBJ_read_result r = PE::IO::read_OBJ_with_uv(in, m, uvm);
    CHECK(r.status == PE::OK && num_vertices(m) == 3 && num_faces(m) == 1, c.first << ": " << describe(r));
  }
  std::cout << "valid variants (" << valid.size() << "): OK" << std::endl;
  return EXIT_SUCCESS;
}

// ---------------------------------------------------------------------------
// read_polygon_mesh: OFF, OBJ, PLY, STL

// A fresh folder for the files of one test, removed by the destructor.
struct Temp_dir
{
  std::filesystem::path path;
  explicit Temp_dir(const std::string& name)
  {
    path = std::filesystem::temp_directory_path() / ("pe_test_io_" + name + "_" + std::to_string(::getpid()));
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
    std::filesystem::create_directories(path);
  }
  ~Temp_dir() { std::error_code ec; std::filesystem::remove_all(path, ec); }
  std::string file(const std::string& name) const { return (path / name).string(); }
  std::size_t count() const
  {
    std::size_t n = 0;
    for(const auto& e : std::filesystem::directory_iterator(path)) { (void)e; ++n; }
    return n;
  }
};

void write_bytes(const std::string& fname, const std::string& bytes)
{
  std::ofstream o(fname, std::ios::binary);
  o << bytes;
}

std::string read_bytes(const std::string& fname)
{
  std::ifstream in(fname, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string describe(const PE::IO::Read_result& r, int)
{
  return std::string(PE::get_error_name(r.status)) + " line " + std::to_string(r.line) + ": " + r.message;
}

// little-endian binary helpers
void put_u32(std::string& s, std::uint32_t x) { for(int k = 0; k < 4; ++k) s += char((x >> (8 * k)) & 0xff); }
void put_f32(std::string& s, float f) { std::uint32_t x; std::memcpy(&x, &f, 4); put_u32(s, x); }
void put_f32_be(std::string& s, float f)
{
  std::uint32_t x; std::memcpy(&x, &f, 4);
  for(int k = 3; k >= 0; --k) s += char((x >> (8 * k)) & 0xff);
}

std::string binary_stl(const std::vector<std::array<float, 9> >& tris, std::uint32_t declared)
{
  std::string s(80, ' ');
  s.replace(0, 6, "binary");
  put_u32(s, declared);
  for(const auto& t : tris)
  {
    for(int k = 0; k < 3; ++k) put_f32(s, 0.f);
    for(float x : t) put_f32(s, x);
    s += std::string(2, '\0');
  }
  return s;
}

int test_read_polygon_mesh_errors()
{
  Temp_dir dir("read");
  const std::string off_head = "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n"; // lines 1-6
  const std::string ply_head = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                               "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
                               "0 0 0\n1 0 0\n0 1 0\n1 1 0\n"; // lines 1-13
  const std::string obj_head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"; // lines 1-4
  // a binary PLY: 3 vertices (float x y z), faces as uchar-counted int lists
  auto binary_ply = [](bool big, const std::vector<std::array<float, 3> >& pts, const std::vector<std::vector<int> >& faces,
                       unsigned long long declared_faces) {
    std::string s = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") + " 1.0\n"
                  + "element vertex " + std::to_string(pts.size()) + "\nproperty float x\nproperty float y\nproperty float z\n"
                  + "element face " + std::to_string(declared_faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
    for(const auto& p : pts) for(float x : p) { if(big) put_f32_be(s, x); else put_f32(s, x); }
    for(const auto& f : faces)
    {
      s += char(f.size());
      for(int i : f)
      {
        std::uint32_t u = std::uint32_t(i);
        if(big) for(int k = 3; k >= 0; --k) s += char((u >> (8 * k)) & 0xff);
        else put_u32(s, u);
      }
    }
    return s;
  };
  const std::vector<std::array<float, 3> > tri3 = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}};
  const float nan = std::numeric_limits<float>::quiet_NaN();

  struct Case { std::string name, file, text; PE::Error_code code; std::size_t line; std::string message; };
  const std::vector<Case> cases = {
    // declared sizes larger than the file: refused at once, at the line of the declaration
    { "OFF declaring 10^9 vertices and faces", "huge.off", "OFF\n1000000000 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
      PE::ERROR_MALFORMED_FILE, 2, "declares 1000000000 vertices" },
    { "OFF face of degree 2e9", "degree.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n",
      PE::ERROR_MALFORMED_FILE, 6, "declares 2000000000 vertices" },
    { "OFF counts on the header line, truncated", "trunc.off", "OFF 4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n",
      PE::ERROR_MALFORMED_FILE, 1, "only 5 lines follow" },
    { "PLY declaring 10^12 vertices", "huge.ply", "ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n",
      PE::ERROR_MALFORMED_FILE, 3, "declares 1000000000000 instances" },
    { "binary PLY declaring 4e9 faces", "huge_binary.ply", binary_ply(false, tri3, {{0, 1, 2}}, 4000000000ull),
      PE::ERROR_MALFORMED_FILE, 7, "declares 4000000000 instances" },
    { "binary PLY face list of 255 entries", "list_binary.ply", binary_ply(false, tri3, {}, 1) + std::string(1, char(255)) + std::string(12, '\0'),
      PE::ERROR_MALFORMED_FILE, 0, "byte offset" },
    { "binary STL declaring 10^9 triangles", "huge.stl", binary_stl({{{0, 0, 0, 1, 0, 0, 0, 1, 0}}}, 1000000000u),
      PE::ERROR_MALFORMED_FILE, 0, "declares 1000000000 triangles" },
    // non-triangular faces: the same code in every format
    { "OFF quad", "quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n", PE::ERROR_NON_TRIANGULAR_MESH, 7, "4 vertices" },
    { "OBJ quad", "quad.obj", obj_head + "f 1 2 4 3\n", PE::ERROR_NON_TRIANGULAR_MESH, 5, "4 corners" },
    { "PLY quad", "quad.ply", ply_head + "4 0 1 3 2\n3 0 1 2\n", PE::ERROR_NON_TRIANGULAR_MESH, 14, "4 vertices" },
    { "binary PLY quad", "quad_binary.ply", binary_ply(true, tri3, {{0, 1, 2, 0}}, 1), PE::ERROR_NON_TRIANGULAR_MESH, 0, "byte offset" },
    { "STL facet with 4 vertices", "quad.stl", "solid q\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
      "      vertex 1 1 0\n      vertex 0 1 0\n    endloop\n  endfacet\nendsolid q\n", PE::ERROR_NON_TRIANGULAR_MESH, 7, "more than 3" },
    // non-finite coordinates
    { "OFF nan", "nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", PE::ERROR_NON_FINITE_COORDINATES, 4, "nan" },
    { "OFF 1e400", "overflow.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 1e400\n3 0 1 2\n", PE::ERROR_NON_FINITE_COORDINATES, 5, "1e400" },
    { "OBJ inf", "inf.obj", "v 0 0 0\nv 1 -inf 0\nv 0 1 0\nf 1 2 3\n", PE::ERROR_NON_FINITE_COORDINATES, 2, "inf" },
    { "PLY inf", "inf.ply", ply_head.substr(0, ply_head.size() - 6) + "inf 1 0\n3 0 1 2\n3 1 3 2\n", PE::ERROR_NON_FINITE_COORDINATES, 13, "inf" },
    { "binary PLY nan", "nan_binary.ply", binary_ply(false, {{{0, 0, 0}}, {{1, nan, 0}}, {{0, 1, 0}}}, {{0, 1, 2}}, 1),
      PE::ERROR_NON_FINITE_COORDINATES, 0, "byte offset" },
    { "STL nan", "nan.stl", "solid n\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 NaN 0\n"
      "      vertex 0 1 0\n    endloop\n  endfacet\nendsolid n\n", PE::ERROR_NON_FINITE_COORDINATES, 5, "NaN" },
    { "binary STL inf", "inf.stl", binary_stl({{{0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::infinity(), 0}}}, 1),
      PE::ERROR_NON_FINITE_COORDINATES, 0, "byte offset 124" },
    // malformed content, with its line
    { "OFF index out of range", "range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", PE::ERROR_MALFORMED_FILE, 6, "out of range" },
    { "OFF negative index", "negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", PE::ERROR_MALFORMED_FILE, 6, "'-1'" },
    { "OFF vertex with 2 coordinates", "short.off", "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", PE::ERROR_MALFORMED_FILE, 4, "3 coordinates" },
    { "OFF not a number", "nan2.off", "OFF\n# comment\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", PE::ERROR_MALFORMED_FILE, 5, "'x'" },
    { "OFF bad counts", "counts.off", "OFF\n3 one 0\n", PE::ERROR_MALFORMED_FILE, 2, "counts" },
    { "OFF 4D", "4d.off", "4OFF\n3 1 0\n", PE::ERROR_MALFORMED_FILE, 1, "unsupported" },
    { "OBJ index out of range", "range.obj", obj_head + "f 1 2 3\nf 2 5 3\n", PE::ERROR_MALFORMED_FILE, 6, "out of range" },
    { "OBJ unsupported statement", "stmt.obj", obj_head + "l 1 2\n", PE::ERROR_MALFORMED_FILE, 5, "unsupported" },
    { "PLY index out of range", "range.ply", ply_head + "3 0 1 2\n3 1 4 2\n", PE::ERROR_MALFORMED_FILE, 15, "out of range" },
    { "PLY list longer than its line", "list.ply", ply_head + "3 0 1 2\n200 1 3 2\n", PE::ERROR_MALFORMED_FILE, 15, "declares 200 values" },
    { "PLY too many values", "values.ply", ply_head + "3 0 1 2 7\n3 1 3 2\n", PE::ERROR_MALFORMED_FILE, 14, "too many" },
    { "PLY without end_header", "header.ply", "ply\nformat ascii 1.0\nelement vertex 3\n", PE::ERROR_MALFORMED_FILE, 3, "end_header" },
    { "STL vertex outside a loop", "loop.stl", "solid s\nvertex 0 0 0\nendsolid s\n", PE::ERROR_MALFORMED_FILE, 2, "unexpected" },
    { "STL truncated", "trunc.stl", "solid s\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n",
      PE::ERROR_MALFORMED_FILE, 5, "ends inside a facet" },
    // not a manifold polygon mesh
    { "repeated vertex", "repeated.off", off_head + "3 0 1 1\n3 1 3 2\n", PE::ERROR_NON_MANIFOLD, 7, "repeated vertex" },
    { "duplicate face", "dup.off", off_head + "3 0 1 2\n3 2 1 0\n", PE::ERROR_NON_MANIFOLD, 8, "duplicate face" },
    { "edge of three faces", "edge3.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n1 1 1\n3 0 1 2\n3 1 3 2\n3 1 4 2\n",
      PE::ERROR_NON_MANIFOLD, 10, "non-manifold edge" },
    { "two fans at a vertex", "bowtie.ply", "ply\nformat ascii 1.0\nelement vertex 5\nproperty double x\nproperty double y\n"
      "property double z\nelement face 2\nproperty list uchar uint vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n"
      "3 0 1 2\n3 0 3 4\n", PE::ERROR_NON_MANIFOLD, 10, "non-manifold vertex (vertex 1 of the file, counting from 1)" },
    { "Moebius strip (cannot be oriented)", "moebius.obj",
      "v 1 0 0\nv 0.3 0.95 0.2\nv -0.8 0.6 -0.2\nv -0.8 -0.6 0.2\nv 0.3 -0.95 -0.2\n"
      "f 1 2 3\nf 2 3 4\nf 3 4 5\nf 4 5 1\nf 5 1 2\n", PE::ERROR_NON_MANIFOLD, 7, "cannot be fixed" },
    // empty
    { "empty OFF", "empty.off", "", PE::ERROR_EMPTY_MESH, 0, "empty" },
    { "OFF without faces", "nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", PE::ERROR_EMPTY_MESH, 0, "no face" },
    { "OBJ comments only", "comments.obj", "# nothing\n\n", PE::ERROR_EMPTY_MESH, 0, "no face" },
    { "PLY without faces", "points.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\n", PE::ERROR_EMPTY_MESH, 0, "no face" },
    { "empty STL", "empty.stl", "", PE::ERROR_EMPTY_MESH, 0, "empty" },
    { "unknown extension", "mesh.xyz", "OFF\n", PE::ERROR_MALFORMED_FILE, 0, "unknown format" },
  };
  for(const Case& c : cases)
  {
    const std::string fname = dir.file(c.file);
    write_bytes(fname, c.text);
    Mesh m;
    PE::IO::Read_result r;
    try { r = PE::IO::read_polygon_mesh(fname, m); }
    catch(...) { CHECK(false, c.name << ": exception escaped"); }
    CHECK(r.status == c.code && r.line == c.line && r.message.find(c.message) != std::string::npos,
          c.name << ": expected " << PE::get_error_name(c.code) << " line " << c.line << " '" << c.message << "', got " << describe(r, 0));
    CHECK(num_vertices(m) == 0 && num_faces(m) == 0 && !r, c.name << ": mesh not empty after a failure");
  }
  std::cout << "read_polygon_mesh: malformed files (" << cases.size() << "): OK" << std::endl;

  // files the system cannot read
  {
    Mesh m;
    PE::IO::Read_result r = PE::IO::read_polygon_mesh(dir.file("no_such_file.off"), m);
    CHECK(r.status == PE::ERROR_CANNOT_READ_FILE && r.message.find(std::strerror(ENOENT)) != std::string::npos, describe(r, 0));
    std::filesystem::create_directory(dir.file("folder.off"));
    r = PE::IO::read_polygon_mesh(dir.file("folder.off"), m);
    CHECK(r.status == PE::ERROR_CANNOT_READ_FILE && r.message.find(std::strerror(EISDIR)) != std::string::npos, describe(r, 0));
    // the OBJ reader with uv refuses a folder as well (it used to read it as an empty file)
    UV_map uvm = m.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
    std::filesystem::create_directory(dir.file("folder.obj"));
    r = PE::IO::read_OBJ_with_uv(dir.file("folder.obj"), m, uvm);
    CHECK(r.status == PE::ERROR_CANNOT_READ_FILE && r.message.find(std::strerror(EISDIR)) != std::string::npos, describe(r, 0));
    // a mesh that is not empty on entry
    write_bytes(dir.file("ok.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    Mesh full;
    full.add_vertex(Point_3(0, 0, 0));
    r = PE::IO::read_polygon_mesh(dir.file("ok.off"), full);
    CHECK(r.status == PE::ERROR_WRONG_PARAMETER && num_vertices(full) == 1, describe(r, 0));
  }
  std::cout << "read_polygon_mesh: unreadable files: OK" << std::endl;
  return EXIT_SUCCESS;
}

// The bounded memory: with the address space limited to 1 GiB more than what the process uses,
// reading files that declare 10^9 elements still gives the error of the declaration (a reader
// trusting the declaration runs out of memory: "out of memory", or is killed).
int test_read_polygon_mesh_memory_bound()
{
#if defined(__SANITIZE_ADDRESS__)
  std::cout << "read_polygon_mesh: address-space limit skipped under AddressSanitizer" << std::endl;
  return EXIT_SUCCESS;
#else
  Temp_dir dir("memory");
  write_bytes(dir.file("h.off"), "OFF\n1000000000 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  write_bytes(dir.file("d.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n");
  write_bytes(dir.file("h.stl"), binary_stl({{{0, 0, 0, 1, 0, 0, 0, 1, 0}}}, 4000000000u));
  std::size_t vm = 0; // current virtual size, in bytes
  {
    std::ifstream st("/proc/self/statm");
    st >> vm;
    vm *= std::size_t(::sysconf(_SC_PAGESIZE));
  }
  struct rlimit old;
  CHECK(::getrlimit(RLIMIT_AS, &old) == 0, "getrlimit");
  struct rlimit lim = old;
  lim.rlim_cur = rlim_t(vm) + (rlim_t(1) << 30);
  if(old.rlim_cur != RLIM_INFINITY && old.rlim_cur < lim.rlim_cur) lim.rlim_cur = old.rlim_cur;
  CHECK(::setrlimit(RLIMIT_AS, &lim) == 0, "setrlimit");
  PE::IO::Read_result r[3];
  const char* names[3] = { "h.off", "d.off", "h.stl" };
  for(int k = 0; k < 3; ++k)
  {
    Mesh m;
    r[k] = PE::IO::read_polygon_mesh(dir.file(names[k]), m);
  }
  ::setrlimit(RLIMIT_AS, &old);
  CHECK(r[0].status == PE::ERROR_MALFORMED_FILE && r[0].line == 2, describe(r[0], 0));
  CHECK(r[1].status == PE::ERROR_MALFORMED_FILE && r[1].line == 6, describe(r[1], 0));
  CHECK(r[2].status == PE::ERROR_MALFORMED_FILE && r[2].message.find("4000000000") != std::string::npos, describe(r[2], 0));
  std::cout << "read_polygon_mesh: huge declared counts under a 1 GiB address-space margin: OK" << std::endl;
  return EXIT_SUCCESS;
#endif
}

// n x n grid, z = a bump: the same mesh written by CGAL's writers in every format is read back
void make_bump_grid(Mesh& m, int n)
{
  std::vector<vertex_descriptor> v;
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      const double x = i / double(n - 1), y = j / double(n - 1);
      v.push_back(m.add_vertex(Point_3(x, y, 0.25 * std::sin(3 * x) * std::cos(2 * y))));
    }
  for(int j = 0; j + 1 < n; ++j)
    for(int i = 0; i + 1 < n; ++i)
    {
      const vertex_descriptor a = v[j * n + i], b = v[j * n + i + 1], c = v[(j + 1) * n + i + 1], d = v[(j + 1) * n + i];
      m.add_face(a, b, c);
      m.add_face(a, c, d);
    }
}

int test_read_polygon_mesh_formats(const std::string& data_dir)
{
  Temp_dir dir("formats");
  Mesh g;
  make_bump_grid(g, 9);
  struct Written { std::string file; bool exact; };
  const std::vector<Written> written = { {"g.off", true}, {"g.obj", true}, {"g_ascii.ply", true}, {"g_binary.ply", true},
                                         {"g_ascii.stl", false}, {"g_binary.STL", false} };
  CHECK(CGAL::IO::write_OFF(dir.file("g.off"), g, CGAL::parameters::stream_precision(17)), "write off");
  CHECK(CGAL::IO::write_OBJ(dir.file("g.obj"), g, CGAL::parameters::stream_precision(17)), "write obj");
  CHECK(CGAL::IO::write_PLY(dir.file("g_ascii.ply"), g, CGAL::parameters::use_binary_mode(false).stream_precision(17)), "write ply");
  CHECK(CGAL::IO::write_PLY(dir.file("g_binary.ply"), g, CGAL::parameters::use_binary_mode(true)), "write binary ply");
  CHECK(CGAL::IO::write_STL(dir.file("g_ascii.stl"), g, CGAL::parameters::use_binary_mode(false)), "write stl");
  CHECK(CGAL::IO::write_STL(dir.file("g_binary.STL"), g, CGAL::parameters::use_binary_mode(true)), "write binary stl");
  for(const Written& w : written)
  {
    Mesh m;
    PE::IO::Read_result r = PE::IO::read_polygon_mesh(dir.file(w.file), m);
    CHECK(r.status == PE::OK && r.line == 0 && r.message.empty(), w.file << ": " << describe(r, 0));
    CHECK(num_vertices(m) == num_vertices(g) && num_faces(m) == num_faces(g) && r.number_of_faces == num_faces(g),
          w.file << ": " << num_vertices(m) << " vertices, " << num_faces(m) << " faces");
    CHECK(CGAL::is_valid_polygon_mesh(m) && CGAL::is_triangle_mesh(m) && !r.reoriented, w.file);
    if(w.exact)
    {
      auto it = vertices(g).begin();
      for(vertex_descriptor v : vertices(m))
      {
        CHECK(m.point(v) == g.point(*it), w.file << ": coordinates");
        ++it;
      }
      CHECK(face_list(m, 0) == face_list(g, 0), w.file << ": faces");
    }
  }
  // another FaceGraph: Polyhedron_3
  {
    Polyhedron P;
    PE::IO::Read_result r = PE::IO::read_polygon_mesh(dir.file("g_binary.ply"), P);
    CHECK(r && num_vertices(P) == num_vertices(g) && num_faces(P) == num_faces(g) && CGAL::is_valid_polygon_mesh(P), describe(r, 0));
    Polyhedron Q;
    r = PE::IO::read_polygon_mesh(dir.file("g.obj"), Q, CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, Q)));
    CHECK(r && num_faces(Q) == num_faces(g), describe(r, 0));
  }
  // unreferenced vertices are dropped in every format, as read_OBJ_with_uv() drops unused vt
  {
    const std::vector<std::pair<std::string, std::string> > files = {
      { "u.off", "OFF\n4 1 0\n9 9 9\n0 0 0\n1 0 0\n0 1 0\n3 1 2 3\n" },
      { "u.obj", "v 9 9 9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 4\n" },
      { "u.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                 "element face 1\nproperty list uchar int vertex_indices\nend_header\n9 9 9\n0 0 0\n1 0 0\n0 1 0\n3 1 2 3\n" } };
    for(const auto& f : files)
    {
      write_bytes(dir.file(f.first), f.second);
      Mesh m;
      PE::IO::Read_result r = PE::IO::read_polygon_mesh(dir.file(f.first), m);
      CHECK(r && num_vertices(m) == 3 && r.number_of_positions == 4 && r.number_of_unreferenced_vertices == 1, f.first << ": " << describe(r, 0));
      CHECK(m.point(*vertices(m).begin()) == Point_3(0, 0, 0), f.first << ": order");
    }
    Mesh m;
    UV_map uvm = m.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
    std::istringstream in("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 9 9\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/2 2/3 3/4\n");
    PE::IO::Read_result r = PE::IO::read_OBJ_with_uv(in, m, uvm);
    CHECK(r && num_vertices(m) == 3 && r.number_of_unreferenced_vertices == 1, describe(r, 0));
  }
  // variants: OFF keywords, comments, colours; OBJ corner forms; a face reversed (reoriented)
  {
    const std::vector<std::pair<std::string, std::string> > files = {
      { "c.off", "COFF\n# colours\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2 128 128 128\n" },
      { "n.off", "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n" },
      { "forms.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvn 0 0 1\nf 1/1 2/1/1 3//1\nf 2 -1 -2\n" },
      { "crlf.ply", "ply\r\nformat ascii 1.0\r\ncomment x\r\nelement vertex 3\r\nproperty double x\r\nproperty double y\r\n"
                    "property double z\r\nproperty uchar red\r\nelement face 1\r\nproperty list uint8 uint32 vertex_index\r\n"
                    "property int flags\r\nend_header\r\n0 0 0 1\r\n1 0 0 2\r\n0 1 0 3\r\n3 0 1 2 7\r\n" },
      { "two.stl", "solid a\n  facet normal nan nan nan\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n      vertex 0 1 0\n"
                   "    endloop\n  endfacet\nendsolid a\nsolid b\n  facet normal 0 0 1\n    outer loop\n      vertex 1 0 0\n"
                   "      vertex 1 1 0\n      vertex 0 1 0\n    endloop\n  endfacet\nendsolid b\n" } };
    const std::size_t expected_faces[] = { 1, 1, 2, 1, 2 };
    for(std::size_t k = 0; k < files.size(); ++k)
    {
      write_bytes(dir.file(files[k].first), files[k].second);
      Mesh m;
      PE::IO::Read_result r = PE::IO::read_polygon_mesh(dir.file(files[k].first), m);
      CHECK(r && num_faces(m) == expected_faces[k], files[k].first << ": " << describe(r, 0));
    }
    write_bytes(dir.file("reversed.off"), "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 2 3\n");
    Mesh m;
    PE::IO::Read_result r = PE::IO::read_polygon_mesh(dir.file("reversed.off"), m);
    CHECK(r && r.reoriented && num_faces(m) == 2 && CGAL::is_valid_polygon_mesh(m), describe(r, 0));
  }
  std::cout << "read_polygon_mesh: formats (OFF, OBJ, PLY ascii and binary, STL ascii and binary): OK" << std::endl;

  // libcgal-demo's meshes: the same meshes as CGAL's reader where both accept a triangle mesh
  CHECK(std::filesystem::is_directory(data_dir + "/meshes"), "libcgal-demo's meshes are missing from '" << data_dir << "'");
  {
    std::size_t n_same = 0, n_refused = 0;
    for(const auto& e : std::filesystem::directory_iterator(data_dir + "/meshes"))
    {
      const std::string f = e.path().string();
      const std::string ext = e.path().extension().string();
      if(ext != ".off" && ext != ".ply" && ext != ".stl" && ext != ".obj") continue;
      if(e.file_size() > (std::uintmax_t(20) << 20)) continue;
      Mesh a, b;
      const PE::IO::Read_result r = PE::IO::read_polygon_mesh(f, a);
      bool ok = false;
      try { ok = CGAL::IO::read_polygon_mesh(f, b); } catch(...) { ok = false; }
      if(r)
      {
        CHECK(CGAL::is_valid_polygon_mesh(a) && CGAL::is_triangle_mesh(a), f);
        if(ok && !r.reoriented && CGAL::is_triangle_mesh(b))
        {
          CHECK(num_faces(a) == num_faces(b) && num_vertices(a) + r.number_of_unreferenced_vertices == num_vertices(b), f);
          ++n_same;
        }
      }
      else
      {
        CHECK(!r.message.empty() && r.status != PE::ERROR_CANNOT_READ_FILE, f << ": " << describe(r, 0));
        if(ok && !CGAL::is_triangle_mesh(b)) CHECK(r.status == PE::ERROR_NON_TRIANGULAR_MESH, f << ": " << describe(r, 0));
        ++n_refused;
      }
    }
    Mesh q;
    const PE::IO::Read_result r = PE::IO::read_polygon_mesh(data_dir + "/meshes/cube_quad.off", q);
    CHECK(r.status == PE::ERROR_NON_TRIANGULAR_MESH && r.line == 11, describe(r, 0));
    std::cout << "read_polygon_mesh: libcgal-demo meshes: OK (" << n_same << " identical to CGAL's reader, "
              << n_refused << " refused with a reason)" << std::endl;
  }
  return EXIT_SUCCESS;
}

// Truncated and corrupted files of every format: every call returns, a failure leaves the mesh
// empty with a reason and a line within the file, a success is a valid triangle mesh.
int test_read_polygon_mesh_fuzz()
{
  Mesh g;
  make_bump_grid(g, 4);
  Temp_dir dir("fuzz");
  CHECK(CGAL::IO::write_OFF(dir.file("g.off"), g, CGAL::parameters::stream_precision(17)), "off");
  CHECK(CGAL::IO::write_OBJ(dir.file("g.obj"), g, CGAL::parameters::stream_precision(17)), "obj");
  CHECK(CGAL::IO::write_PLY(dir.file("a.ply"), g, CGAL::parameters::use_binary_mode(false).stream_precision(17)), "ply");
  CHECK(CGAL::IO::write_PLY(dir.file("b.ply"), g, CGAL::parameters::use_binary_mode(true)), "binary ply");
  CHECK(CGAL::IO::write_STL(dir.file("a.stl"), g, CGAL::parameters::use_binary_mode(false)), "stl");
  CHECK(CGAL::IO::write_STL(dir.file("b.stl"), g, CGAL::parameters::use_binary_mode(true)), "binary stl");
  const std::vector<std::pair<std::string, std::string> > inputs = {
    { "off", read_bytes(dir.file("g.off")) }, { "obj", read_bytes(dir.file("g.obj")) }, { "ply", read_bytes(dir.file("a.ply")) },
    { "ply", read_bytes(dir.file("b.ply")) }, { "stl", read_bytes(dir.file("a.stl")) }, { "stl", read_bytes(dir.file("b.stl")) } };
  std::mt19937 rng(4321);
  std::size_t n_ok = 0, n_fail = 0;
  auto check = [&](const std::string& format, const std::string& text) -> int {
    Mesh m;
    std::istringstream in(text);
    PE::IO::Read_result r;
    try { r = PE::IO::read_polygon_mesh(in, format, m); }
    catch(...) { CHECK(false, "exception escaped"); }
    std::size_t nlines = 1;
    for(char c : text) nlines += (c == '\n');
    if(r)
    {
      ++n_ok;
      CHECK(CGAL::is_valid_polygon_mesh(m) && CGAL::is_triangle_mesh(m) && num_faces(m) == r.number_of_faces, "invalid mesh accepted");
      for(vertex_descriptor v : vertices(m)) CHECK(std::isfinite(m.point(v).x()) && std::isfinite(m.point(v).z()), "non-finite accepted");
    }
    else
    {
      ++n_fail;
      CHECK(num_vertices(m) == 0 && !r.message.empty() && r.line <= nlines, format << ": " << describe(r, 0));
      CHECK(r.status == PE::ERROR_MALFORMED_FILE || r.status == PE::ERROR_NON_TRIANGULAR_MESH || r.status == PE::ERROR_NON_MANIFOLD
            || r.status == PE::ERROR_NON_FINITE_COORDINATES || r.status == PE::ERROR_EMPTY_MESH, format << ": " << describe(r, 0));
    }
    return EXIT_SUCCESS;
  };
  for(const auto& input : inputs)
  {
    const std::string& text = input.second;
    const std::size_t step = (std::max)(std::size_t(1), text.size() / 300);
    for(std::size_t k = 0; k <= text.size(); k += step) RUN(check(input.first, text.substr(0, k)));
    const std::string alphabet = "0123456789 \n-.e#xnaif";
    std::uniform_int_distribution<std::size_t> pos(0, text.size() - 1);
    std::uniform_int_distribution<int> byte(0, 255), pick(0, int(alphabet.size()) + 2);
    for(int k = 0; k < 400; ++k)
    {
      std::string t = text;
      for(int c = 0; c < 1 + k % 3; ++c)
      {
        const int a = pick(rng);
        t[pos(rng)] = (a < int(alphabet.size())) ? alphabet[std::size_t(a)] : char(byte(rng));
      }
      RUN(check(input.first, t));
    }
  }
  std::cout << "read_polygon_mesh: fuzzing (truncations and corruptions of 6 files): OK (" << n_ok << " accepted, "
            << n_fail << " rejected)" << std::endl;
  return EXIT_SUCCESS;
}

// The bad inputs of test/Progressive_embedding/data (also used by the tool's tests): code and line.
int test_data_files()
{
  const std::filesystem::path data = std::filesystem::path(__FILE__).parent_path() / "data";
  // the files are part of the repository: a missing folder is a broken checkout, not a reason to pass
  CHECK(std::filesystem::is_directory(data), "read_polygon_mesh: the data folder " << data << " is missing");
  struct Case { const char* file; PE::Error_code code; std::size_t line; };
  const Case cases[] = {
    { "huge_counts.off", PE::ERROR_MALFORMED_FILE, 2 },
    { "huge_face_degree.off", PE::ERROR_MALFORMED_FILE, 6 },
    { "quad.off", PE::ERROR_NON_TRIANGULAR_MESH, 7 },
    { "quad.obj", PE::ERROR_NON_TRIANGULAR_MESH, 5 },
    { "quad.ply", PE::ERROR_NON_TRIANGULAR_MESH, 14 },
    { "quad.stl", PE::ERROR_NON_TRIANGULAR_MESH, 7 },
    { "nan.off", PE::ERROR_NON_FINITE_COORDINATES, 4 },
    { "non_manifold_edge.off", PE::ERROR_NON_MANIFOLD, 10 },
    { "duplicate_face.off", PE::ERROR_NON_MANIFOLD, 7 },
    { "index_out_of_range.ply", PE::ERROR_MALFORMED_FILE, 13 },
    { "malformed.obj", PE::ERROR_MALFORMED_FILE, 6 },
  };
  for(const Case& c : cases)
  {
    Mesh m;
    const PE::IO::Read_result r = PE::IO::read_polygon_mesh((data / c.file).string(), m);
    CHECK(r.status == c.code && r.line == c.line, c.file << ": " << describe(r, 0));
  }
  std::cout << "read_polygon_mesh: data files (" << sizeof(cases) / sizeof(cases[0]) << "): OK" << std::endl;
  return EXIT_SUCCESS;
}

// ---------------------------------------------------------------------------
// SVG

// n x n grid on [0,1]^2, counterclockwise triangles, uv = (x, y)
void make_grid(Mesh& m, UV_map uvm, int n)
{
  std::vector<vertex_descriptor> v;
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      v.push_back(m.add_vertex(Point_3(i / double(n - 1), j / double(n - 1), 0)));
      uvm[v.back()] = Point_2(i / double(n - 1), j / double(n - 1));
    }
  for(int j = 0; j + 1 < n; ++j)
    for(int i = 0; i + 1 < n; ++i)
    {
      const vertex_descriptor a = v[j * n + i], b = v[j * n + i + 1], c = v[(j + 1) * n + i + 1], d = v[(j + 1) * n + i];
      m.add_face(a, b, c);
      m.add_face(a, c, d);
    }
}

bool xml_is_valid(const std::string& svg, bool& checked)
{
  checked = false;
  // python3 is a dependency of the test suite (scripts/setup.sh installs it): without it the XML is not
  // validated, and the test says so by failing
  if(std::system("python3 -c \"import xml.dom.minidom\" > /dev/null 2>&1") != 0)
  {
    std::cout << "no python3 with xml.dom.minidom: the SVG cannot be validated" << std::endl;
    return false;
  }
  const std::string fname = (std::filesystem::temp_directory_path()
                             / ("pe_test_io_" + std::to_string(std::random_device()()) + ".svg")).string();
  { std::ofstream o(fname, std::ios::binary); o << svg; }
  const std::string cmd = "python3 -c \"import xml.dom.minidom,sys; xml.dom.minidom.parse(sys.argv[1])\" " + fname;
  const int rc = std::system(cmd.c_str());
  std::remove(fname.c_str());
  checked = true;
  return rc == 0;
}

int test_svg()
{
  Mesh m;
  UV_map uvm = m.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
  const int n = 7;
  make_grid(m, uvm, n);
  // drag the vertex (2,2) across its neighbours, and put (4,4) on top of (5,4): flipped and degenerate faces
  const vertex_descriptor v22(2 * n + 2), v44(4 * n + 4), v54(4 * n + 5);
  uvm[v22] = Point_2(0.62, 0.55);
  uvm[v44] = uvm[v54];
  std::size_t pos = 0, neg = 0, zero = 0;
  for(auto f : faces(m))
  {
    std::vector<Point_2> p;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m)) p.push_back(uvm[target(h, m)]);
    const CGAL::Orientation o = CGAL::orientation(p[0], p[1], p[2]);
    (o == CGAL::LEFT_TURN ? pos : o == CGAL::RIGHT_TURN ? neg : zero)++;
  }
  CHECK(neg > 0 && zero > 0 && pos > neg, pos << " " << neg << " " << zero);
  std::ostringstream out;
  const std::string title = "grid <7x7> & \"dragged\" \x01 caf\xc3\xa9 \xff";
  CHECK(PE::IO::write_SVG(out, m, uvm, title) == PE::OK, "svg");
  const std::string svg = out.str();
  CHECK(svg.find(">flipped: " + std::to_string(neg) + "</text>") != std::string::npos, "flipped count");
  CHECK(svg.find(">degenerate: " + std::to_string(zero) + "</text>") != std::string::npos, "degenerate count");
  CHECK(svg.find(">faces: " + std::to_string(num_faces(m)) + "</text>") != std::string::npos, "face count");
  // every face is one closed subpath of the face group; one marker per flipped or degenerate face
  const std::size_t g0 = svg.find("<g id=\"pe-faces\">"), g1 = svg.find("</g>", g0);
  CHECK(g0 != std::string::npos && g1 != std::string::npos, "no face group");
  const std::string face_group = svg.substr(g0, g1 - g0);
  std::size_t n_closed = 0;
  for(char c : face_group) n_closed += (c == 'Z');
  CHECK(n_closed == num_faces(m), "one subpath per face: " << n_closed);
  CHECK(svg.find("<polygon") == std::string::npos && svg.find("<circle") == std::string::npos, "one element per face");
  std::size_t n_flipped_markers = 0, n_degenerate_markers = 0;
  for(std::size_t k = svg.find("a6 6 0 1 0 12 0"); k != std::string::npos; k = svg.find("a6 6 0 1 0 12 0", k + 1)) ++n_flipped_markers;
  for(std::size_t k = svg.find("a9 9 0 1 0 18 0"); k != std::string::npos; k = svg.find("a9 9 0 1 0 18 0", k + 1)) ++n_degenerate_markers;
  CHECK(n_flipped_markers == neg && n_degenerate_markers == zero, "markers: " << n_flipped_markers << ", " << n_degenerate_markers);
  CHECK(svg.find("caf\xc3\xa9") != std::string::npos && svg.find("&lt;7x7&gt; &amp; &quot;dragged&quot;") != std::string::npos,
        "title");
  bool checked = false;
  CHECK(xml_is_valid(svg, checked), "invalid XML");

  // mirrored layout: the majority is clockwise, the same faces are reported
  for(vertex_descriptor v : vertices(m)) uvm[v] = Point_2(-uvm[v].x(), uvm[v].y());
  std::ostringstream out2;
  CHECK(PE::IO::write_SVG(out2, m, uvm) == PE::OK, "svg mirrored");
  CHECK(out2.str().find(">flipped: " + std::to_string(neg) + "</text>") != std::string::npos, "mirrored flipped count");
  CHECK(xml_is_valid(out2.str(), checked), "invalid XML (mirrored)");

  // non-finite uv: faces not drawn, counted
  uvm[v22] = Point_2(std::numeric_limits<double>::infinity(), 0);
  std::ostringstream out3;
  CHECK(PE::IO::write_SVG(out3, m, uvm) == PE::OK, "svg non-finite");
  CHECK(out3.str().find(">non-finite vertices: 1</text>") != std::string::npos, "non-finite count");
  CHECK(xml_is_valid(out3.str(), checked), "invalid XML (non-finite)");

  // errors
  Mesh empty;
  UV_map uve = empty.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
  std::ostringstream o4;
  CHECK(PE::IO::write_SVG(o4, empty, uve) == PE::ERROR_EMPTY_MESH && o4.str().empty(), "empty");
  Mesh q;
  UV_map uvq = q.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
  {
    vertex_descriptor a = q.add_vertex(Point_3(0, 0, 0)), b = q.add_vertex(Point_3(1, 0, 0)),
                      c = q.add_vertex(Point_3(1, 1, 0)), d = q.add_vertex(Point_3(0, 1, 0));
    q.add_face(a, b, c, d);
    uvq[a] = Point_2(0, 0); uvq[b] = Point_2(1, 0); uvq[c] = Point_2(1, 1); uvq[d] = Point_2(0, 1);
  }
  CHECK(PE::IO::write_SVG(o4, q, uvq) == PE::ERROR_NON_TRIANGULAR_MESH && o4.str().empty(), "quad");
  CHECK(PE::IO::write_SVG((std::filesystem::temp_directory_path() / "no_such_dir_pe" / "x.svg").string(), m, uvm)
          == PE::ERROR_CANNOT_WRITE_FILE, "cannot write");
  std::cout << "SVG (" << neg << " flipped, " << zero << " degenerate" << (checked ? ", XML validated" : ", XML not validated: no python3")
            << "): OK" << std::endl;
  return EXIT_SUCCESS;
}

// ---------------------------------------------------------------------------
// Writers: a failed write never leaves a partial file

bool is_char_device(const std::string& f) { struct stat st; return ::stat(f.c_str(), &st) == 0 && S_ISCHR(st.st_mode); }
bool is_folder(const std::string& f) { struct stat st; return ::stat(f.c_str(), &st) == 0 && S_ISDIR(st.st_mode); }
bool exists(const std::string& f) { struct stat st; return ::lstat(f.c_str(), &st) == 0; }

// the names in the folder, sorted
std::vector<std::string> listing(const Temp_dir& dir)
{
  std::vector<std::string> names;
  for(const auto& e : std::filesystem::directory_iterator(dir.path)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

int test_atomic_writes()
{
  Temp_dir dir("write");
  Mesh m;
  UV_map uvm = m.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
  make_grid(m, uvm, 120); // an OBJ of about 1 MB, an SVG of about 1.5 MB
  PE::IO::SVG_options so;
  so.title = "grid";
  std::ostringstream obj_ref, svg_ref;
  CHECK(PE::IO::write_OBJ_with_uv(obj_ref, m, uvm) == PE::OK, "obj to a stream");
  CHECK(PE::IO::write_SVG(svg_ref, m, uvm, so) == PE::OK, "svg to a stream");

  // success: the same bytes as the stream writers; an existing file keeps its mode; a symbolic
  // link is kept and its target replaced; nothing else is left in the folder
  const std::string obj = dir.file("out.obj"), svg = dir.file("out.svg");
  write_bytes(obj, "old content\n");
  CHECK(::chmod(obj.c_str(), 0640) == 0, "chmod");
  CHECK(PE::IO::write_OBJ_with_uv(obj, m, uvm) == PE::OK, "write obj");
  CHECK(read_bytes(obj) == obj_ref.str(), "file and stream outputs differ");
  struct stat st;
  CHECK(::stat(obj.c_str(), &st) == 0 && (st.st_mode & 07777) == 0640, "mode not kept: " << std::oct << (st.st_mode & 07777));
  CHECK(PE::IO::write_SVG(svg, m, uvm, so) == PE::OK && read_bytes(svg) == svg_ref.str(), "write svg");
  CHECK(::symlink("out.svg", dir.file("link.svg").c_str()) == 0, "symlink");
  write_bytes(svg, "old");
  CHECK(PE::IO::write_SVG(dir.file("link.svg"), m, uvm, "grid") == PE::OK, "write through a link");
  CHECK(::lstat(dir.file("link.svg").c_str(), &st) == 0 && S_ISLNK(st.st_mode) && read_bytes(svg) == svg_ref.str(), "link replaced");
  CHECK(listing(dir) == std::vector<std::string>({"link.svg", "out.obj", "out.svg"}), "unexpected files");

  // devices are written in place and stay devices; a full device is an error
  CHECK(PE::IO::write_OBJ_with_uv("/dev/null", m, uvm) == PE::OK && is_char_device("/dev/null"), "/dev/null");
  CHECK(PE::IO::write_SVG("/dev/null", m, uvm, so) == PE::OK && is_char_device("/dev/null"), "/dev/null svg");
  if(is_char_device("/dev/full"))
  {
    CHECK(PE::IO::write_OBJ_with_uv("/dev/full", m, uvm) == PE::ERROR_CANNOT_WRITE_FILE && is_char_device("/dev/full"), "/dev/full");
    CHECK(PE::IO::write_SVG("/dev/full", m, uvm, so) == PE::ERROR_CANNOT_WRITE_FILE && is_char_device("/dev/full"), "/dev/full svg");
  }

  // a folder, a missing folder
  std::filesystem::create_directory(dir.file("folder.obj"));
  CHECK(PE::IO::write_OBJ_with_uv(dir.file("folder.obj"), m, uvm) == PE::ERROR_CANNOT_WRITE_FILE && is_folder(dir.file("folder.obj")), "folder");
  CHECK(PE::IO::write_SVG(dir.file("folder.obj"), m, uvm, so) == PE::ERROR_CANNOT_WRITE_FILE && is_folder(dir.file("folder.obj")), "folder svg");
  CHECK(PE::IO::write_OBJ_with_uv(dir.file("no_such_folder/x.obj"), m, uvm) == PE::ERROR_CANNOT_WRITE_FILE, "missing folder");

  // a file size limit (SIGXFSZ ignored, so that write() fails with EFBIG): errors, the old
  // content intact, the new names absent, no temporary left
  write_bytes(obj, "old content\n");
  void (*old_handler)(int) = std::signal(SIGXFSZ, SIG_IGN);
  struct rlimit old_limit;
  CHECK(::getrlimit(RLIMIT_FSIZE, &old_limit) == 0, "getrlimit");
  struct rlimit lim = old_limit;
  lim.rlim_cur = 64 * 1024;
  CHECK(::setrlimit(RLIMIT_FSIZE, &lim) == 0, "setrlimit");
  const PE::Error_code e_old = PE::IO::write_OBJ_with_uv(obj, m, uvm);
  const PE::Error_code e_new = PE::IO::write_OBJ_with_uv(dir.file("new.obj"), m, uvm);
  const PE::Error_code e_svg = PE::IO::write_SVG(dir.file("new.svg"), m, uvm, so);
  const PE::Error_code e_svg_old = PE::IO::write_SVG(svg, m, uvm, "grid");
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);
  CHECK(e_old == PE::ERROR_CANNOT_WRITE_FILE && read_bytes(obj) == "old content\n", "existing target: " << PE::get_error_name(e_old));
  CHECK(e_new == PE::ERROR_CANNOT_WRITE_FILE && !exists(dir.file("new.obj")), "new target: " << PE::get_error_name(e_new));
  CHECK(e_svg == PE::ERROR_CANNOT_WRITE_FILE && !exists(dir.file("new.svg")), "new svg: " << PE::get_error_name(e_svg));
  CHECK(e_svg_old == PE::ERROR_CANNOT_WRITE_FILE && read_bytes(svg) == svg_ref.str(), "existing svg: " << PE::get_error_name(e_svg_old));
  CHECK(listing(dir) == std::vector<std::string>({"folder.obj", "link.svg", "out.obj", "out.svg"}), "temporary files left");

  // data errors leave nothing either
  uvm[*vertices(m).begin()] = Point_2(std::numeric_limits<double>::quiet_NaN(), 0);
  CHECK(PE::IO::write_OBJ_with_uv(dir.file("nan.obj"), m, uvm) == PE::ERROR_NON_FINITE_COORDINATES && !exists(dir.file("nan.obj")), "nan");
  CHECK(listing(dir).size() == 4, "temporary left after a data error");

  // names of this process's descriptors (/proc/self/fd/N, /dev/fd/N, as /dev/stdout is), written through the
  // descriptor: a pipe (its link's target "pipe:[N]" is no path); a file that a shell opened with `>` (the content
  // where the descriptor stands, what is written to it afterwards after it) or `>>`, never replaced
  namespace AO = PE::IO::internal;
  auto text = [](const std::string& t) { return [t](std::ostream& os) { os << t; return PE::OK; }; };
  int fds[2];
  CHECK(::pipe(fds) == 0, "pipe");
  const std::string pipe_link = "/proc/self/fd/" + std::to_string(fds[1]);
  const bool proc = exists(pipe_link);
  if(proc)
  {
    CHECK(AO::write_file_atomically(pipe_link, text("through a pipe\n")) == PE::OK, "a pipe through a descriptor link");
    ::close(fds[1]);
    char buffer[64] = { 0 };
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer - 1);
    CHECK(n == 15 && std::string(buffer) == "through a pipe\n", "pipe content: " << n);
    for(const int flags : { O_WRONLY | O_TRUNC, O_WRONLY | O_APPEND })
    {
      const std::string log = dir.file("log.txt");
      write_bytes(log, "old\n");
      struct stat before, after;
      CHECK(::stat(log.c_str(), &before) == 0, "stat");
      const int fd = ::open(log.c_str(), flags);
      CHECK(fd >= 0, "open");
      CHECK(::write(fd, "first\n", 6) == 6, "write");
      // through /dev/fd/N, then through a link of the user's to /proc/self/fd/N
      const PE::Error_code e1 = AO::write_file_atomically("/dev/fd/" + std::to_string(fd), text("second\n"));
      const std::string link = dir.file("fd_link");
      CHECK(::symlink(("/proc/self/fd/" + std::to_string(fd)).c_str(), link.c_str()) == 0, "symlink");
      const PE::Error_code e2 = AO::write_file_atomically(link, text("third\n"));
      CHECK(::write(fd, "fourth\n", 7) == 7, "write");
      ::close(fd);
      ::unlink(link.c_str());
      const std::string expected = std::string(flags & O_APPEND ? "old\n" : "") + "first\nsecond\nthird\nfourth\n";
      CHECK(e1 == PE::OK && e2 == PE::OK && read_bytes(log) == expected, "a file through its descriptor: " << read_bytes(log));
      CHECK(::stat(log.c_str(), &after) == 0 && after.st_ino == before.st_ino, "a file through its descriptor replaced");
      ::unlink(log.c_str());
    }
  }
  else
    ::close(fds[1]);
  ::close(fds[0]);

  // several files all or none: a failing device, a failing writer: no file written, the failing one's index
  const std::string fa = dir.file("a.txt"), fb = dir.file("b.txt"), fc = dir.file("c.txt");
  const std::size_t before_together = listing(dir).size();
  std::vector<AO::Atomic_output_file> files = { { fa, text("a") }, { fb, text("b") }, { fc, text("c") } };
  // names are checked before anything is written: a descriptor that is not open, a folder
  files[2].name = "/dev/fd/" + std::to_string(fds[0]); // closed above
  AO::Atomic_output_result checked = AO::write_files_atomically(files);
  CHECK(checked.code == PE::ERROR_CANNOT_WRITE_FILE && checked.failed == 2 && listing(dir).size() == before_together, "a closed descriptor");
  files[2].name = dir.file("folder.obj");
  checked = AO::write_files_atomically(files);
  CHECK(checked.code == PE::ERROR_CANNOT_WRITE_FILE && checked.failed == 2 && listing(dir).size() == before_together, "a folder");
  const int read_only = ::open(obj.c_str(), O_RDONLY); // a descriptor open for reading only
  CHECK(read_only >= 0, "open");
  files[2].name = "/dev/fd/" + std::to_string(read_only);
  checked = AO::write_files_atomically(files);
  ::close(read_only);
  CHECK(checked.code == PE::ERROR_CANNOT_WRITE_FILE && checked.failed == 2 && listing(dir).size() == before_together,
        "a descriptor open for reading only");
  files[2].name = fc;
  if(is_char_device("/dev/full"))
  {
    files[1].name = "/dev/full";
    const AO::Atomic_output_result r = AO::write_files_atomically(files);
    CHECK(r.code == PE::ERROR_CANNOT_WRITE_FILE && r.failed == 1 && !exists(fa) && !exists(fc), "together, /dev/full");
  }
  files[1] = { fb, [](std::ostream& os) { os << "partial"; return PE::ERROR_NON_FINITE_COORDINATES; } };
  const AO::Atomic_output_result data = AO::write_files_atomically(files);
  CHECK(data.code == PE::ERROR_NON_FINITE_COORDINATES && data.failed == 1, "together, a data error: " << PE::get_error_name(data.code));
  CHECK(listing(dir).size() == before_together, "together: a file or a temporary left after a failure");
  files[1] = { "/dev/null", text("b") };
  const AO::Atomic_output_result ok = AO::write_files_atomically(files);
  CHECK(ok.code == PE::OK && read_bytes(fa) == "a" && read_bytes(fc) == "c" && listing(dir).size() == before_together + 2,
        "together, written");
  std::cout << "writers: no partial file (/dev/full, file size limit, folder), devices written in place, descriptors"
            << (proc ? "" : " (no /proc: not checked)") << ", several files all or none: OK" << std::endl;
  return EXIT_SUCCESS;
}

// ---------------------------------------------------------------------------
// SVG with distortion colors and an inset

// the text of the <text> element with the id `id` ("" if none)
std::string svg_text(const std::string& svg, const std::string& id)
{
  const std::size_t k = svg.find("id=\"" + id + "\"");
  if(k == std::string::npos) return std::string();
  const std::size_t b = svg.find('>', k), e = svg.find("</text>", k);
  if(b == std::string::npos || e == std::string::npos || e < b) return std::string();
  return svg.substr(b + 1, e - b - 1);
}

std::size_t occurrences(const std::string& s, const std::string& what)
{
  std::size_t n = 0;
  for(std::size_t k = s.find(what); k != std::string::npos; k = s.find(what, k + 1)) ++n;
  return n;
}

// A big triangle (the border) around a small hexagon of radius r with its center: the failure
// region of a Tutte map often is this small. With `flip`, the center leaves the hexagon.
void make_tiny_region(Mesh& m, UV_map uvm, double r, bool flip)
{
  std::vector<vertex_descriptor> big, hex;
  const double c[3][2] = { {0, 0}, {1, 0}, {0.5, 0.8660254037844386} };
  for(int k = 0; k < 3; ++k) big.push_back(m.add_vertex(Point_3(c[k][0], c[k][1], 0)));
  const double cx = 0.5, cy = 0.3;
  for(int k = 0; k < 6; ++k)
    hex.push_back(m.add_vertex(Point_3(cx + r * std::cos(k * M_PI / 3), cy + r * std::sin(k * M_PI / 3), 0)));
  const vertex_descriptor center = m.add_vertex(Point_3(cx, cy, 0));
  for(int k = 0; k < 6; ++k) m.add_face(center, hex[std::size_t(k)], hex[std::size_t((k + 1) % 6)]);
  // hexagon vertices 0,1 face corner 2 (top), 2,3 corner 0 (left), 4,5 corner 1 (right)
  m.add_face(hex[0], big[2], hex[1]); m.add_face(hex[1], big[2], hex[2]);
  m.add_face(hex[2], big[2], big[0]); m.add_face(hex[2], big[0], hex[3]); m.add_face(hex[3], big[0], hex[4]);
  m.add_face(hex[4], big[0], big[1]); m.add_face(hex[4], big[1], hex[5]); m.add_face(hex[5], big[1], hex[0]);
  m.add_face(hex[0], big[1], big[2]);
  for(vertex_descriptor v : vertices(m)) uvm[v] = Point_2(m.point(v).x(), m.point(v).y());
  if(flip) uvm[center] = Point_2(cx + 2 * r, cy + 0.1 * r);
}

int test_svg_distortion_and_inset(const std::string& out_dir)
{
  // format_number is printf's %.*g in the C locale
  {
    const double values[] = { 4, 4.000001, 12.345, 1234.5678, 1.1e15, 6.2e-7, -3.25, 0, 99.95, 123456789 };
    for(double x : values)
      for(int d : { 3, 6 })
      {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.*g", d, x);
        CHECK(PE::IO::format_number(x, d) == buf, x << ": " << PE::IO::format_number(x, d) << " vs " << buf);
      }
    CHECK(PE::IO::format_number(std::numeric_limits<double>::infinity()) == "inf"
          && PE::IO::format_number(-std::numeric_limits<double>::infinity()) == "-inf"
          && PE::IO::format_number(std::numeric_limits<double>::quiet_NaN()) == "nan"
          && PE::IO::format_number(-0.0) == "0", "non-finite values, negative zero");
  }

  // a valid map of a curved grid: the legend's numbers are the report's; no inset without flipped faces
  Mesh m;
  make_bump_grid(m, 9);
  UV_map uvm = m.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
  for(vertex_descriptor v : vertices(m)) uvm[v] = Point_2(m.point(v).x(), m.point(v).y() * (1 + 0.3 * m.point(v).x()));
  PE::Embedding_report rep = PE::check_embedding(m, uvm);
  CHECK(rep.is_valid() && rep.has_3d_energy && std::isfinite(rep.mean_energy_3d) && rep.mean_energy_3d > 4, rep.summary());
  PE::IO::SVG_options o;
  o.title = "bump";
  o.color_by_distortion = true;
  o.inset = true;
  for(int digits : { 3, 6 })
  {
    o.significant_digits = digits;
    std::ostringstream out;
    CHECK(PE::IO::write_SVG(out, m, uvm, o) == PE::OK, "svg");
    const std::string svg = out.str();
    CHECK(svg_text(svg, "pe-energy-mean") == "mean " + PE::IO::format_number(rep.mean_energy_3d, digits), svg_text(svg, "pe-energy-mean"));
    CHECK(svg_text(svg, "pe-energy-max") == "max " + PE::IO::format_number(rep.max_energy_3d, digits), svg_text(svg, "pe-energy-max"));
    CHECK(svg_text(svg, "pe-energy-median") == "median " + PE::IO::format_number(rep.distortion.symmetric_dirichlet_quantiles[0], digits),
          svg_text(svg, "pe-energy-median"));
    const std::string min_text = svg_text(svg, "pe-energy-min");
    CHECK(min_text.size() > 4 && std::stod(min_text.substr(4)) >= 3.99 && std::stod(min_text.substr(4)) <= rep.mean_energy_3d, min_text);
    CHECK(svg_text(svg, "pe-count-flipped") == "flipped: 0" && svg_text(svg, "pe-count-faces") == "faces: " + std::to_string(rep.faces), "counts");
    CHECK(svg.find("pe-inset") == std::string::npos, "an inset without flipped or degenerate faces");
    CHECK(occurrences(svg, "<path fill=\"") <= std::size_t(o.color_levels) && occurrences(svg, "<path fill=\"") >= 3,
          "faces are grouped by color: " << occurrences(svg, "<path fill=\""));
    bool checked = false;
    CHECK(xml_is_valid(svg, checked), "invalid XML");
  }

  // flipped faces: the counts are the report's, the mean and max are infinite, an inset is drawn
  {
    const std::size_t n = 9;
    uvm[vertex_descriptor(std::uint32_t(3 * n + 3))] = Point_2(0.62, 0.55);
    rep = PE::check_embedding(m, uvm);
    CHECK(rep.flipped > 0 && !rep.is_valid(), rep.summary());
    o.significant_digits = 3;
    std::ostringstream out;
    CHECK(PE::IO::write_SVG(out, m, uvm, o) == PE::OK, "svg");
    const std::string svg = out.str();
    CHECK(svg_text(svg, "pe-count-flipped") == "flipped: " + std::to_string(rep.flipped), svg_text(svg, "pe-count-flipped"));
    CHECK(svg_text(svg, "pe-count-degenerate") == "degenerate: " + std::to_string(rep.degenerate), "degenerate");
    CHECK(svg_text(svg, "pe-energy-mean") == "mean inf" && PE::IO::format_number(rep.mean_energy_3d) == "inf", "mean");
    CHECK(svg.find("<g id=\"pe-inset\">") != std::string::npos && svg.find("id=\"pe-inset-region\"") != std::string::npos, "no inset");
    o.inset = false;
    std::ostringstream out2;
    CHECK(PE::IO::write_SVG(out2, m, uvm, o) == PE::OK && out2.str().find("pe-inset") == std::string::npos, "inset not asked for");
    o.inset = true;
  }

  // a failure region 10^-6 of the view: the inset chooses its own scale, flipped faces inside it
  {
    Mesh t;
    UV_map tuv = t.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
    make_tiny_region(t, tuv, 1e-6, true);
    rep = PE::check_embedding(t, tuv);
    CHECK(rep.status == PE::OK && rep.flipped > 0, rep.summary());
    std::ostringstream out;
    o.title = "a failure region of 1e-6";
    CHECK(PE::IO::write_SVG(out, t, tuv, o) == PE::OK, "svg");
    const std::string svg = out.str();
    const std::size_t z = svg.find("zoom &#215;");
    CHECK(z != std::string::npos, "zoom label");
    const double zoom = std::stod(svg.substr(z + 11, 12));
    CHECK(zoom > 1e4, "zoom " << zoom);
    const std::string inset = svg.substr(svg.find("<g id=\"pe-inset\">"));
    CHECK(inset.find("class=\"pe-flipped\"") != std::string::npos, "flipped faces not drawn in the inset");
    CHECK(svg_text(svg, "pe-count-flipped") == "flipped: " + std::to_string(rep.flipped), "count");
    if(!out_dir.empty()) { std::ofstream f(out_dir + "/tiny_region.svg"); f << svg; }
    // the same map without the flip: no inset
    Mesh t2;
    UV_map tuv2 = t2.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
    make_tiny_region(t2, tuv2, 1e-6, false);
    std::ostringstream out2;
    CHECK(PE::IO::write_SVG(out2, t2, tuv2, o) == PE::OK && out2.str().find("pe-inset") == std::string::npos, "inset of a valid map");
  }

  // malformed options and unusable meshes: an error code, nothing written
  {
    std::vector<PE::IO::SVG_options> bad(7, o);
    bad[0].size = std::numeric_limits<double>::quiet_NaN();
    bad[1].flipped_color = "red";
    bad[2].significant_digits = 0;
    bad[3].color_levels = 1;
    bad[4].coordinate_decimals = 7;
    bad[5].edge_width = -1;
    bad[6].inset_size = 1e9;
    for(const PE::IO::SVG_options& b : bad)
    {
      std::ostringstream out;
      CHECK(PE::IO::write_SVG(out, m, uvm, b) == PE::ERROR_WRONG_PARAMETER && out.str().empty(), "bad options accepted");
    }
    Temp_dir dir("svg");
    CHECK(PE::IO::write_SVG(dir.file("bad.svg"), m, uvm, bad[1]) == PE::ERROR_WRONG_PARAMETER && dir.count() == 0, "file written");

    Mesh tet; // closed: not a disk
    UV_map tuv = tet.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
    CGAL::make_tetrahedron(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(0, 0, 1), tet);
    for(vertex_descriptor v : vertices(tet)) tuv[v] = Point_2(tet.point(v).x() + 0.3 * tet.point(v).z(), tet.point(v).y());
    std::ostringstream out;
    CHECK(PE::IO::write_SVG(out, tet, tuv, o) == PE::ERROR_NOT_A_DISK && out.str().empty(), "not a disk");
    o.color_by_distortion = false;
    CHECK(PE::IO::write_SVG(out, tet, tuv, o) == PE::OK, "not a disk, no distortion");
    o.color_by_distortion = true;
    Mesh flat;
    UV_map fuv = flat.add_property_map<vertex_descriptor, Point_2>("h:uv").first;
    make_grid(flat, fuv, 4);
    for(vertex_descriptor v : vertices(flat)) flat.point(v) = Point_3(1, 1, 1);
    std::ostringstream out2;
    CHECK(PE::IO::write_SVG(out2, flat, fuv, o) == PE::ERROR_DEGENERATE_3D_FACE && out2.str().empty(), "no 3D area");
  }
  std::cout << "SVG with distortion colors and inset: OK (legend = check_embedding's numbers, inset zoom on a 1e-6 region)" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string data_dir = argc > 1 ? argv[1] : std::string();
  const std::string out_dir = argc > 2 ? argv[2] : std::string(); // optional: where to leave pictures
  const Seam_grid g = make_seam_grid();
  RUN(test_round_trip_surface_mesh(g));
  RUN(test_round_trip_polyhedron(g));
  RUN(test_exact_uv(g));
  RUN(test_malformed());
  RUN(test_fuzz(g));
  RUN(test_read_polygon_mesh_errors());
  RUN(test_read_polygon_mesh_memory_bound());
  RUN(test_read_polygon_mesh_formats(data_dir));
  RUN(test_read_polygon_mesh_fuzz());
  RUN(test_data_files());
  RUN(test_svg());
  RUN(test_svg_distortion_and_inset(out_dir));
  RUN(test_atomic_writes());
  // ctest always gives the libcgal-demo data folder: without it the round trip on a real mesh would not run
  CHECK(!data_dir.empty(), "test_io DATA_DIR: the data directory argument is missing");
  RUN(test_mushroom(data_dir));
  std::cout << "test_io: all checks passed" << std::endl;
  return EXIT_SUCCESS;
}
