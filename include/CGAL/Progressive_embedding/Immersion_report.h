// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IMMERSION_REPORT_H
#define CGAL_PROGRESSIVE_EMBEDDING_IMMERSION_REPORT_H

/// \file Immersion_report.h
/// The certificate of an immersion: `Immersion_report`, returned by `check_immersion()`.

#include <CGAL/Progressive_embedding/Error_code.h>

#include <cstddef>
#include <sstream>
#include <string>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingReports
///
/// The exact certificate of a locally injective map (an immersion) of a disk into the plane, returned by
/// `check_immersion()`. An immersion may overlap itself (a map onto a weakly self-overlapping border polygon
/// does), so it is certified locally: every face has the orientation of the map, and the one-ring of every
/// interior vertex winds exactly once around it. A valid embedding (`check_embedding()`) is an immersion; an
/// immersion is an embedding when moreover its border is simple.
struct Immersion_report
{
  /// `OK` when the map could be checked; otherwise why not (`ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`,
  /// `ERROR_NON_MANIFOLD`, `ERROR_NOT_A_DISK`, or `ERROR_WRONG_PARAMETER` for a border polygon of the wrong size)
  Error_code status = OK;
  /// number of faces
  std::size_t faces = 0;
  /// number of vertices
  std::size_t vertices = 0;
  /// number of border vertices
  std::size_t border_vertices = 0;
  /// `true` if the faces are clockwise (the mirror image of a counterclockwise map: then the counts below are
  /// relative to that orientation)
  bool clockwise = false;
  /// faces oriented against the map (the minority orientation)
  std::size_t flipped = 0;
  /// faces of zero area (exact predicate)
  std::size_t degenerate = 0;
  /// vertices with a non-finite coordinate
  std::size_t non_finite = 0;
  /// interior vertices whose one-ring winds a number of times other than once around them (among the interior
  /// vertices whose incident faces are all correctly oriented)
  std::size_t winding_errors = 0;
  /// largest number of turns of the one-ring of an interior vertex (1 for an immersion)
  std::size_t max_winding = 0;
  /// interior vertices not checked because an incident face is flipped, degenerate or not finite
  std::size_t unchecked_vertices = 0;
  /// with a `border_polygon`: the number of border vertices whose uv differs from the polygon's point (compared
  /// by value (`==`: in floating point -0 equals 0), the polygon's first point at the border vertex
  /// `border_polygon_start`)
  std::size_t border_mismatches = 0;
  /// border vertices (among those whose incident faces are all correctly oriented) whose fan of faces does not
  /// turn by the border polygon's angle there plus 2 pi times the vertex's rotation index (index 0 unless the
  /// named parameter `vertex_rotation_index_map` gives one)
  std::size_t border_angle_errors = 0;
  /// largest number of full turns that the fan of a border vertex makes beyond the border polygon's angle there
  /// (0 when no border fan wraps around its vertex)
  std::size_t max_border_turns = 0;

  /// returns `true` if the map is an immersion: no flipped, degenerate or non-finite element, every interior
  /// one-ring winding once, every border fan turning by the border's angle plus its rotation index's full turns,
  /// and (with a border polygon) the border bit-exactly the polygon
  bool is_immersion() const
  {
    return status == OK && faces > 0 && flipped == 0 && degenerate == 0 && non_finite == 0 && winding_errors == 0
        && unchecked_vertices == 0 && border_mismatches == 0 && border_angle_errors == 0;
  }

  /// returns a one-line human-readable summary
  std::string summary() const
  {
    std::ostringstream os;
    if(status != OK) { os << "not checked: " << get_error_message(status); return os.str(); }
    os << (is_immersion() ? "immersion" : "NOT AN IMMERSION") << ": faces " << faces << ", flipped " << flipped
       << ", degenerate " << degenerate;
    if(non_finite) os << ", non-finite vertices " << non_finite;
    os << ", interior one-rings not winding once " << winding_errors << " (max turns " << max_winding << ")";
    if(unchecked_vertices) os << ", unchecked vertices " << unchecked_vertices;
    if(border_angle_errors) os << ", border fans not turning by the border's angle plus their full turns " << border_angle_errors;
    if(max_border_turns) os << ", border fans wrapping up to " << max_border_turns << " extra turn(s)";
    if(border_mismatches) os << ", border vertices off the polygon " << border_mismatches;
    return os.str();
  }
};

} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_IMMERSION_REPORT_H
