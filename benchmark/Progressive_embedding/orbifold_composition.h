// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors
//
// The comparison a CGAL user has for two closed genus-0 meshes: CGAL's Orbifold Tutte embedding (Aigerman and
// Lipman) of each mesh with the same cones (3 or 4 landmarks), composed. Each mesh is cut along CGAL's shortest paths
// between consecutive cones (compute_shortest_paths_between_cones()) into a Seam_mesh whose map is one tile of a
// periodic tiling of the plane; both maps put their cones at the same points, so a vertex of A corresponds to the
// point of B whose image is the same point of the plane up to a motion of the tiling's group. The group is read off
// B's map: across each seam edge, the rigid motion that takes the edge's image on one side onto its image on the other
// (rotations by multiples of 30 degrees, the cones' orders being 2, 3, 4 or 6). B's tile is copied by the products of
// up to three such motions that reach A's tile, and each vertex of A is located among the copies' triangles in double
// precision. Nothing here is certified: faces of a map flipped or degenerate (exact orientation test) are counted,
// and vertices of A found in no positively oriented copied triangle are counted as unlocated.
// Benchmark code, not part of the library.

#ifndef PE_BENCH_ORBIFOLD_COMPOSITION_H
#define PE_BENCH_ORBIFOLD_COMPOSITION_H

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Orbifold_Tutte_parameterizer_3.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Aff_transformation_2.h>
#include <CGAL/Bbox_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <list>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pe_bench {

template <class K>
struct Orbifold_map
{
  typedef typename K::Point_2 Point_2;
  std::vector<std::array<Point_2, 3> > corners; // per face (index order): source(h), target(h), target(next(h)), h = halfedge(f)
  std::vector<Point_2> vertex_uv;                // per vertex: one of its images (a seam vertex has several)
  std::vector<typename K::Aff_transformation_2> gluing; // the motions across the seam, distinct, with their inverses
  std::size_t seam_edges = 0, flipped = 0, degenerate = 0;
  bool mirrored = false; // most faces clockwise: orientations are then read the other way round
};

namespace orbifold_internal {

// the rigid motion taking segment (s1, t1) onto (s2, t2), its angle snapped to a multiple of 30 degrees
template <class K>
typename K::Aff_transformation_2 motion(const typename K::Point_2& s1, const typename K::Point_2& t1,
                                        const typename K::Point_2& s2, const typename K::Point_2& t2)
{
  const typename K::Vector_2 d1 = t1 - s1, d2 = t2 - s2;
  double angle = std::atan2(d1.x() * d2.y() - d1.y() * d2.x(), d1 * d2);
  angle = std::round(angle / (CGAL_PI / 6)) * (CGAL_PI / 6);
  const double c = std::cos(angle), s = std::sin(angle);
  // x -> R (x - m1) + m2, m the segments' midpoints
  const double m1x = 0.5 * (s1.x() + t1.x()), m1y = 0.5 * (s1.y() + t1.y());
  const double m2x = 0.5 * (s2.x() + t2.x()), m2y = 0.5 * (s2.y() + t2.y());
  return typename K::Aff_transformation_2(c, -s, m2x - (c * m1x - s * m1y), s, c, m2y - (s * m1x + c * m1y));
}

template <class T>
bool same_motion(const T& a, const T& b, double tolerance)
{
  for(int i = 0; i < 2; ++i)
    for(int j = 0; j < 3; ++j)
      if(std::abs(a.m(i, j) - b.m(i, j)) > tolerance) return false;
  return true;
}

template <class T>
bool insert_motion(std::vector<T>& motions, const T& t, double tolerance)
{
  for(const T& u : motions) if(same_motion(u, t, tolerance)) return false;
  motions.push_back(t);
  return true;
}

} // namespace orbifold_internal

