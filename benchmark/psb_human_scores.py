#!/usr/bin/env python3
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Per model of a PSB-like directory: the humans' numbers of segments, the
humans' leave-one-out Rand-index error (each human against the others), and
optionally a method's error from a bench_psb_quality --out TSV beside it.

usage: psb_human_scores.py PSB_DIR [RESULTS.tsv [METHOD]]   (METHOD default kway; needs numpy: /usr/bin/python3 on Debian)
"""
import glob
import sys

import numpy as np


def load(path):
    return np.loadtxt(path, dtype=np.int64).ravel()


def rand_index_error(a, b):
    """1 - Rand index over unordered face pairs, from the contingency table."""
    n = len(a)
    _, ai = np.unique(a, return_inverse=True)
    _, bi = np.unique(b, return_inverse=True)
    table = np.zeros((ai.max() + 1, bi.max() + 1))
    np.add.at(table, (ai, bi), 1)
    pairs = lambda x: (x * (x - 1) / 2).sum()
    total = n * (n - 1) / 2
    agree = total - pairs(table.sum(1)) - pairs(table.sum(0)) + 2 * pairs(table)
    return 1 - agree / total


def main():
    root = sys.argv[1]
    ours = {}
    method = sys.argv[3] if len(sys.argv) > 3 else 'kway'
    if len(sys.argv) > 2:
        for line in open(sys.argv[2]).read().split('\n')[1:]:
            t = line.split('\t')
            if len(t) > 6 and t[2] == method:
                ours[t[0]] = float(t[6])
    rows = [l.split('\t') for l in open(root + '/index.tsv').read().split('\n')[1:] if l]
    mean = 0.
    for r in rows:
        humans = [load(f) for f in sorted(glob.glob(f'{root}/seg/{r[0]}/{r[0]}_*.seg'))]
        ks = sorted(len(np.unique(h)) for h in humans)
        loo = np.mean([np.mean([rand_index_error(humans[a], humans[b]) for b in range(len(humans)) if b != a])
                       for a in range(len(humans))])
        mean += loo
        extra = ' method %.3f' % ours[r[0]] if r[0] in ours else ''
        print(f'{r[0]} {r[1]} k {r[3]} humans k {ks} humans {loo:.3f}{extra}')
    print('mean of the humans against each other: %.3f' % (mean / len(rows)))


if __name__ == '__main__':
    main()
