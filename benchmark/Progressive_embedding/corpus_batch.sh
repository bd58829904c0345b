#!/usr/bin/env bash
# The Tutte-failure corpus repaired by `pe batch untangle`, as 4 shards run by GNU parallel, then
# merged by `pe batch-merge` into benchmark/results/corpus_batch/ (results.jsonl, results.csv,
# summary.md).
#
#   corpus_batch.sh TSV DATA_DIR PE WORK_DIR [batch options...]
#
#   TSV       the corpus: 'mesh<TAB>seed<TAB>...' lines after a header, e.g.
#             benchmark/results/study_tutte_failures.tsv
#   DATA_DIR  libcgal-demo's data folder (its meshes/ holds the TSV's meshes), e.g. build/cgal_data/data
#   PE        the pe binary, e.g. build/bin/pe
#   WORK_DIR  scratch folder: the inputs (WORK_DIR/meshes/MESH-SEED.obj, made by `pe thingi`), their
#             list (WORK_DIR/corpus.txt) and the shards' outputs (WORK_DIR/shard-K)
#   options   passed to every `pe batch` (e.g. --no-optimize, --time-limit 300, --jobs 1)
#
# Environment: SHARDS (default 4), PARALLEL_JOBS (default 2), OUT (default benchmark/results/corpus_batch).
set -euo pipefail

if [ $# -lt 4 ]; then
  sed -n '2,17p' "$0" >&2
  exit 2
fi
tsv=$1; data=$2; pe=$3; work=$4; shift 4
here=$(cd "$(dirname "$0")" && pwd)
out=${OUT:-$here/../results/corpus_batch}
shards=${SHARDS:-4}
jobs=${PARALLEL_JOBS:-2}
command -v parallel >/dev/null || { echo "corpus_batch.sh: GNU parallel is needed" >&2; exit 2; }
pe=$(cd "$(dirname "$pe")" && pwd)/$(basename "$pe")

# 1. the inputs: the thingi protocol on each (mesh, seed) of the corpus; its double Tutte map is
#    invalid (pe thingi exits 1) by the corpus's definition
mkdir -p "$work/meshes"
list=$work/corpus.txt
echo "# the Tutte-failure corpus of $(basename "$tsv"): MESH-SEED.obj, double Tutte maps" > "$list"
tail -n +2 "$tsv" | while IFS=$'\t' read -r mesh seed _; do
  [ -n "$mesh" ] || continue
  name=${mesh%.*}-$seed.obj
  if [ ! -s "$work/meshes/$name" ]; then
    status=0
    "$pe" thingi "$data/meshes/$mesh" "$seed" "$work/meshes/$name" >/dev/null || status=$?
    if [ "$status" -gt 1 ]; then echo "corpus_batch.sh: pe thingi $mesh $seed failed (exit $status)" >&2; exit 1; fi
  fi
  echo "meshes/$name" >> "$list"
done
echo "corpus_batch.sh: $(grep -vc '^#' "$list") inputs listed in $list"

# 2. the shards: exit 1 (a mesh not valid) is a result, not a failure of the run
rm -rf "$work"/shard-*
run_shard() { "$pe" batch untangle "$list" "$work/shard-$1" --shard "$1/$shards" --no-progress "${@:2}" || [ $? -eq 1 ]; }
export -f run_shard
export pe list work shards
parallel -j"$jobs" --line-buffer run_shard {} "$@" ::: $(seq 1 "$shards")

# 3. the merge (exit 1 if some mesh is not valid: the files are written all the same)
mkdir -p "$out"
"$pe" batch-merge "$work"/shard-* --out "$out" || [ $? -eq 1 ]
cat "$out/summary.md"
