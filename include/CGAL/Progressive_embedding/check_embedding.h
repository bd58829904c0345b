// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_CHECK_EMBEDDING_H
#define CGAL_PROGRESSIVE_EMBEDDING_CHECK_EMBEDDING_H

/// \file check_embedding.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/distortion.h>
#include <CGAL/Progressive_embedding/Embedding_report.h>
#include <CGAL/Progressive_embedding/internal/check_embedding_impl.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <limits>
#include <string>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingMainFunctions
///
/// certifies a planar map of a triangulated topological disk with exact predicates, whatever
/// the number type of the uv coordinates and whatever their magnitude: every sign (face and border
/// orientations, border self-intersections, face overlaps) is decided by the traits' exact
/// orientation predicate and exact coordinate comparisons; the candidate pairs of the border and
/// overlap tests come from boxes that enclose the points at any magnitude (coordinates beyond
/// double range are scaled exactly by a power of two, then enclosed by intervals). The areas and
/// energies of the report are doubles: the areas in the map's units (so possibly infinite or zero
/// when the map lies beyond double range), the energies computed on the scaled coordinates (they
/// are scale invariant). The function never throws: a mesh that is not a disk is reported in
/// `Embedding_report::status`.
///
/// <b>Multiply connected domains</b> (with `multiply_connected(true)`): the mesh may be any connected genus-0
/// triangle mesh with k >= 1 border cycles (else `ERROR_NOT_GENUS_ZERO`, also for a closed mesh). The <em>outer</em>
/// cycle is the one whose uv polygon has the largest absolute area (exact; the first in the mesh's halfedge order
/// among equal ones), every other cycle is a hole. Faces are expected with the orientation of the outer cycle, and
/// holes with the opposite one: a layout whose outer cycle is clockwise is reported with
/// `Embedding_report::clockwise` and is valid if it is the mirror image of a valid one (faces and outer cycle
/// clockwise, holes counterclockwise). The map is certified valid iff every face has the orientation of the outer
/// cycle (exact), every cycle is simple (`border_intersections`), no two cycles touch (`loop_crossings`), every hole is
/// oriented opposite to the outer cycle (`misoriented_holes`) and lies inside it (`holes_outside`), and no two faces
/// overlap. When the first five hold, the image covers each point of the outer polygon outside the holes exactly
/// once and no point of a hole: the turning numbers of the cycles (1 for the outer one, -1 for each hole) sum to
/// 2 - k, so no interior vertex is branched, and the degree of the map at a point, the sum of the cycles' winding
/// numbers, is then 1 in the domain and 0 in the holes. The overlap test is then skipped
/// (`overlap_by_degree_argument`), as for a disk; otherwise it runs and counts the overlapping pairs exactly.
/// `border_cycles` gives k; `border_area` is the area of the domain (outer polygon minus the holes).
///
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param uvm the uv coordinates
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points, used for the distortion statistics}
///     \cgalParamType{a model of `ReadablePropertyMap` with `Point_3` values}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{check_overlap}
///     \cgalParamDescription{whether to run the global face-overlap test (box intersection and exact triangle tests)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_number}
///     \cgalParamDescription{the cap on the number of overlapping pairs and border intersections counted}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{1000}
///   \cgalParamNEnd
///   \cgalParamNBegin{invalid_energy_threshold}
///     \cgalParamDescription{faces whose equilateral-reference energy exceeds it are counted in `high_energy_faces`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1e20}
///   \cgalParamNEnd
///   \cgalParamNBegin{multiply_connected}
///     \cgalParamDescription{whether a connected genus-0 mesh with several border cycles is certified (see above)
///                           instead of being refused with `ERROR_NOT_A_DISK`}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits class whose exact orientation predicate decides every sign}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2` whose `Point_2` is the uv map's value type}
///     \cgalParamDefault{`Progressive_embedding_traits_2<K>`, `K` the kernel of the uv map's point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the report; the map is a valid embedding iff `Embedding_report::is_valid()`
template <typename TriangleMesh, typename VertexUVMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Embedding_report check_embedding(const TriangleMesh& tm, VertexUVMap uvm,
                                 const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  return internal::check_embedding_impl(tm, uvm, np);
}

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_CHECK_EMBEDDING_H