/// Maps the closed mesh `m` by CGAL's Orbifold Tutte embedding (`type`, mean value weights: positive, so the map is
/// bijective in exact arithmetic) with `cones` (3, or 4 for the parallelogram), cut along CGAL's shortest paths
/// between consecutive cones. Returns CGAL's error code; `ERROR_WRONG_PARAMETER` before solving when those paths do not
/// make a chain through the cones (they cross or overlap: another order of the cones may do).
template <class K, class SM>
int orbifold_map(SM& m, const std::vector<typename SM::Vertex_index>& cones,
                 CGAL::Surface_mesh_parameterization::Orbifold_type type, Orbifold_map<K>& out)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  typedef typename SM::Vertex_index V;
  typedef typename SM::Edge_index E;
  typedef typename SM::Halfedge_index H;
  typedef typename SM::template Property_map<E, bool> Seam_edges;
  typedef typename SM::template Property_map<V, bool> Seam_vertices;
  typedef CGAL::Seam_mesh<SM, Seam_edges, Seam_vertices> Mesh;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor MV;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor MH;
  typedef typename K::Point_2 Point_2;

  out = Orbifold_map<K>(); // nothing kept from a try with another order of the cones
  // fresh property maps, removed on return (the caller may try another order of the cones)
  Seam_edges seam_e = m.template add_property_map<E, bool>("e:orbifold_seam", false).first;
  Seam_vertices seam_v = m.template add_property_map<V, bool>("v:orbifold_seam", false).first;
  typedef typename SM::template Property_map<H, Point_2> UV_map;
  UV_map uv = m.template add_property_map<H, Point_2>("h:orbifold_uv").first;
  struct Remove
  {
    SM& mesh; Seam_edges& e; Seam_vertices& v; UV_map& map;
    ~Remove() { mesh.remove_property_map(e); mesh.remove_property_map(v); mesh.remove_property_map(map); }
  } remove = { m, seam_e, seam_v, uv };
  Mesh mesh(m, seam_e, seam_v);
  std::list<E> seam;
  SMP::compute_shortest_paths_between_cones(m, cones.begin(), cones.end(), seam);
  for(E e : seam) mesh.add_seam(source(e, m), target(e, m));
  out.seam_edges = mesh.number_of_seam_edges();
  std::unordered_map<MV, int> indices;
  int counter = 0;
  for(MV v : vertices(mesh)) indices[v] = counter++;
  std::unordered_map<MV, SMP::Cone_type> cone_map;
  SMP::locate_cones(mesh, cones.begin(), cones.end(), cone_map);
  // the paths must make a chain through the cones, a tree cutting the sphere into one disk: each inner cone twice
  // on the disk's border, and V - E + F = 1 (the shortest paths of consecutive cones may cross or overlap)
  const std::size_t expected = 2 * cones.size() - 2;
  const long euler = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
  if(cone_map.size() != expected || euler != 1) return int(SMP::ERROR_WRONG_PARAMETER);
  SMP::Orbifold_Tutte_parameterizer_3<Mesh> parameterizer(type, SMP::Mean_value);
  const MH border = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  const SMP::Error_code ec =
    parameterizer.parameterize(mesh, border, cone_map, uv, boost::associative_property_map<std::unordered_map<MV, int> >(indices));
  if(ec != SMP::OK) return int(ec);

  out.corners.assign(m.number_of_faces(), std::array<Point_2, 3>());
  out.vertex_uv.assign(m.number_of_vertices(), Point_2(0, 0));
  std::vector<char> seen(m.number_of_vertices(), 0);
  std::size_t positive = 0, negative = 0;
  for(auto f : faces(m))
  {
    MH h = halfedge(f, mesh);
    std::array<Point_2, 3>& c = out.corners[std::size_t(f)];
    for(int k = 0; k < 3; ++k, h = next(h, mesh))
    {
      c[(k + 1) % 3] = get(uv, target(h, mesh)); // halfedge(f) has source corner 0 and target corner 1
      const V v = target(h.tmhd, m);
      if(!seen[std::size_t(v)]) { seen[std::size_t(v)] = 1; out.vertex_uv[std::size_t(v)] = c[(k + 1) % 3]; }
    }
    const CGAL::Orientation o = CGAL::orientation(c[0], c[1], c[2]);
    if(o == CGAL::POSITIVE) ++positive;
    else if(o == CGAL::NEGATIVE) ++negative;
    else ++out.degenerate;
  }
  out.mirrored = negative > positive;
  out.flipped = out.mirrored ? positive : negative;

  // the motions across the seam: side of h onto side of opposite(h)
  double extent = 0;
  for(const Point_2& p : out.vertex_uv) extent = (std::max)(extent, (std::max)(std::abs(p.x()), std::abs(p.y())));
  const double tolerance = 1e-6 * (std::max)(extent, 1.);
  for(E e : edges(m))
  {
    if(!get(seam_e, e)) continue;
    const H h = halfedge(e, m), o = opposite(h, m);
    const MH hs(h), os(o);
    const Point_2 s1 = get(uv, source(hs, mesh)), t1 = get(uv, target(hs, mesh));
    const Point_2 s2 = get(uv, target(os, mesh)), t2 = get(uv, source(os, mesh));
    const typename K::Aff_transformation_2 t = orbifold_internal::motion<K>(s1, t1, s2, t2);
    orbifold_internal::insert_motion(out.gluing, t, tolerance);
    orbifold_internal::insert_motion(out.gluing, t.inverse(), tolerance);
  }
  return int(SMP::OK);
}

