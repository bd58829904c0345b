// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Tests of progressive_embedding(): broken Tutte maps (deep stacked triangulation, corpus runs
// of libcgal-demo), random initializations, all interior vertices at one point, a clockwise
// border, a strictly convex border with vertices 2^-40 apart, maps at any scale and far from the origin, and the inputs it must refuse -- in double, Gmpq and Gmpfr, on
// Surface_mesh and on Polyhedron_3. Every success is checked with an independent certificate
// and a bit-exact border; the internal working copy must get the input connectivity back.
// The repair-and-optimize policy (repair_and_optimize(), parameterize_certified()): its stages, its
// statistics as key-value pairs, its budget and errors.
//
// Usage: test_progressive_embedding DATA_DIR   (DATA_DIR contains libcgal-demo's meshes/)

// counts the indexings of a mesh (internal::indexing_count()): the pipelines index once
#define CGAL_PROGRESSIVE_EMBEDDING_COUNT_INDEXING
#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/certified_pipeline.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/internal/disk_generators.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>

#include "test_util.h"

#include <cmath>
#include <limits>
#include <set>
#include <sstream>

namespace {

template <class Mesh>
using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;

template <class Mesh>
typename boost::graph_traits<Mesh>::halfedge_descriptor null_h() { return boost::graph_traits<Mesh>::null_halfedge(); }

template <class P>
bool same_uv(const P& a, const P& b)
{
  typedef typename CGAL::Kernel_traits<P>::Kernel::FT FT;
  if constexpr(std::is_same<FT, double>::value)
    return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y());
  else
    return a.x() == b.x() && a.y() == b.y();
}

// Runs progressive_embedding() on `uv` (FT of its kernel) and checks everything that an OK
// must guarantee. `expect_no_extra_smoothing`: Lemma A.11 (exact arithmetic).
template <class Mesh, class UVM>
int repair_and_certify(Mesh& m, UVM& uv, const std::string& what, bool expect_no_extra_smoothing)
{
  typedef typename boost::property_traits<UVM>::value_type P;
  // what must not change
  std::vector<std::pair<vertex_descriptor<Mesh>, P> > border;
  for(auto v : vertices(m)) if(CGAL::is_border(v, m)) border.emplace_back(v, get(uv, v));
  const PE::Embedding_report before = PE::check_embedding(m, uv);

  PE::Progressive_embedding_statistics st;
  CGAL::Real_timer t;
  t.start();
  const PE::Error_code ec = PE::progressive_embedding(m, uv, PE::parameters::statistics(&st));
  const double seconds = t.time();
  std::cout << "  " << what << ": input " << (before.is_valid() ? "valid" : "INVALID") << " (flipped " << before.flipped
            << ", degenerate " << before.degenerate << "); progressive_embedding " << PE::get_error_name(ec)
            << " in " << seconds << " s (invalid before " << st.invalid_faces_before << ", collapses " << st.collapses
            << ", insertions " << st.insertions << ", extra smoothing " << st.insertions_with_extra_smoothing << ")" << std::endl;
  CHECK(ec == PE::OK, what << ": progressive_embedding returned " << PE::get_error_name(ec));
  CHECK(st.report.is_valid(), what << ": the returned certificate is valid");
  CHECK(st.insertions == st.collapses, what << ": every collapse undone");

  // independent certificate: check_embedding again, and the orientation count
  const PE::Embedding_report after = PE::check_embedding(m, uv);
  std::cout << "    output: " << after.summary() << std::endl;
  CHECK(after.is_valid() && after.flipped == 0 && after.degenerate == 0 && after.overlapping_pairs == 0, what << ": output valid");
  CHECK(after.clockwise == before.clockwise, what << ": orientation kept (the border is fixed)");
  std::size_t fl = 0, dg = 0;
  count_orientations(m, uv, after.clockwise ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN, fl, dg);
  CHECK(fl == 0 && dg == 0, what << ": independent orientation count");
  for(auto v : vertices(m))
  {
    const P p = get(uv, v);
    CHECK(PE::internal::is_finite_ft(p.x()) && PE::internal::is_finite_ft(p.y()), what << ": finite output");
  }
  for(const auto& b : border)
    CHECK(same_uv(get(uv, b.first), b.second), what << ": border vertex moved");
  // (the mesh is taken by const reference: its connectivity cannot change; that the algorithm's
  // working copy gets the input connectivity back is the "restoration" group)
  if(expect_no_extra_smoothing)
    CHECK(st.insertions_with_extra_smoothing == 0, what << ": no insertion needed extra smoothing (Lemma A.11)");
  return EXIT_SUCCESS;
}

// ---- deep stacked triangulation -------------------------------------------------------

// the broken double map `tutte`, converted exactly into the number type of K, repaired in K
template <class K, class Mesh>
int stacked_in(Mesh& m, std::size_t depth, const std::map<vertex_descriptor<Mesh>, Epick::Point_2>& tutte, bool exact_expectations)
{
  auto uv = make_uv_map(m, typename K::Point_2());
  for(auto v : vertices(m))
    put(uv, v, point<K>(tutte.at(v).x(), tutte.at(v).y()));
  return repair_and_certify(m, uv, std::string("depth ") + std::to_string(depth) + ", " + nt_name<K>(), exact_expectations);
}

template <class Mesh>
int test_stacked(std::size_t depth)
{
  std::cout << "[" << mesh_name<Mesh>() << "] stacked triangulation depth " << depth << std::endl;
  Mesh m;
  const auto c = PE::internal::make_stacked_triangulation(depth, m);
  auto uv = make_uv_map(m, Epick::Point_2());
  pin_corners<Epick>(uv, c);
  CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uv, PE::parameters::border_shape(PE::Border_shape::FIXED)) == PE::OK, "Tutte");
  const PE::Embedding_report r = PE::check_embedding(m, uv);
  std::cout << "  double Tutte: " << r.summary() << " (3 flipped at depth 40, 49 at depth 80 with Eigen's SimplicialLDLT)" << std::endl;
  CHECK(!r.is_valid() && r.flipped > 0, "the double Tutte map is broken");
  std::map<vertex_descriptor<Mesh>, Epick::Point_2> tutte;
  for(auto v : vertices(m)) tutte[v] = get(uv, v);

  // double, from the broken map
  RUN(repair_and_certify(m, uv, "depth " + std::to_string(depth) + ", double", false));
  // the same broken map, converted exactly, repaired in exact and in 256-bit arithmetic
  RUN((stacked_in<Kq>(m, depth, tutte, true)));
  const auto saved = CGAL::Gmpfr::get_default_precision();
  CGAL::Gmpfr::set_default_precision(256);
  const int rc = stacked_in<Kfr>(m, depth, tutte, true);
  CGAL::Gmpfr::set_default_precision(saved);
  RUN(rc);
  return EXIT_SUCCESS;
}

