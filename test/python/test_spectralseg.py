# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Tests of the spectralseg Python module (plain unittest, system python3 + numpy).

Run by CTest (test `python_module`) as
    PYTHONPATH=build/python SPECTRALSEG_CLI=build/tools/spectralseg \
        SPECTRALSEG_DATA=data /usr/bin/python3 -m unittest -v test_spectralseg
from test/python. Without SPECTRALSEG_CLI the comparisons with the
command-line tool are skipped.
"""
import os
import signal
import subprocess
import tempfile
import threading
import time
import unittest

import numpy as np

import spectralseg

DATA = os.environ.get("SPECTRALSEG_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "data"))
CLI = os.environ.get("SPECTRALSEG_CLI", "")
ELEPHANT = os.path.join(DATA, "elephant.off")
HUMAN = os.path.join(DATA, "human_man.off")


def cli_values(args, kind, dtype):
    """Runs `spectralseg KIND MESH ARGS --labels/--field FILE`, returns the file's values."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "out.txt")
        flag = "--labels" if kind == "segment" else "--field"
        subprocess.run([CLI, kind] + args + [flag, out], check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        return np.loadtxt(out, dtype=dtype)


class Mesh:
    """The elephant (5,558 faces), read once."""
    vertices = None
    faces = None

    @classmethod
    def get(cls):
        if cls.vertices is None:
            cls.vertices, cls.faces = spectralseg.read_mesh(ELEPHANT)
        return cls.vertices, cls.faces


class ReadMesh(unittest.TestCase):
    def test_read_mesh(self):
        v, f = spectralseg.read_mesh(ELEPHANT)
        self.assertEqual(v.dtype, np.float64)
        self.assertEqual(f.dtype, np.int64)
        self.assertEqual(v.shape, (2775, 3))
        self.assertEqual(f.shape, (5558, 3))
        self.assertTrue(np.isfinite(v).all())
        self.assertEqual(f.min(), 0)
        self.assertEqual(f.max(), len(v) - 1)

    def test_missing_file_is_an_os_error(self):
        with self.assertRaises(OSError) as e:
            spectralseg.read_mesh(os.path.join(DATA, "no_such_mesh.off"))
        self.assertIsInstance(e.exception, spectralseg.IoError)
        self.assertIsInstance(e.exception, spectralseg.Error)

    def test_polygons_are_refused(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "quad.off")
            with open(path, "w") as out:
                out.write("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
            with self.assertRaisesRegex(ValueError, "face 0 has 4 vertices"):
                spectralseg.read_mesh(path)


class KWay(unittest.TestCase):
    def test_k_labels(self):
        v, f = Mesh.get()
        labels = spectralseg.k_way_segmentation(v, f, 6)
        self.assertEqual(labels.shape, (len(f),))
        self.assertEqual(labels.dtype, np.int64)
        self.assertEqual(sorted(set(labels.tolist())), list(range(6)))

    def test_report(self):
        v, f = Mesh.get()
        labels, report = spectralseg.k_way_segmentation(v, f, 4, report=True, threads=2)
        self.assertEqual(report["segments"], 4)
        self.assertEqual(report["k"], 4)
        self.assertEqual(report["faces"], len(f))
        self.assertEqual(report["threads"], 2)
        self.assertEqual(report["metric"], "part-aware")
        self.assertEqual(report["embedding"], "nystrom")
        self.assertIn(report["merge"], ("concave", "contrast"))
        # the kept over-segmentation: 20 clusters merged by contrast, or 4 + 2 or 4 + 8 by concave strength
        self.assertIn(report["extra_clusters"], (16,) if report["merge"] == "contrast" else (2, 8))
        self.assertGreaterEqual(report["concave_normalized_cut"], 0)
        # every over-segmentation tried, the kept one flagged, with the lowest cut
        kept = [c for c in report["candidates"] if c["kept"]]
        self.assertEqual(len(kept), 1)
        self.assertEqual(kept[0]["extra_clusters"], report["extra_clusters"])
        self.assertEqual(kept[0]["concave_normalized_cut"], report["concave_normalized_cut"])
        self.assertEqual(min(c["concave_normalized_cut"] for c in report["candidates"]), report["concave_normalized_cut"])
        self.assertIn("metric", report["timings"])
        self.assertIn("graph cut", report["timings"])
        self.assertGreater(report["timings"]["total"], 0)
        self.assertEqual(sum(s["faces"] for s in report["segment_list"]), len(f))
        self.assertEqual(report["warnings"], [])

    def test_threads_do_not_change_labels(self):
        v, f = Mesh.get()
        one = spectralseg.k_way_segmentation(v, f, 5, threads=1)
        two = spectralseg.k_way_segmentation(v, f, 5, threads=2)
        np.testing.assert_array_equal(one, two)

    def test_options_are_used(self):
        v, f = Mesh.get()
        default = spectralseg.k_way_segmentation(v, f, 5)
        thesis = spectralseg.k_way_segmentation(v, f, 5, extra_clusters=0, alternative_extra_clusters=[],
                                                contrast_merge_clusters=0, normalization="max")
        geodesic = spectralseg.k_way_segmentation(v, f, 5, metric="geodesic", boundary_enhancement=False)
        self.assertFalse(np.array_equal(default, thesis))
        self.assertFalse(np.array_equal(default, geodesic))
        for labels in (thesis, geodesic):
            self.assertEqual(len(set(labels.tolist())), 5)
        # below the limit every face casts its cone; with a lower one the distances change
        d = spectralseg.face_distances(v, f, 0)
        np.testing.assert_array_equal(d, spectralseg.face_distances(v, f, 0, max_measured_faces=0))
        self.assertFalse(np.array_equal(d, spectralseg.face_distances(v, f, 0, max_measured_faces=len(f) // 4)))

    def test_automatic_k(self):
        v, f = Mesh.get()
        labels, report = spectralseg.k_way_segmentation_automatic(v, f, max_k=12, report=True)
        n = len(set(labels.tolist()))
        self.assertTrue(2 <= n <= 12, n)
        self.assertEqual(report["segments"], n)
        self.assertEqual(report["method"], "concave-merge")


class Automatic(unittest.TestCase):
    def test_methods(self):
        v, f = Mesh.get()
        concave = spectralseg.automatic_segmentation(v, f, method="concave_merge")
        np.testing.assert_array_equal(concave, spectralseg.k_way_segmentation_automatic(v, f))
        for method in ("contrast_merge", "concave-merge", "salient_cuts"):
            labels, report = spectralseg.automatic_segmentation(v, f, method=method, report=True)
            n = len(set(labels.tolist()))
            self.assertGreaterEqual(n, 2, method)
            self.assertEqual(report["segments"], n)
            self.assertEqual(report["method"], method.replace("_", "-"))

    def test_salient_cuts_hierarchy_and_options(self):
        v, f = Mesh.get()
        labels, report = spectralseg.automatic_segmentation(v, f, method="salient_cuts", report=True)
        self.assertEqual(report["parts_found"], len(set(labels.tolist())))
        self.assertEqual(report["hierarchy"]["kind"], "cuts")
        root = report["hierarchy"]["roots"][0]
        self.assertEqual(root["faces"], len(f))
        self.assertIn("children", root)
        three = spectralseg.automatic_segmentation(v, f, method="salient_cuts", parts=3)
        self.assertEqual(len(set(three.tolist())), 3)
        one = spectralseg.automatic_segmentation(v, f, method="salient_cuts", depth=0)
        self.assertEqual(set(one.tolist()), {0})
        strict = spectralseg.automatic_segmentation(v, f, method="salient_cuts", eta=0.9)
        self.assertLessEqual(len(set(strict.tolist())), len(set(labels.tolist())))

    def test_merge_hierarchy_and_parts(self):
        v, f = Mesh.get()
        for method in ("contrast_merge", "concave_merge"):
            labels, report = spectralseg.automatic_segmentation(v, f, method=method, report=True)
            h = report["hierarchy"]
            self.assertEqual(h["kind"], "merges")
            self.assertEqual(len(h["roots"]), 1)
            self.assertEqual(h["roots"][0]["faces"], len(f))
            self.assertGreaterEqual(h["leaves"], len(set(labels.tolist())))
            for parts in (1, 3):
                cut = spectralseg.automatic_segmentation(v, f, method=method, parts=parts)
                self.assertEqual(len(set(cut.tolist())), parts, method)
            with self.assertRaises(ValueError):
                spectralseg.automatic_segmentation(v, f, method=method, depth=1)


class Distances(unittest.TestCase):
    def test_distances(self):
        v, f = Mesh.get()
        d = spectralseg.face_distances(v, f, 10)
        self.assertEqual(d.shape, (len(f),))
        self.assertEqual(d[10], 0.0)
        self.assertTrue((d[np.arange(len(f)) != 10] > 0).all())
        g = spectralseg.face_distances(v, f, 10, metric="geodesic")
        self.assertFalse(np.allclose(d, g))

    def test_nearest_source(self):
        v, f = Mesh.get()
        d, nearest = spectralseg.face_distances(v, f, [10, 3000], return_nearest=True)
        self.assertEqual(nearest[10], 0)
        self.assertEqual(nearest[3000], 1)
        self.assertEqual(set(nearest.tolist()), {0, 1})
        one = spectralseg.face_distances(v, f, 10)
        np.testing.assert_array_equal(d[nearest == 0], one[nearest == 0])


class Retrieval(unittest.TestCase):
    """Shape descriptors (thesis 3.6): invariance, chi-square, ranking, options."""

    def test_descriptor_invariance_and_ranking(self):
        v, f = Mesh.get()
        angle = 0.7
        r = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]])
        moved = 3.5 * v @ r.T + np.array([1.0, -2.0, 0.5])
        other_v, other_f = spectralseg.read_mesh(HUMAN)
        for metric in ("part-aware", "geodesic", "euclidean"):
            a = spectralseg.shape_descriptor(v, f, metric=metric, threads=1)
            self.assertEqual(a["metric"], metric)
            self.assertAlmostEqual(float(a["histogram"].sum()), 1.0, places=12)
            b = spectralseg.shape_descriptor(moved, f, metric=metric, threads=2)
            tolerance = 0.02 if metric == "part-aware" else 1e-9
            self.assertLess(spectralseg.chi_square_distance(a, b), tolerance, metric)
            self.assertEqual(spectralseg.chi_square_distance(a, a), 0.0)
            c = spectralseg.shape_descriptor(other_v, other_f, metric=metric)
            self.assertEqual(spectralseg.chi_square_distance(a, c), spectralseg.chi_square_distance(c, a))
            ranking = spectralseg.rank_shapes(a, [c, b])
            self.assertEqual(ranking[0][0], 1, metric)
            self.assertLessEqual(ranking[0][1], ranking[1][1])

    def test_descriptor_options_are_checked(self):
        v, f = Mesh.get()
        with self.assertRaises(spectralseg.Error):
            spectralseg.shape_descriptor(v, f, metric="angular")
        with self.assertRaises(spectralseg.Error):
            spectralseg.shape_descriptor(v, f, metric="euclidean", weights=[0.5, 0, 0.5])
        with self.assertRaises(spectralseg.Error):
            spectralseg.shape_descriptor(v, f, bins=1)
        with self.assertRaises(spectralseg.Error):
            spectralseg.shape_descriptor(v, f, metric="geodesic", max_measured_faces=10)
        a = spectralseg.shape_descriptor(v, f, metric="geodesic", bins=32)
        b = spectralseg.shape_descriptor(v, f, metric="euclidean", bins=32)
        with self.assertRaises(spectralseg.Error):
            spectralseg.chi_square_distance(a, b)


@unittest.skipUnless(CLI and os.path.exists(CLI), "SPECTRALSEG_CLI not set: no command-line tool to compare with")
class SameAsCommandLine(unittest.TestCase):
    """Labels equal, line for line, the labels file of `spectralseg segment` with the same options."""

    def check(self, python_labels, cli_args):
        expected = cli_values([ELEPHANT] + cli_args, "segment", np.int64)
        np.testing.assert_array_equal(python_labels, expected)

    def test_k_way(self):
        v, f = Mesh.get()
        self.check(spectralseg.k_way_segmentation(v, f, 6), ["--k", "6"])

    def test_k_way_options(self):
        v, f = Mesh.get()
        labels = spectralseg.k_way_segmentation(v, f, 4, ray_caster="aabb", kernel="gaussian", sampling="gamma",
                                                samples=12, seed=3, extra_clusters=0, alternative_extra_clusters=[])
        self.check(labels, ["--k", "4", "--ray-caster", "aabb", "--kernel", "gaussian", "--sampling", "gamma",
                            "--samples", "12", "--seed", "3", "--extra-clusters", "0",
                            "--alternative-extra-clusters", "none"])
        labels = spectralseg.k_way_segmentation(v, f, 4, extra_clusters=1, alternative_extra_clusters=[5, 3])
        self.check(labels, ["--k", "4", "--extra-clusters", "1", "--alternative-extra-clusters", "5,3"])
        labels = spectralseg.k_way_segmentation(v, f, 4, contrast_merge_clusters=0)
        self.check(labels, ["--k", "4", "--contrast-merge-clusters", "0"])
        labels = spectralseg.k_way_segmentation(v, f, 3, min_candidate_clusters=0)
        self.check(labels, ["--k", "3", "--min-candidate-clusters", "0"])
        labels = spectralseg.k_way_segmentation(v, f, 4, flat_seam_angle=0)
        self.check(labels, ["--k", "4", "--flat-seam-angle", "0"])
        labels = spectralseg.k_way_segmentation(v, f, 4, flat_seam_angle=20)
        self.check(labels, ["--k", "4", "--flat-seam-angle", "20"])

    def test_automatic(self):
        v, f = Mesh.get()
        self.check(spectralseg.automatic_segmentation(v, f), ["--k", "auto"])
        self.check(spectralseg.automatic_segmentation(v, f, method="salient_cuts"),
                   ["--k", "auto", "--auto-method", "salient-cuts"])

    def test_distances(self):
        v, f = Mesh.get()
        expected = cli_values([ELEPHANT, "--from", "10"], "distance", np.float64)
        np.testing.assert_array_equal(spectralseg.face_distances(v, f, 10), expected)


class MessySoup(unittest.TestCase):
    def test_unwelded_soup_equals_welded_mesh(self):
        v, f = Mesh.get()
        # every triangle with its own three vertices, as STL files and game exports store them
        soup_v = v[f.reshape(-1)]
        soup_f = np.arange(3 * len(f)).reshape(-1, 3)
        labels, report = spectralseg.k_way_segmentation(soup_v, soup_f, 5, report=True)
        np.testing.assert_array_equal(labels, spectralseg.k_way_segmentation(v, f, 5))
        self.assertEqual(report["repairs"]["merged_vertices"], len(soup_v) - len(v))
        self.assertTrue(any("merged" in w for w in report["warnings"]))

    def test_dropped_and_duplicate_faces(self):
        v, f = Mesh.get()
        messy = np.vstack([f, [[0, 0, 1]], f[:2]])  # a degenerate face and two repeats
        labels = spectralseg.k_way_segmentation(v, messy, 5)
        clean = spectralseg.k_way_segmentation(v, f, 5)
        np.testing.assert_array_equal(labels[:len(f)], clean)
        self.assertEqual(labels[len(f)], -1)
        np.testing.assert_array_equal(labels[len(f) + 1:], clean[:2])
        d = spectralseg.face_distances(v, messy, 0)
        self.assertTrue(np.isnan(d[len(f)]))

    def test_other_dtypes(self):
        v, f = Mesh.get()
        expected = spectralseg.k_way_segmentation(v, f, 3)
        np.testing.assert_array_equal(
            spectralseg.k_way_segmentation(v.astype(np.float32).astype(np.float64), f.astype(np.uint32), 3), expected)
        np.testing.assert_array_equal(spectralseg.k_way_segmentation(v.tolist(), f.tolist(), 3), expected)
        np.testing.assert_array_equal(spectralseg.k_way_segmentation(np.asfortranarray(v), f[:, :], 3), expected)


def cube(origin, size=1.0):
    """An axis-aligned cube with its own 8 vertices and 12 outward triangles."""
    corners = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=np.float64)
    faces = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4],
                      [2, 6, 3], [3, 6, 7], [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]])
    return corners * size + np.asarray(origin, dtype=np.float64), faces


