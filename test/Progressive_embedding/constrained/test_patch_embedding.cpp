// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Tests of embed_patch(): a range of faces of a mesh (a topological disk) mapped into the convex
// polygon its border vertices already have, with collinear vertices along the sides; flat chords
// (find_flat_chords); refused patches and borders; the disk functions on weakly convex borders;
// crowded patches of constrained maps (data/patch_*.off) through the simple-border variant.
// Every certified map is also checked independently: exact orientation of every patch face (in
// rationals) and check_embedding() on a copy of the patch; the border and every vertex outside
// the patch are compared bit by bit.

#include <CGAL/Progressive_embedding/embed_patch.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/internal/patch_chords.h>

#include "registry.h"
#include "../test_util.h"
#include <CGAL/Progressive_embedding/internal/disk_generators.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {

template <class Mesh> using vd_t = typename boost::graph_traits<Mesh>::vertex_descriptor;
template <class Mesh> using hd_t = typename boost::graph_traits<Mesh>::halfedge_descriptor;
template <class Mesh> using fd_t = typename boost::graph_traits<Mesh>::face_descriptor;
template <class Mesh> using ed_t = typename boost::graph_traits<Mesh>::edge_descriptor;

// The faces of the stars of the vertices at edge distance < rings from `seed`.
template <class Mesh>
std::vector<fd_t<Mesh> > ring_patch(const Mesh& m, vd_t<Mesh> seed, int rings)
{
  std::map<vd_t<Mesh>, int> dist;
  std::vector<vd_t<Mesh> > layer(1, seed);
  dist[seed] = 0;
  for(int r = 1; r < rings; ++r)
  {
    std::vector<vd_t<Mesh> > next;
    for(auto v : layer)
      for(auto w : CGAL::vertices_around_target(v, m))
        if(dist.emplace(w, r).second) next.push_back(w);
    layer.swap(next);
  }
  std::set<fd_t<Mesh> > F;
  for(const auto& d : dist)
    for(auto f : CGAL::faces_around_target(halfedge(d.first, m), m))
      if(f != boost::graph_traits<Mesh>::null_face()) F.insert(f);
  return std::vector<fd_t<Mesh> >(F.begin(), F.end());
}

// The border cycle of a disk patch (the patch on the left), computed here independently of the
// package: each border vertex has one outgoing border halfedge of the patch.
template <class Mesh>
std::vector<vd_t<Mesh> > patch_border(const Mesh& m, const std::vector<fd_t<Mesh> >& P)
{
  const std::set<fd_t<Mesh> > in(P.begin(), P.end());
  std::map<vd_t<Mesh>, hd_t<Mesh> > out;
  for(auto f : P)
    for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m))
    {
      const auto o = opposite(h, m);
      if(is_border(o, m) || !in.count(face(o, m))) out[source(h, m)] = h;
    }
  std::vector<vd_t<Mesh> > B;
  if(out.empty()) return B;
  const vd_t<Mesh> first = out.begin()->first;
  vd_t<Mesh> v = first;
  do { B.push_back(v); v = target(out[v], m); } while(v != first && B.size() <= out.size());
  return B;
}

template <class Mesh>
std::set<vd_t<Mesh> > patch_vertices(const Mesh& m, const std::vector<fd_t<Mesh> >& P)
{
  std::set<vd_t<Mesh> > V;
  for(auto f : P) for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) V.insert(v);
  return V;
}

// The border cycle B on the square [0,1]^2 counterclockwise (clockwise if `cw`), corners at
// B[o], B[o + n/4], B[o + n/2], B[o + 3n/4]; the other vertices evenly spaced along the sides (one
// coordinate of each side is constant, so they are exactly collinear).
template <class K, class UVM, class VD>
void place_on_square(UVM& uv, const std::vector<VD>& B, std::size_t o, bool cw)
{
  const std::size_t n = B.size();
  const double cx[4] = { 0, 1, 1, 0 }, cy[4] = { 0, 0, 1, 1 };
  const std::size_t c[5] = { 0, n / 4, n / 2, 3 * n / 4, n };
  for(int s = 0; s < 4; ++s)
    for(std::size_t j = c[s]; j < c[s + 1]; ++j)
    {
      const double t = double(j - c[s]) / double(c[s + 1] - c[s]);
      const double x = cx[s] + (cx[(s + 1) % 4] - cx[s]) * t, y = cy[s] + (cy[(s + 1) % 4] - cy[s]) * t;
      put(uv, B[(o + j) % n], point<K>(x, cw ? -y : y));
    }
}

template <class P>
bool same_point(const P& p, const P& q)
{
  if constexpr(std::is_same<typename CGAL::Kernel_traits<P>::Kernel::FT, double>::value)
    return same_bits(p.x(), q.x()) && same_bits(p.y(), q.y());
  else
    return p.x() == q.x() && p.y() == q.y();
}

// a value that embed_patch must neither read nor write
template <class K>
typename K::Point_2 sentinel(std::size_t i)
{
  if constexpr(std::is_same<typename K::FT, double>::value)
    return typename K::Point_2(std::numeric_limits<double>::quiet_NaN(), double(i));
  else
    return point<K>(1e9 + double(i), -7);
}

// Snapshot of the uv map over every vertex of the mesh.
template <class Mesh, class UVM>
std::map<vd_t<Mesh>, typename boost::property_traits<UVM>::value_type> uv_snapshot(const Mesh& m, const UVM& uv)
{
  std::map<vd_t<Mesh>, typename boost::property_traits<UVM>::value_type> s;
  for(auto v : vertices(m)) s.emplace(v, get(uv, v));
  return s;
}

template <class Mesh, class UVM, class Snap>
std::size_t changed_vertices(const Mesh& m, const UVM& uv, const Snap& before)
{
  std::size_t n = 0;
  for(auto v : vertices(m)) if(!same_point(get(uv, v), before.at(v))) ++n;
  return n;
}