// ---- corpus runs -----------------------------------------------------------------------

template <class Mesh>
int test_corpus(const std::string& data, const std::string& mesh, unsigned seed)
{
  std::cout << "[" << mesh_name<Mesh>() << "] " << mesh << " seed " << seed << " (Tutte-failure protocol)" << std::endl;
  Mesh m;
  CHECK(read_mesh(data + "/meshes/" + mesh, m), "read " << mesh);
  std::array<vertex_descriptor<Mesh>, 3> pinned;
  CHECK(PE::internal::thingi_cut(m, seed, pinned) == PE::OK, "cut");
  auto uv = make_uv_map(m, Epick::Point_2());
  pin_corners<Epick>(uv, pinned);
  CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uv, PE::parameters::border_shape(PE::Border_shape::FIXED)) == PE::OK, "Tutte");
  const PE::Embedding_report r = PE::check_embedding(m, uv);
  std::cout << "  double Tutte: " << r.summary() << std::endl;
  CHECK(!r.is_valid(), "the double Tutte map is broken");
  RUN(repair_and_certify(m, uv, mesh + " seed " + std::to_string(seed), false));
  return EXIT_SUCCESS;
}

// ---- random initialization of a grid disk, in three number types ------------------------

template <class Mesh, class K>
int test_random_init(std::size_t n, unsigned seed)
{
  Mesh m;
  PE::internal::make_grid_disk(n, m);
  auto uvd = make_uv_map(m, Epick::Point_2());
  CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uvd, PE::parameters::border_shape(PE::Border_shape::CIRCLE)) == PE::OK, "border");
  random_init(m, uvd, seed);
  auto uv = make_uv_map(m, typename K::Point_2());
  convert_uv(m, uvd, uv);
  const std::string what = "random init, " + std::to_string(n) + "x" + std::to_string(n) + " grid, seed " + std::to_string(seed) + ", " + nt_name<K>();
  return repair_and_certify(m, uv, what, std::is_same<K, Kq>::value);
}

// ---- degenerate interiors, orientation, refused inputs ----------------------------------

template <class Mesh>
int test_special_inputs()
{
  std::cout << "[" << mesh_name<Mesh>() << "] special inputs" << std::endl;
  typedef vertex_descriptor<Mesh> vd;
  Mesh m;
  PE::internal::make_grid_disk(12, m);
  auto uv = make_uv_map(m, Epick::Point_2());
  CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE)) == PE::OK, "border");
  std::vector<vd> interior;
  for(auto v : vertices(m)) if(!CGAL::is_border(v, m)) interior.push_back(v);

  // all interior vertices at one point
  for(vd v : interior) put(uv, v, Epick::Point_2(0.1, -0.05));
  RUN(repair_and_certify(m, uv, "all interior vertices at one point", false));

  // clockwise border: the mirror image of a random initialization
  random_init(m, uv, 7);
  for(auto v : vertices(m)) put(uv, v, Epick::Point_2(get(uv, v).x(), -get(uv, v).y()));
  RUN(repair_and_certify(m, uv, "clockwise border (mirrored random init)", false));
  CHECK(PE::check_embedding(m, uv).clockwise, "the output stays clockwise");
  return EXIT_SUCCESS;
}

// A strictly convex border (every vertex on the parabola y = x^2, exactly) with 2k+1 of its
// vertices 2^-40 apart around the apex, then a ring of interior vertices and a center; with
// `ears`, every third pair of cluster edges gets a degree-3 vertex inside the (flat) triangle
// of its three border vertices. The faces on the cluster edges have an equilateral energy of
// at least (mean side / 2^-40)^2 ~ 1e22 wherever their third corner is, and the ear faces an
// area far below 1e-12 x the mean: neither criterion of the repair can be met there, and the
// maps are valid all the same (Tutte's is).
template <class Mesh, class UVM>
void make_parabola_cluster(Mesh& m, UVM& uv, int k, bool ears)
{
  typedef vertex_descriptor<Mesh> vd;
  typedef typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point_3;
  const double h = std::ldexp(1., -40);
  std::vector<double> xs = { -1, -0.5 };
  for(int i = -k; i <= k; ++i) xs.push_back(i * h); // x^2 is exact
  xs.push_back(0.5); xs.push_back(1);
  auto vpm = get(CGAL::vertex_point, m);
  auto new_vertex = [&](double x, double y) { const vd v = add_vertex(m); put(vpm, v, Point_3(x, y, 0)); return v; };
  auto face = [&](vd a, vd b, vd c) { std::vector<vd> t = { a, b, c }; CGAL::Euler::add_face(t, m); };
  const std::size_t n = xs.size();
  std::vector<vd> B, I;
  for(double x : xs) B.push_back(new_vertex(x, x * x));
  for(std::size_t i = 0; i < n; ++i) I.push_back(new_vertex(0, 0.5));
  const vd c = new_vertex(0, 0.6);
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t j = (i + 1) % n;
    const bool ear = ears && i >= 3 && i + 4 < n && i % 3 == 0; // cluster edges i and i + 1
    if(ear)
    {
      const vd e = new_vertex(0, 0);
      face(B[i], B[j], e); face(B[j], B[j + 1], e); face(B[j + 1], B[i], e);
      face(B[i], B[j + 1], I[j]); face(I[i], B[i], I[j]);
    }
    else if(ears && i >= 4 && i + 3 < n && (i - 1) % 3 == 0)
      face(I[i], B[j], I[j]); // the second edge of an ear: its border face is the ear's
    else
    {
      face(B[i], B[j], I[i]);
      face(I[i], B[j], I[j]);
    }
  }
  for(std::size_t i = 0; i < n; ++i) face(c, I[i], I[(i + 1) % n]);
  for(auto v : vertices(m)) put(uv, v, Epick::Point_2(get(vpm, v).x(), get(vpm, v).y()));
}

