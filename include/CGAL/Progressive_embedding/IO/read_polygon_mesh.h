// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_READ_POLYGON_MESH_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_READ_POLYGON_MESH_H

/// \file read_polygon_mesh.h
/// Validating readers of triangle meshes in the OFF, OBJ, PLY and STL formats, whose memory is
/// bounded by what the file holds and which report the line of every fault.

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/IO/Read_result.h>
#include <CGAL/Progressive_embedding/IO/OBJ_with_uv.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>
#include <new>
#include <string>
#include <string_view>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include <sys/stat.h>

namespace CGAL {
namespace Progressive_embedding {
namespace IO {

#ifndef DOXYGEN_RUNNING
namespace internal {

// The content of a file once parsed: points and triangles, each with the line that defined it
// (0 in binary files).
struct Pm_soup
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::size_t> point_line;
  std::vector<std::array<std::size_t, 3> > faces;
  std::vector<std::size_t> face_line;
};

inline bool pm_fail(Read_result& r, Error_code c, std::size_t line, std::string msg)
{
  r.status = c;
  r.line = line;
  r.message = std::move(msg);
  return false;
}

// Line-by-line walk through an in-memory file. Lines end with '\n'; a final '\r' is dropped.
struct Pm_lines
{
  std::string_view buf;
  std::size_t pos = 0;
  std::size_t line = 0;

  explicit Pm_lines(std::string_view b, std::size_t start = 0, std::size_t first_line = 0)
    : buf(b), pos(start), line(first_line) { }

  bool next(std::string_view& l)
  {
    if(pos >= buf.size()) return false;
    std::size_t e = buf.find('\n', pos);
    if(e == std::string_view::npos) e = buf.size();
    l = buf.substr(pos, e - pos);
    pos = e + 1;
    ++line;
    if(!l.empty() && l.back() == '\r') l.remove_suffix(1);
    return true;
  }
};

inline std::string_view pm_strip_comment(std::string_view l, bool comments)
{
  if(!comments) return l;
  const std::size_t hash = l.find('#');
  return hash == std::string_view::npos ? l : l.substr(0, hash);
}

inline bool pm_has_content(std::string_view l)
{
  for(char ch : l) if(!obj_is_space(ch)) return true;
  return false;
}

// the next line with a token (comments removed if `comments`), split into tokens
inline bool pm_next_content(Pm_lines& c, std::vector<std::string_view>& tok, bool comments)
{
  std::string_view l;
  while(c.next(l))
  {
    obj_split(pm_strip_comment(l, comments), tok);
    if(!tok.empty()) return true;
  }
  return false;
}

// number of lines with content after the cursor: what the rest of the file can hold
inline std::size_t pm_count_content_lines(Pm_lines c, bool comments)
{
  std::size_t n = 0;
  std::string_view l;
  while(c.next(l))
    if(pm_has_content(pm_strip_comment(l, comments))) ++n;
  return n;
}

inline bool pm_parse_unsigned(std::string_view s, unsigned long long& k)
{
  if(s.empty() || s[0] == '-' || s[0] == '+') return false;
  const std::from_chars_result r = std::from_chars(s.data(), s.data() + s.size(), k);
  return r.ptr == s.data() + s.size() && r.ec == std::errc();
}

inline std::string pm_to_string(unsigned long long k) { return std::to_string(k); }

// Parses a coordinate; fills `r` (at `line`) and returns false on failure.
inline bool pm_coordinate(std::string_view t, double& d, Read_result& r, std::size_t line)
{
  const Obj_number st = obj_parse_double(t, d);
  if(st == Obj_number::NOT_A_NUMBER) return pm_fail(r, ERROR_MALFORMED_FILE, line, "not a number: " + obj_quote(t));
  if(st == Obj_number::NON_FINITE) return pm_fail(r, ERROR_NON_FINITE_COORDINATES, line, "non-finite coordinate: " + obj_quote(t));
  return true;
}

// ---------------------------------------------------------------------------
// OFF: a header keyword ([ST][C][N]OFF, optional), the counts "nv nf [ne]", then one vertex per
// line (x y z, then colours, normals or texture coordinates, ignored) and one face per line
// (degree, indices, then an optional colour, ignored).

inline bool off_parse(std::string_view buf, Pm_soup& s, Read_result& r)
{
  Pm_lines c(buf);
  std::vector<std::string_view> tok;
  if(!pm_next_content(c, tok, true)) return pm_fail(r, ERROR_EMPTY_MESH, 0, "the file is empty");
  std::size_t first = 0;
  {
    std::string_view kw = tok[0];
    unsigned long long dummy;
    if(!pm_parse_unsigned(kw, dummy))
    {
      if(kw.size() < 3 || kw.substr(kw.size() - 3) != "OFF")
        return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "not an OFF file: the header is " + obj_quote(kw));
      std::string_view prefix = kw.substr(0, kw.size() - 3);
      if(prefix.substr(0, 2) == "ST") prefix.remove_prefix(2);
      if(!prefix.empty() && prefix[0] == 'C') prefix.remove_prefix(1);
      if(!prefix.empty() && prefix[0] == 'N') prefix.remove_prefix(1);
      if(!prefix.empty())
        return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "unsupported OFF variant " + obj_quote(kw)
                       + " (only 3D [ST][C][N]OFF is read)");
      if(tok.size() > 1 && tok[1] == "BINARY")
        return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "binary OFF is not supported");
      first = 1;
      if(tok.size() == 1) // the counts are on the next line
      {
        if(!pm_next_content(c, tok, true))
          return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "the file ends before the vertex and face counts");
        first = 0;
      }
    }
  }
  const std::size_t header_line = c.line;
  if(tok.size() - first < 2 || tok.size() - first > 3)
    return pm_fail(r, ERROR_MALFORMED_FILE, header_line, "expected the counts 'vertices faces [edges]'");
  unsigned long long nv = 0, nf = 0, ne = 0;
  if(!pm_parse_unsigned(tok[first], nv) || !pm_parse_unsigned(tok[first + 1], nf)
     || (tok.size() - first == 3 && !pm_parse_unsigned(tok[first + 2], ne)))
    return pm_fail(r, ERROR_MALFORMED_FILE, header_line, "the counts are not non-negative integers");
  // Declared counts against what the rest of the file holds (one element per line), before any
  // allocation: a header declaring 10^9 elements in a short file is refused here.
  const std::size_t rest = pm_count_content_lines(c, true);
  if(nv > rest || nf > rest - nv)
    return pm_fail(r, ERROR_MALFORMED_FILE, header_line,
                   "the header declares " + pm_to_string(nv) + " vertices and " + pm_to_string(nf)
                   + " faces, but only " + std::to_string(rest) + " lines follow");
  s.points.reserve(std::size_t(nv));
  s.point_line.reserve(std::size_t(nv));
  for(unsigned long long i = 0; i < nv; ++i)
  {
    pm_next_content(c, tok, true); // exists: counted above
    if(tok.size() < 3) return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "a vertex needs 3 coordinates");
    std::array<double, 3> p;
    for(int k = 0; k < 3; ++k)
      if(!pm_coordinate(tok[std::size_t(k)], p[std::size_t(k)], r, c.line)) return false;
    s.points.push_back(p);
    s.point_line.push_back(c.line);
  }
  s.faces.reserve(std::size_t(nf));
  s.face_line.reserve(std::size_t(nf));
  for(unsigned long long i = 0; i < nf; ++i)
  {
    pm_next_content(c, tok, true);
    unsigned long long d = 0;
    if(!pm_parse_unsigned(tok[0], d))
      return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "the number of vertices of a face is not an integer: " + obj_quote(tok[0]));
    if(d > tok.size() - 1)
      return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "a face declares " + pm_to_string(d)
                     + " vertices, but the line holds " + std::to_string(tok.size() - 1) + " values");
    if(d != 3)
      return pm_fail(r, ERROR_NON_TRIANGULAR_MESH, c.line,
                     "face with " + pm_to_string(d) + " vertices; only triangles are supported");
    std::array<std::size_t, 3> f;
    for(std::size_t k = 0; k < 3; ++k)
    {
      unsigned long long v = 0;
      if(!pm_parse_unsigned(tok[k + 1], v))
        return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "vertex index is not a non-negative integer: " + obj_quote(tok[k + 1]));
      if(v >= nv)
        return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "vertex index " + pm_to_string(v) + " out of range (the file has "
                       + pm_to_string(nv) + " vertices)");
      f[k] = std::size_t(v);
    }
    s.faces.push_back(f);
    s.face_line.push_back(c.line);
  }
  return true;
}

