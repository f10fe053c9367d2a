# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Headless test of the Blender add-on, run by Blender itself:

    blender -b --factory-startup --python-exit-code 1 --python test_addon.py -- \
        --addon ZIP --module-dir DIR --mesh MESH.off [--expect-k K LABELS.seg] \
        [--expect-auto LABELS.seg] [--auto] [--render OUT.png]

Installs the add-on from its zip (as a user does in Preferences > Add-ons >
Install), enables it, builds the mesh of an OFF file in the file's vertex
and face order, runs the operator and checks its parts against the labels
the spectralseg tool wrote for the same file. With --render it also renders
the segmented mesh with Cycles (the picture of doc/blender.md).
"""
import argparse
import importlib.util
import os
import sys

import bpy
import numpy as np
from mathutils import Vector

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
parser = argparse.ArgumentParser()
parser.add_argument("--addon", required=True)
parser.add_argument("--module-dir", default="")
parser.add_argument("--mesh", required=True)
parser.add_argument("--expect-k", nargs=2, metavar=("K", "LABELS"))
parser.add_argument("--expect-auto", metavar="LABELS")
parser.add_argument("--auto", action="store_true", help="segment automatically, nothing to compare (for --render)")
parser.add_argument("--render", metavar="PNG")
args = parser.parse_args(argv)
failures = []


def check(ok, what):
    print(("ok: " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)


def read_off(path):
    words = []
    for line in open(path):
        words += line.split("#")[0].split()
    assert words[0].endswith("OFF")
    nv, nf = int(words[1]), int(words[2])
    at = 4
    vertices = [tuple(float(x) for x in words[at + 3 * i:at + 3 * i + 3]) for i in range(nv)]
    at += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(words[at])
        faces.append([int(x) for x in words[at + 1:at + 1 + n]])
        at += 1 + n
    return vertices, faces


def read_labels(path):
    return np.array([int(line) for line in open(path) if line.strip()], dtype=np.int64)


def same_partition(a, b):
    """The same parts, whatever their numbers."""
    if len(a) != len(b):
        return False
    pairs = set(zip(a.tolist(), b.tolist()))
    return len(pairs) == len(set(a.tolist())) == len(set(b.tolist()))


bpy.ops.preferences.addon_install(filepath=os.path.abspath(args.addon), overwrite=True)
bpy.ops.preferences.addon_enable(module="spectralseg_blender")
check("spectralseg_blender" in bpy.context.preferences.addons, "the add-on is installed and enabled")
bpy.context.preferences.addons["spectralseg_blender"].preferences.module_dir = args.module_dir

for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj)
vertices, faces = read_off(args.mesh)
mesh = bpy.data.meshes.new("model")
mesh.from_pydata(vertices, [], faces)
mesh.update()
obj = bpy.data.objects.new("model", mesh)
bpy.context.scene.collection.objects.link(obj)
bpy.context.view_layer.objects.active = obj
obj.select_set(True)
check(len(mesh.polygons) == len(faces), "the mesh has the file's %d faces" % len(faces))


def labels_of(o):
    a = o.data.attributes["spectralseg_segment"]
    out = np.zeros(len(a.data), dtype=np.int32)
    a.data.foreach_get("value", out)
    return out.astype(np.int64)


if args.expect_k:
    k, path = int(args.expect_k[0]), args.expect_k[1]
    result = bpy.ops.mesh.spectralseg_segment(method="K_WAY", k=k, vertex_groups=True)
    check(result == {"FINISHED"}, "k-way operator finished")
    labels = labels_of(obj)
    tool = read_labels(path)
    check(same_partition(labels, tool), "k-way: the tool's %d parts" % len(set(tool.tolist())))
    check(len(mesh.materials) == k, "one material per segment")
    index = np.zeros(len(mesh.polygons), dtype=np.int32)
    mesh.polygons.foreach_get("material_index", index)
    check((index == labels).all(), "each face has its segment's material")
    groups = [g for g in obj.vertex_groups if g.name.startswith("segment ")]
    check(len(groups) == k, "one vertex group per segment")

if args.expect_auto:
    result = bpy.ops.mesh.spectralseg_segment(method="CONTRAST_MERGE", separate=True)
    check(result == {"FINISHED"}, "automatic operator finished")
    labels = labels_of(obj)
    tool = read_labels(args.expect_auto)
    check(same_partition(labels, tool), "automatic: the tool's %d parts" % len(set(tool.tolist())))
    parts = [o for o in bpy.data.objects if o.name.startswith("model part ")]
    check(len(parts) == len(set(tool.tolist())), "one object per part")
    check(sum(len(p.data.polygons) for p in parts) == len(faces), "the parts hold every face once")
    for p in parts:
        bpy.data.objects.remove(p)
    obj.hide_set(False)
    result = bpy.ops.mesh.spectralseg_segment(method="CONTRAST_MERGE", parts=3)
    check(len(set(labels_of(obj).tolist())) == 3, "automatic cut at 3 parts")
    # both salient-cut methods (they take no metric), cut at 2 parts
    for method in ("SALIENT_CUTS", "SALIENT_CUTS_THESIS"):
        result = bpy.ops.mesh.spectralseg_segment(method=method, parts=2)
        check(result == {"FINISHED"} and len(set(labels_of(obj).tolist())) == 2, method + " cut at 2 parts")

if args.auto:
    check(bpy.ops.mesh.spectralseg_segment(method="CONTRAST_MERGE") == {"FINISHED"}, "automatic operator finished")

# a missing module is an error the user can act on, not a crash
saved = sys.modules.pop("spectralseg", None)
saved_path = list(sys.path)
sys.path[:] = [p for p in sys.path if os.path.abspath(p) != os.path.abspath(args.module_dir)]
bpy.context.preferences.addons["spectralseg_blender"].preferences.module_dir = "/nonexistent"
if importlib.util.find_spec("spectralseg") is None:  # not installed system-wide
    try:
        result = bpy.ops.mesh.spectralseg_segment(method="K_WAY", k=2)
    except RuntimeError as e:  # an operator that reports an error raises in background mode
        result = {"CANCELLED"}
        check("spectralseg Python module is not found" in str(e), "the missing module is named")
    check(result == {"CANCELLED"}, "without the module the operator cancels")
sys.path[:] = saved_path
if saved is not None:
    sys.modules["spectralseg"] = saved
bpy.context.preferences.addons["spectralseg_blender"].preferences.module_dir = args.module_dir

if args.render:
    # Cycles on the CPU: the segmented mesh seen from the front, a bit above
    scene = bpy.context.scene
    obj.rotation_euler = (np.pi / 2, 0.0, 0.0)  # the OFF file's +y up is Blender's +z, as its importers do
    bpy.context.view_layer.update()
    scene.view_settings.view_transform = "Standard"
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 32
    scene.cycles.use_denoising = False  # Debian's Blender has no OpenImageDenoise
    scene.render.resolution_x, scene.render.resolution_y = 640, 480
    scene.render.film_transparent = False
    world = bpy.data.worlds.new("white")
    world.color = (1.0, 1.0, 1.0)
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
    scene.world = world
    corners = np.array([obj.matrix_world @ v.co for v in obj.data.vertices])
    low, high = corners.min(axis=0), corners.max(axis=0)
    center, size = (low + high) / 2, float(np.linalg.norm(high - low))
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    scene.collection.objects.link(camera)
    direction = np.array([0.3, -1.0, 0.3])  # from the front (-y), a bit right and above
    direction /= np.linalg.norm(direction)
    camera.location = tuple(center + direction * size * 1.6)
    camera.rotation_euler = Vector(tuple(-direction)).to_track_quat("-Z", "Y").to_euler()
    scene.camera = camera
    sun = bpy.data.objects.new("sun", bpy.data.lights.new("sun", type="SUN"))
    sun.data.energy = 3.0
    sun.rotation_euler = (0.6, 0.2, 0.4)
    scene.collection.objects.link(sun)
    scene.render.filepath = os.path.abspath(args.render)
    bpy.ops.render.render(write_still=True)
    check(os.path.exists(args.render), "rendered " + args.render)

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
