// Tests of distortion.h and optimize_distortion.h: measures against hand-computed values,
// the identity as the minimum, validity kept in double and MPFR, hard constraints kept
// bit-exactly, free border kept simple, budgets.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/Unique_hash_map.h>
#include <boost/property_map/property_map.hpp>

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/distortion.h>
#include <CGAL/Progressive_embedding/internal/protocols.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <random>
#include <string>

namespace PE = CGAL::Progressive_embedding;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef CGAL::Polyhedron_3<K> Poly;

static int failures = 0;
#define CHECK(cond, what)                                                                   \
  do { if(!(cond)) { std::cerr << "FAILED: " << what << "  [" #cond "] at line " << __LINE__ << "\n"; ++failures; } \
       else std::cout << "ok: " << what << "\n"; } while(0)

static bool close(double a, double b, double tol) { return std::abs(a - b) <= tol * (1 + std::abs(b)); }

// uv map for any FaceGraph, any point type
template <class Mesh, class P>
struct UV
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  std::map<vd, P> storage;
  boost::associative_property_map<std::map<vd, P> > map() { return boost::associative_property_map<std::map<vd, P> >(storage); }
};

template <class Mesh, class UVM>
void random_interior(const Mesh& m, UVM uvm, unsigned seed, double radius)
{
  typedef typename boost::property_traits<UVM>::value_type P;
  typedef typename CGAL::Kernel_traits<P>::Kernel::FT FT;
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  for(auto v : vertices(m))
  {
    bool border = false;
    for(auto h : CGAL::halfedges_around_target(v, m)) if(is_border(h, m) || is_border(opposite(h, m), m)) border = true;
    if(border) continue;
    double x, y; do { x = U(gen); y = U(gen); } while(x * x + y * y > 1);
    put(uvm, v, P(PE::internal::make_ft<FT>(radius * x), PE::internal::make_ft<FT>(radius * y)));
  }
}

void test_hand_computed()
{
  // one right triangle, 3D (0,0,0),(1,0,0),(0,1,0) -> uv (0,0),(2,0),(0,1/2): same area, J = diag(2, 1/2)
  SM m;
  auto a = m.add_vertex(K::Point_3(0, 0, 0)), b = m.add_vertex(K::Point_3(1, 0, 0)), c = m.add_vertex(K::Point_3(0, 1, 0));
  m.add_face(a, b, c);
  auto uv = m.add_property_map<SM::Vertex_index, K::Point_2>("uv").first;
  uv[a] = K::Point_2(0, 0); uv[b] = K::Point_2(2, 0); uv[c] = K::Point_2(0, 0.5);
  PE::Distortion_report d = PE::measure_distortion(m, uv);
  CHECK(d.status == PE::OK, "measure_distortion on one triangle");
  CHECK(close(d.max_symmetric_dirichlet, 4 + 0.25 + 0.25 + 4, 1e-12), "symmetric Dirichlet of diag(2,1/2) is 8.5");
  CHECK(close(d.max_conformal, 4.25, 1e-12), "conformal distortion of diag(2,1/2) is 4.25");
  CHECK(close(d.max_area, 1, 1e-12), "area distortion of an area-preserving map is 1");
  PE::Embedding_report r = PE::check_embedding(m, uv);
  CHECK(close(r.max_energy_3d, d.max_symmetric_dirichlet, 0) && close(r.mean_energy_3d, d.mean_symmetric_dirichlet, 0),
        "check_embedding reports the same numbers as measure_distortion");
  // the identity: 4, 2, 1
  uv[b] = K::Point_2(1, 0); uv[c] = K::Point_2(0, 1);
  d = PE::measure_distortion(m, uv);
  CHECK(close(d.max_symmetric_dirichlet, 4, 1e-12) && close(d.max_conformal, 2, 1e-12) && close(d.max_area, 1, 1e-12),
        "identity: symmetric Dirichlet 4, conformal 2, area 1");
  // a similarity is scaled away (3D scaled to the uv area): still 4
  uv[b] = K::Point_2(0, 3); uv[c] = K::Point_2(-3, 0);
  d = PE::measure_distortion(m, uv);
  CHECK(close(d.max_symmetric_dirichlet, 4, 1e-12), "a rotated, scaled copy has symmetric Dirichlet 4");
  // flipped: infinite
  uv[b] = K::Point_2(0, 1); uv[c] = K::Point_2(1, 0);
  uv[a] = K::Point_2(0, 0);
  // one triangle alone is its own border, so flip it relative to a second face instead: build two faces
  SM m2;
  auto p0 = m2.add_vertex(K::Point_3(0, 0, 0)), p1 = m2.add_vertex(K::Point_3(1, 0, 0)), p2 = m2.add_vertex(K::Point_3(1, 1, 0)), p3 = m2.add_vertex(K::Point_3(0, 1, 0));
  m2.add_face(p0, p1, p2); m2.add_face(p0, p2, p3);
  auto uv2 = m2.add_property_map<SM::Vertex_index, K::Point_2>("uv").first;
  uv2[p0] = K::Point_2(0, 0); uv2[p1] = K::Point_2(1, 0); uv2[p2] = K::Point_2(1, 1); uv2[p3] = K::Point_2(0, 1);
  d = PE::measure_distortion(m2, uv2);
  CHECK(close(d.mean_symmetric_dirichlet, 4, 1e-12) && close(d.symmetric_dirichlet_quantiles[0], 4, 1e-12), "unit square identity: mean and median 4");
}

