// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// cross_parameterization(): identical meshes (every vertex on its own vertex), a disk and its remeshed
// copy (3D error of the images relative to the bounding-box diagonal, smaller with more landmarks),
// every error path with nothing written, Polyhedron_3, the exact location step in Gmpq, and the
// transfer of vertex properties.

#include <CGAL/Progressive_embedding/cross_parameterization.h>
#include <CGAL/Progressive_embedding/internal/cross/locate_in_map.h>
#include <CGAL/Progressive_embedding/internal/disk_generators.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Progressive_embedding/internal/cross/remeshed_pair_protocol.h>
#include <CGAL/Progressive_embedding/certified_pipeline.h>

#include "registry.h"
#include "../test_util.h"
#include "mesh_fixtures.h"
#include "../../fuzz/cross_parameterization.h"

#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Random.h>

#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

template <class Mesh>
using Location_map = std::unordered_map<typename boost::graph_traits<Mesh>::vertex_descriptor, PE::Cross_location<Mesh>,
                                        boost::hash<typename boost::graph_traits<Mesh>::vertex_descriptor> >;

// the barycentric coordinate of `v` in the location (-1 if `v` is not a corner of its face)
template <class Mesh>
double weight_of(const Mesh& m, const PE::Cross_location<Mesh>& loc, typename boost::graph_traits<Mesh>::vertex_descriptor v)
{
  const auto h = halfedge(loc.first, m);
  if(source(h, m) == v) return loc.second[0];
  if(target(h, m) == v) return loc.second[1];
  if(target(next(h, m), m) == v) return loc.second[2];
  return -1;
}

template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> interior_vertices(const Mesh& m)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> r;
  for(auto v : vertices(m)) if(!CGAL::is_border(v, m)) r.push_back(v);
  return r;
}

// runs cross_parameterization() and checks the call's guarantees: OK, both maps certified, every landmark exact
// (and the other direction, B's vertices located on A, into `back`: every landmark of B exactly on its partner)
template <class MeshA, class MeshB, class Landmarks, class Locations, class BackLocations>
int certified_cross(const MeshA& a, const MeshB& b, const Landmarks& landmarks, Locations& loc,
                    PE::Cross_parameterization_statistics& st, BackLocations& back)
{
  const PE::Error_code ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(loc),
    PE::parameters::b_to_a_locations(boost::make_assoc_property_map(back), PE::parameters::statistics(&st)));
  CHECK(ec == PE::OK, PE::get_error_message(ec) << " (failed mesh " << st.failed_mesh << ")");
  CHECK(st.report_a.is_valid() && st.report_b.is_valid() && st.landmarks_exact, "certified, landmarks exact");
  CHECK(loc.size() == st.vertices_a, "every vertex of A located");
  CHECK(back.size() == st.vertices_b && st.located_b_on_a == st.vertices_b, "every vertex of B located on A");
  for(const auto& p : landmarks) CHECK(weight_of(a, back.at(p.second), p.first) == 1., "landmark of B exact on A");
  return EXIT_SUCCESS;
}

// A == B: landmarks at the same vertices. On a grid with every interior vertex a landmark, every vertex lands
// exactly on itself (the border too: both borders are the same); on mushroom with 5 landmarks, the landmarks and
// the border vertices do, the other vertices land near themselves.
template <class Mesh>
int identical_grid()
{
  Mesh a, b;
  PE::internal::make_grid_disk(7, a);
  PE::internal::make_grid_disk(7, b);
  std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor,
                        typename boost::graph_traits<Mesh>::vertex_descriptor> > landmarks;
  auto va = vertices(a).begin();
  auto vb = vertices(b).begin();
  for(; va != vertices(a).end(); ++va, ++vb)
    if(!CGAL::is_border(*va, a)) landmarks.emplace_back(*va, *vb);
  Location_map<Mesh> loc, back;
  PE::Cross_parameterization_statistics st;
  RUN(certified_cross(a, b, landmarks, loc, st, back));
  va = vertices(a).begin();
  vb = vertices(b).begin();
  for(; va != vertices(a).end(); ++va, ++vb)
  {
    CHECK(weight_of(b, loc.at(*va), *vb) == 1., "vertex on its own vertex");
    CHECK(weight_of(a, back.at(*vb), *va) == 1., "vertex of B on its own vertex of A");
  }
  CHECK(st.located_on_vertex == st.vertices_a, "all on vertices");
  std::cout << "identical grid (" << mesh_name<Mesh>() << "): " << st.vertices_a << " vertices, " << landmarks.size()
            << " landmarks, every vertex exactly on its own vertex, vertices added to A " << st.vertices_added_a
            << ", " << st.seconds_total << " s" << std::endl;
  return EXIT_SUCCESS;
}

// the border vertices of a disk in the order of its border cycle
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> border_cycle(const Mesh& m)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> r;
  for(auto h : halfedges(m))
  {
    if(!CGAL::is_border(h, m)) continue;
    for(auto g : CGAL::halfedges_around_face(h, m)) r.push_back(target(g, m));
    break;
  }
  return r;
}

// Border landmarks: on two copies of a grid disk, 4 border vertices of A matched to the border vertices of B
// a quarter of the border further (a quarter turn: the grid's corners stay on the square's corners, where no
// interior edge joins two vertices of one side) and one interior landmark:
// certified, every landmark exactly on its partner both ways, every border vertex of A on B's border (on an
// edge or a vertex of B). The same landmarks at their own vertices; a border landmark out of order.
template <class Mesh>
int border_landmarks()
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  Mesh a, b;
  PE::internal::make_grid_disk(7, a);
  PE::internal::make_grid_disk(7, b);
  const std::vector<vd> ca = border_cycle(a), cb = border_cycle(b);
  const std::vector<vd> ia = interior_vertices(a), ib = interior_vertices(b);
  const std::size_t n = ca.size();
  CHECK(n == cb.size() && n >= 12, "border cycles");
  // the first landmark (the square's corner (0,0)) at a corner of the grid: the first border vertex of A
  std::size_t p0 = 0;
  for(vd v : vertices(a)) if(CGAL::is_border(v, a)) { p0 = std::size_t(std::find(ca.begin(), ca.end(), v) - ca.begin()); break; }
  for(std::size_t shift : { std::size_t(0), n / 4 })
  {
    std::vector<std::pair<vd, vd> > landmarks;
    for(std::size_t k : { std::size_t(0), n / 4 + 2, n / 2 + 1, 3 * n / 4 - 1 })
      landmarks.emplace_back(ca[(p0 + k) % n], cb[(p0 + k + shift) % n]);
    landmarks.emplace_back(ia[ia.size() / 2], ib[ib.size() / 2]);
    Location_map<Mesh> loc, back;
    PE::Cross_parameterization_statistics st;
    RUN(certified_cross(a, b, landmarks, loc, st, back));
    CHECK(st.border_landmarks == 4 && st.landmarks == 5, "counted: " << st.border_landmarks << " of " << st.landmarks);
    std::size_t on_border = 0;
    for(vd v : ca)
    {
      const auto& l = loc.at(v);
      const int zeros = int(l.second[0] == 0) + int(l.second[1] == 0) + int(l.second[2] == 0);
      if(zeros >= 1) ++on_border;
    }
    CHECK(on_border == n, "border vertices of A on edges or vertices of B: " << on_border << " of " << n);
    std::cout << "border landmarks (" << mesh_name<Mesh>() << ", shift " << shift << "): 4 border and 1 interior landmark "
              << "exactly on their partners both ways, " << on_border << " border vertices of A on B's edges or vertices, "
              << "vertices added to A " << st.vertices_added_a << std::endl;
  }
  // out of order along B's border: landmarks 1 and 2 come in one order along A's border, in the other along B's
  {
    const std::vector<std::pair<vd, vd> > landmarks = { { ca[1], cb[1] }, { ca[n / 3], cb[2 * n / 3] }, { ca[2 * n / 3], cb[n / 3] } };
    Location_map<Mesh> loc;
    PE::Cross_parameterization_statistics st;
    const PE::Error_code ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(loc), PE::parameters::statistics(&st));
    // which of the two is named depends on the direction of the border cycle above (the function walks each border
    // counterclockwise, the interior on the left)
    CHECK(ec == PE::ERROR_LANDMARK_ORDER && (st.failed_landmark == 1 || st.failed_landmark == 2) && st.failed_mesh == 1 && loc.empty(),
          "out of order: " << PE::get_error_name(ec) << ", landmark " << st.failed_landmark << ", mesh " << st.failed_mesh);
    std::cout << "border landmarks out of order (" << mesh_name<Mesh>() << "): " << PE::get_error_name(ec) << ", landmark "
              << st.failed_landmark << std::endl;
  }
  // an arc of A too short for the corner that B's arc holds at the quarter of B's border (A's arc is one edge): the
  // corners go to the landmarks or to arcs with room on both borders, and the maps are certified
  {
    const std::vector<std::pair<vd, vd> > landmarks = { { ca[(p0 + 1) % n], cb[(p0 + 1) % n] }, { ca[(p0 + 2) % n], cb[(p0 + n / 2) % n] } };
    Location_map<Mesh> loc, back;
    PE::Cross_parameterization_statistics st;
    RUN(certified_cross(a, b, landmarks, loc, st, back));
    CHECK(st.border_landmarks == 2, "counted: " << st.border_landmarks);
    std::cout << "border landmarks with an arc of A too short for B's corner (" << mesh_name<Mesh>() << "): certified, "
              << "landmarks exact both ways" << std::endl;
  }
  // no place for the corners: A's arc from the first landmark to the second and B's from the second to the first are
  // single edges, so only the two landmarks could be corners on both borders
  {
    const std::vector<std::pair<vd, vd> > landmarks = { { ca[(p0 + 1) % n], cb[(p0 + 1) % n] }, { ca[(p0 + 2) % n], cb[p0 % n] } };
    Location_map<Mesh> loc;
    PE::Cross_parameterization_statistics st;
    const PE::Error_code ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(loc), PE::parameters::statistics(&st));
    CHECK(ec == PE::ERROR_BORDER_TOO_SHORT && st.failed_mesh == 0 && loc.empty() &&
          (st.failed_landmark == 0 || st.failed_landmark == 1),
          "no place for the corners: " << PE::get_error_name(ec) << ", landmark " << st.failed_landmark << ", mesh " << st.failed_mesh);
    std::cout << "border landmarks with no place for the square's corners (" << mesh_name<Mesh>() << "): "
              << PE::get_error_name(ec) << ", landmark " << st.failed_landmark << std::endl;
  }
  return EXIT_SUCCESS;
}

template <class Mesh>
int identical_mesh(const std::string& file)
{
  Mesh a, b;
  CHECK(CGAL::IO::read_polygon_mesh(file, a) && CGAL::IO::read_polygon_mesh(file, b), "read " << file);
  const auto la = PE::internal::spread_interior_vertices(a, 5);
  std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor,
                        typename boost::graph_traits<Mesh>::vertex_descriptor> > landmarks;
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> va(vertices(a).begin(), vertices(a).end()),
                                                                     vb(vertices(b).begin(), vertices(b).end());
  std::unordered_map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t,
                     boost::hash<typename boost::graph_traits<Mesh>::vertex_descriptor> > index;
  for(std::size_t i = 0; i < va.size(); ++i) index[va[i]] = i;
  for(auto v : la) landmarks.emplace_back(v, vb[index[v]]);
  Location_map<Mesh> loc, back;
  PE::Cross_parameterization_statistics st;
  RUN(certified_cross(a, b, landmarks, loc, st, back));
  const double diag = PE::internal::bbox_diagonal(a);
  double sum = 0, worst = 0, own_weight_min = 1;
  std::size_t border_exact = 0, nb = 0;
  for(std::size_t i = 0; i < va.size(); ++i)
  {
    const PE::Cross_location<Mesh>& l = loc.at(va[i]);
    const double e = std::sqrt(CGAL::to_double(CGAL::squared_distance(PMP::construct_point(l, b), get(CGAL::vertex_point, a, va[i])))) / diag;
    sum += e;
    worst = (std::max)(worst, e);
    if(CGAL::is_border(va[i], a)) { ++nb; if(weight_of(b, l, vb[i]) == 1.) ++border_exact; }
    own_weight_min = (std::min)(own_weight_min, (std::max)(0., weight_of(b, l, vb[i])));
  }
  for(const auto& p : landmarks) CHECK(weight_of(b, loc.at(p.first), p.second) == 1., "landmark exact");
  CHECK(border_exact == nb, "border vertices on their own vertex: " << border_exact << " of " << nb);
  CHECK(sum / va.size() < 2e-3, "mean error " << sum / va.size());
  std::cout << "identical " << file << " (" << mesh_name<Mesh>() << "): 5 landmarks and " << nb
            << " border vertices exactly on their own vertex; the others: mean error " << sum / va.size()
            << " of the diagonal, max " << worst << ", smallest weight of the own vertex " << own_weight_min
            << "; vertices added to A " << st.vertices_added_a << ", " << st.seconds_total << " s" << std::endl;
  return EXIT_SUCCESS;
}

// the vertices of a mesh in iteration order, and each face as their indices
template <class Mesh>
std::pair<std::vector<Epick::Point_3>, std::vector<std::vector<std::size_t> > > indexed_soup(const Mesh& m)
{
  std::unordered_map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t,
                     boost::hash<typename boost::graph_traits<Mesh>::vertex_descriptor> > index;
  std::pair<std::vector<Epick::Point_3>, std::vector<std::vector<std::size_t> > > r;
  for(auto v : vertices(m)) { index[v] = r.first.size(); r.first.push_back(get(CGAL::vertex_point, m, v)); }
  for(auto f : faces(m))
  {
    r.second.emplace_back();
    for(auto v : vertices_around_face(halfedge(f, m), m)) r.second.back().push_back(index.at(v));
  }
  return r;
}

