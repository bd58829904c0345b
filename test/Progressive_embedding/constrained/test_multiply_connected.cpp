// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Multiply connected domains (meshes with holes): the certificate (check_embedding with
// multiply_connected), the fill/unfill machinery, the embedding with holes, and optimize_distortion
// on maps with holes. Invalid maps are compared with brute-force counts (every pair of faces, every
// pair of border edges, decided with exact rationals independently of the package's passes).

#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/internal/constrained/holes.h>

#include "registry.h"
#include "../test_util.h"
#include "mesh_fixtures.h"

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <set>


namespace {

typedef Epick::Point_3 P3;
typedef Epick::Point_2 P2;

// ---- meshes ---------------------------------------------------------------------------------------

// the meshes shared with the other constrained-map tests (mesh_fixtures.h)
using pe_test::make_annulus;
using pe_test::make_grid_with_holes;
using pe_test::cut_one_rings;
using pe_test::far_apart_vertices;
using pe_test::count_vertices;
using pe_test::count_border_cycles;

// The planar positions of the annulus (a valid map): uv = (x, y)
template <class K, class Mesh, class UVM>
void planar_uv(const Mesh& m, UVM& uv)
{
  for(auto v : vertices(m)) put(uv, v, point<K>(get(CGAL::vertex_point, m, v).x(), get(CGAL::vertex_point, m, v).y()));
}

// A torus: n x m grid with wrap-around, major radius 3, minor 1.
template <class Mesh>
void make_torus(Mesh& m, int n, int k)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  auto vpm = get(CGAL::vertex_point, m);
  std::vector<vd> V;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < k; ++j)
    {
      const double u = 2 * CGAL_PI * i / n, w = 2 * CGAL_PI * j / k;
      V.push_back(add_vertex(m));
      put(vpm, V.back(), P3((3 + std::cos(w)) * std::cos(u), (3 + std::cos(w)) * std::sin(u), std::sin(w)));
    }
  auto id = [&](int i, int j) { return V[std::size_t(((i + n) % n) * k + ((j + k) % k))]; };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < k; ++j)
    {
      CGAL::Euler::add_face(std::vector<vd>{ id(i, j), id(i + 1, j), id(i + 1, j + 1) }, m);
      CGAL::Euler::add_face(std::vector<vd>{ id(i, j), id(i + 1, j + 1), id(i, j + 1) }, m);
    }
}

// ---- brute-force counts (exact rationals, every pair) ----------------------------------------------

typedef Kq::Point_2 Q2;

template <class Point_2>
Q2 rational(const Point_2& p) { return Q2(exact_rational(p.x()), exact_rational(p.y())); }

// interiors of two non-degenerate triangles intersect iff no edge line of either weakly separates them
inline bool interiors_meet(std::array<Q2, 3> a, std::array<Q2, 3> b)
{
  if(CGAL::orientation(a[0], a[1], a[2]) == CGAL::RIGHT_TURN) std::swap(a[1], a[2]);
  if(CGAL::orientation(b[0], b[1], b[2]) == CGAL::RIGHT_TURN) std::swap(b[1], b[2]);
  for(int pass = 0; pass < 2; ++pass)
  {
    const std::array<Q2, 3>& s = pass ? b : a;
    const std::array<Q2, 3>& t = pass ? a : b;
    for(int e = 0; e < 3; ++e)
    {
      bool some_left = false;
      for(int q = 0; q < 3; ++q) if(CGAL::orientation(s[e], s[(e + 1) % 3], t[q]) == CGAL::LEFT_TURN) some_left = true;
      if(!some_left) return false;
    }
  }
  return true;
}

struct Brute_counts
{
  std::size_t flipped = 0, degenerate = 0, overlapping_pairs = 0, self_intersections = 0, crossings = 0;
};

