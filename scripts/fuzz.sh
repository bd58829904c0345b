#!/usr/bin/env bash
# Fuzzes the package with libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer: builds one
# binary per fuzz target of test/fuzz/ (clang), runs the targets, copies every finding (crash,
# timeout, leak, out-of-memory input) into test/fuzz/corpus/<target>/ as a regression input, which
# `ctest -L fuzz` then replays (it fails until the cause is fixed), and keeps the campaigns' account:
# the corpora grow in the build folder from run to run, each run appends a row to
# test/fuzz/campaigns.csv, and the per-target totals are printed and written to test/fuzz/campaigns.md.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive

usage() {
  cat <<'EOF'
usage: scripts/fuzz.sh [-t SECONDS | -r RUNS] [-b BUILD_DIR] [-j JOBS] [-p PROCESSES] [-n] [-s] [-l] [TARGET...]

  -t SECONDS    run each target for SECONDS seconds (default 60)
  -r RUNS       run each target for RUNS executions instead
  -b DIR        build folder, outside the source tree and kept between sessions (default: fuzz-build
                next to the source tree); the corpora that the runs grow are kept in DIR/corpus/<target>
                and seed the next runs, the findings in DIR/artifacts/<target>, the logs in DIR/logs/
  -j JOBS       parallel compilations (default 1)
  -p PROCESSES  targets fuzzed at the same time (default 1; at most 2 on a shared machine)
  -n            build only
  -s            print the campaign summary only (and write it to test/fuzz/campaigns.md)
  -l            list the targets
  TARGET...     the targets to build and run (default: all); those with the fewest counted
                executions run first

Everything runs under `nice -n 19`, so that fuzzing takes only idle CPU. With Linux's autogroup
scheduling (kernel.sched_autogroup_enabled=1, the default) niceness only ranks processes of one
session, and each session gets an equal share: a nice-19 fuzzer started from another session took half
of a CPU from a compiler (measured on the 2-core VM). The fuzzers therefore run in a session of their
own (setsid) whose autogroup is given nice 19 (/proc/self/autogroup). The exit status is 1 if a
target had a finding.

The account: each run appends to test/fuzz/campaigns.csv the row
  date, target, harness, executions, seconds, exec_per_s, findings, sanitizers, commit, machine, command
where `harness` is a hash of the test/fuzz sources that the target compiles (its header, the headers
that one includes, fuzz_main.cpp) and `commit` the git commit of the sources (+modified when include/,
tools/pe/ or test/fuzz/ differ from it). The summary counts, per target, only the executions under
AddressSanitizer and UBSan of the current harness: the rows of an older harness are listed apart and
do not count. A finding is open while its regression input test/fuzz/corpus/<target>/regression-*
still fails.

Installs clang and libfuzzer-14-dev (and the packages of scripts/setup.sh) when missing.
EOF
}