// Independent certificate of the patch's map: every patch face of orientation `expected`
// (CGAL::orientation on exact rationals) and, for a Surface_mesh, check_embedding() valid on a copy
// of the patch with its uv.
template <class Mesh, class UVM>
int check_patch_map(const Mesh& m, const std::vector<fd_t<Mesh> >& P, const UVM& uv, CGAL::Orientation expected,
                    const std::string& what)
{
  std::size_t wrong = 0;
  for(auto f : P)
  {
    std::vector<Kq::Point_2> p;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m))
      p.push_back(Kq::Point_2(exact_rational(get(uv, v).x()), exact_rational(get(uv, v).y())));
    if(CGAL::orientation(p[0], p[1], p[2]) != expected) ++wrong;
  }
  CHECK(wrong == 0, what << ": " << wrong << " patch face(s) not of the border's orientation");
  if constexpr(std::is_same<Mesh, Surface_mesh>::value)
  {
    typedef typename boost::property_traits<UVM>::value_type P2;
    Surface_mesh copy;
    auto cuv = copy.add_property_map<Surface_mesh::Vertex_index, P2>("v:uv").first;
    std::map<vd_t<Mesh>, Surface_mesh::Vertex_index> id;
    for(auto v : patch_vertices(m, P)) { id[v] = copy.add_vertex(m.point(v)); put(cuv, id[v], get(uv, v)); }
    for(auto f : P)
    {
      std::vector<Surface_mesh::Vertex_index> t;
      for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) t.push_back(id[v]);
      CHECK(copy.add_face(t) != Surface_mesh::null_face(), what << ": copy of the patch");
    }
    const PE::Embedding_report r = PE::check_embedding(copy, cuv);
    std::cout << "  " << what << ": check_embedding on the patch's copy: " << r.summary() << std::endl;
    CHECK(r.is_valid() && r.clockwise == (expected == CGAL::RIGHT_TURN), what << ": valid copy");
  }
  return EXIT_SUCCESS;
}

// Embeds the patch P whose border B has its uv already, with every other vertex at a sentinel,
// and checks: OK, certified independently, border and outside vertices bit-exact.
template <class K, class Mesh, class UVM>
int embed_and_check(const Mesh& m, const std::vector<fd_t<Mesh> >& P, UVM& uv, bool cw, const std::string& what,
                    PE::Progressive_embedding_statistics* st_out = nullptr)
{
  const std::set<vd_t<Mesh> > V = patch_vertices(m, P);
  const std::vector<vd_t<Mesh> > B = patch_border(m, P);
  const std::set<vd_t<Mesh> > Bs(B.begin(), B.end());
  std::size_t i = 0;
  for(auto v : vertices(m))
  {
    ++i;
    if(!V.count(v)) put(uv, v, sentinel<K>(i));
    else if(!Bs.count(v)) put(uv, v, point<K>(7, -3)); // interior: overwritten
  }
  const auto before = uv_snapshot(m, uv);
  PE::Progressive_embedding_statistics st;
  CGAL::Real_timer t;
  t.start();
  const PE::Error_code ec = PE::embed_patch(m, P, uv, PE::parameters::statistics(&st));
  std::cout << "  " << what << " (" << P.size() << " faces, " << V.size() << " vertices, " << B.size()
            << " on the border): " << PE::get_error_name(ec) << " in " << t.time() << " s; repair: "
            << st.collapses << " collapses; " << st.report.summary() << std::endl;
  CHECK(ec == PE::OK, what << ": embed_patch");
  CHECK(st.report.is_valid() && st.report.faces == P.size() && st.report.vertices == V.size()
        && st.report.border_vertices == B.size() && st.report.clockwise == cw, what << ": the statistics' certificate");
  std::size_t outside = 0, border = 0, interior = 0;
  for(auto v : vertices(m))
  {
    const bool same = same_point(get(uv, v), before.at(v));
    if(!V.count(v)) outside += !same;
    else if(Bs.count(v)) border += !same;
    else interior += same;
  }
  CHECK(outside == 0, what << ": " << outside << " vertices outside the patch changed");
  CHECK(border == 0, what << ": " << border << " border vertices changed");
  CHECK(interior == 0, what << ": " << interior << " interior vertices not written");
  RUN(check_patch_map(m, P, uv, cw ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN, what));
  if(st_out) *st_out = st;
  return EXIT_SUCCESS;
}

// the first corner offset whose square placement has no flat chord
template <class K, class Mesh, class UVM>
std::size_t chord_free_offset(const Mesh& m, const std::vector<fd_t<Mesh> >& P, UVM& uv, const std::vector<vd_t<Mesh> >& B)
{
  for(std::size_t o = 0; o < B.size(); ++o)
  {
    place_on_square<K>(uv, B, o, false);
    std::vector<ed_t<Mesh> > chords;
    if(PE::internal::find_flat_chords(m, P, uv, std::back_inserter(chords)) == PE::OK && chords.empty()) return o;
  }
  return B.size();
}

