// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_FRAME_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_FRAME_H

// Where things go in a picture: the views (uv to pixels, the inset's clipped to its box), the main
// view fit into the picture, the region the inset zooms on, and the column of the legend.

#include <CGAL/Progressive_embedding/IO/SVG_options.h>
#include <CGAL/Progressive_embedding/IO/internal/svg_map.h>

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

// A view: uv coordinates to pixels, v axis up. A clipped view (the inset) draws only what meets its
// box [x0, x1] x [y0, y1], cut 2 pixels outside it, so that the file holds no huge coordinates.
struct Svg_view
{
  double xmin = 0, ymax = 0, scale = 1, ox = 0, oy = 0;
  bool clipped = false;
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  double X(double x) const { return ox + (x - xmin) * scale; }
  double Y(double y) const { return oy + (ymax - y) * scale; }
  std::array<double, 2> operator()(const std::array<double, 2>& q) const { return {{ X(q[0]), Y(q[1]) }}; }

  // whether to draw the polygon or polyline `poly` (in pixels), clipped to the box
  bool keep(std::vector<std::array<double, 2> >& poly) const
  {
    if(!clipped) return true;
    const double inf = std::numeric_limits<double>::infinity();
    double a0 = inf, b0 = inf, a1 = -inf, b1 = -inf;
    for(const auto& q : poly) { a0 = (std::min)(a0, q[0]); a1 = (std::max)(a1, q[0]); b0 = (std::min)(b0, q[1]); b1 = (std::max)(b1, q[1]); }
    if(a1 < x0 - 2 || a0 > x1 + 2 || b1 < y0 - 2 || b0 > y1 + 2) return false;
    svg_clip(poly, x0 - 2, y0 - 2, x1 + 2, y1 + 2);
    return poly.size() >= 2;
  }

  // whether a marker at (x, y) (in pixels) is in the view
  bool visible(double x, double y) const { return !clipped || (x >= x0 && x <= x1 && y >= y0 && y <= y1); }
};

struct Svg_layout
{
  double margin = 20;
  Svg_view view;                    // the main view
  double draw_w = 1, draw_h = 1;    // its size in pixels
  double extent = 0;                // the larger side of the drawn faces' box, in uv
  bool has_inset = false;
  double rx0 = 0, ry0 = 0, side = 0; // the square the inset zooms on, in uv
  double col_x = 0, col_w = 0;      // the column of the legend and the inset
};

// The main view fits the finite faces into an `options.size` box below the title; the inset (if
// asked for) zooms on the bounding box of the flipped and degenerate faces.
inline Svg_layout svg_layout(const Svg_map& map, const SVG_options& options)
{
  const double inf = std::numeric_limits<double>::infinity();
  const std::size_t nf = map.number_of_faces();
  const std::vector<std::array<double, 2> >& p = map.p;
  Svg_layout L;
  double xmin = inf, ymin = inf, xmax = -inf, ymax = -inf;
  for(std::size_t i = 0; i < nf; ++i)
  {
    if(map.kind[i] == 2) continue;
    for(std::size_t v : map.tri[i])
    {
      xmin = (std::min)(xmin, p[v][0]); xmax = (std::max)(xmax, p[v][0]);
      ymin = (std::min)(ymin, p[v][1]); ymax = (std::max)(ymax, p[v][1]);
    }
  }
  if(!(xmin <= xmax)) { xmin = ymin = 0; xmax = ymax = 1; }
  const double box = options.size;
  L.extent = (std::max)(xmax - xmin, ymax - ymin);
  double scale = (L.extent > 0 && std::isfinite(box / L.extent)) ? box / L.extent : 1.;
  if(!std::isfinite(scale * L.extent)) scale = 1.;
  L.draw_w = (std::max)(1., (xmax - xmin) * scale);
  L.draw_h = (std::max)(1., (ymax - ymin) * scale);
  const double title_h = options.title.empty() ? 0. : 36.;
  L.view.xmin = xmin; L.view.ymax = ymax; L.view.scale = scale; L.view.ox = L.margin; L.view.oy = L.margin + title_h;

  if(options.inset)
  {
    double bx0 = inf, by0 = inf, bx1 = -inf, by1 = -inf;
    for(std::size_t i = 0; i < nf; ++i)
    {
      if(map.kind[i] != 0 && map.kind[i] != -1) continue;
      for(std::size_t v : map.tri[i])
      {
        bx0 = (std::min)(bx0, p[v][0]); bx1 = (std::max)(bx1, p[v][0]);
        by0 = (std::min)(by0, p[v][1]); by1 = (std::max)(by1, p[v][1]);
      }
    }
    if(bx0 <= bx1)
    {
      L.has_inset = true;
      L.side = 1.3 * (std::max)(bx1 - bx0, by1 - by0); // a margin of context around the faces
      if(!(L.side > 0)) L.side = L.extent > 0 ? L.extent * 1e-6 : 1.;
      const double cx = 0.5 * (bx0 + bx1), cy = 0.5 * (by0 + by1);
      L.rx0 = cx - 0.5 * L.side; L.ry0 = cy - 0.5 * L.side;
    }
  }
  L.col_x = L.view.ox + L.draw_w + 24;
  L.col_w = (std::max)(250., L.has_inset ? options.inset_size : 0.);
  return L;
}

// The inset's view: the zoomed square into the `options.inset_size` box whose corner is (ix, iy).
inline Svg_view svg_inset_view(const Svg_layout& L, const SVG_options& options, double ix, double iy)
{
  const double S = options.inset_size;
  Svg_view v;
  v.xmin = L.rx0; v.ymax = L.ry0 + L.side; v.scale = S / L.side; v.ox = ix; v.oy = iy;
  v.clipped = true;
  v.x0 = ix; v.y0 = iy; v.x1 = ix + S; v.y1 = iy + S;
  return v;
}

} // namespace internal
} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_FRAME_H