// `outer_sign`: the orientation expected of the faces (that of the outer loop)
template <class Mesh, class UVM>
Brute_counts brute_counts(const Mesh& m, const UVM& uv, CGAL::Orientation outer_sign)
{
  Brute_counts r;
  count_orientations(m, uv, outer_sign, r.flipped, r.degenerate);
  std::vector<std::array<Q2, 3> > T;
  std::vector<std::array<typename boost::graph_traits<Mesh>::vertex_descriptor, 3> > TV;
  for(auto f : faces(m))
  {
    std::array<Q2, 3> t;
    std::array<typename boost::graph_traits<Mesh>::vertex_descriptor, 3> tv;
    int c = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) { tv[c] = v; t[c++] = rational(get(uv, v)); }
    if(CGAL::orientation(t[0], t[1], t[2]) == CGAL::COLLINEAR) continue;
    T.push_back(t); TV.push_back(tv);
  }
  for(std::size_t i = 0; i < T.size(); ++i)
    for(std::size_t j = i + 1; j < T.size(); ++j)
    {
      const bool ok_i = CGAL::orientation(T[i][0], T[i][1], T[i][2]) == outer_sign;
      const bool ok_j = CGAL::orientation(T[j][0], T[j][1], T[j][2]) == outer_sign;
      int shared = 0;
      for(int a = 0; a < 3; ++a) for(int b = 0; b < 3; ++b) shared += (TV[i][a] == TV[j][b]);
      if(ok_i && ok_j && shared >= 2) continue; // correctly oriented neighbours lie on both sides of their edge
      if(interiors_meet(T[i], T[j])) ++r.overlapping_pairs;
    }
  // border edges, with their loop
  std::map<typename boost::graph_traits<Mesh>::halfedge_descriptor, std::size_t> loop;
  std::vector<std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor> > loops;
  for(auto h : halfedges(m))
  {
    if(!is_border(h, m) || loop.count(h)) continue;
    loops.emplace_back();
    for(auto g : CGAL::halfedges_around_face(h, m)) { loop[g] = loops.size() - 1; loops.back().push_back(g); }
  }
  std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor> E;
  for(const auto& L : loops) for(auto h : L) E.push_back(h);
  for(std::size_t i = 0; i < E.size(); ++i)
    for(std::size_t j = i + 1; j < E.size(); ++j)
    {
      const Kq::Segment_2 s(rational(get(uv, source(E[i], m))), rational(get(uv, target(E[i], m))));
      const Kq::Segment_2 t(rational(get(uv, source(E[j], m))), rational(get(uv, target(E[j], m))));
      if(loop[E[i]] != loop[E[j]]) { if(CGAL::do_intersect(s, t)) ++r.crossings; continue; }
      const bool adjacent = target(E[i], m) == source(E[j], m) || target(E[j], m) == source(E[i], m);
      if(!adjacent) { if(CGAL::do_intersect(s, t)) ++r.self_intersections; continue; }
      // adjacent edges: only a fold-back (the two other ends on one side of the shared vertex, collinear)
      const auto sh = (target(E[i], m) == source(E[j], m)) ? target(E[i], m) : target(E[j], m);
      const auto u = (sh == target(E[i], m)) ? source(E[i], m) : target(E[i], m);
      const auto w = (sh == source(E[j], m)) ? target(E[j], m) : source(E[j], m);
      const Q2 S = rational(get(uv, sh)), U = rational(get(uv, u)), W = rational(get(uv, w));
      if(CGAL::orientation(U, S, W) == CGAL::COLLINEAR && CGAL::compare_xy(U, S) == CGAL::compare_xy(W, S)) ++r.self_intersections;
    }
  return r;
}

template <class Report>
int check_against_brute(const Report& r, const Brute_counts& b, const std::string& what)
{
  std::cout << "  " << what << ": " << r.summary() << std::endl;
  std::cout << "    brute force: flipped " << b.flipped << ", degenerate " << b.degenerate << ", overlapping pairs "
            << b.overlapping_pairs << ", loop self-intersections " << b.self_intersections << ", loop contacts "
            << b.crossings << std::endl;
  CHECK(r.status == PE::OK, what << ": checked");
  CHECK(!r.is_valid(), what << ": INVALID");
  CHECK(r.flipped == b.flipped && r.degenerate == b.degenerate, what << ": flipped and degenerate counts");
  CHECK(r.border_intersections == b.self_intersections, what << ": loop self-intersections");
  CHECK(r.loop_crossings == b.crossings, what << ": loop contacts");
  CHECK(r.overlap_checked && !r.overlap_by_degree_argument && r.overlapping_pairs == b.overlapping_pairs,
        what << ": overlapping pairs");
  return EXIT_SUCCESS;
}

template <class Mesh, class UVM>
std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, typename boost::property_traits<UVM>::value_type>
snapshot(const Mesh& m, const UVM& uv)
{
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, typename boost::property_traits<UVM>::value_type> s;
  for(auto v : vertices(m)) s[v] = get(uv, v);
  return s;
}

template <class Mesh, class UVM, class Snap>
bool same_uv(const Mesh& m, const UVM& uv, const Snap& s)
{
  for(auto v : vertices(m))
  {
    const auto p = get(uv, v), q = s.at(v);
    if constexpr(std::is_same<std::decay_t<decltype(p.x())>, double>::value)
    { if(!same_bits(p.x(), q.x()) || !same_bits(p.y(), q.y())) return false; } // NaN too
    else if(!(p.x() == q.x()) || !(p.y() == q.y())) return false;
  }
  return true;
}

// the vertices of the border loop through h
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>
loop_vertices(const Mesh& m, typename boost::graph_traits<Mesh>::halfedge_descriptor h)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> L;
  for(auto g : CGAL::halfedges_around_face(h, m)) L.push_back(target(g, m));
  return L;
}

template <class Report>
int check_valid(const Report& r, std::size_t cycles, const std::string& what)
{
  std::cout << "  " << what << ": " << r.summary() << std::endl;
  CHECK(r.status == PE::OK && r.is_valid(), what << ": certified valid");
  CHECK(r.border_cycles == cycles, what << ": " << cycles << " border cycles (got " << r.border_cycles << ")");
  CHECK(r.flipped == 0 && r.degenerate == 0 && r.overlapping_pairs == 0 && r.loop_crossings == 0
        && r.misoriented_holes == 0 && r.holes_outside == 0 && r.border_intersections == 0, what << ": counts 0");
  CHECK(r.overlap_checked && r.overlap_by_degree_argument, what << ": overlap excluded by the degree argument");
  return EXIT_SUCCESS;
}

// ---- groups -------------------------------------------------------------------------------------

