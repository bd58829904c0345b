// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_DOMAIN_PARTITION_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_DOMAIN_PARTITION_H

// Phase 1 of constrained maps: the target domain cut into convex polygons whose corners are
// border points and constraint targets, and the exact placement of path vertices on the cuts.
//
// partition_domain(border, targets, out [, options])
//   border : the uv border polygon, one point per mesh border vertex, in border order, either
//            orientation (out.counterclockwise says which). It must be strictly convex (checked
//            exactly); with options.allow_flat_border_vertices, convex with flat (180 degree)
//            vertices is accepted too (e.g. a square border shape with several vertices per side).
//   targets: the points that must become polygon corners (constraint targets), each strictly
//            inside the domain.
//   out    : nodes 0..nb-1 are the border points in the given order, nodes nb..nb+nt-1 the targets
//            in the given order. Written only on success (left unchanged on error).
//   Method: CGAL::Constrained_Delaunay_triangulation_2 of all nodes with the border edges as
//   constraints, then a greedy merge of adjacent faces: an interior edge is dropped when the union
//   of its two polygons stays strictly convex (orientation decided exactly, on the caller's points)
//   and each new corner between a border edge and an interior edge turns by a margin: the sine of
//   its turn above 2^-20 (in double, on coordinates scaled by a power of two). Path vertices are
//   placed on their segments only up to one ulp in floating point (place_path_vertices): at a corner
//   convex by less, they can fall on the line of the border side, and the mesh edges joining them to
//   that side's vertices become flat chords of the patch, which no map keeps (e.g. a strip's inner
//   corner whose union with the piece across would be flat but for the rounding of a border point).
//   Polygons only grow, so the angles at an edge's ends only grow: an edge refused once stays
//   refused, and one pass over the edges in a fixed order is the whole greedy algorithm.
//   Order (options.order): LONGEST_FIRST (default): it leaves the fewest interior edges, each one a
//   path traced on the mesh (measured: benchmark/results/constrained_design_measurements.md). Dropping the edges
//   between two border points first changes nothing: such an edge (a chord) is always dropped,
//   whatever the order, because the union of its two polygons has, at each end, an angle inside the
//   domain's angle there (below 180 degrees, or exactly 180 at a flat border vertex; the margin can
//   keep a chord only at a border vertex that turns by less than it without being flat). Hence every
//   interior edge of the result has a target as an endpoint (with that exception).
//   Postconditions: every polygon is strictly convex and counterclockwise (with flat border vertices:
//   convex, its 180 degree corners only at flat border nodes that have no interior edge); every
//   target is a corner of at least 3 polygons (its angles are all below 180 degrees); every interior
//   node has at least 3 interior edges; the polygons tile the domain; V - E + F = 1 with the border
//   edges counted; every interior edge has a target as an endpoint (no chord between two border
//   nodes is left, see above), so there is no interior edge at all without targets.
//   Errors (checked in this order; never an assertion or exception on data):
//     ERROR_NON_FINITE_COORDINATES    a NaN or infinite coordinate (border or target)
//     ERROR_DEGENERATE_BORDER         fewer than 3 points, a repeated consecutive point, all points
//                                     collinear, or (without allow_flat_border_vertices) a flat vertex
//     ERROR_NON_CONVEX_BORDER         a reflex vertex, a spike, or a border winding more than once
//     ERROR_CONSTRAINT_OUTSIDE_DOMAIN a target outside the domain or on its border (border points incl.)
//     ERROR_DUPLICATE_CONSTRAINT      two equal targets
//   Exactness: every decision is an exact predicate. The triangulation runs in
//   Certification_kernel<FT>::Kernel: Epick for float/double (exact predicates, Exact_predicates_tag;
//   no construction happens since the constraints, being the convex hull's edges, never cross),
//   Simple_cartesian<Gmpq> for every other number type (Gmpq, Lazy_exact_nt, boost rationals and
//   Gmpfr, whose values convert exactly to rationals). Output is combinatorial (node indices), so it
//   does not depend on the kernel used inside.
//   Complexity: O((nb + nt) log(nb + nt)): the triangulation with spatial sorting, O(log nb) per
//   target for the inside test, a sort of the edges, a union-find for polygon identities; every loop
//   is bounded by the number of half-edges.
//
// partition_domain with options.allow_non_convex_border (default false: everything above unchanged)
//   A border classified non-convex above may then be any SIMPLE polygon (a convex border, strict or
//   with allowed flat vertices, takes the convex path: the same output as without the option).
//   Checks, in this order after the finite test and the DEGENERATE_BORDER ones above (fewer than 3
//   points, a repeated consecutive point, all collinear):
//     ERROR_DEGENERATE_BORDER         a flat vertex without allow_flat_border_vertices
//     ERROR_NON_CONVEX_BORDER         the border is not simple (two edges meet other than consecutive
//                                     ones at their common vertex; exact): Error_code has no code for
//                                     a non-simple border, and such a border is not convex either
//     ERROR_CONSTRAINT_OUTSIDE_DOMAIN a target outside the polygon (e.g. in a reflex notch), equal to
//                                     a border point or on a border edge (exact)
//     ERROR_DUPLICATE_CONSTRAINT      two equal targets
//   Method: the CDT of the border points with the border edges as constraints, then the targets
//   inserted one by one (a target on a border edge splits that constraint, an equal point returns the
//   existing vertex: both detected); the outside faces are those reached from the infinite face
//   across unconstrained edges (the outside of a simple polygon is connected); only the inside faces
//   enter the same greedy merge. Orientation: that of the lexicographically smallest vertex (a strict
//   corner). A flat vertex is a collinear one whose neighbours lie on both sides of it; a spike (both
//   on one side) makes two edges overlap, hence ERROR_NON_CONVEX_BORDER (not simple).
//   Postconditions: as in the convex case, except that interior edges may now join two border nodes
//   (diagonals at reflex vertices, where no union is convex): "every interior edge has a target as
//   an endpoint" does not hold; a reflex border node always keeps at least one interior edge. All
//   fields keep their meaning (rotation of a border node from the next border side to the previous
//   one across the inside, counterclockwise polygons, edge_polygons left/right).
//
// partition_immersed_domain(border, triangles, out [, options])
//   border   : a weakly self-overlapping polygon (the border of an immersed disk), either orientation;
//              its vertices may coincide in the plane (different sheets); no targets.
//   triangles: its triangulation as an immersed disk, as triangulate_self_overlapping_polygon_2()
//              writes it: nb - 2 index triples, each strictly counterclockwise (exact); every border
//              edge a side of exactly one triangle, in the direction (i, i+1) for a counterclockwise
//              border and (i+1, i) for a clockwise one; every other side (a diagonal) shared by exactly
//              two triangles with opposite directions; the triangles around each node form one fan.
//   out      : as above with number_of_targets == 0; counterclockwise tells the border's orientation
//              (read from the triangles). Written only on success.
//   Method: the combinatorics come from the triangles only (the geometry overlaps, so no point
//   location): half-edges glued by their index pairs, then the same greedy merge, decided locally:
//   two adjacent strictly convex polygons are merged when the union's two new corners are strict
//   left turns (exact; with the margin above at a corner between a border edge and an interior
//   edge). This is enough: the union is an immersed disk whose border turns once, so a locally
//   strictly convex union is an embedded convex polygon; the corners are sums of corners
//   below 180 degrees, so the orientation decides exactly whether the sum stays below 180.
//   Flat vertices (with allow_flat_border_vertices): a collinear border vertex whose total angle is
//   exactly 180 degrees (every fan neighbour strictly left of u -> next) is flat as above; a collinear
//   vertex with a total angle of 540 degrees or more is an ordinary (reflex) corner.
//   Postconditions: every polygon strictly convex and counterclockwise (flat corners as above), the
//   polygons cover the immersed disk once (each triangle is in exactly one polygon; their areas sum
//   to the border's signed area), V - E + F = 1 with the border edges counted (checked before
//   returning, as is every polygon's convexity); interior edges join border nodes (there is no other
//   node); rotation, edge_polygons, polygon_side_edges() as above, combinatorially (two nodes may
//   have equal positions, the rotation is the order of the triangles around the node).
//   Errors: ERROR_NON_FINITE_COORDINATES; ERROR_DEGENERATE_BORDER (fewer than 3 points, a repeated
//   consecutive point, a collinear vertex without allow_flat_border_vertices); ERROR_WRONG_PARAMETER
//   (triangles not as described: count, index range, a non-positive triangle, a border edge missing
//   or in both directions, a diagonal not shared by exactly two triangles, a node whose triangles do
//   not form one fan).
//   Complexity: O(n log n): a sort of the half-edges, then as above.
//
// polygon_side_edges(partition): per polygon side, the interior edge along it or -1 (border edge).
//
// place_path_vertices(partition, border, targets, edge, fractions, positions [, sides])
//   The uv positions of the k vertices of the path traced for partition.edges[edge], from node
//   a = edges[edge][0] (point pa) to node b = edges[edge][1] (point pb); fractions[i] is the 3D
//   arc-length fraction of the i-th path vertex from a (finite, nondecreasing, in [0, 1]; otherwise
//   ERROR_WRONG_PARAMETER). When they are not strictly increasing inside (0, 1) (repeated 3D points,
//   zero-length edges) they are blended with uniform spacing, t' = (1 - 2^-10) t + 2^-10 u_i.
//   Guarantees (all certified exactly before returning OK):
//    - exact number types (Gmpq, Lazy_exact_nt, rationals): positions[i] = pa + t_i (pb - pa) exactly:
//      on the open segment, distinct, strictly increasing along it;
//    - Gmpfr: the same exact point (a dyadic rational), stored with as many bits as it needs;
//    - float/double: the coordinate along the segment's dominant axis (x when |dx| >= |dy|) is
//      strictly monotone from pa to pb, strictly between theirs (nudged to the next representable
//      values when rounding makes two equal or reaches an endpoint); the other coordinate is the
//      representable value nearest to the exact segment point at that abscissa (exactly on the
//      segment whenever that value is representable) or, if that point falls outside the adjacent
//      polygon on its side, the other neighbour. Hence: the polyline pa, positions..., pb is simple
//      (monotone), and every vertex is exactly on the open segment (side COLLINEAR) or strictly inside
//      the polygon on its side (LEFT_TURN: edge_polygons[edge][0], RIGHT_TURN: edge_polygons[edge][1]);
//      so the polyline lies in the interior of the union of the two polygons except its ends, and
//      replacing the edge by the polyline gives two simple polygons A', B' that tile the same union.
//      Every vertex is within one ulp (of the minor coordinate) of its exact segment point, but A' and
//      B' are in general not exactly convex: a vertex strictly inside A is a notch (reflex corner) of
//      A' and a tiny spike of B', and a vertex on the segment can be reflex for either one when its
//      neighbours are off it. `sides` says where each vertex is. With generic double endpoints
//      almost no vertex is exactly on the segment (0 of 8672 in the tests), so the patch embedding
//      must accept such nearly convex borders. Failure (ERROR_PATH_TRACING_FAILED): fewer
//      representable values than path vertices along the segment, or both roundings of a vertex
//      outside both polygons (polygons thinner than one ulp there).
//   Cost: O(k log(|A| + |B|) + |A| + |B|) for the two adjacent polygons A, B.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/internal/border_polygon.h>
#include <CGAL/Progressive_embedding/internal/certification_kernel.h>
#include <CGAL/Progressive_embedding/internal/exact_predicates.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpfr.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/enum.h>