template <class Mesh>
int test_border_cluster()
{
  std::cout << "[" << mesh_name<Mesh>() << "] strictly convex border with vertices 2^-40 apart" << std::endl;
  for(bool ears : { false, true })
    for(bool one_point : { false, true })
    {
      Mesh m;
      auto uv = make_uv_map(m, Epick::Point_2());
      make_parabola_cluster(m, uv, 10, ears);
      PE::internal::Indexed_disk<Mesh> disk;
      CHECK(PE::internal::make_indexed_disk(m, null_h<Mesh>(), disk) == PE::OK, "a disk");
      std::vector<Epick::Point_2> B;
      for(std::size_t i : disk.border) B.push_back(get(uv, disk.vertices[i]));
      int orientation = 0;
      CHECK(PE::internal::classify_convex_polygon(B, Epick().orientation_2_object(), orientation)
              == PE::internal::Polygon_class::STRICTLY_CONVEX, "the border is strictly convex (exactly)");
      CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uv, PE::parameters::border_shape(PE::Border_shape::FIXED)) == PE::OK, "Tutte");
      CHECK(PE::check_embedding(m, uv).is_valid(), "Tutte's map is valid");
      if(one_point)
        for(auto v : vertices(m)) if(!CGAL::is_border(v, m)) put(uv, v, Epick::Point_2(0.1, 0.6));
      RUN(repair_and_certify(m, uv, std::string(ears ? "with ears, " : "") + (one_point ? "interior at one point" : "Tutte's map"), false));
    }
  return EXIT_SUCCESS;
}

template <class Mesh>
int test_refused_inputs()
{
  std::cout << "[" << mesh_name<Mesh>() << "] refused inputs" << std::endl;
  typedef vertex_descriptor<Mesh> vd;
  Mesh m;
  PE::internal::make_grid_disk(12, m);
  auto uv = make_uv_map(m, Epick::Point_2());
  CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE)) == PE::OK, "border");
  std::vector<vd> border, interior;
  for(auto v : vertices(m)) (CGAL::is_border(v, m) ? border : interior).push_back(v);
  auto save = make_uv_map(m, Epick::Point_2());
  for(auto v : vertices(m)) put(save, v, get(uv, v));
  auto restore = [&]() { for(auto v : vertices(m)) put(uv, v, get(save, v)); };

  // refused inputs: a specific error, the uv map unchanged, no hang
  auto expect_error = [&](PE::Error_code expected, const char* what) -> int {
    std::vector<Epick::Point_2> before;
    for(auto v : vertices(m)) before.push_back(get(uv, v));
    CGAL::Real_timer t;
    t.start();
    const PE::Error_code ec = PE::progressive_embedding(m, uv);
    const double seconds = t.time();
    std::cout << "  " << what << ": " << PE::get_error_name(ec) << " in " << seconds << " s" << std::endl;
    CHECK(ec == expected, what << ": expected " << PE::get_error_name(expected) << ", got " << PE::get_error_name(ec));
    CHECK(seconds < 10, what << ": no hang");
    std::size_t k = 0;
    for(auto v : vertices(m))
    {
      const Epick::Point_2 p = get(uv, v), q = before[k++];
      CHECK((std::isnan(p.x()) && std::isnan(q.x())) || (same_bits(p.x(), q.x()) && same_bits(p.y(), q.y())),
            what << ": the uv map is left unchanged");
    }
    return EXIT_SUCCESS;
  };
  restore();
  put(uv, border[0], Epick::Point_2(0.3 * get(save, border[0]).x(), 0.3 * get(save, border[0]).y()));
  RUN(expect_error(PE::ERROR_NON_CONVEX_BORDER, "non-convex border"));
  restore();
  {
    // all border vertices at one point
    for(vd v : border) put(uv, v, Epick::Point_2(0.25, 0.5));
  }
  RUN(expect_error(PE::ERROR_DEGENERATE_BORDER, "border at one point"));
  restore();
  put(uv, interior[5], Epick::Point_2(std::numeric_limits<double>::quiet_NaN(), 0));
  RUN(expect_error(PE::ERROR_NON_FINITE_COORDINATES, "NaN uv inside"));
  restore();
  put(uv, border[2], Epick::Point_2(0, std::numeric_limits<double>::infinity()));
  RUN(expect_error(PE::ERROR_NON_FINITE_COORDINATES, "infinite uv on the border"));
  restore();
  {
    Mesh closed;
    CGAL::make_tetrahedron(Epick::Point_3(0, 0, 0), Epick::Point_3(1, 0, 0), Epick::Point_3(0, 1, 0), Epick::Point_3(0, 0, 1), closed);
    auto uvc = make_uv_map(closed, Epick::Point_2());
    const PE::Error_code ec = PE::progressive_embedding(closed, uvc);
    std::cout << "  closed mesh: " << PE::get_error_name(ec) << std::endl;
    CHECK(ec == PE::ERROR_NOT_A_DISK, "closed mesh");
    Mesh empty;
    auto uve = make_uv_map(empty, Epick::Point_2());
    CHECK(PE::progressive_embedding(empty, uve) == PE::ERROR_EMPTY_MESH, "empty mesh");
  }
  // last, as it fails today (border_polygon.h classifies an all-collinear border as non-convex)
  {
    // every border vertex on a line, the cycle going out and back (zero area)
    typename boost::graph_traits<Mesh>::halfedge_descriptor h0 = null_h<Mesh>();
    for(auto h : halfedges(m)) if(is_border(h, m)) { h0 = h; break; }
    std::size_t k = 0, nb = border.size();
    auto h = h0;
    do
    {
      const double t = (2 * k <= nb) ? double(k) : double(nb - k) + 0.5;
      put(uv, target(h, m), Epick::Point_2(t, -t));
      ++k; h = next(h, m);
    } while(h != h0);
  }
  RUN(expect_error(PE::ERROR_DEGENERATE_BORDER, "collinear border"));
  return EXIT_SUCCESS;
}

template <class Mesh>
int test_random_inits()
{
  std::cout << "[" << mesh_name<Mesh>() << "] random initializations" << std::endl;
  RUN((test_random_init<Mesh, Epick>(12, 1)));
  RUN((test_random_init<Mesh, Kq>(12, 1)));
  const auto saved = CGAL::Gmpfr::get_default_precision();
  CGAL::Gmpfr::set_default_precision(256);
  const int rc = test_random_init<Mesh, Kfr>(12, 1);
  CGAL::Gmpfr::set_default_precision(saved);
  return rc;
}

