# Copyright (c) 2026 The Discrete Lie Flow authors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The Python module against the dlf tool on CGAL's meshes: the same maps bit
# for bit, the same report fields; every error path; arrays of any dtype and
# strides, never modified; the GIL released; a callback that stops the flow.
# Environment (set by CTest): DLF_EXECUTABLE, DLF_DATA_DIR, PYTHONPATH.

import json
import os
import subprocess
import threading
import time

import numpy as np
import pytest
from strict import missing_mesh

import discrete_lie_flow as dlf

DLF = os.environ.get("DLF_EXECUTABLE", "dlf")
MESHES = os.path.join(os.environ.get("DLF_DATA_DIR", "build/data"), "meshes")


def mesh_path(name):
    path = os.path.join(MESHES, name)
    if not os.path.exists(path):
        missing_mesh(path)
    return path


def read_off(path):
    """A plain reader of CGAL's OFF meshes (triangles)."""
    words = []
    with open(path) as f:
        for line in f:
            words += line.split("#")[0].split()
    assert words[0] == "OFF"
    n, m = int(words[1]), int(words[2])
    V = np.array(words[4:4 + 3 * n], dtype=np.float64).reshape(n, 3)
    F, k = [], 4 + 3 * n
    for _ in range(m):
        c = int(words[k])
        F.append([int(w) for w in words[k + 1:k + 1 + c]])
        k += 1 + c
    return V, np.array(F, dtype=np.int64)


def read_obj(path, key):
    """The rows of one record type ("v" or "vt") of an OBJ, as floats."""
    with open(path) as f:
        return np.array([[float(w) for w in line.split()[1:]] for line in f if line.startswith(key + " ")])


def run_tool(*args, check=(0, 3)):
    p = subprocess.run([DLF, *args], capture_output=True, text=True)
    assert p.returncode in check, p.stderr
    return p


def same_report(py, tool):
    """Equal but for the timings and the input's name."""
    def strip(r):
        r = dict(r)
        r.pop("seconds", None)
        r.pop("input", None)
        for k in ("initial", "final"):
            if isinstance(r.get(k), dict):
                r[k] = dict(r[k])
        return r
    assert list(py.keys()) == list(tool.keys())
    assert strip(py) == strip(tool)


@pytest.fixture(scope="module")
def nefertiti():
    return read_off(mesh_path("nefertiti.off"))


@pytest.fixture(scope="module")
def ball():
    return read_off(mesh_path("sphere.off"))


# --- the same results as the tool --------------------------------------------

@pytest.mark.parametrize("options", [{}, {"mode": "paper"}, {"border": "square"}, {"init": "arap"}])
def test_disk_matches_tool_bit_for_bit(tmp_path, nefertiti, options):
    V, F = nefertiti
    uv, report = dlf.disk(V, F, **options)
    args = []
    for k, v in options.items():
        args += ["--" + k, v]
    run_tool("disk", mesh_path("nefertiti.off"), *args, "-o", str(tmp_path / "m.obj"),
             "--report", str(tmp_path / "r.json"), "-q")
    tool_uv = read_obj(tmp_path / "m.obj", "vt")
    assert uv.shape == (len(V), 2) and uv.dtype == np.float64
    assert np.array_equal(uv, tool_uv)  # exact: the OBJ holds shortest round-trip decimals
    assert np.isfinite(uv).all()
    same_report(report, json.loads((tmp_path / "r.json").read_text()))
    assert report["final"]["inverted_faces"] == 0


def test_sphere_matches_tool_bit_for_bit(tmp_path, ball):
    V, F = ball
    points, report = dlf.sphere(V, F)
    run_tool("sphere", mesh_path("sphere.off"), "-o", str(tmp_path / "s.obj"), "--report", str(tmp_path / "r.json"), "-q")
    assert np.array_equal(points, read_obj(tmp_path / "s.obj", "v"))
    same_report(report, json.loads((tmp_path / "r.json").read_text()))
    assert np.allclose(np.linalg.norm(points, axis=1), 1.0)


def test_sphere_starts(tmp_path, ball):
    V, F = ball
    points, report = dlf.sphere(V, F, start="conformal")
    run_tool("sphere", mesh_path("sphere.off"), "--start", "conformal", "-o", str(tmp_path / "s.obj"), "-q")
    assert report["start"] == "conformal"
    assert np.array_equal(points, read_obj(tmp_path / "s.obj", "v"))
    # An earlier result as the start: nothing left to do.
    again, report = dlf.sphere(V, F, init_map=3 * points)
    assert report["start"] == "given" and report["iterations"] <= 1
    folded = points.copy()
    folded[[F[0][0], F[0][1]]] = folded[[F[0][1], F[0][0]]]
    with pytest.raises(ValueError, match="ERROR_INITIAL_MAP_FOLDED"):
        dlf.sphere(V, F, init_map=folded)
    with pytest.raises(ValueError, match="init_map and start exclude each other"):
        dlf.sphere(V, F, init_map=points, start="conformal")


