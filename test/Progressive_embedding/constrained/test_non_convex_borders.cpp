// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// constrained_embedding() onto fixed borders that are not convex: simple polygons (an L, a comb, a star) give
// certified embeddings, with and without constraints; a rectilinear strip winding 1.25 times around a
// square (weakly self-overlapping) gives a certified immersion (a mushroom; 10x10 to 30x30 grids, whose
// partition corners at paths must turn by a margin, see partition_corners_robust), and so does a spiral
// strip winding twice; constraints on it,
// and a polygon that bounds no immersed disk, give clear errors with the mesh and uv untouched. A border that
// wraps around one of its vertices (a fan winding 1.25 and 2.25 turns) maps with its rotation indices
// (border_rotation_indices, vertex_rotation_index_map); border points interpolated in double along the
// slanted sides of a spiral strip, which turn by rounding only, still give a certified immersion.

#include <CGAL/Progressive_embedding/constrained_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/check_immersion.h>
#include <CGAL/Progressive_embedding/triangulate_self_overlapping_polygon_2.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>

#include "registry.h"
#include "polygon_fixtures.h"
#include "mesh_fixtures.h"
#include "../test_util.h"
#include <CGAL/Progressive_embedding/internal/disk_generators.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>

#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

namespace PE = CGAL::Progressive_embedding;
typedef Epick::Point_2 P2;

// Places the border of m on the polygon Q (axis-parallel sides, in the border order of
// make_indexed_disk: interior on the left) by 3D arc length: corner j goes to the border vertex whose
// arc-length fraction is nearest to the corner's perimeter fraction (distinct, in order), the vertices
// between two corners are spread on the side between them (one coordinate exactly constant).
template <class Mesh, class UVM>
bool border_on_polygon(const Mesh& m, UVM& uv, const std::vector<P2>& Q)
{
  PE::internal::Indexed_disk<Mesh> disk;
  if(PE::internal::make_indexed_disk(m, boost::graph_traits<Mesh>::null_halfedge(), disk) != PE::OK) return false;
  const std::size_t nb = disk.border.size(), nq = Q.size();
  if(nb < 2 * nq) return false;
  std::vector<double> s(nb + 1, 0.);
  for(std::size_t k = 0; k < nb; ++k)
  {
    const auto p = get(CGAL::vertex_point, m, disk.vertices[disk.border[k]]);
    const auto q = get(CGAL::vertex_point, m, disk.vertices[disk.border[(k + 1) % nb]]);
    s[k + 1] = s[k] + std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q)));
  }
  std::vector<double> t(nq + 1, 0.);
  for(std::size_t j = 0; j < nq; ++j) t[j + 1] = t[j] + std::sqrt(CGAL::squared_distance(Q[j], Q[(j + 1) % nq]));
  std::vector<std::size_t> at(nq, 0);
  for(std::size_t j = 1; j < nq; ++j)
  {
    const double f = t[j] / t[nq];
    std::size_t best = at[j - 1] + 1;
    for(std::size_t k = best; k + (nq - j) < nb; ++k)
      if(std::abs(s[k] / s[nb] - f) < std::abs(s[best] / s[nb] - f)) best = k;
    at[j] = best;
  }
  for(std::size_t j = 0; j < nq; ++j)
  {
    const std::size_t a = at[j], b = (j + 1 < nq) ? at[j + 1] : nb;
    const P2 A = Q[j], B = Q[(j + 1) % nq];
    for(std::size_t k = a; k < b; ++k)
    {
      const double u = (s[k] - s[a]) / (s[b] - s[a]);
      // axis-parallel sides: the constant coordinate is copied, the other interpolated
      const double x = A.x() == B.x() ? A.x() : A.x() + u * (B.x() - A.x());
      const double y = A.y() == B.y() ? A.y() : A.y() + u * (B.y() - A.y());
      put(uv, disk.vertices[disk.border[k]], P2(x, y));
    }
  }
  return true;
}

