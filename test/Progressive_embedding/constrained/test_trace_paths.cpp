// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Path tracing (phase 2 of constrained maps): partitions of a disk's Tutte map (Delaunay
// triangulations of chosen node positions, hand-made fans) traced on the mesh; every
// postcondition asserted (paths, rotations, one disk patch per polygon, Steiner points on their
// edges' midpoints, original vertices untouched), Steiner counts reported, error codes.

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/internal/constrained/trace_paths.h>
#include <CGAL/Progressive_embedding/internal/constrained/trace_overlay.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include "registry.h"
#include "mesh_fixtures.h"
#include "../test_util.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <unordered_map>

namespace {

namespace PI = CGAL::Progressive_embedding::internal;

typedef Epick::Point_2 P2;

// A partition of the disk: nodes (mesh vertices), interior edges, rotations (from 2D angles).
template <class Mesh>
struct Partition
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::vector<vertex_descriptor> nodes;
  std::vector<P2> position;
  std::vector<std::array<std::size_t, 2> > edges;
  std::vector<std::vector<std::size_t> > rotation;
  std::size_t border_nodes = 0, holes = 0;
  std::vector<std::size_t> next_border; // per node: the next node along its border cycle (interior on the left), or -1
};

// the border vertices in counterclockwise order (interior on the left)
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> border_ccw(const Mesh& m)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> b;
  typename boost::graph_traits<Mesh>::halfedge_descriptor h0 = boost::graph_traits<Mesh>::null_halfedge();
  for(auto h : halfedges(m)) if(CGAL::is_border(h, m)) { h0 = h; break; }
  auto h = h0;
  do { b.push_back(target(h, m)); h = prev(h, m); } while(h != h0);
  return b;
}

// rotations from the node positions: counterclockwise; border nodes from the next border node's direction
template <class Mesh>
void compute_rotations(Partition<Mesh>& P, const std::vector<std::size_t>& next_border)
{
  P.next_border = next_border;
  // canonical edge order: the triangulations' edge iteration order depends on memory addresses
  for(auto& e : P.edges) if(e[0] > e[1]) std::swap(e[0], e[1]);
  std::sort(P.edges.begin(), P.edges.end());
  const std::size_t N = P.nodes.size();
  P.rotation.assign(N, std::vector<std::size_t>());
  for(std::size_t e = 0; e < P.edges.size(); ++e) { P.rotation[P.edges[e][0]].push_back(e); P.rotation[P.edges[e][1]].push_back(e); }
  for(std::size_t i = 0; i < N; ++i)
  {
    double ref = 0;
    if(next_border[i] != std::size_t(-1))
      ref = std::atan2(P.position[next_border[i]].y() - P.position[i].y(), P.position[next_border[i]].x() - P.position[i].x());
    auto angle = [&](std::size_t e)
    {
      const std::size_t j = P.edges[e][0] == i ? P.edges[e][1] : P.edges[e][0];
      double a = std::atan2(P.position[j].y() - P.position[i].y(), P.position[j].x() - P.position[i].x()) - ref;
      while(a < 0) a += 2 * CGAL_PI;
      while(a >= 2 * CGAL_PI) a -= 2 * CGAL_PI;
      return a;
    };
    std::sort(P.rotation[i].begin(), P.rotation[i].end(), [&](std::size_t x, std::size_t y) { return angle(x) < angle(y); });
  }
}

// Delaunay partition of `nb` evenly spaced border vertices and the given interior vertices, at their
// uv positions (interior positions mirrored x -> -x when `mirror`); edges in `drop` (node pairs) removed
template <class Mesh, class UVM>
Partition<Mesh> delaunay_partition(const Mesh& m, const UVM& uv, std::size_t nb,
                                   const std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& interior,
                                   bool mirror, const std::set<std::pair<std::size_t, std::size_t> >& drop = {})
{
  Partition<Mesh> P;
  const auto border = border_ccw(m);
  for(std::size_t k = 0; k < nb; ++k) P.nodes.push_back(border[k * border.size() / nb]);
  P.border_nodes = nb;
  for(auto v : interior) P.nodes.push_back(v);
  for(std::size_t i = 0; i < P.nodes.size(); ++i)
  {
    const P2 p = get(uv, P.nodes[i]);
    P.position.push_back((mirror && i >= nb) ? P2(-p.x(), p.y()) : p);
  }
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, Epick> Vb;
  typedef CGAL::Triangulation_data_structure_2<Vb> Tds;
  typedef CGAL::Delaunay_triangulation_2<Epick, Tds> DT;
  DT dt;
  for(std::size_t i = 0; i < P.nodes.size(); ++i) dt.insert(P.position[i])->info() = i;
  for(auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
  {
    if(dt.is_infinite(e->first) || dt.is_infinite(e->first->neighbor(e->second))) continue; // hull: border side
    std::size_t a = e->first->vertex(DT::cw(e->second))->info(), b = e->first->vertex(DT::ccw(e->second))->info();
    if(drop.count(std::make_pair((std::min)(a, b), (std::max)(a, b)))) continue;
    P.edges.push_back({ { a, b } });
  }
  std::vector<std::size_t> next_border(P.nodes.size(), std::size_t(-1));
  for(std::size_t k = 0; k < nb; ++k) next_border[k] = (k + 1) % nb;
  compute_rotations(P, next_border);
  return P;
}

// `n` distinct random interior vertices with |uv| < r
template <class Mesh, class UVM>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>
random_interior(const Mesh& m, const UVM& uv, std::size_t n, unsigned seed, double r = 0.7)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> cand, out;
  for(auto v : vertices(m))
  {
    const P2 p = get(uv, v);
    if(!CGAL::is_border(v, m) && p.x() * p.x() + p.y() * p.y() < r * r) cand.push_back(v);
  }
  std::mt19937 gen(seed);
  std::shuffle(cand.begin(), cand.end(), gen);
  for(std::size_t k = 0; k < n && k < cand.size(); ++k) out.push_back(cand[k]);
  return out;
}

template <class Mesh>
auto circle_tutte(const Mesh& m)
{
  auto uv = make_uv_map(const_cast<Mesh&>(m), P2());
  const PE::Error_code ec = PE::tutte_embedding(m, boost::graph_traits<Mesh>::null_halfedge(), uv,
                                                PE::parameters::border_shape(PE::Border_shape::CIRCLE));
  if(ec != PE::OK) std::cerr << "tutte_embedding: " << PE::get_error_name(ec) << std::endl;
  // rounded to multiples of 2^-24: the solver's last bits may depend on memory alignment, and the
  // partitions built from these positions should not
  for(auto v : vertices(m))
  {
    const P2 p = get(uv, v);
    put(uv, v, P2(std::ldexp(std::round(std::ldexp(p.x(), 24)), -24), std::ldexp(std::round(std::ldexp(p.y(), 24)), -24)));
  }
  return uv;
}

