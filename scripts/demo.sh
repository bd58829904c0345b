#!/usr/bin/env bash
# Command 1 of the README: set-up, Release build of the `pe` tool, and the main job --
# the Tutte-failure protocol on libcgal-demo's dino.off seed 8 (certificate of the double
# Tutte map, picture build/dino_seed8_tutte.svg), repaired by progressive embedding
# (certificate, picture build/dino_seed8_repaired.svg).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2 --target pe
./build/bin/pe demo "$@"
