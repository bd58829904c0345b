// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_STATISTICS_H
#define CGAL_PROGRESSIVE_EMBEDDING_STATISTICS_H

/// \file Progressive_embedding_statistics.h

#include <CGAL/Progressive_embedding/Embedding_report.h>

#include <cstddef>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingReports
///
/// What `progressive_embedding()` did, filled when a pointer to it is passed with the
/// `statistics` named parameter.
struct Progressive_embedding_statistics
{
  /// faces invalid in the input map (orientation or energy)
  std::size_t invalid_faces_before = 0;
  /// edge collapses of the simplification stage (= vertex insertions of the second stage)
  std::size_t collapses = 0;
  /// tag-expansion rounds of the simplification stage
  std::size_t expansion_rounds = 0;
  /// interior vertices placed at the barycenter of their (border) neighbours
  std::size_t barycenter_placements = 0;
  /// vertices re-inserted
  std::size_t insertions = 0;
  /// restarts with a higher area floor (more faces collapsed) after a failed insertion (floating point only)
  std::size_t restarts = 0;
  /// insertions that found no candidate at first and needed extra smoothing (0 in exact arithmetic, Lemma A.11)
  std::size_t insertions_with_extra_smoothing = 0;
  /// accepted smoothing steps
  std::size_t smoothing_steps = 0;
  /// seconds spent in the simplification stage
  double seconds_collapse = 0;
  /// seconds spent in the insertion stage
  double seconds_insertion = 0;
  /// seconds spent certifying the output with `check_embedding()`
  double seconds_certification = 0;
  /// total seconds, certification included
  double seconds_total = 0;
  /// the certificate of the output map
  Embedding_report report;
};

} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_STATISTICS_H