// ---- the working copy gets the input connectivity back -----------------------------------

// Runs the internal embedder on the map `uv` of `m` and checks that undoing every collapse gave
// the working mesh exactly the input faces (as triples of input indices), and that the
// positions it returns keep the border and make a valid map.
template <class Mesh, class UVM>
int check_restoration(const Mesh& m, const UVM& uv, const std::string& what)
{
  typedef typename PE::internal::Uv_map_types<UVM>::Traits Traits;
  typedef typename Traits::FT FT;
  typedef typename Traits::Point_2 P;
  PE::internal::Indexed_disk<Mesh> disk;
  CHECK(PE::internal::make_indexed_disk(m, null_h<Mesh>(), disk) == PE::OK, what << ": a disk");
  const std::size_t nv = disk.number_of_vertices(), nb = disk.border.size();
  std::vector<P> pos(nv);
  for(std::size_t i = 0; i < nv; ++i) pos[i] = get(uv, disk.vertices[i]);
  FT twice_area(0);
  for(std::size_t k = 0; k < nb; ++k)
  {
    const P& a = pos[disk.border[k]];
    const P& b = pos[disk.border[(k + 1) % nb]];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  if(twice_area < FT(0)) // the embedder works on counterclockwise borders, as progressive_embedding() mirrors
  {
    for(P& p : pos) p = P(p.x(), -p.y());
    twice_area = -twice_area;
  }
  const std::vector<P> input = pos;
  typename PE::internal::Progressive_embedder<Traits>::Options opt;
  opt.insertion.smoothing_iterations = Traits::has_exact_constructions ? 0 : 10;
  PE::internal::Progressive_embedder<Traits> pe{Traits(), opt};
  const PE::Error_code ec = pe.run(pos, disk.faces, disk.on_border, twice_area / FT(2));
  std::cout << "  " << what << ": embedder " << PE::get_error_name(ec) << ", collapses " << pe.counters.collapses
            << ", insertions " << pe.counters.insertions << std::endl;
  CHECK(ec == PE::OK, what << ": " << PE::get_error_name(ec));
  CHECK(pe.counters.collapses > 0 && pe.counters.insertions == pe.counters.collapses, what << ": collapses undone");
  std::vector<std::array<std::size_t, 3> > expected;
  for(const auto& t : disk.faces) expected.push_back(PE::internal::Working_mesh<Traits>::normalized_face(t));
  std::sort(expected.begin(), expected.end());
  const auto restored = pe.working_mesh().input_faces();
  CHECK(restored.size() == expected.size(), what << ": " << restored.size() << " faces restored, " << expected.size() << " in the input");
  CHECK(restored == expected, what << ": the working mesh has the input faces again");
  const typename Traits::Exact_orientation_2 orient = Traits().exact_orientation_2_object();
  for(std::size_t i = 0; i < nv; ++i)
    if(disk.on_border[i]) CHECK(pos[i] == input[i], what << ": border kept");
  for(const auto& t : disk.faces)
    CHECK(orient(pos[t[0]], pos[t[1]], pos[t[2]]) == CGAL::LEFT_TURN, what << ": every face positively oriented");
  return EXIT_SUCCESS;
}

// The two stages alone, on the broken Tutte map of a stacked triangulation (counterclockwise
// after mirroring): the collapse stage leaves no invalid face and records every collapse; the
// insertion stage undoes them all, every face positive, the input faces back.
template <class Mesh>
int test_stages()
{
  typedef PE::Progressive_embedding_traits_2<Epick> Traits;
  typedef PE::internal::Working_mesh<Traits> WMesh;
  Mesh m;
  const auto c = PE::internal::make_stacked_triangulation(80, m);
  auto uv = make_uv_map(m, Epick::Point_2());
  pin_corners<Epick>(uv, c);
  CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uv, PE::parameters::border_shape(PE::Border_shape::FIXED)) == PE::OK, "Tutte");
  PE::internal::Indexed_disk<Mesh> disk;
  CHECK(PE::internal::make_indexed_disk(m, null_h<Mesh>(), disk) == PE::OK, "a disk");
  std::vector<Epick::Point_2> pos;
  for(auto v : disk.vertices) pos.push_back(Epick::Point_2(get(uv, v).x(), -get(uv, v).y())); // counterclockwise
  double twice_area = 0;
  for(std::size_t k = 0; k < disk.border.size(); ++k)
  {
    const Epick::Point_2& a = pos[disk.border[k]];
    const Epick::Point_2& b = pos[disk.border[(k + 1) % disk.border.size()]];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  CHECK(twice_area > 0, "counterclockwise border");
  WMesh wm;
  CHECK(wm.build(pos, disk.faces, disk.on_border) == PE::OK, "working mesh");
  PE::internal::Validity_criteria<Traits> validity;
  validity.orient = Traits().exact_orientation_2_object();
  validity.set_mean_area(twice_area / 2 / double(disk.faces.size()));
  PE::internal::Embedder_counters counters;
  std::vector<PE::internal::Collapse_record<typename WMesh::vertex_descriptor> > history;
  {
    PE::internal::Collapse_stage<Traits> collapse(wm, validity, counters, std::size_t(-1), []() { return false; }, false);
    CHECK(collapse.run(history) == PE::OK, "collapse stage");
    std::size_t invalid = 0;
    for(auto f : wm.m.faces()) if(collapse.face_invalid(f)) ++invalid;
    std::cout << "  collapse stage: " << counters.invalid_faces_before << " invalid faces, " << history.size()
              << " collapses, " << invalid << " invalid faces left" << std::endl;
    CHECK(counters.invalid_faces_before > 0 && !history.empty() && history.size() == counters.collapses, "collapses recorded");
    CHECK(invalid == 0, "no invalid face after the collapse stage");
  }
  {
    PE::internal::Insertion_stage<Traits> insertion(wm, Traits(), validity, counters, PE::internal::Insertion_options(),
                                                    []() { return false; }, std::function<bool(double)>(), false);
    CHECK(insertion.run(history, twice_area / 2) == PE::OK, "insertion stage");
  }
  std::cout << "  insertion stage: " << counters.insertions << " insertions, " << counters.smoothing_steps << " smoothing steps" << std::endl;
  CHECK(counters.insertions == history.size(), "every collapse undone");
  for(auto f : wm.m.faces())
  {
    const auto h = wm.m.halfedge(f);
    CHECK(validity.orient(wm.point(wm.m.source(h)), wm.point(wm.m.target(h)), wm.point(wm.m.target(wm.m.next(h)))) == CGAL::LEFT_TURN,
          "every face positive after the insertion stage");
  }
  std::vector<std::array<std::size_t, 3> > expected;
  for(const auto& t : disk.faces) expected.push_back(WMesh::normalized_face(t));
  std::sort(expected.begin(), expected.end());
  CHECK(wm.input_faces() == expected, "the input faces are back");
  return EXIT_SUCCESS;
}

