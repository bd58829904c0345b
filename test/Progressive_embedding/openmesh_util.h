// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// OpenMesh as a FaceGraph for the tests: a triangle mesh with double-precision points, and a
// vertex point map that reads and writes them exactly.

#ifndef PE_TEST_OPENMESH_UTIL_H
#define PE_TEST_OPENMESH_UTIL_H

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <boost/property_map/property_map.hpp>

// double-precision points: OpenMesh's default traits store floats
struct Om_double_traits : public OpenMesh::DefaultTraits
{
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
typedef OpenMesh::TriMesh_ArrayKernelT<Om_double_traits> Om_mesh;

// The points of an Om_mesh as Epick points. CGAL's default vertex point map of OpenMesh converts the
// points written to float; this one keeps every bit (the vertices added by constrained_embedding()
// lie exactly on the edge they split).
struct Om_point_map
{
  typedef boost::graph_traits<Om_mesh>::vertex_descriptor key_type;
  typedef CGAL::Epick::Point_3 value_type;
  typedef value_type reference;
  typedef boost::read_write_property_map_tag category;

  Om_mesh* mesh = nullptr;

  friend value_type get(const Om_point_map& pm, key_type v)
  {
    const Om_mesh::Point& p = pm.mesh->point(v);
    return value_type(p[0], p[1], p[2]);
  }
  friend void put(const Om_point_map& pm, key_type v, const value_type& p)
  {
    pm.mesh->set_point(v, Om_mesh::Point(p.x(), p.y(), p.z()));
  }
};

#endif // PE_TEST_OPENMESH_UTIL_H
