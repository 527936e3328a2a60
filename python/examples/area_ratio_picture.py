# Copyright (c) 2026 The Discrete Lie Flow authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The picture of doc/python.md: a mesh mapped with discrete_lie_flow: the
initial (Tutte) map, the flow's result, and the flow with 4 times the
density on the faces right of the median x; triangles coloured by the log2
of their area ratio (share of the map's area over share of the surface's).

    python3 python/examples/area_ratio_picture.py MESH.off OUT.png
"""

import sys
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection

import discrete_lie_flow as dlf


def log2_area_ratio(V, F, uv):
    a, b, c = (V[F[:, k]] for k in range(3))
    area3 = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    p, q, r = (uv[F[:, k]] for k in range(3))
    area2 = 0.5 * ((q[:, 0] - p[:, 0]) * (r[:, 1] - p[:, 1]) - (q[:, 1] - p[:, 1]) * (r[:, 0] - p[:, 0]))
    return np.log2((area2 / area2.sum()) / (area3 / area3.sum()))


def main(mesh, out):
    V, F = dlf.read_mesh(mesh)
    # The initial map: no iteration of the flow (not converged, on purpose).
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        tutte, _ = dlf.disk(V, F, max_iterations=0)
    uv, report = dlf.disk(V, F)
    centroid_x = V[F].mean(axis=1)[:, 0]
    rho = np.where(centroid_x > np.median(centroid_x), 4.0, 1.0)  # one value per face
    uv4, report4 = dlf.disk(V, F, density=rho)
    fig, axes = plt.subplots(1, 3, figsize=(12, 4.4))
    panels = (("Tutte (initial map)", tutte),
              (f"Discrete Lie flow: D_area {report['final']['d_area']:.4f}", uv),
              ("density 4 right of the median x", uv4))
    for ax, (title, m) in zip(axes, panels):
        ratio = log2_area_ratio(V, F, m)
        polys = PolyCollection(m[F], array=np.clip(ratio, -3, 3), cmap="RdBu_r", edgecolors="face", linewidths=0.1)
        polys.set_clim(-3, 3)
        ax.add_collection(polys)
        ax.set_aspect("equal")
        ax.autoscale_view()
        ax.set_axis_off()
        ax.set_title(title, fontsize=10)
    fig.colorbar(polys, ax=axes, shrink=0.8, label="log2 area ratio (0: area preserved)")
    fig.savefig(out, dpi=100)
    print(f"wrote {out}: {len(F)} faces; {report['iterations']} iterations, {report['stop_reason']}; "
          f"with the density {report4['iterations']} iterations, {report4['stop_reason']}")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
