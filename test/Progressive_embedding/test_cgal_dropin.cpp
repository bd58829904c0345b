// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Certified_parameterizer_3 around CGAL's fixed-border parameterizers: the user's map is kept when it
// is certified (bit for bit), repaired when it is not, and only the component of the border halfedge
// is mapped (charts of one mesh, Seam_mesh); components with holes get a certified multiply connected map.
//
// Usage: test_cgal_dropin data_dir   (data_dir contains libcgal-demo's meshes/)

#include <CGAL/Progressive_embedding/Certified_parameterizer_3.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_parameterizer_3.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/IO/OBJ_with_uv.h>

#include "test_util.h"

#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Iterative_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Unique_hash_map.h>

#include <boost/property_map/property_map.hpp>

#include <set>
#include <sstream>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef Epick::Point_2 Point_2;

// a closed mesh cut open by removing its last face: CGAL's maps of it are known to fold
template <class Mesh>
bool read_cut(const std::string& fname, Mesh& m)
{
  if(!CGAL::IO::read_polygon_mesh(fname, m) || !CGAL::is_closed(m)) return false;
  typename boost::graph_traits<Mesh>::face_descriptor last = *faces(m).begin();
  for(auto f : faces(m)) last = f;
  CGAL::Euler::remove_face(halfedge(last, m), m);
  return true;
}

// CGAL's parameterizer alone, then wrapped; the wrapped result must be certified, repaired iff CGAL's was invalid
template <class Mesh, class Param>
int wrap_one(Mesh& m, const char* name, int& cgal_invalid)
{
  const auto bhd = CGAL::Polygon_mesh_processing::longest_border(m).first;
  auto uv = make_uv_map(m, Point_2());
  const SMP::Error_code e0 = SMP::parameterize(m, Param(), bhd, uv);
  const bool cgal_valid = (e0 == SMP::OK) && PE::check_embedding(m, uv).is_valid();
  PE::Certified_parameterizer_3<Mesh, Param> p;
  const SMP::Error_code e1 = SMP::parameterize(m, p, bhd, uv);
  const PE::Embedding_report r = PE::check_embedding(m, uv);
  std::cout << mesh_name<Mesh>() << " " << name << ": CGAL " << (cgal_valid ? "valid" : "INVALID")
            << ", wrapped: " << SMP::get_error_message(e1) << (p.repaired() ? " (repaired)" : "")
            << ", " << r.summary() << std::endl;
  CHECK(e1 == SMP::OK, name);
  CHECK(r.is_valid(), name);
  CHECK(p.statistics().report.is_valid(), name);
  CHECK(p.repaired() == !cgal_valid, name);
  if(!cgal_valid) ++cgal_invalid;
  return EXIT_SUCCESS;
}

template <class Mesh>
int test_wrapped_parameterizers(const std::string& dir)
{
  int cgal_invalid = 0;
  for(const char* f : {"bull.off", "dino.off"})
  {
    Mesh m;
    CHECK(read_cut(dir + "/meshes/" + f, m), f);
    RUN((wrap_one<Mesh, SMP::Barycentric_mapping_parameterizer_3<Mesh> >(m, "Barycentric_mapping", cgal_invalid)));
    RUN((wrap_one<Mesh, SMP::Mean_value_coordinates_parameterizer_3<Mesh> >(m, "Mean_value_coordinates", cgal_invalid)));
    RUN((wrap_one<Mesh, SMP::Discrete_conformal_map_parameterizer_3<Mesh> >(m, "Discrete_conformal_map", cgal_invalid)));
    RUN((wrap_one<Mesh, SMP::Discrete_authalic_parameterizer_3<Mesh> >(m, "Discrete_authalic", cgal_invalid)));
  }
  // the cut bull and dino fold under CGAL's barycentric map at least
  CHECK(cgal_invalid >= 2, cgal_invalid);
  return EXIT_SUCCESS;
}

