#!/usr/bin/env bash
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Where the cores are idle in a whole command: samples it with `perf record`
# (F samples per second on each thread) and prints one line per B seconds:
# the samples taken in it (2 x F x B when both cores were busy, F x B when
# one was) and the three functions most seen, the innermost frame of ours,
# CGAL's, Eigen's, Embree's or the max-flow's.
#
# usage: B=0.05 F=2000 benchmark/perf_timeline.sh build/tools/spectralseg segment MESH --k 10 --labels L
# Needs perf (Debian's linux-perf) and python3.
set -euo pipefail
DATA=$(mktemp -d)
trap 'rm -rf "$DATA"' EXIT
perf record -F "${F:-2000}" -g -o "$DATA/perf.data" "$@" >/dev/null 2>&1
perf script -i "$DATA/perf.data" -F tid,time,ip,sym 2>/dev/null >"$DATA/samples.txt"
B=${B:-0.05} python3 - "$DATA/samples.txt" <<'PY'
import collections, os, re, sys
rows, cur = [], None
for line in open(sys.argv[1]):
    m = re.match(r'\s*(\d+)\s+([\d.]+):\s*$', line)
    if m:
        cur = [float(m[2]), []]
        rows.append(cur)
    elif cur is not None and line.strip():
        cur[1].append(line.strip())
if not rows:
    sys.exit("no samples")
width = float(os.environ["B"])
keys = ('SpectralSeg', 'main', 'CGAL', 'Eigen', 'MaxFlow', 'rtc', 'embree')
def name(stack):
    for frame in stack:
        f = frame.split(None, 1)[1] if ' ' in frame else frame
        if any(k in f for k in keys):
            return re.sub(r'\(.*', '', re.sub(r'<.*', '', f))[-45:]
    return (stack[0].split(None, 1)[1] if stack else '?')[:40]
start = rows[0][0]
buckets = collections.defaultdict(list)
for t, stack in rows:
    buckets[int((t - start) / width)].append(name(stack))
for b in sorted(buckets):
    seen = collections.Counter(buckets[b])
    print('%6.2f %4d %s' % (b * width, len(buckets[b]), '; '.join('%s %d' % kv for kv in seen.most_common(3))))
PY