// The planar maps of `planar_maps`: the certified maps as flat meshes, A's and B's own vertices first in their
// meshes' order, the added ones after; each map valid on its own (check_embedding() of (x, y)), its border on the
// unit square, each landmark at its partner's point bit for bit, and every vertex of A at the point of B's map that
// its location gives (the barycentric coordinates rounded once: 1e-12 of the square).
template <class MeshA, class MeshB, class PlaneA, class PlaneB, class Locations>
int planar_maps_agree(const MeshA& a, const MeshB& b,
                      const std::vector<std::pair<typename boost::graph_traits<MeshA>::vertex_descriptor,
                                                  typename boost::graph_traits<MeshB>::vertex_descriptor> >& landmarks,
                      const Locations& loc, const PlaneA& plane_a, const PlaneB& plane_b,
                      const PE::Cross_parameterization_statistics& st)
{
  const auto sa = indexed_soup(plane_a);
  const auto sb = indexed_soup(plane_b);
  CHECK(sa.first.size() == st.vertices_a + st.vertices_added_a && sb.first.size() == st.vertices_b + st.vertices_added_b,
        "planar maps: vertex counts " << sa.first.size() << " " << sb.first.size());
  CHECK(sa.second.size() == st.report_a.faces && sb.second.size() == st.report_b.faces, "planar maps: the certified faces");
  for(const auto* soup : { &sa, &sb })
  {
    Surface_mesh flat;
    std::vector<std::vector<std::size_t> > faces = soup->second;
    PMP::polygon_soup_to_polygon_mesh(soup->first, faces, flat);
    auto uv = flat.add_property_map<Surface_mesh::Vertex_index, Epick::Point_2>("v:uv").first;
    for(auto v : flat.vertices())
    {
      const Epick::Point_3& p = flat.point(v);
      CHECK(p.z() == 0, "planar maps: flat");
      uv[v] = Epick::Point_2(p.x(), p.y());
      if(flat.is_border(v)) CHECK(p.x() == 0 || p.x() == 1 || p.y() == 0 || p.y() == 1, "planar maps: border on the square");
    }
    const PE::Embedding_report r = PE::check_embedding(flat, uv);
    CHECK(r.is_valid() && r.flipped == 0 && r.degenerate == 0, "planar maps: certified, " << r.summary());
  }
  std::unordered_map<typename boost::graph_traits<MeshA>::vertex_descriptor, std::size_t,
                     boost::hash<typename boost::graph_traits<MeshA>::vertex_descriptor> > index_a;
  std::unordered_map<typename boost::graph_traits<MeshB>::vertex_descriptor, std::size_t,
                     boost::hash<typename boost::graph_traits<MeshB>::vertex_descriptor> > index_b;
  for(auto v : vertices(a)) index_a.emplace(v, index_a.size());
  for(auto v : vertices(b)) index_b.emplace(v, index_b.size());
  for(const auto& l : landmarks)
    CHECK(sa.first[index_a.at(l.first)] == sb.first[index_b.at(l.second)], "planar maps: a landmark at its partner");
  double worst = 0;
  for(auto v : vertices(a))
  {
    const PE::Cross_location<MeshB>& l = loc.at(v);
    const auto h = halfedge(l.first, b);
    const std::size_t c[3] = { index_b.at(source(h, b)), index_b.at(target(h, b)), index_b.at(target(next(h, b), b)) };
    double x = 0, y = 0;
    for(int i = 0; i < 3; ++i) { x += l.second[i] * sb.first[c[i]].x(); y += l.second[i] * sb.first[c[i]].y(); }
    const Epick::Point_3& p = sa.first[index_a.at(v)];
    worst = (std::max)(worst, (std::max)(std::abs(x - p.x()), std::abs(y - p.y())));
  }
  CHECK(worst <= 1e-12, "planar maps: the locations point where A's map puts A's vertices, off by " << worst);
  std::cout << "planar maps: A " << sa.first.size() << " vertices (" << st.vertices_added_a << " added), " << sa.second.size()
            << " faces; B " << sb.first.size() << " vertices (" << st.vertices_added_b << " added), " << sb.second.size()
            << " faces; both certified, landmarks bit for bit, locations within " << worst << " of A's map" << std::endl;
  return EXIT_SUCCESS;
}

// A == B with the landmarks' partners shifted by one (landmark k of A on landmark k + 1 of B): A's map must move
// them far, its copy is refined by Steiner vertices; both directions are still located, the landmarks exact, and
// the locations of B's vertices on A (through the Steiner points' positions on A's faces) sum to 1.
template <class Mesh>
int shifted_landmarks(const std::string& file)
{
  Mesh a, b;
  CHECK(CGAL::IO::read_polygon_mesh(file, a) && CGAL::IO::read_polygon_mesh(file, b), "read " << file);
  const auto la = PE::internal::spread_interior_vertices(a, 5);
  const auto lb = PE::internal::spread_interior_vertices(b, 5);
  std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor,
                        typename boost::graph_traits<Mesh>::vertex_descriptor> > landmarks;
  for(std::size_t k = 0; k < la.size(); ++k) landmarks.emplace_back(la[k], lb[(k + 1) % lb.size()]);
  Location_map<Mesh> loc, back;
  PE::Cross_parameterization_statistics st;
  RUN(certified_cross(a, b, landmarks, loc, st, back));
  CHECK(st.vertices_added_a > 0, "A's copy refined");
  {
    // the planar maps, A's on its refined copy: its own vertices first, the added ones after
    Surface_mesh plane_a, plane_b;
    Location_map<Mesh> again;
    PE::Cross_parameterization_statistics st2;
    const PE::Error_code ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(again),
      PE::parameters::planar_maps(std::make_pair(&plane_a, &plane_b), PE::parameters::statistics(&st2)));
    CHECK(ec == PE::OK && st2.vertices_added_a == st.vertices_added_a, "the same map with planar_maps");
    RUN(planar_maps_agree(a, b, landmarks, again, plane_a, plane_b, st2));
    // the null pointer: that map is not written
    Surface_mesh untouched;
    CHECK(PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(again),
            PE::parameters::planar_maps(std::make_pair(static_cast<Surface_mesh*>(nullptr), &untouched))) == PE::OK &&
          num_vertices(untouched) == st2.vertices_b + st2.vertices_added_b, "planar_maps with one null pointer");
  }
  for(const auto& l : back)
  {
    const double sum = l.second.second[0] + l.second.second[1] + l.second.second[2];
    CHECK(std::abs(sum - 1) < 1e-12 && *std::min_element(l.second.second.begin(), l.second.second.end()) >= 0,
          "coordinates of a vertex of B on A");
  }
  std::cout << "shifted landmarks on " << file << " (" << mesh_name<Mesh>() << "): " << st.vertices_added_a
            << " vertices added to A's copy, both directions located, landmarks exact, " << st.seconds_total << " s"
            << std::endl;
  return EXIT_SUCCESS;
}

// A a libcgal-demo disk, B its isotropically remeshed copy; landmarks: vertices of A spread out, matched to the
// nearest vertex of B. The mean 3D distance between a vertex of A and the image of it on B, relative to the
// bounding-box diagonal.
template <class MeshA>
int remeshed_pair(const std::string& file, std::size_t count, double& mean_error, double& max_error)
{
  typedef Surface_mesh MeshB;
  MeshA a;
  MeshB b;
  CHECK(CGAL::IO::read_polygon_mesh(file, a) && CGAL::IO::read_polygon_mesh(file, b), "read " << file);
  PE::internal::remesh_isotropically(b);
  b.collect_garbage();
  const auto landmarks = PE::internal::nearest_vertex_landmarks(a, b, PE::internal::spread_interior_vertices(a, count));
  std::unordered_map<typename boost::graph_traits<MeshA>::vertex_descriptor, PE::Cross_location<MeshB>,
                     boost::hash<typename boost::graph_traits<MeshA>::vertex_descriptor> > loc;
  std::unordered_map<MeshB::Vertex_index, PE::Cross_location<MeshA> > back;
  PE::Cross_parameterization_statistics st;
  RUN(certified_cross(a, b, landmarks, loc, st, back));
  const double diag = PE::internal::bbox_diagonal(a);
  std::tie(mean_error, max_error) = PE::internal::correspondence_error(a, b, boost::make_assoc_property_map(loc));
  // the other direction: B's vertices on A
  const std::pair<double, double> back_error = PE::internal::correspondence_error(b, a, boost::make_assoc_property_map(back));
  CHECK(back_error.first < 2 * mean_error + 1e-3, "B -> A error " << back_error.first);
  for(const auto& p : landmarks) CHECK(weight_of(b, loc.at(p.first), p.second) == 1., "landmark exact");
  // the transfer of B's points gives the same points as PMP::construct_point()
  std::unordered_map<typename boost::graph_traits<MeshA>::vertex_descriptor, Epick::Point_3,
                     boost::hash<typename boost::graph_traits<MeshA>::vertex_descriptor> > moved;
  PE::transfer_vertex_property(a, b, boost::make_assoc_property_map(loc), get(CGAL::vertex_point, b), boost::make_assoc_property_map(moved));
  for(auto v : vertices(a))
    CHECK(CGAL::squared_distance(moved.at(v), PMP::construct_point(loc.at(v), b)) <= 1e-20 * diag * diag, "transfer");
  // a scalar: B's height
  std::unordered_map<MeshB::Vertex_index, double> height_b;
  for(auto w : vertices(b)) height_b[w] = b.point(w).z();
  std::unordered_map<typename boost::graph_traits<MeshA>::vertex_descriptor, double,
                     boost::hash<typename boost::graph_traits<MeshA>::vertex_descriptor> > height_a;
  PE::transfer_vertex_property(a, b, boost::make_assoc_property_map(loc), boost::make_assoc_property_map(height_b),
                               boost::make_assoc_property_map(height_a));
  for(auto v : vertices(a))
    CHECK(std::abs(height_a.at(v) - moved.at(v).z()) <= 1e-12 * diag, "scalar transfer");
  // a uv (Point_2) and a std::array of numbers: B's (x, y) and (x, y, z) give A's moved points' coordinates
  std::unordered_map<MeshB::Vertex_index, Epick::Point_2> uv_b;
  std::unordered_map<MeshB::Vertex_index, std::array<double, 3> > xyz_b;
  for(auto w : vertices(b))
  {
    uv_b[w] = Epick::Point_2(b.point(w).x(), b.point(w).y());
    xyz_b[w] = {{ b.point(w).x(), b.point(w).y(), b.point(w).z() }};
  }
  std::unordered_map<typename boost::graph_traits<MeshA>::vertex_descriptor, Epick::Point_2,
                     boost::hash<typename boost::graph_traits<MeshA>::vertex_descriptor> > uv_a;
  std::unordered_map<typename boost::graph_traits<MeshA>::vertex_descriptor, std::array<double, 3>,
                     boost::hash<typename boost::graph_traits<MeshA>::vertex_descriptor> > xyz_a;
  PE::transfer_vertex_property(a, b, boost::make_assoc_property_map(loc), boost::make_assoc_property_map(uv_b),
                               boost::make_assoc_property_map(uv_a));
  PE::transfer_vertex_property(a, b, boost::make_assoc_property_map(loc), boost::make_assoc_property_map(xyz_b),
                               boost::make_assoc_property_map(xyz_a));
  for(auto v : vertices(a))
  {
    const Epick::Point_3& m = moved.at(v);
    CHECK(std::abs(uv_a.at(v).x() - m.x()) <= 1e-12 * diag && std::abs(uv_a.at(v).y() - m.y()) <= 1e-12 * diag,
          "Point_2 transfer");
    CHECK(std::abs(xyz_a.at(v)[0] - m.x()) <= 1e-12 * diag && std::abs(xyz_a.at(v)[1] - m.y()) <= 1e-12 * diag &&
          std::abs(xyz_a.at(v)[2] - m.z()) <= 1e-12 * diag, "std::array transfer");
  }
  std::cout << file << " (" << mesh_name<MeshA>() << ", " << st.vertices_a << " vertices) -> remeshed ("
            << st.vertices_b << " vertices), " << count << " landmarks: mean error " << mean_error
            << " of the diagonal, max " << max_error << " (B -> A: mean " << back_error.first << ", max "
            << back_error.second << "); vertices added to A " << st.vertices_added_a
            << "; on B: " << st.located_in_face << " in faces, " << st.located_on_edge << " on edges, "
            << st.located_on_vertex << " on vertices; seconds: B " << st.seconds_map_b << ", A " << st.seconds_map_a
            << ", location " << st.seconds_location << ", total " << st.seconds_total << std::endl;
  return EXIT_SUCCESS;
}

template <class MeshA>
int remeshed(const std::string& data_dir, const std::string& name, double bound)
{
  const std::string file = data_dir + "/meshes/" + name;
  double mean5 = 0, max5 = 0, mean20 = 0, max20 = 0;
  RUN(remeshed_pair<MeshA>(file, 5, mean5, max5));
  RUN(remeshed_pair<MeshA>(file, 20, mean20, max20));
  CHECK(mean5 < bound && mean20 < bound, "mean errors " << mean5 << ", " << mean20 << " below " << bound);
  CHECK(mean20 < mean5, "the mean error falls from 5 to 20 landmarks: " << mean5 << " -> " << mean20);
  return EXIT_SUCCESS;
}

