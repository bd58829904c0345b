// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// check_immersion(): the exact certificate of locally injective maps. Embeddings are immersions; a
// strip wound 1.5 times around a center overlaps itself and is an immersion (check_embedding() refuses
// it); a fan whose one-ring winds twice, a flipped face and a non-finite point are not; mirror images;
// exact rationals and MPFR at scales beyond double range; Polyhedron_3; the border-polygon overload.
// Border angles: one polygon bounds two immersed disks whose extra turn sits at different border vertices;
// each is an immersion only with its own rotation indices.

#include <CGAL/Progressive_embedding/check_immersion.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/triangulate_self_overlapping_polygon_2.h>

#include "registry.h"
#include "../test_util.h"
#include <CGAL/Progressive_embedding/internal/disk_generators.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>

#include <cmath>
#include <limits>
#include <vector>

namespace {

namespace PE = CGAL::Progressive_embedding;

// a strip of three rows (radii 1, 1.5, 2) along the angles k * turns * 2 pi / n, k = 0..n: with more than
// one turn it overlaps itself; the middle row's inner vertices are interior
template <class Mesh>
std::vector<std::array<double, 2> > make_spiral_strip(Mesh& m, int n, double turns)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor VD;
  std::vector<std::array<double, 2> > uv;
  std::vector<std::array<VD, 3> > rows;
  const double pi = std::acos(-1.0);
  for(int k = 0; k <= n; ++k)
  {
    const double t = 2 * pi * turns * k / n;
    std::array<VD, 3> row;
    for(int j = 0; j < 3; ++j)
    {
      const double r = 1 + 0.5 * j;
      row[j] = add_vertex(m);
      put(CGAL::vertex_point, m, row[j], Epick::Point_3(k, j, 0.1 * (k % 2)));
      uv.push_back({ { r * std::cos(t), r * std::sin(t) } });
    }
    rows.push_back(row);
  }
  for(int k = 0; k < n; ++k)
    for(int j = 0; j < 2; ++j)
    {
      // counterclockwise in uv: inner -> outer is radial, k -> k + 1 turns counterclockwise
      CGAL::Euler::add_face(std::vector<VD>{ rows[k][j], rows[k][j + 1], rows[k + 1][j + 1] }, m);
      CGAL::Euler::add_face(std::vector<VD>{ rows[k][j], rows[k + 1][j + 1], rows[k + 1][j] }, m);
    }
  return uv;
}

// a fan around one center whose k neighbours sit at angles 2 pi w i / k: the one-ring winds w times
template <class Mesh>
std::vector<std::array<double, 2> > make_fan(Mesh& m, int k, int w)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor VD;
  std::vector<std::array<double, 2> > uv;
  const double pi = std::acos(-1.0);
  const VD c = add_vertex(m);
  put(CGAL::vertex_point, m, c, Epick::Point_3(0, 0, 1));
  uv.push_back({ { 0, 0 } });
  std::vector<VD> ring;
  for(int i = 0; i < k; ++i)
  {
    ring.push_back(add_vertex(m));
    const double t = 2 * pi * w * i / k;
    put(CGAL::vertex_point, m, ring.back(), Epick::Point_3(std::cos(2 * pi * i / k), std::sin(2 * pi * i / k), 0));
    uv.push_back({ { std::cos(t), std::sin(t) } });
  }
  for(int i = 0; i < k; ++i) CGAL::Euler::add_face(std::vector<VD>{ c, ring[i], ring[(i + 1) % k] }, m);
  return uv;
}

// the uv map in the kernel K, every coordinate times 2^e (exact)
template <class K, class Mesh>
auto uv_map_of(Mesh& m, const std::vector<std::array<double, 2> >& uv, int e, bool mirror = false)
{
  typedef typename K::FT FT;
  auto map = make_uv_map(m, typename K::Point_2());
  std::size_t i = 0;
  for(auto v : vertices(m))
  {
    const double x = mirror ? -uv[i][0] : uv[i][0], y = uv[i][1];
    FT fx = ft<FT>(x), fy = ft<FT>(y);
    if(e != 0)
    {
      FT s = ft<FT>(1);
      for(int j = 0; j < std::abs(e); ++j) s = s * ft<FT>(2);
      if(e > 0) { fx = fx * s; fy = fy * s; } else { fx = fx / s; fy = fy / s; }
    }
    put(map, v, typename K::Point_2(fx, fy));
    ++i;
  }
  return map;
}

