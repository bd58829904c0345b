// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_REMESHED_PAIR_PROTOCOL_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_REMESHED_PAIR_PROTOCOL_H

// The ground-truth protocol of cross-parameterization, shared by the tests and the benchmark: B is A
// remeshed by CGAL's isotropic remeshing (one surface, two triangulations); the landmarks are interior
// vertices of A spread out by farthest-point sampling, each matched to the nearest interior vertex of B
// not yet used; the error of a vertex of A is the 3D distance to its image on B, relative to the
// diagonal of A's bounding box.

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// `b` remeshed in place: target edge length `factor` times its mean edge length, `iterations` iterations
template <class Mesh>
void remesh_isotropically(Mesh& b, double factor = 1.3, unsigned iterations = 3)
{
  std::size_t ne = 0;
  double mean = 0;
  for(auto e : edges(b)) { mean += CGAL::to_double(CGAL::Polygon_mesh_processing::edge_length(e, b)); ++ne; }
  mean /= double(ne);
  CGAL::Polygon_mesh_processing::isotropic_remeshing(faces(b), factor * mean, b,
                                                     CGAL::parameters::number_of_iterations(iterations));
}

// `count` interior vertices of `m`, far apart: the middle one of `vertices(m)`, then each time the
// farthest from those chosen
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> spread_interior_vertices(const Mesh& m, std::size_t count)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vd;
  std::vector<vd> in;
  for(vd v : vertices(m)) if(!CGAL::is_border(v, m)) in.push_back(v);
  std::vector<vd> c;
  if(in.empty() || count == 0) return c;
  c.push_back(in[in.size() / 2]);
  std::vector<double> d(in.size(), std::numeric_limits<double>::infinity());
  while(c.size() < (std::min)(count, in.size()))
  {
    std::size_t best = 0;
    for(std::size_t i = 0; i < in.size(); ++i)
    {
      d[i] = (std::min)(d[i], CGAL::to_double(CGAL::squared_distance(get(CGAL::vertex_point, m, in[i]),
                                                                     get(CGAL::vertex_point, m, c.back()))));
      if(d[i] > d[best]) best = i;
    }
    c.push_back(in[best]);
  }
  return c;
}

// each vertex of `la` (of `a`) with the nearest interior vertex of `b` not matched before
template <class MeshA, class MeshB>
std::vector<std::pair<typename boost::graph_traits<MeshA>::vertex_descriptor, typename boost::graph_traits<MeshB>::vertex_descriptor> >
nearest_vertex_landmarks(const MeshA& a, const MeshB& b, const std::vector<typename boost::graph_traits<MeshA>::vertex_descriptor>& la)
{
  typedef typename boost::graph_traits<MeshB>::vertex_descriptor vb;
  std::vector<std::pair<typename boost::graph_traits<MeshA>::vertex_descriptor, vb> > r;
  std::set<vb> used;
  for(auto v : la)
  {
    vb best = boost::graph_traits<MeshB>::null_vertex();
    double bd = std::numeric_limits<double>::infinity();
    for(vb w : vertices(b))
    {
      if(CGAL::is_border(w, b) || used.count(w)) continue;
      const double d = CGAL::to_double(CGAL::squared_distance(get(CGAL::vertex_point, a, v), get(CGAL::vertex_point, b, w)));
      if(d < bd) { bd = d; best = w; }
    }
    if(best == boost::graph_traits<MeshB>::null_vertex()) break;
    used.insert(best);
    r.emplace_back(v, best);
  }
  return r;
}

template <class Mesh>
double bbox_diagonal(const Mesh& m)
{
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(m);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
}

// the distance between the point of `b` at the location of each vertex of `a` (in `vertices(a)` order) and the
// true image of that vertex, the point of `b` nearest to it (an AABB tree of `b`'s faces), relative to the
// diagonal of `a`'s bounding box: for two meshes of one surface, the error of the correspondence alone,
// not the distance between the two discretizations
template <class MeshA, class MeshB, class LocationMap>
std::vector<double> correspondence_errors(const MeshA& a, const MeshB& b, LocationMap locations)
{
  typedef typename boost::property_traits<typename boost::property_map<MeshB, CGAL::vertex_point_t>::const_type>::value_type Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel K;
  typedef CGAL::AABB_face_graph_triangle_primitive<MeshB> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;
  Tree tree(faces(b).first, faces(b).second, b);
  tree.accelerate_distance_queries();
  const double diag = bbox_diagonal(a);
  std::vector<double> errors;
  for(auto v : vertices(a))
  {
    const auto p = CGAL::Polygon_mesh_processing::construct_point(get(locations, v), b);
    const auto q = get(CGAL::vertex_point, a, v);
    const Point_3 truth = tree.closest_point(Point_3(q.x(), q.y(), q.z()));
    errors.push_back(std::sqrt(CGAL::to_double(CGAL::squared_distance(p, truth))) / diag);
  }
  return errors;
}

// the mean and the largest of `correspondence_errors()`
template <class MeshA, class MeshB, class LocationMap>
std::pair<double, double> correspondence_error(const MeshA& a, const MeshB& b, LocationMap locations)
{
  const std::vector<double> errors = correspondence_errors(a, b, locations);
  double sum = 0, worst = 0;
  for(double e : errors) { sum += e; worst = (std::max)(worst, e); }
  return std::make_pair(errors.empty() ? 0. : sum / double(errors.size()), worst);
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_REMESHED_PAIR_PROTOCOL_H