def test_init_uv_matches_tool(tmp_path, nefertiti):
    V, F = nefertiti
    run_tool("disk", mesh_path("nefertiti.off"), "-o", str(tmp_path / "m.obj"), "-q")
    start = read_obj(tmp_path / "m.obj", "vt")
    # A start away from the result: the tool's map squeezed along y, still fold-free.
    start = start * np.array([1.0, 0.5])
    lines = (tmp_path / "m.obj").read_text().splitlines()
    k = iter(start)
    with open(tmp_path / "s.obj", "w") as f:
        for line in lines:
            if line.startswith("vt "):
                u, v = next(k)
                line = "vt %r %r" % (float(u), float(v))
            f.write(line + "\n")
    run_tool("disk", mesh_path("nefertiti.off"), "--init-uv", str(tmp_path / "s.obj"), "-o", str(tmp_path / "o.obj"),
             "--report", str(tmp_path / "r.json"), "-q")
    before = start.copy()
    uv, report = dlf.disk(V, F, init_uv=start)
    assert np.array_equal(start, before)  # the caller's array is only read
    assert np.array_equal(uv, read_obj(tmp_path / "o.obj", "vt"))
    same_report(report, json.loads((tmp_path / "r.json").read_text()))
    assert report["init"] == "uv" and report["final"]["inverted_faces"] == 0
    folded = start.copy()
    folded[[F[0][0], F[0][1]]] = folded[[F[0][1], F[0][0]]]
    with pytest.raises(dlf.FlowError, match="ERROR_INITIAL_MAP_FOLDED: .* first: face 0 "):
        dlf.disk(V, F, init_uv=folded)  # as the tool: exit 2, the start named
    with pytest.raises(ValueError, match="init_uv and init exclude each other"):
        dlf.disk(V, F, init_uv=start, init="mvc")
    with pytest.raises(ValueError, match="border=\"free\" only"):
        dlf.disk(V, F, init_uv=start, border="circle")
    with pytest.raises(ValueError, match=r"init_uv must have shape \(%d, 2\)" % len(V)):
        dlf.disk(V, F, init_uv=start[:-1])
    bad = start.copy()
    bad[3, 1] = np.nan
    with pytest.raises(ValueError, match="init_uv: row 3 is not finite"):
        dlf.disk(V, F, init_uv=bad)


@pytest.mark.parametrize("options", [{"mode": "literal", "threshold": 1e-4}, {"fixed_step": 0.05, "max_iterations": 6},
                                     {"mode": "literal", "fixed_step": 0.01, "max_iterations": 6}])
def test_step_options_match_tool(tmp_path, nefertiti, options):
    V, F = nefertiti
    try:
        uv, report = dlf.disk(V, F, **options)
    except dlf.FlowError as e:  # a documented failure of the literal flow: the tool must fail alike
        uv, report = None, e.report
    args = []
    for k, v in options.items():
        args += ["--" + k.replace("_", "-"), str(v)]
    code = subprocess.run([DLF, "disk", mesh_path("nefertiti.off"), *args, "-o", str(tmp_path / "m.obj"),
                           "--report", str(tmp_path / "r.json"), "-q"], capture_output=True).returncode
    same_report(report, json.loads((tmp_path / "r.json").read_text()))
    if uv is None:
        assert code == 2
    else:
        assert code in (0, 3)
        assert np.array_equal(uv, read_obj(tmp_path / "m.obj", "vt"))
    for key in ("fixed_step", "threshold"):
        if key in options:
            assert report["options"][key] == options[key]


def test_density_matches_tool(tmp_path, nefertiti):
    V, F = nefertiti
    density = 1.0 + (V[:, 0] > np.median(V[:, 0]))  # per vertex: 2 on one half
    np.savetxt(tmp_path / "rho.txt", density)
    uv, report = dlf.disk(V, F, density=density)
    run_tool("disk", mesh_path("nefertiti.off"), "--density", str(tmp_path / "rho.txt"), "-o", str(tmp_path / "m.obj"),
             "--report", str(tmp_path / "r.json"), "-q")
    assert np.array_equal(uv, read_obj(tmp_path / "m.obj", "vt"))
    tool = json.loads((tmp_path / "r.json").read_text())
    assert report["density"]["source"] == "vertex" and tool["density"]["source"] == "vertex"
    assert report["options"] == tool["options"] and report["final"] == tool["final"]


