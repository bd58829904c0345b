// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_TRACER_BUDGETS_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_TRACER_BUDGETS_H

// The default budgets (Steiner vertices each path tracer may add, when the caller gives none), in one
// place: the tracers' own defaults and constrained_embedding()'s choice between them read these.
// Measurements behind the choices: benchmark/results/constrained_embedding_many.csv and
// benchmark/results/polygon_maps.csv.

#include <cstddef>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// a budget linear in a size of the mesh: per_unit * size + base
struct Steiner_budget
{
  std::size_t per_unit;
  std::size_t base;
  constexpr std::size_t of(std::size_t size) const { return per_unit * size + base; }
};

// trace_paths() called on its own: shortest paths that split edges as they go (per edge)
constexpr Steiner_budget shortest_paths_default_budget{ 4, 1000 };
// constrained_embedding()'s first tracing, shortest paths (per vertex of the mesh): they won with at most
// 1.35 times the mesh's vertices added, so they stop at twice, and the time spent is not lost for long
constexpr Steiner_budget first_tracing_budget{ 2, 1000 };
// trace_paths_overlay(): curves over the input edges, the mesh refined once (per edge)
constexpr Steiner_budget overlay_tracing_budget{ 128, 10000 };
// the guided tracings (shortest paths guided by a drawing of the partition; per edge)
constexpr Steiner_budget guided_tracing_budget{ 32, 10000 };
// the guided tracings run after the overlay only when it added at most this many times the mesh's vertices
constexpr std::size_t guided_after_overlay_factor = 4;
// the shortest paths are traced again (overlay, guided) when they add more than vertices / this + 10
constexpr std::size_t retrace_above_fraction = 10;
// Motions of the kinetic tracing: the straight-line one and permutation braids along four directions; the
// kinetic_traced_motions with the fewest crossings of their own start triangulation are traced on the mesh
// (one: with 50 random or jittered targets, the second one never added fewer vertices in 38 runs,
// constrained_design_measurements.md).
constexpr std::size_t kinetic_motions = 5;
constexpr std::size_t kinetic_traced_motions = 1;
// A motion's proxy (crossings of its own start triangulation) stops once its live crossings pass this many times
// the kinetic_traced_motions-th fewest of the motions simulated before it: it would not be traced (the
// straight-line motion's proxy reached 607k crossings against 39k for a braid, 100 random targets on man.off).
constexpr std::size_t kinetic_proxy_cap_factor = 2;
// Under a time budget, the kinetic simulations get this share of the time left, and the tracing on the mesh of
// the motions chosen this share of what the simulations leave; the tracings after them (overlay, guided) keep
// the rest. The kinetic tracing is the one that wins with many random targets (all 8 runs of
// constrained_embedding_200.csv), and the overlay tracing that would follow it does not finish there: with a
// quarter instead of half, a run stopped its kinetic tracing after 23 s and ran out of its budget
// (constrained_design_measurements.md).
constexpr double kinetic_simulation_time_share = 0.25;
constexpr double kinetic_tracing_time_share = 0.5;

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_TRACER_BUDGETS_H
