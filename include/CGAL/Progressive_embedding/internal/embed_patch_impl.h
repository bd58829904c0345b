// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_EMBED_PATCH_IMPL_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_EMBED_PATCH_IMPL_H

// The body of embed_patch(): a patch of a mesh mapped into a given border polygon (Tutte, then the
// progressive repair), certified on the patch's own indexed disk.

#include <CGAL/Progressive_embedding/Error_code.h>
#include <CGAL/Progressive_embedding/parameters.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_traits_2.h>
#include <CGAL/Progressive_embedding/Progressive_embedding_statistics.h>
#include <CGAL/Progressive_embedding/Embedding_report.h>
#include <CGAL/Progressive_embedding/internal/check_embedding_impl.h>
#include <CGAL/Progressive_embedding/internal/tutte_embedding_impl.h>
#include <CGAL/Progressive_embedding/internal/progressive_embedding_impl.h>
#include <CGAL/Progressive_embedding/internal/indexed_disk.h>
#include <CGAL/Progressive_embedding/internal/check_passes.h>
#include <CGAL/Progressive_embedding/internal/patch_chords.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Real_timer.h>

#include <functional>
#include <iostream>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// Exact certificate of the positions `pos` of a patch (by vertex index of `disk`) whose border
// polygon is convex and oriented as `orientation` says: every face strictly of that orientation.
// Why this suffices: the border is a simple closed polygon (convex, traversed once) and fixed, and
// a piecewise linear map of a disk whose triangles are all positively oriented is a local
// homeomorphism inside; by the degree argument every point inside the polygon is then covered
// exactly once and no point outside is covered, so the map is one-to-one (no overlap).
template <class TriangleMesh, class Point_2, class ExactOrientation>
std::size_t count_wrong_faces(const Indexed_disk<TriangleMesh>& disk, const std::vector<Point_2>& pos,
                              int orientation, ExactOrientation orient)
{
  const CGAL::Orientation expected = orientation > 0 ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN;
  std::size_t wrong = 0;
  for(const auto& t : disk.faces)
    if(orient(pos[t[0]], pos[t[1]], pos[t[2]]) != expected) ++wrong;
  return wrong;
}

// Reads the border positions of a patch whose border polygon is only required to be simple (no
// repeated point, no two edges touching except consecutive ones at their common vertex), e.g. a
// polygon that is convex up to the rounding of its vertices. `orientation`: +1 counterclockwise,
// -1 clockwise, decided exactly at the lexicographically smallest vertex (a strictly convex corner
// of any simple polygon).
template <class TriangleMesh, class VertexUVMap, class Traits>
Error_code read_simple_border(const Indexed_disk<TriangleMesh>& disk, VertexUVMap uvm, const Traits& traits,
                              std::vector<typename Traits::Point_2>& bpos, int& orientation)
{
  typedef typename Traits::Point_2 Point_2;
  const typename Traits::Exact_orientation_2 orient = traits.exact_orientation_2_object();
  const std::size_t nb = disk.border.size();
  bpos.clear();
  for(std::size_t k = 0; k < nb; ++k)
  {
    const Point_2 p = get(uvm, disk.vertices[disk.border[k]]);
    if(!is_finite_ft(p.x()) || !is_finite_ft(p.y())) return ERROR_NON_FINITE_COORDINATES;
    bpos.push_back(p);
  }
  std::size_t low = 0;
  for(std::size_t k = 0; k < nb; ++k)
  {
    const Point_2& a = bpos[k];
    const Point_2& b = bpos[(k + 1) % nb];
    if(a.x() == b.x() && a.y() == b.y()) return ERROR_DEGENERATE_BORDER;
    if(a.x() < bpos[low].x() || (a.x() == bpos[low].x() && a.y() < bpos[low].y())) low = k;
  }
  if(count_polygon_self_intersections(bpos, orient, 1) != 0) return ERROR_NON_CONVEX_BORDER;
  const CGAL::Orientation o = orient(bpos[(low + nb - 1) % nb], bpos[low], bpos[(low + 1) % nb]);
  if(o == CGAL::COLLINEAR) return ERROR_DEGENERATE_BORDER; // all points collinear
  orientation = (o == CGAL::LEFT_TURN) ? 1 : -1;
  return OK;
}

