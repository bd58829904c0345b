// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Coarsening of constrained maps (internal/constrained/coarsen.h): an added vertex is removed into an
// end of the edge it split when every face of the fan is strictly positive, kept otherwise; the
// removal replays on another mesh type; in constrained_embedding() the removed and kept vertices add
// up to those inserted, the map stays certified and the constraints bit-exact.

#include <CGAL/Progressive_embedding/constrained_embedding.h>
#include <CGAL/Progressive_embedding/internal/constrained/coarsen.h>
#include <CGAL/Progressive_embedding/internal/constrained/refinement.h>
#include <CGAL/Progressive_embedding/internal/disk_generators.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>

#include "registry.h"
#include "../test_util.h"
#include "mesh_fixtures.h"

#include <CGAL/boost/graph/copy_face_graph.h>

#include <algorithm>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

namespace {

namespace PE = CGAL::Progressive_embedding;
using pe_test::count_vertices;
typedef Epick::Point_2 Point_2;

// The star of a vertex s: s at `centre`, its link the polygon `ring` (counterclockwise), one
// triangle (s, ring[k], ring[k + 1]) per side. The 3D points are the uv lifted to z = 0.
template <class Mesh>
typename boost::graph_traits<Mesh>::vertex_descriptor
make_star(Mesh& m, const Point_2& centre, const std::vector<Point_2>& ring,
          std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& rv,
          std::unordered_map<typename boost::graph_traits<Mesh>::vertex_descriptor, Point_2>& uv)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor VD;
  auto vpm = get(CGAL::vertex_point, m);
  const VD s = add_vertex(m);
  put(vpm, s, Epick::Point_3(centre.x(), centre.y(), 0));
  uv[s] = centre;
  rv.clear();
  for(const Point_2& p : ring)
  {
    const VD v = add_vertex(m);
    put(vpm, v, Epick::Point_3(p.x(), p.y(), 0));
    uv[v] = p;
    rv.push_back(v);
  }
  for(std::size_t k = 0; k < ring.size(); ++k)
    CGAL::Euler::add_face(std::vector<VD>{ s, rv[k], rv[(k + 1) % ring.size()] }, m);
  return s;
}

template <class Mesh>
int star_cases()
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor VD;
  const auto orient = PE::Progressive_embedding_traits_2<Epick>().exact_orientation_2_object();
  {
    // a convex link: removable into any neighbour, the two faces at the kept vertex disappear
    Mesh m;
    std::vector<VD> rv;
    std::unordered_map<VD, Point_2> uvs;
    const std::vector<Point_2> ring{ Point_2(-1, 0), Point_2(0, -1), Point_2(1, 0), Point_2(0, 1) };
    const VD s = make_star(m, Point_2(0, 0), ring, rv, uvs);
    auto uv = boost::make_assoc_property_map(uvs);
    std::vector<VD> link;
    // a bound on the fan faces (the pipeline's distortion bound) is asked about each face of the fan, and
    // one refused face keeps the vertex
    std::size_t asked = 0;
    const auto refuse_last = [&](VD a, VD x, VD y) { ++asked; return !(a == rv[0] && x == rv[2] && y == rv[3]); };
    CHECK(!PE::internal::can_remove_into(m, uv, orient, CGAL::LEFT_TURN, s, rv[0], link, refuse_last) && asked == 2,
          "a refused fan face keeps the vertex (asked " << asked << " times)");
    CHECK(PE::internal::can_remove_into(m, uv, orient, CGAL::LEFT_TURN, s, rv[0], link), "convex link: removable");
    CHECK(link.size() == 4 && link[0] == rv[0], "link starts at the kept vertex");
    CHECK(PE::internal::remove_into(m, s, rv[0]) == PE::OK, "removed");
    CHECK(count_faces(m) == 2 && count_vertices(m) == 4, "a fan of 2 faces over 4 vertices");
    const PE::Embedding_report r = PE::check_embedding(m, uv);
    CHECK(r.is_valid() && r.flipped == 0 && r.degenerate == 0, "the fan is certified valid");
  }
  {
    // a link that neither end of the edge (a, s, b) sees whole: the fan from a has a negative face
    // (a, p2, b), the fan from b a negative face (b, p1, p2): kept, the mesh untouched
    Mesh m;
    std::vector<VD> rv;
    std::unordered_map<VD, Point_2> uvs;
    const std::vector<Point_2> ring{ Point_2(-1, 0), Point_2(-0.5, -1), Point_2(0.1, -0.1), Point_2(1, -0.5), Point_2(0, 1) };
    const VD s = make_star(m, Point_2(0, 0), ring, rv, uvs);
    auto uv = boost::make_assoc_property_map(uvs);
    CHECK(PE::check_embedding(m, uv).is_valid(), "the star is valid");
    std::vector<VD> link;
    CHECK(!PE::internal::can_remove_into(m, uv, orient, CGAL::LEFT_TURN, s, rv[0], link), "blocked from a");
    CHECK(!PE::internal::can_remove_into(m, uv, orient, CGAL::LEFT_TURN, s, rv[3], link), "blocked from b");
    CHECK(count_faces(m) == 5 && count_vertices(m) == 6, "kept: the mesh untouched");
    // from p2, the link's reflex vertex, the fan is positive (the test decides by the fan, not by the edge)
    CHECK(PE::internal::can_remove_into(m, uv, orient, CGAL::LEFT_TURN, s, rv[2], link), "removable into p2");
  }
  return EXIT_SUCCESS;
}

