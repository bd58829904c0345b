// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_SVG_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_SVG_H

/// \file SVG.h
/// A picture of a uv layout: faces colored by their distortion against the 3D triangles, flipped
/// and degenerate faces highlighted, an inset zoomed on them, border, legend.

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/distortion.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/internal/check_passes.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/IO/internal/atomic_output.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace IO {

/// \ingroup PkgProgressiveEmbeddingIO
///
/// What `write_SVG()` draws. Every member has a default; `write_SVG()` returns
/// `ERROR_WRONG_PARAMETER` (and writes nothing) if a value is out of its documented range.
struct SVG_options
{
  /// a title drawn above the picture (escaped for XML; invalid UTF-8 bytes become '?')
  std::string title;
  /// if `true`, each face is filled with a color giving its symmetric Dirichlet energy against its
  /// 3D triangle (the per-face value whose mean and max `check_embedding()` reports as
  /// `Embedding_report::mean_energy_3d` and `Embedding_report::max_energy_3d`), on a logarithmic
  /// scale from the isometry value 4 to the largest finite energy, with a legend giving the
  /// minimum, median, mean and maximum; requires a disk with 3D points. If `false`, faces are
  /// filled with `face_color`.
  bool color_by_distortion = false;
  /// if `true` and the map has flipped or degenerate faces, a framed inset, beside the legend, shows
  /// the bounding box of those faces zoomed to the inset's size (whatever its size: a failure
  /// region a million times smaller than the map is shown as well), and a rectangle marks that
  /// region in the main view; nothing is added when there are no such faces
  bool inset = false;
  /// the size in pixels of the longer side of the main view; in [100, 100000]
  double size = 1000;
  /// the width in pixels of the face edges (0: no edges); in [0, 100]
  double edge_width = 0.3;
  /// the width in pixels of the border; in [0, 100]
  double border_width = 2;
  /// the fill color of flipped faces, `#rgb` or `#rrggbb`
  std::string flipped_color = "#e4002b";
  /// the color of the outline of degenerate (zero-area) faces, `#rgb` or `#rrggbb`
  std::string degenerate_color = "#ff00ff";
  /// the fill color of the other faces when `color_by_distortion` is `false`, `#rgb` or `#rrggbb`
  std::string face_color = "#dce6f0";
  /// the number of significant digits of the numbers printed (see `format_number()`); in [1, 17]
  int significant_digits = 3;
  /// the number of decimals of the pixel coordinates; in [0, 6]
  int coordinate_decimals = 1;
  /// the size in pixels of the inset; in [100, 100000]
  double inset_size = 360;
  /// the number of distinct colors of the distortion scale (faces of one color are one SVG path); in [2, 1024]
  int color_levels = 64;
  /// the width in pixels of the lines between patches (drawn with the `face_patch_map` named parameter of
  /// `write_SVG()`); in [0, 100]
  double patch_border_width = 1.5;
  /// the radius in pixels of the points that mark the vertices of the `constrained_vertices` named parameter of
  /// `write_SVG()`; in [0, 100] (0: not drawn)
  double constrained_vertex_radius = 4;
};

/// \ingroup PkgProgressiveEmbeddingIO
///
/// formats `x` as `std::printf("%.*g", significant_digits, x)` does in the "C" locale (e.g.
/// `12.3`, `1.1e+15`, `4` for 3 digits), independently of the global locale; non-finite values
/// give `inf`, `-inf` and `nan`, and a negative zero gives `0`. This is the format of every number that `write_SVG()` prints,
/// so that a program printing a measure with it prints the same text as the picture.
/// `significant_digits` is clamped to [1, 17].
inline std::string format_number(double x, int significant_digits = 3)
{
  if(std::isnan(x)) return "nan";
  if(std::isinf(x)) return x > 0 ? "inf" : "-inf";
  significant_digits = (std::max)(1, (std::min)(17, significant_digits));
  if(x == 0) x = 0; // no "-0"
  char buf[64];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), x, std::chars_format::general, significant_digits);
  return std::string(buf, r.ptr);
}

#ifndef DOXYGEN_RUNNING
namespace internal {

// fixed-point formatting, independent of the C and C++ locales
inline void svg_append(std::string& s, double x, int decimals = 2)
{
  char buf[64];
  if(!std::isfinite(x)) x = 0;
  if(std::abs(x) < 0.5 * std::pow(10.0, -decimals)) x = 0; // no "-0.0"
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), x, std::chars_format::fixed, decimals);
  s.append(buf, r.ptr);
}

inline std::string svg_number(double x, int decimals = 2)
{
  std::string s;
  svg_append(s, x, decimals);
  return s;
}

// Escapes text for XML character data and attribute values. Characters that XML 1.0
// forbids (most control characters) and invalid UTF-8 bytes become '?'.
inline std::string svg_escape(const std::string& in)
{
  std::string s;
  const std::size_t n = in.size();
  for(std::size_t i = 0; i < n; )
  {
    const unsigned char c = static_cast<unsigned char>(in[i]);
    if(c < 0x80)
    {
      switch(c)
      {
        case '&': s += "&amp;"; break;
        case '<': s += "&lt;"; break;
        case '>': s += "&gt;"; break;
        case '"': s += "&quot;"; break;
        case '\'': s += "&apos;"; break;
        default:
          s += (c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f ? '?' : char(c);
      }
      ++i;
      continue;
    }
    // multi-byte UTF-8 sequence: validate it (no overlong forms, surrogates, or code points above U+10FFFF)
    std::size_t len = 0;
    unsigned cp = 0;
    if(c >= 0xC2 && c <= 0xDF) { len = 2; cp = c & 0x1F; }
    else if(c >= 0xE0 && c <= 0xEF) { len = 3; cp = c & 0x0F; }
    else if(c >= 0xF0 && c <= 0xF4) { len = 4; cp = c & 0x07; }
    bool ok = (len != 0 && i + len <= n);
    for(std::size_t k = 1; ok && k < len; ++k)
    {
      const unsigned char d = static_cast<unsigned char>(in[i + k]);
      if((d & 0xC0) != 0x80) ok = false;
      else cp = (cp << 6) | (d & 0x3F);
    }
    if(ok)
    {
      if((len == 3 && (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF) || cp == 0xFFFE || cp == 0xFFFF))
         || (len == 4 && (cp < 0x10000 || cp > 0x10FFFF)))
        ok = false;
    }
    if(ok) { s.append(in, i, len); i += len; }
    else   { s += '?'; ++i; }
  }
  return s;
}

