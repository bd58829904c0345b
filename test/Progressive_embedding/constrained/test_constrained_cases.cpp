// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// constrained_embedding() on the layouts that force refinement or winding paths: two adjacent
// constrained vertices that no patch can hold together (their mesh edge must be split; double and exact
// rationals), targets in the mirrored cyclic order of the surface's, a constrained vertex of valence 3
// with four partition edges; meshes with holes (an annulus, a sphere with three holes) with and without
// constraints; Surface_mesh and Polyhedron_3; and the vertex order on a Surface_mesh with a removed
// vertex not collected; targets so close together that rounding flattens faces at a sharp corner.
// Every case: OK, the exact certificate on the caller's mesh, constraints bit-exact, the original
// vertices first and unchanged, the Steiner vertices counted, and a count the layout forces.

#include <CGAL/Progressive_embedding/constrained_embedding.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/internal/constrained/domain_partition.h>

#include "registry.h"
#include "../test_util.h"
#include "mesh_fixtures.h"
#include <CGAL/Progressive_embedding/internal/disk_generators.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/centroid.h>

#include <algorithm>
#include <iterator>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

using pe_test::make_annulus;
using pe_test::make_grid_with_holes;
using pe_test::cut_one_rings;
using pe_test::far_apart_vertices;
using pe_test::count_border_cycles;

template <class Mesh> using Vertex = typename boost::graph_traits<Mesh>::vertex_descriptor;

template <class Mesh>
std::size_t degree(const Mesh& m, Vertex<Mesh> v)
{
  const auto r = CGAL::halfedges_around_target(halfedge(v, m), m);
  return static_cast<std::size_t>(std::distance(r.begin(), r.end()));
}

template <class Mesh>
bool adjacent(const Mesh& m, Vertex<Mesh> a, Vertex<Mesh> b) { return halfedge(a, b, m).second; }

template <class Mesh>
std::vector<Vertex<Mesh> > vertex_list(const Mesh& m) { return std::vector<Vertex<Mesh> >(vertices(m).begin(), vertices(m).end()); }

// the border loop of a disk, in the order of its border halfedges
template <class Mesh>
std::vector<Vertex<Mesh> > border_loop(const Mesh& m)
{
  std::vector<Vertex<Mesh> > L;
  for(auto h : halfedges(m))
    if(CGAL::is_border(h, m))
    {
      for(auto g : CGAL::halfedges_around_face(h, m)) L.push_back(target(g, m));
      break;
    }
  return L;
}

// border on the unit square by tutte_embedding (interior: the Tutte map)
template <class Mesh, class UVM>
bool square_tutte(const Mesh& m, UVM& uv)
{
  return PE::tutte_embedding(m, boost::graph_traits<Mesh>::null_halfedge(), uv,
                             PE::parameters::border_shape(PE::Border_shape::SQUARE)) == PE::OK;
}

// the interior vertex whose uv is nearest to (x, y), not in `avoid`
template <class Mesh, class UVM>
Vertex<Mesh> nearest_interior(const Mesh& m, const UVM& uv, double x, double y, const std::vector<Vertex<Mesh> >& avoid)
{
  Vertex<Mesh> best = boost::graph_traits<Mesh>::null_vertex();
  double bd = std::numeric_limits<double>::infinity();
  for(auto v : vertices(m))
  {
    if(CGAL::is_border(v, m) || std::find(avoid.begin(), avoid.end(), v) != avoid.end()) continue;
    const double dx = CGAL::to_double(get(uv, v).x()) - x, dy = CGAL::to_double(get(uv, v).y()) - y;
    if(dx * dx + dy * dy < bd) { bd = dx * dx + dy * dy; best = v; }
  }
  return best;
}

// The partition of the domain that constrained_embedding() computes with a fixed border: every border
// vertex a node (flat ones on the square's sides allowed), then the targets (node nb + i).
template <class Mesh, class UVM, class Point_2>
PE::Error_code partition_of(const Mesh& m, const UVM& uv, const std::vector<std::pair<Vertex<Mesh>, Point_2> >& C,
                            PE::internal::Domain_partition& P)
{
  std::vector<Point_2> B, T;
  for(auto v : border_loop(m)) B.push_back(get(uv, v));
  for(const auto& c : C) T.push_back(c.second);
  PE::internal::Domain_partition_options opt;
  opt.allow_flat_border_vertices = true;
  return PE::internal::partition_domain(B, T, P, opt);
}

