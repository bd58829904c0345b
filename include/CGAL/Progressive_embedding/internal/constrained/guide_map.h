// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_GUIDE_MAP_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_GUIDE_MAP_H

// A guide for the path tracing of constrained maps: where, roughly, each partition edge should run
// on the mesh. Shortest paths between the nodes converge: nested partition edges then squeeze
// through the corridors left by the earlier ones and need one split per edge there. The guide
// draws the partition graph and the mesh in one convex domain, the unit disk:
//  - the partition graph by Tutte's barycentric drawing: its border nodes on the circle at the arc
//    length of their mesh vertices along the mesh border, its interior nodes at the barycenter of
//    their neighbours. Border nodes follow the border order, so two straight edges cross only where
//    the rotation system says they may not (a planar drawing for 3-connected partitions);
//  - the mesh by a harmonic (uniform Tutte) map with its border on the same circle, by the same arc
//    length, and every node vertex pinned at its node's position.
// A path then pays for its distance, in the guide, to the straight segment of its partition edge:
// the paths spread as the partition's edges do. The guide is a heuristic only: it may fold where the
// constraints are in a different order on the surface than in the target; the tracing still decides
// the topology (sectors, free vertices) and the certificate decides validity.
//
// Pinning one interior node vertex far from where the mesh's own harmonic map puts it stretches its
// neighbourhood into a spike: the partition edges that must pass around the node then squeeze along the
// spike, and every one of them needs splits. With a disk factor f > 0, each interior node instead carries
// a disk of the mesh's border-only harmonic map (radius f times the node's displacement, bounded so that
// the disks stay apart and inside the circle) rigidly to its position: the region around the node keeps
// its vertices, the stretch spreads over the rest of the mesh. Neither guide is better on every input
// (the disks help most where a constraint lies near the mesh border and far from its polygon), so the
// caller may trace with both.
//
//   bool compute_guide_map(tm, vpm, vertex_id, n_ids, nodes, partition_edges, node_guide, vertex_guide, vertex_scale,
//                          disk_factor = 0)
//       tm: a triangulated disk (one border cycle); vertex_id(v) in [0, n_ids); nodes: mesh vertex per
//       node; partition_edges: the partition's interior edges (node pairs). Out: node_guide[i], vertex_guide[id], and
//       vertex_scale[id] (mean guide length of the vertex's edges: the local unit of distance).
//       Returns false (nothing usable) when the mesh has several border cycles, when a linear solve
//       fails or when a position is not finite.

#include <CGAL/Progressive_embedding/internal/length_3.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

#ifndef DOXYGEN_RUNNING
namespace internal_np {
enum guide_weight_t { guide_weight };
enum guide_disk_factor_t { guide_disk_factor };
enum interior_edges_first_t { interior_edges_first };
} // namespace internal_np
#endif