// `max_energy`: a bound on the mean 3D energy of the certified map before optimization (sliver pieces of the
// partition give certified maps with huge energies)
template <class Mesh>
int embed_on(const std::string& what, Mesh m, const std::vector<P2>& Q, const std::vector<P2>& targets, bool expect_immersion,
             double max_energy = std::numeric_limits<double>::infinity())
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor VD;
  auto uv = make_uv_map(m, P2());
  for(auto v : vertices(m)) put(uv, v, P2(0, 0));
  CHECK(border_on_polygon(m, uv, Q), "border placed on the polygon");
  std::vector<std::pair<VD, P2> > C;
  std::vector<VD> interior;
  for(auto v : vertices(m)) if(!CGAL::is_border(v, m)) interior.push_back(v);
  std::mt19937 rng(7);
  std::shuffle(interior.begin(), interior.end(), rng);
  for(std::size_t i = 0; i < targets.size(); ++i) C.emplace_back(interior[i], targets[i]);
  std::vector<VD> border;
  std::vector<P2> border_uv;
  for(auto v : vertices(m)) if(CGAL::is_border(v, m)) { border.push_back(v); border_uv.push_back(get(uv, v)); }
  PE::Constrained_embedding_statistics st;
  const PE::Error_code ec = PE::constrained_embedding(m, C, uv, PE::parameters::statistics(&st));
  std::cout << what << ", " << targets.size() << " targets: " << PE::get_error_message(ec) << ", vertices "
            << st.input_vertices << " -> " << st.output_vertices << ", Steiner " << st.steiner_vertices << ", paths "
            << st.paths << ", patches " << st.patches << ", immersion " << st.immersion << ", seconds " << st.seconds_total
            << "; mean energy " << st.report_before_optimization.mean_energy_3d << " -> " << st.report.mean_energy_3d << std::endl;
  CHECK(ec == PE::OK, "constrained_embedding OK");
  CHECK(st.report_before_optimization.mean_energy_3d < max_energy, "mean energy " << st.report_before_optimization.mean_energy_3d
        << " before optimization, at most " << max_energy << " expected");
  for(std::size_t i = 0; i < border.size(); ++i) CHECK(get(uv, border[i]) == border_uv[i], "border bit-exact");
  for(const auto& c : C) CHECK(get(uv, c.first) == c.second, "constraint bit-exact");
  const PE::Immersion_report ir = PE::check_immersion(m, uv);
  std::cout << "  " << ir.summary() << std::endl;
  CHECK(ir.is_immersion(), "certified immersion on the caller's mesh");
  const PE::Embedding_report er = PE::check_embedding(m, uv);
  if(expect_immersion)
  {
    CHECK(st.immersion && st.immersion_report.is_immersion() && st.immersion_report.border_mismatches == 0,
          "reported as a certified immersion");
    CHECK(st.optimized && (st.optimization_status == PE::OK || st.optimization_status == PE::ERROR_BUDGET_EXHAUSTED)
          && st.optimization.immersion && st.report.mean_energy_3d < st.report_before_optimization.mean_energy_3d,
          "optimized as an immersion, energy lowered");
    CHECK(!er.border_simple, "an immersion of an overlapping border is not an embedding");
  }
  else
  {
    std::cout << "  " << er.summary() << std::endl;
    CHECK(!st.immersion && er.is_valid() && er.flipped == 0 && er.degenerate == 0 && er.overlapping_pairs == 0,
          "certified embedding on the caller's mesh");
    CHECK(st.optimized && st.report.is_valid(), "optimized, certified");
  }
  return EXIT_SUCCESS;
}

