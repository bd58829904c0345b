#!/usr/bin/env bash
# The table benchmark/results/large_meshes.{csv,md}: the stages of a certified Tutte map of grid disks from
# 16k to 4M vertices and of a 1M-vertex OBJ file (grid1024.obj, `pe generate grid 1024`: read and write
# included), by sparse solver, and CHOLMOD on the reference BLAS and LAPACK beside OpenBLAS. Runs large_meshes_benchmark several times and merges its tables.
# Then `pe embed --no-optimize` on that file, end to end: OUT_PREFIX_pe.{csv,md}.
#
#   benchmark/large_meshes.sh BUILD_DIR [OUT_PREFIX]     (default OUT_PREFIX: benchmark/results/large_meshes)
#
# BUILD_DIR: a build with PE_BUILD_BENCHMARKS=ON (bin/large_meshes_benchmark, bin/pe). About 20 minutes on
# 2 cores; peak memory about 7 GB (the 4M-vertex grid).
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(cd "$1" && pwd)
out=${2:-benchmark/results/large_meshes}
bench=$build/bin/large_meshes_benchmark
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$build/bin/pe" generate grid 1024 "$work/grid1024.obj" > /dev/null
available() { "$bench" --list-solvers | tr , '\n' | grep -qx "$1"; }
solvers=default,ldlt_amd,llt_amd
for s in cholmod ldlt_metis; do
  if available $s; then solvers=$solvers,$s; fi
done
"$bench" "$work/a" --cases grid:128,grid:256,grid:512,grid:1024 --solvers "$solvers" --repeat 3
"$bench" "$work/b" --cases grid:128,grid:256,grid:512 --solvers cg_jacobi,cg_ichol,cg_amg --repeat 1
big=default
if available cholmod; then big=default,cholmod; fi
"$bench" "$work/c" --cases grid:2048 --solvers $big --repeat 1 --memory-limit-mb 20000
mkdir -p "$work/out"
# the file case as `pe` runs it by default (4 KB pages; huge pages only with PE_HUGE_PAGES=1)
unset PE_HUGE_PAGES
"$bench" "$work/d" --cases "$work/grid1024.obj" --solvers default --repeat 3 \
  --write-dir "$work/out"
# CHOLMOD on Debian's reference BLAS and LAPACK (the alternatives that libsuitesparse-dev alone installs)
ref=/usr/lib/x86_64-linux-gnu
if [ -e $ref/blas/libblas.so.3 ] && [ -e $ref/lapack/liblapack.so.3 ] && available cholmod; then
  LD_LIBRARY_PATH=$ref/blas:$ref/lapack "$bench" "$work/e" --cases grid:512,grid:1024 --solvers cholmod --repeat 3
fi

# `pe embed --no-optimize` itself on the 1M-vertex OBJ file, end to end (wall clock and peak of the process,
# /usr/bin/time), 3 runs as it starts by default (4 KB pages) and 3 with PE_HUGE_PAGES=1 (the process's large
# allocations on transparent huge pages), alternated
pe_csv=${out}_pe.csv
echo "program,command,run,huge_pages,wall_s,peak_mb,exit_status,machine,date" > "$pe_csv"
for run in 1 2 3; do
  for hp in no yes; do
    if [ $hp = yes ]; then export PE_HUGE_PAGES=1; else unset PE_HUGE_PAGES; fi
    set +e
    /usr/bin/time -f "%e %M" -o "$work/time.txt" "$build/bin/pe" embed "$work/grid1024.obj" "$work/out/pe_embed.obj" \
      --border circle --no-optimize --no-progress > "$work/pe_embed.log" 2>&1
    status=$?
    set -e
    read -r wall peak_kb < "$work/time.txt"
    echo "pe,pe embed grid1024.obj OUT.obj --border circle --no-optimize --no-progress,$run,$hp,$wall,$((peak_kb / 1024)),$status,$(hostname),$(date -u '+%Y-%m-%d %H:%M UTC')" >> "$pe_csv"
  done
done
unset PE_HUGE_PAGES
python3 - "$pe_csv" <<'EOF'
import csv, statistics, sys
path = sys.argv[1]
rows = list(csv.DictReader(open(path)))
def med(hp, key):
    return statistics.median(float(r[key]) for r in rows if r["huge_pages"] == hp)
with open(path[:-4] + ".md", "w") as md:
    md.write("# `pe embed --no-optimize` on the 1M-vertex grid disk, end to end\n\n")
    md.write("`benchmark/large_meshes.sh`, %s, host %s. `%s` (grid1024.obj: `pe generate grid 1024`, 1,048,576 vertices, "
             "2,093,058 faces): read, Tutte map (the default solver: conjugate gradients with the multigrid preconditioner), certificate, OBJ written. Wall clock and peak resident size of the "
             "process (`/usr/bin/time`), 3 runs each, alternated; huge pages: no as `pe` starts by default, yes with `PE_HUGE_PAGES=1` "
             "(glibc's malloc, and CHOLMOD's large blocks where it runs, on transparent huge pages).\n\n" % (rows[0]["date"], rows[0]["machine"], rows[0]["command"]))
    md.write("| huge pages | runs (s) | median wall (s) | median peak (MB) | exit status |\n|---|---|---:|---:|---|\n")
    for hp in ("no", "yes"):
        rs = [r for r in rows if r["huge_pages"] == hp]
        md.write("| %s | %s | %.2f | %d | %s |\n" % (hp, ", ".join(r["wall_s"] for r in rs), med(hp, "wall_s"), med(hp, "peak_mb"),
                                                     ", ".join(sorted({r["exit_status"] for r in rs}))))
    md.write("\nWith huge pages / without (the default): %.2f× the wall time.\n" % (med("yes", "wall_s") / med("no", "wall_s")))
print("wrote", path, "and", path[:-4] + ".md")
EOF

python3 - "$work" "$out" <<'EOF'
import os, sys
work, out = sys.argv[1], sys.argv[2]
parts = [p for p in "abcde" if os.path.exists(os.path.join(work, p + ".csv"))]
def read(p, ext):
    # the generated OBJ file is named by what it is, not by its temporary folder
    return open(os.path.join(work, p + ext)).read().replace(os.path.join(work, "grid1024.obj"), "grid1024.obj")
with open(out + ".csv", "w") as csv:
    for i, p in enumerate(parts):
        lines = read(p, ".csv").splitlines()
        csv.write("\n".join(lines if i == 0 else lines[1:]) + "\n")
with open(out + ".md", "w") as md:
    for i, p in enumerate(parts):
        text = read(p, ".md")
        if i == 0:
            md.write(text)
        else:
            # the next table's rows only, after its own date and BLAS line
            lines = text.splitlines()
            md.write("\n" + lines[2].split(". `grid")[0] + ":\n\n" + "\n".join(l for l in lines if l.startswith("|")) + "\n")
print("wrote %s.csv and %s.md" % (out, out))
EOF