template <class Mesh>
int certificate_annulus()
{
  std::cout << mesh_name<Mesh>() << std::endl;
  Mesh m;
  make_annulus(m, 4, 16);
  auto uv = make_uv_map(m, P2());
  planar_uv<Epick>(m, uv);
  // disk behaviour unchanged by default: refused, with the number of cycles
  const PE::Embedding_report d = PE::check_embedding(m, uv);
  CHECK(d.status == PE::ERROR_NOT_A_DISK && !d.is_valid() && d.border_cycles == 2, "default: not a disk, 2 cycles");
  const auto holes = PE::parameters::multiply_connected(true);
  PE::Embedding_report r = PE::check_embedding(m, uv, holes);
  RUN(check_valid(r, 2, "planar annulus"));
  CHECK(r.border_vertices == 32 && !r.clockwise, "32 border vertices, counterclockwise");
  CHECK(std::abs(r.border_area - 0.5 * 16 * (4 - 1) * std::sin(2 * CGAL_PI / 16)) < 1e-12, "domain area: outer minus hole");
  // the mirror image: valid, reported clockwise
  for(auto v : vertices(m)) put(uv, v, P2(get(uv, v).x(), -get(uv, v).y()));
  r = PE::check_embedding(m, uv, holes);
  RUN(check_valid(r, 2, "mirrored annulus"));
  CHECK(r.clockwise, "mirror: clockwise");
  // the hole scaled up beyond the outer circle
  planar_uv<Epick>(m, uv);
  auto inner = loop_vertices(m, *std::find_if(halfedges(m).begin(), halfedges(m).end(), [&](auto h) {
    return is_border(h, m) && CGAL::squared_distance(get(CGAL::vertex_point, m, target(h, m)), P3(0, 0, 0)) < 1.5; }));
  CHECK(inner.size() == 16, "inner loop");
  {
    // one hole vertex pushed out through the outer border
    const auto v = inner[0];
    const P2 p = get(uv, v);
    put(uv, v, P2(2.5 * p.x(), 2.5 * p.y()));
    r = PE::check_embedding(m, uv, holes);
    RUN(check_against_brute(r, brute_counts(m, uv, r.clockwise ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN), "hole vertex through the outer border"));
    CHECK(r.loop_crossings >= 2 && r.flipped >= 1, "crossings and flips");
    put(uv, v, p);
  }
  {
    // the whole hole loop scaled beyond the outer circle: the largest loop, clockwise, is now the outer
    // one (the map is read as a mirror image), the former outer loop a hole inside it
    for(auto v : inner) { const P2 p = get(uv, v); put(uv, v, P2(3.0 * p.x(), 3.0 * p.y())); }
    r = PE::check_embedding(m, uv, holes);
    RUN(check_against_brute(r, brute_counts(m, uv, r.clockwise ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN), "hole loop around the outer loop"));
    CHECK(r.clockwise && r.flipped > 0 && r.misoriented_holes == 0 && r.holes_outside == 0 && r.loop_crossings == 0,
          "the former hole is the (clockwise) outer loop; faces flipped");
    planar_uv<Epick>(m, uv);
  }
  {
    // the hole loop traversed the other way round (its vertices mirrored in the x axis): the hole is
    // counterclockwise like the outer loop, the faces along it fold over
    for(auto v : inner) { const P2 p = get(uv, v); put(uv, v, P2(p.x(), -p.y())); }
    r = PE::check_embedding(m, uv, holes);
    RUN(check_against_brute(r, brute_counts(m, uv, r.clockwise ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN), "hole loop reversed"));
    CHECK(r.misoriented_holes == 1 && r.loop_crossings == 0 && r.border_intersections == 0 && r.holes_outside == 0 && !r.clockwise,
          "one misoriented hole, loops simple and apart");
    planar_uv<Epick>(m, uv);
  }
  CHECK(PE::check_embedding(m, uv, holes).is_valid(), "restored");
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(holes_certificate_annulus)
{
  (void)data_dir;
  RUN(certificate_annulus<Surface_mesh>());
  RUN(certificate_annulus<Polyhedron>());
  return EXIT_SUCCESS;
}

// two holes (unit cells (2,2) and (4,2)) in a 7 x 5 grid: one pushed into the other, touching,
// a face moved into a hole, a hole through the outer border
template <class Mesh>
int certificate_two_holes()
{
  std::cout << mesh_name<Mesh>() << std::endl;
  Mesh m;
  make_grid_with_holes(m, 7, 5, { { 2, 2 }, { 4, 2 } });
  auto uv = make_uv_map(m, P2());
  planar_uv<Epick>(m, uv);
  const auto holes = PE::parameters::multiply_connected(true);
  PE::Embedding_report r = PE::check_embedding(m, uv, holes);
  RUN(check_valid(r, 3, "grid with two holes"));
  CHECK(r.border_vertices == 24 + 4 + 4, "32 border vertices");
  CHECK(r.border_area == 35 - 2, "domain area 33");
  auto at = [&](double x, double y) {
    for(auto v : vertices(m)) if(get(uv, v) == P2(x, y)) return v;
    return *vertices(m).begin();
  };
  {
    // corner (3,2) of hole A moved into hole B: the loops overlap
    const auto v = at(3, 2);
    put(uv, v, P2(4.5, 2.5));
    r = PE::check_embedding(m, uv, holes);
    RUN(check_against_brute(r, brute_counts(m, uv, r.clockwise ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN), "hole loops overlapping"));
    CHECK(r.loop_crossings > 0 && r.border_cycles == 3, "loop contacts");
    put(uv, v, P2(3, 2));
  }
  {
    // corner (3,2) of hole A moved onto the edge (4,2)-(4,3) of hole B: the loops touch
    const auto v = at(3, 2);
    put(uv, v, P2(4, 2.5));
    r = PE::check_embedding(m, uv, holes);
    RUN(check_against_brute(r, brute_counts(m, uv, r.clockwise ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN), "hole loops touching"));
    CHECK(r.loop_crossings == 2, "two contacts (the two edges at the moved vertex)");
    put(uv, v, P2(3, 2));
  }
  {
    // the interior vertex (1,1) moved into hole A: its faces cover the hole, the loops stay apart
    const auto v = at(1, 1);
    put(uv, v, P2(2.5, 2.5));
    r = PE::check_embedding(m, uv, holes);
    RUN(check_against_brute(r, brute_counts(m, uv, r.clockwise ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN), "faces inside a hole"));
    CHECK(r.loop_crossings == 0 && r.border_intersections == 0 && r.holes_outside == 0 && r.misoriented_holes == 0
          && r.flipped > 0 && r.overlapping_pairs > 0, "loops fine, faces flipped and overlapping");
    put(uv, v, P2(1, 1));
  }
  {
    // a vertex of hole B pushed through the outer border (1 unit below)
    const auto v = at(5, 2);
    put(uv, v, P2(5.5, -1));
    r = PE::check_embedding(m, uv, holes);
    RUN(check_against_brute(r, brute_counts(m, uv, r.clockwise ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN), "hole crossing the outer border"));
    CHECK(r.loop_crossings > 0 && r.holes_outside == 1, "outer border crossed, the hole has a vertex outside");
    put(uv, v, P2(5, 2));
  }
  CHECK(PE::check_embedding(m, uv, holes).is_valid(), "restored");
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(holes_certificate_invalid)
{
  (void)data_dir;
  RUN(certificate_two_holes<Surface_mesh>());
  RUN(certificate_two_holes<Polyhedron>());
  return EXIT_SUCCESS;
}

// fill_holes / unfill_holes: a disk while filled, exactly the input afterwards
template <class Mesh>
int fill_unfill(const std::string& data_dir)
{
  typedef boost::graph_traits<Mesh> GT;
  std::cout << mesh_name<Mesh>() << std::endl;
  Mesh m;
  if(!read_mesh(data_dir + "/meshes/sphere966.off", m)) return EXIT_FAILURE;
  cut_one_rings(m, far_apart_vertices(m, 3));
  CHECK(count_border_cycles(m) == 3, "3 holes cut");
  // the input's incidences, by descriptor
  std::map<typename GT::face_descriptor, std::vector<typename GT::halfedge_descriptor> > F;
  for(auto f : faces(m)) for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m)) F[f].push_back(h);
  std::map<typename GT::halfedge_descriptor, std::array<typename GT::halfedge_descriptor, 2> > H;
  std::map<typename GT::vertex_descriptor, typename GT::halfedge_descriptor> VH;
  std::map<typename GT::vertex_descriptor, P3> VP;
  for(auto h : halfedges(m)) H[h] = {{ next(h, m), opposite(h, m) }};
  for(auto v : vertices(m)) { VH[v] = halfedge(v, m); VP[v] = get(CGAL::vertex_point, m, v); }
  const std::size_t nv = count_vertices(m), nf = count_faces(m), nh = H.size();
  std::size_t loop_edges = 0;
  for(auto h : halfedges(m)) if(is_border(h, m)) ++loop_edges;

  PE::internal::Filled_holes<Mesh> rec;
  // the outer loop given: a border halfedge of one hole
  typename GT::halfedge_descriptor outer = GT::null_halfedge();
  for(auto h : halfedges(m)) if(is_border(h, m)) { outer = h; break; }
  const PE::Error_code ef = PE::internal::fill_holes(m, outer, get(CGAL::vertex_point, m), rec);
  CHECK(ef == PE::OK, "filled: " << PE::get_error_name(ef));
  const std::size_t outer_size = loop_vertices(m, outer).size();
  CHECK(rec.number_of_holes() == 2 && count_border_cycles(m) == 1 && is_border(outer, m), "two holes filled, the outer one open");
  CHECK(count_vertices(m) == nv + 2 && count_faces(m) == nf + (loop_edges - outer_size), "one vertex and one face per hole edge");
  PE::internal::Indexed_domain<Mesh> filled;
  CHECK(PE::internal::make_indexed_domain(m, filled) == PE::OK && filled.number_of_loops() == 1, "a disk while filled");
  for(std::size_t i = 0; i < rec.number_of_holes(); ++i)
  {
    // the centre: the centroid of its loop
    double x = 0, y = 0, z = 0, n = 0;
    for(auto w : CGAL::vertices_around_target(halfedge(rec.centers[i], m), m))
    { const P3& p = get(CGAL::vertex_point, m, w); x += p.x(); y += p.y(); z += p.z(); ++n; }
    const P3& c = get(CGAL::vertex_point, m, rec.centers[i]);
    CHECK(n == double(rec.loop_sizes[i]) && std::abs(c.x() - x / n) + std::abs(c.y() - y / n) + std::abs(c.z() - z / n) < 1e-12,
          "centre at the loop's centroid");
  }
  CHECK(PE::internal::unfill_holes(m, rec) == PE::OK, "unfilled");
  CHECK(count_vertices(m) == nv && count_faces(m) == nf && count_border_cycles(m) == 3, "sizes restored");
  std::size_t nh_after = 0;
  for(auto h : halfedges(m))
  {
    ++nh_after;
    CHECK(H.count(h) && H[h][0] == next(h, m) && H[h][1] == opposite(h, m), "halfedge incidences restored");
  }
  CHECK(nh_after == nh, "halfedges restored");
  for(auto f : faces(m))
  {
    std::vector<typename GT::halfedge_descriptor> hs;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m)) hs.push_back(h);
    CHECK(F.count(f) && F[f] == hs, "face restored with its halfedge");
  }
  for(auto v : vertices(m)) CHECK(VH.count(v) && VH[v] == halfedge(v, m) && VP[v] == get(CGAL::vertex_point, m, v), "vertex restored");
  CHECK(CGAL::is_valid_polygon_mesh(m), "valid mesh");
  // a fan changed after filling: unfill refuses and leaves the mesh as it is
  CHECK(PE::internal::fill_holes(m, GT::null_halfedge(), get(CGAL::vertex_point, m), rec) == PE::OK && rec.number_of_holes() == 2, "refilled (longest loop outer)");
  {
    const auto c = rec.centers[0];
    CGAL::Euler::split_edge(halfedge(c, m), m); // a spoke split: the fan is no longer the recorded one
    const std::size_t nv2 = count_vertices(m);
    CHECK(PE::internal::unfill_holes(m, rec) == PE::ERROR_WRONG_PARAMETER && count_vertices(m) == nv2 && rec.number_of_holes() == 2,
          "changed fan: refused, nothing done");
  }
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(holes_fill_unfill)
{
  RUN(fill_unfill<Surface_mesh>(data_dir));
  RUN(fill_unfill<Polyhedron>(data_dir));
  return EXIT_SUCCESS;
}

