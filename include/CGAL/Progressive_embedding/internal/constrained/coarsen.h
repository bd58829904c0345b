// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_COARSEN_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_COARSEN_H

// Coarsening of a refined map: a vertex added by an edge split is removed again, its star replaced
// by the fan from one end of the edge it split, wherever every face of that fan is strictly
// positive (exact orientation) in the current map and, optionally, passes a bound on its distortion
// (the caller's: the constrained pipeline refuses a fan face more distorted than the map's worst face,
// so that the coarsening never makes the optimized map worse). Nothing else moves, so the map stays certified:
// the faces away from the fan are unchanged, the border is unchanged (added vertices are interior),
// and a map whose faces are all positive with its border fixed and simple is one-to-one.
//
// Why the fan from an end of the split edge: the removed vertex lies on that edge of the input
// surface (or on a chord of one input face), and each face of its star lies in one input face that
// has this end on its boundary, so every face of the fan lies in an input face too: the output is
// still a refinement of the input surface, and the positions of the other added vertices on it do
// not change.
//
// The removal is written with Euler operations only (remove_center_vertex(), then split_face() for
// the fan), so that the caller's mesh replays it exactly (replay_removals()), with its vertex
// descriptors kept (no vertex but the removed one changes).

#include <CGAL/Progressive_embedding/Error_code.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// One removal: `removed` was replaced by the fan from `kept`
template <class Vertex>
struct Vertex_removal
{
  Vertex removed, kept;
};

// The link of interior vertex s as a cycle starting after `a` (a is a neighbour of s): the other
// neighbours in the order of the faces around s; empty when s is on the border or a is not adjacent.
template <class TM>
bool fan_link(const TM& tm, typename boost::graph_traits<TM>::vertex_descriptor s,
              typename boost::graph_traits<TM>::vertex_descriptor a,
              std::vector<typename boost::graph_traits<TM>::vertex_descriptor>& link)
{
  link.clear();
  const auto h = halfedge(a, s, tm); // a -> s
  if(!h.second || CGAL::is_border(s, tm)) return false;
  // around s counterclockwise: from the halfedge s -> a, next(opposite) gives the following neighbour
  auto g = opposite(h.first, tm); // s -> a
  const auto start = g;
  std::size_t guard = 0;
  do
  {
    if(CGAL::is_border(g, tm)) return false;
    link.push_back(target(g, tm));
    g = opposite(prev(g, tm), tm); // the next halfedge out of s around its faces
    if(++guard > 1000000) return false;
  } while(g != start);
  return true; // link[0] == a
}

// Every fan face is acceptable (no bound on its shape)
struct Any_fan_face
{
  template <class Vertex>
  bool operator()(Vertex, Vertex, Vertex) const { return true; }
};

// Whether removing s into a keeps every new face strictly `positive` in `uv` (exact `orient`), and
// the mesh a manifold (the link condition of the edge s-a); with `accept`, each new face (a, x, y) must
// also pass accept(a, x, y) (a bound on its distortion)
template <class TM, class UVMap, class Orientation, class FaceAccept = Any_fan_face>
bool can_remove_into(const TM& tm, UVMap uv, Orientation orient, CGAL::Orientation positive,
                     typename boost::graph_traits<TM>::vertex_descriptor s,
                     typename boost::graph_traits<TM>::vertex_descriptor a,
                     std::vector<typename boost::graph_traits<TM>::vertex_descriptor>& link,
                     const FaceAccept& accept = FaceAccept())
{
  if(!fan_link(tm, s, a, link) || link.size() < 3) return false;
  const auto h = halfedge(a, s, tm);
  if(!CGAL::Euler::does_satisfy_link_condition(edge(h.first, tm), tm)) return false;
  // the fan faces (a, link[k], link[k + 1]) for k = 1 .. n-2, oriented as the faces around s
  const auto pa = get(uv, a);
  for(std::size_t k = 1; k + 1 < link.size(); ++k)
    if(orient(pa, get(uv, link[k]), get(uv, link[k + 1])) != positive) return false;
  for(std::size_t k = 1; k + 1 < link.size(); ++k)
    if(!accept(a, link[k], link[k + 1])) return false;
  return true;
}