// ---------------------------------------------------------------------------
// OBJ without texture coordinates: the statements of read_OBJ_with_uv() (same rules, same
// messages); faces may have any of the forms a, a/ta, a/ta/na, a//na, only `v` indices are used.

inline bool obj_plain_parse(std::string_view buf, Pm_soup& s, Read_result& r)
{
  Pm_lines c(buf);
  std::vector<std::string_view> tok, parts;
  std::string_view l;
  std::size_t n_vt = 0, n_vn = 0;
  struct Pending { std::size_t vt, vn, line; };  // largest 1-based vt and vn indices used by a face
  std::vector<Pending> checks;
  while(c.next(l))
  {
    obj_split(pm_strip_comment(l, true), tok);
    if(tok.empty()) continue;
    const std::string_view kw = tok[0];
    if(kw == "v" || kw == "vt")
    {
      const bool is_v = (kw == "v");
      const std::size_t min_n = is_v ? 3 : 2, max_n = is_v ? 7 : 3;
      if(tok.size() - 1 < min_n)
        return pm_fail(r, ERROR_MALFORMED_FILE, c.line,
                       std::string(is_v ? "'v'" : "'vt'") + " needs at least " + std::to_string(min_n) + " coordinates");
      if(tok.size() - 1 > max_n)
        return pm_fail(r, ERROR_MALFORMED_FILE, c.line,
                       std::string(is_v ? "'v'" : "'vt'") + " has more than " + std::to_string(max_n) + " values");
      std::array<double, 7> x{};
      for(std::size_t i = 1; i < tok.size(); ++i)
        if(!pm_coordinate(tok[i], x[i - 1], r, c.line)) return false;
      if(is_v) { s.points.push_back({{x[0], x[1], x[2]}}); s.point_line.push_back(c.line); }
      else ++n_vt;
    }
    else if(kw == "f")
    {
      const std::size_t n = tok.size() - 1;
      if(n == 0) return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "face without vertices");
      std::array<std::size_t, 3> f{};
      Pending p{0, 0, c.line};
      for(std::size_t i = 0; i < n; ++i)
      {
        const std::string_view corner = tok[i + 1];
        parts.clear();
        std::size_t b = 0;
        for(std::size_t j = 0; j <= corner.size(); ++j)
          if(j == corner.size() || corner[j] == '/') { parts.push_back(corner.substr(b, j - b)); b = j + 1; }
        if(parts.size() > 3)
          return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "face corner with more than three indices: " + obj_quote(corner));
        long long kv = 0, kt = 0, kn = 0;
        const bool has_t = parts.size() >= 2 && !parts[1].empty(), has_n = parts.size() == 3;
        if(!obj_parse_index(parts[0], kv) || (has_t && !obj_parse_index(parts[1], kt)) || (has_n && !obj_parse_index(parts[2], kn)))
          return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "face corner with a non-integer index: " + obj_quote(corner));
        std::size_t iv = 0, it = 0, in_ = 0;
        if(!obj_resolve(kv, s.points.size(), iv) || (has_t && !obj_resolve(kt, n_vt, it)) || (has_n && !obj_resolve(kn, n_vn, in_)))
          return pm_fail(r, ERROR_MALFORMED_FILE, c.line,
                         "face corner with index 0 or a relative index before the first element: " + obj_quote(corner));
        if(has_t) p.vt = (std::max)(p.vt, it + 1);
        if(has_n) p.vn = (std::max)(p.vn, in_ + 1);
        if(i < 3) f[i] = iv;
      }
      if(n != 3)
        return pm_fail(r, ERROR_NON_TRIANGULAR_MESH, c.line, "face with " + std::to_string(n) + " corners; only triangles are supported");
      s.faces.push_back(f);
      s.face_line.push_back(c.line);
      if(p.vt > n_vt || p.vn > n_vn) checks.push_back(p); // forward references: checked at the end
    }
    else if(kw == "vn") ++n_vn;
    else if(kw == "vp" || kw == "o" || kw == "g" || kw == "s" || kw == "usemtl" || kw == "mtllib") { }
    else return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "unsupported statement " + obj_quote(kw));
  }
  r.number_of_texture_coordinates = n_vt;
  for(const Pending& p : checks)
  {
    if(p.vt > n_vt)
      return pm_fail(r, ERROR_MALFORMED_FILE, p.line, "texture coordinate index " + std::to_string(p.vt)
                     + " out of range (the file has " + std::to_string(n_vt) + " 'vt')");
    if(p.vn > n_vn)
      return pm_fail(r, ERROR_MALFORMED_FILE, p.line, "normal index " + std::to_string(p.vn)
                     + " out of range (the file has " + std::to_string(n_vn) + " 'vn')");
  }
  for(std::size_t i = 0; i < s.faces.size(); ++i)
    for(std::size_t v : s.faces[i])
      if(v >= s.points.size())
        return pm_fail(r, ERROR_MALFORMED_FILE, s.face_line[i], "vertex index " + std::to_string(v + 1)
                       + " out of range (the file has " + std::to_string(s.points.size()) + " 'v')");
  return true;
}