// the embedding of an annulus: circle border, then a fixed (bit-exact) border
template <class Mesh>
int embed_annulus()
{
  typedef boost::graph_traits<Mesh> GT;
  std::cout << mesh_name<Mesh>() << std::endl;
  Mesh m;
  make_annulus(m, 6, 24, 0.8);
  const std::size_t nv = count_vertices(m), nf = count_faces(m);
  auto uv = make_uv_map(m, P2());
  PE::Embedding_report r;
  CHECK(PE::internal::embed_with_holes(m, GT::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE), &r) == PE::OK,
        "annulus on a circle");
  RUN(check_valid(r, 2, "annulus, circle"));
  CHECK(count_vertices(m) == nv && count_faces(m) == nf, "mesh unchanged");
  RUN(check_valid(PE::check_embedding(m, uv, PE::parameters::multiply_connected(true)), 2, "re-certified"));
  // fixed border: a square-ish convex polygon on the outer loop (the longest in 3D), interior garbage
  typename GT::halfedge_descriptor outer = PE::internal::longest_border_loop(m, get(CGAL::vertex_point, m));
  const auto L = loop_vertices(m, outer);
  CHECK(L.size() == 24, "the outer loop is the longest");
  for(std::size_t k = 0; k < L.size(); ++k)
  {
    const double t = 2 * CGAL_PI * double(k) / double(L.size());
    put(uv, L[k], P2(std::cos(t) * 3 + 0.25 * std::cos(3 * t), std::sin(t) * 3)); // convex, not a circle
  }
  for(auto v : vertices(m)) if(std::find(L.begin(), L.end(), v) == L.end()) put(uv, v, P2(std::nan(""), 7));
  const auto before = snapshot(m, uv);
  // a non-convex fixed border is refused and nothing is written
  const P2 keep = get(uv, L[3]);
  put(uv, L[3], P2(0, 0));
  const auto before_bad = snapshot(m, uv);
  CHECK(PE::internal::embed_with_holes(m, outer, uv, CGAL::parameters::default_values()) == PE::ERROR_NON_CONVEX_BORDER
        && same_uv(m, uv, before_bad), "non-convex outer border: refused, uv unchanged");
  put(uv, L[3], keep);
  CHECK(PE::internal::embed_with_holes(m, outer, uv, CGAL::parameters::default_values(), &r) == PE::OK, "fixed border");
  RUN(check_valid(r, 2, "annulus, fixed border"));
  bool exact = true;
  for(auto v : L) exact = exact && same_bits(get(uv, v).x(), before.at(v).x()) && same_bits(get(uv, v).y(), before.at(v).y());
  CHECK(exact, "outer border bit-exact");
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(holes_embed_annulus)
{
  (void)data_dir;
  RUN(embed_annulus<Surface_mesh>());
  RUN(embed_annulus<Polyhedron>());
  return EXIT_SUCCESS;
}

