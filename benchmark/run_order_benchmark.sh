#!/usr/bin/env bash
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The armadillo table of doc/benchmarks.md ("Speed on any face order"): the
# whole command a user runs, `spectralseg segment MESH --k 10 --labels L
# --json J`, on armadillo at 52,000, 208,000 and 832,000 faces, each in two
# orders of its faces and vertices (benchmark/make_order_meshes.py: the
# children of a face next to each other, and scrambled), with the default
# Embree ray caster, `--ray-caster aabb` and `--k auto`; CGAL's SDF
# segmentation (sdf_values + segmentation_from_sdf_values, single-threaded,
# build/benchmark/bench_segmentation_speed) in the same run as the reference.
# Wall seconds and peak resident memory of each process (GNU time), the
# median of REPEATS runs, the configurations alternating within each round.
#
# usage: benchmark/run_order_benchmark.sh [--repeats 3] [--levels 0,1,2]
#          [--cgal-levels 0,1,2] [--threads 2] [--out doc/armadillo_speed_table.md]
#          [--mesh ../shared/data/meshes/armadillo.off] [--work DIR]
# Needs build/tools/spectralseg and build/benchmark/bench_segmentation_speed
# (or those of BUILD_DIR)
# (built first if missing), python3 with numpy. Takes about 25 minutes on 2
# cores with the defaults (CGAL alone about 10 of them). Run it on a quiet
# machine: another process on the same cores changes the figures by 50%.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
REPEATS=3
LEVELS=0,1,2
CGAL_LEVELS=0,1,2
THREADS=2
OUT=$ROOT/doc/armadillo_speed_table.md
MESH=$ROOT/../shared/data/meshes/armadillo.off
WORK=${TMPDIR:-/tmp}/spectralseg-order-benchmark
while [ $# -gt 0 ]; do
  case $1 in
    --repeats) REPEATS=${2:?}; shift 2 ;;
    --levels) LEVELS=${2:?}; shift 2 ;;
    --cgal-levels) CGAL_LEVELS=${2:?}; shift 2 ;;
    --threads) THREADS=${2:?}; shift 2 ;;
    --out) OUT=${2:?}; shift 2 ;;
    --mesh) MESH=${2:?}; shift 2 ;;
    --work) WORK=${2:?}; shift 2 ;;
    -h|--help) sed -n '/^# usage:/,/^# machine/p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "unknown option $1" >&2; exit 1 ;;
  esac
done
BUILD=${BUILD_DIR:-$ROOT/build} # another build folder: BUILD_DIR=...
TOOL=$BUILD/tools/spectralseg
BENCH=$BUILD/benchmark/bench_segmentation_speed
for t in spectralseg bench_segmentation_speed; do
  cmake --build "$BUILD" --target $t >/dev/null
done
mkdir -p "$WORK"
/usr/bin/python3 "$ROOT/benchmark/make_order_meshes.py" "$MESH" "$WORK" --levels "$LEVELS"
NAME=$(basename "$MESH" .off)
RUNS=$WORK/runs.tsv
: >"$RUNS"

# one process: appends "config mesh faces seconds peak_kb"
run() {
  local config=$1 mesh=$2 faces=$3
  shift 3
  local t=$WORK/time.txt
  /usr/bin/time -o "$t" -f "%e %M" "$@" >/dev/null 2>"$WORK/stderr.txt" || {
    echo "failed: $*" >&2
    cat "$WORK/stderr.txt" >&2
    exit 1
  }
  echo "$config $mesh $faces $(cat "$t")" >>"$RUNS"
}

