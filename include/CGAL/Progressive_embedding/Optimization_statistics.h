// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_OPTIMIZATION_STATISTICS_H
#define CGAL_PROGRESSIVE_EMBEDDING_OPTIMIZATION_STATISTICS_H

/// \file Optimization_statistics.h
/// What `optimize_distortion()` minimizes and did: `Distortion_energy`, `Optimization_statistics`.

#include <CGAL/Progressive_embedding/Embedding_report.h>
#include <CGAL/Progressive_embedding/Immersion_report.h>

#include <cstddef>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingEnums
/// The energy minimized by `optimize_distortion()`.
enum class Distortion_energy
{
  SYMMETRIC_DIRICHLET, ///< \f$\|J\|_F^2 + \|J^{-1}\|_F^2\f$, a barrier against degeneracy (4 for an isometry)
  ARAP                 ///< as-rigid-as-possible, \f$\|J - R\|_F^2\f$ with \f$R\f$ the closest rotation
};

/// \ingroup PkgProgressiveEmbeddingReports
/// What `optimize_distortion()` did, filled when a pointer to it is passed with the `optimization_statistics` named parameter.
struct Optimization_statistics
{
  /// iterations performed
  std::size_t iterations = 0;
  /// `true` if the convergence criterion was met
  bool converged = false;
  /// `true` if the optimization stopped because its time budget (`maximum_running_time`) ran out; when it stopped
  /// unconverged with this `false`, its iteration limit (`number_of_iterations`) or the `callback` stopped it
  bool time_budget_reached = false;
  /// area-weighted mean symmetric Dirichlet energy of the input, as `check_embedding()` reports it (`mean_energy_3d`)
  double energy_before = 0;
  /// the same for the output (with a free border both are measured against the 3D triangles scaled to the current border
  /// area; the symmetric Dirichlet optimization then minimizes that measure, so it does not rise beyond rounding unless
  /// the border barrier acted, see `optimize_distortion()`)
  double energy_after = 0;
  /// the energy of the current map while the optimization runs: updated after each iteration, before the `callback`
  /// is called (the optimizer's own measure in double of the energy it minimizes, area-weighted over the faces with a
  /// 3D area: for the symmetric Dirichlet energy the mean that `energy_after` gives at the end; with a free border,
  /// plus the border barrier's term while parts of the border are near each other)
  double energy_current = 0;
  /// seconds
  double seconds = 0;
  /// global (Newton) steps accepted
  std::size_t global_steps = 0;
  /// per-vertex sweeps run
  std::size_t vertex_sweeps = 0;
  /// factorizations of the Hessian made by the direct solver (fewer than the global steps when the
  /// named parameter `reuse_factorization` lets steps reuse one; 0 when the iterative solver ran)
  std::size_t factorizations = 0;
  /// certificate of the output (of the input when the input is refused); for an immersion, its energies
  /// (its overlap test is skipped and it reports the border as not simple, by design)
  Embedding_report report;
  /// `true` if the input map was an immersion whose border overlaps itself (a map onto a weakly self-overlapping
  /// polygon, e.g. from `constrained_embedding()`): it was optimized as an immersion and certified by
  /// `check_immersion()` (`immersion_report`)
  bool immersion = false;
  /// the immersion certificate of the output (of the input when refused), when `immersion` is `true`
  Immersion_report immersion_report;
};

} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_OPTIMIZATION_STATISTICS_H
