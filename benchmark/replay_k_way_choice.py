#!/usr/bin/env python3
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Replays k-way's choice between its over-segmentation candidates offline.

Input: one or more files written by
    bench_psb_quality PSB_DIR --methods kway --candidates-out C.tsv [options]
(one row per candidate of each model: its concave normalized cut before and
after its graph cut, whether it was kept, and its own Rand-index error).

For each file, and averaged over the files, prints the psb-dev mean (and the
38 models whose id ends in 1 / the 57 others) of:
  - the library's choice (the kept candidate),
  - the lowest cut after the graph cut (the library's rule, recomputed),
  - the lowest cut before the graph cut (no graph cut needed to choose),
  - only the N candidates of the lowest cut before the graph cut cut, then
    the lowest cut after it among them (N = 1 .. candidates - 1),
  - the best candidate against the humans (an oracle, not a rule),
  - each candidate on its own (by its position in the order tried).
With --leave-out I (repeatable), candidate positions I are left out first,
counted from the end when negative (-2: the one before the contrast merge).

usage: replay_k_way_choice.py C1.tsv [C2.tsv ...] [--leave-out I ...]
"""
import csv
import sys
from collections import OrderedDict


def load(path):
    models = OrderedDict()
    with open(path) as f:
        for row in csv.DictReader(f, delimiter='\t'):
            models.setdefault(int(row['id']), []).append({
                'before': float(row['cut_before_graph_cut']),
                'after': float(row['cut']),
                'ri': float(row['ri_error']),
                'kept': row['kept'] == '1',
            })
    return models


def lowest(candidates, key):
    # ties go to the first tried, as in the library
    return min(range(len(candidates)), key=lambda i: (candidates[i][key], i))


def rules(count):
    out = OrderedDict()
    out['kept by the library'] = lambda c: next(i for i, x in enumerate(c) if x['kept'])
    out['lowest cut after the graph cut'] = lambda c: lowest(c, 'after')
    out['lowest cut before the graph cut'] = lambda c: lowest(c, 'before')
    for n in range(2, count):
        def top(c, n=n):
            order = sorted(range(len(c)), key=lambda i: (c[i]['before'], i))[:n]
            return min(order, key=lambda i: (c[i]['after'], i))
        out['%d graph cuts (lowest before), then lowest after' % n] = top
    out['best against the humans (oracle)'] = lambda c: lowest(c, 'ri')
    for i in range(count):
        out['candidate %d alone' % i] = lambda c, i=i: min(i, len(c) - 1)
    return out


def main(argv):
    files, leave_out = [], []
    it = iter(argv)
    for a in it:
        if a == '--leave-out':
            leave_out.append(int(next(it)))
        else:
            files.append(a)
    if not files:
        sys.exit(__doc__)
    data = []
    for path in files:
        models = load(path)
        for mid, c in models.items():
            drop = {i % len(c) for i in leave_out if -len(c) <= i < len(c)}
            models[mid] = [x for i, x in enumerate(c) if i not in drop] or c
        data.append(models)
    count = max(len(c) for models in data for c in models.values())
    table = OrderedDict()
    for name, rule in rules(count).items():
        row = []
        for models in data:
            try:
                picks = {mid: c[rule(c)]['ri'] for mid, c in models.items()}
            except StopIteration:  # a candidate left out was the kept one
                row.append(None)
                continue
            old = [v for mid, v in picks.items() if mid % 10 == 1]
            new = [v for mid, v in picks.items() if mid % 10 != 1]
            row.append((sum(picks.values()) / len(picks), sum(old) / max(1, len(old)), sum(new) / max(1, len(new))))
        table[name] = row
    print('| rule | ' + ' | '.join(files) + ' | mean (38 / 57) |')
    print('|---|' + '---:|' * (len(files) + 1))
    for name, row in table.items():
        cells = ['%.4f' % x[0] if x else '-' for x in row]
        done = [x for x in row if x]
        mean = ('%.4f (%.4f / %.4f)' % tuple(sum(x[j] for x in done) / len(done) for j in range(3))) if done else '-'
        print('| %s | %s | %s |' % (name, ' | '.join(cells), mean))


if __name__ == '__main__':
    main(sys.argv[1:])
