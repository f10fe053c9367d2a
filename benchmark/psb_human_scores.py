#!/usr/bin/env python3
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Per model of a PSB-like directory: the humans' numbers of segments, the
humans' leave-one-out Rand-index error (each human against the others), and
optionally a method's error from a bench_psb_quality --out TSV beside it.

With --categories, a Markdown table per category instead: each human's
leave-one-out error on a model, summarised per model as the humans' mean,
their median and the best human (the one closest to the others), averaged
over the category's models; then every method of RESULTS.tsv, and the
peers' labels in PSB_DIR/peers/<name>/<id>.seg when that folder exists.
A category's bar below the humans' mean asks a method to agree with the
humans more than a typical human does; the best human shows how far that
can go.

usage: psb_human_scores.py PSB_DIR [RESULTS.tsv [METHOD]]   (METHOD default kway; needs numpy: /usr/bin/python3 on Debian)
       psb_human_scores.py --categories PSB_DIR [RESULTS.tsv]
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


def human_errors(root, model):
    """Each human's leave-one-out Rand-index error on `model`, and the humans' labels."""
    humans = [load(f) for f in sorted(glob.glob(f'{root}/seg/{model}/{model}_*.seg'))]
    loo = [np.mean([rand_index_error(humans[a], humans[b]) for b in range(len(humans)) if b != a])
           for a in range(len(humans))]
    return loo, humans


def categories(root, results):
    rows = [l.split('\t') for l in open(root + '/index.tsv').read().split('\n')[1:] if l]
    methods, ours = [], {}
    if results:
        for line in open(results).read().split('\n')[1:]:
            t = line.split('\t')
            if len(t) > 6:
                if t[2] not in methods:
                    methods.append(t[2])
                ours[(t[0], t[2])] = float(t[6])
    peers = sorted(d.split('/')[-2] for d in glob.glob(f'{root}/peers/*/'))
    columns = ['humans, mean', 'humans, median', 'best human'] + methods + peers
    table = {}
    for r in rows:
        loo, humans = human_errors(root, r[0])
        values = [np.mean(loo), np.median(loo), min(loo)]
        values += [ours.get((r[0], m), np.nan) for m in methods]
        for p in peers:
            labels = load(f'{root}/peers/{p}/{r[0]}.seg')
            values.append(np.mean([rand_index_error(labels, h) for h in humans]))
        table.setdefault(r[1], []).append(values)
    print('| category | ' + ' | '.join(columns) + ' |')
    print('|---|' + '---:|' * len(columns))
    every = []
    for c in sorted(table):
        every += table[c]
        print(f'| {c} | ' + ' | '.join('%.3f' % v for v in np.mean(table[c], axis=0)) + ' |')
    print('| **all** | ' + ' | '.join('**%.3f**' % v for v in np.mean(every, axis=0)) + ' |')


def main():
    if len(sys.argv) > 2 and sys.argv[1] == '--categories':
        categories(sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else None)
        return
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
        each, humans = human_errors(root, r[0])
        ks = sorted(len(np.unique(h)) for h in humans)
        loo = np.mean(each)
        mean += loo
        extra = ' method %.3f' % ours[r[0]] if r[0] in ours else ''
        print(f'{r[0]} {r[1]} k {r[3]} humans k {ks} humans {loo:.3f}{extra}')
    print('mean of the humans against each other: %.3f' % (mean / len(rows)))


if __name__ == '__main__':
    main()