// a closed genus-0 mesh with the 1-rings of 4 far-apart vertices removed: 4 border cycles, the
// longest one the outer loop and 3 holes; then optimized with the outer loop fixed
template <class Mesh>
int embed_sphere_three_holes(const std::string& data_dir)
{
  typedef boost::graph_traits<Mesh> GT;
  std::cout << mesh_name<Mesh>() << std::endl;
  Mesh m;
  if(!read_mesh(data_dir + "/meshes/sphere966.off", m)) return EXIT_FAILURE;
  cut_one_rings(m, far_apart_vertices(m, 4));
  CHECK(count_border_cycles(m) == 4, "4 border cycles");
  auto uv = make_uv_map(m, P2());
  PE::Embedding_report r;
  const PE::Error_code ee = PE::internal::embed_with_holes(m, GT::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::SQUARE), &r);
  CHECK(ee == PE::OK, "embedded on a square: " << PE::get_error_name(ee));
  RUN(check_valid(r, 4, "sphere with 3 holes (4 border cycles)"));
  const typename GT::halfedge_descriptor outer = PE::internal::longest_border_loop(m, get(CGAL::vertex_point, m));
  const auto L = loop_vertices(m, outer);
  const auto before = snapshot(m, uv);
  PE::Optimization_statistics st;
  const PE::Error_code ec = PE::optimize_distortion(m, uv, PE::parameters::optimization_statistics(&st,
                                                    CGAL::parameters::number_of_iterations(200)));
  std::cout << "  optimize: " << PE::get_error_name(ec) << ", " << st.iterations << " iterations, energy " << st.energy_before
            << " -> " << st.energy_after << "; " << st.report.summary() << std::endl;
  CHECK(ec == PE::OK || ec == PE::ERROR_BUDGET_EXHAUSTED, "optimized");
  RUN(check_valid(PE::check_embedding(m, uv, PE::parameters::multiply_connected(true)), 4, "optimized sphere with 3 holes"));
  CHECK(st.energy_after < st.energy_before, "energy lowered");
  bool exact = true, hole_moved = false;
  for(auto v : L) exact = exact && same_bits(get(uv, v).x(), before.at(v).x()) && same_bits(get(uv, v).y(), before.at(v).y());
  for(auto h : halfedges(m))
    if(is_border(h, m) && std::find(L.begin(), L.end(), target(h, m)) == L.end() && !(get(uv, target(h, m)) == before.at(target(h, m))))
      hole_moved = true;
  CHECK(exact, "outer border bit-exact");
  CHECK(hole_moved, "hole vertices are free");
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(holes_embed_sphere)
{
  RUN(embed_sphere_three_holes<Surface_mesh>(data_dir));
  RUN(embed_sphere_three_holes<Polyhedron>(data_dir));
  return EXIT_SUCCESS;
}

