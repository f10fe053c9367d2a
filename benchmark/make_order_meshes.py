#!/usr/bin/env python3
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The meshes of the face-order speed benchmark (doc/benchmarks.md, "Speed
on any face order"): one triangle mesh at 1, 4 and 16 times its face count,
each in two orders of its faces and vertices.

- `NAME_xS_first.off`: 1-to-4 midpoint subdivision applied L times (S = 4^L);
  the four children of each face are written next to each other, the input's
  vertices first, then the midpoints in the order they are made (the order
  a subdividing exporter writes);
- `NAME_xS_scrambled.off`: the same mesh with its faces listed child by
  child (all first children, then all second children, ... of the last
  subdivision; at S = 1 a pseudo-random permutation) and its vertices in a
  pseudo-random order (fixed seed: the files are the same on every run).

usage: make_order_meshes.py MESH.off OUT_DIR [--levels 0,1,2]
Needs numpy (Debian's python3-numpy).
"""
import argparse
import os
import sys

import numpy as np


def read_off(path):
    with open(path) as f:
        words = f.read().split()
    if not words or words[0] != "OFF":
        sys.exit(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    at = 4
    points = np.array(words[at:at + 3 * nv], dtype=np.float64).reshape(nv, 3)
    at += 3 * nv
    faces = np.empty((nf, 3), dtype=np.int64)
    for i in range(nf):
        if words[at] != "3":
            sys.exit(f"{path}: face {i} is not a triangle")
        faces[i] = [int(words[at + 1]), int(words[at + 2]), int(words[at + 3])]
        at += 4
    return points, faces


def subdivide(points, faces):
    """1-to-4 midpoint subdivision; children of face f are 4f .. 4f+3."""
    edges = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    keys = np.sort(edges, axis=1)
    unique, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
    # midpoints numbered in the order their edge is first met (face by face)
    order = np.argsort(first, kind="stable")
    rank = np.empty_like(order)
    rank[order] = np.arange(len(order))
    mid_index = len(points) + rank[inverse.reshape(-1)]
    n = len(faces)
    ab, bc, ca = mid_index[:n], mid_index[n:2 * n], mid_index[2 * n:]
    mids = 0.5 * (points[unique[order, 0]] + points[unique[order, 1]])
    a, b, c = faces[:, 0], faces[:, 1], faces[:, 2]
    children = np.stack([np.stack([a, ab, ca], 1), np.stack([ab, b, bc], 1),
                         np.stack([ca, bc, c], 1), np.stack([ab, bc, ca], 1)], 1)
    return np.concatenate([points, mids]), children.reshape(-1, 3)


def write_off(path, points, faces):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(points)} {len(faces)} 0\n")
        np.savetxt(f, points, fmt="%.9g")
        np.savetxt(f, np.concatenate([np.full((len(faces), 1), 3), faces], 1), fmt="%d")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("mesh")
    p.add_argument("out_dir")
    p.add_argument("--levels", default="0,1,2")
    a = p.parse_args()
    os.makedirs(a.out_dir, exist_ok=True)
    name = os.path.splitext(os.path.basename(a.mesh))[0]
    points, faces = read_off(a.mesh)
    levels = sorted(int(x) for x in a.levels.split(","))
    rng = np.random.default_rng(20261125)
    for level in range(levels[-1] + 1):
        if level > 0:
            points, faces = subdivide(points, faces)
        if level not in levels:
            continue
        stem = os.path.join(a.out_dir, f"{name}_x{4 ** level}")
        write_off(stem + "_first.off", points, faces)
        if level == 0:
            face_order = rng.permutation(len(faces))
        else:
            face_order = np.arange(len(faces)).reshape(-1, 4).T.reshape(-1)
        new_of_old = rng.permutation(len(points))
        scrambled_points = np.empty_like(points)
        scrambled_points[new_of_old] = points
        write_off(stem + "_scrambled.off", scrambled_points, new_of_old[faces[face_order]])
        print(f"{stem}_first.off, {stem}_scrambled.off: {len(faces)} faces, {len(points)} vertices")


if __name__ == "__main__":
    main()
