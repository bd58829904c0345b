// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_CERTIFIED_PARAMETERIZER_3_H
#define CGAL_PROGRESSIVE_EMBEDDING_CERTIFIED_PARAMETERIZER_3_H

/// \file Certified_parameterizer_3.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/certified_pipeline.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_statistics.h>
#include <CGAL/Progressive_embedding/internal/constrained/holes.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/functional/hash.hpp>

#include <memory>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingParameterizers
///
/// A parameterizer that keeps the user's method: it runs the wrapped CGAL fixed-border parameterizer
/// (`Mean_value_coordinates_parameterizer_3`, `Discrete_conformal_map_parameterizer_3`,
/// `Discrete_authalic_parameterizer_3`, `Barycentric_mapping_parameterizer_3`,
/// `Iterative_authalic_parameterizer_3`, each with its border parameterizer), certifies its result
/// exactly with `check_embedding()`, and repairs it with `progressive_embedding()` only when it is not a
/// valid embedding (then optimizes it with `optimize_distortion()` if asked). A valid map of the wrapped
/// parameterizer is returned bit for bit as it computed it (with `Optimization::NEVER` or `WHEN_REPAIRED`).
///
/// Only the connected component of the border halfedge `bhd` is mapped, checked and repaired (CGAL's
/// contract): the uv coordinates of the other components are left untouched, so that the charts of an
/// atlas (several components of one mesh, or the charts of a `Seam_mesh`) are mapped one call each.
/// The component is a topological disk, or a connected genus-0 surface with several border cycles (holes):
/// the border cycle of `bhd` is then the outer border, and the map is certified as a multiply connected map
/// (`check_embedding()` with `multiply_connected(true)`: every hole an empty region inside the outer border).
/// The wrapped parameterizer treats the vertices of the holes as interior vertices, which in general folds
/// the holes; its map is then replaced by the map of the disk whose holes are closed by fans around one new
/// vertex each (Tutte, repaired by progressive embedding if needed), from which the fans are removed: no
/// vertex is added to the mesh, and the outer border keeps the wrapped parameterizer's positions.
/// A component that is neither (closed, or of higher genus) is refused before the uv map is read back,
/// with `ERROR_NO_TOPOLOGICAL_DISC` and `error_code()` (`ERROR_NOT_A_DISK`, `ERROR_NOT_GENUS_ZERO`);
/// `number_of_border_cycles()` gives the count. On any error the uv of the original vertices is not written
/// by the repair: a program that ignores the returned status must not use it.
///
/// The repair starts from the wrapped parameterizer's map: the border it computed stays fixed, and the
/// interior is repaired on a copy of the component (a `Surface_mesh`), then written back.
///
/// \tparam TriangleMesh_ a model of `FaceGraph` (`Surface_mesh`, `Polyhedron_3`, `Seam_mesh`...)
/// \tparam FixedBorderParameterizer_ a model of `Parameterizer_3` computing a map with a fixed convex border,
///         e.g. `CGAL::Surface_mesh_parameterization::Mean_value_coordinates_parameterizer_3<TriangleMesh_>`
///
/// \cgalModels `Parameterizer_3`
template <class TriangleMesh_, class FixedBorderParameterizer_>
class Certified_parameterizer_3
{
public:
  /// the mesh type
  typedef TriangleMesh_ TriangleMesh;
  /// the wrapped parameterizer
  typedef FixedBorderParameterizer_ Fixed_border_parameterizer;
  /// halfedge descriptor of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  /// vertex descriptor of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// face descriptor of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;

  /// When `optimize_distortion()` runs after the wrapped parameterizer.
  enum class Optimization
  {
    NEVER,          ///< the output is the wrapped parameterizer's map, or its repair
    WHEN_REPAIRED,  ///< a repaired map is optimized; a valid map is returned as the wrapped parameterizer computed it
    ALWAYS          ///< every certified map is optimized
  };

  /// constructs the parameterizer around a default-constructed wrapped parameterizer.
  Certified_parameterizer_3(Optimization optimization = Optimization::WHEN_REPAIRED)
    : m_param(std::make_shared<Fixed_border_parameterizer>()), m_optimization(optimization),
      m_state(std::make_shared<State>()) { }