#include <mpfr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

/// The sine of the smallest turn at a partition corner next to a path (2^-20): a corner that turns by
/// less is flat up to the rounding of the path vertices placed next to it (see partition_domain).
inline double corner_turn_margin() { return 0x1p-20; }

/// Whether a corner turns left by a sine above corner_turn_margin(), in double precision from its two
/// edge vectors: (ax, ay) into the corner, (bx, by) out of it.
inline bool turns_left_by_margin(double ax, double ay, double bx, double by)
{
  return ax * by - ay * bx > corner_turn_margin() * std::sqrt(ax * ax + ay * ay) * std::sqrt(bx * bx + by * by);
}

/// Whether a corner is flat up to corner_turn_margin(): it goes on forwards and the sine of its turn, either
/// way, is below the margin (same edge vectors as turns_left_by_margin()).
inline bool flat_by_margin(double ax, double ay, double bx, double by)
{
  return ax * bx + ay * by > 0 &&
         std::abs(ax * by - ay * bx) < corner_turn_margin() * std::sqrt(ax * ax + ay * ay) * std::sqrt(bx * bx + by * by);
}

/// The target domain cut into convex polygons (see the comment at the top of this file).
/// Nodes 0..nb-1 are the border points in the given order, nodes nb..nb+nt-1 the targets in the
/// given order. Every geometric order below is counterclockwise in the plane, whatever the
/// orientation of the given border.
struct Domain_partition
{
  /// nb: nodes 0..nb-1 are the border points, in the given order
  std::size_t number_of_border_nodes = 0;
  /// nt: nodes nb..nb+nt-1 are the targets, in the given order
  std::size_t number_of_targets = 0;
  /// `true` when the given border runs counterclockwise
  bool counterclockwise = true;
  /// interior edges (to be traced), each once, as node pairs with edges[i][0] < edges[i][1], sorted
  std::vector<std::array<std::size_t, 2> > edges;
  /// each polygon's nodes, counterclockwise, starting from its smallest node (polygon order:
  /// deterministic for a given input, otherwise unspecified)
  std::vector<std::vector<std::size_t> > polygons;
  /// the polygon on the left / on the right of edges[i] directed from edges[i][0] to edges[i][1]
  /// (both always exist: interior edges separate two polygons)
  std::vector<std::array<std::ptrdiff_t, 2> > edge_polygons;
  /// per node, its incident interior edges (indices into `edges`) in counterclockwise order around it.
  /// For a border node: from the one next to the border edge towards the border node that follows
  /// it counterclockwise (node i+1 when `counterclockwise`, i-1 otherwise) to the one next to the
  /// border edge towards the preceding node, i.e. across the inside of the domain. For a target the
  /// cyclic order starts anywhere.
  std::vector<std::vector<std::size_t> > rotation;

  std::size_t number_of_nodes() const { return number_of_border_nodes + number_of_targets; }
  bool is_target(std::size_t node) const { return node >= number_of_border_nodes; }
  /// the other end of edges[e] seen from `node`
  std::size_t opposite(std::size_t e, std::size_t node) const { return edges[e][0] == node ? edges[e][1] : edges[e][0]; }
};

/// Order in which the greedy merge considers the interior edges of the triangulation.
enum class Domain_merge_order
{
  LONGEST_FIRST,        ///< longest first (fewest edges left in the measurements)
  SHORTEST_FIRST,       ///< shortest first (for comparisons)
  TRIANGULATION_ORDER   ///< the triangulation's own edge order (for comparisons)
};

