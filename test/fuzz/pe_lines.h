// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Fuzz targets of the line readers of the `pe` tool (tools/pe/input_output.cpp, linked in): the
// --fix constraint files (`vertex_index u v` lines) and the polygon files (`x y` lines). Any input
// must be either refused as an input error, or give finite values and indices in range.
// They read files: each input is written to a file of its own first.

#ifndef PE_FUZZ_PE_LINES_H
#define PE_FUZZ_PE_LINES_H

#include "fuzz_util.h"

#include "pe.h"

#include <cstdio>
#include <unistd.h>

namespace pe_fuzz {

// A file holding the bytes, for the length of a call; in /dev/shm when there is one (no disk write)
class Temporary_file
{
  std::string name_;
public:
  Temporary_file(const std::uint8_t* data, std::size_t size)
  {
    const char* dir = ::access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    name_ = std::string(dir) + "/pe_fuzz_lines_" + std::to_string(::getpid()) + ".txt";
    std::FILE* f = std::fopen(name_.c_str(), "wb");
    PE_FUZZ_CHECK(f != nullptr, "cannot write the temporary file " << name_);
    if(size > 0) PE_FUZZ_CHECK(std::fwrite(data, 1, size, f) == size, "cannot write the temporary file " << name_);
    std::fclose(f);
  }
  ~Temporary_file() { std::remove(name_.c_str()); }
  const std::string& name() const { return name_; }
};

// Runs `read(run, filename)`, a line reader of the tool, on the bytes written to a file, silently:
// it must return success or an input error; true on success.
template <class Read>
bool read_lines(const std::uint8_t* data, std::size_t size, const char* what, Read read)
{
  const Temporary_file file(data, size);
  pe_tool::Arguments args;
  pe_tool::Run run(args);
  int status;
  {
    const Silence quiet;
    status = read(run, file.name());
  }
  PE_FUZZ_CHECK(status == pe_tool::EXIT_VALID || status == pe_tool::EXIT_INPUT, what << ": exit status " << status);
  return status == pe_tool::EXIT_VALID;
}

PE_FUZZ_TARGET_FUNCTION(pe_fix_lines)
{
  // a mesh of 16 vertices: the indices in the file are checked against this count
  static pe_tool::Input in;
  static bool made = false;
  if(!made)
  {
    for(int i = 0; i < 16; ++i) in.mesh.add_vertex(pe_tool::Point_3(i, 0, 0));
    in.uv = in.mesh.add_property_map<pe_tool::vertex_descriptor, pe_tool::Point_2>("v:pe_uv", pe_tool::Point_2(0, 0)).first;
    made = true;
  }
  for(pe_tool::vertex_descriptor v : vertices(in.mesh)) in.uv[v] = pe_tool::Point_2(0, 0);
  std::vector<pe_tool::vertex_descriptor> fixed;
  if(!read_lines(data, size, "--fix reader", [&](pe_tool::Run& run, const std::string& f) {
       return pe_tool::read_constraints(run, f, in, fixed); }))
    return 0;
  for(pe_tool::vertex_descriptor v : fixed)
  {
    PE_FUZZ_CHECK(std::size_t(v) < in.mesh.number_of_vertices(), "--fix reader: vertex " << std::size_t(v) << " out of range");
    PE_FUZZ_CHECK(std::isfinite(in.uv[v].x()) && std::isfinite(in.uv[v].y()), "--fix reader: a non-finite target");
  }
  return 0;
}

PE_FUZZ_TARGET_FUNCTION(pe_polygon_lines)
{
  std::vector<pe_tool::Point_2> points;
  if(!read_lines(data, size, "polygon reader", [&](pe_tool::Run& run, const std::string& f) {
       return pe_tool::read_polygon(run, f, points); }))
    return 0;
  for(const pe_tool::Point_2& p : points)
    PE_FUZZ_CHECK(std::isfinite(p.x()) && std::isfinite(p.y()), "polygon reader: a non-finite point");
  return 0;
}

} // namespace pe_fuzz

#endif // PE_FUZZ_PE_LINES_H
