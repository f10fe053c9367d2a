#!/usr/bin/python3
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The mesh outputs of `spectralseg segment` and `render`, read back as a user
would: with Open3D (Debian's python3-open3d) and with a small PLY reader for
the face property `segment`, which Open3D does not expose.

usage: check_mesh_outputs.py SPECTRALSEG MESH WORK_DIR
Exit code 77 (skipped) when open3d cannot be imported.
"""
import os
import shutil
import struct
import subprocess
import sys

try:
    import numpy as np
    import open3d as o3d
except ImportError as e:
    print(f"skipped: {e} (install python3-open3d)")
    sys.exit(77)

failures = []


def check(ok, what):
    print(("ok: " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)


PLY_TYPES = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
             "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
             "float": "f", "float32": "f", "double": "d", "float64": "d"}


def read_ply(path):
    """{element: {property: [values]}} of an ASCII or binary little-endian PLY file."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    fmt = None
    elements = []  # (name, count, [(property, type, list count type or None)])
    for line in header:
        words = line.split()
        if words[0] == "format":
            fmt = words[1]
        elif words[0] == "element":
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property":
            if words[1] == "list":
                elements[-1][2].append((words[4], words[3], words[2]))
            else:
                elements[-1][2].append((words[2], words[1], None))
    assert fmt in ("ascii", "binary_little_endian"), fmt
    out = {}
    if fmt == "ascii":
        tokens = data[end:].split()
        at = 0
        for name, count, props in elements:
            values = {p[0]: [] for p in props}
            for _ in range(count):
                for prop, kind, count_kind in props:
                    if count_kind:
                        n = int(tokens[at])
                        values[prop].append([float(t) for t in tokens[at + 1:at + 1 + n]])
                        at += 1 + n
                    else:
                        values[prop].append(float(tokens[at]))
                        at += 1
            out[name] = values
        check(at == len(tokens), f"{path}: no data after the last element")
        return out
    at = end
    for name, count, props in elements:
        values = {p[0]: [] for p in props}
        for _ in range(count):
            for prop, kind, count_kind in props:
                if count_kind:
                    (n,) = struct.unpack_from("<" + PLY_TYPES[count_kind], data, at)
                    at += struct.calcsize(PLY_TYPES[count_kind])
                    f = "<" + PLY_TYPES[kind] * n
                    values[prop].append(list(struct.unpack_from(f, data, at)))
                    at += struct.calcsize(f)
                else:
                    f = "<" + PLY_TYPES[kind]
                    (v,) = struct.unpack_from(f, data, at)
                    values[prop].append(v)
                    at += struct.calcsize(f)
        out[name] = values
    check(at == len(data), f"{path}: the binary data ends with the last element")
    return out


def run(*args):
    r = subprocess.run(args, capture_output=True, text=True)
    check(r.returncode == 0, " ".join(args) + (f"\n{r.stdout}{r.stderr}" if r.returncode else ""))
    return r


def check_ply(path, labels, whole=True):
    """An Open3D read with vertex colours, one colour per segment, crisp
    faces, and the labels of the face property `segment`."""
    mesh = o3d.io.read_triangle_mesh(path)
    segments = sorted(set(labels))
    check(mesh.has_vertex_colors(), f"{path}: Open3D reads vertex colours")
    colors = np.round(np.asarray(mesh.vertex_colors) * 255).astype(int)
    distinct = {tuple(c) for c in colors}
    check(len(distinct) == len(segments),
          f"{path}: {len(distinct)} distinct vertex colours for {len(segments)} segments")
    check(len(mesh.triangles) == len(labels), f"{path}: {len(mesh.triangles)} triangles, {len(labels)} expected")
    ply = read_ply(path)
    face = ply["face"]
    read_labels = [int(s) for s in face["segment"]]
    check(read_labels == labels, f"{path}: the face property 'segment' holds the labels")
    # crisp: a face's three vertices have its colour, and one colour is one segment
    color_of_segment = {}
    crisp = True
    for f, corners in enumerate(face["vertex_indices"]):
        fc = (int(face["red"][f]), int(face["green"][f]), int(face["blue"][f]))
        crisp &= all(tuple(colors[int(v)]) == fc for v in corners)
        crisp &= color_of_segment.setdefault(read_labels[f], fc) == fc
    check(crisp, f"{path}: each face's vertices have the face's colour, one colour per segment")
    check(len(set(color_of_segment.values())) == len(segments), f"{path}: different segments, different colours")
    return mesh


def main():
    spectralseg, mesh_file, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    w = lambda name: os.path.join(work, name)

    # segment: labels, ASCII PLY, one binary PLY per part
    run(spectralseg, "segment", mesh_file, "--k", "4", "--labels", w("k4.seg"), "--mesh", w("k4.ply"),
        "--parts-dir", w("parts"), "--binary", "-q")
    run(spectralseg, "segment", mesh_file, "--k", "4", "--labels", w("k4_ascii.seg"), "--mesh", w("k4_ascii.ply"), "-q")
    labels = [int(l) for l in open(w("k4.seg")).read().split()]
    check(len(set(labels)) == 4 and min(labels) == 0, "4 segments labelled 0 to 3")
    check_ply(w("k4_ascii.ply"), [int(l) for l in open(w("k4_ascii.seg")).read().split()])
    whole = check_ply(w("k4.ply"), labels)  # binary: --binary
    check(open(w("k4.ply"), "rb").read(60).startswith(b"ply\nformat binary_little_endian 1.0\n"), "--binary: binary PLY")

    # --parts-dir: one file per segment, together the whole mesh
    parts = sorted(os.listdir(w("parts")))
    check(parts == [f"part_{s:03d}.ply" for s in range(4)], f"--parts-dir wrote {parts}")
    total = 0
    for s, name in enumerate(parts):
        part_labels = [s] * labels.count(s)
        part = check_ply(os.path.join(w("parts"), name), part_labels)
        total += len(part.triangles)
    check(total == len(whole.triangles), "the parts hold all the faces")

    # render: the same labels as OBJ + MTL, one material per segment
    run(spectralseg, "render", mesh_file, w("k4.seg"), "--mesh", w("k4.obj"), "-q")
    obj = o3d.io.read_triangle_mesh(w("k4.obj"))
    check(len(obj.triangles) == len(labels), "Open3D reads the OBJ")
    materials = [l.split()[1] for l in open(w("k4.mtl")) if l.startswith("newmtl ")]
    check(materials == [f"segment_{s}" for s in range(4)], f"the .mtl defines {materials}")
    current, obj_labels = None, []
    for line in open(w("k4.obj")):
        if line.startswith("usemtl "):
            current = int(line.split()[1].replace("segment_", ""))
        elif line.startswith("f "):
            obj_labels.append(current)
        elif line.startswith("mtllib "):
            check(line.split()[1] == "k4.mtl", "mtllib names the .mtl beside the OBJ")
    check(obj_labels == labels, "each OBJ face uses the material of its segment")

    print(f"mesh outputs: {len(failures)} failed")
    sys.exit(1 if failures else 0)


main()