struct Counts
{
  std::size_t steiner = 0, patches = 0, chords_all = 0, chords_same_side = 0, path_edges = 0;
  double path_length = 0;
};

// Independent checks of the postconditions, then the package's own check, the patches, the
// Steiner vertices (bit-exact midpoints of their edges) and the untouched original vertices.
template <class Mesh>
int verify(const Mesh& m, const Partition<Mesh>& P,
           const std::vector<std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> >& paths,
           const std::vector<PI::Steiner_vertex<Mesh> >& steiner, std::size_t vertices_before,
           const std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type>& original,
           Counts& c)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  auto vpm = get(CGAL::vertex_point, m);
  CHECK(paths.size() == P.edges.size(), "one path per edge");
  std::set<vd> node_set(P.nodes.begin(), P.nodes.end()), used;
  c.path_edges = 0; c.path_length = 0;
  for(std::size_t e = 0; e < paths.size(); ++e)
  {
    const auto& p = paths[e];
    CHECK(p.size() >= 2 && p.front() == P.nodes[P.edges[e][0]] && p.back() == P.nodes[P.edges[e][1]], "path " << e << " ends");
    for(std::size_t k = 0; k + 1 < p.size(); ++k)
    {
      const auto h = halfedge(p[k], p[k + 1], m);
      CHECK(h.second, "path " << e << " edge " << k << " is a mesh edge");
      CHECK(!CGAL::is_border(edge(h.first, m), m), "path " << e << " runs along the border");
      ++c.path_edges;
      c.path_length += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, p[k]), get(vpm, p[k + 1]))));
    }
    for(std::size_t k = 1; k + 1 < p.size(); ++k)
    {
      CHECK(!CGAL::is_border(p[k], m), "inner path vertex on the border");
      CHECK(!node_set.count(p[k]), "inner path vertex is a node");
      CHECK(used.insert(p[k]).second, "inner path vertex shared (path " << e << ")");
    }
  }
  std::size_t np = 0;
  CHECK(PI::check_traced_paths(m, P.nodes, P.edges, P.rotation, paths, &np) == PE::OK, "postconditions");
  auto fpm = get(CGAL::dynamic_face_property_t<std::size_t>(), const_cast<Mesh&>(m));
  std::vector<PI::Traced_patch<Mesh> > patches;
  CHECK(PI::label_patches(m, P.nodes, paths, fpm, patches) == PE::OK, "patches");
  std::size_t faces_total = 0;
  for(const auto& pa : patches)
  {
    CHECK(pa.is_disk, "patch is a disk");
    CHECK(P.nodes.empty() || pa.corners.size() >= 2, "patch has corners");
    faces_total += pa.number_of_faces;
  }
  CHECK(faces_total == count_faces(m), "every face in one patch");
  // every patch is a polygon of the partition: its corner cycle is a face of the rotation system
  // (border nodes 0..border_nodes-1 in border order; next dart after a -> b: predecessor of b -> a at b)
  if(!P.nodes.empty())
  {
    const std::size_t N = P.nodes.size(), nb = P.border_nodes;
    std::vector<std::vector<std::size_t> > full(N);
    std::vector<std::size_t> prev_border(N, std::size_t(-1));
    for(std::size_t i = 0; i < N; ++i) if(P.next_border[i] != std::size_t(-1)) prev_border[P.next_border[i]] = i;
    for(std::size_t i = 0; i < N; ++i)
    {
      if(P.next_border[i] != std::size_t(-1)) full[i].push_back(P.next_border[i]);
      for(std::size_t e : P.rotation[i]) full[i].push_back(P.edges[e][0] == i ? P.edges[e][1] : P.edges[e][0]);
      if(P.next_border[i] != std::size_t(-1)) full[i].push_back(prev_border[i]);
    }
    std::set<std::pair<std::size_t, std::size_t> > darts;
    for(const auto& pa : patches)
    {
      const std::size_t k = pa.corners.size();
      for(std::size_t j = 0; j < k; ++j)
      {
        const std::size_t a = pa.corners[j], b = pa.corners[(j + 1) % k], c = pa.corners[(j + 2) % k];
        CHECK(darts.insert(std::make_pair(a, b)).second, "directed side used twice");
        const auto& r = full[b];
        const std::size_t ia = static_cast<std::size_t>(std::find(r.begin(), r.end(), a) - r.begin());
        CHECK(ia < r.size() && r[(ia + r.size() - 1) % r.size()] == c, "patch corners follow the partition's faces");
      }
    }
    CHECK(darts.size() == 2 * P.edges.size() + nb, "every directed edge and border side bounds one patch");
  }
  const std::size_t expected = 1 + P.edges.size() + P.border_nodes - P.nodes.size() - P.holes;
  CHECK(patches.size() == expected && np == expected, "one patch per polygon: " << patches.size() << " vs " << expected);
  c.patches = patches.size();
  // Steiner vertices
  std::size_t nv = 0;
  for(auto v : vertices(m)) { (void)v; ++nv; }
  CHECK(nv == vertices_before + steiner.size(), "vertices added = Steiner vertices");
  for(const auto& s : steiner)
    CHECK(get(vpm, s.v) == CGAL::midpoint(get(vpm, s.a), get(vpm, s.b)) && s.t == 0.5, "Steiner vertex at its edge's midpoint");
  for(const auto& o : original) CHECK(get(vpm, o.first) == o.second, "original vertex moved");
  c.steiner = steiner.size();
  c.chords_all = PI::collect_chords(m, paths).size();
  c.chords_same_side = PI::collect_chords(m, paths, PI::Same_side_chord<Mesh>(m, P.nodes, paths)).size();
  return EXIT_SUCCESS;
}

template <class Mesh>
std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type>
snapshot(const Mesh& m)
{
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type> s;
  for(auto v : vertices(m)) s.emplace(v, get(CGAL::vertex_point, m, v));
  return s;
}

using pe_test::count_vertices;