inline bool joined(const PE::internal::Domain_partition& P, std::size_t a, std::size_t b)
{
  for(const auto& e : P.edges) if((e[0] == a && e[1] == b) || (e[0] == b && e[1] == a)) return true;
  return false;
}

// Runs constrained_embedding() and checks what it promises. `cycles` 1: a disk whose border is the
// fixed one in `uv` (kept bit-exact); `cycles` >= 2: a mesh with holes, border_shape(SQUARE), the
// certificate multiply connected with that many border cycles.
template <class Mesh, class UVM, class Point_2>
int run_checked(Mesh& m, UVM& uv, const std::vector<std::pair<Vertex<Mesh>, Point_2> >& C, const std::string& what,
                std::size_t cycles, PE::Constrained_embedding_statistics& st, bool coarsen = true)
{
  typedef Vertex<Mesh> VD;
  const bool holes = cycles > 1;
  const std::vector<VD> V = vertex_list(m);
  std::vector<pe_test::Mesh_point_3<Mesh> > X;
  std::vector<std::pair<VD, Point_2> > border_uv;
  for(auto v : V)
  {
    X.push_back(get(CGAL::vertex_point, m, v));
    if(!holes && CGAL::is_border(v, m)) border_uv.emplace_back(v, get(uv, v));
  }
  std::vector<PE::Steiner_point<VD> > sp;
  const PE::Error_code ec = holes
    ? PE::constrained_embedding(m, C, uv, PE::parameters::statistics(&st, PE::parameters::steiner_points(&sp,
                                            PE::parameters::border_shape(PE::Border_shape::SQUARE).coarsen(coarsen))))
    : PE::constrained_embedding(m, C, uv, PE::parameters::statistics(&st, PE::parameters::steiner_points(&sp,
                                            PE::parameters::coarsen(coarsen))));
  std::cout << what << ", " << mesh_name<Mesh>() << ", " << nt_name<typename CGAL::Kernel_traits<Point_2>::Kernel>()
            << ", " << C.size() << " constraints: " << PE::get_error_name(ec) << ", vertices " << st.input_vertices
            << " -> " << st.output_vertices << ", Steiner " << st.steiner_vertices << " (" << st.chord_splits
            << " chord splits), paths " << st.paths << ", patches " << st.patches << " (" << st.repaired_patches
            << " repaired), " << st.seconds_total << " s" << std::endl;
  if(ec != PE::OK)
    std::cout << "  before optimization: " << st.report_before_optimization.summary() << "\n  after: " << st.report.summary() << std::endl;
  CHECK(ec == PE::OK, what << ": constrained_embedding OK");
  const PE::Embedding_report r = PE::check_embedding(m, uv, PE::parameters::multiply_connected(holes));
  CHECK(r.status == PE::OK && r.is_valid() && r.flipped == 0 && r.degenerate == 0 && r.non_finite == 0 && r.overlapping_pairs == 0,
        what << ": certified on the caller's mesh: " << r.summary());
  CHECK(r.border_simple && r.border_intersections == 0 && r.loop_crossings == 0 && r.misoriented_holes == 0 && r.holes_outside == 0,
        what << ": border simple, loops apart: " << r.summary());
  CHECK(r.border_cycles == cycles, what << ": " << cycles << " border cycle(s), got " << r.border_cycles);
  CHECK(count_border_cycles(m) == cycles, what << ": the mesh keeps its border cycles");
  for(const auto& c : C) CHECK(get(uv, c.first) == c.second, what << ": constraint bit-exact");
  // the original vertices first, same descriptors, same 3D points; then the Steiner vertices
  const std::vector<VD> W = vertex_list(m);
  CHECK(W.size() == V.size() + st.steiner_vertices, what << ": vertices added = Steiner count (" << W.size() << " vs "
        << V.size() << " + " << st.steiner_vertices << ")");
  CHECK(st.input_vertices == V.size() && st.output_vertices == W.size(), what << ": vertex counts reported");
  CHECK(sp.size() == st.steiner_vertices, what << ": one surface position per Steiner vertex");
  std::set<VD> added(W.begin(), W.end());
  for(std::size_t i = 0; i < V.size(); ++i)
  {
    CHECK(added.erase(V[i]) == 1 && get(CGAL::vertex_point, m, V[i]) == X[i], what << ": original vertex " << i << " kept, same 3D point");
  }
  for(const auto& s : sp)
  {
    CHECK(added.count(s.vertex) == 1, what << ": Steiner points are the added vertices");
    double w = 0;
    for(std::size_t k = 0; k < s.size; ++k) { CHECK(s.weights[k] > 0, what << ": positive weight"); w += s.weights[k]; }
    CHECK(s.size >= 1 && s.size <= 3 && w == 1, what << ": a convex combination of 1 to 3 input vertices");
  }
  for(std::size_t i = 0; i < V.size(); ++i)
    CHECK(W[i] == V[i], what << ": original vertex " << i << " at rank " << i << " (input vertices first), found "
          << (added.count(W[i]) ? "an added vertex" : "another input vertex"));
  for(const auto& b : border_uv) CHECK(get(uv, b.first) == b.second, what << ": fixed border bit-exact");
  // the partition: a disk tiled by the patches (patches = paths - targets + 1), every target a corner
  // of at least 3 patches (at least 3n/2 paths)
  const std::size_t n = C.size();
  CHECK(st.patches + n == st.paths + 1, what << ": Euler's relation of the partition");
  CHECK(2 * st.paths >= 3 * n, what << ": at least 3 paths at each target");
  return EXIT_SUCCESS;
}

