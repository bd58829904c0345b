// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_NEWTON_STEP_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_NEWTON_STEP_H

// The pieces of a flip-free Newton step shared by the local smoothing of progressive
// embedding and by the distortion optimizer:
//  - the direction of one vertex (2x2 Hessian projected to SPD),
//  - the first time a triangle degenerates when one corner moves (linear in t) or when all
//    three move (quadratic in t).
// Directions and bounds are computed in double; callers certify accepted positions exactly.

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// Newton direction d = -H^-1 g with the 2x2 Hessian H = (hxx, hxy, hyy) projected to SPD
// (eigenvalues clamped to 1e-12 times the largest); false if no finite non-zero direction exists.
inline bool projected_newton_direction(const double g[2], const double H[3], double d[2])
{
  if(!std::isfinite(g[0]) || !std::isfinite(g[1]) || !std::isfinite(H[0]) || !std::isfinite(H[1]) || !std::isfinite(H[2]))
    return false;
  const double tr2 = 0.5 * (H[0] + H[2]);
  // sqrt of the sum of squares is exact enough here; hypot (several times slower) only when the squares overflow
  const double hd = 0.5 * (H[0] - H[2]);
  double disc = std::sqrt(hd * hd + H[1] * H[1]);
  if(!std::isfinite(disc)) disc = std::hypot(hd, H[1]);
  double l1 = tr2 + disc, l2 = tr2 - disc;
  double e1x, e1y; // eigenvector of l1
  if(H[1] != 0) { e1x = l1 - H[2]; e1y = H[1]; }
  else if(H[0] >= H[2]) { e1x = 1; e1y = 0; }
  else { e1x = 0; e1y = 1; }
  double nrm = std::sqrt(e1x * e1x + e1y * e1y);
  if(!std::isfinite(nrm) || !(nrm > 0)) nrm = std::hypot(e1x, e1y);
  if(!(nrm > 0) || !std::isfinite(nrm)) return false;
  e1x /= nrm; e1y /= nrm;
  const double e2x = -e1y, e2y = e1x;
  if(!(l1 > 0)) return false; // no positive curvature at all: no Newton direction
  const double floor_l = 1e-12 * l1; // relative: the Hessian's scale is the energy's
  l1 = (std::max)(l1, floor_l); l2 = (std::max)(l2, floor_l);
  const double g1 = e1x * g[0] + e1y * g[1], g2 = e2x * g[0] + e2y * g[1];
  d[0] = -(g1 / l1) * e1x - (g2 / l2) * e2x;
  d[1] = -(g1 / l1) * e1y - (g2 / l2) * e2y;
  return std::isfinite(d[0]) && std::isfinite(d[1]) && (d[0] != 0 || d[1] != 0);
}

// First t > 0 at which the triangle (p + t d, a, b), positively oriented at t = 0, degenerates
// (its signed area is affine in t); +infinity if it never does.
inline double vertex_degeneration_time(double px, double py, double dx, double dy,
                                       double ax, double ay, double bx, double by)
{
  const double A0 = (ax - px) * (by - py) - (ay - py) * (bx - px); // twice the area
  const double dA = dx * (ay - by) + dy * (bx - ax);                 // its derivative in t
  if(dA < 0 && A0 > 0) return A0 / -dA;
  return std::numeric_limits<double>::infinity();
}

// The real times t at which the triangle with corners (x_i + t dx_i, y_i + t dy_i) is degenerate
// (its signed area is quadratic in t), in `roots`, in no particular order; returns their number (0 to 2).
inline int triangle_degeneration_roots(double x0, double y0, double x1, double y1, double x2, double y2,
                                       double dx0, double dy0, double dx1, double dy1, double dx2, double dy2,
                                       double roots[2])
{
  const double ex1 = x1 - x0, ey1 = y1 - y0, ex2 = x2 - x0, ey2 = y2 - y0;
  const double fx1 = dx1 - dx0, fy1 = dy1 - dy0, fx2 = dx2 - dx0, fy2 = dy2 - dy0;
  const double c = ex1 * ey2 - ey1 * ex2;
  const double b = ex1 * fy2 + fx1 * ey2 - ey1 * fx2 - fy1 * ex2;
  const double a = fx1 * fy2 - fy1 * fx2;
  int n = 0;
  if(a == 0)
  { if(b != 0) roots[n++] = -c / b; }
  else
  {
    const double disc = b * b - 4 * a * c;
    if(disc >= 0)
    {
      const double sq = std::sqrt(disc);
      const double q = -0.5 * (b + (b >= 0 ? sq : -sq)); // stable roots, also for a tiny a
      if(q != 0) roots[n++] = c / q;
      roots[n++] = q / a;
    }
  }
  return n;
}