// a real mesh with 4 border cycles (libcgal-demo's mech-holes-shark: genus 0)
PE_TEST_GROUP(holes_embed_shark)
{
  typedef boost::graph_traits<Surface_mesh> GT;
  Surface_mesh m;
  if(!read_mesh(data_dir + "/meshes/mech-holes-shark.off", m)) return EXIT_FAILURE;
  CHECK(count_border_cycles(m) == 4, "4 border cycles");
  auto uv = make_uv_map(m, P2());
  PE::Embedding_report r;
  const PE::Error_code ec = PE::internal::embed_with_holes(m, GT::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE), &r);
  std::cout << "  embed: " << PE::get_error_name(ec) << std::endl;
  CHECK(ec == PE::OK, "embedded");
  RUN(check_valid(r, 4, "mech-holes-shark"));
  const auto outer = loop_vertices(m, PE::internal::longest_border_loop(m, get(CGAL::vertex_point, m)));
  const auto before = snapshot(m, uv);
  PE::Optimization_statistics st;
  const PE::Error_code eo = PE::optimize_distortion(m, uv, PE::parameters::optimization_statistics(&st,
                                                    CGAL::parameters::number_of_iterations(30)));
  std::cout << "  optimize: " << PE::get_error_name(eo) << ", " << st.iterations << " iterations, energy " << st.energy_before
            << " -> " << st.energy_after << "; " << st.report.summary() << std::endl;
  CHECK(eo == PE::OK || eo == PE::ERROR_BUDGET_EXHAUSTED, "optimized");
  RUN(check_valid(st.report, 4, "optimized mech-holes-shark"));
  CHECK(st.energy_after < st.energy_before, "energy lowered");
  bool exact = true;
  for(auto v : outer) exact = exact && same_bits(get(uv, v).x(), before.at(v).x()) && same_bits(get(uv, v).y(), before.at(v).y());
  CHECK(exact, "outer border bit-exact");
  return EXIT_SUCCESS;
}

