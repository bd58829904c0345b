#!/bin/sh
# Regenerates the tables and pictures of benchmark/results (see benchmark/results/README.md).
#
#   benchmark/regenerate_results.sh [--build DIR] [--out DIR] [--study] [--benchmark] [--constrained]
#                                   [--polygons [--polygon-obj FILE.obj]] [--cross [--cross-pairs DIR]]
#
# (default)    from the committed comparison-study run (study_runs.csv.gz, study_gallery.csv): the
#              study's tables, plot and gallery; the driver only draws the gallery runs again (under
#              a minute), nothing is measured again. Unchanged inputs give byte-identical files.
# --study      runs the whole comparison study again instead (about 30 minutes on 2 cores).
# --benchmark  also runs pe_benchmark again on the failing corpus runs (study_tutte_failures.tsv)
#              and the generated grids: progressive_embedding.{csv,md} and, with --optimize,
#              progressive_embedding_optimized.{csv,md} (tens of minutes).
# --constrained also runs constrained_benchmark again: constrained_embedding*.{csv,md} (about 10 minutes;
# the timed tables run each case 3 times and keep the median time).
# --polygons   also runs polygon_benchmark (polygon_triangulation.{csv,md}, about 2 minutes) and
#              polygon_map_benchmark (polygon_maps.{csv,md}: maps onto Hilbert, star and spiral borders,
#              about 15 minutes); --polygon-obj adds an OBJ disk with texture coordinates (repeatable).
# --cross      also runs cross_benchmark (cross_parameterization.{csv,md}: mushroom and lion-head against
#              their remeshed copies, 5, 20 and 50 landmarks, each without and with the composed distortion
#              and B's matched map, and the naive composition of two Tutte maps, about two minutes),
#              cross_parameterization_closed.{csv,md} (nine closed genus-0 meshes against their remeshed copies,
#              without and with B's matched map, and CGAL's Orbifold Tutte maps composed, about 10 minutes) and
#              cross_parameterization_closed_identity.{csv,md} (the same meshes each onto itself, about 4
#              minutes); with --cross-pairs DIR also
#              cross_parameterization_pairs.{csv,md}: two resolutions of one surface, 0, 5, 20 and 50 landmarks,
#              from the OBJ files of OptCuts' inputs (its input/benchmark and input/scalability/lucy_o folders)
#              that DIR holds: cat, cat_f1500, bishop_part, bishop_part_f1000, lucy_o_f12067, _f24136, _f48275
#              (about 10 minutes), and cross_protocol_floor.{csv,md} on the same pairs (what the landmarks and the
#              border rule allow before any map; NumPy).
# --build DIR  the CMake build directory (default: build); the drivers are built there.
# --out DIR    the results folder (default: benchmark/results), e.g. a copy to compare with.
#
# Needs cmake, python3, and rsvg-convert (Debian librsvg2-bin) or chromium for the PNG pictures;
# pngquant (Debian pngquant) keeps them small.
set -eu

repo=$(cd "$(dirname "$0")/.." && pwd)
build="$repo/build"
results="$repo/benchmark/results"
study=0
benchmark=0
constrained=0
polygons=0
cross=0
cross_pairs=""
polygon_objs=""
while [ $# -gt 0 ]; do
  case "$1" in
    --build) [ $# -ge 2 ] || { echo "--build needs a directory" >&2; exit 2; }; build=$2; shift 2 ;;
    --out) [ $# -ge 2 ] || { echo "--out needs a directory" >&2; exit 2; }; results=$2; shift 2 ;;
    --cross-pairs) [ $# -ge 2 ] || { echo "--cross-pairs needs a directory" >&2; exit 2; }; cross_pairs=$2; shift 2 ;;
    --study) study=1; shift ;;
    --benchmark) benchmark=1; shift ;;
    --constrained) constrained=1; shift ;;
    --polygons) polygons=1; shift ;;
    --cross) cross=1; shift ;;
    --polygon-obj) [ $# -ge 2 ] || { echo "--polygon-obj needs a file" >&2; exit 2; }
                   polygon_objs="$polygon_objs --obj $(cd "$(dirname "$2")" && pwd)/$(basename "$2")"; shift 2 ;;
    -h|--help) sed -n '2,24p' "$0"; exit 0 ;;
    *) echo "unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
build=$(cd "$build" && pwd)
results=$(cd "$results" && pwd)

if ! command -v rsvg-convert >/dev/null 2>&1 && ! command -v chromium >/dev/null 2>&1; then
  echo "no SVG renderer: apt-get install librsvg2-bin (the pictures would stay SVG)" >&2
  exit 1
fi

cmake --build "$build" --target comparison_study
if [ "$study" = 1 ]; then
  python3 "$repo/benchmark/Progressive_embedding/run_study.py" --no-build --build "$build" --out "$results"
else
  python3 "$repo/benchmark/Progressive_embedding/run_study.py" --report-only --redraw-gallery --no-build \
    --build "$build" --out "$results"
fi