// Iterative_authalic_parameterizer_3's four-argument overload is forwarded
int test_iterative_authalic(const std::string& dir)
{
  typedef SMP::Iterative_authalic_parameterizer_3<Surface_mesh> Param;
  Surface_mesh m;
  CHECK(read_cut(dir + "/meshes/bull.off", m), "bull");
  const auto bhd = CGAL::Polygon_mesh_processing::longest_border(m).first;
  auto uv = m.add_property_map<Surface_mesh::Vertex_index, Point_2>("v:uv").first;
  PE::Certified_parameterizer_3<Surface_mesh, Param> p;
  const SMP::Error_code e = p.parameterize(m, bhd, uv, 5u);
  std::cout << "Iterative_authalic (5 iterations): " << SMP::get_error_message(e)
            << (p.repaired() ? " (repaired)" : "") << std::endl;
  CHECK(e == SMP::OK, "iterative authalic");
  CHECK(PE::check_embedding(m, uv).is_valid(), "iterative authalic");
  return EXIT_SUCCESS;
}

// a valid map of the wrapped parameterizer is returned bit for bit (NEVER and WHEN_REPAIRED)
int test_valid_unchanged(const std::string& dir)
{
  typedef SMP::Mean_value_coordinates_parameterizer_3<Surface_mesh> Param;
  typedef PE::Certified_parameterizer_3<Surface_mesh, Param> Wrapped;
  Surface_mesh m;
  CHECK(CGAL::IO::read_polygon_mesh(dir + "/meshes/mushroom.off", m), "mushroom");
  const auto bhd = CGAL::Polygon_mesh_processing::longest_border(m).first;
  auto a = m.add_property_map<Surface_mesh::Vertex_index, Point_2>("v:a").first;
  CHECK(SMP::parameterize(m, Param(), bhd, a) == SMP::OK, "CGAL");
  CHECK(PE::check_embedding(m, a).is_valid(), "CGAL's mean value map of the mushroom is valid");
  for(Wrapped::Optimization o : {Wrapped::Optimization::NEVER, Wrapped::Optimization::WHEN_REPAIRED})
  {
    auto b = m.add_property_map<Surface_mesh::Vertex_index, Point_2>("v:b", Point_2(9, 9)).first;
    Wrapped p(Param(), o);
    CHECK(SMP::parameterize(m, p, bhd, b) == SMP::OK, "wrapped");
    CHECK(!p.repaired() && !p.optimized(), "valid map untouched");
    for(auto v : vertices(m)) CHECK(get(a, v) == get(b, v), "bit-identical uv");
    m.remove_property_map(b);
  }
  Wrapped p(Param(), Wrapped::Optimization::ALWAYS);
  auto c = m.add_property_map<Surface_mesh::Vertex_index, Point_2>("v:c").first;
  CHECK(SMP::parameterize(m, p, bhd, c) == SMP::OK && p.optimized(), "ALWAYS optimizes");
  CHECK(PE::check_embedding(m, c).is_valid(), "optimized map certified");
  std::cout << "valid mean value map of the mushroom returned bit for bit" << std::endl;
  return EXIT_SUCCESS;
}

