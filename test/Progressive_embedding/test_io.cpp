// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

// Tests of IO/OBJ_with_uv.h and IO/SVG.h.
// Usage: test_io [data_dir]   (data_dir contains meshes/mushroom.off; optional)

#include <CGAL/Progressive_embedding/IO/OBJ_with_uv.h>
#include <CGAL/Progressive_embedding/IO/SVG.h>
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

#include <cmath>
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
  if(std::system("python3 -c \"import xml.dom.minidom\" > /dev/null 2>&1") != 0) return true;
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
  std::size_t n_polygons = 0, n_circles = 0;
  for(std::size_t k = svg.find("<polygon"); k != std::string::npos; k = svg.find("<polygon", k + 1)) ++n_polygons;
  for(std::size_t k = svg.find("<circle"); k != std::string::npos; k = svg.find("<circle", k + 1)) ++n_circles;
  CHECK(n_polygons == num_faces(m), "one polygon per face: " << n_polygons);
  CHECK(n_circles == neg + zero, "markers");
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
  CHECK(out3.str().find(">non-finite: 6</text>") != std::string::npos, "non-finite count");
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

} // namespace

int main(int argc, char** argv)
{
  const Seam_grid g = make_seam_grid();
  RUN(test_round_trip_surface_mesh(g));
  RUN(test_round_trip_polyhedron(g));
  RUN(test_exact_uv(g));
  RUN(test_malformed());
  RUN(test_fuzz(g));
  RUN(test_svg());
  if(argc > 1)
    RUN(test_mushroom(argv[1]));
  else
    std::cout << "no data directory given: mushroom.off round trip skipped" << std::endl;
  std::cout << "test_io: all checks passed" << std::endl;
  return EXIT_SUCCESS;
}