cd "$(dirname "$0")/.."
src=$(pwd)
# Runs a command at the lowest priority: nice 19, in a session of its own whose autogroup has nice 19
# too (see the usage above; without autogroup scheduling the write fails and nice alone suffices).
lowest() {
  setsid -w bash -c 'echo 19 > /proc/self/autogroup 2> /dev/null; exec nice -n 19 "$@"' lowest "$@"
}
command_line="scripts/fuzz.sh $*"
seconds=60
runs=
build=$(dirname "$src")/fuzz-build
jobs=1
processes=1
build_only=0
summary_only=0
while getopts "t:r:b:j:p:nslh" opt; do
  case $opt in
    t) seconds=$OPTARG; runs= ;;
    r) runs=$OPTARG ;;
    b) build=$OPTARG ;;
    j) jobs=$OPTARG ;;
    p) processes=$OPTARG ;;
    n) build_only=1 ;;
    s) summary_only=1 ;;
    l) grep -ho '^PE_FUZZ_TARGET_FUNCTION([a-z_0-9]*)' test/fuzz/*.h | sed 's/.*(\(.*\))/\1/' | sort; exit 0 ;;
    h) usage; exit 0 ;;
    *) usage >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
build=$(realpath -m "$build")
case "$build" in
  "$src"|"$src"/*) echo "fuzz.sh: the build folder must be outside the source tree" >&2; exit 2 ;;
esac
campaigns_csv=$src/test/fuzz/campaigns.csv
campaigns_md=$src/test/fuzz/campaigns.md
sanitizers=address,undefined
sanitizers_label=address+undefined   # the csv field

# ---- targets ----------------------------------------------------------------------------------
all_targets=$(grep -ho '^PE_FUZZ_TARGET_FUNCTION([a-z_0-9]*)' test/fuzz/*.h | sed 's/.*(\(.*\))/\1/' | sort)
if [ $# -gt 0 ]; then targets=("$@"); else read -r -a targets <<< "$(echo $all_targets)"; fi
for t in "${targets[@]}"; do
  if ! grep -qx "$t" <<< "$all_targets"; then echo "fuzz.sh: unknown target '$t' (-l lists them)" >&2; exit 2; fi
done
header_of() { grep -l "^PE_FUZZ_TARGET_FUNCTION($1)" test/fuzz/*.h | head -1; }

# The harness of a target: its header and the test/fuzz headers it includes (recursively), then
# fuzz_main.cpp (whose own includes are the replay program's); its id hashes their contents.
harness_files() {
  local -A seen=()
  local queue=("$(header_of "$1")") order=() f inc
  while [ ${#queue[@]} -gt 0 ]; do
    f=${queue[0]}; queue=("${queue[@]:1}")
    [ -n "${seen[$f]:-}" ] && continue
    seen[$f]=1; order+=("$f")
    for inc in $(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$f"); do
      if [ -f "test/fuzz/$inc" ]; then queue+=("test/fuzz/$inc"); fi
    done
  done
  printf '%s\n' "${order[@]}" | sort
  echo test/fuzz/fuzz_main.cpp
}
harness_id() { harness_files "$1" | xargs cat | sha256sum | cut -c1-12; }
harnesses=""
for t in $all_targets; do harnesses+="$t=$(harness_id "$t") "; done

# ---- the account ------------------------------------------------------------------------------
csv_header=date,target,harness,executions,seconds,exec_per_s,findings,sanitizers,commit,machine,command
[ -s "$campaigns_csv" ] || echo "$csv_header" > "$campaigns_csv"

# Replays each regression input of the target on its own (open findings: those that still fail).
open_findings() {
  local t=$1 bin=$build/bin/fuzz_$1 n=0 f
  compgen -G "test/fuzz/corpus/$t/regression-*" > /dev/null || { echo 0; return; }
  [ -x "$bin" ] || { echo "?"; return; }
  for f in test/fuzz/corpus/"$t"/regression-*; do
    lowest "$bin" -timeout=30 -rss_limit_mb=2560 "$f" > /dev/null 2>&1 || n=$((n + 1))
  done
  echo "$n"
}

# summary ORDER|WRITE: the targets by counted executions (ORDER), or the table (WRITE: printed and
# written to test/fuzz/campaigns.md; OPEN gives the open findings per target)
account() {
  python3 - "$1" "$campaigns_csv" "$campaigns_md" "$sanitizers_label" "$harnesses" "${open_list:-}" "${targets[*]}" <<'PY'
import csv, sys
mode, path, md, sanitizers, harnesses, opens, wanted = sys.argv[1:8]
current = dict(h.split('=') for h in harnesses.split())
opened = dict(o.split('=') for o in opens.split())
rows = list(csv.DictReader(open(path)))
goal = 10_000_000
stats = {t: dict(execs=0, secs=0.0, runs=0, findings=0, old_execs=0, old_runs=0, other=0) for t in current}
for r in rows:
    s = stats.get(r['target'])
    if s is None:
        continue
    if r['sanitizers'] != sanitizers:
        s['other'] += int(r['executions'] or 0)
    elif r['harness'] == current[r['target']]:
        s['execs'] += int(r['executions'] or 0); s['secs'] += float(r['seconds'] or 0)
        s['runs'] += 1; s['findings'] += int(r['findings'] or 0)
    else:
        s['old_execs'] += int(r['executions'] or 0); s['old_runs'] += 1
if mode == 'order':
    print(' '.join(sorted(wanted.split(), key=lambda t: (stats[t]['execs'], t))))
    sys.exit(0)
def hours(s):
    if s['execs'] >= goal: return 'reached'
    if s['secs'] <= 0 or s['execs'] == 0: return '?'
    return '%.1f h' % ((goal - s['execs']) / (s['execs'] / s['secs']) / 3600)
lines = ['# Fuzzing campaigns', '',
         'Written by `scripts/fuzz.sh` from `campaigns.csv` (one row per run). Counted: the executions under',
         'AddressSanitizer and UBSan of the current harness of each target (the hash of its test/fuzz sources);',
         'the rows of an older harness are listed apart and do not count. Goal: %d executions per target;' % goal,
         'the time still needed assumes the mean rate of the counted runs (wall clock, under `nice -n 19`).', '',
         '| target | harness | counted executions | runs | seconds | exec/s | findings | open findings | to %dM | older harness (not counted) |' % (goal // 1_000_000),
         '|---|---|---:|---:|---:|---:|---:|---:|---:|---|']
total = 0
for t in sorted(stats):
    s = stats[t]; total += s['execs']
    rate = '%.0f' % (s['execs'] / s['secs']) if s['secs'] > 0 else '-'
    old = '%d executions in %d runs' % (s['old_execs'], s['old_runs']) if s['old_runs'] else '-'
    lines.append('| %s | %s | %d | %d | %.0f | %s | %d | %s | %s | %s |' % (t, current[t], s['execs'], s['runs'], s['secs'],
                 rate, s['findings'], opened.get(t, '?'), hours(s), old))
lines += ['', 'Total counted executions: %d.' % total]
text = '\n'.join(lines) + '\n'
open(md, 'w').write(text)
print(text, end='')
PY
}

summary() {
  open_list=""
  for t in $all_targets; do open_list+="$t=$(open_findings "$t") "; done
  echo
  account write
}

if [ "$summary_only" -eq 1 ]; then summary; exit 0; fi

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

# ---- build ------------------------------------------------------------------------------------
# -O2 with frame pointers for readable reports; CGAL's assertions on (no NDEBUG) and expensive
# preconditions too, as in the test programs; every sanitizer report is fatal. Coverage feedback
# comes only from the package, the targets and the `pe` tool (test/fuzz/coverage_allowlist.txt):
# tracing the comparisons of CGAL's number types, Surface_mesh and the box intersection tree cost
# more than half of each execution, and their branches are not under test. AddressSanitizer and
# UBSan still instrument everything.
mkdir -p "$build/obj" "$build/bin" "$build/logs"
cxx=(nice -n 19 clang++ -std=gnu++17 -O2 -g -fno-omit-frame-pointer -fno-sanitize-recover=all
     -DCGAL_CHECK_EXPENSIVE -DCGAL_EIGEN3_ENABLED -I"$src/include" -I"$src/tools/pe" -isystem /usr/include/eigen3
     -ffunction-sections -w)
san=-fsanitize=$sanitizers
cov=-fsanitize-coverage-allowlist=$src/test/fuzz/coverage_allowlist.txt
libs=(-lgmp -lmpfr -Wl,--gc-sections)
# everything is rebuilt when the flags change, an object or binary when a file it compiled (its
# dependency list OUT.d, written by the compiler) is newer than it
flags="${cxx[*]} $san $cov $(sha256sum test/fuzz/coverage_allowlist.txt | cut -c1-12)"
if [ "$(cat "$build/obj/flags" 2>/dev/null)" != "$flags" ]; then
  rm -f "$build"/obj/*.o "$build"/bin/fuzz_*
  echo "$flags" > "$build/obj/flags"
fi
stale() {
  [ -e "$1" ] && [ -e "$1.d" ] || return 0
  local f
  for f in $(sed -e 's/\\$//' -e 's/^[^:]*://' "$1.d"); do [ "$f" -nt "$1" ] && return 0; done
  return 1
}

# the pe line readers: the tool's own sources, main() renamed; --gc-sections drops main.cpp's table
# of commands, which are not linked. main.cpp gets no coverage instrumentation: its tables would
# keep that table alive (the readers call only its number parser and failure report).
build_pe_objects() {
  local o=$build/obj
  if stale "$o/input_output.o"; then
    "${cxx[@]}" $san -fsanitize=fuzzer-no-link "$cov" -MMD -MF "$o/input_output.o.d" -c tools/pe/input_output.cpp -o "$o/input_output.o"
  fi
  if stale "$o/pe_main.o"; then "${cxx[@]}" $san -Dmain=pe_tool_main -MMD -MF "$o/pe_main.o.d" -c tools/pe/main.cpp -o "$o/pe_main.o"; fi
}

build_target() {
  local t=$1 header extra=()
  header=$(basename "$(header_of "$t")")
  if [ "$header" = pe_lines.h ]; then extra=("$build/obj/input_output.o" "$build/obj/pe_main.o"); fi
  local bin=$build/bin/fuzz_$t
  if stale "$bin" || { [ "$header" = pe_lines.h ] && { [ "$build/obj/input_output.o" -nt "$bin" ] || [ "$build/obj/pe_main.o" -nt "$bin" ]; }; }; then
    echo "fuzz.sh: building $bin"
    "${cxx[@]}" $san,fuzzer "$cov" -DPE_FUZZ_TARGET="$t" -DPE_FUZZ_HEADER="\"$header\"" -MMD -MF "$bin.d.tmp" \
      -MT "$bin" test/fuzz/fuzz_main.cpp "${extra[@]}" "${libs[@]}" -o "$bin.tmp"
    mv "$bin.tmp" "$bin"
    mv "$bin.d.tmp" "$bin.d"
    harness_id "$t" > "$bin.harness"
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
# malloc_context_size=0: no stack is recorded at each allocation (a fifth of an execution of the map
# targets); a finding's report then lacks the allocation stack, which its replay by
# `ctest -L fuzz` and scripts/sanitize.sh prints in full.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:malloc_context_size=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
commit=$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
if [ -n "$(git status --porcelain -- include tools/pe test/fuzz 2>/dev/null | grep -v 'test/fuzz/campaigns\.' || true)" ]; then
  commit+="+modified"
fi
machine="$(hostname) $(nproc) cpus"

# Runs target $1 once; its result line goes to $build/logs/result_$1.
run_target() {
  local t=$1
  local corpus=$build/corpus/$t artifacts=$build/artifacts/$t
  mkdir -p "$corpus" "$artifacts"
  # the readers need room for long lines and headers; the decoders of small maps read few bytes
  local max_len=512 dict=()
  case $t in read_*|pe_*) max_len=8192 ;; esac
  case $t in read_*) dict=(-dict=test/fuzz/mesh_formats.dict) ;; esac
  local budget=(-max_total_time="$seconds")
  if [ -n "$runs" ]; then budget=(-runs="$runs"); fi
  local date start log harness
  date=$(date -u +%Y-%m-%dT%H:%M:%SZ)
  # the harness the binary was built from (written with it)
  harness=$(cat "$build/bin/fuzz_$t.harness" 2>/dev/null || echo unknown)
  log=$build/logs/${t}_$(date -u +%Y%m%d-%H%M%S).log
  touch "$build/.start_$t"
  echo "fuzz.sh: running $t (${runs:+$runs runs}${runs:-$seconds s}), log $log"
  start=$(date +%s.%N)
  set +e
  # new inputs go to the first folder (the build's, kept between runs), the committed corpus seeds the run
  lowest "$build/bin/fuzz_$t" "${budget[@]}" -timeout=30 -rss_limit_mb=2560 -max_len="$max_len" \
    -print_final_stats=1 -artifact_prefix="$artifacts/" "${dict[@]}" "$corpus" "test/fuzz/corpus/$t" > "$log" 2>&1
  local rc=$?
  set -e
  local secs execs rate findings=()
  secs=$(echo "$(date +%s.%N) - $start" | bc)
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1 || true)
  if [ -z "$execs" ]; then execs=$(grep -o '^#[0-9]*' "$log" | tail -1 | tr -d '#' || true); fi
  execs=${execs:-0}
  rate=$(echo "scale=0; $execs / $secs" | bc)
  while IFS= read -r f; do findings+=("$(basename "$f")"); done < <(find "$artifacts" -type f -newer "$build/.start_$t")
  if [ "$rc" -ne 0 ] || [ ${#findings[@]} -gt 0 ]; then
    for f in "${findings[@]}"; do
      # a regression input, named by its kind and content
      cp "$artifacts/$f" "test/fuzz/corpus/$t/regression-$f"
      echo "fuzz.sh: $t: finding $artifacts/$f, copied to test/fuzz/corpus/$t/regression-$f"
    done
    grep -m1 -E 'FUZZ FINDING|ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error' "$log" || true
  fi
  local nf=${#findings[@]}
  if [ "$rc" -ne 0 ] && [ "$nf" -eq 0 ]; then nf=1; fi
  (
    flock 9
    printf '%s,%s,%s,%s,%.0f,%s,%s,%s,%s,%s,"%s"\n' "$date" "$t" "$harness" "$execs" "$secs" "$rate" "$nf" \
      "$sanitizers_label" "$commit" "$machine" "$command_line" >> "$campaigns_csv"
  ) 9> "$build/campaigns.lock"
  printf '%-24s %12s executions %8s exec/s %3d findings (exit %d)\n' "$t" "$execs" "$rate" "$nf" "$rc" > "$build/logs/result_$t"
  [ "$nf" -eq 0 ]
}

read -r -a targets <<< "$(account order)"
status=0
running=0
for t in "${targets[@]}"; do
  run_target "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$processes" ]; then wait -n || status=1; running=$((running - 1)); fi
done
while [ "$running" -gt 0 ]; do wait -n || status=1; running=$((running - 1)); done
echo
echo "fuzz.sh: ASan+UBSan, ${runs:+$runs runs}${runs:-$seconds s} per target"
for t in "${targets[@]}"; do cat "$build/logs/result_$t"; done
summary
exit $status