// traces P on m, verifies everything, then splits the same-side chords and re-verifies
template <class Mesh, class NP = CGAL::parameters::Default_named_parameters>
int trace_and_verify(Mesh& m, const Partition<Mesh>& P, Counts& c, const char* what,
                     const NP& np = CGAL::parameters::default_values())
{
  const auto before = snapshot(m);
  const std::size_t nv0 = count_vertices(m);
  std::vector<std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> > paths;
  std::vector<PI::Steiner_vertex<Mesh> > steiner;
  CGAL::Real_timer t; t.start();
  const PE::Error_code ec = PI::trace_paths(m, get(CGAL::vertex_point, m), P.nodes, P.edges, P.rotation, paths, steiner, np);
  t.stop();
  CHECK(ec == PE::OK, what << ": trace_paths returned " << PE::get_error_name(ec));
  RUN(verify(m, P, paths, steiner, nv0, before, c));
  // splitting the same-side chords keeps every postcondition and removes them
  const std::size_t s = PI::split_chords(m, get(CGAL::vertex_point, m), paths, steiner, PI::Same_side_chord<Mesh>(m, P.nodes, paths));
  CHECK(s == c.chords_same_side, "split_chords splits what collect_chords lists");
  Counts c2;
  RUN(verify(m, P, paths, steiner, nv0, before, c2));
  CHECK(c2.chords_same_side == 0, "no same-side chord left");
  CHECK(c2.patches == c.patches, "same patches");
  std::cout << "  " << what << ": " << mesh_name<Mesh>() << " " << nv0 << " vertices, " << P.nodes.size() << " nodes ("
            << P.border_nodes << " border), " << P.edges.size() << " paths, " << c.patches << " patches; Steiner: "
            << c.steiner << " tracing + " << c.chords_same_side << " same-side chords = " << c.steiner + c.chords_same_side
            << " (splitting every chord: " << c.chords_all << "); path edges " << c.path_edges << ", length " << c.path_length
            << "; " << t.time() << " s" << std::endl;
  return EXIT_SUCCESS;
}

// 3, 10, 50 interior nodes on disks of several sizes: the default (3D length, proximity penalty), guided
// by the partition's drawing, and plain hop-count shortest paths (no proximity penalty), whose chords the authors' protocol splits all
template <class Mesh>
int sizes_case(const std::string& file, const std::vector<std::size_t>& counts, unsigned seeds, std::size_t& total_ours, std::size_t& total_plain)
{
  Mesh m0;
  if(!read_mesh(file, m0)) return EXIT_FAILURE;
  auto uv = circle_tutte(m0);
  for(std::size_t n : counts)
    for(unsigned seed = 0; seed < seeds; ++seed)
    {
      // Surface_mesh copies keep the vertex indices: one partition for every run
      const auto P = delaunay_partition(m0, uv, 8, random_interior(m0, uv, n, seed), false);
      const std::string what = file.substr(file.find_last_of('/') + 1) + " n=" + std::to_string(n) + " seed " + std::to_string(seed);
      Counts c, ch, cp;
      { Mesh m = m0; RUN(trace_and_verify(m, P, c, (what + " default").c_str())); }
      { Mesh m = m0; RUN(trace_and_verify(m, P, ch, (what + " hops").c_str(), PE::parameters::path_metric(PE::Path_metric::HOP_COUNT))); }
      { Mesh m = m0; RUN(trace_and_verify(m, P, cp, (what + " plain hops").c_str(),
                                          PE::parameters::proximity_penalty(0., PE::parameters::path_metric(PE::Path_metric::HOP_COUNT)))); }
      // guided by the partition's drawing (the second tracing of constrained_embedding()): also traced, every postcondition verified
      { Mesh m = m0; Counts cg; RUN(trace_and_verify(m, P, cg, (what + " guided").c_str(),
                                                     PE::internal::guide_weight(1., CGAL::parameters::default_values()))); }
      total_ours += c.steiner + c.chords_same_side;
      total_plain += cp.chords_all;
      CHECK(2 * (c.steiner + c.chords_same_side) <= cp.chords_all, "at most half the Steiner vertices of splitting every chord");
    }
  return EXIT_SUCCESS;
}

} // namespace

