// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_CHECK_EMBEDDING_H
#define CGAL_PROGRESSIVE_EMBEDDING_CHECK_EMBEDDING_H

/// \file check_embedding.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/distortion.h>
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

/// \ingroup PkgProgressiveEmbeddingReports
///
/// The exact validity certificate of a planar map of a disk, returned by `check_embedding()`.
/// Orientation-dependent counts are relative to the orientation of the border polygon:
/// a layout whose border and faces are all clockwise is valid (it is a mirror image).
struct Embedding_report
{
  /// `OK`, or why the mesh itself could not be checked (not a disk, empty, ...)
  Error_code status = OK;
  /// number of faces
  std::size_t faces = 0;
  /// number of vertices
  std::size_t vertices = 0;
  /// number of border vertices (on every border cycle)
  std::size_t border_vertices = 0;
  /// number of border cycles of the mesh: 1 for a disk, 1 + the number of holes for a multiply connected
  /// domain (also filled when the mesh is refused for having several, `ERROR_NOT_A_DISK`; 0 when not counted)
  std::size_t border_cycles = 0;
  /// faces whose orientation is opposite to the border's (exact predicate)
  std::size_t flipped = 0;
  /// faces whose three uv corners are collinear (exact predicate)
  std::size_t degenerate = 0;
  /// vertices with a NaN or infinite uv coordinate
  std::size_t non_finite = 0;
  /// `true` if the border polygon is oriented clockwise (then faces are expected clockwise)
  bool clockwise = false;
  /// `true` if the border polygon has no self-intersection (exact)
  bool border_simple = true;
  /// number of intersecting pairs of non-adjacent edges of one border cycle, summed over the cycles (counting
  /// stops at `overlap_limit`)
  std::size_t border_intersections = 0;
  /// multiply connected domains: pairs of edges of two different border cycles that touch (closed segments, exact;
  /// counting, together with `border_intersections`, stops at `overlap_limit`); 0 for a disk
  std::size_t loop_crossings = 0;
  /// multiply connected domains: holes whose border cycle is not oriented opposite to the outer cycle (exact area
  /// zero or of the outer cycle's sign); 0 for a disk
  std::size_t misoriented_holes = 0;
  /// multiply connected domains: holes whose border cycle has a vertex outside the outer cycle (exact winding
  /// number 0, vertices on the outer cycle not counted); when no two cycles touch one vertex per hole decides, else
  /// every vertex is tested (up to 10^7 point-edge tests per hole); 0 for a disk
  std::size_t holes_outside = 0;
  /// `true` if global overlap was decided
  bool overlap_checked = false;
  /// `true` if no overlap was concluded without the box test, because all faces are positively
  /// oriented and the border is simple (then every point is covered at most once)
  bool overlap_by_degree_argument = false;
  /// pairs of faces whose interiors intersect (exact; counting stops at `overlap_limit`)
  std::size_t overlapping_pairs = 0;
  /// the cap on the two counts above
  std::size_t overlap_limit = 1000;
  /// smallest signed uv area, the sign taken relative to the border orientation (double, rounded from the exact value where the double evaluation is unreliable)
  double min_signed_area = 0;
  /// largest signed uv area, relative to the border orientation (double)
  double max_signed_area = 0;
  /// area enclosed by the border polygon (absolute value, double); for a multiply connected domain the signed sum
  /// over the cycles (the outer area minus the holes' when valid), in absolute value
  double border_area = 0;
  /// max symmetric Dirichlet energy against the 3D triangles scaled to the uv area (infinite if a face is flipped or degenerate)
  double max_energy_3d = 0;
  /// 3D-area-weighted mean of that energy
  double mean_energy_3d = 0;
  /// max symmetric Dirichlet energy against an equilateral triangle of area `border_area / faces`
  double max_energy_equilateral = 0;
  /// mean of that energy (all reference areas are equal)
  double mean_energy_equilateral = 0;
  /// faces whose equilateral energy is not finite or exceeds `energy_threshold`
  std::size_t high_energy_faces = 0;
  /// threshold used for `high_energy_faces` (the `invalid_energy_threshold` named parameter)
  double energy_threshold = 1e20;
  /// `true` if the 3D energies were computed (the mesh has 3D points of non-zero total area)
  bool has_3d_energy = false;
  /// all distortion measures against the 3D triangles (`max_energy_3d` and `mean_energy_3d` repeat two of them)
  Distortion_report distortion;

  /// returns `true` if the map is a valid embedding: no flipped, degenerate or non-finite
  /// element, a simple border and no overlap; with several border cycles also no contact between two
  /// cycles, every hole oriented opposite to the outer cycle and inside it.
  bool is_valid() const
  {
    return status == OK && faces > 0 && flipped == 0 && degenerate == 0 && non_finite == 0
        && border_simple && overlapping_pairs == 0 && loop_crossings == 0 && misoriented_holes == 0
        && holes_outside == 0;
  }

