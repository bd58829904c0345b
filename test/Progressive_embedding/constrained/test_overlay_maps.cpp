// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// The overlay of two triangulations of one square by clipping (internal/cross/overlay_maps.h, what
// cross_parameterization() uses for its compatible meshes) against CGAL's arrangement overlay
// (internal/cross/overlay_by_arrangement.h): the same cells (the same pairs of triangles), crossings, points
// and triangles, and the triangulated overlay certified (internal/cross/certify_overlay.h, and
// check_embedding() in exact rationals). The cases: two random triangulations (every crossing in general
// position), grids whose vertices and edges partly coincide (vertices of one on the other's vertices and
// edges, edges along edges, borders that interleave), each both ways, a map against itself; faces that are not
// triangles of the points and two maps of different domains refused.

#include <CGAL/Progressive_embedding/internal/cross/overlay_maps.h>
#include <CGAL/Progressive_embedding/internal/cross/overlay_by_arrangement.h>
#include <CGAL/Progressive_embedding/internal/cross/certify_overlay.h>
#include <CGAL/Progressive_embedding/check_embedding.h>

#include "registry.h"
#include "../test_util.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

typedef CGAL::Epick::Point_2 Overlay_point;
struct Planar_map
{
  std::vector<Overlay_point> uv;
  std::vector<std::array<std::size_t, 3> > faces;
};

// the Delaunay triangulation of `points` (their convex hull the domain), counterclockwise
Planar_map delaunay_map(const std::vector<Overlay_point>& points)
{
  typedef CGAL::Delaunay_triangulation_2<CGAL::Epick> DT;
  DT dt(points.begin(), points.end());
  Planar_map m;
  std::map<DT::Vertex_handle, std::size_t> index;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
  {
    index.emplace(v, m.uv.size());
    m.uv.push_back(v->point());
  }
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    m.faces.push_back({{ index.at(f->vertex(0)), index.at(f->vertex(1)), index.at(f->vertex(2)) }});
  return m;
}

// the unit square's corners, `random` points inside, and an n x n grid of points (n > 1) with its border
std::vector<Overlay_point> square_points(std::size_t random, std::size_t n, CGAL::Random& rng)
{
  std::vector<Overlay_point> p{ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  for(std::size_t k = 0; k < random; ++k) p.emplace_back(rng.get_double(0.001, 0.999), rng.get_double(0.001, 0.999));
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j)
      p.emplace_back(double(i) / double(n - 1), double(j) / double(n - 1));
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  return p;
}

// the cells as the multiset of their pairs of triangles (one entry per cell)
std::multiset<std::array<std::size_t, 2> > cell_pairs(const PE::internal::Map_overlay& o)
{
  std::map<std::array<std::size_t, 2>, std::size_t> triangles;
  for(const auto& d : o.cell_faces) ++triangles[d];
  std::multiset<std::array<std::size_t, 2> > r;
  for(const auto& t : triangles) r.insert(t.first);
  return r;
}

