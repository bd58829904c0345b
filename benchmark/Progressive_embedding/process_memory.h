// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Benchmark helpers (Linux): the process's resident memory, from /proc/self/status; a measurement run
// in a child process (its own memory peak, a crash or a memory limit seen as such).

#ifndef PE_BENCHMARK_PROCESS_MEMORY_H
#define PE_BENCHMARK_PROCESS_MEMORY_H

#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

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

// Runs `child(fd)` in a forked process (with an address-space limit of `memory_mb` MB when positive)
// and returns what it wrote to `fd`; `status` receives its waitpid() status (-1 if it could not start).
template <class Child>
std::string run_in_child(Child child, double memory_mb, int& status)
{
  status = -1;
  int fds[2];
  if(pipe(fds) != 0) return std::string();
  const pid_t pid = fork();
  if(pid < 0) { close(fds[0]); close(fds[1]); return std::string(); }
  if(pid == 0)
  {
    close(fds[0]);
    if(memory_mb > 0)
    {
      struct rlimit rl;
      rl.rlim_cur = rl.rlim_max = static_cast<rlim_t>(memory_mb * 1024 * 1024);
      setrlimit(RLIMIT_AS, &rl);
    }
    child(fds[1]);
    close(fds[1]);
    _exit(0);
  }
  close(fds[1]);
  std::string out;
  char buf[512];
  ssize_t k;
  while((k = read(fds[0], buf, sizeof buf)) > 0) out.append(buf, std::size_t(k));
  close(fds[0]);
  waitpid(pid, &status, 0);
  return out;
}

} // namespace pe_bench

#endif // PE_BENCHMARK_PROCESS_MEMORY_H
