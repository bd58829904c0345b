// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_SVG_OPTIONS_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_SVG_OPTIONS_H

/// \file SVG_options.h
/// What `write_SVG()` draws (`SVG_options`), and the format of the numbers it prints (`format_number()`).

#include <CGAL/Progressive_embedding/IO/internal/svg_text.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

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

inline bool svg_options_are_valid(const SVG_options& o)
{
  auto in = [](double x, double lo, double hi) { return std::isfinite(x) && x >= lo && x <= hi; };
  return in(o.size, 100, 100000) && in(o.edge_width, 0, 100) && in(o.border_width, 0, 100)
      && in(o.inset_size, 100, 100000) && o.significant_digits >= 1 && o.significant_digits <= 17
      && o.coordinate_decimals >= 0 && o.coordinate_decimals <= 6 && o.color_levels >= 2 && o.color_levels <= 1024
      && svg_is_color(o.flipped_color) && svg_is_color(o.degenerate_color) && svg_is_color(o.face_color)
      && in(o.patch_border_width, 0, 100) && in(o.constrained_vertex_radius, 0, 100);
}

} // namespace internal
#endif // DOXYGEN_RUNNING

} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_SVG_OPTIONS_H