/// Locates each vertex of A (`map_a`) in the copies of B's tile (`map_b`) under the products of up to `depth` of B's
/// gluing motions that reach A's tile. `located[v]` is the face of B and the barycentric coordinates (in the
/// order of Face_location) of the vertex `v` of A, or `std::size_t(-1)` as face when no positively oriented copied
/// triangle holds it; returns the number of such vertices, and the number of copies of B's tile used in `copies`.
template <class K>
std::size_t locate_in_tiling(const Orbifold_map<K>& map_a, const Orbifold_map<K>& map_b, int depth,
                             std::vector<std::pair<std::size_t, std::array<double, 3> > >& located, std::size_t& copies)
{
  typedef typename K::Point_2 Point_2;
  typedef typename K::Aff_transformation_2 T;
  CGAL::Bbox_2 box_a = CGAL::bbox_2(map_a.vertex_uv.begin(), map_a.vertex_uv.end());
  CGAL::Bbox_2 box_b = CGAL::bbox_2(map_b.vertex_uv.begin(), map_b.vertex_uv.end());
  const double extent = (std::max)({ box_a.xmax() - box_a.xmin(), box_a.ymax() - box_a.ymin(), 1e-300 });
  const double tolerance = 1e-6 * (std::max)(1., extent);
  // the copies of B's tile: products of the gluing motions, kept when they reach A's tile
  std::vector<T> motions(1, T(CGAL::IDENTITY)), frontier = motions, kept;
  auto reaches = [&](const T& t) {
    const Point_2 corners[4] = { t(Point_2(box_b.xmin(), box_b.ymin())), t(Point_2(box_b.xmax(), box_b.ymin())),
                                 t(Point_2(box_b.xmax(), box_b.ymax())), t(Point_2(box_b.xmin(), box_b.ymax())) };
    return CGAL::do_overlap(CGAL::bbox_2(corners, corners + 4), box_a);
  };
  for(int d = 0; d < depth; ++d)
  {
    std::vector<T> next;
    for(const T& t : frontier)
      for(const T& g : map_b.gluing)
      {
        const T u = t * g;
        if(orbifold_internal::insert_motion(motions, u, tolerance)) next.push_back(u);
      }
    frontier.swap(next);
  }
  for(const T& t : motions) if(reaches(t)) kept.push_back(t);
  copies = kept.size();

  // a grid over A's tile holding the copied triangles of B that overlap it
  const std::size_t n = map_a.vertex_uv.size();
  const std::size_t cells = (std::max)(std::size_t(1), std::size_t(std::sqrt(double(n))));
  const double cw = (box_a.xmax() - box_a.xmin()) / double(cells) + 1e-300, ch = (box_a.ymax() - box_a.ymin()) / double(cells) + 1e-300;
  auto cell = [&](double v, double lo, double w) {
    const double c = std::floor((v - lo) / w);
    return std::size_t((std::min)((std::max)(c, 0.), double(cells - 1)));
  };
  struct Tri { std::size_t face; std::array<Point_2, 3> p; };
  std::vector<Tri> triangles;
  std::vector<std::vector<std::size_t> > grid(cells * cells);
  // a rotation keeps orientations: a triangle of B counts where its own map has it positive
  const CGAL::Orientation positive = map_b.mirrored ? CGAL::NEGATIVE : CGAL::POSITIVE;
  std::vector<std::size_t> usable;
  for(std::size_t f = 0; f < map_b.corners.size(); ++f)
  {
    const std::array<Point_2, 3>& c = map_b.corners[f];
    if(CGAL::orientation(c[0], c[1], c[2]) == positive) usable.push_back(f);
  }
  for(const T& t : kept)
  {
    for(std::size_t f : usable)
    {
      const std::array<Point_2, 3>& c = map_b.corners[f];
      const Tri tri = { f, {{ t(c[0]), t(c[1]), t(c[2]) }} };
      const CGAL::Bbox_2 b = CGAL::bbox_2(tri.p.begin(), tri.p.end());
      if(!CGAL::do_overlap(b, box_a)) continue;
      const std::size_t x0 = cell(b.xmin(), box_a.xmin(), cw), x1 = cell(b.xmax(), box_a.xmin(), cw);
      const std::size_t y0 = cell(b.ymin(), box_a.ymin(), ch), y1 = cell(b.ymax(), box_a.ymin(), ch);
      for(std::size_t x = x0; x <= x1; ++x)
        for(std::size_t y = y0; y <= y1; ++y) grid[x * cells + y].push_back(triangles.size());
      triangles.push_back(tri);
    }
  }
  located.assign(n, std::make_pair(std::size_t(-1), std::array<double, 3>{{ 1., 0., 0. }}));
  std::size_t unlocated = 0;
  for(std::size_t v = 0; v < n; ++v)
  {
    const Point_2& q = map_a.vertex_uv[v];
    double best = -1e-9;
    for(std::size_t i : grid[cell(q.x(), box_a.xmin(), cw) * cells + cell(q.y(), box_a.ymin(), ch)])
    {
      const std::array<Point_2, 3>& p = triangles[i].p;
      const double area = CGAL::area(p[0], p[1], p[2]);
      std::array<double, 3> w = {{ CGAL::area(q, p[1], p[2]) / area, CGAL::area(p[0], q, p[2]) / area, 0. }};
      w[2] = 1. - w[0] - w[1];
      const double worst = (std::min)({ w[0], w[1], w[2] });
      if(worst > best) { best = worst; located[v] = std::make_pair(triangles[i].face, w); }
    }
    if(located[v].first == std::size_t(-1)) ++unlocated;
  }
  return unlocated;
}

} // namespace pe_bench

#endif // PE_BENCH_ORBIFOLD_COMPOSITION_H