// ---------------------------------------------------------------------------
// PLY (ascii, binary_little_endian, binary_big_endian): element "vertex" with scalar properties
// x, y, z; element "face" with a list property vertex_indices (or vertex_index). Other elements
// and properties are read and ignored. In ascii files, each element instance is one line.

enum class Ply_type { NONE, INT8, UINT8, INT16, UINT16, INT32, UINT32, FLOAT32, FLOAT64 };

inline Ply_type ply_type(std::string_view t)
{
  if(t == "char" || t == "int8") return Ply_type::INT8;
  if(t == "uchar" || t == "uint8") return Ply_type::UINT8;
  if(t == "short" || t == "int16") return Ply_type::INT16;
  if(t == "ushort" || t == "uint16") return Ply_type::UINT16;
  if(t == "int" || t == "int32") return Ply_type::INT32;
  if(t == "uint" || t == "uint32") return Ply_type::UINT32;
  if(t == "float" || t == "float32") return Ply_type::FLOAT32;
  if(t == "double" || t == "float64") return Ply_type::FLOAT64;
  return Ply_type::NONE;
}

inline std::size_t ply_size(Ply_type t)
{
  switch(t)
  {
    case Ply_type::INT8: case Ply_type::UINT8: return 1;
    case Ply_type::INT16: case Ply_type::UINT16: return 2;
    case Ply_type::INT32: case Ply_type::UINT32: case Ply_type::FLOAT32: return 4;
    case Ply_type::FLOAT64: return 8;
    default: return 0;
  }
}

inline bool ply_is_float(Ply_type t) { return t == Ply_type::FLOAT32 || t == Ply_type::FLOAT64; }

struct Ply_property
{
  std::string name;
  Ply_type type = Ply_type::NONE;        // the item type for a list
  Ply_type count_type = Ply_type::NONE;  // NONE: a scalar
  bool is_list() const { return count_type != Ply_type::NONE; }
};

struct Ply_element
{
  std::string name;
  unsigned long long count = 0;
  std::size_t line = 0;
  std::vector<Ply_property> properties;
};

// A value read from a binary body.
struct Ply_value { double d; long long i; bool is_float; };

inline Ply_value ply_read_binary(const unsigned char* p, Ply_type t, bool big_endian)
{
  unsigned char b[8];
  const std::size_t n = ply_size(t);
  for(std::size_t k = 0; k < n; ++k) b[k] = big_endian ? p[n - 1 - k] : p[k];
  Ply_value v{0., 0, false};
  switch(t)
  {
    case Ply_type::INT8: { std::int8_t x; std::memcpy(&x, b, 1); v.i = x; break; }
    case Ply_type::UINT8: { std::uint8_t x; std::memcpy(&x, b, 1); v.i = x; break; }
    case Ply_type::INT16: { std::int16_t x; std::memcpy(&x, b, 2); v.i = x; break; }
    case Ply_type::UINT16: { std::uint16_t x; std::memcpy(&x, b, 2); v.i = x; break; }
    case Ply_type::INT32: { std::int32_t x; std::memcpy(&x, b, 4); v.i = x; break; }
    case Ply_type::UINT32: { std::uint32_t x; std::memcpy(&x, b, 4); v.i = x; break; }
    case Ply_type::FLOAT32: { float x; std::memcpy(&x, b, 4); v.d = double(x); v.is_float = true; break; }
    case Ply_type::FLOAT64: { double x; std::memcpy(&x, b, 8); v.d = x; v.is_float = true; break; }
    default: break;
  }
  if(!v.is_float) v.d = double(v.i);
  return v;
}

