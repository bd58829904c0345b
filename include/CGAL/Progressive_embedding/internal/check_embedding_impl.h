// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CHECK_EMBEDDING_IMPL_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CHECK_EMBEDDING_IMPL_H

// The body of check_embedding(), for the pipelines that certify their own results without
// going through the public header (internal headers never include public algorithm headers).

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/Embedding_report.h>
#include <CGAL/Progressive_embedding/internal/distortion_measures.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/check_passes.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <limits>
#include <string>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// the body of check_embedding() (see its documentation there); `given`: the disk already indexed from
// `tm` by the caller (a pipeline indexes once), or null; not used with `multiply_connected`
template <typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Embedding_report check_embedding_impl(const TriangleMesh& tm, VertexUVMap uvm,
                                      const CGAL_NP_CLASS& np = CGAL::parameters::default_values(),
                                      const Indexed_disk<TriangleMesh>* given = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename internal::Check_traits<VertexUVMap, CGAL_NP_CLASS>::type Traits;
  typedef typename internal::Uv_map_types<VertexUVMap>::Point_2             Point_2;
  const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const typename Traits::Exact_orientation_2 orient = traits.exact_orientation_2_object();
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));

  Embedding_report r;
  r.overlap_limit = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_number), std::size_t(1000));
  r.energy_threshold = choose_parameter(get_parameter(np, internal_np::invalid_energy_threshold), 1e20);
  const bool do_overlap = choose_parameter(get_parameter(np, internal_np::check_overlap), true);

  const bool holes = choose_parameter(get_parameter(np, internal_np::multiply_connected), false);

  internal::Indexed_domain<TriangleMesh> domain;
  const internal::Indexed_disk<TriangleMesh>* indexed = &domain.disk;
  if(!holes && given)
  {
    indexed = given;
    r.border_cycles = 1;
  }
  else if(!holes)
  {
    r.status = internal::make_indexed_disk(tm, boost::graph_traits<TriangleMesh>::null_halfedge(), domain.disk);
    if(r.status == ERROR_NOT_A_DISK)
    {
      // say how many border cycles there are (e.g. several: `multiply_connected` would check it)
      internal::make_indexed_domain(tm, domain);
      r.border_cycles = domain.number_of_loops();
    }
    if(r.status != OK) return r;
    r.border_cycles = 1;
  }
  else
  {
    r.status = internal::make_indexed_domain(tm, domain);
    r.border_cycles = domain.number_of_loops();
    if(r.status != OK) return r;
  }
  const internal::Indexed_disk<TriangleMesh>& disk = *indexed;
  r.faces = disk.number_of_faces(); r.vertices = disk.number_of_vertices();

  internal::Uv_samples<Point_2> samples;
  internal::sample_uv(disk, uvm, samples);
  r.non_finite = samples.non_finite;
  std::vector<CGAL::Gmpq> loop_twice_area;
  std::vector<char> loop_finite;
  bool loops_finite = true;
  if(holes)
  {
    // the outer cycle: largest absolute uv area; it becomes disk.border for the passes below
    internal::loop_areas(domain, samples, loop_twice_area, loop_finite);
    domain.set_outer(internal::largest_loop(loop_twice_area, loop_finite));
    for(char f : loop_finite) if(!f) loops_finite = false;
    r.border_vertices = 0;
    for(const auto& L : domain.loops) r.border_vertices += L.size();
  }
  else
    r.border_vertices = disk.border.size();

  // orientation pass (relative to the outer cycle)
  internal::Face_orientations o;
  internal::orientation_pass(disk, samples, orient, o);
  if(holes)
  {
    o.border_finite = loops_finite;
    if(loops_finite)
    {
      // the domain's area: the signed sum over the cycles
      CGAL::Gmpq sum(0);
      for(const CGAL::Gmpq& a : loop_twice_area) sum += a;
      o.border_twice_area = sum;
    }
  }
  r.flipped = o.flipped; r.degenerate = o.degenerate; r.clockwise = (o.border_sign == CGAL::RIGHT_TURN);
  internal::Face_areas areas;
  internal::area_pass(disk, samples, o, areas);
  r.min_signed_area = areas.min_area; r.max_signed_area = areas.max_area; r.border_area = areas.border_area;

  // border pass (every cycle, and their contacts, orientations and nesting)
  if(o.border_finite)
  {
    if(!holes) r.border_intersections = internal::border_pass(disk, samples, orient, r.overlap_limit);
    else
    {
      const internal::Loops_result lr = internal::loops_pass(domain, samples, orient, loop_twice_area, o.border_sign,
                                                             r.overlap_limit);
      r.border_intersections = lr.self_intersections;
      r.loop_crossings = lr.crossings;
      r.misoriented_holes = lr.misoriented_holes;
      r.holes_outside = lr.holes_outside;
    }
  }
  r.border_simple = o.border_finite && r.border_intersections == 0;

  // Overlap pass. When every face is correctly oriented and the border is simple (both decided
  // exactly), the map has degree one over the region the border encloses (each point is covered
  // as many times as the border winds around it): no overlap is possible, the pass is skipped.
  // With holes the same holds once the cycles are pairwise disjoint, the holes oriented opposite
  // to the outer cycle and inside it: the degree is 1 outside the holes and 0 inside them.
  if(do_overlap && r.flipped == 0 && r.degenerate == 0 && r.non_finite == 0 && r.border_simple
     && r.loop_crossings == 0 && r.misoriented_holes == 0 && r.holes_outside == 0)
    r.overlap_checked = r.overlap_by_degree_argument = true;
  else if(do_overlap)
  {
    const internal::Overlap_result ov = internal::overlap_pass(disk, samples, o, orient, r.overlap_limit);
    r.overlap_checked = ov.checked;
    r.overlapping_pairs = ov.overlapping_pairs;
  }

  // distortion pass
  const internal::Equilateral_energies eq = internal::equilateral_energy_pass(disk, samples, o, areas, r.energy_threshold);
  r.max_energy_equilateral = eq.max_energy; r.mean_energy_equilateral = eq.mean_energy; r.high_energy_faces = eq.high_energy_faces;
  r.distortion = internal::distortion_pass(disk, vpm, samples, o, areas, r.has_3d_energy);
  if(r.has_3d_energy)
  {
    r.max_energy_3d = r.distortion.max_symmetric_dirichlet;
    r.mean_energy_3d = r.distortion.mean_symmetric_dirichlet;
  }
  return r;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CHECK_EMBEDDING_IMPL_H