// Removes s and fans its link from a (precondition: can_remove_into() held, or the same
// connectivity as a mesh where it did)
template <class TM>
Error_code remove_into(TM& tm, typename boost::graph_traits<TM>::vertex_descriptor s,
                       typename boost::graph_traits<TM>::vertex_descriptor a)
{
  typedef typename boost::graph_traits<TM>::halfedge_descriptor halfedge_descriptor;
  std::vector<typename boost::graph_traits<TM>::vertex_descriptor> link;
  if(!fan_link(tm, s, a, link) || link.size() < 3) return ERROR_WRONG_PARAMETER;
  const auto h = halfedge(a, s, tm); // a -> s: target s is the centre
  halfedge_descriptor f = CGAL::Euler::remove_center_vertex(h.first, tm); // a halfedge of the merged face
  // the merged face: its halfedge leaving a
  std::size_t guard = 0;
  while(source(f, tm) != a && ++guard <= link.size() + 1) f = next(f, tm);
  if(source(f, tm) != a) return ERROR_WRONG_PARAMETER;
  // fan: the face is a, x1, x2, ..., xm; each split cuts off the triangle a, x1, x2 by the halfedge x2 -> a,
  // and leaves into_a -> (a -> x2) -> ... as the rest of the face
  const halfedge_descriptor into_a = prev(f, tm); // ends at a
  for(std::size_t k = 0; k + 3 < link.size(); ++k)
  {
    const halfedge_descriptor h_x1x2 = next(next(into_a, tm), tm);
    CGAL::Euler::split_face(h_x1x2, into_a, tm);
  }
  return OK;
}

// The removals of a coarsening: passes over the added vertices `added` (members v, a, b: the vertex and
// the ends of the edge it split), latest first (they split edges between earlier vertices), repeated
// while a pass removes something (a removal can free an earlier refusal). `test(v, a, link)`: whether v
// can go into a (can_remove_into(), which fills v's link from a); `remove(v, a, link)`: removes it,
// returning OK. Appends each removal to `removals`; done[k]: whether added[k] was removed.
// A test of v into a reads the stars of v and a only (the link, the link condition, the fan faces;
// nothing moves), and a removal changes the stars of the removed vertex's link, the kept end among them.
// So a vertex is tested again only when the star of it or of an end of its edge changed since its last
// test: the same removals in the same order as testing every vertex in every pass (`retest_all`, kept
// for the tests), without the passes' repeated tests (diplodocus with 200 random targets: 688,500 added
// vertices, 15.9 s of coarsening before). Vertex descriptors convert to indices below `vertex_slots`
// (Surface_mesh). `passes`: the passes made.
template <class Added, class Vertex, class Test, class Remove>
Error_code remove_added_vertices(const std::vector<Added>& added, std::size_t vertex_slots, const Test& test,
                                 const Remove& remove, std::vector<char>& done,
                                 std::vector<Vertex_removal<Vertex> >& removals, std::size_t& passes,
                                 bool retest_all = false)
{
  std::vector<Vertex> link;
  std::vector<std::size_t> changed(vertex_slots, 0);               // per vertex: removals when its star last changed
  std::vector<std::size_t> tested(added.size(), std::size_t(-1));  // per added vertex: removals at its last test
  done.assign(added.size(), 0);
  passes = 0;
  for(std::size_t pass = 0; pass < added.size(); ++pass) // each pass but the last removes a vertex
  {
    ++passes;
    std::size_t removed = 0;
    for(std::size_t k = added.size(); k-- > 0;)
    {
      if(done[k]) continue;
      const auto& sv = added[k];
      CGAL_assertion(std::size_t(sv.v) < vertex_slots && std::size_t(sv.a) < vertex_slots && std::size_t(sv.b) < vertex_slots);
      const std::size_t last = tested[k];
      if(!retest_all && last != std::size_t(-1) && changed[std::size_t(sv.v)] <= last &&
         changed[std::size_t(sv.a)] <= last && changed[std::size_t(sv.b)] <= last)
        continue;
      tested[k] = removals.size();
      for(const Vertex a : { sv.a, sv.b })
      {
        if(!test(sv.v, a, link)) continue;
        const Error_code ec = remove(sv.v, a, link);
        if(ec != OK) return ec;
        removals.push_back({ sv.v, a });
        for(const Vertex x : link) changed[std::size_t(x)] = removals.size(); // link[0] is a
        done[k] = 1;
        ++removed;
        break;
      }
    }
    if(removed == 0) break;
  }
  return OK;
}

// Replays removals recorded on a copy onto tm, through the vertex correspondence
template <class TM, class CopyVertex, class VertexMap>
Error_code replay_removals(const std::vector<Vertex_removal<CopyVertex> >& removals, TM& tm, const VertexMap& copy_to_mesh)
{
  for(const auto& r : removals)
  {
    const auto s = copy_to_mesh.find(r.removed), a = copy_to_mesh.find(r.kept);
    if(s == copy_to_mesh.end() || a == copy_to_mesh.end()) return ERROR_WRONG_PARAMETER;
    const Error_code ec = remove_into(tm, s->second, a->second);
    if(ec != OK) return ec;
  }
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_COARSEN_H