template <class K, class Mesh>
int cases(int e)
{
  std::cout << mesh_name<Mesh>() << ", " << nt_name<K>() << ", scale 2^" << e << std::endl;
  {
    Mesh m;
    const auto uv = make_spiral_strip(m, 60, 1.5);
    auto map = uv_map_of<K>(m, uv, e);
    const PE::Immersion_report r = PE::check_immersion(m, map);
    std::cout << "  spiral strip, 1.5 turns: " << r.summary() << std::endl;
    CHECK(r.is_immersion() && !r.clockwise && r.faces == 240 && r.max_winding == 1 && r.winding_errors == 0,
          "an overlapping strip is an immersion");
    const PE::Embedding_report er = PE::check_embedding(m, map, PE::parameters::check_overlap(false));
    CHECK(!er.is_valid() && !er.border_simple, "but not an embedding: its border crosses itself");
    auto mirrored = uv_map_of<K>(m, uv, e, true);
    const PE::Immersion_report rm = PE::check_immersion(m, mirrored);
    std::cout << "  mirrored: " << rm.summary() << std::endl;
    CHECK(rm.is_immersion() && rm.clockwise, "its mirror image is a (clockwise) immersion");
  }
  {
    Mesh m;
    const auto uv = make_fan(m, 7, 2);
    auto map = uv_map_of<K>(m, uv, e);
    const PE::Immersion_report r = PE::check_immersion(m, map);
    std::cout << "  fan winding twice: " << r.summary() << std::endl;
    CHECK(!r.is_immersion() && r.flipped == 0 && r.degenerate == 0 && r.winding_errors == 1 && r.max_winding == 2,
          "a one-ring winding twice is refused, every face positive");
    auto mirrored = uv_map_of<K>(m, uv, e, true);
    const PE::Immersion_report rm = PE::check_immersion(m, mirrored);
    CHECK(!rm.is_immersion() && rm.clockwise && rm.winding_errors == 1 && rm.max_winding == 2, "mirrored: refused too");
    Mesh once;
    const auto uv1 = make_fan(once, 7, 1);
    auto map1 = uv_map_of<K>(once, uv1, e);
    CHECK(PE::check_immersion(once, map1).is_immersion(), "the same fan winding once is an immersion");
  }
  {
    // a grid disk's Tutte map (an embedding), then one interior vertex moved across its ring
    Mesh m;
    PE::internal::make_grid_disk(6, m);
    auto uvd = make_uv_map(m, Epick::Point_2());
    CHECK(PE::tutte_embedding(m, boost::graph_traits<Mesh>::null_halfedge(), uvd, PE::parameters::border_shape(PE::Border_shape::CIRCLE)) == PE::OK, "Tutte map");
    std::vector<std::array<double, 2> > uv;
    for(auto v : vertices(m)) uv.push_back({ { get(uvd, v).x(), get(uvd, v).y() } });
    auto map = uv_map_of<K>(m, uv, e);
    const PE::Immersion_report r = PE::check_immersion(m, map);
    CHECK(r.is_immersion() && r.faces == 50 && r.vertices == 36 && r.border_vertices == 20, "an embedding is an immersion");
    // the border overload: the border as it is, then one point changed, then the wrong size
    typedef typename K::Point_2 P;
    // the border in the order the function documents (interior on the left), from its first vertex
    PE::internal::Indexed_disk<Mesh> disk;
    CHECK(PE::internal::make_indexed_disk(m, boost::graph_traits<Mesh>::null_halfedge(), disk) == PE::OK, "indexed");
    std::vector<P> border;
    for(std::size_t k = 0; k < disk.border.size(); ++k) border.push_back(get(map, disk.vertices[disk.border[(k + 5) % disk.border.size()]]));
    const auto start = disk.vertices[disk.border[5]];
    const PE::Immersion_report rb = PE::check_immersion(m, map, start, border);
    std::cout << "  grid with its border: " << rb.summary() << std::endl;
    CHECK(rb.is_immersion() && rb.border_mismatches == 0, "the border is the given polygon");
    border[3] = P(border[3].x() + border[3].x() + ft<typename K::FT>(1), border[3].y());
    const PE::Immersion_report rb2 = PE::check_immersion(m, map, start, border);
    CHECK(!rb2.is_immersion() && rb2.border_mismatches == 1, "one border point differs");
    border.pop_back();
    CHECK(PE::check_immersion(m, map, start, border).status == PE::ERROR_WRONG_PARAMETER, "polygon of the wrong size");
    // a flipped face: an interior vertex moved far outside its one-ring
    auto v = *vertices(m).begin();
    for(auto w : vertices(m)) if(!CGAL::is_border(w, m)) { v = w; break; }
    put(map, v, P(ft<typename K::FT>(-5), ft<typename K::FT>(-5)));
    const PE::Immersion_report rf = PE::check_immersion(m, map);
    std::cout << "  one vertex thrown out: " << rf.summary() << std::endl;
    CHECK(!rf.is_immersion() && rf.flipped > 0, "flipped faces refused");
  }
  return EXIT_SUCCESS;
}

