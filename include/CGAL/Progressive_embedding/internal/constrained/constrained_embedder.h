// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_CONSTRAINED_EMBEDDER_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_CONSTRAINED_EMBEDDER_H

// The pipeline of constrained_embedding() (MatchMaker++) as a class with one method per phase:
//
//   read_parameters()   the named parameters (read by the constructor) checked; ERROR_WRONG_PARAMETER when out of range
//   validate()          the caller's mesh indexed (a disk, or a genus-0 surface with holes), the constraints
//                       checked (interior, distinct, finite), the border placed (fixed or a shape)
//   make_partition()    the domain cut into convex polygons (a clockwise border mirrored; an immersed disk cut
//                       along its Shor-Van Wyk triangulation)
//   make_working_copy() the Surface_mesh copy, holes filled with fans, the partition's nodes on the copy
//   trace()             the partition's interior edges traced as paths (the choice of tracer and its budgets),
//                       then the chords no convex-polygon map keeps split
//   map_patches()       path vertices placed on their segments, each patch mapped into its polygon
//   certify()           check_embedding() (or check_immersion()); holes opened again and certified
//   optimize_map()      optimize_distortion() with border and constraints fixed, certified again
//   coarsen_map()       added vertices that the certified map can do without removed, certified again
//   check_constraints() constraints and border bit-exact
//   write_output()      the refinement replayed on the caller's mesh, the uv map written
//
// Each phase returns an Error_code and times itself into the statistics; run() calls them in this order and
// stops at the first error. Nothing of the caller's mesh or uv map is touched before write_output(), which
// cannot fail on a mesh that passed validate(). The state is public so that tests can run and inspect the
// phases one by one. Every predicate goes through the traits of the `geom_traits` named parameter (the uv
// map's default traits otherwise); the domain partition decides in its own exact kernel.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/Constrained_embedding_statistics.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/internal/check_embedding_impl.h>
#include <CGAL/Progressive_embedding/internal/check_immersion_impl.h>
#include <CGAL/Progressive_embedding/internal/self_overlapping/triangulate_polygon_impl.h>
#include <CGAL/Progressive_embedding/internal/tutte_embedding_impl.h>
#include <CGAL/Progressive_embedding/internal/embed_patch_impl.h>
#include <CGAL/Progressive_embedding/internal/optimize_distortion_impl.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/parallel_for.h>
#include <CGAL/Progressive_embedding/internal/constrained/domain_partition.h>
#include <CGAL/Progressive_embedding/internal/constrained/path_network.h>
#include <CGAL/Progressive_embedding/internal/constrained/trace_paths.h>
#include <CGAL/Progressive_embedding/internal/constrained/trace_overlay.h>
#include <CGAL/Progressive_embedding/internal/constrained/trace_kinetic.h>
#include <CGAL/Progressive_embedding/internal/constrained/guide_map.h>
#include <CGAL/Progressive_embedding/internal/patch_chords.h>
#include <CGAL/Progressive_embedding/internal/constrained/embed_patches.h>
#include <CGAL/Progressive_embedding/internal/constrained/refinement.h>
#include <CGAL/Progressive_embedding/internal/constrained/holes.h>
#include <CGAL/Progressive_embedding/internal/constrained/coarsen.h>
#include <CGAL/Progressive_embedding/internal/constrained/tracer_budgets.h>
#include <CGAL/Progressive_embedding/internal/scaling.h>

#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Real_timer.h>

#include <boost/functional/hash.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <numeric>
#include <set>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// chords of a patch that no convex-polygon map keeps: along one path or one straight side of the
// domain border (several border vertices per side with a square or triangle border)
template <class Work>
struct Constrained_chord_predicate
{
  typedef typename boost::graph_traits<Work>::vertex_descriptor vertex_descriptor;
  const Same_side_chord<Work>& same_side;
  const std::unordered_map<vertex_descriptor, std::size_t>& border_index; // position on the border
  const std::vector<char>& corner;
  const std::vector<std::size_t>& side;
  std::size_t number_of_sides;
  bool operator()(vertex_descriptor a, vertex_descriptor b) const
  {
    if(same_side(a, b)) return true;
    const auto ia = border_index.find(a), ib = border_index.find(b);
    if(ia == border_index.end() || ib == border_index.end()) return false;
    auto sides_of = [&](std::size_t k, std::size_t* s) -> std::size_t {
      s[0] = side[k];
      if(!corner[k]) return 1;
      s[1] = (side[k] + number_of_sides - 1) % number_of_sides;
      return 2;
    };
    std::size_t sa[2], sb[2];
    const std::size_t na = sides_of(ia->second, sa), nb = sides_of(ib->second, sb);
    for(std::size_t i = 0; i < na; ++i)
      for(std::size_t j = 0; j < nb; ++j)
        if(sa[i] == sb[j]) return true;
    return false;
  }
};

// chords one of whose faces has its third vertex on the path network too (split_chords() passes
// only edges between two network vertices) and is not strictly positive in `uv`
template <class Work, class UVMap, class Orientation>
struct Non_positive_face_chord
{
  typedef typename boost::graph_traits<Work>::vertex_descriptor vertex_descriptor;
  const Work& work;
  UVMap uv;
  Orientation orient;
  const std::vector<char>& on_network; // by vertex index: border, node or path vertex
  bool operator()(vertex_descriptor a, vertex_descriptor b) const
  {
    const auto hb = halfedge(a, b, work);
    if(!hb.second) return false;
    for(auto h : { hb.first, opposite(hb.first, work) })
    {
      if(CGAL::is_border(h, work)) continue;
      const vertex_descriptor c = target(next(h, work), work);
      if(!on_network[static_cast<std::size_t>(c)]) continue;
      if(orient(get(uv, source(h, work)), get(uv, target(h, work)), get(uv, c)) != CGAL::LEFT_TURN) return true;
    }
    return false;
  }
};

// The constraint that partition_domain(B, targets) refused with `ec`: the first target that a partition
// refuses alone (outside the domain), or the later of the first two equal targets in lexicographic
// order (duplicate). Runs only on that error path: O(targets x partition of B).
template <class Point_2>
std::size_t failed_target(const std::vector<Point_2>& B, const std::vector<Point_2>& targets,
                          const Domain_partition_options& options, Error_code ec)
{
  if(ec == ERROR_CONSTRAINT_OUTSIDE_DOMAIN)
  {
    for(std::size_t i = 0; i < targets.size(); ++i)
    {
      Domain_partition one;
      if(partition_domain(B, std::vector<Point_2>(1, targets[i]), one, options) == ERROR_CONSTRAINT_OUTSIDE_DOMAIN) return i;
    }
    return std::size_t(-1);
  }
  std::vector<std::size_t> order(targets.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  // stable: equal targets stay in input order, so the later one follows
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return CGAL::compare_xy(targets[a], targets[b]) == CGAL::SMALLER; });
  for(std::size_t k = 0; k + 1 < order.size(); ++k)
    if(CGAL::compare_xy(targets[order[k]], targets[order[k + 1]]) == CGAL::EQUAL) return order[k + 1];
  return std::size_t(-1);
}

// The vertices of the polygon P that turn by more than rounding: the sine of the turn at least 2^-20 in
// magnitude (the corner margin of domain_partition.h), or a turn backwards. The others lie on the
// segment between their neighbours up to rounding (e.g. points interpolated in floating point along a
// side): as partition nodes they give sliver polygons, thinner than an ulp, where no path vertex fits.
template <class Point_2>
void turning_vertices(const std::vector<Point_2>& P, std::vector<std::size_t>& turning, const std::vector<int>& turns)
{
  const std::size_t n = P.size();
  turning.clear();
  for(std::size_t i = 0; i < n; ++i)
  {
    if(!turns.empty() && turns[i] > 0) { turning.push_back(i); continue; } // wraps around: a corner whatever its turn
    const Point_2& a = P[(i + n - 1) % n];
    const Point_2& b = P[i];
    const Point_2& c = P[(i + 1) % n];
    if(!flat_by_margin(CGAL::to_double(b.x()) - CGAL::to_double(a.x()), CGAL::to_double(b.y()) - CGAL::to_double(a.y()),
                       CGAL::to_double(c.x()) - CGAL::to_double(b.x()), CGAL::to_double(c.y()) - CGAL::to_double(b.y())))
      turning.push_back(i);
  }
}

// Whether every corner of a partition polygon between a border side and an interior edge (where a path
// meets the border) turns by a sine above 2^-20: path vertices are placed on their segments up to one
// ulp (place_path_vertices), so a thinner corner leaves no room for them (the patch cannot be mapped)
template <class Point_2>
bool path_corners_turn_by_margin(const Domain_partition& partition, const std::vector<Point_2>& B)
{
  const std::vector<std::vector<std::ptrdiff_t> > sides = polygon_side_edges(partition);
  for(std::size_t f = 0; f < partition.polygons.size(); ++f)
  {
    const std::vector<std::size_t>& P = partition.polygons[f];
    for(std::size_t k = 0, n = P.size(); k < n; ++k)
    {
      const std::size_t km = (k + n - 1) % n, kp = (k + 1) % n;
      if((sides[f][km] < 0) == (sides[f][k] < 0)) continue; // the border's own corner, or two paths
      if(P[km] >= B.size() || P[k] >= B.size() || P[kp] >= B.size()) continue; // a target: no border side
      const Point_2 &a = B[P[km]], &u = B[P[k]], &b = B[P[kp]];
      if(!turns_left_by_margin(CGAL::to_double(u.x()) - CGAL::to_double(a.x()), CGAL::to_double(u.y()) - CGAL::to_double(a.y()),
                               CGAL::to_double(b.x()) - CGAL::to_double(u.x()), CGAL::to_double(b.y()) - CGAL::to_double(u.y())))
        return false;
    }
  }
  return true;
}