// The partition of the immersed domain bounded by Q (the border of m placed by border_on_polygon):
// every polygon corner between a border side and an interior edge (a traced path) turns by a sine
// above 2^-20 (in double: a margin, not a certificate).
int partition_corners_robust(const Surface_mesh& m, const std::vector<P2>& Q)
{
  Surface_mesh copy = m;
  auto cuv = make_uv_map(copy, P2());
  CHECK(border_on_polygon(copy, cuv, Q), "border placed");
  PE::internal::Indexed_disk<Surface_mesh> disk;
  CHECK(PE::internal::make_indexed_disk(copy, boost::graph_traits<Surface_mesh>::null_halfedge(), disk) == PE::OK, "a disk");
  std::vector<P2> B;
  for(std::size_t k : disk.border) B.push_back(get(cuv, disk.vertices[k]));
  std::vector<std::array<std::size_t, 3> > triangles;
  CHECK(PE::triangulate_self_overlapping_polygon_2(B, std::back_inserter(triangles)) == PE::OK, "weakly self-overlapping");
  PE::internal::Domain_partition partition;
  PE::internal::Domain_partition_options options;
  options.allow_flat_border_vertices = true;
  CHECK(PE::internal::partition_immersed_domain(B, triangles, partition, options) == PE::OK, "immersed partition");
  const auto sides = PE::internal::polygon_side_edges(partition);
  std::size_t path_corners = 0;
  for(std::size_t f = 0; f < partition.polygons.size(); ++f)
  {
    const std::vector<std::size_t>& P = partition.polygons[f];
    for(std::size_t k = 0, n = P.size(); k < n; ++k)
    {
      const std::size_t km = (k + n - 1) % n;
      if((sides[f][km] < 0) == (sides[f][k] < 0)) continue; // the border's own corner, or two paths
      ++path_corners;
      const P2 &a = B[P[km]], &u = B[P[k]], &b = B[P[(k + 1) % n]];
      const double ax = u.x() - a.x(), ay = u.y() - a.y(), bx = b.x() - u.x(), by = b.y() - u.y();
      const double sine = (ax * by - ay * bx) / (std::sqrt(ax * ax + ay * ay) * std::sqrt(bx * bx + by * by));
      CHECK(sine > std::ldexp(1., -20), "a corner at a path turns by more than the margin");
    }
  }
  std::cout << "  partition: " << partition.edges.size() << " interior edges, " << partition.polygons.size()
            << " polygons, " << path_corners << " corners between a path and the border, all turning by a sine above 2^-20"
            << std::endl;
  CHECK(path_corners > 0, "corners at paths checked");
  return EXIT_SUCCESS;
}

// an L: the unit square without its upper right quarter; a comb with three teeth
std::vector<P2> l_shape() { return { P2(0, 0), P2(1, 0), P2(1, 0.5), P2(0.5, 0.5), P2(0.5, 1), P2(0, 1) }; }
std::vector<P2> comb()
{
  return { P2(0, 0), P2(5, 0), P2(5, 3), P2(4, 3), P2(4, 1), P2(3, 1), P2(3, 3), P2(2, 3), P2(2, 1), P2(1, 1), P2(1, 3), P2(0, 3) };
}
// a strip of width 1 along the square path (1,0) -> (4,0) -> (4,4) -> (0,4) -> (0,0) -> (3,0): it winds
// 1.25 times and its last part lies on its first one (weakly self-overlapping, not simple)
std::vector<P2> spiral_strip()
{
  return { P2(1, -0.5), P2(4.5, -0.5), P2(4.5, 4.5), P2(-0.5, 4.5), P2(-0.5, -0.5), P2(3, -0.5),
           P2(3, 0.5), P2(0.5, 0.5), P2(0.5, 3.5), P2(3.5, 3.5), P2(3.5, 0.5), P2(1, 0.5) };
}

// a star with 8 tips (radii 1 and 0.4): simple, not convex, no side axis-parallel
std::vector<P2> star8()
{
  std::vector<P2> Q;
  const double pi = std::acos(-1.);
  for(int k = 0; k < 16; ++k)
  {
    const double r = (k % 2) ? 0.4 : 1.0;
    Q.push_back(P2(r * std::cos(pi * k / 8), r * std::sin(pi * k / 8)));
  }
  return Q;
}
// a strip of width 0.6 along the spiral r = 1 + 0.3 t / (2 pi), t in [0, 4 pi], 12 vertices per side:
// it winds twice and each turn overlaps the previous one (weakly self-overlapping, not simple)
std::vector<P2> spiral_twice()
{
  std::vector<P2> Q;
  const double two_pi = 2 * std::acos(-1.);
  const int m = 12;
  for(int k = 0; k < m; ++k)
  {
    const double t = 2 * two_pi * k / (m - 1);
    Q.push_back(P2((1.6 + 0.3 * t / two_pi) * std::cos(t), (1.6 + 0.3 * t / two_pi) * std::sin(t)));
  }
  for(int k = m; k-- > 0; )
  {
    const double t = 2 * two_pi * k / (m - 1);
    Q.push_back(P2((1 + 0.3 * t / two_pi) * std::cos(t), (1 + 0.3 * t / two_pi) * std::sin(t)));
  }
  return Q;
}

