#!/usr/bin/env bash
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# A change of a constant or a rule is judged on psb-dev in several
# conditions, not in one (doc/benchmarks.md, "How far a score moves when the
# metric is perturbed"): this runs build/benchmark/bench_psb_quality with
# the options given after `--` in eight of them (Nyström seeds 0, 1 and 2;
# 12 and 24 rays per reference-point cone; cone openings of 79 and 81
# degrees; the AABB ray caster) and prints, per condition and method, the
# Rand-index error on all models, on the 38 whose ids end in 1 and on the
# 57 others, and the segments per model. Each run's rows stay in OUT.
#
# usage: benchmark/run_quality_conditions.sh [--methods kway,contrast] [--out DIR]
#          [--psb ../shared/data/psb-dev] [-- BENCH_OPTIONS...]
# example: benchmark/run_quality_conditions.sh --methods contrast -- --over-segmentations 5
# About 4 minutes for both methods on a quiet 2-core machine.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
METHODS=kway,contrast
OUT=${TMPDIR:-/tmp}/spectralseg-quality-conditions
PSB=$ROOT/../shared/data/psb-dev
while [ $# -gt 0 ]; do
  case $1 in
    --methods) METHODS=${2:?}; shift 2 ;;
    --out) OUT=${2:?}; shift 2 ;;
    --psb) PSB=${2:?}; shift 2 ;;
    --) shift; break ;;
    -h|--help) sed -n '/^# usage:/,/^# About/p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "unknown option $1 (bench options go after --)" >&2; exit 1 ;;
  esac
done
BUILD=${BUILD_DIR:-$ROOT/build} # another build folder: BUILD_DIR=...
cmake --build "$BUILD" --target bench_psb_quality >/dev/null
mkdir -p "$OUT"
conditions=("seed0:--seed 0" "seed1:--seed 1" "seed2:--seed 2" "rays12:--reference-rays 12"
            "rays24:--reference-rays 24" "cone79:--reference-cone 79" "cone81:--reference-cone 81"
            "aabb:--ray-caster aabb")
for c in "${conditions[@]}"; do
  name=${c%%:*}
  read -r -a condition <<<"${c#*:}"
  "$BUILD/benchmark/bench_psb_quality" "$PSB" --methods "$METHODS" "${condition[@]}" "$@" \
    --out "$OUT/$name.tsv" >/dev/null
  python3 - "$OUT/$name.tsv" "$name" <<'EOF'
import sys
rows = {}
for line in open(sys.argv[1]):
    f = line.rstrip("\n").split("\t")
    if f[0] == "id":
        continue
    rows.setdefault(f[2], []).append((int(f[0]), int(f[5]), float(f[6])))
for method, r in sorted(rows.items()):
    mean = lambda v: sum(v) / len(v) if v else float("nan")
    print(f"{sys.argv[2]:7s} {method:9s} all {mean([e for _, _, e in r]):.4f}"
          f"  38 {mean([e for i, _, e in r if i % 10 == 1]):.4f}"
          f"  57 {mean([e for i, _, e in r if i % 10 != 1]):.4f}"
          f"  segments {mean([s for _, s, _ in r]):.2f}")
EOF
done
