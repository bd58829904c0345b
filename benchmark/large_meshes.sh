#!/usr/bin/env bash
# The table benchmark/results/large_meshes.{csv,md}: the stages of a certified Tutte map of grid disks from
# 16k to 4M vertices and of a 1M-vertex OBJ file (grid1024.obj, `pe generate grid 1024`: read and write
# included), by sparse solver, and the default solver on the reference BLAS and LAPACK beside OpenBLAS. Runs large_meshes_benchmark several times and merges its tables.
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
solvers=default,ldlt_amd,llt_amd
for s in cholmod ldlt_metis; do
  if "$bench" --list-solvers | tr , '\n' | grep -qx $s; then solvers=$solvers,$s; fi
done
"$bench" "$work/a" --cases grid:128,grid:256,grid:512,grid:1024 --solvers "$solvers" --repeat 3
"$bench" "$work/b" --cases grid:128,grid:256,grid:512 --solvers cg_jacobi,cg_ichol --repeat 1
"$bench" "$work/c" --cases grid:2048 --solvers default,ldlt_amd --repeat 1 --memory-limit-mb 20000
mkdir -p "$work/out"
"$bench" "$work/d" --cases "$work/grid1024.obj" --solvers default --repeat 3 --write-dir "$work/out"
# CHOLMOD on Debian's reference BLAS and LAPACK (the alternatives that libsuitesparse-dev alone installs)
ref=/usr/lib/x86_64-linux-gnu
if [ -e $ref/blas/libblas.so.3 ] && [ -e $ref/lapack/liblapack.so.3 ]; then
  LD_LIBRARY_PATH=$ref/blas:$ref/lapack "$bench" "$work/e" --cases grid:512,grid:1024 --solvers default --repeat 3
fi

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