// two copies of the cut bull in one Surface_mesh: each call maps one chart, the other is untouched
int test_two_charts(const std::string& dir)
{
  typedef SMP::Barycentric_mapping_parameterizer_3<Surface_mesh> Param;
  Surface_mesh one, two;
  CHECK(read_cut(dir + "/meshes/bull.off", one), "bull");
  CGAL::copy_face_graph(one, two);
  CGAL::copy_face_graph(one, two);
  CHECK(count_faces(two) == 2 * count_faces(one), "two copies");
  std::vector<Surface_mesh::Halfedge_index> borders;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(two, std::back_inserter(borders));
  CHECK(borders.size() == 2, borders.size());
  auto uv = two.add_property_map<Surface_mesh::Vertex_index, Point_2>("v:uv", Point_2(7, 7)).first;
  PE::Certified_parameterizer_3<Surface_mesh, Param> p;
  std::size_t untouched_after_first = 0;
  for(std::size_t c = 0; c < 2; ++c)
  {
    CHECK(SMP::parameterize(two, p, borders[c], uv) == SMP::OK, "chart " << c);
    CHECK(p.number_of_faces() == count_faces(one), p.number_of_faces() << " vs " << count_faces(one));
    CHECK(p.number_of_border_cycles() == 1, "one border");
    CHECK(p.statistics().report.is_valid(), "chart certified");
    CHECK(p.repaired(), "CGAL's map of the cut bull folds");
    if(c == 0)
      for(auto v : vertices(two)) if(get(uv, v) == Point_2(7, 7)) ++untouched_after_first;
  }
  CHECK(untouched_after_first == num_vertices(one), untouched_after_first);
  std::cout << "two charts mapped one at a time, " << untouched_after_first << " vertices untouched by the first" << std::endl;
  // the package's own parameterizer maps one chart at a time too
  auto uv2 = two.add_property_map<Surface_mesh::Vertex_index, Point_2>("v:uv2", Point_2(7, 7)).first;
  PE::Progressive_embedding_parameterizer_3<Surface_mesh> q;
  for(std::size_t c = 0; c < 2; ++c)
  {
    CHECK(SMP::parameterize(two, q, borders[c], uv2) == SMP::OK, "Progressive_embedding_parameterizer_3, chart " << c);
    CHECK(q.statistics().report.is_valid() && q.statistics().report.faces == count_faces(one), "chart certified");
    std::size_t untouched = 0;
    for(auto v : vertices(two)) if(get(uv2, v) == Point_2(7, 7)) ++untouched;
    CHECK(untouched == (c == 0 ? num_vertices(one) : 0), "only the chart of the border halfedge is written");
  }
  return EXIT_SUCCESS;
}

