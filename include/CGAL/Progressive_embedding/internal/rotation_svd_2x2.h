// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_ROTATION_SVD_2X2_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_ROTATION_SVD_2X2_H

// The singular value decomposition J = U diag(s1, s2) V^T of a 2x2 matrix with det J > 0, U and V
// rotations, s1 >= s2 > 0, in closed form: J is the sum of a similarity [[E, -H], [H, E]] and an
// anti-similarity [[F, G], [G, -F]]; with Q = |(E, H)| and R = |(F, G)|, s1 = Q + R, s2 = Q - R = det J / s1, and the
// two rotations are by the half sum and half difference of their angles (found without trigonometry). The optimizer takes one per
// face per iteration: Eigen's JacobiSVD (iterative, general) was a tenth of a whole cross-parameterization.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

// false (nothing written) unless det J > 0 and the result is finite
inline bool rotation_svd_2x2(const Eigen::Matrix2d& J, Eigen::Matrix2d& U, Eigen::Vector2d& s, Eigen::Matrix2d& V)
{
  const double E = (J(0, 0) + J(1, 1)) / 2, F = (J(0, 0) - J(1, 1)) / 2;
  const double G = (J(1, 0) + J(0, 1)) / 2, H = (J(1, 0) - J(0, 1)) / 2;
  const double Q = std::sqrt(E * E + H * H), R = std::sqrt(F * F + G * G);
  const double det = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
  if(!(det > 0) || !(Q > 0) || !std::isfinite(Q + R)) return false;
  // the unit complex numbers of the two angles a1 (of (F, G)) and a2 (of (E, H)), without trigonometry
  const double c2 = E / Q, s2 = H / Q;
  const double c1 = R > 0 ? F / R : 1., s1 = R > 0 ? G / R : 0.;
  // phi = (a1 + a2) / 2: a square root of e^(i a1) e^(i a2), by the half-angle formulas (the stable one of the
  // two for each sign of the cosine); theta = phi - a1 = (a2 - a1) / 2. The other square root turns both U and V
  // by pi: the same product.
  const double cw = c1 * c2 - s1 * s2, sw = s1 * c2 + c1 * s2;
  double cp, sp;
  if(cw >= 0) { cp = std::sqrt((1 + cw) / 2); sp = sw / (2 * cp); }
  else { sp = std::sqrt((1 - cw) / 2); if(sw < 0) sp = -sp; cp = sw / (2 * sp); }
  const double ct = cp * c1 + sp * s1, st = sp * c1 - cp * s1;
  U << cp, -sp, sp, cp;
  // V^T is the rotation by theta
  V << ct, st, -st, ct;
  // Q - R would cancel on thin triangles (s2 << s1); det / s1 may round above s1 on a similarity
  s << Q + R, (std::min)(Q + R, det / (Q + R));
  return true;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_ROTATION_SVD_2X2_H
