# Copyright (c) 2026 The Discrete Lie Flow authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The cost of calling the flow from Python: discrete_lie_flow.disk() on a
mesh against the C++ call it wraps, alternated, median of N each.

  C++:    `dlf disk MESH --report R.json -q`, the report's seconds.total (the
          parameterize() call, timed inside the C++ process);
  Python: wall time of dlf.disk(V, F) (array checks and copies, the tool's
          topology checks, the same parameterize() call, the report as a
          dict), and, of that same call, its report's seconds.total.

  PYTHONPATH=build/python python3 benchmark/python_overhead.py build/examples/dlf MESH.off [N]
"""

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import discrete_lie_flow as dlf


def read_off(path):
    words = []
    with open(path) as f:
        for line in f:
            words += line.split("#")[0].split()
    n, m = int(words[1]), int(words[2])
    V = np.array(words[4:4 + 3 * n], dtype=float).reshape(n, 3)
    F = np.array(words[4 + 3 * n:4 + 3 * n + 4 * m], dtype=int).reshape(m, 4)[:, 1:]
    return V, F


def main(tool, mesh, runs=7):
    V, F = read_off(mesh)
    cpp, py_wall, py_inner = [], [], []
    with tempfile.TemporaryDirectory() as tmp:
        report_path = os.path.join(tmp, "r.json")
        for _ in range(runs):
            subprocess.run([tool, "disk", mesh, "--report", report_path, "-q"], check=True)
            with open(report_path) as f:
                cpp.append(json.load(f)["seconds"]["total"])
            start = time.perf_counter()
            uv, report = dlf.disk(V, F)
            py_wall.append(time.perf_counter() - start)
            py_inner.append(report["seconds"]["total"])
    c, w, i = statistics.median(cpp), statistics.median(py_wall), statistics.median(py_inner)
    print(f"{os.path.basename(mesh)}: {len(F)} faces, {runs} runs each, load average {os.getloadavg()[0]:.1f}")
    print(f"  C++ parameterize() (dlf disk)       median {c:.4f} s  (min {min(cpp):.4f}, max {max(cpp):.4f})")
    print(f"  Python dlf.disk() wall              median {w:.4f} s  (min {min(py_wall):.4f}, max {max(py_wall):.4f})")
    print(f"  parameterize() inside the Python call median {i:.4f} s")
    print(f"  overhead: Python wall / C++ call = {w / c:.4f} ({100 * (w / c - 1):+.2f}%); "
          f"Python wall / its own inner call = {w / i:.4f} ({100 * (w / i - 1):+.2f}%)")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 7)