// The indices of the strict corners of the exact convex hull of the polygon P (Andrew's monotone
// chain with the exact orientation), in the polygon's order. ERROR_NON_CONVEX_BORDER when they are
// not in the hull's cyclic order along the polygon (the polygon is not convex up to rounding),
// ERROR_DEGENERATE_BORDER when the hull is flat.
template <class Point_2, class ExactOrientation>
Error_code hull_corners(const std::vector<Point_2>& P, ExactOrientation orient, std::vector<std::size_t>& corners)
{
  const std::size_t n = P.size();
  std::vector<std::size_t> idx(n);
  for(std::size_t i = 0; i < n; ++i) idx[i] = i;
  std::sort(idx.begin(), idx.end(), [&P](std::size_t a, std::size_t b)
            { return P[a].x() < P[b].x() || (P[a].x() == P[b].x() && P[a].y() < P[b].y()); });
  std::vector<std::size_t> H;
  for(int pass = 0; pass < 2; ++pass) // lower hull, then upper hull (each loop: n steps, pops bounded by pushes)
  {
    const std::size_t base = H.size();
    for(std::size_t k = 0; k < n; ++k)
    {
      const std::size_t i = pass == 0 ? idx[k] : idx[n - 1 - k];
      while(H.size() >= base + 2 && orient(P[H[H.size() - 2]], P[H.back()], P[i]) != CGAL::LEFT_TURN) H.pop_back();
      H.push_back(i);
    }
    H.pop_back(); // the last point starts the other chain
  }
  if(H.size() < 3) return ERROR_DEGENERATE_BORDER;
  // along the polygon the corners must come in the hull's cyclic order, either way round
  corners = H;
  std::sort(corners.begin(), corners.end());
  const std::size_t m = H.size();
  const std::size_t start = static_cast<std::size_t>(std::find(H.begin(), H.end(), corners[0]) - H.begin());
  bool forward = true, backward = true;
  for(std::size_t k = 0; k < m; ++k)
  {
    if(H[(start + k) % m] != corners[k]) forward = false;
    if(H[(start + m - k) % m] != corners[k]) backward = false;
  }
  return (forward || backward) ? OK : ERROR_NON_CONVEX_BORDER;
}

// face_patch_map of constrained_embedding(), through `put_patch(f, patch)` (the writer the constructor of
// Constrained_embedder made for the caller's map; empty: no map, nothing written)
template <class TriangleMesh, class Work, class CopyToMesh, class Labels>
void write_face_patch_map(const TriangleMesh& tm, const Work& work, const CopyToMesh& copy_to_mesh, const Labels& labels,
                          const std::function<void(typename boost::graph_traits<TriangleMesh>::face_descriptor,
                                                   std::size_t)>& put_patch)
{
  if(!put_patch) return;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Work>::vertex_descriptor         wvertex;
  std::unordered_map<vertex_descriptor, wvertex, boost::hash<vertex_descriptor> > to_copy;
  for(const auto& p : copy_to_mesh) to_copy.emplace(p.second, p.first);
  for(auto f : faces(tm))
  {
    const auto h = halfedge(f, tm);
    const auto a = to_copy.find(source(h, tm)), b = to_copy.find(target(h, tm));
    if(a == to_copy.end() || b == to_copy.end()) continue; // cannot happen: every vertex of tm has its copy
    const auto wh = halfedge(a->second, b->second, work);
    if(!wh.second || CGAL::is_border(wh.first, work)) continue; // cannot happen: same connectivity
    put_patch(f, static_cast<std::size_t>(get(labels, face(wh.first, work))));
  }
}

// The class is a template of the mesh, the maps and the traits only, not of the named parameters: the
// constructor reads them once (the maps it writes through type-erased writers), so that calls with different
// parameter packs share one instantiation of the whole pipeline (a test program passes dozens of packs).
// Constrained_embedder_for<ConcurrencyTag, TriangleMesh, VertexUVMap, NamedParameters> names the class
// constrained_embedding() makes for a pack.
template <class ConcurrencyTag, class TriangleMesh, class VertexUVMap, class VertexPointMap, class GeomTraits>
class Constrained_embedder
{
public:
  typedef boost::graph_traits<TriangleMesh>                                       GT;
  typedef typename GT::vertex_descriptor                                          vertex_descriptor;
  typedef typename GT::halfedge_descriptor                                        halfedge_descriptor;
  typedef typename GT::face_descriptor                                            face_descriptor;
  typedef GeomTraits                                                              Traits;
  typedef typename Traits::Point_2                                                Point_2;
  static_assert(std::is_same<Point_2, typename Uv_map_types<VertexUVMap>::Point_2>::value,
                "the geom_traits' Point_2 must be the value type of the uv map");
  typedef VertexPointMap                                                          VPM;
  typedef typename boost::property_traits<VPM>::value_type                        Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel                           K3;
  typedef CGAL::Surface_mesh<Point_3>                                             Work;
  typedef typename boost::graph_traits<Work>::vertex_descriptor                   wvertex;
  typedef typename boost::graph_traits<Work>::face_descriptor                     wface;
  typedef typename boost::property_map<Work, CGAL::vertex_point_t>::type          Work_vpm;
  typedef typename Work::template Property_map<wvertex, Point_2>                  Work_uv;
  typedef typename Work::template Property_map<wface, std::size_t>                Work_patch;
  typedef typename Work::template Property_map<wvertex, int>                      Work_turns;

  // ---- the caller's objects and parameters (read by the constructor) ----
  TriangleMesh& tm;
  VertexUVMap uvm;
  VPM vpm;
  Traits traits;
  typename Traits::Exact_orientation_2 orient;
  Border_shape shape = Border_shape::FIXED;
  Weights wts = Weights::UNIFORM;
  bool optimize = true, coarsen = true, kinetic = true, verbose = false;
  double max_seconds = std::numeric_limits<double>::infinity();
  double optimization_seconds = std::numeric_limits<double>::infinity();
  CGAL::Real_timer timer;
  Constrained_embedding_statistics local_stats;
  Constrained_embedding_statistics& stats;
  std::vector<Steiner_point<vertex_descriptor> >* steiner_out = nullptr;
  std::function<bool(const Constrained_embedding_progress&)> progress; // the `phase_callback`
  std::size_t max_steiner_vertices = std::size_t(-1); // `maximum_steiner_vertices`; -1: not given
  // the border positions (`bpos`) of `disk` as the named parameters place them (place_border())
  std::function<Error_code(const Indexed_disk<TriangleMesh>&, VertexUVMap, VPM, const Traits&, std::vector<Point_2>&)> border_placer;
  std::function<int(vertex_descriptor)> rotation_index; // `vertex_rotation_index_map`; empty: not given
  std::function<void(face_descriptor, std::size_t)> put_patch; // `face_patch_map`; empty: not given
  bool stopped = false;                     // the callback stopped the optimization

  // ---- validate(): the indexed mesh, the constraints, the border ----
  Indexed_disk<TriangleMesh> disk;
  bool holes = false;                       // several border cycles: the outer one is the border
  halfedge_descriptor outer;                // with holes: a halfedge of the outer border cycle
  std::size_t nv = 0, nb = 0;               // vertices, border vertices
  std::vector<vertex_descriptor> cverts;    // constrained vertices
  std::vector<Point_2> targets;             // their targets
  std::vector<Point_2> bpos;                // border uv, in border order
  std::vector<int> border_turns;            // rotation indices of the border vertices (empty: all 0)
  int total_turns = 0;
  bool non_convex = false;                  // a fixed border that is not convex (or wraps around a vertex)

  // ---- make_partition() ----
  Domain_partition_options popt;
  Domain_partition partition;
  std::vector<std::size_t> border_nodes;    // border vertices (positions in the border) that are nodes
  std::vector<Point_2> B;                   // their uv (mirrored when the border is clockwise)
  bool immersed = false;                    // the border is weakly self-overlapping: an immersion
  std::vector<std::array<std::size_t, 3> > sheet_triangles;
  std::size_t nbn = 0;                      // border nodes
  bool mirrored = false;                    // clockwise border: computed mirrored (x -> -x), mirrored back
  std::vector<Point_2> T, Bfull;            // targets and whole border as computed (mirrored or not)

  // ---- make_working_copy(), trace() ----
  Work work;
  std::unordered_map<vertex_descriptor, wvertex, boost::hash<vertex_descriptor> > to_work;
  std::unordered_map<wvertex, vertex_descriptor> to_mesh;
  Work_vpm wvpm;
  std::set<std::pair<wvertex, wvertex> > loop_pieces; // hole loops, tracked through the splits
  std::vector<wvertex> centers;             // the fans' centers that close the holes
  std::vector<wvertex> nodes;               // border nodes, then constrained vertices, on the copy
  std::vector<std::vector<wvertex> > paths; // per interior edge of the partition
  std::vector<Steiner_vertex<Work> > steiner;
  std::unordered_map<wvertex, std::size_t> border_index;

  // ---- map_patches(), certify(), optimize_map(), coarsen_map() ----
  Work_uv wuv;
  std::vector<wvertex> wborder;
  Work_patch fpatch;
  std::vector<Traced_patch<Work> > patches;
  std::vector<std::vector<wface> > patch_faces;
  Work_turns work_turns;
  std::vector<Vertex_removal<wvertex> > removals;

