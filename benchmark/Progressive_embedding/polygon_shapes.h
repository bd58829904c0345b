// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Benchmark fixtures: the polygons of the polygon benchmarks (counterclockwise):
//  - convex(n): regular n-gon;
//  - star(n): n/2 tips, radii 1 and 0.4;
//  - spiral(n): a strip of width 0.6 along the spiral r = 1 + 0.4 t / (2 pi), t in [0, 4 pi], 2 (n/2)
//    vertices (n/2 per side, or n/2 + 1 outside and n/2 - 1 inside when n/2 is odd): it winds twice
//    and overlaps itself (weakly self-overlapping, not simple) but never touches itself: two turns
//    overlap by 0.6 - 0.4 = 0.2, the end cap lies 2 * 0.4 - 0.6 = 0.2 beyond the start cap, and no
//    vertex but the caps' lies on the caps' direction (each side has an odd number of steps, so none
//    at t = 2 pi, where it would lie on a cap in exact arithmetic); empty for n < 16 (too coarse);
//  - hilbert(order): the outline of the Hilbert curve of that order thickened into a polyomino (cells at
//    even grid positions and their connectors), a vertex at every unit step (collinear runs, vertices on
//    diagonals); corners_only() keeps its corners.

#ifndef PE_BENCHMARK_POLYGON_SHAPES_H
#define PE_BENCHMARK_POLYGON_SHAPES_H

#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace pe_bench {

template <class Point>
struct Shapes
{
  static constexpr double two_pi = 6.283185307179586;

  static std::vector<Point> convex(std::size_t n)
  {
    std::vector<Point> P;
    for(std::size_t k = 0; k < n; ++k) P.push_back(Point(std::cos(two_pi * k / n), std::sin(two_pi * k / n)));
    return P;
  }

  static std::vector<Point> star(std::size_t n)
  {
    std::vector<Point> P;
    for(std::size_t k = 0; k < n; ++k)
    {
      const double r = (k % 2) ? 0.4 : 1.0;
      P.push_back(Point(r * std::cos(two_pi * k / n), r * std::sin(two_pi * k / n)));
    }
    return P;
  }

  static std::vector<Point> spiral(std::size_t n)
  {
    // a pitch of 0.3 (half the width) made the end cap's inner corner meet the start cap's outer
    // corner (r = 1.6 at angle 0): apart by 8e-16 only through the rounding of sin(4 pi)
    const double pitch = 0.4, width = 0.6;
    const std::size_t m = n / 2;
    // an even number of vertices per side: then no side has a vertex at t = 2 pi
    const std::size_t outer = m % 2 ? m + 1 : m, inner = 2 * m - outer;
    std::vector<Point> P;
    if(m < 8) return P; // too coarse: the chords of the two turns cross (n = 10 or 14 bounds no immersed disk)
    for(std::size_t k = 0; k < outer; ++k)
    {
      const double t = 2 * two_pi * double(k) / double(outer - 1), r = 1 + pitch * t / two_pi + width;
      P.push_back(Point(r * std::cos(t), r * std::sin(t)));
    }
    for(std::size_t k = inner; k-- > 0; )
    {
      const double t = 2 * two_pi * double(k) / double(inner - 1), r = 1 + pitch * t / two_pi;
      P.push_back(Point(r * std::cos(t), r * std::sin(t)));
    }
    return P;
  }

  // Hilbert curve of order `order`: cell d -> (x, y) (the classical iterative conversion)
  static void hilbert_d2xy(int side, int d, int& x, int& y)
  {
    x = y = 0;
    for(int s = 1, t = d; s < side; s *= 2, t /= 4)
    {
      const int rx = 1 & (t / 2), ry = 1 & (t ^ rx);
      if(ry == 0)
      {
        if(rx == 1) { x = s - 1 - x; y = s - 1 - y; }
        std::swap(x, y);
      }
      x += s * rx; y += s * ry;
    }
  }

  // the outline of the thickened Hilbert curve, counterclockwise, a vertex at every unit step
  static std::vector<Point> hilbert(int order)
  {
    const int side = 1 << order, S = 2 * side + 1;
    std::vector<char> g(std::size_t(S) * S, 0);
    auto at = [&](int x, int y) -> char& { return g[std::size_t(y) * S + x]; };
    int px = 0, py = 0;
    for(int d = 0; d < side * side; ++d)
    {
      int x, y;
      hilbert_d2xy(side, d, x, y);
      at(2 * x + 1, 2 * y + 1) = 1;
      if(d > 0) at(x + px + 1, y + py + 1) = 1; // the connector between two consecutive cells
      px = x; py = y;
    }
    std::map<std::pair<int, int>, std::pair<int, int> > next;
    for(int y = 1; y < S - 1; ++y)
      for(int x = 1; x < S - 1; ++x)
      {
        if(!at(x, y)) continue;
        if(!at(x, y - 1)) next[{ x, y }] = { x + 1, y };
        if(!at(x + 1, y)) next[{ x + 1, y }] = { x + 1, y + 1 };
        if(!at(x, y + 1)) next[{ x + 1, y + 1 }] = { x, y + 1 };
        if(!at(x - 1, y)) next[{ x, y + 1 }] = { x, y };
      }
    std::vector<Point> P;
    const std::pair<int, int> start = next.begin()->first;
    std::pair<int, int> v = start;
    do { P.push_back(Point(v.first, v.second)); v = next[v]; } while(v != start && P.size() <= next.size());
    return P;
  }

  // the polygon without its flat vertices (exact for the integer coordinates of hilbert())
  static std::vector<Point> corners_only(const std::vector<Point>& P)
  {
    std::vector<Point> C;
    const std::size_t n = P.size();
    for(std::size_t i = 0; i < n; ++i)
    {
      const Point& a = P[(i + n - 1) % n];
      const Point& b = P[i];
      const Point& c = P[(i + 1) % n];
      if((b.x() - a.x()) * (c.y() - b.y()) - (b.y() - a.y()) * (c.x() - b.x()) != 0) C.push_back(b);
    }
    return C;
  }
};

} // namespace pe_bench

#endif // PE_BENCHMARK_POLYGON_SHAPES_H