namespace internal {

typedef std::array<double, 2> Guide_point;

// appends the (internal) named parameter guide_weight, read by trace_paths(): the cost, in mean edge
// costs, of one local unit of guide distance between a path vertex and its partition edge's segment
template <class NP>
CGAL::Named_function_parameters<double, internal_np::guide_weight_t, NP> guide_weight(double w, const NP& np)
{
  return CGAL::Named_function_parameters<double, internal_np::guide_weight_t, NP>(w, np);
}

// appends the (internal) named parameter interior_edges_first, read by trace_paths()
template <class NP>
CGAL::Named_function_parameters<bool, internal_np::interior_edges_first_t, NP> interior_edges_first(bool b, const NP& np)
{
  return CGAL::Named_function_parameters<bool, internal_np::interior_edges_first_t, NP>(b, np);
}

// appends the (internal) named parameter guide_disk_factor, read by trace_paths(): compute_guide_map()'s
// disk_factor (0: only the node vertices are pinned)
template <class NP>
CGAL::Named_function_parameters<double, internal_np::guide_disk_factor_t, NP> guide_disk_factor(double f, const NP& np)
{
  return CGAL::Named_function_parameters<double, internal_np::guide_disk_factor_t, NP>(f, np);
}

// distance from p to the segment [a, b]
inline double guide_segment_distance(const Guide_point& p, const Guide_point& a, const Guide_point& b)
{
  const double ux = b[0] - a[0], uy = b[1] - a[1], wx = p[0] - a[0], wy = p[1] - a[1];
  const double uu = ux * ux + uy * uy;
  double t = uu > 0 ? (wx * ux + wy * uy) / uu : 0.;
  t = t < 0 ? 0. : (t > 1 ? 1. : t);
  const double dx = wx - t * ux, dy = wy - t * uy;
  return std::sqrt(dx * dx + dy * dy);
}

// Solves the uniform Laplace system of a graph: fixed[i] >= 0 marks a vertex placed at pos[i];
// the others get the barycenter of their neighbours. Returns false if the system cannot be solved.
inline bool solve_barycentric(const std::vector<std::vector<std::size_t> >& adjacency, const std::vector<char>& fixed,
                              std::vector<Guide_point>& pos)
{
  const std::size_t n = adjacency.size();
  std::vector<std::ptrdiff_t> index(n, -1);
  std::ptrdiff_t m = 0;
  for(std::size_t i = 0; i < n; ++i) if(!fixed[i]) index[i] = m++;
  if(m == 0) return true;
  typedef Eigen::SparseMatrix<double> SpMat;
  std::vector<Eigen::Triplet<double> > triplets;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(m, 2);
  for(std::size_t i = 0; i < n; ++i)
  {
    if(fixed[i]) continue;
    if(adjacency[i].empty()) return false;
    triplets.emplace_back(index[i], index[i], double(adjacency[i].size()));
    for(std::size_t j : adjacency[i])
    {
      if(fixed[j]) { rhs(index[i], 0) += pos[j][0]; rhs(index[i], 1) += pos[j][1]; }
      else triplets.emplace_back(index[i], index[j], -1.);
    }
  }
  SpMat A(m, m);
  A.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<SpMat> solver(A);
  if(solver.info() != Eigen::Success) return false;
  const Eigen::MatrixXd x = solver.solve(rhs);
  if(solver.info() != Eigen::Success) return false;
  for(std::size_t i = 0; i < n; ++i)
    if(!fixed[i])
    {
      pos[i] = { { x(index[i], 0), x(index[i], 1) } };
      if(!std::isfinite(pos[i][0]) || !std::isfinite(pos[i][1])) return false;
    }
  return true;
}

// the local unit of guide distance at each vertex: the mean guide length of its edges
inline void guide_scales(const std::vector<std::vector<std::size_t> >& adjacency, const std::vector<Guide_point>& guide,
                         std::vector<double>& scale)
{
  scale.assign(guide.size(), 0.);
  for(std::size_t i = 0; i < guide.size(); ++i)
  {
    double s = 0;
    for(std::size_t j : adjacency[i]) s += std::hypot(guide[i][0] - guide[j][0], guide[i][1] - guide[j][1]);
    scale[i] = adjacency[i].empty() ? 1. : s / double(adjacency[i].size());
    if(!(scale[i] > 0)) scale[i] = 1e-12;
  }
}

// The disks of compute_guide_map(): in the harmonic map with only `fixed` vertices pinned, the vertices
// within the disk of each interior node (nfixed[i] == 0) are pinned (fixed[] = 1, guide[] set), translated by the
// node's displacement to node_guide[i]. Radius: factor times the displacement, at most 0.9 times the distance of
// either center to the circle and 0.45 times the distance to any other node (before and after), so that
// the disks stay inside the circle and apart.
template <class VertexId, class Vertex>
bool pin_node_disks(const std::vector<std::vector<std::size_t> >& adjacency, std::vector<char>& fixed, VertexId vertex_id,
                    const std::vector<Vertex>& nodes, const std::vector<char>& nfixed,
                    const std::vector<Guide_point>& node_guide, double factor, std::vector<Guide_point>& guide)
{
  std::vector<Guide_point> natural = guide;
  if(!solve_barycentric(adjacency, fixed, natural)) return false;
  auto dist = [](const Guide_point& p, const Guide_point& q) { return std::hypot(p[0] - q[0], p[1] - q[1]); };
  auto norm = [](const Guide_point& p) { return std::hypot(p[0], p[1]); };
  std::vector<std::size_t> inner;
  for(std::size_t i = 0; i < nodes.size(); ++i) if(!nfixed[i]) inner.push_back(i);
  std::vector<Guide_point> from(inner.size()), to(inner.size());
  for(std::size_t k = 0; k < inner.size(); ++k) { from[k] = natural[vertex_id(nodes[inner[k]])]; to[k] = node_guide[inner[k]]; }
  std::vector<double> radius(inner.size());
  for(std::size_t k = 0; k < inner.size(); ++k)
  {
    double r = (std::min)(factor * dist(from[k], to[k]), 0.9 * (std::min)(1. - norm(from[k]), 1. - norm(to[k])));
    for(std::size_t l = 0; l < inner.size(); ++l)
      if(l != k) r = (std::min)(r, 0.45 * (std::min)(dist(from[k], from[l]), dist(to[k], to[l])));
    radius[k] = r;
  }
  // every vertex against every disk: O(vertices x interior nodes), small next to the tracing
  for(std::size_t v = 0; v < fixed.size(); ++v)
  {
    if(fixed[v]) continue;
    for(std::size_t k = 0; k < inner.size(); ++k)
      if(dist(natural[v], from[k]) < radius[k])
      {
        guide[v] = { { natural[v][0] + to[k][0] - from[k][0], natural[v][1] + to[k][1] - from[k][1] } };
        fixed[v] = 1;
        break;
      }
  }
  return true;
}

template <class TM, class VPM, class VertexId>
bool compute_guide_map(const TM& tm, VPM vpm, VertexId vertex_id, std::size_t n_ids,
                       const std::vector<typename boost::graph_traits<TM>::vertex_descriptor>& nodes,
                       const std::vector<std::array<std::size_t, 2> >& partition_edges,
                       std::vector<Guide_point>& node_guide, std::vector<Guide_point>& vertex_guide,
                       std::vector<double>& vertex_scale, double disk_factor = 0.)
{
  typedef typename boost::graph_traits<TM>::halfedge_descriptor halfedge_descriptor;
  // the one border cycle, walked with the interior on the left (border halfedges backwards)
  halfedge_descriptor b0 = boost::graph_traits<TM>::null_halfedge();
  std::size_t cycles = 0, border_halfedges = 0;
  for(halfedge_descriptor h : halfedges(tm))
    if(CGAL::is_border(h, tm)) { ++border_halfedges; if(b0 == boost::graph_traits<TM>::null_halfedge()) b0 = h; }
  if(b0 == boost::graph_traits<TM>::null_halfedge()) return false;
  std::vector<std::size_t> loop;
  std::vector<double> arc;
  {
    halfedge_descriptor h = b0;
    double s = 0;
    std::size_t guard = 0;
    do
    {
      loop.push_back(vertex_id(target(h, tm)));
      arc.push_back(s);
      const auto p = get(vpm, source(h, tm)), q = get(vpm, target(h, tm));
      s += length_3(p, q);
      h = prev(h, tm);
    } while(h != b0 && ++guard <= border_halfedges);
    ++cycles;
    if(loop.size() != border_halfedges) return false; // several border cycles
    if(!(s > 0)) return false;
    for(double& a : arc) a /= s;
  }
  (void)cycles;
  const double two_pi = 6.283185307179586;
  vertex_guide.assign(n_ids, Guide_point{ { 0., 0. } });
  std::vector<char> vfixed(n_ids, 0);
  for(std::size_t k = 0; k < loop.size(); ++k)
  {
    vertex_guide[loop[k]] = { { std::cos(two_pi * arc[k]), std::sin(two_pi * arc[k]) } };
    vfixed[loop[k]] = 1;
  }
  // the partition graph's Tutte drawing
  const std::size_t N = nodes.size();
  std::vector<std::vector<std::size_t> > nadj(N);
  for(const auto& e : partition_edges) { nadj[e[0]].push_back(e[1]); nadj[e[1]].push_back(e[0]); }
  std::vector<char> nfixed(N, 0);
  node_guide.assign(N, Guide_point{ { 0., 0. } });
  for(std::size_t i = 0; i < N; ++i)
  {
    const std::size_t id = vertex_id(nodes[i]);
    if(vfixed[id]) { nfixed[i] = 1; node_guide[i] = vertex_guide[id]; }
  }
  if(!solve_barycentric(nadj, nfixed, node_guide)) return false;
  // the mesh's harmonic map with the nodes pinned (measured on Hilbert-curve borders: fewer Steiner
  // vertices than leaving the nodes where the mesh's own Tutte map puts them)
  std::vector<std::vector<std::size_t> > vadj(n_ids);
  for(auto e : edges(tm))
  {
    const std::size_t a = vertex_id(source(halfedge(e, tm), tm)), b = vertex_id(target(halfedge(e, tm), tm));
    vadj[a].push_back(b); vadj[b].push_back(a);
  }
  if(disk_factor > 0 && !pin_node_disks(vadj, vfixed, vertex_id, nodes, nfixed, node_guide, disk_factor, vertex_guide))
    return false;
  for(std::size_t i = 0; i < N; ++i) { const std::size_t id = vertex_id(nodes[i]); vertex_guide[id] = node_guide[i]; vfixed[id] = 1; }
  if(!solve_barycentric(vadj, vfixed, vertex_guide)) return false;
  guide_scales(vadj, vertex_guide, vertex_scale);
  return true;
}


} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_GUIDE_MAP_H
