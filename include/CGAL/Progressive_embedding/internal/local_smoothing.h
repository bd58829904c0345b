// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_LOCAL_SMOOTHING_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_LOCAL_SMOOTHING_H

// One vertex at a time Newton descent on the symmetric Dirichlet energy of its
// incident faces (2x2 Hessian projected to SPD), with a flip-free backtracking
// line search: a step is accepted only if every incident face stays positively
// oriented under the exact predicate and the energy decreases.

#include <CGAL/Progressive_embedding/internal/symmetric_dirichlet.h>
#include <CGAL/Progressive_embedding/internal/newton_step.h>
#include <CGAL/Progressive_embedding/internal/number_utils.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

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

  Local_smoother(Mesh& m, const Traits& traits, const Reference_triangle<FT>& ref) : m(m), traits(traits), ref(ref) {}

  const Point_2& pos(vertex_descriptor v) const { return m.point(v); }

  static bool same(const Point_2& a, const Point_2& b) { return a.x() == b.x() && a.y() == b.y(); }

  // corners (v, a, b) of the face of halfedge h, h pointing to v; false if the face
  // is degenerate because two of its vertices coincide (a vertex being inserted)
  bool corners(halfedge_descriptor h, const Point_2*& a, const Point_2*& b) const
  {
    a = &pos(target(next(h, m), m));
    b = &pos(source(h, m));
    return !same(*a, *b) && !same(*a, pos(target(h, m))) && !same(*b, pos(target(h, m)));
  }

  // energy of the faces around v with v at x; +inf if one is not positively oriented
  double energy_at(vertex_descriptor v, const Point_2& x, bool check_orientation) const
  {
    typename Traits::Exact_orientation_2 orient = traits.exact_orientation_2_object();
    FT sum(0);
    for(halfedge_descriptor h : halfedges_around_target(v, m))
    {
      if(is_border(h, m)) continue;
      const Point_2 *a, *b;
      if(!corners(h, a, b)) continue;
      if(check_orientation && orient(x, *a, *b) != CGAL::LEFT_TURN) return std::numeric_limits<double>::infinity();
      bool ok;
      FT e = symmetric_dirichlet(ref, x.x(), x.y(), a->x(), a->y(), b->x(), b->y(), ok);
      if(!ok) return std::numeric_limits<double>::infinity();
      sum += e;
    }
    const double d = CGAL::to_double(sum);
    return std::isfinite(d) ? d : std::numeric_limits<double>::infinity();
  }

  // one Newton step at v; returns true if v moved
  bool step(vertex_descriptor v)
  {
    const Point_2 x = pos(v);
    FT E(0);
    double g[2] = {0, 0}, H[3] = {0, 0, 0};
    double tmax = 1.0;
    // gradient/Hessian in FT per face, accumulated in double for the direction
    std::array<FT, 2> gf; std::array<FT, 3> Hf; FT Ef;
    for(halfedge_descriptor h : halfedges_around_target(v, m))
    {
      if(is_border(h, m)) continue;
      const Point_2 *a, *b;
      if(!corners(h, a, b)) continue;
      if(!symmetric_dirichlet_local(ref, x.x(), x.y(), a->x(), a->y(), b->x(), b->y(), Ef, gf, Hf))
        return false;
      E += Ef;
      g[0] += CGAL::to_double(gf[0]); g[1] += CGAL::to_double(gf[1]);
      H[0] += CGAL::to_double(Hf[0]); H[1] += CGAL::to_double(Hf[1]); H[2] += CGAL::to_double(Hf[2]);
    }
    if(!std::isfinite(g[0]) || !std::isfinite(g[1]) || !std::isfinite(H[0]) || !std::isfinite(H[1]) || !std::isfinite(H[2]))
      return false;
    double d[2];
    if(!projected_newton_direction(g, H, d)) return false;

    // largest step before a face degenerates: its area is affine along d
    for(halfedge_descriptor h : halfedges_around_target(v, m))
    {
      if(is_border(h, m)) continue;
      const Point_2 *a, *b;
      if(!corners(h, a, b)) continue;
      const double ax = CGAL::to_double(a->x()), ay = CGAL::to_double(a->y());
      const double bx = CGAL::to_double(b->x()), by = CGAL::to_double(b->y());
      const double xx = CGAL::to_double(x.x()), xy = CGAL::to_double(x.y());
      tmax = (std::min)(tmax, 0.9 * vertex_degeneration_time(xx, xy, d[0], d[1], ax, ay, bx, by));
    }
    const double E0 = CGAL::to_double(E);
    double t = tmax;
    for(int k = 0; k < 30; ++k, t *= 0.5)
    {
      const Point_2 xn(x.x() + make_ft<FT>(t * d[0]), x.y() + make_ft<FT>(t * d[1]));
      if(same(xn, x)) return false;
      const double En = energy_at(v, xn, true);
      if(En < E0)
      {
        m.point(v) = xn;
        ++steps_accepted;
        // converged when the decrease is negligible: the caller's sweep may stop
        return En < E0 * (1 - relative_tolerance);
      }
    }
    return false;
  }
};

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