  /// constructs the parameterizer around a copy of `parameterizer` (for copyable parameterizers; copies of
  /// this object share the wrapped one, which is how non-copyable ones such as
  /// `Iterative_authalic_parameterizer_3` are held).
  Certified_parameterizer_3(const Fixed_border_parameterizer& parameterizer,
                            Optimization optimization = Optimization::WHEN_REPAIRED)
    : m_param(std::make_shared<Fixed_border_parameterizer>(parameterizer)), m_optimization(optimization),
      m_state(std::make_shared<State>()) { }

  /// returns the wrapped parameterizer
  Fixed_border_parameterizer& fixed_border_parameterizer() const { return *m_param; }

  /// returns `true` if the last call had to repair the wrapped parameterizer's map.
  /// Copies share the state of the last call: `CGAL::Surface_mesh_parameterization::parameterize()` takes the
  /// parameterizer by value, and the caller's object still reports the call.
  bool repaired() const { return m_state->repaired; }
  /// returns `true` if the last call ran `optimize_distortion()`
  bool optimized() const { return m_state->optimized; }
  /// returns the package's error code of the last call (`OK` on success; `ERROR_NOT_A_DISK` when the component
  /// of `bhd` has no border; `ERROR_NOT_GENUS_ZERO` when it has several border cycles but is not of genus 0)
  Error_code error_code() const { return m_state->error; }
  /// returns the number of border cycles of the component of `bhd` in the last call (1 for a disk, 1 + the
  /// number of holes otherwise)
  std::size_t number_of_border_cycles() const { return m_state->border_cycles; }
  /// returns the number of faces of the component of `bhd` in the last call
  std::size_t number_of_faces() const { return m_state->faces; }
  /// returns the certificate of the wrapped parameterizer's map, on the component, in the last call
  const Embedding_report& input_report() const { return m_state->input_report; }
  /// returns the statistics of the repair of the last call; its `report` certifies the final map of the component
  const Progressive_embedding_statistics& statistics() const { return m_state->stats; }
  /// returns the statistics of the last optimization, if `optimized()`
  const Optimization_statistics& optimization_statistics() const { return m_state->optimization; }

