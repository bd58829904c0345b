// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// constrained_embedding()'s face_patch_map: every face of the refined mesh gets the patch it was
// mapped with (Surface_mesh property map, Polyhedron_3 dynamic map), the patches are connected,
// meet at every constrained vertex, and before the optimization each lies in its own convex polygon
// of the domain (the hulls of the patches tile the domain); the optimization changes no label;
// nothing is written on error.

#include <CGAL/Progressive_embedding/constrained_embedding.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>

#include "registry.h"
#include "../test_util.h"

#include <CGAL/convex_hull_2.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace PE = CGAL::Progressive_embedding;
typedef Epick::Point_2 Point_2;

// the patches of a labeled mesh: counts and checks that do not depend on the face order
struct Patch_summary
{
  std::size_t faces = 0;
  std::vector<std::size_t> sizes;  // faces per patch, sorted
  double hull_area = 0;            // sum of the areas of the convex hulls of the patches' uv
};

template <class Mesh, class UVM, class FPM, class VD>
int check_patches(const Mesh& m, const UVM& uv, const FPM& fpm, std::size_t patches,
                  const std::vector<std::pair<VD, Point_2> >& constraints, Patch_summary& out, const std::string& what)
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor FD;
  std::vector<std::size_t> sizes(patches, 0);
  std::vector<std::vector<Point_2> > points(patches);
  out.faces = 0;
  for(FD f : faces(m))
  {
    ++out.faces;
    const int p = get(fpm, f);
    CHECK(p >= 0 && std::size_t(p) < patches, what << ": every face has a patch in [0, patches)");
    ++sizes[std::size_t(p)];
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) points[std::size_t(p)].push_back(get(uv, v));
  }
  for(std::size_t p = 0; p < patches; ++p) CHECK(sizes[p] > 0, what << ": patch " << p << " has faces");
  // each patch is connected: a flood fill across the edges inside one patch reaches all its faces
  std::set<FD> seen;
  std::size_t components = 0;
  for(FD f0 : faces(m))
  {
    if(seen.count(f0)) continue;
    ++components;
    std::vector<FD> stack(1, f0);
    seen.insert(f0);
    while(!stack.empty())
    {
      const FD f = stack.back(); stack.pop_back();
      for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m))
      {
        const FD g = face(opposite(h, m), m);
        if(g == boost::graph_traits<Mesh>::null_face() || get(fpm, g) != get(fpm, f) || seen.count(g)) continue;
        seen.insert(g);
        stack.push_back(g);
      }
    }
  }
  CHECK(components == patches, what << ": each patch is connected (" << components << " components, " << patches << " patches)");
  // an interior target is a corner of at least 3 convex polygons
  for(const auto& c : constraints)
  {
    std::set<int> around;
    for(FD f : CGAL::faces_around_target(halfedge(c.first, m), m))
      if(f != boost::graph_traits<Mesh>::null_face()) around.insert(get(fpm, f));
    CHECK(around.size() >= 3, what << ": at least 3 patches meet at each constrained vertex (" << around.size() << ")");
  }
  out.hull_area = 0;
  for(std::size_t p = 0; p < patches; ++p)
  {
    std::vector<Point_2> hull;
    CGAL::convex_hull_2(points[p].begin(), points[p].end(), std::back_inserter(hull));
    out.hull_area += CGAL::polygon_area_2(hull.begin(), hull.end(), Epick());
  }
  std::sort(sizes.begin(), sizes.end());
  out.sizes = sizes;
  return EXIT_SUCCESS;
}

// the three targets of the pe constrain test on the mushroom, border on the unit square
template <class Mesh>
std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor, Point_2> > mushroom_constraints(const Mesh& m)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> V(vertices(m).begin(), vertices(m).end());
  return { { V[581], Point_2(0.25, 0.25) }, { V[274], Point_2(0.75, 0.25) }, { V[1080], Point_2(0.25, 0.75) } };
}

