// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_SVG_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_SVG_H

/// \file SVG.h
/// A picture of a uv layout and of its certificate: faces colored by their distortion against the
/// 3D triangles, flipped and degenerate faces highlighted, an inset zoomed on them, border, legend.

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/IO/SVG_options.h>
#include <CGAL/Progressive_embedding/IO/internal/atomic_output.h>
#include <CGAL/Progressive_embedding/IO/internal/svg_layers.h>
#include <CGAL/Progressive_embedding/IO/internal/svg_map.h>
#include <CGAL/Progressive_embedding/IO/internal/svg_patches.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <iostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace IO {

#ifndef DOXYGEN_RUNNING
namespace internal {

template <class VertexUVMap, class NamedParameters>
struct Svg_traits
{
  typedef typename boost::property_traits<VertexUVMap>::value_type                           Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel                                      K;
  typedef typename Progressive_embedding::internal::Get_pe_traits<K>::type                   Default_traits;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t,
                                                             NamedParameters, Default_traits>::type type;
};

// The certificate that the overloads of write_SVG() without one draw: check_embedding() with the
// picture's 3D points and traits, without the global overlap test, which the picture does not show.
template <class TriangleMesh, class VertexUVMap, class NamedParameters>
Embedding_report svg_certificate(const TriangleMesh& tm, VertexUVMap uvm, const NamedParameters& np)
{
  typedef typename Svg_traits<VertexUVMap, NamedParameters>::type Traits;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  return check_embedding(tm, uvm, Progressive_embedding::parameters::check_overlap(false,
                                    CGAL::parameters::vertex_point_map(vpm).geom_traits(traits)));
}

} // namespace internal
#endif // DOXYGEN_RUNNING

/// \ingroup PkgProgressiveEmbeddingIO
///
/// writes an SVG picture of the uv layout of `tm` and of its certificate `report`, fit into a
/// `options.size` pixel box with the v axis up, with the legend (and the inset) on its right. The
/// writer only draws: `report` is the caller's, e.g. the one it prints or tests, so that the picture
/// shows the same numbers and a map is certified once.
///
/// Faces are classified as `check_embedding()` does: exact orientations relative to the border's
/// (or, when the mesh is not a disk, relative to the majority of the faces). Flipped faces are
/// filled with `options.flipped_color`; degenerate (zero-area) faces are outlined with
/// `options.degenerate_color`; both are also marked by a circle in the main view, so that they
/// are visible on large meshes. Faces with a non-finite corner are not drawn. See `SVG_options`
/// for the distortion colors and the inset.
///
/// Every number printed is the certificate's, formatted by `format_number()` with
/// `options.significant_digits` digits: the counts of faces, flipped and degenerate faces and
/// non-finite vertices; with `color_by_distortion`, the legend's `median`, `mean` and `max` are
/// `Embedding_report::distortion.symmetric_dirichlet_quantiles[0]`, `Embedding_report::mean_energy_3d`
/// and `Embedding_report::max_energy_3d`, and `min` is the smallest of the per-face energies whose
/// mean and max these are (`inf` when a face is flipped). When the mesh is not a disk, `report` is
/// not used (`check_embedding()` certifies disks only, unless `multiply_connected` is set) and the counts
/// are those of the majority classification. The numbers are in `<text>` elements with
/// the ids `pe-count-faces`, `pe-count-flipped`, `pe-count-degenerate`, `pe-count-non-finite`,
/// `pe-energy-min`, `pe-energy-median`, `pe-energy-mean` and `pe-energy-max`; the inset is the group
/// `pe-inset`, its region in the main view the rectangle `pe-inset-region`.
///
/// Faces of one color are one SVG path and pixel coordinates have `options.coordinate_decimals`
/// decimals, so that the file stays small.
///
/// With the named parameter `face_patch_map`, the picture shows a partition of the faces into patches
/// (e.g. the patches of `constrained_embedding()`): unless `options.color_by_distortion` is set, the
/// correctly oriented faces of each patch are filled with one light color, two patches that share an
/// edge never with the same color (ten colors used evenly, so that up to ten patches all differ; more
/// colors only where the neighbors of a patch use all ten); the faces of each patch are one path of class `pe-patch` whose attribute `data-patch`
/// is the patch's value in the map. The edges between faces of different patches are drawn as lines
/// `options.patch_border_width` wide (the path of class `pe-patch-borders`), and the number of patches
/// is in the legend (`<text>` of id `pe-count-patches`). With the named parameter `constrained_vertices`,
/// each listed vertex is marked by a black point of radius `options.constrained_vertex_radius` ringed
/// in white (one `<circle>` of class `pe-constrained` each), and their number is in the legend (id
/// `pe-count-constrained`).
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam VertexUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type
/// \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
///
/// \param out the output stream
/// \param tm the mesh
/// \param uvm the uv coordinates of the vertices of `tm`
/// \param report the certificate of the map: `check_embedding(tm, uvm)` with the 3D points and traits of `np`
///        (its overlap test and `multiply_connected` do not matter)
/// \param options what to draw
/// \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points, for the distortion}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits providing the exact orientation predicate}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2` whose `Point_2` is the value type of `uvm`}
///     \cgalParamDefault{`Progressive_embedding_traits_2<K>`, where `K` is the kernel of the value type of `uvm`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_patch_map}
///     \cgalParamDescription{the patch of every face: faces filled by patch, lines between patches (see above); a face
///                           whose value is negative once converted to `long long` (e.g. `-1` or `std::size_t(-1)`)
///                           is in no patch and filled with `options.face_color`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
///                    as key type and an integral value type}
///     \cgalParamDefault{none: no patches}
///   \cgalParamNEnd
///   \cgalParamNBegin{constrained_vertices}
///     \cgalParamDescription{vertices marked by points (e.g. the constrained vertices of `constrained_embedding()`)}
///     \cgalParamType{a range of `boost::graph_traits<TriangleMesh>::%vertex_descriptor` (e.g. a `std::vector`)}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK`; nothing is written if the result is not `OK` or `ERROR_CANNOT_WRITE_FILE`:
///         `ERROR_WRONG_PARAMETER` if an option is out of range or if `tm` is a disk and `report` is not its
///         certificate (its status is not `OK`, or its counts of faces, flipped and degenerate faces or non-finite
///         vertices are not the map's), `ERROR_EMPTY_MESH` if `tm` has no face,
///         `ERROR_NON_TRIANGULAR_MESH` if a face is not a triangle; with `color_by_distortion`,
///         `ERROR_NOT_A_DISK` (or the reason why `tm` is not a disk) if the mesh is not a disk, and
///         `ERROR_DEGENERATE_3D_FACE` if the 3D triangles have no area (`report.has_3d_energy` is `false`);
///         `ERROR_CANNOT_WRITE_FILE` if the stream fails
///
/// \sa `check_embedding()`
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_SVG(std::ostream& out, const TriangleMesh& tm, VertexUVMap uvm, const Embedding_report& report,
                     const SVG_options& options = SVG_options(),
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename internal::Svg_traits<VertexUVMap, NamedParameters>::type Traits;
  typedef typename boost::property_traits<VertexUVMap>::value_type        Point_2;
  namespace PI = Progressive_embedding::internal;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  if(!internal::svg_options_are_valid(options)) return ERROR_WRONG_PARAMETER;

  try
  {
    const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
    auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));

    // the map by indices, its faces classified as check_embedding() does
    auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
    auto fid = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
    internal::Svg_map map;
    std::vector<Point_2> uv;
    Error_code status = internal::svg_index_map(tm, uvm, vid, fid, map, uv);
    if(status != OK) return status;
    PI::Indexed_disk<TriangleMesh> disk;
    const Error_code disk_status = PI::make_indexed_disk(tm, boost::graph_traits<TriangleMesh>::null_halfedge(), disk);
    if(disk_status == OK)
      status = internal::svg_classify_disk(disk, uvm, vpm, traits.exact_orientation_2_object(), report,
                                           options.color_by_distortion, map);
    else if(options.color_by_distortion)
      status = disk_status; // the energies are those of a disk
    else
      internal::svg_classify_by_majority(uv, traits.exact_orientation_2_object(), map);
    if(status != OK) return status;

    // what the named parameters add
    const internal::Svg_patches patches =
      internal::svg_patches(tm, vid, fid, get_parameter(np, Progressive_embedding::internal_np::face_patch_map));
    std::vector<std::size_t> marked;
    internal::svg_marked_vertices(vid, get_parameter(np, Progressive_embedding::internal_np::constrained_vertices), marked);

    out << internal::svg_picture(map, patches, marked, report, options);
    out.flush();
    return out ? OK : ERROR_CANNOT_WRITE_FILE;
  }
  catch(...)
  {
    return ERROR_CANNOT_WRITE_FILE;
  }
}

