// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// OpenMesh's TriMesh_ArrayKernelT as a third FaceGraph model: the main functions of the package on it,
// with the same certificates as on Surface_mesh and Polyhedron_3.
//
// Usage: test_openmesh DATA_DIR GROUP   (DATA_DIR contains libcgal-demo's meshes/)
// GROUP: tutte, repair, optimize, constrained, parameterizer

#include "openmesh_util.h"

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/distortion.h>
#include <CGAL/Progressive_embedding/constrained_embedding.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_parameterizer_3.h>

#include "test_util.h"
#include <CGAL/Progressive_embedding/internal/disk_generators.h>
#include <CGAL/Progressive_embedding/internal/tutte_failure_protocol.h>

#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

namespace {

typedef boost::graph_traits<Om_mesh>::vertex_descriptor VD;
typedef Epick::Point_2 Point_2;

const auto null_h = boost::graph_traits<Om_mesh>::null_halfedge();

bool read_om(const std::string& fname, Om_mesh& m)
{
  m.clear();
  if(!CGAL::IO::read_polygon_mesh(fname, m, CGAL::parameters::vertex_point_map(Om_point_map{ &m })))
  {
    std::cerr << "cannot read " << fname << std::endl;
    return false;
  }
  return true;
}

// the border vertices' uv, to compare bit for bit
template <class UVM>
std::vector<Point_2> border_uv(const Om_mesh& m, const UVM& uv)
{
  std::vector<Point_2> b;
  for(auto v : vertices(m))
    if(CGAL::is_border(v, m)) b.push_back(get(uv, v));
  return b;
}

// Tutte maps of a real disk in every border shape and both weights, certified
int test_tutte(const std::string& data)
{
  Om_mesh m;
  if(!read_om(data + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
  std::cout << "[OpenMesh] mushroom: " << num_vertices(m) << " vertices, " << num_faces(m) << " faces" << std::endl;
  auto uv = make_uv_map(m, Point_2());
  for(PE::Border_shape shape : { PE::Border_shape::CIRCLE, PE::Border_shape::SQUARE, PE::Border_shape::TRIANGLE })
    for(PE::Weights w : { PE::Weights::UNIFORM, PE::Weights::MEAN_VALUE })
    {
      const PE::Error_code ec = PE::tutte_embedding(m, null_h, uv, PE::parameters::border_shape(shape).weights(w)
                                                                      .vertex_point_map(Om_point_map{ &m }));
      const PE::Embedding_report r = PE::check_embedding(m, uv);
      std::cout << "  Tutte shape " << int(shape) << " weights " << int(w) << ": " << r.summary() << std::endl;
      CHECK(ec == PE::OK && r.status == PE::OK, "Tutte ran");
      CHECK(r.is_valid() && r.flipped == 0 && r.degenerate == 0 && r.faces == num_faces(m), "certified");
    }
  // a closed mesh is refused
  Om_mesh closed;
  if(!read_om(data + "/meshes/bull.off", closed)) return EXIT_FAILURE;
  auto uvc = make_uv_map(closed, Point_2());
  const PE::Error_code ec = PE::tutte_embedding(closed, null_h, uvc, PE::parameters::border_shape(PE::Border_shape::CIRCLE));
  std::cout << "  closed bull: " << PE::get_error_name(ec) << std::endl;
  CHECK(ec == PE::ERROR_NOT_A_DISK, "closed mesh refused");
  return EXIT_SUCCESS;
}

// the deep stacked triangulation: double Tutte flips faces, progressive embedding repairs them, the
// border is kept bit for bit, and the same map comes out as on Surface_mesh
int test_repair()
{
  Om_mesh m;
  const auto corners = PE::internal::make_stacked_triangulation(40, m);
  auto uv = make_uv_map(m, Point_2());
  pin_corners<Epick>(uv, corners);
  const auto fixed = PE::parameters::border_shape(PE::Border_shape::FIXED);
  CHECK(PE::tutte_embedding(m, null_h, uv, fixed) == PE::OK, "double Tutte ran");
  const PE::Embedding_report before = PE::check_embedding(m, uv);
  std::cout << "[OpenMesh] stacked depth 40, double Tutte: " << before.summary() << std::endl;
  CHECK(!before.is_valid() && before.flipped > 0, "double Tutte fails");
  const std::vector<Point_2> border = border_uv(m, uv);
  PE::Progressive_embedding_statistics st;
  CHECK(PE::progressive_embedding(m, uv, PE::parameters::statistics(&st)) == PE::OK, "repaired");
  const PE::Embedding_report after = PE::check_embedding(m, uv);
  std::cout << "  progressive embedding: " << after.summary() << ", " << st.insertions << " insertions" << std::endl;
  CHECK(after.is_valid() && after.flipped == 0 && after.degenerate == 0, "certified");
  CHECK(border_uv(m, uv) == border, "border bit-exact");

  // the same input on Surface_mesh gives the same certificate counts
  Surface_mesh s;
  const auto sc = PE::internal::make_stacked_triangulation(40, s);
  auto suv = make_uv_map(s, Point_2());
  pin_corners<Epick>(suv, sc);
  CHECK(PE::tutte_embedding(s, boost::graph_traits<Surface_mesh>::null_halfedge(), suv, fixed) == PE::OK, "Surface_mesh Tutte");
  const PE::Embedding_report sb = PE::check_embedding(s, suv);
  CHECK(sb.flipped == before.flipped && sb.degenerate == before.degenerate, "same double Tutte map as on Surface_mesh");
  return EXIT_SUCCESS;
}

// optimization of a real disk's Tutte map: lower energy, still certified, border and fixed vertices bit-exact
int test_optimize(const std::string& data)
{
  Om_mesh m;
  if(!read_om(data + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
  auto uv = make_uv_map(m, Point_2());
  const Om_point_map vpm{ &m };
  CHECK(PE::tutte_embedding(m, null_h, uv, PE::parameters::border_shape(PE::Border_shape::CIRCLE).vertex_point_map(vpm)) == PE::OK, "Tutte");
  const PE::Distortion_report d0 = PE::measure_distortion(m, uv, CGAL::parameters::vertex_point_map(vpm));
  std::vector<VD> pinned;
  for(auto v : vertices(m))
    if(!CGAL::is_border(v, m) && pinned.size() < 2 && int(v.idx()) % 97 == 0) pinned.push_back(v);
  std::vector<Point_2> pinned_uv;
  for(VD v : pinned) pinned_uv.push_back(get(uv, v));
  const std::vector<Point_2> border = border_uv(m, uv);
  PE::Optimization_statistics os;
  const PE::Error_code ec = PE::optimize_distortion(m, uv, PE::parameters::optimization_statistics(&os).constrained_vertices(pinned)
                                                               .vertex_point_map(vpm).number_of_iterations(200));
  const PE::Distortion_report d1 = PE::measure_distortion(m, uv, CGAL::parameters::vertex_point_map(vpm));
  std::cout << "[OpenMesh] mushroom optimization (" << PE::get_error_name(ec) << ", " << os.iterations << " iterations): mean symmetric Dirichlet "
            << d0.mean_symmetric_dirichlet << " -> " << d1.mean_symmetric_dirichlet << std::endl;
  CHECK(ec == PE::OK || ec == PE::ERROR_BUDGET_EXHAUSTED, "optimized");
  CHECK(PE::check_embedding(m, uv).is_valid() && os.report.is_valid(), "certified");
  CHECK(d1.mean_symmetric_dirichlet < d0.mean_symmetric_dirichlet, "lower energy");
  CHECK(border_uv(m, uv) == border, "border bit-exact");
  for(std::size_t i = 0; i < pinned.size(); ++i) CHECK(get(uv, pinned[i]) == pinned_uv[i], "fixed vertex bit-exact");
  return EXIT_SUCCESS;
}

// constrained map: the mesh is refined by OpenMesh's own Euler operations (through CGAL's graph
// traits), constraints bit-exact, original vertices unchanged, new vertices on their edges. With 12
// scattered targets the refinement runs (vertices inserted, asserted); without the coarsening they are
// all kept, with it some are removed again (OpenMesh marks them deleted: its garbage collection
// compacts the mesh, the input vertices first and unchanged). The optimization runs before the coarsening
// only: the run without it checks the refinement, and optimizing its 6.7k vertices was most of the test's time.
int constrained_case(const std::string& data, std::size_t count, bool coarsen)
{
  Om_mesh m;
  if(!read_om(data + "/meshes/mushroom.off", m)) return EXIT_FAILURE;
  const std::size_t n0 = num_vertices(m);
  std::vector<Epick::Point_3> p0;
  const Om_point_map vpm{ &m };
  for(auto v : vertices(m)) p0.push_back(get(vpm, v));
  auto uv = make_uv_map(m, Point_2());
  // interior vertices far apart in index, targets on a 4 x 3 lattice in an order unrelated to the surface
  std::vector<std::pair<VD, Point_2> > C;
  std::size_t k = 0;
  for(auto v : vertices(m))
    if(k < count && !CGAL::is_border(v, m) && v.idx() >= int(k * n0 / count))
    {
      const std::size_t j = (7 * k + 3) % count; // a permutation of the lattice points (7 and 12 coprime)
      C.emplace_back(v, Point_2(0.2 + 0.2 * double(j % 4), 0.25 + 0.25 * double(j / 4)));
      ++k;
    }
  CHECK(C.size() == count, "interior vertices");
  std::vector<PE::Steiner_point<VD> > steiner;
  PE::Constrained_embedding_statistics st;
  const PE::Error_code ec = PE::constrained_embedding(m, C, uv, PE::parameters::border_shape(PE::Border_shape::SQUARE)
                                                                   .vertex_point_map(vpm).statistics(&st).steiner_points(&steiner)
                                                                   .coarsen(coarsen).optimize(coarsen));
  const PE::Embedding_report r = PE::check_embedding(m, uv);
  std::cout << "[OpenMesh] mushroom, " << count << " constraints" << (coarsen ? "" : ", no coarsening") << ": "
            << PE::get_error_name(ec) << ", " << n0 << " -> " << st.output_vertices << " vertices (" << st.steiner_vertices_inserted
            << " inserted, " << st.steiner_vertices_removed << " removed), " << r.summary() << std::endl;
  CHECK(ec == PE::OK && r.is_valid() && r.flipped == 0 && r.degenerate == 0, "certified");
  for(const auto& c : C) CHECK(get(uv, c.first) == c.second, "constraint bit-exact");
  CHECK(st.steiner_vertices_inserted > 0, "the refinement ran: vertices were inserted");
  CHECK(st.steiner_vertices + st.steiner_vertices_removed == st.steiner_vertices_inserted, "kept + removed = inserted");
  CHECK(steiner.size() == st.steiner_vertices, "one Steiner point per kept vertex");
  if(!coarsen) CHECK(st.steiner_vertices_removed == 0 && st.steiner_vertices > 0, "every inserted vertex kept");
  else CHECK(st.steiner_vertices_removed > 0, "the coarsening removed vertices (it runs on OpenMesh's own Euler operations)");
  std::size_t live = 0;
  for(auto v : vertices(m)) { (void)v; ++live; }
  CHECK(live == n0 + st.steiner_vertices && st.output_vertices == live, "the mesh has the kept vertices");
  if(st.steiner_vertices_removed > 0)
  {
    CHECK(num_vertices(m) == n0 + st.steiner_vertices_inserted, "removed vertices marked deleted until the garbage collection");
    m.garbage_collection();
    CHECK(num_vertices(m) == n0 + st.steiner_vertices, "compacted");
  }
  std::size_t i = 0;
  for(auto v : vertices(m))
    if(i < n0) { CHECK(get(vpm, v) == p0[i], "original vertex kept"); ++i; }
  CHECK(PE::check_embedding(m, uv).is_valid(), "certified after the garbage collection");
  return EXIT_SUCCESS;
}

int test_constrained(const std::string& data)
{
  RUN(constrained_case(data, 12, false));
  RUN(constrained_case(data, 12, true));
  return EXIT_SUCCESS;
}

// CGAL's parameterize() with this package's parameterizer, on a closed mesh cut open
int test_parameterizer(const std::string& data)
{
  Om_mesh m;
  if(!read_om(data + "/meshes/bull.off", m)) return EXIT_FAILURE;
  m.request_face_status();
  m.request_edge_status();
  m.request_vertex_status();
  auto last = *faces(m).begin();
  for(auto f : faces(m)) last = f;
  CGAL::Euler::remove_face(halfedge(last, m), m);
  const auto bhd = CGAL::Polygon_mesh_processing::longest_border(m).first;
  auto uv = make_uv_map(m, Point_2());
  PE::Progressive_embedding_parameterizer_3<Om_mesh> p;
  const auto e = CGAL::Surface_mesh_parameterization::parameterize(m, p, bhd, uv);
  const PE::Embedding_report r = PE::check_embedding(m, uv);
  std::cout << "[OpenMesh] bull cut open, Progressive_embedding_parameterizer_3: "
            << CGAL::Surface_mesh_parameterization::get_error_message(e) << ", " << r.summary() << std::endl;
  CHECK(e == CGAL::Surface_mesh_parameterization::OK && r.is_valid(), "certified");
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " DATA_DIR tutte|repair|optimize|constrained|parameterizer" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string data = argv[1], group = argv[2];
  if(group == "tutte") return test_tutte(data);
  if(group == "repair") return test_repair();
  if(group == "optimize") return test_optimize(data);
  if(group == "constrained") return test_constrained(data);
  if(group == "parameterizer") return test_parameterizer(data);
  std::cerr << "unknown group " << group << std::endl;
  return EXIT_FAILURE;
}