// Optimization that pulls hole loops towards the outer border and towards each other: the 3D
// shapes are planar with a hole 0.05 from the outer circle, and two holes 0.05 apart, while the
// Tutte maps start with wide gaps; every iteration is certified (one call per iteration).
template <class Mesh, class UVM>
int optimize_each_iteration(const Mesh& m, UVM& uv, std::size_t cycles, const std::string& what)
{
  const auto outer = loop_vertices(m, PE::internal::longest_border_loop(m, get(CGAL::vertex_point, m)));
  const auto start = snapshot(m, uv);
  double first = 0, last = 0;
  for(int it = 0; it < 40; ++it)
  {
    PE::Optimization_statistics st;
    const PE::Error_code ec = PE::optimize_distortion(m, uv, PE::parameters::optimization_statistics(&st,
                                                      CGAL::parameters::number_of_iterations(1)));
    CHECK(ec == PE::OK || ec == PE::ERROR_BUDGET_EXHAUSTED, what << ": iteration " << it << ": " << PE::get_error_name(ec));
    const PE::Embedding_report c = PE::check_embedding(m, uv, PE::parameters::multiply_connected(true));
    CHECK(c.is_valid() && c.border_cycles == cycles && c.loop_crossings == 0, what << ": iteration " << it << " certified: " << c.summary());
    if(it == 0) first = st.energy_before;
    last = st.energy_after;
  }
  std::cout << "  " << what << ": 40 iterations certified, energy " << first << " -> " << last << std::endl;
  CHECK(last < first, what << ": energy lowered");
  bool exact = true;
  for(auto v : outer) exact = exact && same_bits(get(uv, v).x(), start.at(v).x()) && same_bits(get(uv, v).y(), start.at(v).y());
  CHECK(exact, what << ": outer border bit-exact");
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(holes_optimize_every_step)
{
  (void)data_dir;
  typedef boost::graph_traits<Surface_mesh> GT;
  {
    // annulus: outer circle of radius 1, hole of radius 0.5 centred at (0.45, 0)
    Surface_mesh m;
    make_annulus(m, 5, 48, 0.0);
    auto vpm = get(CGAL::vertex_point, m);
    for(auto v : vertices(m))
    {
      const P3 p = get(vpm, v);
      const double r = std::sqrt(p.x() * p.x() + p.y() * p.y()), c = p.x() / r, s = p.y() / r, a = r - 1; // a in [0, 1]
      put(vpm, v, P3((1 - a) * (0.45 + 0.5 * c) + a * c, (1 - a) * 0.5 * s + a * s, 0));
    }
    auto uv = make_uv_map(m, P2());
    PE::Embedding_report r;
    CHECK(PE::internal::embed_with_holes(m, GT::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE), &r) == PE::OK,
          "off-centre annulus embedded");
    RUN(check_valid(r, 2, "off-centre annulus"));
    RUN(optimize_each_iteration(m, uv, 2, "off-centre annulus"));
  }
  {
    // two holes 0.05 apart in 3D: a 7 x 5 grid whose column 3 is squeezed to width 0.05
    Surface_mesh m;
    make_grid_with_holes(m, 7, 5, { { 2, 2 }, { 4, 2 } });
    auto vpm = get(CGAL::vertex_point, m);
    for(auto v : vertices(m))
    {
      const P3 p = get(vpm, v);
      const double x = p.x() <= 3 ? p.x() : 3.05 + (p.x() - 4);
      put(vpm, v, P3(x, p.y(), 0));
    }
    auto uv = make_uv_map(m, P2());
    PE::Embedding_report r;
    CHECK(PE::internal::embed_with_holes(m, GT::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::SQUARE), &r) == PE::OK,
          "squeezed grid embedded");
    RUN(check_valid(r, 3, "two holes close together"));
    RUN(optimize_each_iteration(m, uv, 3, "two holes close together"));
    // the free-border variant keeps the loops apart as well
    PE::Optimization_statistics st;
    const PE::Error_code ec = PE::optimize_distortion(m, uv, PE::parameters::free_border(true, PE::parameters::optimization_statistics(&st,
                                                      CGAL::parameters::number_of_iterations(30))));
    CHECK(ec == PE::OK || ec == PE::ERROR_BUDGET_EXHAUSTED, "free border");
    RUN(check_valid(st.report, 3, "free border, two holes close together"));
    CHECK(!(st.energy_after > st.energy_before), "free border, two holes close together: energy " << st.energy_before << " -> " << st.energy_after);
  }
  return EXIT_SUCCESS;
}

// exact number type on a small annulus
PE_TEST_GROUP(holes_gmpq)
{
  (void)data_dir;
  typedef boost::graph_traits<Surface_mesh> GT;
  Surface_mesh m;
  make_annulus(m, 3, 8);
  auto uv = make_uv_map(m, Kq::Point_2());
  PE::Embedding_report r;
  CHECK(PE::internal::embed_with_holes(m, GT::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE), &r) == PE::OK,
        "Gmpq annulus embedded");
  RUN(check_valid(r, 2, "Gmpq annulus"));
  RUN(check_valid(PE::check_embedding(m, uv, PE::parameters::multiply_connected(true)), 2, "Gmpq re-certified"));
  // the certificate in Gmpq agrees with the double one on the planar map, and on an invalid one
  auto uvd = make_uv_map(m, P2());
  planar_uv<Epick>(m, uvd);
  auto uvq = make_uv_map(m, Kq::Point_2());
  planar_uv<Kq>(m, uvq);
  RUN(check_valid(PE::check_embedding(m, uvq, PE::parameters::multiply_connected(true)), 2, "planar, Gmpq"));
  auto v0 = *std::find_if(vertices(m).begin(), vertices(m).end(), [&](auto v) { return get(uvd, v) == P2(1, 0); });
  put(uvq, v0, Kq::Point_2(3, 0));
  put(uvd, v0, P2(3, 0));
  const PE::Embedding_report rq = PE::check_embedding(m, uvq, PE::parameters::multiply_connected(true));
  RUN(check_against_brute(rq, brute_counts(m, uvq, rq.clockwise ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN), "Gmpq: hole vertex through the outer border"));
  const PE::Embedding_report rd = PE::check_embedding(m, uvd, PE::parameters::multiply_connected(true));
  CHECK(rd.flipped == rq.flipped && rd.loop_crossings == rq.loop_crossings && rd.overlapping_pairs == rq.overlapping_pairs,
        "double and Gmpq agree");
  // a few optimization iterations in Gmpq: valid, outer border exact
  const auto before = snapshot(m, uv);
  const auto L = loop_vertices(m, PE::internal::longest_border_loop(m, get(CGAL::vertex_point, m)));
  PE::Optimization_statistics st;
  const PE::Error_code ec = PE::optimize_distortion(m, uv, PE::parameters::optimization_statistics(&st,
                                                    CGAL::parameters::number_of_iterations(3)));
  CHECK(ec == PE::OK || ec == PE::ERROR_BUDGET_EXHAUSTED, "Gmpq optimized");
  RUN(check_valid(st.report, 2, "Gmpq optimized"));
  bool exact = true;
  for(auto v : L) exact = exact && get(uv, v) == before.at(v);
  CHECK(exact, "Gmpq outer border exact");
  return EXIT_SUCCESS;
}