// The paper's stress test: a disk onto the outline of the Hilbert curve of order 3 (104 corners), with
// constraints or not. Nested partition edges squeeze shortest paths into corridors; the guided second tracing
// (`guided_tracing` in the statistics) helps. Not optimized (the test is about the map).
int hilbert_map(const std::string& what, Surface_mesh m, const std::vector<P2>& targets, bool* guided)
{
  typedef boost::graph_traits<Surface_mesh>::vertex_descriptor VD;
  auto uv = make_uv_map(m, P2());
  for(auto v : vertices(m)) put(uv, v, P2(0, 0));
  const std::vector<P2> Q = pe_test::hilbert_corners(3);
  CHECK(Q.size() == 104, "Hilbert outline of order 3: 104 corners");
  CHECK(border_on_polygon(m, uv, Q), "border placed on the Hilbert outline");
  std::vector<std::pair<VD, P2> > C;
  std::vector<VD> interior;
  for(auto v : vertices(m)) if(!CGAL::is_border(v, m)) interior.push_back(v);
  std::mt19937 rng(11);
  std::shuffle(interior.begin(), interior.end(), rng);
  for(std::size_t i = 0; i < targets.size(); ++i) C.emplace_back(interior[i], targets[i]);
  std::vector<std::pair<VD, P2> > border;
  for(auto v : vertices(m)) if(CGAL::is_border(v, m)) border.emplace_back(v, get(uv, v));
  PE::Constrained_embedding_statistics st;
  const PE::Error_code ec = PE::constrained_embedding(m, C, uv, PE::parameters::optimize(false, PE::parameters::statistics(&st)));
  std::cout << what << ": " << PE::get_error_message(ec) << ", vertices " << st.input_vertices << " -> " << st.output_vertices
            << ", Steiner " << st.steiner_vertices << ", paths " << st.paths << ", patches " << st.patches
            << ", guided tracing " << st.guided_tracing << " (kept " << st.guided_tracing_kept << "), seconds " << st.seconds_total << std::endl;
  CHECK(ec == PE::OK, "constrained_embedding OK");
  for(const auto& b : border) CHECK(get(uv, b.first) == b.second, "border bit-exact");
  for(const auto& c : C) CHECK(get(uv, c.first) == c.second, "constraint bit-exact");
  const PE::Embedding_report er = PE::check_embedding(m, uv);
  std::cout << "  " << er.summary() << std::endl;
  CHECK(er.is_valid() && er.flipped == 0 && er.degenerate == 0 && er.overlapping_pairs == 0, "certified embedding");
  CHECK(st.output_vertices == st.input_vertices + st.steiner_vertices, "Steiner vertices counted");
  *guided = st.guided_tracing;
  return EXIT_SUCCESS;
}

// ---- borders that wrap around a vertex ---------------------------------------------------------

typedef boost::graph_traits<Surface_mesh>::vertex_descriptor Sm_vertex;

// the wrapped fan mesh (mesh_fixtures.h) with its uv map; the center (the wrapped border vertex) is the first vertex
template <class UVM>
void fill_uv(const Surface_mesh& m, UVM& uv, const std::vector<std::array<double, 2> >& uvs)
{
  std::size_t i = 0;
  for(auto v : vertices(m)) { put(uv, v, P2(uvs[i][0], uvs[i][1])); ++i; }
}