/// Options of `partition_domain()`.
struct Domain_partition_options
{
  Domain_merge_order order = Domain_merge_order::LONGEST_FIRST;
  /// accept a convex border with flat (180 degree) vertices; the polygons are then convex with their
  /// flat corners only at flat border nodes (default: strictly convex border required)
  bool allow_flat_border_vertices = false;
  /// accept a simple border polygon that is not convex (checked exactly); a convex border gives the
  /// same partition as without this option (default: a convex border required)
  bool allow_non_convex_border = false;
};

namespace domain_detail {

template <class Point_2>
struct Node_points
{
  const std::vector<Point_2>& border;
  const std::vector<Point_2>& targets;
  const Point_2& operator()(std::size_t n) const
  { return n < border.size() ? border[n] : targets[n - border.size()]; }
};

// `q` strictly inside the convex polygon P(0), ..., P(m-1) (counterclockwise; P(0) a strict corner;
// other vertices may be flat). Binary search in the fan from P(0): O(log m) exact orientations.
template <class Point_2, class Vertex>
bool strictly_inside_convex(std::size_t m, const Vertex& P, const Point_2& q)
{
  if(m < 3) return false;
  const Point_2& p0 = P(0);
  if(exact_orientation(p0, P(1), q) != CGAL::LEFT_TURN) return false;
  if(exact_orientation(p0, P(m - 1), q) != CGAL::RIGHT_TURN) return false;
  // invariant: orientation(p0, P(lo), q) != RIGHT_TURN, orientation(p0, P(hi), q) == RIGHT_TURN
  std::size_t lo = 1, hi = m - 1;
  while(hi - lo > 1) // halves each time: bounded by log2(m) steps
  {
    const std::size_t mid = lo + (hi - lo) / 2;
    if(exact_orientation(p0, P(mid), q) == CGAL::RIGHT_TURN) hi = mid;
    else lo = mid;
  }
  return exact_orientation(P(lo), P(hi), q) == CGAL::LEFT_TURN;
}

// Node coordinates in double, all scaled by one power of two so that the largest is about 1: the
// edge lengths that order the merge do not overflow or underflow whatever the magnitude, and the
// order (hence the partition) is the same after a scaling of the input by a power of two.
template <class Point_2, class Points>
std::vector<std::array<double, 2> > scaled_coordinates(const Points& point, std::size_t nn)
{
  typedef typename Point_ft<Point_2>::type FT;
  std::vector<std::array<double, 2> > c(nn);
  if constexpr(std::is_floating_point<FT>::value)
  {
    std::vector<double> v;
    v.reserve(2 * nn);
    for(std::size_t n = 0; n < nn; ++n) { v.push_back(double(point(n).x())); v.push_back(double(point(n).y())); }
    const long s = unit_shift(v);
    for(std::size_t n = 0; n < nn; ++n)
      c[n] = {{ std::ldexp(v[2 * n], int(s)), std::ldexp(v[2 * n + 1], int(s)) }};
  }
  else
  {
    std::vector<CGAL::Gmpq> v;
    v.reserve(2 * nn);
    for(std::size_t n = 0; n < nn; ++n) { v.push_back(to_rational(point(n).x())); v.push_back(to_rational(point(n).y())); }
    const long s = unit_shift(v);
    for(std::size_t n = 0; n < nn; ++n)
      c[n] = {{ CGAL::to_double(times_power_of_two(v[2 * n], s)), CGAL::to_double(times_power_of_two(v[2 * n + 1], s)) }};
  }
  return c;
}

struct Union_find
{
  std::vector<std::size_t> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t(0)); }
  std::size_t find(std::size_t x)
  {
    std::size_t r = x;
    while(parent[r] != r) r = parent[r];          // bounded: parent chains are acyclic
    while(parent[x] != r) { const std::size_t n = parent[x]; parent[x] = r; x = n; }
    return r;
  }
  void unite(std::size_t a, std::size_t b) { parent[find(b)] = find(a); }
};

