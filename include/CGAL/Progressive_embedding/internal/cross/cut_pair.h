// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CUT_PAIR_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CUT_PAIR_H

// Where to cut a closed genus-0 surface with many landmarks: between two landmarks near each other along the mesh's
// edges. Any two landmarks joined by a path make a cut that opens the surface into a disk (a slit); the
// other landmarks then stay inside the disk, pinned like the landmarks of two disks. A short cut is traced alike on
// two meshes of one surface, where a long one (between far landmarks) follows one of several nearly equal shortest
// paths, which two triangulations choose differently, and carries that difference into the border of both maps.

#include <CGAL/Progressive_embedding/internal/length_3.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// Candidate pairs of landmarks to cut between, nearest first: the positions in `landmarks` (distinct vertices of
// `tm`), the first the smaller, and the length of an edge path between them through no other landmark and through a
// vertex that is no landmark (two landmarks joined by an edge make a cut that opens nothing: the cut between them
// avoids that edge, cut_along_chain()'s `no_direct_edge`). Lengths are 3D edge lengths; ties go to the smaller
// positions. One multi-source Dijkstra labels each vertex by its nearest landmark; the pairs whose regions meet
// across an edge with an end that is no landmark are the candidates, each with its shortest such crossing (the
// nearest two landmarks are among them). Empty when there is none (fewer than two landmarks, or every vertex a
// landmark). O(E log V).
template <class TriangleMesh, class VPM>
std::vector<std::pair<double, std::pair<std::size_t, std::size_t> > >
landmark_pairs_to_cut(const TriangleMesh& tm, VPM vpm,
                      const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& landmarks)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef std::pair<std::size_t, std::size_t> Pair;
  constexpr std::size_t none = std::size_t(-1);
  std::vector<std::pair<double, Pair> > candidates;
  if(landmarks.size() < 2) return candidates;
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
  std::map<Pair, double> shortest;
  for(auto e : edges(tm))
  {
    const vertex_descriptor u = source(halfedge(e, tm), tm), w = target(halfedge(e, tm), tm);
    const std::size_t iu = index.at(u), iw = index.at(w);
    if(label[iu] == none || label[iw] == none || label[iu] == label[iw]) continue;
    if(landmark_of[iu] != none && landmark_of[iw] != none) continue; // the edge between two landmarks itself
    const Pair p((std::min)(label[iu], label[iw]), (std::max)(label[iu], label[iw]));
    const double d = distance[iu] + length_3(get(vpm, u), get(vpm, w)) + distance[iw];
    auto it = shortest.find(p);
    if(it == shortest.end()) shortest.emplace(p, d);
    else if(d < it->second) it->second = d;
  }
  for(const auto& s : shortest) candidates.emplace_back(s.second, s.first);
  std::sort(candidates.begin(), candidates.end());
  return candidates;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CUT_PAIR_H