PE_TEST_GROUP(trace_paths_sizes)
{
  std::size_t ours = 0, plain = 0;
  RUN(sizes_case<Surface_mesh>(data_dir + "/meshes/mushroom.off", { 3, 10, 50 }, 2, ours, plain));
  RUN(sizes_case<Surface_mesh>(data_dir + "/meshes/lion-head.off", { 3, 10, 50 }, 2, ours, plain));
  RUN(sizes_case<Surface_mesh>(data_dir + "/meshes/mannequin-devil.off", { 3, 10, 50 }, 2, ours, plain));
  std::cout << "total Steiner vertices: " << ours << " (default: tracing + same-side chords); splitting every chord of plain hop-count paths: "
            << plain << std::endl;
  CHECK(2 * ours <= plain, "at most half the Steiner vertices of splitting every chord, in all");
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(trace_paths_polyhedron)
{
  Polyhedron m;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
  auto uv = circle_tutte(m);
  for(std::size_t n : { 3, 10, 50 })
  {
    Polyhedron mm = m; // handles differ in a copy: partition built on the copy
    auto uvm = circle_tutte(mm);
    const auto P = delaunay_partition(mm, uvm, 8, random_interior(mm, uvm, n, 7), false);
    Counts c;
    RUN(trace_and_verify(mm, P, c, ("Polyhedron_3 n=" + std::to_string(n)).c_str()));
    Polyhedron mg = mm; // a copy for the guided tracing: its own handles, so its own partition
    auto uvg = circle_tutte(mg);
    const auto Pg = delaunay_partition(mg, uvg, 8, random_interior(mg, uvg, n, 7), false);
    Counts cg;
    RUN(trace_and_verify(mg, Pg, cg, ("Polyhedron_3 guided n=" + std::to_string(n)).c_str(),
                         PE::internal::guide_weight(1., CGAL::parameters::default_values())));
  }
  (void)uv;
  return EXIT_SUCCESS;
}

// two mesh-adjacent nodes, partition-adjacent (one-edge path) or not (the edge stays a chord
// between two corners of one patch, split by split_chords)
namespace {

// appends to `interior` a mesh neighbour of its first vertex (interior, not in it yet) and returns it
Surface_mesh::Vertex_index add_interior_neighbour(const Surface_mesh& m, std::vector<Surface_mesh::Vertex_index>& interior)
{
  Surface_mesh::Vertex_index y;
  for(auto w : CGAL::vertices_around_target(halfedge(interior[0], m), m))
    if(!CGAL::is_border(w, m) && std::find(interior.begin(), interior.end(), w) == interior.end()) { y = w; break; }
  interior.push_back(y);
  return y;
}

// the index of the partition edge joining nodes a and b, or -1
template <class Mesh>
std::size_t partition_edge(const Partition<Mesh>& P, std::size_t a, std::size_t b)
{
  for(std::size_t e = 0; e < P.edges.size(); ++e)
    if(std::set<std::size_t>{ P.edges[e][0], P.edges[e][1] } == std::set<std::size_t>{ a, b }) return e;
  return std::size_t(-1);
}

} // namespace

PE_TEST_GROUP(trace_paths_adjacent_nodes)
{
  Surface_mesh m0;
  if(!read_mesh(data_dir + "/meshes/lion-head.off", m0)) return EXIT_FAILURE;
  auto uv = circle_tutte(m0);
  auto interior = random_interior(m0, uv, 8, 3);
  const auto x = interior[0], y = add_interior_neighbour(m0, interior);
  const std::size_t ix = 8, iy = 8 + interior.size() - 1;
  {
    Surface_mesh m = m0;
    const auto P = delaunay_partition(m, uv, 8, interior, false);
    const std::size_t exy = partition_edge(P, ix, iy);
    CHECK(exy != std::size_t(-1), "the Delaunay partition joins the two close nodes");
    std::vector<std::vector<Surface_mesh::Vertex_index> > paths;
    std::vector<PI::Steiner_vertex<Surface_mesh> > steiner;
    CHECK(PI::trace_paths(m, get(CGAL::vertex_point, m), P.nodes, P.edges, P.rotation, paths, steiner) == PE::OK, "adjacent, joined");
    CHECK(paths[exy].size() == 2, "the mesh edge is the path");
    Counts c;
    RUN(verify(m, P, paths, steiner, count_vertices(m0), snapshot(m0), c));
    std::cout << "  adjacent nodes joined: one-edge path, " << c.steiner << " Steiner vertices" << std::endl;
  }
  {
    Surface_mesh m = m0;
    const auto P = delaunay_partition(m, uv, 8, interior, false, { { ix, iy } });
    Counts c;
    RUN(trace_and_verify(m, P, c, "adjacent nodes, not joined"));
    // the mesh edge between them is a chord (not a path edge): splitting every chord removes it
    std::vector<std::vector<Surface_mesh::Vertex_index> > paths;
    std::vector<PI::Steiner_vertex<Surface_mesh> > steiner;
    Surface_mesh m2 = m0;
    CHECK(PI::trace_paths(m2, get(CGAL::vertex_point, m2), P.nodes, P.edges, P.rotation, paths, steiner) == PE::OK, "retrace");
    CHECK(halfedge(x, y, m2).second, "the edge between the nodes is kept by tracing");
    const auto chords = PI::collect_chords(m2, paths);
    CHECK(std::count_if(chords.begin(), chords.end(), [&](const auto& ch) { return (ch.first == x && ch.second == y) || (ch.first == y && ch.second == x); }) == 1,
          "the edge between the nodes is a chord");
    const std::size_t s = PI::split_chords(m2, get(CGAL::vertex_point, m2), paths, steiner);
    CHECK(s == chords.size() && !halfedge(x, y, m2).second, "split_chords split it");
    Counts c2;
    RUN(verify(m2, P, paths, steiner, count_vertices(m0), snapshot(m0), c2));
    CHECK(c2.chords_all == 0, "no chord left");
    std::cout << "  every chord split: " << s << " more Steiner vertices" << std::endl;
  }
  return EXIT_SUCCESS;
}

// a node of mesh valence 3 (the center of a split face) with more partition edges than neighbours:
// splits are forced around it; and a hand-made fan whose center has partition degree 3
PE_TEST_GROUP(trace_paths_degree_three)
{
  Surface_mesh m0;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", m0)) return EXIT_FAILURE;
  auto uv0 = circle_tutte(m0);
  // the face closest to the uv center gets a center vertex
  Surface_mesh::Face_index fc;
  double best = 1e300;
  for(auto f : faces(m0))
  {
    double sx = 0, sy = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m0), m0)) { sx += get(uv0, v).x(); sy += get(uv0, v).y(); }
    if(sx * sx + sy * sy < best) { best = sx * sx + sy * sy; fc = f; }
  }
  std::vector<Epick::Point_3> tri;
  for(auto v : CGAL::vertices_around_face(halfedge(fc, m0), m0)) tri.push_back(m0.point(v));
  const auto hc = CGAL::Euler::add_center_vertex(halfedge(fc, m0), m0);
  const auto c3 = target(hc, m0);
  m0.point(c3) = CGAL::centroid(tri[0], tri[1], tri[2]);
  CHECK(CGAL::halfedges_around_target(c3, m0).size() == 3, "valence 3");
  auto uv = circle_tutte(m0);
  {
    Surface_mesh m = m0;
    auto interior = random_interior(m, uv, 12, 11);
    interior.erase(std::remove(interior.begin(), interior.end(), c3), interior.end());
    interior.push_back(c3);
    const auto P = delaunay_partition(m, uv, 8, interior, false);
    const std::size_t deg = P.rotation.back().size();
    CHECK(deg > 3, "partition degree above the valence: " << deg);
    Counts c;
    RUN(trace_and_verify(m, P, c, "valence-3 node"));
    CHECK(c.steiner >= deg - 3, "splits forced around the valence-3 node");
    std::cout << "  valence-3 node of partition degree " << deg << ": " << c.steiner << " Steiner vertices" << std::endl;
    // no split allowed: the budget is exhausted
    Surface_mesh mb = m0;
    std::vector<std::vector<Surface_mesh::Vertex_index> > paths;
    std::vector<PI::Steiner_vertex<Surface_mesh> > steiner;
    CHECK(PI::trace_paths(mb, get(CGAL::vertex_point, mb), P.nodes, P.edges, P.rotation, paths, steiner,
                          PE::parameters::maximum_steiner_vertices(std::size_t(0))) == PE::ERROR_BUDGET_EXHAUSTED,
          "split budget 0");
    CHECK(steiner.empty() && count_vertices(mb) == count_vertices(m0), "no split beyond the budget");
  }
  {
    // fan: 3 border nodes, one interior node of partition degree 3
    Surface_mesh m = m0;
    Partition<Surface_mesh> P;
    const auto border = border_ccw(m);
    for(std::size_t k = 0; k < 3; ++k) P.nodes.push_back(border[k * border.size() / 3]);
    P.border_nodes = 3;
    P.nodes.push_back(c3);
    for(auto v : P.nodes) P.position.push_back(get(uv, v));
    P.edges = { { { 3, 0 } }, { { 3, 1 } }, { { 3, 2 } } };
    compute_rotations(P, { 1, 2, 0, std::size_t(-1) });
    Counts c;
    RUN(trace_and_verify(m, P, c, "fan, degree-3 center"));
    CHECK(c.patches == 3, "three patches");
  }
  return EXIT_SUCCESS;
}

