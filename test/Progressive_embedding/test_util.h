// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Helpers shared by the test programs: CHECK macros, uv maps on any FaceGraph,
// number-type conversions, the data protocols written out independently of the
// package where a test compares against them.

#ifndef CGAL_PROGRESSIVE_EMBEDDING_TEST_UTIL_H
#define CGAL_PROGRESSIVE_EMBEDDING_TEST_UTIL_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Real_timer.h>

#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace PE = CGAL::Progressive_embedding;

typedef CGAL::Exact_predicates_inexact_constructions_kernel   Epick;
typedef CGAL::Simple_cartesian<CGAL::Gmpq>                    Kq;
typedef CGAL::Simple_cartesian<CGAL::Gmpfr>                   Kfr;
typedef CGAL::Surface_mesh<Epick::Point_3>                    Surface_mesh;
typedef CGAL::Polyhedron_3<Epick>                             Polyhedron;

// Stops the test at the first failed check, saying what failed and where.
#define CHECK(cond, msg)                                                                          \
  do {                                                                                            \
    if(!(cond)) {                                                                                 \
      std::cerr << "FAILED " << __FILE__ << ":" << __LINE__ << ": " << #cond << " -- " << msg << std::endl; \
      return EXIT_FAILURE;                                                                        \
    }                                                                                             \
  } while(0)

#define RUN(call) do { if((call) != EXIT_SUCCESS) return EXIT_FAILURE; } while(0)

// The default traits with an orientation predicate that counts its calls: a function that honours
// `geom_traits` decides its signs through it.
struct Counting_traits : public PE::Progressive_embedding_traits_2<Kq>
{
  typedef PE::Progressive_embedding_traits_2<Kq> Base;
  static inline std::size_t calls = 0;
  struct Exact_orientation_2
  {
    typedef CGAL::Orientation result_type;
    CGAL::Orientation operator()(const Kq::Point_2& p, const Kq::Point_2& q, const Kq::Point_2& r) const
    { ++calls; return Base::Exact_orientation_2()(p, q, r); }
  };
  Exact_orientation_2 exact_orientation_2_object() const { return Exact_orientation_2(); }
};

template <class Mesh> const char* mesh_name();
template <> inline const char* mesh_name<Surface_mesh>() { return "Surface_mesh"; }
template <> inline const char* mesh_name<Polyhedron>() { return "Polyhedron_3"; }

template <class K> const char* nt_name();
template <> inline const char* nt_name<Epick>() { return "double"; }
template <> inline const char* nt_name<Kq>() { return "Gmpq"; }
template <> inline const char* nt_name<Kfr>() { return "Gmpfr"; }

// A uv map on any FaceGraph: a dynamic vertex property (a Surface_mesh property, a hash map for Polyhedron_3).
template <class Mesh, class Point_2>
auto make_uv_map(Mesh& m, const Point_2&)
{
  return get(CGAL::dynamic_vertex_property_t<Point_2>(), m);
}

// FT from a double, exactly (Gmpfr gets at least the default precision)
template <class FT>
FT ft(double d)
{
  if constexpr(std::is_same<FT, CGAL::Gmpfr>::value)
    return CGAL::Gmpfr(d, (std::max)(CGAL::Gmpfr::Precision_type(53), CGAL::Gmpfr::get_default_precision()));
  else
    return FT(d);
}

template <class K>
typename K::Point_2 point(double x, double y) { return typename K::Point_2(ft<typename K::FT>(x), ft<typename K::FT>(y)); }

// copies a uv map into another number type: exactly from double, with to_double towards double
template <class Mesh, class From, class To>
void convert_uv(const Mesh& m, const From& from, To& to)
{
  typedef typename boost::property_traits<To>::value_type P;
  typedef typename CGAL::Kernel_traits<P>::Kernel::FT FT;
  for(auto v : vertices(m))
  {
    const auto& p = get(from, v);
    if constexpr(std::is_same<FT, double>::value)
      put(to, v, P(CGAL::to_double(p.x()), CGAL::to_double(p.y())));
    else
      put(to, v, P(ft<FT>(CGAL::to_double(p.x())), ft<FT>(CGAL::to_double(p.y()))));
  }
}

inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

// faces(m).size(): num_faces(Surface_mesh) also counts removed faces
template <class Mesh>
std::size_t count_faces(const Mesh& m) { return static_cast<std::size_t>(std::distance(faces(m).begin(), faces(m).end())); }

template <class Mesh>
std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t> vertex_ids(const Mesh& m)
{
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t> id;
  for(auto v : vertices(m)) id.emplace(v, id.size());
  return id;
}