// The greedy merge and the output, shared by every kind of domain. The faces are given as half-edge
// cycles: half-edge h runs from from[h] to to[h] with its face on the left, next/prev in its face,
// twin[h] the opposite half-edge or `none` on the border (a border half-edge runs from a border node
// to its counterclockwise successor). flat[u]: border node u has a total angle of exactly 180 degrees.
// Every polygon corner is below 180 degrees (or 180 at a flat node covering it wholly), so the union
// of two polygons across an edge turns at its two ends by the sum of the two corners there (below 360
// degrees): the exact orientation of the union's corner decides whether it stays strictly convex,
// without any global test. This holds for an immersed disk as well as for a planar one.
template <class Point_2, class Points>
Error_code merge_into_convex_polygons(const Points& point, std::size_t nb, std::size_t nt, bool ccw,
                                      const std::vector<char>& flat,
                                      const std::vector<std::size_t>& from, const std::vector<std::size_t>& to,
                                      std::vector<std::size_t>& next, std::vector<std::size_t>& prev,
                                      const std::vector<std::size_t>& twin,
                                      const Domain_partition_options& options, Domain_partition& out)
{
  const std::size_t nn = nb + nt, nh = from.size(), nf = nh / 3;
  const std::size_t none = std::size_t(-1);

  // ---- greedy merge ---------------------------------------------------------------------------------
  std::vector<std::size_t> candidates;
  candidates.reserve(nh / 2);
  for(std::size_t h = 0; h < nh; ++h)
    if(twin[h] != none && h < twin[h]) candidates.push_back(h);
  // approximate coordinates: for the merge order and the margin of corners next to paths (below)
  const std::vector<std::array<double, 2> > c = domain_detail::scaled_coordinates<Point_2>(point, nn);
  if(options.order != Domain_merge_order::TRIANGULATION_ORDER)
  {
    // lengths for ordering only (an approximation is fine: the order is a heuristic)
    std::vector<double> len(nh, 0);
    for(std::size_t h : candidates)
    {
      const double dx = c[to[h]][0] - c[from[h]][0], dy = c[to[h]][1] - c[from[h]][1];
      len[h] = dx * dx + dy * dy;
    }
    const bool longest = options.order == Domain_merge_order::LONGEST_FIRST;
    std::stable_sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) {
      return longest ? len[a] > len[b] : len[a] < len[b]; });
  }

  // strictly convex at node u between incoming p->u and outgoing u->q; flat allowed at flat border nodes.
  // A corner between a border edge and an interior edge (`at_path`: the edge is traced, its vertices
  // placed on the segment only up to one ulp in floating point) must moreover turn by more than the
  // margin: a corner convex by less, e.g. an inner corner of a strip with a border point of the
  // opposite side almost on the line of its other side, lets the rounded path vertices fall on (or
  // beyond) the line of the border side, and the mesh edges between them and that side's vertices
  // become flat chords of the patch (no valid map). Refusing the merge keeps the two pieces, whose corners there are far from
  // 180 degrees. In double on the scaled coordinates: a heuristic choice of merges only; convexity is
  // still decided by the exact orientation. Between two interior edges no margin: such a corner
  // nearly flat comes with a sliver (e.g. a target within rounding of the border), whose refusal
  // would only keep shorter edges.
  auto robust_turn = [&](std::size_t p, std::size_t u, std::size_t q) {
    return turns_left_by_margin(c[u][0] - c[p][0], c[u][1] - c[p][1], c[q][0] - c[u][0], c[q][1] - c[u][1]);
  };
  auto convex_corner = [&](std::size_t p, std::size_t u, std::size_t q, bool at_path) {
    const CGAL::Orientation o = exact_orientation(point(p), point(u), point(q));
    if(o == CGAL::LEFT_TURN) return !at_path || robust_turn(p, u, q);
    return o == CGAL::COLLINEAR && u < nb && flat[u] && p != q && !at_path;
  };
  domain_detail::Union_find faces(nf);
  std::vector<char> alive(nh, 1);
  for(std::size_t h : candidates)
  {
    const std::size_t t = twin[h];
    const std::size_t A = faces.find(h / 3), B = faces.find(t / 3);
    if(A == B) continue; // cannot happen for convex polygons; never merge a polygon with itself
    const std::size_t u = from[h], v = to[h];
    // h = u->v in A, t = v->u in B; the union turns at u from prev(h) to next(t), at v from prev(t) to next(h)
    if(!convex_corner(from[prev[h]], u, to[next[t]], (twin[prev[h]] == none) != (twin[next[t]] == none))) continue;
    if(!convex_corner(from[prev[t]], v, to[next[h]], (twin[prev[t]] == none) != (twin[next[h]] == none))) continue;
    next[prev[h]] = next[t]; prev[next[t]] = prev[h];
    next[prev[t]] = next[h]; prev[next[h]] = prev[t];
    alive[h] = alive[t] = 0;
    faces.unite(A, B);
  }

  // ---- output --------------------------------------------------------------------------------------
  Domain_partition result;
  result.number_of_border_nodes = nb;
  result.number_of_targets = nt;
  result.counterclockwise = ccw;

  std::vector<std::size_t> polygon_of(nh, none);
  for(std::size_t h0 = 0; h0 < nh; ++h0)
  {
    if(!alive[h0] || polygon_of[h0] != none) continue;
    const std::size_t pid = result.polygons.size();
    std::vector<std::size_t> poly;
    std::size_t h = h0;
    for(std::size_t step = 0; step < nh; ++step) // a cycle has at most nh half-edges
    {
      polygon_of[h] = pid;
      poly.push_back(from[h]);
      h = next[h];
      if(h == h0) break;
    }
    if(h != h0) return ERROR_DEGENERATE_BORDER; // broken cycle: cannot happen
    std::rotate(poly.begin(), std::min_element(poly.begin(), poly.end()), poly.end());
    result.polygons.push_back(std::move(poly));
  }

  std::vector<std::size_t> interior;
  for(std::size_t h = 0; h < nh; ++h)
    if(alive[h] && twin[h] != none && from[h] < to[h]) interior.push_back(h);
  std::sort(interior.begin(), interior.end(), [&](std::size_t a, std::size_t b) {
    return std::make_pair(from[a], to[a]) < std::make_pair(from[b], to[b]); });
  std::vector<std::size_t> edge_of(nh, none);
  for(std::size_t h : interior)
  {
    edge_of[h] = edge_of[twin[h]] = result.edges.size();
    result.edges.push_back({{ from[h], to[h] }});
    // a half-edge has its polygon on its left
    result.edge_polygons.push_back({{ std::ptrdiff_t(polygon_of[h]), std::ptrdiff_t(polygon_of[twin[h]]) }});
  }

  // rotations: around u, the half-edge after u->v counterclockwise is twin(prev(u->v))
  std::vector<std::size_t> start(nn, none);
  for(std::size_t h = 0; h < nh; ++h)
  {
    if(!alive[h]) continue;
    const std::size_t u = from[h];
    if(twin[h] == none) { if(u < nb) start[u] = h; } // border half-edge u -> counterclockwise successor
    else if(start[u] == none) start[u] = h;
  }
  result.rotation.assign(nn, std::vector<std::size_t>());
  for(std::size_t u = 0; u < nn; ++u)
  {
    const std::size_t h0 = start[u];
    if(h0 == none) return ERROR_DEGENERATE_BORDER; // every node keeps an edge: cannot happen
    std::size_t h = h0;
    for(std::size_t step = 0; step < nh; ++step)
    {
      if(twin[h] != none) result.rotation[u].push_back(edge_of[h]);
      const std::size_t p = prev[h];
      if(twin[p] == none) break;   // reached the border half-edge into u: done (border node)
      h = twin[p];
      if(h == h0) break;           // full turn (target)
    }
  }

  out = std::move(result);
  return OK;
}