def pieces(*cubes):
    """One soup of separate cubes: faces 12 i to 12 i + 11 are cube i's."""
    vertices, faces = zip(*cubes)
    offsets = np.cumsum([0] + [len(v) for v in vertices[:-1]])
    return np.vstack(vertices), np.vstack([f + o for f, o in zip(faces, offsets)])


class TouchingPieces(unittest.TestCase):
    """The dual graph's contact edges (connect_touching_parts, contact_distance, speck_area_fraction)."""
    # two unit cubes side by side, 0.001 apart (0.0004 of the bounding-box
    # diagonal, within the default contact distance 0.005): no shared vertex
    v, f = pieces(cube((0, 0, 0)), cube((1.001, 0, 0)))
    # the same and a cube of side 0.05 far above them: 0.1 % of the area
    sv, sf = pieces(cube((0, 0, 0)), cube((1.001, 0, 0)), cube((0.5, 0.5, 3), 0.05))
    apart = {"connect_touching_parts": False}
    too_close_to_join = {"contact_distance": 1e-4}
    by_cube = [0] * 12 + [1] * 12

    def test_k_way(self):
        seg = spectralseg.k_way_segmentation
        self.assertEqual(seg(self.v, self.f, 1).tolist(), [0] * 24)
        self.assertEqual(seg(self.v, self.f, 2).tolist(), self.by_cube)  # joined, then cut where they touch
        self.assertEqual(seg(self.v, self.f, 1, **self.apart).tolist(), self.by_cube)
        labels, report = seg(self.v, self.f, 1, report=True, **self.too_close_to_join)
        self.assertEqual(labels.tolist(), self.by_cube)
        self.assertEqual(report["segments"], 2)
        self.assertEqual(seg(self.v, self.f, 1, contact_distance=1e-3).tolist(), [0] * 24)

    def test_specks(self):
        seg = spectralseg.k_way_segmentation
        self.assertEqual(seg(self.sv, self.sf, 1).tolist(), [0] * 36)  # the speck joins the nearest cube
        self.assertEqual(seg(self.sv, self.sf, 1, speck_area_fraction=0).tolist(), [0] * 24 + [1] * 12)
        self.assertEqual(seg(self.sv, self.sf, 1, speck_area_fraction=0.0005).tolist(), [0] * 24 + [1] * 12)
        self.assertEqual(seg(self.sv, self.sf, 1, **self.apart).tolist(), self.by_cube + [2] * 12)

    def test_automatic(self):
        auto = spectralseg.automatic_segmentation
        # salient cuts at depth 0: one part per piece of the graph
        self.assertEqual(auto(self.v, self.f, method="salient_cuts", depth=0).tolist(), [0] * 24)
        for options in (self.apart, self.too_close_to_join):
            self.assertEqual(auto(self.v, self.f, method="salient_cuts", depth=0, **options).tolist(), self.by_cube)
        self.assertEqual(auto(self.sv, self.sf, method="salient_cuts", depth=0, speck_area_fraction=0).tolist(),
                         [0] * 24 + [1] * 12)
        joined = spectralseg.k_way_segmentation_automatic(self.v, self.f)
        apart = spectralseg.k_way_segmentation_automatic(self.v, self.f, **self.apart)
        # joined by contact edges, the cubes are still told apart: the seams
        # across their flat faces are merged first, the cubes' contact stays
        self.assertEqual(joined.tolist(), self.by_cube)
        self.assertEqual(apart.tolist(), self.by_cube)
        np.testing.assert_array_equal(
            spectralseg.k_way_segmentation_automatic(self.v, self.f, **self.too_close_to_join), apart)
        np.testing.assert_array_equal(auto(self.v, self.f, method="concave_merge", **self.apart), apart)

    def test_distances(self):
        dist = spectralseg.face_distances
        self.assertTrue(np.isfinite(dist(self.v, self.f, 0)).all())
        for options in (self.apart, self.too_close_to_join):
            d, nearest = dist(self.v, self.f, 0, return_nearest=True, **options)
            self.assertTrue(np.isfinite(d[:12]).all())
            self.assertTrue(np.isinf(d[12:]).all())
            self.assertEqual(nearest.tolist(), [0] * 12 + [-1] * 12)
        self.assertTrue(np.isfinite(dist(self.sv, self.sf, 0)).all())
        self.assertTrue(np.isinf(dist(self.sv, self.sf, 0, speck_area_fraction=0)[24:]).all())


