// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PARALLEL_FOR_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PARALLEL_FOR_H

// for_each_index<ConcurrencyTag, FT>(n, workers, body): body(i, w) for i in [0, n), w the index of
// the worker thread in [0, workers) (for per-thread scratch the caller creates beforehand). In
// parallel (TBB) only with CGAL::Parallel_tag, a floating-point FT (exact number types are
// reference-counted handles, shared between neighbouring items) and more than one worker; the items
// are taken one at a time, in the given order (put the largest first). Otherwise sequential, w = 0.
// number_of_workers<ConcurrencyTag, FT>(n, cap): the `workers` to pass (1 when sequential).
// run_pair<ConcurrencyTag>(f0, f1): f0() and f1(), at the same time with CGAL::Parallel_tag when TBB
// is linked and more than one thread is available (the two must share nothing they write), one after
// the other otherwise; pair_is_parallel<ConcurrencyTag>() says which.

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cstddef>
#include <type_traits>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

template <class ConcurrencyTag, class FT>
int number_of_workers(std::size_t n, int cap)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value && std::is_floating_point<FT>::value)
    return (std::max)(1, (std::min)({ tbb::this_task_arena::max_concurrency(), cap,
                                      static_cast<int>((std::min)(n, std::size_t(1) << 20)) }));
#endif
  (void)n; (void)cap;
  return 1;
}

template <class ConcurrencyTag, class FT, class Body>
void for_each_index(std::size_t n, int workers, Body body)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(workers > 1 && std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value && std::is_floating_point<FT>::value)
  {
    tbb::task_arena arena(workers);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1), [&](const tbb::blocked_range<std::size_t>& range) {
        const int w = tbb::this_task_arena::current_thread_index();
        for(std::size_t i = range.begin(); i != range.end(); ++i) body(i, w);
      }, tbb::simple_partitioner());
    });
    return;
  }
#endif
  (void)workers;
  for(std::size_t i = 0; i < n; ++i) body(i, 0);
}

template <class ConcurrencyTag>
bool pair_is_parallel()
{
#ifdef CGAL_LINKED_WITH_TBB
  return std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value && tbb::this_task_arena::max_concurrency() > 1;
#else
  return false;
#endif
}

template <class ConcurrencyTag, class F0, class F1>
void run_pair(F0&& f0, F1&& f1)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(pair_is_parallel<ConcurrencyTag>()) { tbb::parallel_invoke(f0, f1); return; }
#endif
  f0();
  f1();
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PARALLEL_FOR_H
