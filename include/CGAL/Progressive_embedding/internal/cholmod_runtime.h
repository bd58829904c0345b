// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CHOLMOD_RUNTIME_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CHOLMOD_RUNTIME_H

// How CHOLMOD runs inside the package: its large blocks on transparent huge pages (on request), and its OpenMP
// threads no more than the machine has free.
//
// Huge pages, on request only (PE_HUGE_PAGES=1 in the environment). Why they may help: the supernodal
// factor of a 1M-unknown Tutte system is about a gigabyte that CHOLMOD allocates and clears at once.
// Touched 4 KB page by 4 KB page, that memory costs a page fault per page, and on a virtual machine a
// fault may be expensive. Linux's default policy (transparent_hugepage=madvise) gives 2 MB pages only
// to memory marked with madvise(MADV_HUGEPAGE), which glibc's malloc does not do by default.
// SuiteSparse lets its user choose its memory functions (SuiteSparse_config); on request the package
// sets them, once, to functions that map blocks of `huge_block_minimum` bytes or more themselves,
// 2 MB-aligned and marked, and pass every other request to malloc.
// Why not by default: what they save depends on the host; the same virtual machine made the 1M-vertex
// `pe embed` faster with them on one day and twice as slow on another (the manual's "The Linear Solver
// and Large Meshes", benchmark/results/large_meshes_pe.md). Without them the worse case is the milder one.
//
// Only when the functions in place are still the C library's (a program that chose its own keeps
// them). A block is freed by the function that allocated it: the mapped blocks are registered, and a
// pointer that is not registered (from malloc, possibly allocated before the functions were set) goes
// to free() or realloc(). Where madvise or huge pages are unavailable the blocks are plain mappings.
//
// Threads. Debian's CHOLMOD (SuiteSparse 5) runs the loops of its supernodal factorization that
// clear, map and assemble large supernodes in OpenMP regions of a fixed 4 threads (the compile-time
// CHOLMOD_OMP_NUM_THREADS), whatever OMP_NUM_THREADS says: on 2 cores, one of them busy, the 4
// threads wait on each other at every region (futex calls: another third of the factorization on the
// VM). Cholmod_dynamic_threads turns on OpenMP's dynamic adjustment (omp_set_dynamic, a setting of
// the calling thread only) for the duration of a CHOLMOD call, so that the runtime gives each region
// at most the cores that the load average leaves free. The OpenMP runtime is CHOLMOD's: its
// functions are looked up in the process (dlsym) rather than linked, so that the package does not
// depend on OpenMP, and nothing happens where they are absent.

#ifdef CGAL_PROGRESSIVE_EMBEDDING_CHOLMOD_ENABLED

#include <cholmod.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#if defined(__unix__)
#include <dlfcn.h>
#endif

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <unordered_map>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

#if defined(__linux__) && defined(MADV_HUGEPAGE)

// PE_HUGE_PAGES=1: large blocks on transparent huge pages (see above); read at each call
inline bool huge_pages_requested()
{
  const char* v = std::getenv("PE_HUGE_PAGES");
  return v != nullptr && std::strcmp(v, "1") == 0;
}

constexpr std::size_t huge_page_size = std::size_t(2) << 20;
constexpr std::size_t huge_block_minimum = std::size_t(8) << 20;

struct Huge_block_registry
{
  std::mutex mutex;
  std::unordered_map<void*, std::size_t> length; // mapped block -> its mapped length
};

inline Huge_block_registry& huge_blocks()
{
  static Huge_block_registry r;
  return r;
}

