#!/usr/bin/env python3
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""A copy of a Princeton Segmentation Benchmark folder whose meshes are
tessellated otherwise (doc/benchmarks.md, "The same shapes with other
triangles"): on each model, the faces whose centroid lies on the lower
half of the longest axis of the bounding box (below the median centroid)
are split at their centroid into three, L times (3^L faces each); the
other half is unchanged. The
shape is the same, only its triangles differ: a segmentation that depends
on the shape alone scores the same on the copy. Every child face keeps its
parent's label in each human segmentation (`seg/ID/ID_i.seg`), and
`index.tsv` is copied with the new face counts.

`--half upper` splits the other half; `--half all` splits every face (a
control: the same change of the triangles, evenly); `--half all --scheme
midpoint` cuts every face into four at its edges' midpoints instead (a
finer copy of the same surface with triangles of the same shapes), and
`--half all --scheme loop` does the same with Loop's subdivision rules (the
surface smoothed, as a finer scan of the shape would be: its dihedral
angles shrink with the edges instead of staying on the old edges). The
first child of input face i is face i of the copy, so labels of the copy
cut to the input's face count score against the input's segmentations.

usage: make_uneven_psb.py PSB_DIR OUT_DIR [--levels 1] [--half lower|upper|all]
                          [--scheme centroid|midpoint|loop] [--ids 1,5,...]
Needs numpy (Debian's python3-numpy).
"""
import argparse
import os
import sys

import numpy as np

from make_order_meshes import read_off, subdivide, write_off
from psb_human_scores import load


def split_half(points, faces, levels, half):
    """Returns (points, faces, parent): parent[i] is the input face of face i."""
    centroids = points[faces].mean(axis=1)
    extent = points.max(axis=0) - points.min(axis=0)
    axis = int(np.argmax(extent))
    median = np.median(centroids[:, axis])
    chosen = {"lower": centroids[:, axis] < median, "upper": centroids[:, axis] >= median,
              "all": np.ones(len(faces), dtype=bool)}[half]
    parent = np.arange(len(faces))
    for _ in range(levels):
        idx = np.nonzero(chosen)[0]
        centre = points[faces[idx]].mean(axis=1)
        new_vertex = len(points) + np.arange(len(idx))
        points = np.concatenate([points, centre])
        a, b, c = faces[idx, 0], faces[idx, 1], faces[idx, 2]
        # the first child replaces its parent in place, the two others follow
        kids = [np.stack([a, b, new_vertex], 1), np.stack([b, c, new_vertex], 1),
                np.stack([c, a, new_vertex], 1)]
        faces = faces.copy()
        faces[idx] = kids[0]
        faces = np.concatenate([faces, kids[1], kids[2]])
        parent = np.concatenate([parent, parent[idx], parent[idx]])
        chosen = np.concatenate([chosen, np.ones(2 * len(idx), dtype=bool)])
    return points, faces, parent


def four_way_split(points, faces, levels, split=subdivide):
    """1-to-4 subdivision of every face by `split` (subdivide(): at the
    midpoints; loop_subdivide(): Loop's rules), L times; the first child of
    every face comes first, in the input's face order."""
    parent = np.arange(len(faces))
    for _ in range(levels):
        points, children = split(points, faces)
        faces = children.reshape(-1, 4, 3).transpose(1, 0, 2).reshape(-1, 3)
        parent = np.tile(parent, 4)
    return points, faces, parent


def loop_subdivide(points, faces):
    """subdivide()'s 1-to-4 split with Loop's rules for the positions: an
    edge's new vertex at 3/8 of its ends and 1/8 of the two opposite
    vertices (the midpoint on a boundary edge), an old vertex of valence n
    moved towards its neighbours' mean by n beta (Loop's beta); boundary
    vertices stay."""
    new_points, children = subdivide(points, faces)
    n_old = len(points)
    edges = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    opposite = np.concatenate([faces[:, 2], faces[:, 0], faces[:, 1]])
    keys = np.sort(edges, axis=1)
    unique, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.reshape(-1)
    order = np.argsort(first, kind="stable")  # as subdivide() numbers the midpoints
    far = np.zeros((len(unique), 3))
    count = np.zeros(len(unique))
    np.add.at(far, inverse, points[opposite])
    np.add.at(count, inverse, 1)
    ends = points[unique[:, 0]] + points[unique[:, 1]]
    edge_point = np.where((count == 2)[:, None], 0.375 * ends + 0.125 * far, 0.5 * ends)
    boundary = np.zeros(n_old, dtype=bool)
    boundary[unique[count != 2].reshape(-1)] = True
    total = np.zeros((n_old, 3))
    valence = np.zeros(n_old)
    for i, j in ((0, 1), (1, 0)):
        np.add.at(total, unique[:, i], points[unique[:, j]])
        np.add.at(valence, unique[:, i], 1)
    v = np.maximum(valence, 1)
    beta = (0.625 - (0.375 + 0.25 * np.cos(2 * np.pi / v)) ** 2) / v
    moved = (1 - v * beta)[:, None] * points + beta[:, None] * total
    moved[boundary | (valence == 0)] = points[boundary | (valence == 0)]
    new_points = new_points.copy()
    new_points[:n_old] = moved
    new_points[n_old:] = edge_point[order]
    return new_points, children


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("psb")
    parser.add_argument("out")
    parser.add_argument("--levels", type=int, default=1)
    parser.add_argument("--ids", default="")
    parser.add_argument("--half", choices=["lower", "upper", "all"], default="lower",
                        help="the faces split: the lower half (default), the upper half, or all (a control)")
    parser.add_argument("--scheme", choices=["centroid", "midpoint", "loop"], default="centroid",
                        help="centroid: each chosen face into 3 at its centroid (default); midpoint: every "
                             "face into 4 at its edges' midpoints (a finer copy; needs --half all); loop: "
                             "the same split with Loop's smoothing rules (needs --half all)")
    args = parser.parse_args()
    if args.levels < 1:
        sys.exit("--levels must be at least 1")
    if args.scheme in ("midpoint", "loop") and args.half != "all":
        sys.exit(f"--scheme {args.scheme} splits every face: give --half all")
    wanted = set(args.ids.split(",")) if args.ids else None
    with open(os.path.join(args.psb, "index.tsv")) as f:
        header, *rows = [line.rstrip("\n").split("\t") for line in f if line.strip()]
    os.makedirs(os.path.join(args.out, "off"), exist_ok=True)
    kept = []
    for row in rows:
        model = row[0]
        if wanted is not None and model not in wanted:
            continue
        points, faces = read_off(os.path.join(args.psb, "off", model + ".off"))
        if args.scheme in ("midpoint", "loop"):
            split = loop_subdivide if args.scheme == "loop" else subdivide
            points, faces, parent = four_way_split(points, faces, args.levels, split)
        else:
            points, faces, parent = split_half(points, faces, args.levels, args.half)
        write_off(os.path.join(args.out, "off", model + ".off"), points, faces)
        seg_in = os.path.join(args.psb, "seg", model)
        seg_out = os.path.join(args.out, "seg", model)
        os.makedirs(seg_out, exist_ok=True)
        for name in sorted(os.listdir(seg_in)):
            labels = load(os.path.join(seg_in, name))
            np.savetxt(os.path.join(seg_out, name), labels[parent], fmt="%d")
        row = list(row)
        row[header.index("faces")] = str(len(faces))
        kept.append(row)
    with open(os.path.join(args.out, "index.tsv"), "w") as f:
        for row in [header] + kept:
            f.write("\t".join(row) + "\n")


if __name__ == "__main__":
    main()