// interior node positions mirrored relative to the surface: the partition is still a partition of
// the disk, so tracing succeeds (paths wind around, more splits)
PE_TEST_GROUP(trace_paths_mirrored)
{
  Surface_mesh m0;
  if(!read_mesh(data_dir + "/meshes/lion-head.off", m0)) return EXIT_FAILURE;
  auto uv = circle_tutte(m0);
  for(std::size_t n : { 3, 10, 50 })
  {
    const auto interior = random_interior(m0, uv, n, 5);
    Counts straight, mirrored;
    { Surface_mesh m = m0; RUN(trace_and_verify(m, delaunay_partition(m, uv, 8, interior, false), straight, ("n=" + std::to_string(n)).c_str())); }
    { Surface_mesh m = m0; RUN(trace_and_verify(m, delaunay_partition(m, uv, 8, interior, true), mirrored, ("mirrored n=" + std::to_string(n)).c_str())); }
    CHECK(mirrored.steiner > straight.steiner, "winding paths need more splits");
  }
  {
    // with a split budget the mirrored case stops with ERROR_BUDGET_EXHAUSTED: the mesh is refined
    // (a valid triangle mesh, every added vertex listed) and no more than the budget was added
    Surface_mesh m = m0;
    const auto P = delaunay_partition(m, uv, 8, random_interior(m0, uv, 50, 5), true);
    std::vector<std::vector<Surface_mesh::Vertex_index> > paths;
    std::vector<PI::Steiner_vertex<Surface_mesh> > steiner;
    const PE::Error_code ec = PI::trace_paths(m, get(CGAL::vertex_point, m), P.nodes, P.edges, P.rotation, paths, steiner,
                                              PE::parameters::maximum_steiner_vertices(std::size_t(2000)));
    CHECK(ec == PE::ERROR_BUDGET_EXHAUSTED, "budget 2000: " << PE::get_error_name(ec));
    CHECK(steiner.size() <= 2000 && count_vertices(m) == count_vertices(m0) + steiner.size(), "budget respected");
    CHECK(CGAL::is_valid_polygon_mesh(m) && CGAL::is_triangle_mesh(m), "refined mesh valid");
    for(const auto& s : steiner) CHECK(m.point(s.v) == CGAL::midpoint(m.point(s.a), m.point(s.b)), "Steiner midpoint");
    std::cout << "  mirrored n=50, budget 2000: " << PE::get_error_name(ec) << " after " << steiner.size() << " splits" << std::endl;
  }
  return EXIT_SUCCESS;
}

// the border cycle through the border vertex v, interior on the left
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>
border_loop_from(const Mesh& m, typename boost::graph_traits<Mesh>::vertex_descriptor v)
{
  typename boost::graph_traits<Mesh>::halfedge_descriptor h0 = boost::graph_traits<Mesh>::null_halfedge();
  for(auto h : CGAL::halfedges_around_target(v, m)) if(CGAL::is_border(h, m)) h0 = h;
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> b;
  auto h = h0;
  do { b.push_back(target(h, m)); h = prev(h, m); } while(h != h0);
  return b;
}