// A zeroed mapping of at least n bytes, 2 MB-aligned, marked for huge pages; nullptr on failure.
inline void* map_huge_block(std::size_t n)
{
  const std::size_t len = (n + huge_page_size - 1) / huge_page_size * huge_page_size;
  const std::size_t over = len + huge_page_size;
  void* raw = ::mmap(nullptr, over, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if(raw == MAP_FAILED) return nullptr;
  char* const begin = static_cast<char*>(raw);
  const std::size_t head = (huge_page_size - reinterpret_cast<std::uintptr_t>(begin) % huge_page_size) % huge_page_size;
  char* const p = begin + head;
  if(head > 0) ::munmap(begin, head);
  if(over - head > len) ::munmap(p + len, over - head - len);
  ::madvise(p, len, MADV_HUGEPAGE); // advice only: without huge pages the block still works
  try
  {
    std::lock_guard<std::mutex> lock(huge_blocks().mutex);
    huge_blocks().length.emplace(p, len);
  }
  catch(...)
  {
    ::munmap(p, len);
    return nullptr;
  }
  return p;
}

// The mapped length of p, 0 if p is not one of the mapped blocks; `remove`: forget it.
inline std::size_t huge_block_length(void* p, bool remove)
{
  if(p == nullptr) return 0;
  std::lock_guard<std::mutex> lock(huge_blocks().mutex);
  auto it = huge_blocks().length.find(p);
  if(it == huge_blocks().length.end()) return 0;
  const std::size_t len = it->second;
  if(remove) huge_blocks().length.erase(it);
  return len;
}

inline void* pe_cholmod_malloc(std::size_t n)
{
  if(n >= huge_block_minimum) if(void* p = map_huge_block(n)) return p;
  return std::malloc(n);
}
inline void* pe_cholmod_calloc(std::size_t count, std::size_t size)
{
  // a fresh mapping is zeroed already
  if(size != 0 && count >= huge_block_minimum / size && count <= std::size_t(-1) / size)
    if(void* p = map_huge_block(count * size)) return p;
  return std::calloc(count, size);
}
inline void pe_cholmod_free(void* p)
{
  if(const std::size_t len = huge_block_length(p, true)) ::munmap(p, len);
  else std::free(p);
}
inline void* pe_cholmod_realloc(void* p, std::size_t n)
{
  const std::size_t len = huge_block_length(p, false);
  if(len == 0 && !(p == nullptr && n >= huge_block_minimum)) return std::realloc(p, n);
  if(len >= n && n > 0) return p; // shrinking a mapped block: keep it
  void* q = pe_cholmod_malloc(n == 0 ? 1 : n);
  if(q == nullptr) return nullptr; // p stays valid, as realloc() leaves it
  if(p != nullptr)
  {
    std::memcpy(q, p, (std::min)(len, n));
    pe_cholmod_free(p);
  }
  return q;
}

// Sets SuiteSparse's memory functions to the ones above, once per process (the first call decides),
// if huge pages are requested and the functions are still the C library's.
inline void use_huge_pages_for_cholmod()
{
  static std::once_flag once;
  std::call_once(once, []() {
    if(!huge_pages_requested()) return;
#if SUITESPARSE_MAIN_VERSION >= 7
    if(SuiteSparse_config_malloc_func_get() != &std::malloc || SuiteSparse_config_calloc_func_get() != &std::calloc ||
       SuiteSparse_config_realloc_func_get() != &std::realloc || SuiteSparse_config_free_func_get() != &std::free)
      return;
    SuiteSparse_config_malloc_func_set(&pe_cholmod_malloc);
    SuiteSparse_config_calloc_func_set(&pe_cholmod_calloc);
    SuiteSparse_config_realloc_func_set(&pe_cholmod_realloc);
    SuiteSparse_config_free_func_set(&pe_cholmod_free);
#else
    if(SuiteSparse_config.malloc_func != &std::malloc || SuiteSparse_config.calloc_func != &std::calloc ||
       SuiteSparse_config.realloc_func != &std::realloc || SuiteSparse_config.free_func != &std::free)
      return;
    SuiteSparse_config.malloc_func = &pe_cholmod_malloc;
    SuiteSparse_config.calloc_func = &pe_cholmod_calloc;
    SuiteSparse_config.realloc_func = &pe_cholmod_realloc;
    SuiteSparse_config.free_func = &pe_cholmod_free;
#endif
  });
}

#else

inline bool huge_pages_requested() { return false; }
inline void use_huge_pages_for_cholmod() { }

#endif

// Gives the free memory of glibc's heap back to the system before a large factorization. Why: the
// system's rows, the weights and a mesh reader's buffers are many small blocks; freed, they stay in
// the heap (glibc returns only its top on its own), and CHOLMOD's large blocks are mappings of their
// own that cannot reuse them, so they would count in the peak beside the factor (at 1M unknowns
// about 100 MB on the grid disk, benchmark/results/large_meshes_memory.md). Nothing elsewhere.
inline void release_free_heap_memory()
{
#if defined(__GLIBC__)
  ::malloc_trim(0);
#endif
}

// Dynamic OpenMP threads on the calling thread while it lives (see above); the former setting after.
class Cholmod_dynamic_threads
{
public:
  Cholmod_dynamic_threads()
  {
#if defined(__unix__)
    typedef void (*Set)(int);
    typedef int (*Get)();
    m_set = reinterpret_cast<Set>(::dlsym(RTLD_DEFAULT, "omp_set_dynamic"));
    const Get get = reinterpret_cast<Get>(::dlsym(RTLD_DEFAULT, "omp_get_dynamic"));
    if(m_set == nullptr || get == nullptr) { m_set = nullptr; return; }
    m_former = get();
    m_set(1);
#endif
  }
  ~Cholmod_dynamic_threads() { if(m_set != nullptr) m_set(m_former); }
  Cholmod_dynamic_threads(const Cholmod_dynamic_threads&) = delete;
  Cholmod_dynamic_threads& operator=(const Cholmod_dynamic_threads&) = delete;

private:
  void (*m_set)(int) = nullptr;
  int m_former = 0;
};

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_CHOLMOD_ENABLED

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CHOLMOD_RUNTIME_H