inline bool ply_parse(std::string_view buf, Pm_soup& s, Read_result& r)
{
  if(buf.empty()) return pm_fail(r, ERROR_EMPTY_MESH, 0, "the file is empty");
  Pm_lines c(buf);
  std::vector<std::string_view> tok;
  std::string_view l;
  if(!c.next(l) || l != "ply") return pm_fail(r, ERROR_MALFORMED_FILE, 1, "not a PLY file: the first line is not 'ply'");
  int format = -1; // 0 ascii, 1 little endian, 2 big endian
  std::vector<Ply_element> elements;
  bool end = false;
  while(!end && c.next(l))
  {
    obj_split(l, tok);
    if(tok.empty()) continue;
    if(tok[0] == "comment" || tok[0] == "obj_info") continue;
    if(tok[0] == "format")
    {
      if(tok.size() != 3 || tok[2] != "1.0") return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "expected 'format <type> 1.0'");
      if(tok[1] == "ascii") format = 0;
      else if(tok[1] == "binary_little_endian") format = 1;
      else if(tok[1] == "binary_big_endian") format = 2;
      else return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "unknown PLY format " + obj_quote(tok[1]));
    }
    else if(tok[0] == "element")
    {
      Ply_element e;
      if(tok.size() != 3 || !pm_parse_unsigned(tok[2], e.count))
        return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "expected 'element <name> <count>'");
      e.name = std::string(tok[1]);
      e.line = c.line;
      elements.push_back(std::move(e));
    }
    else if(tok[0] == "property")
    {
      if(elements.empty()) return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "a property before any element");
      Ply_property p;
      if(tok.size() == 3 && (p.type = ply_type(tok[1])) != Ply_type::NONE) p.name = std::string(tok[2]);
      else if(tok.size() == 5 && tok[1] == "list" && (p.count_type = ply_type(tok[2])) != Ply_type::NONE
              && !ply_is_float(p.count_type) && (p.type = ply_type(tok[3])) != Ply_type::NONE)
        p.name = std::string(tok[4]);
      else return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "malformed or unsupported property declaration");
      elements.back().properties.push_back(p);
    }
    else if(tok[0] == "end_header") end = true;
    else return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "unknown header keyword " + obj_quote(tok[0]));
  }
  if(!end) return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "the header has no 'end_header'");
  if(format < 0) return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "the header has no 'format' line");
  const std::size_t header_end_line = c.line;
  const std::size_t body = (std::min)(c.pos, buf.size());

  // where x, y, z and the face indices are
  const Ply_element* ve = nullptr;
  const Ply_element* fe = nullptr;
  for(const Ply_element& e : elements)
  {
    if(e.name == "vertex" && ve == nullptr) ve = &e;
    if(e.name == "face" && fe == nullptr) fe = &e;
  }
  std::array<int, 3> xyz = {{-1, -1, -1}};
  int fidx = -1;
  if(ve != nullptr)
    for(std::size_t k = 0; k < ve->properties.size(); ++k)
    {
      const Ply_property& p = ve->properties[k];
      for(int a = 0; a < 3; ++a)
        if(!p.is_list() && p.name == std::string(1, char('x' + a))) xyz[std::size_t(a)] = int(k);
    }
  if(fe != nullptr)
    for(std::size_t k = 0; k < fe->properties.size(); ++k)
      if(fe->properties[k].is_list() && (fe->properties[k].name == "vertex_indices" || fe->properties[k].name == "vertex_index"))
        fidx = int(k);
  if(fe == nullptr || fe->count == 0) return pm_fail(r, ERROR_EMPTY_MESH, 0, "the file has no face");
  if(ve == nullptr) return pm_fail(r, ERROR_MALFORMED_FILE, fe->line, "faces but no 'vertex' element");
  if(xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0)
    return pm_fail(r, ERROR_MALFORMED_FILE, ve->line, "the 'vertex' element has no scalar properties x, y and z");
  if(fidx < 0) return pm_fail(r, ERROR_MALFORMED_FILE, fe->line, "the 'face' element has no list property 'vertex_indices'");
  const unsigned long long nv = ve->count;

  // Declared counts against the rest of the file, before any allocation.
  if(format == 0)
  {
    const std::size_t rest = pm_count_content_lines(c, false);
    unsigned long long used = 0;
    for(const Ply_element& e : elements)
    {
      if(e.properties.empty()) continue; // nothing to read
      if(e.count > rest - used)
        return pm_fail(r, ERROR_MALFORMED_FILE, e.line, "element '" + e.name + "' declares " + pm_to_string(e.count)
                       + " instances, but only " + std::to_string(rest - used) + " lines remain");
      used += e.count;
    }
  }
  else
  {
    const std::size_t rest = buf.size() - body;
    unsigned long long used = 0;
    for(const Ply_element& e : elements)
    {
      std::size_t minimum = 0; // bytes of an instance whose lists are empty
      for(const Ply_property& p : e.properties) minimum += p.is_list() ? ply_size(p.count_type) : ply_size(p.type);
      if(minimum == 0) continue;
      if(e.count > (rest - used) / minimum)
        return pm_fail(r, ERROR_MALFORMED_FILE, e.line, "element '" + e.name + "' declares " + pm_to_string(e.count)
                       + " instances of at least " + std::to_string(minimum) + " bytes, but only "
                       + std::to_string(rest - used) + " bytes remain");
      used += e.count * minimum;
    }
  }

  s.points.reserve(std::size_t(nv));
  s.point_line.reserve(std::size_t(nv));
  s.faces.reserve(std::size_t(fe->count));
  s.face_line.reserve(std::size_t(fe->count));
  const bool big = (format == 2);
  Pm_lines bc(buf, body, header_end_line);
  std::size_t off = body;
  for(const Ply_element& e : elements)
  {
    if(e.properties.empty()) continue;
    const bool is_v = (&e == ve), is_f = (&e == fe);
    for(unsigned long long i = 0; i < e.count; ++i)
    {
      std::array<double, 3> p{};
      std::array<std::size_t, 3> f{};
      if(format == 0)
      {
        std::string_view line;
        do { bc.next(line); obj_split(line, tok); } while(tok.empty()); // a line exists: counted above
        std::size_t t = 0;
        for(std::size_t k = 0; k < e.properties.size(); ++k)
        {
          const Ply_property& pr = e.properties[k];
          std::size_t n = 1;
          if(pr.is_list())
          {
            unsigned long long d = 0;
            if(t >= tok.size() || !pm_parse_unsigned(tok[t], d))
              return pm_fail(r, ERROR_MALFORMED_FILE, bc.line, "missing or invalid list length for property '" + pr.name + "'");
            ++t;
            if(d > tok.size() - t)
              return pm_fail(r, ERROR_MALFORMED_FILE, bc.line, "list '" + pr.name + "' declares " + pm_to_string(d)
                             + " values, but the line holds " + std::to_string(tok.size() - t));
            n = std::size_t(d);
            if(is_f && int(k) == fidx && n != 3)
              return pm_fail(r, ERROR_NON_TRIANGULAR_MESH, bc.line, "face with " + std::to_string(n) + " vertices; only triangles are supported");
          }
          else if(t >= tok.size())
            return pm_fail(r, ERROR_MALFORMED_FILE, bc.line, "too few values for element '" + e.name + "'");
          for(std::size_t j = 0; j < n; ++j, ++t)
          {
            const std::string_view v = tok[t];
            const bool wanted = (is_v && (int(k) == xyz[0] || int(k) == xyz[1] || int(k) == xyz[2])) || (is_f && int(k) == fidx);
            double d = 0;
            long long q = 0;
            if(ply_is_float(pr.type))
            {
              if(wanted && is_v) { if(!pm_coordinate(v, d, r, bc.line)) return false; }
              else if(obj_parse_double(v, d) == Obj_number::NOT_A_NUMBER)
                return pm_fail(r, ERROR_MALFORMED_FILE, bc.line, "not a number: " + obj_quote(v));
            }
            else
            {
              if(!obj_parse_index(v, q))
                return pm_fail(r, ERROR_MALFORMED_FILE, bc.line, "not an integer: " + obj_quote(v));
              d = double(q);
            }
            if(!wanted) continue;
            if(is_v) p[std::size_t(int(k) == xyz[0] ? 0 : int(k) == xyz[1] ? 1 : 2)] = d;
            else
            {
              if(ply_is_float(pr.type) || q < 0 || (unsigned long long)(q) >= nv)
                return pm_fail(r, ERROR_MALFORMED_FILE, bc.line, "vertex index " + obj_quote(v) + " out of range (the file has "
                               + pm_to_string(nv) + " vertices)");
              f[j] = std::size_t(q);
            }
          }
        }
        if(t != tok.size())
          return pm_fail(r, ERROR_MALFORMED_FILE, bc.line, "too many values for element '" + e.name + "'");
        if(is_v) { s.points.push_back(p); s.point_line.push_back(bc.line); }
        if(is_f) { s.faces.push_back(f); s.face_line.push_back(bc.line); }
      }
      else
      {
        const unsigned char* data = reinterpret_cast<const unsigned char*>(buf.data());
        for(std::size_t k = 0; k < e.properties.size(); ++k)
        {
          const Ply_property& pr = e.properties[k];
          std::size_t n = 1;
          if(pr.is_list())
          {
            const std::size_t cs = ply_size(pr.count_type);
            if(cs > buf.size() - off)
              return pm_fail(r, ERROR_MALFORMED_FILE, 0, "the file ends inside element '" + e.name + "' at byte offset " + std::to_string(off));
            const Ply_value cv = ply_read_binary(data + off, pr.count_type, big);
            if(cv.i < 0)
              return pm_fail(r, ERROR_MALFORMED_FILE, 0, "negative list length at byte offset " + std::to_string(off));
            if((unsigned long long)(cv.i) > (buf.size() - off - cs) / ply_size(pr.type))
              return pm_fail(r, ERROR_MALFORMED_FILE, 0, "list '" + pr.name + "' at byte offset " + std::to_string(off) + " declares "
                             + std::to_string(cv.i) + " values, more than the rest of the file holds");
            if(is_f && int(k) == fidx && cv.i != 3)
              return pm_fail(r, ERROR_NON_TRIANGULAR_MESH, 0, "face with " + std::to_string(cv.i)
                             + " vertices at byte offset " + std::to_string(off) + "; only triangles are supported");
            off += cs;
            n = std::size_t(cv.i);
          }
          const std::size_t sz = ply_size(pr.type);
          for(std::size_t j = 0; j < n; ++j)
          {
            if(sz > buf.size() - off)
              return pm_fail(r, ERROR_MALFORMED_FILE, 0, "the file ends inside element '" + e.name + "' at byte offset " + std::to_string(off));
            const Ply_value v = ply_read_binary(data + off, pr.type, big);
            if(is_v && (int(k) == xyz[0] || int(k) == xyz[1] || int(k) == xyz[2]))
            {
              if(!std::isfinite(v.d))
                return pm_fail(r, ERROR_NON_FINITE_COORDINATES, 0, "non-finite coordinate at byte offset " + std::to_string(off));
              p[std::size_t(int(k) == xyz[0] ? 0 : int(k) == xyz[1] ? 1 : 2)] = v.d;
            }
            else if(is_f && int(k) == fidx)
            {
              if(v.is_float || v.i < 0 || (unsigned long long)(v.i) >= nv)
                return pm_fail(r, ERROR_MALFORMED_FILE, 0, "vertex index out of range at byte offset " + std::to_string(off)
                               + " (the file has " + pm_to_string(nv) + " vertices)");
              f[j] = std::size_t(v.i);
            }
            off += sz;
          }
        }
        if(is_v) { s.points.push_back(p); s.point_line.push_back(0); }
        if(is_f) { s.faces.push_back(f); s.face_line.push_back(0); }
      }
    }
  }
  return true;
}

