// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_TEXT_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_TEXT_H

// The text of an SVG file: numbers in fixed point, XML escapes, colors, path data. Independent of
// the C and C++ locales, so that a picture is the same file whatever the program's locale.

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace IO {
namespace internal {

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

// A point of path data: "x y", with `decimals` decimals.
inline void svg_append_point(std::string& d, const std::array<double, 2>& q, int decimals)
{
  svg_append(d, q[0], decimals); d += ' '; svg_append(d, q[1], decimals);
}

// A polygon as a closed subpath.
inline void svg_append_polygon(std::string& d, const std::vector<std::array<double, 2> >& poly, int decimals)
{
  for(std::size_t k = 0; k < poly.size(); ++k) { d += (k == 0 ? 'M' : 'L'); svg_append_point(d, poly[k], decimals); }
  if(!poly.empty()) d += 'Z';
}

// A polyline as an open subpath.
inline void svg_append_polyline(std::string& d, const std::vector<std::array<double, 2> >& line, int decimals)
{
  for(std::size_t k = 0; k < line.size(); ++k) { d += (k == 0 ? 'M' : 'L'); svg_append_point(d, line[k], decimals); }
}

} // namespace internal
} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_TEXT_H
