// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_TRACE_KINETIC_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_TRACE_KINETIC_H

// Phase 2 of constrained maps in the homeomorphism class of a motion of the targets
// (kinetic_triangulation.h): the start triangulation's edges are traced as curves over the input
// edges (trace_overlay.h's Overlay_tracer), then every flip of the motion takes its edge's curve out
// and traces the new diagonal inside the quadrilateral the two triangles leave (the new curve leaves c
// between the curves to a and b and arrives at d between those to b and a, and crosses no curve: it
// stays in the quadrilateral); the edges the merge into convex polygons dropped are taken out at the
// end, and the mesh is refined once.
//
//   Error_code trace_paths_kinetic(tm, vpm, nodes, kinetic, partition, paths, steiner, np)
//       tm: a triangulated disk; nodes[i]: the mesh vertex of node i (border nodes first, in border
//       order, interior on the left); kinetic: the motion, whose end triangulation `partition` merges
//       (every edge of partition.edges is an edge of kinetic.final_triangles). On OK, paths[i] runs
//       from nodes[partition.edges[i][0]] to nodes[partition.edges[i][1]] and check_traced_paths()
//       accepts the paths (patches not labelled); steiner receives the vertices added, as
//       trace_paths_overlay() records them. np: maximum_steiner_vertices (live crossings at any time;
//       default overlay_tracing_budget), CGAL::parameters::maximum_running_time.
//   Errors: ERROR_BUDGET_EXHAUSTED (either budget), ERROR_PATH_TRACING_FAILED (no curve in a sector:
//   a motion that the floating-point simulation got wrong), the errors of check_triangulated_disk().
//
//   std::size_t kinetic_proxy_crossings(kinetic, border, start, max_crossings, max_seconds)
//       how much the motion's curves wind, cheaply: their crossings with a mesh made of the motion's own
//       start triangulation (see there); used to choose which motion is traced on the mesh.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/internal/constrained/domain_partition.h>
#include <CGAL/Progressive_embedding/internal/constrained/kinetic_triangulation.h>
#include <CGAL/Progressive_embedding/internal/constrained/path_network.h>
#include <CGAL/Progressive_embedding/internal/constrained/trace_overlay.h>
#include <CGAL/Progressive_embedding/internal/constrained/tracer_budgets.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// The interior edges of a triangulation of nodes 0..nn-1 (border nodes 0..nb-1 counterclockwise) with
// given ids, and each node's rotation (ids counterclockwise; a border node's from its side towards
// node + 1 to its side towards node - 1), as Domain_partition orders them.
inline bool triangulation_rotation(const std::vector<std::array<std::size_t, 3> >& tri, std::size_t nb, std::size_t nn,
                                   const std::vector<std::array<std::size_t, 2> >& edges,
                                   std::vector<std::vector<std::size_t> >& rotation)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> id;
  for(std::size_t e = 0; e < edges.size(); ++e)
    id[std::minmax(edges[e][0], edges[e][1])] = e;
  const std::size_t none = std::size_t(-1);
  auto edge_id = [&](std::size_t u, std::size_t v) {
    const auto it = id.find(std::minmax(u, v));
    return it == id.end() ? none : it->second; // none: a border side
  };
  // around u, after the edge to y comes the edge to z for every counterclockwise triangle (u, y, z)
  std::vector<std::map<std::size_t, std::size_t> > after(nn);
  for(const auto& t : tri)
    for(int i = 0; i < 3; ++i)
    {
      if(t[i] >= nn) return false;
      after[t[i]][t[(i + 1) % 3]] = t[(i + 2) % 3];
    }
  rotation.assign(nn, std::vector<std::size_t>());
  for(std::size_t u = 0; u < nn; ++u)
  {
    if(after[u].empty()) return false;
    std::size_t y = u < nb ? (u + 1) % nb : after[u].begin()->first;
    const std::size_t first = y;
    for(std::size_t step = 0; step <= after[u].size(); ++step)
    {
      if(!(u < nb && (y == (u + 1) % nb || y == (u + nb - 1) % nb))) rotation[u].push_back(edge_id(u, y));
      const auto it = after[u].find(y);
      if(it == after[u].end()) break; // border node: reached its side towards node - 1
      y = it->second;
      if(y == first) break;           // interior node: full turn
    }
    for(std::size_t e : rotation[u]) if(e == none) return false;
  }
  return true;
}

