// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CUT_CLOSED_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CUT_CLOSED_H

// A closed genus-0 triangle mesh cut into a disk along a chain of landmarks (the MatchMaker way): the
// shortest edge path from each landmark to the next, the paths disjoint (each avoids the vertices of the
// earlier ones and every other landmark), then every vertex inside the chain is doubled, the faces on one
// side (counterclockwise from the next chain vertex to the previous one) taking the copy. The chain's two
// ends stay single. Cutting two meshes along chains through the same landmarks in the same order gives two
// disks whose borders correspond: both run along the chain and back, and a landmark's copy on one side of
// one chain matches the copy on the same side of the other. split_chords() then splits the edges that join
// two border vertices of a cut disk.

#include <CGAL/Progressive_embedding/internal/length_3.h>
#include <CGAL/Progressive_embedding/Error_code.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/squared_distance_3.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// the cut disk as a soup: the points (the mesh's vertices in `vertices(tm)` order, then the copies), the
// triangles (in `faces(tm)` order), and for every point the mesh vertex it is (a copy of)
template <class TriangleMesh>
struct Cut_disk
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  std::vector<vertex_descriptor> vertices;                // point index -> mesh vertex (copies repeat it)
  std::vector<face_descriptor> faces;                     // face index -> mesh face
  std::vector<std::array<std::size_t, 3> > triangles;     // source(h), target(h), target(next(h)), h = halfedge(f)
  std::vector<std::size_t> copy;                          // point index of each doubled vertex's copy, or -1
  std::size_t path_edges = 0;
};

// whether `tm` is a closed triangle mesh (no border halfedge)
template <class TriangleMesh>
bool is_closed_mesh(const TriangleMesh& tm)
{
  for(auto h : halfedges(tm))
    if(is_border(h, tm)) return false;
  return !faces(tm).empty();
}

