// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_LOCAL_SMOOTHING_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_LOCAL_SMOOTHING_H

// One vertex at a time Newton descent on the symmetric Dirichlet energy of its
// incident faces (2x2 Hessian projected to SPD, internal/newton_step.h), with a flip-free
// backtracking line search: a step is accepted only if every incident face stays positively
// oriented under the exact predicate and the energy decreases. In double, when the step rounds
// to no move (stars a few ulps wide, as in patches of constrained maps a few hundred ulps across),
// the neighbouring doubles in the step's quadrant are tried instead.

#include <CGAL/Progressive_embedding/internal/symmetric_dirichlet.h>
#include <CGAL/Progressive_embedding/internal/newton_step.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// `Mesh` is a Surface_mesh whose points are the uv positions.
template <class Mesh, class Traits>
struct Local_smoother
{
  typedef typename Traits::FT                                 FT;
  typedef typename Traits::Point_2                            Point_2;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor   vertex_descriptor;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;

  Mesh& m;
  const Traits& traits;
  Reference_triangle<FT> ref;
  std::size_t steps_accepted = 0;
  double relative_tolerance = 1e-3;

private:
  // the two other corners (a, b) of each face around the vertex being moved, counterclockwise
  // (v, a, b); gathered once per step (the points do not move during a step)
  struct Corners { const Point_2* a; const Point_2* b; };
  std::vector<Corners> star;
  typename Traits::Exact_orientation_2 orient;
  // pass in which a vertex is stepped again (see smooth())
  typename Mesh::template Property_map<vertex_descriptor, std::size_t> active;
  std::size_t pass_base = 0;

public:
  Local_smoother(Mesh& m, const Traits& traits, const Reference_triangle<FT>& ref)
    : m(m), traits(traits), ref(ref), orient(traits.exact_orientation_2_object())
  {
    active = m.template add_property_map<vertex_descriptor, std::size_t>("v:pe_smoothing_pass", 0).first;
  }

  ~Local_smoother() { m.remove_property_map(active); }

  Local_smoother(const Local_smoother&) = delete;
  Local_smoother& operator=(const Local_smoother&) = delete;

  static bool same(const Point_2& a, const Point_2& b) { return a.x() == b.x() && a.y() == b.y(); }

  // Fills `star` for v. Faces with two coincident corners (a vertex being inserted sits on
  // its partner) are left out: they have no energy and no orientation to keep.
  void gather(vertex_descriptor v)
  {
    star.clear();
    const Point_2& x = m.point(v);
    for(halfedge_descriptor h : halfedges_around_target(v, m))
    {
      if(is_border(h, m)) continue;
      const Point_2* a = &m.point(target(next(h, m), m));
      const Point_2* b = &m.point(source(h, m));
      if(same(*a, *b) || same(*a, x) || same(*b, x)) continue;
      star.push_back(Corners{a, b});
    }
  }

  // energy of the gathered star with its center at x; +inf if a face is not positively oriented
  double star_energy(const Point_2& x) const
  {
    FT sum(0);
    for(const Corners& c : star)
    {
      FT e;
      if(!positive_face_energy(ref, orient, x, *c.a, *c.b, e)) return std::numeric_limits<double>::infinity();
      sum += e;
    }
    const double d = CGAL::to_double(sum);
    return std::isfinite(d) ? d : std::numeric_limits<double>::infinity();
  }

  // energy of the faces around v with v at x; +inf if one is not positively oriented
  double energy_at(vertex_descriptor v, const Point_2& x)
  {
    gather(v);
    return star_energy(x);
  }