// a component with holes: a certified multiply connected map, CGAL's folded map repaired
int test_holes(const std::string& dir)
{
  typedef SMP::Mean_value_coordinates_parameterizer_3<Surface_mesh> Param;
  Surface_mesh m;
  // bull cut open (CGAL's maps of it fold), with two more holes: interior faces far from the border and
  // from each other
  CHECK(read_cut(dir + "/meshes/bull.off", m), "bull");
  const auto bhd = CGAL::Polygon_mesh_processing::longest_border(m).first; // the cut: the outer border
  std::vector<Surface_mesh::Face_index> removed;
  std::set<Surface_mesh::Vertex_index> used;
  for(auto f : faces(m))
  {
    if(removed.size() == 2) break;
    if(std::size_t(f) % 4000 != 2000) continue;
    bool ok = true;
    for(auto v : vertices_around_face(halfedge(f, m), m))
    {
      if(is_border(v, m) || used.count(v)) ok = false;
      for(auto w : vertices_around_target(halfedge(v, m), m)) if(is_border(w, m) || used.count(w)) ok = false;
    }
    if(!ok) continue;
    removed.push_back(f);
    for(auto v : vertices_around_face(halfedge(f, m), m))
      for(auto w : vertices_around_target(halfedge(v, m), m)) used.insert(w);
  }
  CHECK(removed.size() == 2, "two interior faces");
  for(auto f : removed) CGAL::Euler::remove_face(halfedge(f, m), m);
  const std::size_t n0 = m.number_of_vertices();

  // CGAL's own map treats the hole vertices as interior ones
  auto cgal_uv = m.add_property_map<Surface_mesh::Vertex_index, Point_2>("v:cgal_uv").first;
  CHECK(SMP::parameterize(m, Param(), bhd, cgal_uv) == SMP::OK, "CGAL's map");
  const PE::Embedding_report rc = PE::check_embedding(m, cgal_uv, PE::parameters::multiply_connected(true));
  std::cout << "bull cut open with 2 holes, CGAL's mean value map: " << rc.summary() << std::endl;

  auto uv = m.add_property_map<Surface_mesh::Vertex_index, Point_2>("v:uv").first;
  PE::Certified_parameterizer_3<Surface_mesh, Param> p;
  const SMP::Error_code e = SMP::parameterize(m, p, bhd, uv);
  const PE::Embedding_report r = PE::check_embedding(m, uv, PE::parameters::multiply_connected(true));
  std::cout << "wrapped: " << SMP::get_error_message(e) << (p.repaired() ? " (repaired)" : " (kept)") << ", "
            << p.number_of_border_cycles() << " border cycles, " << r.summary() << std::endl;
  CHECK(e == SMP::OK && p.error_code() == PE::OK && p.number_of_border_cycles() == 3, "mapped, 3 border cycles");
  CHECK(r.status == PE::OK && r.is_valid() && r.border_cycles == 3 && r.flipped == 0 && r.degenerate == 0, "certified with holes");
  CHECK(p.repaired() == !rc.is_valid(), "repaired iff CGAL's map is not valid");
  for(auto h : halfedges_around_face(bhd, m))
    CHECK(get(uv, target(h, m)) == get(cgal_uv, target(h, m)), "outer border as CGAL computed it");
  CHECK(m.number_of_vertices() == n0, "no vertex added");
  // the package's own parameterizer too
  auto uv2 = m.add_property_map<Surface_mesh::Vertex_index, Point_2>("v:uv2").first;
  PE::Progressive_embedding_parameterizer_3<Surface_mesh> q;
  CHECK(SMP::parameterize(m, q, bhd, uv2) == SMP::OK, "Progressive_embedding_parameterizer_3 with holes");
  const PE::Embedding_report r2 = PE::check_embedding(m, uv2, PE::parameters::multiply_connected(true));
  std::cout << "Progressive_embedding_parameterizer_3: " << r2.summary() << std::endl;
  CHECK(r2.is_valid() && r2.border_cycles == 3, "certified with holes");

  // a closed component has no border to map
  Surface_mesh closed;
  CHECK(CGAL::IO::read_polygon_mesh(dir + "/meshes/bull.off", closed), "bull");
  auto cuv = closed.add_property_map<Surface_mesh::Vertex_index, Point_2>("v:uv", Point_2(3, 3)).first;
  PE::Certified_parameterizer_3<Surface_mesh, Param> pc;
  CHECK(SMP::parameterize(closed, pc, *halfedges(closed).begin(), cuv) == SMP::ERROR_NO_TOPOLOGICAL_DISC, "closed refused");
  CHECK(pc.error_code() == PE::ERROR_NOT_A_DISK && pc.number_of_border_cycles() == 0, "ERROR_NOT_A_DISK");
  for(auto v : vertices(closed)) CHECK(get(cuv, v) == Point_2(3, 3), "uv untouched");
  return EXIT_SUCCESS;
}

