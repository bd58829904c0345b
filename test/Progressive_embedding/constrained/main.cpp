// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

// test_constrained DATA_DIR GROUP: runs one registered group (see registry.h); `list` prints them.

#include "registry.h"

#include <cstdlib>
#include <iostream>

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: " << argv[0] << " DATA_DIR GROUP|list" << std::endl;
    return EXIT_FAILURE;
  }
  const std::string data = argv[1], group = argv[2];
  if(group == "list")
  {
    for(const auto& g : pe_test::groups()) std::cout << g.first << "\n";
    return EXIT_SUCCESS;
  }
  const auto it = pe_test::groups().find(group);
  if(it == pe_test::groups().end())
  {
    std::cerr << "test_constrained: no group '" << group << "' (run with 'list')" << std::endl;
    return EXIT_FAILURE;
  }
  if(it->second(data) != EXIT_SUCCESS)
  {
    std::cerr << "test_constrained " << group << ": FAILED" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "test_constrained " << group << ": all checks passed" << std::endl;
  return EXIT_SUCCESS;
}
