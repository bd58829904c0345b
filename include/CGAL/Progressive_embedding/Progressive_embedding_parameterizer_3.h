// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_PARAMETERIZER_3_H
#define CGAL_PROGRESSIVE_EMBEDDING_PARAMETERIZER_3_H

/// \file Progressive_embedding_parameterizer_3.h

#include <CGAL/disable_warnings.h>

#include <CGAL/Progressive_embedding/tutte_embedding.h>
#include <CGAL/Progressive_embedding/check_embedding.h>
#include <CGAL/Progressive_embedding/progressive_embedding.h>
#include <CGAL/Progressive_embedding/optimize_distortion.h>
#include <CGAL/Progressive_embedding/certified_pipeline.h>
#include <CGAL/Progressive_embedding/Certified_parameterizer_3.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Default.h>

#include <memory>
#include <type_traits>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingParameterizers
///
/// A drop-in parameterizer for `CGAL::Surface_mesh_parameterization::parameterize()`: the border is
/// placed by `BorderParameterizer`, the interior by Tutte's barycentric mapping
/// (`tutte_embedding()` with the border fixed), and, when the Tutte map fails the exact certificate,
/// it is repaired by `progressive_embedding()`, then, by default, optimized by `optimize_distortion()` with the
/// border fixed (see `Optimization`). It returns
/// `CGAL::Surface_mesh_parameterization::OK` only with a map certified valid by `check_embedding()`,
/// and `CGAL::Surface_mesh_parameterization::ERROR_NO_1_TO_1_MAPPING` otherwise (CGAL's own
/// `Barycentric_mapping_parameterizer_3` returns `OK` on broken maps).
///
/// When the mesh is not one disk, only the connected component of `bhd` is mapped (CGAL's contract: the charts
/// of an atlas, the components of one file); a component with holes gets a multiply connected map (see
/// `Certified_parameterizer_3`, which this class then uses around CGAL's `Barycentric_mapping_parameterizer_3`
/// with the same border parameterizer and the same `Optimization`).
///
/// \tparam TriangleMesh_ a model of `FaceGraph`
/// \tparam BorderParameterizer_ a model of `Parameterizer_3` that places a convex border;
///         default: `CGAL::Surface_mesh_parameterization::Circular_border_arc_length_parameterizer_3<TriangleMesh_>`
/// \tparam SolverTraits_ a model of `SparseLinearAlgebraWithFactorTraits_d` over `double` that solves the Tutte
///         system (the `sparse_linear_solver` of `tutte_embedding()`), as in CGAL's `Fixed_border_parameterizer_3`;
///         default: the solver `tutte_embedding()` chooses (`Eigen::SimplicialLDLT`, or CHOLMOD's supernodal
///         Cholesky for 100,000 interior vertices or more when the package is built with CHOLMOD)
///
/// \cgalModels `Parameterizer_3`
template <class TriangleMesh_, class BorderParameterizer_ = CGAL::Default, class SolverTraits_ = CGAL::Default>
class Progressive_embedding_parameterizer_3
{
public:
#ifndef DOXYGEN_RUNNING
  typedef typename CGAL::Default::Get<BorderParameterizer_,
            CGAL::Surface_mesh_parameterization::Circular_border_arc_length_parameterizer_3<TriangleMesh_> >::type Border_parameterizer;
#else
  /// the border parameterizer
  typedef BorderParameterizer_ Border_parameterizer;
#endif
  /// the solver of the Tutte system (`CGAL::Default`: the one `tutte_embedding()` chooses)
  typedef SolverTraits_ Solver_traits;
  /// the mesh type
  typedef TriangleMesh_ TriangleMesh;
  /// halfedge descriptor of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  /// When `optimize_distortion()` runs after the Tutte map.
  enum class Optimization
  {
    NEVER,          ///< the output is Tutte's map, or its repair
    WHEN_REPAIRED,  ///< a repaired map is optimized; a valid Tutte map is returned as CGAL's barycentric mapping returns it
    ALWAYS          ///< every map is optimized
  };

