#!/usr/bin/env python3
# Copyright (c) 2026 The Discrete Lie Flow authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Two atlases of one mesh side by side in one PNG (no library beyond Python's).

    atlas_picture.py OUT.png TITLE_A A.obj TITLE_B B.obj [SIZE]

Each OBJ holds per-corner uv (`vt`, faces `f v/vt`). Each panel shows its
atlas's uv bounding square; every uv triangle is filled by the log of its
share of the uv area over its share of the surface area, on the colour
scale of `dlf atlas --svg`: white where the share is kept, red where the
triangle gets more than its share (up to 2x and beyond: full red), blue
where it gets less. Overlapping triangles are drawn in file order.
"""
import math
import struct
import sys
import zlib


def read_obj(path):
    v, vt, faces = [], [], []
    for line in open(path):
        p = line.split()
        if not p:
            continue
        if p[0] == "v":
            v.append(tuple(float(x) for x in p[1:4]))
        elif p[0] == "vt":
            vt.append(tuple(float(x) for x in p[1:3]))
        elif p[0] == "f":
            corners = [c.split("/") for c in p[1:]]
            for k in range(1, len(corners) - 1):  # a fan of the polygon
                tri = (corners[0], corners[k], corners[k + 1])
                faces.append(tuple((int(c[0]) - 1, int(c[1]) - 1) for c in tri))
    return v, vt, faces


def area3(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    w = [c[i] - a[i] for i in range(3)]
    n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    return 0.5 * math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)


def area2(a, b, c):
    return 0.5 * abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))


def colour(log_ratio):
    # log 2 (twice the share) and beyond: full red; −log 2: full blue.
    t = max(-1.0, min(1.0, log_ratio / math.log(2)))
    if t >= 0:
        return (255, int(255 * (1 - t)), int(255 * (1 - t)))
    return (int(255 * (1 + t)), int(255 * (1 + t)), 255)


def panel(path, size):
    v, vt, faces = read_obj(path)
    a3 = [area3(v[f[0][0]], v[f[1][0]], v[f[2][0]]) for f in faces]
    a2 = [area2(vt[f[0][1]], vt[f[1][1]], vt[f[2][1]]) for f in faces]
    s3, s2 = sum(a3), sum(a2)
    us = [p[0] for p in vt]
    vs = [p[1] for p in vt]
    x0, y0 = min(us), min(vs)
    extent = max(max(us) - x0, max(vs) - y0) or 1.0
    img = [[(235, 235, 235)] * size for _ in range(size)]
    for f, s, t in zip(faces, a2, a3):
        rgb = colour(math.log(max(s / s2, 1e-300) / max(t / s3, 1e-300))) if s > 0 else (0, 0, 0)
        P = [((vt[c[1]][0] - x0) / extent * (size - 1), (1 - (vt[c[1]][1] - y0) / extent) * (size - 1)) for c in f]
        xmin, xmax = max(0, int(min(p[0] for p in P))), min(size - 1, int(math.ceil(max(p[0] for p in P))))
        ymin, ymax = max(0, int(min(p[1] for p in P))), min(size - 1, int(math.ceil(max(p[1] for p in P))))
        (ax, ay), (bx, by), (cx, cy) = P
        d = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
        if d == 0:
            continue
        drawn = False
        for y in range(ymin, ymax + 1):
            py = y + 0.5
            row = img[y]
            for x in range(xmin, xmax + 1):
                px = x + 0.5
                l1 = ((bx - px) * (cy - py) - (by - py) * (cx - px)) / d
                l2 = ((cx - px) * (ay - py) - (cy - py) * (ax - px)) / d
                if l1 >= 0 and l2 >= 0 and l1 + l2 <= 1:
                    row[x] = rgb
                    drawn = True
        if not drawn:  # smaller than a pixel: its nearest pixel
            x = min(size - 1, max(0, int((ax + bx + cx) / 3)))
            y = min(size - 1, max(0, int((ay + by + cy) / 3)))
            img[y][x] = rgb
    return img


def write_png(path, rows):
    h, w = len(rows), len(rows[0])
    raw = b"".join(b"\x00" + bytes(c for px in r for c in px) for r in rows)
    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                  + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    if len(sys.argv) not in (6, 7):
        sys.exit(__doc__)
    out, title_a, obj_a, title_b, obj_b = sys.argv[1:6]
    size = int(sys.argv[6]) if len(sys.argv) == 7 else 480
    a, b = panel(obj_a, size), panel(obj_b, size)
    gap = 16
    rows = [ra + [(255, 255, 255)] * gap + rb for ra, rb in zip(a, b)]
    write_png(out, rows)
    print(f"atlas_picture: {out}: left {title_a}, right {title_b}, {size} px a panel", file=sys.stderr)


if __name__ == "__main__":
    main()
