// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Benchmark helpers (Linux): the process's resident memory, from /proc/self/status.

#ifndef PE_BENCHMARK_PROCESS_MEMORY_H
#define PE_BENCHMARK_PROCESS_MEMORY_H

#include <cstdlib>
#include <fstream>
#include <string>

namespace pe_bench {

// the value of a `Vm...:` line of /proc/self/status, in MB (0 if absent)
inline double status_mb(const char* key)
{
  std::ifstream f("/proc/self/status");
  const std::string k(key);
  std::string line;
  while(std::getline(f, line))
    if(line.compare(0, k.size(), k) == 0) return std::atof(line.c_str() + k.size()) / 1024.;
  return 0;
}

// peak resident memory since the process started or the last reset_peak_rss()
inline double peak_rss_mb() { return status_mb("VmHWM:"); }
inline double current_rss_mb() { return status_mb("VmRSS:"); }

// resets the peak to the current size (clear_refs 5); false if the kernel refuses
inline bool reset_peak_rss()
{
  std::ofstream f("/proc/self/clear_refs");
  f << "5" << std::flush;
  return bool(f);
}

} // namespace pe_bench

#endif // PE_BENCHMARK_PROCESS_MEMORY_H