template <class Mesh>
int test_restoration(const std::string& data)
{
  std::cout << "[" << mesh_name<Mesh>() << "] restoration of the connectivity" << std::endl;
  RUN(test_stages<Mesh>());
  {
    Mesh m;
    const auto c = PE::internal::make_stacked_triangulation(80, m);
    auto uv = make_uv_map(m, Epick::Point_2());
    pin_corners<Epick>(uv, c);
    CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uv, PE::parameters::border_shape(PE::Border_shape::FIXED)) == PE::OK, "Tutte");
    RUN(check_restoration(m, uv, "stacked depth 80, double"));
    auto uvq = make_uv_map(m, Kq::Point_2());
    convert_uv(m, uv, uvq);
    RUN(check_restoration(m, uvq, "stacked depth 80, Gmpq"));
  }
  {
    Mesh m;
    PE::internal::make_grid_disk(16, m);
    auto uv = make_uv_map(m, Epick::Point_2());
    CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE)) == PE::OK, "border");
    random_init(m, uv, 5);
    RUN(check_restoration(m, uv, "random init 16x16"));
  }
  {
    Mesh m;
    CHECK(read_mesh(data + "/meshes/bull.off", m), "read bull.off");
    std::array<vertex_descriptor<Mesh>, 3> pinned;
    CHECK(PE::internal::thingi_cut(m, 0, pinned) == PE::OK, "cut");
    auto uv = make_uv_map(m, Epick::Point_2());
    pin_corners<Epick>(uv, pinned);
    CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uv, PE::parameters::border_shape(PE::Border_shape::FIXED)) == PE::OK, "Tutte");
    RUN(check_restoration(m, uv, "bull seed 0"));
  }
  return EXIT_SUCCESS;
}

// ---- any scale the number type represents --------------------------------------------

// `uv` multiplied by `s` (in FT: 10^k is not a power of two, so the scaled map is a new map)
template <class Mesh, class UVM, class FT>
void scale_uv(const Mesh& m, UVM& uv, const FT& s)
{
  typedef typename boost::property_traits<UVM>::value_type P;
  for(auto v : vertices(m)) put(uv, v, P(get(uv, v).x() * s, get(uv, v).y() * s));
}

// A valid map at scale s: accepted as it is (no face invalid, nothing moved, bit for bit).
template <class Mesh>
int valid_map_at_scale(double s)
{
  Mesh m;
  PE::internal::make_grid_disk(12, m);
  auto uv = make_uv_map(m, Epick::Point_2());
  CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE)) == PE::OK, "Tutte");
  scale_uv(m, uv, s);
  CHECK(PE::check_embedding(m, uv).is_valid(), "the scaled Tutte map of a grid is valid");
  std::vector<Epick::Point_2> before;
  for(auto v : vertices(m)) before.push_back(get(uv, v));
  PE::Progressive_embedding_statistics st;
  const PE::Error_code ec = PE::progressive_embedding(m, uv, PE::parameters::statistics(&st));
  std::cout << "  valid map at scale " << s << ": " << PE::get_error_name(ec) << ", invalid faces " << st.invalid_faces_before << std::endl;
  CHECK(ec == PE::OK, "valid map at scale " << s << ": " << PE::get_error_name(ec));
  CHECK(st.invalid_faces_before == 0 && st.collapses == 0, "valid map at scale " << s << ": no face is invalid");
  CHECK(st.report.is_valid(), "certified");
  std::size_t k = 0;
  for(auto v : vertices(m))
  {
    const Epick::Point_2 p = get(uv, v), q = before[k++];
    CHECK(same_bits(p.x(), q.x()) && same_bits(p.y(), q.y()), "valid map at scale " << s << ": unchanged bit for bit");
  }
  return EXIT_SUCCESS;
}

// The power-of-two normalization alone: extent brought to [1/2, 1), exact round trips, and the
// identity when a border coordinate would not come back bit-exactly.
template <class K>
int scaling_case(const std::vector<typename K::Point_2>& border, long expected_exponent, const std::string& what)
{
  typedef typename K::FT FT;
  const auto s = PE::internal::Power_of_two_scaling<FT>::normalizing(border);
  std::cout << "  scaling of " << what << ": 2^" << s.exponent() << std::endl;
  CHECK(s.exponent() == expected_exponent, what << ": exponent " << s.exponent() << ", expected " << expected_exponent);
  for(const auto& p : border)
  {
    CHECK(s.backward(s.forward(p.x())) == p.x() && s.backward(s.forward(p.y())) == p.y(), what << ": exact round trip");
    if(s.exponent() != 0)
    {
      const FT x = s.forward(p.x());
      CHECK(CGAL::abs(x) <= FT(1), what << ": scaled coordinates within the unit box");
    }
  }
  return EXIT_SUCCESS;
}