// a disk with two holes (the one-rings of two interior vertices removed): border nodes on the
// three border cycles, a constrained Delaunay partition of the annular domain at the Tutte
// positions of the disk; and the errors of a hole without node and of a closed mesh
PE_TEST_GROUP(trace_paths_holes)
{
  typedef CGAL::Constrained_Delaunay_triangulation_2<Epick, CGAL::Default, CGAL::Exact_predicates_tag> CDT;
  Surface_mesh m0;
  if(!read_mesh(data_dir + "/meshes/lion-head.off", m0)) return EXIT_FAILURE;
  auto uv = circle_tutte(m0);
  const auto outer0 = border_ccw(m0);
  for(std::size_t n : { 3, 10, 50 })
  {
    Surface_mesh m = m0;
    // two centers far apart, their one-rings disjoint
    const auto cand = random_interior(m0, uv, 200, 17, 0.5);
    Surface_mesh::Vertex_index c1 = cand[0], c2;
    std::set<Surface_mesh::Vertex_index> ring1;
    for(auto w : CGAL::vertices_around_target(halfedge(c1, m0), m0)) ring1.insert(w);
    for(auto c : cand)
    {
      if(CGAL::squared_distance(get(uv, c), get(uv, c1)) < 0.09) continue;
      bool ok = true;
      for(auto w : CGAL::vertices_around_target(halfedge(c, m0), m0)) if(ring1.count(w) || w == c1) ok = false;
      if(ok) { c2 = c; break; }
    }
    CHECK(c2 != Surface_mesh::null_vertex(), "second center");
    const auto ring1_vertices = std::vector<Surface_mesh::Vertex_index>(ring1.begin(), ring1.end());
    for(auto c : { c1, c2 })
    {
      const auto h = CGAL::Euler::remove_center_vertex(halfedge(c, m), m);
      CGAL::Euler::remove_face(h, m);
    }
    CHECK(CGAL::is_valid_polygon_mesh(m), "mesh with two holes");
    // nodes: 8 outer border nodes, every vertex of the two hole cycles, n interior vertices
    Partition<Surface_mesh> P;
    const auto outer = border_loop_from(m, outer0[0]);
    for(std::size_t k = 0; k < 8; ++k) P.nodes.push_back(outer[k * outer.size() / 8]);
    std::vector<std::size_t> next(8);
    for(std::size_t k = 0; k < 8; ++k) next[k] = (k + 1) % 8;
    std::vector<std::vector<Surface_mesh::Vertex_index> > hole_loops;
    for(auto c : { c1, c2 })
    {
      Surface_mesh::Vertex_index w0;
      for(auto w : CGAL::vertices_around_target(halfedge(c, m0), m0)) w0 = w;
      hole_loops.push_back(border_loop_from(m, w0));
      const std::size_t first = P.nodes.size(), k = hole_loops.back().size();
      for(std::size_t j = 0; j < k; ++j) { P.nodes.push_back(hole_loops.back()[j]); next.push_back(first + (j + 1) % k); }
    }
    P.border_nodes = P.nodes.size();
    P.holes = 2;
    std::set<Surface_mesh::Vertex_index> taken(P.nodes.begin(), P.nodes.end());
    for(auto v : random_interior(m0, uv, 400, 23, 0.7))
    {
      if(P.nodes.size() >= P.border_nodes + n) break;
      if(taken.count(v) || v == c1 || v == c2 || CGAL::is_border(v, m)) continue;
      bool near_hole = false; // keep interior nodes off the hole polygons' Delaunay neighbourhood
      for(auto w : CGAL::vertices_around_target(halfedge(v, m), m)) if(CGAL::is_border(w, m)) near_hole = true;
      if(near_hole) continue;
      P.nodes.push_back(v); next.push_back(std::size_t(-1));
    }
    for(auto v : P.nodes) P.position.push_back(get(uv, v));
    // constrained Delaunay triangulation; the hole sides are constraints, edges inside a hole dropped
    CDT cdt;
    std::map<CDT::Vertex_handle, std::size_t> index;
    std::vector<CDT::Vertex_handle> vh;
    for(std::size_t i = 0; i < P.nodes.size(); ++i) { vh.push_back(cdt.insert(P.position[i])); index[vh.back()] = i; }
    std::vector<CGAL::Polygon_2<Epick> > hole_polygons(2);
    for(std::size_t i = 8; i < P.border_nodes; ++i)
    {
      cdt.insert_constraint(vh[i], vh[next[i]]);
      hole_polygons[P.nodes[i] == P.nodes[8] || i < 8 + hole_loops[0].size() ? 0 : 1].push_back(P.position[i]);
    }
    CHECK(cdt.number_of_vertices() == P.nodes.size(), "distinct node positions");
    for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    {
      if(cdt.is_infinite(e->first) || cdt.is_infinite(e->first->neighbor(e->second)) || cdt.is_constrained(*e)) continue;
      const std::size_t a = index[e->first->vertex(CDT::cw(e->second))], b = index[e->first->vertex(CDT::ccw(e->second))];
      const P2 mid = CGAL::midpoint(P.position[a], P.position[b]);
      bool inside = false;
      for(const auto& hp : hole_polygons) if(hp.bounded_side(mid) != CGAL::ON_UNBOUNDED_SIDE) inside = true;
      if(!inside) P.edges.push_back({ { a, b } });
    }
    compute_rotations(P, next);
    Counts c;
    RUN(trace_and_verify(m, P, c, ("two holes, n=" + std::to_string(n)).c_str()));
    if(n == 3)
    {
      // a hole without node: no partition into polygons
      Partition<Surface_mesh> Q = P;
      Surface_mesh mq = m;
      std::vector<std::vector<Surface_mesh::Vertex_index> > paths;
      std::vector<PI::Steiner_vertex<Surface_mesh> > steiner;
      Q.nodes.resize(8); Q.edges.clear(); Q.rotation.assign(8, std::vector<std::size_t>());
      CHECK(PI::trace_paths(mq, get(CGAL::vertex_point, mq), Q.nodes, Q.edges, Q.rotation, paths, steiner) == PE::ERROR_WRONG_PARAMETER,
            "hole without node");
    }
    (void)ring1_vertices;
  }
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(trace_paths_errors)
{
  Surface_mesh m0;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", m0)) return EXIT_FAILURE;
  auto uv = circle_tutte(m0);
  const auto P = delaunay_partition(m0, uv, 8, random_interior(m0, uv, 10, 2), false);
  const std::size_t nv0 = count_vertices(m0);
  typedef std::vector<std::vector<Surface_mesh::Vertex_index> > Paths;
  typedef std::vector<PI::Steiner_vertex<Surface_mesh> > Steiner;
  auto run = [&](Surface_mesh& m, const Partition<Surface_mesh>& Q, auto np)
  {
    Paths paths; Steiner steiner;
    return PI::trace_paths(m, get(CGAL::vertex_point, m), Q.nodes, Q.edges, Q.rotation, paths, steiner, np);
  };
  const auto dflt = CGAL::parameters::default_values();
  auto expect = [&](const Partition<Surface_mesh>& Q, PE::Error_code want, const char* what) -> int
  {
    Surface_mesh m = m0;
    const PE::Error_code ec = run(m, Q, dflt);
    CHECK(ec == want, what << ": " << PE::get_error_name(ec));
    CHECK(count_vertices(m) == nv0, what << ": mesh unchanged");
    std::cout << "  " << what << ": " << PE::get_error_name(ec) << std::endl;
    return EXIT_SUCCESS;
  };
  { auto Q = P; Q.nodes[9] = Surface_mesh::Vertex_index(static_cast<Surface_mesh::size_type>(nv0 + 5)); RUN(expect(Q, PE::ERROR_WRONG_PARAMETER, "node not a vertex")); }
  { auto Q = P; Q.nodes[9] = Q.nodes[10]; RUN(expect(Q, PE::ERROR_WRONG_PARAMETER, "two nodes on one vertex")); }
  { auto Q = P; Q.edges[0][1] = 1000; RUN(expect(Q, PE::ERROR_WRONG_PARAMETER, "edge index out of range")); }
  { auto Q = P; Q.edges.push_back(Q.edges[0]); Q.rotation[Q.edges[0][0]].push_back(Q.edges.size() - 1); Q.rotation[Q.edges[0][1]].push_back(Q.edges.size() - 1);
    RUN(expect(Q, PE::ERROR_WRONG_PARAMETER, "duplicate edge")); }
  { auto Q = P; Q.rotation[9].pop_back(); RUN(expect(Q, PE::ERROR_WRONG_PARAMETER, "rotation misses an edge")); }
  {
    // one interior node's rotation reversed: no partition of the disk has these rotations
    auto Q = P;
    std::size_t i = 8;
    while(Q.rotation[i].size() < 3) ++i;
    std::reverse(Q.rotation[i].begin(), Q.rotation[i].end());
    RUN(expect(Q, PE::ERROR_WRONG_PARAMETER, "reversed (non-planar) rotation"));
  }
  {
    // an interior node not connected to the border
    auto Q = P;
    Q.nodes.push_back(random_interior(m0, uv, 40, 99).back());
    Q.rotation.emplace_back();
    RUN(expect(Q, PE::ERROR_WRONG_PARAMETER, "isolated interior node"));
  }
  {
    Surface_mesh closed;
    if(!read_mesh(data_dir + "/meshes/elephant.off", closed)) return EXIT_FAILURE;
    Paths paths; Steiner steiner;
    const PE::Error_code ec = PI::trace_paths(closed, get(CGAL::vertex_point, closed), std::vector<Surface_mesh::Vertex_index>(),
                                              std::vector<std::array<std::size_t, 2> >(), std::vector<std::vector<std::size_t> >(), paths, steiner);
    CHECK(ec == PE::ERROR_NOT_A_DISK, "closed mesh: " << PE::get_error_name(ec));
  }
  {
    // genus 3 with one hole: not a disk; with two holes: not genus 0
    Surface_mesh torus;
    if(!read_mesh(data_dir + "/meshes/3torus.off", torus)) return EXIT_FAILURE;
    CGAL::Polygon_mesh_processing::triangulate_faces(torus);
    Paths paths; Steiner steiner;
    const std::vector<Surface_mesh::Vertex_index> no_nodes;
    const std::vector<std::array<std::size_t, 2> > no_edges;
    const std::vector<std::vector<std::size_t> > no_rotation;
    CGAL::Euler::remove_face(halfedge(*faces(torus).begin(), torus), torus);
    PE::Error_code ec = PI::trace_paths(torus, get(CGAL::vertex_point, torus), no_nodes, no_edges, no_rotation, paths, steiner);
    CHECK(ec == PE::ERROR_NOT_A_DISK, "genus 3, one hole: " << PE::get_error_name(ec));
    for(auto f : faces(torus))
    {
      bool touches = false;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, torus), torus))
        for(auto v : CGAL::vertices_around_target(target(h, torus), torus)) if(CGAL::is_border(v, torus)) touches = true;
      if(!touches) { CGAL::Euler::remove_face(halfedge(f, torus), torus); break; }
    }
    ec = PI::trace_paths(torus, get(CGAL::vertex_point, torus), no_nodes, no_edges, no_rotation, paths, steiner);
    CHECK(ec == PE::ERROR_NOT_GENUS_ZERO, "genus 3, two holes: " << PE::get_error_name(ec));
    std::cout << "  genus 3: ERROR_NOT_A_DISK with one hole, ERROR_NOT_GENUS_ZERO with two" << std::endl;
  }
  {
    Surface_mesh m = m0;
    const PE::Error_code ec = run(m, P, CGAL::parameters::maximum_running_time(0.));
    CHECK(ec == PE::ERROR_BUDGET_EXHAUSTED, "time budget 0: " << PE::get_error_name(ec));
    CHECK(run(m, P, CGAL::parameters::maximum_running_time(-1.)) == PE::ERROR_WRONG_PARAMETER, "negative time");
    CHECK(run(m, P, PE::parameters::split_penalty(-1.)) == PE::ERROR_WRONG_PARAMETER, "negative split penalty");
    CHECK(run(m, P, PE::parameters::proximity_penalty(std::nan(""))) == PE::ERROR_WRONG_PARAMETER, "NaN proximity penalty");
    CHECK(run(m, P, PE::internal::guide_weight(-1., CGAL::parameters::default_values())) == PE::ERROR_WRONG_PARAMETER, "negative guide weight");
    CHECK(count_vertices(m) == nv0, "mesh unchanged");
  }
  {
    // no node at all: one patch, the whole disk
    Surface_mesh m = m0;
    Partition<Surface_mesh> Q;
    Counts c;
    RUN(trace_and_verify(m, Q, c, "no node"));
    CHECK(c.patches == 1 && c.steiner == 0, "one patch, no split");
  }
  return EXIT_SUCCESS;
}

