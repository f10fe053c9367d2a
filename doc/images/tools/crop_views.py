#!/usr/bin/env python3
# Copyright (c) 2026 SpectralSeg developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Crops the white margins of each view of a picture made by SpectralSeg's
renderer (views side by side), optionally scales it down, and writes it
again as PNG. Pure Python (no imaging library needed); 8-bit RGB only.

usage: crop_views.py IN.png OUT.png [views=3] [scale=1.0]
"""
import sys, zlib, struct

def read_png(path):
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n'
    pos = 8; idat = b''; w = h = None
    while pos < len(data):
        n, = struct.unpack('>I', data[pos:pos+4]); t = data[pos+4:pos+8]
        body = data[pos+8:pos+8+n]; pos += 12 + n
        if t == b'IHDR':
            w, h, bd, ct, _, _, il = struct.unpack('>IIBBBBB', body)
            assert bd == 8 and ct == 2 and il == 0, (bd, ct, il)
        elif t == b'IDAT': idat += body
    raw = zlib.decompress(idat); bpp = 3; stride = w * bpp
    rows = []; prev = bytearray(stride); i = 0
    for y in range(h):
        f = raw[i]; line = bytearray(raw[i+1:i+1+stride]); i += 1 + stride
        for x in range(stride):
            a = line[x-bpp] if x >= bpp else 0; b = prev[x]; c = prev[x-bpp] if x >= bpp else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p-a), abs(p-b), abs(p-c)
                pr = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[x] = (line[x] + pr) & 255
        rows.append(line); prev = line
    return w, h, rows

def write_png(path, w, h, rows):
    bpp = 3; stride = w * bpp; out = bytearray(); prev = bytearray(stride)
    for line in rows:
        best = None
        for f in range(5):
            r = bytearray(stride)
            for x in range(stride):
                a = line[x-bpp] if x >= bpp else 0; b = prev[x]; c = prev[x-bpp] if x >= bpp else 0
                if f == 0: p = 0
                elif f == 1: p = a
                elif f == 2: p = b
                elif f == 3: p = (a + b) // 2
                else:
                    q = a + b - c; pa, pb, pc = abs(q-a), abs(q-b), abs(q-c)
                    p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                r[x] = (line[x] - p) & 255
            score = sum(v if v < 128 else 256 - v for v in r)
            if best is None or score < best[0]: best = (score, f, r)
        out.append(best[1]); out += best[2]; prev = line
    def chunk(t, b): return struct.pack('>I', len(b)) + t + b + struct.pack('>I', zlib.crc32(t + b) & 0xffffffff)
    png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0))
    png += chunk(b'IDAT', zlib.compress(bytes(out), 9)) + chunk(b'IEND', b'')
    open(path, 'wb').write(png)

def main():
    src, dst = sys.argv[1], sys.argv[2]
    views = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    scale = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0
    margin = 8
    w, h, rows = read_png(src)
    vw = w // views
    def white(x, y): return rows[y][3*x] == 255 and rows[y][3*x+1] == 255 and rows[y][3*x+2] == 255
    ys = [y for y in range(h) if any(not white(x, y) for x in range(0, w))]
    y0, y1 = max(0, ys[0] - margin), min(h, ys[-1] + 1 + margin)
    spans = []
    for v in range(views):
        xs = [x for x in range(v*vw, (v+1)*vw) if any(not white(x, y) for y in range(y0, y1))]
        spans.append((max(v*vw, xs[0] - margin), min((v+1)*vw, xs[-1] + 1 + margin)))
    nw = sum(b - a for a, b in spans); nh = y1 - y0
    img = []
    for y in range(y0, y1):
        line = bytearray()
        for a, b in spans: line += rows[y][3*a:3*b]
        img.append(line)
    if scale != 1.0:
        ow, oh = max(1, round(nw * scale)), max(1, round(nh * scale))
        # area-average resampling
        def weights(n, o):
            r = n / o; res = []
            for i in range(o):
                s, e = i * r, (i + 1) * r; ws = []
                for j in range(int(s), min(n, int(e) + 1)):
                    ov = min(e, j + 1) - max(s, j)
                    if ov > 1e-9: ws.append((j, ov / r))
                res.append(ws)
            return res
        wx, wy = weights(nw, ow), weights(nh, oh)
        tmp = []
        for line in img:
            nl = bytearray(3 * ow)
            for i, ws in enumerate(wx):
                for ch in range(3):
                    nl[3*i+ch] = min(255, int(round(sum(line[3*j+ch] * wt for j, wt in ws))))
            tmp.append(nl)
        img = []
        for ws in wy:
            nl = bytearray(3 * ow)
            for x in range(3 * ow):
                nl[x] = min(255, int(round(sum(tmp[j][x] * wt for j, wt in ws))))
            img.append(nl)
        nw, nh = ow, oh
    write_png(dst, nw, nh, img)
    print(dst, nw, 'x', nh)

main()
