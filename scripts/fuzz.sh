#!/usr/bin/env bash
# Fuzzes the package with libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer: builds one
# binary per fuzz target of test/fuzz/ (clang), runs the targets one after the other, prints per
# target the executions, executions per second and findings, and copies every finding (crash,
# timeout, leak, out-of-memory input) into test/fuzz/corpus/<target>/ as a regression input, which
# `ctest -L fuzz` then replays (it fails until the cause is fixed).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive

usage() {
  cat <<'EOF'
usage: scripts/fuzz.sh [-t SECONDS | -r RUNS] [-b BUILD_DIR] [-j JOBS] [-n] [-l] [TARGET...]

  -t SECONDS   run each target for SECONDS seconds (default 60)
  -r RUNS      run each target for RUNS executions instead
  -b DIR       build folder, outside the source tree (default /tmp/pe-fuzz-build); the corpora that
               the runs grow are kept in DIR/corpus/<target>, the findings in DIR/artifacts/<target>
  -j JOBS      parallel compilations (default 1)
  -n           build only
  -l           list the targets
  TARGET...    the targets to build and run (default: all)

One target runs at a time, under `nice -n 10`. The exit status is 1 if a target had a finding.
Installs clang and libfuzzer-14-dev (and the packages of scripts/setup.sh) when missing.
EOF
}