// The compatible meshes of A and B: one connectivity (B' a Polyhedron_3, A' of A's type), the overlay certified;
// A' on A's surface (every vertex of A in A' bit for bit, the same area), B' on B's likewise; each landmark one
// vertex of both, at its point on A and at its partner's on B. `identical`: A == B with every interior vertex a
// landmark, so the overlay is the mesh itself (no crossing, A' == B').
template <class MeshA>
int compatible(const MeshA& a, const Surface_mesh& b,
               const std::vector<std::pair<typename boost::graph_traits<MeshA>::vertex_descriptor, Surface_mesh::Vertex_index> >& landmarks,
               bool identical, const std::string& what)
{
  MeshA a_out;
  Polyhedron b_out;
  Surface_mesh plane_a;
  Polyhedron plane_b;
  std::unordered_map<typename boost::graph_traits<MeshA>::vertex_descriptor, PE::Cross_location<Surface_mesh>,
                     boost::hash<typename boost::graph_traits<MeshA>::vertex_descriptor> > loc;
  PE::Cross_parameterization_statistics st;
  const PE::Error_code ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(loc),
    PE::parameters::compatible_meshes(std::make_pair(&a_out, &b_out),
      PE::parameters::planar_maps(std::make_pair(&plane_a, &plane_b), PE::parameters::statistics(&st))));
  CHECK(ec == PE::OK, PE::get_error_message(ec));
  RUN(planar_maps_agree(a, b, landmarks, loc, plane_a, plane_b, st));
  CHECK(st.report_compatible.is_valid(), "the triangulated overlay certified");
  CHECK(st.report_compatible.flipped == 0 && st.report_compatible.degenerate == 0, "no flipped or flat triangle");
  const auto sa = indexed_soup(a_out);
  const auto sb = indexed_soup(b_out);
  CHECK(sa.first.size() == st.compatible_vertices && sb.first.size() == st.compatible_vertices, "vertex counts");
  CHECK(sa.second == sb.second && sa.second.size() == st.compatible_faces, "one connectivity");
  std::map<Epick::Point_3, std::size_t> at_a, at_b;
  for(std::size_t i = 0; i < sa.first.size(); ++i) { at_a.emplace(sa.first[i], i); at_b.emplace(sb.first[i], i); }
  for(auto v : vertices(a)) CHECK(at_a.count(get(CGAL::vertex_point, a, v)) == 1, "a vertex of A in A'");
  for(auto w : vertices(b)) CHECK(at_b.count(b.point(w)) == 1, "a vertex of B in B'");
  for(const auto& l : landmarks)
    CHECK(at_a.at(get(CGAL::vertex_point, a, l.first)) == at_b.at(b.point(l.second)), "a landmark, one vertex of both");
  const double area_a = PMP::area(a), area_b = PMP::area(b);
  CHECK(std::abs(PMP::area(a_out) - area_a) <= 1e-9 * area_a, "A' covers A");
  CHECK(std::abs(PMP::area(b_out) - area_b) <= 1e-9 * area_b, "B' covers B");
  if(identical)
  {
    CHECK(st.overlay_crossings == 0 && st.compatible_vertices == st.vertices_a && st.compatible_faces == st.faces_a,
          "identical maps: the overlay is the mesh");
    CHECK(sa.first == sb.first, "identical maps: A' == B'");
  }
  else CHECK(st.overlay_crossings > 0, "the maps cross");
  // both pointers null: no overlay is made, the same map otherwise (a caller may pass the parameters always)
  {
    std::unordered_map<typename boost::graph_traits<MeshA>::vertex_descriptor, PE::Cross_location<Surface_mesh>,
                       boost::hash<typename boost::graph_traits<MeshA>::vertex_descriptor> > loc0;
    PE::Cross_parameterization_statistics s0;
    CHECK(PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(loc0),
            PE::parameters::compatible_meshes(std::make_pair(static_cast<MeshA*>(nullptr), static_cast<Polyhedron*>(nullptr)),
              PE::parameters::planar_maps(std::make_pair(static_cast<Surface_mesh*>(nullptr), static_cast<Polyhedron*>(nullptr)),
                PE::parameters::statistics(&s0)))) == PE::OK, "compatible_meshes and planar_maps with null pointers");
    CHECK(s0.overlay_cells == 0 && s0.compatible_vertices == 0 && !s0.report_compatible.is_valid(), "no overlay made");
    CHECK(loc0 == loc, "the same locations");
  }
  std::cout << "compatible meshes, " << what << " (A " << mesh_name<MeshA>() << ", B' Polyhedron_3): A " << st.vertices_a
            << " vertices, B " << st.vertices_b << ", " << landmarks.size() << " landmarks; overlay " << st.overlay_cells
            << " cells, " << st.overlay_crossings << " crossings, " << st.overlay_centers << " centers; A' and B' "
            << st.compatible_vertices << " vertices, " << st.compatible_faces << " faces, certified; areas A' "
            << PMP::area(a_out) / area_a << " of A, B' " << PMP::area(b_out) / area_b << " of B; "
            << st.seconds_compatible << " s of " << st.seconds_total << " s" << std::endl;
  return EXIT_SUCCESS;
}

template <class MeshA>
int compatible_cases(const std::string& data_dir)
{
  {
    MeshA a;
    Surface_mesh b;
    PE::internal::make_grid_disk(7, a);
    PE::internal::make_grid_disk(7, b);
    std::vector<std::pair<typename boost::graph_traits<MeshA>::vertex_descriptor, Surface_mesh::Vertex_index> > landmarks;
    auto vb = vertices(b).begin();
    for(auto va = vertices(a).begin(); va != vertices(a).end(); ++va, ++vb)
      if(!CGAL::is_border(*va, a)) landmarks.emplace_back(*va, *vb);
    RUN(compatible(a, b, landmarks, true, "identical grids"));
  }
  const std::string file = data_dir + "/meshes/mushroom.off";
  MeshA a;
  Surface_mesh b;
  CHECK(CGAL::IO::read_polygon_mesh(file, a) && CGAL::IO::read_polygon_mesh(file, b), "read " << file);
  PE::internal::remesh_isotropically(b);
  b.collect_garbage();
  RUN(compatible(a, b, PE::internal::nearest_vertex_landmarks(a, b, PE::internal::spread_interior_vertices(a, 20)),
                 false, "mushroom and its remeshed copy"));
  return EXIT_SUCCESS;
}

// A convex polygon triangulated by a fan from its first vertex: every inside edge joins two border vertices, so
// B's map must put the corners of the square where no such edge has both ends on one side (at the quarters of
// the border, edges would be flat: ERROR_DEGENERATE_CHORD before the corners were chosen around them).
template <class Mesh>
int fan_disks()
{
  Mesh a, b;
  for(Mesh* m : { &a, &b })
  {
    typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
    std::vector<vd> v;
    for(int k = 0; k < 12; ++k)
    {
      v.push_back(add_vertex(*m));
      put(CGAL::vertex_point, *m, v.back(), Epick::Point_3(std::cos(0.5 * k) * (1 + 0.1 * (k % 3)), std::sin(0.5 * k), 0.01 * k));
    }
    for(int k = 1; k + 1 < 12; ++k) CGAL::Euler::add_face(std::vector<vd>{ v[0], v[k], v[k + 1] }, *m);
  }
  const std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor,
                              typename boost::graph_traits<Mesh>::vertex_descriptor> > no_landmarks;
  Location_map<Mesh> loc;
  PE::Cross_parameterization_statistics st;
  const PE::Error_code ec = PE::cross_parameterization(a, b, no_landmarks, boost::make_assoc_property_map(loc),
                                                       PE::parameters::statistics(&st));
  CHECK(ec == PE::OK, PE::get_error_message(ec) << " (failed mesh " << st.failed_mesh << ")");
  CHECK(st.report_a.is_valid() && st.report_b.is_valid(), "both maps certified");
  auto vb = vertices(b).begin();
  for(auto va = vertices(a).begin(); va != vertices(a).end(); ++va, ++vb)
    CHECK(weight_of(b, loc.at(*va), *vb) == 1., "a vertex of the fan on its own vertex");
  std::cout << "fan disks (" << mesh_name<Mesh>() << "): 12 border vertices, 9 inside edges joining border vertices, "
            << "both maps certified, every vertex on its own vertex" << std::endl;
  return EXIT_SUCCESS;
}

// A decagon with five ears (each ear's inside edge joins two border vertices around the ear's tip) and a centre
// vertex: the five tips would all have to be corners of the square, which has four, so whatever the corners one
// inside edge of B has both ends on one side and B itself has no valid map (this gave ERROR_DEGENERATE_CHORD). B's first map is then made on a copy of B with that edge split; B's map is on the
// refined copy, matched or not, and every location is still written in B's own faces. A == B and every vertex but
// the centre on the border: with the centres as landmark, every vertex lands exactly on its own vertex.
template <class Mesh>
int eared_decagon(Mesh& m)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  std::vector<vd> v;
  for(int k = 0; k < 11; ++k)
  {
    v.push_back(add_vertex(m));
    const double r = k == 10 ? 0. : 1 + 0.05 * (k % 3);
    put(CGAL::vertex_point, m, v.back(), Epick::Point_3(r * std::cos(0.6283 * k), r * std::sin(0.6283 * k), 0.02 * (k % 4)));
  }
  for(int i = 0; i < 5; ++i)
  {
    CHECK(CGAL::Euler::add_face(std::vector<vd>{ v[2 * i], v[2 * i + 1], v[(2 * i + 2) % 10] }, m) != boost::graph_traits<Mesh>::null_face(), "ear");
    CHECK(CGAL::Euler::add_face(std::vector<vd>{ v[2 * i], v[(2 * i + 2) % 10], v[10] }, m) != boost::graph_traits<Mesh>::null_face(), "inner face");
  }
  return EXIT_SUCCESS;
}

template <class Mesh>
int eared_disks()
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  Mesh a, b;
  RUN(eared_decagon(a));
  RUN(eared_decagon(b));
  const vd centre_a = *std::next(vertices(a).begin(), 10), centre_b = *std::next(vertices(b).begin(), 10);
  const std::vector<std::pair<vd, vd> > centres{ { centre_a, centre_b } }, none;
  for(int variant = 0; variant < 3; ++variant) // the matched map, B's first map kept, no landmark
  {
    const bool matched = variant == 0;
    const auto& landmarks = variant == 2 ? none : centres;
    Location_map<Mesh> loc, back;
    Mesh ca, cb;
    PE::Cross_parameterization_statistics st;
    const PE::Error_code ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(loc),
      PE::parameters::b_to_a_locations(boost::make_assoc_property_map(back),
        PE::parameters::matched_maps(matched, PE::parameters::compatible_meshes(std::make_pair(&ca, &cb),
          PE::parameters::statistics(&st)))));
    CHECK(ec == PE::OK, "variant " << variant << ": " << PE::get_error_message(ec) << " (failed mesh " << st.failed_mesh << ")");
    CHECK(st.report_a.is_valid() && st.report_b.is_valid() && st.landmarks_exact, "certified, landmarks exact");
    CHECK(st.chords_split_b >= 1 && st.vertices_added_b >= 1, "B's map on a refined copy: " << st.chords_split_b
          << " edges split, " << st.vertices_added_b << " vertices added");
    CHECK(st.matched_b == (variant == 0), "the matched map used when asked, with a landmark");
    CHECK(loc.size() == 11 && back.size() == 11 && st.located_b_on_a == 11, "every vertex located both ways");
    auto vb = vertices(b).begin();
    int k = 0;
    for(auto va = vertices(a).begin(); va != vertices(a).end(); ++va, ++vb, ++k)
    {
      if(variant == 2 && *va == centre_a) continue; // not a landmark: somewhere inside
      CHECK(weight_of(b, loc.at(*va), *vb) == 1., "vertex " << k << " of A on its own vertex");
      CHECK(weight_of(a, back.at(*vb), *va) == 1., "vertex " << k << " of B on its own vertex");
    }
    for(const auto& l : { loc.at(centre_a), back.at(centre_b) })
    {
      CHECK(l.second[0] >= 0 && l.second[1] >= 0 && l.second[2] >= 0, "a barycentric coordinate below zero");
      CHECK(std::abs(l.second[0] + l.second[1] + l.second[2] - 1) <= 1e-12, "barycentric coordinates summing to 1");
    }
    CHECK(st.report_compatible.is_valid() && num_vertices(ca) == num_vertices(cb) && num_faces(ca) == num_faces(cb)
          && num_faces(ca) > 10, "compatible meshes certified, of one size");
    std::cout << "eared decagons (" << mesh_name<Mesh>() << ", " << (variant == 0 ? "matched map" : variant == 1
              ? "B's first map" : "no landmark") << "): " << st.chords_split_b << " inside edge(s) of B split, "
              << st.vertices_added_b << " vertex(es) added to B's copy, both maps certified, every "
              << (variant == 2 ? "border vertex" : "vertex") << " on its own vertex both ways, compatible meshes of "
              << num_faces(ca) << " faces" << std::endl;
  }
  return EXIT_SUCCESS;
}

// Closed genus-0 surfaces: both cut into disks between the two landmarks nearest to each other, the others inside.
// blobby against itself (every landmark exactly on its partner, the map the identity up to the optimizer's
// tolerance; the compatible meshes closed, of one connectivity) and against its remeshed copy (the error bound of
// the disks); a genus-3 surface, a closed surface against a disk and a single landmark are refused, and the join
// along the cut refuses what is not closed.
// `k` vertices of `a` spread out, each with the vertex of `b` at its place in vertices(): two copies of one file
template <class Mesh>
std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor, typename boost::graph_traits<Mesh>::vertex_descriptor> >
same_place_landmarks(const Mesh& a, const Mesh& b, std::size_t k)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  std::vector<vd> va(vertices(a).begin(), vertices(a).end()), vb(vertices(b).begin(), vertices(b).end());
  std::unordered_map<vd, std::size_t, boost::hash<vd> > index;
  for(std::size_t i = 0; i < va.size(); ++i) index[va[i]] = i;
  std::vector<std::pair<vd, vd> > landmarks;
  for(vd v : PE::internal::spread_interior_vertices(a, k)) landmarks.emplace_back(v, vb[index.at(v)]);
  return landmarks;
}