  // One Newton step at v; true if v moved and decreased its energy by more than the relative
  // tolerance (a smaller decrease counts as converged).
  bool step(vertex_descriptor v)
  {
    gather(v);
    const Point_2 x = m.point(v);
    FT E(0);
    double g[2] = {0, 0}, H[3] = {0, 0, 0};
    // gradient/Hessian in FT per face, accumulated in double for the direction
    std::array<FT, 2> gf; std::array<FT, 3> Hf; FT Ef;
    for(const Corners& c : star)
    {
      if(!symmetric_dirichlet_local(ref, x.x(), x.y(), c.a->x(), c.a->y(), c.b->x(), c.b->y(), Ef, gf, Hf))
        return false;
      E += Ef;
      g[0] += CGAL::to_double(gf[0]); g[1] += CGAL::to_double(gf[1]);
      H[0] += CGAL::to_double(Hf[0]); H[1] += CGAL::to_double(Hf[1]); H[2] += CGAL::to_double(Hf[2]);
    }
    double d[2];
    if(!projected_newton_direction(g, H, d)) return false;

    // largest step before a face degenerates (its area is affine along d), with a margin
    const double xx = CGAL::to_double(x.x()), xy = CGAL::to_double(x.y());
    double tmax = 1.0;
    for(const Corners& c : star)
      tmax = (std::min)(tmax, 0.9 * vertex_degeneration_time(xx, xy, d[0], d[1],
                                                             CGAL::to_double(c.a->x()), CGAL::to_double(c.a->y()),
                                                             CGAL::to_double(c.b->x()), CGAL::to_double(c.b->y())));
    const double E0 = CGAL::to_double(E);
    double t = tmax;
    for(int k = 0; k < 30; ++k, t *= 0.5)
    {
      const Point_2 xn(x.x() + make_ft<FT>(t * d[0]), x.y() + make_ft<FT>(t * d[1]));
      if(same(xn, x)) return (k == 0) ? lattice_step(v, x, E0, d) : false;
      const double En = star_energy(xn);
      if(En < E0)
      {
        m.point(v) = xn;
        ++steps_accepted;
        return En < E0 * (1 - relative_tolerance);
      }
    }
    return false;
  }

  // The Newton step is below the resolution of the number type (the star is a few ulps wide):
  // tries the neighbouring representable points in the direction's quadrant.
  bool lattice_step(vertex_descriptor v, const Point_2& x, double E0, const double d[2])
  {
    if(!std::is_same<FT, double>::value) return false;
    const double xx = CGAL::to_double(x.x()), xy = CGAL::to_double(x.y());
    const double sx = d[0] > 0 ? 1 : (d[0] < 0 ? -1 : 0), sy = d[1] > 0 ? 1 : (d[1] < 0 ? -1 : 0);
    const double inf = std::numeric_limits<double>::infinity();
    double best = E0; Point_2 best_p = x;
    // the diagonal neighbour, and the two axis neighbours when the step has both components
    const double cand[3][2] = {{sx, sy}, {sx, 0}, {0, sy}};
    const int candidates = (sx != 0 && sy != 0) ? 3 : 1;
    for(int k = 0; k < candidates; ++k)
    {
      const double* c = cand[k];
      if(c[0] == 0 && c[1] == 0) continue;
      const double nx = c[0] == 0 ? xx : std::nextafter(xx, c[0] * inf);
      const double ny = c[1] == 0 ? xy : std::nextafter(xy, c[1] * inf);
      const Point_2 xn(make_ft<FT>(nx), make_ft<FT>(ny));
      const double En = star_energy(xn);
      if(En < best) { best = En; best_p = xn; }
    }
    if(!(best < E0)) return false;
    m.point(v) = best_p;
    ++steps_accepted;
    return best < E0 * (1 - relative_tolerance);
  }

  // At most `passes` passes of one step per vertex of `vs` (skipping those for which `is_fixed`
  // holds). After the first pass, a vertex is stepped only if it or a neighbour decreased its
  // energy by more than the fraction `tolerance` in the previous pass: the others are converged.
  template <class VertexRange, class IsFixed>
  void smooth(const VertexRange& vs, int passes, const IsFixed& is_fixed, double tolerance)
  {
    if(passes <= 0) return;
    relative_tolerance = tolerance;
    const std::size_t base = pass_base + 1;
    pass_base += std::size_t(passes) + 1;
    for(vertex_descriptor v : vs) active[v] = base;
    for(int p = 0; p < passes; ++p)
    {
      const std::size_t now = base + std::size_t(p);
      bool moved = false;
      for(vertex_descriptor v : vs)
      {
        if(active[v] < now || is_fixed(v) || !step(v)) continue;
        moved = true;
        active[v] = now + 1;
        for(vertex_descriptor w : CGAL::vertices_around_target(v, m))
          if(active[w] < now + 1) active[w] = now + 1;
      }
      if(!moved) break;
    }
  }
};

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
