// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PATCH_CHORDS_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PATCH_CHORDS_H

// Flat chords of a disk (or patch) whose border is a weakly convex polygon: interior edges
// whose two endpoints are border vertices on one straight side of the polygon (corners
// included). No valid map keeps such an edge: the part of the disk it cuts off is bounded by
// the edge and a piece of that side, a segment, so it has zero area. Conversely, when there is
// none, the Tutte map in exact arithmetic is one-to-one (Floater, "One-to-one piecewise linear
// mappings over triangulations", Math. Comp. 2003: no "dividing edge"), so a valid map exists.
// A face whose three vertices lie on one side has a flat chord among its edges (not all three
// are border edges, or the border would be that flat triangle), so the chords say it all.
// On a strictly convex border a side holds only its two corners, joined by a border edge:
// there is never a flat chord.
//
//  - flat_chords(disk, bpos, orient, chords): on an Indexed_disk whose border positions (in
//    border order) are classified convex; the chords as pairs of disk vertex indices.
//  - find_flat_chords(tm, patch_faces, uvm, out, np): on a face range of a mesh, the chords as
//    edge descriptors of the mesh; what the constrained pipeline splits before embed_patch().

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/border_polygon.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <array>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// The sides of a convex polygon `B` (no repeated consecutive points, at least one corner):
// corner[k] says if vertex k is a corner (exact orientation of its two neighbours not
// collinear); side[k] is the side that starts at the last corner at or before k, so a corner
// lies on sides side[k] and side[k] - 1 (mod the number of sides), any other vertex on side[k].
template <class Point_2, class ExactOrientation>
std::size_t polygon_sides(const std::vector<Point_2>& B, ExactOrientation orient,
                          std::vector<char>& corner, std::vector<std::size_t>& side)
{
  const std::size_t nb = B.size();
  corner.assign(nb, 0);
  side.assign(nb, 0);
  std::size_t first = nb, nsides = 0;
  for(std::size_t k = 0; k < nb; ++k)
  {
    corner[k] = orient(B[(k + nb - 1) % nb], B[k], B[(k + 1) % nb]) != CGAL::COLLINEAR;
    if(corner[k]) { ++nsides; if(first == nb) first = k; }
  }
  if(first == nb) return 0;
  std::size_t s = 0;
  for(std::size_t j = 0; j < nb; ++j)
  {
    const std::size_t k = (first + j) % nb;
    if(corner[k] && j > 0) ++s;
    side[k] = s;
  }
  return nsides;
}

// Whether border vertices a and b (border positions) lie on a common side.
inline bool on_common_side(std::size_t a, std::size_t b, const std::vector<char>& corner,
                           const std::vector<std::size_t>& side, std::size_t nsides)
{
  auto prev = [nsides](std::size_t s) { return (s + nsides - 1) % nsides; };
  const std::size_t sa = side[a], sb = side[b];
  if(sa == sb) return true;
  if(corner[a] && prev(sa) == sb) return true;
  return corner[b] && prev(sb) == sa;
}

// The flat chords of `disk` (pairs of vertex indices, smaller first, sorted) given the border
// positions `bpos` (in border order, classified convex by classify_convex_polygon()).
template <class TriangleMesh, class Point_2, class ExactOrientation>
void flat_chords(const Indexed_disk<TriangleMesh>& disk, const std::vector<Point_2>& bpos, ExactOrientation orient,
                 std::vector<std::pair<std::size_t, std::size_t> >& chords)
{
  chords.clear();
  const std::size_t nb = disk.border.size(), nv = disk.number_of_vertices();
  std::vector<char> corner;
  std::vector<std::size_t> side;
  const std::size_t nsides = polygon_sides(bpos, orient, corner, side);
  if(nsides == 0 || nsides == nb) return; // strictly convex: no flat chord
  std::vector<std::size_t> border_pos(nv, nb);
  for(std::size_t k = 0; k < nb; ++k) border_pos[disk.border[k]] = k;
  // edges between two border vertices, once per face side: an edge seen twice is interior
  // (a border edge has one face; a duplicated edge is seen more often, and is interior too)
  std::vector<std::pair<std::size_t, std::size_t> > E;
  for(const auto& t : disk.faces)
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t i = t[c], j = t[(c + 1) % 3];
      if(border_pos[i] == nb || border_pos[j] == nb) continue;
      E.push_back(std::make_pair((std::min)(i, j), (std::max)(i, j)));
    }
  std::sort(E.begin(), E.end());
  for(std::size_t a = 0; a < E.size(); )
  {
    std::size_t b = a;
    while(b < E.size() && E[b] == E[a]) ++b;
    if(b - a >= 2 && on_common_side(border_pos[E[a].first], border_pos[E[a].second], corner, side, nsides))
      chords.push_back(E[a]);
    a = b;
  }
}