cd "$(dirname "$0")/.."
src=$(pwd)
seconds=60
runs=
build=/tmp/pe-fuzz-build
jobs=1
build_only=0
while getopts "t:r:b:j:nlh" opt; do
  case $opt in
    t) seconds=$OPTARG; runs= ;;
    r) runs=$OPTARG ;;
    b) build=$OPTARG ;;
    j) jobs=$OPTARG ;;
    n) build_only=1 ;;
    l) grep -ho '^PE_FUZZ_TARGET_FUNCTION([a-z_0-9]*)' test/fuzz/*.h | sed 's/.*(\(.*\))/\1/' | sort; exit 0 ;;
    h) usage; exit 0 ;;
    *) usage >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
case "$build" in
  "$src"|"$src"/*) echo "fuzz.sh: the build folder must be outside the source tree" >&2; exit 2 ;;
esac

# ---- packages ---------------------------------------------------------------------------------
scripts/setup.sh
missing=()
for p in clang libfuzzer-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "fuzz.sh: installing ${missing[*]}"
  sudo=()
  if [ "$(id -u)" -ne 0 ]; then sudo=(sudo env DEBIAN_FRONTEND=noninteractive); fi
  "${sudo[@]}" apt-get update
  "${sudo[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
fi

# ---- targets ----------------------------------------------------------------------------------
all_targets=$(grep -ho '^PE_FUZZ_TARGET_FUNCTION([a-z_0-9]*)' test/fuzz/*.h | sed 's/.*(\(.*\))/\1/' | sort)
if [ $# -gt 0 ]; then targets=("$@"); else read -r -a targets <<< "$(echo $all_targets)"; fi
for t in "${targets[@]}"; do
  if ! grep -qx "$t" <<< "$all_targets"; then echo "fuzz.sh: unknown target '$t' (-l lists them)" >&2; exit 2; fi
done

# ---- build ------------------------------------------------------------------------------------
# -O2 with frame pointers for readable reports; CGAL's assertions on (no NDEBUG) and expensive
# preconditions too, as in the test programs; every sanitizer report is fatal.
mkdir -p "$build/obj" "$build/bin"
cxx=(nice -n 10 clang++ -std=gnu++17 -O2 -g -fno-omit-frame-pointer -fno-sanitize-recover=all
     -DCGAL_CHECK_EXPENSIVE -DCGAL_EIGEN3_ENABLED -I"$src/include" -I"$src/tools/pe" -isystem /usr/include/eigen3
     -ffunction-sections -w)
san=-fsanitize=address,undefined
libs=(-lgmp -lmpfr -Wl,--gc-sections)
# rebuilt when a source is newer than the binary
stale() { [ ! -e "$1" ] || [ -n "$(find "$src/include" "$src/tools/pe" "$src/test/fuzz" -newer "$1" -name '*.[ch]*' -print -quit)" ]; }

# the pe line readers: the tool's own sources, main() renamed; --gc-sections drops main.cpp's table
# of commands, which are not linked. main.cpp gets no coverage instrumentation: its tables would
# keep that table alive (the readers call only its number parser and failure report).
build_pe_objects() {
  local o=$build/obj
  if stale "$o/input_output.o"; then "${cxx[@]}" $san -fsanitize=fuzzer-no-link -c tools/pe/input_output.cpp -o "$o/input_output.o"; fi
  if stale "$o/pe_main.o"; then "${cxx[@]}" $san -Dmain=pe_tool_main -c tools/pe/main.cpp -o "$o/pe_main.o"; fi
}

build_target() {
  local t=$1 header extra=()
  header=$(grep -l "^PE_FUZZ_TARGET_FUNCTION($t)" test/fuzz/*.h | head -1)
  header=$(basename "$header")
  if [ "$header" = pe_lines.h ]; then extra=("$build/obj/input_output.o" "$build/obj/pe_main.o"); fi
  local bin=$build/bin/fuzz_$t
  if stale "$bin"; then
    echo "fuzz.sh: building $bin"
    "${cxx[@]}" $san,fuzzer -DPE_FUZZ_TARGET="$t" -DPE_FUZZ_HEADER="\"$header\"" test/fuzz/fuzz_main.cpp "${extra[@]}" \
      "${libs[@]}" -o "$bin.tmp"
    mv "$bin.tmp" "$bin"
  fi
}

for t in "${targets[@]}"; do
  if grep -q "^PE_FUZZ_TARGET_FUNCTION($t)" test/fuzz/pe_lines.h; then build_pe_objects; break; fi
done
running=0
for t in "${targets[@]}"; do
  build_target "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then wait -n; running=$((running - 1)); fi
done
while [ "$running" -gt 0 ]; do wait -n; running=$((running - 1)); done
for t in "${targets[@]}"; do [ -x "$build/bin/fuzz_$t" ] || { echo "fuzz.sh: fuzz_$t was not built" >&2; exit 1; }; done
[ "$build_only" -eq 1 ] && exit 0

# ---- run --------------------------------------------------------------------------------------
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
summary=()
for t in "${targets[@]}"; do
  corpus=$build/corpus/$t
  artifacts=$build/artifacts/$t
  mkdir -p "$corpus" "$artifacts"
  # the readers need room for long lines and headers; the decoders of small maps read few bytes
  case $t in read_*|pe_*) max_len=8192 ;; *) max_len=512 ;; esac
  dict=()
  case $t in read_*) dict=(-dict=test/fuzz/mesh_formats.dict) ;; esac
  budget=(-max_total_time="$seconds")
  if [ -n "$runs" ]; then budget=(-runs="$runs"); fi
  log=$build/fuzz_$t.log
  touch "$build/.start_$t"
  echo "fuzz.sh: running $t (${runs:+$runs runs}${runs:-$seconds s}), log $log"
  set +e
  # new inputs go to the first folder (the build's), the committed corpus seeds the run
  nice -n 10 "$build/bin/fuzz_$t" "${budget[@]}" -timeout=30 -rss_limit_mb=2560 -max_len="$max_len" \
    -print_final_stats=1 -artifact_prefix="$artifacts/" "${dict[@]}" "$corpus" "test/fuzz/corpus/$t" > "$log" 2>&1
  rc=$?
  set -e
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  if [ -z "$execs" ]; then execs=$(grep -o '^#[0-9]*' "$log" | tail -1 | tr -d '#'); fi
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  findings=()
  while IFS= read -r f; do findings+=("$(basename "$f")"); done < <(find "$artifacts" -type f -newer "$build/.start_$t")
  if [ "$rc" -ne 0 ] || [ ${#findings[@]} -gt 0 ]; then
    status=1
    for f in "${findings[@]}"; do
      # a regression input, named by its kind and content
      cp "$artifacts/$f" "test/fuzz/corpus/$t/regression-$f"
      echo "fuzz.sh: $t: finding $artifacts/$f, copied to test/fuzz/corpus/$t/regression-$f"
    done
    grep -m1 -E 'FUZZ FINDING|ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error' "$log" || true
  fi
  summary+=("$(printf '%-24s %12s executions %8s exec/s %3d findings (exit %d)' "$t" "${execs:-?}" "${rate:-?}" "${#findings[@]}" "$rc")")
done
echo
echo "fuzz.sh: ASan+UBSan, ${runs:+$runs runs}${runs:-$seconds s} per target"
printf '%s\n' "${summary[@]}"
exit $status