// the same removal on a Polyhedron_3 copy through a vertex correspondence (the caller's mesh)
int replay_case()
{
  typedef boost::graph_traits<Surface_mesh>::vertex_descriptor VD;
  typedef boost::graph_traits<Polyhedron>::vertex_descriptor PVD;
  Surface_mesh m;
  std::vector<VD> rv;
  std::unordered_map<VD, Point_2> uvs;
  const std::vector<Point_2> ring{ Point_2(-1, 0), Point_2(-0.5, -1), Point_2(0.5, -1), Point_2(1, 0), Point_2(0.5, 1), Point_2(-0.5, 1) };
  const VD s = make_star(m, Point_2(0.1, 0), ring, rv, uvs);
  Polyhedron p;
  std::vector<std::pair<VD, PVD> > v2v;
  CGAL::copy_face_graph(m, p, CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v)));
  std::unordered_map<VD, PVD> to_p(v2v.begin(), v2v.end());
  std::vector<PE::internal::Vertex_removal<VD> > removals{ { s, rv[3] } };
  CHECK(PE::internal::remove_into(m, s, rv[3]) == PE::OK, "removed on the copy");
  CHECK(PE::internal::replay_removals(removals, p, to_p) == PE::OK, "replayed on the Polyhedron_3");
  CHECK(count_faces(p) == 4 && count_vertices(p) == 6 && count_faces(m) == 4, "same fan on both");
  // every face of the Polyhedron_3 is a face of the copy, through the correspondence
  std::unordered_map<PVD, VD> back;
  for(const auto& q : v2v) back[q.second] = q.first;
  for(auto f : faces(p))
  {
    const auto h = halfedge(f, p);
    const auto hm = halfedge(back.at(source(h, p)), back.at(target(h, p)), m);
    CHECK(hm.second && !CGAL::is_border(hm.first, m), "an edge of the same face");
    CHECK(back.at(target(next(h, p), p)) == target(next(hm.first, m), m), "the same triangle");
  }
  return EXIT_SUCCESS;
}