  /// returns a one-line human-readable summary
  std::string summary() const
  {
    std::ostringstream os;
    if(status != OK) { os << "not checked: " << get_error_message(status); return os.str(); }
    os << (is_valid() ? "valid" : "INVALID") << ": faces " << faces << ", flipped " << flipped
       << ", degenerate " << degenerate;
    if(non_finite) os << ", non-finite vertices " << non_finite;
    os << ", border " << (border_simple ? "simple" : "self-intersecting");
    if(border_cycles > 1)
    {
      os << ", border cycles " << border_cycles;
      if(loop_crossings) os << ", touching cycle pairs " << loop_crossings;
      if(misoriented_holes) os << ", misoriented holes " << misoriented_holes;
      if(holes_outside) os << ", holes outside " << holes_outside;
    }
    if(overlap_checked) os << ", overlapping pairs " << overlapping_pairs
                           << (overlapping_pairs >= overlap_limit ? "+" : "");
    if(clockwise) os << " (clockwise layout)";
    os << ", min area " << min_signed_area;
    if(has_3d_energy) os << ", sym. Dirichlet max " << max_energy_3d << " mean " << mean_energy_3d;
    return os.str();
  }
};


/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// certifies a planar map of a triangulated topological disk with exact predicates, whatever
/// the number type of the uv coordinates and whatever their magnitude: every sign (face and border
/// orientations, border self-intersections, face overlaps) is decided by the traits' exact
/// orientation predicate and exact coordinate comparisons; the candidate pairs of the border and
/// overlap tests come from boxes that enclose the points at any magnitude (coordinates beyond
/// double range are scaled exactly by a power of two, then enclosed by intervals). The areas and
/// energies of the report are doubles: the areas in the map's units (so possibly infinite or zero
/// when the map lies beyond double range), the energies computed on the scaled coordinates (they
/// are scale invariant). The function never throws: a mesh that is not a disk is reported in
/// `Embedding_report::status`.
///
/// <b>Multiply connected domains</b> (with `multiply_connected(true)`): the mesh may be any connected genus-0
/// triangle mesh with k >= 1 border cycles (else `ERROR_NOT_GENUS_ZERO`, also for a closed mesh). The <em>outer</em>
/// cycle is the one whose uv polygon has the largest absolute area (exact; the first in the mesh's halfedge order
/// among equal ones), every other cycle is a hole. Faces are expected with the orientation of the outer cycle, and
/// holes with the opposite one: a layout whose outer cycle is clockwise is reported with
/// `Embedding_report::clockwise` and is valid if it is the mirror image of a valid one (faces and outer cycle
/// clockwise, holes counterclockwise). The map is certified valid iff every face has the orientation of the outer
/// cycle (exact), every cycle is simple (`border_intersections`), no two cycles touch (`loop_crossings`), every hole is
/// oriented opposite to the outer cycle (`misoriented_holes`) and lies inside it (`holes_outside`), and no two faces
/// overlap. When the first five hold, the image covers each point of the outer polygon outside the holes exactly
/// once and no point of a hole: the turning numbers of the cycles (1 for the outer one, -1 for each hole) sum to
/// 2 - k, so no interior vertex is branched, and the degree of the map at a point, the sum of the cycles' winding
/// numbers, is then 1 in the domain and 0 in the holes. The overlap test is then skipped
/// (`overlap_by_degree_argument`), as for a disk; otherwise it runs and counts the overlapping pairs exactly.
/// `border_cycles` gives k; `border_area` is the area of the domain (outer polygon minus the holes).
///
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param uvm the uv coordinates
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points, used for the distortion statistics}
///     \cgalParamType{a model of `ReadablePropertyMap` with `Point_3` values}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{check_overlap}
///     \cgalParamDescription{whether to run the global face-overlap test (box intersection and exact triangle tests)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_number}
///     \cgalParamDescription{the cap on the number of overlapping pairs and border intersections counted}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{1000}
///   \cgalParamNEnd
///   \cgalParamNBegin{invalid_energy_threshold}
///     \cgalParamDescription{faces whose equilateral-reference energy exceeds it are counted in `high_energy_faces`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1e20}
///   \cgalParamNEnd
///   \cgalParamNBegin{multiply_connected}
///     \cgalParamDescription{whether a connected genus-0 mesh with several border cycles is certified (see above)
///                           instead of being refused with `ERROR_NOT_A_DISK`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits class whose exact orientation predicate decides every sign}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2` whose `Point_2` is the uv map's value type}
///     \cgalParamDefault{`Progressive_embedding_traits_2<K>`, `K` the kernel of the uv map's point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the report; the map is a valid embedding iff `Embedding_report::is_valid()`
template <typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Embedding_report check_embedding(const TriangleMesh& tm, VertexUVMap uvm,
                                 const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
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
  internal::Indexed_disk<TriangleMesh>& disk = domain.disk;
  if(!holes)
  {
    r.status = internal::make_indexed_disk(tm, boost::graph_traits<TriangleMesh>::null_halfedge(), disk);
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

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_CHECK_EMBEDDING_H
