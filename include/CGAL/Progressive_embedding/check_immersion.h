// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_CHECK_IMMERSION_H
#define CGAL_PROGRESSIVE_EMBEDDING_CHECK_IMMERSION_H

/// \file check_immersion.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/distortion.h>
#include <CGAL/Progressive_embedding/Immersion_report.h>
#include <CGAL/Progressive_embedding/internal/check_immersion_impl.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <iterator>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// certifies exactly that the uv map `uvm` of the disk `tm` is an immersion (a locally injective map): every face
/// strictly oriented like the map (counterclockwise, or every face clockwise for a mirror image), and the one-ring
/// of every interior vertex winding exactly once around it, and the fan of every border vertex turning by the
/// border polygon's angle there plus 2 pi times the vertex's rotation index. The winding is counted exactly: with
/// every incident face correctly oriented, each face turns the direction from the vertex by an angle in (0, pi),
/// and the number of turns is the number of faces whose turn passes the direction (1, 0) (coordinate comparisons
/// and the exact orientation predicate only: exact in every number type, at every scale). Never throws on data.
///
/// <b>Border angles.</b> The border polygon's angle at a border vertex, in (0, 2 pi], is the angle from the
/// direction of the next border vertex to that of the previous one, in the map's orientation (pi at a flat vertex,
/// 2 pi where the border turns back on itself). The uv positions give it only modulo 2 pi, while the fan of
/// faces may wrap around the vertex several times (a border that winds around its vertex, as at a cone of a
/// seamless map cut open): `vertex_rotation_index_map` says how many full turns each border vertex adds, and
/// without it every fan must turn by the border's angle alone. The full turns found are in
/// `Immersion_report::max_border_turns`; `border_rotation_indices()` reads them from a map taken as the reference.
///
/// Overlaps between faces far apart are allowed (a map onto a weakly self-overlapping border has them): use
/// `check_embedding()` for a one-to-one map.
///
/// \tparam TriangleMesh a model of `FaceListGraph` (triangles)
/// \tparam VertexUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type
/// \tparam PointRange a range of the uv map's `Point_2` (only for the second overload)
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh, a triangulated topological disk
/// \param uvm the uv map
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits class whose exact orientation predicate decides every sign}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2` whose `Point_2` is the uv map's value type}
///     \cgalParamDefault{`Progressive_embedding_traits_2<K>`, `K` the kernel of the uv map's point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_rotation_index_map}
///     \cgalParamDescription{the rotation index of every border vertex: the full turns its fan adds to the border's
///                           angle there (a negative value, or one above a million, never matches)}
///     \cgalParamType{a model of `ReadablePropertyMap` with the vertex descriptor as key type and an integral value
///                    type}
///     \cgalParamDefault{all 0: every border fan turns by the border's angle alone}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the report; the map is an immersion iff `Immersion_report::is_immersion()`
template <typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Immersion_report check_immersion(const TriangleMesh& tm, VertexUVMap uvm,
                                 const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  return internal::check_immersion_impl(tm, uvm, np);
}

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// certifies that the uv map `uvm` of the disk `tm` is an immersion (as the first overload) whose border is
/// bit-exactly the polygon `border`: the border vertex `start` at `border[0]`, and the next ones along the border
/// (mesh interior on the left) at the next points. A polygon whose size is not the number of border vertices, or a
/// `start` that is not a border vertex, gives `ERROR_WRONG_PARAMETER` in the report's status.
///
/// \param tm the mesh, a triangulated topological disk
/// \param uvm the uv map
/// \param start a border vertex of `tm`
/// \param border the expected uv of the border vertices, from `start` on
/// \param np the named parameters of the first overload (`geom_traits`, `vertex_rotation_index_map`)
template <typename TriangleMesh, typename VertexUVMap, typename PointRange, typename CGAL_NP_TEMPLATE_PARAMETERS>
Immersion_report check_immersion(const TriangleMesh& tm, VertexUVMap uvm,
                                 typename boost::graph_traits<TriangleMesh>::vertex_descriptor start,
                                 const PointRange& border,
                                 const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  return internal::check_immersion_impl(tm, uvm, start, border, np);
}

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// reads, from a map `uvm` of the disk `tm`, how many full turns its border makes around each border vertex beyond
/// its angle in (0, 2 pi]: the rotation index that `constrained_embedding()` takes as `vertex_rotation_index_map` to
/// map onto the same border, and that `check_immersion()` takes to certify such a map. The turns are counted
/// exactly, as `check_immersion()` counts them (coordinate comparisons and the exact orientation predicate, at
/// every scale): the number of times the fan of the vertex passes a fixed direction, minus the times the border's
/// angle alone passes it. A border vertex with a face that is not strictly oriented like the map (or a non-finite
/// point) gets 0, and so does every border vertex when `tm` is not a triangulated disk. Vertices that are not on the
/// border are not written.
///
/// \tparam TriangleMesh a model of `FaceListGraph` (triangles)
/// \tparam VertexUVMap a readable vertex property map whose values are points of a CGAL kernel
/// \tparam VertexIndexMap a writable vertex property map with `int` values
/// \return the sum of the indices written
template <class TriangleMesh, class VertexUVMap, class VertexIndexMap>
int border_rotation_indices(const TriangleMesh& tm, VertexUVMap uvm, VertexIndexMap rotation_index_map)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename internal::Check_traits<VertexUVMap, CGAL::parameters::Default_named_parameters>::type Traits;
  for(halfedge_descriptor h : halfedges(tm))
    if(CGAL::is_border(h, tm)) put(rotation_index_map, target(h, tm), 0);
  internal::Indexed_disk<TriangleMesh> disk;
  if(internal::make_indexed_disk(tm, boost::graph_traits<TriangleMesh>::null_halfedge(), disk) != OK) return 0;
  std::vector<int> measured;
  internal::check_immersion_of_disk(disk, uvm, Traits().exact_orientation_2_object(), std::vector<int>(), &measured);
  int total = 0;
  for(std::size_t k = 0; k < disk.border.size(); ++k)
  {
    const int r = measured[k] > 0 ? measured[k] : 0;
    put(rotation_index_map, disk.vertices[disk.border[k]], r);
    total += r;
  }
  return total;
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_CHECK_IMMERSION_H
