// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_EMBEDDING_REPORT_H
#define CGAL_PROGRESSIVE_EMBEDDING_EMBEDDING_REPORT_H

/// \file Embedding_report.h
/// The certificate of a planar map: `Embedding_report`, returned by `check_embedding()`.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Distortion_report.h>

#include <cstddef>
#include <sstream>
#include <string>

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
  /// smallest signed uv area, the sign taken relative to the border orientation (double: in floating point, rounded from
  /// the exact value where the double evaluation is unreliable; for exact and MPFR coordinates, within a relative
  /// 2<sup>-40</sup> of the exact value, with its exact sign)
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

} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_EMBEDDING_REPORT_H