  /// constructs the parameterizer. The default, `Optimization::WHEN_REPAIRED`, keeps the drop-in promise (a valid
  /// Tutte map is returned unchanged, as CGAL's `Barycentric_mapping_parameterizer_3` computes it) while a repaired
  /// map, whose faces inherit Tutte's areas of \f$10^{-20}\f$ and below, becomes a map that can be textured.
  /// `solver` solves the Tutte system when `SolverTraits_` is not `CGAL::Default`.
  Progressive_embedding_parameterizer_3(Border_parameterizer border_parameterizer = Border_parameterizer(),
                                        Optimization optimization = Optimization::WHEN_REPAIRED,
                                        Solver_traits solver = Solver_traits())
    : m_border(border_parameterizer), m_optimization(optimization), m_solver(solver), m_state(std::make_shared<State>()) { }

  /// returns the statistics of the last call (progressive embedding counts are zero when Tutte was valid).
  /// Copies share them: `CGAL::Surface_mesh_parameterization::parameterize()` takes the parameterizer by value,
  /// and the caller's object still reports the call.
  const Progressive_embedding_statistics& statistics() const { return m_state->stats; }
  /// returns `true` if the last call had to repair the Tutte map (shared by copies, like `statistics()`)
  bool repaired() const { return m_state->repaired; }
  /// returns `true` if the last call ran `optimize_distortion()` (shared by copies, like `statistics()`)
  bool optimized() const { return m_state->optimized; }
  /// returns the statistics of the last optimization, if `optimized()` (shared by copies, like `statistics()`)
  const Optimization_statistics& optimization_statistics() const { return m_state->optimization; }

  /// computes a certified parameterization of the disk `mesh` whose border contains `bhd`.
  /// \tparam VertexUVmap a model of `ReadWritePropertyMap` with `Point_2` values
  /// \tparam VertexIndexMap a model of `ReadablePropertyMap` (vertex to index)
  /// \tparam VertexParameterizedMap a model of `ReadWritePropertyMap` (vertex to `bool`)
  /// \param mesh the mesh \param bhd a border halfedge \param uvmap the uv map
  /// \param vimap the vertex index map \param vpmap marks the parameterized vertices
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  CGAL::Surface_mesh_parameterization::Error_code
  parameterize(const TriangleMesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap,
               VertexIndexMap vimap, VertexParameterizedMap vpmap)
  {
    namespace SMP = CGAL::Surface_mesh_parameterization;
    bool& m_repaired = m_state->repaired;
    Progressive_embedding_statistics& m_stats = m_state->stats;
    m_repaired = false;
    m_state->optimized = false;
    m_state->optimization = Optimization_statistics();
    m_stats = Progressive_embedding_statistics();
    SMP::Error_code status = m_border.parameterize(mesh, bhd, uvmap, vimap, vpmap);
    if(status != SMP::OK) return status;
    // one indexed disk for every stage
    internal::Indexed_disk<TriangleMesh> disk;
    const bool indexed = internal::make_indexed_disk(mesh, bhd, disk) == OK;
    Error_code ec = solve_tutte(mesh, bhd, uvmap, indexed ? &disk : nullptr);
    if(ec == ERROR_NOT_A_DISK && bhd != boost::graph_traits<TriangleMesh>::null_halfedge())
      return parameterize_component(mesh, bhd, uvmap, vimap, vpmap);
    if(ec == ERROR_NON_CONVEX_BORDER || ec == ERROR_DEGENERATE_BORDER) return SMP::ERROR_NON_CONVEX_BORDER;
    if(ec == ERROR_NOT_A_DISK) return SMP::ERROR_NO_TOPOLOGICAL_DISC;
    if(ec == ERROR_NON_TRIANGULAR_MESH) return SMP::ERROR_NON_TRIANGULAR_MESH;
    if(ec == ERROR_EMPTY_MESH) return SMP::ERROR_EMPTY_MESH;
    if(ec != OK) return SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    for(auto v : vertices(mesh)) put(vpmap, v, true);
    // the package's repair-and-optimize policy (repair_and_optimize()); an optimization that fails leaves the
    // certified repaired map, which is returned
    Pipeline_statistics ps;
    internal::start_border_as_default(mesh, disk);
    ec = internal::repair_and_optimize_impl(mesh, uvmap, parameters::optimization_policy(policy(m_optimization)).pipeline_statistics(&ps),
                                            &disk);
    m_repaired = ps.repaired;
    if(ps.repaired) m_stats = ps.repair;
    else m_stats.report = ps.input_report;
    m_state->optimized = ps.optimized;
    m_state->optimization = ps.optimization;
    if(ec != OK && !(ps.optimized && ps.report.is_valid())) return SMP::ERROR_NO_1_TO_1_MAPPING;
    return SMP::OK;
  }

private:
  template <typename VertexUVmap>
  Error_code solve_tutte(const TriangleMesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap,
                         const internal::Indexed_disk<TriangleMesh>* disk)
  {
    if constexpr(std::is_same<Solver_traits, CGAL::Default>::value)
      return internal::tutte_embedding_impl(mesh, bhd, uvmap, CGAL::parameters::default_values(), disk);
    else return internal::tutte_embedding_impl(mesh, bhd, uvmap, CGAL::parameters::sparse_linear_solver(m_solver), disk);
  }

