#!/usr/bin/env bash
# Builds the test suite with AddressSanitizer and UndefinedBehaviorSanitizer (frame pointers kept; -O1,
# except the test programs, whose own -O2 comes after the build type's flags) in build-sanitize/ and runs it, the bad-input suite included. The constrained
# tests are compiled as 4 units instead of one (instrumented, the single unit took 15 GB of memory
# to compile and was killed when other work needed memory too). Any sanitizer report fails the
# run: ASan aborts on the first error, and UBSan is made fatal too. Timeouts are tripled
# (PE_TEST_TIMEOUT_FACTOR): instrumented tests run several times slower.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
dir=${SANITIZE_BUILD_DIR:-build-sanitize}
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all"
# -O1 and line tables only (-g1) through the build type's own flags: given in CMAKE_CXX_FLAGS, -O1 came before the
# build type's -O2 -g on the command line and lost. A sanitizer report needs function names and lines, not variables.
# The test programs add -O2 after these (test/Progressive_embedding/CMakeLists.txt, as in every build); everything
# else is built at -O1.
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBUILD_TESTING=ON \
      -DPE_BUILD_DOC=OFF -DPE_BUILD_BENCHMARKS=OFF -DPE_EXAMPLES_TOGETHER=ON -DPE_TEST_TIMEOUT_FACTOR=3 \
      -DPE_CONSTRAINED_UNITY_GROUPS=4 \
      -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
      -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined"
cmake --build "$dir" -j"$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
# one suppression, explained in the file: CGAL's arrangement faces (the overlay of the compatible meshes)
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:suppressions=$PWD/scripts/ubsan_suppressions.txt
# the bad-input suite limits address space, which AddressSanitizer cannot run under
export PE_BAD_INPUT_MEMORY_LIMIT_MB=0
# The install/find_package test rebuilds a consumer without the sanitizer flags, and the study is
# a benchmark; everything else runs.
ctest --test-dir "$dir" --output-on-failure -j2 -E '^(find_package|comparison_study_quick|headers_[01]|benchmarks_compile)$' "$@"