// The curves of the motion on the mesh, as crossings held by `tracer`: the start triangulation's edges, then
// each flip's new diagonal (the curve of the flipped edge taken out).
template <class TriangleMesh, class VertexPointMap>
Error_code trace_kinetic_curves(TriangleMesh& tm, VertexPointMap vpm, Overlay_tracer<TriangleMesh, VertexPointMap>& tracer,
                                const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& nodes,
                                const Kinetic_triangulation& kinetic, const std::vector<std::vector<std::size_t> >& rotation0,
                                std::size_t max_splits, const CGAL::Real_timer& timer, double max_seconds)
{
  tracer.set_crossing_cost(4.);
  const Error_code status = trace_partition_curves(tm, vpm, tracer, nodes, kinetic.edges, rotation0, max_splits, timer, max_seconds);
  if(status != OK) return status;
  for(const Kinetic_flip& f : kinetic.flips)
  {
    if(timer.time() > max_seconds) return ERROR_BUDGET_EXHAUSTED;
    tracer.remove(static_cast<int>(f.edge));
    if(!tracer.trace(static_cast<int>(f.edge), nodes[f.c], static_cast<int>(f.ca), static_cast<int>(f.cb),
                     nodes[f.d], static_cast<int>(f.db), static_cast<int>(f.da)))
      return tracer.timed_out() ? ERROR_BUDGET_EXHAUSTED : ERROR_PATH_TRACING_FAILED;
    if(tracer.live_crossings() > max_splits) return ERROR_BUDGET_EXHAUSTED;
  }
  return OK;
}

// A cheap estimate of how much a motion's curves wind: their crossings with the edges of a mesh made of the
// motion's own start triangulation, subdivided once (a few hundred vertices for 50 targets), the curves
// traced as on the input mesh. The class of the curves is the one the mesh tracing follows; the input
// mesh scales the crossings by about the number of its edges along a start edge.
// (size_t)-1 when the tracing fails or runs out of max_crossings or max_seconds.
inline std::size_t kinetic_proxy_crossings(const Kinetic_triangulation& kinetic, const std::vector<std::array<double, 2> >& border,
                                           const std::vector<std::array<double, 2> >& start, std::size_t max_crossings,
                                           double max_seconds)
{
  typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;
  const std::size_t failed = std::size_t(-1), nb = border.size(), nn = nb + start.size();
  Mesh m;
  std::vector<Mesh::Vertex_index> nodes;
  for(std::size_t n = 0; n < nn; ++n)
  {
    const std::array<double, 2>& p = n < nb ? border[n] : start[n - nb];
    nodes.push_back(m.add_vertex(CGAL::Simple_cartesian<double>::Point_3(p[0], p[1], 0.)));
  }
  for(const auto& t : kinetic.initial)
    if(m.add_face(nodes[t[0]], nodes[t[1]], nodes[t[2]]) == Mesh::null_face()) return failed;
  // one step of sqrt(3) subdivision: the curves need room between the nodes (the tracer finds none along an
  // edge that joins two of them); the new edges cross the start edges, one crossing per start edge and
  // face centre, and the nodes keep their indices
  CGAL::Subdivision_method_3::Sqrt3_subdivision(m, CGAL::parameters::number_of_iterations(1));
  std::vector<std::vector<std::size_t> > rotation0;
  if(!triangulation_rotation(kinetic.initial, nb, nn, kinetic.edges, rotation0)) return failed;
  CGAL::Real_timer timer;
  timer.start();
  auto vpm = get(CGAL::vertex_point, m);
  Overlay_tracer<Mesh, decltype(vpm)> tracer(m, vpm);
  if(trace_kinetic_curves(m, vpm, tracer, nodes, kinetic, rotation0, max_crossings, timer, max_seconds) != OK) return failed;
  return tracer.live_crossings();
}