if [ "$benchmark" = 1 ]; then
  cmake --build "$build" --target pe_benchmark
  "$build/bin/pe_benchmark" "$build/cgal_data/data" "$results/study_tutte_failures.tsv" \
    "$results/progressive_embedding" --repeat 3
  "$build/bin/pe_benchmark" "$build/cgal_data/data" "$results/study_tutte_failures.tsv" \
    "$results/progressive_embedding_optimized" --optimize
fi
if [ "$constrained" = 1 ]; then
  cmake --build "$build" --target constrained_benchmark
  # exits 1 when a run did not end certified (the tables list those runs): keep the tables anyway
  meshes=retinal.off,dino.off,homer.off,camel.off,bear_bis.off,man.off,diplodocus.off,mushroom.off,lion-head.off,mannequin-devil.off
  "$build/bin/constrained_benchmark" "$build/cgal_data/data" "$results/constrained_embedding" \
    --meshes "$meshes" --seeds 10 --counts 3 --optimize-seeds 0 --budget 60 --repeat 3 || true
  "$build/bin/constrained_benchmark" "$build/cgal_data/data" "$results/constrained_embedding_many" \
    --meshes "$meshes" --seeds 3 --counts 10,50 --optimize-seeds 0 --budget 60 --repeat 3 || true
  # the same without the kinetic tracing: what it changes, side by side
  "$build/bin/constrained_benchmark" "$build/cgal_data/data" "$results/constrained_embedding_many_no_kinetic" \
    --meshes "$meshes" --seeds 3 --counts 10,50 --optimize-seeds 0 --budget 60 --repeat 3 --no-kinetic || true
  # 100 and 200 random constraints on the 20k-vertex disks, with and without the kinetic tracing
  for k in "" --no-kinetic; do
    "$build/bin/constrained_benchmark" "$build/cgal_data/data" "$results/constrained_embedding_200${k:+_no_kinetic}" \
      --meshes man.off,diplodocus.off --seeds 2 --counts 100,200 --targets random --optimize-seeds 0 --budget 120 $k || true
  done
  # the default pe constrain command (optimization included) with 50 random constraints, as a user runs it
  python3 "$repo/benchmark/constrained_default_command.py" "$build" --optimize-time 30 --out "$results/constrained_default_command"
  "$build/bin/constrained_benchmark" "$build/cgal_data/data" "$results/constrained_embedding_optimized" \
    --meshes retinal.off,dino.off,homer.off,mushroom.off,lion-head.off --seeds 1 --counts 3,10 --targets layout \
    --optimize-seeds 1 --budget 120 || true
  # the same without the coarsening: the vertices it removes and the distortion side by side
  "$build/bin/constrained_benchmark" "$build/cgal_data/data" "$results/constrained_embedding_optimized_no_coarsen" \
    --meshes retinal.off,dino.off,homer.off,mushroom.off,lion-head.off --seeds 1 --counts 3,10 --targets layout \
    --optimize-seeds 1 --budget 120 --no-coarsen || true
fi
if [ "$polygons" = 1 ]; then
  cmake --build "$build" --target polygon_benchmark polygon_map_benchmark
  "$build/bin/polygon_benchmark" "$results/polygon_triangulation" --budget 300
  # shellcheck disable=SC2086 # polygon_objs is a list of options
  "$build/bin/polygon_map_benchmark" "$build/cgal_data/data" "$results/polygon_maps" --seeds 2 --budget 20 $polygon_objs
fi
if [ "$cross" = 1 ]; then
  cmake --build "$build" --target cross_benchmark
  "$build/bin/cross_benchmark" "$build/cgal_data/data" "$results/cross_parameterization" --composed both --matched both
  closed=blobby.off,cow.off,hand.off,triceratops.off,homer.off,bull.off,camel.off,bear_bis.off,man.off
  "$build/bin/cross_benchmark" "$build/cgal_data/data" "$results/cross_parameterization_closed" --meshes "$closed" \
    --counts 5,20,50 --matched both
  m=$build/cgal_data/data/meshes
  "$build/bin/cross_benchmark" "$build/cgal_data/data" "$results/cross_parameterization_closed_identity" --counts 5,20,50 \
    --matched both --pairs "$(echo "$closed" | tr ',' '\n' | sed "s|.*|$m/&:$m/&|" | paste -sd, -)"
  if [ -n "$cross_pairs" ]; then
    d=$cross_pairs
    "$build/bin/cross_benchmark" "$build/cgal_data/data" "$results/cross_parameterization_pairs" --counts 0,5,20,50 --composed both --matched both \
      --pairs "$d/cat_f1500.obj:$d/cat.obj,$d/bishop_part_f1000.obj:$d/bishop_part.obj,$d/lucy_o_f24136.obj:$d/lucy_o_f12067.obj,$d/lucy_o_f48275.obj:$d/lucy_o_f24136.obj"
    python3 "$repo/benchmark/Progressive_embedding/cross_protocol_floor.py" "$d/cat_f1500.obj:$d/cat.obj" \
      "$d/bishop_part_f1000.obj:$d/bishop_part.obj" "$d/lucy_o_f24136.obj:$d/lucy_o_f12067.obj" \
      "$d/lucy_o_f48275.obj:$d/lucy_o_f24136.obj" --out "$results/cross_protocol_floor"
  fi
fi
echo "$results regenerated"
