// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// constrained_embedding(): certified maps with hard positional constraints on real disks and cut
// closed meshes, border fixed or shaped, every error code with the caller's mesh and uv untouched,
// Polyhedron_3 and exact rationals.

#include <CGAL/Progressive_embedding/constrained_embedding.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/internal/constrained/kinetic_triangulation.h>
#include <CGAL/Progressive_embedding/internal/constrained/trace_kinetic.h>
#include <CGAL/Progressive_embedding/internal/constrained/domain_partition.h>

#include "registry.h"
#include "../test_util.h"
#include <CGAL/Progressive_embedding/internal/disk_generators.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <array>
#include <set>
#include <algorithm>
#include <string>
#include <vector>

namespace {

namespace PE = CGAL::Progressive_embedding;

// a snapshot of a mesh and its uv: vertices in order, their 3D points and uv (to check "unchanged")
template <class Mesh, class UVM>
struct Snapshot
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> verts;
  std::vector<typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type> points;
  std::vector<typename boost::property_traits<UVM>::value_type> uv;
  std::size_t faces = 0;
  Snapshot(const Mesh& m, const UVM& uvm)
  {
    for(auto v : vertices(m)) { verts.push_back(v); points.push_back(get(CGAL::vertex_point, m, v)); uv.push_back(get(uvm, v)); }
    faces = count_faces(m);
  }
  bool same_mesh(const Mesh& m) const
  {
    std::size_t i = 0;
    for(auto v : vertices(m))
    {
      if(i >= verts.size() || verts[i] != v || !(points[i] == get(CGAL::vertex_point, m, v))) return false;
      ++i;
    }
    return i == verts.size() && faces == count_faces(m);
  }
  // the original vertices come first, with their descriptors and 3D points
  bool originals_first(const Mesh& m) const
  {
    std::size_t i = 0;
    for(auto v : vertices(m))
    {
      if(i == verts.size()) break;
      if(verts[i] != v || !(points[i] == get(CGAL::vertex_point, m, v))) return false;
      ++i;
    }
    return i == verts.size();
  }
  bool same_uv(const Mesh& m, const UVM& uvm) const
  {
    std::size_t i = 0;
    for(auto v : vertices(m))
    {
      if(i >= uv.size() || !(uv[i] == get(uvm, v))) return false;
      ++i;
    }
    return true;
  }
};

// border uv: the given shape by tutte_embedding (the interior uv is irrelevant)
template <class Mesh, class UVM>
bool shaped_border(const Mesh& m, UVM& uv, PE::Border_shape shape)
{
  return PE::tutte_embedding(m, boost::graph_traits<Mesh>::null_halfedge(), uv, PE::parameters::border_shape(shape)) == PE::OK;
}

// n seeded random interior vertices with targets strictly inside the border polygon: uniformly random
// points of the polygon (rejection in its bounding box) pulled halfway to its centroid; or, with
// `consistent`, the vertices' own positions in the current uv map (a Tutte map) pulled 2% towards the
// centroid, slightly jittered (landmarks roughly consistent with the surface, as in practice)
template <class K, class Mesh, class UVM>
std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor, typename K::Point_2> >
random_constraints(const Mesh& m, const UVM& uv, std::size_t n, unsigned seed, bool consistent = false)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor VD;
  typedef Epick::Point_2 P;
  std::vector<P> border;
  for(auto h : halfedges(m))
    if(CGAL::is_border(h, m))
    {
      for(auto g : CGAL::halfedges_around_face(h, m))
        border.push_back(P(CGAL::to_double(get(uv, target(g, m)).x()), CGAL::to_double(get(uv, target(g, m)).y())));
      break;
    }
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300, cx = 0, cy = 0;
  for(const P& p : border)
  {
    x0 = std::min(x0, p.x()); x1 = std::max(x1, p.x()); y0 = std::min(y0, p.y()); y1 = std::max(y1, p.y());
    cx += p.x() / border.size(); cy += p.y() / border.size();
  }
  std::vector<VD> interior;
  for(auto v : vertices(m)) if(!CGAL::is_border(v, m)) interior.push_back(v);
  std::mt19937 rng(seed);
  std::shuffle(interior.begin(), interior.end(), rng);
  std::uniform_real_distribution<double> U(0, 1), J(-1e-3, 1e-3);
  std::vector<std::pair<VD, typename K::Point_2> > c;
  for(std::size_t i = 0; i < n && i < interior.size(); ++i)
  {
    double x, y;
    if(consistent)
    {
      x = cx + 0.98 * (CGAL::to_double(get(uv, interior[i]).x()) - cx) + J(rng) * (x1 - x0);
      y = cy + 0.98 * (CGAL::to_double(get(uv, interior[i]).y()) - cy) + J(rng) * (y1 - y0);
    }
    else
    {
      P q;
      for(int tries = 0; tries < 1000; ++tries)
      {
        q = P(x0 + U(rng) * (x1 - x0), y0 + U(rng) * (y1 - y0));
        if(CGAL::bounded_side_2(border.begin(), border.end(), q, Epick()) == CGAL::ON_BOUNDED_SIDE) break;
      }
      x = cx + 0.5 * (q.x() - cx);
      y = cy + 0.5 * (q.y() - cy);
    }
    c.emplace_back(interior[i], point<K>(x, y));
  }
  return c;
}

// runs constrained_embedding and checks everything it promises
template <class K, class Mesh>
int run_case(Mesh& m, std::size_t n, unsigned seed, const std::string& what, bool fixed_border,
             PE::Border_shape shape = PE::Border_shape::SQUARE, bool consistent = false, std::size_t max_steiner = 0,
             PE::Constrained_embedding_statistics* stats_out = nullptr, bool optimize = true, bool kinetic = true)
{
  typedef typename K::Point_2 Point_2;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor VD;
  auto uv = make_uv_map(m, Point_2());
  for(auto v : vertices(m)) put(uv, v, point<K>(0, 0));
  CHECK(shaped_border(m, uv, shape), "border placed");
  const auto C = random_constraints<K>(m, uv, n, seed, consistent);
  CHECK(C.size() == n, "enough interior vertices");
  const Snapshot<Mesh, decltype(uv)> before(m, uv);
  PE::Constrained_embedding_statistics st;
  std::vector<PE::Steiner_point<VD> > sp;
  if(max_steiner == 0) max_steiner = 4 * static_cast<std::size_t>(num_edges(m)) + 1000; // the default
  const PE::Error_code ec = fixed_border
    ? PE::constrained_embedding(m, C, uv, PE::parameters::statistics(&st, PE::parameters::steiner_points(&sp,
                                            PE::parameters::maximum_steiner_vertices(max_steiner).optimize(optimize)
                                            .kinetic_tracing(kinetic))))
    : PE::constrained_embedding(m, C, uv, PE::parameters::statistics(&st, PE::parameters::steiner_points(&sp,
                                            PE::parameters::maximum_steiner_vertices(max_steiner,
                                            PE::parameters::border_shape(shape)).optimize(optimize).kinetic_tracing(kinetic))));
  std::cout << what << (consistent ? " consistent" : " random") << " n=" << n << " seed " << seed << ": " << PE::get_error_message(ec) << ", vertices "
            << st.input_vertices << " -> " << st.output_vertices << ", Steiner " << st.steiner_vertices << " ("
            << st.chord_splits << " chord splits), paths " << st.paths << ", patches " << st.patches << " ("
            << st.repaired_patches << " repaired), seconds: trace " << st.seconds_tracing << ", patches "
            << st.seconds_patches << ", optimize " << st.seconds_optimization << ", total " << st.seconds_total
            << "; mean energy " << st.report_before_optimization.mean_energy_3d << " -> " << st.report.mean_energy_3d
            << std::endl;
  CHECK(ec == PE::OK, "constrained_embedding OK");
  const PE::Embedding_report r = PE::check_embedding(m, uv);
  CHECK(r.is_valid() && r.flipped == 0 && r.degenerate == 0 && r.overlapping_pairs == 0 && r.non_finite == 0,
        "certified valid on the caller's mesh");
  CHECK(st.report.is_valid() && st.report_before_optimization.is_valid(), "certificates in the statistics");
  if(optimize)
    CHECK(st.report.mean_energy_3d <= st.report_before_optimization.mean_energy_3d,
          "the optimized and coarsened map no more distorted than before the optimization: mean "
          << st.report_before_optimization.mean_energy_3d << " -> " << st.report.mean_energy_3d);
  const std::size_t nv = static_cast<std::size_t>(std::distance(vertices(m).begin(), vertices(m).end()));
  CHECK(nv == before.verts.size() + st.steiner_vertices && st.output_vertices == nv, "Steiner count reported");
  CHECK(sp.size() == st.steiner_vertices, "one surface position per Steiner vertex");
  CHECK(before.originals_first(m), "original vertices first, same descriptors and 3D points");
  CHECK(st.max_constraint_error == 0, "max constraint error 0");
  for(const auto& c : C)
    CHECK(get(uv, c.first) == c.second, "constraint bit-exact");
  if(fixed_border)
  {
    std::size_t i = 0;
    for(auto v : vertices(m))
    {
      if(i == before.verts.size()) break;
      if(CGAL::is_border(v, m)) CHECK(get(uv, v) == before.uv[i], "border bit-exact (FIXED)");
      ++i;
    }
  }
  // every Steiner point is the convex combination it claims (exactly: dyadic weights, midpoints)
  for(const auto& s : sp)
  {
    CHECK(s.size >= 1 && s.size <= 3, "Steiner point support");
    double w = 0;
    for(std::size_t k = 0; k < s.size; ++k) { w += s.weights[k]; CHECK(s.weights[k] > 0, "positive weight"); }
    CHECK(w == 1, "weights sum to 1");
  }
  if(stats_out) *stats_out = st;
  return EXIT_SUCCESS;
}