template <class Mesh>
int closed_surfaces(const std::string& data_dir)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  Mesh a, b;
  const std::string file = data_dir + "/meshes/blobby.off";
  CHECK(CGAL::IO::read_polygon_mesh(file, a) && CGAL::IO::read_polygon_mesh(file, b), "read " << file);
  std::vector<vd> va(vertices(a).begin(), vertices(a).end()), vb(vertices(b).begin(), vertices(b).end());
  std::unordered_map<vd, std::size_t, boost::hash<vd> > index;
  for(std::size_t i = 0; i < va.size(); ++i) index[va[i]] = i;
  const std::vector<std::pair<vd, vd> > landmarks = same_place_landmarks(a, b, 6);
  Location_map<Mesh> loc;
  PE::Cross_parameterization_statistics st;
  PE::Error_code ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(loc), PE::parameters::statistics(&st));
  CHECK(ec == PE::OK, PE::get_error_message(ec) << " (failed mesh " << st.failed_mesh << ")");
  CHECK(st.closed && st.cut_edges_a > 0 && st.cut_edges_a == st.cut_edges_b, "cut along the same path");
  // two landmarks on the cut (the nearest pair of A, checked in the planar maps below), the four others inside
  CHECK(st.landmarks == 6 && st.cut_landmarks == 2 && st.border_landmarks == 2,
        "cut between two landmarks: " << st.cut_landmarks << " on the cut, " << st.border_landmarks << " border landmarks");
  std::vector<vd> landmarks_a;
  for(const auto& l : landmarks) landmarks_a.push_back(l.first);
  const auto candidates = PE::internal::landmark_pairs_to_cut(a, get(CGAL::vertex_point, a), landmarks_a);
  CHECK(!candidates.empty() && candidates.front().second.first < candidates.front().second.second, "pairs to cut between");
  CHECK(st.report_a.is_valid() && st.report_b.is_valid() && st.landmarks_exact, "certified, landmarks exact");
  CHECK(loc.size() == va.size(), "every vertex located");
  for(const auto& l : landmarks) CHECK(weight_of(b, loc.at(l.first), l.second) == 1., "landmark exactly on its partner");
  const auto error = PE::internal::correspondence_error(a, b, boost::make_assoc_property_map(loc));
  // the same cut and the same border on both (the corners avoid flat chords, so B's disk is not split), the four
  // landmarks inside pinned where B's first map puts them, in A's map and in B's matched map alike: one computation,
  // the identity (0 here; up to a rounding of the barycentric coordinates)
  CHECK(st.chords_split_b == 0 && st.matched_b && error.second < 1e-12,
        "the identity: mean error " << error.first << ", max " << error.second);
  std::cout << "closed " << file << " (" << mesh_name<Mesh>() << ") against itself, 6 landmarks: cut along "
            << st.cut_edges_a << " edges, both disks certified, landmarks exact, mean error " << error.first
            << " of the diagonal, max " << error.second << ", " << st.seconds_total << " s" << std::endl;
  // the other direction: B's vertices located on A's faces, the identity too, every landmark of B on its partner;
  // a border pair does not apply to closed meshes
  {
    Location_map<Mesh> same, back;
    PE::Cross_parameterization_statistics sb;
    ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(same),
           PE::parameters::b_to_a_locations(boost::make_assoc_property_map(back), PE::parameters::statistics(&sb)));
    CHECK(ec == PE::OK && same == loc && back.size() == vb.size() && sb.located_b_on_a == vb.size(),
          "closed surfaces with b_to_a_locations: " << PE::get_error_name(ec) << ", " << back.size() << " located");
    for(const auto& l : landmarks) CHECK(weight_of(a, back.at(l.second), l.first) == 1., "landmark of B exactly on its partner");
    const auto back_error = PE::internal::correspondence_error(b, a, boost::make_assoc_property_map(back));
    CHECK(back_error.second < 1e-9, "B onto A: the identity, max error " << back_error.second);
    std::cout << "closed, B's vertices on A: max error " << back_error.second << std::endl;
    Location_map<Mesh> none;
    ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(none),
                                    PE::parameters::border_vertex_pair(landmarks.front()));
    CHECK(ec == PE::ERROR_WRONG_PARAMETER && none.empty(), "a border pair on closed meshes refused");
  }
  // the compatible meshes: the overlay of the cut disks' maps joined along the cut, two closed genus-0 meshes of one
  // connectivity, the same locations; the planar maps are those of the cut disks (the mesh's vertices first, then the
  // copies on the cut); nothing asked with null pointers
  {
    Location_map<Mesh> with_meshes, again;
    Surface_mesh ca, cb, pa, pb;
    PE::Cross_parameterization_statistics sm;
    ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(with_meshes),
           PE::parameters::compatible_meshes(std::make_pair(&ca, &cb), PE::parameters::statistics(&sm)));
    CHECK(ec == PE::OK && with_meshes == loc, "closed surfaces with compatible meshes: the same map");
    CHECK(sm.report_compatible.is_valid() && sm.cut_vertices_welded > 0, "overlays certified, joined along the cut");
    CHECK(num_vertices(ca) == num_vertices(cb) && num_faces(ca) == num_faces(cb) && num_vertices(ca) == sm.compatible_vertices &&
          CGAL::is_closed(ca) && CGAL::is_closed(cb) && CGAL::is_valid_polygon_mesh(ca) && CGAL::is_triangle_mesh(ca) &&
          long(num_vertices(ca)) - long(num_edges(ca)) + long(num_faces(ca)) == 2, "two closed genus-0 meshes");
    bool same_faces = true;
    for(auto f : faces(ca))
    {
      auto ha = halfedge(f, ca), hb = halfedge(f, cb);
      for(int k = 0; k < 3; ++k, ha = next(ha, ca), hb = next(hb, cb)) same_faces = same_faces && target(ha, ca) == target(hb, cb);
    }
    CHECK(same_faces, "one connectivity");
    std::set<std::array<double, 3> > points_a;
    for(auto v : vertices(ca)) points_a.insert({{ ca.point(v).x(), ca.point(v).y(), ca.point(v).z() }});
    std::size_t kept = 0;
    for(vd v : vertices(a))
    {
      const auto& p = get(CGAL::vertex_point, a, v);
      kept += points_a.count({{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }});
    }
    // (not once each: a vertex of B within rounding of a vertex of A in the plane lands on the same 3D point)
    CHECK(kept == va.size(), "every vertex of A in A'");
    std::cout << "closed compatible meshes: " << num_vertices(ca) << " vertices, " << num_faces(ca) << " faces, "
              << sm.cut_vertices_welded << " joined along the cut, closed, Euler characteristic 2" << std::endl;
    // two landmarks (the way back the mirror image of the way there) and three (two on the cut, one inside)
    for(std::size_t k : { std::size_t(2), std::size_t(3) })
    {
      const std::vector<std::pair<vd, vd> > few(landmarks.begin(), landmarks.begin() + std::ptrdiff_t(k));
      Location_map<Mesh> lk;
      Surface_mesh ka, kb;
      PE::Cross_parameterization_statistics sk;
      ec = PE::cross_parameterization(a, b, few, boost::make_assoc_property_map(lk),
             PE::parameters::compatible_meshes(std::make_pair(&ka, &kb), PE::parameters::statistics(&sk)));
      CHECK(ec == PE::OK && sk.landmarks_exact && sk.cut_vertices_welded > 0, k << " landmarks: " << PE::get_error_name(ec));
      CHECK(CGAL::is_closed(ka) && num_vertices(ka) == num_vertices(kb) &&
            long(num_vertices(ka)) - long(num_edges(ka)) + long(num_faces(ka)) == 2, k << " landmarks: closed genus 0");
      const auto ek = PE::internal::correspondence_error(a, b, boost::make_assoc_property_map(lk));
      // with two, no landmark inside: no matched map, A's map optimized on its own to the optimizer's tolerance
      // (4.4e-12 of the diagonal); with three, matched: 0
      CHECK(ek.second < (k == 2 ? 1e-8 : 1e-12), k << " landmarks: the identity, max error " << ek.second);
      std::cout << k << " landmarks: compatible meshes of " << num_vertices(ka) << " vertices (" << sk.cut_vertices_welded
                << " joined), max error " << ek.second << std::endl;
    }
    PE::Cross_parameterization_statistics sp;
    ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(again),
           PE::parameters::compatible_meshes(std::make_pair(static_cast<Surface_mesh*>(nullptr), static_cast<Surface_mesh*>(nullptr)),
             PE::parameters::planar_maps(std::make_pair(&pa, &pb), PE::parameters::statistics(&sp))));
    CHECK(ec == PE::OK && again == loc, "closed surfaces with planar_maps (compatible_meshes with null pointers): the same map");
    CHECK(num_vertices(pa) == va.size() + sp.cut_edges_a - 1 + sp.vertices_added_a && num_vertices(pa) == sp.vertices_a + sp.vertices_added_a &&
          num_vertices(pb) == sp.vertices_b + sp.vertices_added_b, "the planar maps of the cut disks");
    for(const auto& l : landmarks)
      CHECK(pa.point(Surface_mesh::Vertex_index(static_cast<Surface_mesh::size_type>(index[l.first]))) ==
              pb.point(Surface_mesh::Vertex_index(static_cast<Surface_mesh::size_type>(index[l.first]))),
            "a landmark at its partner's point in the planar maps");
    // the first pair to cut between on the square's border, the other landmarks strictly inside
    for(std::size_t k = 0; k < landmarks.size(); ++k)
    {
      const auto& p = pa.point(Surface_mesh::Vertex_index(static_cast<Surface_mesh::size_type>(index[landmarks[k].first])));
      const bool on_square = p.x() == 0 || p.x() == 1 || p.y() == 0 || p.y() == 1;
      const bool on_cut = k == candidates.front().second.first || k == candidates.front().second.second;
      CHECK(on_square == on_cut && p.x() >= 0 && p.x() <= 1 && p.y() >= 0 && p.y() <= 1,
            "landmark " << k << (on_cut ? " on the cut" : " inside") << ": at (" << p.x() << ", " << p.y() << ")");
    }
  }
  // cow.off against itself with 50 landmarks: B's map of its cut disk made again as A's is (matched maps), on a
  // copy refined by a Steiner vertex as A's is; the two maps one computation, so the map is the identity (with B's
  // first map, A's settled elsewhere: largest error 3.2% of the diagonal), and the overlay of the refined copies
  // is joined along the cut (a vertex of B's copy named by the vertex of B's cut disk it is)
  {
    Mesh s, t;
    const std::string cow = data_dir + "/meshes/cow.off";
    CHECK(CGAL::IO::read_polygon_mesh(cow, s) && CGAL::IO::read_polygon_mesh(cow, t), "read " << cow);
    const std::vector<std::pair<vd, vd> > fifty = same_place_landmarks(s, t, 50);
    Location_map<Mesh> ls, back;
    Surface_mesh cs, ct, ps, pt;
    PE::Cross_parameterization_statistics ss;
    ec = PE::cross_parameterization(s, t, fifty, boost::make_assoc_property_map(ls),
           PE::parameters::compatible_meshes(std::make_pair(&cs, &ct),
             PE::parameters::b_to_a_locations(boost::make_assoc_property_map(back),
               PE::parameters::planar_maps(std::make_pair(&ps, &pt), PE::parameters::statistics(&ss)))));
    CHECK(ec == PE::OK && ss.closed && ss.landmarks_exact, "cow against itself: " << PE::get_error_name(ec));
    CHECK(ss.matched_b && ss.vertices_added_b > 0 && ss.vertices_added_b == ss.vertices_added_a,
          "B's matched map on a refined copy: matched " << ss.matched_b << ", " << ss.vertices_added_b << " added to B, "
          << ss.vertices_added_a << " to A");
    const auto es = PE::internal::correspondence_error(s, t, boost::make_assoc_property_map(ls));
    CHECK(es.second < 1e-12, "cow against itself: the identity, max error " << es.second);
    // B's vertices located through its refined copy onto A, and B's planar map that copy's (its added vertex last)
    const auto eb = PE::internal::correspondence_error(t, s, boost::make_assoc_property_map(back));
    CHECK(back.size() == num_vertices(t) && ss.located_b_on_a == num_vertices(t) && eb.second < 1e-12,
          "cow against itself, B onto A: " << back.size() << " located, max error " << eb.second);
    CHECK(num_vertices(pt) == ss.vertices_b + ss.vertices_added_b && num_vertices(ps) == ss.vertices_a + ss.vertices_added_a,
          "the planar maps of the refined copies");
    // the two copies' overlay is the refined copy itself, joined along the cut: A' and B' the same points
    CHECK(CGAL::is_closed(cs) && num_vertices(cs) == num_vertices(ct) && num_vertices(cs) == num_vertices(s) + ss.vertices_added_a &&
          ss.cut_vertices_welded > 0 && long(num_vertices(cs)) - long(num_edges(cs)) + long(num_faces(cs)) == 2,
          "cow against itself: compatible meshes closed genus 0, " << num_vertices(cs) << " vertices");
    bool same_points = true;
    for(auto v : vertices(cs)) same_points = same_points && CGAL::squared_distance(cs.point(v), ct.point(v)) < 1e-20;
    CHECK(same_points, "cow against itself: A' and B' the same points");
    std::cout << "closed " << cow << " (" << mesh_name<Mesh>() << ") against itself, 50 landmarks: B's matched map with "
              << ss.vertices_added_b << " vertex added, max error " << es.second << " (B onto A " << eb.second
              << "), compatible meshes of " << num_vertices(cs) << " vertices joined along the cut ("
              << ss.cut_vertices_welded << " points)" << std::endl;
    // against its remeshed copy with 20 landmarks: B's matched map on a copy refined by Steiner vertices, its
    // overlay with A's map joined along the cut (the points of B's refined copy named by its cut disk's vertices)
    Surface_mesh r;
    CHECK(CGAL::IO::read_polygon_mesh(cow, r), "read " << cow);
    PE::internal::remesh_isotropically(r);
    r.collect_garbage();
    std::unordered_map<vd, PE::Cross_location<Surface_mesh>, boost::hash<vd> > lr;
    Surface_mesh cr, dr;
    PE::Cross_parameterization_statistics sr;
    ec = PE::cross_parameterization(s, r, PE::internal::nearest_vertex_landmarks(s, r, PE::internal::spread_interior_vertices(s, 20)),
           boost::make_assoc_property_map(lr), PE::parameters::compatible_meshes(std::make_pair(&cr, &dr), PE::parameters::statistics(&sr)));
    CHECK(ec == PE::OK && sr.landmarks_exact && sr.matched_b && sr.vertices_added_b > 0 && sr.report_compatible.is_valid() &&
          sr.cut_vertices_welded > 0 && CGAL::is_closed(cr) && num_vertices(cr) == num_vertices(dr) &&
          long(num_vertices(cr)) - long(num_edges(cr)) + long(num_faces(cr)) == 2,
          "cow against its remeshed copy: " << PE::get_error_name(ec) << ", matched " << sr.matched_b << ", "
          << sr.vertices_added_b << " added to B");
    const auto er = PE::internal::correspondence_error(s, r, boost::make_assoc_property_map(lr));
    CHECK(er.first < 0.03, "cow against its remeshed copy: mean error " << er.first);
    std::cout << "closed " << cow << " against its remeshed copy, 20 landmarks: B's matched map with " << sr.vertices_added_b
              << " vertices added, compatible meshes of " << num_vertices(cr) << " vertices joined along the cut, mean error "
              << er.first << ", max " << er.second << std::endl;
  }
  // against its remeshed copy
  Surface_mesh c;
  CHECK(CGAL::IO::read_polygon_mesh(file, c), "read " << file);
  PE::internal::remesh_isotropically(c);
  c.collect_garbage();
  std::unordered_map<vd, PE::Cross_location<Surface_mesh>, boost::hash<vd> > loc_c;
  PE::Cross_parameterization_statistics sc;
  ec = PE::cross_parameterization(a, c, PE::internal::nearest_vertex_landmarks(a, c, PE::internal::spread_interior_vertices(a, 6)),
                                  boost::make_assoc_property_map(loc_c), PE::parameters::statistics(&sc));
  CHECK(ec == PE::OK, PE::get_error_message(ec) << " (failed mesh " << sc.failed_mesh << ")");
  const auto error_c = PE::internal::correspondence_error(a, c, boost::make_assoc_property_map(loc_c));
  CHECK(error_c.first < 0.02, "mean error against the remeshed copy " << error_c.first);
  std::cout << "closed " << file << " against its remeshed copy (" << sc.vertices_b << " vertices after the cut), 6 landmarks: "
            << "mean error " << error_c.first << ", max " << error_c.second << ", " << sc.seconds_total << " s" << std::endl;
  // the join along the cut alone: refused, nothing changed, when a border point is of neither map or the joined
  // triangles are not a closed surface
  {
    std::vector<std::array<double, 3> > on_a = { {{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}} }, on_b = on_a;
    std::vector<std::array<std::size_t, 3> > triangles = { {{0, 1, 2}} };
    const std::size_t none = std::size_t(-1);
    std::size_t welded = 7;
    ec = PE::internal::weld_cut_overlay(on_a, on_b, triangles, { {{none, none}}, {{1, none}}, {{2, none}} }, welded);
    CHECK(ec == PE::ERROR_INVALID_EMBEDDING && welded == 0 && on_a.size() == 3 && triangles.size() == 1, "a border point of neither map");
    ec = PE::internal::weld_cut_overlay(on_a, on_b, triangles, { {{0, none}}, {{1, none}}, {{2, none}} }, welded);
    CHECK(ec == PE::ERROR_INVALID_EMBEDDING && on_a.size() == 3, "a triangle is not closed");
    // the certificate of the joined triangles: a tetrahedron, and what is not a closed genus-0 surface
    typedef std::vector<std::array<std::size_t, 3> > Soup;
    const Soup tetrahedron = { {{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 3}}, {{0, 3, 2}} };
    std::vector<std::array<double, 3> > points = { {{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}} };
    CHECK(PE::internal::is_closed_genus_zero_soup(points, tetrahedron), "a tetrahedron is a closed genus-0 surface");
    Soup open(tetrahedron.begin(), tetrahedron.end() - 1), flipped = tetrahedron, two = tetrahedron, pinched = tetrahedron;
    std::swap(flipped[3][1], flipped[3][2]);
    CHECK(!PE::internal::is_closed_genus_zero_soup(points, open), "a tetrahedron without one face");
    CHECK(!PE::internal::is_closed_genus_zero_soup(points, flipped), "a tetrahedron with one face the other way");
    CHECK(!PE::internal::is_closed_genus_zero_soup(points, Soup()), "no triangle");
    std::vector<std::array<double, 3> > more = points;
    for(const auto& p : points) more.push_back({{p[0] + 2, p[1], p[2]}});
    for(const auto& t : tetrahedron) two.push_back({{t[0] + 4, t[1] + 4, t[2] + 4}});
    CHECK(!PE::internal::is_closed_genus_zero_soup(more, two), "two tetrahedra: two components");
    CHECK(!PE::internal::is_closed_genus_zero_soup(more, tetrahedron), "points in no triangle");
    // the second tetrahedron's vertices 1, 2, 3 are points 4, 5, 6, its vertex 0 is the first's
    for(const auto& t : tetrahedron) pinched.push_back({{t[0] == 0 ? 0 : t[0] + 3, t[1] == 0 ? 0 : t[1] + 3, t[2] == 0 ? 0 : t[2] + 3}});
    more.resize(7);
    CHECK(!PE::internal::is_closed_genus_zero_soup(more, pinched), "two tetrahedra sharing a vertex");
    // a tetrahedron whose vertex 3 is two points on a border: joined into one, the tetrahedron again
    on_a = points;
    on_a.push_back(points[3]);
    on_b = on_a;
    triangles = { {{0, 2, 1}}, {{0, 1, 3}}, {{1, 2, 4}}, {{0, 3, 2}} };
    ec = PE::internal::weld_cut_overlay(on_a, on_b, triangles, { {{0, none}}, {{1, none}}, {{2, none}}, {{3, none}}, {{3, none}} }, welded);
    CHECK(ec == PE::OK && welded == 1 && on_a.size() == 4 && on_b.size() == 4 && triangles == tetrahedron,
          "a tetrahedron cut at one vertex joined: " << PE::get_error_name(ec) << ", " << welded << " joined");
  }
  // refused: genus 3; a closed surface and a disk; one landmark
  {
    Mesh g;
    CHECK(CGAL::IO::read_polygon_mesh(data_dir + "/meshes/elephant.off", g), "read elephant.off");
    std::vector<std::pair<vd, vd> > two;
    auto gv = vertices(g).begin();
    for(std::size_t k = 0; k < 2; ++k, ++gv) two.emplace_back(*gv, landmarks[k].second);
    Location_map<Mesh> none;
    ec = PE::cross_parameterization(g, b, two, boost::make_assoc_property_map(none), PE::parameters::statistics(&st));
    CHECK(ec == PE::ERROR_NOT_GENUS_ZERO && st.failed_mesh == 0 && none.empty(), "genus 3 refused: " << PE::get_error_name(ec));
    Mesh disk;
    CHECK(CGAL::IO::read_polygon_mesh(data_dir + "/meshes/mushroom.off", disk), "read mushroom.off");
    const std::vector<std::pair<vd, vd> > no_landmarks;
    ec = PE::cross_parameterization(a, disk, no_landmarks, boost::make_assoc_property_map(none), PE::parameters::statistics(&st));
    CHECK(ec == PE::ERROR_NOT_A_DISK && st.failed_mesh == 0 && none.empty(), "closed and disk refused: " << PE::get_error_name(ec));
    ec = PE::cross_parameterization(a, b, std::vector<std::pair<vd, vd> >(1, landmarks[0]), boost::make_assoc_property_map(none),
                                    PE::parameters::statistics(&st));
    CHECK(ec == PE::ERROR_WRONG_PARAMETER && none.empty(), "one landmark refused: " << PE::get_error_name(ec));
    // two landmarks joined by an edge of A: a cut along one edge opens nothing; the second landmark is named
    {
      const vd v0 = landmarks[0].first, v1 = source(halfedge(v0, a), a);
      const std::vector<std::pair<vd, vd> > joined{ { v0, landmarks[0].second }, { v1, landmarks[1].second } };
      ec = PE::cross_parameterization(a, b, joined, boost::make_assoc_property_map(none), PE::parameters::statistics(&st));
      CHECK(ec == PE::ERROR_NOT_A_DISK && st.failed_landmark == 1 && st.failed_mesh == 0 && none.empty(),
            "two landmarks joined by an edge refused: " << PE::get_error_name(ec) << ", landmark " << st.failed_landmark);
    }
    // B read again with a NaN point: its landmarks are its vertices at the same positions in the file
    Mesh nan_b;
    CHECK(CGAL::IO::read_polygon_mesh(file, nan_b), "read " << file);
    const std::vector<vd> vn(vertices(nan_b).begin(), vertices(nan_b).end());
    std::unordered_map<vd, std::size_t, boost::hash<vd> > index_b;
    for(std::size_t i = 0; i < vb.size(); ++i) index_b[vb[i]] = i;
    std::vector<std::pair<vd, vd> > landmarks_n;
    for(const auto& l : landmarks) landmarks_n.emplace_back(l.first, vn[index_b.at(l.second)]);
    put(get(CGAL::vertex_point, nan_b), vn[7], Epick::Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0));
    ec = PE::cross_parameterization(a, nan_b, landmarks_n, boost::make_assoc_property_map(none), PE::parameters::statistics(&st));
    CHECK(ec == PE::ERROR_NON_FINITE_COORDINATES && st.failed_mesh == 1 && none.empty(), "a NaN point refused: " << PE::get_error_name(ec));
  }
  std::cout << "closed surfaces refused: genus 3 (ERROR_NOT_GENUS_ZERO), closed against a disk (ERROR_NOT_A_DISK), "
            << "one landmark (ERROR_WRONG_PARAMETER), two landmarks joined by an edge (ERROR_NOT_A_DISK, the second named), "
            << "a NaN point in B (ERROR_NON_FINITE_COORDINATES)" << std::endl;
  return EXIT_SUCCESS;
}