// constrained_embedding() with and without the coarsening on one input: same refinement before it,
// kept + removed = inserted, certified on the caller's mesh, constraints bit-exact, one surface
// position per kept vertex
template <class Mesh>
int pipeline_case(const std::string& file, std::size_t n, unsigned seed, bool expect_removal)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor VD;
  std::size_t inserted[2] = { 0, 0 };
  for(int coarsen = 0; coarsen < 2; ++coarsen)
  {
    Mesh m;
    if(!read_mesh(file, m)) return EXIT_FAILURE;
    auto uv = make_uv_map(m, Point_2());
    CHECK(PE::tutte_embedding(m, boost::graph_traits<Mesh>::null_halfedge(), uv,
                              PE::parameters::border_shape(PE::Border_shape::SQUARE)) == PE::OK, "border placed");
    std::vector<VD> interior;
    for(auto v : vertices(m)) if(!CGAL::is_border(v, m)) interior.push_back(v);
    std::mt19937 rng(seed);
    std::shuffle(interior.begin(), interior.end(), rng);
    std::uniform_real_distribution<double> U(0.2, 0.8);
    std::vector<std::pair<VD, Point_2> > C;
    for(std::size_t i = 0; i < n; ++i) C.emplace_back(interior[i], Point_2(U(rng), U(rng)));
    const std::size_t nv0 = count_vertices(m);
    PE::Constrained_embedding_statistics st;
    std::vector<PE::Steiner_point<VD> > sp;
    const PE::Error_code ec = PE::constrained_embedding(m, C, uv,
      PE::parameters::statistics(&st, PE::parameters::steiner_points(&sp, PE::parameters::coarsen(coarsen == 1))));
    std::cout << mesh_name<Mesh>() << " n=" << n << " seed " << seed << (coarsen ? " coarsened" : " not coarsened") << ": "
              << PE::get_error_message(ec) << ", inserted " << st.steiner_vertices_inserted << ", removed "
              << st.steiner_vertices_removed << ", kept " << st.steiner_vertices << std::endl;
    CHECK(ec == PE::OK, "OK");
    CHECK(st.steiner_vertices_inserted == st.steiner_vertices_removed + st.steiner_vertices, "kept + removed = inserted");
    CHECK(coarsen == 1 || st.steiner_vertices_removed == 0, "nothing removed without the coarsening");
    CHECK(count_vertices(m) == nv0 + st.steiner_vertices && st.output_vertices == count_vertices(m), "vertex count");
    CHECK(sp.size() == st.steiner_vertices, "one surface position per kept vertex");
    for(const auto& s : sp) CHECK(!CGAL::is_border(s.vertex, m), "a kept vertex of the mesh");
    const PE::Embedding_report r = PE::check_embedding(m, uv);
    CHECK(r.is_valid() && r.flipped == 0 && r.degenerate == 0 && r.overlapping_pairs == 0 && r.non_finite == 0,
          "certified on the caller's mesh");
    for(const auto& c : C) CHECK(get(uv, c.first) == c.second, "constraint bit-exact");
    inserted[coarsen] = st.steiner_vertices_inserted;
    if(coarsen == 1 && expect_removal) CHECK(st.steiner_vertices_removed > 0, "some added vertices removed");
  }
  CHECK(inserted[0] == inserted[1], "the same refinement before the coarsening");
  return EXIT_SUCCESS;
}

