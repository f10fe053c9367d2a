#!/usr/bin/env bash
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Speed benchmark: SpectralSeg's k-way segmentation against CGAL's SDF
# segmentation (sdf_values + segmentation_from_sdf_values) on one mesh at
# sizes from about 1,000 to about 1,400,000 faces, every configuration in its
# own process (build/benchmark/bench_segmentation_speed). Writes the table and
# the plot of doc/benchmarks.md:
#   OUT/speed_table.md         every run, per stage, with the ratio to CGAL,
#                              the fitted growth exponents, the machine, the date
#   OUT/images/speed_plot.png  total seconds against faces, log-log (needs
#                              gnuplot; skipped, and said so, without it)
#   OUT/speed_runs.tsv         the raw rows the two are made from
#
# usage: benchmark/run_speed_benchmark.sh [options]       (from anywhere)
#   --max-faces N       largest size (default 1500000: all sizes)
#   --cgal-max-faces N  largest size for CGAL (default 400000; CGAL takes about
#                       400 s at 1.4M faces, so by default it stops at 356k)
#   --k K               number of segments (default 10)
#   --mesh FILE         input mesh (default data/elephant.off)
#   --out DIR           output directory (default doc)
#   --bin EXE           bench_segmentation_speed to run (default: build the
#                       target in build/ first, then run build/benchmark/...)
#   --smoke             only the two smallest sizes (the CTest smoke run)
#
# Sizes, from data/elephant.off (5,558 faces): decimated by edge collapse to
# a quarter (about 1,400 faces), as shipped, then 1, 2, 3, 4 midpoint
# subdivisions (22,232, 88,928, 355,712, 1,422,848 faces).
# Configurations: SpectralSeg with AABB ray casting on 1 thread and on all
# hardware threads, SpectralSeg with Embree ray casting (if built) on all
# threads, CGAL SDF (single-threaded).
# The full run takes about 7 minutes on 2 cores (longer on a busy machine);
# its largest process (SpectralSeg at 1.4M faces) peaks at about 1 GB.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)

MAX_FACES=1500000
CGAL_MAX_FACES=400000
K=10
MESH=$ROOT/data/elephant.off
OUT=$ROOT/doc
BIN=
SMOKE=0
usage() { sed -n '/^# usage:/,/^# *--smoke/p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 1; }
while [ $# -gt 0 ]; do
  case $1 in
    --max-faces) MAX_FACES=${2:?}; shift 2 ;;
    --cgal-max-faces) CGAL_MAX_FACES=${2:?}; shift 2 ;;
    --k) K=${2:?}; shift 2 ;;
    --mesh) MESH=${2:?}; shift 2 ;;
    --out) OUT=${2:?}; shift 2 ;;
    --bin) BIN=${2:?}; shift 2 ;;
    --smoke) SMOKE=1; shift ;;
    -h|--help) usage ;;
    *) echo "unknown option $1" >&2; usage ;;
  esac
done

if [ -z "$BIN" ]; then
  if [ ! -f "$ROOT/build/CMakeCache.txt" ]; then
    echo "no build/ directory: run scripts/build.sh first, or give --bin" >&2
    exit 1
  fi
  cmake --build "$ROOT/build" --target bench_segmentation_speed
  BIN=$ROOT/build/benchmark/bench_segmentation_speed
fi
command -v python3 >/dev/null || { echo "python3 is needed to write the table" >&2; exit 1; }

F0=$("$BIN" "$MESH" faces)
# size arguments of bench_segmentation_speed, with the face counts they give
SIZES=("--faces $((F0 / 4))")
FACES=($((F0 / 4)))
LEVELS=4
[ "$SMOKE" = 1 ] && LEVELS=0
for level in $(seq 0 "$LEVELS"); do
  SIZES+=("--subdivisions $level")
  FACES+=($((F0 << (2 * level))))
done

CONFIGS=("spectralseg 1")
THREADS_ALL=$(nproc)
[ "$THREADS_ALL" -gt 1 ] && CONFIGS+=("spectralseg 0")
if "$BIN" --methods | grep -x spectralseg-embree >/dev/null; then
  CONFIGS+=("spectralseg-embree 0")
else
  echo "note: built without Embree, no spectralseg-embree runs"
fi
CONFIGS+=("cgal-sdf 1")

mkdir -p "$OUT"
RUNS=$OUT/speed_runs.tsv
: > "$RUNS"
echo "speed benchmark: $(basename "$MESH") ($F0 faces), k = $K, sizes up to $MAX_FACES faces (CGAL up to $CGAL_MAX_FACES)," \
     "$THREADS_ALL hardware threads"
start=$SECONDS
for i in "${!SIZES[@]}"; do
  faces=${FACES[$i]}
  [ "$faces" -le "$MAX_FACES" ] || continue
  for config in "${CONFIGS[@]}"; do
    read -r method threads <<< "$config"
    if [ "$method" = cgal-sdf ] && [ "$faces" -gt "$CGAL_MAX_FACES" ]; then
      continue
    fi
    # shellcheck disable=SC2086 # the size is two words on purpose
    if row=$("$BIN" "$MESH" "$method" --k "$K" ${SIZES[$i]} --threads "$threads" --tsv); then
      echo "$row" >> "$RUNS"
      awk -F'\t' '{ printf "  %-20s %-26s %9s faces  %2s threads  total %9s s  peak %5s MB\n", $1, $2, $3, $4, $13, $14 }' <<< "$row"
    else
      status=$?
      printf '#failed\t%s\t%s\t%s\t%s\n' "$method" "${SIZES[$i]}" "$threads" "exit $status" >> "$RUNS"
      echo "  run FAILED: $method ${SIZES[$i]} --threads $threads (exit $status)"
    fi
  done
done
echo "runs took $((SECONDS - start)) s; raw rows in $RUNS"

python3 "$ROOT/benchmark/speed_report.py" "$RUNS" "$OUT" --mesh "${MESH#"$ROOT"/}" --cgal-max-faces "$CGAL_MAX_FACES" \
  --build-dir "$(dirname "$(dirname "$BIN")")" --commit "$(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo unknown)"