// Where a closed surface is cut (internal/cross/cut_pair.h) on the octahedron (poles 0 and 5, equator 1 2 3 4): the
// pairs whose regions of nearest vertices meet across an edge with an end that is no landmark, nearest first (ties to
// the earlier positions); none when every vertex is a landmark (the chain through all is then the cut, certified with
// the compatible meshes). A pair that A can cut and B cannot is passed over: A the octahedron with each face split
// in four, B the octahedron, landmarks 1 2 0 5 4: on B landmark 1 has only landmarks around it, so the four pairs
// with it (the nearest on A) are passed over and a later pair is cut.
template <class Mesh>
int cut_between_nearest_landmarks()
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  typedef std::vector<std::array<std::size_t, 3> > Soup;
  const std::vector<Epick::Point_3> points = { { 0, 0, 1 }, { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 }, { 0, -1, 0 }, { 0, 0, -1 } };
  const Soup triangles = { {{ 0, 1, 2 }}, {{ 0, 2, 3 }}, {{ 0, 3, 4 }}, {{ 0, 4, 1 }},
                           {{ 5, 2, 1 }}, {{ 5, 3, 2 }}, {{ 5, 4, 3 }}, {{ 5, 1, 4 }} };
  Mesh m;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, m);
  std::vector<vd> v(vertices(m).begin(), vertices(m).end());
  auto first_pair = [&](const std::vector<std::size_t>& chosen) {
    std::vector<vd> l;
    for(std::size_t i : chosen) l.push_back(v[i]);
    const auto c = PE::internal::landmark_pairs_to_cut(m, get(CGAL::vertex_point, m), l);
    return c.empty() ? std::make_pair(std::size_t(7), std::size_t(7)) : c.front().second;
  };
  typedef std::pair<std::size_t, std::size_t> Pair;
  // the poles: two edges apart through the equator
  CHECK(first_pair({ 0, 5 }) == Pair(0, 1), "the poles");
  // 1, 2, 3: the vertices that are no landmarks all nearest to 1 (ties to the earlier), whose region meets 2's and
  // 3's: the pair 1-2, joined by an edge, is cut around it
  CHECK(first_pair({ 1, 2, 3 }) == Pair(0, 1), "1, 2, 3");
  CHECK(first_pair({ 2, 0, 4, 5 }) == Pair(0, 1), "2, 0, 4, 5");
  // every vertex a landmark, and a single landmark: no pair
  CHECK(first_pair({ 0, 1, 2, 3, 4, 5 }) == Pair(7, 7), "all six: no pair");
  CHECK(first_pair({ 3 }) == Pair(7, 7), "one landmark: no pair");
  // the call with all six: the chain through them, in their order (1 0 2 3 4 5 makes one), with the compatible meshes
  Mesh b;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, b);
  std::vector<vd> w(vertices(b).begin(), vertices(b).end());
  std::vector<std::pair<vd, vd> > landmarks;
  for(std::size_t i : { 1, 0, 2, 3, 4, 5 }) landmarks.emplace_back(v[i], w[i]);
  Location_map<Mesh> loc;
  PE::Cross_parameterization_statistics st;
  Surface_mesh ca, cb;
  PE::Error_code ec = PE::cross_parameterization(m, b, landmarks, boost::make_assoc_property_map(loc),
                        PE::parameters::compatible_meshes(std::make_pair(&ca, &cb), PE::parameters::statistics(&st)));
  CHECK(ec == PE::OK && st.closed && st.cut_landmarks == 6 && st.landmarks == 6 && st.landmarks_exact &&
        st.report_a.is_valid() && st.report_b.is_valid() && st.report_compatible.is_valid() && CGAL::is_closed(ca) &&
        num_vertices(ca) == num_vertices(cb) && long(num_vertices(ca)) - long(num_edges(ca)) + long(num_faces(ca)) == 2,
        "the octahedron's chain: " << PE::get_error_name(ec) << ", " << st.cut_landmarks << " landmarks on the cut");
  // A: each face split in four at its edges' midpoints
  std::vector<Epick::Point_3> fine_points = points;
  Soup fine;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> midpoint;
  auto mid = [&](std::size_t i, std::size_t j) {
    const auto key = std::make_pair((std::min)(i, j), (std::max)(i, j));
    auto it = midpoint.find(key);
    if(it != midpoint.end()) return it->second;
    fine_points.push_back(CGAL::midpoint(points[i], points[j]));
    return midpoint[key] = fine_points.size() - 1;
  };
  for(const auto& t : triangles)
  {
    const std::size_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca_ = mid(t[2], t[0]);
    fine.push_back({{ t[0], ab, ca_ }});
    fine.push_back({{ ab, t[1], bc }});
    fine.push_back({{ ca_, bc, t[2] }});
    fine.push_back({{ ab, bc, ca_ }});
  }
  Mesh f;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(fine_points, fine, f);
  std::vector<vd> vf(vertices(f).begin(), vertices(f).end());
  std::vector<std::pair<vd, vd> > five;
  std::vector<vd> five_a;
  for(std::size_t i : { 1, 2, 0, 5, 4 }) { five.emplace_back(vf[i], w[i]); five_a.push_back(vf[i]); }
  const auto candidates = PE::internal::landmark_pairs_to_cut(f, get(CGAL::vertex_point, f), five_a);
  // (the four pairs with landmark 1 come first, all as near: on B each has only landmarks around landmark 1)
  CHECK(candidates.size() == 9 && candidates[0].second == Pair(0, 1) && candidates[3].second == Pair(0, 4),
        "the subdivided octahedron's pairs: " << candidates.size());
  Location_map<Mesh> loc5;
  PE::Cross_parameterization_statistics s5;
  ec = PE::cross_parameterization(f, b, five, boost::make_assoc_property_map(loc5), PE::parameters::statistics(&s5));
  CHECK(ec == PE::OK && s5.cut_landmarks == 2 && s5.landmarks_exact && s5.report_a.is_valid() && s5.report_b.is_valid(),
        "a pair B cannot cut passed over: " << PE::get_error_name(ec) << ", " << s5.cut_landmarks << " landmarks on the cut");
  for(const auto& l : five) CHECK(weight_of(b, loc5.at(l.first), l.second) == 1., "landmark exactly on its partner");
  std::cout << "cut between landmarks near each other (" << mesh_name<Mesh>() << "): the octahedron's pairs as expected, "
            << "none with every vertex a landmark (the chain through all six, certified with the compatible meshes: "
            << num_vertices(ca) << " vertices); the subdivided octahedron onto the octahedron, 5 landmarks: the pairs "
            << "B cannot cut passed over, a later one cut, certified, landmarks exact" << std::endl;
  return EXIT_SUCCESS;
}

// every error: the code, the landmark and the mesh named, nothing written
template <class Mesh>
int errors(const std::string& data_dir)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  Mesh a, b, holed;
  PE::internal::make_grid_disk(6, a);
  PE::internal::make_grid_disk(6, b);
  PE::internal::make_grid_disk(6, holed);
  const std::vector<vd> ia = interior_vertices(a), ib = interior_vertices(b);
  std::vector<vd> ba, bb;
  for(auto v : vertices(a)) if(CGAL::is_border(v, a)) ba.push_back(v);
  for(auto v : vertices(b)) if(CGAL::is_border(v, b)) bb.push_back(v);
  // a hole in the middle: two border cycles
  {
    const std::vector<vd> ih = interior_vertices(holed);
    CGAL::Euler::remove_face(halfedge(*faces_around_target(halfedge(ih[ih.size() / 2], holed), holed).begin(), holed), holed);
  }
  vd foreign;
  {
    // a vertex of another mesh with more vertices
    static Mesh big;
    PE::internal::make_grid_disk(9, big);
    foreign = *std::prev(vertices(big).end());
  }
  (void)data_dir;
  Location_map<Mesh> loc;
  auto run = [&](const Mesh& ma, const Mesh& mb, const std::vector<std::pair<vd, vd> >& l, PE::Error_code expected,
                 std::size_t failed_landmark, int failed_mesh, const char* what) -> int
  {
    PE::Cross_parameterization_statistics st;
    const std::size_t na = num_vertices(ma), nb = num_vertices(mb);
    const PE::Error_code ec = PE::cross_parameterization(ma, mb, l, boost::make_assoc_property_map(loc), PE::parameters::statistics(&st));
    CHECK(ec == expected, what << ": " << PE::get_error_name(ec));
    CHECK(st.failed_landmark == failed_landmark && st.failed_mesh == failed_mesh,
          what << ": landmark " << st.failed_landmark << ", mesh " << st.failed_mesh);
    CHECK(loc.empty(), what << ": nothing written");
    CHECK(num_vertices(ma) == na && num_vertices(mb) == nb, what << ": meshes untouched");
    std::cout << "  " << mesh_name<Mesh>() << ", " << what << ": " << PE::get_error_name(ec) << std::endl;
    return EXIT_SUCCESS;
  };
  const std::size_t none = std::size_t(-1);
  RUN(run(holed, b, {}, PE::ERROR_NOT_A_DISK, none, 0, "A not a disk"));
  RUN(run(a, holed, {}, PE::ERROR_NOT_A_DISK, none, 1, "B not a disk"));
  RUN(run(a, b, { { ia[0], ib[0] }, { foreign, ib[1] } }, PE::ERROR_WRONG_PARAMETER, 1, 0, "landmark not of A"));
  RUN(run(a, b, { { ia[0], ib[0] }, { ia[1], foreign } }, PE::ERROR_WRONG_PARAMETER, 1, 1, "landmark not of B"));
  RUN(run(a, b, { { ia[0], ib[0] }, { ia[0], ib[1] } }, PE::ERROR_DUPLICATE_CONSTRAINT, 1, 0, "vertex of A twice"));
  RUN(run(a, b, { { ia[0], ib[0] }, { ia[1], ib[0] } }, PE::ERROR_DUPLICATE_CONSTRAINT, 1, 1, "vertex of B twice"));
  RUN(run(a, b, { { ia[0], ib[0] }, { ba[0], ib[1] } }, PE::ERROR_CONSTRAINT_ON_BORDER, 1, 0, "landmark on A's border"));
  RUN(run(a, b, { { ia[0], ib[0] }, { ia[1], bb[0] } }, PE::ERROR_CONSTRAINT_ON_BORDER, 1, 1, "landmark on B's border"));
  {
    // a border landmark that gives a vertex of border_vertex_pair another partner: that landmark is named
    PE::Cross_parameterization_statistics st;
    const std::vector<std::pair<vd, vd> > l{ { ia[0], ib[0] }, { ba[0], bb[0] } };
    const PE::Error_code ec = PE::cross_parameterization(a, b, l, boost::make_assoc_property_map(loc),
      PE::parameters::border_vertex_pair(std::make_pair(ba[0], bb[1]), PE::parameters::statistics(&st)));
    CHECK(ec == PE::ERROR_DUPLICATE_CONSTRAINT && st.failed_landmark == 1 && st.failed_mesh == 0 && loc.empty(),
          "a border landmark against border_vertex_pair: " << PE::get_error_name(ec) << ", landmark " << st.failed_landmark);
    std::cout << "  " << mesh_name<Mesh>() << ", a border landmark against border_vertex_pair: " << PE::get_error_name(ec)
              << ", landmark " << st.failed_landmark << std::endl;
  }
  {
    // a single triangle: three border vertices for the square's four corners, on A or on B
    Mesh tri;
    CGAL::make_triangle(Epick::Point_3(0, 0, 0), Epick::Point_3(1, 0, 0), Epick::Point_3(0, 1, 0), tri);
    RUN(run(tri, b, {}, PE::ERROR_BORDER_TOO_SHORT, none, 0, "A with three border vertices"));
    RUN(run(a, tri, {}, PE::ERROR_BORDER_TOO_SHORT, none, 1, "B with three border vertices"));
  }
  {
    // an empty mesh, against a disk or against a closed mesh: empty (not "a closed mesh against a disk")
    Mesh empty, closed;
    CGAL::make_tetrahedron(Epick::Point_3(0, 0, 0), Epick::Point_3(1, 0, 0), Epick::Point_3(0, 1, 0),
                           Epick::Point_3(0, 0, 1), closed);
    RUN(run(empty, b, {}, PE::ERROR_EMPTY_MESH, none, 0, "A empty"));
    RUN(run(closed, empty, {}, PE::ERROR_EMPTY_MESH, none, 1, "B empty against a closed A"));
  }
  {
    // a NaN 3D point inside A, an infinite one on B's border (not a path that cannot be traced)
    Mesh nan_a, inf_b;
    PE::internal::make_grid_disk(6, nan_a);
    PE::internal::make_grid_disk(6, inf_b);
    const std::vector<vd> in_nan = interior_vertices(nan_a), in_inf = interior_vertices(inf_b);
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    put(get(CGAL::vertex_point, nan_a), in_nan[in_nan.size() / 2], Epick::Point_3(nan, 0, 0));
    for(auto v : vertices(inf_b))
      if(CGAL::is_border(v, inf_b)) { put(get(CGAL::vertex_point, inf_b), v, Epick::Point_3(0, inf, 0)); break; }
    RUN(run(nan_a, b, { { in_nan[0], ib[0] } }, PE::ERROR_NON_FINITE_COORDINATES, none, 0, "a NaN point in A"));
    RUN(run(a, inf_b, { { ia[0], in_inf[0] } }, PE::ERROR_NON_FINITE_COORDINATES, none, 1, "an infinite point on B's border"));
  }
  {
    // extreme sizes are not bad input: A, or A and B, scaled by 2^600 or 2^-600 (squared 3D lengths overflow or
    // underflow in double) give the locations of A itself, bit for bit (a power of two is exact)
    const std::vector<std::pair<vd, vd> > one{ { ia[0], ib[0] } };
    Location_map<Mesh> ref;
    PE::Cross_parameterization_statistics st;
    CHECK(PE::cross_parameterization(a, b, one, boost::make_assoc_property_map(ref), PE::parameters::statistics(&st)) == PE::OK,
          "A itself");
    auto scaled_copy = [](const Mesh& m, int e) {
      Mesh s(m); // the same order of vertices, faces and halfedges
      for(auto v : vertices(s))
      {
        const Epick::Point_3 p = get(CGAL::vertex_point, s, v);
        put(get(CGAL::vertex_point, s), v, Epick::Point_3(std::ldexp(p.x(), e), std::ldexp(p.y(), e), std::ldexp(p.z(), e)));
      }
      return s;
    };
    // the same element of a copy: at the same place in the order
    auto same_place = [](const auto& range, const auto& copy_range, const auto& x) {
      return *std::next(copy_range.begin(), std::distance(range.begin(), std::find(range.begin(), range.end(), x)));
    };
    for(const bool both : { false, true })
      for(const int e : { 600, -600 })
      {
        const std::string what = std::string(both ? "A and B" : "A") + " scaled by 2^" + std::to_string(e);
        const Mesh as = scaled_copy(a, e), bs = both ? scaled_copy(b, e) : Mesh(b);
        Location_map<Mesh> scaled;
        const std::vector<std::pair<vd, vd> > one_s{ { same_place(vertices(a), vertices(as), ia[0]),
                                                       same_place(vertices(b), vertices(bs), ib[0]) } };
        const PE::Error_code ec = PE::cross_parameterization(as, bs, one_s, boost::make_assoc_property_map(scaled),
                                                             PE::parameters::statistics(&st));
        CHECK(ec == PE::OK && st.report_a.is_valid() && st.report_b.is_valid(), what << ": " << PE::get_error_name(ec));
        auto vs = vertices(as).begin();
        for(auto va = vertices(a).begin(); va != vertices(a).end(); ++va, ++vs)
          CHECK(scaled.count(*vs) == 1 && scaled.at(*vs).first == same_place(faces(b), faces(bs), ref.at(*va).first)
                && scaled.at(*vs).second == ref.at(*va).second, what << ": the location of A itself");
        std::cout << "  " << mesh_name<Mesh>() << ", " << what << ": OK, every location bit for bit that of A" << std::endl;
      }
  }
  {
    PE::Cross_parameterization_statistics st;
    const PE::Error_code ec = PE::cross_parameterization(a, b, std::vector<std::pair<vd, vd> >(), boost::make_assoc_property_map(loc),
      PE::parameters::border_vertex_pair(std::make_pair(ia[0], bb[0]), PE::parameters::statistics(&st)));
    CHECK(ec == PE::ERROR_WRONG_PARAMETER && st.failed_mesh == 0 && loc.empty(), "border pair not on A's border");
    std::cout << "  " << mesh_name<Mesh>() << ", border pair not on A's border: " << PE::get_error_name(ec) << std::endl;
  }
  {
    // no time at all: B's first map cannot be made, nothing is written (the statuses of the steps skipped when the
    // budget runs out later, ERROR_BUDGET_EXHAUSTED, depend on the clock: not tested here)
    PE::Cross_parameterization_statistics st;
    const std::vector<std::pair<vd, vd> > one{ { ia[0], ib[0] } };
    const PE::Error_code ec = PE::cross_parameterization(a, b, one, boost::make_assoc_property_map(loc),
      PE::parameters::statistics(&st, CGAL::parameters::maximum_running_time(0.)));
    CHECK(ec == PE::ERROR_BUDGET_EXHAUSTED && loc.empty() && !st.matched_b && st.seconds_composed == 0,
          "no time: " << PE::get_error_name(ec) << ", mesh " << st.failed_mesh);
    std::cout << "  " << mesh_name<Mesh>() << ", no time: " << PE::get_error_name(ec) << ", mesh " << st.failed_mesh << std::endl;
  }
  return EXIT_SUCCESS;
}

