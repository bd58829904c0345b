// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// What the fuzz targets share: the finding report, a byte reader, the decoding of bytes into
// coordinates (small lattice values, which make collinear and repeated points likely, and
// extreme doubles) and into small triangulated disks, and the exact brute-force geometry of the
// oracles (exact arithmetic, every pair, no filtering, written independently of the package).

#ifndef PE_FUZZ_UTIL_H
#define PE_FUZZ_UTIL_H

#include <CGAL/Progressive_embedding/Error_code.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <streambuf>
#include <string>
#include <utility>
#include <vector>

// Defines the entry point of the fuzz target `name`; scripts/fuzz.sh and test/fuzz/CMakeLists.txt
// find the targets by this macro.
#define PE_FUZZ_TARGET_FUNCTION(name) inline int name(const std::uint8_t* data, std::size_t size)

// A finding: the message on stderr, then abort(), which libFuzzer and ctest both report.
#define PE_FUZZ_CHECK(cond, msg)                                                                   \
  do {                                                                                             \
    if(!(cond)) {                                                                                  \
      std::ostringstream pe_fuzz_os;                                                               \
      pe_fuzz_os << msg;                                                                           \
      pe_fuzz::finding(__FILE__, __LINE__, #cond, pe_fuzz_os.str());                               \
    }                                                                                              \
  } while(0)

namespace pe_fuzz {

namespace PE = CGAL::Progressive_embedding;

typedef CGAL::Exact_predicates_inexact_constructions_kernel  K;
typedef K::Point_2                                           Point_2;
typedef K::Point_3                                           Point_3;
typedef CGAL::Surface_mesh<Point_3>                          Mesh;
typedef Mesh::Vertex_index                                   vertex_descriptor;
typedef Mesh::Face_index                                     face_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Point_2>       Uv_map;
typedef std::array<std::size_t, 3>                           Tri;

[[noreturn]] inline void finding(const char* file, int line, const char* cond, const std::string& msg)
{
  std::cerr << "FUZZ FINDING " << file << ":" << line << ": " << cond << " -- " << msg << std::endl;
  std::abort();
}

// Swallows what the code under test prints (the `pe` line readers report every failure on
// stdout and stderr): printing would dominate the time of an execution.
class Silence
{
  struct Null_buffer : std::streambuf { int overflow(int c) override { return c; } };
  Null_buffer null_;
  std::streambuf* out_;
  std::streambuf* err_;
public:
  Silence() : out_(std::cout.rdbuf(&null_)), err_(std::cerr.rdbuf(&null_)) {}
  ~Silence() { std::cout.rdbuf(out_); std::cerr.rdbuf(err_); }
};

// Reads the input byte by byte; past the end every byte is 0, so every input decodes.
struct Bytes
{
  const std::uint8_t* data;
  std::size_t size;
  std::size_t pos = 0;

  Bytes(const std::uint8_t* d, std::size_t n) : data(d), size(n) {}
  std::uint8_t u8() { return pos < size ? data[pos++] : 0; }
  bool done() const { return pos >= size; }
  double raw_double()
  {
    std::uint64_t b = 0;
    for(int k = 0; k < 8; ++k) b |= std::uint64_t(u8()) << (8 * k);
    double x;
    std::memcpy(&x, &b, sizeof x);
    return x;
  }
};

// One coordinate from the input: mostly an integer in [-8, 8] (so that collinear, repeated and
// symmetric points are frequent), else a fraction, a double at an end of the range (denormals,
// overflowing products, the largest double, integers beyond 2^53), a non-finite value or any
// 8 bytes taken as a double.
inline double coordinate(Bytes& b)
{
  const int c = b.u8();
  if(c < 208) return double(c % 17 - 8);
  const double inf = std::numeric_limits<double>::infinity();
  switch(c - 208)
  {
    case 0: return 0.5;
    case 1: return -0.5;
    case 2: return 1. / 3.;
    case 3: return std::numeric_limits<double>::denorm_min();
    case 4: return -std::numeric_limits<double>::denorm_min();
    case 5: return std::numeric_limits<double>::min();
    case 6: return 1e-300;
    case 7: return -1e-300;
    case 8: return 1e300;
    case 9: return -1e300;
    case 10: return std::numeric_limits<double>::max();
    case 11: return -std::numeric_limits<double>::max();
    case 12: return 9007199254740992.;        // 2^53
    case 13: return 9007199254740994.;        // 2^53 + 2
    case 14: return 1. + std::numeric_limits<double>::epsilon();
    case 15: return 1. - std::numeric_limits<double>::epsilon() / 2;
    case 16: return -0.;
    case 17: return std::numeric_limits<double>::quiet_NaN();
    case 18: return inf;
    case 19: return -inf;
    case 20: return 1e-160;                   // products underflow
    case 21: return 1e160;                    // products overflow
    default: break;
  }
  if(c - 208 < 30) return b.raw_double();
  return double(c - 208 - 38) / 8.;           // eighths in [-1, 1.125]
}

// Applies an optional global transformation, chosen by one byte, to finite coordinates: a scale by
// a power of two (exact unless it overflows or underflows) and a translation (rounded).
inline void transform(Bytes& b, std::vector<double>& xy)
{
  const int mode = b.u8();
  if(mode & 1)
  {
    const int e = int(b.u8()) * 9 - 1150;
    for(double& x : xy) if(std::isfinite(x)) x = std::ldexp(x, e);
  }
  if(mode & 2)
  {
    const double t = coordinate(b) * std::ldexp(1., b.u8() % 64);
    for(double& x : xy) if(std::isfinite(x)) x += t;
  }
}

// ---- small disks -----------------------------------------------------------------------------

// A triangulated disk given by its faces (vertex indices, consistently oriented) and its border
// cycle (the faces on its left).
struct Small_disk
{
  std::size_t nv = 0;
  std::vector<Tri> faces;
  std::vector<std::size_t> border;
  // the grid layout of the grid disks (else empty): the position a valid map may give each vertex
  std::vector<std::array<int, 2> > grid;
};

// every triangulation of the polygon i..j (indices increasing counterclockwise), chosen by the bytes
inline void triangulate_polygon(Bytes& b, std::size_t i, std::size_t j, std::vector<Tri>& out)
{
  if(j < i + 2) return;
  const std::size_t k = i + 1 + b.u8() % (j - i - 1);
  out.push_back(Tri{{ i, k, j }});
  triangulate_polygon(b, i, k, out);
  triangulate_polygon(b, k, j, out);
}

// the border cycle of consistently oriented faces forming a disk: the directed edges without a twin
inline std::vector<std::size_t> border_cycle(const std::vector<Tri>& faces)
{
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for(const Tri& t : faces)
    for(int c = 0; c < 3; ++c) directed[std::make_pair(t[c], t[(c + 1) % 3])] = 1;
  std::map<std::size_t, std::size_t> next;
  for(const auto& e : directed)
    if(!directed.count(std::make_pair(e.first.second, e.first.first))) next[e.first.first] = e.first.second;
  std::vector<std::size_t> cycle;
  if(next.empty()) return cycle;
  std::size_t v = next.begin()->first;
  do { cycle.push_back(v); v = next[v]; } while(v != cycle.front() && cycle.size() <= next.size());
  return cycle;
}

// A small disk: a triangulated polygon (3 to 9 vertices), a wheel (3 to 8 spokes), a grid
// (1 to 3 cells each way, each cell cut along either diagonal), or a triangulated polygon with a
// few faces split at a new interior vertex.
inline Small_disk small_disk(Bytes& b)
{
  Small_disk d;
  switch(b.u8() % 4)
  {
    case 0:
      d.nv = 3 + b.u8() % 7;
      triangulate_polygon(b, 0, d.nv - 1, d.faces);
      break;
    case 1:
    {
      const std::size_t n = 3 + b.u8() % 6;
      d.nv = n + 1;
      for(std::size_t i = 0; i < n; ++i) d.faces.push_back(Tri{{ i, (i + 1) % n, n }});
      break;
    }
    case 2:
    {
      const std::size_t w = 1 + b.u8() % 3, h = 1 + b.u8() % 3;
      d.nv = (w + 1) * (h + 1);
      for(std::size_t y = 0; y <= h; ++y)
        for(std::size_t x = 0; x <= w; ++x) d.grid.push_back({{ int(x), int(y) }});
      for(std::size_t y = 0; y < h; ++y)
        for(std::size_t x = 0; x < w; ++x)
        {
          const std::size_t a = y * (w + 1) + x, bb = a + 1, c = a + w + 2, e = a + w + 1; // ccw square
          if(b.u8() & 1) { d.faces.push_back(Tri{{ a, bb, c }}); d.faces.push_back(Tri{{ a, c, e }}); }
          else           { d.faces.push_back(Tri{{ a, bb, e }}); d.faces.push_back(Tri{{ bb, c, e }}); }
        }
      break;
    }
    default:
    {
      d.nv = 3 + b.u8() % 4;
      triangulate_polygon(b, 0, d.nv - 1, d.faces);
      const int splits = b.u8() % 4;
      for(int s = 0; s < splits; ++s)
      {
        const std::size_t f = b.u8() % d.faces.size(), v = d.nv++;
        const Tri t = d.faces[f];
        d.faces[f] = Tri{{ t[0], t[1], v }};
        d.faces.push_back(Tri{{ t[1], t[2], v }});
        d.faces.push_back(Tri{{ t[2], t[0], v }});
      }
      break;
    }
  }
  d.border = border_cycle(d.faces);
  return d;
}

// The Surface_mesh of a small disk (vertex i is the i-th vertex added) with 3D points that are not
// degenerate in general (their exact values do not matter).
inline void build_mesh(const Small_disk& d, Mesh& m, std::vector<vertex_descriptor>& V)
{
  V.clear();
  for(std::size_t i = 0; i < d.nv; ++i)
    V.push_back(m.add_vertex(Point_3(double(i % 4), double((i * i) % 5), double((i * 7) % 3))));
  for(const Tri& t : d.faces)
  {
    const face_descriptor f = m.add_face(V[t[0]], V[t[1]], V[t[2]]);
    PE_FUZZ_CHECK(f != Mesh::null_face(), "the fuzz decoder built a face that is not a disk face");
  }
}

// ---- exact brute-force geometry ------------------------------------------------------------

// Exact on doubles: the oracles only add, subtract, multiply and compare. Signs are taken from the
// double evaluation when its error bound (a few units in the last place of the two products, with
// a margin of 20) proves them, then from the double evaluation when every operation of it is
// proved exact (error-free transformations), and computed exactly otherwise (Mpzf, CGAL's exact
// floating-point ring: no division, fewer allocations than Gmpq).
typedef CGAL::Mpzf Q;

struct Qpoint { double x, y; };

inline Qpoint qpoint(double x, double y) { return Qpoint{ x, y }; }

// b - a, true if it is exact in double: Knuth's two-sum gives its rounding error (false on overflow)
inline bool exact_difference(double b, double a, double& d)
{
  d = b - a;
  if(!std::isfinite(d)) return false;
  const double bv = d - b;
  return (b - (d - bv)) + (-a - bv) == 0;
}

// u v, true if it is exact in double: the fused multiply-add gives its rounding error, which is
// representable away from the subnormal range (false there and on overflow)
inline bool exact_product(double u, double v, double& p)
{
  p = u * v;
  if(!std::isfinite(p)) return false;
  if(p == 0) return u == 0 || v == 0;
  return std::abs(p) >= 0x1p-960 && std::fma(u, v, -p) == 0;
}

// The sign of (bx - ax)(dy - cy) - (by - ay)(dx - cx) when the four differences and the two products
// are exact in double (then comparing the products is exact), else 2. It decides the small lattice
// coordinates that the filters below leave to Mpzf (collinear and repeated points) without it.
inline int exact_in_double_sign(double ax, double bx, double cy, double dy, double ay, double by, double cx, double dx)
{
  double u, v, w, z, p, q;
  if(!exact_difference(bx, ax, u) || !exact_difference(dy, cy, v) || !exact_difference(by, ay, w)
     || !exact_difference(dx, cx, z) || !exact_product(u, v, p) || !exact_product(w, z, q)) return 2;
  return p > q ? 1 : (p < q ? -1 : 0);
}

// the sign of the determinant of (b - a, c - a)
inline int orient(const Qpoint& a, const Qpoint& b, const Qpoint& c)
{
  const double t1 = (b.x - a.x) * (c.y - a.y), t2 = (b.y - a.y) * (c.x - a.x), d = t1 - t2;
  const double scale = std::abs(t1) + std::abs(t2);
  // away from overflow and from the subnormal range, where relative error bounds fail
  if(std::isfinite(d) && std::isfinite(scale) && scale > 1e-280 && std::abs(d) > 1e-14 * scale) return d > 0 ? 1 : -1;
  const int s = exact_in_double_sign(a.x, b.x, a.y, c.y, a.y, b.y, a.x, c.x);
  if(s != 2) return s;
  const Q e = (Q(b.x) - Q(a.x)) * (Q(c.y) - Q(a.y)) - (Q(b.y) - Q(a.y)) * (Q(c.x) - Q(a.x));
  return int(e.sign());
}

inline bool same(const Qpoint& a, const Qpoint& b) { return a.x == b.x && a.y == b.y; }

// c in the bounding box of segment ab (for a point collinear with a and b: on the closed segment)
inline bool in_box(const Qpoint& a, const Qpoint& b, const Qpoint& c)
{
  return (std::min)(a.x, b.x) <= c.x && c.x <= (std::max)(a.x, b.x)
      && (std::min)(a.y, b.y) <= c.y && c.y <= (std::max)(a.y, b.y);
}

// the closed segments pq and rs have a common point (degenerate segments included)
inline bool closed_segments_meet(const Qpoint& p, const Qpoint& q, const Qpoint& r, const Qpoint& s)
{
  const int o1 = orient(p, q, r), o2 = orient(p, q, s), o3 = orient(r, s, p), o4 = orient(r, s, q);
  if(o1 * o2 < 0 && o3 * o4 < 0) return true;
  if(o1 == 0 && in_box(p, q, r) && (!same(p, q) || same(p, r))) return true;
  if(o2 == 0 && in_box(p, q, s) && (!same(p, q) || same(p, s))) return true;
  if(o3 == 0 && in_box(r, s, p) && (!same(r, s) || same(r, p))) return true;
  if(o4 == 0 && in_box(r, s, q) && (!same(r, s) || same(r, q))) return true;
  return false;
}

// The open interiors of two non-degenerate triangles meet: no line through an edge of one of them
// has the other one on its closed outer side (separating axis theorem; in the plane the edges'
// normals are the only candidate axes).
inline bool triangle_interiors_meet(const std::array<Qpoint, 3>& A, const std::array<Qpoint, 3>& B)
{
  for(int pass = 0; pass < 2; ++pass)
  {
    const std::array<Qpoint, 3>& T = pass ? B : A;
    const std::array<Qpoint, 3>& U = pass ? A : B;
    for(int e = 0; e < 3; ++e)
    {
      const Qpoint& p = T[e];
      const Qpoint& q = T[(e + 1) % 3];
      const int inside = orient(p, q, T[(e + 2) % 3]); // non-zero
      bool separated = true;
      for(int k = 0; k < 3 && separated; ++k)
        if(orient(p, q, U[k]) == inside) separated = false;
      if(separated) return false;
    }
  }
  return true;
}

// twice the signed area of a polygon (shoelace, exact)
inline Q twice_area(const std::vector<Qpoint>& P)
{
  Q a(0);
  for(std::size_t k = 0; k < P.size(); ++k)
  {
    const Qpoint& p = P[k];
    const Qpoint& q = P[(k + 1) % P.size()];
    a = a + (Q(p.x) * Q(q.y) - Q(p.y) * Q(q.x));
  }
  return a;
}

// The certificate of check_embedding() on a disk, recomputed by brute force: the orientation of
// the border (exact area; if zero or not finite, the majority of the faces), each face's exact
// orientation, the pairs of border edges that meet (adjacent ones when they fold back onto each
// other), and the pairs of faces whose interiors meet (every pair, each face taken in its own
// orientation, two correctly oriented faces sharing an edge excepted).
struct Embedding_oracle
{
  std::size_t non_finite = 0, flipped = 0, degenerate = 0, border_intersections = 0, overlapping_pairs = 0;
  bool border_finite = true;
  int border_sign = 0;

  bool border_simple() const { return border_finite && border_intersections == 0; }
  bool valid() const
  {
    return non_finite == 0 && flipped == 0 && degenerate == 0 && border_simple() && overlapping_pairs == 0;
  }
};

inline Embedding_oracle embedding_oracle(const Small_disk& d, const std::vector<double>& xy)
{
  Embedding_oracle o;
  std::vector<char> finite(d.nv);
  std::vector<Qpoint> P(d.nv);
  for(std::size_t i = 0; i < d.nv; ++i)
  {
    finite[i] = std::isfinite(xy[2 * i]) && std::isfinite(xy[2 * i + 1]);
    if(!finite[i]) { ++o.non_finite; continue; }
    P[i] = qpoint(xy[2 * i], xy[2 * i + 1]);
  }
  const std::size_t nb = d.border.size();
  for(std::size_t v : d.border) if(!finite[v]) o.border_finite = false;
  std::vector<Qpoint> B;
  if(o.border_finite)
  {
    for(std::size_t v : d.border) B.push_back(P[v]);
    const Q a = twice_area(B);
    o.border_sign = int(a.sign());
  }
  std::vector<int> fo(d.faces.size(), 0);
  std::vector<char> face_finite(d.faces.size(), 0);
  std::size_t pos = 0, neg = 0;
  for(std::size_t f = 0; f < d.faces.size(); ++f)
  {
    const Tri& t = d.faces[f];
    if(!finite[t[0]] || !finite[t[1]] || !finite[t[2]]) continue;
    face_finite[f] = 1;
    fo[f] = orient(P[t[0]], P[t[1]], P[t[2]]);
    if(fo[f] > 0) ++pos; else if(fo[f] < 0) ++neg;
  }
  if(o.border_sign == 0) o.border_sign = neg > pos ? -1 : 1;
  for(std::size_t f = 0; f < d.faces.size(); ++f)
  {
    if(!face_finite[f]) continue;
    if(fo[f] == 0) ++o.degenerate;
    else if(fo[f] != o.border_sign) ++o.flipped;
  }
  if(o.border_finite && nb >= 3)
    for(std::size_t i = 0; i < nb; ++i)
      for(std::size_t j = i + 1; j < nb; ++j)
      {
        const Qpoint &p0 = B[i], &p1 = B[(i + 1) % nb], &q0 = B[j], &q1 = B[(j + 1) % nb];
        bool meet;
        if(j == i + 1 || (i == 0 && j == nb - 1))
        {
          // adjacent: they meet elsewhere than at their common vertex s only by folding back
          const Qpoint& s = (j == i + 1) ? p1 : p0;
          const Qpoint& u = (j == i + 1) ? p0 : p1;
          const Qpoint& w = (j == i + 1) ? q1 : q0;
          const auto side = [](const Qpoint& a, const Qpoint& c) { // lexicographic comparison of a with c
            return a.x < c.x ? -1 : (a.x > c.x ? 1 : (a.y < c.y ? -1 : (a.y > c.y ? 1 : 0)));
          };
          meet = orient(u, s, w) == 0 && side(u, s) == side(w, s);
        }
        else meet = closed_segments_meet(p0, p1, q0, q1);
        if(meet) ++o.border_intersections;
      }
  for(std::size_t f = 0; f < d.faces.size(); ++f)
    for(std::size_t g = f + 1; g < d.faces.size(); ++g)
    {
      if(!face_finite[f] || !face_finite[g] || fo[f] == 0 || fo[g] == 0) continue;
      const Tri &s = d.faces[f], &t = d.faces[g];
      int shared = 0;
      for(int i = 0; i < 3; ++i) for(int j = 0; j < 3; ++j) shared += (s[i] == t[j]);
      if(fo[f] == o.border_sign && fo[g] == o.border_sign && shared >= 2) continue;
      const std::array<Qpoint, 3> A = {{ P[s[0]], P[s[1]], P[s[2]] }};
      const std::array<Qpoint, 3> C = {{ P[t[0]], P[t[1]], P[t[2]] }};
      if(triangle_interiors_meet(A, C)) ++o.overlapping_pairs;
    }
  return o;
}

} // namespace pe_fuzz

#endif // PE_FUZZ_UTIL_H