// Planar patch, border fixed at its own coordinates, interior scrambled then repaired:
// the optimization returns to the identity (energy 4, i.e. 2 per dimension).
template <class Mesh>
void test_identity_is_minimum(const char* name)
{
  Mesh m;
  PE::internal::make_grid_disk(12, m);
  UV<Mesh, K::Point_2> store;
  auto uvm = store.map();
  for(auto v : vertices(m)) { const auto& p = get(CGAL::vertex_point, m, v); put(uvm, v, K::Point_2(p.x(), p.y())); }
  random_interior(m, uvm, 3, 0.3);
  // shift the random points into the unit square
  for(auto v : vertices(m))
  {
    bool border = false;
    for(auto h : CGAL::halfedges_around_target(v, m)) if(is_border(h, m) || is_border(opposite(h, m), m)) border = true;
    if(!border) { K::Point_2 p = get(uvm, v); put(uvm, v, K::Point_2(p.x() + 0.5, p.y() + 0.5)); }
  }
  std::vector<K::Point_2> border_before;
  for(auto v : vertices(m)) border_before.push_back(get(uvm, v));
  // the square border has collinear vertices: not strictly convex, but convex, which progressive embedding accepts
  PE::Error_code ec = PE::progressive_embedding(m, uvm);
  CHECK(ec == PE::OK, std::string(name) + ": repair of the scrambled patch");
  PE::Optimization_statistics st;
  ec = PE::optimize_distortion(m, uvm, PE::parameters::optimization_statistics(&st, CGAL::parameters::number_of_iterations(500)));
  CHECK(ec == PE::OK && st.converged, std::string(name) + ": optimization converged");
  CHECK(st.report.is_valid(), std::string(name) + ": optimized map certified valid");
  CHECK(std::abs(st.energy_after - 4) < 1e-3, std::string(name) + ": energy back to the identity's 4 (got " + std::to_string(st.energy_after) + ")");
  double err = 0;
  for(auto v : vertices(m))
  {
    const auto& p = get(CGAL::vertex_point, m, v);
    err = (std::max)(err, std::abs(get(uvm, v).x() - p.x()) + std::abs(get(uvm, v).y() - p.y()));
  }
  CHECK(err < 1e-3, std::string(name) + ": positions back to the identity (max error " + std::to_string(err) + ")");
  std::size_t k = 0; bool same = true;
  for(auto v : vertices(m))
  {
    bool border = false;
    for(auto h : CGAL::halfedges_around_target(v, m)) if(is_border(h, m) || is_border(opposite(h, m), m)) border = true;
    if(border && !(get(uvm, v) == border_before[k])) same = false;
    ++k;
  }
  CHECK(same, std::string(name) + ": border bit-exact");
}