// the location step in exact rationals: B's map of a small disk converted exactly to Gmpq; the map's own vertices,
// edge midpoints and face centroids located the same way as in double, on vertices and edges exactly
int exact_location()
{
  Surface_mesh m;
  PE::internal::make_grid_disk(8, m);
  auto uv = m.add_property_map<Surface_mesh::Vertex_index, Epick::Point_2>("v:uv").first;
  const PE::Error_code ec = PE::parameterize_certified(m, boost::graph_traits<Surface_mesh>::null_halfedge(), uv,
    PE::parameters::border_shape(PE::Border_shape::CIRCLE, PE::parameters::optimization_policy(PE::Optimization_policy::ALWAYS)));
  CHECK(ec == PE::OK, PE::get_error_message(ec));
  std::vector<Epick::Point_2> pd;
  std::vector<Kq::Point_2> pq;
  for(auto v : vertices(m)) { pd.push_back(uv[v]); pq.push_back(Kq::Point_2(CGAL::Gmpq(uv[v].x()), CGAL::Gmpq(uv[v].y()))); }
  std::vector<std::array<std::size_t, 3> > f;
  for(auto fc : faces(m))
  {
    const auto h = halfedge(fc, m);
    f.push_back({{ std::size_t(source(h, m)), std::size_t(target(h, m)), std::size_t(target(next(h, m), m)) }});
  }
  std::vector<Kq::Point_2> qq(pq);
  std::vector<std::size_t> kind(pq.size(), 2);
  for(const auto& t : f)
  {
    qq.push_back(CGAL::midpoint(pq[t[0]], pq[t[1]]));
    kind.push_back(1);
    qq.push_back(CGAL::centroid(pq[t[0]], pq[t[1]], pq[t[2]]));
    kind.push_back(0);
  }
  std::vector<PE::internal::Map_location> rq, rd;
  CHECK(PE::internal::locate_in_map(pq, f, qq, rq) == 0, "every exact query located");
  // in double: the vertices (exact) and the rounded centroids
  std::vector<Epick::Point_2> qd;
  for(const auto& q : qq) qd.push_back(Epick::Point_2(CGAL::to_double(q.x()), CGAL::to_double(q.y())));
  CHECK(PE::internal::locate_in_map(pd, f, qd, rd) == 0, "every double query located");
  std::size_t same = 0;
  for(std::size_t i = 0; i < qq.size(); ++i)
  {
    CHECK(rq[i].zeros == int(kind[i]) || (kind[i] == 1 && rq[i].zeros == 1), "exact kind of query " << i);
    if(kind[i] == 2) CHECK(std::count(rq[i].barycentric.begin(), rq[i].barycentric.end(), 1.) == 1, "vertex weight 1");
    if(kind[i] == 1) CHECK(std::count(rq[i].barycentric.begin(), rq[i].barycentric.end(), 0.5) == 2, "midpoint weights 1/2");
    if(i < pq.size()) CHECK(rd[i].face == rq[i].face && rd[i].barycentric == rq[i].barycentric, "double = Gmpq on vertices");
    if(rd[i].face == rq[i].face) ++same;
  }
  std::cout << "exact location (Gmpq): " << qq.size() << " queries (vertices, edge midpoints, centroids) located, on"
            << " vertices and edges exactly; double gives the same face for " << same << std::endl;
  return EXIT_SUCCESS;
}

// The composed distortion's building blocks on a grid map of the unit square: B's inverse Jacobians (a map that is
// its own 3D triangles up to scale gives the identity, a stretched one the inverse stretch) and the walk that
// locates a point from any face.
int composed_metric_blocks()
{
  const std::size_t n = 12;
  std::vector<Epick::Point_2> uv;
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i) uv.emplace_back(double(i) / n, double(j) / n);
  std::vector<std::array<std::size_t, 3> > faces;
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      faces.push_back({{ a, b, d }});
      faces.push_back({{ a, d, c }});
    }
  for(double stretch : { 1., 3. })
  {
    std::vector<Epick::Point_3> points;
    for(const auto& p : uv) points.emplace_back(2 * p.x(), 2 * stretch * p.y(), 0.);
    const PE::internal::Inverse_map_metric m = PE::internal::inverse_map_metric(uv, points, faces);
    // the 3D triangles scaled to the map's area: lengths (2x, 2 stretch y) / (2 sqrt(stretch)); M undoes the map
    double worst = 0;
    for(const Eigen::Matrix2d& M : m.inverse_jacobian)
    {
      Eigen::JacobiSVD<Eigen::Matrix2d> svd(M);
      const double r = std::sqrt(stretch);
      worst = (std::max)(worst, std::abs(svd.singularValues()(0) - r) + std::abs(svd.singularValues()(1) - 1 / r));
    }
    CHECK(worst < 1e-12, "inverse Jacobians of the stretch " << stretch << ": singular values off by " << worst);
    std::size_t neighbours = 0;
    for(const auto& nb : m.neighbour)
      for(std::size_t g : nb) if(g != PE::internal::Inverse_map_metric::none) ++neighbours;
    CHECK(neighbours == 2 * (3 * n * n - 2 * n), "every inside edge has its two faces: " << neighbours);
    // the walk from random faces ends in a face holding the point
    CGAL::Random random(7);
    for(int q = 0; q < 2000; ++q)
    {
      const double x = random.get_double(0, 1), y = random.get_double(0, 1);
      const std::size_t g = m.locate(x, y, std::size_t(random.get_int(0, int(faces.size()))));
      bool inside = true;
      for(int k = 0; k < 3; ++k)
      {
        const auto& p = m.uv[faces[g][k]];
        const auto& r = m.uv[faces[g][(k + 1) % 3]];
        if((r[0] - p[0]) * (y - p[1]) - (r[1] - p[1]) * (x - p[0]) < 0) inside = false;
      }
      CHECK(inside, "the walk to (" << x << ", " << y << ") ends in face " << g << ", which does not hold it");
    }
  }
  std::cout << "composed distortion: B's inverse Jacobians of a grid map (stretch 1 and 3) exact to 1e-12, "
            << "2000 walks each ending in a face that holds their point" << std::endl;
  return EXIT_SUCCESS;
}

// mushroom against its remeshed copy, without and with the composed distortion: both certified, the optimization
// for the composed map ran and certified, its energy that of a near-isometry, and the error not larger
int composed_distortion_on_pair(const std::string& file, std::size_t count)
{
  Surface_mesh a, b;
  CHECK(CGAL::IO::read_polygon_mesh(file, a) && CGAL::IO::read_polygon_mesh(file, b), "read " << file);
  PE::internal::remesh_isotropically(b);
  b.collect_garbage();
  const auto landmarks = PE::internal::nearest_vertex_landmarks(a, b, PE::internal::spread_interior_vertices(a, count));
  double mean[2] = { 0, 0 }, max[2] = { 0, 0 };
  PE::Cross_parameterization_statistics st[2];
  for(int with = 0; with < 2; ++with)
  {
    Location_map<Surface_mesh> loc;
    const PE::Error_code ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(loc),
      PE::parameters::composed_distortion(with == 1, PE::parameters::statistics(&st[with])));
    CHECK(ec == PE::OK && st[with].report_a.is_valid() && st[with].report_b.is_valid() && st[with].landmarks_exact,
          "certified (" << PE::get_error_name(ec) << ")");
    std::tie(mean[with], max[with]) = PE::internal::correspondence_error(a, b, boost::make_assoc_property_map(loc));
  }
  CHECK(st[0].composed.iterations == 0 && st[0].seconds_composed == 0, "composed_distortion(false): not run");
  const PE::Optimization_statistics& c = st[1].composed;
  CHECK((st[1].composed_status == PE::OK || st[1].composed_status == PE::ERROR_BUDGET_EXHAUSTED)
        && c.iterations > 0 && c.report.is_valid(), "the composed optimization ran, certified: "
        << PE::get_error_name(st[1].composed_status) << ", " << c.iterations << " iterations");
  CHECK(c.energy_current >= 4 && c.energy_current < 4.5, "the composed map's mean energy " << c.energy_current);
  // on this pair the planar maps already agree (0.3-0.4% of the diagonal): the step must not make it worse by more
  // than 5% (measured: 1% worse with 5 landmarks, 5% better with 20); what it
  // gains where they slide apart is measured by cross_benchmark on the lucy pairs
  CHECK(mean[1] <= 1.05 * mean[0], "mean error with the composed distortion " << mean[1] << ", without " << mean[0]);
  std::cout << file << " -> remeshed, " << count << " landmarks: mean error " << mean[0] << " -> " << mean[1]
            << " of the diagonal with the composed distortion (max " << max[0] << " -> " << max[1] << "), "
            << c.iterations << " iterations, composed energy " << c.energy_current << ", "
            << st[1].seconds_composed << " s" << std::endl;
  return EXIT_SUCCESS;
}

// A: the mesh of `file`; B: its isotropically remeshed copy, as a MeshB
template <class MeshB>
int read_remeshed_pair(const std::string& file, Surface_mesh& a, MeshB& b)
{
  Surface_mesh remeshed;
  CHECK(CGAL::IO::read_polygon_mesh(file, a) && CGAL::IO::read_polygon_mesh(file, remeshed), "read " << file);
  PE::internal::remesh_isotropically(remeshed);
  remeshed.collect_garbage();
  CGAL::copy_face_graph(remeshed, b);
  return EXIT_SUCCESS;
}