// ---------------------------------------------------------------------------
// STL, ascii or binary. Corners with equal coordinates are one vertex.

struct Stl_points
{
  std::map<std::array<double, 3>, std::size_t> index;
  std::size_t get(Pm_soup& s, std::array<double, 3> p, std::size_t line)
  {
    for(double& x : p) x += 0.; // -0 and +0 are one point
    const auto it = index.emplace(p, s.points.size());
    if(it.second) { s.points.push_back(p); s.point_line.push_back(line); }
    return it.first->second;
  }
};

inline bool stl_binary_parse(std::string_view buf, Pm_soup& s, Read_result& r)
{
  if(buf.size() < 84)
    return pm_fail(r, ERROR_MALFORMED_FILE, 0, "binary STL shorter than its 84-byte header");
  const unsigned char* data = reinterpret_cast<const unsigned char*>(buf.data());
  const std::uint32_t n = std::uint32_t(data[80]) | (std::uint32_t(data[81]) << 8) | (std::uint32_t(data[82]) << 16)
                        | (std::uint32_t(data[83]) << 24);
  if(n > (buf.size() - 84) / 50)
    return pm_fail(r, ERROR_MALFORMED_FILE, 0, "the header (byte offset 80) declares " + std::to_string(n)
                   + " triangles, but the file holds at most " + std::to_string((buf.size() - 84) / 50));
  if(n == 0) return pm_fail(r, ERROR_EMPTY_MESH, 0, "the file has no face");
  Stl_points pts;
  s.faces.reserve(n);
  s.face_line.reserve(n);
  for(std::uint32_t i = 0; i < n; ++i)
  {
    const std::size_t base = 84 + std::size_t(i) * 50 + 12; // after the normal
    std::array<std::size_t, 3> f;
    for(std::size_t k = 0; k < 3; ++k)
    {
      std::array<double, 3> p;
      for(std::size_t a = 0; a < 3; ++a)
      {
        const std::size_t o = base + 12 * k + 4 * a;
        p[a] = ply_read_binary(data + o, Ply_type::FLOAT32, false).d;
        if(!std::isfinite(p[a]))
          return pm_fail(r, ERROR_NON_FINITE_COORDINATES, 0, "non-finite coordinate at byte offset " + std::to_string(o));
      }
      f[k] = pts.get(s, p, 0);
    }
    s.faces.push_back(f);
    s.face_line.push_back(0);
  }
  return true;
}

inline bool stl_ascii_parse(std::string_view buf, Pm_soup& s, Read_result& r)
{
  Pm_lines c(buf);
  std::vector<std::string_view> tok;
  Stl_points pts;
  enum { OUTSIDE, SOLID, FACET, LOOP, LOOP_DONE } state = OUTSIDE;
  std::array<std::size_t, 3> f{};
  std::size_t corners = 0, facet_line = 0;
  while(pm_next_content(c, tok, false))
  {
    const std::string_view kw = tok[0];
    auto unexpected = [&]() { return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "unexpected " + obj_quote(kw)); };
    if(kw == "solid") { if(state != OUTSIDE) return unexpected(); state = SOLID; }
    else if(kw == "endsolid") { if(state != SOLID) return unexpected(); state = OUTSIDE; }
    else if(kw == "facet")
    {
      if(state != SOLID) return unexpected();
      state = FACET; facet_line = c.line;
    }
    else if(kw == "outer")
    {
      if(state != FACET || tok.size() != 2 || tok[1] != "loop") return unexpected();
      state = LOOP; corners = 0;
    }
    else if(kw == "vertex")
    {
      if(state != LOOP) return unexpected();
      if(corners == 3)
        return pm_fail(r, ERROR_NON_TRIANGULAR_MESH, c.line, "facet with more than 3 vertices; only triangles are supported");
      if(tok.size() != 4) return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "'vertex' needs 3 coordinates");
      std::array<double, 3> p;
      for(std::size_t a = 0; a < 3; ++a)
        if(!pm_coordinate(tok[a + 1], p[a], r, c.line)) return false;
      f[corners++] = pts.get(s, p, c.line);
    }
    else if(kw == "endloop")
    {
      if(state != LOOP) return unexpected();
      if(corners != 3)
        return pm_fail(r, ERROR_NON_TRIANGULAR_MESH, c.line, "facet with " + std::to_string(corners)
                       + " vertices; only triangles are supported");
      state = LOOP_DONE;
    }
    else if(kw == "endfacet")
    {
      if(state != LOOP_DONE) return unexpected();
      s.faces.push_back(f);
      s.face_line.push_back(facet_line);
      state = SOLID;
    }
    else return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "unknown STL keyword " + obj_quote(kw));
  }
  if(state == OUTSIDE && c.line == 0) return pm_fail(r, ERROR_EMPTY_MESH, 0, "the file is empty");
  if(state != OUTSIDE && state != SOLID)
    return pm_fail(r, ERROR_MALFORMED_FILE, c.line, "the file ends inside a facet");
  return true;
}