// First t > 0 at which the triangle with corners (x_i + t dx_i, y_i + t dy_i) degenerates;
// +infinity if it never does.
inline double triangle_degeneration_time(double x0, double y0, double x1, double y1, double x2, double y2,
                                         double dx0, double dy0, double dx1, double dy1, double dx2, double dy2)
{
  double roots[2];
  const int n = triangle_degeneration_roots(x0, y0, x1, y1, x2, y2, dx0, dy0, dx1, dy1, dx2, dy2, roots);
  double t = std::numeric_limits<double>::infinity();
  for(int k = 0; k < n; ++k) if(roots[k] > 0 && roots[k] < t) t = roots[k];
  return t;
}

// ---- border barrier (free borders) ----
// A free border must stay simple. The exact test that certifies a step says only yes or no: a
// Newton step that drives two parts of the border together is halved again and again, each
// accepted step bringing them closer, until the line search stalls with the parts ulps apart.
// The barrier makes the energy see the border's self-distance: every pair (vertex v, border edge
// ab not incident to v) closer than its reach h adds k * b(d / h), d the distance from v to the
// segment ab and b(x) = -(1 - x)^2 ln x (zero with its first two derivatives at x = 1, infinite
// at 0); and the largest step is bounded by the first time a vertex would reach a segment.

// b(x), b'(x), b''(x) for 0 < x < 1 (b'' > 0: convex)
inline void border_barrier_terms(double x, double& b, double& b1, double& b2)
{
  const double l = std::log(x), m = 1 - x;
  b = -m * m * l;
  b1 = 2 * m * l - m * m / x;
  b2 = -2 * l + 4 * m / x + m * m / (x * x);
}

// Distance d from v to the segment ab and its gradient with respect to v, a and b
// (g = (gvx, gvy, gax, gay, gbx, gby)); false if d is zero or not finite.
inline bool point_segment_distance(double vx, double vy, double ax, double ay, double bx, double by,
                                   double& d, double g[6])
{
  const double ex = bx - ax, ey = by - ay, l2 = ex * ex + ey * ey;
  double t = (l2 > 0) ? ((vx - ax) * ex + (vy - ay) * ey) / l2 : 0;
  t = (std::min)(1., (std::max)(0., t));
  const double px = vx - (ax + t * ex), py = vy - (ay + t * ey);
  d = std::sqrt(px * px + py * py);
  if(!(d > 0) || !std::isfinite(d)) return false;
  const double nx = px / d, ny = py / d; // unit vector from the closest point to v
  g[0] = nx; g[1] = ny;
  g[2] = -(1 - t) * nx; g[3] = -(1 - t) * ny;
  g[4] = -t * nx; g[5] = -t * ny;
  return true;
}

// First t > 0 at which the vertex v + t dv lies on the segment (a + t da, b + t db) (all three
// move linearly: the triangle (v, a, b) is then degenerate with v between a and b); +infinity if
// it never does. Computed in double: a bound for the line search, which the exact test backs up.
inline double vertex_segment_contact_time(double vx, double vy, double ax, double ay, double bx, double by,
                                          double dvx, double dvy, double dax, double day, double dbx, double dby)
{
  double roots[2];
  const int n = triangle_degeneration_roots(vx, vy, ax, ay, bx, by, dvx, dvy, dax, day, dbx, dby, roots);
  if(n == 2 && roots[1] < roots[0]) std::swap(roots[0], roots[1]);
  for(int k = 0; k < n; ++k)
  {
    const double t = roots[k];
    if(!(t > 0) || !std::isfinite(t)) continue;
    // where v lies along the edge at time t (with a margin for the rounding of t)
    const double px = vx + t * dvx, py = vy + t * dvy;
    const double qx = ax + t * dax, qy = ay + t * day, rx = bx + t * dbx, ry = by + t * dby;
    const double ex = rx - qx, ey = ry - qy, l2 = ex * ex + ey * ey;
    if(!(l2 > 0)) return t;
    const double s = ((px - qx) * ex + (py - qy) * ey) / l2;
    if(s > -1e-3 && s < 1 + 1e-3) return t;
  }
  return std::numeric_limits<double>::infinity();
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif
