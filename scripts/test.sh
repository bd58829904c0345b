#!/usr/bin/env bash
# Command 2 of the README: set-up, Release build of everything with the tests, and the
# whole test suite (ctest; the doxygen build and an install + find_package test included).
# The benchmark drivers that no test runs are not linked here: the test benchmarks_compile checks
# that they compile (syntax only, a third of the time); -DPE_BUILD_BENCHMARKS=ON builds them.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON -DPROGRESSIVE_EMBEDDING_PYTHON=ON -DPE_BUILD_BENCHMARKS=OFF
cmake --build build -j2
# two tests at a time (the machine has 2 cores); the tests that must run alone say so (RUN_SERIAL)
ctest --test-dir build --output-on-failure -j2