// A real patch: 5 rings around a vertex of elephant.off, border on a square (about a quarter of
// the border vertices on each side), counterclockwise and clockwise.
template <class Mesh>
int real_ring_patch(const std::string& data)
{
  std::cout << "[" << mesh_name<Mesh>() << "] a ring patch of elephant.off on a square" << std::endl;
  Mesh m;
  CHECK(read_mesh(data + "/meshes/elephant.off", m), "read elephant.off");
  std::vector<vd_t<Mesh> > all(vertices(m).begin(), vertices(m).end());
  const std::vector<fd_t<Mesh> > P = ring_patch(m, all[100], 5);
  const std::vector<vd_t<Mesh> > B = patch_border(m, P);
  auto uv = make_uv_map(m, Epick::Point_2());
  const std::size_t o = chord_free_offset<Epick>(m, P, uv, B);
  CHECK(o < B.size(), "a square placement without flat chord");
  CHECK(B.size() >= 16, "several collinear vertices per side");
  for(bool cw : { false, true })
  {
    place_on_square<Epick>(uv, B, o, cw);
    RUN(embed_and_check<Epick>(m, P, uv, cw, cw ? "ring patch, clockwise square" : "ring patch, square"));
  }
  // mean value weights
  place_on_square<Epick>(uv, B, o, false);
  const auto before = uv_snapshot(m, uv);
  CHECK(PE::embed_patch(m, P, uv, PE::parameters::weights(PE::Weights::MEAN_VALUE)) == PE::OK, "mean value weights");
  RUN(check_patch_map(m, P, uv, CGAL::LEFT_TURN, "ring patch, mean value weights"));
  for(auto v : vertices(m))
    if(!patch_vertices(m, P).count(v) || CGAL::is_border(v, m)) CHECK(same_point(get(uv, v), before.at(v)), "outside untouched");
  return EXIT_SUCCESS;
}

// A whole real disk (mushroom.off): the patch border is the mesh border; then a sub-patch whose
// border runs partly along the mesh border and partly inside.
template <class Mesh>
int real_disk_patch(const std::string& data)
{
  std::cout << "[" << mesh_name<Mesh>() << "] mushroom.off on a square" << std::endl;
  Mesh m;
  CHECK(read_mesh(data + "/meshes/mushroom.off", m), "read mushroom.off");
  const std::vector<fd_t<Mesh> > P(faces(m).begin(), faces(m).end());
  const std::vector<vd_t<Mesh> > B = patch_border(m, P);
  auto uv = make_uv_map(m, Epick::Point_2());
  const std::size_t o = chord_free_offset<Epick>(m, P, uv, B);
  CHECK(o < B.size(), "a square placement without flat chord");
  place_on_square<Epick>(uv, B, o, false);
  RUN(embed_and_check<Epick>(m, P, uv, false, "mushroom.off, whole disk"));

  // rings around a border vertex: the patch border is partly the mesh border
  vd_t<Mesh> seed = B[B.size() / 3];
  const std::vector<fd_t<Mesh> > Q = ring_patch(m, seed, 4);
  const std::vector<vd_t<Mesh> > BQ = patch_border(m, Q);
  std::size_t on_mesh_border = 0;
  for(auto v : BQ) on_mesh_border += CGAL::is_border(v, m) ? 1 : 0;
  CHECK(on_mesh_border > 2 && on_mesh_border < BQ.size(), "the patch border is partly the mesh border");
  const std::size_t oq = chord_free_offset<Epick>(m, Q, uv, BQ);
  CHECK(oq < BQ.size(), "a square placement without flat chord");
  place_on_square<Epick>(uv, BQ, oq, false);
  RUN(embed_and_check<Epick>(m, Q, uv, false, "mushroom.off, rings at a border vertex"));
  return EXIT_SUCCESS;
}

// The deep stacked triangulation (double Tutte flips faces) with one more face outside the
// patch across edge (a, b), so that the patch border runs along an interior edge of the mesh;
// the corners pinned clockwise (the Tutte-failure protocol); then the outer edges split into
// collinear border vertices.
template <class Mesh>
int repaired_patch()
{
  std::cout << "[" << mesh_name<Mesh>() << "] a deep stacked patch whose double Tutte map is invalid" << std::endl;
  for(int split : { 0, 1 })
  {
    Mesh m;
    const auto c = PE::internal::make_stacked_triangulation(80, m);
    std::vector<fd_t<Mesh> > P(faces(m).begin(), faces(m).end());
    auto vpm = get(CGAL::vertex_point, m);
    // an extra vertex below edge (a, b), outside the patch
    const vd_t<Mesh> d = add_vertex(m);
    put(vpm, d, Epick::Point_3(0.5, -0.5, 0));
    CHECK(CGAL::Euler::add_face(std::vector<vd_t<Mesh> >{ c[1], c[0], d }, m) != boost::graph_traits<Mesh>::null_face(), "outer face");
    auto uv = make_uv_map(m, Epick::Point_2());
    pin_corners<Epick>(uv, c);
    if(split)
    {
      // a clockwise right triangle: the points at k/4 of its sides are exactly on them
      put(uv, c[0], Epick::Point_2(0, 0)); put(uv, c[1], Epick::Point_2(0, 1)); put(uv, c[2], Epick::Point_2(1, 0));
    }
    if(split)
    {
      // split every outer edge of the patch 3 times; the new vertices on the straight sides
      for(int s = 0; s < 3; ++s)
      {
        const vd_t<Mesh> a = c[s], b = c[(s + 1) % 3];
        const Epick::Point_2 pa = get(uv, a), pb = get(uv, b);
        const Epick::Point_3 qa = get(vpm, a), qb = get(vpm, b);
        hd_t<Mesh> h = halfedge(a, b, m).first; // a -> b, in a patch face
        if(!CGAL::is_border(h, m) && std::find(P.begin(), P.end(), face(h, m)) == P.end()) h = opposite(h, m);
        for(int k = 1; k <= 3; ++k)
        {
          // split a -> b at its first quarter, then go on with the remaining piece
          const hd_t<Mesh> hn = CGAL::Euler::split_edge(h, m); // hn: source(h) -> new vertex
          const vd_t<Mesh> w = target(hn, m);
          const double t = double(k) / 4;
          put(uv, w, Epick::Point_2(pa.x() + (pb.x() - pa.x()) * t, pa.y() + (pb.y() - pa.y()) * t));
          put(vpm, w, qa + (qb - qa) * t);
          // triangulate the quads on both sides (the patch face, and the outer face if any)
          for(hd_t<Mesh> g : { hn, opposite(h, m) })
          {
            if(CGAL::is_border(g, m)) continue;
            const fd_t<Mesh> f = face(g, m);
            const bool in_patch = std::find(P.begin(), P.end(), f) != P.end();
            const hd_t<Mesh> e = CGAL::Euler::split_face(g, next(next(g, m), m), m);
            const fd_t<Mesh> f2 = face(opposite(e, m), m) == f ? face(e, m) : face(opposite(e, m), m);
            if(in_patch) P.push_back(f2);
          }
        }
      }
    }
    const char* what = split ? "stacked depth 80, sides split" : "stacked depth 80";
    {
      // no time: refused, the map unchanged
      const auto before = uv_snapshot(m, uv);
      const PE::Error_code ec = PE::embed_patch(m, P, uv, CGAL::parameters::maximum_running_time(0.).verbose(true));
      std::cout << "  " << what << ", no time: " << PE::get_error_name(ec) << std::endl;
      CHECK(ec == PE::ERROR_BUDGET_EXHAUSTED, what << ": no time");
      CHECK(changed_vertices(m, uv, before) == 0, what << ": no time, the map is unchanged");
    }
    // the double Tutte map of the patch is invalid: the repair must run
    PE::Progressive_embedding_statistics st;
    RUN(embed_and_check<Epick>(m, P, uv, true, what, &st));
    CHECK(st.collapses > 0 && st.invalid_faces_before > 0, what << ": the Tutte map was repaired");
    // the same in exact arithmetic: Tutte's map is valid, nothing to repair
    auto uvq = make_uv_map(m, Kq::Point_2());
    for(auto v : vertices(m))
      if(std::isfinite(get(uv, v).x()) && std::isfinite(get(uv, v).y()))
        put(uvq, v, Kq::Point_2(exact_rational(get(uv, v).x()), exact_rational(get(uv, v).y())));
    if(!split)
    {
      PE::Progressive_embedding_statistics stq;
      RUN(embed_and_check<Kq>(m, P, uvq, true, std::string(what) + ", Gmpq", &stq));
      CHECK(stq.collapses == 0 && stq.invalid_faces_before == 0, "the exact Tutte map is valid");
    }
  }
  return EXIT_SUCCESS;
}

