// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// Benchmark helpers for the drivers' options and tables: splitting a list option, true medians, fixed-point
// numbers.

#ifndef PE_BENCHMARK_TABLE_UTIL_H
#define PE_BENCHMARK_TABLE_UTIL_H

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace pe_bench {

// "a,b,,c" -> {"a", "b", "", "c"}
inline std::vector<std::string> split(const std::string& s, char c)
{
  std::vector<std::string> out;
  std::string cur;
  for(char ch : s) { if(ch == c) { out.push_back(cur); cur.clear(); } else cur += ch; }
  out.push_back(cur);
  return out;
}

// the median (the mean of the two middle values for an even count; 0 for none)
inline double median(std::vector<double> v)
{
  if(v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t k = v.size() / 2;
  return v.size() % 2 ? v[k] : 0.5 * (v[k - 1] + v[k]);
}

// x with d digits after the point
inline std::string fixed(double x, int d)
{
  std::ostringstream os;
  os << std::fixed << std::setprecision(d) << x;
  return os.str();
}

} // namespace pe_bench

#endif // PE_BENCHMARK_TABLE_UTIL_H
