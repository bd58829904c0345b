// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_INDEXED_DISK_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_INDEXED_DISK_H

// The compact structure every algorithm starts from: vertices numbered 0..n-1,
// faces as index triples, and the border cycle with the interior on its left.
// Building it also validates the input: empty, not triangulated, not manifold,
// not a disk -> specific Error_code. It is built from a whole mesh (make_indexed_disk) or from a
// range of faces of a mesh forming a disk, a patch (make_indexed_patch).

#include <CGAL/Progressive_embedding/Error_code.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>

#include <array>
#include <cstddef>
#include <iterator>
#include <unordered_map>
#include <algorithm>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

#ifdef CGAL_PROGRESSIVE_EMBEDDING_COUNT_INDEXING
// for the tests only: how many times a mesh was indexed (a pipeline indexes its mesh once and hands the
// indexed disk from stage to stage)
inline std::size_t& indexing_count() { static std::size_t n = 0; return n; }
#define CGAL_PROGRESSIVE_EMBEDDING_COUNT_ONE_INDEXING() (++::CGAL::Progressive_embedding::internal::indexing_count())
#else
#define CGAL_PROGRESSIVE_EMBEDDING_COUNT_ONE_INDEXING()
#endif

template <class TriangleMesh>
struct Indexed_disk
{
  typedef boost::graph_traits<TriangleMesh>                  GT;
  typedef typename GT::vertex_descriptor                     vertex_descriptor;
  typedef typename GT::halfedge_descriptor                   halfedge_descriptor;
  typedef typename GT::face_descriptor                       face_descriptor;

  std::vector<vertex_descriptor> vertices;           // index -> descriptor
  std::vector<std::array<std::size_t, 3> > faces;    // in the mesh's face orientation
  std::vector<std::size_t> border;                   // border cycle, mesh interior on the left
  std::vector<char> on_border;                       // per vertex

  std::size_t number_of_vertices() const { return vertices.size(); }
  std::size_t number_of_faces() const { return faces.size(); }
  std::size_t number_of_interior_vertices() const { return vertices.size() - border.size(); }
};

// Fills `disk` from `tm`. `bhd` may be a border halfedge or `null_halfedge()`
// (then the mesh's unique border cycle is used). `vertex_index` is any function
// vertex_descriptor -> index in [0, num_vertices); a dynamic map is used.
template <class TriangleMesh>
Error_code make_indexed_disk(const TriangleMesh& tm,
                             typename boost::graph_traits<TriangleMesh>::halfedge_descriptor bhd,
                             Indexed_disk<TriangleMesh>& disk)
{
  typedef boost::graph_traits<TriangleMesh>                  GT;
  typedef typename GT::vertex_descriptor                     vertex_descriptor;
  typedef typename GT::halfedge_descriptor                   halfedge_descriptor;
  typedef typename GT::face_descriptor                       face_descriptor;

  CGAL_PROGRESSIVE_EMBEDDING_COUNT_ONE_INDEXING();
  disk = Indexed_disk<TriangleMesh>();
  if(faces(tm).first == faces(tm).second)
    return ERROR_EMPTY_MESH;
  if(!CGAL::is_valid_polygon_mesh(tm))
    return ERROR_NON_MANIFOLD;
  if(!CGAL::is_triangle_mesh(tm))
    return ERROR_NON_TRIANGULAR_MESH;

  auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  const std::size_t none = std::size_t(-1);
  for(vertex_descriptor v : vertices(tm))
  {
    put(vid, v, disk.vertices.size());
    disk.vertices.push_back(v);
  }
  const std::size_t nv = disk.vertices.size();
  disk.on_border.assign(nv, 0);

  for(face_descriptor f : faces(tm))
  {
    halfedge_descriptor h = halfedge(f, tm);
    disk.faces.push_back({ get(vid, source(h, tm)), get(vid, target(h, tm)), get(vid, target(next(h, tm), tm)) });
  }

  // Border cycles; a vertex with two incoming border halfedges is a pinched (non-manifold) vertex.
  std::vector<char> border_seen(nv, 0);
  std::size_t n_border_cycles = 0, n_border_halfedges = 0;
  halfedge_descriptor first_border = GT::null_halfedge();
  for(halfedge_descriptor h : halfedges(tm))
  {
    if(!is_border(h, tm)) continue;
    ++n_border_halfedges;
    const std::size_t t = get(vid, target(h, tm));
    if(border_seen[t]) return ERROR_NON_MANIFOLD;
    border_seen[t] = 1;
    if(first_border == GT::null_halfedge()) first_border = h;
  }
  if(n_border_halfedges == 0)
    return ERROR_NOT_A_DISK; // closed
  {
    // count cycles
    std::vector<char> visited(nv, 0);
    for(halfedge_descriptor h : halfedges(tm))
    {
      if(!is_border(h, tm)) continue;
      const std::size_t t = get(vid, target(h, tm));
      if(visited[t]) continue;
      ++n_border_cycles;
      halfedge_descriptor c = h;
      std::size_t guard = 0;
      do { visited[get(vid, target(c, tm))] = 1; c = next(c, tm); } while(c != h && ++guard <= n_border_halfedges);
    }
  }
  if(n_border_cycles != 1)
    return ERROR_NOT_A_DISK;

  if(bhd == GT::null_halfedge())
    bhd = first_border;
  else if(!is_border(bhd, tm))
    return ERROR_WRONG_PARAMETER;

  // isolated vertices and connectivity. The vertices joined by the faces (union-find over the indexed faces, no
  // walk of the halfedge graph: a third of the indexing of a 1M-vertex disk went to a breadth-first search over
  // faces) are as connected as the faces through their edges: in a valid halfedge graph the halfedges around
  // each vertex form one cycle, which only a border halfedge breaks, and no vertex has two (checked above).
  for(vertex_descriptor v : vertices(tm))
    if(halfedge(v, tm) == GT::null_halfedge())
      return ERROR_NOT_A_DISK;
  {
    std::size_t nf = disk.faces.size();
    std::vector<std::size_t> parent(nv);
    for(std::size_t i = 0; i < nv; ++i) parent[i] = i;
    auto root = [&parent](std::size_t x) {
      while(parent[x] != x) { parent[x] = parent[parent[x]]; x = parent[x]; } // path halving
      return x;
    };
    std::size_t components = nv;
    for(const auto& t : disk.faces)
      for(int k = 1; k < 3; ++k)
      {
        const std::size_t a = root(t[0]), b = root(t[k]);
        if(a != b) { parent[(std::max)(a, b)] = (std::min)(a, b); --components; }
      }
    if(components != 1)
      return ERROR_NOT_A_DISK;
    // Euler characteristic of a disk is 1
    // counted by iteration: num_halfedges() of a Surface_mesh also counts removed (garbage) halfedges
    long nh = 0;
    for(auto h : halfedges(tm)) { (void)h; ++nh; }
    const long ne = nh / 2;
    if(static_cast<long>(nv) - ne + static_cast<long>(nf) != 1)
      return ERROR_NOT_A_DISK;
  }

  // border with the interior on the left: walk the border halfedges backwards
  std::vector<std::size_t> cyc;
  halfedge_descriptor c = bhd;
  do { cyc.push_back(get(vid, target(c, tm))); c = next(c, tm); } while(c != bhd);
  disk.border.assign(cyc.rbegin(), cyc.rend());
  for(std::size_t b : disk.border) disk.on_border[b] = 1;
  (void)none;
  return OK;
}

// Slots of a whole mesh for make_indexed_patch() called on many patches of it (the constrained
// pipeline): index + 1 of each face and vertex of the current patch, 0 elsewhere, cleared after each
// call. With Surface_mesh they are arrays: no hashing (measured: a third of the patch phase on maps
// with 0.4 M Steiner vertices).
template <class TriangleMesh>
struct Patch_slots
{
  typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<std::size_t> >::type face;
  typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::type vertex;
  explicit Patch_slots(TriangleMesh& tm)
    : face(get(CGAL::dynamic_face_property_t<std::size_t>(), tm)),
      vertex(get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm))
  {
    for(auto f : faces(tm)) put(face, f, std::size_t(0));
    for(auto v : vertices(tm)) put(vertex, v, std::size_t(0));
  }
};

// Fills `disk` from the faces `patch_faces` of `tm` (a face range; `tm` itself may be any
// valid FaceGraph: only the patch and the halfedges around its vertices are visited, so the
// cost is proportional to the patch, not to `tm`). The vertices are those of the patch faces,
// numbered in the order they are met; the border is the patch's border cycle with the patch
// on its left, which may run along border edges of `tm` as well as along its interior edges.
// ERROR_EMPTY_MESH (no face), ERROR_WRONG_PARAMETER (a null face, or a face given twice),
// ERROR_NON_TRIANGULAR_MESH, or ERROR_NOT_A_DISK when the patch is not a topological disk:
// not connected (through its interior edges), a vertex where the patch is pinched (met twice by
// the border), no border or several border cycles, or Euler characteristic not 1.
// `slots` (optional): the mesh's Patch_slots, instead of hash maps.
template <class TriangleMesh, class FaceRange>
Error_code make_indexed_patch(const TriangleMesh& tm, const FaceRange& patch_faces, Indexed_disk<TriangleMesh>& disk,
                              Patch_slots<TriangleMesh>* slots = nullptr)
{
  typedef boost::graph_traits<TriangleMesh>                  GT;
  typedef typename GT::vertex_descriptor                     vertex_descriptor;
  typedef typename GT::halfedge_descriptor                   halfedge_descriptor;
  typedef typename GT::face_descriptor                       face_descriptor;
  const std::size_t none = std::size_t(-1);

  disk = Indexed_disk<TriangleMesh>();
  // patch membership and vertex indices: in hash maps (proportional to the patch) or in the slots
  std::unordered_map<face_descriptor, std::size_t> fid;
  std::unordered_map<vertex_descriptor, std::size_t> vid;
  std::vector<face_descriptor> F;
  {
    const auto n = std::distance(std::begin(patch_faces), std::end(patch_faces));
    if(!slots)
    {
      fid.reserve(static_cast<std::size_t>(n));
      vid.reserve(static_cast<std::size_t>(n) / 2 + 16); // V ~ F/2 + border/2 in a triangulated disk
    }
    F.reserve(static_cast<std::size_t>(n));
  }
  // the slots are cleared on every return
  struct Clear_slots
  {
    Patch_slots<TriangleMesh>* s; const std::vector<face_descriptor>& F; const std::vector<vertex_descriptor>& V;
    ~Clear_slots()
    {
      if(!s) return;
      for(face_descriptor f : F) put(s->face, f, std::size_t(0));
      for(vertex_descriptor v : V) put(s->vertex, v, std::size_t(0));
    }
  } clear_slots{ slots, F, disk.vertices };
  auto insert_face = [&](face_descriptor f) -> bool
  {
    if(!slots) return fid.emplace(f, F.size()).second;
    if(get(slots->face, f) != 0) return false;
    put(slots->face, f, F.size() + 1);
    return true;
  };
  auto face_index = [&](face_descriptor f) -> std::size_t
  {
    if(!slots) { const auto it = fid.find(f); return it == fid.end() ? none : it->second; }
    return get(slots->face, f) - 1; // none when 0
  };
  auto insert_vertex = [&](vertex_descriptor v) -> std::size_t
  {
    if(!slots) { const auto ins = vid.emplace(v, disk.vertices.size()); if(ins.second) disk.vertices.push_back(v); return ins.first->second; }
    const std::size_t k = get(slots->vertex, v);
    if(k != 0) return k - 1;
    put(slots->vertex, v, disk.vertices.size() + 1);
    disk.vertices.push_back(v);
    return disk.vertices.size() - 1;
  };
  for(face_descriptor f : patch_faces)
  {
    if(f == GT::null_face()) return ERROR_WRONG_PARAMETER;
    if(!insert_face(f)) return ERROR_WRONG_PARAMETER;
    F.push_back(f);
  }
  if(F.empty()) return ERROR_EMPTY_MESH;
  auto in_patch = [&](halfedge_descriptor h) { return !is_border(h, tm) && face_index(face(h, tm)) != none; };
  // a halfedge of a patch face is on the patch border when the face across is not in the patch
  auto on_patch_border = [&](halfedge_descriptor h) { return !in_patch(opposite(h, tm)); };

  std::size_t n_border_halfedges = 0;
  halfedge_descriptor first_border = GT::null_halfedge();
  for(face_descriptor f : F)
  {
    const halfedge_descriptor h0 = halfedge(f, tm);
    if(next(next(next(h0, tm), tm), tm) != h0) return ERROR_NON_TRIANGULAR_MESH;
    std::array<std::size_t, 3> t;
    halfedge_descriptor h = h0;
    for(int c = 0; c < 3; ++c, h = next(h, tm))
    {
      t[c] = insert_vertex(source(h, tm));
      if(on_patch_border(h))
      {
        ++n_border_halfedges;
        if(first_border == GT::null_halfedge()) first_border = h;
      }
    }
    disk.faces.push_back(t);
  }
  const std::size_t nv = disk.vertices.size(), nf = F.size();
  disk.on_border.assign(nv, 0);
  if(n_border_halfedges == 0) return ERROR_NOT_A_DISK; // closed

  // connectivity: depth-first search over the patch faces through the patch's interior edges
  {
    std::vector<char> seen(nf, 0);
    std::vector<std::size_t> stack(1, 0);
    seen[0] = 1;
    std::size_t reached = 1;
    while(!stack.empty())
    {
      const face_descriptor f = F[stack.back()];
      stack.pop_back();
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      {
        const halfedge_descriptor o = opposite(h, tm);
        if(!in_patch(o)) continue;
        const std::size_t g = face_index(face(o, tm));
        if(!seen[g]) { seen[g] = 1; ++reached; stack.push_back(g); }
      }
    }
    if(reached != nf) return ERROR_NOT_A_DISK;
  }

  // The border cycle through the first border halfedge: the next border halfedge leaves the
  // target, found by turning around it through patch faces (at most one step per patch face).
  // Each vertex may be met once: a second visit is a pinched vertex.
  std::vector<char> met(nv, 0);
  halfedge_descriptor h = first_border;
  for(std::size_t k = 0; ; ++k)
  {
    if(k >= n_border_halfedges) return ERROR_NOT_A_DISK; // bounded: more steps than border halfedges
    const std::size_t s = insert_vertex(source(h, tm)); // met before: its index
    if(met[s]) return ERROR_NOT_A_DISK;
    met[s] = 1;
    disk.border.push_back(s);
    halfedge_descriptor g = next(h, tm);
    std::size_t turns = 0;
    while(!on_patch_border(g))
    {
      g = next(opposite(g, tm), tm);
      if(++turns > nf) return ERROR_NOT_A_DISK;
    }
    h = g;
    if(h == first_border) break;
  }
  // a second border cycle (or a pinch the walk did not meet) leaves border halfedges unvisited
  if(disk.border.size() != n_border_halfedges) return ERROR_NOT_A_DISK;
  for(std::size_t b : disk.border) disk.on_border[b] = 1;
  // Euler characteristic of a disk is 1; each interior edge has two patch halfedges
  const std::size_t twice_edges = 3 * nf + n_border_halfedges;
  if(twice_edges % 2 != 0) return ERROR_NOT_A_DISK;
  if(static_cast<long>(nv) - static_cast<long>(twice_edges / 2) + static_cast<long>(nf) != 1)
    return ERROR_NOT_A_DISK;
  return OK;
}

// Rotates `disk.border` (indexed from `tm` with a chosen border halfedge) to start where
// make_indexed_disk(tm, null_halfedge()) starts it: a pipeline indexes its mesh once, with the border
// halfedge its first stage was given, and its later stages see the border as when they index it themselves.
template <class TriangleMesh>
void start_border_as_default(const TriangleMesh& tm, Indexed_disk<TriangleMesh>& disk)
{
  for(auto h : halfedges(tm))
  {
    if(!is_border(h, tm)) continue;
    const auto v = target(h, tm); // the last vertex of the default border
    for(std::size_t k = 0; k < disk.border.size(); ++k)
      if(disk.vertices[disk.border[k]] == v)
      {
        std::rotate(disk.border.begin(), disk.border.begin() + static_cast<std::ptrdiff_t>(k) + 1, disk.border.end());
        return;
      }
    return;
  }
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
