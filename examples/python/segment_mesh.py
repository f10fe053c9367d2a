# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Segments a mesh with the spectralseg Python module.

Reads a mesh file into numpy arrays, segments it into k parts (k-way) and
into as many parts as it finds (automatic), prints the parts' areas, the
stage timings and the part-aware distance from a face to the farthest one,
and writes the labels, one per face, as `spectralseg segment --labels` does.

usage (from the repository root, after building):
    PYTHONPATH=build/python /usr/bin/python3 examples/python/segment_mesh.py [mesh.off] [k=6] [labels.seg]
"""
import sys

import numpy as np

import spectralseg


def face_areas(vertices, faces):
    a, b, c = (vertices[faces[:, i]] for i in range(3))
    return 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "data/human_man.off"
    k = int(sys.argv[2]) if len(sys.argv) > 2 else 6
    # Any (n, 3) float array and (m, 3) int array will do: trimesh's
    # mesh.vertices / mesh.faces, Open3D's np.asarray(mesh.triangles), libigl's V, F.
    vertices, faces = spectralseg.read_mesh(path)
    print(f"{path}: {len(vertices)} vertices, {len(faces)} faces")

    # k-way: part-aware metric, Nystrom embedding, K-means, graph cut
    labels, report = spectralseg.k_way_segmentation(vertices, faces, k, report=True)
    areas = np.bincount(labels, weights=face_areas(vertices, faces))
    print(f"k-way: {report['segments']} segments, area fractions "
          + " ".join(f"{a / areas.sum():.2f}" for a in areas))
    print("  stages: " + ", ".join(f"{stage} {seconds:.2f} s" for stage, seconds in report["timings"].items()))

    # k chosen by the library (the default method, contrast merge), then the
    # thesis's chapter 6 (recursive salient cuts)
    automatic = spectralseg.automatic_segmentation(vertices, faces)
    salient = spectralseg.automatic_segmentation(vertices, faces, method="salient_cuts")
    print(f"automatic: {automatic.max() + 1} segments (contrast merge), {salient.max() + 1} (salient cuts)")

    # part-aware distances from face 0
    distances = spectralseg.face_distances(vertices, faces, 0)
    far = int(np.argmax(np.where(np.isfinite(distances), distances, -1)))
    print(f"farthest face from face 0: {far}, part-aware distance {distances[far]:.3f}")

    if len(sys.argv) > 3:
        np.savetxt(sys.argv[3], labels, fmt="%d")
        print(f"labels: {sys.argv[3]}")

    # errors are Python exceptions: InvalidInputError is a ValueError
    try:
        spectralseg.k_way_segmentation(vertices, faces, len(faces) + 1)
    except ValueError as e:
        print(f"as expected: {e}")


if __name__ == "__main__":
    main()