template <class TriangleMesh, class VertexPointMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
Error_code trace_paths_kinetic(TriangleMesh& tm, VertexPointMap vpm,
                               const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& nodes,
                               const Kinetic_triangulation& kinetic, const Domain_partition& partition,
                               std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >& paths,
                               std::vector<Steiner_vertex<TriangleMesh> >& steiner,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  CGAL::Real_timer timer;
  timer.start();
  paths.assign(partition.edges.size(), std::vector<vertex_descriptor>());
  double max_seconds = 0;
  std::size_t max_splits = 0;
  Error_code status = read_curve_tracing_budgets(tm, np, max_seconds, max_splits);
  if(status != OK) return status;
  const std::size_t nb = partition.number_of_border_nodes, nn = partition.number_of_nodes();
  if(nodes.size() != nn) return ERROR_WRONG_PARAMETER;
  const std::vector<std::array<std::size_t, 2> >& edges0 = kinetic.edges;
  std::vector<std::vector<std::size_t> > rotation0;
  if(!triangulation_rotation(kinetic.initial, nb, nn, edges0, rotation0)) return ERROR_PATH_TRACING_FAILED;
  Overlay_tracer<TriangleMesh, VertexPointMap> tracer(tm, vpm);
  status = trace_kinetic_curves(tm, vpm, tracer, nodes, kinetic, rotation0, max_splits, timer, max_seconds);
  if(status != OK) return status;
  // the edges the merge kept, by node pair; the others are taken out
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> final_id;
  std::vector<std::pair<vertex_descriptor, vertex_descriptor> > ends(edges0.size());
  for(std::size_t t = 0; t < kinetic.final_triangles.size(); ++t)
    for(int i = 0; i < 3; ++i)
    {
      const std::ptrdiff_t id = kinetic.final_edge_id[t][i];
      if(id < 0) continue;
      const std::size_t u = kinetic.final_triangles[t][(i + 1) % 3], v = kinetic.final_triangles[t][(i + 2) % 3];
      final_id[std::minmax(u, v)] = static_cast<std::size_t>(id);
    }
  for(std::size_t e = 0; e < edges0.size(); ++e) ends[e] = tracer.curve_ends(static_cast<int>(e));
  std::vector<char> kept(edges0.size(), 0);
  std::vector<std::size_t> curve_of(partition.edges.size());
  for(std::size_t i = 0; i < partition.edges.size(); ++i)
  {
    const auto it = final_id.find(std::minmax(partition.edges[i][0], partition.edges[i][1]));
    if(it == final_id.end()) return ERROR_WRONG_PARAMETER; // not a merge of the end triangulation
    curve_of[i] = it->second;
    kept[it->second] = 1;
  }
  for(std::size_t e = 0; e < edges0.size(); ++e) if(!kept[e]) tracer.remove(static_cast<int>(e));
  std::vector<std::vector<vertex_descriptor> > curves;
  if(!partition.edges.empty() && !tracer.realize(ends, curves, steiner)) return ERROR_PATH_TRACING_FAILED;
  for(std::size_t i = 0; i < partition.edges.size(); ++i)
  {
    paths[i] = curves[curve_of[i]];
    if(paths[i].empty()) return ERROR_PATH_TRACING_FAILED;
    if(paths[i].front() != nodes[partition.edges[i][0]]) std::reverse(paths[i].begin(), paths[i].end());
  }
  if(check_traced_paths(tm, nodes, partition.edges, partition.rotation, paths, nullptr, false) != OK)
    return ERROR_PATH_TRACING_FAILED;
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_TRACE_KINETIC_H