// the sum of the face corners at v (double), counterclockwise
template <class UVM>
double corner_sum(const Surface_mesh& m, const UVM& uv, Sm_vertex v)
{
  double sum = 0;
  for(auto h : CGAL::halfedges_around_target(halfedge(v, m), m))
  {
    if(CGAL::is_border(h, m)) continue;
    const P2 o = get(uv, v), a = get(uv, target(next(h, m), m)), b = get(uv, source(h, m));
    const double ux = a.x() - o.x(), uy = a.y() - o.y(), wx = b.x() - o.x(), wy = b.y() - o.y();
    sum += std::atan2(ux * wy - uy * wx, ux * wx + uy * wy);
  }
  return sum;
}

// constrained_embedding onto the border of a fan winding `angle` (r full turns beyond 2 pi) around its center:
// the indices read by border_rotation_indices, errors without them or with a negative one (mesh and uv
// untouched), then a certified immersion with the border bit-exact and the same angle at the center.
int wrapped_border(double angle, std::size_t steps, std::size_t rings, int r)
{
  const std::string what = "fan of " + std::to_string(steps) + " steps, " + std::to_string(rings) + " rings, r = " + std::to_string(r);
  Surface_mesh m;
  const std::vector<std::array<double, 2> > uvs = pe_test::make_wrapped_fan_mesh(m, angle, steps, rings);
  auto uv = make_uv_map(m, P2());
  fill_uv(m, uv, uvs);
  const Sm_vertex center = *vertices(m).begin();
  CHECK(CGAL::is_border(center, m), what << ": the center is a border vertex");
  std::size_t interior = 0;
  for(auto v : vertices(m)) if(!CGAL::is_border(v, m)) ++interior;
  CHECK(interior == (rings - 1) * (steps - 1), what << ": " << interior << " interior vertices");
  CHECK(std::abs(corner_sum(m, uv, center) - angle) < 1e-9, what << ": the input's angle at the center");

  auto turns = m.add_property_map<Sm_vertex, int>("v:test_turns", -7).first;
  const int total = PE::border_rotation_indices(m, uv, turns);
  const PE::Immersion_report in = PE::check_immersion(m, uv, PE::parameters::vertex_rotation_index_map(turns));
  CHECK(in.is_immersion() && in.max_border_turns == std::size_t(r), what << ": the input map is an immersion: " << in.summary());
  const PE::Immersion_report in0 = PE::check_immersion(m, uv);
  CHECK(in0.is_immersion() == (r == 0) && in0.border_angle_errors == (r == 0 ? 0u : 1u),
        what << ": without its rotation index, the wrapped center counts as an error: " << in0.summary());
  CHECK(total == r && get(turns, center) == r, what << ": border_rotation_indices " << total << ", center " << get(turns, center));
  for(auto v : vertices(m))
    CHECK(get(turns, v) == (v == center ? r : CGAL::is_border(v, m) ? 0 : -7), what << ": index of vertex " << v);

  std::vector<std::pair<Sm_vertex, P2> > border;
  for(auto v : vertices(m)) if(CGAL::is_border(v, m)) border.emplace_back(v, get(uv, v));
  const std::vector<std::pair<Sm_vertex, P2> > no_constraints;

  // errors: mesh and uv untouched
  auto expect = [&](PE::Error_code want, bool with_map, const char* why) -> int {
    Surface_mesh c;
    pe_test::make_wrapped_fan_mesh(c, angle, steps, rings);
    auto cuv = make_uv_map(c, P2());
    fill_uv(c, cuv, uvs);
    auto ct = c.add_property_map<Sm_vertex, int>("v:test_turns", 0).first;
    PE::border_rotation_indices(c, cuv, ct);
    if(with_map) put(ct, *vertices(c).begin(), -1);
    const std::size_t nv = c.number_of_vertices(), nf = c.number_of_faces();
    const PE::Error_code ec = with_map ? PE::constrained_embedding(c, no_constraints, cuv, PE::parameters::vertex_rotation_index_map(ct))
                                       : PE::constrained_embedding(c, no_constraints, cuv);
    CHECK(ec == want, what << ", " << why << ": " << PE::get_error_name(ec));
    CHECK(c.number_of_vertices() == nv && c.number_of_faces() == nf, what << ", " << why << ": mesh unchanged");
    std::size_t i = 0;
    for(auto v : vertices(c)) { CHECK(get(cuv, v) == P2(uvs[i][0], uvs[i][1]), what << ", " << why << ": uv unchanged"); ++i; }
    return EXIT_SUCCESS;
  };
  RUN(expect(PE::ERROR_NOT_SELF_OVERLAPPING, false, "without the rotation indices"));
  RUN(expect(PE::ERROR_WRONG_PARAMETER, true, "a negative index"));

  PE::Constrained_embedding_statistics st;
  const PE::Error_code ec = PE::constrained_embedding(m, no_constraints, uv,
                              PE::parameters::vertex_rotation_index_map(turns).statistics(&st));
  std::cout << what << ": " << PE::get_error_message(ec) << ", vertices " << st.input_vertices << " -> " << st.output_vertices
            << ", Steiner " << st.steiner_vertices << ", paths " << st.paths << ", patches " << st.patches
            << ", immersion " << st.immersion << ", optimized " << st.optimized << std::endl;
  CHECK(ec == PE::OK, what << ": constrained_embedding " << PE::get_error_name(ec));
  CHECK(st.immersion && st.immersion_report.is_immersion() && st.immersion_report.border_mismatches == 0
        && st.immersion_report.flipped == 0 && st.immersion_report.degenerate == 0, what << ": certified immersion in the statistics");
  for(const auto& b : border) CHECK(get(uv, b.first) == b.second, what << ": border bit-exact");
  const PE::Immersion_report ir = PE::check_immersion(m, uv, PE::parameters::vertex_rotation_index_map(turns));
  std::cout << "  " << ir.summary() << std::endl;
  CHECK(ir.is_immersion() && ir.flipped == 0 && ir.degenerate == 0 && ir.winding_errors == 0 && ir.border_angle_errors == 0,
        what << ": check_immersion on the caller's mesh, with the input's rotation indices");
  CHECK(!PE::check_embedding(m, uv).is_valid(), what << ": a wrapped border is no embedding");
  // the map wraps as the input did: the same angle at the center, the same indices read back
  CHECK(std::abs(corner_sum(m, uv, center) - angle) < 1e-9, what << ": angle " << corner_sum(m, uv, center) << " at the center");
  auto back = m.add_property_map<Sm_vertex, int>("v:test_turns_back", 0).first;
  CHECK(PE::border_rotation_indices(m, uv, back) == r && get(back, center) == r, what << ": the indices read back");
  CHECK(st.output_vertices == st.input_vertices + st.steiner_vertices && pe_test::count_vertices(m) == st.output_vertices,
        what << ": vertices counted");
  return EXIT_SUCCESS;
}

// Places the border of m on the polygon Q like border_on_polygon, and returns how many border vertices turn by
// rounding only: not exactly collinear with their neighbours, but by a sine below 1e-12 (points interpolated in
// double along a slanted side)
template <class UVM>
std::size_t rounding_turns(const Surface_mesh& m, const UVM& uv)
{
  PE::internal::Indexed_disk<Surface_mesh> disk;
  if(PE::internal::make_indexed_disk(m, boost::graph_traits<Surface_mesh>::null_halfedge(), disk) != PE::OK) return 0;
  const std::size_t nb = disk.border.size();
  std::size_t count = 0;
  for(std::size_t k = 0; k < nb; ++k)
  {
    const P2 a = get(uv, disk.vertices[disk.border[(k + nb - 1) % nb]]), b = get(uv, disk.vertices[disk.border[k]]),
             c = get(uv, disk.vertices[disk.border[(k + 1) % nb]]);
    const double ux = b.x() - a.x(), uy = b.y() - a.y(), vx = c.x() - b.x(), vy = c.y() - b.y();
    const double sine = (ux * vy - uy * vx) / (std::sqrt(ux * ux + uy * uy) * std::sqrt(vx * vx + vy * vy));
    if(CGAL::orientation(a, b, c) != CGAL::COLLINEAR && std::abs(sine) < 1e-12) ++count;
  }
  return count;
}

} // namespace