// Two patches of constrained maps of dino.off (test/Progressive_embedding/data), with the
// exact uv of their border vertices: path vertices placed on straight sides in double, so the
// polygons are convex up to rounding only (embed_patch() refuses them; the constrained
// pipeline embeds them with internal::embed_patch_impl(..., simple_border = true)).
//  - patch_small_far.off: 3.5e-9 across, 0.38 from the origin; Tutte's map solved where the
//    patch is loses the 8 digits between the two and flips 71 faces, which the repair cannot
//    place on the grid of doubles there;
//  - patch_border_cluster.off: 2.6 across, with runs of border vertices less than 1e-6 apart
//    (edges down to 8e-13): faces on those edges can meet neither the repair's energy
//    threshold nor its area floor, both relative to the mean face, wherever they are placed;
//  - patch_needle.off: a triangle 270 x 3200 ulps wide holding 132 interior vertices: valid faces of
//    a few ulps^2 are left in clusters whose Newton steps round to no move (the smoothing then steps
//    to a neighbouring double) and that only the higher area floors (1e-3 to 0.1 of the mean) collapse.
template <class Mesh>
int crowded_patches()
{
  std::cout << "[" << mesh_name<Mesh>() << "] crowded patches of constrained maps" << std::endl;
  const std::string data = (std::filesystem::path(__FILE__).parent_path().parent_path() / "data").string();
  for(const char* name : { "patch_small_far.off", "patch_border_cluster.off", "patch_needle.off" })
  {
    Mesh m;
    CHECK(read_mesh(data + "/" + name, m), name << ": read");
    std::vector<fd_t<Mesh> > P(faces(m).begin(), faces(m).end());
    auto uv = make_uv_map(m, Epick::Point_2());
    auto vpm = get(CGAL::vertex_point, m);
    for(auto v : vertices(m)) put(uv, v, Epick::Point_2(get(vpm, v).x(), get(vpm, v).y()));
    CHECK(PE::embed_patch(m, P, uv) == PE::ERROR_NON_CONVEX_BORDER, name << ": convex up to rounding only");
    const auto before = uv_snapshot(m, uv);
    PE::Progressive_embedding_statistics st;
    const PE::Error_code ec = PE::internal::embed_patch_impl(m, P, uv, PE::parameters::statistics(&st), true);
    std::cout << "  " << name << " (" << P.size() << " faces): " << PE::get_error_name(ec) << "; repair: "
              << st.invalid_faces_before << " invalid faces, " << st.collapses << " collapses; " << st.report.summary() << std::endl;
    CHECK(ec == PE::OK, name << ": embed_patch_impl with a simple border");
    CHECK(st.report.is_valid() && st.report.flipped == 0 && st.report.degenerate == 0 && st.report.faces == P.size(),
          name << ": the statistics' certificate");
    std::size_t border = 0;
    for(auto v : vertices(m)) if(CGAL::is_border(v, m) && !same_point(get(uv, v), before.at(v))) ++border;
    CHECK(border == 0, name << ": " << border << " border vertices changed");
    RUN(check_patch_map(m, P, uv, CGAL::LEFT_TURN, name));
  }
  return EXIT_SUCCESS;
}

