// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Fuzz target of progressive_embedding(): a small disk whose border is put on a convex polygon
// (strictly convex lattice or rounded polygons, either orientation, the grid's square with its
// straight sides) or anywhere the input says, and whose interior vertices are anywhere the input
// says, all possibly scaled and translated. Whatever it returns, it must not crash or loop; OK
// requires a map that the brute-force certificate finds valid with the border bit-exactly kept,
// and any error an unchanged uv map.

#ifndef PE_FUZZ_PROGRESSIVE_EMBEDDING_H
#define PE_FUZZ_PROGRESSIVE_EMBEDDING_H

#include "fuzz_util.h"

#include <CGAL/Progressive_embedding/progressive_embedding.h>

namespace pe_fuzz {

inline std::uint64_t double_bits(double x) { std::uint64_t b; std::memcpy(&b, &x, sizeof b); return b; }

// the border positions: vertex d.border[k] gets the k-th corner of the polygon chosen by the input
inline void border_layout(Bytes& b, const Small_disk& d, std::vector<double>& xy)
{
  const std::size_t nb = d.border.size();
  const double pi = 3.14159265358979323846;
  const int mode = b.u8() % 6;
  for(std::size_t k = 0; k < nb; ++k)
  {
    const std::size_t v = d.border[k];
    const double a = 2 * pi * double(k) / double(nb);
    double x = 0, y = 0;
    switch(mode)
    {
      case 0: x = double(k); y = double(k * k); break;                       // parabola: strictly convex, counterclockwise
      case 1: x = std::cos(a); y = std::sin(a); break;                       // regular polygon, exact decisions on rounded points
      case 2: x = std::round(std::cos(a) * 1024) / 1024; y = -std::round(std::sin(a) * 1024) / 1024; break; // clockwise
      case 3:
        if(!d.grid.empty()) { x = d.grid[v][0]; y = d.grid[v][1]; }           // a square with straight sides
        else { x = -double(k); y = double(k * k); }                          // clockwise parabola
        break;
      default: x = coordinate(b); y = coordinate(b); break;                  // anything
    }
    xy[2 * v] = x;
    xy[2 * v + 1] = y;
  }
}

PE_FUZZ_TARGET_FUNCTION(progressive_embedding)
{
  Bytes b(data, size);
  const Small_disk d = small_disk(b);
  std::vector<double> xy(2 * d.nv, 0.);
  std::vector<char> on_border(d.nv, 0);
  for(std::size_t v : d.border) on_border[v] = 1;
  border_layout(b, d, xy);
  // the interior: anywhere, or all at one point (the collapsed start of the paper's examples)
  const bool one_point = (b.u8() % 4) == 0;
  double px = 0, py = 0;
  if(one_point) { px = coordinate(b); py = coordinate(b); }
  for(std::size_t v = 0; v < d.nv; ++v)
    if(!on_border[v])
    {
      xy[2 * v] = one_point ? px : coordinate(b);
      xy[2 * v + 1] = one_point ? py : coordinate(b);
    }
  transform(b, xy);

  Mesh m;
  std::vector<vertex_descriptor> V;
  build_mesh(d, m, V);
  Uv_map uv = m.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
  for(std::size_t i = 0; i < d.nv; ++i) uv[V[i]] = Point_2(xy[2 * i], xy[2 * i + 1]);

  // Small budgets, named: the maps have at most 16 vertices. An insertion that fails gets 2 retries of
  // 10 smoothing passes (not 20 of 50): a map that needs more returns an error, which is checked like
  // any other. The time budget only bounds what the counts do not; libFuzzer's timeout catches a loop
  // that ignores both.
  const PE::Error_code ec = PE::progressive_embedding(m, uv, PE::parameters::insertion_retries(2).retry_smoothing_iterations(10)
                                                               .line_search_factor(0.5).line_search_steps(25)
                                                               .maximum_running_time(0.25));
  std::vector<double> out(2 * d.nv);
  for(std::size_t i = 0; i < d.nv; ++i) { out[2 * i] = uv[V[i]].x(); out[2 * i + 1] = uv[V[i]].y(); }
  if(ec != PE::OK)
  {
    for(std::size_t i = 0; i < 2 * d.nv; ++i)
      PE_FUZZ_CHECK(double_bits(out[i]) == double_bits(xy[i]), "the uv map changed on " << PE::get_error_name(ec));
    return 0;
  }
  for(std::size_t v : d.border)
    PE_FUZZ_CHECK(double_bits(out[2 * v]) == double_bits(xy[2 * v]) && double_bits(out[2 * v + 1]) == double_bits(xy[2 * v + 1]),
                  "OK with border vertex " << v << " moved");
  const Embedding_oracle o = embedding_oracle(d, out);
  PE_FUZZ_CHECK(o.valid(), "OK with a map the brute force finds invalid: flipped " << o.flipped << ", degenerate "
                << o.degenerate << ", non-finite " << o.non_finite << ", border intersections " << o.border_intersections
                << ", overlapping pairs " << o.overlapping_pairs);
  return 0;
}

} // namespace pe_fuzz

#endif // PE_FUZZ_PROGRESSIVE_EMBEDDING_H