inline bool stl_parse(std::string_view buf, Pm_soup& s, Read_result& r)
{
  if(buf.empty()) return pm_fail(r, ERROR_EMPTY_MESH, 0, "the file is empty");
  // binary if the size matches the declared count; otherwise ascii if it starts with "solid"
  if(buf.size() >= 84)
  {
    const unsigned char* d = reinterpret_cast<const unsigned char*>(buf.data());
    const std::uint64_t n = std::uint64_t(d[80]) | (std::uint64_t(d[81]) << 8) | (std::uint64_t(d[82]) << 16) | (std::uint64_t(d[83]) << 24);
    if(84 + 50 * n == buf.size()) return stl_binary_parse(buf, s, r);
  }
  std::size_t i = 0;
  while(i < buf.size() && (obj_is_space(buf[i]) || buf[i] == '\n')) ++i;
  if(buf.substr(i, 5) == "solid") return stl_ascii_parse(buf, s, r);
  return stl_binary_parse(buf, s, r);
}

// ---------------------------------------------------------------------------
// From a soup to a mesh: the topological checks, with the line of the first offending element.

// true if the faces around `v` form one fan (one path or one cycle of link edges)
inline bool pm_vertex_is_manifold(std::size_t v, const std::vector<std::size_t>& incident,
                                  const std::vector<std::array<std::size_t, 3> >& faces,
                                  std::vector<std::size_t>& link, std::vector<std::size_t>& parent)
{
  link.clear();
  for(std::size_t f : incident)
    for(std::size_t k = 0; k < 3; ++k)
      if(faces[f][k] != v) link.push_back(faces[f][k]);
  std::sort(link.begin(), link.end());
  link.erase(std::unique(link.begin(), link.end()), link.end());
  parent.resize(link.size());
  for(std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto find = [&](std::size_t x) {
    while(parent[x] != x) { parent[x] = parent[parent[x]]; x = parent[x]; }
    return x;
  };
  std::size_t components = link.size();
  for(std::size_t f : incident)
  {
    std::size_t a = 0, b = 0, k = 0;
    for(std::size_t j = 0; j < 3; ++j)
      if(faces[f][j] != v) (k++ == 0 ? a : b) = faces[f][j];
    const std::size_t ia = std::size_t(std::lower_bound(link.begin(), link.end(), a) - link.begin());
    const std::size_t ib = std::size_t(std::lower_bound(link.begin(), link.end(), b) - link.begin());
    const std::size_t ra = find(ia), rb = find(ib);
    if(ra != rb) { parent[ra] = rb; --components; }
  }
  return components == 1;
}

inline bool pm_check_topology(Pm_soup& s, Read_result& r)
{
  const std::size_t nf = s.faces.size();
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  // repeated vertex in a face
  for(std::size_t i = 0; i < nf; ++i)
  {
    const auto& f = s.faces[i];
    if(f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
      return pm_fail(r, ERROR_NON_MANIFOLD, s.face_line[i], "face with a repeated vertex");
  }
  // duplicate faces (same vertices, any order)
  {
    std::vector<std::pair<std::array<std::size_t, 3>, std::size_t> > sorted(nf);
    for(std::size_t i = 0; i < nf; ++i)
    {
      sorted[i].first = s.faces[i];
      std::sort(sorted[i].first.begin(), sorted[i].first.end());
      sorted[i].second = i;
    }
    std::sort(sorted.begin(), sorted.end());
    std::size_t worst = none, other = none;
    for(std::size_t i = 1; i < nf; ++i)
      if(sorted[i].first == sorted[i - 1].first && (worst == none || sorted[i].second < worst))
      { worst = sorted[i].second; other = sorted[i - 1].second; }
    if(worst != none)
      return pm_fail(r, ERROR_NON_MANIFOLD, s.face_line[worst], "duplicate face (the same vertices as face "
                     + std::to_string(other + 1) + " of the file, counting from 1" + (s.face_line[other] ? ", line " + std::to_string(s.face_line[other]) : std::string())
                     + ")");
  }
  // edges: at most two faces, used in opposite directions
  std::size_t misoriented = none;
  {
    std::vector<std::tuple<std::size_t, std::size_t, std::size_t, bool> > edges; // (min, max, face, forward)
    edges.reserve(3 * nf);
    for(std::size_t i = 0; i < nf; ++i)
      for(std::size_t k = 0; k < 3; ++k)
      {
        const std::size_t a = s.faces[i][k], b = s.faces[i][(k + 1) % 3];
        edges.emplace_back((std::min)(a, b), (std::max)(a, b), i, a < b);
      }
    std::sort(edges.begin(), edges.end());
    std::size_t worst = none;
    for(std::size_t i = 0; i < edges.size(); )
    {
      std::size_t j = i;
      while(j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i]) && std::get<1>(edges[j]) == std::get<1>(edges[i])) ++j;
      if(j - i > 2) worst = (std::min)(worst, std::get<2>(edges[i + 2])); // the third face (file order)
      else if(j - i == 2 && std::get<3>(edges[i]) == std::get<3>(edges[i + 1]))
        misoriented = (std::min)(misoriented, std::get<2>(edges[i + 1]));
      i = j;
    }
    if(worst != none)
      return pm_fail(r, ERROR_NON_MANIFOLD, s.face_line[worst], "non-manifold edge: this face is the third face on one of its edges");
  }
  // inconsistent orientation: reoriented when possible
  if(misoriented != none)
  {
    std::vector<std::array<double, 3> > points = s.points;
    std::vector<std::vector<std::size_t> > polygons(nf);
    for(std::size_t i = 0; i < nf; ++i) polygons[i].assign(s.faces[i].begin(), s.faces[i].end());
    bool ok = false;
    try { ok = CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons); }
    catch(const std::bad_alloc&) { throw; }
    catch(...) { ok = false; }
    if(!ok || points.size() != s.points.size())
      return pm_fail(r, ERROR_NON_MANIFOLD, s.face_line[misoriented],
                     "inconsistent face orientation that cannot be fixed (a non-orientable surface or a non-manifold vertex)");
    for(std::size_t i = 0; i < nf; ++i)
      for(std::size_t k = 0; k < 3; ++k) s.faces[i][k] = polygons[i][k];
    r.reoriented = true;
  }
  // non-manifold vertices (two fans meeting at a vertex)
  {
    const std::size_t np = s.points.size();
    std::vector<std::size_t> start(np + 1, 0), incident(3 * nf);
    for(const auto& f : s.faces) for(std::size_t v : f) ++start[v + 1];
    for(std::size_t v = 0; v < np; ++v) start[v + 1] += start[v];
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for(std::size_t i = 0; i < nf; ++i) for(std::size_t v : s.faces[i]) incident[fill[v]++] = i;
    std::vector<std::size_t> link, parent, around;
    for(std::size_t v = 0; v < np; ++v)
    {
      if(start[v] == start[v + 1]) continue;
      around.assign(incident.begin() + std::ptrdiff_t(start[v]), incident.begin() + std::ptrdiff_t(start[v + 1]));
      if(!pm_vertex_is_manifold(v, around, s.faces, link, parent))
        return pm_fail(r, ERROR_NON_MANIFOLD, s.point_line[v], "non-manifold vertex (vertex " + std::to_string(v + 1)
                       + " of the file, counting from 1): two or more fans of faces meet there");
    }
  }
  return true;
}

