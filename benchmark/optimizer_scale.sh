#!/usr/bin/env bash
# The table benchmark/results/optimizer_scale.{csv,md}: the default optimization (`pe optimize`, no option) of
# repaired random initializations of grid disks from 50k to 1M vertices: iterations, whether the stopping rule
# (two iterations below a relative decrease of 1e-5) was met, time per iteration and its growth from the
# 50k-vertex case, peak memory, the energy, the certificate. With BASELINE_PE (a `pe` built from an earlier
# commit of this repository), both programs run alternately on the same maps and the table gives the ratios.
#
#   benchmark/optimizer_scale.sh BUILD_DIR [BASELINE_PE [BASELINE_LABEL]] [--sizes 224,256,512,1024] [--repeat 3]
#                                [--time-limit SECONDS] [--out benchmark/results/optimizer_scale]
#
# --sizes also takes Tutte-failure maps, `thingi:MESH:SEED` (`pe thingi` on libcgal-demo's MESH.off, then `pe untangle
# --no-optimize`): benchmark/results/optimizer_reuse.{csv,md} (the reuse of the factorization, against the commit
# before it) is `--sizes thingi:bull:0,thingi:dino:8,thingi:man:4,thingi:camel:3,64,128,200`.
#
# --time-limit: passed to `pe optimize` (a budget: the optimization stops there with its certified map, status
# ERROR_BUDGET_EXHAUSTED); benchmark/results/optimizer_scale_budget.{csv,md} is the 1024 grid with 60 s.
# pe's default budget for the optimization (--optimize-time, 60 s) stops the 1024 grid before the stopping rule;
# the table of 2026-12-02 was measured before that default existed (no budget).
# --table-only: runs nothing, writes OUT.md again from OUT.csv.
#
# BUILD_DIR holds bin/pe. Each size N: `pe generate grid N`, `pe random-init --seed 1`, `pe untangle
# --no-optimize` (the repaired map both programs start from), then `pe optimize IN OUT --json` under
# /usr/bin/time. The 1024 case runs once per program whatever --repeat says (minutes each). About 15 minutes
# with a baseline; peak memory about 3 GB (the baseline at 1M vertices).
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(cd "$1" && pwd)
shift
baseline=""
baseline_label="baseline"
sizes=224,256,512,1024
repeat=3
limit=()
table_only=0
out=benchmark/results/optimizer_scale
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then baseline=$(realpath "$1"); shift; fi
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then baseline_label=$1; shift; fi
while [ $# -gt 0 ]; do
  case $1 in
    --sizes) sizes=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --time-limit) limit=(--time-limit "$2"); shift 2 ;;
    --table-only) table_only=1; shift ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
done
pe=$build/bin/pe
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

csv=$out.csv
if [ $table_only = 0 ]; then
echo "program,commit,command,grid,vertices,run,iterations,converged,energy_before,energy_after,seconds_optimization,wall_s,peak_mb,valid,status,exit_status,machine,date,load1" > "$csv"
commit=$(git rev-parse --short HEAD)$(git diff --quiet HEAD -- include tools || echo "+changes")
for n in ${sizes//,/ }; do
  runs=$repeat
  case $n in
    thingi:*)
      IFS=: read -r _ mesh seed <<< "$n"
      "$pe" thingi "$build/cgal_data/data/meshes/$mesh.off" "$seed" "$work/t.obj" > /dev/null || true # exit 1: Tutte fails, as meant
      "$pe" untangle "$work/t.obj" "$work/un.obj" --no-optimize --no-progress > /dev/null ;;
    *)
      "$pe" generate grid "$n" "$work/g.obj" > /dev/null
      "$pe" random-init "$work/g.obj" "$work/ri.obj" --seed 1 > /dev/null || true # exit 1: the random map is invalid, as meant
      "$pe" untangle "$work/ri.obj" "$work/un.obj" --no-optimize --no-progress > /dev/null
      [ "$n" -ge 1024 ] && runs=1 ;;
  esac
  for run in $(seq 1 "$runs"); do
    for prog in pe $([ -n "$baseline" ] && echo "$baseline_label"); do
      bin=$pe; rev=$commit
      if [ "$prog" != pe ]; then bin=$baseline; rev=$baseline_label; fi
      set +e
      /usr/bin/time -f "%e %M" -o "$work/time.txt" "$bin" optimize "$work/un.obj" "$work/out.obj" --json --no-progress "${limit[@]}" \
        > "$work/out.json" 2> "$work/err.txt"
      status=$?
      set -e
      read -r wall peak_kb < <(tail -1 "$work/time.txt") # "Command exited with ..." comes first on a failure
      load=$(cut -d' ' -f1 /proc/loadavg)
      python3 - "$work/out.json" "$prog,$rev,pe optimize un.obj out.obj --json${limit[*]:+ ${limit[*]}},$n" "$run,$wall,$((peak_kb / 1024)),$status,$(hostname),$(date -u '+%Y-%m-%d %H:%M UTC'),$load" >> "$csv" <<'EOF'
import json, sys
head, tail = sys.argv[2], sys.argv[3].split(",")
try:
    j = json.loads(open(sys.argv[1]).read().splitlines()[-1])
