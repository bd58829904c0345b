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
// Every patch is tried (but once the time budget is exhausted the workers stop): the failed ones
// are listed, and the error of the lowest index is returned, the same in sequential and parallel.
//
// merge_failed_patch(work, patch_faces, face_patch, is_node, failed, uvm, weights, remaining, excluded,
// merged_with): the fallback for a patch whose polygon has no room for its vertices (a needle a few
// ulps wide, when targets lie within a few ulps of each other). The patch is mapped together with
// neighbours across its paths, into the union of their polygons, the vertices of the paths between
// them free: the neighbour with the largest polygon first, then, while the map fails, the largest
// neighbour of the union, up to max_merged_patches patches. A neighbour is added only if every node
// (constrained vertex, border point) stays on the union's border, its uv fixed; `excluded` patches
// (merged already) are not added. The union's map has the certificate of embed_patch_impl() (simple
// border, every face strictly positive); the whole map is certified afterwards as before.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_statistics.h>
#include <CGAL/Progressive_embedding/internal/embed_patch_impl.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/Progressive_embedding/internal/parallel_for.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <atomic>
#include <cmath>
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
  Error_code status = OK;                     // ERROR_BUDGET_EXHAUSTED if any patch ran out of time
  std::size_t failed_patch = std::size_t(-1); // with status != OK: the lowest index of `failed`
  std::vector<std::size_t> failed;            // the patches not mapped, increasing
  std::size_t repaired_patches = 0;           // patches whose Tutte map needed collapses or insertions
};

// Upper bound on the worker threads (each holds a face and a vertex array of the whole mesh).
constexpr int max_patch_workers = 16;

// `remaining()`: seconds left of the caller's budget (read by every patch when it starts).
// `traits`: the geometric traits of every patch map (the `geom_traits` of embed_patch()).
template <class ConcurrencyTag, class Mesh, class UVMap, class Traits, class Remaining>
Patch_phase_result embed_patches(Mesh& work, const std::vector<std::vector<typename boost::graph_traits<Mesh>::face_descriptor> >& patch_faces,
                                 UVMap uvm, Weights weights, const Traits& traits, Remaining remaining)
{
  typedef typename boost::property_traits<UVMap>::value_type Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel::FT  FT;
  const std::size_t n = patch_faces.size();
  std::vector<Error_code> status(n, OK);
  std::vector<char> repaired(n, 0), ran(n, 0);
  std::atomic<bool> failed(false);

  auto embed_one = [&](std::size_t p, Patch_slots<Mesh>& slots)
  {
    if(failed.load(std::memory_order_relaxed)) return; // out of time: the result is an error anyway
    ran[p] = 1;
    if(!(remaining() > 0)) { status[p] = ERROR_BUDGET_EXHAUSTED; failed = true; return; }
    Progressive_embedding_statistics pst;
    status[p] = embed_patch_impl(work, patch_faces[p], uvm,
                                 parameters::statistics(&pst, parameters::weights(weights).geom_traits(traits).maximum_running_time(remaining())),
                                 true, &slots, false);
    repaired[p] = (pst.collapses > 0 || pst.insertions > 0);
    if(status[p] == ERROR_BUDGET_EXHAUSTED) failed = true;
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
    if(!ran[p] || status[p] == OK) continue;
    if(result.status == OK) { result.status = status[p]; result.failed_patch = p; }
    result.failed.push_back(p);
  }
  if(failed) result.status = ERROR_BUDGET_EXHAUSTED; // out of time: no fallback either
  return result;
}