// ---- 1. two adjacent constrained vertices the partition does not join -----------------------------

// the polygons of the partition with both nodes as corners
inline std::size_t common_polygons(const PE::internal::Domain_partition& P, std::size_t a, std::size_t b)
{
  std::size_t k = 0;
  for(const auto& poly : P.polygons)
    if(std::find(poly.begin(), poly.end(), a) != poly.end() && std::find(poly.begin(), poly.end(), b) != poly.end()) ++k;
  return k;
}

enum class Layout
{
  BETWEEN,       // c's target the midpoint of a's and b's, c elsewhere on the surface
  BETWEEN_FACE,  // the same, c the third corner of a face on the edge a-b (that face would be flat)
  ACROSS         // c and d on either side of the segment: the triangulation's edge c-d crosses a-b
};

// a and b (joined by a mesh edge) get targets (0.25, 0.5) and (0.75, 0.5).
// BETWEEN, BETWEEN_FACE: c gets the midpoint (0.5, 0.5). A convex polygon with corners a and b contains
// the segment ab, hence c, which can only be a corner of it (a node), impossible on the open segment
// of a strictly convex polygon: no patch has both a and b on its border, whatever the partition, so
// the mesh edge a-b (on no path either: a path ends at its nodes) must be split.
// ACROSS: c and d get (0.5, 0.45) and (0.5, 0.55): the partition has no edge a-b, but the merge may
// drop c-d (the quadrilateral a c b d is convex), and then the edge a-b may stay as a diagonal of
// that patch: no split is forced, the map must be valid either way.
template <class K, class Mesh>
int adjacent_case(Mesh& m, Vertex<Mesh> a, Vertex<Mesh> b, Vertex<Mesh> c, Vertex<Mesh> d, Layout layout, const std::string& what)
{
  typedef typename K::Point_2 Point_2;
  CHECK(adjacent(m, a, b), what << ": a and b adjacent");
  CHECK(!CGAL::is_border(a, m) && !CGAL::is_border(b, m) && !CGAL::is_border(c, m) && !CGAL::is_border(d, m), "interior vertices");
  if(layout == Layout::BETWEEN_FACE)
  {
    const auto h = halfedge(a, b, m).first;
    CHECK(target(next(h, m), m) == c || target(next(opposite(h, m), m), m) == c, what << ": a, b, c a face");
  }
  auto uv = make_uv_map(m, Point_2());
  CHECK(square_tutte(m, uv), "border placed");
  std::vector<std::pair<Vertex<Mesh>, Point_2> > C = { { a, point<K>(0.25, 0.5) }, { b, point<K>(0.75, 0.5) } };
  if(layout != Layout::ACROSS) C.emplace_back(c, point<K>(0.5, 0.5));
  else { C.emplace_back(c, point<K>(0.5, 0.45)); C.emplace_back(d, point<K>(0.5, 0.55)); }
  PE::internal::Domain_partition P;
  CHECK(partition_of(m, uv, C, P) == PE::OK, "partition");
  const std::size_t nb = P.number_of_border_nodes, shared = common_polygons(P, nb, nb + 1);
  CHECK(!joined(P, nb, nb + 1), what << ": the partition has no edge a-b");
  if(layout != Layout::ACROSS) CHECK(shared == 0, what << ": no polygon has both a and b as corners");
  PE::Constrained_embedding_statistics st;
  RUN(run_checked(m, uv, C, what, 1, st));
  const bool kept = adjacent(m, a, b);
  std::cout << "  partition: " << P.edges.size() << " edges, " << P.polygons.size() << " polygons, " << shared
            << " with a and b as corners; edge a-b " << (kept ? "kept" : "split") << std::endl;
  if(layout != Layout::ACROSS)
  {
    CHECK(st.steiner_vertices >= 1, what << ": the edge a-b forces a Steiner vertex");
    CHECK(!kept, what << ": a and b no longer adjacent");
  }
  return EXIT_SUCCESS;
}