// A small disk with a flat chord: a pentagon p0 p1 p2 p3 p4 with p0, p1, p2 on its bottom side and
// an interior vertex q; the edge p0-p2 is interior. `with_face`: the face (p0, p1, p2) is flat;
// otherwise a vertex r between the chord and the side (its three neighbours on the side).
template <class Mesh>
void make_chord_disk(Mesh& m, bool with_face, std::vector<vd_t<Mesh> >& V)
{
  auto vpm = get(CGAL::vertex_point, m);
  const double xy[6][2] = { { 0, 0 }, { 1, 0 }, { 2, 0 }, { 2, 2 }, { 0, 2 }, { 1, 1 } };
  V.clear();
  for(int i = 0; i < 6; ++i) { V.push_back(add_vertex(m)); put(vpm, V.back(), Epick::Point_3(xy[i][0], xy[i][1], 0)); }
  auto F = [&](int a, int b, int c) { CGAL::Euler::add_face(std::vector<vd_t<Mesh> >{ V[a], V[b], V[c] }, m); };
  F(0, 2, 5); F(2, 3, 5); F(3, 4, 5); F(4, 0, 5);
  if(with_face) F(0, 1, 2);
  else
  {
    V.push_back(add_vertex(m)); put(vpm, V.back(), Epick::Point_3(1, 0.2, 0));
    F(0, 1, 6); F(1, 2, 6); F(2, 0, 6);
  }
}

template <class Mesh>
int flat_chords()
{
  std::cout << "[" << mesh_name<Mesh>() << "] flat chords" << std::endl;
  for(bool with_face : { true, false })
  {
    Mesh m;
    std::vector<vd_t<Mesh> > V;
    make_chord_disk(m, with_face, V);
    auto uv = make_uv_map(m, Epick::Point_2());
    auto vpm = get(CGAL::vertex_point, m);
    for(auto v : vertices(m)) put(uv, v, Epick::Point_2(get(vpm, v).x(), get(vpm, v).y()));
    put(uv, V[5], Epick::Point_2(0.5, 0.25)); // interior: any value, must stay
    if(!with_face) put(uv, V[6], Epick::Point_2(3, 3));
    const std::vector<fd_t<Mesh> > P(faces(m).begin(), faces(m).end());
    const auto before = uv_snapshot(m, uv);
    const char* what = with_face ? "flat face" : "flat chord over an interior vertex";
    const PE::Error_code ec = PE::embed_patch(m, P, uv);
    std::cout << "  " << what << ": embed_patch " << PE::get_error_name(ec) << std::endl;
    CHECK(ec == PE::ERROR_DEGENERATE_CHORD, what);
    CHECK(changed_vertices(m, uv, before) == 0, what << ": the map is unchanged");
    std::vector<ed_t<Mesh> > chords;
    CHECK(PE::internal::find_flat_chords(m, P, uv, std::back_inserter(chords)) == PE::OK, "find_flat_chords");
    CHECK(chords.size() == 1, what << ": one chord, not " << chords.size());
    const vd_t<Mesh> s = source(halfedge(chords[0], m), m), t = target(halfedge(chords[0], m), m);
    CHECK((s == V[0] && t == V[2]) || (s == V[2] && t == V[0]), what << ": the chord is p0-p2");
    // the disk functions refuse it the same way on the fixed border
    CHECK(PE::tutte_embedding(m, boost::graph_traits<Mesh>::null_halfedge(), uv) == PE::ERROR_DEGENERATE_CHORD,
          what << ": tutte_embedding");
    CHECK(PE::progressive_embedding(m, uv) == PE::ERROR_DEGENERATE_CHORD, what << ": progressive_embedding");
    CHECK(changed_vertices(m, uv, before) == 0, what << ": the map is unchanged by the disk functions");

    // split the chord as the constrained pipeline does: then the patch is accepted
    const hd_t<Mesh> h = halfedge(chords[0], m);
    const hd_t<Mesh> hn = CGAL::Euler::split_edge(h, m);
    const vd_t<Mesh> w = target(hn, m);
    put(vpm, w, Epick::Point_3(1, 0.1, 0));
    for(hd_t<Mesh> g : { hn, opposite(h, m) })
      CGAL::Euler::split_face(g, next(next(g, m), m), m);
    put(uv, w, Epick::Point_2(5, 5));
    const std::vector<fd_t<Mesh> > P2(faces(m).begin(), faces(m).end());
    chords.clear();
    CHECK(PE::internal::find_flat_chords(m, P2, uv, std::back_inserter(chords)) == PE::OK && chords.empty(),
          what << ": no chord after the split");
    RUN(embed_and_check<Epick>(m, P2, uv, false, std::string(what) + ", chord split"));
  }
  // a strictly convex border never has a flat chord: the same disk with p1 moved below the side
  {
    Mesh m;
    std::vector<vd_t<Mesh> > V;
    make_chord_disk(m, true, V);
    auto uv = make_uv_map(m, Epick::Point_2());
    auto vpm = get(CGAL::vertex_point, m);
    for(auto v : vertices(m)) put(uv, v, Epick::Point_2(get(vpm, v).x(), get(vpm, v).y()));
    put(uv, V[1], Epick::Point_2(1, -0.5));
    const std::vector<fd_t<Mesh> > P(faces(m).begin(), faces(m).end());
    std::vector<ed_t<Mesh> > chords;
    CHECK(PE::internal::find_flat_chords(m, P, uv, std::back_inserter(chords)) == PE::OK && chords.empty(), "strictly convex: no chord");
    RUN(embed_and_check<Epick>(m, P, uv, false, "strictly convex pentagon"));
  }
  return EXIT_SUCCESS;
}