inline bool svg_is_color(const std::string& c)
{
  if(c.size() != 4 && c.size() != 7) return false;
  if(c[0] != '#') return false;
  for(std::size_t i = 1; i < c.size(); ++i)
    if(!((c[i] >= '0' && c[i] <= '9') || (c[i] >= 'a' && c[i] <= 'f') || (c[i] >= 'A' && c[i] <= 'F'))) return false;
  return true;
}

inline bool svg_options_are_valid(const SVG_options& o)
{
  auto in = [](double x, double lo, double hi) { return std::isfinite(x) && x >= lo && x <= hi; };
  return in(o.size, 100, 100000) && in(o.edge_width, 0, 100) && in(o.border_width, 0, 100)
      && in(o.inset_size, 100, 100000) && o.significant_digits >= 1 && o.significant_digits <= 17
      && o.coordinate_decimals >= 0 && o.coordinate_decimals <= 6 && o.color_levels >= 2 && o.color_levels <= 1024
      && svg_is_color(o.flipped_color) && svg_is_color(o.degenerate_color) && svg_is_color(o.face_color)
      && in(o.patch_border_width, 0, 100) && in(o.constrained_vertex_radius, 0, 100);
}

// Sequential color scale (YlGnBu): light for low energies, dark blue for high ones; red, the
// color of flipped faces, is not on it.
struct Svg_color_map
{
  static const std::array<std::array<int, 3>, 5>& stops()
  {
    static const std::array<std::array<int, 3>, 5> s = {{
      {{0xff, 0xff, 0xd9}}, {{0xc7, 0xe9, 0xb4}}, {{0x41, 0xb6, 0xc4}}, {{0x22, 0x5e, 0xa8}}, {{0x08, 0x1d, 0x58}} }};
    return s;
  }

  static std::string hex(const std::array<int, 3>& c)
  {
    static const char* digits = "0123456789abcdef";
    std::string s = "#";
    for(int k = 0; k < 3; ++k) { s += digits[(c[k] >> 4) & 15]; s += digits[c[k] & 15]; }
    return s;
  }

  // the color at t in [0, 1]
  static std::string color(double t)
  {
    if(!(t >= 0)) t = 0;
    if(t > 1) t = 1;
    const int n = int(stops().size());
    const double x = t * (n - 1);
    int i = int(std::floor(x));
    if(i >= n - 1) i = n - 2;
    const double a = x - i;
    std::array<int, 3> c;
    for(int k = 0; k < 3; ++k)
      c[k] = int(std::lround((1 - a) * stops()[std::size_t(i)][std::size_t(k)] + a * stops()[std::size_t(i) + 1][std::size_t(k)]));
    return hex(c);
  }
};

// the number of light qualitative colors of svg_patch_color()
constexpr std::size_t svg_patch_palette_size = 10;

// The fill color of the patch color class `k`: light qualitative colors (none red, the color of
// flipped faces), then, past them, hues spaced by the golden angle.
inline std::string svg_patch_color(std::size_t k)
{
  static const char* palette[svg_patch_palette_size] = { "#8dd3c7", "#ffffb3", "#bebada", "#80b1d3", "#fdb462",
                                                         "#b3de69", "#fccde5", "#d9d9d9", "#bc80bd", "#ccebc5" };
  const std::size_t n = svg_patch_palette_size;
  if(k < n) return palette[k];
  const double h = std::fmod(double(k - n) * 137.508, 360.) / 60., s = 0.55, l = 0.75;
  const double c = (1 - std::abs(2 * l - 1)) * s, x = c * (1 - std::abs(std::fmod(h, 2.) - 1)), m = l - c / 2;
  double r = 0, g = 0, b = 0;
  switch(int(h))
  {
    case 0: r = c; g = x; break;
    case 1: r = x; g = c; break;
    case 2: g = c; b = x; break;
    case 3: g = x; b = c; break;
    case 4: r = x; b = c; break;
    default: r = c; b = x; break;
  }
  const std::array<int, 3> rgb = {{ int(std::lround((r + m) * 255)), int(std::lround((g + m) * 255)), int(std::lround((b + m) * 255)) }};
  return Svg_color_map::hex(rgb);
}

// Colors of the patches 0..P-1 such that two adjacent patches differ: greedy coloring in the reverse
// of a smallest-last order, each patch taking, among the colors its colored neighbors do not use, the
// palette color used least so far (so that up to a palette of patches all differ), and a color past
// the palette only when its neighbors use all of the palette.
inline std::vector<std::size_t> svg_color_patches(const std::vector<std::vector<std::size_t> >& adjacency)
{
  const std::size_t P = adjacency.size();
  std::vector<std::size_t> degree(P), order, color(P, 0);
  std::vector<char> removed(P, 0), colored(P, 0);
  std::set<std::pair<std::size_t, std::size_t> > queue;
  for(std::size_t i = 0; i < P; ++i) { degree[i] = adjacency[i].size(); queue.emplace(degree[i], i); }
  while(!queue.empty()) // each patch leaves the queue once
  {
    const std::size_t i = queue.begin()->second;
    queue.erase(queue.begin());
    removed[i] = 1;
    order.push_back(i);
    for(std::size_t j : adjacency[i])
      if(!removed[j]) { queue.erase(std::make_pair(degree[j], j)); queue.emplace(--degree[j], j); }
  }
  std::vector<char> used;
  std::vector<std::size_t> uses(svg_patch_palette_size, 0);
  for(std::size_t k = P; k-- > 0; )
  {
    const std::size_t i = order[k];
    used.assign((std::max)(svg_patch_palette_size, adjacency[i].size() + 1), 0);
    for(std::size_t j : adjacency[i])
      if(colored[j] && color[j] < used.size()) used[color[j]] = 1;
    std::size_t c = used.size();
    for(std::size_t q = 0; q < svg_patch_palette_size; ++q)
      if(!used[q] && (c == used.size() || uses[q] < uses[c])) c = q;
    if(c == used.size())
    {
      c = svg_patch_palette_size;
      while(used[c]) ++c; // a free color among the first degree + 1
    }
    else ++uses[c];
    color[i] = c;
    colored[i] = 1;
  }
  return color;
}

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