// remove_added_vertices() tests a vertex again only when a star it depends on changed: on a grid disk refined by
// 600 random edge splits (edges between added vertices among them), its interior vertices then moved where their
// stars stay positive, and a bound on the fan faces that refuses a third of them by a hash of their corners (as
// the pipeline's distortion bound reads the fan face only), so that many removals wait for others or never come:
// the same removals in the same order and the same passes as testing every vertex in every pass, with fewer
// tests; the map certified after.
int tracked_passes_case()
{
  typedef Surface_mesh Mesh;
  typedef boost::graph_traits<Mesh>::vertex_descriptor VD;
  typedef boost::graph_traits<Mesh>::halfedge_descriptor HD;
  struct Added { VD v, a, b; };
  Mesh m;
  PE::internal::make_grid_disk(12, m);
  auto uv = m.add_property_map<VD, Point_2>("v:test_uv").first;
  auto vpm = get(CGAL::vertex_point, m);
  for(VD v : vertices(m)) put(uv, v, Point_2(get(vpm, v).x(), get(vpm, v).y()));
  const auto orient = PE::Progressive_embedding_traits_2<Epick>().exact_orientation_2_object();
  const auto star_positive = [&](VD v) {
    for(HD h : CGAL::halfedges_around_target(v, m))
      if(!CGAL::is_border(h, m) &&
         orient(get(uv, source(h, m)), get(uv, target(h, m)), get(uv, target(next(h, m), m))) != CGAL::LEFT_TURN)
        return false;
    return true;
  };
  std::mt19937 rng(7);
  std::vector<Added> added;
  for(int i = 0; i < 600; ++i)
  {
    std::vector<HD> interior;
    for(auto e : edges(m)) if(!CGAL::is_border_edge(halfedge(e, m), m)) interior.push_back(halfedge(e, m));
    const HD h = interior[std::uniform_int_distribution<std::size_t>(0, interior.size() - 1)(rng)];
    const VD a = source(h, m), b = target(h, m);
    const double t = std::uniform_real_distribution<double>(0.3, 0.7)(rng);
    const Point_2 p = get(uv, a) + t * (get(uv, b) - get(uv, a));
    const HD hn = PE::internal::split_edge_and_faces(h, Epick::Point_3(p.x(), p.y(), 0), m, vpm);
    put(uv, target(hn, m), p);
    added.push_back({ target(hn, m), a, b });
  }
  std::size_t moved = 0;
  std::normal_distribution<double> N(0., 0.02);
  for(int round = 0; round < 3; ++round)
    for(VD v : vertices(m))
    {
      if(CGAL::is_border(v, m)) continue;
      const Point_2 old = get(uv, v);
      put(uv, v, Point_2(old.x() + N(rng), old.y() + N(rng)));
      if(star_positive(v)) ++moved; else put(uv, v, old);
    }
  CHECK(PE::check_embedding(m, uv).is_valid(), "the refined map is certified");
  const auto refuse_some = [](VD a, VD x, VD y) {
    return (std::size_t(a) * 73856093u ^ std::size_t(x) * 19349663u ^ std::size_t(y) * 83492791u) % 3 != 0;
  };
  typedef PE::internal::Vertex_removal<VD> Removal;
  std::vector<Removal> removals[2];
  std::size_t passes[2] = { 0, 0 }, tests[2] = { 0, 0 };
  for(int retest = 0; retest < 2; ++retest)
  {
    Mesh c = m; // the same vertex indices, the uv map copied with the mesh
    auto cuv = c.property_map<VD, Point_2>("v:test_uv").first;
    const auto test = [&](VD v, VD a, std::vector<VD>& link) {
      ++tests[retest];
      return !c.is_removed(v) && !c.is_removed(a) &&
             PE::internal::can_remove_into(c, cuv, orient, CGAL::LEFT_TURN, v, a, link, refuse_some);
    };
    const auto remove = [&](VD v, VD a, const std::vector<VD>&) { return PE::internal::remove_into(c, v, a); };
    std::vector<char> done;
    CHECK(PE::internal::remove_added_vertices(added, c.number_of_vertices() + c.number_of_removed_vertices(), test, remove,
                                              done, removals[retest], passes[retest], retest == 1) == PE::OK, "removals");
    CHECK(PE::check_embedding(c, cuv).is_valid(), "certified after the removals");
    CHECK(std::size_t(std::count(done.begin(), done.end(), 1)) == removals[retest].size(), "done marks the removed");
  }
  std::cout << "  600 splits, " << moved << " vertex moves; " << removals[0].size() << " removed in " << passes[0]
            << " passes, " << tests[0] << " tests (testing everything: " << removals[1].size() << " in " << passes[1]
            << " passes, " << tests[1] << " tests)" << std::endl;
  CHECK(removals[0].size() == removals[1].size() && passes[0] == passes[1], "as many removals and passes");
  for(std::size_t i = 0; i < removals[0].size() && i < removals[1].size(); ++i)
    CHECK(removals[0][i].removed == removals[1][i].removed && removals[0][i].kept == removals[1][i].kept,
          "the same removal at " << i);
  CHECK(passes[0] >= 3 && removals[0].size() >= 300 && removals[0].size() + 100 <= added.size(),
        "several passes, many vertices removed, many kept");
  CHECK(tests[0] < tests[1], "fewer tests");
  return EXIT_SUCCESS;
}

} // namespace

PE_TEST_GROUP(coarsen_star)
{
  RUN(star_cases<Surface_mesh>());
  RUN(star_cases<Polyhedron>());
  RUN(replay_case());
  RUN(tracked_passes_case());
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(coarsen_pipeline)
{
  RUN(pipeline_case<Surface_mesh>(data_dir + "/meshes/mushroom.off", 10, 3u, true));
  RUN(pipeline_case<Polyhedron>(data_dir + "/meshes/mushroom.off", 10, 3u, true));
  return EXIT_SUCCESS;
}
