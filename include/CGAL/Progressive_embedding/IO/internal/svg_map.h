// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_MAP_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_MAP_H

// The map as a picture draws it: vertices and faces by index (in the order of vertices(tm) and
// faces(tm), as the indexed disk numbers them), each face classified as check_embedding() does,
// with its energy when the faces are colored by distortion. Drawing then needs no mesh.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/distortion.h>
#include <CGAL/Progressive_embedding/internal/check_passes.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace IO {
namespace internal {

struct Svg_map
{
  std::vector<std::array<double, 2> > p;            // uv, rounded to double
  std::vector<char> finite;                         // both coordinates finite, in the number type and in double
  std::vector<std::array<std::size_t, 3> > tri;     // the vertices of each face
  std::vector<std::array<std::size_t, 2> > border;  // border edges (source, target), in the order of halfedges(tm)
  std::vector<int> kind;                            // 1 correctly oriented, -1 flipped, 0 degenerate, 2 non-finite corner
  std::vector<double> energy;                       // symmetric Dirichlet against the 3D triangle
  double min_energy = std::numeric_limits<double>::infinity();
  std::size_t flipped = 0, degenerate = 0, non_finite_vertices = 0;

  std::size_t number_of_faces() const { return tri.size(); }
};

// Numbers the vertices (`vid`) and faces (`fid`) of `tm` and fills the geometry of `map`; `uv` gets the
// uv points in their number type. Every face is unclassified (non-finite) until a classification.
template <class TriangleMesh, class VertexUVMap, class VertexIndexMap, class FaceIndexMap, class Point_2>
Error_code svg_index_map(const TriangleMesh& tm, VertexUVMap uvm, VertexIndexMap vid, FaceIndexMap fid,
                         Svg_map& map, std::vector<Point_2>& uv)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  namespace PI = Progressive_embedding::internal;
  std::size_t nv = 0;
  for(auto vd : vertices(tm))
  {
    put(vid, vd, nv++);
    uv.push_back(get(uvm, vd));
    const double x = CGAL::to_double(uv.back().x()), y = CGAL::to_double(uv.back().y());
    map.p.push_back({{x, y}});
    map.finite.push_back(PI::is_finite_ft(uv.back().x()) && PI::is_finite_ft(uv.back().y()) && std::isfinite(x) && std::isfinite(y));
  }
  for(auto f : faces(tm))
  {
    put(fid, f, map.tri.size());
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
    {
      if(k == 3) return ERROR_NON_TRIANGULAR_MESH;
      t[k++] = get(vid, target(h, tm));
    }
    if(k != 3) return ERROR_NON_TRIANGULAR_MESH;
    map.tri.push_back(t);
  }
  const std::size_t nf = map.tri.size();
  if(nf == 0) return ERROR_EMPTY_MESH;
  for(halfedge_descriptor h : halfedges(tm))
    if(is_border(h, tm)) map.border.push_back({{ get(vid, source(h, tm)), get(vid, target(h, tm)) }});
  map.kind.assign(nf, 2);
  map.energy.assign(nf, std::numeric_limits<double>::infinity());
  return OK;
}

// Classifies the faces of a disk by the orientation pass of check_embedding() (relative to the
// border's orientation) and, with `with_energies`, computes their energies as its distortion pass
// does. `report` is the certificate the caller passes for this map: ERROR_WRONG_PARAMETER if its
// counts are not the map's (the legend would print another map's numbers), ERROR_DEGENERATE_3D_FACE
// if energies are asked for and the 3D triangles have no area.
template <class TriangleMesh, class VertexUVMap, class VertexPointMap, class Orientation_2>
Error_code svg_classify_disk(const Progressive_embedding::internal::Indexed_disk<TriangleMesh>& disk, VertexUVMap uvm,
                             VertexPointMap vpm, const Orientation_2& orientation, const Embedding_report& report,
                             bool with_energies, Svg_map& map)
{
  typedef typename boost::property_traits<VertexUVMap>::value_type Point_2;
  namespace PI = Progressive_embedding::internal;
  const std::size_t nf = map.number_of_faces();
  PI::Uv_samples<Point_2> samples;
  PI::sample_uv(disk, uvm, samples);
  PI::Face_orientations o;
  PI::orientation_pass(disk, samples, orientation, o);
  for(std::size_t f = 0; f < nf; ++f)
    map.kind[f] = !o.face_ok[f] ? 2 : o.fo[f] == CGAL::COLLINEAR ? 0 : o.fo[f] == o.border_sign ? 1 : -1;
  map.flipped = o.flipped;
  map.degenerate = o.degenerate;
  map.non_finite_vertices = samples.non_finite;
  if(report.status != OK || report.faces != nf || report.flipped != map.flipped || report.degenerate != map.degenerate
     || report.non_finite != map.non_finite_vertices)
    return ERROR_WRONG_PARAMETER;
  if(!with_energies) return OK;
  if(!report.has_3d_energy) return ERROR_DEGENERATE_3D_FACE;
  // the per-face values that check_embedding() aggregates
  PI::Face_areas areas;
  PI::area_pass(disk, samples, o, areas);
  const double sgn = (o.border_sign == CGAL::RIGHT_TURN) ? -1. : 1.;
  std::vector<double> rel_area(nf, 0.);
  for(std::size_t f = 0; f < nf; ++f)
    rel_area[f] = (o.face_ok[f] && o.fo[f] == o.border_sign) ? areas.scaled[f] : 0.;
  const std::vector<PI::Face_distortion> fds =
    PI::face_distortions(disk, vpm, samples.X, samples.Y, sgn, rel_area, areas.border_area_scaled);
  for(std::size_t f = 0; f < nf; ++f)
  {
    map.energy[f] = fds[f].symmetric_dirichlet;
    map.min_energy = (std::min)(map.min_energy, map.energy[f]);
  }
  return OK;
}

// Classifies the faces of a map that is not a disk (no border orientation to refer to): relative to
// the orientation of the majority of the faces.
template <class Point_2, class Orientation_2>
void svg_classify_by_majority(const std::vector<Point_2>& uv, const Orientation_2& orientation, Svg_map& map)
{
  const std::size_t nf = map.number_of_faces();
  std::size_t n_pos = 0, n_neg = 0;
  std::vector<int> sign(nf, 2);
  for(std::size_t i = 0; i < nf; ++i)
  {
    const std::array<std::size_t, 3>& t = map.tri[i];
    if(!map.finite[t[0]] || !map.finite[t[1]] || !map.finite[t[2]]) continue;
    const CGAL::Orientation ori = orientation(uv[t[0]], uv[t[1]], uv[t[2]]);
    sign[i] = (ori == CGAL::LEFT_TURN) ? 1 : (ori == CGAL::RIGHT_TURN ? -1 : 0);
    if(sign[i] > 0) ++n_pos; else if(sign[i] < 0) ++n_neg;
  }
  const int majority = (n_neg > n_pos) ? -1 : 1;
  for(std::size_t i = 0; i < nf; ++i)
  {
    map.kind[i] = sign[i] == 2 ? 2 : sign[i] == 0 ? 0 : sign[i] == majority ? 1 : -1;
    if(map.kind[i] == -1) ++map.flipped;
    if(map.kind[i] == 0) ++map.degenerate;
  }
  for(char f : map.finite) if(!f) ++map.non_finite_vertices;
}

} // namespace internal
} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_MAP_H