// `chain`: mesh vertices (distinct); `avoid`: other vertices no path may go through (the landmarks that stay inside
// the cut disk); `no_direct_edge`: no path takes the edge joining its two ends (for a chain of two landmarks joined by
// an edge, a path around it; without it such a chain is refused, see below). On success `cut` is a disk (for a
// connected genus-0 mesh). Returns
// ERROR_NON_TRIANGULAR_MESH, ERROR_NOT_GENUS_ZERO (not connected, or Euler characteristic not 2),
// ERROR_PATH_TRACING_FAILED with `failed` the chain position whose path from the previous one was not
// found (the earlier paths and the other landmarks closed every way), or ERROR_NOT_A_DISK with `failed` 1 when
// the whole cut is one edge (two landmarks joined by an edge: only the inner vertices of a cut are doubled, so
// such a cut opens nothing and the surface would stay closed).
template <class TriangleMesh, class VPM>
Error_code cut_along_chain(const TriangleMesh& tm, VPM vpm,
                           const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& chain,
                           Cut_disk<TriangleMesh>& cut, std::size_t& failed,
                           const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& avoid = {},
                           bool no_direct_edge = false)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  cut = Cut_disk<TriangleMesh>();
  failed = std::size_t(-1);
  std::unordered_map<vertex_descriptor, std::size_t> index;
  for(vertex_descriptor v : vertices(tm)) { index.emplace(v, cut.vertices.size()); cut.vertices.push_back(v); }
  const std::size_t n = cut.vertices.size();
  for(auto f : faces(tm))
  {
    if(!is_triangle(halfedge(f, tm), tm)) return ERROR_NON_TRIANGULAR_MESH;
    const halfedge_descriptor h = halfedge(f, tm);
    cut.faces.push_back(f);
    cut.triangles.push_back({{ index.at(source(h, tm)), index.at(target(h, tm)), index.at(target(next(h, tm), tm)) }});
  }
  // connected, Euler characteristic 2
  {
    std::vector<char> seen(n, 0);
    std::vector<vertex_descriptor> stack(1, cut.vertices[0]);
    seen[0] = 1;
    std::size_t reached = 1;
    while(!stack.empty())
    {
      const vertex_descriptor v = stack.back();
      stack.pop_back();
      for(vertex_descriptor w : vertices_around_target(halfedge(v, tm), tm))
        if(!seen[index.at(w)]) { seen[index.at(w)] = 1; ++reached; stack.push_back(w); }
    }
    const long chi = long(n) - long(edges(tm).size()) + long(faces(tm).size());
    if(reached != n || chi != 2) return ERROR_NOT_GENUS_ZERO;
  }
  // the chain: shortest paths (3D edge lengths), disjoint
  std::vector<char> blocked(n, 0);
  for(vertex_descriptor l : chain) blocked[index.at(l)] = 1;
  for(vertex_descriptor l : avoid) blocked[index.at(l)] = 1;
  std::vector<std::size_t> path(1, index.at(chain.front()));
  for(std::size_t i = 0; i + 1 < chain.size(); ++i)
  {
    const std::size_t from = index.at(chain[i]), to = index.at(chain[i + 1]);
    std::vector<double> distance(n, std::numeric_limits<double>::infinity());
    std::vector<std::size_t> parent(n, std::size_t(-1));
    typedef std::pair<double, std::size_t> Entry;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
    distance[from] = 0;
    queue.emplace(0., from);
    while(!queue.empty())
    {
      const Entry e = queue.top();
      queue.pop();
      if(e.first > distance[e.second]) continue;
      if(e.second == to) break;
      const vertex_descriptor v = cut.vertices[e.second];
      for(vertex_descriptor w : vertices_around_target(halfedge(v, tm), tm))
      {
        const std::size_t j = index.at(w);
        if(blocked[j] && j != to) continue;
        if(no_direct_edge && e.second == from && j == to) continue;
        const double d = e.first + length_3(get(vpm, v), get(vpm, w));
        if(d < distance[j]) { distance[j] = d; parent[j] = e.second; queue.emplace(d, j); }
      }
    }
    if(parent[to] == std::size_t(-1)) { failed = i + 1; return ERROR_PATH_TRACING_FAILED; }
    std::vector<std::size_t> piece;
    for(std::size_t j = to; j != from; j = parent[j]) piece.push_back(j);
    for(auto it = piece.rbegin(); it != piece.rend(); ++it) { path.push_back(*it); blocked[*it] = 1; }
  }
  if(path.size() < 3) { failed = 1; return ERROR_NOT_A_DISK; }
  cut.path_edges = path.size() - 1;
  // every vertex inside the chain doubled: the faces counterclockwise from the next chain vertex to the
  // previous one take the copy
  cut.copy.assign(n, std::size_t(-1));
  std::unordered_map<typename GT::face_descriptor, std::size_t> face_index;
  for(std::size_t f = 0; f < cut.faces.size(); ++f) face_index.emplace(cut.faces[f], f);
  for(std::size_t k = 1; k + 1 < path.size(); ++k)
  {
    const vertex_descriptor v = cut.vertices[path[k]], next_v = cut.vertices[path[k + 1]], prev_v = cut.vertices[path[k - 1]];
    const std::size_t c = cut.vertices.size();
    cut.vertices.push_back(v);
    cut.copy[path[k]] = c;
    halfedge_descriptor h = halfedge(v, next_v, tm).first; // v -> next, its face on the left
    const std::size_t around = degree(v, tm);
    for(std::size_t step = 0; target(h, tm) != prev_v && step < around; ++step)
    {
      std::array<std::size_t, 3>& t = cut.triangles[face_index.at(face(h, tm))];
      for(std::size_t& x : t) if(x == path[k]) x = c;
      h = opposite(prev(h, tm), tm); // the next halfedge out of v, counterclockwise
    }
  }
  return OK;
}

