// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_DISTORTION_H
#define CGAL_PROGRESSIVE_EMBEDDING_DISTORTION_H

/// \file distortion.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/Distortion_report.h>
#include <CGAL/Progressive_embedding/internal/distortion_measures.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// measures the distortion of the uv map `uvm` of the disk `tm` against its 3D triangles (see
/// `Distortion_report`). The values are the ones `check_embedding()` reports (the same passes:
/// exact orientations, then the measures on the coordinates scaled by a power of two, so that
/// they do not depend on the magnitude of the coordinates).
///
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexUVMap a model of `ReadablePropertyMap` with `Point_2` values
/// \tparam NamedParameters a sequence of named parameters
/// \param tm the mesh \param uvm the uv map
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points}
///     \cgalParamType{a model of `ReadablePropertyMap` with `Point_3` values}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits class whose exact orientation predicate decides the face and border orientations}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2` whose `Point_2` is the uv map's value type}
///     \cgalParamDefault{`Progressive_embedding_traits_2<K>`, `K` the kernel of the uv map's point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Distortion_report measure_distortion(const TriangleMesh& tm, VertexUVMap uvm,
                                     const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename internal::Check_traits<VertexUVMap, CGAL_NP_CLASS>::type Traits;
  typedef typename internal::Uv_map_types<VertexUVMap>::Point_2             Point_2;
  const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));

  Distortion_report r;
  internal::Indexed_disk<TriangleMesh> disk;
  r.status = internal::make_indexed_disk(tm, boost::graph_traits<TriangleMesh>::null_halfedge(), disk);
  if(r.status != OK) return r;
  internal::Uv_samples<Point_2> samples;
  internal::sample_uv(disk, uvm, samples);
  internal::Face_orientations orientations;
  internal::orientation_pass(disk, samples, traits.exact_orientation_2_object(), orientations);
  internal::Face_areas areas;
  internal::area_pass(disk, samples, orientations, areas);
  bool has_3d = false;
  r = internal::distortion_pass(disk, vpm, samples, orientations, areas, has_3d);
  r.status = OK;
  return r;
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_DISTORTION_H