// The non-convex case of partition_domain() (options.allow_non_convex_border): `border` is known to be
// finite, with at least 3 points, no repeated consecutive point and not all collinear. See the top of
// this file for the contract.
template <class Point_2>
Error_code partition_simple_domain(const std::vector<Point_2>& border, const std::vector<Point_2>& targets,
                                   Domain_partition& out, const Domain_partition_options& options)
{
  typedef typename Point_ft<Point_2>::type FT;
  typedef Certification_kernel<FT> CKS;
  typedef typename CKS::Kernel CK;
  const std::size_t nb = border.size(), nt = targets.size(), nn = nb + nt;
  const Node_points<Point_2> point{ border, targets };
  const std::size_t none = std::size_t(-1);

  // flat vertices: collinear with the next point beyond the vertex from the previous one (the other
  // collinear case, a spike, makes two edges overlap: not simple, refused below)
  std::vector<char> flat(nb, 0);
  bool any_flat = false;
  for(std::size_t i = 0; i < nb; ++i)
  {
    const Point_2& a = border[(i + nb - 1) % nb];
    const Point_2& c = border[(i + 1) % nb];
    flat[i] = exact_orientation(a, border[i], c) == CGAL::COLLINEAR
              && exact_compare_xy(a, border[i]) == exact_compare_xy(border[i], c);
    if(flat[i]) any_flat = true;
  }
  if(any_flat && !options.allow_flat_border_vertices) return ERROR_DEGENERATE_BORDER;

  // simplicity, exactly (no two edges meet except consecutive ones at their common vertex): there is
  // no dedicated code, and a non-simple border is in particular not the border of a convex domain
  if(count_polygon_self_intersections(border, Exact_orientation_2<Point_2>(), 1) != 0)
    return ERROR_NON_CONVEX_BORDER;

  // orientation: the lexicographically smallest vertex is a strict corner of a simple polygon
  std::size_t lowest = 0;
  for(std::size_t i = 1; i < nb; ++i)
    if(exact_compare_xy(border[i], border[lowest]) == CGAL::SMALLER) lowest = i;
  const CGAL::Orientation lo = exact_orientation(border[(lowest + nb - 1) % nb], border[lowest], border[(lowest + 1) % nb]);
  if(lo == CGAL::COLLINEAR) return ERROR_DEGENERATE_BORDER; // cannot happen for a simple polygon
  const bool ccw = lo == CGAL::LEFT_TURN;

  // ---- constrained Delaunay triangulation of the border, then the targets ----------------------
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, CK>           Vb;
  typedef CGAL::Triangulation_face_base_with_info_2<std::size_t, CK>             Fbb;
  typedef CGAL::Constrained_triangulation_face_base_2<CK, Fbb>                   Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb>                           Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<CK, Tds, CGAL::Exact_predicates_tag> CDT;
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;

  CDT cdt;
  {
    std::vector<std::pair<typename CK::Point_2, std::size_t> > pts;
    pts.reserve(nb);
    for(std::size_t n = 0; n < nb; ++n) pts.emplace_back(CKS::convert(border[n]), n);
    cdt.insert(pts.begin(), pts.end()); // spatially sorted insertion
  }
  if(cdt.number_of_vertices() != nb || cdt.dimension() != 2)
    return ERROR_DEGENERATE_BORDER; // cannot happen for a simple polygon (distinct, not collinear)
  std::vector<Vertex_handle> vh(nn);
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) vh[v->info()] = v;
  for(std::size_t i = 0; i < nb; ++i) cdt.insert_constraint(vh[i], vh[(i + 1) % nb]);
  if(cdt.number_of_vertices() != nb) return ERROR_DEGENERATE_BORDER; // simple: no constraint crossed another
  // targets one by one: an existing vertex comes back for a point already there (a border point or an
  // earlier target); a target on a border edge splits its constraint
  std::vector<Vertex_handle> target_vertex(nt);
  bool duplicate = false;
  {
    Face_handle hint;
    for(std::size_t t = 0; t < nt; ++t)
    {
      const std::size_t before = cdt.number_of_vertices();
      const Vertex_handle v = cdt.insert(CKS::convert(targets[t]), hint);
      if(cdt.number_of_vertices() == before + 1) { v->info() = nb + t; vh[nb + t] = v; }
      else if(v->info() >= nb) duplicate = true; // equal to an earlier target
      target_vertex[t] = v;
      hint = v->face();
    }
  }

  // inside faces: not reachable from the infinite face without crossing the border (the outside of
  // a simple polygon is connected); each face is pushed once, so the fill is bounded
  for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = none;
  const std::size_t outside = none - 1;
  {
    std::vector<Face_handle> stack(1, cdt.infinite_face());
    cdt.infinite_face()->info() = outside;
    while(!stack.empty())
    {
      const Face_handle f = stack.back();
      stack.pop_back();
      for(int i = 0; i < 3; ++i)
      {
        const Face_handle g = f->neighbor(i);
        if(g->info() == outside || f->is_constrained(i)) continue;
        g->info() = outside;
        stack.push_back(g);
      }
    }
  }

  // targets strictly inside: not a border point, not on a border edge, in an inside face
  for(std::size_t t = 0; t < nt; ++t)
  {
    const Vertex_handle v = target_vertex[t];
    if(v->info() < nb || cdt.are_there_incident_constraints(v)) return ERROR_CONSTRAINT_OUTSIDE_DOMAIN;
    if(v->face()->info() == outside) return ERROR_CONSTRAINT_OUTSIDE_DOMAIN; // no constraint at v: all its faces agree
  }
  if(duplicate) return ERROR_DUPLICATE_CONSTRAINT;
  if(cdt.number_of_vertices() != nn) return ERROR_DEGENERATE_BORDER; // cannot happen after the checks above

  // ---- half-edges of the inside triangles -----------------------------------------------------------
  std::size_t nf = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if(f->info() != outside) f->info() = nf++;
  const std::size_t nh = 3 * nf;
  std::vector<std::size_t> from(nh), to(nh), next(nh), prev(nh), twin(nh, none);
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if(f->info() == outside) continue;
    const std::size_t id = f->info();
    for(int i = 0; i < 3; ++i)
    {
      const std::size_t h = 3 * id + i;
      from[h] = f->vertex(CDT::ccw(i))->info();
      to[h] = f->vertex(CDT::cw(i))->info();
      next[h] = 3 * id + (i + 1) % 3;
      prev[h] = 3 * id + (i + 2) % 3;
      const auto g = f->neighbor(i);
      if(!f->is_constrained(i) && !cdt.is_infinite(g) && g->info() != outside) twin[h] = 3 * g->info() + g->index(f);
    }
  }
  return merge_into_convex_polygons<Point_2>(point, nb, nt, ccw, flat, from, to, next, prev, twin, options, out);
}

} // namespace domain_detail

/// Cuts the domain bounded by `border` into convex polygons whose corners are border points and
/// targets, every target a corner (see the top of this file for the full contract).
/// \tparam Point_2 a point of a CGAL kernel whose FT is supported (double, Gmpq, Gmpfr, ...)
template <class Point_2>
Error_code partition_domain(const std::vector<Point_2>& border, const std::vector<Point_2>& targets,
                            Domain_partition& out,
                            const Domain_partition_options& options = Domain_partition_options())
{
  typedef typename Point_ft<Point_2>::type FT;
  static_assert(Check_number_type<FT>::value, "");
  typedef Certification_kernel<FT> CKS;
  typedef typename CKS::Kernel CK;

  const std::size_t nb = border.size(), nt = targets.size(), nn = nb + nt;
  const domain_detail::Node_points<Point_2> point{ border, targets };

  // ---- input checks --------------------------------------------------------------------------
  for(std::size_t n = 0; n < nn; ++n)
    if(!is_finite_ft(point(n).x()) || !is_finite_ft(point(n).y()))
      return ERROR_NON_FINITE_COORDINATES;

  int orientation = 0;
  const Polygon_class pc = classify_convex_polygon(border, Exact_orientation_2<Point_2>(), orientation);
  if(pc == Polygon_class::DEGENERATE) return ERROR_DEGENERATE_BORDER;
  if(pc == Polygon_class::NON_CONVEX)
  {
    if(!options.allow_non_convex_border) return ERROR_NON_CONVEX_BORDER;
    return domain_detail::partition_simple_domain(border, targets, out, options);
  }
  if(pc == Polygon_class::CONVEX && !options.allow_flat_border_vertices) return ERROR_DEGENERATE_BORDER;
  const bool ccw = orientation > 0;

  // flat border vertices (only with allow_flat_border_vertices)
  std::vector<char> flat(nb, 0);
  std::size_t corner0 = nb;
  for(std::size_t i = 0; i < nb; ++i)
  {
    flat[i] = exact_orientation(border[(i + nb - 1) % nb], border[i], border[(i + 1) % nb]) == CGAL::COLLINEAR;
    if(!flat[i] && corner0 == nb) corner0 = i;
  }
  if(corner0 == nb) return ERROR_DEGENERATE_BORDER; // classified degenerate above; kept for safety

  // targets strictly inside: fan search from a strict corner, counterclockwise
  auto ccw_border = [&](std::size_t k) -> const Point_2& {
    return ccw ? border[(corner0 + k) % nb] : border[(corner0 + nb - k % nb) % nb];
  };
  for(std::size_t t = 0; t < nt; ++t)
    if(!domain_detail::strictly_inside_convex(nb, ccw_border, targets[t]))
      return ERROR_CONSTRAINT_OUTSIDE_DOMAIN;

  {
    std::vector<std::size_t> order(nt);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return exact_compare_xy(targets[a], targets[b]) == CGAL::SMALLER; });
    for(std::size_t k = 1; k < nt; ++k)
      if(exact_compare_xy(targets[order[k - 1]], targets[order[k]]) == CGAL::EQUAL)
        return ERROR_DUPLICATE_CONSTRAINT;
  }

  // ---- constrained Delaunay triangulation -------------------------------------------------------
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, CK>           Vb;
  typedef CGAL::Triangulation_face_base_with_info_2<std::size_t, CK>             Fbb;
  typedef CGAL::Constrained_triangulation_face_base_2<CK, Fbb>                   Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb>                           Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<CK, Tds, CGAL::Exact_predicates_tag> CDT;
  typedef typename CDT::Vertex_handle Vertex_handle;

  CDT cdt;
  {
    std::vector<std::pair<typename CK::Point_2, std::size_t> > pts;
    pts.reserve(nn);
    for(std::size_t n = 0; n < nn; ++n) pts.emplace_back(CKS::convert(point(n)), n);
    cdt.insert(pts.begin(), pts.end()); // spatially sorted insertion
  }
  if(cdt.number_of_vertices() != nn || cdt.dimension() != 2)
    return ERROR_DEGENERATE_BORDER; // cannot happen after the checks above (distinct, not collinear)
  std::vector<Vertex_handle> vh(nn);
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) vh[v->info()] = v;
  for(std::size_t i = 0; i < nb; ++i) cdt.insert_constraint(vh[i], vh[(i + 1) % nb]);
  if(cdt.number_of_vertices() != nn) return ERROR_DEGENERATE_BORDER; // no constraint crossed anything

  // ---- half-edges of the triangles ---------------------------------------------------------------
  // half-edge 3f+i of face f runs counterclockwise along the edge opposite to vertex i
  std::size_t nf = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) f->info() = nf++;
  const std::size_t nh = 3 * nf;
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> from(nh), to(nh), next(nh), prev(nh), twin(nh, none);
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    const std::size_t id = f->info();
    for(int i = 0; i < 3; ++i)
    {
      const std::size_t h = 3 * id + i;
      from[h] = f->vertex(CDT::ccw(i))->info();
      to[h] = f->vertex(CDT::cw(i))->info();
      next[h] = 3 * id + (i + 1) % 3;
      prev[h] = 3 * id + (i + 2) % 3;
      const auto g = f->neighbor(i);
      if(!cdt.is_infinite(g) && !f->is_constrained(i)) twin[h] = 3 * g->info() + g->index(f);
    }
  }

  return domain_detail::merge_into_convex_polygons<Point_2>(point, nb, nt, ccw, flat, from, to, next, prev, twin,
                                                            options, out);
}

