#!/usr/bin/env python3
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Speed table and plot from the rows of bench_segmentation_speed --tsv.

usage: speed_report.py RUNS.tsv OUT_DIR [--mesh NAME] [--cgal-max-faces N]
                       [--fit-min-faces 5000] [--build-dir DIR] [--commit C]

Writes OUT_DIR/speed_table.md (markdown: every run, the ratio of each
SpectralSeg total to CGAL's at the same size, the fitted growth exponent of
the total time of each configuration, the machine and the date) and, if
gnuplot is installed, OUT_DIR/images/speed_plot.png (log-log, total seconds
against faces, one line per configuration). Lines of RUNS.tsv that start
with "method" (a header) are skipped; lines that start with "#failed" record
a run that failed (method, size, threads, exit status) and are listed under
the table. Needs nothing but Python 3 (and gnuplot for the plot).
"""

import argparse
import datetime
import math
import os
import shutil
import subprocess
import sys

COLUMNS = ["method", "mesh", "faces", "threads", "k", "segments", "metric", "sampling", "distances",
           "eigen-solve", "clustering", "cut", "total", "peak MB"]
STAGES = ["metric", "sampling", "distances", "eigen-solve", "clustering", "cut"]
METHOD_ORDER = {"spectralseg": 0, "spectralseg-embree": 1, "cgal-sdf": 2}
METHOD_LABEL = {"spectralseg": "SpectralSeg, AABB", "spectralseg-embree": "SpectralSeg, Embree",
                "cgal-sdf": "CGAL SDF"}


def read_runs(path):
    runs, failures = [], []
    with open(path) as f:
        for line in f:
            line = line.rstrip("\n")
            if not line or line.startswith("method\t"):
                continue
            fields = line.split("\t")
            if fields[0] == "#failed":
                failures.append(fields[1:])
                continue
            if line.startswith("#") or len(fields) != len(COLUMNS):
                continue
            row = dict(zip(COLUMNS, fields))
            for key in ["faces", "threads", "k", "segments"]:
                row[key] = int(row[key])
            for key in STAGES + ["total", "peak MB"]:
                row[key] = float(row[key]) if row[key] != "" else None
            runs.append(row)
    return runs, failures


def configuration(row):
    return (METHOD_ORDER.get(row["method"], 9), row["method"], row["threads"])


def label(config):
    _, method, threads = config
    return "%s, %d thread%s" % (METHOD_LABEL.get(method, method), threads, "" if threads == 1 else "s")


def seconds(value):
    if value is None:
        return ""
    if value < 10:
        return "%.3f" % value
    if value < 100:
        return "%.2f" % value
    return "%.1f" % value


def slope(points):
    """Least-squares slope of log t on log n."""
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    return sxy / sxx if sxx > 0 else float("nan")


def machine():
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    try:
        threads = len(os.sched_getaffinity(0))
    except AttributeError:
        threads = os.cpu_count() or 1
    memory = ""
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemTotal:"):
                    memory = ", %.0f GB of memory" % (int(line.split()[1]) / 1024.0 / 1024.0)
                    break
    except OSError:
        pass
    return "%s, %d hardware threads (`nproc`)%s" % (model, threads, memory)


def build_type(build_dir):
    try:
        with open(os.path.join(build_dir, "CMakeCache.txt")) as f:
            for line in f:
                if line.startswith("CMAKE_BUILD_TYPE:"):
                    return line.split("=", 1)[1].strip() or "no build type"
    except (OSError, TypeError):
        pass
    return None


def plot(runs, configs, exponents, out_dir, title):
    """Writes OUT_DIR/images/speed_plot.png with gnuplot; returns its path or None."""
    gnuplot = shutil.which("gnuplot")
    if gnuplot is None:
        return None
    images = os.path.join(out_dir, "images")
    os.makedirs(images, exist_ok=True)
    png = os.path.join(images, "speed_plot.png")
    script = ['set terminal pngcairo size 900,600 font "sans,11"',
              'set output "%s"' % png.replace('"', '\\"'),
              'set title "%s"' % title,
              "set logscale xy",
              'set xlabel "faces"',
              'set ylabel "total time (s)"',
              'set format x "%.0s%c"',
              "set grid xtics ytics mxtics mytics lw 0.5 lc rgb '#dddddd'",
              "set key top left box opaque"]
    plots = []
    for i, config in enumerate(configs):
        points = sorted((r["faces"], r["total"]) for r in runs if configuration(r) == config and r["total"])
        if not points:
            continue
        script.append("$d%d << EOD" % i)
        script += ["%d %.6g" % p for p in points]
        script.append("EOD")
        name = label(config) + (" (exponent %.2f)" % exponents[config] if config in exponents else "")
        dashes = 2 if config[2] == 1 and config[1] != "cgal-sdf" else 1
        plots.append('$d%d using 1:2 with linespoints lw 2 dt %d pt %d ps 1.2 title "%s"' % (
            i, dashes, 5 + 2 * (i % 4), name))
    if not plots:
        return None
    script.append("plot " + ", \\\n     ".join(plots))
    result = subprocess.run([gnuplot], input="\n".join(script) + "\n", text=True, capture_output=True)
    if result.returncode != 0:
        sys.stderr.write(result.stderr)
        return None
    return png


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("runs")
    p.add_argument("out_dir")
    p.add_argument("--mesh", default="data/elephant.off")
    p.add_argument("--cgal-max-faces", type=int, default=None)
    p.add_argument("--fit-min-faces", type=int, default=5000)
    p.add_argument("--build-dir", default=None)
    p.add_argument("--commit", default=None)
    a = p.parse_args()

    runs, failures = read_runs(a.runs)
    if not runs:
        sys.exit("speed_report: no successful run in %s" % a.runs)
    runs.sort(key=lambda r: (r["faces"], configuration(r)))
    configs = sorted({configuration(r) for r in runs})
    cgal = {r["faces"]: r["total"] for r in runs if r["method"] == "cgal-sdf" and r["total"]}
    ks = sorted({r["k"] for r in runs})

    md = ["# Speed: SpectralSeg against CGAL's SDF segmentation", "",
          "<!-- written by benchmark/run_speed_benchmark.sh; do not edit by hand -->", ""]
    built = build_type(a.build_dir)
    md.append("Measured on %s, %s%s%s." % (
        datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), machine(),
        ("; %s build" % built) if built else "",
        ("; commit %s" % a.commit) if a.commit else ""))
    sizes = sorted({r["faces"] for r in runs})
    made = []
    if any(" decimated" in r["mesh"] for r in runs):
        made.append("decimated by edge collapse (CGAL's Surface_mesh_simplification)")
    if any(" " not in r["mesh"] for r in runs):
        made.append("as shipped")
    if any(" x" in r["mesh"] for r in runs):
        made.append("with 1-to-4 midpoint subdivisions (x4, x16, ...)")
    md.append("")
    md.append("Mesh `%s` at %d size%s (%s faces): %s; k = %s; every configuration in its "
              "own process. SpectralSeg runs the default k-way segmentation (part-aware metric, Nyström embedding "
              "above 2,000 faces and exact embedding below, K-means, graph cut, merge); CGAL runs `CGAL::sdf_values` "
              "and `CGAL::segmentation_from_sdf_values` with their defaults, single-threaded%s." % (
                  a.mesh, len(sizes), "" if len(sizes) == 1 else "s", ", ".join("{:,}".format(n) for n in sizes),
                  ", ".join(made), ", ".join(str(k) for k in ks),
                  (", on the sizes up to %s faces" % "{:,}".format(a.cgal_max_faces)) if a.cgal_max_faces else ""))
    md.append("")
    md.append("| mesh | faces | method | threads | segments | metric s | sampling s | distances s | eigen-solve s "
              "| clustering s | cut s | total s | peak MB | total / CGAL |")
    md.append("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in runs:
        if r["method"] == "cgal-sdf":
            ratio = ""
        elif r["faces"] in cgal and r["total"] is not None:
            ratio = "%.3f" % (r["total"] / cgal[r["faces"]])
        else:
            ratio = "(not run)"
        md.append("| %s | %s | %s | %d | %d | %s | %s | %s | %s | %s | %s | %s | %.0f | %s |" % (
            r["mesh"], "{:,}".format(r["faces"]), r["method"], r["threads"], r["segments"],
            *[seconds(r[s]) for s in STAGES], seconds(r["total"]), r["peak MB"], ratio))
    md += ["",
           "Columns (seconds of wall-clock time; the stage columns add up to the total): "
           "*metric* is the dual graph and the part-aware edge weights (geodesic, angular and VSI: ray casting, "
           "reference points, shape images), or CGAL's `sdf_values`; *sampling* the farthest-point sampling "
           "of the Nyström samples (empty for the exact embedding); *distances* the distance rows of the samples "
           "(of all faces for the exact embedding) and their conversion into affinities; *eigen-solve* the "
           "eigen-solve and the Nyström extension; *clustering* K-means, connected segments and merge, or "
           "CGAL's `segmentation_from_sdf_values` (its soft clustering and graph cut in one call); *cut* the "
           "graph-cut boundary enhancement. The stage boundaries come from the library's progress reports. "
           "*peak MB* is the peak resident memory during the segmentation, the mesh included (its decimation "
           "or subdivision excluded). *total / CGAL* is the total time divided by CGAL's total time at the "
           "same size. CGAL's *segments* are the connected segments it returns for k = %s clusters of SDF "
           "values." % ", ".join(str(k) for k in ks) +
           (" Below 2,000 faces SpectralSeg uses the exact embedding (the distance rows of all faces and an "
            "eigen-solve of the full affinity matrix), which is why its smallest size can take longer than the "
            "next one." if any(r["method"] != "cgal-sdf" and r["sampling"] is None for r in runs) else ""),
           "", "## Growth of the total time", "",
           "| configuration | sizes fitted | exponent |", "|---|---|---:|"]
    exponents = {}
    for config in configs:
        points = sorted((r["faces"], r["total"]) for r in runs
                        if configuration(r) == config and r["total"] and r["faces"] >= a.fit_min_faces)
        if len(points) >= 2:
            exponents[config] = slope(points)
            md.append("| %s | %s to %s faces (%d sizes) | %.2f |" % (
                label(config), "{:,}".format(points[0][0]), "{:,}".format(points[-1][0]), len(points),
                exponents[config]))
        else:
            md.append("| %s | %d size%s of at least %s faces | (needs two) |" % (
                label(config), len(points), "" if len(points) == 1 else "s", "{:,}".format(a.fit_min_faces)))
    md += ["",
           "Exponent: least-squares slope of log(total time) against log(faces) over the sizes with at least "
           "%s faces (below that, fixed costs weigh too much); 1 is linear growth." % "{:,}".format(a.fit_min_faces),
           ""]
    title = "k-way segmentation vs CGAL SDF, %s, k = %s" % (os.path.basename(a.mesh), ", ".join(str(k) for k in ks))
    png = plot(runs, configs, exponents, a.out_dir, title)
    if png:
        md += ["![Total time against faces, log-log](images/speed_plot.png)", ""]
    else:
        md += ["(No plot: gnuplot was %s when this table was written.)" % (
            "not installed" if shutil.which("gnuplot") is None else "failing"), ""]
    if failures:
        md += ["Failed runs (method, size, threads, exit status): " +
               "; ".join(", ".join(f) for f in failures) + ".", ""]
    table = os.path.join(a.out_dir, "speed_table.md")
    os.makedirs(a.out_dir, exist_ok=True)
    with open(table, "w") as f:
        f.write("\n".join(md))
    print("speed table written: %s" % table)
    if png:
        print("speed plot written: %s" % png)
    elif shutil.which("gnuplot") is None:
        print("speed plot SKIPPED: gnuplot not found (apt-get install gnuplot-nox); the table has no plot")
    else:
        print("speed plot SKIPPED: gnuplot failed (see above)")


if __name__ == "__main__":
    main()