// Tutte's map of the patch (interior of `pos`, by vertex index of `disk`; `bpos`: the border in
// border order, already in `pos`) solved relative to the first border vertex. In floating point
// the solve's error is relative to the coordinates, not to the patch: a patch 1e-9 across at
// 0.36 (a crowded region of a constrained map) loses the 8 digits between the two, and its
// Tutte map flips many faces that a solve near the origin keeps valid (the repair must then
// place vertices where the grid of doubles at 0.36 has almost no room). Translated only if the
// translation is exact on the whole border (Sterbenz: a border small next to its distance from
// the origin), so the system is the same one with the border bit-exactly where it was; the
// interior is translated back (rounded once, at the end).
template <class TriangleMesh, class VPM, class NamedParameters, class Point_2>
Error_code tutte_interior_translated(const Indexed_disk<TriangleMesh>& disk, VPM vpm, const NamedParameters& np,
                                     Progress_budget& budget, const std::vector<Point_2>& bpos, std::vector<Point_2>& pos)
{
  const std::size_t nv = disk.number_of_vertices(), nb = disk.border.size();
  const Point_2 o = bpos[0];
  std::vector<Point_2> tpos(nv, Point_2(0, 0));
  for(std::size_t k = 0; k < nb; ++k)
  {
    const Point_2 t(bpos[k].x() - o.x(), bpos[k].y() - o.y());
    if(!(t.x() + o.x() == bpos[k].x() && t.y() + o.y() == bpos[k].y()))
      return tutte_interior(disk, vpm, np, budget, pos); // not exact: solved where it is
    tpos[disk.border[k]] = t;
  }
  const Error_code ec = tutte_interior(disk, vpm, np, budget, tpos);
  if(ec != OK) return ec;
  for(std::size_t i = 0; i < nv; ++i)
    if(!disk.on_border[i]) pos[i] = Point_2(tpos[i].x() + o.x(), tpos[i].y() + o.y());
  return OK;
}

