// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Tests of progressive_embedding() (issue 3): broken Tutte maps (deep stacked triangulation,
// corpus runs of libcgal-demo), random initializations, all interior vertices at one point,
// a clockwise border, and the inputs it must refuse -- in double, Gmpq and Gmpfr, on
// Surface_mesh and on Polyhedron_3. Every success is checked with an independent certificate,
// a bit-exact border and unchanged connectivity.
//
// Usage: test_progressive_embedding DATA_DIR   (DATA_DIR contains libcgal-demo's meshes/)

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/internal/protocols.h>

#include "test_util.h"

#include <limits>

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
  const auto faces_before = face_list(m);
  const std::size_t nv = num_vertices(m), nf = num_faces(m);
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
  CHECK(num_vertices(m) == nv && num_faces(m) == nf && face_list(m) == faces_before, what << ": connectivity unchanged");
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
  std::cout << "  double Tutte: " << r.summary() << " (DESIGN.md: 3 flipped at depth 40, 49 at depth 80)" << std::endl;
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

// one group of tests on one mesh type
template <class Mesh>
int run_group(const std::string& group, const std::string& data)
{
  if(group == "stacked") { RUN(test_stacked<Mesh>(40)); return test_stacked<Mesh>(80); }
  if(group == "random_init") return test_random_inits<Mesh>();
  if(group == "special") return test_special_inputs<Mesh>();
  if(group == "refused") return test_refused_inputs<Mesh>();
  if(group == "bull") return test_corpus<Mesh>(data, "bull.off", 0);
  if(group == "man") return test_corpus<Mesh>(data, "man.off", 35);
  std::cerr << "unknown group " << group << std::endl;
  return EXIT_FAILURE;
}

} // namespace

// Usage: test_progressive_embedding DATA_DIR [GROUP [surface_mesh|polyhedron]]
// GROUP: stacked, random_init, special, refused, bull, man (default: all, on both mesh types)
int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " DATA_DIR [GROUP [surface_mesh|polyhedron]]" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string data = argv[1];
  const std::string group = (argc > 2) ? argv[2] : "all", mesh = (argc > 3) ? argv[3] : "all";
  const std::vector<std::string> groups = { "stacked", "random_init", "special", "refused", "bull", "man" };
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