// exact 3D points: Steiner vertices exactly at the midpoints
PE_TEST_GROUP(trace_paths_exact)
{
  typedef CGAL::Surface_mesh<Kq::Point_3> Mesh_q;
  Surface_mesh m0;
  Mesh_q mq;
  if(!read_mesh(data_dir + "/meshes/nefertiti.off", m0) || !read_mesh(data_dir + "/meshes/nefertiti.off", mq)) return EXIT_FAILURE;
  auto uv = circle_tutte(m0);
  const auto P0 = delaunay_partition(m0, uv, 8, random_interior(m0, uv, 10, 1), true);
  Partition<Mesh_q> P;
  for(auto v : P0.nodes) P.nodes.push_back(Mesh_q::Vertex_index(static_cast<Mesh_q::size_type>(v))); // same file, same order
  P.position = P0.position; P.edges = P0.edges; P.rotation = P0.rotation; P.border_nodes = P0.border_nodes; P.next_border = P0.next_border;
  const auto before = snapshot(mq);
  const std::size_t nv0 = count_vertices(mq);
  std::vector<std::vector<Mesh_q::Vertex_index> > paths;
  std::vector<PI::Steiner_vertex<Mesh_q> > steiner;
  CHECK(PI::trace_paths(mq, get(CGAL::vertex_point, mq), P.nodes, P.edges, P.rotation, paths, steiner) == PE::OK, "Gmpq mesh");
  Counts c;
  RUN(verify(mq, P, paths, steiner, nv0, before, c));
  std::cout << "  Gmpq nefertiti (mirrored partition): " << c.steiner << " Steiner vertices, " << c.patches << " patches" << std::endl;
  return EXIT_SUCCESS;
}

