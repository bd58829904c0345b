// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_SVG_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_SVG_H

/// \file SVG.h
/// A picture of a uv layout: faces coloured by distortion, flipped and degenerate
/// faces highlighted, border, legend.

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/internal/symmetric_dirichlet.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
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
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace IO {

#ifndef DOXYGEN_RUNNING
namespace internal {

// fixed-point formatting, independent of the C and C++ locales
inline void svg_append(std::string& s, double x, int decimals = 2)
{
  char buf[64];
  if(!std::isfinite(x)) x = 0;
  if(std::abs(x) < 0.5 * std::pow(10.0, -decimals)) x = 0; // no "-0.00"
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

// Colour scale: YlGnBu, light (energy 4, the minimum) to dark (1e4 and above), log scale.
struct Svg_colour_map
{
  static constexpr int number_of_stops = 5;
  static const std::array<std::array<int, 3>, 5>& stops()
  {
    static const std::array<std::array<int, 3>, 5> s = {{
      {{0xff, 0xff, 0xd9}}, {{0xc7, 0xe9, 0xb4}}, {{0x41, 0xb6, 0xc4}}, {{0x22, 0x5e, 0xa8}}, {{0x08, 0x1d, 0x58}} }};
    return s;
  }
  static constexpr double e_min = 4.;
  static constexpr double e_max = 1e4;

  // position in [0,1] of an energy on the scale
  static double position(double e)
  {
    if(!(e > e_min)) return std::isnan(e) ? 1. : 0.;
    if(!(e < e_max)) return 1.;
    return std::log(e / e_min) / std::log(e_max / e_min);
  }

  static std::string hex(const std::array<int, 3>& c)
  {
    static const char* digits = "0123456789abcdef";
    std::string s = "#";
    for(int k = 0; k < 3; ++k) { s += digits[(c[k] >> 4) & 15]; s += digits[c[k] & 15]; }
    return s;
  }

  static std::string colour(double t)
  {
    if(!(t >= 0)) t = 0;
    if(t > 1) t = 1;
    const double x = t * (number_of_stops - 1);
    int i = int(std::floor(x));
    if(i >= number_of_stops - 1) i = number_of_stops - 2;
    const double a = x - i;
    std::array<int, 3> c;
    for(int k = 0; k < 3; ++k)
      c[k] = int(std::lround((1 - a) * stops()[i][k] + a * stops()[i + 1][k]));
    return hex(c);
  }
};

} // namespace internal
#endif // DOXYGEN_RUNNING

/// \ingroup PkgProgressiveEmbeddingIO
///
/// writes an SVG picture of the uv layout of `tm`, fit into a 1000 pixel box with the v axis up.
///
/// Each face is filled with a colour giving its symmetric Dirichlet energy
/// \f$ \|J\|^2 (1 + \det(J)^{-2}) \f$ with respect to an equilateral reference triangle whose area is
/// the mean absolute uv face area, on a logarithmic scale from 4 (the minimum, light) to \f$10^4\f$
/// and above (dark), computed in `double`. Faces whose exact orientation is opposite to that of the
/// majority of the faces (flipped) are filled red; faces with zero area (degenerate) are outlined
/// in magenta with a thick stroke; both also get a circle at their centroid so that they are visible
/// on large meshes. Edges are thin, border edges thick. A legend gives the colour scale and the
/// numbers of faces, flipped faces, degenerate faces, and faces with a non-finite coordinate (not drawn);
/// the counts are in `<text>` elements with the ids `pe-count-faces`, `pe-count-flipped`,
/// `pe-count-degenerate` and `pe-count-non-finite`.
///
/// \tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
/// \tparam VertexUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type
/// \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
///
/// \param out the output stream
/// \param tm the mesh
/// \param uvm the uv coordinates of the vertices of `tm`
/// \param title an optional title, drawn above the picture (escaped for XML)
/// \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the traits providing the exact orientation predicate}
///     \cgalParamType{a model of `ProgressiveEmbeddingTraits_2` whose `Point_2` is the value type of `uvm`}
///     \cgalParamDefault{`Progressive_embedding_traits_2<K>`, where `K` is the kernel of the value type of `uvm`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK`; `ERROR_EMPTY_MESH` if `tm` has no face, `ERROR_NON_TRIANGULAR_MESH` if a face
///         is not a triangle (nothing is written in both cases); `ERROR_CANNOT_WRITE_FILE` if the stream fails
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_SVG(std::ostream& out, const TriangleMesh& tm, VertexUVMap uvm,
                     const std::string& title = std::string(),
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
  typedef internal::Svg_colour_map                                       Colours;

  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const typename Traits::Exact_orientation_2 orientation = traits.exact_orientation_2_object();

  try
  {
    // vertices
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
      p.push_back({x, y});
      finite.push_back(std::isfinite(x) && std::isfinite(y));
    }

    // faces
    std::vector<std::array<std::size_t, 3> > tri;
    for(face_descriptor f : faces(tm))
    {
      std::array<std::size_t, 3> t;
      std::size_t k = 0;
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
      {
        if(k == 3) return ERROR_NON_TRIANGULAR_MESH;
        t[k++] = get(vid, target(h, tm));
      }
      if(k != 3) return ERROR_NON_TRIANGULAR_MESH;
      tri.push_back(t);
    }
    const std::size_t nf = tri.size();
    if(nf == 0) return ERROR_EMPTY_MESH;

    // exact orientations; 2 marks a face with a non-finite coordinate
    std::vector<int> sign(nf, 0);
    std::size_t n_pos = 0, n_neg = 0, n_nonfinite = 0;
    double area_sum = 0;
    for(std::size_t i = 0; i < nf; ++i)
    {
      const std::array<std::size_t, 3>& t = tri[i];
      if(!finite[t[0]] || !finite[t[1]] || !finite[t[2]]) { sign[i] = 2; ++n_nonfinite; continue; }
      const CGAL::Orientation o = orientation(uv[t[0]], uv[t[1]], uv[t[2]]);
      sign[i] = (o == CGAL::LEFT_TURN) ? 1 : (o == CGAL::RIGHT_TURN ? -1 : 0);
      if(sign[i] > 0) ++n_pos; else if(sign[i] < 0) ++n_neg;
      const double a = Progressive_embedding::internal::signed_area(p[t[0]][0], p[t[0]][1], p[t[1]][0], p[t[1]][1],
                                                                    p[t[2]][0], p[t[2]][1]);
      if(std::isfinite(a)) area_sum += std::abs(a);
    }
    const int majority = (n_neg > n_pos) ? -1 : 1;
    const std::size_t n_flipped = (majority > 0) ? n_neg : n_pos;
    const std::size_t n_degenerate = nf - n_pos - n_neg - n_nonfinite;
    const std::size_t n_finite_faces = nf - n_nonfinite;

    // energies, in double
    const double ref_area = n_finite_faces > 0 ? area_sum / double(n_finite_faces) : 0.;
    const Progressive_embedding::internal::Reference_triangle<double> ref =
      Progressive_embedding::internal::equilateral_reference<double>(ref_area, std::sqrt(3.));
    std::vector<double> energy(nf, std::numeric_limits<double>::infinity());
    double max_energy = 0;
    for(std::size_t i = 0; i < nf; ++i)
    {
      if(sign[i] != majority) continue;
      const std::array<std::size_t, 3>& t = tri[i];
      bool ok = false;
      double e = 0;
      if(ref_area > 0 && std::isfinite(ref_area))
        e = Progressive_embedding::internal::symmetric_dirichlet<double>(ref, p[t[0]][0], p[t[0]][1], p[t[1]][0], p[t[1]][1],
                                                                         p[t[2]][0], p[t[2]][1], ok);
      energy[i] = (ok && std::isfinite(e)) ? e : std::numeric_limits<double>::infinity();
      max_energy = std::max(max_energy, energy[i]);
    }

    // frame: the drawing fits a 1000 px box, v axis up
    double xmin = std::numeric_limits<double>::infinity(), ymin = xmin;
    double xmax = -xmin, ymax = -xmin;
    for(std::size_t i = 0; i < nf; ++i)
    {
      if(sign[i] == 2) continue;
      for(std::size_t v : tri[i])
      {
        xmin = std::min(xmin, p[v][0]); xmax = std::max(xmax, p[v][0]);
        ymin = std::min(ymin, p[v][1]); ymax = std::max(ymax, p[v][1]);
      }
    }
    if(!(xmin <= xmax)) { xmin = ymin = 0; xmax = ymax = 1; }
    const double box = 1000., margin = 20., legend_w = 230., legend_h = 400.;
    const double extent = std::max(xmax - xmin, ymax - ymin);
    double scale = (extent > 0 && std::isfinite(box / extent)) ? box / extent : 1.;
    if(!std::isfinite(scale * extent)) scale = 1.;
    const double draw_w = std::max(1., (xmax - xmin) * scale), draw_h = std::max(1., (ymax - ymin) * scale);
    const double title_h = title.empty() ? 0. : 36.;
    const double ox = margin, oy = margin + title_h;
    const double width = draw_w + 2 * margin + legend_w;
    const double height = std::max(draw_h, legend_h) + 2 * margin + title_h;
    auto X = [&](double x) { return ox + (x - xmin) * scale; };
    auto Y = [&](double y) { return oy + (ymax - y) * scale; };

    auto points = [&](std::string& s, const std::array<std::size_t, 3>& t) {
      s += "points=\"";
      for(int k = 0; k < 3; ++k)
      {
        if(k) s += ' ';
        internal::svg_append(s, X(p[t[k]][0])); s += ','; internal::svg_append(s, Y(p[t[k]][1]));
      }
      s += '"';
    };

    std::string s;
    s.reserve(200 + nf * 90);
    s += "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n";
    s += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + internal::svg_number(width, 0)
       + "\" height=\"" + internal::svg_number(height, 0) + "\" viewBox=\"0 0 " + internal::svg_number(width, 0)
       + " " + internal::svg_number(height, 0) + "\">\n";
    const std::string esc_title = internal::svg_escape(title);
    if(!title.empty()) s += "<title>" + esc_title + "</title>\n";
    s += "<defs><linearGradient id=\"pe-energy\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">";
    for(int k = 0; k < Colours::number_of_stops; ++k)
      s += "<stop offset=\"" + internal::svg_number(double(k) / (Colours::number_of_stops - 1)) + "\" stop-color=\""
         + Colours::hex(Colours::stops()[k]) + "\"/>";
    s += "</linearGradient></defs>\n";
    s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    if(!title.empty())
      s += "<text x=\"" + internal::svg_number(margin) + "\" y=\"" + internal::svg_number(margin + 20)
         + "\" font-family=\"sans-serif\" font-size=\"22\">" + esc_title + "</text>\n";

    // faces of the majority orientation, coloured by energy
    s += "<g id=\"pe-faces\" stroke=\"#404040\" stroke-width=\"0.3\" stroke-linejoin=\"round\">\n";
    for(std::size_t i = 0; i < nf; ++i)
    {
      if(sign[i] != majority) continue;
      s += "<polygon "; points(s, tri[i]);
      s += " fill=\"" + Colours::colour(Colours::position(energy[i])) + "\"/>\n";
    }
    s += "</g>\n";
    // flipped faces
    s += "<g id=\"pe-flipped\" fill=\"#ff0000\" stroke=\"#800000\" stroke-width=\"0.5\" stroke-linejoin=\"round\">\n";
    for(std::size_t i = 0; i < nf; ++i)
      if(sign[i] == -majority) { s += "<polygon "; points(s, tri[i]); s += "/>\n"; }
    s += "</g>\n";
    // border
    s += "<path id=\"pe-border\" fill=\"none\" stroke=\"#000000\" stroke-width=\"2\" stroke-linecap=\"round\" d=\"";
    for(halfedge_descriptor h : halfedges(tm))
    {
      if(!is_border(h, tm)) continue;
      const std::size_t a = get(vid, source(h, tm)), b = get(vid, target(h, tm));
      if(!finite[a] || !finite[b]) continue;
      s += 'M'; internal::svg_append(s, X(p[a][0])); s += ' '; internal::svg_append(s, Y(p[a][1]));
      s += 'L'; internal::svg_append(s, X(p[b][0])); s += ' '; internal::svg_append(s, Y(p[b][1]));
    }
    s += "\"/>\n";
    // degenerate faces
    s += "<g id=\"pe-degenerate\" fill=\"none\" stroke=\"#ff00ff\" stroke-width=\"3\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
    for(std::size_t i = 0; i < nf; ++i)
      if(sign[i] == 0) { s += "<polygon "; points(s, tri[i]); s += "/>\n"; }
    s += "</g>\n";
    // markers at the centroids of flipped and degenerate faces
    s += "<g id=\"pe-markers\" fill=\"none\" stroke-width=\"2\">\n";
    for(std::size_t i = 0; i < nf; ++i)
    {
      if(sign[i] == majority || sign[i] == 2) continue;
      const std::array<std::size_t, 3>& t = tri[i];
      const double cx = (X(p[t[0]][0]) + X(p[t[1]][0]) + X(p[t[2]][0])) / 3.;
      const double cy = (Y(p[t[0]][1]) + Y(p[t[1]][1]) + Y(p[t[2]][1])) / 3.;
      s += "<circle cx=\""; internal::svg_append(s, cx); s += "\" cy=\""; internal::svg_append(s, cy);
      s += (sign[i] == 0) ? "\" r=\"7\" stroke=\"#ff00ff\"/>\n" : "\" r=\"7\" stroke=\"#ff0000\"/>\n";
    }
    s += "</g>\n";

    // legend
    const double lx = ox + draw_w + 20, ly = oy;
    const double bar_x = lx + 14, bar_y = ly + 54, bar_w = 22, bar_h = 180;
    auto num = [](double x) { return internal::svg_number(x); };
    s += "<g id=\"pe-legend\" font-family=\"sans-serif\" font-size=\"13\">\n";
    s += "<rect x=\"" + num(lx) + "\" y=\"" + num(ly) + "\" width=\"" + num(legend_w - 30) + "\" height=\"" + num(legend_h)
       + "\" fill=\"#ffffff\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
    s += "<text x=\"" + num(lx + 10) + "\" y=\"" + num(ly + 18) + "\">symmetric Dirichlet</text>\n";
    s += "<text x=\"" + num(lx + 10) + "\" y=\"" + num(ly + 33) + "\">energy (log scale)</text>\n";
    s += "<rect x=\"" + num(bar_x) + "\" y=\"" + num(bar_y) + "\" width=\"" + num(bar_w) + "\" height=\"" + num(bar_h)
       + "\" fill=\"url(#pe-energy)\" stroke=\"#000000\" stroke-width=\"0.5\"/>\n";
    const double ticks[] = { 4., 10., 100., 1000., 1e4 };
    const char* labels[] = { "4 (isometry)", "10", "100", "1000", "&#8805; 10000" };
    for(int k = 0; k < 5; ++k)
    {
      const double ty = bar_y + bar_h - Colours::position(ticks[k]) * bar_h;
      s += "<line x1=\"" + num(bar_x + bar_w) + "\" y1=\"" + num(ty) + "\" x2=\"" + num(bar_x + bar_w + 6) + "\" y2=\""
         + num(ty) + "\" stroke=\"#000000\" stroke-width=\"1\"/>\n";
      s += "<text x=\"" + num(bar_x + bar_w + 10) + "\" y=\"" + num(ty + 4) + "\">" + labels[k] + "</text>\n";
    }
    double y = bar_y + bar_h + 28;
    s += "<rect x=\"" + num(bar_x) + "\" y=\"" + num(y - 11) + "\" width=\"14\" height=\"14\" fill=\"#ff0000\" stroke=\"#800000\"/>\n";
    s += "<text x=\"" + num(bar_x + 22) + "\" y=\"" + num(y) + "\">flipped</text>\n";
    y += 20;
    s += "<rect x=\"" + num(bar_x) + "\" y=\"" + num(y - 11) + "\" width=\"14\" height=\"14\" fill=\"none\" stroke=\"#ff00ff\" stroke-width=\"3\"/>\n";
    s += "<text x=\"" + num(bar_x + 22) + "\" y=\"" + num(y) + "\">degenerate</text>\n";
    y += 26;
    auto count_line = [&](const char* id, const std::string& text) {
      s += "<text id=\"" + std::string(id) + "\" x=\"" + num(lx + 10) + "\" y=\"" + num(y) + "\">" + text + "</text>\n";
      y += 17;
    };
    count_line("pe-count-faces", "faces: " + std::to_string(nf));
    count_line("pe-count-flipped", "flipped: " + std::to_string(n_flipped));
    count_line("pe-count-degenerate", "degenerate: " + std::to_string(n_degenerate));
    count_line("pe-count-non-finite", "non-finite: " + std::to_string(n_nonfinite));
    {
      char buf[64];
      std::string e;
      if(std::isfinite(max_energy))
      {
        const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), max_energy, std::chars_format::general, 4);
        e.assign(buf, r.ptr);
      }
      else e = "infinite";
      count_line("pe-max-energy", "max energy: " + e);
    }
    s += "</g>\n</svg>\n";

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
/// writes an SVG picture of the uv layout of `tm` to the file `filename`;
/// see the stream overload for the picture and the parameters.
///
/// \return as the stream overload; `ERROR_CANNOT_WRITE_FILE` if the file cannot be opened or written
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code write_SVG(const std::string& filename, const TriangleMesh& tm, VertexUVMap uvm,
                     const std::string& title = std::string(),
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  std::ofstream out(filename, std::ios::binary);
  if(!out) return ERROR_CANNOT_WRITE_FILE;
  const Error_code ec = write_SVG(out, tm, uvm, title, np);
  out.close();
  if(ec == OK && !out) return ERROR_CANNOT_WRITE_FILE;
  return ec;
}

} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_SVG_H
