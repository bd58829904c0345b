#!/usr/bin/env bash
# Command 2 of the README: set-up, Release build of everything with the tests, and the
# whole test suite (ctest; the doxygen build and an install + find_package test included).
# The benchmark drivers that no test runs are not linked here: the test benchmarks_compile checks
# that they compile (syntax only, a third of the time); -DPE_BUILD_BENCHMARKS=ON builds them. The examples
# are linked as one program (PE_EXAMPLES_TOGETHER: one compilation of the templates they all share).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON -DPROGRESSIVE_EMBEDDING_PYTHON=ON -DPE_BUILD_BENCHMARKS=OFF \
      -DPE_EXAMPLES_TOGETHER=ON
cmake --build build -j2
# two tests at a time (the machine has 2 cores); the tests that must run alone say so (RUN_SERIAL).
# ctest starts the longest tests first when it knows their times: a fresh build gets the times of a
# full run on a 2-core machine (test/ctest_cost_data.txt), so that no long test is left to run alone at
# the end; ctest then keeps its own measurements.
if [ ! -e build/Testing/Temporary/CTestCostData.txt ]; then
  mkdir -p build/Testing/Temporary
  cp test/ctest_cost_data.txt build/Testing/Temporary/CTestCostData.txt
fi
ctest --test-dir build --output-on-failure -j2