inline std::string pm_lower_extension(const std::string& filename)
{
  const std::size_t slash = filename.find_last_of('/');
  const std::size_t dot = filename.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash)) return std::string();
  std::string e = filename.substr(dot + 1);
  for(char& ch : e) if(ch >= 'A' && ch <= 'Z') ch = char(ch - 'A' + 'a');
  return e;
}

// reads the whole stream; false on a read error
inline bool pm_slurp(std::istream& in, std::string& buf)
{
  char chunk[1 << 16];
  while(in)
  {
    in.read(chunk, sizeof chunk);
    buf.append(chunk, std::size_t(in.gcount()));
  }
  return !in.bad();
}

// Reads the file; returns "" or the reason of the failure.
inline std::string pm_read_file(const std::string& filename, std::string& buf)
{
  struct stat st;
  if(::stat(filename.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    return "cannot read '" + filename + "': " + std::strerror(EISDIR);
  errno = 0;
  std::FILE* f = std::fopen(filename.c_str(), "rb");
  if(f == nullptr) return "cannot open '" + filename + "': " + std::strerror(errno != 0 ? errno : ENOENT);
  if(S_ISREG(st.st_mode) && st.st_size > 0) buf.reserve(std::size_t(st.st_size)); // the real size, not a declared one
  char chunk[1 << 16];
  std::size_t n = 0;
  errno = 0;
  while((n = std::fread(chunk, 1, sizeof chunk, f)) > 0) buf.append(chunk, n);
  const int err = errno;
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if(failed) return "cannot read '" + filename + "': " + std::strerror(err != 0 ? err : EIO);
  return std::string();
}

template <class PolygonMesh, class NamedParameters>
Read_result pm_read_buffer(const std::string& buf, const std::string& format, PolygonMesh& pm, const NamedParameters& np)
{
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, NamedParameters>::type  VPM;
  typedef typename boost::property_traits<VPM>::value_type                     Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel::FT                    FT;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Progressive_embedding::internal::make_ft;

  Read_result r;
  Pm_soup s;
  bool ok = false;
  const std::string_view view(buf);
  if(format == "off") ok = off_parse(view, s, r);
  else if(format == "obj") ok = obj_plain_parse(view, s, r);
  else if(format == "ply") ok = ply_parse(view, s, r);
  else if(format == "stl") ok = stl_parse(view, s, r);
  else
  {
    pm_fail(r, ERROR_MALFORMED_FILE, 0, "unknown format '" + format + "' (OFF, OBJ, PLY or STL expected)");
    return r;
  }
  r.number_of_positions = s.points.size();
  r.number_of_faces = s.faces.size();
  if(!ok) return r;
  if(s.faces.empty()) { pm_fail(r, ERROR_EMPTY_MESH, 0, "the file has no face"); return r; }
  if(!pm_check_topology(s, r)) return r;

  // unreferenced vertices are dropped, as read_OBJ_with_uv() drops unreferenced `vt`
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> new_index(s.points.size(), none);
  for(const auto& f : s.faces) for(std::size_t v : f) new_index[v] = 0;
  std::vector<Point_3> points;
  for(std::size_t v = 0; v < s.points.size(); ++v)
  {
    if(new_index[v] == none) { ++r.number_of_unreferenced_vertices; continue; }
    new_index[v] = points.size();
    points.push_back(Point_3(make_ft<FT>(s.points[v][0]), make_ft<FT>(s.points[v][1]), make_ft<FT>(s.points[v][2])));
  }
  for(auto& f : s.faces) for(std::size_t& v : f) v = new_index[v];
  // pm_check_topology() proved CGAL's condition on the faces as read (distinct vertices, each edge in at most
  // two faces and in opposite directions, manifold vertices); after a reorientation CGAL checks it again
  if(r.reoriented && !CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(s.faces))
  {
    pm_fail(r, ERROR_NON_MANIFOLD, 0, "the faces do not form a manifold polygon mesh");
    return r;
  }
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, pm));
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, s.faces, pm, CGAL::parameters::default_values(),
                                                              CGAL::parameters::vertex_point_map(vpm));
  if(std::size_t(std::distance(faces(pm).first, faces(pm).second)) != s.faces.size())
  {
    CGAL::clear(pm);
    pm_fail(r, ERROR_NON_MANIFOLD, 0, "the faces do not form a manifold polygon mesh");
  }
  return r;
}

