#!/usr/bin/env bash
# slurm_batch_test.sh PE DATA_DIR WORK_DIR [WAIT] : the ctest slurm_batch. Generates the 7 inputs of the
# batch_shards test (pe generate, pe tutte and pe thingi on DATA_DIR/meshes, a broken file, a closed
# mesh) into WORK_DIR/inputs and runs scripts/slurm_batch.sh on them: a 3-task job array on a
# one-node Slurm started for the test, its merge compared with the unsharded run.
# Exit 77 (skipped) when Slurm cannot run here; it installs no package (--no-install). WAIT: the bound in
# seconds on each wait, for the array and for the unsharded run (default 60).
set -euo pipefail
PE=$1 DATA=$2 WORK=$3 WAIT=${4:-60}
script=$(cd "$(dirname "$0")/../.." && pwd)/scripts/slurm_batch.sh
rm -rf "$WORK"
mkdir -p "$WORK/inputs"
in=$WORK/inputs
run() { echo "\$ pe $*"; "$PE" "$@" >/dev/null || [ $? -eq 1 ]; }   # exit 1: an invalid map, written
run generate grid 5 "$in/grid5.obj"
run generate grid 12 "$in/grid12.obj"
run generate stacked 40 "$in/stacked40.obj"          # invalid in double: repaired
run tutte "$DATA/meshes/mushroom.off" "$in/mushroom.obj"
run thingi "$DATA/meshes/bull.off" 4 "$in/bull-4.obj" # the Tutte-failure protocol: repaired
printf 'this is not a mesh\n{ garbage }\n' > "$in/broken.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n%s\n' \
  'f 1/1 3/3 2/2' 'f 1/1 2/2 4/4' 'f 2/2 3/3 4/4' 'f 3/3 1/1 4/4' > "$in/closed.obj"
exec "$script" --no-install --pe "$PE" --shards 3 --jobs 1 --timeout "$WAIT" "$in" "$WORK/run"