class Errors(unittest.TestCase):
    def assertInvalid(self, regex, function, *args, **kwargs):
        with self.assertRaisesRegex(ValueError, regex) as e:
            function(*args, **kwargs)
        self.assertIsInstance(e.exception, spectralseg.InvalidInputError)
        self.assertIsInstance(e.exception, spectralseg.Error)
        self.assertIsInstance(e.exception, RuntimeError)

    def test_bad_arrays(self):
        v, f = Mesh.get()
        seg = spectralseg.k_way_segmentation
        self.assertInvalid(r"vertices must be an \(n, 3\) array", seg, v[:, :2], f, 3)
        self.assertInvalid(r"vertices must be an \(n, 3\) array", seg, v.reshape(-1), f, 3)
        self.assertInvalid(r"vertices must be an \(n, 3\) array", seg, np.array(["a", "b", "c"]).reshape(1, 3), f, 3)
        self.assertInvalid(r"faces must be an \(m, 3\) array", seg, v, f[:, :2], 3)
        self.assertInvalid(r"faces must be an \(m, 3\) array", seg, v, f.astype(np.float64), 3)
        self.assertInvalid("faces is empty", seg, v, np.zeros((0, 3), dtype=np.int64), 3)
        bad = v.copy()
        bad[7, 1] = np.nan
        self.assertInvalid("vertex 7 has a non-finite coordinate", seg, bad, f, 3)
        bad[7, 1] = np.inf
        self.assertInvalid("vertex 7 has a non-finite coordinate", seg, bad, f, 3)
        out = f.copy()
        out[12, 2] = len(v)
        self.assertInvalid("face 12 has vertex index 2775", seg, v, out, 3)
        out[12, 2] = -1
        self.assertInvalid("face 12 has vertex index -1", seg, v, out, 3)
        self.assertInvalid("no usable face", seg, v, np.array([[0, 0, 1], [2, 2, 2]]), 1)

    def test_bad_options(self):
        v, f = Mesh.get()
        seg = spectralseg.k_way_segmentation
        self.assertInvalid(r"k must be an integer in \[1", seg, v, f, 0)
        self.assertInvalid("larger than the number of faces", seg, v, f[:10], 11)
        self.assertInvalid("metric must be one of", seg, v, f, 3, metric="euclidean")
        self.assertInvalid("sampling must be one of", seg, v, f, 3, sampling="random")
        self.assertInvalid("threads must be", seg, v, f, 3, threads=-1)
        self.assertInvalid("max_measured_faces must be", seg, v, f, 3, max_measured_faces=-1)
        self.assertInvalid(r"flat_seam_angle must be a number of degrees in \[0, 180\)", seg, v, f, 3,
                           flat_seam_angle=float("nan"))
        self.assertInvalid("weights must hold 2 or 3", seg, v, f, 3, weights=[1.0])
        self.assertInvalid("weights must not all be 0", seg, v, f, 3, weights=[0, 0, 0])
        self.assertInvalid("method must be one of", spectralseg.automatic_segmentation, v, f, method="magic")
        self.assertInvalid("eta must be", spectralseg.automatic_segmentation, v, f, method="salient_cuts",
                           eta=float("nan"))
        # keywords of one automatic method are refused by the others, not ignored
        auto = spectralseg.automatic_segmentation
        for option in ({"metric": "geodesic"}, {"weights": [1, 0, 0]}, {"vsi_fraction": 0.02},
                       {"max_measured_faces": 10}, {"kernel": "gaussian"}, {"samples": 5}, {"seed": 3},
                       {"boundary_enhancement": False}, {"max_k": 10}, {"min_boundary_contrast": 2.0}):
            for method in ("salient_cuts", "salient_cuts_thesis"):
                self.assertInvalid("do not apply to method='" + method + "'", auto, v, f, method=method, **option)
        for option in ({"eta": 0.2}, {"structure_only": True}, {"min_part_area": 0.1}, {"max_parts": 4},
                       {"depth": 1}):
            for method in ("contrast_merge", "concave_merge"):
                self.assertInvalid("apply to method='salient_cuts', not '" + method + "'", auto, v, f,
                                   method=method, **option)
        self.assertInvalid("source face 99999 does not exist", spectralseg.face_distances, v, f, 99999)
        self.assertInvalid("sources must be", spectralseg.face_distances, v, f, [])
        self.assertInvalid(r"contact_distance must be a number in \[0", seg, v, f, 3, contact_distance=-1)
        self.assertInvalid("contact_distance must be", spectralseg.automatic_segmentation, v, f,
                           contact_distance=float("nan"))
        self.assertInvalid("contact_distance must be", spectralseg.face_distances, v, f, 0, contact_distance=1.5)
        self.assertInvalid("speck_area_fraction must be", spectralseg.face_distances, v, f, 0,
                           speck_area_fraction=2)
        self.assertInvalid("speck_area_fraction must be", spectralseg.k_way_segmentation_automatic, v, f,
                           speck_area_fraction=-0.1)
        if not spectralseg.has_embree:
            self.assertInvalid("not available", seg, v, f, 3, ray_caster="embree")
        with self.assertRaises(TypeError):
            seg(v, f, 2.5)
        with self.assertRaises(TypeError):
            seg(v, f, 3, 1)  # options are keyword-only


