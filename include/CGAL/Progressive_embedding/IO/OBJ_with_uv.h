// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_OBJ_WITH_UV_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_OBJ_WITH_UV_H

/// \file OBJ_with_uv.h
/// Reading and writing Wavefront OBJ files whose faces carry texture coordinates
/// (`f a/ta b/tb c/tc`). The mesh read is the mesh of the texture coordinates: a
/// seam of the surface is a border of the mesh.

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/IO/Read_result.h>
#include <CGAL/Progressive_embedding/IO/internal/atomic_output.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <limits>
#include <locale>
#include <new>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <utility>
#include <vector>

#include <sys/stat.h>
#include <unordered_map>
#include <boost/functional/hash.hpp>

namespace CGAL {
template <class TM, class SEM, class SVM> class Seam_mesh;
} // namespace CGAL

namespace CGAL {
namespace Progressive_embedding {
namespace IO {

/// \ingroup PkgProgressiveEmbeddingIO
///
/// The former name of `Read_result`, the outcome of `read_OBJ_with_uv()`.
typedef Read_result OBJ_read_result;

#ifndef DOXYGEN_RUNNING
namespace internal {

// ---------------------------------------------------------------------------
// lexing

inline bool obj_is_space(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// splits `line` (comment already removed) into whitespace-separated tokens
inline void obj_split(std::string_view line, std::vector<std::string_view>& tokens)
{
  tokens.clear();
  std::size_t i = 0;
  const std::size_t n = line.size();
  while(i < n)
  {
    while(i < n && obj_is_space(line[i])) ++i;
    if(i == n) break;
    std::size_t j = i;
    while(j < n && !obj_is_space(line[j])) ++j;
    tokens.push_back(line.substr(i, j - i));
    i = j;
  }
}

// For a well-formed decimal token whose conversion overflowed or underflowed:
// true if |value| < 1 (an underflow), from the position of the first non-zero digit
// and the exponent.
inline bool obj_underflows(std::string_view s)
{
  std::size_t i = 0;
  if(i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  long long order = 0;  // decimal exponent of the leading non-zero digit
  bool found = false;
  for(; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i)
  {
    if(found) ++order;
    else if(s[i] != '0') found = true;
  }
  if(i < s.size() && s[i] == '.')
  {
    ++i;
    for(long long k = 1; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i, ++k)
      if(!found && s[i] != '0') { found = true; order = -k; }
  }
  if(i < s.size() && (s[i] == 'e' || s[i] == 'E'))
  {
    ++i;
    bool neg = false;
    if(i < s.size() && (s[i] == '+' || s[i] == '-')) { neg = (s[i] == '-'); ++i; }
    long long e = 0;
    for(; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i)
      if(e < 100000000) e = 10 * e + (s[i] - '0');
    order += neg ? -e : e;
  }
  return order < 0;
}

enum class Obj_number { OK, NOT_A_NUMBER, NON_FINITE };

// locale-independent, exact (correctly rounded) conversion of a whole token
inline Obj_number obj_parse_double(std::string_view s, double& d)
{
  const char* b = s.data();
  const char* e = b + s.size();
  if(b != e && *b == '+')
  {
    ++b;
    if(b == e || *b == '+' || *b == '-') return Obj_number::NOT_A_NUMBER;
  }
  if(b == e) return Obj_number::NOT_A_NUMBER;
  double x = 0;
  const std::from_chars_result r = std::from_chars(b, e, x, std::chars_format::general);
  if(r.ptr != e || r.ec == std::errc::invalid_argument)
    return Obj_number::NOT_A_NUMBER;
  if(r.ec == std::errc::result_out_of_range)
  {
    if(obj_underflows(std::string_view(b, std::size_t(e - b))))
    {
      d = (*b == '-') ? -0.0 : 0.0;
      return Obj_number::OK;
    }
    return Obj_number::NON_FINITE;
  }
  if(!std::isfinite(x)) return Obj_number::NON_FINITE;
  d = x;
  return Obj_number::OK;
}

inline bool obj_parse_index(std::string_view s, long long& k)
{
  if(s.empty()) return false;
  const char* b = s.data();
  const char* e = b + s.size();
  const std::from_chars_result r = std::from_chars(b, e, k);
  return r.ptr == e && r.ec == std::errc();
}

struct Obj_face
{
  std::array<std::size_t, 3> v;
  std::array<std::size_t, 3> vt;
  std::size_t max_vn; // largest 1-based normal index (0: none)
  std::size_t line;
};

// Error reporting
inline Read_result& obj_fail(Read_result& r, Error_code c, std::size_t line, std::string msg)
{
  r.status = c;
  r.line = line;
  r.message = std::move(msg);
  return r;
}

inline std::string obj_quote(std::string_view t)
{
  std::string s;
  for(char c : t.substr(0, 40))
    s += (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) ? '?' : c;
  if(t.size() > 40) s += "...";
  return "'" + s + "'";
}

// Resolves a 1-based or negative (relative) OBJ index into a 0-based one.
// Positive indices are range-checked once the whole file is read (forward references are allowed).
inline bool obj_resolve(long long k, std::size_t count, std::size_t& out)
{
  if(k > 0) { out = std::size_t(k - 1); return true; }
  if(k < 0)
  {
    const unsigned long long back = (k == std::numeric_limits<long long>::min())
                                      ? (unsigned long long)(std::numeric_limits<long long>::max()) + 1ull
                                      : (unsigned long long)(-k);
    if(back > count) return false;
    out = count - std::size_t(back);
    return true;
  }
  return false;
}

// The parsed file, before any mesh is built.
struct Obj_soup
{
  std::vector<std::array<double, 3> > positions;
  std::vector<std::array<double, 2> > uvs;
  std::size_t number_of_normals = 0;
  std::vector<Obj_face> faces;
  std::size_t number_of_lines = 0;
};

// Parses the whole stream; on error, fills `r` and returns false.
inline bool obj_parse(std::istream& in, Obj_soup& soup, Read_result& r)
{
  std::string line;
  std::vector<std::string_view> tok;
  std::vector<std::string_view> parts;
  std::size_t lineno = 0;
  while(std::getline(in, line))
  {
    ++lineno;
    soup.number_of_lines = lineno;
    std::string_view l(line);
    const std::size_t hash = l.find('#');
    if(hash != std::string_view::npos) l = l.substr(0, hash);
    obj_split(l, tok);
    if(tok.empty()) continue;
    const std::string_view kw = tok[0];

    if(kw == "v" || kw == "vt")
    {
      const bool is_v = (kw == "v");
      const std::size_t min_n = is_v ? 3 : 2, max_n = is_v ? 7 : 3;
      if(tok.size() - 1 < min_n)
      {
        obj_fail(r, ERROR_MALFORMED_FILE, lineno,
                 std::string(is_v ? "'v'" : "'vt'") + " needs at least " + std::to_string(min_n) + " coordinates");
        return false;
      }
      if(tok.size() - 1 > max_n)
      {
        obj_fail(r, ERROR_MALFORMED_FILE, lineno,
                 std::string(is_v ? "'v'" : "'vt'") + " has more than " + std::to_string(max_n) + " values");
        return false;
      }
      double c[7] = {0, 0, 0, 0, 0, 0, 0};
      for(std::size_t i = 1; i < tok.size(); ++i)
      {
        const Obj_number st = obj_parse_double(tok[i], c[i - 1]);
        if(st == Obj_number::NOT_A_NUMBER)
        {
          obj_fail(r, ERROR_MALFORMED_FILE, lineno, "not a number: " + obj_quote(tok[i]));
          return false;
        }
        if(st == Obj_number::NON_FINITE)
        {
          obj_fail(r, ERROR_NON_FINITE_COORDINATES, lineno, "non-finite coordinate: " + obj_quote(tok[i]));
          return false;
        }
      }
      if(is_v) { soup.positions.push_back({c[0], c[1], c[2]}); ++r.number_of_positions; }
      else     { soup.uvs.push_back({c[0], c[1]}); ++r.number_of_texture_coordinates; }
    }
    else if(kw == "f")
    {
      const std::size_t n = tok.size() - 1;
      if(n == 0)
      {
        obj_fail(r, ERROR_MALFORMED_FILE, lineno, "face without vertices");
        return false;
      }
      Obj_face f;
      f.max_vn = 0;
      f.line = lineno;
      for(std::size_t i = 0; i < n; ++i)
      {
        // split the corner "a/b/c" on '/'
        const std::string_view c = tok[i + 1];
        parts.clear();
        std::size_t s = 0;
        for(std::size_t j = 0; j <= c.size(); ++j)
          if(j == c.size() || c[j] == '/') { parts.push_back(c.substr(s, j - s)); s = j + 1; }
        if(parts.size() > 3)
        {
          obj_fail(r, ERROR_MALFORMED_FILE, lineno, "face corner with more than three indices: " + obj_quote(c));
          return false;
        }
        if(parts.size() == 1 || parts[1].empty())
        {
          obj_fail(r, ERROR_MALFORMED_FILE, lineno, "face corner without texture coordinate index: " + obj_quote(c));
          return false;
        }
        long long kv = 0, kt = 0, kn = 0;
        if(!obj_parse_index(parts[0], kv) || !obj_parse_index(parts[1], kt)
           || (parts.size() == 3 && !obj_parse_index(parts[2], kn)))
        {
          obj_fail(r, ERROR_MALFORMED_FILE, lineno, "face corner with a non-integer index: " + obj_quote(c));
          return false;
        }
        std::size_t iv = 0, it = 0, in_ = 0;
        if(!obj_resolve(kv, soup.positions.size(), iv) || !obj_resolve(kt, soup.uvs.size(), it)
           || (parts.size() == 3 && !obj_resolve(kn, soup.number_of_normals, in_)))
        {
          obj_fail(r, ERROR_MALFORMED_FILE, lineno,
                   "face corner with index 0 or a relative index before the first element: " + obj_quote(c));
          return false;
        }
        if(parts.size() == 3 && in_ + 1 > f.max_vn) f.max_vn = in_ + 1;
        if(i < 3) { f.v[i] = iv; f.vt[i] = it; }
      }
      if(n != 3)
      {
        obj_fail(r, ERROR_NON_TRIANGULAR_MESH, lineno,
                 "face with " + std::to_string(n) + " corners; only triangles are supported");
        return false;
      }
      soup.faces.push_back(f);
      ++r.number_of_faces;
    }
    else if(kw == "vn")
    {
      ++soup.number_of_normals;
    }
    else if(kw == "vp" || kw == "o" || kw == "g" || kw == "s" || kw == "usemtl" || kw == "mtllib")
    {
      // ignored
    }
    else
    {
      obj_fail(r, ERROR_MALFORMED_FILE, lineno, "unsupported statement " + obj_quote(kw));
      return false;
    }
  }
  if(in.bad())
  {
    obj_fail(r, ERROR_CANNOT_READ_FILE, lineno + 1, "read error");
    return false;
  }
  return true;
}

// Empties a mesh without invalidating the property maps a user attached to it
// (Surface_mesh::clear() would remove them).
template <class Mesh, class = void>
struct Obj_has_clear_keeping_maps : std::false_type {};
template <class Mesh>
struct Obj_has_clear_keeping_maps<Mesh, std::void_t<decltype(std::declval<Mesh&>().clear_without_removing_property_maps())> >
  : std::true_type {};

// A Seam_mesh: its vertices are the sides of the seams of an underlying mesh, whose vertices are the 3D ones.
template <class Mesh> struct Obj_is_seam_mesh : std::false_type {};
template <class TM, class SEM, class SVM> struct Obj_is_seam_mesh<CGAL::Seam_mesh<TM, SEM, SVM> > : std::true_type {};

template <class Mesh>
void obj_clear_mesh(Mesh& tm)
{
  if constexpr(Obj_has_clear_keeping_maps<Mesh>::value)
    tm.clear_without_removing_property_maps();
  else
    CGAL::clear(tm);
}

template <class Point>
Point obj_make_point_3(const std::array<double, 3>& c)
{
  typedef typename CGAL::Kernel_traits<Point>::Kernel::FT FT;
  using Progressive_embedding::internal::make_ft;
  return Point(make_ft<FT>(c[0]), make_ft<FT>(c[1]), make_ft<FT>(c[2]));
}

template <class Point>
Point obj_make_point_2(const std::array<double, 2>& c)
{
  typedef typename CGAL::Kernel_traits<Point>::Kernel::FT FT;
  using Progressive_embedding::internal::make_ft;
  return Point(make_ft<FT>(c[0]), make_ft<FT>(c[1]));
}

// Restores the formatting state of a stream on scope exit.
struct Obj_stream_state_guard
{
  std::ostream& out;
  std::ios_base::fmtflags flags;
  std::streamsize precision;
  std::locale locale;
  explicit Obj_stream_state_guard(std::ostream& o)
    : out(o), flags(o.flags()), precision(o.precision()), locale(o.imbue(std::locale::classic())) { }
  ~Obj_stream_state_guard() { out.flags(flags); out.precision(precision); out.imbue(locale); }
};

// The writer's text: numbers formatted by std::to_chars into a buffer that goes to the stream in blocks. The
// characters are those of the stream's default float format at the same precision (printf's %g), at a
// fraction of the cost of one formatted insertion per number (a 1M-vertex map: about 3 s through operator<<).
class Obj_text_writer
{
public:
  Obj_text_writer(std::ostream& out, int precision) : m_out(out), m_precision(precision < 0 ? 6 : precision) { m_buf.reserve(1 << 17); }
  ~Obj_text_writer() { flush(); }
  void text(const char* s) { m_buf.insert(m_buf.end(), s, s + std::strlen(s)); }
  void character(char c) { m_buf.push_back(c); }
  void number(double x)
  {
    char tmp[64];
    const std::to_chars_result r = std::to_chars(tmp, tmp + sizeof tmp, x, std::chars_format::general, m_precision);
    m_buf.insert(m_buf.end(), tmp, r.ptr);
  }
  void index(std::size_t i)
  {
    char tmp[32];
    const std::to_chars_result r = std::to_chars(tmp, tmp + sizeof tmp, i);
    m_buf.insert(m_buf.end(), tmp, r.ptr);
  }
  // ends a line, writing the buffer out when it is full
  void end_line()
  {
    m_buf.push_back('\n');
    if(m_buf.size() >= (1 << 16)) flush();
  }
  void flush()
  {
    if(!m_buf.empty()) m_out.write(m_buf.data(), static_cast<std::streamsize>(m_buf.size()));
    m_buf.clear();
  }

private:
  std::ostream& m_out;
  int m_precision;
  std::vector<char> m_buf;
};

// Opens `filename` for reading; returns "" on success, or why it cannot be read (folders are
// refused here: on POSIX systems an ifstream opens them and then reads nothing).
inline std::string open_for_reading(const std::string& filename, std::ifstream& in)
{
  struct stat st;
  if(::stat(filename.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    return "cannot read '" + filename + "': " + std::strerror(EISDIR);
  errno = 0;
  in.open(filename, std::ios::binary);
  if(!in)
    return "cannot open '" + filename + "': " + std::strerror(errno != 0 ? errno : ENOENT);
  return std::string();
}

template <class TriangleMesh, class NamedParameters>
struct Obj_point_3
{
  typedef typename boost::property_traits<
    typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type>::value_type type;
};

} // namespace internal
#endif // DOXYGEN_RUNNING

/// \ingroup PkgProgressiveEmbeddingIO
///
/// reads a triangle mesh with texture coordinates from a Wavefront OBJ stream.
///
/// The mesh built is the mesh of the *texture coordinates*: its vertices are the
/// `vt` entries used by the faces, so that a surface vertex lying on a seam becomes
/// as many mesh vertices as it has `vt` entries, and seams are borders of `tm`.
/// A file with 3643 `v` and 3791 `vt` cut into a disk thus gives a disk with 3791 vertices.
///
/// The mesh vertices are the `vt` entries referenced by at least one face, in
/// increasing `vt` order (file order); unreferenced `vt` entries are dropped (counted in
/// `Read_result::number_of_unreferenced_vertices`), as `read_polygon_mesh()` drops unreferenced vertices.
/// The 3D point of a vertex is the `v` that the faces pair with its `vt`; pairing a
/// `vt` with two different `v` is an error.
///
/// Accepted statements: `v x y z [w [...]]` (3 to 7 numbers, the first 3 used), `vt u v [w]`,
/// `f a/ta b/tb c/tc` and `f a/ta/na ...` (1-based or negative, relative indices; positive
/// indices may refer to elements defined later in the file). `vn`, `vp`, `o`, `g`, `s`, `usemtl`
/// and `mtllib` lines, comments (`#` to the end of the line) and blank lines are ignored.
/// Any other statement is an error. Numbers are parsed independently of the locale,
/// correctly rounded to `double`, then converted to the number types of the points.
///
/// Reading never throws, asserts or exits: every problem is reported in the result.
/// - `ERROR_MALFORMED_FILE`: a line that is not a number list of the right length, an index
///   that is 0, not an integer or out of range, a face corner without `vt`, a `vt`
///   paired with two different `v`, an unsupported statement;
/// - `ERROR_NON_TRIANGULAR_MESH`: a face with a number of corners other than 3;
/// - `ERROR_NON_FINITE_COORDINATES`: a `v` or `vt` value that is NaN, infinite or overflows `double`;
/// - `ERROR_NON_MANIFOLD`: a face that `CGAL::Euler::add_face()` refuses (repeated vertex,
///   an edge used by more than two faces or twice in the same direction, non-manifold vertex
///   configuration); vertices where two fans meet (pinched vertices) are accepted here;
/// - `ERROR_EMPTY_MESH`: no face;
/// - `ERROR_CANNOT_READ_FILE`: a stream error.
///
/// The line of the first offending line is given in the result (1-based).
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` with an internal or given vertex point map
///         (e.g. `CGAL::Surface_mesh<Point_3>`, `CGAL::Polyhedron_3<K>`)
/// \tparam VertexUVMap a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type (any kernel: `double`, `CGAL::Gmpq`, `CGAL::Gmpfr`, ...;
///         `CGAL::Gmpfr` values get `CGAL::Gmpfr::get_default_precision()` bits)
/// \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
///
/// \param in the input stream
/// \param tm the output mesh; it is emptied first (for `Surface_mesh`, with
///        `clear_without_removing_property_maps()`, so that `uvm` stays valid), and is empty after a failure
/// \param uvm receives the texture coordinates of the vertices of `tm`
/// \param vt_to_v if not null, receives, for each vertex of `tm` in the order of `vertices(tm)`,
///        the 0-based index of its `v` in the file (pass it to `write_OBJ_with_uv()` to write the seams back)
/// \param positions if not null, receives the points of all `v` lines of the file, in file order
///        (pass it to `write_OBJ_with_uv()` to write the original `v` list back, unreferenced entries included)
/// \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the status, the line and message of a failure, and the numbers of `v`, `vt` and faces read
///
/// \sa `write_OBJ_with_uv()`
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Read_result
read_OBJ_with_uv(std::istream& in, TriangleMesh& tm, VertexUVMap uvm,
                 std::vector<std::size_t>* vt_to_v = nullptr,
                 std::vector<typename boost::property_traits<
                   typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::type>::value_type>* positions = nullptr,
                 const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh>                              GT;
  typedef typename GT::vertex_descriptor                                 vertex_descriptor;
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type               Point_3;
  typedef typename boost::property_traits<VertexUVMap>::value_type       Point_2;

  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  Read_result r;
  if(vt_to_v) vt_to_v->clear();
  if(positions) positions->clear();
  try
  {
    internal::obj_clear_mesh(tm);
    VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, tm));

    internal::Obj_soup soup;
    if(!internal::obj_parse(in, soup, r))
      return r;
    if(soup.faces.empty())
      return internal::obj_fail(r, ERROR_EMPTY_MESH, 0, "the file has no face");

    // range checks and vt -> v pairing, in file order
    const std::size_t none = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> vt_v(soup.uvs.size(), none);
    for(const internal::Obj_face& f : soup.faces)
    {
      for(int i = 0; i < 3; ++i)
      {
        if(f.v[i] >= soup.positions.size())
          return internal::obj_fail(r, ERROR_MALFORMED_FILE, f.line,
                                    "vertex index " + std::to_string(f.v[i] + 1) + " out of range (the file has "
                                    + std::to_string(soup.positions.size()) + " 'v')");
        if(f.vt[i] >= soup.uvs.size())
          return internal::obj_fail(r, ERROR_MALFORMED_FILE, f.line,
                                    "texture coordinate index " + std::to_string(f.vt[i] + 1) + " out of range (the file has "
                                    + std::to_string(soup.uvs.size()) + " 'vt')");
      }
      if(f.max_vn > soup.number_of_normals)
        return internal::obj_fail(r, ERROR_MALFORMED_FILE, f.line,
                                  "normal index " + std::to_string(f.max_vn) + " out of range (the file has "
                                  + std::to_string(soup.number_of_normals) + " 'vn')");
      for(int i = 0; i < 3; ++i)
      {
        std::size_t& p = vt_v[f.vt[i]];
        if(p == none) p = f.v[i];
        else if(p != f.v[i])
          return internal::obj_fail(r, ERROR_MALFORMED_FILE, f.line,
                                    "texture coordinate " + std::to_string(f.vt[i] + 1) + " is paired with vertices "
                                    + std::to_string(p + 1) + " and " + std::to_string(f.v[i] + 1));
      }
    }

    // one mesh vertex per used vt, in vt order
    std::vector<vertex_descriptor> vt_vertex(soup.uvs.size(), GT::null_vertex());
    for(std::size_t t = 0; t < soup.uvs.size(); ++t)
    {
      if(vt_v[t] == none) { ++r.number_of_unreferenced_vertices; continue; }
      vertex_descriptor vd = add_vertex(tm);
      vt_vertex[t] = vd;
      put(vpm, vd, internal::obj_make_point_3<Point_3>(soup.positions[vt_v[t]]));
      put(uvm, vd, internal::obj_make_point_2<Point_2>(soup.uvs[t]));
    }

    std::array<vertex_descriptor, 3> fv;
    for(const internal::Obj_face& f : soup.faces)
    {
      for(int i = 0; i < 3; ++i) fv[i] = vt_vertex[f.vt[i]];
      const bool repeated = (f.vt[0] == f.vt[1] || f.vt[1] == f.vt[2] || f.vt[0] == f.vt[2]);
      bool added = false;
      if(!repeated)
      {
        try { added = (CGAL::Euler::add_face(fv, tm) != GT::null_face()); }
        catch(const std::bad_alloc&) { throw; }
        catch(...) { added = false; }
      }
      if(!added)
      {
        internal::obj_clear_mesh(tm);
        return internal::obj_fail(r, ERROR_NON_MANIFOLD, f.line,
                                  repeated ? std::string("face with a repeated texture coordinate index")
                                           : std::string("face cannot be added: an edge would have more than two faces, "
                                                         "inconsistent orientation, or a non-manifold vertex"));
      }
    }

    if(vt_to_v)
    {
      auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
      for(std::size_t t = 0; t < soup.uvs.size(); ++t)
        if(vt_vertex[t] != GT::null_vertex()) put(vid, vt_vertex[t], vt_v[t]);
      vt_to_v->reserve(num_vertices(tm));
      for(vertex_descriptor vd : vertices(tm))
        vt_to_v->push_back(get(vid, vd));
    }
    if(positions)
    {
      positions->reserve(soup.positions.size());
      for(const std::array<double, 3>& p : soup.positions)
        positions->push_back(internal::obj_make_point_3<Point_3>(p));
    }
    return r;
  }
  catch(const std::bad_alloc&)
  {
    try { internal::obj_clear_mesh(tm); } catch(...) { }
    if(vt_to_v) { vt_to_v->clear(); vt_to_v->shrink_to_fit(); }
    if(positions) { positions->clear(); positions->shrink_to_fit(); }
    r.status = ERROR_CANNOT_READ_FILE; r.message = "out of memory";
    return r;
  }
  catch(const std::exception& e)
  {
    try { internal::obj_clear_mesh(tm); } catch(...) { }
    if(vt_to_v) vt_to_v->clear();
    if(positions) positions->clear();
    r.status = ERROR_MALFORMED_FILE; r.message = std::string("unexpected exception: ") + e.what();
    return r;
  }
  catch(...)
  {
    try { internal::obj_clear_mesh(tm); } catch(...) { }
    if(vt_to_v) vt_to_v->clear();
    if(positions) positions->clear();
    r.status = ERROR_MALFORMED_FILE; r.message = "unexpected exception";
    return r;
  }
}

/// \ingroup PkgProgressiveEmbeddingIO
///
/// reads a triangle mesh with texture coordinates from the Wavefront OBJ file `filename`;
/// see the stream overload for the format and the parameters.
///
/// \return as the stream overload; the status is `ERROR_CANNOT_READ_FILE` if the file cannot be opened
///         or is a folder (the message gives the system's reason, e.g. "Is a directory")
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Read_result
read_OBJ_with_uv(const std::string& filename, TriangleMesh& tm, VertexUVMap uvm,
                 std::vector<std::size_t>* vt_to_v = nullptr,
                 std::vector<typename boost::property_traits<
                   typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::type>::value_type>* positions = nullptr,
                 const NamedParameters& np = CGAL::parameters::default_values())
{
  std::ifstream in;
  const std::string why = internal::open_for_reading(filename, in);
  if(!why.empty())
  {
    Read_result r;
    try { internal::obj_clear_mesh(tm); } catch(...) { }
    if(vt_to_v) vt_to_v->clear();
    if(positions) positions->clear();
    return internal::obj_fail(r, ERROR_CANNOT_READ_FILE, 0, why);
  }
  return read_OBJ_with_uv(in, tm, uvm, vt_to_v, positions, np);
}

/// \ingroup PkgProgressiveEmbeddingIO
///
/// writes a triangle mesh with texture coordinates as a Wavefront OBJ stream
/// (`v`, `vt`, then `f a/ta b/tb c/tc` lines), one `vt` per vertex of `tm`, in the order of `vertices(tm)`.
///
/// The `v` list depends on the optional arguments:
/// - `vt_to_v == nullptr` (a plain mesh): one `v` per vertex, from the vertex point map;
///   `positions` must then be null;
/// - `vt_to_v != nullptr` and `positions != nullptr` (writing back what `read_OBJ_with_uv()` read):
///   the `v` list is `*positions`, and the corner of vertex `i` refers to `v` number `(*vt_to_v)[i]`,
///   so that the seams and the original `v` list (unreferenced entries included) are kept;
/// - `vt_to_v != nullptr` and `positions == nullptr`: the `v` are the distinct values of `*vt_to_v`,
///   in increasing order (renumbered without gaps), each at the point of the first vertex mapped to it.
///
/// Coordinates are written as `CGAL::to_double()` of the values, in the classic locale,
/// with 17 significant digits by default, so that `double` values are read back bit-exactly.
/// Faces of any degree are written. Nothing is written if an argument is inconsistent or a
/// coordinate is not finite.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam VertexUVMap a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///         as key type and a CGAL `Point_2` as value type
/// \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"
///
/// \param out the output stream; its formatting state and locale are restored on return
/// \param tm the mesh
/// \param uvm the texture coordinates of the vertices of `tm`
/// \param vt_to_v if not null, the 0-based `v` index of each vertex of `tm`, in the order of `vertices(tm)`
/// \param positions if not null, the `v` list to write; requires `vt_to_v`
/// \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a class model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{stream_precision}
///     \cgalParamDescription{the number of significant digits of the coordinates}
///     \cgalParamType{int}
///     \cgalParamDefault{`17` (`std::numeric_limits<double>::%max_digits10`)}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK`; `ERROR_WRONG_PARAMETER` if `vt_to_v` does not have one entry per vertex, an entry
///         is not an index of `*positions`, or `positions` is given without `vt_to_v`;
///         `ERROR_NON_FINITE_COORDINATES` if a coordinate to be written is not finite;
///         `ERROR_CANNOT_WRITE_FILE` if the stream fails
///
/// On a `CGAL::Seam_mesh` (without `vt_to_v`), each vertex of the underlying mesh is written once as a `v`
/// line, shared by the sides of the seams through it, each of which gets its own `vt` line.
///
/// \sa `read_OBJ_with_uv()`
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code
write_OBJ_with_uv(std::ostream& out, const TriangleMesh& tm, VertexUVMap uvm,
                  const std::vector<std::size_t>* vt_to_v = nullptr,
                  const std::vector<typename internal::Obj_point_3<TriangleMesh, NamedParameters>::type>* positions = nullptr,
                  const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh>                              GT;
  typedef typename GT::vertex_descriptor                                 vertex_descriptor;
  typedef typename GT::halfedge_descriptor                               halfedge_descriptor;
  typedef typename GT::face_descriptor                                   face_descriptor;
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;

  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const int precision = choose_parameter(get_parameter(np, CGAL::internal_np::stream_precision),
                                         std::numeric_limits<double>::max_digits10);

  try
  {
    std::size_t nv = 0;
    auto vid = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
    for(vertex_descriptor vd : vertices(tm))
      put(vid, vd, nv++);

    if(positions != nullptr && vt_to_v == nullptr) return ERROR_WRONG_PARAMETER;
    if(vt_to_v != nullptr && vt_to_v->size() != nv) return ERROR_WRONG_PARAMETER;

    // the v list and the v index of each vertex
    std::vector<std::array<double, 3> > vlist;
    std::vector<std::size_t> v_of(nv);
    auto to3 = [](const auto& p) { return std::array<double, 3>{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }; };
    if constexpr(internal::Obj_is_seam_mesh<TriangleMesh>::value)
    {
      if(vt_to_v == nullptr)
      {
        // one `v` per vertex of the underlying mesh, shared by the seam sides (one `vt` each)
        typedef typename std::remove_cv<typename std::remove_reference<decltype(tm.mesh())>::type>::type TM;
        typedef typename boost::graph_traits<TM>::vertex_descriptor TM_vertex;
        std::unordered_map<TM_vertex, std::size_t, boost::hash<TM_vertex> > v_index;
        for(vertex_descriptor vd : vertices(tm))
        {
          const TM_vertex u = target(vd.hd.tmhd, tm.mesh());
          auto it = v_index.find(u);
          if(it == v_index.end())
          {
            it = v_index.emplace(u, vlist.size()).first;
            vlist.push_back(to3(get(vpm, vd)));
          }
          v_of[get(vid, vd)] = it->second;
        }
      }
    }
    if(vt_to_v == nullptr && internal::Obj_is_seam_mesh<TriangleMesh>::value)
    {
      // done above
    }
    else if(vt_to_v == nullptr)
    {
      vlist.reserve(nv);
      for(vertex_descriptor vd : vertices(tm))
      {
        v_of[get(vid, vd)] = vlist.size();
        vlist.push_back(to3(get(vpm, vd)));
      }
    }
    else if(positions != nullptr)
    {
      for(std::size_t i = 0; i < nv; ++i)
      {
        if((*vt_to_v)[i] >= positions->size()) return ERROR_WRONG_PARAMETER;
        v_of[i] = (*vt_to_v)[i];
      }
      vlist.reserve(positions->size());
      for(const auto& p : *positions) vlist.push_back(to3(p));
    }
    else
    {
      // compact renumbering of the used v, in increasing order
      std::vector<std::pair<std::size_t, std::size_t> > order; // (v, vertex)
      order.reserve(nv);
      for(std::size_t i = 0; i < nv; ++i) order.emplace_back((*vt_to_v)[i], i);
      std::sort(order.begin(), order.end());
      std::vector<vertex_descriptor> vds;
      vds.reserve(nv);
      for(vertex_descriptor vd : vertices(tm)) vds.push_back(vd);
      for(std::size_t k = 0; k < order.size(); ++k)
      {
        if(k == 0 || order[k].first != order[k - 1].first)
          vlist.push_back(to3(get(vpm, vds[order[k].second])));
        v_of[order[k].second] = vlist.size() - 1;
      }
    }

    std::vector<std::array<double, 2> > uvs(nv);
    for(vertex_descriptor vd : vertices(tm))
    {
      const auto& uv = get(uvm, vd);
      uvs[get(vid, vd)] = { CGAL::to_double(uv.x()), CGAL::to_double(uv.y()) };
    }
    for(const auto& p : vlist)
      if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return ERROR_NON_FINITE_COORDINATES;
    for(const auto& p : uvs)
      if(!std::isfinite(p[0]) || !std::isfinite(p[1])) return ERROR_NON_FINITE_COORDINATES;

    internal::Obj_stream_state_guard guard(out);
    out.unsetf(std::ios_base::floatfield);
    out.precision(precision);
    out << "# OBJ with texture coordinates, written by CGAL::Progressive_embedding::IO::write_OBJ_with_uv\n";
    out << "# " << vlist.size() << " positions, " << nv << " texture coordinates, " << num_faces(tm) << " faces\n";
    {
      internal::Obj_text_writer w(out, precision);
      for(const auto& p : vlist)
      {
        w.text("v ");
        w.number(p[0]); w.character(' '); w.number(p[1]); w.character(' '); w.number(p[2]);
        w.end_line();
      }
      for(const auto& p : uvs)
      {
        w.text("vt ");
        w.number(p[0]); w.character(' '); w.number(p[1]);
        w.end_line();
      }
      for(face_descriptor f : faces(tm))
      {
        w.character('f');
        for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
        {
          const std::size_t i = get(vid, target(h, tm));
          w.character(' '); w.index(v_of[i] + 1); w.character('/'); w.index(i + 1);
        }
        w.end_line();
      }
    }
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
/// writes a triangle mesh with texture coordinates to the Wavefront OBJ file `filename`;
/// see the stream overload for the parameters.
///
/// A failed write never leaves a partial file: when `filename` is a regular file or does not exist,
/// the content is written to a temporary file in the same folder, which replaces `filename` only
/// once it is completely written and closed (a symbolic link is kept and its target replaced);
/// on failure the temporary file is removed and an existing `filename` is left untouched.
/// A name of one of the process's file descriptors (`/dev/stdout`, `/dev/fd/N`, `/proc/self/fd/N`,
/// or a link to one) is written through that descriptor, where it stands (a pipe, or a file a shell
/// opened with `>` or `>>`); anything else that is not a regular file (a device such as `/dev/null`,
/// a named pipe) is written directly. No exception escapes.
///
/// \return as the stream overload; `ERROR_CANNOT_WRITE_FILE` if the file cannot be written (a folder,
///         no permission, no space left, a file size limit, ...)
template <class TriangleMesh, class VertexUVMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code
write_OBJ_with_uv(const std::string& filename, const TriangleMesh& tm, VertexUVMap uvm,
                  const std::vector<std::size_t>* vt_to_v = nullptr,
                  const std::vector<typename internal::Obj_point_3<TriangleMesh, NamedParameters>::type>* positions = nullptr,
                  const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::write_file_atomically(filename, [&](std::ostream& out) {
    return write_OBJ_with_uv(out, tm, uvm, vt_to_v, positions, np);
  });
}

} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_OBJ_WITH_UV_H
