// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_POLYGON_TRIANGULATION_REPORT_H
#define CGAL_PROGRESSIVE_EMBEDDING_POLYGON_TRIANGULATION_REPORT_H

/// \file Polygon_triangulation_report.h
/// What `triangulate_self_overlapping_polygon_2()` found: `Polygon_triangulation_report`.

#include <cstddef>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingReports
///
/// What `triangulate_self_overlapping_polygon_2()` found, filled through its named parameter
/// `polygon_report` (also when it fails).
struct Polygon_triangulation_report
{
  /// number of polygon vertices
  std::size_t vertices = 0;
  /// rotation (turning) number of the polygon, computed exactly: +1 or -1 for a weakly self-overlapping
  /// polygon; 0 when not computed (fewer than 3 vertices, a non-finite coordinate, a repeated consecutive
  /// vertex or a reversal)
  int rotation_number = 0;
  /// `true` if the polygon is oriented clockwise (rotation number -1)
  bool clockwise = false;
  /// `true` if the polygon is simple (no two edges meet except consecutive ones at their common vertex;
  /// exact); decided only when the rotation number is +1 or -1
  bool simple = false;
  /// `true` if the polygon is weakly self-overlapping (simple polygons included) and was triangulated
  bool self_overlapping = false;
  /// sum of the rotation indices given (named parameter `rotation_indices`; 0 without them)
  int turns = 0;
  /// `true` if the triangulation came from the dynamic program (the polygon is not simple)
  bool dynamic_program = false;
  /// dynamic program: chords that passed the exact sector and rotation tests
  std::size_t chords_tested = 0;
  /// dynamic program: chords stored as valid (one 32-bit word each), edges included
  std::size_t chords_stored = 0;
  /// dynamic program: candidate triangles tested
  std::size_t triangles_tested = 0;
  /// wall-clock seconds of the call
  double seconds = 0;
};

} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_POLYGON_TRIANGULATION_REPORT_H