  /// maps the connected component of `bhd` with the wrapped parameterizer, certifies and, if needed, repairs it.
  /// \tparam VertexUVmap a model of `ReadWritePropertyMap` with `Point_2` values
  /// \tparam VertexIndexMap a model of `ReadablePropertyMap` (vertex to index), as the wrapped parameterizer needs
  /// \tparam VertexParameterizedMap a model of `ReadWritePropertyMap` (vertex to `bool`)
  /// \tparam Extra further arguments forwarded to the wrapped parameterizer (e.g. the number of iterations of
  ///         `Iterative_authalic_parameterizer_3`)
  /// \param mesh the mesh \param bhd a border halfedge of the component to map \param uvmap the uv map
  /// \param vimap the vertex index map \param vpmap marks the parameterized vertices
  /// \param extra forwarded to the wrapped parameterizer
  /// \return `OK` only if the component's map is certified; the wrapped parameterizer's error if it failed;
  ///         `ERROR_NO_TOPOLOGICAL_DISC` (neither a disk nor a genus-0 surface with holes),
  ///         `ERROR_NON_TRIANGULAR_MESH`, `ERROR_EMPTY_MESH`;
  ///         `ERROR_NO_1_TO_1_MAPPING` if the repair failed (see `error_code()`)
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap, typename... Extra>
  CGAL::Surface_mesh_parameterization::Error_code
  parameterize(TriangleMesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap,
               VertexIndexMap vimap, VertexParameterizedMap vpmap, Extra&&... extra)
  {
    namespace SMP = CGAL::Surface_mesh_parameterization;
    *m_state = State();
    State& s = *m_state;

    // the component of bhd and its border cycles, before the wrapped parameterizer writes anything
    std::vector<face_descriptor> faces;
    SMP::Error_code status = component(mesh, bhd, faces);
    if(status != SMP::OK) return status;

    status = m_param->parameterize(mesh, bhd, uvmap, vimap, vpmap, std::forward<Extra>(extra)...);
    if(status != SMP::OK) { s.error = ERROR_CANNOT_SOLVE_LINEAR_SYSTEM; return status; }

    // a copy of the component carries the certificate and the repair: the package's functions map a
    // whole mesh, and the copy restricts them to the component whatever the mesh type is
    typedef typename boost::property_traits<VertexUVmap>::value_type                         Point_2;
    typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type      Vpm;
    typedef typename boost::property_traits<Vpm>::value_type                                  Point_3;
    typedef CGAL::Surface_mesh<Point_3>                                                       Copy;
    Copy copy;
    std::vector<vertex_descriptor> originals;
    std::unordered_map<vertex_descriptor, typename Copy::Vertex_index, boost::hash<vertex_descriptor> > to_copy;
    Vpm vpm = get(CGAL::vertex_point, mesh);
    auto cuv = copy.template add_property_map<typename Copy::Vertex_index, Point_2>("v:pe_uv").first;
    for(face_descriptor f : faces)
    {
      std::vector<typename Copy::Vertex_index> fv;
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
      {
        auto it = to_copy.find(v);
        if(it == to_copy.end())
        {
          typename Copy::Vertex_index cv = copy.add_vertex(get(vpm, v));
          put(cuv, cv, get(uvmap, v));
          it = to_copy.emplace(v, cv).first;
          originals.push_back(v);
        }
        fv.push_back(it->second);
      }
      if(copy.add_face(fv) == Copy::null_face()) { s.error = ERROR_NOT_A_DISK; return SMP::ERROR_NO_TOPOLOGICAL_DISC; }
    }

    const bool holes = s.border_cycles > 1;
    const bool optimize_always = m_optimization == Optimization::ALWAYS;
    if(!holes)
    {
      // a disk: the package's repair-and-optimize policy (repair_and_optimize()), the wrapped parameterizer's
      // border kept; an optimization that fails leaves the certified repaired map, which is returned
      Pipeline_statistics ps;
      const Optimization_policy policy = optimize_always ? Optimization_policy::ALWAYS
                                       : m_optimization == Optimization::NEVER ? Optimization_policy::NEVER
                                                                               : Optimization_policy::WHEN_REPAIRED;
      const Error_code ec = repair_and_optimize(copy, cuv, parameters::optimization_policy(policy).pipeline_statistics(&ps));
      s.input_report = ps.input_report;
      if(ps.repaired) s.stats = ps.repair;
      else s.stats.report = ps.input_report;
      s.repaired = ps.repaired;
      s.optimized = ps.optimized;
      s.optimization = ps.optimization;
      if(ps.input_report.status != OK) { s.error = ps.input_report.status; return SMP::ERROR_NO_TOPOLOGICAL_DISC; }
      if(ec != OK && !(ps.optimized && ps.report.is_valid()))
      {
        s.error = ec;
        return SMP::ERROR_NO_1_TO_1_MAPPING; // the uv map keeps the wrapped parameterizer's map
      }
    }
    else
    {
      // holes: the same policy on a multiply connected map (repair_and_optimize() takes disks)
      s.input_report = check_embedding(copy, cuv, parameters::multiply_connected(true));
      s.stats.report = s.input_report;
      if(s.input_report.status != OK) { s.error = s.input_report.status; return SMP::ERROR_NO_TOPOLOGICAL_DISC; }
      if(!s.input_report.is_valid())
      {
        // the holes closed by fans, a disk map with the outer border kept, the fans removed (see the class)
        s.repaired = true;
        if(!is_border(bhd, mesh)) bhd = opposite(bhd, mesh);
        const auto outer = halfedge(to_copy[source(bhd, mesh)], to_copy[target(bhd, mesh)], copy);
        CGAL_assertion(outer.second && is_border(outer.first, copy));
        const Error_code ec = internal::embed_with_holes(copy, outer.first, cuv, parameters::border_shape(Border_shape::FIXED),
                                                         &s.stats.report);
        if(ec != OK || !s.stats.report.is_valid())
        {
          s.error = (ec != OK ? ec : ERROR_INVALID_EMBEDDING);
          return SMP::ERROR_NO_1_TO_1_MAPPING; // the uv map keeps the wrapped parameterizer's map
        }
      }
      if(optimize_always || (s.repaired && m_optimization == Optimization::WHEN_REPAIRED))
      {
        // any outcome leaves a certified map: the optimizer writes only certified maps
        optimize_distortion(copy, cuv, parameters::optimization_statistics(&s.optimization));
        s.optimized = true;
      }
    }
    if(s.repaired || s.optimized)
      for(vertex_descriptor v : originals) put(uvmap, v, get(cuv, to_copy[v]));
    for(vertex_descriptor v : originals) put(vpmap, v, true);
    return SMP::OK;
  }