inline std::string layout_name(Layout l)
{
  return l == Layout::BETWEEN ? "c between a and b" : l == Layout::BETWEEN_FACE ? "c between a and b, face abc" : "c-d across a-b";
}

// on a grid disk: a = (3, 4), b = (4, 4); c = (4, 2) or, for the face, (4, 5); d = (3, 6)
template <class K, class Mesh>
int adjacent_on_grid(int N, Layout layout)
{
  Mesh m;
  make_grid_with_holes(m, N, N, {});
  const auto V = vertex_list(m);
  auto at = [&](int x, int y) { return V[std::size_t(y * (N + 1) + x)]; };
  return adjacent_case<K>(m, at(3, 4), at(4, 4), layout == Layout::BETWEEN_FACE ? at(4, 5) : at(4, 2), at(3, 6), layout,
                          "grid " + std::to_string(N) + "x" + std::to_string(N) + ", " + layout_name(layout));
}

// on a real disk: a near (0.4, 0.5) in the Tutte map, b an interior neighbour; c and d away from both,
// or c the third corner of a face on a-b
template <class Mesh>
int adjacent_on_mesh(const std::string& file, Layout layout)
{
  Mesh m;
  if(!read_mesh(file, m)) return EXIT_FAILURE;
  auto uv0 = make_uv_map(m, Epick::Point_2());
  CHECK(square_tutte(m, uv0), "Tutte map");
  const auto a = nearest_interior(m, uv0, 0.4, 0.5, {});
  Vertex<Mesh> b = boost::graph_traits<Mesh>::null_vertex();
  for(auto w : CGAL::vertices_around_target(halfedge(a, m), m)) if(!CGAL::is_border(w, m)) { b = w; break; }
  CHECK(b != boost::graph_traits<Mesh>::null_vertex(), "interior neighbour");
  std::vector<Vertex<Mesh> > avoid = { a, b };
  for(auto w : CGAL::vertices_around_target(halfedge(a, m), m)) avoid.push_back(w);
  for(auto w : CGAL::vertices_around_target(halfedge(b, m), m)) avoid.push_back(w);
  Vertex<Mesh> c = nearest_interior(m, uv0, 0.5, 0.3, avoid);
  if(layout == Layout::BETWEEN_FACE)
  {
    const auto h = halfedge(a, b, m).first;
    c = target(next(h, m), m);
    if(CGAL::is_border(c, m)) c = target(next(opposite(h, m), m), m);
  }
  avoid.push_back(c);
  const auto d = nearest_interior(m, uv0, 0.5, 0.7, avoid);
  const std::string name = file.substr(file.find_last_of('/') + 1);
  return adjacent_case<Epick>(m, a, b, c, d, layout, name + ", " + layout_name(layout));
}

} // namespace

