// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// `pe generate`: test inputs (the deep stacked triangulation, a grid disk).

#include "pe.h"

#include <CGAL/Progressive_embedding/internal/disk_generators.h>

#include <cmath>

namespace pe_tool {

int cmd_generate(const Arguments& a)
{
  const std::string& kind = a.positional[0];
  if(kind != "stacked" && kind != "grid") return usage("generate needs 'stacked DEPTH OUT.obj' or 'grid N OUT.obj', not '" + kind + "'");
  unsigned long long n = 0;
  std::string why;
  const bool grid = kind == "grid";
  if(!parse_count(a.positional[1], grid ? 2 : 0, grid ? 4000 : 100000, n, why))
    return usage(std::string(grid ? "N" : "DEPTH") + ": " + why);
  Run run(a);
  run.result.add("output", a.positional[2]);
  run.summary << "generate " << kind << " " << n << " -> " << a.positional[2] << ": ";
  Input in;
  in.uv = in.mesh.add_property_map<vertex_descriptor, Point_2>("v:pe_uv", Point_2(0, 0)).first;
  if(!grid)
  {
    const auto c = PE::internal::make_stacked_triangulation(static_cast<std::size_t>(n), in.mesh);
    in.uv[c[0]] = Point_2(0, 0);
    in.uv[c[1]] = Point_2(0.5, std::sqrt(3.) / 2);
    in.uv[c[2]] = Point_2(1, 0);
  }
  else
  {
    PE::internal::make_grid_disk(static_cast<std::size_t>(n), in.mesh);
    for(vertex_descriptor v : vertices(in.mesh)) in.uv[v] = Point_2(in.mesh.point(v).x(), in.mesh.point(v).y());
  }
  run.result.add("status", "OK");
  return write_and_finish(run, in, a.positional[2], certify(in));
}

} // namespace pe_tool