template <class Mesh>
// optimize: false where the case checks the partition only (the optimization of these maps is checked by
// the cases that keep it, and it is most of their time)
int disk_cases(const std::string& file, const std::vector<std::size_t>& counts, bool fixed_border,
               PE::Border_shape shape = PE::Border_shape::SQUARE, bool consistent = false, bool optimize = true)
{
  Mesh m0;
  if(!read_mesh(file, m0)) return EXIT_FAILURE;
  const std::string name = file.substr(file.find_last_of('/') + 1);
  for(std::size_t n : counts)
  {
    Mesh m = m0;
    RUN((run_case<Epick>(m, n, static_cast<unsigned>(n) + 7, name + (fixed_border ? " fixed" : " shape"), fixed_border, shape, consistent,
                         0, nullptr, optimize)));
  }
  return EXIT_SUCCESS;
}

} // namespace

PE_TEST_GROUP(constrained_embedding_disks)
{
  RUN(disk_cases<Surface_mesh>(data_dir + "/meshes/mushroom.off", { 1, 3, 10 }, true));
  RUN(disk_cases<Surface_mesh>(data_dir + "/meshes/lion-head.off", { 1 }, true));
  RUN(disk_cases<Surface_mesh>(data_dir + "/meshes/lion-head.off", { 3, 10 }, true, PE::Border_shape::SQUARE, false, false));
  RUN(disk_cases<Surface_mesh>(data_dir + "/meshes/three_peaks.off", { 1, 3, 10 }, true));
  // 50 landmarks roughly consistent with the surface (50 random targets tangle the paths: see the budget test)
  RUN(disk_cases<Surface_mesh>(data_dir + "/meshes/mushroom.off", { 50 }, true, PE::Border_shape::SQUARE, true));
  RUN(disk_cases<Surface_mesh>(data_dir + "/meshes/lion-head.off", { 50 }, true, PE::Border_shape::SQUARE, true, false));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(constrained_embedding_shapes)
{
  RUN(disk_cases<Surface_mesh>(data_dir + "/meshes/mushroom.off", { 3, 10 }, false, PE::Border_shape::CIRCLE));
  RUN(disk_cases<Surface_mesh>(data_dir + "/meshes/lion-head.off", { 10 }, false, PE::Border_shape::SQUARE));
  RUN(disk_cases<Surface_mesh>(data_dir + "/meshes/lion-head.off", { 10 }, false, PE::Border_shape::CIRCLE, false, false));
  // the slanted sides of a triangle are straight only up to rounding: the nodes are the hull's corners
  RUN(disk_cases<Surface_mesh>(data_dir + "/meshes/mushroom.off", { 3 }, false, PE::Border_shape::TRIANGLE));
  RUN(disk_cases<Surface_mesh>(data_dir + "/meshes/mushroom.off", { 10 }, false, PE::Border_shape::TRIANGLE, false, false));
  // optimized, then coarsened: three border vertices of a slanted side made a fan face of area 1e-19 that the
  // second optimization could not move (mean energy 961 before the optimization, 2e26 after)
  RUN(disk_cases<Surface_mesh>(data_dir + "/meshes/three_peaks.off", { 10 }, false, PE::Border_shape::TRIANGLE));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(constrained_embedding_cut_closed)
{
  Surface_mesh m0;
  if(!read_mesh(data_dir + "/meshes/cow.off", m0)) return EXIT_FAILURE;
  std::array<boost::graph_traits<Surface_mesh>::vertex_descriptor, 3> pinned;
  CHECK(PE::internal::thingi_cut(m0, 1u, pinned) == PE::OK, "cut open");
  m0.collect_garbage();
  for(std::size_t n : { 1, 3, 10 })
  {
    Surface_mesh m = m0;
    RUN((run_case<Epick>(m, n, 11u + static_cast<unsigned>(n), "cow cut", true, PE::Border_shape::CIRCLE)));
  }
  return EXIT_SUCCESS;
}

namespace {

// a disk with holes: on a multiply connected mesh, border on the unit square (border_shape), targets
// random in its middle; certified with multiply_connected(true), the hole loops kept
template <class Mesh>
int holes_case(Mesh& m, std::size_t n, unsigned seed, const std::string& what, std::size_t cycles)
{
  typedef Epick::Point_2 Point_2;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor VD;
  auto uv = make_uv_map(m, Point_2());
  for(auto v : vertices(m)) put(uv, v, Point_2(0, 0));
  std::vector<VD> interior;
  for(auto v : vertices(m)) if(!CGAL::is_border(v, m)) interior.push_back(v);
  std::mt19937 rng(seed);
  std::shuffle(interior.begin(), interior.end(), rng);
  std::uniform_real_distribution<double> U(0.25, 0.75);
  std::vector<std::pair<VD, Point_2> > C;
  for(std::size_t i = 0; i < n; ++i) C.emplace_back(interior[i], Point_2(U(rng), U(rng)));
  const Snapshot<Mesh, decltype(uv)> before(m, uv);
  std::size_t border_before = 0;
  for(auto h : halfedges(m)) if(CGAL::is_border(h, m)) ++border_before;
  PE::Constrained_embedding_statistics st;
  std::vector<PE::Steiner_point<VD> > sp;
  const PE::Error_code ec = PE::constrained_embedding(m, C, uv, PE::parameters::statistics(&st,
                              PE::parameters::steiner_points(&sp, PE::parameters::border_shape(PE::Border_shape::SQUARE))));
  std::cout << what << " n=" << n << " seed " << seed << ": " << PE::get_error_message(ec) << ", vertices "
            << st.input_vertices << " -> " << st.output_vertices << ", Steiner " << st.steiner_vertices << ", paths "
            << st.paths << ", patches " << st.patches << ", seconds " << st.seconds_total << std::endl;
  if(ec != PE::OK)
    std::cout << "  before optimization: " << st.report_before_optimization.summary() << "\n  after: " << st.report.summary() << std::endl;
  CHECK(ec == PE::OK, "constrained_embedding OK with holes");
  // the holes are free loops: where one pinches itself, the global steps hold the touching edges'
  // vertices instead of failing from then on (which left 1000 slow iterations, unconverged)
  std::cout << "  optimization: " << st.optimization.iterations << " iterations, " << st.optimization.global_steps
            << " global steps, converged " << st.optimization.converged << "; again after the coarsening: "
            << st.reoptimization.iterations << " iterations, converged " << st.reoptimization.converged << std::endl;
  CHECK(st.optimized && st.optimization.converged && st.optimization.global_steps == st.optimization.iterations,
        "the optimization converges, every iteration with a global step");
  const PE::Embedding_report r = PE::check_embedding(m, uv, PE::parameters::multiply_connected(true));
  std::cout << "  " << r.summary() << std::endl;
  CHECK(r.is_valid() && r.flipped == 0 && r.degenerate == 0 && r.overlapping_pairs == 0 && r.border_cycles == cycles,
        "certified valid, multiply connected, every loop kept");
  const std::size_t nv = static_cast<std::size_t>(std::distance(vertices(m).begin(), vertices(m).end()));
  CHECK(nv == before.verts.size() + st.steiner_vertices && sp.size() == st.steiner_vertices, "Steiner count reported");
  CHECK(before.originals_first(m), "original vertices first, same descriptors and 3D points");
  for(const auto& c : C) CHECK(get(uv, c.first) == c.second, "constraint bit-exact");
  return EXIT_SUCCESS;
}

} // namespace

PE_TEST_GROUP(constrained_embedding_holes)
{
  {
    // a real mesh with 7 border cycles (genus 0)
    Surface_mesh m0;
    if(!read_mesh(data_dir + "/meshes/holes.off", m0)) return EXIT_FAILURE;
    for(std::size_t n : { 1, 3, 10 })
    {
      Surface_mesh m = m0;
      RUN(holes_case(m, n, 3u + static_cast<unsigned>(n), "holes.off", 7));
    }
  }
  {
    // three holes cut in a disk: the faces around three interior vertices removed
    Surface_mesh m;
    if(!read_mesh(data_dir + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
    std::vector<boost::graph_traits<Surface_mesh>::vertex_descriptor> centers;
    for(auto v : vertices(m))
    {
      if(centers.size() == 3) break;
      bool far = !CGAL::is_border(v, m);
      for(auto w : CGAL::vertices_around_target(v, m)) if(CGAL::is_border(w, m)) far = false;
      for(auto c : centers)
        for(auto w : CGAL::vertices_around_target(c, m))
          for(auto x : CGAL::vertices_around_target(w, m)) if(x == v || w == v) far = false;
      if(far && v.idx() % 500 == 100) centers.push_back(v);
    }
    CHECK(centers.size() == 3, "three hole centers");
    for(auto c : centers)
    {
      std::vector<boost::graph_traits<Surface_mesh>::face_descriptor> F;
      for(auto f : CGAL::faces_around_target(halfedge(c, m), m)) F.push_back(f);
      for(auto f : F) CGAL::Euler::remove_face(halfedge(f, m), m);
    }
    m.collect_garbage();
    RUN(holes_case(m, 10, 5u, "mushroom with 3 holes", 4));
  }
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(constrained_embedding_polyhedron)
{
  Polyhedron m;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
  RUN((run_case<Epick>(m, 10, 3u, "mushroom Polyhedron_3", true)));
  return EXIT_SUCCESS;
}

// Targets at random places, unrelated to where the surface puts their vertices: the partition's
// paths wind around the constrained vertices and nest; traced as curves over the input edges (the
// shortest paths run out of their Steiner budget), certified and bit-exact, on Surface_mesh and on
// Polyhedron_3 (the refinement, several points per input edge and the edges across each face,
// replayed on the caller's mesh). Not optimized: the optimization of such maps is slow (their
// distortion is large) and is tested elsewhere.
PE_TEST_GROUP(constrained_embedding_winding)
{
  for(unsigned seed : { 1u, 2u })
  {
    Surface_mesh m;
    if(!read_mesh(data_dir + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
    PE::Constrained_embedding_statistics st;
    RUN((run_case<Epick>(m, 30, seed, "mushroom winding", true, PE::Border_shape::SQUARE, false, 100000, &st, false, false)));
    CHECK(!st.kinetic_tracing, "kinetic_tracing(false): no kinetic tracing");
    CHECK(st.overlay_tracing && st.overlay_tracing_kept, "the overlay tracing's paths kept");
    CHECK(st.steiner_vertices > 1000, "winding paths need many Steiner vertices: " << st.steiner_vertices);
  }
  {
    Polyhedron m;
    if(!read_mesh(data_dir + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
    PE::Constrained_embedding_statistics st;
    RUN((run_case<Epick>(m, 30, 1u, "mushroom Polyhedron_3 winding", true, PE::Border_shape::SQUARE, false, 100000, &st, false, false)));
    CHECK(st.overlay_tracing_kept, "the overlay tracing's paths kept");
  }
  return EXIT_SUCCESS;
}

// Parallel_tag maps the patches (and places the path vertices) in parallel: the map is bit-for-bit the
// sequential one, since each patch's map depends on its border only. Winding paths give many patches
// and long paths; then a small case with the (parallel) optimization, certified.
PE_TEST_GROUP(constrained_embedding_parallel)
{
  typedef boost::graph_traits<Surface_mesh>::vertex_descriptor VD;
  Surface_mesh m0;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", m0)) return EXIT_FAILURE;
  auto uv0 = m0.add_property_map<VD, Epick::Point_2>("v:test_uv", Epick::Point_2(0, 0)).first; // copied with the mesh
  CHECK(shaped_border(m0, uv0, PE::Border_shape::SQUARE), "border placed");
  const auto C = random_constraints<Epick>(m0, uv0, 30, 1u);
  std::vector<std::vector<Epick::Point_2> > results;
  std::vector<std::size_t> repaired;
  for(int parallel = 0; parallel < 2; ++parallel)
  {
    Surface_mesh m = m0;
    auto uv = m.property_map<VD, Epick::Point_2>("v:test_uv").first;
    PE::Constrained_embedding_statistics st;
    const auto np = PE::parameters::statistics(&st, PE::parameters::maximum_steiner_vertices(100000).optimize(false));
    const PE::Error_code ec = parallel ? PE::constrained_embedding<CGAL::Parallel_if_available_tag>(m, C, uv, np)
                                       : PE::constrained_embedding<CGAL::Sequential_tag>(m, C, uv, np);
    std::cout << (parallel ? "parallel" : "sequential") << ": " << PE::get_error_message(ec) << ", Steiner "
              << st.steiner_vertices << ", patches " << st.patches << " (" << st.repaired_patches << " repaired), "
              << st.seconds_patches << " s in the patch phase" << std::endl;
    CHECK(ec == PE::OK, "constrained_embedding OK");
    CHECK(PE::check_embedding(m, uv).is_valid(), "certified");
    CHECK(st.patches > 20, "many patches: " << st.patches);
    for(const auto& c : C) CHECK(get(uv, c.first) == c.second, "constraint bit-exact");
    results.emplace_back();
    for(auto v : vertices(m)) results.back().push_back(get(uv, v));
    repaired.push_back(st.repaired_patches);
  }
  CHECK(results[0].size() == results[1].size(), "same refinement");
  std::size_t differ = 0;
  for(std::size_t i = 0; i < results[0].size(); ++i)
    if(!(results[0][i].x() == results[1][i].x() && results[0][i].y() == results[1][i].y())) ++differ;
  CHECK(differ == 0, "parallel map bit-for-bit the sequential one (" << differ << " vertices differ)");
  CHECK(repaired[0] == repaired[1], "same repaired patch count");
  {
    Surface_mesh m;
    if(!read_mesh(data_dir + "/meshes/lion-head.off", m)) return EXIT_FAILURE;
    auto uv = make_uv_map(m, Epick::Point_2());
    for(auto v : vertices(m)) put(uv, v, Epick::Point_2(0, 0));
    CHECK(shaped_border(m, uv, PE::Border_shape::SQUARE), "border placed");
    const auto C10 = random_constraints<Epick>(m, uv, 10, 3u);
    PE::Constrained_embedding_statistics st;
    const PE::Error_code ec = PE::constrained_embedding<CGAL::Parallel_if_available_tag>(m, C10, uv, PE::parameters::statistics(&st));
    std::cout << "lion-head, 10 constraints, parallel, optimized: " << PE::get_error_message(ec) << ", mean SD "
              << st.report_before_optimization.mean_energy_3d << " -> " << st.report.mean_energy_3d << std::endl;
    CHECK(ec == PE::OK && st.optimized && PE::check_embedding(m, uv).is_valid(), "optimized in parallel, certified");
    CHECK(st.report.mean_energy_3d <= st.report_before_optimization.mean_energy_3d, "the optimization lowered the energy");
    for(const auto& c : C10) CHECK(get(uv, c.first) == c.second, "constraint bit-exact");
  }
  return EXIT_SUCCESS;
}

// Targets a few ulps apart: dino (cut open around the Tutte-failure protocol's face for seed 2), 50
// interior vertices pinned at their places in its Tutte map on the square [-1.5, 2.5]^2, a map that
// crushes a region into 1e-14. Two patches are needles a few hundred ulps long and an ulp wide holding
// about 120 vertices: no double lies inside them for some. They are mapped with neighbouring patches
// into the union of their polygons (merged_patches), the whole map certified, the constraints exact.
PE_TEST_GROUP(constrained_embedding_needles)
{
  typedef boost::graph_traits<Surface_mesh>::vertex_descriptor VD;
  Surface_mesh m;
  if(!read_mesh(data_dir + "/meshes/dino.off", m)) return EXIT_FAILURE;
  const unsigned seed = 2;
  PE::internal::remove_protocol_face_star(m, seed);
  auto uv = m.add_property_map<VD, Epick::Point_2>("v:test_uv", Epick::Point_2(0, 0)).first;
  CHECK(PE::tutte_embedding(m, Surface_mesh::null_halfedge(), uv, PE::parameters::border_shape(PE::Border_shape::SQUARE)) == PE::OK,
        "Tutte map");
  for(VD v : vertices(m)) put(uv, v, Epick::Point_2(4 * get(uv, v).x() - 1.5, 4 * get(uv, v).y() - 1.5));
  std::vector<VD> pick;
  for(VD v : vertices(m)) if(!CGAL::is_border(v, m)) pick.push_back(v);
  std::mt19937 gen(seed * 1000u + 50u);
  std::shuffle(pick.begin(), pick.end(), gen);
  std::vector<std::pair<VD, Epick::Point_2> > C;
  std::set<std::pair<double, double> > used;
  auto inside = [](double x) { return std::min(2.4, std::max(-1.4, x)); };
  for(std::size_t j = 0; j < pick.size() && C.size() < 50; ++j)
  {
    const Epick::Point_2 t(inside(get(uv, pick[j]).x()), inside(get(uv, pick[j]).y()));
    if(used.insert({ t.x(), t.y() }).second) C.emplace_back(pick[j], t);
  }
  CHECK(C.size() == 50, "50 distinct targets");
  PE::Constrained_embedding_statistics st;
  const PE::Error_code ec = PE::constrained_embedding(m, C, uv, PE::parameters::statistics(&st).optimize(false));
  std::cout << "dino seed 2, 50 layout targets: " << PE::get_error_message(ec) << ", Steiner " << st.steiner_vertices
            << ", patches " << st.patches << ", merged " << st.merged_patches << ", min area "
            << st.report.min_signed_area << std::endl;
  CHECK(ec == PE::OK, "constrained_embedding OK");
  CHECK(st.merged_patches >= 2, "needles mapped with their neighbours: " << st.merged_patches);
  const PE::Embedding_report r = PE::check_embedding(m, uv);
  CHECK(r.is_valid() && r.flipped == 0 && r.degenerate == 0 && r.overlapping_pairs == 0, "certified valid");
  for(const auto& c : C) CHECK(get(uv, c.first) == c.second, "constraint bit-exact");
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(constrained_embedding_gmpq)
{
  // a small triangulated grid disk, uv in exact rationals
  Surface_mesh m;
  const int N = 6;
  std::vector<boost::graph_traits<Surface_mesh>::vertex_descriptor> V;
  for(int j = 0; j <= N; ++j)
    for(int i = 0; i <= N; ++i)
      V.push_back(m.add_vertex(Epick::Point_3(i, j, 0.1 * ((i * j) % 3))));
  for(int j = 0; j < N; ++j)
    for(int i = 0; i < N; ++i)
    {
      const auto a = V[j * (N + 1) + i], b = V[j * (N + 1) + i + 1], c = V[(j + 1) * (N + 1) + i + 1], d = V[(j + 1) * (N + 1) + i];
      m.add_face(a, b, c);
      m.add_face(a, c, d);
    }
  RUN((run_case<Kq>(m, 3, 5u, "grid Gmpq", true)));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(constrained_embedding_errors)
{
  typedef Epick::Point_2 Point_2;
  typedef boost::graph_traits<Surface_mesh>::vertex_descriptor VD;
  Surface_mesh m;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
  auto uv = make_uv_map(m, Point_2());
  CHECK(shaped_border(m, uv, PE::Border_shape::SQUARE), "border placed");
  auto C = random_constraints<Epick>(m, uv, 3, 1u);
  VD bv;
  for(auto v : vertices(m)) if(CGAL::is_border(v, m)) { bv = v; break; }
  const Snapshot<Surface_mesh, decltype(uv)> before(m, uv);
  // `failed`: the constraint the statistics must name (its index in the range)
  auto expect = [&](std::vector<std::pair<VD, Point_2> > c, PE::Error_code code, const char* what, std::size_t failed) -> int
  {
    PE::Constrained_embedding_statistics st;
    const PE::Error_code ec = PE::constrained_embedding(m, c, uv, PE::parameters::statistics(&st));
    std::cout << what << ": " << PE::get_error_message(ec) << ", constraint " << st.failed_constraint << std::endl;
    CHECK(ec == code, what);
    CHECK(st.failed_constraint == failed, what << ": the failed constraint named");
    CHECK(before.same_mesh(m) && before.same_uv(m, uv), "mesh and uv unchanged");
    return EXIT_SUCCESS;
  };
  { auto c = C; c[1].first = bv; RUN(expect(c, PE::ERROR_CONSTRAINT_ON_BORDER, "constraint on border", 1)); }
  { auto c = C; c[2].first = c[0].first; RUN(expect(c, PE::ERROR_DUPLICATE_CONSTRAINT, "same vertex twice", 2)); }
  { auto c = C; c[2].second = c[0].second; RUN(expect(c, PE::ERROR_DUPLICATE_CONSTRAINT, "same target twice", 2)); }
  { auto c = C; c[1].second = Point_2(std::numeric_limits<double>::quiet_NaN(), 0.5); RUN(expect(c, PE::ERROR_NON_FINITE_COORDINATES, "NaN target", 1)); }
  { auto c = C; c[1].second = Point_2(5, 5); RUN(expect(c, PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "target outside", 1)); }
  { auto c = C; c[2].second = get(uv, bv); RUN(expect(c, PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "target on the border", 2)); }
  {
    // a NaN 3D point (an interior vertex, not constrained): bad input, not a path that cannot be traced
    Surface_mesh m2 = m;
    auto uvn = make_uv_map(m2, Point_2());
    for(auto v : vertices(m2)) put(uvn, v, get(uv, v));
    for(auto v : vertices(m2))
      if(!CGAL::is_border(v, m2) && v != C[0].first && v != C[1].first && v != C[2].first)
      {
        m2.point(v) = Epick::Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
        break;
      }
    PE::Constrained_embedding_statistics st;
    const PE::Error_code ec = PE::constrained_embedding(m2, C, uvn, PE::parameters::statistics(&st));
    std::cout << "NaN 3D point: " << PE::get_error_message(ec) << std::endl;
    CHECK(ec == PE::ERROR_NON_FINITE_COORDINATES && st.failed_constraint == std::size_t(-1), "a NaN 3D point refused");
  }
  {
    // extreme sizes: the mesh scaled by 2^600 and by 2^-600, where squared 3D lengths overflow or underflow in
    // double (path costs, arc lengths): the same map as the mesh's own, bit for bit (a power of two is exact)
    Surface_mesh ref = m;
    auto uvr = make_uv_map(ref, Point_2());
    for(auto v : vertices(ref)) put(uvr, v, get(uv, v));
    CHECK(PE::constrained_embedding(ref, C, uvr) == PE::OK, "the mesh itself");
    for(const int e : { 600, -600 })
    {
      Surface_mesh ms = m;
      auto uvs = make_uv_map(ms, Point_2());
      for(auto v : vertices(ms))
      {
        put(uvs, v, get(uv, v));
        const Epick::Point_3 p = ms.point(v);
        ms.point(v) = Epick::Point_3(std::ldexp(p.x(), e), std::ldexp(p.y(), e), std::ldexp(p.z(), e));
      }
      PE::Constrained_embedding_statistics st;
      const PE::Error_code ec = PE::constrained_embedding(ms, C, uvs, PE::parameters::statistics(&st));
      CHECK(ec == PE::OK && st.report.is_valid(), "scaled by 2^" << e << ": " << PE::get_error_message(ec));
      CHECK(ms.number_of_vertices() == ref.number_of_vertices(), "scaled by 2^" << e << ": the same refinement");
      for(auto v : vertices(ref)) CHECK(get(uvs, v) == get(uvr, v), "scaled by 2^" << e << ": the same uv");
      std::cout << "mesh scaled by 2^" << e << ": certified, " << ms.number_of_vertices()
                << " vertices, every uv bit for bit that of the mesh itself" << std::endl;
    }
  }

  {
    // a fixed border on a figure eight (turning number 0): it bounds no immersed disk (non-convex simple
    // and weakly self-overlapping borders are accepted: test_non_convex_borders.cpp)
    auto uv2 = make_uv_map(m, Point_2());
    for(auto v : vertices(m)) put(uv2, v, get(uv, v));
    PE::internal::Indexed_disk<Surface_mesh> disk;
    CHECK(PE::internal::make_indexed_disk(m, boost::graph_traits<Surface_mesh>::null_halfedge(), disk) == PE::OK, "disk");
    const double pi = std::acos(-1.0);
    for(std::size_t k = 0; k < disk.border.size(); ++k)
    {
      const double t = 2 * pi * (double(k) + 0.5) / double(disk.border.size());
      put(uv2, disk.vertices[disk.border[k]], Point_2(0.5 + 0.4 * std::sin(2 * t), 0.5 + 0.4 * std::sin(t)));
    }
    const PE::Error_code ec = PE::constrained_embedding(m, C, uv2);
    std::cout << "figure-eight border: " << PE::get_error_message(ec) << std::endl;
    CHECK(ec == PE::ERROR_NOT_SELF_OVERLAPPING, "a border bounding no immersed disk refused");
    CHECK(before.same_mesh(m), "mesh unchanged");
  }
  {
    // a closed mesh: not a disk
    Surface_mesh closed;
    if(!read_mesh(data_dir + "/meshes/cow.off", closed)) return EXIT_FAILURE;
    auto uvc = make_uv_map(closed, Point_2());
    std::vector<std::pair<VD, Point_2> > none;
    const std::size_t nv = closed.number_of_vertices();
    CHECK(PE::constrained_embedding(closed, none, uvc) == PE::ERROR_NOT_A_DISK, "closed mesh refused");
    CHECK(closed.number_of_vertices() == nv, "closed mesh unchanged");
  }
  {
    // one border cycle, genus 3 (a closed genus-3 mesh cut open)
    Surface_mesh g3;
    if(!read_mesh(data_dir + "/meshes/elephant.off", g3)) return EXIT_FAILURE;
    std::array<VD, 3> pinned;
    CHECK(PE::internal::thingi_cut(g3, 1u, pinned) == PE::OK, "cut open");
    auto uvg = make_uv_map(g3, Point_2());
    std::vector<std::pair<VD, Point_2> > none;
    const PE::Error_code ec = PE::constrained_embedding(g3, none, uvg, PE::parameters::border_shape(PE::Border_shape::CIRCLE));
    std::cout << "genus 3: " << PE::get_error_message(ec) << std::endl;
    CHECK(ec == PE::ERROR_NOT_GENUS_ZERO, "higher genus refused");
  }
  {
    // several border cycles on a genus-3 surface
    Surface_mesh holes;
    if(!read_mesh(data_dir + "/meshes/elephant-with-holes.off", holes)) return EXIT_FAILURE;
    auto uvh = make_uv_map(holes, Point_2());
    std::vector<std::pair<VD, Point_2> > none;
    const std::size_t nv = holes.number_of_vertices();
    const PE::Error_code ec = PE::constrained_embedding(holes, none, uvh, PE::parameters::border_shape(PE::Border_shape::SQUARE));
    std::cout << "106 border cycles, genus 3: " << PE::get_error_message(ec) << std::endl;
    CHECK(ec == PE::ERROR_NOT_GENUS_ZERO, "several border cycles, higher genus refused");
    CHECK(holes.number_of_vertices() == nv, "mesh unchanged");
  }
  {
    // a time budget of zero
    const PE::Error_code ec = PE::constrained_embedding(m, C, uv, CGAL::parameters::maximum_running_time(0.));
    CHECK(ec == PE::ERROR_BUDGET_EXHAUSTED, "no time");
    CHECK(before.same_mesh(m) && before.same_uv(m, uv), "mesh and uv unchanged");
    CHECK(PE::constrained_embedding(m, C, uv, CGAL::parameters::maximum_running_time(-1.)) == PE::ERROR_WRONG_PARAMETER,
          "negative time");
  }
  {
    // 50 random targets tangle the paths: a small Steiner budget runs out, nothing is changed
    auto c50 = random_constraints<Epick>(m, uv, 50, 57u);
    const PE::Error_code ec = PE::constrained_embedding(m, c50, uv, PE::parameters::maximum_steiner_vertices(100));
    std::cout << "50 random targets, 100 Steiner vertices allowed: " << PE::get_error_message(ec) << std::endl;
    CHECK(ec == PE::ERROR_BUDGET_EXHAUSTED, "Steiner budget exhausted");
    CHECK(before.same_mesh(m) && before.same_uv(m, uv), "mesh and uv unchanged");
  }
  // no constraint: the (certified) Tutte map with the border fixed
  {
    Surface_mesh m2 = m;
    auto uv3 = make_uv_map(m2, Point_2());
    for(auto v : vertices(m2)) put(uv3, v, get(uv, v));
    std::vector<std::pair<VD, Point_2> > none;
    PE::Constrained_embedding_statistics st;
    CHECK(PE::constrained_embedding(m2, none, uv3, PE::parameters::statistics(&st)) == PE::OK, "no constraint");
    CHECK(st.steiner_vertices == 0 && st.patches == 1 && PE::check_embedding(m2, uv3).is_valid(), "one patch, valid");
    CHECK(st.failed_constraint == std::size_t(-1), "no constraint named on success");
  }
  return EXIT_SUCCESS;
}

// The pipeline's phases one by one (internal::Constrained_embedder), on the mushroom disk with 10
// random targets (winding paths: Steiner vertices to insert and to coarsen): what each phase leaves,
// its time in the statistics, and the caller's mesh and uv untouched until the last phase.
PE_TEST_GROUP(constrained_embedding_phases)
{
  typedef Epick::Point_2 Point_2;
  Surface_mesh m;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
  auto uv = make_uv_map(m, Point_2());
  for(auto v : vertices(m)) put(uv, v, Point_2(0, 0));
  CHECK(shaped_border(m, uv, PE::Border_shape::SQUARE), "border placed");
  const auto C = random_constraints<Epick>(m, uv, 10, 3u);
  const Snapshot<Surface_mesh, decltype(uv)> before(m, uv);
  PE::Constrained_embedding_statistics st;
  const auto np = PE::parameters::statistics(&st).optimization_time_limit(5.);
  typedef PE::internal::Constrained_embedder_for<CGAL::Sequential_tag, Surface_mesh, decltype(uv), decltype(np)> Embedder;
  Embedder e(m, uv, np);
  CHECK(&e.stats == &st, "the caller's statistics");
  CHECK(e.read_parameters() == PE::OK && e.optimize && e.coarsen && e.optimization_seconds == 5., "parameters read");
  CHECK(e.validate(C) == PE::OK, "validate");
  const std::size_t nv = before.verts.size();
  CHECK(st.input_vertices == nv && e.nv == nv && e.cverts.size() == C.size() && e.targets.size() == C.size()
        && e.bpos.size() == e.nb && !e.holes && !e.non_convex, "validate: mesh indexed, constraints and border read");
  CHECK(e.make_partition() == PE::OK, "partition");
  CHECK(st.paths == e.partition.edges.size() && st.paths >= C.size() && e.nbn == e.border_nodes.size() && !e.immersed
        && e.T.size() == C.size(), "partition: interior edges, border nodes");
  CHECK(e.make_working_copy() == PE::OK, "working copy");
  CHECK(static_cast<std::size_t>(num_vertices(e.work)) == nv && e.nodes.size() == e.nbn + C.size() && e.paths.empty(),
        "working copy: the mesh and its nodes");
  CHECK(e.trace() == PE::OK, "trace");
  CHECK(e.paths.size() == st.paths && st.steiner_vertices == e.steiner.size() && !e.steiner.empty()
        && static_cast<std::size_t>(num_vertices(e.work)) == nv + e.steiner.size() && st.seconds_tracing > 0,
        "trace: one path per edge, the mesh refined, timed");
  CHECK(e.map_patches() == PE::OK, "patches");
  CHECK(e.patches.size() == e.partition.polygons.size() && st.patches == e.patches.size() && st.seconds_patches > 0,
        "patches: one per polygon, timed");
  CHECK(e.certify() == PE::OK, "certify");
  CHECK(st.report_before_optimization.is_valid() && st.report.is_valid() && st.report.overlapping_pairs == 0
        && st.report.non_finite == 0, "certify: the whole certificate");
  const double energy_before = st.report.mean_energy_3d;
  CHECK(e.optimize_map() == PE::OK, "optimize");
  CHECK(st.optimized && st.report.is_valid() && st.report.mean_energy_3d < energy_before && st.seconds_optimization > 0,
        "optimize: certified, lower energy " << energy_before << " -> " << st.report.mean_energy_3d);
  const std::size_t inserted = e.steiner.size();
  CHECK(e.coarsen_map() == PE::OK, "coarsen");
  CHECK(st.steiner_vertices_inserted == inserted && st.steiner_vertices_removed == e.removals.size()
        && st.report.is_valid(), "coarsen: counted and certified");
  CHECK(e.check_constraints() == PE::OK && st.max_constraint_error == 0, "constraints bit-exact");
  CHECK(before.same_mesh(m) && before.same_uv(m, uv), "the caller's mesh and uv untouched before the output");
  CHECK(e.write_output() == PE::OK, "output");
  const std::size_t out = static_cast<std::size_t>(std::distance(vertices(m).begin(), vertices(m).end()));
  CHECK(out == nv + inserted - e.removals.size() && st.output_vertices == out && st.steiner_vertices == out - nv,
        "output: inserted minus removed");
  CHECK(before.originals_first(m), "original vertices first");
  for(const auto& c : C) CHECK(get(uv, c.first) == c.second, "constraint bit-exact on the caller's mesh");
  const PE::Embedding_report r = PE::check_embedding(m, uv);
  CHECK(r.is_valid() && r.overlapping_pairs == 0, "the caller's map certified");
  std::cout << "phases: " << nv << " -> " << out << " vertices (" << inserted << " inserted, " << e.removals.size()
            << " removed), " << st.paths << " paths, " << st.patches << " patches" << std::endl;

  // an error stops at its phase, with nothing of the caller's touched: a constraint on the border
  Surface_mesh m2;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", m2)) return EXIT_FAILURE;
  auto uv2 = make_uv_map(m2, Point_2());
  for(auto v : vertices(m2)) put(uv2, v, Point_2(0, 0));
  CHECK(shaped_border(m2, uv2, PE::Border_shape::SQUARE), "border placed");
  std::vector<std::pair<boost::graph_traits<Surface_mesh>::vertex_descriptor, Point_2> > bad;
  for(auto v : vertices(m2)) if(CGAL::is_border(v, m2)) { bad.emplace_back(v, Point_2(0.5, 0.5)); break; }
  PE::Constrained_embedding_statistics st2;
  const auto np2 = PE::parameters::statistics(&st2);
  typedef PE::internal::Constrained_embedder_for<CGAL::Sequential_tag, Surface_mesh, decltype(uv2), decltype(np2)> Embedder2;
  // another pack of named parameters, the same pipeline: compiled once per mesh type, not once per pack
  static_assert(std::is_same<Embedder, Embedder2>::value, "one Constrained_embedder for both packs");
  Embedder2 e2(m2, uv2, np2);
  CHECK(e2.run(bad) == PE::ERROR_CONSTRAINT_ON_BORDER && st2.failed_constraint == 0 && st2.paths == 0, "stopped in validate");
  return EXIT_SUCCESS;
}

// geom_traits: every sign of the uv map goes through the given traits (a counting orientation), and
// the map is the one of the default traits, bit for bit
PE_TEST_GROUP(constrained_embedding_traits)
{
  typedef Kq::Point_2 Point_2;
  Surface_mesh m0;
  PE::internal::make_grid_disk(8, m0);
  Surface_mesh m1 = m0, m2 = m0;
  auto uv1 = make_uv_map(m1, Point_2()), uv2 = make_uv_map(m2, Point_2());
  for(auto v : vertices(m1)) put(uv1, v, Point_2(0, 0));
  for(auto v : vertices(m2)) put(uv2, v, Point_2(0, 0));
  CHECK(shaped_border(m1, uv1, PE::Border_shape::SQUARE) && shaped_border(m2, uv2, PE::Border_shape::SQUARE), "borders");
  const auto C1 = random_constraints<Kq>(m1, uv1, 4, 11u);
  const auto C2 = random_constraints<Kq>(m2, uv2, 4, 11u);
  PE::Constrained_embedding_statistics s1, s2;
  CHECK(PE::constrained_embedding(m1, C1, uv1, PE::parameters::statistics(&s1).optimize(false)) == PE::OK, "default traits");
  Counting_traits::calls = 0;
  CHECK(PE::constrained_embedding(m2, C2, uv2, PE::parameters::statistics(&s2).optimize(false)
                                                 .geom_traits(Counting_traits())) == PE::OK, "counting traits");
  const std::size_t faces = count_faces(m2);
  std::cout << "geom_traits: " << Counting_traits::calls << " orientation calls for " << faces << " faces" << std::endl;
  CHECK(Counting_traits::calls >= 3 * faces, "patch maps and certificates take the given traits");
  CHECK(s1.steiner_vertices == s2.steiner_vertices && count_faces(m1) == faces, "same refinement");
  auto a = vertices(m1).begin();
  for(auto v : vertices(m2)) { CHECK(get(uv1, *a) == get(uv2, v), "same map"); ++a; }
  return EXIT_SUCCESS;
}

// phase_callback: every phase reported in order, the optimization with its energy and its time left; a
// `false` before the certificate stops the call with nothing written, in the optimization it stops the
// optimization only
PE_TEST_GROUP(constrained_embedding_progress)
{
  typedef Epick::Point_2 Point_2;
  typedef PE::Constrained_embedding_phase Phase;
  Surface_mesh m0;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", m0)) return EXIT_FAILURE;
  auto uv0 = make_uv_map(m0, Point_2());
  for(auto v : vertices(m0)) put(uv0, v, Point_2(0, 0));
  CHECK(shaped_border(m0, uv0, PE::Border_shape::SQUARE), "border placed");
  const auto C0 = random_constraints<Epick>(m0, uv0, 10, 3u);
  std::vector<std::size_t> index; // constraints by vertex position, to rebuild them on copies
  {
    std::vector<boost::graph_traits<Surface_mesh>::vertex_descriptor> verts(vertices(m0).begin(), vertices(m0).end());
    for(const auto& c : C0) index.push_back(static_cast<std::size_t>(std::find(verts.begin(), verts.end(), c.first) - verts.begin()));
  }
  auto copy_case = [&](Surface_mesh& m) {
    m = m0;
    std::vector<boost::graph_traits<Surface_mesh>::vertex_descriptor> verts(vertices(m).begin(), vertices(m).end());
    std::vector<std::pair<boost::graph_traits<Surface_mesh>::vertex_descriptor, Point_2> > C;
    for(std::size_t i = 0; i < C0.size(); ++i) C.emplace_back(verts[index[i]], C0[i].second);
    return C;
  };
  {
    Surface_mesh m;
    const auto C = copy_case(m);
    auto uv = make_uv_map(m, Point_2());
    for(auto v : vertices(m)) put(uv, v, get(uv0, v));
    std::vector<PE::Constrained_embedding_progress> seen;
    const std::function<bool(const PE::Constrained_embedding_progress&)> cb =
      [&seen](const PE::Constrained_embedding_progress& p) { seen.push_back(p); return true; };
    PE::Constrained_embedding_statistics st;
    CHECK(PE::constrained_embedding(m, C, uv, PE::parameters::phase_callback(cb).statistics(&st).optimization_time_limit(3.)) == PE::OK, "OK");
    std::vector<Phase> order;
    for(const auto& p : seen) if(order.empty() || order.back() != p.phase) order.push_back(p.phase);
    const std::vector<Phase> expected = { Phase::VALIDATION, Phase::PARTITION, Phase::TRACING, Phase::PATCHES, Phase::CERTIFICATION,
                                          Phase::OPTIMIZATION, Phase::COARSENING, Phase::OUTPUT };
    // the optimization may run again after the coarsening
    if(order.size() == expected.size() + 1 && order[order.size() - 2] == Phase::OPTIMIZATION) order.erase(order.end() - 2);
    CHECK(order == expected, "every phase, in order (" << order.size() << " changes)");
    std::size_t iterations = 0;
    for(const auto& p : seen)
    {
      CHECK(p.seconds >= 0 && p.seconds_left == std::numeric_limits<double>::infinity() && p.fraction >= 0 && p.fraction <= 1, "times");
      if(p.phase != Phase::OPTIMIZATION || p.fraction == 0) { CHECK(p.energy != p.energy, "no energy outside the iterations"); continue; }
      ++iterations;
      CHECK(std::isfinite(p.energy) && p.energy >= 4 && p.optimization_seconds_left <= 3., "energy " << p.energy << ", left " << p.optimization_seconds_left);
    }
    CHECK(iterations == st.optimization.iterations + st.reoptimization.iterations && iterations > 0,
          "one report per iteration: " << iterations);
  }
  {
    Surface_mesh m;
    const auto C = copy_case(m);
    auto uv = make_uv_map(m, Point_2());
    for(auto v : vertices(m)) put(uv, v, get(uv0, v));
    const Snapshot<Surface_mesh, decltype(uv)> before(m, uv);
    const std::function<bool(const PE::Constrained_embedding_progress&)> stop_tracing =
      [](const PE::Constrained_embedding_progress& p) { return p.phase != Phase::TRACING; };
    CHECK(PE::constrained_embedding(m, C, uv, PE::parameters::phase_callback(stop_tracing)) == PE::ERROR_BUDGET_EXHAUSTED,
          "stopped before tracing");
    CHECK(before.same_mesh(m) && before.same_uv(m, uv), "nothing written");
  }
  {
    Surface_mesh m;
    const auto C = copy_case(m);
    auto uv = make_uv_map(m, Point_2());
    for(auto v : vertices(m)) put(uv, v, get(uv0, v));
    std::size_t calls = 0;
    const std::function<bool(const PE::Constrained_embedding_progress&)> two_iterations =
      [&calls](const PE::Constrained_embedding_progress& p) { return p.phase != Phase::OPTIMIZATION || p.fraction == 0 || ++calls < 2; };
    PE::Constrained_embedding_statistics st;
    CHECK(PE::constrained_embedding(m, C, uv, PE::parameters::phase_callback(two_iterations).statistics(&st)) == PE::OK, "OK");
    CHECK(st.optimized && st.optimization.iterations == 2 && st.optimization_status == PE::ERROR_BUDGET_EXHAUSTED
          && !st.reoptimized && st.report.is_valid(), "the optimization stopped after 2 iterations, the map certified");
    const PE::Embedding_report r = PE::check_embedding(m, uv);
    CHECK(r.is_valid(), "the caller's map certified");
    for(const auto& c : C) CHECK(get(uv, c.first) == c.second, "constraint bit-exact");
  }
  return EXIT_SUCCESS;
}

// The paths in the class of the targets' straight-line motion: with 50 random targets (paths that wind),
// the kinetic tracing runs; whichever tracing is kept, the map is certified on the caller's mesh with its
// constraints bit-exact (run_case), and never with more vertices than without it (the same inputs,
// kinetic_tracing(false)). On this input it is kept: 38.5k Steiner vertices against 64.7k.
PE_TEST_GROUP(constrained_embedding_kinetic)
{
  std::size_t wins = 0;
  for(unsigned seed : { 3u })
  {
    PE::Constrained_embedding_statistics with, without;
    {
      Surface_mesh m;
      if(!read_mesh(data_dir + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
      RUN((run_case<Epick>(m, 50, seed, "mushroom kinetic", true, PE::Border_shape::SQUARE, false, 2000000, &with, false, true)));
    }
    {
      Surface_mesh m;
      if(!read_mesh(data_dir + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
      RUN((run_case<Epick>(m, 50, seed, "mushroom without kinetic", true, PE::Border_shape::SQUARE, false, 2000000, &without, false, false)));
    }
    CHECK(with.kinetic_tracing && with.kinetic_flips > 0 && !without.kinetic_tracing, "the kinetic tracing ran (flips " << with.kinetic_flips << ")");
    CHECK(with.steiner_vertices <= without.steiner_vertices, "never more vertices: " << with.steiner_vertices << " vs " << without.steiner_vertices);
    CHECK(with.kinetic_tracing_kept == (with.kinetic_motion >= 0) && with.kinetic_motion < 5 && without.kinetic_motion == -1,
          "the kept motion reported: " << with.kinetic_motion);
    if(with.kinetic_tracing_kept)
    {
      ++wins;
      CHECK(!with.overlay_tracing_kept && !with.guided_tracing_kept, "one tracing kept");
      CHECK(with.steiner_vertices < without.steiner_vertices, "kept because it added fewer vertices");
    }
  }
  CHECK(wins >= 1, "the kinetic tracing kept at least once");
  return EXIT_SUCCESS;
}

// The motion itself (kinetic_triangulation.h) on random points of a 24-gon: the start triangulation has
// 2n - h - 2 counterclockwise triangles at the start positions; replaying the flips on it gives the end
// triangulation, every triangle counterclockwise at the targets (exactly); each flip replaces an edge of
// the current triangulation by the other diagonal of its quadrilateral. Bad inputs fail.
PE_TEST_GROUP(kinetic_triangulation)
{
  namespace PI = CGAL::Progressive_embedding::internal;
  typedef std::array<double, 2> P2;
  std::vector<P2> border;
  for(int k = 0; k < 24; ++k) border.push_back({ { std::cos(2 * CGAL_PI * k / 24), std::sin(2 * CGAL_PI * k / 24) } });
  auto orient = [](const P2& a, const P2& b, const P2& c) {
    return CGAL::orientation(Epick::Point_2(a[0], a[1]), Epick::Point_2(b[0], b[1]), Epick::Point_2(c[0], c[1]));
  };
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-0.6, 0.6);
  std::size_t total_flips = 0;
  for(std::size_t n : { 1, 5, 20, 60 })
  for(int motion = 0; motion < 3; ++motion)
  {
    std::vector<P2> start(n), end(n);
    for(std::size_t i = 0; i < n; ++i) { start[i] = { { U(rng), U(rng) } }; end[i] = { { U(rng), U(rng) } }; }
    PI::Kinetic_triangulation kt;
    if(motion == 0)
      CHECK(PI::kinetic_triangulation(border, start, end, 1000000, kt), "motion of " << n << " points");
    else
    {
      // a permutation braid along x (motion 1) or y (motion 2): four waypoints, the ends given
      const auto w = PI::permutation_braid_waypoints(border, start, end, motion == 1 ? 0. : 0.5 * CGAL_PI);
      CHECK(w.size() == 4 && w.front() == start && w.back() == end, "waypoints of a permutation braid");
      CHECK(PI::kinetic_triangulation(border, w, 1000000, kt), "braid motion of " << n << " points");
    }
    const std::size_t nb = border.size(), nn = nb + n;
    CHECK(kt.initial.size() == 2 * nn - nb - 2 && kt.final_triangles.size() == kt.initial.size(), "triangle counts");
    auto pos = [&](std::size_t v, bool at_end) -> const P2& { return v < nb ? border[v] : (at_end ? end[v - nb] : start[v - nb]); };
    for(const auto& t : kt.initial) CHECK(orient(pos(t[0], false), pos(t[1], false), pos(t[2], false)) == CGAL::LEFT_TURN, "start ccw");
    for(const auto& t : kt.final_triangles) CHECK(orient(pos(t[0], true), pos(t[1], true), pos(t[2], true)) == CGAL::LEFT_TURN, "end ccw");
    // replay: triangles as sorted triples, edges by id
    std::multiset<std::array<std::size_t, 3> > tris;
    auto key = [](std::size_t a, std::size_t b, std::size_t c) { std::array<std::size_t, 3> k{ { a, b, c } }; std::sort(k.begin(), k.end()); return k; };
    for(const auto& t : kt.initial) tris.insert(key(t[0], t[1], t[2]));
    std::vector<std::array<std::size_t, 2> > edge = kt.edges;
    for(const auto& f : kt.flips)
    {
      CHECK(f.edge < edge.size() && std::minmax(edge[f.edge][0], edge[f.edge][1]) == std::minmax(f.a, f.b), "the flipped edge is current");
      auto t1 = tris.find(key(f.a, f.b, f.c)), t2 = tris.find(key(f.a, f.b, f.d));
      CHECK(t1 != tris.end() && t2 != tris.end() && f.c != f.d, "its two triangles are current");
      tris.erase(t1); tris.erase(tris.find(key(f.a, f.b, f.d)));
      tris.insert(key(f.a, f.d, f.c)); tris.insert(key(f.c, f.d, f.b));
      edge[f.edge] = { { f.c, f.d } };
      for(std::ptrdiff_t side : { f.ca, f.cb, f.db, f.da })
        CHECK(side < static_cast<std::ptrdiff_t>(edge.size()), "side ids");
    }
    std::multiset<std::array<std::size_t, 3> > fin;
    for(const auto& t : kt.final_triangles) fin.insert(key(t[0], t[1], t[2]));
    CHECK(fin == tris, "the flips lead from the start to the end triangulation");
    // the end triangulation merged into convex polygons (as the Delaunay partition is); the start one,
    // not valid at the targets once points crossed edges, refused
    std::vector<Epick::Point_2> bp, ep;
    for(const P2& p : border) bp.emplace_back(p[0], p[1]);
    for(const P2& p : end) ep.emplace_back(p[0], p[1]);
    PI::Domain_partition part;
    CHECK(PI::merge_triangulation(bp, ep, kt.final_triangles, part) == PE::OK && !part.polygons.empty()
          && part.polygons.size() <= kt.final_triangles.size() && part.number_of_targets == n, "end triangulation merged");
    if(!kt.flips.empty())
      CHECK(PI::merge_triangulation(bp, ep, kt.initial, part) == PE::ERROR_DEGENERATE_BORDER, "start triangulation refused at the targets");
    total_flips += kt.flips.size();
    // the proxy of how much the curves wind: every curve crosses the subdivided start triangulation at least
    // once, and exactly once (its own edge's replacement) when nothing moved across an edge
    const std::size_t proxy = PI::kinetic_proxy_crossings(kt, border, start, 100000000, 60.);
    CHECK(proxy != std::size_t(-1) && proxy >= kt.edges.size() && (!kt.flips.empty() || proxy == kt.edges.size()),
          "proxy crossings " << proxy << " of " << kt.edges.size() << " curves");
    // a cap below the count stops it (constrained_embedding() caps the motions that would not be traced)
    CHECK(PI::kinetic_proxy_crossings(kt, border, start, proxy - 1, 60.) == std::size_t(-1), "capped proxy");
    std::cout << "  " << n << " moving points, motion " << motion << ": " << kt.initial.size() << " triangles, "
              << kt.flips.size() << " flips, " << proxy << " proxy crossings" << std::endl;
  }
  CHECK(total_flips > 0, "points crossed edges");
  {
    // two points at the same x at the start: no braid along x (they would meet on the way to the band), one along y
    const std::vector<P2> s{ { { 0.1, 0.3 } }, { { 0.1, -0.3 } } }, e{ { { 0.2, -0.1 } }, { { -0.2, 0.1 } } };
    CHECK(PI::permutation_braid_waypoints(border, s, e, 0.).empty(), "a tie along the direction: no waypoints");
    const auto w = PI::permutation_braid_waypoints(border, s, e, 0.5 * CGAL_PI);
    PI::Kinetic_triangulation kt;
    CHECK(w.size() == 4 && PI::kinetic_triangulation(border, w, 1000, kt), "the other direction moves");
  }
  {
    PI::Kinetic_triangulation kt;
    std::vector<P2> s{ { { 0.1, 0.1 } }, { { 0.1, 0.1 } } }, e{ { { 0.2, 0.1 } }, { { -0.2, 0.1 } } };
    CHECK(!PI::kinetic_triangulation(border, s, e, 1000, kt), "two equal start points refused");
    s = { { { 0.1, 0.1 } } }; e = { { { 1.5, 0.1 } } };
    CHECK(!PI::kinetic_triangulation(border, s, e, 1000, kt), "a target outside refused");
    s = { { { -0.5, 0.0 } }, { { 0.0, 0.05 } }, { { 0.0, -0.05 } } }; e = { { { 0.5, 0.0 } }, { { 0.0, 0.05 } }, { { 0.0, -0.05 } } };
    CHECK(!PI::kinetic_triangulation(border, s, e, 0, kt), "no flip allowed: the budget runs out");
  }
  return EXIT_SUCCESS;
}