  // reads every named parameter (their values are checked by read_parameters(), the first phase); `np` must
  // outlive the object (the border placement reads it when validate() runs)
  template <class NamedParameters>
  Constrained_embedder(TriangleMesh& tm_, VertexUVMap uvm_, const NamedParameters& np)
    : tm(tm_), uvm(uvm_),
      vpm(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                             get_property_map(CGAL::vertex_point, tm_))),
      traits(CGAL::parameters::choose_parameter<Traits>(CGAL::parameters::get_parameter(np, CGAL::internal_np::geom_traits))),
      orient(traits.exact_orientation_2_object()),
      stats(*CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::statistics), &local_stats))
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    timer.start();
    stats = Constrained_embedding_statistics();
    steiner_out = choose_parameter(get_parameter(np, internal_np::steiner_points),
                                   static_cast<std::vector<Steiner_point<vertex_descriptor> >*>(nullptr));
    shape = choose_parameter(get_parameter(np, internal_np::border_shape), Border_shape::FIXED);
    wts = choose_parameter(get_parameter(np, internal_np::weights), Weights::UNIFORM);
    optimize = choose_parameter(get_parameter(np, internal_np::optimize), true);
    coarsen = choose_parameter(get_parameter(np, internal_np::coarsen), true);
    kinetic = choose_parameter(get_parameter(np, internal_np::kinetic_tracing), true);
    verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
    max_seconds = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time),
                                   std::numeric_limits<double>::infinity());
    optimization_seconds = choose_parameter(get_parameter(np, internal_np::optimization_time_limit),
                                            std::numeric_limits<double>::infinity());
    progress = choose_parameter(get_parameter(np, internal_np::phase_callback),
                                std::function<bool(const Constrained_embedding_progress&)>());
    max_steiner_vertices = choose_parameter(get_parameter(np, internal_np::maximum_steiner_vertices), std::size_t(-1));
    border_placer = [&np](const Indexed_disk<TriangleMesh>& d, VertexUVMap u, VPM p, const Traits& gt, std::vector<Point_2>& out)
                    { return internal::place_border(d, u, p, gt, np, out); };
    typedef typename CGAL::internal_np::Lookup_named_param_def<internal_np::vertex_rotation_index_map_t, NamedParameters,
                                                               CGAL::internal_np::Param_not_found>::type Turn_map;
    if constexpr(!std::is_same<Turn_map, CGAL::internal_np::Param_not_found>::value)
      rotation_index = [turns = get_parameter(np, internal_np::vertex_rotation_index_map)](vertex_descriptor v)
                       { return internal::read_rotation_index(turns, v); };
    typedef typename CGAL::internal_np::Lookup_named_param_def<internal_np::face_patch_map_t, NamedParameters,
                                                               CGAL::internal_np::Param_not_found>::type Patch_map;
    if constexpr(!std::is_same<Patch_map, CGAL::internal_np::Param_not_found>::value)
      put_patch = [fpm = get_parameter(np, internal_np::face_patch_map)](face_descriptor f, std::size_t patch)
                  { put(fpm, f, static_cast<typename boost::property_traits<Patch_map>::value_type>(patch)); };
  }

  double remaining() const { return (std::max)(0., max_seconds - timer.time()); }
  static Point_2 mirror(const Point_2& p) { return Point_2(-p.x(), p.y()); }
  static std::pair<wvertex, wvertex> piece(wvertex a, wvertex b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }

  // tells the `phase_callback` (if any) where the computation is; false: the callback asks to stop
  bool report(Constrained_embedding_phase phase, double fraction = 0,
              double energy = std::numeric_limits<double>::quiet_NaN(),
              double optimization_left = std::numeric_limits<double>::infinity())
  {
    if(!progress) return true;
    Constrained_embedding_progress p;
    p.phase = phase;
    p.fraction = fraction;
    p.seconds = timer.time();
    p.seconds_left = remaining();
    p.optimization_seconds_left = (std::max)(0., (std::min)(optimization_left, p.seconds_left));
    p.energy = energy;
    return progress(p);
  }

  /// runs every phase in order; the statistics' total time is set whatever the outcome
  template <class ConstraintRange>
  Error_code run(const ConstraintRange& constraints)
  {
    typedef Constrained_embedding_phase Phase;
    // before the map is certified, a callback's `false` stops the call; after, it stops the optimization only
    auto start = [this](Phase phase) { return report(phase) ? OK : ERROR_BUDGET_EXHAUSTED; };
    Error_code ec = read_parameters();
    if(ec == OK) ec = start(Phase::VALIDATION);
    if(ec == OK) ec = validate(constraints);
    if(ec == OK) ec = start(Phase::PARTITION);
    if(ec == OK) ec = make_partition();
    if(ec == OK) ec = start(Phase::TRACING);
    if(ec == OK) ec = make_working_copy();
    if(ec == OK) ec = trace();
    if(ec == OK) ec = start(Phase::PATCHES);
    if(ec == OK) ec = map_patches();
    if(ec == OK) ec = start(Phase::CERTIFICATION);
    if(ec == OK) ec = certify();
    if(ec == OK && optimize && !report(Phase::OPTIMIZATION)) stopped = true;
    if(ec == OK && !stopped) ec = optimize_map();
    if(ec == OK) { report(Phase::COARSENING); ec = coarsen_map(); }
    if(ec == OK) ec = check_constraints();
    if(ec == OK) { report(Phase::OUTPUT); ec = write_output(); }
    stats.seconds_total = timer.time();
    return ec;
  }

  // the values of the named parameters the constructor read
  Error_code read_parameters() const
  {
    if(!(max_seconds >= 0)) return ERROR_WRONG_PARAMETER;
    if(!(optimization_seconds >= 0)) return ERROR_WRONG_PARAMETER;
    return OK;
  }

  // ---- 1. validation, border ----------------------------------------------------------------
  template <class ConstraintRange>
  Error_code validate(const ConstraintRange& constraints)
  {
    const double t0 = timer.time();
    disk = internal::Indexed_disk<TriangleMesh>();
    Error_code ec = internal::make_indexed_disk(tm, GT::null_halfedge(), disk);
    // several border cycles (holes): the disk is the mesh with its outer loop (the longest in 3D) as
    // border; the holes are filled with fans on the working copy and opened again once the map is
    // certified (see step 5)
    holes = false;
    outer = GT::null_halfedge();
    if(ec == ERROR_NOT_A_DISK)
    {
      std::size_t V = 0, E = 0, F = 0;
      for(auto v : vertices(tm)) { (void)v; ++V; }
      for(auto e : edges(tm)) { (void)e; ++E; }
      for(auto f : faces(tm)) { (void)f; ++F; }
      const std::size_t cycles = number_of_border_cycles(tm);
      const long chi = static_cast<long>(V) - static_cast<long>(E) + static_cast<long>(F);
      if(cycles >= 1 && chi < 2 - static_cast<long>(cycles)) ec = ERROR_NOT_GENUS_ZERO;
      else if(cycles >= 2 && chi == 2 - static_cast<long>(cycles))
      {
        // connectedness is checked by fill_holes() on the copy
        holes = true;
        outer = internal::longest_border_loop(tm, vpm);
        disk = internal::Indexed_disk<TriangleMesh>();
        std::unordered_map<vertex_descriptor, std::size_t, boost::hash<vertex_descriptor> > vid;
        for(vertex_descriptor v : vertices(tm))
        {
          vid.emplace(v, disk.vertices.size());
          disk.vertices.push_back(v);
          disk.on_border.push_back(CGAL::is_border(v, tm) ? 1 : 0);
        }
        // the outer loop with the interior on the left, as make_indexed_disk() orders a border
        std::vector<std::size_t> cyc;
        halfedge_descriptor c = outer;
        std::size_t guard = 0;
        do { cyc.push_back(vid.at(target(c, tm))); c = next(c, tm); } while(c != outer && ++guard <= E);
        disk.border.assign(cyc.rbegin(), cyc.rend());
        ec = OK;
      }
    }
    if(ec != OK) return ec;
    // the 3D points give the paths' lengths and the distortion: a NaN or infinite one is bad input, not a path
    // that cannot be traced
    if(!internal::points_are_finite(tm, vpm)) return ERROR_NON_FINITE_COORDINATES;
    nv = disk.number_of_vertices();
    nb = disk.border.size();
    if(nb < 3) return ERROR_BORDER_TOO_SHORT;
    stats.input_vertices = nv;
    std::unordered_map<vertex_descriptor, std::size_t, boost::hash<vertex_descriptor> > index_of;
    for(std::size_t i = 0; i < nv; ++i) index_of.emplace(disk.vertices[i], i);

    cverts.clear();
    targets.clear();
    for(const auto& c : constraints)
    {
      cverts.push_back(c.first);
      targets.push_back(c.second);
    }
    {
      std::unordered_set<vertex_descriptor, boost::hash<vertex_descriptor> > seen;
      for(std::size_t i = 0; i < cverts.size(); ++i)
      {
        stats.failed_constraint = i;
        const auto it = index_of.find(cverts[i]);
        if(it == index_of.end()) return ERROR_WRONG_PARAMETER;
        if(disk.on_border[it->second]) return ERROR_CONSTRAINT_ON_BORDER;
        if(!seen.insert(cverts[i]).second) return ERROR_DUPLICATE_CONSTRAINT;
        if(!internal::is_finite_ft(targets[i].x()) || !internal::is_finite_ft(targets[i].y()))
          return ERROR_NON_FINITE_COORDINATES;
        stats.failed_constraint = std::size_t(-1);
      }
    }
    bpos.clear();
    ec = border_placer(disk, uvm, vpm, traits, bpos);
    // a fixed border that is not convex (read in full before the test): a simple polygon gives an
    // embedding, a weakly self-overlapping one an immersion (step 2 decides which)
    // rotation indices of the border vertices (a fixed border that wraps around some of them)
    border_turns.clear();
    total_turns = 0;
    if(shape == Border_shape::FIXED && !holes && rotation_index)
    {
      border_turns.resize(nb);
      for(std::size_t k = 0; k < nb; ++k)
      {
        border_turns[k] = rotation_index(disk.vertices[disk.border[k]]);
        if(border_turns[k] < 0) return ERROR_WRONG_PARAMETER;
        total_turns += border_turns[k];
      }
    }
    non_convex = (ec == ERROR_NON_CONVEX_BORDER || (ec == OK && total_turns > 0)) && shape == Border_shape::FIXED &&
                 bpos.size() == nb;
    if(non_convex) ec = OK;
    if(ec != OK) return ec;
    for(const Point_2& p : bpos)
      if(!internal::is_finite_ft(p.x()) || !internal::is_finite_ft(p.y())) return ERROR_NON_FINITE_COORDINATES;
    stats.seconds_validation = timer.time() - t0;
    return OK;
  }

  // ---- 2. partition of the domain -----------------------------------------------------------
  // the rotation indices of the border nodes
  std::vector<int> node_turns() const
  {
    std::vector<int> t;
    if(total_turns > 0) for(std::size_t k : border_nodes) t.push_back(border_turns[k]);
    return t;
  }

  // an immersed disk's partition: along the border's Shor-Van Wyk triangulation
  Error_code partition_immersed(const std::vector<Point_2>& border, const std::vector<int>& turns)
  {
    sheet_triangles.clear();
    const Error_code e = turns.empty()
      ? triangulate_self_overlapping_polygon_2_impl(border, std::back_inserter(sheet_triangles),
                                               CGAL::parameters::geom_traits(traits))
      : triangulate_self_overlapping_polygon_2_impl(border, std::back_inserter(sheet_triangles),
                                               parameters::rotation_indices(turns).maximum_running_time(remaining())
                                                 .geom_traits(traits));
    if(e != OK) return e;
    partition = Domain_partition();
    return partition_immersed_domain(border, sheet_triangles, partition, popt);
  }

  Error_code make_partition()
  {
    const double t0 = timer.time();
    // The partition's counterclockwise order must be the mesh faces' orientation (trace_paths'
    // convention): a clockwise border is mirrored, exactly, and the map mirrored back at the end.
    popt = internal::Domain_partition_options();
    popt.allow_flat_border_vertices = true;
    popt.allow_non_convex_border = non_convex;
    partition = internal::Domain_partition();
    // border nodes: every border vertex (its index in `border_nodes`), or, when a border shape computed
    // in floating point is convex only up to rounding (e.g. a triangle's slanted sides), the strict
    // corners of the points' exact convex hull; the other border vertices then lie on the border
    // sides between them, within rounding, like path vertices on their segments
    border_nodes.assign(nb, 0);
    for(std::size_t k = 0; k < nb; ++k) border_nodes[k] = k;
    B = bpos;
    // a border with turns is not simple: straight to the immersed disks below
    Error_code ec = total_turns > 0 ? ERROR_NON_CONVEX_BORDER : internal::partition_domain(B, targets, partition, popt);
    // a fixed border that is not simple: a weakly self-overlapping polygon (Shor-Van Wyk) bounds an
    // immersed disk, cut into convex polygons along its triangulation; a target there could lie on
    // several sheets, so only the border may be prescribed
    immersed = false;
    sheet_triangles.clear();
    if(ec == ERROR_NON_CONVEX_BORDER && non_convex)
    {
      if(holes) return ERROR_NOT_A_DISK; // an immersion with holes is not supported
      immersed = true;
      ec = partition_immersed(B, node_turns()); // ERROR_NOT_SELF_OVERLAPPING first: it says what is wrong with the border
      if(ec == OK && !targets.empty())
      {
        stats.failed_constraint = 0; // none can be placed: a target could lie on several sheets
        return ERROR_CONSTRAINT_OUTSIDE_DOMAIN;
      }
      // nodes: the vertices that turn by more than rounding (as the strict hull corners of a convex border
      // below); the others stay on the sides between them, within rounding, like path vertices on their
      // segments. Every vertex a node made sliver triangles of three nearly collinear border points (the
      // dynamic program's triangulation keeps ears at vertices convex by 1e-16, which no merge removes).
      std::vector<std::size_t> turning;
      if(ec == OK) internal::turning_vertices(bpos, turning, border_turns);
      if(turning.size() >= 3 && turning.size() < nb)
      {
        std::vector<Point_2> Bt;
        for(std::size_t k : turning) Bt.push_back(bpos[k]);
        const internal::Domain_partition every_vertex = partition;
        const std::vector<std::size_t> every_node = border_nodes;
        border_nodes = turning;
        if(partition_immersed(Bt, node_turns()) == OK) B.swap(Bt);
        else { partition = every_vertex; border_nodes = every_node; }
      }
    }
    if(ec == ERROR_NON_CONVEX_BORDER && shape != Border_shape::FIXED)
    {
      ec = internal::hull_corners(bpos, orient, border_nodes);
      if(ec != OK) return ec;
      B.clear();
      for(std::size_t k : border_nodes) B.push_back(bpos[k]);
      partition = internal::Domain_partition();
      ec = internal::partition_domain(B, targets, partition, popt);
    }
    if(ec == ERROR_CONSTRAINT_OUTSIDE_DOMAIN || ec == ERROR_DUPLICATE_CONSTRAINT)
      stats.failed_constraint = internal::failed_target(B, targets, popt, ec);
    if(ec != OK) return ec;
    nbn = border_nodes.size();
    mirrored = !partition.counterclockwise;
    T = targets;
    Bfull = bpos;
    if(mirrored)
    {
      for(Point_2& p : B) p = mirror(p);
      for(Point_2& p : T) p = mirror(p);
      for(Point_2& p : Bfull) p = mirror(p);
      partition = internal::Domain_partition();
      ec = immersed ? partition_immersed(B, node_turns()) : internal::partition_domain(B, T, partition, popt);
      if(ec != OK) return ec;
      if(!partition.counterclockwise) return ERROR_PATH_TRACING_FAILED; // cannot happen
    }
    // a sliver polygon at the border (e.g. a border vertex that turns by less than rounding but is a
    // node): no path fits in it; refused before tracing, with the border as the reason
    if(immersed && !internal::path_corners_turn_by_margin(partition, B)) return ERROR_DEGENERATE_BORDER;
    stats.paths = partition.edges.size();
    if(verbose)
      std::cerr << "[constrained_embedding] partition: " << partition.edges.size() << " interior edges, "
                << partition.polygons.size() << " polygons" << (immersed ? " (immersed)" : "") << std::endl;
    stats.seconds_partition = timer.time() - t0;
    return OK;
  }

  // ---- 3. the working copy ------------------------------------------------------------------
  Error_code make_working_copy()
  {
    work = Work();
    Error_code ec = OK;
    std::vector<std::pair<vertex_descriptor, wvertex> > v2v;
    CGAL::copy_face_graph(tm, work, CGAL::parameters::vertex_point_map(vpm).vertex_to_vertex_output_iterator(std::back_inserter(v2v)));
    to_work.clear();
    to_mesh.clear();
    for(const auto& p : v2v) { to_work.emplace(p.first, p.second); to_mesh.emplace(p.second, p.first); }
    wvpm = get(CGAL::vertex_point, work);
    // Path costs, arc lengths and areas square 3D lengths in double: a mesh beyond 2^+-100 in size is brought near
    // 1 by an exact power of two (the caller's mesh keeps its points: the refinement is replayed on them)
    internal::normalize_points_3(work);
    // holes: fans around new vertices; the pieces of the hole loops are tracked through the splits
    // so that the hole regions (what the fans became) can be removed after the certificate
    loop_pieces.clear();
    centers.clear();
    if(holes)
    {
      const auto ho = halfedge(to_work.at(source(outer, tm)), to_work.at(target(outer, tm)), work);
      if(!ho.second) return ERROR_WRONG_PARAMETER; // cannot happen: the copy has tm's connectivity
      const auto wouter = CGAL::is_border(ho.first, work) ? ho.first : opposite(ho.first, work);
      internal::Filled_holes<Work> filled;
      ec = internal::fill_holes(work, wouter, wvpm, filled);
      if(ec != OK) return ec;
      centers = filled.centers;
      for(wvertex c : centers)
        for(auto h : CGAL::halfedges_around_target(c, work))
        {
          const auto opp = prev(h, work); // h ends at c: in its fan face, the edge opposite c (a loop edge)
          if(!CGAL::is_border(h, work)) loop_pieces.insert(piece(source(opp, work), target(opp, work)));
        }
    }
    nodes.clear();
    for(std::size_t k : border_nodes) nodes.push_back(to_work.at(disk.vertices[disk.border[k]]));
    for(vertex_descriptor v : cverts) nodes.push_back(to_work.at(v));
    paths.clear();
    steiner.clear();
    return OK;
  }

  // ---- 3b. path tracing, chord splits -------------------------------------------------------
  // The motions of the kinetic tracing (kinetic_triangulation.h, trace_kinetic.h): from where a uniform
  // Tutte map of the copy puts the constrained vertices to their targets, each with its end triangulation
  // merged into convex polygons (its own partition) and the proxy of its crossings; ordered by the proxy.
  // For a convex border without holes and with targets only.
  struct Kinetic_candidate
  {
    std::size_t motion = 0;           // 0: straight lines; 1, 2, 3, 4: permutation braid along 0, 90, 45, 135 degrees
    internal::Kinetic_triangulation kt;
    internal::Domain_partition part;
    std::size_t proxy = 0;            // kinetic_proxy_crossings()
  };
  Error_code kinetic_candidates(std::vector<Kinetic_candidate>& out, double seconds)
  {
    out.clear();
    if(holes || immersed || non_convex || targets.empty()) return ERROR_WRONG_PARAMETER;
    const std::size_t n = static_cast<std::size_t>(num_vertices(work)), nt = T.size();
    std::vector<std::vector<std::size_t> > adjacency(n);
    for(wvertex v : vertices(work))
      for(auto h : CGAL::halfedges_around_target(v, work))
        adjacency[static_cast<std::size_t>(v)].push_back(static_cast<std::size_t>(source(h, work)));
    std::vector<char> fixed(n, 0);
    std::vector<internal::Guide_point> pos(n, internal::Guide_point{ { 0., 0. } });
    for(std::size_t k = 0; k < nb; ++k)
    {
      const std::size_t w = static_cast<std::size_t>(to_work.at(disk.vertices[disk.border[k]]));
      fixed[w] = 1;
      pos[w] = { { CGAL::to_double(Bfull[k].x()), CGAL::to_double(Bfull[k].y()) } };
    }
    if(!internal::solve_barycentric(adjacency, fixed, pos)) return ERROR_PATH_TRACING_FAILED;
    std::vector<std::array<double, 2> > border, start, end;
    for(const Point_2& p : B) border.push_back({ { CGAL::to_double(p.x()), CGAL::to_double(p.y()) } });
    for(std::size_t i = 0; i < nt; ++i)
    {
      start.push_back(pos[static_cast<std::size_t>(nodes[nbn + i])]);
      end.push_back({ { CGAL::to_double(T[i].x()), CGAL::to_double(T[i].y()) } });
    }
    const std::size_t max_flips = 64 * (nbn + nt) * (nt + 1) + 1000;
    const double t0 = timer.time();
    static_assert(internal::kinetic_motions == 5, "one direction per braid motion");
    for(std::size_t m = 0; m < internal::kinetic_motions; ++m)
    {
      const std::size_t motion = (m + 1) % internal::kinetic_motions; // the braids first: they win ties
      Kinetic_candidate c;
      c.motion = motion;
      std::vector<std::vector<std::array<double, 2> > > waypoints{ start, end };
      if(motion > 0)
      {
        const double pi = 3.14159265358979323846;
        const double directions[] = { 0., 0.5 * pi, 0.25 * pi, 0.75 * pi };
        waypoints = internal::permutation_braid_waypoints(border, start, end, directions[motion - 1]);
        if(waypoints.empty()) continue;
      }
      const bool moved = internal::kinetic_triangulation(border, waypoints, max_flips, c.kt);
      // the cap: a motion whose proxy passes a multiple of the ones that would be traced is not traced
      std::size_t cap = (std::numeric_limits<std::size_t>::max)() - 1;
      if(out.size() >= internal::kinetic_traced_motions)
      {
        std::vector<std::size_t> so_far;
        for(const Kinetic_candidate& o : out) so_far.push_back(o.proxy);
        std::nth_element(so_far.begin(), so_far.begin() + (internal::kinetic_traced_motions - 1), so_far.end());
        const std::size_t k = so_far[internal::kinetic_traced_motions - 1];
        if(k < cap / internal::kinetic_proxy_cap_factor) cap = internal::kinetic_proxy_cap_factor * k;
      }
      // the end triangulation, checked exactly at the targets, merged into convex polygons as the Delaunay one is
      if(moved && internal::merge_triangulation(B, T, c.kt.final_triangles, c.part, popt) == OK)
        c.proxy = internal::kinetic_proxy_crossings(c.kt, border, start, cap, seconds - (timer.time() - t0));
      if(verbose)
        std::cerr << "[constrained_embedding] kinetic triangulation (motion " << motion << "): " << (moved ? "" : "failed, ")
                  << c.kt.flips.size() << " flips, " << (moved && c.proxy != std::size_t(-1) ? std::to_string(c.proxy) : "no count (over " + std::to_string(cap) + ")")
                  << " crossings of the start triangulation" << std::endl;
      if(moved && c.proxy != std::size_t(-1)) out.push_back(std::move(c));
    }
    // fewest crossings first (stable: on a tie, the order above)
    std::stable_sort(out.begin(), out.end(), [](const Kinetic_candidate& a, const Kinetic_candidate& b) { return a.proxy < b.proxy; });
    return out.empty() ? ERROR_PATH_TRACING_FAILED : OK;
  }

  Error_code trace()
  {
    const double t_tracing = timer.time();
    Error_code ec = OK;
    if(!(remaining() > 0)) return ERROR_BUDGET_EXHAUSTED;
    if(!partition.edges.empty())
    {
      // Four tracings at most. Shortest paths first: on most inputs they add few vertices. When they run
      // out of their budget or add many vertices (nested partition edges squeezed into corridors, as
      // on space-filling-curve borders or with targets in an order unrelated to the surface), the paths
      // are traced again on a copy of the mesh as it was: as curves crossing the input edges only, the
      // mesh refined once at the end (trace_overlay.h: no compounding of nested paths; disks only), then
      // guided by a drawing of the partition (guide_map.h), with two guides and edge orders that help on
      // different inputs, and the result with the fewest Steiner vertices is kept (the measurements behind
      // these choices: benchmark/results/constrained_design_measurements.md). Each later tracing
      // stops as soon as it would add as many as the best so far; after a successful overlay tracing,
      // the guided ones run only when it added at most 4 times the mesh's vertices, each stopped after a
      // quarter of its time (at least 1 s). A budget given by the caller bounds every tracing.
      const std::size_t unset = std::size_t(-1);
      const std::size_t user_max = max_steiner_vertices;
      const std::size_t ne = static_cast<std::size_t>(num_edges(work));
      // the default budgets of each tracing: internal/constrained/tracer_budgets.h
      const std::size_t first_max = user_max != unset ? user_max : internal::first_tracing_budget.of(static_cast<std::size_t>(num_vertices(work)));
      const std::size_t guided_max = user_max != unset ? user_max : internal::guided_tracing_budget.of(ne);
      const Work before_tracing = work;
      ec = internal::trace_paths(work, wvpm, nodes, partition.edges, partition.rotation, paths, steiner,
                                 parameters::maximum_steiner_vertices(first_max).maximum_running_time(remaining()));
      if(verbose)
        std::cerr << "[constrained_embedding] shortest-path tracing: " << get_error_message(ec) << ", "
                  << steiner.size() << " Steiner vertices, " << timer.time() - t_tracing << " s" << std::endl;
      const std::size_t many = num_vertices(before_tracing) / internal::retrace_above_fraction + 10;
      if((ec == ERROR_BUDGET_EXHAUSTED || (ec == OK && steiner.size() > many)) && remaining() > 0)
      {
        // the best result so far (kept in `best_*` while a guided tracing runs on `work`)
        Work best_work;
        std::vector<std::vector<wvertex> > best_paths;
        std::vector<internal::Steiner_vertex<Work> > best_steiner;
        const internal::Domain_partition original_partition = partition;
        internal::Domain_partition best_partition;
        const Error_code first_ec = ec;
        bool have_best = false;
        auto keep_if_best = [&]()
        {
          if(ec != OK || (have_best && steiner.size() >= best_steiner.size())) return;
          best_work = std::move(work); best_paths.swap(paths); best_steiner.swap(steiner);
          best_partition = partition;
          have_best = true;
        };
        keep_if_best();
        // the class of a motion of the targets, with a partition of its own (kinetic_triangulation.h): the
        // straight-line motion and permutation braids along four directions are simulated, and the ones whose
        // curves cross their own start triangulation least are traced on the mesh, each stopped as soon as it
        // would add as many vertices as the best so far (benchmark/results/constrained_design_measurements.md)
        if(!holes && !immersed && !non_convex && !targets.empty() && remaining() > 0 && kinetic)
        {
          // under a time budget, the simulations and then the tracing on the mesh get their shares of what
          // is left (tracer_budgets.h): the tracings after it keep the rest
          work = before_tracing;
          wvpm = get(CGAL::vertex_point, work);
          std::vector<Kinetic_candidate> candidates;
          ec = kinetic_candidates(candidates, internal::kinetic_simulation_time_share * remaining());
          stats.kinetic_tracing = true;
          const double kinetic_end = std::isfinite(remaining())
                                   ? timer.time() + internal::kinetic_tracing_time_share * remaining() : remaining();
          for(std::size_t m = 0; m < (std::min)(candidates.size(), internal::kinetic_traced_motions); ++m)
          {
            const Kinetic_candidate& c = candidates[m];
            const double seconds = std::isfinite(kinetic_end) ? kinetic_end - timer.time() : kinetic_end;
            if(!(seconds > 0) || (have_best && best_steiner.empty())) break;
            work = before_tracing;
            wvpm = get(CGAL::vertex_point, work);
            paths.clear();
            steiner.clear();
            const std::size_t max_k = have_best ? best_steiner.size() - 1 : (user_max != unset ? user_max : internal::overlay_tracing_budget.of(ne));
            const double t_kinetic = timer.time();
            ec = internal::trace_paths_kinetic(work, wvpm, nodes, c.kt, c.part, paths, steiner,
                                               parameters::maximum_steiner_vertices(max_k).maximum_running_time(seconds));
            if(verbose)
              std::cerr << "[constrained_embedding] kinetic tracing (motion " << c.motion << "): " << get_error_message(ec) << ", "
                        << steiner.size() << " Steiner vertices, " << timer.time() - t_kinetic << " s" << std::endl;
            if(m == 0) stats.kinetic_flips = c.kt.flips.size();
            if(ec == OK && (!have_best || steiner.size() < best_steiner.size()))
            {
              stats.kinetic_tracing_kept = true;
              stats.kinetic_motion = static_cast<int>(c.motion);
              stats.kinetic_flips = c.kt.flips.size();
            }
            if(ec == OK) partition = c.part;
            keep_if_best();
            partition = original_partition;
          }
        }
        double t_overlay_start = timer.time();
        if(!holes && remaining() > 0)
        {
          // the paths may wind around the constrained vertices (targets in an order unrelated to the
          // surface): curves crossing only the input edges, the mesh refined once (trace_overlay.h)
          work = before_tracing;
          wvpm = get(CGAL::vertex_point, work);
          paths.clear();
          steiner.clear();
          const std::size_t max_o = have_best ? best_steiner.size() - 1 : (user_max != unset ? user_max : internal::overlay_tracing_budget.of(ne));
          t_overlay_start = timer.time();
          ec = internal::trace_paths_overlay(work, wvpm, nodes, partition.edges, partition.rotation, paths, steiner,
                                             parameters::maximum_steiner_vertices(max_o).maximum_running_time(remaining()));
          stats.overlay_tracing = true;
          if(verbose)
            std::cerr << "[constrained_embedding] overlay tracing: " << get_error_message(ec) << ", "
                      << steiner.size() << " Steiner vertices, " << timer.time() - t_overlay_start << " s" << std::endl;
          if(ec == OK && (!have_best || steiner.size() < best_steiner.size()))
          {
            stats.overlay_tracing_kept = true;
            stats.kinetic_tracing_kept = false;
            stats.kinetic_motion = -1;
          }
          keep_if_best();
        }
        // After a successful overlay tracing, the guided ones run only when it added at most 4 times the
        // mesh's vertices, each with a quarter of its time, at least 1 s: on winding partitions (targets in
        // an order unrelated to the surface) they compound and run out of their budgets, slowly, and
        // rarely win (benchmark/results/constrained_design_measurements.md).
        const bool guided_after_overlay = best_steiner.size() <= internal::guided_after_overlay_factor * num_vertices(before_tracing);
        const double guided_seconds = stats.overlay_tracing_kept ? (std::max)(1., 0.25 * (timer.time() - t_overlay_start)) : -1;
        struct Guided_variant { double disk_factor; bool interior_first; };
        const Guided_variant variants[] = { { 0., false }, { 1., true } };
        for(const Guided_variant& g : variants)
        {
          if(!(remaining() > 0) || (have_best && best_steiner.empty())) break;
          if(stats.overlay_tracing_kept && !guided_after_overlay) break;
          const double guided_budget = guided_seconds >= 0 ? (std::min)(remaining(), guided_seconds) : remaining();
          work = before_tracing;
          wvpm = get(CGAL::vertex_point, work); // the copy's own point array
          paths.clear();
          steiner.clear();
          const std::size_t max_g = have_best ? best_steiner.size() - 1 : guided_max;
          const double t_guided = timer.time();
          ec = internal::trace_paths(work, wvpm, nodes, partition.edges, partition.rotation, paths, steiner,
                                     internal::guide_weight(1., internal::guide_disk_factor(g.disk_factor,
                                     internal::interior_edges_first(g.interior_first,
                                     parameters::maximum_steiner_vertices(max_g).maximum_running_time(guided_budget)))));
          stats.guided_tracing = true;
          if(verbose)
            std::cerr << "[constrained_embedding] guided tracing (" << (g.disk_factor > 0 ? "node disks" : "pinned nodes")
                      << (g.interior_first ? ", interior edges first" : "") << "): " << get_error_message(ec) << ", "
                      << steiner.size() << " Steiner vertices, " << timer.time() - t_guided << " s" << std::endl;
          if(ec == OK && (!have_best || steiner.size() < best_steiner.size()))
          {
            stats.guided_tracing_kept = true;
            stats.overlay_tracing_kept = false;
            stats.kinetic_tracing_kept = false;
            stats.kinetic_motion = -1;
          }
          keep_if_best();
        }
        if(have_best)
        {
          ec = OK;
          work = std::move(best_work);
          wvpm = get(CGAL::vertex_point, work);
          paths.swap(best_paths);
          steiner.swap(best_steiner);
          partition = std::move(best_partition);
          stats.paths = partition.edges.size();
        }
        else ec = first_ec; // every tracing failed: the shortest paths' reason (a guided search may give up)
      }
      stats.steiner_vertices = steiner.size();
      if(ec != OK)
      {
        if(verbose) std::cerr << "[constrained_embedding] path tracing failed: " << get_error_message(ec) << std::endl;
        return ec;
      }
    }
    border_index.clear();
    for(std::size_t k = 0; k < nbn; ++k) border_index.emplace(nodes[k], k);
    {
      std::vector<char> corner;
      std::vector<std::size_t> side;
      const std::size_t nsides = internal::polygon_sides(B, orient, corner, side);
      const internal::Same_side_chord<Work> same_side(work, nodes, paths);
      const internal::Constrained_chord_predicate<Work> accept{ same_side, border_index, corner, side, nsides };
      stats.chord_splits = internal::split_chords(work, wvpm, paths, steiner, accept);
    }
    stats.steiner_vertices = steiner.size();
    stats.seconds_tracing = timer.time() - t_tracing;
    if(verbose)
      std::cerr << "[constrained_embedding] " << paths.size() << " path(s), " << steiner.size() << " Steiner vertices ("
                << stats.chord_splits << " chord splits)" << std::endl;
    return OK;
  }

  // ---- 4. uv of the path network, patch embeddings ------------------------------------------
  Error_code map_patches()
  {
    const double t_patches = timer.time();
    wuv = work.template add_property_map<wvertex, Point_2>("v:pe_constrained_uv", Point_2(0, 0)).first;
    wborder.clear();
    for(std::size_t k = 0; k < nb; ++k) wborder.push_back(to_work.at(disk.vertices[disk.border[k]]));
    for(std::size_t k = 0; k < nb; ++k) put(wuv, wborder[k], Bfull[k]);
    for(std::size_t i = 0; i < T.size(); ++i) put(wuv, nodes[nbn + i], T[i]);
    {
      // each path writes its own interior vertices: the paths are placed in parallel with Parallel_tag
      std::vector<Error_code> placed(paths.size(), OK);
      typedef typename Traits::FT FT_uv;
      std::vector<std::size_t> order(paths.size()); // longest first: the workers end together
      std::iota(order.begin(), order.end(), std::size_t(0));
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return paths[a].size() > paths[b].size(); });
      internal::for_each_index<ConcurrencyTag, FT_uv>(
        paths.size(), internal::number_of_workers<ConcurrencyTag, FT_uv>(paths.size(), internal::max_patch_workers),
        [&](std::size_t k, int) {
          const std::size_t e = order[k];
          const std::vector<wvertex>& P = paths[e];
          if(P.size() < 3) return;
          // 3D arc-length fractions of the interior path vertices
          std::vector<double> len(1, 0.);
          for(std::size_t k = 0; k + 1 < P.size(); ++k)
            len.push_back(len.back() + std::sqrt(CGAL::to_double(CGAL::squared_distance(get(wvpm, P[k]), get(wvpm, P[k + 1])))));
          std::vector<double> fractions;
          for(std::size_t k = 1; k + 1 < P.size(); ++k)
          {
            double f = len.back() > 0 ? len[k] / len.back() : double(k) / double(P.size() - 1);
            if(!(f >= 0)) f = 0;
            if(f > 1) f = 1;
            if(!fractions.empty() && f < fractions.back()) f = fractions.back();
            fractions.push_back(f);
          }
          std::vector<Point_2> positions;
          placed[e] = internal::place_path_vertices(partition, B, T, e, fractions, positions);
          if(placed[e] != OK) return;
          for(std::size_t k = 1; k + 1 < P.size(); ++k) put(wuv, P[k], positions[k - 1]);
        });
      for(Error_code pe : placed) if(pe != OK) return pe;
    }
    {
      // A face whose three vertices lie on the path network is fixed by the placement above; when
      // rounding made it flat or negative (two path vertices within an ulp of a sharp corner's other
      // side), no patch map can repair it. Splitting its chord gives it a free vertex.
      std::vector<char> on_network(num_vertices(work), 0);
      for(wvertex v : vertices(work)) if(CGAL::is_border(v, work)) on_network[static_cast<std::size_t>(v)] = 1;
      for(wvertex v : nodes) on_network[static_cast<std::size_t>(v)] = 1;
      for(const auto& P : paths) for(wvertex v : P) on_network[static_cast<std::size_t>(v)] = 1;
      const internal::Non_positive_face_chord<Work, decltype(wuv), typename Traits::Exact_orientation_2>
        bad_face{ work, wuv, orient, on_network };
      const std::size_t splits = internal::split_chords(work, wvpm, paths, steiner, bad_face);
      stats.chord_splits += splits;
      if(verbose && splits > 0)
        std::cerr << "[constrained_embedding] " << splits << " chord(s) of faces left flat by rounding split" << std::endl;
    }
    patches.clear();
    fpatch = work.template add_property_map<wface, std::size_t>("f:pe_constrained_patch", std::size_t(0)).first;
    Error_code ec = internal::label_patches(work, nodes, paths, fpatch, patches);
    if(ec != OK) return ec;
    // one patch per polygon (the overlay tracing leaves this postcondition to this labelling)
    if(!holes && patches.size() != partition.polygons.size()) return ERROR_PATH_TRACING_FAILED;
    stats.patches = patches.size();
    patch_faces.assign(patches.size(), std::vector<wface>());
    for(wface f : faces(work)) patch_faces[get(fpatch, f)].push_back(f);
    internal::Patch_phase_result patch_phase =
      internal::embed_patches<ConcurrencyTag>(work, patch_faces, wuv, wts, traits, [this]() { return remaining(); });
    stats.repaired_patches += patch_phase.repaired_patches;
    if(patch_phase.status != OK && patch_phase.status != ERROR_BUDGET_EXHAUSTED)
    {
      // no room in a patch's polygon: mapped with a neighbour into the union of their polygons
      std::vector<char> excluded(patches.size(), 0), is_node(num_vertices(work), 0);
      for(wvertex v : nodes) is_node[static_cast<std::size_t>(v)] = 1;
      Error_code merge_ec = OK;
      for(std::size_t p : patch_phase.failed)
      {
        if(excluded[p]) continue; // mapped with an earlier failed patch
        std::vector<std::size_t> with;
        excluded[p] = 1;
        merge_ec = internal::merge_failed_patch(work, patch_faces, fpatch, is_node, p, wuv, wts, traits,
                                                [this]() { return remaining(); }, excluded, with);
        if(verbose)
        {
          std::cerr << "[constrained_embedding] patch " << p << " (" << patch_faces[p].size() << " faces) with its neighbours: ";
          if(merge_ec == OK) { std::cerr << "mapped with patch(es)"; for(std::size_t q : with) std::cerr << ' ' << q; }
          else std::cerr << get_error_message(merge_ec);
          std::cerr << std::endl;
        }
        if(merge_ec != OK) break;
        for(std::size_t q : with) excluded[q] = 1;
        stats.merged_patches += 1 + with.size();
      }
      if(merge_ec == OK) patch_phase.status = OK;
    }
    if(patch_phase.status != OK)
    {
      if(verbose)
      {
        const std::size_t p = patch_phase.failed_patch;
        const std::streamsize precision = std::cerr.precision(17); // bit-exact: the failures are about rounding
        std::cerr << "[constrained_embedding] patch " << p << " (" << patch_faces[p].size() << " faces): "
                  << get_error_message(patch_phase.status) << "; border:";
        for(auto h : patches[p].border)
          std::cerr << " (" << CGAL::to_double(get(wuv, target(h, work)).x()) << ", "
                    << CGAL::to_double(get(wuv, target(h, work)).y()) << ")";
        std::cerr << std::endl;
        std::cerr.precision(precision);
      }
      return patch_phase.status;
    }
    stats.seconds_patches = timer.time() - t_patches;
    return OK;
  }

  // ---- 5. certificate ------------------------------------------------------------------------
  Error_code certify()
  {
    const double t_cert = timer.time();
    // the border fans' full turns that the immersion certificate expects: the caller's rotation indices
    work_turns = work.template add_property_map<wvertex, int>("v:pe_rotation_index", 0).first;
    if(!border_turns.empty())
      for(std::size_t k = 0; k < nb; ++k) work_turns[to_work.at(disk.vertices[disk.border[k]])] = border_turns[k];
    stats.report_before_optimization = check_embedding_impl(work, wuv, parameters::check_overlap(!immersed).geom_traits(traits));
    if(immersed)
    {
      // locally injective with the border bit-exactly the given polygon (an immersion overlaps itself:
      // the embedding certificate above fails on the border, by design)
      stats.immersion = true;
      std::vector<Point_2> polygon(Bfull.begin(), Bfull.begin() + static_cast<std::ptrdiff_t>(nb));
      stats.immersion_report = check_immersion_impl(work, wuv, to_work.at(disk.vertices[disk.border[0]]), polygon,
                                               parameters::vertex_rotation_index_map(work_turns).geom_traits(traits));
      stats.seconds_certification = timer.time() - t_cert;
      if(verbose) std::cerr << "[constrained_embedding] " << stats.immersion_report.summary() << std::endl;
      stats.report = stats.report_before_optimization;
      if(!stats.immersion_report.is_immersion()) return ERROR_INVALID_EMBEDDING;
    }
    stats.seconds_certification = timer.time() - t_cert;
    if(!immersed && !stats.report_before_optimization.is_valid())
    {
      stats.report = stats.report_before_optimization;
      if(verbose) std::cerr << "[constrained_embedding] " << stats.report.summary() << std::endl;
      return ERROR_INVALID_EMBEDDING;
    }
    if(holes)
    {
      // the splits of loop pieces refine the loops; then every face reachable from a center without
      // crossing a loop piece is what a fan became: removed (with the vertices it isolates). The
      // restriction of the certified one-to-one map to the remaining faces is one-to-one and each
      // hole is the image of a disk bounded by its loop: certified again below
      for(const auto& sv : steiner)
      {
        const auto it = loop_pieces.find(piece(sv.a, sv.b));
        if(it == loop_pieces.end()) continue;
        loop_pieces.erase(it);
        loop_pieces.insert(piece(sv.a, sv.v));
        loop_pieces.insert(piece(sv.v, sv.b));
      }
      std::set<wface> hole_faces;
      std::vector<wface> stack;
      for(wvertex c : centers)
        for(wface f : CGAL::faces_around_target(halfedge(c, work), work))
          if(f != boost::graph_traits<Work>::null_face() && hole_faces.insert(f).second) stack.push_back(f);
      while(!stack.empty()) // each face pushed once
      {
        const wface f = stack.back(); stack.pop_back();
        for(auto h : CGAL::halfedges_around_face(halfedge(f, work), work))
        {
          if(loop_pieces.count(piece(source(h, work), target(h, work)))) continue;
          const wface g = face(opposite(h, work), work);
          if(g != boost::graph_traits<Work>::null_face() && hole_faces.insert(g).second) stack.push_back(g);
        }
      }
      for(wface f : hole_faces) CGAL::Euler::remove_face(halfedge(f, work), work);
      stats.report_before_optimization = check_embedding_impl(work, wuv, parameters::multiply_connected(true).geom_traits(traits));
      if(!stats.report_before_optimization.is_valid())
      {
        stats.report = stats.report_before_optimization;
        if(verbose) std::cerr << "[constrained_embedding] holes: " << stats.report.summary() << std::endl;
        return ERROR_INVALID_EMBEDDING;
      }
    }
    stats.report = stats.report_before_optimization;
    return OK;
  }

  // the optimization with border and constraints fixed, within `seconds`; its time is added to the statistics
  Error_code run_optimization(Optimization_statistics& os, double seconds)
  {
    const std::vector<wvertex> constrained_nodes(nodes.begin() + static_cast<std::ptrdiff_t>(nbn), nodes.end());
    const double t_opt = timer.time();
    // each iteration reported with the energy and the time left of the optimization's budget
    const std::function<bool(double)> each_iteration = [this, &os, t_opt, seconds](double fraction) {
      if(report(Constrained_embedding_phase::OPTIMIZATION, fraction, os.energy_current, t_opt + seconds - timer.time())) return true;
      stopped = true;
      return false;
    };
    const Error_code e = optimize_distortion_impl<ConcurrencyTag>(work, wuv, parameters::optimization_statistics(&os,
                           parameters::constrained_vertices(constrained_nodes).maximum_running_time(seconds)
                           .geom_traits(traits).callback(each_iteration)));
    stats.seconds_optimization += timer.time() - t_opt;
    return e;
  }

  // ---- 5a. optimization ----------------------------------------------------------------------
  Error_code optimize_map()
  {
    if(!optimize) return OK;
    {
      stats.optimized = true;
      stats.optimization_status = run_optimization(stats.optimization, (std::min)(remaining(), optimization_seconds));
      // OK / ERROR_BUDGET_EXHAUSTED: a certified, improved map was written; otherwise nothing was
      stats.report = check_embedding_impl(work, wuv, parameters::multiply_connected(holes, parameters::check_overlap(!immersed).geom_traits(traits)));
      if(immersed)
      {
        // the optimizer keeps immersions (border fixed): certified again here, with the border polygon
        std::vector<Point_2> polygon(Bfull.begin(), Bfull.begin() + static_cast<std::ptrdiff_t>(nb));
        stats.immersion_report = check_immersion_impl(work, wuv, to_work.at(disk.vertices[disk.border[0]]), polygon,
                                                 parameters::vertex_rotation_index_map(work_turns).geom_traits(traits));
        if(!stats.immersion_report.is_immersion() || stats.immersion_report.border_mismatches != 0)
          return ERROR_INVALID_EMBEDDING;
      }
      else if(!stats.report.is_valid()) return ERROR_INVALID_EMBEDDING;
    }
    return OK;
  }

  // ---- 5b. coarsening: added vertices that the certified map can do without are removed ------
  // The symmetric Dirichlet energy of a triangle (a, x, y) of the working map against its 3D triangle,
  // both scaled to one total area (as check_embedding() measures it; the coarsening leaves both totals
  // unchanged: the fans lie in the input faces); infinite unless positive.
  struct Fan_energy
  {
    const Constrained_embedder& e;
    double k2 = 0, sgn = 1;
    Fan_energy(const Constrained_embedder& emb, CGAL::Orientation positive) : e(emb), sgn(positive == CGAL::RIGHT_TURN ? -1. : 1.)
    {
      double total3d = 0, total_uv = 0;
      for(auto f : faces(e.work))
      {
        const auto h = halfedge(f, e.work);
        const wvertex a = source(h, e.work), x = target(h, e.work), y = target(next(h, e.work), e.work);
        total3d += std::sqrt((std::max)(0., internal::reference_from_points<double, 3>(p3(a), p3(x), p3(y)).area2));
        total_uv += uv_area(a, x, y);
      }
      k2 = (total3d > 0 && total_uv > 0) ? total_uv / total3d : 0.;
    }
    std::array<double, 3> p3(wvertex v) const
    {
      const auto& q = get(e.wvpm, v);
      return {{ CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()) }};
    }
    double uv_area(wvertex a, wvertex x, wvertex y) const
    {
      const auto& pa = get(e.wuv, a); const auto& px = get(e.wuv, x); const auto& py = get(e.wuv, y);
      const double ax = CGAL::to_double(pa.x()), ay = CGAL::to_double(pa.y());
      return sgn * ((CGAL::to_double(px.x()) - ax) * (CGAL::to_double(py.y()) - ay)
                    - (CGAL::to_double(px.y()) - ay) * (CGAL::to_double(py.x()) - ax)) / 2;
    }
    double energy(wvertex a, wvertex x, wvertex y) const
    {
      if(!(k2 > 0)) return 0; // no 3D area: no bound
      const auto& pa = get(e.wuv, a); const auto& px = get(e.wuv, x); const auto& py = get(e.wuv, y);
      return internal::face_distortion(p3(a), p3(x), p3(y), k2,
                                       CGAL::to_double(pa.x()), sgn * CGAL::to_double(pa.y()),
                                       CGAL::to_double(px.x()), sgn * CGAL::to_double(px.y()),
                                       CGAL::to_double(py.x()), sgn * CGAL::to_double(py.y()),
                                       uv_area(a, x, y)).symmetric_dirichlet;
    }
  };

  Error_code coarsen_map()
  {
    removals.clear();
    stats.steiner_vertices_inserted = steiner.size();
    if(coarsen && !immersed && !steiner.empty())
    {
      const double t_coarsen = timer.time();
      const CGAL::Orientation positive = stats.report.clockwise ? CGAL::RIGHT_TURN : CGAL::LEFT_TURN;
      // A removal reshapes the faces of a fan after the optimization: a fan face may be positive and yet
      // far thinner than any face of the optimized map. The second optimization below smooths a fan face
      // if it may move one of its vertices, but not a face between border and constrained vertices only
      // (three border vertices of a triangle's slanted side, collinear up to rounding, made a face of area
      // 1e-19 that took a map's mean energy from 138 to 2e26). Such a face, and any fan face when no
      // optimization follows, may not be more distorted than the map's worst face before the coarsening.
      const Fan_energy fan_energy(*this, positive);
      double worst = 0;
      for(auto f : faces(work))
      {
        const auto h = halfedge(f, work);
        worst = (std::max)(worst, fan_energy.energy(source(h, work), target(h, work), target(next(h, work), work)));
      }
      std::vector<char> held(work.number_of_vertices() + work.number_of_removed_vertices(), 0); // indexed by vertex index
      for(auto v : vertices(work)) if(CGAL::is_border(v, work)) held[std::size_t(v)] = 1;
      for(std::size_t i = nbn; i < nodes.size(); ++i) held[std::size_t(nodes[i])] = 1;
      const bool reoptimize = optimize && !stopped && (std::min)(remaining(), optimization_seconds - stats.seconds_optimization) > 0;
      const auto accept = [&](wvertex a, wvertex x, wvertex y) {
        if(reoptimize && !(held[std::size_t(a)] && held[std::size_t(x)] && held[std::size_t(y)])) return true;
        return fan_energy.energy(a, x, y) <= worst;
      };
      std::vector<char> done;
      std::size_t passes = 0;
      const auto test = [&](wvertex v, wvertex a, std::vector<wvertex>& link) {
        return !work.is_removed(v) && !CGAL::is_border(v, work) && !work.is_removed(a) &&
               internal::can_remove_into(work, wuv, orient, positive, v, a, link, accept);
      };
      const auto remove = [&](wvertex v, wvertex a, const std::vector<wvertex>& link) {
        // each fan face (a, x, y) takes the patch of the face (v, x, y) it replaces
        std::vector<std::size_t> fan_labels;
        for(std::size_t j = 1; j + 1 < link.size(); ++j)
          fan_labels.push_back(get(fpatch, face(halfedge(link[j], link[j + 1], work).first, work)));
        if(internal::remove_into(work, v, a) != OK) return ERROR_INVALID_EMBEDDING; // cannot happen
        for(std::size_t j = 1; j + 1 < link.size(); ++j)
          put(fpatch, face(halfedge(link[j], link[j + 1], work).first, work), fan_labels[j - 1]);
        return OK;
      };
      const Error_code rec = internal::remove_added_vertices(steiner, held.size(), test, remove, done, removals, passes);
      if(rec != OK) return rec;
      stats.steiner_vertices_removed = removals.size();
      // the vertices kept only by the distortion bound: removable with every fan face positive
      std::vector<wvertex> link;
      for(std::size_t k = 0; k < steiner.size(); ++k)
      {
        const auto& sv = steiner[k];
        if(done[k] || work.is_removed(sv.v) || CGAL::is_border(sv.v, work)) continue;
        for(wvertex a : { sv.a, sv.b })
          if(!work.is_removed(a) && internal::can_remove_into(work, wuv, orient, positive, sv.v, a, link))
          {
            ++stats.steiner_vertices_kept_for_distortion;
            break;
          }
      }
      // every face of every fan was tested positive, exactly; the whole map is certified again
      stats.report = check_embedding_impl(work, wuv, parameters::multiply_connected(holes).geom_traits(traits));
      stats.seconds_coarsening = timer.time() - t_coarsen;
      if(verbose)
        std::cerr << "[constrained_embedding] coarsening: " << removals.size() << " of " << steiner.size()
                  << " added vertices removed in " << passes << " passes, " << stats.seconds_coarsening << " s; "
                  << stats.report.summary() << std::endl;
      if(!stats.report.is_valid()) return ERROR_INVALID_EMBEDDING;
      // the fans are shaped by the removal only: the optimization runs again on the coarser mesh, with
      // what is left of its budget (it starts near its optimum: the faces away from the fans are optimized)
      const double left = (std::min)(remaining(), optimization_seconds - stats.seconds_optimization);
      if(optimize && !stopped && !removals.empty() && left > 0)
      {
        stats.reoptimized = true;
        const Error_code rec = run_optimization(stats.reoptimization, left);
        if(rec != OK && rec != ERROR_BUDGET_EXHAUSTED && stats.optimization_status == OK) stats.optimization_status = rec;
        stats.report = check_embedding_impl(work, wuv, parameters::multiply_connected(holes).geom_traits(traits));
        if(!stats.report.is_valid()) return ERROR_INVALID_EMBEDDING;
      }
    }
    return OK;
  }

  // ---- 5c. constraints and border, exactly (before mirroring back) --------------------------
  Error_code check_constraints()
  {
    for(std::size_t i = 0; i < T.size(); ++i)
    {
      const Point_2 p = get(wuv, nodes[nbn + i]);
      if(!(p.x() == T[i].x() && p.y() == T[i].y()))
      {
        stats.max_constraint_error = std::max(stats.max_constraint_error,
          std::sqrt(CGAL::to_double(CGAL::squared_distance(p, T[i]))));
      }
    }
    for(std::size_t k = 0; k < nb; ++k)
    {
      const Point_2 p = get(wuv, wborder[k]);
      if(!(p.x() == Bfull[k].x() && p.y() == Bfull[k].y())) return ERROR_INVALID_EMBEDDING;
    }
    if(stats.max_constraint_error != 0) return ERROR_INVALID_EMBEDDING;
    return OK;
  }

  // ---- 6. replay the refinement on tm, write the uv -----------------------------------------
  Error_code write_output()
  {
    const double t_out = timer.time();
    std::vector<internal::Edge_split<wvertex, double> > splits;
    splits.reserve(steiner.size());
    std::vector<internal::Steiner_vertex<Work> > kept; // Steiner vertices inside a hole were removed with it
    std::unordered_set<wvertex> coarsened; // removed by the coarsening: replayed, then removed on tm too
    for(const auto& r : removals) coarsened.insert(r.removed);
    for(const auto& s : steiner)
      if(!work.is_removed(s.v) || coarsened.count(s.v))
      {
        kept.push_back(s);
      {
        internal::Edge_split<wvertex, double> e{ s.a, s.b, s.v, s.t };
        e.join_faces = s.join_faces;
        e.diagonals = s.diagonals;
        splits.push_back(std::move(e));
      }
      }
    steiner.swap(kept);
    stats.steiner_vertices = steiner.size() - coarsened.size();
    std::unordered_map<wvertex, vertex_descriptor> copy_to_mesh(to_mesh);
    auto midpoint = [](const Point_3& a, const Point_3& b, double) { return K3().construct_midpoint_3_object()(a, b); };
    // the steiner points on the input surface, computed before tm changes
    typedef internal::Surface_position<vertex_descriptor, double> Position;
    std::unordered_map<wvertex, Position> position;
    if(steiner_out)
      for(const auto& p : to_mesh) position.emplace(p.first, Position::vertex(p.second));
    std::vector<Position> steiner_positions;
    if(steiner_out)
      for(const auto& s : steiner)
      {
        Position q;
        const auto ia = position.find(s.a), ib = position.find(s.b);
        if(ia == position.end() || ib == position.end() || !Position::combine(ia->second, ib->second, s.t, q))
          q = Position(); // not on one input face: cannot happen (kept splits are on the input surface)
        position[s.v] = q;
        steiner_positions.push_back(q);
      }
    Error_code ec = OK;
    {
      const internal::No_recycling_guard<TriangleMesh> append_only(tm); // added vertices after the input's
      ec = internal::replay_splits(splits, tm, vpm, copy_to_mesh, midpoint);
      if(ec == OK) ec = internal::replay_removals(removals, tm, copy_to_mesh);
    }
    if(ec != OK) return ec; // cannot happen: tm has the copy's connectivity
    for(wvertex v : vertices(work))
    {
      const Point_2 p = get(wuv, v);
      put(uvm, copy_to_mesh.at(v), mirrored ? mirror(p) : p);
    }
    if(mirrored) stats.report.clockwise = !stats.report.clockwise;
    // the patch of every face of the refined tm: the faces of tm are the faces of the copy (same
    // connectivity after the replay), each found from one of its halfedges (same orientation)
    internal::write_face_patch_map(tm, work, copy_to_mesh, fpatch, put_patch);
    if(steiner_out)
    {
      steiner_out->clear();
      for(std::size_t i = 0; i < steiner.size(); ++i)
      {
        if(work.is_removed(steiner[i].v)) continue; // removed by the coarsening
        Steiner_point<vertex_descriptor> sp;
        sp.vertex = copy_to_mesh.at(steiner[i].v);
        sp.size = steiner_positions[i].size;
        for(std::size_t k = 0; k < sp.size; ++k)
        {
          sp.corners[k] = steiner_positions[i].corners[k];
          sp.weights[k] = steiner_positions[i].weights[k];
        }
        steiner_out->push_back(sp);
      }
    }
    stats.output_vertices = static_cast<std::size_t>(work.number_of_vertices());
    stats.seconds_output = timer.time() - t_out;
    if(verbose) std::cerr << "[constrained_embedding] " << stats.report.summary() << std::endl;
    return OK;
  }
};

template <class ConcurrencyTag, class TriangleMesh, class VertexUVMap, class NamedParameters>
using Constrained_embedder_for =
  Constrained_embedder<ConcurrencyTag, TriangleMesh, VertexUVMap,
                       typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::type,
                       typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::geom_traits_t, NamedParameters,
                                                                          typename Uv_map_types<VertexUVMap>::Traits>::type>;

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_CONSTRAINED_EMBEDDER_H