def test_score_and_info_match_tool(tmp_path, nefertiti):
    V, F = nefertiti
    uv, report = dlf.disk(V, F)
    metrics = dlf.score(V, F, uv)
    assert metrics == report["final"]
    run_tool("disk", mesh_path("nefertiti.off"), "-o", str(tmp_path / "m.obj"), "-q")
    run_tool("score", mesh_path("nefertiti.off"), str(tmp_path / "m.obj"), "--report", str(tmp_path / "s.json"), "-q")
    assert metrics == json.loads((tmp_path / "s.json").read_text())["metrics"]
    info = dlf.info(V, F)
    run_tool("info", mesh_path("nefertiti.off"), "--report", str(tmp_path / "i.json"), "-q")
    tool = json.loads((tmp_path / "i.json").read_text())
    assert info["mesh"] == "mesh"
    info.pop("mesh"), tool.pop("mesh")
    assert info == tool and info["fits"] == "dlf disk"


# --- arrays --------------------------------------------------------------------

def test_dtypes_and_strides_give_the_same_map(nefertiti):
    V, F = nefertiti
    uv, _ = dlf.disk(V, F)
    wide = np.zeros((len(V), 6))
    wide[:, ::2] = V                            # non-contiguous rows
    Vf = np.asfortranarray(V)                   # column-major
    F32 = np.ascontiguousarray(F, dtype=np.int32)
    Fu = np.asfortranarray(F.astype(np.uint64))
    for V2, F2 in ((wide[:, ::2], F), (Vf, F32), (V, Fu), (V.tolist(), F.tolist())):
        uv2, _ = dlf.disk(V2, F2)
        assert np.array_equal(uv, uv2)


def test_input_arrays_are_not_modified(nefertiti):
    V, F = nefertiti
    V2, F2 = V.copy(), F.copy()
    V2.flags.writeable = False
    F2.flags.writeable = False
    dlf.disk(V2, F2)
    dlf.disk(V2, F2, mode="paper")
    assert np.array_equal(V, V2) and np.array_equal(F, F2)
    # An inconsistently oriented mesh is oriented on a copy.
    F3 = F.copy()
    F3[0] = F3[0][::-1]
    before = F3.copy()
    uv, _ = dlf.disk(V, F3)
    assert np.array_equal(F3, before) and np.isfinite(uv).all()


# --- errors --------------------------------------------------------------------

def tetrahedron():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    return V, F


def eared_hexagon():
    """A hexagon fan with a triangle on each side: six ears, which no
    square border takes (a valid disk on which the flow fails)."""
    ring = [[np.cos(a), np.sin(a), 0] for a in np.arange(6) * np.pi / 3]
    tips = [[2 * np.cos(a), 2 * np.sin(a), 0] for a in (np.arange(6) + 0.5) * np.pi / 3]
    V = np.array([[0, 0, 0]] + ring + tips, dtype=float)
    F = [[0, 1 + i, 1 + (i + 1) % 6] for i in range(6)] + [[1 + i, 7 + i, 1 + (i + 1) % 6] for i in range(6)]
    return V, np.array(F)


@pytest.mark.parametrize("V, F, message", [
    (np.zeros((3, 2)), [[0, 1, 2]], r"V must have shape \(n, 3\), got \(3, 2\)"),
    (np.array([["a", "b", "c"]] * 3), [[0, 1, 2]], "V must hold real numbers"),
    (np.eye(3), np.array([[0.0, 1.0, 2.0]]), "F must hold integers, got dtype float64"),
    (np.eye(3), [[0, 1, 3]], "F: face 0 refers to vertex 3 of 3"),
    (np.eye(3), [[0, -1, 2]], "F: face 0 refers to vertex -1 of 3"),
    (np.eye(3), [[0, 1, 1]], "face 0 uses vertex 1 twice"),
    (np.eye(3), np.zeros((0, 3), dtype=int), "the mesh has no faces"),
    (np.array([[0, 0, 0], [1, 0, 0], [0, np.nan, 0]]), [[0, 1, 2]], "vertex 2 has a non-finite coordinate"),
    (np.eye(4)[:, :3], [[0, 1, 2]], "1 vertex is not used by any face"),
    (None, [[0, 1, 2]], "V must be an array, not None"),
])
def test_bad_arrays_raise_value_error(V, F, message):
    for f in (dlf.disk, dlf.sphere):
        with pytest.raises(ValueError, match=message):
            f(V, F)