// embed_patch() (convex border, flat chords refused) or, with `simple_border`, the same map for a
// patch whose border is only a simple polygon: the constrained pipeline's patches, whose path
// vertices are placed on their segments up to rounding (convex up to an ulp). No flat-chord test
// then (the caller splits the chords along one side beforehand); Tutte and the repair run as for a
// convex border, and the same exact certificate (every face strictly oriented like the border,
// border unchanged and simple) proves the map one-to-one by the degree argument, which needs a
// simple border only, not a convex one. `slots`: see make_indexed_patch() (many patches of one mesh).
// `report_distortion`: whether the statistics' report gets the areas and energies of the patch (three
// more passes over it; the constrained pipeline certifies and measures the whole map afterwards).
template <typename TriangleMesh, typename FaceRange, typename VertexUVMap, typename NamedParameters>
Error_code embed_patch_impl(const TriangleMesh& tm, const FaceRange& patch_faces, VertexUVMap uvm,
                            const NamedParameters& np, bool simple_border,
                            Patch_slots<TriangleMesh>* slots = nullptr, bool report_distortion = true)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename internal::Uv_map_types<VertexUVMap>::Traits                    Default_traits;
  typedef typename CGAL::internal_np::Lookup_named_param_def<
            CGAL::internal_np::geom_traits_t, NamedParameters, Default_traits>::type  Traits;
  typedef typename Traits::Point_2                                                Point_2;
  typedef typename Traits::FT                                                     FT;
  static_assert(std::is_same<Point_2, typename internal::Uv_map_types<VertexUVMap>::Point_2>::value,
                "the geom_traits' Point_2 must be the value type of the uv map");

  CGAL::Real_timer timer;
  timer.start();
  Progressive_embedding_statistics local_stats;
  Progressive_embedding_statistics* stats_out =
    choose_parameter(get_parameter(np, internal_np::statistics), static_cast<Progressive_embedding_statistics*>(nullptr));
  Progressive_embedding_statistics& stats = stats_out ? *stats_out : local_stats;
  stats = Progressive_embedding_statistics();

  const Traits traits = choose_parameter<Traits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const typename Traits::Exact_orientation_2 orient = traits.exact_orientation_2_object();
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);
  const double max_seconds = choose_parameter(get_parameter(np, CGAL::internal_np::maximum_running_time),
                                              std::numeric_limits<double>::infinity());
  if(!(max_seconds >= 0)) return ERROR_WRONG_PARAMETER;
  typename internal::Progressive_embedder<Traits>::Options opt;
  Error_code ec = internal::progressive_embedder_options<Traits>(np, opt);
  if(ec != OK) return ec;
  opt.callback = std::function<bool(double)>(); // one callback could not report two phases monotonically

  // the patch, its border polygon (exact classification) and its flat chords
  internal::Indexed_disk<TriangleMesh> disk;
  ec = internal::make_indexed_patch(tm, patch_faces, disk, slots);
  if(ec != OK) return ec;
  const std::size_t nv = disk.number_of_vertices(), nb = disk.border.size();
  if(nb < 3) return ERROR_BORDER_TOO_SHORT;
  std::vector<Point_2> bpos;
  int orientation = 0;
  ec = simple_border ? internal::read_simple_border(disk, uvm, traits, bpos, orientation)
                     : internal::read_convex_border(disk, uvm, traits, bpos, orientation);
  if(ec != OK) return ec;
  if(!simple_border)
  {
    std::vector<std::pair<std::size_t, std::size_t> > chords;
    internal::flat_chords(disk, bpos, orient, chords);
    if(!chords.empty())
    {
      if(verbose) std::cerr << "[embed_patch] " << chords.size() << " flat chord(s): no valid map" << std::endl;
      return ERROR_DEGENERATE_CHORD;
    }
  }
  std::vector<Point_2> pos(nv);
  for(std::size_t k = 0; k < nb; ++k) pos[disk.border[k]] = bpos[k];
  if(verbose)
    std::cerr << "[embed_patch] patch: " << disk.number_of_faces() << " faces, " << nv << " vertices, "
              << nb << " on its border (" << (orientation > 0 ? "counterclockwise" : "clockwise") << ")" << std::endl;

  // Tutte's map with the border fixed: exact solves are valid (Tutte, Floater), floating-point
  // ones may not be
  if(disk.number_of_interior_vertices() > 0)
  {
    internal::Progress_budget budget(std::function<bool(double)>(), max_seconds);
    ec = internal::tutte_interior_translated(disk, vpm, np, budget, bpos, pos);
    if(ec == ERROR_CANNOT_SOLVE_LINEAR_SYSTEM)
    {
      // the repair accepts any finite start: every interior vertex at the border's centroid
      FT sx(0), sy(0);
      for(const Point_2& p : bpos) { sx += p.x(); sy += p.y(); }
      const Point_2 c(sx / FT(double(nb)), sy / FT(double(nb)));
      for(std::size_t i = 0; i < nv; ++i) if(!disk.on_border[i]) pos[i] = c;
      if(!internal::is_finite_ft(c.x()) || !internal::is_finite_ft(c.y())) return ec;
      if(verbose) std::cerr << "[embed_patch] the Tutte solve failed: repairing from the centroid" << std::endl;
    }
    else if(ec != OK) return ec;
    const std::size_t wrong = internal::count_wrong_faces(disk, pos, orientation, orient);
    if(verbose) std::cerr << "[embed_patch] Tutte map: " << wrong << " face(s) not strictly positive" << std::endl;
    if(wrong > 0)
    {
      opt.time_budget = max_seconds - timer.time();
      if(!(opt.time_budget > 0)) return ERROR_BUDGET_EXHAUSTED;
      ec = internal::repair_disk_map(disk, bpos, orientation, traits, opt, pos, stats);
      if(ec != OK) { stats.seconds_total = timer.time(); return ec; }
    }
  }

  // certificate on the patch (see internal::count_wrong_faces for why it implies no overlap):
  // written first, certified from the uv map itself, rolled back if refused
  const double t_certificate = timer.time();
  std::vector<Point_2> old(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    if(disk.on_border[i]) continue;
    old[i] = get(uvm, disk.vertices[i]);
    put(uvm, disk.vertices[i], pos[i]);
  }
  Embedding_report& r = stats.report;
  r = Embedding_report();
  r.faces = disk.number_of_faces(); r.vertices = nv; r.border_vertices = nb;
  internal::Uv_samples<Point_2> samples;
  internal::sample_uv(disk, uvm, samples);
  r.non_finite = samples.non_finite;
  internal::Face_orientations o;
  internal::orientation_pass(disk, samples, orient, o);
  r.flipped = o.flipped; r.degenerate = o.degenerate; r.clockwise = (o.border_sign == CGAL::RIGHT_TURN);
  if(o.border_finite) r.border_intersections = internal::border_pass(disk, samples, orient, r.overlap_limit);
  r.border_simple = o.border_finite && r.border_intersections == 0;
  bool border_kept = true;
  for(std::size_t k = 0; k < nb; ++k)
  {
    const Point_2 p = get(uvm, disk.vertices[disk.border[k]]);
    if(!(p.x() == bpos[k].x() && p.y() == bpos[k].y())) border_kept = false;
  }
  const bool certified = border_kept && r.non_finite == 0 && r.flipped == 0 && r.degenerate == 0 && r.border_simple
                         && r.clockwise == (orientation < 0)
                         && internal::count_wrong_faces(disk, pos, orientation, orient) == 0;
  r.overlap_checked = r.overlap_by_degree_argument = certified;
  if(stats_out && report_distortion)
  {
    internal::Face_areas areas;
    internal::area_pass(disk, samples, o, areas);
    r.min_signed_area = areas.min_area; r.max_signed_area = areas.max_area; r.border_area = areas.border_area;
    const internal::Equilateral_energies eq = internal::equilateral_energy_pass(disk, samples, o, areas, r.energy_threshold);
    r.max_energy_equilateral = eq.max_energy; r.mean_energy_equilateral = eq.mean_energy; r.high_energy_faces = eq.high_energy_faces;
    r.distortion = internal::distortion_pass(disk, vpm, samples, o, areas, r.has_3d_energy);
    if(r.has_3d_energy)
    {
      r.max_energy_3d = r.distortion.max_symmetric_dirichlet;
      r.mean_energy_3d = r.distortion.mean_symmetric_dirichlet;
    }
  }
  stats.seconds_total = timer.time();
  stats.seconds_certification = stats.seconds_total - t_certificate;
  if(verbose) std::cerr << "[embed_patch] " << (certified ? "certified" : "NOT certified") << ": " << r.summary() << std::endl;
  if(!certified)
  {
    for(std::size_t i = 0; i < nv; ++i)
      if(!disk.on_border[i]) put(uvm, disk.vertices[i], old[i]);
    return ERROR_INVALID_EMBEDDING;
  }
  return OK;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_EMBED_PATCH_IMPL_H