int test_scaling_helper()
{
  // extent 2e200 = 2^665.x: scaled by 2^-666 into [1/2, 1)
  RUN(scaling_case<Epick>({ Epick::Point_2(-1e200, 0), Epick::Point_2(1e200, 0), Epick::Point_2(0, 1e200) }, -666, "double at 1e200"));
  RUN(scaling_case<Epick>({ Epick::Point_2(0, 0), Epick::Point_2(1, 0), Epick::Point_2(0, 1) }, 0, "double at 1 (left alone)"));
  // 1e-300 * 2^-997 underflows: it would not come back, so no scaling at all
  RUN(scaling_case<Epick>({ Epick::Point_2(1e-300, 0), Epick::Point_2(1e300, 0), Epick::Point_2(0, 1e300) }, 0, "double with a coordinate that underflows"));
  // beyond double range, exactly: 2^1100 and 2^-5000 in Gmpq
  const CGAL::Gmpq big = PE::internal::power_of_two<CGAL::Gmpq>(1100), tiny = PE::internal::power_of_two<CGAL::Gmpq>(-5000);
  CHECK(big == CGAL::Gmpq(1) / PE::internal::power_of_two<CGAL::Gmpq>(-1100), "2^1100 is exact");
  RUN(scaling_case<Kq>({ Kq::Point_2(0, 0), Kq::Point_2(big, 0), Kq::Point_2(0, big) }, -1101, "Gmpq at 2^1100"));
  RUN(scaling_case<Kq>({ Kq::Point_2(0, 0), Kq::Point_2(tiny * 3, 0), Kq::Point_2(0, tiny) }, 4998, "Gmpq at 2^-5000"));
  return EXIT_SUCCESS;
}

template <class Mesh>
int test_scale()
{
  std::cout << "[" << mesh_name<Mesh>() << "] maps at any scale" << std::endl;
  RUN(test_scaling_helper());
  const double scales[] = { 1e80, 1e200, 1e-80, 1e-200, 1e300, 1e-300 };
  for(double s : scales)
    RUN(valid_map_at_scale<Mesh>(s));

  // broken Tutte maps (deep stacked triangulation) and random initializations, scaled, in double
  Mesh m;
  const auto c = PE::internal::make_stacked_triangulation(40, m);
  auto uv = make_uv_map(m, Epick::Point_2());
  for(double s : scales)
  {
    pin_corners<Epick>(uv, c);
    CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uv, PE::parameters::border_shape(PE::Border_shape::FIXED)) == PE::OK, "Tutte");
    scale_uv(m, uv, s);
    CHECK(!PE::check_embedding(m, uv).is_valid(), "the scaled Tutte map is broken");
    std::ostringstream what; what << "stacked depth 40 at scale " << s << ", double";
    RUN(repair_and_certify(m, uv, what.str(), false));
  }
  Mesh g;
  PE::internal::make_grid_disk(12, g);
  auto uvg = make_uv_map(g, Epick::Point_2());
  for(double s : { 1e80, 1e-200 })
  {
    CHECK(PE::tutte_embedding(g, null_h<Mesh>(), uvg, PE::parameters::border_shape(PE::Border_shape::CIRCLE)) == PE::OK, "border");
    random_init(g, uvg, 3);
    scale_uv(g, uvg, s);
    for(auto v : vertices(g)) put(uvg, v, Epick::Point_2(get(uvg, v).x(), -get(uvg, v).y())); // clockwise too
    std::ostringstream what; what << "clockwise random init at scale " << s << ", double";
    RUN(repair_and_certify(g, uvg, what.str(), false));
  }

  // A small map far from the origin: the 8 x 8 grid on a square 2^-30 wide at (0.125, 0.375)
  // (every coordinate exact), all interior vertices at one point, then folded. The area inside
  // the border must be summed relative to the border: the shoelace sum on these coordinates
  // cancels to rounding noise 100 times the area, of either sign.
  for(int folded : { 0, 1 })
  {
    Mesh f;
    PE::internal::make_grid_disk(9, f);
    auto uvf = make_uv_map(f, Epick::Point_2());
    const double w = std::ldexp(1., -30);
    auto vpm = get(CGAL::vertex_point, f);
    for(auto v : vertices(f))
    {
      const double x = get(vpm, v).x(), y = get(vpm, v).y();
      if(CGAL::is_border(v, f)) put(uvf, v, Epick::Point_2(0.125 + x * w, 0.375 + y * w));
      else if(folded) put(uvf, v, Epick::Point_2(0.125 + (1 - x) * w, 0.375 + y * y * w));
      else put(uvf, v, Epick::Point_2(0.125 + 0.3 * w, 0.375 + 0.4 * w));
    }
    RUN(repair_and_certify(f, uvf, folded ? "folded grid 2^-30 wide at (0.125, 0.375)"
                                          : "grid 2^-30 wide at (0.125, 0.375), interior at one point", false));
  }

  // the broken double map converted exactly to Gmpq, then scaled by 10^200 and 10^-200 exactly
  pin_corners<Epick>(uv, c);
  CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uv, PE::parameters::border_shape(PE::Border_shape::FIXED)) == PE::OK, "Tutte");
  for(int e : { 200, -200 })
  {
    auto uvq = make_uv_map(m, Kq::Point_2());
    convert_uv(m, uv, uvq);
    CGAL::Gmpq s(1);
    for(int i = 0; i < 200; ++i) s = (e > 0) ? s * CGAL::Gmpq(10) : s / CGAL::Gmpq(10);
    scale_uv(m, uvq, s);
    RUN(repair_and_certify(m, uvq, "stacked depth 40 at scale 1e" + std::to_string(e) + ", Gmpq", true));
  }
  return EXIT_SUCCESS;
}

// the same certificate, field by field (bit for bit in the measures)
inline bool same_report(const PE::Embedding_report& a, const PE::Embedding_report& b)
{
  const PE::Distortion_report& da = a.distortion, & db = b.distortion;
  return a.summary() == b.summary() && a.status == b.status && a.faces == b.faces && a.vertices == b.vertices
      && a.border_vertices == b.border_vertices && a.flipped == b.flipped && a.degenerate == b.degenerate
      && a.border_simple == b.border_simple && a.overlap_checked == b.overlap_checked
      && a.overlapping_pairs == b.overlapping_pairs && a.min_signed_area == b.min_signed_area
      && a.max_signed_area == b.max_signed_area && a.border_area == b.border_area && a.max_energy_3d == b.max_energy_3d
      && a.mean_energy_3d == b.mean_energy_3d && a.max_energy_equilateral == b.max_energy_equilateral
      && a.mean_energy_equilateral == b.mean_energy_equilateral && a.high_energy_faces == b.high_energy_faces
      && a.has_3d_energy == b.has_3d_energy && da.faces == db.faces
      && da.mean_symmetric_dirichlet == db.mean_symmetric_dirichlet && da.max_symmetric_dirichlet == db.max_symmetric_dirichlet
      && da.symmetric_dirichlet_quantiles == db.symmetric_dirichlet_quantiles && da.mean_conformal == db.mean_conformal
      && da.max_conformal == db.max_conformal && da.mean_area == db.mean_area && da.max_area == db.max_area;
}

