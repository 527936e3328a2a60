#!/usr/bin/env python3
"""Renders a textured OBJ written by `dlf disk` (v, vt, f v/vt: per-vertex or
per-corner uv, as with --seam) as an SVG picture of the 3D model under a
checkerboard texture: orthographic view, painter's order, Lambert shading;
each triangle takes the colour of the checker square under its uv centroid.
No dependency beyond Python 3; turn the SVG into PNG with rsvg-convert.

  python3 benchmark/render_textured.py OUT.obj picture.svg [--squares 16]
      [--view X Y Z] [--up X Y Z] [--size 640]
"""
import argparse
import math


def read_obj(path):
    v, vt, faces = [], [], []
    with open(path) as f:
        for line in f:
            t = line.split()
            if not t:
                continue
            if t[0] == "v":
                v.append(tuple(float(x) for x in t[1:4]))
            elif t[0] == "vt":
                vt.append(tuple(float(x) for x in t[1:3]))
            elif t[0] == "f":
                corners = [c.split("/") for c in t[1:]]
                faces.append([(int(c[0]) - 1, int(c[1]) - 1 if len(c) > 1 and c[1] else int(c[0]) - 1)
                              for c in corners])
    return v, vt, faces


def normalized(a):
    n = math.sqrt(sum(x * x for x in a)) or 1.0
    return tuple(x / n for x in a)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("obj")
    ap.add_argument("svg")
    ap.add_argument("--squares", type=int, default=16, help="checker squares along the uv bounding box's longer side")
    ap.add_argument("--view", type=float, nargs=3, default=(0.0, 0.0, 1.0), help="direction towards the viewer")
    ap.add_argument("--up", type=float, nargs=3, default=(0.0, 1.0, 0.0))
    ap.add_argument("--size", type=int, default=640, help="picture width in pixels")
    a = ap.parse_args()
    v, vt, faces = read_obj(a.obj)
    view = normalized(a.view)
    right = normalized(cross(a.up, view))
    up = cross(view, right)
    xs = [dot(p, right) for p in v]
    ys = [dot(p, up) for p in v]
    zs = [dot(p, view) for p in v]
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    scale = (a.size - 20) / max(x1 - x0, 1e-300)
    height = int((y1 - y0) * scale) + 20
    us = [t[0] for t in vt]
    vs = [t[1] for t in vt]
    side = max(max(us) - min(us), max(vs) - min(vs)) / a.squares
    umin, vmin = min(us), min(vs)
    polys = []
    for f in faces:
        p = [v[c[0]] for c in f]
        n = normalized(cross(sub(p[1], p[0]), sub(p[2], p[0])))
        shade = 0.25 + 0.75 * abs(dot(n, view))
        uc = sum(vt[c[1]][0] for c in f) / len(f)
        vc = sum(vt[c[1]][1] for c in f) / len(f)
        dark = (int((uc - umin) / side) + int((vc - vmin) / side)) % 2 == 0
        base = (40, 70, 140) if dark else (235, 225, 200)
        colour = "#%02x%02x%02x" % tuple(int(c * shade) for c in base)
        depth = sum(zs[c[0]] for c in f) / len(f)
        pts = " ".join("%.1f,%.1f" % (10 + (xs[c[0]] - x0) * scale, height - 10 - (ys[c[0]] - y0) * scale) for c in f)
        polys.append((depth, pts, colour))
    polys.sort()
    with open(a.svg, "w") as out:
        out.write('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d">\n' % (a.size, height))
        out.write('<rect width="100%" height="100%" fill="white"/>\n')
        for _, pts, colour in polys:
            out.write('<polygon points="%s" fill="%s" stroke="%s" stroke-width="0.3"/>\n' % (pts, colour, colour))
        out.write("</svg>\n")


if __name__ == "__main__":
    main()