// Reads the patch's border uv from `uvm` and classifies it: ERROR_NON_FINITE_COORDINATES,
// ERROR_DEGENERATE_BORDER, ERROR_NON_CONVEX_BORDER or OK (then `orientation` is +1 for a
// counterclockwise border, -1 for a clockwise one).
template <class TriangleMesh, class VertexUVMap, class Traits>
Error_code read_convex_border(const Indexed_disk<TriangleMesh>& disk, VertexUVMap uvm, const Traits& traits,
                              std::vector<typename Traits::Point_2>& bpos, int& orientation)
{
  const std::size_t nb = disk.border.size();
  orientation = 0;
  bpos.resize(nb);
  for(std::size_t k = 0; k < nb; ++k)
  {
    bpos[k] = get(uvm, disk.vertices[disk.border[k]]);
    if(!is_finite_ft(bpos[k].x()) || !is_finite_ft(bpos[k].y())) return ERROR_NON_FINITE_COORDINATES;
  }
  const Polygon_class pc = classify_convex_polygon(bpos, traits.exact_orientation_2_object(), orientation);
  if(pc == Polygon_class::DEGENERATE) return ERROR_DEGENERATE_BORDER;
  if(pc == Polygon_class::NON_CONVEX) return ERROR_NON_CONVEX_BORDER;
  return OK;
}

// Lists the flat chords of the patch `patch_faces` of `tm` whose border vertices have their
// uv in `uvm`: the interior edges of the patch (both incident faces in the patch) joining two
// patch border vertices that lie on one straight side of the patch's polygon. `embed_patch()`
// refuses such a patch with `ERROR_DEGENERATE_CHORD`; splitting each listed edge (e.g. with
// `CGAL::Euler::split_edge()` and a triangulation of the two faces) removes them, as the new
// vertex is interior.
//
// \param tm the mesh, not modified
// \param patch_faces a range of faces of `tm` forming a topological disk
// \param uvm read on the patch border vertices only
// \param out receives one `edge_descriptor` of `tm` per flat chord (none when OK and the patch has none)
// \param np `geom_traits` (the exact orientation predicate), as in `embed_patch()`
// \return `OK`, or the error that `embed_patch()` would return on the patch or its border before
//         looking for chords (`ERROR_EMPTY_MESH`, `ERROR_WRONG_PARAMETER`, `ERROR_NON_TRIANGULAR_MESH`,
//         `ERROR_NOT_A_DISK`, `ERROR_BORDER_TOO_SHORT`, `ERROR_NON_FINITE_COORDINATES`,
//         `ERROR_DEGENERATE_BORDER`, `ERROR_NON_CONVEX_BORDER`); nothing is written to `out` then
template <class TriangleMesh, class FaceRange, class VertexUVMap, class OutputIterator,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code find_flat_chords(const TriangleMesh& tm, const FaceRange& patch_faces, VertexUVMap uvm, OutputIterator out,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef boost::graph_traits<TriangleMesh>                                      GT;
  typedef typename Uv_map_types<VertexUVMap>::Traits                            Default_traits;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
            CGAL::internal_np::geom_traits_t, NamedParameters, Default_traits>::type Traits;
  const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));

  Indexed_disk<TriangleMesh> disk;
  Error_code ec = make_indexed_patch(tm, patch_faces, disk);
  if(ec != OK) return ec;
  if(disk.border.size() < 3) return ERROR_BORDER_TOO_SHORT;
  std::vector<typename Traits::Point_2> bpos;
  int orientation = 0;
  ec = read_convex_border(disk, uvm, traits, bpos, orientation);
  if(ec != OK) return ec;
  std::vector<std::pair<std::size_t, std::size_t> > chords;
  flat_chords(disk, bpos, traits.exact_orientation_2_object(), chords);
  if(chords.empty()) return OK;
  // the mesh edge of each chord: the one between its ends with patch faces on both sides
  std::unordered_set<typename GT::face_descriptor> F(patch_faces.begin(), patch_faces.end());
  auto in_patch = [&](typename GT::halfedge_descriptor h) { return !is_border(h, tm) && F.count(face(h, tm)) != 0; };
  for(const auto& c : chords)
    for(typename GT::halfedge_descriptor h : CGAL::halfedges_around_target(disk.vertices[c.first], tm))
      if(source(h, tm) == disk.vertices[c.second] && in_patch(h) && in_patch(opposite(h, tm)))
      {
        *out++ = edge(h, tm);
        break;
      }
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_PATCH_CHORDS_H