/// The partition of a convex, counterclockwise `border` with `targets` merged from a given triangulation of
/// them (nodes numbered as partition_domain() numbers them; `triangles` counterclockwise, tiling the domain),
/// by the same greedy merge as partition_domain(). Each triangle is checked strictly counterclockwise exactly
/// first: ERROR_DEGENERATE_BORDER when one is not (the caller's triangulation is not valid at these points).
/// \param out written on success only
template <class Point_2>
Error_code merge_triangulation(const std::vector<Point_2>& border, const std::vector<Point_2>& targets,
                               const std::vector<std::array<std::size_t, 3> >& triangles, Domain_partition& out,
                               const Domain_partition_options& options = Domain_partition_options())
{
  const std::size_t nb = border.size(), nt = targets.size(), nn = nb + nt;
  const domain_detail::Node_points<Point_2> point{ border, targets };
  // half-edge 3f+i of triangle f runs counterclockwise along the edge opposite its corner i
  const std::size_t nf = triangles.size(), nh = 3 * nf, none = std::size_t(-1);
  std::vector<std::size_t> from(nh), to(nh), next(nh), prev(nh), twin(nh, none);
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> half;
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = triangles[f];
    if(t[0] >= nn || t[1] >= nn || t[2] >= nn) return ERROR_DEGENERATE_BORDER;
    if(exact_orientation(point(t[0]), point(t[1]), point(t[2])) != CGAL::LEFT_TURN) return ERROR_DEGENERATE_BORDER;
    for(std::size_t i = 0; i < 3; ++i)
    {
      const std::size_t h = 3 * f + i;
      from[h] = t[(i + 1) % 3]; to[h] = t[(i + 2) % 3];
      next[h] = 3 * f + (i + 1) % 3; prev[h] = 3 * f + (i + 2) % 3;
      half[std::make_pair(from[h], to[h])] = h;
    }
  }
  for(std::size_t h = 0; h < nh; ++h)
  {
    const auto it = half.find(std::make_pair(to[h], from[h]));
    if(it != half.end()) twin[h] = it->second;
  }
  std::vector<char> flat(nb, 0);
  for(std::size_t i = 0; i < nb; ++i)
    flat[i] = exact_orientation(border[(i + nb - 1) % nb], border[i], border[(i + 1) % nb]) == CGAL::COLLINEAR;
  return domain_detail::merge_into_convex_polygons<Point_2>(point, nb, nt, true, flat, from, to, next, prev, twin, options, out);
}

