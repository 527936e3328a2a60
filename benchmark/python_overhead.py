# Copyright (c) 2026 The Discrete Lie Flow authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The cost of calling the flow from Python: discrete_lie_flow.disk(V, F)
against the same call made from C++, alternated, median of N each, on a
busy or idle machine alike (the ratio is what counts).

  C++:    build/benchmark/dlf_call_timing MESH 1: the input checks, the flow
          and the report on index arrays in memory, through the code the
          module calls, timed inside the C++ process;
  Python: wall time of dlf.disk(V, F): the same work, plus the conversion
          of the NumPy arrays and of the report into a dict.
  Both also print the parameterize() call alone (the report's seconds.total).

  PYTHONPATH=build/python /usr/bin/python3 benchmark/python_overhead.py build MESH.off [N]
"""

import os
import statistics
import subprocess
import sys
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


def main(build, mesh, runs=7):
    timing = os.path.join(build, "benchmark", "dlf_call_timing")
    V, F = read_off(mesh)
    cpp, cpp_inner, py_wall, py_inner = [], [], [], []
    dlf.disk(V, F)  # warm up (page cache, the module's first import of json)
    for _ in range(runs):
        out = subprocess.run([timing, mesh, "1"], check=True, capture_output=True, text=True).stdout.split()
        cpp.append(float(out[0]))
        cpp_inner.append(float(out[1]))
        start = time.perf_counter()
        uv, report = dlf.disk(V, F)
        py_wall.append(time.perf_counter() - start)
        py_inner.append(report["seconds"]["total"])
    med = statistics.median
    c, w = med(cpp), med(py_wall)
    print(f"{os.path.basename(mesh)}: {len(F)} faces, {runs} runs each, alternated; "
          f"load average {os.getloadavg()[0]:.1f}")
    print(f"  C++ call     median {c:.4f} s (min {min(cpp):.4f}, max {max(cpp):.4f}); "
          f"parameterize() median {med(cpp_inner):.4f} s")
    print(f"  Python call  median {w:.4f} s (min {min(py_wall):.4f}, max {max(py_wall):.4f}); "
          f"parameterize() median {med(py_inner):.4f} s")
    print(f"  Python / C++ = {w / c:.4f} ({100 * (w / c - 1):+.2f}%)")
    # The flow's own time varies most on a busy machine; what the binding
    # adds is the time around it: the call minus its parameterize().
    around_cpp = med([a - b for a, b in zip(cpp, cpp_inner)])
    around_py = med([a - b for a, b in zip(py_wall, py_inner)])
    print(f"  around parameterize(): C++ {around_cpp:.4f} s, Python {around_py:.4f} s; "
          f"the difference is {100 * (around_py - around_cpp) / c:+.2f}% of the C++ call")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 7)
