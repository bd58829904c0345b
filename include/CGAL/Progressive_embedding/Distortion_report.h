// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_DISTORTION_REPORT_H
#define CGAL_PROGRESSIVE_EMBEDDING_DISTORTION_REPORT_H

/// \file Distortion_report.h
/// The distortion measures of a uv map: `Distortion_report`.

#include <CGAL/Progressive_embedding/Error_code.h>

#include <array>
#include <cstddef>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingReports
///
/// Distortion of a uv map against the 3D triangles, each 3D triangle scaled by the one factor that
/// makes the total 3D area equal to the area enclosed by the uv border. Means are weighted by the
/// (scaled) 3D areas. Faces that are not positively oriented (relative to the border orientation)
/// have infinite distortion. Returned by `measure_distortion()`.
struct Distortion_report
{
  /// `OK`, or why the mesh could not be measured
  Error_code status = OK;
  /// number of faces
  std::size_t faces = 0;
  /// max of the symmetric Dirichlet energy \f$\|J\|_F^2 + \|J^{-1}\|_F^2\f$ (4 for an isometry)
  double max_symmetric_dirichlet = 0;
  /// area-weighted mean of the symmetric Dirichlet energy
  double mean_symmetric_dirichlet = 0;
  /// median, 90% and 99% quantiles (by face count) of the symmetric Dirichlet energy
  std::array<double, 3> symmetric_dirichlet_quantiles = {{0, 0, 0}};
  /// max of the conformal (MIPS) distortion \f$\sigma_1/\sigma_2 + \sigma_2/\sigma_1\f$ (2 for a similarity)
  double max_conformal = 0;
  /// area-weighted mean of the conformal distortion
  double mean_conformal = 0;
  /// max of the area distortion \f$\max(\det J, 1/\det J)\f$ (1 when areas are preserved)
  double max_area = 0;
  /// area-weighted mean of the area distortion
  double mean_area = 0;
};

} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_DISTORTION_REPORT_H
