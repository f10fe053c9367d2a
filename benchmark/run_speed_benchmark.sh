#!/usr/bin/env bash
# Speed table: SpectralSeg k-way (AABB and Embree ray casting) against CGAL's
# SDF segmentation (sdf_values + segmentation_from_sdf_values) on the same
# meshes in the same run, each configuration in its own process.
# usage: benchmark/run_speed_benchmark.sh MESH [max_subdivisions=2] [k=10] [threads=0]
set -euo pipefail
cd "$(dirname "$0")/.."
MESH=${1:?usage: $0 MESH [max_subdivisions] [k] [threads]}
LEVELS=${2:-2}
K=${3:-10}
THREADS=${4:-0}
BIN=./build/benchmark/bench_segmentation_speed
echo "| method | mesh | faces | threads | k | segments | metric s | segmentation s | total s | peak MB |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"
for level in $(seq 0 "$LEVELS"); do
  for method in spectralseg spectralseg-embree cgal-sdf; do
    "$BIN" "$MESH" "$method" "$K" "$level" "$THREADS" || echo "| $method | failed at level $level | | | | | | | | |"
  done
done