PE_TEST_GROUP(constrained_embedding_wrapped_border)
{
  (void)data_dir;
  const double pi = std::acos(-1.);
  // an ordinary convex disk and a simple non-convex fan (1.5 pi at the center): no turns
  {
    Surface_mesh grid;
    PE::internal::make_grid_disk(8, grid);
    auto uv = make_uv_map(grid, P2());
    for(auto v : vertices(grid)) put(uv, v, P2(grid.point(v).x(), grid.point(v).y()));
    auto t = grid.add_property_map<Sm_vertex, int>("v:test_turns", -7).first;
    CHECK(PE::border_rotation_indices(grid, uv, t) == 0, "a convex disk has no turns");
    for(auto v : vertices(grid)) CHECK(get(t, v) == (CGAL::is_border(v, grid) ? 0 : -7), "index 0 on the border, interior untouched");
    Surface_mesh fan;
    const std::vector<std::array<double, 2> > uvs = pe_test::make_wrapped_fan_mesh(fan, 1.5 * pi, 8, 3);
    auto fuv = make_uv_map(fan, P2());
    fill_uv(fan, fuv, uvs);
    auto ft = fan.add_property_map<Sm_vertex, int>("v:test_turns", -7).first;
    CHECK(PE::border_rotation_indices(fan, fuv, ft) == 0 && get(ft, *vertices(fan).begin()) == 0, "a fan of 1.5 pi has no turns");
  }
  RUN(wrapped_border(2.5 * pi, 10, 4, 1));
  RUN(wrapped_border(2.5 * pi, 20, 6, 1));
  RUN(wrapped_border(4.5 * pi, 18, 4, 2));
  return EXIT_SUCCESS;
}