template <class Mesh, class FPM>
int run_mushroom(Mesh& m, FPM fpm, bool optimize, Patch_summary& s, const std::string& what)
{
  auto uv = make_uv_map(m, Point_2());
  CHECK(PE::tutte_embedding(m, boost::graph_traits<Mesh>::null_halfedge(), uv,
                            PE::parameters::border_shape(PE::Border_shape::SQUARE)) == PE::OK, what << ": square border");
  const auto C = mushroom_constraints(m);
  for(auto f : faces(m)) put(fpm, f, -1);
  PE::Constrained_embedding_statistics st;
  const PE::Error_code ec = PE::constrained_embedding(m, C, uv,
    PE::parameters::optimize(optimize, PE::parameters::coarsen(false, // the patches as traced (see below for the coarsening)
      PE::parameters::statistics(&st, PE::parameters::face_patch_map(fpm)))));
  std::cout << what << ": " << PE::get_error_message(ec) << ", " << st.patches << " patches, " << st.steiner_vertices
            << " Steiner vertices" << std::endl;
  CHECK(ec == PE::OK, what << ": certified");
  CHECK(st.patches >= 4, what << ": three interior targets cut the square into at least 4 patches");
  RUN(check_patches(m, uv, fpm, st.patches, C, s, what));
  std::cout << what << ": " << s.faces << " faces, hull area " << s.hull_area << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

PE_TEST_GROUP(face_patch_map_surface_mesh)
{
  Surface_mesh raw, opt;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", raw) || !read_mesh(data_dir + "/meshes/mushroom.off", opt)) return EXIT_FAILURE;
  auto fraw = raw.add_property_map<Surface_mesh::Face_index, int>("f:patch", -7).first;
  auto fopt = opt.add_property_map<Surface_mesh::Face_index, int>("f:patch", -7).first;
  Patch_summary a, b;
  RUN(run_mushroom(raw, fraw, false, a, "mushroom, not optimized"));
  // before the optimization each patch lies in its convex polygon: the hulls tile the unit square
  CHECK(std::abs(a.hull_area - 1.) < 1e-9, "the hulls of the patches tile the domain (" << a.hull_area << ")");
  RUN(run_mushroom(opt, fopt, true, b, "mushroom, optimized"));
  // same refinement, same labels face by face: the optimization moves vertices only
  CHECK(raw.number_of_faces() == opt.number_of_faces(), "same refined mesh");
  auto fa = faces(raw).begin();
  for(auto f : faces(opt)) { CHECK(get(fraw, *fa) == get(fopt, f), "the optimization changes no label"); ++fa; }
  // with the coarsening (the default), every face of the coarser mesh still has a patch (the fan faces take the
  // patches of the faces they replace; a deflected path may cut a patch in pieces)
  Surface_mesh coarse;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", coarse)) return EXIT_FAILURE;
  auto fcoarse = coarse.add_property_map<Surface_mesh::Face_index, int>("f:patch", -7).first;
  auto uv = make_uv_map(coarse, Point_2());
  CHECK(PE::tutte_embedding(coarse, boost::graph_traits<Surface_mesh>::null_halfedge(), uv,
                            PE::parameters::border_shape(PE::Border_shape::SQUARE)) == PE::OK, "square border");
  PE::Constrained_embedding_statistics st;
  CHECK(PE::constrained_embedding(coarse, mushroom_constraints(coarse), uv,
                                  PE::parameters::statistics(&st, PE::parameters::face_patch_map(fcoarse))) == PE::OK, "coarsened");
  std::size_t labelled = 0;
  for(auto f : faces(coarse))
  {
    CHECK(get(fcoarse, f) >= 0 && std::size_t(get(fcoarse, f)) < st.patches, "a patch for every face of the coarser mesh");
    ++labelled;
  }
  std::cout << "mushroom, optimized and coarsened: " << st.steiner_vertices_removed << " of " << st.steiner_vertices_inserted
            << " added vertices removed, " << labelled << " faces labelled" << std::endl;
  CHECK(labelled == coarse.number_of_faces() && labelled <= b.faces, "the coarsening removes faces, never adds");
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(face_patch_map_polyhedron)
{
  Surface_mesh sm;
  Polyhedron ph;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", sm) || !read_mesh(data_dir + "/meshes/mushroom.off", ph)) return EXIT_FAILURE;
  auto fsm = sm.add_property_map<Surface_mesh::Face_index, int>("f:patch", -7).first;
  auto fph = get(CGAL::dynamic_face_property_t<int>(), ph);
  Patch_summary a, b;
  RUN(run_mushroom(sm, fsm, false, a, "mushroom Surface_mesh"));
  RUN(run_mushroom(ph, fph, false, b, "mushroom Polyhedron_3"));
  CHECK(a.faces == b.faces && a.sizes == b.sizes, "the same patches on both mesh types");
  CHECK(std::abs(b.hull_area - 1.) < 1e-9, "the hulls of the patches tile the domain");
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(face_patch_map_cases)
{
  Surface_mesh m;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
  auto fpm = m.add_property_map<Surface_mesh::Face_index, int>("f:patch", -7).first;
  auto uv = make_uv_map(m, Point_2());
  CHECK(PE::tutte_embedding(m, Surface_mesh::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::SQUARE)) == PE::OK,
        "square border");
  // on error nothing is written
  auto C = mushroom_constraints(m);
  for(auto v : vertices(m)) if(CGAL::is_border(v, m)) { C[1].first = v; break; }
  CHECK(PE::constrained_embedding(m, C, uv, PE::parameters::face_patch_map(fpm)) == PE::ERROR_CONSTRAINT_ON_BORDER, "refused");
  for(auto f : faces(m)) CHECK(get(fpm, f) == -7, "nothing written on error");
  // no constraint: one patch, the whole disk
  std::vector<std::pair<Surface_mesh::Vertex_index, Point_2> > none;
  PE::Constrained_embedding_statistics st;
  CHECK(PE::constrained_embedding(m, none, uv, PE::parameters::statistics(&st, PE::parameters::face_patch_map(fpm))) == PE::OK,
        "no constraint");
  CHECK(st.patches == 1, "one patch");
  for(auto f : faces(m)) CHECK(get(fpm, f) == 0, "every face in patch 0");
  return EXIT_SUCCESS;
}