// Seam_mesh over two cut bulls, with a seam cut into the first: two charts, each certified
int test_seam_mesh(const std::string& dir)
{
  typedef Surface_mesh::Edge_index                              SM_edge;
  typedef Surface_mesh::Vertex_index                            SM_vertex;
  typedef Surface_mesh::Halfedge_index                          SM_halfedge;
  typedef Surface_mesh::Property_map<SM_edge, bool>             Seam_edge_pmap;
  typedef Surface_mesh::Property_map<SM_vertex, bool>           Seam_vertex_pmap;
  typedef CGAL::Seam_mesh<Surface_mesh, Seam_edge_pmap, Seam_vertex_pmap> Seam;
  typedef boost::graph_traits<Seam>::halfedge_descriptor        halfedge_descriptor;
  typedef SMP::Discrete_conformal_map_parameterizer_3<Seam>     Param;
  Surface_mesh one, sm;
  CHECK(read_cut(dir + "/meshes/bull.off", one), "bull");
  CGAL::copy_face_graph(one, sm);
  CGAL::copy_face_graph(one, sm);
  Seam_edge_pmap seam_edges = sm.add_property_map<SM_edge, bool>("e:on_seam", false).first;
  Seam_vertex_pmap seam_vertices = sm.add_property_map<SM_vertex, bool>("v:on_seam", false).first;
  Seam mesh(sm, seam_edges, seam_vertices);
  // a slit of two edges from a border vertex of the first copy into its interior
  SM_halfedge b0 = *halfedges(sm).begin();
  for(SM_halfedge h : halfedges(sm)) if(is_border(h, sm) && std::size_t(target(h, sm)) < num_vertices(one)) { b0 = h; break; }
  SM_vertex v0 = target(b0, sm), v1 = v0, v2 = v0;
  for(SM_halfedge h : halfedges_around_target(v0, sm))
    if(!is_border(source(h, sm), sm)) { v1 = source(h, sm); break; }
  for(SM_halfedge h : halfedges_around_target(v1, sm))
    if(!is_border(source(h, sm), sm) && source(h, sm) != v0) { v2 = source(h, sm); break; }
  CHECK(v1 != v0 && v2 != v0, "slit");
  mesh.add_seam(v0, v1);
  mesh.add_seam(v1, v2);
  typedef CGAL::Unique_hash_map<SM_halfedge, Point_2> UV_uhm;
  UV_uhm uv_uhm;
  boost::associative_property_map<UV_uhm> uv(uv_uhm);
  PE::Certified_parameterizer_3<Seam, Param> p;
  std::vector<SM_halfedge> borders;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(sm, std::back_inserter(borders));
  CHECK(borders.size() == 2, borders.size());
  for(SM_halfedge b : borders)
  {
    const halfedge_descriptor bhd(b);
    const SMP::Error_code e = SMP::parameterize(mesh, p, bhd, uv);
    std::cout << "Seam_mesh chart of " << p.number_of_faces() << " faces: " << SMP::get_error_message(e)
              << (p.repaired() ? " (repaired)" : "") << std::endl;
    CHECK(e == SMP::OK, "seam chart");
    CHECK(p.number_of_faces() == count_faces(one), p.number_of_faces() << " vs " << count_faces(one));
    CHECK(p.statistics().report.is_valid(), "seam chart certified");
  }
  // the OBJ of the cut mesh: one v per 3D vertex, one vt per seam side
  std::ostringstream obj;
  CHECK(PE::IO::write_OBJ_with_uv(obj, mesh, uv) == PE::OK, "write_OBJ_with_uv");
  std::istringstream in(obj.str());
  std::string line;
  std::size_t nv = 0, nvt = 0, nf = 0;
  while(std::getline(in, line))
  {
    if(line.rfind("v ", 0) == 0) ++nv;
    else if(line.rfind("vt ", 0) == 0) ++nvt;
    else if(line.rfind("f ", 0) == 0) ++nf;
  }
  std::cout << "Seam_mesh OBJ: " << nv << " v, " << nvt << " vt, " << nf << " f" << std::endl;
  CHECK(nv == num_vertices(sm), nv << " v lines, " << num_vertices(sm) << " vertices");
  CHECK(nvt == num_vertices(mesh), nvt << " vt lines, " << num_vertices(mesh) << " seam mesh vertices");
  CHECK(nvt == nv + 2, "the slit of two edges from the border doubles two vertices");
  CHECK(nf == 2 * count_faces(one), nf);
  return EXIT_SUCCESS;
}

int main(int argc, char** argv)
{
  if(argc < 2) { std::cerr << "usage: test_cgal_dropin data_dir" << std::endl; return EXIT_FAILURE; }
  const std::string dir = argv[1];
  const std::string which = argc > 2 ? argv[2] : "all";
  if(which == "all" || which == "wrapped") RUN(test_wrapped_parameterizers<Surface_mesh>(dir));
  if(which == "all" || which == "polyhedron") RUN(test_wrapped_parameterizers<Polyhedron>(dir));
  if(which == "all" || which == "iterative") RUN(test_iterative_authalic(dir));
  if(which == "all" || which == "valid") RUN(test_valid_unchanged(dir));
  if(which == "all" || which == "charts") RUN(test_two_charts(dir));
  if(which == "all" || which == "holes") RUN(test_holes(dir));
  if(which == "all" || which == "seam") RUN(test_seam_mesh(dir));
  std::cout << "all passed" << std::endl;
  return EXIT_SUCCESS;
}