// optimize_distortion() on an immersion: certified again as one, the border bit-exact, the energy lower;
// free_border refused; a map that is not an immersion refused; the uv map untouched on every error
template <class K, class Mesh>
int optimize_cases()
{
  std::cout << "optimize_distortion on immersions: " << mesh_name<Mesh>() << ", " << nt_name<K>() << std::endl;
  typedef typename K::Point_2 P;
  auto snapshot = [](const Mesh& m, const auto& map) {
    std::vector<P> pts;
    for(auto v : vertices(m)) pts.push_back(get(map, v));
    return pts;
  };
  {
    Mesh m;
    const auto uv = make_spiral_strip(m, 60, 1.5);
    auto map = uv_map_of<K>(m, uv, 0);
    const std::vector<P> before = snapshot(m, map);
    PE::Optimization_statistics st;
    const PE::Error_code ec = PE::optimize_distortion(m, map, PE::parameters::optimization_statistics(&st,
                                CGAL::parameters::number_of_iterations(30)));
    std::cout << "  spiral strip, 1.5 turns: " << PE::get_error_message(ec) << ", iterations " << st.iterations
              << ", energy " << st.energy_before << " -> " << st.energy_after << "; " << st.immersion_report.summary() << std::endl;
    CHECK(ec == PE::OK || ec == PE::ERROR_BUDGET_EXHAUSTED, "optimized");
    CHECK(st.immersion && st.immersion_report.is_immersion() && st.immersion_report.border_mismatches == 0,
          "optimized as an immersion, certified");
    CHECK(st.energy_after < st.energy_before, "energy lowered");
    const PE::Immersion_report r = PE::check_immersion(m, map);
    CHECK(r.is_immersion() && r.faces == 240, "the map written is an immersion");
    std::size_t i = 0, moved = 0;
    for(auto v : vertices(m))
    {
      const P q = get(map, v);
      if(CGAL::is_border(v, m)) CHECK(q == before[i], "border bit-exact");
      else if(q != before[i]) ++moved;
      ++i;
    }
    CHECK(moved > 0, "interior vertices moved");
    // free border: refused (the border could stop being self-overlapping), nothing written
    auto map2 = uv_map_of<K>(m, uv, 0);
    const std::vector<P> before2 = snapshot(m, map2);
    PE::Optimization_statistics st2;
    CHECK(PE::optimize_distortion(m, map2, PE::parameters::free_border(true, PE::parameters::optimization_statistics(&st2)))
            == PE::ERROR_WRONG_PARAMETER && st2.immersion, "free_border on an immersion refused");
    CHECK(snapshot(m, map2) == before2, "uv unchanged");
  }
  {
    // every face positive, but the one-ring winds twice: neither valid nor an immersion
    Mesh m;
    const auto uv = make_fan(m, 7, 2);
    auto map = uv_map_of<K>(m, uv, 0);
    const std::vector<P> before = snapshot(m, map);
    PE::Optimization_statistics st;
    const PE::Error_code ec = PE::optimize_distortion(m, map, PE::parameters::optimization_statistics(&st));
    std::cout << "  fan winding twice: " << PE::get_error_message(ec) << "; " << st.immersion_report.summary() << std::endl;
    CHECK(ec == PE::ERROR_INVALID_EMBEDDING && !st.immersion && st.immersion_report.winding_errors == 1, "refused");
    CHECK(snapshot(m, map) == before, "uv unchanged");
  }
  return EXIT_SUCCESS;
}

} // namespace