class Progress(unittest.TestCase):
    def test_progress_is_reported(self):
        v, f = Mesh.get()
        seen = []
        spectralseg.k_way_segmentation(v, f, 3, progress=lambda stage, fraction: seen.append((stage, fraction)))
        self.assertTrue(seen)
        self.assertTrue(all(0.0 <= fraction <= 1.0 for _, fraction in seen))

    def test_cancel(self):
        v, f = Mesh.get()
        with self.assertRaises(spectralseg.CancelledError):
            spectralseg.k_way_segmentation(v, f, 3, progress=lambda stage, fraction: False)

    def test_exception_in_callback_propagates(self):
        v, f = Mesh.get()

        def fail(stage, fraction):
            raise ZeroDivisionError("from the callback")

        with self.assertRaisesRegex(ZeroDivisionError, "from the callback"):
            spectralseg.automatic_segmentation(v, f, progress=fail)
        # the module still works afterwards
        self.assertEqual(len(set(spectralseg.k_way_segmentation(v, f, 2).tolist())), 2)


class Gil(unittest.TestCase):
    def test_gil_is_released(self):
        """A Python thread keeps ticking while a segmentation runs."""
        v, f = spectralseg.read_mesh(HUMAN)
        ticks = []
        stop = threading.Event()

        def tick():
            while not stop.is_set():
                ticks.append(time.perf_counter())
                time.sleep(0.001)

        thread = threading.Thread(target=tick)
        thread.start()
        try:
            time.sleep(0.05)
            start = time.perf_counter()
            spectralseg.k_way_segmentation(v, f, 6, threads=1)
            end = time.perf_counter()
        finally:
            stop.set()
            thread.join()
        inside = [t for t in ticks if start <= t <= end]
        # with the GIL held the thread could not tick at all during the call
        self.assertGreaterEqual(len(inside), 5, "%d ticks in %.3f s" % (len(inside), end - start))
        stamps = [start] + inside + [end]
        longest_gap = max(b - a for a, b in zip(stamps, stamps[1:]))
        self.assertLess(longest_gap, 0.5 * (end - start) + 0.05)

    @unittest.skipUnless(hasattr(signal, "SIGINT"), "no SIGINT")
    def test_ctrl_c_interrupts(self):
        v, f = spectralseg.read_mesh(HUMAN)
        finished = []
        timer = threading.Timer(0.02, lambda: os.kill(os.getpid(), signal.SIGINT))
        timer.start()
        try:
            with self.assertRaises(KeyboardInterrupt):
                spectralseg.k_way_segmentation(v, f, 6, threads=1)
                finished.append(True)
                time.sleep(5)  # not reached unless the signal came late
        finally:
            timer.cancel()
        self.assertEqual(finished, [], "the segmentation ran to its end before Ctrl-C was seen")


if __name__ == "__main__":
    unittest.main()