// Refused patches and borders: a specific error, the uv map unchanged bit for bit.
template <class Mesh>
int refused(const std::string& data)
{
  std::cout << "[" << mesh_name<Mesh>() << "] refused patches and borders" << std::endl;
  Mesh m;
  CHECK(read_mesh(data + "/meshes/elephant.off", m), "read elephant.off");
  std::vector<vd_t<Mesh> > all(vertices(m).begin(), vertices(m).end());
  const std::vector<fd_t<Mesh> > P = ring_patch(m, all[100], 4);
  const std::vector<vd_t<Mesh> > B = patch_border(m, P);
  auto uv = make_uv_map(m, Epick::Point_2());
  const std::size_t o = chord_free_offset<Epick>(m, P, uv, B);
  CHECK(o < B.size(), "a square placement without flat chord");
  std::size_t i = 0;
  for(auto v : vertices(m)) put(uv, v, Epick::Point_2(double(i++), -1.5));
  place_on_square<Epick>(uv, B, o, false);
  // the indexing with the mesh's slots (the constrained pipeline's) gives the same verdict and the
  // same disk as with hash maps, and leaves every slot cleared
  PE::internal::Patch_slots<Mesh> slots(m);
  auto expect = [&](const std::vector<fd_t<Mesh> >& Q, PE::Error_code expected, const char* what) -> int {
    PE::internal::Indexed_disk<Mesh> dh, ds;
    const PE::Error_code eh = PE::internal::make_indexed_patch(m, Q, dh);
    const PE::Error_code es = PE::internal::make_indexed_patch(m, Q, ds, &slots);
    CHECK(eh == es, what << ": indexing with slots: " << PE::get_error_name(es) << ", with hash maps: " << PE::get_error_name(eh));
    CHECK(eh != PE::OK || (dh.vertices == ds.vertices && dh.faces == ds.faces && dh.border == ds.border),
          what << ": the same indexed patch with slots");
    std::size_t dirty = 0;
    for(auto f : faces(m)) dirty += get(slots.face, f) != 0;
    for(auto v : vertices(m)) dirty += get(slots.vertex, v) != 0;
    CHECK(dirty == 0, what << ": " << dirty << " slots left set");
    const auto before = uv_snapshot(m, uv);
    const PE::Error_code ec = PE::embed_patch(m, Q, uv);
    std::cout << "  " << what << ": " << PE::get_error_name(ec) << std::endl;
    CHECK(ec == expected, what << ": expected " << PE::get_error_name(expected) << ", got " << PE::get_error_name(ec));
    CHECK(changed_vertices(m, uv, before) == 0, what << ": the uv map is unchanged");
    return EXIT_SUCCESS;
  };
  // not a disk
  RUN(expect(std::vector<fd_t<Mesh> >(), PE::ERROR_EMPTY_MESH, "no face"));
  {
    std::vector<fd_t<Mesh> > Q = P;
    Q.push_back(P[3]);
    RUN(expect(Q, PE::ERROR_WRONG_PARAMETER, "a face given twice"));
  }
  {
    const std::vector<fd_t<Mesh> > Q(faces(m).begin(), faces(m).end());
    RUN(expect(Q, PE::ERROR_NOT_A_DISK, "the whole closed mesh"));
  }
  {
    // two faces far apart: not connected
    const std::vector<fd_t<Mesh> > all_f(faces(m).begin(), faces(m).end());
    RUN(expect(std::vector<fd_t<Mesh> >{ all_f[0], all_f[all_f.size() / 2] }, PE::ERROR_NOT_A_DISK, "two faces apart"));
  }
  {
    // an annulus: the ring patch without the star of its center
    std::vector<fd_t<Mesh> > Q;
    std::set<fd_t<Mesh> > star;
    for(auto f : CGAL::faces_around_target(halfedge(all[100], m), m)) star.insert(f);
    for(auto f : P) if(!star.count(f)) Q.push_back(f);
    RUN(expect(Q, PE::ERROR_NOT_A_DISK, "an annulus"));
  }
  {
    // two faces sharing only a vertex: pinched
    const vd_t<Mesh> v = all[100];
    std::vector<fd_t<Mesh> > star;
    for(auto f : CGAL::faces_around_target(halfedge(v, m), m)) star.push_back(f);
    CHECK(star.size() >= 5, "degree of the seed");
    RUN(expect(std::vector<fd_t<Mesh> >{ star[0], star[2] }, PE::ERROR_NOT_A_DISK, "two faces pinched at a vertex"));
    // the ring patch minus two faces of the star: the center vertex is pinched
    std::vector<fd_t<Mesh> > Q;
    for(auto f : P) if(f != star[1] && f != star[3]) Q.push_back(f);
    RUN(expect(Q, PE::ERROR_NOT_A_DISK, "a patch pinched at its center"));
  }
  // borders
  const Epick::Point_2 b0 = get(uv, B[(o + 1) % B.size()]);
  put(uv, B[(o + 1) % B.size()], Epick::Point_2(b0.x(), 0.25));
  RUN(expect(P, PE::ERROR_NON_CONVEX_BORDER, "a border vertex moved inside"));
  put(uv, B[(o + 1) % B.size()], Epick::Point_2(-0.125, 0));
  RUN(expect(P, PE::ERROR_NON_CONVEX_BORDER, "a side vertex beyond the corner"));
  CHECK(B.size() / 4 >= 3, "three vertices on the first side");
  put(uv, B[(o + 1) % B.size()], Epick::Point_2(0.75, 0));
  RUN(expect(P, PE::ERROR_NON_CONVEX_BORDER, "a spike: the side goes to 0.75 and back"));
  put(uv, B[(o + 1) % B.size()], get(uv, B[o]));
  RUN(expect(P, PE::ERROR_DEGENERATE_BORDER, "a repeated point"));
  put(uv, B[(o + 1) % B.size()], Epick::Point_2(std::numeric_limits<double>::quiet_NaN(), 0));
  RUN(expect(P, PE::ERROR_NON_FINITE_COORDINATES, "NaN on the border"));
  put(uv, B[(o + 1) % B.size()], b0);
  {
    // the border going twice around the square
    std::vector<vd_t<Mesh> > BB;
    for(std::size_t k = 0; k < B.size(); ++k) BB.push_back(B[(o + k) % B.size()]);
    const std::size_t n = BB.size(), hlf = n / 2;
    std::vector<vd_t<Mesh> > first(BB.begin(), BB.begin() + hlf), second(BB.begin() + hlf, BB.end());
    place_on_square<Epick>(uv, first, 0, false);
    place_on_square<Epick>(uv, second, 0, false);
    RUN(expect(P, PE::ERROR_NON_CONVEX_BORDER, "a border winding twice"));
    place_on_square<Epick>(uv, B, o, false);
  }
  // parameters
  {
    const auto before = uv_snapshot(m, uv);
    CHECK(PE::embed_patch(m, P, uv, CGAL::parameters::maximum_running_time(-1.)) == PE::ERROR_WRONG_PARAMETER, "negative time");
    CHECK(PE::embed_patch(m, P, uv, PE::parameters::line_search_factor(2.)) == PE::ERROR_WRONG_PARAMETER, "line search factor");
    CHECK(changed_vertices(m, uv, before) == 0, "wrong parameters: the uv map is unchanged");
  }
  // and the accepted one, for contrast
  RUN(embed_and_check<Epick>(m, P, uv, false, "the same patch and border, untouched"));
  return EXIT_SUCCESS;
}