PE_TEST_GROUP(optimize_immersion)
{
  (void)data_dir;
  RUN((optimize_cases<Epick, Surface_mesh>()));
  RUN((optimize_cases<Epick, Polyhedron>()));
  RUN((optimize_cases<Kq, Surface_mesh>()));
  RUN((optimize_cases<Kfr, Surface_mesh>()));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(check_immersion)
{
  (void)data_dir;
  RUN((cases<Epick, Surface_mesh>(0)));
  RUN((cases<Epick, Polyhedron>(0)));
  RUN((cases<Epick, Surface_mesh>(-600))); // tiny but normal doubles
  RUN((cases<Kq, Surface_mesh>(0)));
  RUN((cases<Kq, Surface_mesh>(1100)));   // beyond double range
  RUN((cases<Kq, Surface_mesh>(-1100)));
  RUN((cases<Kfr, Surface_mesh>(1100)));
  return EXIT_SUCCESS;
}

namespace {

// A polygon bounding two immersed disks: A = (0, 0), an arc of radius 1 from angle 0 to 2.5 pi (k + 1 points), then
// B = (-0.25, -0.125). Its rotation number is 2, so one vertex must wrap once around itself: A (the disk is a fan
// around A) or B (a fan around B). The positions are those of both disks, bit for bit; only the faces differ.
std::vector<std::array<double, 2> > two_disk_polygon(int k)
{
  const double pi = std::acos(-1.0);
  std::vector<std::array<double, 2> > P{ { { 0, 0 } } };
  for(int i = 0; i <= k; ++i) P.push_back({ { std::cos(i * 2.5 * pi / k), std::sin(i * 2.5 * pi / k) } });
  P.push_back({ { -0.25, -0.125 } });
  return P;
}

// the disk bounded by P whose fan at `wrap` makes one extra turn (built by triangulate_self_overlapping_polygon_2)
template <class Mesh>
bool make_wrapped_disk(Mesh& m, const std::vector<std::array<double, 2> >& P, std::size_t wrap)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor VD;
  std::vector<Epick::Point_2> pts;
  for(const auto& p : P) pts.push_back(Epick::Point_2(p[0], p[1]));
  std::vector<int> r(P.size(), 0);
  r[wrap] = 1;
  std::vector<std::array<std::size_t, 3> > T;
  if(PE::triangulate_self_overlapping_polygon_2(pts, std::back_inserter(T), PE::parameters::rotation_indices(r)) != PE::OK)
    return false;
  std::vector<VD> V;
  for(std::size_t i = 0; i < P.size(); ++i)
  {
    V.push_back(add_vertex(m));
    put(CGAL::vertex_point, m, V.back(), Epick::Point_3(P[i][0], P[i][1], 0.01 * double(i % 3)));
  }
  for(const auto& t : T)
    if(CGAL::Euler::add_face(std::vector<VD>{ V[t[0]], V[t[1]], V[t[2]] }, m) == boost::graph_traits<Mesh>::null_face())
      return false;
  return true;
}

template <class K, class Mesh>
int border_angle_cases(int e)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor VD;
  const int k = 10;
  const auto P = two_disk_polygon(k);
  const std::size_t a = 0, b = P.size() - 1;
  for(std::size_t wrap : { a, b })
  {
    const std::size_t other = wrap == a ? b : a;
    Mesh m;
    CHECK(make_wrapped_disk(m, P, wrap), "the disk wrapping at one vertex is built");
    const std::vector<VD> V(vertices(m).begin(), vertices(m).end());
    auto rot = get(CGAL::dynamic_vertex_property_t<int>(), m);
    for(VD v : V) put(rot, v, 0);
    for(bool mirror : { false, true })
    {
      auto map = uv_map_of<K>(m, P, e, mirror);
      const std::string what = std::string(wrap == a ? "fan around A" : "fan around B") + (mirror ? ", mirrored" : "");
      // no index given: the extra turn is an error wherever it is
      const PE::Immersion_report r0 = PE::check_immersion(m, map);
      std::cout << "  " << what << ", no index: " << r0.summary() << std::endl;
      CHECK(!r0.is_immersion() && r0.flipped == 0 && r0.degenerate == 0 && r0.winding_errors == 0 && r0.clockwise == mirror
              && r0.border_angle_errors == 1 && r0.max_border_turns == 1, what + ": the extra turn refused without its index");
      // the index at the other vertex: both vertices wrong (the counterexample a check of the faces alone accepts)
      put(rot, V[wrap], 0);
      put(rot, V[other], 1);
      const PE::Immersion_report rw = PE::check_immersion(m, map, PE::parameters::vertex_rotation_index_map(rot));
      std::cout << "  " << what << ", index at the other vertex: " << rw.summary() << std::endl;
      CHECK(!rw.is_immersion() && rw.border_angle_errors == 2 && rw.flipped == 0 && rw.winding_errors == 0,
            what + ": the extra turn at the wrong border vertex is refused");
      // its own index: an immersion, with the border polygon overload too
      put(rot, V[other], 0);
      put(rot, V[wrap], 1);
      const PE::Immersion_report rr = PE::check_immersion(m, map, PE::parameters::vertex_rotation_index_map(rot));
      CHECK(rr.is_immersion() && rr.border_angle_errors == 0 && rr.max_border_turns == 1, what + ": an immersion with its index");
      // the polygon overload, from the vertex after the wrapping one
      const std::size_t s = (wrap + 1) % V.size();
      std::vector<typename K::Point_2> border;
      for(std::size_t i = 0; i < V.size(); ++i) border.push_back(get(map, V[(s + i) % V.size()]));
      CHECK(PE::check_immersion(m, map, V[s], border, PE::parameters::vertex_rotation_index_map(rot)).is_immersion(),
            what + ": an immersion onto its polygon, with its index");
      CHECK(PE::check_immersion(m, map, V[s], border).border_angle_errors == 1, what + ": onto its polygon, without");
      put(rot, V[wrap], 0);
      // border_rotation_indices() reads the index back from the map (exactly, at every scale, either orientation)
      {
        auto read = get(CGAL::dynamic_vertex_property_t<int>(), m);
        CHECK(PE::border_rotation_indices(m, map, read) == 1 && get(read, V[wrap]) == 1 && get(read, V[other]) == 0,
              what + ": border_rotation_indices() finds the extra turn");
        CHECK(PE::check_immersion(m, map, PE::parameters::vertex_rotation_index_map(read)).is_immersion(),
              what + ": an immersion with the indices read from it");
      }
    }
  }
  return EXIT_SUCCESS;
}

} // namespace