// The cut disk with its chords split: an interior edge joining two border vertices gets a vertex at its
// midpoint, its two triangles split in two each (no new chord: the new vertex is interior). Where two
// paths of the chain run side by side (up and down a thin limb to a landmark at its tip) the edges across
// them are chords, and the mesh mapped first onto the square (B, by Tutte's method) flattens any chord
// whose ends lie on one side. `triangles` and `face` (the index in `cut.faces` of the face holding each
// triangle) describe the split soup; a point of index i >= cut.vertices.size() is the midpoint of the two
// points `midpoint[i - cut.vertices.size()]`. Returns the number of chords split.
struct Split_soup
{
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::size_t> face;
  std::vector<std::array<std::size_t, 2> > midpoint;
};

template <class TriangleMesh>
std::size_t split_chords(const Cut_disk<TriangleMesh>& cut, Split_soup& out)
{
  typedef std::pair<std::size_t, std::size_t> Edge;
  struct Edge_hash { std::size_t operator()(const Edge& e) const { return e.first * 1000003u ^ e.second; } };
  out.triangles = cut.triangles;
  out.face.resize(cut.triangles.size());
  for(std::size_t t = 0; t < out.face.size(); ++t) out.face[t] = t;
  out.midpoint.clear();
  auto key = [](std::size_t a, std::size_t b) { return a < b ? Edge(a, b) : Edge(b, a); };
  std::unordered_map<Edge, std::vector<std::size_t>, Edge_hash> incident;
  for(std::size_t t = 0; t < out.triangles.size(); ++t)
    for(int k = 0; k < 3; ++k) incident[key(out.triangles[t][k], out.triangles[t][(k + 1) % 3])].push_back(t);
  std::vector<char> on_border(cut.vertices.size(), 0);
  std::vector<Edge> chords;
  for(const auto& e : incident)
    if(e.second.size() == 1) on_border[e.first.first] = on_border[e.first.second] = 1;
  for(const auto& e : incident)
    if(e.second.size() == 2 && on_border[e.first.first] && on_border[e.first.second]) chords.push_back(e.first);
  std::sort(chords.begin(), chords.end()); // the same split whatever the hash order
  std::size_t next = cut.vertices.size();
  for(const Edge& c : chords)
  {
    const std::vector<std::size_t> ts = incident.at(c);
    const std::size_t m = next++;
    out.midpoint.push_back({{ c.first, c.second }});
    for(std::size_t t : ts)
    {
      // (a, b, x) with a -> b the chord: (a, m, x) in place, (m, b, x) added, in the same face
      std::array<std::size_t, 3> tri = out.triangles[t];
      int k = 0;
      while(key(tri[k], tri[(k + 1) % 3]) != c) ++k;
      const std::size_t a = tri[k], b = tri[(k + 1) % 3], x = tri[(k + 2) % 3];
      const std::size_t added = out.triangles.size();
      out.triangles[t] = {{ a, m, x }};
      out.triangles.push_back({{ m, b, x }});
      out.face.push_back(out.face[t]);
      auto& bx = incident[key(b, x)];
      std::replace(bx.begin(), bx.end(), t, added);
      incident[key(a, m)].push_back(t);
      incident[key(m, x)].push_back(t);
      incident[key(m, x)].push_back(added);
      incident[key(m, b)].push_back(added);
    }
    incident.erase(c);
  }
  return chords.size();
}

// per point of `cut` (and of any point added after them): the point that is the same mesh vertex on the other side of
// the cut, or -1
template <class TriangleMesh>
std::vector<std::size_t> cut_twins(const Cut_disk<TriangleMesh>& cut, std::size_t points)
{
  std::vector<std::size_t> twin(points, std::size_t(-1));
  for(std::size_t i = 0; i < cut.copy.size(); ++i)
    if(cut.copy[i] != std::size_t(-1)) { twin[i] = cut.copy[i]; twin[cut.copy[i]] = i; }
  return twin;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CUT_CLOSED_H