// A map one step from flipping: one interior vertex almost on the segment of two neighbours.
template <class Kernel2>
void test_near_flip(const char* name)
{
  typedef typename Kernel2::Point_2 P;
  typedef typename Kernel2::FT FT;
  SM m;
  PE::internal::make_grid_disk(8, m);
  auto uvm = m.add_property_map<SM::Vertex_index, P>(std::string("uv_") + name).first;
  for(auto v : m.vertices()) { const auto& p = m.point(v); uvm[v] = P(PE::internal::make_ft<FT>(p.x()), PE::internal::make_ft<FT>(p.y())); }
  // vertex (3,3) of the 8x8 grid; the face (v, (4,3), (4,4)) has the edge x = 4/7 opposite to v:
  // put v at distance 1e-13 from that edge, inside its star
  SM::Vertex_index v(3 * 8 + 3);
  const double eps = 1e-13;
  const double x = 4.0 / 7 - eps, y = 3.5 / 7;
  uvm[v] = P(PE::internal::make_ft<FT>(x), PE::internal::make_ft<FT>(y));
  PE::Embedding_report r0 = PE::check_embedding(m, uvm);
  CHECK(r0.is_valid() && r0.min_signed_area < 1e-12, std::string(name) + ": the input is valid and almost degenerate (min area " + std::to_string(r0.min_signed_area) + ")");
  PE::Optimization_statistics st;
  PE::Error_code ec = PE::optimize_distortion(m, uvm, PE::parameters::optimization_statistics(&st, CGAL::parameters::number_of_iterations(50)));
  CHECK((ec == PE::OK || ec == PE::ERROR_BUDGET_EXHAUSTED) && st.report.is_valid(), std::string(name) + ": stays valid (" + PE::get_error_name(ec) + ")");
  CHECK(st.energy_after < st.energy_before && st.report.min_signed_area > 1e-6, std::string(name) + ": the thin face recovered (energy "
        + std::to_string(st.energy_before) + " -> " + std::to_string(st.energy_after) + ")");
}

void test_constraints_and_budgets()
{
  SM m;
  PE::internal::make_grid_disk(20, m);
  auto uvm = m.add_property_map<SM::Vertex_index, K::Point_2>("uv").first;
  PE::tutte_embedding(m, SM::null_halfedge(), uvm, PE::parameters::border_shape(PE::Border_shape::CIRCLE));
  random_interior(m, uvm, 5, 0.9);
  CHECK(PE::progressive_embedding(m, uvm) == PE::OK, "random init on a 20x20 disk repaired");
  // constrain a few interior vertices where they are
  std::vector<SM::Vertex_index> constrained;
  std::vector<K::Point_2> values;
  for(auto v : m.vertices()) if(!m.is_border(v) && (std::size_t(v) % 37 == 0)) { constrained.push_back(v); values.push_back(uvm[v]); }
  PE::Optimization_statistics st;
  PE::Error_code ec = PE::optimize_distortion(m, uvm, PE::parameters::constrained_vertices(constrained,
                                                PE::parameters::optimization_statistics(&st)));
  CHECK(ec == PE::OK && st.report.is_valid(), "optimization with hard constraints: converged and valid");
  bool exact = true;
  for(std::size_t k = 0; k < constrained.size(); ++k)
    if(std::memcmp(&uvm[constrained[k]], &values[k], sizeof(K::Point_2)) != 0) exact = false;
  CHECK(exact && !constrained.empty(), "constrained vertices bit-exact (" + std::to_string(constrained.size()) + " vertices)");
  CHECK(st.energy_after < st.energy_before, "energy lowered with constraints");

  // free border: the border moves and stays simple
  std::vector<K::Point_2> before;
  for(auto v : m.vertices()) before.push_back(uvm[v]);
  ec = PE::optimize_distortion(m, uvm, PE::parameters::free_border(true, PE::parameters::optimization_statistics(&st)));
  bool border_moved = false;
  for(auto v : m.vertices()) if(m.is_border(v) && !(uvm[v] == before[std::size_t(v)])) border_moved = true;
  CHECK((ec == PE::OK || ec == PE::ERROR_BUDGET_EXHAUSTED) && st.report.is_valid() && st.report.border_simple && border_moved,
        "free-border optimization: border moved and stays simple, map valid");

  // the parallel sweeps (greedy colouring, TBB when linked) end as valid and as good
  {
    std::vector<K::Point_2> start;
    for(auto v : m.vertices()) start.push_back(uvm[v]);
    PE::Optimization_statistics seq, par;
    for(auto v : m.vertices()) if(!m.is_border(v)) uvm[v] = start[std::size_t(v)];
    PE::Error_code e1 = PE::optimize_distortion<CGAL::Sequential_tag>(m, uvm, PE::parameters::optimization_statistics(&seq));
    for(auto v : m.vertices()) uvm[v] = start[std::size_t(v)];
    PE::Error_code e2 = PE::optimize_distortion<CGAL::Parallel_tag>(m, uvm, PE::parameters::optimization_statistics(&par));
#ifdef CGAL_LINKED_WITH_TBB
    const std::string how = "with TBB";
#else
    const std::string how = "without TBB (sequential fallback)";
#endif
    CHECK(e1 == e2 && par.report.is_valid() && std::abs(par.energy_after - seq.energy_after) < 1e-2 * seq.energy_after,
          "Parallel_tag " + how + ": valid, energy " + std::to_string(par.energy_after) + " (sequential " + std::to_string(seq.energy_after) + ")");
  }

  // budgets: one iteration from a scrambled start ends with a specific code and a valid map
  random_interior(m, uvm, 9, 0.5);
  for(auto v : m.vertices()) if(m.is_border(v)) uvm[v] = before[std::size_t(v)];
  PE::progressive_embedding(m, uvm);
  ec = PE::optimize_distortion(m, uvm, PE::parameters::optimization_statistics(&st, CGAL::parameters::number_of_iterations(1)));
  CHECK(ec == PE::ERROR_BUDGET_EXHAUSTED && st.report.is_valid(), "iteration budget: ERROR_BUDGET_EXHAUSTED with a valid map");
  ec = PE::optimize_distortion(m, uvm, PE::parameters::optimization_statistics(&st, CGAL::parameters::maximum_running_time(0.0)));
  CHECK(ec == PE::ERROR_BUDGET_EXHAUSTED && st.report.is_valid(), "time budget: ERROR_BUDGET_EXHAUSTED with a valid map");
  // invalid input is refused, nothing written
  auto some = *m.vertices().begin();
  for(auto v : m.vertices()) if(!m.is_border(v)) { some = v; break; }
  uvm[some] = K::Point_2(5, 5);
  const K::Point_2 kept = uvm[some];
  ec = PE::optimize_distortion(m, uvm);
  CHECK(ec == PE::ERROR_INVALID_EMBEDDING && uvm[some] == kept, "an invalid input map is refused (ERROR_INVALID_EMBEDDING)");
}

