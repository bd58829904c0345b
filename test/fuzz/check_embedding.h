// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Fuzz target of check_embedding(): a small disk with uv coordinates taken from the input (small
// integers, fractions, extreme and non-finite doubles, scaled and translated), whose certificate
// must equal the brute-force exact one of fuzz_util.h count for count. When the certificate skips
// the overlap test by the degree argument (every face positive, border simple), the brute force
// confirms that no two faces overlap.

#ifndef PE_FUZZ_CHECK_EMBEDDING_H
#define PE_FUZZ_CHECK_EMBEDDING_H

#include "fuzz_util.h"

#include <CGAL/Progressive_embedding/check_embedding.h>

namespace pe_fuzz {

// a small disk and its uv coordinates (x0, y0, x1, y1, ...) from the input
inline void small_map(Bytes& b, Small_disk& d, std::vector<double>& xy)
{
  d = small_disk(b);
  xy.resize(2 * d.nv);
  for(double& x : xy) x = coordinate(b);
  transform(b, xy);
}

inline void set_uv(const std::vector<vertex_descriptor>& V, const std::vector<double>& xy, Uv_map uv)
{
  for(std::size_t i = 0; i < V.size(); ++i) uv[V[i]] = Point_2(xy[2 * i], xy[2 * i + 1]);
}

PE_FUZZ_TARGET_FUNCTION(check_embedding)
{
  Bytes b(data, size);
  Small_disk d;
  std::vector<double> xy;
  small_map(b, d, xy);
  Mesh m;
  std::vector<vertex_descriptor> V;
  build_mesh(d, m, V);
  Uv_map uv = m.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
  set_uv(V, xy, uv);

  const PE::Embedding_report r = PE::check_embedding(m, uv);
  const Embedding_oracle o = embedding_oracle(d, xy);
  PE_FUZZ_CHECK(r.status == PE::OK, "a disk refused: " << PE::get_error_name(r.status));
  PE_FUZZ_CHECK(r.faces == d.faces.size() && r.vertices == d.nv && r.border_vertices == d.border.size(), "wrong counts");
  PE_FUZZ_CHECK(r.non_finite == o.non_finite, "non-finite " << r.non_finite << ", brute force " << o.non_finite);
  PE_FUZZ_CHECK(r.clockwise == (o.border_sign < 0), "clockwise " << r.clockwise << ", brute force border sign " << o.border_sign);
  PE_FUZZ_CHECK(r.flipped == o.flipped, "flipped " << r.flipped << ", brute force " << o.flipped);
  PE_FUZZ_CHECK(r.degenerate == o.degenerate, "degenerate " << r.degenerate << ", brute force " << o.degenerate);
  PE_FUZZ_CHECK(r.border_simple == o.border_simple(), "border simple " << r.border_simple << ", brute force "
                << o.border_simple() << " (" << o.border_intersections << " intersecting pairs)");
  if(o.border_finite)
    PE_FUZZ_CHECK(r.border_intersections == o.border_intersections,
                  "border intersections " << r.border_intersections << ", brute force " << o.border_intersections);
  PE_FUZZ_CHECK(r.overlap_checked, "overlap not decided on a map of " << d.faces.size() << " faces");
  if(r.overlap_by_degree_argument)
    PE_FUZZ_CHECK(o.overlapping_pairs == 0, "overlap excluded by the degree argument, but the brute force finds "
                  << o.overlapping_pairs << " overlapping pairs");
  else
    PE_FUZZ_CHECK(r.overlapping_pairs == o.overlapping_pairs,
                  "overlapping pairs " << r.overlapping_pairs << ", brute force " << o.overlapping_pairs);
  PE_FUZZ_CHECK(r.is_valid() == o.valid(), "is_valid() " << r.is_valid() << ", brute force " << o.valid());
  if(r.is_valid())
    PE_FUZZ_CHECK(!(r.min_signed_area < 0), "a valid map with a negative face area " << r.min_signed_area);
  return 0;
}

} // namespace pe_fuzz

#endif // PE_FUZZ_CHECK_EMBEDDING_H
