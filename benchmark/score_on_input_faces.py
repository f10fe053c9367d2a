#!/usr/bin/env python3
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Scores the label files that bench_psb_quality --labels-dir wrote for a
copy made by make_uneven_psb.py against the input's human segmentations,
on the input's faces: face i of the copy is the first child of input face
i, so each file is cut to the input's face count. Prints the mean
Rand-index error over all models, over the ids ending in 1 (the 38 of the
old psb-dev) and over the others, the parts per model, and the mean per
category (doc/benchmarks.md, "The same shapes with other triangles").

usage: score_on_input_faces.py PSB_DIR LABELS_DIR METHOD
Needs numpy (Debian's python3-numpy).
"""
import collections
import os
import sys

import numpy as np

from psb_human_scores import load, rand_index_error


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: score_on_input_faces.py PSB_DIR LABELS_DIR METHOD")
    psb, labels_dir, method = sys.argv[1:]
    with open(os.path.join(psb, "index.tsv")) as f:
        rows = [line.rstrip("\n").split("\t") for line in f if line.strip()][1:]
    error, parts, category = {}, {}, {}
    for row in rows:
        model = row[0]
        seg_dir = os.path.join(psb, "seg", model)
        humans = [load(os.path.join(seg_dir, name)) for name in sorted(os.listdir(seg_dir))]
        ours = load(os.path.join(labels_dir, f"{method}_{model}.seg"))
        if len(ours) < len(humans[0]):
            sys.exit(f"{method}_{model}.seg: {len(ours)} labels for {len(humans[0])} input faces")
        ours = ours[:len(humans[0])]
        error[model] = np.mean([rand_index_error(ours, h) for h in humans])
        parts[model] = len(np.unique(ours[ours >= 0]))
        category[model] = row[1]

    def mean(models):
        return np.mean([error[m] for m in models]) if models else float("nan")

    old = [m for m in error if m.endswith("1")]
    new = [m for m in error if not m.endswith("1")]
    print(f"{method}: all {mean(list(error)):.4f}  ids ending in 1 {mean(old):.4f}  others {mean(new):.4f}  "
          f"parts per model {np.mean(list(parts.values())):.2f}")
    by = collections.defaultdict(list)
    for m, c in category.items():
        by[c].append(m)
    print("  " + " ".join(f"{c} {mean(ms):.3f}" for c, ms in sorted(by.items(), key=lambda x: -mean(x[1]))))


if __name__ == "__main__":
    main()