// repair_and_optimize() and parameterize_certified() on the broken double Tutte map of the stacked
// triangulation (depth 40) and on a valid grid map: which stages run under each policy, the certificates,
// the border kept, the statistics listed once each, the budget and the errors
template <class Mesh>
int test_pipeline()
{
  typedef PE::Optimization_policy Policy;
  std::cout << "[" << mesh_name<Mesh>() << "] repair_and_optimize" << std::endl;
  Mesh m;
  const auto c = PE::internal::make_stacked_triangulation(40, m);
  auto uv = make_uv_map(m, Epick::Point_2());
  auto broken = [&]() {
    pin_corners<Epick>(uv, c);
    CHECK(PE::tutte_embedding(m, null_h<Mesh>(), uv, PE::parameters::border_shape(PE::Border_shape::FIXED)) == PE::OK, "Tutte");
    return EXIT_SUCCESS;
  };
  for(Policy policy : { Policy::NEVER, Policy::WHEN_REPAIRED, Policy::ALWAYS })
  {
    RUN(broken());
    std::map<vertex_descriptor<Mesh>, Epick::Point_2> before;
    for(auto v : vertices(m)) before[v] = get(uv, v);
    PE::Pipeline_statistics ps;
    PE::internal::indexing_count() = 0;
    const PE::Error_code ec = PE::repair_and_optimize(m, uv, PE::parameters::optimization_policy(policy).pipeline_statistics(&ps));
    CHECK(PE::internal::indexing_count() == 1, "the stages share one indexing of the mesh, not " << PE::internal::indexing_count());
    std::cout << "  broken map, policy " << int(policy) << ": " << PE::get_error_name(ec) << ", repaired " << ps.repaired
              << ", optimized " << ps.optimized << ", " << ps.report.summary() << std::endl;
    CHECK(ec == PE::OK && !ps.input_report.is_valid() && ps.repaired && ps.repair.collapses > 0, "the broken map is repaired");
    CHECK(ps.optimized == (policy != Policy::NEVER), "optimized as the policy says");
    CHECK(ps.report.is_valid() && same_report(ps.report, PE::check_embedding(m, uv)),
          "certified, and the report is the certificate of the map left in uv (pe writes the map with it)");
    for(auto v : vertices(m))
      if(CGAL::is_border(v, m)) CHECK(get(uv, v) == before[v], "border bit-exact");
    if(ps.optimized)
      CHECK(ps.optimization_status == PE::OK && ps.optimization.energy_after < ps.optimization.energy_before,
            "the optimization lowers the energy");
    // every statistic once, with the keys pe prints
    std::set<std::string> keys;
    std::size_t n = 0;
    PE::for_each_statistic(ps, [&](const char* key, const auto&) { keys.insert(key); ++n; });
    CHECK(n == 15 && keys.size() == n && keys.count("collapses") && keys.count("energy_after") && keys.count("optimization_status"),
          "15 statistics, each once");
  }
  // a valid map: nothing to repair; optimized only with ALWAYS, unchanged otherwise
  {
    Mesh g;
    PE::internal::make_grid_disk(12, g);
    auto uvg = make_uv_map(g, Epick::Point_2());
    CHECK(PE::tutte_embedding(g, null_h<Mesh>(), uvg, PE::parameters::border_shape(PE::Border_shape::CIRCLE)) == PE::OK, "grid");
    std::map<vertex_descriptor<Mesh>, Epick::Point_2> before;
    for(auto v : vertices(g)) before[v] = get(uvg, v);
    PE::Pipeline_statistics ps;
    CHECK(PE::repair_and_optimize(g, uvg, PE::parameters::pipeline_statistics(&ps)) == PE::OK && !ps.repaired && !ps.optimized
          && same_report(ps.report, PE::check_embedding(g, uvg)), "a valid map is neither repaired nor optimized by default");
    bool same = true;
    for(auto v : vertices(g)) same = same && get(uvg, v) == before[v];
    CHECK(same, "and left bit-exactly as it was");
    CHECK(PE::repair_and_optimize(g, uvg, PE::parameters::pipeline_statistics(&ps).optimization_policy(Policy::ALWAYS)) == PE::OK
          && !ps.repaired && ps.optimized && ps.report.is_valid(), "ALWAYS optimizes a valid map");
    // the optimization's own budget: it stops at once with the certified map, and the call still succeeds
    for(auto v : vertices(g)) put(uvg, v, before[v]);
    CHECK(PE::repair_and_optimize(g, uvg, PE::parameters::pipeline_statistics(&ps).optimization_policy(Policy::ALWAYS)
                                            .optimization_time_limit(0.)) == PE::OK
          && ps.optimized && ps.optimization_status == PE::ERROR_BUDGET_EXHAUSTED && !ps.optimization.converged
          && ps.optimization.iterations <= 1 && ps.report.is_valid() && same_report(ps.report, PE::check_embedding(g, uvg)),
          "optimization_time_limit(0): OK, the optimization stopped by its budget (ERROR_BUDGET_EXHAUSTED), a certified map");
  }
  // parameterize_certified: Tutte, then the policy, on one indexing of the mesh; from every border halfedge the
  // map of the stages run one by one (each indexing the mesh itself), bit for bit
  {
    std::size_t starts = 0;
    for(auto bh : halfedges(m))
    {
      if(!CGAL::is_border(bh, m) || ++starts > 3) continue;
      PE::Pipeline_statistics ps;
      pin_corners<Epick>(uv, c);
      PE::internal::indexing_count() = 0;
      const PE::Error_code ec = PE::parameterize_certified(m, bh, uv,
                                  PE::parameters::border_shape(PE::Border_shape::FIXED).pipeline_statistics(&ps));
      CHECK(ec == PE::OK && !ps.input_report.is_valid() && ps.repaired && ps.optimized && ps.report.is_valid()
            && ps.seconds_tutte > 0 && ps.seconds_total >= ps.seconds_tutte, "parameterize_certified: Tutte, repair, optimization");
      CHECK(PE::internal::indexing_count() == 1, "parameterize_certified indexes the mesh once, not " << PE::internal::indexing_count());
      CHECK(same_report(ps.report, PE::check_embedding(m, uv)), "parameterize_certified: the certificate of the map left in uv");
      auto uv2 = make_uv_map(m, Epick::Point_2());
      pin_corners<Epick>(uv2, c);
      CHECK(PE::tutte_embedding(m, bh, uv2, PE::parameters::border_shape(PE::Border_shape::FIXED)) == PE::OK
            && PE::check_embedding(m, uv2).flipped > 0
            && PE::progressive_embedding(m, uv2, PE::parameters::minimum_area_ratio(1e-3)) == PE::OK
            && PE::optimize_distortion(m, uv2) == PE::OK, "the stages one by one");
      bool same = true;
      for(auto v : vertices(m)) same = same && get(uv, v) == get(uv2, v);
      CHECK(same, "parameterize_certified from a border halfedge: the map of the stages one by one");
    }
    // the border of a disk indexed from any border halfedge, started as make_indexed_disk() starts it by default
    PE::internal::Indexed_disk<Mesh> d0, d;
    CHECK(PE::internal::make_indexed_disk(m, null_h<Mesh>(), d0) == PE::OK, "indexed");
    std::size_t rotated = 0;
    for(auto bh : halfedges(m))
    {
      if(!CGAL::is_border(bh, m)) continue;
      CHECK(PE::internal::make_indexed_disk(m, bh, d) == PE::OK, "indexed from a border halfedge");
      rotated += (d.border != d0.border);
      PE::internal::start_border_as_default(m, d);
      CHECK(d.border == d0.border && d.faces == d0.faces && d.vertices == d0.vertices, "start_border_as_default");
    }
    CHECK(rotated > 0, "some border halfedges start the border elsewhere");
  }
  // budget and errors: the uv map unchanged
  {
    RUN(broken());
    std::map<vertex_descriptor<Mesh>, Epick::Point_2> before;
    for(auto v : vertices(m)) before[v] = get(uv, v);
    CHECK(PE::repair_and_optimize(m, uv, CGAL::parameters::maximum_running_time(0.)) == PE::ERROR_BUDGET_EXHAUSTED,
          "no time: ERROR_BUDGET_EXHAUSTED");
    CHECK(PE::repair_and_optimize(m, uv, CGAL::parameters::maximum_running_time(-1.)) == PE::ERROR_WRONG_PARAMETER,
          "a negative budget: ERROR_WRONG_PARAMETER");
    CHECK(PE::repair_and_optimize(m, uv, PE::parameters::optimization_time_limit(-1.)) == PE::ERROR_WRONG_PARAMETER
          && PE::repair_and_optimize(m, uv, PE::parameters::optimization_time_limit(std::nan(""))) == PE::ERROR_WRONG_PARAMETER,
          "a negative or NaN optimization budget: ERROR_WRONG_PARAMETER");
    bool same = true;
    for(auto v : vertices(m)) same = same && get(uv, v) == before[v];
    CHECK(same, "the uv map unchanged on error");
    Mesh closed;
    CGAL::make_tetrahedron(Epick::Point_3(0, 0, 0), Epick::Point_3(1, 0, 0), Epick::Point_3(0, 1, 0), Epick::Point_3(0, 0, 1), closed);
    auto uvc = make_uv_map(closed, Epick::Point_2());
    CHECK(PE::repair_and_optimize(closed, uvc) == PE::ERROR_NOT_A_DISK, "a closed mesh: ERROR_NOT_A_DISK");
    CHECK(PE::parameterize_certified(closed, null_h<Mesh>(), uvc) == PE::ERROR_NOT_A_DISK, "parameterize_certified too");
  }
  // exact rationals: the broken map converted exactly, repaired exactly (no optimization: it runs in double)
  {
    RUN(broken());
    auto uvq = make_uv_map(m, Kq::Point_2());
    convert_uv(m, uv, uvq);
    PE::Pipeline_statistics ps;
    CHECK(PE::repair_and_optimize(m, uvq, PE::parameters::optimization_policy(Policy::NEVER).pipeline_statistics(&ps)) == PE::OK
          && ps.repaired && ps.report.is_valid() && PE::check_embedding(m, uvq).is_valid(), "Gmpq: repaired and certified");
  }
  return EXIT_SUCCESS;
}