def test_unsuitable_meshes_and_options_raise_value_error(nefertiti):
    V, F = nefertiti
    T, TF = tetrahedron()
    with pytest.raises(ValueError, match="not a disk"):
        dlf.disk(T, TF)
    with pytest.raises(ValueError, match="NOT_GENUS_0|genus"):
        dlf.sphere(V, F)
    nm = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]], dtype=float)
    with pytest.raises(ValueError, match="not manifold"):
        dlf.disk(nm, [[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    with pytest.raises(ValueError, match="invalid value 'fast' for --mode|mode"):
        dlf.disk(V, F, mode="fast")
    with pytest.raises(ValueError, match="--tolerance must be a number >= 0"):
        dlf.disk(V, F, tolerance=-1)
    with pytest.raises(ValueError, match="--mu must be in"):
        dlf.sphere(T, TF, mu=1.5)
    with pytest.raises(ValueError, match="--border square needs a fixed-border"):
        dlf.disk(V, F, init="arap", border="square")
    with pytest.raises(ValueError, match="density: 5 values; expected 562"):
        dlf.disk(V, F, density=np.ones(5))
    with pytest.raises(ValueError, match=r"density\[3\]: the density of face 3 is -1"):
        rho = np.ones(len(F))
        rho[3] = -1
        dlf.disk(V, F, density=rho)
    with pytest.raises(ValueError, match=r"uv must have shape \(299, 2\)"):
        dlf.score(V, F, np.zeros((3, 2)))
    with pytest.raises(ValueError, match="uv: vertex 0 has a non-finite coordinate"):
        dlf.score(V, F, np.full((len(V), 2), np.inf))
    with pytest.raises(TypeError, match="tolerance must be a number, got str"):
        dlf.disk(V, F, tolerance="small")
    with pytest.raises(TypeError, match="max_iterations must be an integer, got float"):
        dlf.disk(V, F, max_iterations=2.5)
    with pytest.raises(TypeError):
        dlf.disk(V, F, mode=3)
    with pytest.raises(ValueError, match="invalid value '--help' for init"):
        dlf.disk(V, F, init="--help")


def test_flow_error_carries_the_report():
    V, F = eared_hexagon()
    with pytest.raises(dlf.FlowError, match="ERROR_BORDER_TOO_SHORT.*6 ears") as e:
        dlf.disk(V, F, border="square")
    assert isinstance(e.value, RuntimeError)
    assert e.value.report["status"] == "ERROR_BORDER_TOO_SHORT" and e.value.report["final"] is None
    uv, report = dlf.disk(V, F)  # the circle takes it
    assert report["final"]["inverted_faces"] == 0 and np.isfinite(uv).all()


# --- callback, GIL ----------------------------------------------------------

def test_callback_sees_every_iteration_and_can_stop(nefertiti):
    V, F = nefertiti
    seen = []
    _, full = dlf.disk(V, F, tolerance=1e-6, callback=lambda it: seen.append(it))
    assert [it["iteration"] for it in seen] == list(range(1, full["iterations"] + 1))
    assert seen[-1]["d_area"] == full["domain_d_area"]
    assert full["iterations"] >= 3
    uv, report = dlf.disk(V, F, tolerance=1e-6, callback=lambda it: it["iteration"] < 2)
    assert report["iterations"] == 2 and report["stop_reason"] == "interrupted"
    assert report["status"] == "not_converged" and np.isfinite(uv).all()
    assert report["final"]["inverted_faces"] == 0


def test_callback_exception_propagates(ball):
    V, F = ball

    class Stop(Exception):
        pass

    def boom(it):
        raise Stop(f"stopped at {it['iteration']}")

    with pytest.raises(Stop, match="stopped at 1"):
        dlf.sphere(V, F, callback=boom)
    points, _ = dlf.sphere(V, F)  # the module still works
    assert np.isfinite(points).all()


def test_flow_runs_without_the_gil():
    # One call long enough on any machine (about 0.3 s here): between calls
    # the spinner would run even if a call held the GIL.
    V, F = read_off(mesh_path("mannequin-devil.off"))
    count = [0]
    stop = threading.Event()

    def spin():
        while not stop.is_set():
            count[0] += 1

    t = threading.Thread(target=spin)
    t.start()
    time.sleep(0.05)
    before = count[0]
    start = time.perf_counter()
    dlf.disk(V, F)
    elapsed = time.perf_counter() - start
    during = count[0] - before
    stop.set()
    t.join()
    # With the GIL held for the whole call the other thread would not run.
    assert elapsed > 0.05
    assert during > 10000, (during, elapsed)