// mushroom (Surface_mesh) against its remeshed copy as a MeshB, with and without B's matched map: both certified,
// every landmark exact, every location a convex combination; with it (the default) B's map is the one made by
// constrained_embedding() with B's landmarks pinned, optimized; the error is not larger (the two maps already agree
// on this pair: what it gains where they drift apart is measured by cross_benchmark on the lucy pairs)
template <class MeshB>
int matched_maps_on_pair(const std::string& file, std::size_t count)
{
  Surface_mesh a;
  MeshB b;
  RUN(read_remeshed_pair(file, a, b));
  const auto landmarks = PE::internal::nearest_vertex_landmarks(a, b, PE::internal::spread_interior_vertices(a, count));
  double mean[2] = { 0, 0 }, max[2] = { 0, 0 };
  PE::Cross_parameterization_statistics st[2];
  for(int with = 0; with < 2; ++with)
  {
    std::unordered_map<Surface_mesh::Vertex_index, PE::Cross_location<MeshB> > loc;
    const PE::Error_code ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(loc),
      PE::parameters::matched_maps(with == 1, PE::parameters::statistics(&st[with])));
    CHECK(ec == PE::OK && st[with].report_a.is_valid() && st[with].report_b.is_valid() && st[with].landmarks_exact,
          "certified (" << PE::get_error_name(ec) << ")");
    CHECK(loc.size() == num_vertices(a), "every vertex of A located");
    for(const auto& p : landmarks) CHECK(weight_of(b, loc.at(p.first), p.second) == 1., "landmark exact");
    for(const auto& l : loc)
    {
      const auto& w = l.second.second;
      CHECK(w[0] >= 0 && w[1] >= 0 && w[2] >= 0 && std::abs(w[0] + w[1] + w[2] - 1) <= 1e-12, "a convex combination");
    }
    std::tie(mean[with], max[with]) = PE::internal::correspondence_error(a, b, boost::make_assoc_property_map(loc));
  }
  CHECK(!st[0].matched_b && st[0].map_b_matched.optimization.iterations == 0 && st[0].vertices_added_b == 0,
        "matched_maps(false): B's first map kept");
  CHECK(st[1].matched_b && st[1].matched_status == PE::OK && !st[1].matched_more_distorted && st[1].map_b_matched.optimized
        && st[1].map_b_matched.optimization.iterations > 0, "B's matched map made and optimized");
  // the rule that keeps B's first map when the matched map is more distorted (it went around the landmarks another
  // way): at most 5% above the first map's mean energy; reports without 3D energies are not compared
  {
    PE::Embedding_report first, matched;
    first.has_3d_energy = matched.has_3d_energy = true;
    first.mean_energy_3d = 16.6673;
    matched.mean_energy_3d = 16.6654;
    CHECK(PE::internal::matched_map_acceptable(first, matched), "a matched map as distorted as the first kept");
    matched.mean_energy_3d = 1.05 * first.mean_energy_3d;
    CHECK(PE::internal::matched_map_acceptable(first, matched), "5% above: kept");
    matched.mean_energy_3d = 50.61;
    CHECK(!PE::internal::matched_map_acceptable(first, matched), "three times the first map's energy: the first kept");
    // unless A's map, made the same way, is as distorted (it went around the landmarks the same way)
    PE::Embedding_report a;
    a.has_3d_energy = true;
    a.mean_energy_3d = 16.53;
    CHECK(!PE::internal::matched_map_acceptable(first, matched, &a), "A's map far less distorted: the first kept");
    a.mean_energy_3d = 49.0;
    CHECK(PE::internal::matched_map_acceptable(first, matched, &a), "A's map as distorted: the matched map kept");
    a.has_3d_energy = false;
    CHECK(!PE::internal::matched_map_acceptable(first, matched, &a), "A's map without 3D energy: the first kept");
    matched.has_3d_energy = false;
    CHECK(PE::internal::matched_map_acceptable(first, matched), "no 3D energy: not compared");
  }
  CHECK(mean[1] <= 1.05 * mean[0], "mean error with B's matched map " << mean[1] << ", without " << mean[0]);
  // CGAL::Parallel_tag: B's matched map and A's map made side by side, the same result bit for bit
  {
    std::unordered_map<Surface_mesh::Vertex_index, PE::Cross_location<MeshB> > seq, par;
    PE::Cross_parameterization_statistics sp;
    CHECK(PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(seq)) == PE::OK, "sequential");
    CHECK(PE::cross_parameterization<CGAL::Parallel_tag>(a, b, landmarks, boost::make_assoc_property_map(par),
            PE::parameters::statistics(&sp)) == PE::OK && sp.matched_b, "parallel");
    for(const auto& l : seq) CHECK(par.at(l.first) == l.second, "the same location with CGAL::Parallel_tag");
  }
  std::cout << file << " -> remeshed (" << mesh_name<MeshB>() << "), " << count << " landmarks: mean error "
            << mean[0] << " -> " << mean[1] << " of the diagonal with B's matched map (max " << max[0] << " -> "
            << max[1] << "), " << st[1].map_b_matched.optimization.iterations << " iterations, "
            << st[1].vertices_added_b << " vertices added to B's copy, seconds for B " << st[0].seconds_map_b
            << " -> " << st[1].seconds_map_b << std::endl;
  return EXIT_SUCCESS;
}

// B's matched map on a refined copy of B: patch-21.off (libcgal-demo, 145 vertices) against its remeshed copy with
// 100 landmarks keeps a Steiner vertex in B's copy after the coarsening. Every vertex of A is located in the refined
// map and written in B's faces (a convex combination, every landmark exactly on its partner), the compatible meshes
// are certified, B's vertices are located on A, and the result is the same with CGAL::Parallel_tag.
template <class MeshB>
int matched_map_on_refined_copy(const std::string& file)
{
  Surface_mesh a;
  MeshB b;
  RUN(read_remeshed_pair(file, a, b));
  const auto landmarks = PE::internal::nearest_vertex_landmarks(a, b, PE::internal::spread_interior_vertices(a, 100));
  std::unordered_map<Surface_mesh::Vertex_index, PE::Cross_location<MeshB> > loc, par;
  std::unordered_map<typename boost::graph_traits<MeshB>::vertex_descriptor, PE::Cross_location<Surface_mesh>,
                     boost::hash<typename boost::graph_traits<MeshB>::vertex_descriptor> > back;
  PE::Cross_parameterization_statistics st;
  Surface_mesh ca, cb;
  const PE::Error_code ec = PE::cross_parameterization(a, b, landmarks, boost::make_assoc_property_map(loc),
    PE::parameters::compatible_meshes(std::make_pair(&ca, &cb),
      PE::parameters::b_to_a_locations(boost::make_assoc_property_map(back), PE::parameters::statistics(&st))));
  CHECK(ec == PE::OK && st.report_a.is_valid() && st.report_b.is_valid() && st.landmarks_exact,
        "certified (" << PE::get_error_name(ec) << ")");
  CHECK(st.matched_b && st.vertices_added_b > 0 && st.report_b.faces > num_faces(b),
        "B's map on its refined copy: " << st.vertices_added_b << " vertices added");
  CHECK(loc.size() == num_vertices(a) && st.unlocated == 0, "every vertex of A located");
  std::size_t zeros[3] = { 0, 0, 0 }; // locations inside a face, on an edge, on a vertex, counted here
  for(const auto& l : loc)
  {
    const auto& w = l.second.second;
    CHECK(w[0] >= 0 && w[1] >= 0 && w[2] >= 0 && std::abs(w[0] + w[1] + w[2] - 1) <= 1e-12, "a convex combination");
    ++zeros[int(w[0] == 0) + int(w[1] == 0) + int(w[2] == 0)];
  }
  CHECK(zeros[0] == st.located_in_face && zeros[1] == st.located_on_edge && zeros[2] == st.located_on_vertex,
        "the statistics count the written locations: " << zeros[0] << " " << zeros[1] << " " << zeros[2]);
  CHECK(st.located_on_vertex >= landmarks.size(), "every landmark on a vertex of B");
  for(const auto& p : landmarks)
  {
    CHECK(weight_of(b, loc.at(p.first), p.second) == 1., "landmark of A exact on B");
    CHECK(weight_of(a, back.at(p.second), p.first) == 1., "landmark of B exact on A");
  }
  CHECK(st.located_b_on_a == num_vertices(b) && back.size() == num_vertices(b), "every vertex of B located on A");
  CHECK(st.report_compatible.is_valid() && num_vertices(ca) == num_vertices(cb) && num_faces(ca) == num_faces(cb),
        "compatible meshes certified");
  CHECK(PE::cross_parameterization<CGAL::Parallel_tag>(a, b, landmarks, boost::make_assoc_property_map(par)) == PE::OK,
        "parallel");
  for(const auto& l : loc) CHECK(par.at(l.first) == l.second, "the same location with CGAL::Parallel_tag");
  std::cout << file << " -> remeshed (" << mesh_name<MeshB>() << "), 100 landmarks: B's map on its copy refined by "
            << st.vertices_added_b << " vertices (" << st.report_b.faces << " faces against " << num_faces(b)
            << "), A's vertices " << st.located_in_face << " in faces, " << st.located_on_edge << " on edges, "
            << st.located_on_vertex << " on vertices, compatible meshes " << st.compatible_vertices << " vertices" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

PE_TEST_GROUP(cross_matched)
{
  RUN(matched_maps_on_pair<Surface_mesh>(data_dir + "/meshes/mushroom.off", 20));
  RUN(matched_maps_on_pair<Polyhedron>(data_dir + "/meshes/mushroom.off", 20));
  RUN(matched_map_on_refined_copy<Surface_mesh>(data_dir + "/meshes/patch-21.off"));
  RUN(matched_map_on_refined_copy<Polyhedron>(data_dir + "/meshes/patch-21.off"));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(cross_composed)
{
  RUN(composed_metric_blocks());
  RUN(composed_distortion_on_pair(data_dir + "/meshes/mushroom.off", 5));
  RUN(composed_distortion_on_pair(data_dir + "/meshes/mushroom.off", 20));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(cross_identical)
{
  RUN(identical_grid<Surface_mesh>());
  RUN(identical_grid<Polyhedron>());
  RUN(identical_mesh<Surface_mesh>(data_dir + "/meshes/mushroom.off"));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(cross_border_landmarks)
{
  RUN(border_landmarks<Surface_mesh>());
  RUN(border_landmarks<Polyhedron>());
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(cross_shifted)
{
  RUN(shifted_landmarks<Surface_mesh>(data_dir + "/meshes/mushroom.off"));
  RUN(shifted_landmarks<Polyhedron>(data_dir + "/meshes/mushroom.off"));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(cross_remeshed)
{
  RUN(remeshed<Surface_mesh>(data_dir, "mushroom.off", 0.02));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(cross_polyhedron)
{
  RUN(remeshed<Polyhedron>(data_dir, "mushroom.off", 0.02));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(cross_errors)
{
  RUN(errors<Surface_mesh>(data_dir));
  RUN(errors<Polyhedron>(data_dir));
  return EXIT_SUCCESS;
}

// The corpus of the fuzz target (test/fuzz/cross_parameterization.h) replayed: DATA_DIR is the corpus folder
// (test/fuzz/CMakeLists.txt registers it as ctest's fuzz_cross_parameterization); a finding aborts with its message.
PE_TEST_GROUP(fuzz_cross_parameterization)
{
  std::vector<std::string> files;
  std::error_code error;
  for(const auto& e : std::filesystem::directory_iterator(data_dir, error))
    if(e.is_regular_file() && e.path().filename().string()[0] != '.') files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  CHECK(!error && !files.empty(), "no input in " << data_dir);
  for(const std::string& f : files)
  {
    std::ifstream in(f, std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(in.good() || in.eof(), "read " << f);
    pe_fuzz::cross_parameterization(bytes.data(), bytes.size());
  }
  std::cout << "cross_parameterization: " << files.size() << " inputs replayed, no finding" << std::endl;
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(cross_compatible)
{
  RUN(fan_disks<Surface_mesh>());
  RUN(fan_disks<Polyhedron>());
  RUN(eared_disks<Surface_mesh>());
  RUN(eared_disks<Polyhedron>());
  RUN(compatible_cases<Surface_mesh>(data_dir));
  RUN(compatible_cases<Polyhedron>(data_dir));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(cross_closed)
{
  RUN(closed_surfaces<Surface_mesh>(data_dir));
  RUN(closed_surfaces<Polyhedron>(data_dir));
  RUN(cut_between_nearest_landmarks<Surface_mesh>());
  RUN(cut_between_nearest_landmarks<Polyhedron>());
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(cross_exact_location)
{
  RUN(exact_location());
  return EXIT_SUCCESS;
}

// Meshes with exact rational and MPFR points: mushroom.off to itself with five interior landmarks. The maps are
// computed in double from the points rounded once, so the result is bit for bit the one of the same meshes with
// double points; every vertex lands on its own vertex.
template <class K>
int exact_input(const std::string& data_dir, const std::vector<PE::Cross_location<Surface_mesh> >& reference)
{
  typedef CGAL::Surface_mesh<typename K::Point_3> Mesh;
  typedef typename Mesh::Vertex_index Vertex;
  Mesh a;
  CHECK(CGAL::IO::read_polygon_mesh(data_dir + "/meshes/mushroom.off", a), "read mushroom.off");
  const Mesh b = a;
  std::vector<std::pair<Vertex, Vertex> > landmarks;
  for(Vertex v : vertices(a))
    if(!a.is_border(v) && std::size_t(v) % 97 == 3 && landmarks.size() < 5) landmarks.emplace_back(v, v);
  auto loc = a.template add_property_map<Vertex, PE::Cross_location<Mesh> >("v:cross").first;
  PE::Cross_parameterization_statistics st;
  const PE::Error_code ec = PE::cross_parameterization(a, b, landmarks, loc, PE::parameters::statistics(&st));
  CHECK(ec == PE::OK, nt_name<K>() << ": " << PE::get_error_message(ec));
  CHECK(st.report_a.is_valid() && st.report_b.is_valid() && st.landmarks_exact, nt_name<K>() << ": certified");
  CHECK(st.located_on_vertex == a.number_of_vertices(), nt_name<K>() << ": every vertex on a vertex");
  CHECK(reference.size() == a.number_of_vertices(), "reference size");
  for(Vertex v : vertices(a))
  {
    const auto& l = loc[v];
    const auto& r = reference[std::size_t(v)];
    CHECK(std::size_t(l.first) == std::size_t(r.first) && l.second == r.second, nt_name<K>() << ": vertex " << std::size_t(v)
          << " located as with double points");
    const auto h = halfedge(l.first, b);
    const std::array<Vertex, 3> corners{{ source(h, b), target(h, b), target(next(h, b), b) }};
    bool own = false;
    for(int i = 0; i < 3; ++i) own = own || (corners[i] == v && l.second[i] == 1.);
    CHECK(own, nt_name<K>() << ": vertex " << std::size_t(v) << " on itself");
  }
  std::cout << "  " << nt_name<K>() << " points: " << landmarks.size() << " landmarks, " << st.located_on_vertex
            << " vertices each on itself, bit for bit as with double points" << std::endl;
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(cross_exact_input)
{
  Surface_mesh a;
  CHECK(CGAL::IO::read_polygon_mesh(data_dir + "/meshes/mushroom.off", a), "read mushroom.off");
  const Surface_mesh b = a;
  typedef Surface_mesh::Vertex_index Vertex;
  std::vector<std::pair<Vertex, Vertex> > landmarks;
  for(Vertex v : vertices(a))
    if(!a.is_border(v) && std::size_t(v) % 97 == 3 && landmarks.size() < 5) landmarks.emplace_back(v, v);
  std::vector<PE::Cross_location<Surface_mesh> > reference(a.number_of_vertices());
  const PE::Error_code ec = PE::cross_parameterization(a, b, landmarks,
    boost::make_iterator_property_map(reference.begin(), get(CGAL::vertex_index, a)));
  CHECK(ec == PE::OK, PE::get_error_message(ec));
  RUN(exact_input<Kq>(data_dir, reference));
  RUN(exact_input<Kfr>(data_dir, reference));
  return EXIT_SUCCESS;
}