// inputs that are not genus 0 / not connected; errors leave the uv map unchanged
template <class Mesh>
int errors()
{
  typedef boost::graph_traits<Mesh> GT;
  std::cout << mesh_name<Mesh>() << std::endl;
  const auto holes = PE::parameters::multiply_connected(true);
  {
    // a torus with two holes: genus 1, 2 border cycles
    Mesh m;
    make_torus(m, 12, 8);
    std::vector<typename GT::vertex_descriptor> c;
    auto it = vertices(m).begin();
    c.push_back(*it);
    std::advance(it, 6 * 8 + 4);
    c.push_back(*it);
    cut_one_rings(m, c);
    CHECK(count_border_cycles(m) == 2, "torus with 2 holes");
    auto uv = make_uv_map(m, P2());
    for(auto v : vertices(m)) put(uv, v, P2(0.5, 0.25));
    const auto before = snapshot(m, uv);
    CHECK(PE::internal::embed_with_holes(m, GT::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE))
            == PE::ERROR_NOT_GENUS_ZERO && same_uv(m, uv, before), "torus: ERROR_NOT_GENUS_ZERO, uv unchanged");
    PE::internal::Filled_holes<Mesh> rec;
    const std::size_t nv = count_vertices(m);
    CHECK(PE::internal::fill_holes(m, GT::null_halfedge(), get(CGAL::vertex_point, m), rec) == PE::ERROR_NOT_GENUS_ZERO
          && count_vertices(m) == nv, "fill_holes: ERROR_NOT_GENUS_ZERO, mesh unchanged");
    const PE::Embedding_report r = PE::check_embedding(m, uv, holes);
    CHECK(r.status == PE::ERROR_NOT_GENUS_ZERO && !r.is_valid() && r.border_cycles == 2, "certificate: ERROR_NOT_GENUS_ZERO");
    CHECK(PE::optimize_distortion(m, uv) == PE::ERROR_NOT_GENUS_ZERO && same_uv(m, uv, before), "optimize: ERROR_NOT_GENUS_ZERO");
  }
  {
    // a torus with one hole: one border cycle, genus 1
    Mesh m;
    make_torus(m, 12, 8);
    cut_one_rings(m, std::vector<typename GT::vertex_descriptor>(1, *vertices(m).begin()));
    auto uv = make_uv_map(m, P2());
    CHECK(PE::internal::embed_with_holes(m, GT::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE))
            == PE::ERROR_NOT_GENUS_ZERO, "torus with one hole: ERROR_NOT_GENUS_ZERO");
    CHECK(PE::check_embedding(m, uv, holes).status == PE::ERROR_NOT_GENUS_ZERO, "certificate: ERROR_NOT_GENUS_ZERO");
    CHECK(PE::check_embedding(m, uv).status == PE::ERROR_NOT_A_DISK, "default certificate: ERROR_NOT_A_DISK as before");
  }
  {
    // closed sphere-like mesh; two annuli (two components)
    Mesh m;
    CGAL::make_icosahedron(m, P3(0, 0, 0), 1.0);
    auto uv = make_uv_map(m, P2());
    CHECK(PE::internal::embed_with_holes(m, GT::null_halfedge(), uv, CGAL::parameters::default_values()) == PE::ERROR_NOT_GENUS_ZERO,
          "closed: ERROR_NOT_GENUS_ZERO");
    CHECK(PE::check_embedding(m, uv, holes).status == PE::ERROR_NOT_GENUS_ZERO, "closed: certificate ERROR_NOT_GENUS_ZERO");
    CHECK(PE::check_embedding(m, uv).status == PE::ERROR_NOT_A_DISK, "closed: default certificate ERROR_NOT_A_DISK as before");
    Mesh two;
    make_annulus(two, 2, 6);
    Mesh other;
    make_annulus(other, 2, 6);
    CGAL::copy_face_graph(other, two);
    auto uv2 = make_uv_map(two, P2());
    CHECK(PE::internal::embed_with_holes(two, GT::null_halfedge(), uv2, PE::parameters::border_shape(PE::Border_shape::CIRCLE))
            == PE::ERROR_NOT_GENUS_ZERO, "two components: ERROR_NOT_GENUS_ZERO");
    const PE::Embedding_report r = PE::check_embedding(two, uv2, holes);
    CHECK(r.status == PE::ERROR_NOT_GENUS_ZERO && r.border_cycles == 4, "two components: certificate ERROR_NOT_GENUS_ZERO, 4 cycles");
  }
  {
    // the outer halfedge must be a border halfedge
    Mesh m;
    make_annulus(m, 3, 8);
    auto uv = make_uv_map(m, P2());
    typename GT::halfedge_descriptor interior = GT::null_halfedge();
    for(auto h : halfedges(m)) if(!is_border(h, m) && !is_border(opposite(h, m), m)) { interior = h; break; }
    CHECK(PE::internal::embed_with_holes(m, interior, uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE)) == PE::ERROR_WRONG_PARAMETER,
          "interior halfedge as outer: ERROR_WRONG_PARAMETER");
    PE::internal::Filled_holes<Mesh> rec;
    CHECK(PE::internal::fill_holes(m, interior, get(CGAL::vertex_point, m), rec) == PE::ERROR_WRONG_PARAMETER, "fill_holes: ERROR_WRONG_PARAMETER");
  }
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(holes_errors)
{
  (void)data_dir;
  RUN(errors<Surface_mesh>());
  RUN(errors<Polyhedron>());
  return EXIT_SUCCESS;
}

} // namespace
