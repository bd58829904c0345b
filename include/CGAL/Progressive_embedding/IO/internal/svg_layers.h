// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_LAYERS_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_LAYERS_H

// The drawing steps of write_SVG(), each returning its SVG elements: the faces (colored by distortion,
// by patch or in one color, flipped ones filled, degenerate ones outlined, the border and the lines
// between patches), the markers of flipped, degenerate and constrained vertices, the legend, the
// inset, and the document that holds them. They draw what they are given; nothing is measured here.

#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/IO/SVG_options.h>
#include <CGAL/Progressive_embedding/IO/internal/svg_colors.h>
#include <CGAL/Progressive_embedding/IO/internal/svg_frame.h>
#include <CGAL/Progressive_embedding/IO/internal/svg_map.h>
#include <CGAL/Progressive_embedding/IO/internal/svg_patches.h>
#include <CGAL/Progressive_embedding/IO/internal/svg_text.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace IO {
namespace internal {

// legend and frame coordinates: one decimal
inline std::string svg_num(double x) { return svg_number(x, 1); }

inline void svg_text(std::string& g, const std::string& id, double x, double y, const std::string& t,
                     const char* extra = "")
{
  g += "<text" + (id.empty() ? std::string() : " id=\"" + id + "\"") + " x=\"" + svg_num(x) + "\" y=\"" + svg_num(y)
     + "\"" + extra + ">" + t + "</text>\n";
}

// The path data of the edges (vertex index pairs) whose ends are finite, through `view`.
inline std::string svg_edge_path(const std::vector<std::array<std::size_t, 2> >& edges, const Svg_map& map,
                                 const Svg_view& view, int decimals)
{
  std::string d;
  std::vector<std::array<double, 2> > line;
  for(const std::array<std::size_t, 2>& e : edges)
  {
    if(!map.finite[e[0]] || !map.finite[e[1]]) continue;
    line.clear();
    line.push_back(view(map.p[e[0]])); line.push_back(view(map.p[e[1]]));
    if(!view.keep(line) || line.size() < 2) continue;
    svg_append_polyline(d, line, decimals);
  }
  return d;
}

// The path data of the faces through `view`, one string per fill: the correctly oriented faces
// by color level (one level without distortion colors) or by patch, the flipped faces, the
// degenerate ones.
struct Svg_face_paths
{
  std::vector<std::string> by_level, by_patch;
  std::string flipped, degenerate;
};

inline Svg_face_paths svg_face_paths(const Svg_map& map, const Svg_patches& patches, const Svg_energy_scale& scale,
                                     const SVG_options& options, const Svg_view& view)
{
  const bool by_patch = patches.present && !options.color_by_distortion;
  Svg_face_paths d;
  d.by_level.resize(static_cast<std::size_t>(options.color_levels));
  d.by_patch.resize(patches.ids.size());
  std::vector<std::array<double, 2> > poly;
  for(std::size_t i = 0; i < map.number_of_faces(); ++i)
  {
    const int kind = map.kind[i];
    if(kind == 2) continue;
    poly.clear();
    for(std::size_t v : map.tri[i]) poly.push_back(view(map.p[v]));
    if(!view.keep(poly)) continue;
    std::string* path = &d.degenerate;
    if(kind == 1 && by_patch && patches.of_face[i] != std::size_t(-1)) path = &d.by_patch[patches.of_face[i]];
    else if(kind == 1)
      path = &d.by_level[options.color_by_distortion ? std::size_t(svg_level(scale, map.energy[i], options.color_levels)) : 0];
    else if(kind == -1) path = &d.flipped;
    svg_append_polygon(*path, poly, options.coordinate_decimals);
  }
  return d;
}

// The faces layer through `view`, its strokes `stroke_scale` times as wide (the inset's are wider):
// faces by level, by patch, the lines between patches, flipped faces, the border, degenerate faces
// on top.
inline std::string svg_faces_layer(const Svg_map& map, const Svg_patches& patches, const Svg_energy_scale& scale,
                                   const SVG_options& options, const Svg_view& view, double stroke_scale)
{
  const Svg_face_paths d = svg_face_paths(map, patches, scale, options, view);
  const std::string border = svg_edge_path(map.border, map, view, options.coordinate_decimals);
  const std::string between = svg_edge_path(patches.edges, map, view, options.coordinate_decimals);
  const std::string es = options.edge_width > 0
    ? " stroke=\"#404040\" stroke-opacity=\"0.7\" stroke-width=\"" + svg_number(options.edge_width * stroke_scale, 2)
      + "\" stroke-linejoin=\"round\"" : std::string(" stroke=\"none\"");
  std::string g;
  for(int l = 0; l < options.color_levels; ++l)
    if(!d.by_level[std::size_t(l)].empty())
      g += "<path fill=\"" + (options.color_by_distortion ? svg_level_color(l, options.color_levels) : options.face_color) + "\"" + es
         + " d=\"" + d.by_level[std::size_t(l)] + "\"/>\n";
  for(std::size_t k = 0; k < d.by_patch.size(); ++k)
    if(!d.by_patch[k].empty())
      g += "<path class=\"pe-patch\" data-patch=\"" + std::to_string(patches.ids[k]) + "\" fill=\""
         + svg_patch_color(patches.color[k]) + "\"" + es + " d=\"" + d.by_patch[k] + "\"/>\n";
  if(!between.empty() && options.patch_border_width > 0)
    g += "<path class=\"pe-patch-borders\" fill=\"none\" stroke=\"#1a1a1a\" stroke-width=\""
       + svg_number(options.patch_border_width * stroke_scale, 2)
       + "\" stroke-linecap=\"round\" stroke-linejoin=\"round\" d=\"" + between + "\"/>\n";
  if(!d.flipped.empty())
    g += "<path class=\"pe-flipped\" fill=\"" + options.flipped_color + "\" stroke=\"" + options.flipped_color
       + "\" stroke-width=\"" + svg_number((std::max)(0.5, options.edge_width) * stroke_scale, 2)
       + "\" stroke-linejoin=\"round\" d=\"" + d.flipped + "\"/>\n";
  if(!border.empty() && options.border_width > 0)
    g += "<path class=\"pe-border\" fill=\"none\" stroke=\"#000000\" stroke-width=\""
       + svg_number(options.border_width * stroke_scale, 2) + "\" stroke-linecap=\"round\" d=\"" + border + "\"/>\n";
  if(!d.degenerate.empty())
    g += "<path class=\"pe-degenerate\" fill=\"none\" stroke=\"" + options.degenerate_color
       + "\" stroke-width=\"" + svg_number(2.5 * stroke_scale, 2)
       + "\" stroke-linejoin=\"round\" stroke-linecap=\"round\" d=\"" + d.degenerate + "\"/>\n";
  return g;
}

// Circles at the centroids of the flipped and degenerate faces (one path for each kind), so that
// faces too small to be seen are found, and the marked vertices: black points ringed in white,
// seen on any fill.
inline std::string svg_markers_layer(const Svg_map& map, const std::vector<std::size_t>& marked,
                                     const SVG_options& options, const Svg_view& view)
{
  const int dec = options.coordinate_decimals;
  const std::vector<std::array<double, 2> >& p = map.p;
  std::string mf, md, g;
  for(std::size_t i = 0; i < map.number_of_faces(); ++i)
  {
    if(map.kind[i] != -1 && map.kind[i] != 0) continue;
    const std::array<std::size_t, 3>& t = map.tri[i];
    const double cx = (p[t[0]][0] + p[t[1]][0] + p[t[2]][0]) / 3., cy = (p[t[0]][1] + p[t[1]][1] + p[t[2]][1]) / 3.;
    const std::array<double, 2> c = view({{ cx, cy }});
    if(!view.visible(c[0], c[1])) continue;
    // flipped: radius 6, on top of the degenerate ones (radius 9), so that both are seen
    if(map.kind[i] == -1) { mf += 'M'; svg_append_point(mf, {{ c[0] - 6, c[1] }}, dec); mf += "a6 6 0 1 0 12 0a6 6 0 1 0 -12 0"; }
    else                  { md += 'M'; svg_append_point(md, {{ c[0] - 9, c[1] }}, dec); md += "a9 9 0 1 0 18 0a9 9 0 1 0 -18 0"; }
  }
  if(!md.empty()) g += "<path class=\"pe-degenerate-markers\" fill=\"none\" stroke=\"" + options.degenerate_color + "\" stroke-width=\"1.5\" d=\"" + md + "\"/>\n";
  if(!mf.empty()) g += "<path class=\"pe-flipped-markers\" fill=\"none\" stroke=\"" + options.flipped_color + "\" stroke-width=\"2\" d=\"" + mf + "\"/>\n";
  if(options.constrained_vertex_radius > 0)
    for(std::size_t v : marked)
    {
      if(v >= p.size() || !map.finite[v]) continue;
      const std::array<double, 2> c = view(p[v]);
      if(!view.visible(c[0], c[1])) continue;
      g += "<circle class=\"pe-constrained\" cx=\"" + svg_number(c[0], dec) + "\" cy=\"" + svg_number(c[1], dec)
         + "\" r=\"" + svg_number(options.constrained_vertex_radius, 2)
         + "\" fill=\"#000000\" stroke=\"#ffffff\" stroke-width=\"1.5\"/>\n";
    }
  return g;
}

// The distortion part of the legend, from its top `y` (returns its bottom): the color bar with decade
// ticks, where the min, median, mean and max are on it, and their values. The median, mean and max
// are the certificate's, the min the smallest per-face energy of the map.
inline double svg_energy_legend(std::string& g, const Svg_map& map, const Embedding_report& report,
                                const Svg_energy_scale& scale, const SVG_options& options, double x, double y)
{
  const int digits = options.significant_digits;
  svg_text(g, "", x, y, "symmetric Dirichlet energy"); y += 16;
  svg_text(g, "", x, y, "against the 3D triangles (log scale)"); y += 12;
  const double bar_x = x + 60, bar_y = y, bar_w = 22, bar_h = 200;
  g += "<defs><linearGradient id=\"pe-energy\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">";
  for(int k = 0; k <= 8; ++k)
    g += "<stop offset=\"" + svg_number(k / 8., 3) + "\" stop-color=\"" + Svg_color_map::color(k / 8.) + "\"/>";
  g += "</linearGradient></defs>\n";
  g += "<rect x=\"" + svg_num(bar_x) + "\" y=\"" + svg_num(bar_y) + "\" width=\"" + svg_num(bar_w) + "\" height=\"" + svg_num(bar_h)
     + "\" fill=\"url(#pe-energy)\" stroke=\"#000000\" stroke-width=\"0.5\"/>\n";
  auto bar_y_of = [&](double e) { return bar_y + bar_h - scale.position(e) * bar_h; };
  // decade ticks, at most 8
  const int k0 = int(std::ceil(std::log10(scale.lo) - 1e-9)), k1 = int(std::floor(std::log10(scale.hi) + 1e-9));
  const int stride = (std::max)(1, (k1 - k0 + 7) / 8);
  std::vector<double> ticks = { scale.lo };
  for(int k = k0; k <= k1; k += stride)
    if(std::pow(10., k) > 1.5 * scale.lo) ticks.push_back(std::pow(10., k));
  double last_label = std::numeric_limits<double>::infinity();
  for(double t : ticks)
  {
    const double ty = bar_y_of(t);
    g += "<line x1=\"" + svg_num(bar_x + bar_w) + "\" y1=\"" + svg_num(ty) + "\" x2=\"" + svg_num(bar_x + bar_w + 5) + "\" y2=\""
       + svg_num(ty) + "\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
    if(std::abs(ty - last_label) < 14) continue; // no overlapping labels
    svg_text(g, "", bar_x + bar_w + 8, ty + 4, format_number(t, digits));
    last_label = ty;
  }
  // where the min, median, mean and max are on the bar (infinite values at its top); the names of
  // marks closer than a line of text share one label
  const double marks[4] = { map.min_energy, report.distortion.symmetric_dirichlet_quantiles[0], report.mean_energy_3d,
                            report.max_energy_3d };
  const char* names[4] = { "min", "median", "mean", "max" };
  std::vector<std::pair<double, std::string> > labels;
  for(int k = 0; k < 4; ++k)
  {
    const double ty = std::isfinite(marks[k]) ? bar_y_of(marks[k]) : bar_y;
    g += "<path d=\"M" + svg_num(bar_x - 1) + " " + svg_num(ty) + "l-7 -4v8z\" fill=\"#000000\"/>\n";
    if(!labels.empty() && std::abs(labels.back().first - ty) < 11) labels.back().second += std::string(", ") + names[k];
    else labels.emplace_back(ty, names[k]);
  }
  for(const auto& l : labels)
    svg_text(g, "", bar_x - 10, l.first + 4, l.second, " text-anchor=\"end\" font-size=\"11\"");
  y = bar_y + bar_h + 22;
  const std::string ids[4] = { "pe-energy-min", "pe-energy-median", "pe-energy-mean", "pe-energy-max" };
  for(int k = 0; k < 4; ++k)
  {
    svg_text(g, ids[k], x, y, std::string(names[k]) + " " + format_number(marks[k], digits));
    y += 17;
  }
  return y + 6;
}

// The legend in the column at `x`, from its top `top` (returns its bottom): the distortion scale
// (with distortion colors), the keys of flipped and degenerate faces, the counts, the patches and
// the constrained vertices (when drawn).
inline double svg_legend(std::string& g, const Svg_map& map, const Svg_patches& patches, const std::vector<std::size_t>& marked,
                         const Embedding_report& report, const Svg_energy_scale& scale, const SVG_options& options,
                         double x, double top)
{
  g += "<g id=\"pe-legend\" font-family=\"sans-serif\" font-size=\"13\">\n";
  double y = top + 14;
  if(options.color_by_distortion) y = svg_energy_legend(g, map, report, scale, options, x, y);
  g += "<rect x=\"" + svg_num(x) + "\" y=\"" + svg_num(y - 11) + "\" width=\"14\" height=\"14\" fill=\"" + options.flipped_color + "\"/>\n";
  svg_text(g, "", x + 22, y, "flipped");
  y += 20;
  g += "<rect x=\"" + svg_num(x) + "\" y=\"" + svg_num(y - 11) + "\" width=\"14\" height=\"14\" fill=\"none\" stroke=\""
     + options.degenerate_color + "\" stroke-width=\"2.5\"/>\n";
  svg_text(g, "", x + 22, y, "degenerate");
  y += 24;
  svg_text(g, "pe-count-faces", x, y, "faces: " + std::to_string(map.number_of_faces())); y += 17;
  svg_text(g, "pe-count-flipped", x, y, "flipped: " + std::to_string(map.flipped)); y += 17;
  svg_text(g, "pe-count-degenerate", x, y, "degenerate: " + std::to_string(map.degenerate)); y += 17;
  svg_text(g, "pe-count-non-finite", x, y, "non-finite vertices: " + std::to_string(map.non_finite_vertices)); y += 17;
  if(patches.present)
  {
    y += 7;
    if(!options.color_by_distortion) // the faces are filled by patch: three of the colors
      for(std::size_t k = 0; k < 3; ++k)
        g += "<rect x=\"" + svg_num(x + 5 * double(k)) + "\" y=\"" + svg_num(y - 11 + 2 * double(k)) + "\" width=\"10\" height=\"10\" fill=\""
           + svg_patch_color(k) + "\" stroke=\"#404040\" stroke-width=\"0.5\"/>\n";
    svg_text(g, "pe-count-patches", x + 22, y, "patches: " + std::to_string(patches.ids.size())); y += 20;
    g += "<line x1=\"" + svg_num(x) + "\" y1=\"" + svg_num(y - 4) + "\" x2=\"" + svg_num(x + 16) + "\" y2=\"" + svg_num(y - 4)
       + "\" stroke=\"#1a1a1a\" stroke-width=\"" + svg_number((std::max)(1., options.patch_border_width), 2) + "\"/>\n";
    svg_text(g, "", x + 22, y, "patch border"); y += 20;
  }
  if(!marked.empty())
  {
    g += "<circle cx=\"" + svg_num(x + 7) + "\" cy=\"" + svg_num(y - 4) + "\" r=\"4\" fill=\"#000000\" stroke=\"#ffffff\" stroke-width=\"1.5\"/>\n";
    svg_text(g, "pe-count-constrained", x + 22, y, "constrained vertices: " + std::to_string(marked.size())); y += 17;
  }
  g += "</g>\n";
  return y;
}

// The inset below the legend (whose bottom is `top`; returns the inset's bottom): the faces of the
// zoomed region at the inset's size, their markers, the frame, the region's rectangle in the main
// view (at least 10 pixels, to be seen) and the lines joining it to the inset.
inline double svg_inset(std::string& g, const Svg_map& map, const Svg_patches& patches, const std::vector<std::size_t>& marked,
                        const Svg_energy_scale& scale, const SVG_options& options, const Svg_layout& L, double top)
{
  const double S = options.inset_size;
  const double ix = L.col_x, iy = top + 30;
  const Svg_view inset = svg_inset_view(L, options, ix, iy);
  const double zoom = inset.scale / L.view.scale;
  const std::string frame = "x=\"" + svg_num(ix) + "\" y=\"" + svg_num(iy) + "\" width=\"" + svg_num(S) + "\" height=\"" + svg_num(S) + "\"";
  g += "<g id=\"pe-inset\">\n";
  g += "<text x=\"" + svg_num(ix) + "\" y=\"" + svg_num(iy - 8) + "\" font-family=\"sans-serif\" font-size=\"13\">zoom &#215;"
     + format_number(zoom, options.significant_digits) + " on the flipped and degenerate faces</text>\n";
  g += "<clipPath id=\"pe-inset-clip\"><rect " + frame + "/></clipPath>\n";
  g += "<rect " + frame + " fill=\"#ffffff\"/>\n";
  g += "<g clip-path=\"url(#pe-inset-clip)\">\n";
  g += svg_faces_layer(map, patches, scale, options, inset, 2.);
  // faces still too small to be seen at this zoom are marked as in the main view
  g += svg_markers_layer(map, marked, options, inset);
  g += "</g>\n";
  g += "<rect " + frame + " fill=\"none\" stroke=\"#000000\" stroke-width=\"1.5\"/>\n";
  double mx = L.view.X(L.rx0), my = L.view.Y(L.ry0 + L.side), mw = L.side * L.view.scale;
  if(!(mw >= 10)) { mx += 0.5 * mw - 5; my += 0.5 * mw - 5; mw = 10; }
  g += "<rect id=\"pe-inset-region\" x=\"" + svg_num(mx) + "\" y=\"" + svg_num(my) + "\" width=\"" + svg_num(mw) + "\" height=\""
     + svg_num(mw) + "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1.5\"/>\n";
  g += "<path d=\"M" + svg_num(mx + mw) + " " + svg_num(my) + "L" + svg_num(ix) + " " + svg_num(iy) + "M" + svg_num(mx + mw) + " " + svg_num(my + mw)
     + "L" + svg_num(ix) + " " + svg_num(iy + S) + "\" stroke=\"#000000\" stroke-opacity=\"0.5\" stroke-width=\"0.8\" stroke-dasharray=\"4 3\"/>\n";
  g += "</g>\n";
  return iy + S;
}

// The whole picture: the main view (faces, then markers), the legend and the inset in the column on
// its right, the title above.
inline std::string svg_picture(const Svg_map& map, const Svg_patches& patches, const std::vector<std::size_t>& marked,
                               const Embedding_report& report, const SVG_options& options)
{
  const Svg_energy_scale scale = options.color_by_distortion ? svg_energy_scale(map.kind, map.energy) : Svg_energy_scale();
  const Svg_layout L = svg_layout(map, options);
  std::string legend, inset;
  const double legend_bottom = svg_legend(legend, map, patches, marked, report, scale, options, L.col_x, L.view.oy);
  const double inset_bottom = L.has_inset ? svg_inset(inset, map, patches, marked, scale, options, L, legend_bottom) : legend_bottom;
  const double width = L.col_x + L.col_w + L.margin;
  const double height = (std::max)(L.view.oy + L.draw_h, inset_bottom) + L.margin;

  std::string s;
  s.reserve(4096 + map.number_of_faces() * 40);
  s += "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + svg_number(width, 0)
     + "\" height=\"" + svg_number(height, 0) + "\" viewBox=\"0 0 " + svg_number(width, 0)
     + " " + svg_number(height, 0) + "\">\n";
  const std::string title = svg_escape(options.title);
  if(!options.title.empty()) s += "<title>" + title + "</title>\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if(!options.title.empty())
    s += "<text x=\"" + svg_num(L.margin) + "\" y=\"" + svg_num(L.margin + 20) + "\" font-family=\"sans-serif\" font-size=\"20\">" + title + "</text>\n";
  s += "<g id=\"pe-faces\">\n";
  s += svg_faces_layer(map, patches, scale, options, L.view, 1.);
  s += "</g>\n";
  s += svg_markers_layer(map, marked, options, L.view);
  s += legend;
  s += inset;
  s += "</svg>\n";
  return s;
}

} // namespace internal
} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_LAYERS_H