PE_TEST_GROUP(check_immersion_border_angles)
{
  (void)data_dir;
  RUN((border_angle_cases<Epick, Surface_mesh>(0)));
  RUN((border_angle_cases<Epick, Polyhedron>(0)));
  RUN((border_angle_cases<Kq, Surface_mesh>(1100)));  // beyond double range
  RUN((border_angle_cases<Kfr, Surface_mesh>(-1100)));
  return EXIT_SUCCESS;
}

PE_TEST_GROUP(check_immersion_errors)
{
  (void)data_dir;
  {
    // a non-finite coordinate
    Surface_mesh m;
    const auto uv = make_spiral_strip(m, 20, 1.5);
    auto map = uv_map_of<Epick>(m, uv, 0);
    put(map, *std::next(vertices(m).begin(), 4), Epick::Point_2(std::numeric_limits<double>::quiet_NaN(), 0));
    const PE::Immersion_report r = PE::check_immersion(m, map);
    std::cout << "NaN: " << r.summary() << std::endl;
    CHECK(!r.is_immersion() && r.non_finite == 1 && r.status == PE::OK, "a NaN point refused, counted");
  }
  {
    // not a disk: a closed mesh; an empty mesh
    Surface_mesh closed;
    CGAL::make_tetrahedron(Epick::Point_3(0, 0, 0), Epick::Point_3(1, 0, 0), Epick::Point_3(0, 1, 0), Epick::Point_3(0, 0, 1), closed);
    auto map = make_uv_map(closed, Epick::Point_2());
    CHECK(PE::check_immersion(closed, map).status == PE::ERROR_NOT_A_DISK, "a closed mesh is not a disk");
    Surface_mesh empty;
    auto map2 = make_uv_map(empty, Epick::Point_2());
    const PE::Immersion_report r = PE::check_immersion(empty, map2);
    CHECK(r.status != PE::OK && !r.is_immersion(), "an empty mesh is refused");
  }
  return EXIT_SUCCESS;
}