// The readers' common frame: `pm` must be empty; `read()` reads into it and returns the result. An exception
// (out of memory, or one of a library underneath) leaves `pm` empty and becomes a failure.
template <class PolygonMesh, class Read>
Read_result pm_read_guarded(PolygonMesh& pm, Read read)
{
  Read_result r;
  try
  {
    if(vertices(pm).first != vertices(pm).second)
    {
      pm_fail(r, ERROR_WRONG_PARAMETER, 0, "the mesh must be empty");
      return r;
    }
    r = read();
    return r;
  }
  catch(const std::bad_alloc&)
  {
    try { CGAL::clear(pm); } catch(...) { }
    r = Read_result();
    pm_fail(r, ERROR_CANNOT_READ_FILE, 0, "out of memory");
  }
  catch(const std::exception& e)
  {
    try { CGAL::clear(pm); } catch(...) { }
    r = Read_result();
    pm_fail(r, ERROR_MALFORMED_FILE, 0, std::string("unexpected exception: ") + e.what());
  }
  catch(...)
  {
    try { CGAL::clear(pm); } catch(...) { }
    r = Read_result();
    pm_fail(r, ERROR_MALFORMED_FILE, 0, "unexpected exception");
  }
  return r;
}

} // namespace internal
#endif // DOXYGEN_RUNNING

/// \ingroup PkgProgressiveEmbeddingIO
///
/// reads a triangle mesh from a stream in the format `format` (`"off"`, `"obj"`, `"ply"` or `"stl"`,
/// case-insensitive); see the file overload for the formats, the checks and the parameters.
/// The whole stream is read first.
template <class PolygonMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Read_result read_polygon_mesh(std::istream& in, const std::string& format, PolygonMesh& pm,
                              const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::pm_read_guarded(pm, [&]() {
    Read_result r;
    std::string buf;
    if(!internal::pm_slurp(in, buf))
    {
      internal::pm_fail(r, ERROR_CANNOT_READ_FILE, 0, "read error");
      return r;
    }
    std::string f = format;
    for(char& ch : f) if(ch >= 'A' && ch <= 'Z') ch = char(ch - 'A' + 'a');
    return internal::pm_read_buffer(buf, f, pm, np);
  });
}

/// \ingroup PkgProgressiveEmbeddingIO
///
/// reads a triangle mesh from the file `filename`, in the OFF, OBJ, PLY or STL format chosen by its
/// extension (case-insensitive: `.off`, `.obj`, `.ply`, `.stl`), and checks it on the way.
///
/// Memory is bounded by the size of the file, whatever counts the file declares: declared numbers
/// of vertices, faces, list entries or triangles are compared with what the rest of the file can
/// hold (lines, or bytes in binary files) before anything is allocated, and a file declaring more
/// is refused at once with `ERROR_MALFORMED_FILE` and the line of the declaration.
///
/// Formats:
/// - OFF: optional header keyword `OFF`, `COFF`, `NOFF`, `CNOFF`, `STOFF`, ... (3D only, ascii only),
///   the counts `#vertices #faces [#edges]`, then one vertex per line (`x y z`, further values such as
///   colours ignored) and one face per line (`3 a b c`, 0-based, an optional colour ignored);
///   `#` starts a comment;
/// - OBJ: the statements accepted by `read_OBJ_with_uv()` (`v`, `vt`, `vn`, `f`, ignored `vp`, `o`,
///   `g`, `s`, `usemtl`, `mtllib`), faces as `a`, `a/ta`, `a/ta/na` or `a//na` (1-based or negative
///   relative indices, forward references allowed); only the `v` indices are used;
/// - PLY: ascii (one element instance per line), binary little or big endian; an element `vertex`
///   with scalar properties `x`, `y`, `z` of any type, an element `face` with a list property
///   `vertex_indices` (or `vertex_index`); other elements and properties are ignored;
/// - STL: ascii (`solid` ... `endsolid`, several solids allowed) or binary (chosen when the size
///   of the file is the one that the binary header's triangle count implies); corners with the
///   same coordinates are one vertex.
///
/// Numbers are parsed independently of the locale and correctly rounded to `double`, then
/// converted to the number type of the points.
/// Vertices that no face uses are dropped (counted in `Read_result::number_of_unreferenced_vertices`),
/// as `read_OBJ_with_uv()` drops unused texture coordinates; the other vertices keep their file order.
/// Faces whose orientations disagree are reoriented consistently when possible
/// (`CGAL::Polygon_mesh_processing::orient_polygon_soup()`, `Read_result::reoriented` is then `true`).
///
/// Reading never throws, asserts or exits; every problem is reported in the result, with the
/// 1-based line of the offending line (0 in binary files, whose messages give the byte offset):
/// - `ERROR_MALFORMED_FILE`: a line that is not what the format expects, a declared count larger
///   than what the file holds, an index out of range, an unknown extension;
/// - `ERROR_NON_TRIANGULAR_MESH`: a face with a number of vertices other than 3 (in every format);
/// - `ERROR_NON_FINITE_COORDINATES`: a coordinate that is NaN, infinite, or overflows `double`;
/// - `ERROR_NON_MANIFOLD`: a face with a repeated vertex, a duplicate face, an edge of three faces or
///   more, an orientation that cannot be made consistent, a vertex where several fans of faces meet
///   (the line is that of the face or of the vertex at fault);
/// - `ERROR_EMPTY_MESH`: an empty file, or no face;
/// - `ERROR_CANNOT_READ_FILE`: the file cannot be opened or read, or is a folder (the message gives
///   the system's reason), or memory ran out;
/// - `ERROR_WRONG_PARAMETER`: `pm` is not empty.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` with an internal or given vertex point map
///         (e.g. `CGAL::Surface_mesh<Point_3>`, `CGAL::Polyhedron_3<K>`)
/// \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
///
/// \param filename the name of the file
/// \param pm the output mesh; it must be empty, and is empty after a failure
/// \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `pm`}
///     \cgalParamType{a class model of `WritablePropertyMap` with `boost::graph_traits<PolygonMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, pm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the status, the line and message of a failure, and what was read
///
/// \sa `read_OBJ_with_uv()`
template <class PolygonMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Read_result read_polygon_mesh(const std::string& filename, PolygonMesh& pm,
                              const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::pm_read_guarded(pm, [&]() {
    Read_result r;
    std::string buf;
    const std::string why = internal::pm_read_file(filename, buf);
    if(!why.empty())
    {
      internal::pm_fail(r, ERROR_CANNOT_READ_FILE, 0, why);
      return r;
    }
    const std::string ext = internal::pm_lower_extension(filename);
    if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
    {
      internal::pm_fail(r, ERROR_MALFORMED_FILE, 0, "unknown format '." + ext + "' (OFF, OBJ, PLY or STL expected)");
      return r;
    }
    return internal::pm_read_buffer(buf, ext, pm, np);
  });
}

} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_READ_POLYGON_MESH_H