/// Cuts the immersed disk bounded by the weakly self-overlapping polygon `border` into strictly convex
/// polygons, from a triangulation of it (see the top of this file for the full contract).
/// \tparam Point_2 a point of a CGAL kernel whose FT is supported (double, Gmpq, Gmpfr, ...)
/// \param border the polygon, either orientation
/// \param triangles its triangulation as an immersed disk, as `triangulate_self_overlapping_polygon_2()`
///        writes it: `border.size() - 2` index triples, each strictly counterclockwise
/// \param out written on success only; it has no target (`number_of_targets == 0`)
/// \param options the merge order, and whether flat border vertices are accepted
template <class Point_2>
Error_code partition_immersed_domain(const std::vector<Point_2>& border,
                                     const std::vector<std::array<std::size_t, 3> >& triangles,
                                     Domain_partition& out,
                                     const Domain_partition_options& options = Domain_partition_options())
{
  typedef typename Point_ft<Point_2>::type FT;
  static_assert(Check_number_type<FT>::value, "");
  const std::size_t nb = border.size();
  const std::vector<Point_2> no_targets;
  const domain_detail::Node_points<Point_2> point{ border, no_targets };
  const std::size_t none = std::size_t(-1);

  // ---- input checks --------------------------------------------------------------------------
  for(std::size_t n = 0; n < nb; ++n)
    if(!is_finite_ft(border[n].x()) || !is_finite_ft(border[n].y()))
      return ERROR_NON_FINITE_COORDINATES;
  if(nb < 3) return ERROR_DEGENERATE_BORDER;
  for(std::size_t i = 0; i < nb; ++i)
    if(exact_compare_xy(border[i], border[(i + 1) % nb]) == CGAL::EQUAL) return ERROR_DEGENERATE_BORDER;
  if(triangles.size() != nb - 2) return ERROR_WRONG_PARAMETER;
  for(const std::array<std::size_t, 3>& t : triangles)
  {
    if(t[0] >= nb || t[1] >= nb || t[2] >= nb || t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      return ERROR_WRONG_PARAMETER;
    if(exact_orientation(border[t[0]], border[t[1]], border[t[2]]) != CGAL::LEFT_TURN)
      return ERROR_WRONG_PARAMETER;
  }

  // ---- half-edges, glued by their index pairs (the geometry overlaps: no point location) -----------
  const std::size_t nf = triangles.size(), nh = 3 * nf;
  std::vector<std::size_t> from(nh), to(nh), next(nh), prev(nh), twin(nh, none);
  for(std::size_t f = 0; f < nf; ++f)
    for(std::size_t i = 0; i < 3; ++i)
    {
      const std::size_t h = 3 * f + i;
      from[h] = triangles[f][i];
      to[h] = triangles[f][(i + 1) % 3];
      next[h] = 3 * f + (i + 1) % 3;
      prev[h] = 3 * f + (i + 2) % 3;
    }
  std::vector<std::size_t> order(nh);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::make_pair(from[a], to[a]) < std::make_pair(from[b], to[b]); });
  auto find_half_edge = [&](std::size_t u, std::size_t v) {
    const auto it = std::lower_bound(order.begin(), order.end(), std::make_pair(u, v),
      [&](std::size_t h, const std::pair<std::size_t, std::size_t>& key) { return std::make_pair(from[h], to[h]) < key; });
    return (it != order.end() && from[*it] == u && to[*it] == v) ? *it : none;
  };
  for(std::size_t k = 1; k < nh; ++k)
    if(from[order[k]] == from[order[k - 1]] && to[order[k]] == to[order[k - 1]]) return ERROR_WRONG_PARAMETER; // a repeated half-edge
  // the border's orientation: its edges are the triangles' sides in one direction only
  const bool ccw = find_half_edge(0, 1) != none;
  std::vector<char> border_half_edge(nh, 0);
  for(std::size_t i = 0; i < nb; ++i)
  {
    const std::size_t j = (i + 1) % nb;
    const std::size_t h = ccw ? find_half_edge(i, j) : find_half_edge(j, i);
    if(h == none || (ccw ? find_half_edge(j, i) : find_half_edge(i, j)) != none) return ERROR_WRONG_PARAMETER;
    border_half_edge[h] = 1;
  }
  for(std::size_t h = 0; h < nh; ++h)
  {
    if(border_half_edge[h]) continue;
    twin[h] = find_half_edge(to[h], from[h]);
    if(twin[h] == none) return ERROR_WRONG_PARAMETER; // a diagonal must join exactly two triangles
  }
  // every node's triangles form one fan from its border half-edge (around u, the half-edge after h
  // counterclockwise is twin(prev(h))): with n - 2 triangles and every node on the border, the
  // triangles then form a disk bordered by the polygon (Euler characteristic 1)
  std::vector<std::size_t> out_border(nb, none);
  for(std::size_t h = 0; h < nh; ++h) if(border_half_edge[h]) out_border[from[h]] = h;
  std::size_t corners = 0;
  std::vector<char> flat(nb, 0);
  for(std::size_t u = 0; u < nb; ++u)
  {
    const std::size_t h0 = out_border[u];
    const std::size_t n1 = to[h0], n0 = ccw ? (u + nb - 1) % nb : (u + 1) % nb;
    // flat: the total angle at u is exactly 180 degrees, i.e. collinear and every fan neighbour
    // strictly left of u -> n1 (a total angle of 180 + 360 k, k >= 1, has a fan direction in
    // [180, 360] since each step is below 180; 0 or 360 would be a reversal)
    const bool collinear = exact_orientation(border[n0], border[u], border[n1]) == CGAL::COLLINEAR;
    bool all_left = true;
    std::size_t h = h0, step = 0;
    for(; step < nh; ++step)
    {
      ++corners;
      const std::size_t p = prev[h];
      if(border_half_edge[p]) break; // the border half-edge into u: the fan is complete
      h = twin[p];
      if(h == h0) return ERROR_WRONG_PARAMETER; // a closed fan: u would be an interior node
      if(exact_orientation(border[u], border[n1], border[to[h]]) != CGAL::LEFT_TURN) all_left = false;
    }
    if(step == nh) return ERROR_WRONG_PARAMETER;
    if(collinear)
    {
      if(!options.allow_flat_border_vertices) return ERROR_DEGENERATE_BORDER;
      flat[u] = all_left;
    }
  }
  if(corners != nh) return ERROR_WRONG_PARAMETER; // some triangles are not in the fans: not a disk

  Domain_partition result;
  const Error_code ec = domain_detail::merge_into_convex_polygons<Point_2>(point, nb, 0, ccw, flat, from, to, next, prev,
                                                                          twin, options, result);
  if(ec != OK) return ec;

  // consistency: V - E + F = 1 with the border edges counted, every polygon strictly convex (flat
  // corners only at flat nodes)
  if(std::ptrdiff_t(nb) - std::ptrdiff_t(nb + result.edges.size()) + std::ptrdiff_t(result.polygons.size()) != 1)
    return ERROR_WRONG_PARAMETER;
  for(const std::vector<std::size_t>& poly : result.polygons)
    for(std::size_t k = 0, m = poly.size(); k < m; ++k)
    {
      const CGAL::Orientation o = exact_orientation(border[poly[(k + m - 1) % m]], border[poly[k]], border[poly[(k + 1) % m]]);
      if(!(o == CGAL::LEFT_TURN || (o == CGAL::COLLINEAR && flat[poly[k]]))) return ERROR_WRONG_PARAMETER;
    }
  out = std::move(result);
  return OK;
}

/// The sides of every polygon: result[f][k] is the interior edge (index into `partition.edges`) that
/// runs from polygons[f][k] to polygons[f][k+1] (cyclically), or -1 when that side is a border edge.
/// O(sum of the polygon sizes times the largest node degree).
inline std::vector<std::vector<std::ptrdiff_t> > polygon_side_edges(const Domain_partition& partition)
{
  std::vector<std::vector<std::ptrdiff_t> > result(partition.polygons.size());
  for(std::size_t f = 0; f < partition.polygons.size(); ++f)
  {
    const std::vector<std::size_t>& poly = partition.polygons[f];
    result[f].assign(poly.size(), -1);
    for(std::size_t k = 0; k < poly.size(); ++k)
    {
      const std::size_t u = poly[k], v = poly[(k + 1) % poly.size()];
      if(u >= partition.rotation.size()) continue;
      for(std::size_t e : partition.rotation[u])
        if(partition.opposite(e, u) == v) { result[f][k] = std::ptrdiff_t(e); break; }
    }
  }
  return result;
}

// ---- path vertex placement ----------------------------------------------------------------------------

namespace domain_detail {

// the nearest representable floating values below and above the rational q
template <class FT>
void bracket(const CGAL::Gmpq& q, FT& down, FT& up)
{
  FT c = FT(CGAL::to_double(q));
  // to_double is within an ulp of q; a few steps reach the bracket (bounded loops)
  for(int k = 0; k < 8 && to_rational(c) > q; ++k) c = std::nextafter(c, -std::numeric_limits<FT>::infinity());
  for(int k = 0; k < 8 && to_rational(std::nextafter(c, std::numeric_limits<FT>::infinity())) <= q; ++k)
    c = std::nextafter(c, std::numeric_limits<FT>::infinity());
  down = c;
  up = (to_rational(c) == q) ? c : std::nextafter(c, std::numeric_limits<FT>::infinity());
}

inline CGAL::Gmpfr exact_gmpfr(const CGAL::Gmpq& q)
{
  // q is a dyadic rational: its numerator's bits are enough for an exact binary value
  const mpfr_prec_t bits = (std::max)(mpfr_prec_t(2), mpfr_prec_t(mpz_sizeinbase(mpq_numref(q.mpq()), 2)));
  CGAL::Gmpfr r(0., CGAL::Gmpfr::Precision_type(bits));
  mpfr_set_q(r.fr(), q.mpq(), MPFR_RNDN);
  return r;
}

} // namespace domain_detail