// the vertices to mark (constrained_vertices); none without the parameter
template <class VertexIndexMap>
void svg_marked_vertices(const VertexIndexMap&, CGAL::internal_np::Param_not_found, std::vector<std::size_t>&) {}

template <class VertexIndexMap, class VertexRange>
void svg_marked_vertices(const VertexIndexMap& vid, const VertexRange& vertices, std::vector<std::size_t>& out)
{
  for(const auto& v : vertices) out.push_back(get(vid, v));
}

// Logarithmic energy scale from `lo` (at most 4, the isometry) to `hi`.
struct Svg_energy_scale
{
  double lo = 4, hi = 40;
  double position(double e) const
  {
    if(std::isnan(e) || e >= hi) return 1.;
    if(!(e > lo)) return 0.;
    return std::log(e / lo) / std::log(hi / lo);
  }
};

// Sutherland-Hodgman clipping of a polygon to the box [x0, x1] x [y0, y1].
inline void svg_clip(std::vector<std::array<double, 2> >& poly, double x0, double y0, double x1, double y1)
{
  std::vector<std::array<double, 2> > out;
  for(int side = 0; side < 4 && !poly.empty(); ++side)
  {
    auto inside = [&](const std::array<double, 2>& p) {
      switch(side) { case 0: return p[0] >= x0; case 1: return p[0] <= x1; case 2: return p[1] >= y0; default: return p[1] <= y1; }
    };
    auto cut = [&](const std::array<double, 2>& p, const std::array<double, 2>& q) {
      const int axis = side < 2 ? 0 : 1;
      const double v = side == 0 ? x0 : side == 1 ? x1 : side == 2 ? y0 : y1;
      const double t = (v - p[std::size_t(axis)]) / (q[std::size_t(axis)] - p[std::size_t(axis)]);
      std::array<double, 2> r = {{ p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]) }};
      r[std::size_t(axis)] = v;
      return r;
    };
    out.clear();
    for(std::size_t i = 0; i < poly.size(); ++i)
    {
      const std::array<double, 2>& p = poly[i];
      const std::array<double, 2>& q = poly[(i + 1) % poly.size()];
      const bool ip = inside(p), iq = inside(q);
      if(ip) out.push_back(p);
      if(ip != iq) out.push_back(cut(p, q));
    }
    poly.swap(out);
  }
}

// A view: uv coordinates to pixels, v axis up.
struct Svg_view
{
  double xmin = 0, ymax = 0, scale = 1, ox = 0, oy = 0;
  double X(double x) const { return ox + (x - xmin) * scale; }
  double Y(double y) const { return oy + (ymax - y) * scale; }
};

// The classification of the faces and their energies, as check_embedding() computes them.
struct Svg_faces
{
  std::vector<std::array<std::size_t, 3> > tri;  // vertex indices, in the order of faces(tm)
  std::vector<int> kind;                         // 1 correctly oriented, -1 flipped, 0 degenerate, 2 non-finite corner
  std::vector<double> energy;                    // symmetric Dirichlet against the 3D triangle
  std::size_t flipped = 0, degenerate = 0, non_finite_vertices = 0;
};

} // namespace internal
#endif // DOXYGEN_RUNNING