// one group of tests on one mesh type
template <class Mesh>
int run_group(const std::string& group, const std::string& data)
{
  if(group == "stacked") { RUN(test_stacked<Mesh>(40)); return test_stacked<Mesh>(80); }
  if(group == "random_init") return test_random_inits<Mesh>();
  if(group == "special") { RUN(test_border_cluster<Mesh>()); return test_special_inputs<Mesh>(); }
  if(group == "refused") return test_refused_inputs<Mesh>();
  if(group == "bull") return test_corpus<Mesh>(data, "bull.off", 0);
  if(group == "man") return test_corpus<Mesh>(data, "man.off", 35);
  if(group == "scale") return test_scale<Mesh>();
  if(group == "restoration") return test_restoration<Mesh>(data);
  if(group == "pipeline") return test_pipeline<Mesh>();
  std::cerr << "unknown group " << group << std::endl;
  return EXIT_FAILURE;
}

} // namespace

// Usage: test_progressive_embedding DATA_DIR [GROUP [surface_mesh|polyhedron]]
// GROUP: stacked, random_init, special, refused, bull, man, scale, restoration, pipeline (default: all, on both mesh types)
int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " DATA_DIR [GROUP [surface_mesh|polyhedron]]" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string data = argv[1];
  const std::string group = (argc > 2) ? argv[2] : "all", mesh = (argc > 3) ? argv[3] : "all";
  const std::vector<std::string> groups = { "stacked", "random_init", "special", "refused", "bull", "man", "scale", "restoration",
                                          "pipeline" };
  bool ran = false;
  for(const std::string& g : groups)
  {
    if(group != "all" && group != g) continue;
    if(mesh == "all" || mesh == "surface_mesh") { RUN(run_group<Surface_mesh>(g, data)); ran = true; }
    if(mesh == "all" || mesh == "polyhedron") { RUN(run_group<Polyhedron>(g, data)); ran = true; }
  }
  if(!ran) { std::cerr << "nothing to run for group '" << group << "' and mesh '" << mesh << "'" << std::endl; return EXIT_FAILURE; }
  std::cout << "test_progressive_embedding " << group << " " << mesh << ": all checks passed" << std::endl;
  return EXIT_SUCCESS;
}