namespace {

// traces P on m with trace_paths_overlay() (curves crossing the input edges, the mesh refined once),
// verifies every postcondition as above, and checks that every added vertex lies on an input edge
template <class Mesh>
int overlay_and_verify(Mesh& m, const Partition<Mesh>& P, Counts& c, const std::string& what)
{
  const auto before = snapshot(m);
  const std::size_t nv0 = count_vertices(m);
  std::set<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor, typename boost::graph_traits<Mesh>::vertex_descriptor> > input_edges;
  for(auto e : edges(m)) input_edges.insert(std::minmax(source(halfedge(e, m), m), target(halfedge(e, m), m)));
  std::vector<std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> > paths;
  std::vector<PI::Steiner_vertex<Mesh> > steiner;
  CGAL::Real_timer t; t.start();
  const PE::Error_code ec = PI::trace_paths_overlay(m, get(CGAL::vertex_point, m), P.nodes, P.edges, P.rotation, paths, steiner);
  t.stop();
  CHECK(ec == PE::OK, what << ": trace_paths_overlay returned " << PE::get_error_name(ec));
  CHECK(CGAL::is_valid_polygon_mesh(m) && CGAL::is_triangle_mesh(m), what << ": refined mesh valid");
  RUN(verify(m, P, paths, steiner, nv0, before, c));
  // each split is of a piece of one input edge: the input edge of each added vertex
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  std::map<vd, std::pair<vd, vd> > on;
  for(const auto& s : steiner)
  {
    CHECK(!s.join_faces, "overlay splits leave the faces to the diagonals");
    const auto ia = on.find(s.a), ib = on.find(s.b);
    std::pair<vd, vd> e;
    if(ia == on.end() && ib == on.end()) e = std::minmax(s.a, s.b);
    else if(ia != on.end() && ib != on.end()) { CHECK(ia->second == ib->second, "one input edge"); e = ia->second; }
    else
    {
      e = (ia != on.end()) ? ia->second : ib->second;
      const vd x = (ia != on.end()) ? s.b : s.a;
      CHECK(x == e.first || x == e.second, "an endpoint of the input edge");
    }
    CHECK(input_edges.count(e), "Steiner vertex on an input edge");
    on[s.v] = e;
  }
  std::cout << "  " << what << ": " << nv0 << " vertices, " << P.edges.size() << " paths, " << c.patches << " patches; Steiner "
            << c.steiner << "; path edges " << c.path_edges << "; " << t.time() << " s" << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

// Partitions whose nodes are mirrored relative to the surface, traced as curves over the input edges:
// every postcondition, the Steiner vertices on input edges, fewer than the tracing that refines as it
// goes once the paths nest (50 nodes), and the replay of the refinement on a Polyhedron_3
PE_TEST_GROUP(trace_paths_overlay)
{
  Surface_mesh m0;
  if(!read_mesh(data_dir + "/meshes/lion-head.off", m0)) return EXIT_FAILURE;
  auto uv = circle_tutte(m0);
  for(std::size_t n : { 3, 10, 50 })
  {
    const auto interior = random_interior(m0, uv, n, 5);
    Counts overlay, nested;
    { Surface_mesh m = m0; RUN(overlay_and_verify(m, delaunay_partition(m, uv, 8, interior, false), overlay, "straight n=" + std::to_string(n))); }
    { Surface_mesh m = m0; RUN(overlay_and_verify(m, delaunay_partition(m, uv, 8, interior, true), overlay, "mirrored n=" + std::to_string(n))); }
    if(n == 50)
    {
      Surface_mesh m = m0;
      RUN(trace_and_verify(m, delaunay_partition(m, uv, 8, interior, true), nested, "mirrored n=50, trace_paths"));
      CHECK(overlay.steiner < nested.steiner, "curves over the input edges: " << overlay.steiner << " vs " << nested.steiner);
    }
  }
  for(bool mirrored : { false, true })
  {
    // two nodes joined by an input edge: the curve between them runs along that edge (no crossing, where a
    // crossing curve finds no room), and the curves traced after it go around it
    auto interior = random_interior(m0, uv, 8, 3);
    const auto x = interior[0], y = add_interior_neighbour(m0, interior);
    Surface_mesh m = m0;
    const auto P = delaunay_partition(m, uv, 8, interior, mirrored);
    const std::size_t exy = partition_edge(P, 8, 8 + interior.size() - 1);
    CHECK(exy != std::size_t(-1), "the partition joins the two adjacent nodes");
    const auto before = snapshot(m);
    std::vector<std::vector<Surface_mesh::Vertex_index> > paths;
    std::vector<PI::Steiner_vertex<Surface_mesh> > steiner;
    CHECK(PI::trace_paths_overlay(m, get(CGAL::vertex_point, m), P.nodes, P.edges, P.rotation, paths, steiner) == PE::OK,
          "adjacent nodes traced (mirrored " << mirrored << ")");
    CHECK(paths[exy].size() == 2 && std::set<Surface_mesh::Vertex_index>(paths[exy].begin(), paths[exy].end()) ==
                                      (std::set<Surface_mesh::Vertex_index>{ x, y }), "the curve is the input edge");
    Counts c;
    RUN(verify(m, P, paths, steiner, count_vertices(m0), before, c));
    std::cout << "  adjacent nodes (mirrored " << mirrored << "): the curve along their edge, " << c.steiner
              << " Steiner vertices for the " << P.edges.size() << " paths" << std::endl;
  }
  {
    // the refinement replayed on a Polyhedron_3 with the same connectivity gives the same mesh
    Surface_mesh m = m0;
    const auto P = delaunay_partition(m, uv, 8, random_interior(m0, uv, 10, 5), true);
    std::vector<std::vector<Surface_mesh::Vertex_index> > paths;
    std::vector<PI::Steiner_vertex<Surface_mesh> > steiner;
    CHECK(PI::trace_paths_overlay(m, get(CGAL::vertex_point, m), P.nodes, P.edges, P.rotation, paths, steiner) == PE::OK, "traced");
    Polyhedron poly;
    std::unordered_map<Surface_mesh::Vertex_index, boost::graph_traits<Polyhedron>::vertex_descriptor> to_poly;
    CGAL::copy_face_graph(m0, poly, CGAL::parameters::vertex_to_vertex_output_iterator(std::inserter(to_poly, to_poly.end())));
    std::vector<PI::Edge_split<Surface_mesh::Vertex_index, double> > splits;
    for(const auto& s : steiner)
    {
      PI::Edge_split<Surface_mesh::Vertex_index, double> e{ s.a, s.b, s.v, s.t };
      e.join_faces = s.join_faces;
      e.diagonals = s.diagonals;
      splits.push_back(e);
    }
    auto mid = [](const Epick::Point_3& a, const Epick::Point_3& b, double) { return CGAL::midpoint(a, b); };
    CHECK(PI::replay_splits(splits, poly, get(CGAL::vertex_point, poly), to_poly, mid) == PE::OK, "replayed");
    CHECK(num_vertices(poly) == num_vertices(m) && num_faces(poly) == num_faces(m), "same size");
    std::size_t same = 0;
    for(auto f : faces(m))
    {
      std::vector<boost::graph_traits<Polyhedron>::vertex_descriptor> c;
      for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) c.push_back(to_poly.at(v));
      const auto h = halfedge(c[0], c[1], poly);
      CHECK(h.second && target(next(h.first, poly), poly) == c[2] && !CGAL::is_border(h.first, poly), "face replayed");
      ++same;
    }
    std::cout << "  replayed on Polyhedron_3: " << steiner.size() << " splits, " << same << " faces identical" << std::endl;
  }
  return EXIT_SUCCESS;
}