/// \ingroup PkgProgressiveEmbeddingIO
///
/// writes an SVG picture of the uv layout of `tm` and of its certificate `report` to the file
/// `filename`; see the stream overload for the picture and the parameters.
///
/// A failed write never leaves a partial file: when `filename` is a regular file or does not exist,
/// the picture is written to a temporary file in the same folder, which replaces `filename` only once
/// it is completely written and closed; on failure the temporary file is removed and an existing
/// `filename` is left untouched. A name of one of the process's file descriptors (`/dev/stdout`,
/// `/dev/fd/N`, `/proc/self/fd/N`, or a link to one) is written through that descriptor, where it
/// stands (a pipe, or a file a shell opened with `>` or `>>`); anything else that is not a regular
/// file (a device such as `/dev/null`, a named pipe) is written directly. No exception escapes.
///
/// \return as the stream overload; `ERROR_CANNOT_WRITE_FILE` if the file cannot be written (a folder,
///         no permission, no space left, a file size limit, ...)
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_SVG(const std::string& filename, const TriangleMesh& tm, VertexUVMap uvm, const Embedding_report& report,
                     const SVG_options& options = SVG_options(),
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  if(!internal::svg_options_are_valid(options)) return ERROR_WRONG_PARAMETER;
  return internal::write_file_atomically(filename, [&](std::ostream& out) { return write_SVG(out, tm, uvm, report, options, np); });
}

/// \ingroup PkgProgressiveEmbeddingIO
///
/// certifies the uv layout of `tm`, then draws it: writes the SVG picture of the overload with a
/// certificate, for the certificate `check_embedding(tm, uvm)` with the 3D points and traits of `np`
/// and without its overlap test, which the picture does not show. A caller that has the certificate
/// already passes it instead.
///
/// \return as the overload with a certificate
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_SVG(std::ostream& out, const TriangleMesh& tm, VertexUVMap uvm, const SVG_options& options,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  const Embedding_report report = internal::svg_certificate(tm, uvm, np);
  return write_SVG(out, tm, uvm, report, options, np);
}

/// \ingroup PkgProgressiveEmbeddingIO
///
/// certifies the uv layout of `tm`, then draws it to the file `filename`, as the stream overload
/// without a certificate does, never leaving a partial file (see the file overload with a certificate).
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_SVG(const std::string& filename, const TriangleMesh& tm, VertexUVMap uvm, const SVG_options& options,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  const Embedding_report report = internal::svg_certificate(tm, uvm, np);
  return write_SVG(filename, tm, uvm, report, options, np);
}

/// \ingroup PkgProgressiveEmbeddingIO
///
/// certifies the uv layout of `tm`, then draws it with default `SVG_options` and the title `title`:
/// faces in one color, flipped and degenerate faces highlighted, no inset.
/// See the overload with `SVG_options` and no certificate.
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_SVG(std::ostream& out, const TriangleMesh& tm, VertexUVMap uvm,
                     const std::string& title = std::string(),
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  SVG_options options;
  options.title = title;
  return write_SVG(out, tm, uvm, options, np);
}

/// \ingroup PkgProgressiveEmbeddingIO
///
/// certifies the uv layout of `tm`, then draws it with default `SVG_options` and the title `title`
/// to the file `filename`, never leaving a partial file (see the overload with `SVG_options` and no certificate).
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_SVG(const std::string& filename, const TriangleMesh& tm, VertexUVMap uvm,
                     const std::string& title = std::string(),
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  SVG_options options;
  options.title = title;
  return write_SVG(filename, tm, uvm, options, np);
}

} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_SVG_H