  // CGAL's barycentric mapping with the same border parameterizer and, when one is given, the same solver
  template <class Tutte>
  Tutte make_barycentric() const
  {
    if constexpr(std::is_same<Solver_traits, CGAL::Default>::value) return Tutte(m_border);
    else return Tutte(m_border, m_solver);
  }

  static Optimization_policy policy(Optimization o)
  {
    return o == Optimization::NEVER ? Optimization_policy::NEVER
         : o == Optimization::ALWAYS ? Optimization_policy::ALWAYS : Optimization_policy::WHEN_REPAIRED;
  }

  // several components or holes: the component of bhd, through Certified_parameterizer_3 around CGAL's
  // barycentric mapping (which reads the mesh only: the non-const reference is CGAL's signature)
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  CGAL::Surface_mesh_parameterization::Error_code
  parameterize_component(const TriangleMesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap,
                         VertexIndexMap vimap, VertexParameterizedMap vpmap)
  {
    typedef CGAL::Surface_mesh_parameterization::Barycentric_mapping_parameterizer_3<TriangleMesh, Border_parameterizer, SolverTraits_> Tutte;
    typedef Certified_parameterizer_3<TriangleMesh, Tutte> Wrapper;
    typename Wrapper::Optimization o = m_optimization == Optimization::NEVER ? Wrapper::Optimization::NEVER
                                     : m_optimization == Optimization::ALWAYS ? Wrapper::Optimization::ALWAYS
                                                                              : Wrapper::Optimization::WHEN_REPAIRED;
    Wrapper w(make_barycentric<Tutte>(), o);
    const auto status = w.parameterize(const_cast<TriangleMesh&>(mesh), bhd, uvmap, vimap, vpmap);
    m_state->repaired = w.repaired();
    m_state->optimized = w.optimized();
    m_state->stats = w.statistics();
    m_state->optimization = w.optimization_statistics();
    return status;
  }

  struct State
  {
    Progressive_embedding_statistics stats;
    bool repaired = false;
    bool optimized = false;
    Optimization_statistics optimization;
  };
  Border_parameterizer m_border;
  Optimization m_optimization;
  Solver_traits m_solver;
  std::shared_ptr<State> m_state;
};

} // namespace Progressive_embedding
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_PROGRESSIVE_EMBEDDING_PARAMETERIZER_3_H
