# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Blender add-on: segments the active mesh object with SpectralSeg.

The result is stored the way Blender users work with parts: an integer face
attribute ``spectralseg_segment``, one material per segment (its colour is
the tool's colour of that segment), optionally one vertex group per segment
and one object per part. The work is done by the ``spectralseg`` Python
module (``pip install --no-build-isolation .`` from a SpectralSeg checkout,
or the folder of a build given in the add-on's preferences).
"""

bl_info = {
    "name": "SpectralSeg",
    "author": "SpectralSeg developers",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > SpectralSeg; Object > SpectralSeg: Segment Mesh",
    "description": "Split a mesh into the parts a person would see (spectral mesh segmentation)",
    "category": "Mesh",
}

import importlib
import sys

import bpy
import numpy as np
from bpy.props import BoolProperty, EnumProperty, IntProperty, StringProperty

ATTRIBUTE = "spectralseg_segment"

METHODS = [
    ("CONTRAST_MERGE", "Automatic", "As many parts as the shape has: over-segment, merge where boundaries are weak "
     "(the tool's --k auto, its default method)", 0),
    ("K_WAY", "k parts", "Exactly k parts by spectral clustering of the part-aware metric (--k K)", 1),
    ("CONCAVE_MERGE", "Automatic, concavity only", "Merge while the weakest boundary is weakly concave "
     "(--k auto --auto-method concave-merge)", 2),
    ("SALIENT_CUTS", "Automatic, salient cuts", "Top-down after the thesis's chapter 6: recursive cuts of the pieces "
     "that pass the segmentability test, limbs first (--k auto --auto-method salient-cuts)", 3),
    ("SALIENT_CUTS_THESIS", "Automatic, salient cuts (thesis)", "The thesis's chapter 6 as published "
     "(--k auto --auto-method salient-cuts-thesis)", 4),
]
METRICS = [
    ("part-aware", "Part-aware", "Geodesic, angular and volumetric distance blended (the default)"),
    ("geodesic", "Geodesic", "Distance along the surface"),
    ("angular", "Angular", "Steps at concave creases only"),
]


# The tool's label palette (SpectralSeg::Rendering::label_color()), sRGB
PALETTE = (0x4E79A7, 0xF28E2B, 0xE15759, 0x76B7B2, 0x59A14F, 0xEDC948, 0xB07AA1, 0xFF9DA7, 0x9C755F, 0x0BB4E0,
           0x9EA7F5, 0x8DB600, 0x7A1FA2, 0x882D17, 0xD9C8A0, 0xD6338A, 0x00695C, 0x6B6B1F, 0x1A2A6C, 0xC9F07A)


def segment_colors(count):
    """The tool's colour of each segment, as Blender's linear RGBA."""
    def linear(c):
        c /= 255.0
        return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
    colors = []
    for i in range(count):
        rgb = PALETTE[i % len(PALETTE)]
        colors.append((linear(rgb >> 16 & 255), linear(rgb >> 8 & 255), linear(rgb & 255), 1.0))
    return colors


def find_module(context):
    """The spectralseg module: importable as it is, or from the preferences' folder."""
    try:
        return importlib.import_module("spectralseg")
    except ImportError:
        pass
    prefs = context.preferences.addons[__name__].preferences if __name__ in context.preferences.addons else None
    folder = bpy.path.abspath(prefs.module_dir) if prefs and prefs.module_dir else ""
    if folder and folder not in sys.path:
        sys.path.append(folder)
        try:
            return importlib.import_module("spectralseg")
        except ImportError:
            pass
    return None


def mesh_arrays(obj):
    """World-space vertices and the triangles of the object's mesh, each with its polygon."""
    mesh = obj.data
    mesh.calc_loop_triangles()
    vertices = np.empty(len(mesh.vertices) * 3, dtype=np.float64)
    mesh.vertices.foreach_get("co", vertices)
    vertices = vertices.reshape(-1, 3)
    m = np.array(obj.matrix_world, dtype=np.float64)
    vertices = vertices @ m[:3, :3].T + m[:3, 3]
    triangles = np.empty(len(mesh.loop_triangles) * 3, dtype=np.int64)
    mesh.loop_triangles.foreach_get("vertices", triangles)
    polygons = np.empty(len(mesh.loop_triangles), dtype=np.int64)
    mesh.loop_triangles.foreach_get("polygon_index", polygons)
    return vertices, triangles.reshape(-1, 3), polygons


def polygon_labels(triangle_labels, polygons, count):
    """One label per polygon: the label most of its triangles have (-1, for
    a polygon the reader dropped, becomes the most common label)."""
    labels = np.full(count, -1, dtype=np.int64)
    for p in np.unique(polygons):
        mine = triangle_labels[polygons == p]
        mine = mine[mine >= 0]
        if len(mine):
            labels[p] = np.bincount(mine).argmax()
    if (labels < 0).any():
        known = labels[labels >= 0]
        labels[labels < 0] = np.bincount(known).argmax() if len(known) else 0
    return labels


class SPECTRALSEG_OT_segment(bpy.types.Operator):
    """Segment the active mesh object into parts (SpectralSeg)"""

    bl_idname = "mesh.spectralseg_segment"
    bl_label = "SpectralSeg: Segment Mesh"
    bl_options = {"REGISTER", "UNDO"}

    method: EnumProperty(name="Method", items=METHODS, default="CONTRAST_MERGE")
    k: IntProperty(name="Parts (k)", description="Number of parts of the k-way method", default=6, min=1,
                   soft_max=50)
    parts: IntProperty(name="Parts", description="Automatic methods: this many parts, the method's hierarchy cut "
                       "there (0: the method decides)", default=0, min=0, soft_max=50)
    metric: EnumProperty(name="Metric", items=METRICS, default="part-aware",
                         description="k-way and merge methods: the distance between faces")
    threads: IntProperty(name="Threads", description="0: all; the result does not depend on it", default=0, min=0)
    materials: BoolProperty(name="Materials", description="One material per segment", default=True)
    vertex_groups: BoolProperty(name="Vertex groups", description="One vertex group per segment", default=False)
    separate: BoolProperty(name="Separate objects", description="Also one new object per part", default=False)

    @classmethod
    def poll(cls, context):
        obj = context.active_object
        return obj is not None and obj.type == "MESH" and context.mode == "OBJECT"

    def execute(self, context):
        seg = find_module(context)
        if seg is None:
            self.report({"ERROR"}, "the spectralseg Python module is not found: pip install it from a SpectralSeg "
                        "checkout, or give the folder of a build in the add-on's preferences")
            return {"CANCELLED"}
        obj = context.active_object
        vertices, triangles, polygons = mesh_arrays(obj)
        if len(triangles) < 2:
            self.report({"ERROR"}, "the mesh has fewer than 2 faces")
            return {"CANCELLED"}
        options = {"threads": self.threads}
        try:
            if self.method == "K_WAY":
                if self.k > len(triangles):
                    raise ValueError("k = %d but the mesh has %d triangles" % (self.k, len(triangles)))
                labels = seg.k_way_segmentation(vertices, triangles, self.k, metric=self.metric, **options)
            else:
                method = self.method.lower()
                if not method.startswith("salient_cuts"):
                    options["metric"] = self.metric
                if self.parts > 0:
                    options["parts"] = self.parts
                labels = seg.automatic_segmentation(vertices, triangles, method=method, **options)
        except (ValueError, RuntimeError) as e:
            self.report({"ERROR"}, "SpectralSeg: %s" % e)
            return {"CANCELLED"}
        labels = polygon_labels(np.asarray(labels), polygons, len(obj.data.polygons))
        count = int(labels.max()) + 1
        store(obj, labels, count, self.materials, self.vertex_groups)
        if self.separate:
            separate_parts(context, obj, labels, count)
        self.report({"INFO"}, "SpectralSeg: %d segments" % count)
        return {"FINISHED"}


def store(obj, labels, count, materials, vertex_groups):
    """The labels as a face attribute, materials and vertex groups."""
    mesh = obj.data
    if ATTRIBUTE in mesh.attributes:
        mesh.attributes.remove(mesh.attributes[ATTRIBUTE])
    attribute = mesh.attributes.new(name=ATTRIBUTE, type="INT", domain="FACE")
    attribute.data.foreach_set("value", labels.astype(np.int32))
    if materials:
        mesh.materials.clear()
        for i, color in enumerate(segment_colors(count)):
            name = "SpectralSeg segment %d" % i
            mat = bpy.data.materials.get(name) or bpy.data.materials.new(name)
            mat.diffuse_color = color  # the viewport's solid mode
            mat.use_nodes = True
            bsdf = mat.node_tree.nodes.get("Principled BSDF")
            if bsdf is not None:
                bsdf.inputs["Base Color"].default_value = color
            mesh.materials.append(mat)
        mesh.polygons.foreach_set("material_index", labels.astype(np.int32))
    if vertex_groups:
        for group in [g for g in obj.vertex_groups if g.name.startswith("segment ")]:
            obj.vertex_groups.remove(group)
        for i in range(count):
            group = obj.vertex_groups.new(name="segment %d" % i)
            members = sorted({v for p in np.flatnonzero(labels == i) for v in mesh.polygons[int(p)].vertices})
            group.add(members, 1.0, "REPLACE")
    mesh.update()


def separate_parts(context, obj, labels, count):
    """One new object per part, named after the object, in its collections."""
    mesh = obj.data
    coordinates = [v.co.copy() for v in mesh.vertices]
    made = []
    for i in range(count):
        polygons = [mesh.polygons[int(p)] for p in np.flatnonzero(labels == i)]
        used = sorted({v for p in polygons for v in p.vertices})
        index = {v: j for j, v in enumerate(used)}
        part = bpy.data.meshes.new("%s part %d" % (obj.name, i))
        part.from_pydata([coordinates[v] for v in used], [], [[index[v] for v in p.vertices] for p in polygons])
        if i < len(mesh.materials) and mesh.materials[i] is not None:
            part.materials.append(mesh.materials[i])
        part.update()
        part_obj = bpy.data.objects.new(part.name, part)
        part_obj.matrix_world = obj.matrix_world
        for collection in obj.users_collection:
            collection.objects.link(part_obj)
        made.append(part_obj)
    obj.hide_set(True)
    return made


class SpectralSegSettings(bpy.types.PropertyGroup):
    method: EnumProperty(name="Method", items=METHODS, default="CONTRAST_MERGE")
    k: IntProperty(name="Parts (k)", default=6, min=1, soft_max=50)
    parts: IntProperty(name="Parts", description="0: the method decides", default=0, min=0, soft_max=50)
    metric: EnumProperty(name="Metric", items=METRICS, default="part-aware")
    materials: BoolProperty(name="Materials", default=True)
    vertex_groups: BoolProperty(name="Vertex groups", default=False)
    separate: BoolProperty(name="Separate objects", default=False)


class SPECTRALSEG_PT_panel(bpy.types.Panel):
    bl_label = "SpectralSeg"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "SpectralSeg"

    def draw(self, context):
        s = context.scene.spectralseg
        layout = self.layout
        layout.prop(s, "method")
        layout.prop(s, "k" if s.method == "K_WAY" else "parts")
        if not s.method.startswith("SALIENT_CUTS"):
            layout.prop(s, "metric")
        layout.prop(s, "materials")
        layout.prop(s, "vertex_groups")
        layout.prop(s, "separate")
        op = layout.operator(SPECTRALSEG_OT_segment.bl_idname, text="Segment")
        for name in ("method", "k", "parts", "metric", "materials", "vertex_groups", "separate"):
            setattr(op, name, getattr(s, name))


class SpectralSegPreferences(bpy.types.AddonPreferences):
    bl_idname = __name__
    module_dir: StringProperty(name="Module folder", subtype="DIR_PATH",
                               description="Folder holding the spectralseg module (for example build/python of a "
                               "SpectralSeg build), when Python does not find it by itself")

    def draw(self, context):
        self.layout.prop(self, "module_dir")


def menu_entry(self, context):
    self.layout.operator(SPECTRALSEG_OT_segment.bl_idname)


CLASSES = (SpectralSegPreferences, SpectralSegSettings, SPECTRALSEG_OT_segment, SPECTRALSEG_PT_panel)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.spectralseg = bpy.props.PointerProperty(type=SpectralSegSettings)
    bpy.types.VIEW3D_MT_object.append(menu_entry)


def unregister():
    bpy.types.VIEW3D_MT_object.remove(menu_entry)
    del bpy.types.Scene.spectralseg
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