// the face list, as vertex indices in the order of vertices(m)
template <class Mesh>
std::vector<std::array<std::size_t, 3> > face_list(const Mesh& m)
{
  auto id = vertex_ids(m);
  std::vector<std::array<std::size_t, 3> > F;
  for(auto f : faces(m))
  {
    std::array<std::size_t, 3> t = { 0, 0, 0 };
    int k = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) { if(k < 3) t[k] = id[v]; ++k; }
    F.push_back(t);
  }
  return F;
}

// exact rationals of the coordinates, written independently of the package
inline CGAL::Gmpq exact_rational(double d) { return CGAL::Gmpq(d); }
inline CGAL::Gmpq exact_rational(const CGAL::Gmpq& q) { return q; }
inline CGAL::Gmpq exact_rational(const CGAL::Gmpfr& f) { return CGAL::Gmpq(f); }

// Independent certificate count: orientation of every face with CGAL::orientation on exact
// rational points (whatever the number type and magnitude of the uv coordinates), compared
// with the orientation `expected` of a valid map.
template <class Mesh, class UVM>
void count_orientations(const Mesh& m, const UVM& uv, CGAL::Orientation expected, std::size_t& flipped, std::size_t& degenerate)
{
  flipped = degenerate = 0;
  for(auto f : faces(m))
  {
    std::vector<Kq::Point_2> p;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m))
      p.push_back(Kq::Point_2(exact_rational(get(uv, v).x()), exact_rational(get(uv, v).y())));
    const CGAL::Orientation o = CGAL::orientation(p[0], p[1], p[2]);
    if(o == CGAL::COLLINEAR) ++degenerate;
    else if(o != expected) ++flipped;
  }
}

// d * 2^e, exactly, in FT (Gmpfr: 53 bits, enough for a double)
template <class FT>
FT scaled_ft(double d, long e)
{
  if constexpr(std::is_same<FT, CGAL::Gmpq>::value)
  {
    CGAL::Gmpq q(d), r;
    if(e >= 0) mpq_mul_2exp(r.mpq(), q.mpq(), static_cast<mp_bitcnt_t>(e));
    else mpq_div_2exp(r.mpq(), q.mpq(), static_cast<mp_bitcnt_t>(-e));
    return r;
  }
  else
  {
    static_assert(std::is_same<FT, CGAL::Gmpfr>::value, "Gmpq or Gmpfr");
    CGAL::Gmpfr r(d, 53); // exact; r is not shared, its value can be scaled in place
    mpfr_mul_2si(r.fr(), r.fr(), e, MPFR_RNDN);
    return r;
  }
}

// copies a double uv map into K, every coordinate times 2^e exactly
template <class K, class Mesh, class From, class To>
void scaled_copy(const Mesh& m, const From& from, To& to, long e)
{
  typedef typename K::FT FT;
  for(auto v : vertices(m))
    put(to, v, typename K::Point_2(scaled_ft<FT>(get(from, v).x(), e), scaled_ft<FT>(get(from, v).y(), e)));
}

template <class Mesh>
bool read_mesh(const std::string& filename, Mesh& m)
{
  if(!CGAL::IO::read_polygon_mesh(filename, m)) { std::cerr << "cannot read " << filename << std::endl; return false; }
  return true;
}

// The Tutte-failure protocol's pins, clockwise.
template <class K, class UVM, class VD>
void pin_corners(UVM& uv, const std::array<VD, 3>& c)
{
  put(uv, c[0], point<K>(0, 0));
  put(uv, c[1], point<K>(0.5, std::sqrt(3.) / 2));
  put(uv, c[2], point<K>(1, 0));
}

// Random-init protocol: border on the unit circle by arc length (computed in double by
// tutte_embedding), interior vertices uniformly random in the disk inscribed in the border
// polygon (radius: the smallest distance from the center to a border edge).
template <class Mesh, class UVM>
void random_init(const Mesh& m, UVM& uv, unsigned seed)
{
  double r_in = 1;
  for(auto h : halfedges(m))
  {
    if(!is_border(h, m)) continue;
    const auto p = get(uv, source(h, m)), q = get(uv, target(h, m));
    const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y()), qx = CGAL::to_double(q.x()), qy = CGAL::to_double(q.y());
    const double len = std::hypot(qx - px, qy - py);
    if(len > 0) r_in = (std::min)(r_in, std::abs(px * qy - py * qx) / len);
  }
  r_in *= 1 - 1e-9;
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> unif(-1., 1.);
  typedef typename boost::property_traits<UVM>::value_type P;
  typedef typename CGAL::Kernel_traits<P>::Kernel K;
  for(auto v : vertices(m))
  {
    if(CGAL::is_border(v, m)) continue;
    double x, y;
    do { x = unif(gen); y = unif(gen); } while(x * x + y * y >= 1);
    put(uv, v, point<K>(r_in * x, r_in * y));
  }
}

#endif // CGAL_PROGRESSIVE_EMBEDDING_TEST_UTIL_H