/// Places the `fractions.size()` vertices of the path traced for `partition.edges[edge]` (see the top
/// of this file for the guarantees). `border` and `targets` are the points given to `partition_domain()`.
/// `sides`, if not null, receives per vertex its exact side of the directed edge (COLLINEAR: on it).
template <class Point_2>
Error_code place_path_vertices(const Domain_partition& partition, const std::vector<Point_2>& border,
                               const std::vector<Point_2>& targets, std::size_t edge,
                               const std::vector<double>& fractions, std::vector<Point_2>& positions,
                               std::vector<CGAL::Orientation>* sides = nullptr)
{
  typedef typename Point_ft<Point_2>::type FT;
  static_assert(Check_number_type<FT>::value, "");
  if(edge >= partition.edges.size() || border.size() != partition.number_of_border_nodes
     || targets.size() != partition.number_of_targets)
    return ERROR_WRONG_PARAMETER;
  const std::size_t k = fractions.size();
  for(std::size_t i = 0; i < k; ++i)
    if(!std::isfinite(fractions[i]) || fractions[i] < 0 || fractions[i] > 1 || (i > 0 && fractions[i] < fractions[i - 1]))
      return ERROR_WRONG_PARAMETER;

  const domain_detail::Node_points<Point_2> point{ border, targets };
  const std::size_t na = partition.edges[edge][0], nbn = partition.edges[edge][1];
  const Point_2& pa = point(na);
  const Point_2& pb = point(nbn);

  // exact parameters, strictly increasing inside (0, 1)
  std::vector<CGAL::Gmpq> t(k);
  bool strict = true;
  for(std::size_t i = 0; i < k; ++i)
    if(!(fractions[i] > 0 && fractions[i] < 1 && (i == 0 || fractions[i] > fractions[i - 1]))) strict = false;
  for(std::size_t i = 0; i < k; ++i)
  {
    if(strict) t[i] = CGAL::Gmpq(fractions[i]);
    else
    {
      // blend with uniform spacing: nondecreasing + strictly increasing stays strictly increasing,
      // and [0, 1] maps into (0, 1); u_i rounded to double keeps t dyadic (exact in MPFR)
      const CGAL::Gmpq lambda(1, 1024);
      const CGAL::Gmpq u(double(i + 1) / double(k + 1));
      t[i] = (CGAL::Gmpq(1) - lambda) * CGAL::Gmpq(fractions[i]) + lambda * u;
    }
  }

  std::vector<Point_2> result;
  result.reserve(k);
  std::vector<CGAL::Orientation> side(k, CGAL::COLLINEAR);
  const CGAL::Gmpq ax = to_rational(pa.x()), ay = to_rational(pa.y());
  const CGAL::Gmpq dx = to_rational(pb.x()) - ax, dy = to_rational(pb.y()) - ay;
  const bool x_major = CGAL::abs(dx) >= CGAL::abs(dy);

  if constexpr(std::is_floating_point<FT>::value)
  {
    // dominant coordinate c: strictly monotone from pa to pb
    const FT ca = x_major ? pa.x() : pa.y(), cb = x_major ? pb.x() : pb.y();
    const FT toward = cb; // nextafter direction
    const FT backward = ca;
    std::vector<FT> c(k);
    for(std::size_t i = 0; i < k; ++i)
    {
      c[i] = FT(double(ca) + CGAL::to_double(t[i]) * (double(cb) - double(ca)));
      const FT low = (i == 0) ? ca : c[i - 1];
      // strictly after `low` (towards cb)
      const bool after = (cb > ca) ? (c[i] > low) : (c[i] < low);
      if(!after) c[i] = std::nextafter(low, toward);
    }
    // strictly before cb: pull back from the end
    for(std::size_t j = k; j-- > 0; )
    {
      const FT high = (j + 1 == k) ? cb : c[j + 1];
      const bool before = (cb > ca) ? (c[j] < high) : (c[j] > high);
      if(!before) c[j] = std::nextafter(high, backward);
    }
    for(std::size_t i = 0; i < k; ++i)
    {
      const FT low = (i == 0) ? ca : c[i - 1];
      const bool after = (cb > ca) ? (c[i] > low) : (c[i] < low);
      if(!after) return ERROR_PATH_TRACING_FAILED; // not enough representable values on the segment
    }
    if(k > 0)
    {
      const bool before = (cb > ca) ? (c[k - 1] < cb) : (c[k - 1] > cb);
      if(!before) return ERROR_PATH_TRACING_FAILED;
    }

    // polygons on both sides, as accessors starting at node a (a strict corner of both: the edge
    // leaves it inside the domain)
    const std::ptrdiff_t left = partition.edge_polygons[edge][0], right = partition.edge_polygons[edge][1];
    if(left < 0 || right < 0) return ERROR_WRONG_PARAMETER;
    const std::vector<std::size_t>& PL = partition.polygons[std::size_t(left)];
    const std::vector<std::size_t>& PR = partition.polygons[std::size_t(right)];
    const std::size_t sl = std::size_t(std::find(PL.begin(), PL.end(), na) - PL.begin());
    const std::size_t sr = std::size_t(std::find(PR.begin(), PR.end(), na) - PR.begin());
    if(sl == PL.size() || sr == PR.size()) return ERROR_WRONG_PARAMETER;
    auto vl = [&](std::size_t i) -> const Point_2& { return point(PL[(sl + i) % PL.size()]); };
    auto vr = [&](std::size_t i) -> const Point_2& { return point(PR[(sr + i) % PR.size()]); };

    for(std::size_t i = 0; i < k; ++i)
    {
      const CGAL::Gmpq cq = to_rational(c[i]);
      // the other coordinate of the exact segment point at this abscissa
      const CGAL::Gmpq m = x_major ? ay + (cq - ax) * dy / dx : ax + (cq - ay) * dx / dy;
      FT down, up;
      domain_detail::bracket(m, down, up);
      // nearest first
      FT first = down, second = up;
      if(!(down == up) && (m - to_rational(down)) > (to_rational(up) - m)) std::swap(first, second);
      bool placed = false;
      for(int attempt = 0; attempt < 2 && !placed; ++attempt)
      {
        const FT o = attempt == 0 ? first : second;
        const Point_2 p = x_major ? Point_2(c[i], o) : Point_2(o, c[i]);
        const CGAL::Orientation s = exact_orientation(pa, pb, p);
        const bool ok = (s == CGAL::COLLINEAR)
                     || (s == CGAL::LEFT_TURN ? domain_detail::strictly_inside_convex(PL.size(), vl, p)
                                              : domain_detail::strictly_inside_convex(PR.size(), vr, p));
        if(ok) { result.push_back(p); side[i] = s; placed = true; }
        if(down == up) break;
      }
      if(!placed) return ERROR_PATH_TRACING_FAILED;
    }
  }
  else
  {
    for(std::size_t i = 0; i < k; ++i)
    {
      if constexpr(Is_mpfr<FT>::value)
        result.push_back(Point_2(domain_detail::exact_gmpfr(ax + t[i] * dx), domain_detail::exact_gmpfr(ay + t[i] * dy)));
      else
      {
        // the same exact value as t[i], built in FT (doubles convert exactly to an exact field)
        const FT lambda = FT(1) / FT(1024);
        const FT ti = strict ? FT(fractions[i])
                             : (FT(1) - lambda) * FT(fractions[i]) + lambda * FT(double(i + 1) / double(k + 1));
        result.push_back(Point_2(pa.x() + ti * (pb.x() - pa.x()), pa.y() + ti * (pb.y() - pa.y())));
      }
    }
    // certify: on the segment, strictly monotone along the dominant axis
    for(std::size_t i = 0; i < k; ++i)
    {
      if(exact_orientation(pa, pb, result[i]) != CGAL::COLLINEAR) return ERROR_PATH_TRACING_FAILED;
      const Point_2& low = (i == 0) ? pa : result[i - 1];
      const CGAL::Gmpq l = to_rational(x_major ? low.x() : low.y()), c = to_rational(x_major ? result[i].x() : result[i].y());
      const CGAL::Gmpq d = x_major ? dx : dy;
      if(!(d > 0 ? c > l : c < l)) return ERROR_PATH_TRACING_FAILED;
    }
    if(k > 0)
    {
      const CGAL::Gmpq l = to_rational(x_major ? result[k - 1].x() : result[k - 1].y());
      const CGAL::Gmpq e = to_rational(x_major ? pb.x() : pb.y());
      if(!((x_major ? dx : dy) > 0 ? e > l : e < l)) return ERROR_PATH_TRACING_FAILED;
    }
  }
  positions = std::move(result);
  if(sides) *sides = std::move(side);
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_CONSTRAINED_DOMAIN_PARTITION_H