template <class Kernel2>
void test_number_type(const char* name)
{
  typedef typename Kernel2::Point_2 P;
  typedef typename Kernel2::FT FT;
  SM m;
  PE::internal::make_grid_disk(6, m);
  auto uvm = m.add_property_map<SM::Vertex_index, P>(std::string("uvn_") + name).first;
  for(auto v : m.vertices()) { const auto& p = m.point(v); uvm[v] = P(PE::internal::make_ft<FT>(p.x()), PE::internal::make_ft<FT>(p.y())); }
  random_interior(m, uvm, 4, 0.2);
  for(auto v : m.vertices())
    if(!m.is_border(v)) uvm[v] = P(uvm[v].x() + PE::internal::make_ft<FT>(0.5), uvm[v].y() + PE::internal::make_ft<FT>(0.5));
  CHECK(PE::progressive_embedding(m, uvm) == PE::OK, std::string(name) + ": repair");
  PE::Optimization_statistics st;
  PE::Error_code ec = PE::optimize_distortion(m, uvm, PE::parameters::optimization_statistics(&st, CGAL::parameters::number_of_iterations(20)));
  CHECK((ec == PE::OK || ec == PE::ERROR_BUDGET_EXHAUSTED) && st.report.is_valid() && st.energy_after < st.energy_before,
        std::string(name) + ": optimization certified in the number type, energy " + std::to_string(st.energy_before) + " -> " + std::to_string(st.energy_after));
}

int main()
{
  test_hand_computed();
  test_identity_is_minimum<SM>("Surface_mesh");
  test_identity_is_minimum<Poly>("Polyhedron_3");
  test_near_flip<K>("double");
  CGAL::Gmpfr::set_default_precision(128);
  test_near_flip<CGAL::Simple_cartesian<CGAL::Gmpfr> >("Gmpfr(128)");
  test_constraints_and_budgets();
  test_number_type<CGAL::Simple_cartesian<CGAL::Gmpq> >("Gmpq");
  test_number_type<CGAL::Simple_cartesian<CGAL::Gmpfr> >("Gmpfr(128)");
  if(failures) { std::cerr << failures << " check(s) failed\n"; return EXIT_FAILURE; }
  std::cout << "all distortion checks passed\n";
  return EXIT_SUCCESS;
}