PE_TEST_GROUP(constrained_cases_adjacent)
{
  for(Layout l : { Layout::BETWEEN, Layout::BETWEEN_FACE, Layout::ACROSS })
  {
    RUN((adjacent_on_grid<Epick, Surface_mesh>(10, l)));
    RUN(adjacent_on_mesh<Surface_mesh>(data_dir + "/meshes/mushroom.off", l));
  }
  RUN((adjacent_on_grid<Epick, Polyhedron>(10, Layout::BETWEEN)));
  RUN(adjacent_on_mesh<Polyhedron>(data_dir + "/meshes/mushroom.off", Layout::BETWEEN_FACE));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(constrained_cases_adjacent_gmpq)
{
  (void)data_dir;
  for(Layout l : { Layout::BETWEEN, Layout::BETWEEN_FACE, Layout::ACROSS })
    RUN((adjacent_on_grid<Kq, Surface_mesh>(7, l)));
  return EXIT_SUCCESS;
}

namespace {

// ---- 2. targets in the mirrored order ------------------------------------------------------------

// n seeded random interior vertices; targets: their Tutte positions (border on the unit square)
// mirrored, x -> 1 - x, so that every triple of targets turns the other way round than on the surface
// (checked exactly). The same vertices with their own (unmirrored) positions as targets for comparison:
// every partition is realizable by paths on the disk, so no split is forced in general, but the paths of
// the mirrored targets wind around each other: never fewer Steiner vertices, and (measured) far more
// from 6 targets on (e.g. 67 against 1 on mushroom with 6, 465 against 3 on a 20x20 grid with 10).
template <class Mesh>
int mirrored_case(const Mesh& m0, std::size_t n, unsigned seed, const std::string& name)
{
  typedef Epick::Point_2 P2;
  typedef Vertex<Mesh> VD;
  // vertices are chosen by their rank in vertices(): the descriptors of a Polyhedron_3 copy differ
  Mesh m = m0;
  auto uv0 = make_uv_map(m, P2());
  CHECK(square_tutte(m, uv0), "Tutte map");
  const std::vector<VD> V0 = vertex_list(m);
  std::vector<std::size_t> interior;
  for(std::size_t i = 0; i < V0.size(); ++i)
  {
    const P2 p = get(uv0, V0[i]);
    if(!CGAL::is_border(V0[i], m) && p.x() > 0.1 && p.x() < 0.9 && p.y() > 0.1 && p.y() < 0.9) interior.push_back(i);
  }
  std::mt19937 rng(seed);
  std::shuffle(interior.begin(), interior.end(), rng);
  CHECK(interior.size() >= n, "enough vertices");
  std::vector<P2> mirrored, straight;
  for(std::size_t i = 0; i < n; ++i)
  {
    const P2 p = get(uv0, V0[interior[i]]);
    mirrored.push_back(P2(1 - p.x(), p.y()));
    straight.push_back(p);
  }
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
      for(std::size_t k = j + 1; k < n; ++k)
      {
        const CGAL::Orientation s = CGAL::orientation(straight[i], straight[j], straight[k]);
        const CGAL::Orientation t = CGAL::orientation(mirrored[i], mirrored[j], mirrored[k]);
        CHECK(s != CGAL::COLLINEAR && t == -s, name << ": targets in the reverse cyclic order");
      }
  PE::Constrained_embedding_statistics sm, ss;
  for(int pass = 0; pass < 2; ++pass)
  {
    Mesh m1 = m0;
    const std::vector<VD> V1 = vertex_list(m1);
    auto uv = make_uv_map(m1, P2());
    CHECK(square_tutte(m1, uv), "border placed");
    std::vector<std::pair<VD, P2> > C;
    for(std::size_t i = 0; i < n; ++i) C.emplace_back(V1[interior[i]], pass == 0 ? straight[i] : mirrored[i]);
    RUN(run_checked(m1, uv, C, name + (pass == 0 ? " at their Tutte positions" : " mirrored"), 1, pass == 0 ? ss : sm));
  }
  CHECK(sm.steiner_vertices >= ss.steiner_vertices, name << ": no fewer Steiner vertices than with the targets in the surface's order");
  if(n >= 6) CHECK(sm.steiner_vertices > ss.steiner_vertices, name << ": the paths wind: more Steiner vertices");
  return EXIT_SUCCESS;
}

} // namespace

PE_TEST_GROUP(constrained_cases_mirrored)
{
  {
    Surface_mesh m;
    if(!read_mesh(data_dir + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
    RUN(mirrored_case(m, 3, 3u, "mushroom"));
    RUN(mirrored_case(m, 6, 6u, "mushroom"));
    RUN(mirrored_case(m, 10, 10u, "mushroom"));
  }
  {
    Surface_mesh m;
    make_grid_with_holes(m, 20, 20, {});
    RUN(mirrored_case(m, 3, 3u, "grid 20x20"));
    RUN(mirrored_case(m, 10, 10u, "grid 20x20"));
  }
  {
    Polyhedron m;
    make_grid_with_holes(m, 12, 12, {});
    RUN(mirrored_case(m, 5, 5u, "grid 12x12"));
  }
  return EXIT_SUCCESS;
}

namespace {

// ---- 3. a constrained vertex of valence 3 ----------------------------------------------------------

// The face nearest to (0.5, 0.5) in the Tutte map gets a center vertex v (valence 3, at the face's 3D
// centroid). v's target: its Tutte position p; four more constraints at p +- (0.1, 0) and p +- (0, 0.1)
// (the vertices nearest to those points). Every other node being farther than 0.15 from p, the
// Delaunay neighbours of p are those four points, and dropping one of their edges would leave a 180
// degree angle at p: the partition gives v exactly 4 edges, one more than its valence. The paths
// leave v by distinct edges: at least one is split.
template <class Mesh>
int degree_three_case(Mesh& m, const std::string& what)
{
  typedef Epick::Point_2 P2;
  typedef Vertex<Mesh> VD;
  auto uv0 = make_uv_map(m, P2());
  CHECK(square_tutte(m, uv0), "Tutte map");
  typename boost::graph_traits<Mesh>::face_descriptor fc = boost::graph_traits<Mesh>::null_face();
  double best = std::numeric_limits<double>::infinity();
  for(auto f : faces(m))
  {
    double sx = 0, sy = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) { sx += get(uv0, v).x() / 3; sy += get(uv0, v).y() / 3; }
    const double d = (sx - 0.5) * (sx - 0.5) + (sy - 0.5) * (sy - 0.5);
    if(d < best) { best = d; fc = f; }
  }
  std::vector<pe_test::Mesh_point_3<Mesh> > tri;
  for(auto v : CGAL::vertices_around_face(halfedge(fc, m), m)) tri.push_back(get(CGAL::vertex_point, m, v));
  const VD v3 = target(CGAL::Euler::add_center_vertex(halfedge(fc, m), m), m);
  put(get(CGAL::vertex_point, m), v3, CGAL::centroid(tri[0], tri[1], tri[2]));
  CHECK(degree(m, v3) == 3, "valence 3");
  auto uv = make_uv_map(m, P2());
  CHECK(square_tutte(m, uv), "Tutte map with the center vertex");
  const P2 p = get(uv, v3);
  const double d = 0.1;
  std::vector<std::pair<VD, P2> > C = { { v3, p } };
  const P2 arms[4] = { P2(p.x() + d, p.y()), P2(p.x(), p.y() + d), P2(p.x() - d, p.y()), P2(p.x(), p.y() - d) };
  std::vector<VD> used = { v3 };
  for(const P2& q : arms)
  {
    const VD w = nearest_interior(m, uv, q.x(), q.y(), used);
    used.push_back(w);
    C.emplace_back(w, q);
  }
  for(auto w : border_loop(m)) CHECK(CGAL::squared_distance(get(uv, w), p) > 0.15 * 0.15, "border nodes far from p");
  PE::internal::Domain_partition P;
  CHECK(partition_of(m, uv, C, P) == PE::OK, "partition");
  const std::size_t deg = P.rotation[P.number_of_border_nodes].size();
  CHECK(deg == 4, what << ": partition degree 4 at the valence-3 vertex, got " << deg);
  PE::Constrained_embedding_statistics st;
  // the refinement as traced: the coarsening would take back splits that the optimized map no longer needs
  RUN(run_checked(m, uv, C, what, 1, st, false));
  const std::size_t out = degree(m, v3);
  std::cout << "  valence 3 -> " << out << " in the output, partition degree " << deg << std::endl;
  CHECK(st.steiner_vertices >= deg - 3, what << ": splits forced at the valence-3 vertex");
  CHECK(out >= deg && out > 3, what << ": at least one edge per path at the vertex");
  return EXIT_SUCCESS;
}

} // namespace

PE_TEST_GROUP(constrained_cases_degree_three)
{
  {
    Surface_mesh m;
    make_grid_with_holes(m, 12, 12, {});
    RUN(degree_three_case(m, "grid 12x12, valence-3 vertex"));
  }
  {
    Polyhedron m;
    make_grid_with_holes(m, 12, 12, {});
    RUN(degree_three_case(m, "grid 12x12, valence-3 vertex"));
  }
  {
    Surface_mesh m;
    if(!read_mesh(data_dir + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
    RUN(degree_three_case(m, "mushroom, valence-3 vertex"));
  }
  return EXIT_SUCCESS;
}

namespace {

// ---- 4. meshes with holes ----------------------------------------------------------------------

// n seeded random interior vertices (on no border cycle) with random targets in [0.25, 0.75]^2
template <class Mesh>
std::vector<std::pair<Vertex<Mesh>, Epick::Point_2> > random_inside(const Mesh& m, std::size_t n, unsigned seed)
{
  std::vector<Vertex<Mesh> > interior;
  for(auto v : vertices(m)) if(!CGAL::is_border(v, m)) interior.push_back(v);
  std::mt19937 rng(seed);
  std::shuffle(interior.begin(), interior.end(), rng);
  std::uniform_real_distribution<double> U(0.25, 0.75);
  std::vector<std::pair<Vertex<Mesh>, Epick::Point_2> > C;
  for(std::size_t i = 0; i < n && i < interior.size(); ++i) C.emplace_back(interior[i], Epick::Point_2(U(rng), U(rng)));
  return C;
}

template <class Mesh>
int holes_case(const Mesh& m0, std::size_t n, unsigned seed, std::size_t cycles, const std::string& what)
{
  Mesh m = m0;
  CHECK(count_border_cycles(m) == cycles, what << ": " << cycles << " border cycles");
  const auto C = random_inside(m, n, seed);
  CHECK(C.size() == n, "enough interior vertices");
  auto uv = make_uv_map(m, Epick::Point_2());
  for(auto v : vertices(m)) put(uv, v, Epick::Point_2(0, 0));
  PE::Constrained_embedding_statistics st;
  RUN(run_checked(m, uv, C, what, cycles, st));
  if(n == 0)
    CHECK(st.paths == 0 && st.patches == 1 && st.steiner_vertices == 0, what << ": no constraint: one patch, no path, no split");
  else
    CHECK(st.patches >= 3, what << ": each target a corner of at least 3 patches");
  // the outer loop is on the unit square's boundary
  const auto outer = PE::internal::longest_border_loop(m, get(CGAL::vertex_point, m));
  for(auto h : CGAL::halfedges_around_face(outer, m))
  {
    const Epick::Point_2 q = get(uv, target(h, m));
    CHECK((q.x() == 0 || q.x() == 1 || q.y() == 0 || q.y() == 1) && q.x() >= 0 && q.x() <= 1 && q.y() >= 0 && q.y() <= 1,
          what << ": outer loop on the unit square");
  }
  return EXIT_SUCCESS;
}

template <class Mesh>
int annulus_cases()
{
  Mesh m;
  make_annulus(m, 6, 24, 0.8);
  RUN(holes_case(m, 0, 1u, 2, "annulus"));
  RUN(holes_case(m, 3, 3u, 2, "annulus"));
  RUN(holes_case(m, 10, 10u, 2, "annulus"));
  return EXIT_SUCCESS;
}

template <class Mesh>
int sphere_cases(const std::string& data_dir)
{
  Mesh m;
  if(!read_mesh(data_dir + "/meshes/sphere966.off", m)) return EXIT_FAILURE;
  cut_one_rings(m, far_apart_vertices(m, 4));
  // the removed centers are garbage in a Surface_mesh: collected, so that no Steiner vertex takes
  // their slots (see constrained_cases_recycled_vertex)
  if constexpr(std::is_same<Mesh, Surface_mesh>::value) m.collect_garbage();
  RUN(holes_case(m, 0, 1u, 4, "sphere with 3 holes"));
  RUN(holes_case(m, 3, 3u, 4, "sphere with 3 holes"));
  RUN(holes_case(m, 10, 10u, 4, "sphere with 3 holes"));
  return EXIT_SUCCESS;
}

} // namespace

PE_TEST_GROUP(constrained_cases_annulus)
{
  (void)data_dir;
  RUN(annulus_cases<Surface_mesh>());
  RUN(annulus_cases<Polyhedron>());
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(constrained_cases_sphere_holes)
{
  RUN(sphere_cases<Surface_mesh>(data_dir));
  RUN(sphere_cases<Polyhedron>(data_dir));
  return EXIT_SUCCESS;
}

// A Surface_mesh with a removed vertex whose slot is not collected (the grid's corner (0, 0) cut off with
// its two faces: still a disk). Surface_mesh recycles removed slots, so a Steiner vertex added by the
// replayed edge splits takes rank 0, ahead of the input vertices, against the documented order (input
// vertices first, then the Steiner vertices). The descriptors and points of the input vertices are kept.
PE_TEST_GROUP(constrained_cases_recycled_vertex)
{
  (void)data_dir;
  const int N = 10;
  Surface_mesh m;
  make_grid_with_holes(m, N, N, {});
  const auto V = vertex_list(m);
  auto at = [&](int x, int y) { return V[std::size_t(y * (N + 1) + x)]; };
  std::vector<Surface_mesh::Face_index> corner;
  for(auto f : CGAL::faces_around_target(halfedge(at(0, 0), m), m)) if(f != Surface_mesh::null_face()) corner.push_back(f);
  for(auto f : corner) CGAL::Euler::remove_face(halfedge(f, m), m);
  CHECK(corner.size() == 2 && m.is_removed(at(0, 0)) && m.has_garbage() && count_border_cycles(m) == 1, "corner cut off, not collected");
  RUN(adjacent_case<Epick>(m, at(3, 4), at(4, 4), at(4, 2), at(3, 6), Layout::BETWEEN,
                           "grid 10x10 without its corner (0, 0), not collected, " + layout_name(Layout::BETWEEN)));
  return EXIT_SUCCESS;
}

// Targets at the constrained vertices' own places in a Tutte map, where it crowds them: the dinosaur
// cut open around the Tutte-failure protocol's face for seed 2 (the one-ring of the face removed), its
// border on the square [-1.5, 2.5]^2 by arc length, 10 interior vertices (mt19937(2010) shuffle) pinned
// where the Tutte map puts them. Some partition polygons are 1e-8 across at 0.36, with corners so
// sharp that two path vertices, placed within an ulp of their segments, fall on the line of the other
// side: a face with its three vertices on the path network is flat, and no patch map can move it. Its
// chord is split (a free vertex), and the map is certified.
PE_TEST_GROUP(constrained_cases_rounded_corner)
{
  typedef Epick::Point_2 P2;
  typedef Vertex<Surface_mesh> VD;
  Surface_mesh m;
  if(!read_mesh(data_dir + "/meshes/dino.off", m)) return EXIT_FAILURE;
  {
    const std::vector<Surface_mesh::Face_index> F(faces(m).begin(), faces(m).end());
    const auto f = F[PE::internal::thingi_face_index(F.size(), 2u)];
    std::set<Surface_mesh::Face_index> ring;
    for(VD v : CGAL::vertices_around_face(halfedge(f, m), m))
      for(auto g : CGAL::faces_around_target(halfedge(v, m), m))
        if(g != Surface_mesh::null_face()) ring.insert(g);
    for(auto g : ring) CGAL::Euler::remove_face(halfedge(g, m), m);
    m.collect_garbage();
  }
  CHECK(count_border_cycles(m) == 1, "dino cut open: a disk");
  auto uv = make_uv_map(m, P2());
  CHECK(square_tutte(m, uv), "Tutte map");
  for(VD v : vertices(m)) { const P2 p = get(uv, v); put(uv, v, P2(4 * p.x() - 1.5, 4 * p.y() - 1.5)); }
  std::vector<VD> interior;
  for(VD v : vertices(m)) if(!CGAL::is_border(v, m)) interior.push_back(v);
  std::mt19937 gen(2u * 1000u + 10u);
  std::shuffle(interior.begin(), interior.end(), gen);
  std::vector<std::pair<VD, P2> > C;
  std::set<std::pair<double, double> > used;
  for(std::size_t j = 0; j < interior.size() && C.size() < 10; ++j)
  {
    const P2 p = get(uv, interior[j]);
    if(used.insert({p.x(), p.y()}).second) C.emplace_back(interior[j], p);
  }
  CHECK(C.size() == 10, "10 distinct targets");
  PE::Constrained_embedding_statistics st;
  RUN(run_checked(m, uv, C, "dino cut open, 10 targets at their crowded Tutte places", 1, st));
  // no chord joins two vertices of one side here: every split is of a face flattened by rounding
  CHECK(st.chord_splits >= 1, "the faces flattened by rounding are split");
  return EXIT_SUCCESS;
}
