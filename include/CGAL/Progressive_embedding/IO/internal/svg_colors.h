// Copyright (c) 2026 Progressive_embedding contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_COLORS_H
#define CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_COLORS_H

// The colors of a picture: the distortion scale (energies to colors) and the patch colors (a
// palette, and a coloring in which adjacent patches differ).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace IO {
namespace internal {

// Sequential color scale (YlGnBu): light for low energies, dark blue for high ones; red, the
// color of flipped faces, is not on it.
struct Svg_color_map
{
  static const std::array<std::array<int, 3>, 5>& stops()
  {
    static const std::array<std::array<int, 3>, 5> s = {{
      {{0xff, 0xff, 0xd9}}, {{0xc7, 0xe9, 0xb4}}, {{0x41, 0xb6, 0xc4}}, {{0x22, 0x5e, 0xa8}}, {{0x08, 0x1d, 0x58}} }};
    return s;
  }

  static std::string hex(const std::array<int, 3>& c)
  {
    static const char* digits = "0123456789abcdef";
    std::string s = "#";
    for(int k = 0; k < 3; ++k) { s += digits[(c[k] >> 4) & 15]; s += digits[c[k] & 15]; }
    return s;
  }

  // the color at t in [0, 1]
  static std::string color(double t)
  {
    if(!(t >= 0)) t = 0;
    if(t > 1) t = 1;
    const int n = int(stops().size());
    const double x = t * (n - 1);
    int i = int(std::floor(x));
    if(i >= n - 1) i = n - 2;
    const double a = x - i;
    std::array<int, 3> c;
    for(int k = 0; k < 3; ++k)
      c[k] = int(std::lround((1 - a) * stops()[std::size_t(i)][std::size_t(k)] + a * stops()[std::size_t(i) + 1][std::size_t(k)]));
    return hex(c);
  }
};

// the number of light qualitative colors of svg_patch_color()
constexpr std::size_t svg_patch_palette_size = 10;

// The fill color of the patch color class `k`: light qualitative colors (none red, the color of
// flipped faces), then, past them, hues spaced by the golden angle.
inline std::string svg_patch_color(std::size_t k)
{
  static const char* palette[svg_patch_palette_size] = { "#8dd3c7", "#ffffb3", "#bebada", "#80b1d3", "#fdb462",
                                                         "#b3de69", "#fccde5", "#d9d9d9", "#bc80bd", "#ccebc5" };
  const std::size_t n = svg_patch_palette_size;
  if(k < n) return palette[k];
  const double h = std::fmod(double(k - n) * 137.508, 360.) / 60., s = 0.55, l = 0.75;
  const double c = (1 - std::abs(2 * l - 1)) * s, x = c * (1 - std::abs(std::fmod(h, 2.) - 1)), m = l - c / 2;
  double r = 0, g = 0, b = 0;
  switch(int(h))
  {
    case 0: r = c; g = x; break;
    case 1: r = x; g = c; break;
    case 2: g = c; b = x; break;
    case 3: g = x; b = c; break;
    case 4: r = x; b = c; break;
    default: r = c; b = x; break;
  }
  const std::array<int, 3> rgb = {{ int(std::lround((r + m) * 255)), int(std::lround((g + m) * 255)), int(std::lround((b + m) * 255)) }};
  return Svg_color_map::hex(rgb);
}

// Colors of the patches 0..P-1 such that two adjacent patches differ: greedy coloring in the reverse
// of a smallest-last order, each patch taking, among the colors its colored neighbors do not use, the
// palette color used least so far (so that up to a palette of patches all differ), and a color past
// the palette only when its neighbors use all of the palette.
inline std::vector<std::size_t> svg_color_patches(const std::vector<std::vector<std::size_t> >& adjacency)
{
  const std::size_t P = adjacency.size();
  std::vector<std::size_t> degree(P), order, color(P, 0);
  std::vector<char> removed(P, 0), colored(P, 0);
  std::set<std::pair<std::size_t, std::size_t> > queue;
  for(std::size_t i = 0; i < P; ++i) { degree[i] = adjacency[i].size(); queue.emplace(degree[i], i); }
  while(!queue.empty()) // each patch leaves the queue once
  {
    const std::size_t i = queue.begin()->second;
    queue.erase(queue.begin());
    removed[i] = 1;
    order.push_back(i);
    for(std::size_t j : adjacency[i])
      if(!removed[j]) { queue.erase(std::make_pair(degree[j], j)); queue.emplace(--degree[j], j); }
  }
  std::vector<char> used;
  std::vector<std::size_t> uses(svg_patch_palette_size, 0);
  for(std::size_t k = P; k-- > 0; )
  {
    const std::size_t i = order[k];
    used.assign((std::max)(svg_patch_palette_size, adjacency[i].size() + 1), 0);
    for(std::size_t j : adjacency[i])
      if(colored[j] && color[j] < used.size()) used[color[j]] = 1;
    std::size_t c = used.size();
    for(std::size_t q = 0; q < svg_patch_palette_size; ++q)
      if(!used[q] && (c == used.size() || uses[q] < uses[c])) c = q;
    if(c == used.size())
    {
      c = svg_patch_palette_size;
      while(used[c]) ++c; // a free color among the first degree + 1
    }
    else ++uses[c];
    color[i] = c;
    colored[i] = 1;
  }
  return color;
}

// Logarithmic energy scale from `lo` (at most 4, the isometry) to `hi`.
struct Svg_energy_scale
{
  double lo = 4, hi = 40;
  double position(double e) const
  {
    if(std::isnan(e) || e >= hi) return 1.;
    if(!(e > lo)) return 0.;
    return std::log(e / lo) / std::log(hi / lo);
  }
};

// The scale of the faces drawn correctly oriented (`kind` 1) with a finite energy: from the isometry
// value 4 (or below) to the largest of those energies, at least a decade.
inline Svg_energy_scale svg_energy_scale(const std::vector<int>& kind, const std::vector<double>& energy)
{
  double lo = 4, hi = 0;
  for(std::size_t f = 0; f < kind.size(); ++f)
    if(kind[f] == 1 && std::isfinite(energy[f])) { lo = (std::min)(lo, energy[f]); hi = (std::max)(hi, energy[f]); }
  if(!(lo > 0)) lo = 4;
  Svg_energy_scale scale;
  scale.lo = lo;
  scale.hi = (std::max)(hi, 10 * lo);
  return scale;
}

// the color level, 0 to `levels` - 1, of the energy `e`, and its color
inline int svg_level(const Svg_energy_scale& scale, double e, int levels)
{
  return int(std::lround(scale.position(e) * (levels - 1)));
}

inline std::string svg_level_color(int level, int levels)
{
  return Svg_color_map::color(double(level) / double(levels - 1));
}

} // namespace internal
} // namespace IO
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_IO_INTERNAL_SVG_COLORS_H
