// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// The fuzz targets, in one translation unit (CGAL and Eigen headers are parsed once).
//
// Compiled normally, it is the replay program of the committed corpora (ctest label fuzz):
//   pe_fuzz_replay TARGET PATH...    runs every file of each PATH (a file or a folder) through TARGET
//   pe_fuzz_replay --list            prints the target names
// A finding aborts with its message.
//
// With -DPE_FUZZ_TARGET=name -DPE_FUZZ_HEADER='"header.h"' and clang's -fsanitize=fuzzer, it is the
// libFuzzer binary of that one target (scripts/fuzz.sh builds them), which compiles only its header.

#include <cstddef>
#include <cstdint>

#ifdef PE_FUZZ_TARGET

#include PE_FUZZ_HEADER

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  return pe_fuzz::PE_FUZZ_TARGET(data, size);
}

#else

#include "readers.h"
#include "pe_lines.h"
#include "check_embedding.h"
#include "check_immersion.h"
#include "progressive_embedding.h"
#include "triangulate_polygon.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <dirent.h>
#include <sys/stat.h>

namespace {

struct Target { const char* name; int (*run)(const std::uint8_t*, std::size_t); };

const Target targets[] = {
  { "read_off", &pe_fuzz::read_off },
  { "read_obj", &pe_fuzz::read_obj },
  { "read_ply", &pe_fuzz::read_ply },
  { "read_stl", &pe_fuzz::read_stl },
  { "read_obj_uv", &pe_fuzz::read_obj_uv },
  { "pe_fix_lines", &pe_fuzz::pe_fix_lines },
  { "pe_polygon_lines", &pe_fuzz::pe_polygon_lines },
  { "check_embedding", &pe_fuzz::check_embedding },
  { "check_immersion", &pe_fuzz::check_immersion },
  { "progressive_embedding", &pe_fuzz::progressive_embedding },
  { "triangulate_polygon", &pe_fuzz::triangulate_polygon },
};

// the files of `path` (itself if it is a file), sorted
std::vector<std::string> files_of(const std::string& path)
{
  std::vector<std::string> files;
  struct stat st;
  if(::stat(path.c_str(), &st) != 0) return files;
  if(!S_ISDIR(st.st_mode)) { files.push_back(path); return files; }
  if(DIR* d = ::opendir(path.c_str()))
  {
    while(const dirent* e = ::readdir(d))
    {
      const std::string f = path + "/" + e->d_name;
      if(e->d_name[0] != '.' && ::stat(f.c_str(), &st) == 0 && S_ISREG(st.st_mode)) files.push_back(f);
    }
    ::closedir(d);
  }
  std::sort(files.begin(), files.end());
  return files;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc == 2 && std::string(argv[1]) == "--list")
  {
    for(const Target& t : targets) std::printf("%s\n", t.name);
    return 0;
  }
  if(argc < 3)
  {
    std::fprintf(stderr, "usage: %s TARGET PATH...   (replays every file of each PATH through TARGET)\n"
                         "       %s --list\n", argv[0], argv[0]);
    return 2;
  }
  const std::string name = argv[1];
  const Target* target = nullptr;
  for(const Target& t : targets) if(name == t.name) target = &t;
  if(target == nullptr) { std::fprintf(stderr, "unknown target '%s' (--list gives them)\n", name.c_str()); return 2; }
  std::size_t count = 0;
  for(int a = 2; a < argc; ++a)
  {
    const std::vector<std::string> files = files_of(argv[a]);
    if(files.empty()) { std::fprintf(stderr, "%s: no input file\n", argv[a]); return 2; }
    for(const std::string& f : files)
    {
      std::ifstream in(f, std::ios::binary);
      const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      std::fprintf(stderr, "%s\n", f.c_str()); // names the input of a finding
      target->run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      ++count;
    }
  }
  std::printf("%s: %zu inputs replayed, no finding\n", target->name, count);
  return 0;
}

#endif