// twice the signed area of a patch under the current uv (the sum over its faces, in double): the area
// of its polygon when its map is valid
template <class Mesh, class UVMap>
double patch_polygon_area(const Mesh& work, const std::vector<typename boost::graph_traits<Mesh>::face_descriptor>& faces,
                          UVMap uvm)
{
  double a = 0;
  for(auto f : faces)
  {
    const auto h = halfedge(f, work);
    const auto p = get(uvm, source(h, work)), q = get(uvm, target(h, work)), r = get(uvm, target(next(h, work), work));
    a += (CGAL::to_double(q.x()) - CGAL::to_double(p.x())) * (CGAL::to_double(r.y()) - CGAL::to_double(p.y()))
       - (CGAL::to_double(q.y()) - CGAL::to_double(p.y())) * (CGAL::to_double(r.x()) - CGAL::to_double(p.x()));
  }
  return a;
}

// Maximum number of patches mapped as one by merge_failed_patch().
constexpr std::size_t max_merged_patches = 8;

template <class Mesh, class FacePatchMap, class UVMap, class Traits, class Remaining>
Error_code merge_failed_patch(Mesh& work, const std::vector<std::vector<typename boost::graph_traits<Mesh>::face_descriptor> >& patch_faces,
                              FacePatchMap face_patch, const std::vector<char>& is_node, std::size_t failed, UVMap uvm,
                              Weights weights, const Traits& traits, Remaining remaining, const std::vector<char>& excluded,
                              std::vector<std::size_t>& merged_with)
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::vector<std::size_t> region(1, failed);
  auto in_region = [&](std::size_t q) { return std::find(region.begin(), region.end(), q) != region.end(); };
  // the region's neighbours across paths (not mesh border edges), not excluded
  auto neighbours = [&]()
  {
    std::vector<std::size_t> result;
    for(std::size_t r : region)
      for(face_descriptor f : patch_faces[r])
        for(auto h : CGAL::halfedges_around_face(halfedge(f, work), work))
        {
          const auto o = opposite(h, work);
          if(CGAL::is_border(o, work)) continue;
          const std::size_t q = static_cast<std::size_t>(get(face_patch, face(o, work)));
          if(!excluded[q] && !in_region(q) && std::find(result.begin(), result.end(), q) == result.end()) result.push_back(q);
        }
    return result;
  };
  // every node of the union stays on its border (its target is fixed): some face around it is outside
  auto nodes_on_border = [&](std::size_t q)
  {
    for(face_descriptor f : patch_faces[q])
      for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, work), work))
      {
        if(!is_node[static_cast<std::size_t>(v)]) continue;
        bool outside = false;
        for(auto h : CGAL::halfedges_around_target(halfedge(v, work), work))
        {
          if(CGAL::is_border(h, work)) { outside = true; break; }
          const std::size_t g = static_cast<std::size_t>(get(face_patch, face(h, work)));
          if(g != q && !in_region(g)) { outside = true; break; }
        }
        if(!outside) return false;
      }
    return true;
  };
  Error_code ec = ERROR_INVALID_EMBEDDING;
  while(region.size() < max_merged_patches)
  {
    if(!(remaining() > 0)) return ERROR_BUDGET_EXHAUSTED;
    // the neighbour with the largest polygon (valid maps: their areas; refused ones keep the placement's uv)
    std::size_t best = std::size_t(-1);
    double best_area = -1;
    for(std::size_t q : neighbours())
    {
      const double area = std::abs(patch_polygon_area(work, patch_faces[q], uvm));
      if(area > best_area && nodes_on_border(q)) { best = q; best_area = area; }
    }
    if(best == std::size_t(-1)) break;
    region.push_back(best);
    std::vector<face_descriptor> faces;
    for(std::size_t r : region) faces.insert(faces.end(), patch_faces[r].begin(), patch_faces[r].end());
    ec = embed_patch_impl(work, faces, uvm, parameters::weights(weights).geom_traits(traits).maximum_running_time(remaining()),
                          true, static_cast<Patch_slots<Mesh>*>(nullptr), false);
    if(ec == OK) { merged_with.assign(region.begin() + 1, region.end()); return OK; }
    if(ec == ERROR_BUDGET_EXHAUSTED) return ec;
  }
  return ec;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_EMBED_PATCHES_H
