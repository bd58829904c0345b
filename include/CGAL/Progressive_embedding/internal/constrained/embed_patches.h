// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_EMBED_PATCHES_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_EMBED_PATCHES_H

// The patch phase of the constrained pipeline: every patch of the traced mesh mapped into its
// convex polygon by embed_patch_impl(). The patches are independent: each one reads the mesh,
// the 3D points and the uv of its own border, and writes the uv of its own interior vertices
// only, which no other patch touches. With CGAL::Parallel_tag (TBB linked, floating-point uv)
// they run in parallel, largest first; each worker thread has its own Patch_slots, created before
// the threads start (adding a property to the mesh is not thread-safe). Exact number types stay
// sequential: their reference-counted handles are shared by neighbouring patches.
//
// The result does not depend on the order: each patch's map is a function of its border alone.
// On failure, the error of the failed patch with the lowest index is returned (the other
// workers stop at their next patch), so the sequential and parallel runs report the same patch
// whenever only one can fail.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_statistics.h>
#include <CGAL/Progressive_embedding/embed_patch.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/Progressive_embedding/internal/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <memory>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// what embed_patches() reports
struct Patch_phase_result
{
  Error_code status = OK;
  std::size_t failed_patch = std::size_t(-1); // with status != OK
  std::size_t repaired_patches = 0;           // patches whose Tutte map needed collapses or insertions
};

// Upper bound on the worker threads (each holds a face and a vertex array of the whole mesh).
constexpr int max_patch_workers = 16;

// `remaining()`: seconds left of the caller's budget (read by every patch when it starts).
template <class ConcurrencyTag, class Mesh, class UVMap, class Remaining>
Patch_phase_result embed_patches(Mesh& work, const std::vector<std::vector<typename boost::graph_traits<Mesh>::face_descriptor> >& patch_faces,
                                 UVMap uvm, Weights weights, Remaining remaining)
{
  typedef typename boost::property_traits<UVMap>::value_type Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel::FT  FT;
  const std::size_t n = patch_faces.size();
  std::vector<Error_code> status(n, OK);
  std::vector<char> repaired(n, 0), ran(n, 0);
  std::atomic<bool> failed(false);

  auto embed_one = [&](std::size_t p, Patch_slots<Mesh>& slots)
  {
    if(failed.load(std::memory_order_relaxed)) return; // another patch failed: the result is an error anyway
    ran[p] = 1;
    if(!(remaining() > 0)) { status[p] = ERROR_BUDGET_EXHAUSTED; failed = true; return; }
    Progressive_embedding_statistics pst;
    status[p] = embed_patch_impl(work, patch_faces[p], uvm,
                                 parameters::statistics(&pst, parameters::weights(weights).maximum_running_time(remaining())),
                                 true, &slots, false);
    repaired[p] = (pst.collapses > 0 || pst.insertions > 0);
    if(status[p] != OK) failed = true;
  };

  // Patch_slots hold a property of the mesh: created here, before any thread runs
  const int workers = number_of_workers<ConcurrencyTag, FT>(n, max_patch_workers);
  std::vector<std::unique_ptr<Patch_slots<Mesh> > > slots;
  for(int k = 0; k < workers; ++k) slots.emplace_back(new Patch_slots<Mesh>(work));
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  if(workers > 1) // largest first: the last patches taken are small, the workers end together
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return patch_faces[a].size() > patch_faces[b].size(); });
  for_each_index<ConcurrencyTag, FT>(n, workers, [&](std::size_t k, int w) { embed_one(order[k], *slots[static_cast<std::size_t>(w)]); });

  Patch_phase_result result;
  for(std::size_t p = 0; p < n; ++p)
  {
    if(ran[p] && repaired[p]) ++result.repaired_patches;
    if(ran[p] && status[p] != OK && result.status == OK) { result.status = status[p]; result.failed_patch = p; }
  }
  return result;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_EMBED_PATCHES_H