IFS=, read -r -a levels <<<"$LEVELS"
IFS=, read -r -a cgal_levels <<<"$CGAL_LEVELS"
for round in $(seq 1 "$REPEATS"); do
  for level in "${levels[@]}"; do
    scale=$((1 << (2 * level)))
    for order in first scrambled; do
      mesh=$WORK/${NAME}_x${scale}_${order}.off
      faces=$(head -2 "$mesh" | tail -1 | cut -d' ' -f2)
      common=(segment "$mesh" --labels "$WORK/labels.txt" --json "$WORK/report.json" --threads "$THREADS")
      run default "x${scale}_${order}" "$faces" "$TOOL" "${common[@]}" --k 10
      run aabb "x${scale}_${order}" "$faces" "$TOOL" "${common[@]}" --k 10 --ray-caster aabb
      run auto "x${scale}_${order}" "$faces" "$TOOL" "${common[@]}" --k auto
    done
    # CGAL once per size and round (its time does not depend on our order)
    if [[ " ${cgal_levels[*]} " == *" $level "* ]] && { [ "$level" = 0 ] || [ "$round" = 1 ]; }; then
      mesh=$WORK/${NAME}_x${scale}_first.off
      faces=$(head -2 "$mesh" | tail -1 | cut -d' ' -f2)
      run cgal-sdf "x${scale}_first" "$faces" "$BENCH" "$mesh" cgal-sdf --k 10
    fi
  done
done

/usr/bin/python3 - "$RUNS" "$OUT" "$THREADS" "$REPEATS" "$NAME" <<'PY'
import collections, datetime, os, platform, statistics, sys
runs, out, threads, repeats, name = sys.argv[1:6]
rows = collections.defaultdict(list)
faces = {}
for line in open(runs):
    config, mesh, f, sec, kb = line.split()
    rows[(config, mesh)].append((float(sec), int(kb)))
    faces[mesh] = int(f)
def med(key):
    v = rows.get(key)
    if not v:
        return None
    return statistics.median(s for s, _ in v), max(k for _, k in v) / 1024.
cgal = {}
for (config, mesh), v in rows.items():
    if config == "cgal-sdf":
        cgal[mesh.split("_")[0]] = med((config, mesh))[0]
lines = []
cpu = "?"
try:
    for l in open("/proc/cpuinfo"):
        if l.startswith("model name"):
            cpu = l.split(":", 1)[1].strip()
            break
except OSError:
    pass
lines.append(f"Whole command, {name}, k = 10 (`--k auto`: chosen), {threads} threads for SpectralSeg, "
             f"CGAL's SDF segmentation single-threaded; median of {repeats} runs (CGAL: 1 run above 52,000 "
             f"faces); {datetime.date.today()}, {cpu}, {os.cpu_count()} hardware threads. "
             f"Regenerate: `bash benchmark/run_order_benchmark.sh`.")
lines.append("")
lines.append("| faces | order | default s | default MB | ratio to CGAL | `--ray-caster aabb` s | ratio | `--k auto` s | `--k auto` MB | CGAL SDF s |")
lines.append("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
meshes = sorted({m for (_, m) in rows if not m.startswith("cgal")}, key=lambda m: (faces[m], m))
for m in meshes:
    size, order = m.split("_")
    d, a, au = med(("default", m)), med(("aabb", m)), med(("auto", m))
    if d is None:
        continue
    c = cgal.get(size)
    ratio = lambda x: f"{x / c:.3f}" if c and x is not None else ""
    lines.append(f"| {faces[m]:,} | {order} | {d[0]:.2f} | {d[1]:.0f} | {ratio(d[0])} | {a[0]:.2f} | {ratio(a[0])} | "
                 f"{au[0]:.2f} | {au[1]:.0f} | {c:.1f} |" if c else
                 f"| {faces[m]:,} | {order} | {d[0]:.2f} | {d[1]:.0f} | | {a[0]:.2f} | | {au[0]:.2f} | {au[1]:.0f} | |")
# growth exponents from the smallest size, per order
import math
for order in ("first", "scrambled"):
    ms = [m for m in meshes if m.endswith(order)]
    if len(ms) >= 2:
        lo, hi = ms[0], ms[-1]
        e = math.log(med(("default", hi))[0] / med(("default", lo))[0]) / math.log(faces[hi] / faces[lo])
        lines.append("")
        lines.append(f"Growth exponent of the default command, {order} order, {faces[lo]:,} to {faces[hi]:,} faces: {e:.2f}.")
open(out, "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY
