// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CERTIFY_OVERLAY_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CERTIFY_OVERLAY_H

// The certificate of a triangulated overlay (internal/cross/overlay_maps.h), whose points are lazy exact
// (`CGAL::Epeck`): a crossing is a construction, and check_embedding() turns every point into an exact
// rational first (for its exact areas), which evaluates every crossing exactly: half of the compatible
// meshes' time. The same facts are decided here with the kernel's filtered predicates, exact only where
// the interval sign is uncertain: the triangles make a triangulated disk, every triangle is
// counterclockwise, the border polygon is simple and counterclockwise (CGAL::Polygon_2). Then the map has
// degree one over the region its border encloses (each point covered once): an embedding, as
// check_embedding() concludes from the same facts. Should any fail, check_embedding() itself gives the
// report (its counts of what is wrong). On success the areas are those of the rounded points (doubles)
// and the energies are not computed.

#include <CGAL/Progressive_embedding/Embedding_report.h>
#include <CGAL/Progressive_embedding/internal/check_embedding_impl.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

inline Embedding_report certify_overlay(const std::vector<CGAL::Epeck::Point_2>& points,
                                        const std::vector<std::array<std::size_t, 3> >& triangles)
{
  typedef CGAL::Epeck EK;
  typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Soup;
  typedef Soup::Vertex_index svertex;
  Soup soup;
  Embedding_report r;
  for(std::size_t i = 0; i < points.size(); ++i) soup.add_vertex();
  for(const auto& t : triangles)
    if(soup.add_face(svertex(t[0]), svertex(t[1]), svertex(t[2])) == soup.null_face())
    {
      r.status = ERROR_NON_MANIFOLD; // not a triangulated surface
      return r;
    }
  auto full = [&]() {
    auto exact_uv = soup.add_property_map<svertex, EK::Point_2>("v:pe_overlay_uv").first;
    for(std::size_t i = 0; i < points.size(); ++i) exact_uv[svertex(i)] = points[i];
    return check_embedding_impl(soup, exact_uv);
  };
  Indexed_disk<Soup> disk;
  if(make_indexed_disk(soup, boost::graph_traits<Soup>::null_halfedge(), disk) != OK) return full();
  // the point of the disk's vertex k
  auto at = [&](std::size_t k) -> const EK::Point_2& { return points[std::size_t(disk.vertices[k])]; };
  r.faces = disk.number_of_faces();
  r.vertices = disk.number_of_vertices();
  r.border_vertices = disk.border.size();
  r.border_cycles = 1;
  const EK::Orientation_2 orientation = EK().orientation_2_object();
  for(const auto& t : disk.faces)
    if(orientation(at(t[0]), at(t[1]), at(t[2])) != CGAL::LEFT_TURN) return full();
  CGAL::Polygon_2<EK> border;
  for(std::size_t b : disk.border) border.push_back(at(b));
  if(!border.is_simple() || border.orientation() != CGAL::COUNTERCLOCKWISE) return full();
  r.border_simple = true;
  r.overlap_checked = r.overlap_by_degree_argument = true;
  // the areas of the rounded points, in the map's units
  r.min_signed_area = std::numeric_limits<double>::infinity();
  r.max_signed_area = 0;
  for(const auto& t : disk.faces)
  {
    const double ax = CGAL::to_double(at(t[0]).x()), ay = CGAL::to_double(at(t[0]).y());
    const double area = ((CGAL::to_double(at(t[1]).x()) - ax) * (CGAL::to_double(at(t[2]).y()) - ay) -
                         (CGAL::to_double(at(t[1]).y()) - ay) * (CGAL::to_double(at(t[2]).x()) - ax)) / 2;
    r.min_signed_area = (std::min)(r.min_signed_area, area);
    r.max_signed_area = (std::max)(r.max_signed_area, area);
  }
  double twice = 0;
  for(std::size_t k = 0; k < disk.border.size(); ++k)
  {
    const auto& p = at(disk.border[k]);
    const auto& q = at(disk.border[(k + 1) % disk.border.size()]);
    twice += CGAL::to_double(p.x()) * CGAL::to_double(q.y()) - CGAL::to_double(p.y()) * CGAL::to_double(q.x());
  }
  r.border_area = twice / 2;
  return r;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CROSS_CERTIFY_OVERLAY_H
