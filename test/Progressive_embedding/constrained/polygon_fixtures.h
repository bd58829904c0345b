// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Target polygons shared by the constrained-map tests: the outline of a thickened Hilbert curve
// (a space-filling-curve border, the paper's stress test), with or without its flat vertices; a polygon
// that wraps around one of its vertices (an interior angle beyond 2 pi).

#ifndef PE_TEST_CONSTRAINED_POLYGON_FIXTURES_H
#define PE_TEST_CONSTRAINED_POLYGON_FIXTURES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace pe_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;

// The outline of the Hilbert curve of the given order thickened into cells (a curve point every
// second cell, a connecting cell between consecutive points), counterclockwise, a vertex at every
// unit step: many flat vertices.
inline std::vector<Epick::Point_2> hilbert_outline(int order)
{
  const int n = 1 << order, S = 2 * n + 1;
  std::vector<char> cell(S * S, 0);
  auto at = [&](int x, int y) -> char& { return cell[(y + 1) * S + x + 1]; };
  auto d2xy = [&](int d, int& x, int& y) {
    x = y = 0;
    for(int s = 1, t = d; s < n; s *= 2, t /= 4)
    {
      const int rx = 1 & (t / 2), ry = 1 & (t ^ rx);
      if(ry == 0) { if(rx == 1) { x = s - 1 - x; y = s - 1 - y; } std::swap(x, y); }
      x += s * rx; y += s * ry;
      }
  };
  int px = 0, py = 0;
  for(int d = 0; d < n * n; ++d)
  {
    int x, y;
    d2xy(d, x, y);
    at(2 * x, 2 * y) = 1;
    if(d > 0) at(x + px, y + py) = 1; // the cell between (2 px, 2 py) and (2 x, 2 y)
    px = x; py = y;
  }
  auto filled = [&](int x, int y) { return x >= 0 && y >= 0 && x < S - 2 && y < S - 2 && at(x, y); };
  // directed unit border edges with the filled cell on their left
  std::map<std::pair<int, int>, std::pair<int, int> > next;
  for(int y = 0; y < S - 2; ++y)
    for(int x = 0; x < S - 2; ++x)
    {
      if(!filled(x, y)) continue;
      if(!filled(x, y - 1)) next[std::make_pair(x, y)] = std::make_pair(x + 1, y);
      if(!filled(x + 1, y)) next[std::make_pair(x + 1, y)] = std::make_pair(x + 1, y + 1);
      if(!filled(x, y + 1)) next[std::make_pair(x + 1, y + 1)] = std::make_pair(x, y + 1);
      if(!filled(x - 1, y)) next[std::make_pair(x, y + 1)] = std::make_pair(x, y);
    }
  std::vector<Epick::Point_2> P;
  std::pair<int, int> v = next.begin()->first;
  for(std::size_t guard = 0; guard <= next.size(); ++guard)
  {
    P.push_back(Epick::Point_2(v.first, v.second));
    v = next[v];
    if(v == next.begin()->first) break;
  }
  return P;
}

// the same polygon without its flat vertices (exact: integer coordinates)
inline std::vector<Epick::Point_2> hilbert_corners(int order)
{
  const std::vector<Epick::Point_2> P = hilbert_outline(order);
  std::vector<Epick::Point_2> Q;
  for(std::size_t k = 0, n = P.size(); k < n; ++k)
    if(CGAL::orientation(P[(k + n - 1) % n], P[k], P[(k + 1) % n]) != CGAL::COLLINEAR) Q.push_back(P[k]);
  return Q;
}


// A polygon whose border winds `angle` radians (beyond 2 pi) around its vertex 0 = (0, 0): vertex 0, then
// the points at the angles t = angle k / steps (k = 0 .. steps) on the spiral of radius 1 + t / 10 (so
// that consecutive turns do not meet), counterclockwise. Its angle at vertex 0 is `angle`: in (0, 2 pi)
// that is angle - 2 pi r, with r = floor(angle / (2 pi)) the rotation index of vertex 0. The fan of the
// triangles (0, k, k + 1) triangulates the immersed disk (each of them positive when angle / steps < pi).
inline std::vector<Epick::Point_2> wrapped_fan_polygon(double angle, std::size_t steps)
{
  std::vector<Epick::Point_2> P(1, Epick::Point_2(0, 0));
  for(std::size_t k = 0; k <= steps; ++k)
  {
    const double t = angle * double(k) / double(steps), r = 1 + t / 10;
    P.push_back(Epick::Point_2(r * std::cos(t), r * std::sin(t)));
  }
  return P;
}

} // namespace pe_test

#endif // PE_TEST_CONSTRAINED_POLYGON_FIXTURES_H
