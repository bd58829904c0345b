// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_PATCHES_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_PATCHES_H

// What the named parameters of write_SVG() add to a picture: the patches of `face_patch_map` (compact
// indices, the edges between patches, colors in which adjacent patches differ) and the vertices of
// `constrained_vertices`, by the indices of the picture's map.

#include <CGAL/Progressive_embedding/IO/internal/svg_colors.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace IO {
namespace internal {

struct Svg_patches
{
  bool present = false;                            // `face_patch_map` was given
  std::vector<std::size_t> of_face;                // the compact index of the patch of each face, -1: none
  std::vector<long long> ids;                      // the value in the map of each compact index
  std::vector<std::size_t> color;                  // the color class of each compact index (svg_patch_color())
  std::vector<std::array<std::size_t, 2> > edges;  // vertex indices of the edges between patches
};

// the patch of every face (face_patch_map), in the order of faces(tm); false without the parameter
template <class TriangleMesh>
bool svg_face_patches(const TriangleMesh&, CGAL::internal_np::Param_not_found, std::vector<long long>&) { return false; }

template <class TriangleMesh, class FacePatchMap>
bool svg_face_patches(const TriangleMesh& tm, const FacePatchMap& fpm, std::vector<long long>& patch)
{
  patch.clear();
  for(auto f : faces(tm)) patch.push_back(static_cast<long long>(get(fpm, f)));
  return true;
}

// The patches of `face_patch_map` (or CGAL::internal_np::Param_not_found: none), `vid` and `fid` the
// indices of the map's vertices and faces.
template <class TriangleMesh, class VertexIndexMap, class FaceIndexMap, class FacePatchMap>
Svg_patches svg_patches(const TriangleMesh& tm, VertexIndexMap vid, FaceIndexMap fid, const FacePatchMap& fpm)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  Svg_patches P;
  std::vector<long long> value;
  P.present = svg_face_patches(tm, fpm, value);
  if(!P.present) return P;
  const std::size_t nf = value.size();
  P.of_face.assign(nf, std::size_t(-1));
  std::map<long long, std::size_t> compact;
  for(std::size_t i = 0; i < nf; ++i)
    if(value[i] >= 0)
    {
      const auto it = compact.emplace(value[i], compact.size()).first;
      P.of_face[i] = it->second;
    }
  P.ids.resize(compact.size());
  for(const auto& c : compact) P.ids[c.second] = c.first;
  std::vector<std::vector<std::size_t> > adjacency(compact.size());
  for(auto e : edges(tm))
  {
    const halfedge_descriptor h = halfedge(e, tm), o = opposite(h, tm);
    if(is_border(h, tm) || is_border(o, tm)) continue;
    const std::size_t a = get(fid, face(h, tm)), b = get(fid, face(o, tm));
    if(value[a] == value[b] || (value[a] < 0 && value[b] < 0)) continue;
    P.edges.push_back({{ get(vid, source(h, tm)), get(vid, target(h, tm)) }});
    if(value[a] >= 0 && value[b] >= 0)
    {
      adjacency[P.of_face[a]].push_back(P.of_face[b]);
      adjacency[P.of_face[b]].push_back(P.of_face[a]);
    }
  }
  for(auto& l : adjacency) { std::sort(l.begin(), l.end()); l.erase(std::unique(l.begin(), l.end()), l.end()); }
  P.color = svg_color_patches(adjacency);
  return P;
}

// the vertices to mark (constrained_vertices); none without the parameter
template <class VertexIndexMap>
void svg_marked_vertices(const VertexIndexMap&, CGAL::internal_np::Param_not_found, std::vector<std::size_t>&) {}

template <class VertexIndexMap, class VertexRange>
void svg_marked_vertices(const VertexIndexMap& vid, const VertexRange& vertices, std::vector<std::size_t>& out)
{
  for(const auto& v : vertices) out.push_back(get(vid, v));
}

} // namespace internal
} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_PATCHES_H
