// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CUT_PAIR_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CUT_PAIR_H

// Where to cut a closed genus-0 surface with many landmarks: between the two landmarks nearest to each other along
// the mesh's edges. Any two landmarks joined by a path make a cut that opens the surface into a disk (a slit); the
// other landmarks then stay inside the disk, pinned like the landmarks of two disks. A short cut is traced alike on
// two meshes of one surface, where a long one (between far landmarks) follows one of several nearly equal shortest
// paths, which two triangulations choose differently, and carries that difference into the border of both maps.

#include <CGAL/Progressive_embedding/internal/length_3.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// The positions in `landmarks` (distinct vertices of `tm`) of the two landmarks with the shortest edge path between
// them that goes through no other landmark and has a vertex inside (two landmarks joined by an edge make a cut that
// opens nothing); the first position the smaller. Lengths are 3D edge lengths; ties go to the smaller positions.
// One multi-source Dijkstra labels each vertex by its nearest landmark, and the pairs whose regions meet across an
// edge are the candidates: the nearest pair of landmarks is among them, so the result is the nearest qualifying
// pair unless nearer landmarks are joined by an edge (then it is the nearest of the other candidates). False when
// no candidate qualifies (fewer than two landmarks, or every pair whose regions meet joined by an edge).
// O(E log V).
template <class TriangleMesh, class VPM>
bool nearest_landmark_pair(const TriangleMesh& tm, VPM vpm,
                           const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks,
                           std::size_t& first, std::size_t& second)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  constexpr std::size_t none = std::size_t(-1);
  if(landmarks.size() < 2) return false;
  std::unordered_map<vertex_descriptor, std::size_t> index;
  std::vector<vertex_descriptor> at;
  for(vertex_descriptor v : vertices(tm)) { index.emplace(v, at.size()); at.push_back(v); }
  const std::size_t n = at.size();
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> label(n, none), landmark_of(n, none);
  typedef std::pair<double, std::size_t> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  for(std::size_t k = 0; k < landmarks.size(); ++k)
  {
    const std::size_t i = index.at(landmarks[k]);
    landmark_of[i] = label[i] = k;
    distance[i] = 0;
    queue.emplace(0., i);
  }
  while(!queue.empty())
  {
    const Entry e = queue.top();
    queue.pop();
    if(e.first > distance[e.second]) continue;
    const vertex_descriptor v = at[e.second];
    for(vertex_descriptor w : vertices_around_target(halfedge(v, tm), tm))
    {
      const std::size_t j = index.at(w);
      const double d = e.first + length_3(get(vpm, v), get(vpm, w));
      // (a landmark stays its own label: no path goes through it)
      if(landmark_of[j] == none && (d < distance[j] || (d == distance[j] && label[e.second] < label[j])))
      {
        distance[j] = d;
        label[j] = label[e.second];
        queue.emplace(d, j);
      }
    }
  }
  // landmarks joined by an edge: their shortest path is that edge
  std::set<std::pair<std::size_t, std::size_t> > adjacent;
  for(vertex_descriptor l : landmarks)
    for(vertex_descriptor w : vertices_around_target(halfedge(l, tm), tm))
    {
      const std::size_t a = landmark_of[index.at(l)], b = landmark_of[index.at(w)];
      if(b != none) adjacent.emplace((std::min)(a, b), (std::max)(a, b));
    }
  double best = std::numeric_limits<double>::infinity();
  std::pair<std::size_t, std::size_t> best_pair(none, none);
  for(auto e : edges(tm))
  {
    const vertex_descriptor u = source(halfedge(e, tm), tm), w = target(halfedge(e, tm), tm);
    const std::size_t iu = index.at(u), iw = index.at(w);
    if(label[iu] == none || label[iw] == none || label[iu] == label[iw]) continue;
    const std::pair<std::size_t, std::size_t> p((std::min)(label[iu], label[iw]), (std::max)(label[iu], label[iw]));
    if(adjacent.count(p) != 0) continue;
    const double d = distance[iu] + length_3(get(vpm, u), get(vpm, w)) + distance[iw];
    if(d < best || (d == best && p < best_pair)) { best = d; best_pair = p; }
  }
  if(best_pair.first == none) return false;
  first = best_pair.first;
  second = best_pair.second;
  return true;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CUT_PAIR_H