/// \ingroup PkgProgressiveEmbeddingIO
///
/// writes an SVG picture of the uv layout of `tm`, fit into a `options.size` pixel box with the
/// v axis up, with the legend (and the inset) on its right.
///
/// Faces are classified as `check_embedding()` does: exact orientations relative to the border's
/// (or, when the mesh is not a disk, relative to the majority of the faces). Flipped faces are
/// filled with `options.flipped_color`; degenerate (zero-area) faces are outlined with
/// `options.degenerate_color`; both are also marked by a circle in the main view, so that they
/// are visible on large meshes. Faces with a non-finite corner are not drawn. See `SVG_options`
/// for the distortion colors and the inset.
///
/// Every number printed equals what `check_embedding()` reports, formatted by `format_number()`
/// with `options.significant_digits` digits: the counts of faces, flipped and degenerate faces and
/// non-finite vertices; with `color_by_distortion`, the legend's `median`, `mean` and `max` are
/// `Embedding_report::distortion.symmetric_dirichlet_quantiles[0]`, `Embedding_report::mean_energy_3d`
/// and `Embedding_report::max_energy_3d`, and `min` is the smallest of the per-face energies whose
/// mean and max these are (`inf` when a face is flipped). The numbers are in `<text>` elements with
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
///         `ERROR_WRONG_PARAMETER` if an option is out of range, `ERROR_EMPTY_MESH` if `tm` has no face,
///         `ERROR_NON_TRIANGULAR_MESH` if a face is not a triangle; with `color_by_distortion`, the
///         status of `check_embedding()` if the mesh is not a disk (e.g. `ERROR_NOT_A_DISK`), and
///         `ERROR_DEGENERATE_3D_FACE` if the 3D triangles have no area; `ERROR_CANNOT_WRITE_FILE` if
///         the stream fails
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_SVG(std::ostream& out, const TriangleMesh& tm, VertexUVMap uvm, const SVG_options& options,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh>                              GT;
  typedef typename GT::vertex_descriptor                                 vertex_descriptor;
  typedef typename GT::halfedge_descriptor                               halfedge_descriptor;
  typedef typename GT::face_descriptor                                   face_descriptor;
  typedef typename boost::property_traits<VertexUVMap>::value_type       Point_2;
  typedef typename CGAL::Kernel_traits<Point_2>::Kernel                  K;
  typedef typename Progressive_embedding::internal::Get_pe_traits<K>::type Default_traits;
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t,
                                                       NamedParameters, Default_traits>::type Traits;
  namespace PI = Progressive_embedding::internal;

  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  if(!internal::svg_options_are_valid(options)) return ERROR_WRONG_PARAMETER;

  try
  {
    const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
    const typename Traits::Exact_orientation_2 orientation = traits.exact_orientation_2_object();
    const double inf = std::numeric_limits<double>::infinity();
    const int dec = options.coordinate_decimals;
    const int digits = options.significant_digits;

    // ---- vertices and faces, in the order of vertices(tm) and faces(tm) (as the indexed disk)
    std::size_t nv = 0;
    auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
    std::vector<Point_2> uv;
    std::vector<std::array<double, 2> > p;
    std::vector<char> finite;
    for(vertex_descriptor vd : vertices(tm))
    {
      put(vid, vd, nv++);
      uv.push_back(get(uvm, vd));
      const double x = CGAL::to_double(uv.back().x()), y = CGAL::to_double(uv.back().y());
      p.push_back({{x, y}});
      finite.push_back(PI::is_finite_ft(uv.back().x()) && PI::is_finite_ft(uv.back().y()) && std::isfinite(x) && std::isfinite(y));
    }
    internal::Svg_faces F;
    auto fidx = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
    for(face_descriptor f : faces(tm))
    {
      put(fidx, f, F.tri.size());
      std::array<std::size_t, 3> t;
      std::size_t k = 0;
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
      {
        if(k == 3) return ERROR_NON_TRIANGULAR_MESH;
        t[k++] = get(vid, target(h, tm));
      }
      if(k != 3) return ERROR_NON_TRIANGULAR_MESH;
      F.tri.push_back(t);
    }
    const std::size_t nf = F.tri.size();
    if(nf == 0) return ERROR_EMPTY_MESH;
    F.kind.assign(nf, 2);
    F.energy.assign(nf, inf);

    // ---- classification and energies: the passes of check_embedding()
    Embedding_report report;
    PI::Indexed_disk<TriangleMesh> disk;
    const Error_code disk_status = PI::make_indexed_disk(tm, GT::null_halfedge(), disk);
    double min_energy = inf;
    if(disk_status == OK)
    {
      auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
      report = check_embedding(tm, uvm, Progressive_embedding::parameters::check_overlap(false,
                                          CGAL::parameters::vertex_point_map(vpm).geom_traits(traits)));
      if(report.status != OK) return report.status;
      PI::Uv_samples<Point_2> samples;
      PI::sample_uv(disk, uvm, samples);
      PI::Face_orientations o;
      PI::orientation_pass(disk, samples, orientation, o);
      for(std::size_t f = 0; f < nf; ++f)
        F.kind[f] = !o.face_ok[f] ? 2 : o.fo[f] == CGAL::COLLINEAR ? 0 : o.fo[f] == o.border_sign ? 1 : -1;
      F.flipped = report.flipped;
      F.degenerate = report.degenerate;
      F.non_finite_vertices = report.non_finite;
      if(options.color_by_distortion)
      {
        if(!report.has_3d_energy) return ERROR_DEGENERATE_3D_FACE;
        // the per-face values that check_embedding() aggregates (distortion pass)
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
          F.energy[f] = fds[f].symmetric_dirichlet;
          min_energy = (std::min)(min_energy, F.energy[f]);
        }
      }
    }
    else
    {
      // not a disk: no report; orientations relative to the majority of the faces
      if(options.color_by_distortion) return disk_status;
      std::size_t n_pos = 0, n_neg = 0;
      std::vector<int> sign(nf, 2);
      for(std::size_t i = 0; i < nf; ++i)
      {
        const std::array<std::size_t, 3>& t = F.tri[i];
        if(!finite[t[0]] || !finite[t[1]] || !finite[t[2]]) continue;
        const CGAL::Orientation ori = orientation(uv[t[0]], uv[t[1]], uv[t[2]]);
        sign[i] = (ori == CGAL::LEFT_TURN) ? 1 : (ori == CGAL::RIGHT_TURN ? -1 : 0);
        if(sign[i] > 0) ++n_pos; else if(sign[i] < 0) ++n_neg;
      }
      const int majority = (n_neg > n_pos) ? -1 : 1;
      for(std::size_t i = 0; i < nf; ++i)
      {
        F.kind[i] = sign[i] == 2 ? 2 : sign[i] == 0 ? 0 : sign[i] == majority ? 1 : -1;
        if(F.kind[i] == -1) ++F.flipped;
        if(F.kind[i] == 0) ++F.degenerate;
      }
      for(std::size_t v = 0; v < nv; ++v) if(!finite[v]) ++F.non_finite_vertices;
    }

    // ---- energy scale: from the isometry value 4 (or below) to the largest finite energy
    internal::Svg_energy_scale scale_e;
    if(options.color_by_distortion)
    {
      double lo = 4, hi = 0;
      for(std::size_t f = 0; f < nf; ++f)
        if(F.kind[f] == 1 && std::isfinite(F.energy[f])) { lo = (std::min)(lo, F.energy[f]); hi = (std::max)(hi, F.energy[f]); }
      if(!(lo > 0)) lo = 4;
      scale_e.lo = lo;
      scale_e.hi = (std::max)(hi, 10 * lo);
    }
    // ---- patches: compact indices, the edges between patches, colors; the marked vertices
    std::vector<long long> patch_value;
    const bool has_patches =
      internal::svg_face_patches(tm, get_parameter(np, Progressive_embedding::internal_np::face_patch_map), patch_value);
    std::vector<std::size_t> patch_of(nf, std::size_t(-1)), patch_color;
    std::vector<long long> patch_ids;               // the value of each compact patch index
    std::vector<std::array<std::size_t, 2> > patch_edges; // vertex indices of the edges between patches
    if(has_patches)
    {
      std::map<long long, std::size_t> compact;
      for(std::size_t i = 0; i < nf; ++i)
        if(patch_value[i] >= 0)
        {
          const auto it = compact.emplace(patch_value[i], compact.size()).first;
          patch_of[i] = it->second;
        }
      patch_ids.resize(compact.size());
      for(const auto& c : compact) patch_ids[c.second] = c.first;
      std::vector<std::vector<std::size_t> > adjacency(compact.size());
      for(auto e : edges(tm))
      {
        const halfedge_descriptor h = halfedge(e, tm), o = opposite(h, tm);
        if(is_border(h, tm) || is_border(o, tm)) continue;
        const std::size_t a = get(fidx, face(h, tm)), b = get(fidx, face(o, tm));
        if(patch_value[a] == patch_value[b] || (patch_value[a] < 0 && patch_value[b] < 0)) continue;
        patch_edges.push_back({{ get(vid, source(h, tm)), get(vid, target(h, tm)) }});
        if(patch_value[a] >= 0 && patch_value[b] >= 0)
        {
          adjacency[patch_of[a]].push_back(patch_of[b]);
          adjacency[patch_of[b]].push_back(patch_of[a]);
        }
      }
      for(auto& l : adjacency) { std::sort(l.begin(), l.end()); l.erase(std::unique(l.begin(), l.end()), l.end()); }
      patch_color = internal::svg_color_patches(adjacency);
    }
    std::vector<std::size_t> marked;
    internal::svg_marked_vertices(vid, get_parameter(np, Progressive_embedding::internal_np::constrained_vertices), marked);
    const bool by_patch = has_patches && !options.color_by_distortion;

    const int levels = options.color_levels;
    auto level_of = [&](double e) { return int(std::lround(scale_e.position(e) * (levels - 1))); };
    auto level_color = [&](int l) { return internal::Svg_color_map::color(double(l) / double(levels - 1)); };

    // ---- main view: the finite faces fit a size x size box
    double xmin = inf, ymin = inf, xmax = -inf, ymax = -inf;
    for(std::size_t i = 0; i < nf; ++i)
    {
      if(F.kind[i] == 2) continue;
      for(std::size_t v : F.tri[i])
      {
        xmin = (std::min)(xmin, p[v][0]); xmax = (std::max)(xmax, p[v][0]);
        ymin = (std::min)(ymin, p[v][1]); ymax = (std::max)(ymax, p[v][1]);
      }
    }
    if(!(xmin <= xmax)) { xmin = ymin = 0; xmax = ymax = 1; }
    const double box = options.size, margin = 20.;
    const double extent = (std::max)(xmax - xmin, ymax - ymin);
    double scale = (extent > 0 && std::isfinite(box / extent)) ? box / extent : 1.;
    if(!std::isfinite(scale * extent)) scale = 1.;
    const double draw_w = (std::max)(1., (xmax - xmin) * scale), draw_h = (std::max)(1., (ymax - ymin) * scale);
    const double title_h = options.title.empty() ? 0. : 36.;
    internal::Svg_view view;
    view.xmin = xmin; view.ymax = ymax; view.scale = scale; view.ox = margin; view.oy = margin + title_h;

    // ---- the inset region: bounding box of the flipped and degenerate faces
    bool has_inset = false;
    double rx0 = 0, ry0 = 0, side = 0;
    if(options.inset)
    {
      double bx0 = inf, by0 = inf, bx1 = -inf, by1 = -inf;
      for(std::size_t i = 0; i < nf; ++i)
      {
        if(F.kind[i] != 0 && F.kind[i] != -1) continue;
        for(std::size_t v : F.tri[i])
        {
          bx0 = (std::min)(bx0, p[v][0]); bx1 = (std::max)(bx1, p[v][0]);
          by0 = (std::min)(by0, p[v][1]); by1 = (std::max)(by1, p[v][1]);
        }
      }
      if(bx0 <= bx1)
      {
        has_inset = true;
        side = 1.3 * (std::max)(bx1 - bx0, by1 - by0); // a margin of context around the faces
        if(!(side > 0)) side = extent > 0 ? extent * 1e-6 : 1.;
        const double cx = 0.5 * (bx0 + bx1), cy = 0.5 * (by0 + by1);
        rx0 = cx - 0.5 * side; ry0 = cy - 0.5 * side;
      }
    }

    std::string s;
    s.reserve(4096 + nf * 40);
    auto num = [](double x) { return internal::svg_number(x, 1); };
    auto pt = [&](std::string& d, double x, double y) {
      internal::svg_append(d, x, dec); d += ' '; internal::svg_append(d, y, dec);
    };
    // a polygon in pixels as a closed subpath
    auto subpath = [&](std::string& d, const std::vector<std::array<double, 2> >& poly) {
      for(std::size_t k = 0; k < poly.size(); ++k) { d += (k == 0 ? 'M' : 'L'); pt(d, poly[k][0], poly[k][1]); }
      if(!poly.empty()) d += 'Z';
    };
    // Draws the faces through `to_px`, keeping the polygons that `keep` accepts (clipping them).
    auto draw_faces = [&](std::string& g, auto to_px, auto keep, double stroke_scale) {
      std::vector<std::string> by_level(static_cast<std::size_t>(levels)), by_patch_d(patch_ids.size());
      std::string flipped, degenerate, border, between;
      std::vector<std::array<double, 2> > poly;
      for(std::size_t i = 0; i < nf; ++i)
      {
        if(F.kind[i] == 2) continue;
        poly.clear();
        for(std::size_t v : F.tri[i]) poly.push_back(to_px(p[v][0], p[v][1]));
        if(!keep(poly)) continue;
        if(F.kind[i] == 1 && by_patch && patch_of[i] != std::size_t(-1)) subpath(by_patch_d[patch_of[i]], poly);
        else if(F.kind[i] == 1)
          subpath(by_level[options.color_by_distortion ? std::size_t(level_of(F.energy[i])) : 0], poly);
        else if(F.kind[i] == -1) subpath(flipped, poly);
        else subpath(degenerate, poly);
      }
      for(halfedge_descriptor h : halfedges(tm))
      {
        if(!is_border(h, tm)) continue;
        const std::size_t a = get(vid, source(h, tm)), b = get(vid, target(h, tm));
        if(!finite[a] || !finite[b]) continue;
        poly.clear();
        poly.push_back(to_px(p[a][0], p[a][1])); poly.push_back(to_px(p[b][0], p[b][1]));
        if(!keep(poly) || poly.size() < 2) continue;
        border += 'M'; pt(border, poly[0][0], poly[0][1]);
        for(std::size_t k = 1; k < poly.size(); ++k) { border += 'L'; pt(border, poly[k][0], poly[k][1]); }
      }
      const std::string es = options.edge_width > 0
        ? " stroke=\"#404040\" stroke-opacity=\"0.7\" stroke-width=\"" + internal::svg_number(options.edge_width * stroke_scale, 2)
          + "\" stroke-linejoin=\"round\"" : std::string(" stroke=\"none\"");
      for(int l = 0; l < levels; ++l)
        if(!by_level[std::size_t(l)].empty())
          g += "<path fill=\"" + (options.color_by_distortion ? level_color(l) : options.face_color) + "\"" + es
             + " d=\"" + by_level[std::size_t(l)] + "\"/>\n";
      for(std::size_t k = 0; k < by_patch_d.size(); ++k)
        if(!by_patch_d[k].empty())
          g += "<path class=\"pe-patch\" data-patch=\"" + std::to_string(patch_ids[k]) + "\" fill=\""
             + internal::svg_patch_color(patch_color[k]) + "\"" + es + " d=\"" + by_patch_d[k] + "\"/>\n";
      for(const std::array<std::size_t, 2>& e : patch_edges)
      {
        if(!finite[e[0]] || !finite[e[1]]) continue;
        poly.clear();
        poly.push_back(to_px(p[e[0]][0], p[e[0]][1])); poly.push_back(to_px(p[e[1]][0], p[e[1]][1]));
        if(!keep(poly) || poly.size() < 2) continue;
        between += 'M'; pt(between, poly[0][0], poly[0][1]);
        for(std::size_t k = 1; k < poly.size(); ++k) { between += 'L'; pt(between, poly[k][0], poly[k][1]); }
      }
      if(!between.empty() && options.patch_border_width > 0)
        g += "<path class=\"pe-patch-borders\" fill=\"none\" stroke=\"#1a1a1a\" stroke-width=\""
           + internal::svg_number(options.patch_border_width * stroke_scale, 2)
           + "\" stroke-linecap=\"round\" stroke-linejoin=\"round\" d=\"" + between + "\"/>\n";
      if(!flipped.empty())
        g += "<path class=\"pe-flipped\" fill=\"" + options.flipped_color + "\" stroke=\"" + options.flipped_color
           + "\" stroke-width=\"" + internal::svg_number((std::max)(0.5, options.edge_width) * stroke_scale, 2)
           + "\" stroke-linejoin=\"round\" d=\"" + flipped + "\"/>\n";
      if(!border.empty() && options.border_width > 0)
        g += "<path class=\"pe-border\" fill=\"none\" stroke=\"#000000\" stroke-width=\""
           + internal::svg_number(options.border_width * stroke_scale, 2) + "\" stroke-linecap=\"round\" d=\"" + border + "\"/>\n";
      if(!degenerate.empty())
        g += "<path class=\"pe-degenerate\" fill=\"none\" stroke=\"" + options.degenerate_color
           + "\" stroke-width=\"" + internal::svg_number(2.5 * stroke_scale, 2)
           + "\" stroke-linejoin=\"round\" stroke-linecap=\"round\" d=\"" + degenerate + "\"/>\n";
    };

    // circles at the centroids of the flipped and degenerate faces, one path for each kind
    auto markers = [&](auto to_px, auto visible) {
      std::string mf, md, g;
      for(std::size_t i = 0; i < nf; ++i)
      {
        if(F.kind[i] != -1 && F.kind[i] != 0) continue;
        const std::array<std::size_t, 3>& t = F.tri[i];
        const double cx = (p[t[0]][0] + p[t[1]][0] + p[t[2]][0]) / 3., cy = (p[t[0]][1] + p[t[1]][1] + p[t[2]][1]) / 3.;
        const std::array<double, 2> c = to_px(cx, cy);
        if(!visible(c[0], c[1])) continue;
        // flipped: radius 6, on top of the degenerate ones (radius 9), so that both are seen
        if(F.kind[i] == -1) { mf += 'M'; pt(mf, c[0] - 6, c[1]); mf += "a6 6 0 1 0 12 0a6 6 0 1 0 -12 0"; }
        else                { md += 'M'; pt(md, c[0] - 9, c[1]); md += "a9 9 0 1 0 18 0a9 9 0 1 0 -18 0"; }
      }
      if(!md.empty()) g += "<path class=\"pe-degenerate-markers\" fill=\"none\" stroke=\"" + options.degenerate_color + "\" stroke-width=\"1.5\" d=\"" + md + "\"/>\n";
      if(!mf.empty()) g += "<path class=\"pe-flipped-markers\" fill=\"none\" stroke=\"" + options.flipped_color + "\" stroke-width=\"2\" d=\"" + mf + "\"/>\n";
      // the marked vertices: black points ringed in white, seen on any fill
      if(options.constrained_vertex_radius > 0)
        for(std::size_t v : marked)
        {
          if(v >= nv || !finite[v]) continue;
          const std::array<double, 2> c = to_px(p[v][0], p[v][1]);
          if(!visible(c[0], c[1])) continue;
          g += "<circle class=\"pe-constrained\" cx=\"" + internal::svg_number(c[0], dec) + "\" cy=\"" + internal::svg_number(c[1], dec)
             + "\" r=\"" + internal::svg_number(options.constrained_vertex_radius, 2)
             + "\" fill=\"#000000\" stroke=\"#ffffff\" stroke-width=\"1.5\"/>\n";
        }
      return g;
    };

    // ---- header
    const double col_x = view.ox + draw_w + 24;
    const double col_w = (std::max)(250., has_inset ? options.inset_size : 0.);
    std::string legend, inset;
    double ly = view.oy;
    {
      // legend
      auto text = [&](const std::string& id, double x, double y, const std::string& t, const char* extra = "") {
        legend += "<text" + (id.empty() ? std::string() : " id=\"" + id + "\"") + " x=\"" + num(x) + "\" y=\"" + num(y)
                + "\"" + extra + ">" + t + "</text>\n";
      };
      legend += "<g id=\"pe-legend\" font-family=\"sans-serif\" font-size=\"13\">\n";
      double y = ly + 14;
      if(options.color_by_distortion)
      {
        text("", col_x, y, "symmetric Dirichlet energy"); y += 16;
        text("", col_x, y, "against the 3D triangles (log scale)"); y += 12;
        const double bar_x = col_x + 60, bar_y = y, bar_w = 22, bar_h = 200;
        legend += "<defs><linearGradient id=\"pe-energy\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">";
        for(int k = 0; k <= 8; ++k)
          legend += "<stop offset=\"" + internal::svg_number(k / 8., 3) + "\" stop-color=\"" + internal::Svg_color_map::color(k / 8.) + "\"/>";
        legend += "</linearGradient></defs>\n";
        legend += "<rect x=\"" + num(bar_x) + "\" y=\"" + num(bar_y) + "\" width=\"" + num(bar_w) + "\" height=\"" + num(bar_h)
                + "\" fill=\"url(#pe-energy)\" stroke=\"#000000\" stroke-width=\"0.5\"/>\n";
        auto bar_y_of = [&](double e) { return bar_y + bar_h - scale_e.position(e) * bar_h; };
        // decade ticks, at most 8
        const int k0 = int(std::ceil(std::log10(scale_e.lo) - 1e-9)), k1 = int(std::floor(std::log10(scale_e.hi) + 1e-9));
        const int stride = (std::max)(1, (k1 - k0 + 7) / 8);
        std::vector<double> ticks = { scale_e.lo };
        for(int k = k0; k <= k1; k += stride)
          if(std::pow(10., k) > 1.5 * scale_e.lo) ticks.push_back(std::pow(10., k));
        double last_label = inf;
        for(double t : ticks)
        {
          const double ty = bar_y_of(t);
          legend += "<line x1=\"" + num(bar_x + bar_w) + "\" y1=\"" + num(ty) + "\" x2=\"" + num(bar_x + bar_w + 5) + "\" y2=\""
                  + num(ty) + "\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
          if(std::abs(ty - last_label) < 14) continue; // no overlapping labels
          text("", bar_x + bar_w + 8, ty + 4, format_number(t, digits));
          last_label = ty;
        }
        // where the min, median, mean and max are on the bar (infinite values at its top); the
        // names of marks closer than a line of text share one label
        const double marks[4] = { min_energy, report.distortion.symmetric_dirichlet_quantiles[0], report.mean_energy_3d, report.max_energy_3d };
        const char* names[4] = { "min", "median", "mean", "max" };
        std::vector<std::pair<double, std::string> > labels;
        for(int k = 0; k < 4; ++k)
        {
          const double ty = std::isfinite(marks[k]) ? bar_y_of(marks[k]) : bar_y;
          legend += "<path d=\"M" + num(bar_x - 1) + " " + num(ty) + "l-7 -4v8z\" fill=\"#000000\"/>\n";
          if(!labels.empty() && std::abs(labels.back().first - ty) < 11) labels.back().second += std::string(", ") + names[k];
          else labels.emplace_back(ty, names[k]);
        }
        for(const auto& l : labels)
          text("", bar_x - 10, l.first + 4, l.second, " text-anchor=\"end\" font-size=\"11\"");
        y = bar_y + bar_h + 22;
        const std::string ids[4] = { "pe-energy-min", "pe-energy-median", "pe-energy-mean", "pe-energy-max" };
        for(int k = 0; k < 4; ++k)
        {
          text(ids[k], col_x, y, std::string(names[k]) + " " + format_number(marks[k], digits));
          y += 17;
        }
        y += 6;
      }
      legend += "<rect x=\"" + num(col_x) + "\" y=\"" + num(y - 11) + "\" width=\"14\" height=\"14\" fill=\"" + options.flipped_color + "\"/>\n";
      text("", col_x + 22, y, "flipped");
      y += 20;
      legend += "<rect x=\"" + num(col_x) + "\" y=\"" + num(y - 11) + "\" width=\"14\" height=\"14\" fill=\"none\" stroke=\""
              + options.degenerate_color + "\" stroke-width=\"2.5\"/>\n";
      text("", col_x + 22, y, "degenerate");
      y += 24;
      text("pe-count-faces", col_x, y, "faces: " + std::to_string(nf)); y += 17;
      text("pe-count-flipped", col_x, y, "flipped: " + std::to_string(F.flipped)); y += 17;
      text("pe-count-degenerate", col_x, y, "degenerate: " + std::to_string(F.degenerate)); y += 17;
      text("pe-count-non-finite", col_x, y, "non-finite vertices: " + std::to_string(F.non_finite_vertices)); y += 17;
      if(has_patches)
      {
        y += 7;
        if(by_patch)
          for(std::size_t k = 0; k < 3; ++k)
            legend += "<rect x=\"" + num(col_x + 5 * double(k)) + "\" y=\"" + num(y - 11 + 2 * double(k)) + "\" width=\"10\" height=\"10\" fill=\""
                    + internal::svg_patch_color(k) + "\" stroke=\"#404040\" stroke-width=\"0.5\"/>\n";
        text("pe-count-patches", col_x + 22, y, "patches: " + std::to_string(patch_ids.size())); y += 20;
        legend += "<line x1=\"" + num(col_x) + "\" y1=\"" + num(y - 4) + "\" x2=\"" + num(col_x + 16) + "\" y2=\"" + num(y - 4)
                + "\" stroke=\"#1a1a1a\" stroke-width=\"" + internal::svg_number((std::max)(1., options.patch_border_width), 2) + "\"/>\n";
        text("", col_x + 22, y, "patch border"); y += 20;
      }
      if(!marked.empty())
      {
        legend += "<circle cx=\"" + num(col_x + 7) + "\" cy=\"" + num(y - 4) + "\" r=\"4\" fill=\"#000000\" stroke=\"#ffffff\" stroke-width=\"1.5\"/>\n";
        text("pe-count-constrained", col_x + 22, y, "constrained vertices: " + std::to_string(marked.size())); y += 17;
      }
      legend += "</g>\n";
      ly = y;
    }

    double inset_bottom = ly;
    if(has_inset)
    {
      const double S = options.inset_size;
      const double ix = col_x, iy = ly + 30;
      const double iscale = S / side;
      const double zoom = iscale / scale;
      auto to_inset = [&](double x, double y) {
        return std::array<double, 2>{{ ix + (x - rx0) * iscale, iy + (ry0 + side - y) * iscale }};
      };
      // keep the polygons whose box meets the inset, clipped to it (no huge coordinates in the file)
      auto keep = [&](std::vector<std::array<double, 2> >& poly) {
        double a0 = inf, b0 = inf, a1 = -inf, b1 = -inf;
        for(const auto& q : poly) { a0 = (std::min)(a0, q[0]); a1 = (std::max)(a1, q[0]); b0 = (std::min)(b0, q[1]); b1 = (std::max)(b1, q[1]); }
        if(a1 < ix - 2 || a0 > ix + S + 2 || b1 < iy - 2 || b0 > iy + S + 2) return false;
        internal::svg_clip(poly, ix - 2, iy - 2, ix + S + 2, iy + S + 2);
        return poly.size() >= 2;
      };
      inset += "<g id=\"pe-inset\">\n";
      inset += "<text x=\"" + num(ix) + "\" y=\"" + num(iy - 8) + "\" font-family=\"sans-serif\" font-size=\"13\">zoom &#215;"
             + format_number(zoom, digits) + " on the flipped and degenerate faces</text>\n";
      inset += "<clipPath id=\"pe-inset-clip\"><rect x=\"" + num(ix) + "\" y=\"" + num(iy) + "\" width=\"" + num(S) + "\" height=\""
             + num(S) + "\"/></clipPath>\n";
      inset += "<rect x=\"" + num(ix) + "\" y=\"" + num(iy) + "\" width=\"" + num(S) + "\" height=\"" + num(S) + "\" fill=\"#ffffff\"/>\n";
      inset += "<g clip-path=\"url(#pe-inset-clip)\">\n";
      draw_faces(inset, to_inset, keep, 2.);
      // faces still too small to be seen at this zoom are marked as in the main view
      inset += markers(to_inset, [&](double x, double y) { return x >= ix && x <= ix + S && y >= iy && y <= iy + S; });
      inset += "</g>\n";
      inset += "<rect x=\"" + num(ix) + "\" y=\"" + num(iy) + "\" width=\"" + num(S) + "\" height=\"" + num(S)
             + "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1.5\"/>\n";
      // the zoomed region in the main view (at least 10 px, to be seen), joined to the inset
      double mx = view.X(rx0), my = view.Y(ry0 + side), mw = side * scale;
      if(!(mw >= 10)) { mx += 0.5 * mw - 5; my += 0.5 * mw - 5; mw = 10; }
      inset += "<rect id=\"pe-inset-region\" x=\"" + num(mx) + "\" y=\"" + num(my) + "\" width=\"" + num(mw) + "\" height=\""
             + num(mw) + "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1.5\"/>\n";
      inset += "<path d=\"M" + num(mx + mw) + " " + num(my) + "L" + num(ix) + " " + num(iy) + "M" + num(mx + mw) + " " + num(my + mw)
             + "L" + num(ix) + " " + num(iy + S) + "\" stroke=\"#000000\" stroke-opacity=\"0.5\" stroke-width=\"0.8\" stroke-dasharray=\"4 3\"/>\n";
      inset += "</g>\n";
      inset_bottom = iy + S;
    }

    const double width = col_x + col_w + margin;
    const double height = (std::max)(view.oy + draw_h, inset_bottom) + margin;

    s += "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
    s += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + internal::svg_number(width, 0)
       + "\" height=\"" + internal::svg_number(height, 0) + "\" viewBox=\"0 0 " + internal::svg_number(width, 0)
       + " " + internal::svg_number(height, 0) + "\">\n";
    const std::string esc_title = internal::svg_escape(options.title);
    if(!options.title.empty()) s += "<title>" + esc_title + "</title>\n";
    s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    if(!options.title.empty())
      s += "<text x=\"" + num(margin) + "\" y=\"" + num(margin + 20) + "\" font-family=\"sans-serif\" font-size=\"20\">" + esc_title + "</text>\n";

    // main view
    s += "<g id=\"pe-faces\">\n";
    draw_faces(s, [&](double x, double y) { return std::array<double, 2>{{ view.X(x), view.Y(y) }}; },
               [](std::vector<std::array<double, 2> >&) { return true; }, 1.);
    s += "</g>\n";
    s += markers([&](double x, double y) { return std::array<double, 2>{{ view.X(x), view.Y(y) }}; },
                 [](double, double) { return true; });
    s += legend;
    s += inset;
    s += "</svg>\n";

    out << s;
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
/// writes an SVG picture of the uv layout of `tm` to the file `filename`; see the stream overload
/// for the picture and the parameters.
///
/// A failed write never leaves a partial file: when `filename` is a regular file or does not exist,
/// the picture is written to a temporary file in the same folder, which replaces `filename` only once
/// it is completely written and closed; on failure the temporary file is removed and an existing
/// `filename` is left untouched. Anything else (a device such as `/dev/null` or `/dev/stdout`, a pipe)
/// is written directly. No exception escapes.
///
/// \return as the stream overload; `ERROR_CANNOT_WRITE_FILE` if the file cannot be written (a folder,
///         no permission, no space left, a file size limit, ...)
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_SVG(const std::string& filename, const TriangleMesh& tm, VertexUVMap uvm, const SVG_options& options,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  if(!internal::svg_options_are_valid(options)) return ERROR_WRONG_PARAMETER;
  return internal::write_file_atomically(filename, [&](std::ostream& out) { return write_SVG(out, tm, uvm, options, np); });
}

/// \ingroup PkgProgressiveEmbeddingIO
///
/// writes an SVG picture of the uv layout of `tm` with default `SVG_options` and the title `title`:
/// faces in one color, flipped and degenerate faces highlighted, no inset.
/// See the overload with `SVG_options` for the picture, the parameters and the result.
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
/// writes an SVG picture of the uv layout of `tm` with default `SVG_options` and the title `title`
/// to the file `filename`, never leaving a partial file (see the overload with `SVG_options`).
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