// A spiral strip winding twice (slanted sides), the border vertices of a grid disk placed on it by arc length,
// several per side, interpolated in double: they turn by about 1e-16 (not exactly collinear). Only the
// vertices that turn by more than rounding may be nodes of the partition, else its pieces are slivers
// thinner than an ulp: the map must still be a certified immersion with the border bit-exact.
PE_TEST_GROUP(constrained_embedding_sliver_border)
{
  (void)data_dir;
  const std::vector<P2> Q = spiral_twice();
  for(std::size_t n : { 20, 30, 40 })
  {
    Surface_mesh grid;
    PE::internal::make_grid_disk(n, grid);
    {
      Surface_mesh c = grid;
      auto cuv = make_uv_map(c, P2());
      CHECK(border_on_polygon(c, cuv, Q), "border placed");
      const std::size_t slivers = rounding_turns(c, cuv);
      std::cout << "grid " << n << "x" << n << ": " << slivers << " of " << 4 * (n - 1)
                << " border vertices turn by rounding only (sine below 1e-12, not 0)" << std::endl;
      CHECK(slivers >= 4, "border vertices that turn by rounding");
    }
    // (every border vertex a node: pieces thinner than an ulp, a certified map of mean energy about 1e29 for 20x20)
    RUN(embed_on("grid " + std::to_string(n) + "x" + std::to_string(n) + " on a spiral strip winding twice", grid, Q, {}, true, 1e4));
  }
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(constrained_embedding_hilbert)
{
  // 93 nested partition edges: shortest paths run out of their budget (or add more than a tenth of the
  // vertices), the guided tracing gives the certified map
  Surface_mesh grid;
  PE::internal::make_grid_disk(60, grid);
  bool guided = false;
  RUN(hilbert_map("grid 60x60 on the Hilbert outline of order 3", grid, {}, &guided));
  CHECK(guided, "traced a second time, guided");
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(constrained_embedding_non_convex)
{
  Surface_mesh grid;
  PE::internal::make_grid_disk(20, grid);
  Surface_mesh mushroom;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", mushroom)) return EXIT_FAILURE;
  RUN(embed_on("grid 20x20 on an L", grid, l_shape(), {}, false));
  RUN(embed_on("grid 20x20 on an L", grid, l_shape(), { P2(0.25, 0.25), P2(0.75, 0.25), P2(0.25, 0.75) }, false));
  RUN(embed_on("mushroom on an L", mushroom, l_shape(), { P2(0.2, 0.2), P2(0.8, 0.3), P2(0.3, 0.8) }, false));
  RUN(embed_on("mushroom on a comb", mushroom, comb(), {}, false));
  RUN(embed_on("grid 20x20 on a comb", grid, comb(), {}, false));
  RUN(embed_on("mushroom on a star", mushroom, star8(), { P2(0.2, 0), P2(-0.1, 0.15), P2(0, -0.25) }, false));
  RUN(embed_on("mushroom on a comb", mushroom, comb(), { P2(0.5, 2.5), P2(2.5, 0.5), P2(4.5, 2.5) }, false));
  Polyhedron poly;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", poly)) return EXIT_FAILURE;
  RUN(embed_on("mushroom (Polyhedron_3) on an L", poly, l_shape(), { P2(0.2, 0.2), P2(0.8, 0.3), P2(0.3, 0.8) }, false));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(constrained_embedding_immersion)
{
  Surface_mesh mushroom;
  if(!read_mesh(data_dir + "/meshes/mushroom.off", mushroom)) return EXIT_FAILURE;
  RUN(embed_on("mushroom on a strip winding 1.25 times", mushroom, spiral_strip(), {}, true));
  RUN(embed_on("mushroom on a spiral strip winding twice", mushroom, spiral_twice(), {}, true));
  // grids: with 20x20, the border point placed by arc length near (4.5, 0.5) on the outer side lands
  // at y = 0.5 - 2^-52, below the line y = 0.5 of the inner side ending at (3.5, 0.5); the partition
  // must not make that inner corner a corner of a piece convex by that much only (the path vertices
  // along it, rounded onto y = 0.5, gave flat chords with the inner side's vertices: the patch map
  // failed its certificate)
  for(std::size_t n : { 10, 20, 30 })
  {
    Surface_mesh grid;
    PE::internal::make_grid_disk(n, grid);
    RUN(partition_corners_robust(grid, spiral_strip()));
    RUN(embed_on("grid " + std::to_string(n) + "x" + std::to_string(n) + " on a strip winding 1.25 times", grid,
                 spiral_strip(), {}, true));
  }
  // errors: constraints on an overlapping border; a figure eight (no immersed disk); mesh and uv untouched
  typedef boost::graph_traits<Surface_mesh>::vertex_descriptor VD;
  auto expect = [&](const std::vector<P2>& Q, const std::vector<std::pair<VD, P2> >& C, PE::Error_code code, const char* what) -> int
  {
    Surface_mesh m = mushroom;
    auto uv = make_uv_map(m, P2());
    for(auto v : vertices(m)) put(uv, v, P2(0, 0));
    CHECK(border_on_polygon(m, uv, Q), "border placed");
    std::vector<P2> before;
    for(auto v : vertices(m)) before.push_back(get(uv, v));
    const std::size_t nv = m.number_of_vertices();
    const PE::Error_code ec = PE::constrained_embedding(m, C, uv);
    std::cout << what << ": " << PE::get_error_message(ec) << std::endl;
    CHECK(ec == code, what);
    CHECK(m.number_of_vertices() == nv, "mesh unchanged");
    std::size_t i = 0;
    for(auto v : vertices(m)) CHECK(get(uv, v) == before[i++], "uv unchanged");
    return EXIT_SUCCESS;
  };
  VD inner = *vertices(mushroom).begin();
  for(auto v : vertices(mushroom)) if(!CGAL::is_border(v, mushroom)) { inner = v; break; }
  RUN(expect(spiral_strip(), { { inner, P2(2, 4) } }, PE::ERROR_CONSTRAINT_OUTSIDE_DOMAIN, "a constraint on an overlapping border"));
  const std::vector<P2> eight = { P2(0, 0), P2(2, 2), P2(2, 0), P2(0, 2) }; // a bowtie: crosses itself
  RUN(expect(eight, {}, PE::ERROR_NOT_SELF_OVERLAPPING, "a figure eight"));
  return EXIT_SUCCESS;
}