  /// maps the component of `bhd` with internal index and parameterized maps, forwarding `iterations` (as
  /// `Iterative_authalic_parameterizer_3::parameterize(mesh, bhd, uvmap, iterations)` does).
  /// \tparam VertexUVmap a model of `ReadWritePropertyMap` with `Point_2` values
  /// \param mesh the mesh \param bhd a border halfedge \param uvmap the uv map
  /// \param iterations forwarded to the wrapped parameterizer's six-argument `parameterize()`
  /// \return as the five-argument overload
  template <typename VertexUVmap>
  CGAL::Surface_mesh_parameterization::Error_code
  parameterize(TriangleMesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap, const unsigned int iterations)
  {
    // the vertices of the component of bhd, indexed 0..n-1 as CGAL's parameterizers expect
    auto vimap = get(CGAL::dynamic_vertex_property_t<int>(), mesh);
    auto vpmap = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
    for(vertex_descriptor v : vertices(mesh)) { put(vimap, v, -1); put(vpmap, v, false); }
    std::vector<face_descriptor> faces;
    const CGAL::Surface_mesh_parameterization::Error_code status = component(mesh, bhd, faces);
    if(status != CGAL::Surface_mesh_parameterization::OK) return status;
    int n = 0;
    for(face_descriptor f : faces)
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
        if(get(vimap, v) < 0) put(vimap, v, n++);
    return parameterize(mesh, bhd, uvmap, vimap, vpmap, iterations);
  }

private:
  // the faces of the connected component of bhd (faces joined by edges), its triangularity and its
  // number of border cycles; each loop visits every face or border halfedge once
  CGAL::Surface_mesh_parameterization::Error_code
  component(const TriangleMesh& mesh, halfedge_descriptor bhd, std::vector<face_descriptor>& faces)
  {
    namespace SMP = CGAL::Surface_mesh_parameterization;
    State& s = *m_state;
    faces.clear();
    if(bhd == boost::graph_traits<TriangleMesh>::null_halfedge()) { s.error = ERROR_EMPTY_MESH; return SMP::ERROR_EMPTY_MESH; }
    if(!is_border(bhd, mesh)) bhd = opposite(bhd, mesh);
    face_descriptor f0 = face(opposite(bhd, mesh), mesh);
    if(!is_border(bhd, mesh) || f0 == boost::graph_traits<TriangleMesh>::null_face())
    { s.error = ERROR_NOT_A_DISK; s.border_cycles = 0; return SMP::ERROR_NO_TOPOLOGICAL_DISC; }
    std::unordered_set<face_descriptor, boost::hash<face_descriptor> > seen;
    std::unordered_set<halfedge_descriptor, boost::hash<halfedge_descriptor> > border;
    faces.push_back(f0);
    seen.insert(f0);
    for(std::size_t i = 0; i < faces.size(); ++i)
    {
      std::size_t d = 0; // degree(f, mesh) is not defined for every FaceGraph (Seam_mesh)
      for(halfedge_descriptor h : halfedges_around_face(halfedge(faces[i], mesh), mesh)) { (void)h; ++d; }
      if(d != 3) { s.error = ERROR_NON_TRIANGULAR_MESH; return SMP::ERROR_NON_TRIANGULAR_MESH; }
      for(halfedge_descriptor h : halfedges_around_face(halfedge(faces[i], mesh), mesh))
      {
        halfedge_descriptor o = opposite(h, mesh);
        if(is_border(o, mesh)) { border.insert(o); continue; }
        face_descriptor g = face(o, mesh);
        if(seen.insert(g).second) faces.push_back(g);
      }
    }
    s.faces = faces.size();
    std::unordered_set<halfedge_descriptor, boost::hash<halfedge_descriptor> > walked;
    std::size_t cycles = 0;
    for(halfedge_descriptor h : border)
    {
      if(walked.count(h)) continue;
      ++cycles;
      halfedge_descriptor c = h;
      for(std::size_t k = 0; k <= border.size() && walked.insert(c).second; ++k) c = next(c, mesh);
    }
    s.border_cycles = cycles; // several: holes, checked by the multiply connected certificate
    return SMP::OK;
  }

  struct State
  {
    bool repaired = false;
    bool optimized = false;
    Error_code error = OK;
    std::size_t border_cycles = 0;
    std::size_t faces = 0;
    Embedding_report input_report;
    Progressive_embedding_statistics stats;
    Optimization_statistics optimization;
  };
  std::shared_ptr<Fixed_border_parameterizer> m_param;
  Optimization m_optimization;
  std::shared_ptr<State> m_state;
};

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_CERTIFIED_PARAMETERIZER_3_H