except (IndexError, ValueError):  # the program failed before its JSON line: a row that says so
    j = dict(vertices=0, iterations=0, converged="", energy_before=float("nan"), energy_after=float("nan"),
             seconds_optimization=float("nan"), valid="", status="")
run, wall, peak, status = tail[0], tail[1], tail[2], tail[3]
print("%s,%d,%s,%d,%s,%.6g,%.6g,%.4f,%s,%s,%s,%s,%s,%s,%s,%s" % (head, j["vertices"], run, j["iterations"], j["converged"],
      j["energy_before"], j["energy_after"], j["seconds_optimization"], wall, peak, j["valid"], j["status"], status, tail[4],
      tail[5], tail[6]))
EOF
      echo "$n run $run $prog: $(tail -1 "$csv")"
    done
  done
done
fi

python3 - "$csv" <<'EOF'
import csv, statistics, sys
path = sys.argv[1]
rows = list(csv.DictReader(open(path)))
progs = list(dict.fromkeys(r["program"] for r in rows))
grids = list(dict.fromkeys(r["grid"] for r in rows))
def med(rs, k): return statistics.median(float(r[k]) for r in rs)
stats = {}
for p in progs:
    for g in grids:
        rs = [r for r in rows if r["program"] == p and r["grid"] == g]
        if not rs: continue
        it = med(rs, "iterations")
        stats[p, g] = dict(n=len(rs), vertices=int(rs[0]["vertices"]), it=it, conv=",".join(sorted({r["converged"] for r in rs})),
                           e0=med(rs, "energy_before"), e1=med(rs, "energy_after"), sec=med(rs, "seconds_optimization"),
                           wall=med(rs, "wall_s"), peak=med(rs, "peak_mb"), per=med(rs, "seconds_optimization") / max(it, 1),
                           valid=",".join(sorted({r["valid"] for r in rs})), status=",".join(sorted({r["status"] for r in rs})),
                           load=",".join(r["load1"] for r in rs))
with open(path[:-4] + ".md", "w") as md:
    thingi = any(g.startswith("thingi:") for g in grids)
    md.write("# The default optimization%s: `pe optimize` on repaired %s\n\n" % (
        "" if thingi else " at scale", "maps" if thingi else "random initializations of grid disks"))
    md.write("`benchmark/optimizer_scale.sh`, %s to %s, host %s (2 cores). Each grid disk N x N: `pe generate grid N`, "
             "`pe random-init --seed 1`, `pe untangle --no-optimize`%s, then `pe optimize IN OUT --json` (the defaults: at most "
             "1000 iterations, stopping when two consecutive iterations lower the mean symmetric Dirichlet energy by less "
             "than a relative 1e-5, and from commit d268197 on a budget of 60 s, `--optimize-time`; the command: `%s`). Medians of the runs (the 1024 grid: one run per program); programs alternated; "
             "s/it: optimization seconds per iteration; growth: s/it over the smallest grid's s/it of the same program; "
             "load1: the 1-minute load average after each run.\n\n" % (rows[0]["date"], rows[-1]["date"], rows[0]["machine"],
             "; each `thingi:MESH:SEED`: `pe thingi` (the Tutte-failure protocol) on libcgal-demo's MESH.off, then `pe untangle "
             "--no-optimize`" if thingi else "", rows[0]["command"]))
    col = (lambda g: g + " | ") if thingi else (lambda g: "")
    md.write("| program | commit | %svertices | runs | iterations | stopping rule met | status | energy before | energy after | "
             "optimization s | wall s | s/it | growth of s/it | peak MB | certified | load1 |\n" % ("input | " if thingi else ""))
    md.write("|---|---|%s---:|---:|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---|---|\n" % ("---|" if thingi else ""))
    for p in progs:
        first = None
        commit = next(r["commit"] for r in rows if r["program"] == p)
        for g in grids:
            s = stats.get((p, g))
            if not s: continue
            if first is None: first = s
            md.write("| %s | %s | %s%d | %d | %g | %s | %s | %.4f | %.4f | %.2f | %.2f | %.3f | %.1f× | %d | %s | %s |\n" % (
                p, commit, col(g), s["vertices"], s["n"], s["it"], s["conv"], s["status"], s["e0"], s["e1"], s["sec"], s["wall"],
                s["per"], s["per"] / first["per"], s["peak"], "yes" if s["valid"] == "True" else s["valid"], s["load"]))
    if len(progs) > 1:
        base = progs[1]
        md.write("\nRatios, %s over %s (below 1: %s is faster or smaller):\n\n" % (progs[0], base, progs[0]))
        md.write("| %svertices | optimization time | time per iteration | peak memory |\n|%s---:|---:|---:|---:|\n" % (
            "input | " if thingi else "", "---|" if thingi else ""))
        for g in grids:
            a, b = stats.get((progs[0], g)), stats.get((base, g))
            if a and b:
                md.write("| %s%d | %.2f× | %.2f× | %.2f× |\n" % (col(g), a["vertices"], a["sec"] / b["sec"], a["per"] / b["per"],
                                                               a["peak"] / b["peak"]))
print("wrote", path, "and", path[:-4] + ".md")
EOF