// Simple_cartesian<Gmpq>: a 3-ring patch of pig.off on a square; exact Tutte is valid.
template <class Mesh>
int gmpq_patch(const std::string& data)
{
  std::cout << "[" << mesh_name<Mesh>() << "] Gmpq patch" << std::endl;
  Mesh m;
  CHECK(read_mesh(data + "/meshes/pig.off", m), "read pig.off");
  std::vector<vd_t<Mesh> > all(vertices(m).begin(), vertices(m).end());
  // the first seed from vertex 50 on whose 3-ring patch a square placement has no flat chord
  auto uv = make_uv_map(m, Kq::Point_2());
  std::vector<fd_t<Mesh> > P;
  std::vector<vd_t<Mesh> > B;
  std::size_t o = 0, seed = 50;
  for(; seed < all.size(); ++seed)
  {
    P = ring_patch(m, all[seed], 3);
    B = patch_border(m, P);
    o = chord_free_offset<Kq>(m, P, uv, B);
    if(o < B.size()) break;
  }
  std::cout << "  seed vertex " << seed << std::endl;
  CHECK(seed < all.size() && o < B.size(), "a square placement without flat chord");
  place_on_square<Kq>(uv, B, o, false);
  PE::Progressive_embedding_statistics st;
  RUN(embed_and_check<Kq>(m, P, uv, false, "pig.off 3 rings, Gmpq", &st));
  CHECK(st.collapses == 0 && st.invalid_faces_before == 0, "exact Tutte needs no repair");
  return EXIT_SUCCESS;
}

// The disk functions on a weakly convex fixed border: mushroom.off on a square with collinear
// vertices (a placement without flat chord), Tutte then progressive embedding, certified.
template <class Mesh>
int disk_functions(const std::string& data)
{
  std::cout << "[" << mesh_name<Mesh>() << "] tutte_embedding and progressive_embedding on a weakly convex fixed border" << std::endl;
  Mesh m;
  CHECK(read_mesh(data + "/meshes/mushroom.off", m), "read mushroom.off");
  const std::vector<fd_t<Mesh> > P(faces(m).begin(), faces(m).end());
  const std::vector<vd_t<Mesh> > B = patch_border(m, P);
  auto uv = make_uv_map(m, Epick::Point_2());
  const std::size_t o = chord_free_offset<Epick>(m, P, uv, B);
  CHECK(o < B.size(), "a square placement without flat chord");
  place_on_square<Epick>(uv, B, o, false);
  const auto before = uv_snapshot(m, uv);
  CHECK(PE::tutte_embedding(m, boost::graph_traits<Mesh>::null_halfedge(), uv) == PE::OK, "Tutte, fixed weakly convex border");
  const PE::Embedding_report r = PE::check_embedding(m, uv);
  std::cout << "  Tutte: " << r.summary() << std::endl;
  for(auto v : B) CHECK(same_point(get(uv, v), before.at(v)), "Tutte keeps the border");
  CHECK(r.is_valid(), "the Tutte map is valid");
  // a random interior in [1/4, 3/4]^2: the repair on the weakly convex border
  {
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> unif(0.25, 0.75);
    for(auto v : vertices(m)) if(!CGAL::is_border(v, m)) put(uv, v, Epick::Point_2(unif(gen), unif(gen)));
  }
  PE::Progressive_embedding_statistics st;
  CHECK(PE::progressive_embedding(m, uv, PE::parameters::statistics(&st)) == PE::OK, "progressive embedding");
  std::cout << "  progressive embedding from a random interior: " << st.report.summary() << ", " << st.collapses << " collapses" << std::endl;
  CHECK(st.report.is_valid() && st.collapses > 0, "repaired");
  for(auto v : B) CHECK(same_point(get(uv, v), before.at(v)), "progressive embedding keeps the border");
  return EXIT_SUCCESS;
}

// Independent disk test of a face set: connected through shared edges, every vertex with at most
// one outgoing border halfedge (not pinched), one border cycle, V - E + F = 1.
template <class Mesh>
bool is_disk_patch(const Mesh& m, const std::vector<fd_t<Mesh> >& P)
{
  if(P.empty()) return false;
  const std::set<fd_t<Mesh> > in(P.begin(), P.end());
  auto inside = [&](hd_t<Mesh> h) { return !is_border(h, m) && in.count(face(h, m)) != 0; };
  std::map<vd_t<Mesh>, int> out;
  std::size_t nbh = 0, ninner = 0;
  for(auto f : P)
    for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m))
    {
      if(inside(opposite(h, m))) { ++ninner; continue; }
      ++nbh;
      if(++out[source(h, m)] > 1) return false;
    }
  if(nbh == 0 || patch_border(m, P).size() != nbh) return false;
  std::set<fd_t<Mesh> > seen;
  std::vector<fd_t<Mesh> > stack(1, P[0]);
  seen.insert(P[0]);
  while(!stack.empty())
  {
    const fd_t<Mesh> f = stack.back(); stack.pop_back();
    for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m))
      if(inside(opposite(h, m)) && seen.insert(face(opposite(h, m), m)).second) stack.push_back(face(opposite(h, m), m));
  }
  if(seen.size() != P.size()) return false;
  const long V = long(patch_vertices(m, P).size()), E = long(nbh + ninner / 2), F = long(P.size());
  return V - E + F == 1;
}

