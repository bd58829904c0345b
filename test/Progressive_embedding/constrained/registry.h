// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// The groups of test_constrained: each source file of this folder registers its groups with
// PE_TEST_GROUP(name) { ... return EXIT_SUCCESS; }, and `test_constrained DATA_DIR GROUP` runs one.
// One executable for every constrained-map test keeps the (heavy) link count low.

#ifndef CGAL_PROGRESSIVE_EMBEDDING_TEST_CONSTRAINED_REGISTRY_H
#define CGAL_PROGRESSIVE_EMBEDDING_TEST_CONSTRAINED_REGISTRY_H

#include <map>
#include <string>

namespace pe_test {

typedef int (*Group_function)(const std::string& data_dir);

inline std::map<std::string, Group_function>& groups()
{
  static std::map<std::string, Group_function> g;
  return g;
}

struct Register_group
{
  Register_group(const char* name, Group_function f) { groups()[name] = f; }
};

} // namespace pe_test

#define PE_TEST_GROUP(name)                                                          \
  static int pe_test_group_##name(const std::string& data_dir);                      \
  static const pe_test::Register_group pe_test_register_##name(#name, &pe_test_group_##name); \
  static int pe_test_group_##name(const std::string& data_dir)

#endif