int compare_overlays(const Planar_map& a, const Planar_map& b, const std::string& what)
{
  PE::internal::Map_overlay clipped, reference;
  CHECK(PE::internal::overlay_maps(a.uv, a.faces, b.uv, b.faces, clipped) == PE::OK, what << ": the overlay by clipping");
  CHECK(PE::internal::overlay_maps_by_arrangement(a.uv, a.faces, b.uv, b.faces, reference) == PE::OK,
        what << ": CGAL's overlay");
  CHECK(clipped.cells == reference.cells, what << ": cells " << clipped.cells << " against " << reference.cells);
  CHECK(clipped.crossings == reference.crossings, what << ": crossings " << clipped.crossings << " against " << reference.crossings);
  CHECK(clipped.centers == reference.centers, what << ": centers");
  CHECK(clipped.points.size() == reference.points.size(), what << ": points " << clipped.points.size() << " against "
        << reference.points.size());
  CHECK(clipped.triangles.size() == reference.triangles.size(), what << ": triangles");
  CHECK(cell_pairs(clipped) == cell_pairs(reference), what << ": the same pairs of triangles");
  // every point where the reference has it: the same features for the same exact point
  std::map<CGAL::Epeck::Point_2, std::array<PE::internal::Map_feature, 2>, CGAL::Epeck::Less_xy_2> features;
  for(std::size_t i = 0; i < reference.points.size(); ++i) features.emplace(reference.points[i], reference.features[i]);
  for(std::size_t i = 0; i < clipped.points.size(); ++i)
  {
    const auto it = features.find(clipped.points[i]);
    CHECK(it != features.end(), what << ": point " << i << " in the reference");
    for(int m = 0; m < 2; ++m)
    {
      auto f = clipped.features[i][m], g = it->second[m];
      if(f[1] != std::size_t(-1)) std::sort(f.begin(), f.end());
      if(g[1] != std::size_t(-1)) std::sort(g.begin(), g.end());
      CHECK(f == g, what << ": point " << i << ", where it lies in map " << m);
    }
  }
  const PE::Embedding_report fast = PE::internal::certify_overlay(clipped.points, clipped.triangles);
  CHECK(fast.is_valid() && fast.overlap_by_degree_argument, what << ": certified: " << fast.summary());
  // the same verdict from check_embedding() in exact rationals
  CGAL::Surface_mesh<CGAL::Epick::Point_3> soup;
  typedef CGAL::Surface_mesh<CGAL::Epick::Point_3>::Vertex_index sv;
  for(std::size_t i = 0; i < clipped.points.size(); ++i) soup.add_vertex();
  for(const auto& t : clipped.triangles) CHECK(soup.add_face(sv(t[0]), sv(t[1]), sv(t[2])) != soup.null_face(), what << ": a face");
  auto uv = soup.add_property_map<sv, CGAL::Epeck::Point_2>("v:uv").first;
  for(std::size_t i = 0; i < clipped.points.size(); ++i) uv[sv(i)] = clipped.points[i];
  const PE::Embedding_report full = PE::check_embedding(soup, uv);
  CHECK(full.is_valid() && full.faces == fast.faces && full.border_vertices == fast.border_vertices,
        what << ": check_embedding() agrees: " << full.summary());
  std::cout << what << ": " << a.faces.size() << " and " << b.faces.size() << " triangles, overlay " << clipped.cells
            << " cells, " << clipped.crossings << " crossings, " << clipped.points.size() << " points, "
            << clipped.triangles.size() << " triangles, the same as CGAL's overlay; certified" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

PE_TEST_GROUP(cross_overlay)
{
  (void)data_dir;
  CGAL::Random rng(7);
  const Planar_map random_a = delaunay_map(square_points(300, 0, rng));
  const Planar_map random_b = delaunay_map(square_points(200, 0, rng));
  RUN(compare_overlays(random_a, random_b, "two random triangulations"));
  RUN(compare_overlays(random_b, random_a, "the same, A and B swapped"));
  // grids of 5 and 9 points a side: every vertex of the first is one of the second, edges along edges
  RUN(compare_overlays(delaunay_map(square_points(0, 5, rng)), delaunay_map(square_points(0, 9, rng)), "grids 5 and 9"));
  // grids of 4 and 7 with random points: vertices on edges, crossings at vertices
  RUN(compare_overlays(delaunay_map(square_points(40, 4, rng)), delaunay_map(square_points(60, 7, rng)), "grids 4 and 7 with random points"));
  // the other way: every other vertex of A inside an edge of B (on the border, along the axes, on diagonals)
  RUN(compare_overlays(delaunay_map(square_points(0, 9, rng)), delaunay_map(square_points(0, 5, rng)), "grids 9 and 5"));
  {
    // borders that interleave (border edges overlapping in part), a vertex of B inside an edge of A and one of A
    // inside an edge of B, A's centre on a diagonal of B collinear with edges of A
    const std::vector<Overlay_point> quarters{ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { 0.25, 0 }, { 0.75, 0 },
      { 0.25, 1 }, { 0.75, 1 }, { 0, 0.25 }, { 0, 0.75 }, { 1, 0.25 }, { 1, 0.75 }, { 0.5, 0.25 }, { 0.5, 0.75 },
      { 0.25, 0.5 }, { 0.75, 0.5 } };
    const Planar_map halves = delaunay_map(square_points(0, 3, rng));
    RUN(compare_overlays(halves, delaunay_map(quarters), "grid 3 and interleaved quarters"));
    RUN(compare_overlays(delaunay_map(quarters), halves, "interleaved quarters and grid 3"));
  }
  RUN(compare_overlays(random_a, random_a, "a map and itself"));
  {
    PE::internal::Map_overlay o;
    const PE::Error_code ec = PE::internal::overlay_maps(random_a.uv, random_a.faces, random_a.uv, random_a.faces, o);
    CHECK(ec == PE::OK && o.crossings == 0 && o.cells == random_a.faces.size() && o.points.size() == random_a.uv.size(),
          "a map and itself: the overlay is the map");
  }
  // a face with a vertex out of range, a face with a repeated vertex: refused
  {
    Planar_map bad = random_b;
    PE::internal::Map_overlay o;
    bad.faces[3][1] = bad.uv.size();
    CHECK(PE::internal::overlay_maps(random_a.uv, random_a.faces, bad.uv, bad.faces, o) == PE::ERROR_INVALID_EMBEDDING,
          "a vertex index out of range: refused");
    bad.faces[3][1] = bad.faces[3][0];
    CHECK(PE::internal::overlay_maps(random_a.uv, random_a.faces, bad.uv, bad.faces, o) == PE::ERROR_INVALID_EMBEDDING,
          "a face with a repeated vertex: refused");
  }
  // B on a smaller square: refused by both
  {
    Planar_map small = random_b;
    for(auto& p : small.uv) p = Overlay_point(0.25 + 0.5 * p.x(), 0.25 + 0.5 * p.y());
    PE::internal::Map_overlay o;
    CHECK(PE::internal::overlay_maps(random_a.uv, random_a.faces, small.uv, small.faces, o) == PE::ERROR_INVALID_EMBEDDING,
          "B's domain inside A's: refused by clipping");
    CHECK(PE::internal::overlay_maps(small.uv, small.faces, random_a.uv, random_a.faces, o) == PE::ERROR_INVALID_EMBEDDING,
          "A's domain inside B's: refused by clipping");
    CHECK(PE::internal::overlay_maps_by_arrangement(random_a.uv, random_a.faces, small.uv, small.faces, o) == PE::ERROR_INVALID_EMBEDDING,
          "B's domain inside A's: refused by CGAL's overlay");
    std::cout << "two maps of different squares: refused by both overlays" << std::endl;
  }
  return EXIT_SUCCESS;
}
