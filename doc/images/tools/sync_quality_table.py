#!/usr/bin/env python3
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Copies the table of doc/quality_table.md (written by bench_psb_quality
--markdown) into the first table of doc/benchmarks.md that has the same
header, without the timing row, so the two never disagree.

usage: sync_quality_table.py doc/quality_table.md doc/benchmarks.md
"""
import sys


def table(lines, header):
    """(first, end) line indices of the table that starts with `header`."""
    first = lines.index(header)
    end = first
    while end < len(lines) and lines[end].startswith("|"):
        end += 1
    return first, end


def main():
    source, target = sys.argv[1], sys.argv[2]
    quality = open(source).read().split("\n")
    header = next(l for l in quality if l.startswith("| category"))
    a, b = table(quality, header)
    rows = [l for l in quality[a:b] if not l.startswith("| total time")]
    text = open(target).read().split("\n")
    try:
        c, d = table(text, header)
    except ValueError:
        sys.exit(f"{target}: no table headed {header!r}")
    text[c:d] = rows
    open(target, "w").write("\n".join(text))


if __name__ == "__main__":
    main()