// Ring patches of several sizes around many vertices of bull.off, the border on a square from an
// arbitrary corner: every outcome is a certified map, a patch that is not a disk, or a flat chord
// (then find_flat_chords lists some), each confirmed independently; the map changes only on the
// patch's interior vertices, and only on success.
template <class Mesh>
int sweep(const std::string& data)
{
  std::cout << "[" << mesh_name<Mesh>() << "] ring patches of bull.off" << std::endl;
  Mesh m;
  CHECK(read_mesh(data + "/meshes/bull.off", m), "read bull.off");
  std::vector<vd_t<Mesh> > all(vertices(m).begin(), vertices(m).end());
  auto uv = make_uv_map(m, Epick::Point_2());
  std::size_t i = 0;
  for(auto v : vertices(m)) put(uv, v, Epick::Point_2(double(i++), 0.5));
  std::size_t ok = 0, not_disk = 0, chord = 0, repaired = 0;
  for(std::size_t k = 0; k < 60; ++k)
  {
    const vd_t<Mesh> seed = all[(k * 104729) % all.size()];
    const int rings = 2 + int(k % 3) * 2;
    std::vector<fd_t<Mesh> > P = ring_patch(m, seed, rings);
    if(k % 4 >= 2)
    {
      // ears: the faces across every third border edge join the patch
      const std::set<fd_t<Mesh> > in(P.begin(), P.end());
      std::set<fd_t<Mesh> > added;
      std::size_t n = 0;
      for(auto f : in)
        for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m))
        {
          const hd_t<Mesh> o = opposite(h, m);
          if(!is_border(o, m) && !in.count(face(o, m)) && n++ % 3 == 0) added.insert(face(o, m));
        }
      P.insert(P.end(), added.begin(), added.end());
    }
    const bool disk = is_disk_patch(m, P);
    std::vector<vd_t<Mesh> > B;
    if(disk)
    {
      B = patch_border(m, P);
      if(B.size() < 4) continue;
      place_on_square<Epick>(uv, B, k % B.size(), k % 2 == 1);
    }
    const auto before = uv_snapshot(m, uv);
    PE::Progressive_embedding_statistics st;
    const PE::Error_code ec = PE::embed_patch(m, P, uv, PE::parameters::statistics(&st));
    std::vector<ed_t<Mesh> > chords;
    const PE::Error_code ecc = PE::internal::find_flat_chords(m, P, uv, std::back_inserter(chords));
    if(ec == PE::OK)
    {
      ++ok;
      if(st.collapses > 0) ++repaired;
      CHECK(disk && chords.empty() && ecc == PE::OK, "seed " << k << ": certified only if a disk without chord");
      RUN(check_patch_map(m, P, uv, k % 2 == 1 ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN, "sweep " + std::to_string(k)));
      const std::set<vd_t<Mesh> > V = patch_vertices(m, P);
      const std::set<vd_t<Mesh> > Bs(B.begin(), B.end());
      for(auto v : vertices(m))
        if(!V.count(v) || Bs.count(v)) CHECK(same_point(get(uv, v), before.at(v)), "seed " << k << ": only interior vertices change");
    }
    else
    {
      CHECK(changed_vertices(m, uv, before) == 0, "seed " << k << ": unchanged on error");
      if(ec == PE::ERROR_NOT_A_DISK) { ++not_disk; CHECK(!disk && ecc == PE::ERROR_NOT_A_DISK, "seed " << k << ": not a disk"); }
      else
      {
        CHECK(ec == PE::ERROR_DEGENERATE_CHORD, "seed " << k << ": unexpected " << PE::get_error_name(ec));
        ++chord;
        CHECK(disk && ecc == PE::OK && !chords.empty(), "seed " << k << ": flat chords listed");
      }
    }
  }
  std::cout << "  60 patches: " << ok << " certified (" << repaired << " repaired), " << not_disk << " not disks, "
            << chord << " with flat chords" << std::endl;
  CHECK(ok >= 10 && chord >= 1, "a mix of outcomes");
  return EXIT_SUCCESS;
}

} // namespace

PE_TEST_GROUP(patch_embedding_real)
{
  RUN(real_ring_patch<Surface_mesh>(data_dir));
  return real_disk_patch<Surface_mesh>(data_dir);
}

PE_TEST_GROUP(patch_embedding_polyhedron)
{
  RUN(real_ring_patch<Polyhedron>(data_dir));
  RUN(flat_chords<Polyhedron>());
  return refused<Polyhedron>(data_dir);
}

PE_TEST_GROUP(patch_embedding_repair)
{
  (void)data_dir;
  RUN(crowded_patches<Surface_mesh>());
  return repaired_patch<Surface_mesh>();
}

PE_TEST_GROUP(patch_embedding_chords)
{
  (void)data_dir;
  return flat_chords<Surface_mesh>();
}

PE_TEST_GROUP(patch_embedding_refused)
{
  return refused<Surface_mesh>(data_dir);
}

PE_TEST_GROUP(patch_embedding_gmpq)
{
  RUN(gmpq_patch<Surface_mesh>(data_dir));
  return gmpq_patch<Polyhedron>(data_dir);
}

PE_TEST_GROUP(patch_embedding_disk_functions)
{
  return disk_functions<Surface_mesh>(data_dir);
}

PE_TEST_GROUP(patch_embedding_sweep)
{
  return sweep<Surface_mesh>(data_dir);
}
