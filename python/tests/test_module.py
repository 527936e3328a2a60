# Copyright (c) 2026 The Discrete Lie Flow authors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# The Python module against the dlf tool on CGAL's meshes: the same maps bit
# for bit, the same report fields; every error path (TypeError for types,
# ValueError for shapes and values, in the keywords' words); arrays of any
# dtype and strides, never modified; the GIL released; a callback that stops
# the flow; warnings for maps that fall short; the atlas checked in NumPy.
# Environment (set by CTest): DLF_EXECUTABLE, DLF_DATA_DIR, PYTHONPATH.

import ast
import inspect
import json
import os
import subprocess
import sys
import threading
import warnings

import numpy as np
import pytest
from strict import missing_mesh

import discrete_lie_flow as dlf

DLF = os.environ.get("DLF_EXECUTABLE", "dlf")
MESHES = os.path.join(os.environ.get("DLF_DATA_DIR", "build/data"), "meshes")
SEAMS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "test", "data")


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
    (None, [[0, 1, 2]], "V must be an array, not None"),
    (np.eye(3), None, "F must be an array, not None"),
    ("mesh.off", [[0, 1, 2]], "V must be an array, not str"),
    (np.eye(3), "0 1 2", "F must be an array, not str"),
    (np.array([["a", "b", "c"]] * 3), [[0, 1, 2]], "V must hold real numbers, got dtype <U1"),
    ([["a", "b", "c"]] * 3, [[0, 1, 2]], "V must hold real numbers"),
    (np.eye(3) * (1 + 1j), [[0, 1, 2]], "V must hold real numbers, got dtype complex128"),
    (np.eye(3, dtype=bool), [[0, 1, 2]], "V must hold real numbers, got dtype bool"),
    ({"V": 1}, [[0, 1, 2]], "V must hold real numbers, got dtype object"),
    (np.eye(3), np.array([[0.0, 1.0, 2.0]]), "F must hold integers, got dtype float64"),
])
def test_wrong_types_raise_type_error(V, F, message):
    for f in (dlf.disk, dlf.sphere, dlf.atlas, dlf.info):
        with pytest.raises(TypeError, match=message):
            f(V, F)


@pytest.mark.parametrize("V, F, message", [
    (np.zeros((3, 2)), [[0, 1, 2]], r"V must have shape \(n, 3\), got \(3, 2\)"),
    ([[0, 0, 0], [1, 0]], [[0, 1, 2]], "V must be an array"),
    (np.eye(3), [[0, 1, 2, 0]], r"F must have shape \(m, 3\), got \(1, 4\)"),
    (np.eye(3), [0, 1, 2], r"F must have shape \(m, 3\), got \(3,\)"),
    (np.eye(3), [[0, 1, 3]], "F: face 0 refers to vertex 3 of 3"),
    (np.eye(3), [[0, -1, 2]], "F: face 0 refers to vertex -1 of 3"),
    (np.eye(3), [[0, 1, 1]], "face 0 uses vertex 1 twice"),
    (np.eye(3), np.zeros((0, 3), dtype=int), "the mesh has no faces"),
    (np.array([[0, 0, 0], [1, 0, 0], [0, np.nan, 0]]), [[0, 1, 2]], "vertex 2 has a non-finite coordinate"),
    (np.eye(4)[:, :3], [[0, 1, 2]], "1 vertex is not used by any face"),
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
    # The messages name the keywords, never the tool's options.
    for call, message in (
            (lambda: dlf.disk(V, F, mode="fast"), r"^invalid value 'fast' for mode \(expected certified, paper or literal\)$"),
            (lambda: dlf.disk(V, F, tolerance=-1), "^tolerance must be a number >= 0$"),
            (lambda: dlf.disk(V, F, max_iterations=-1), "^max_iterations must be >= 0$"),
            (lambda: dlf.sphere(T, TF, mu=1.5), r"^mu must be in \(0, 1\)$"),
            (lambda: dlf.disk(V, F, share_tolerance=-1), "^share_tolerance must be a number >= 0$"),
            (lambda: dlf.disk(V, F, init="arap", border="square"), "^border square needs a fixed-border initial map "
                                                                    r"\(init tutte, mvc or dcp\); arap gives a free border$"),
            (lambda: dlf.disk(V, F, delaunay_flips=False), "^delaunay_flips=False applies to mode paper only$"),
            (lambda: dlf.disk(V, F, fixed_step=-1.0), "^fixed_step must be a number > 0$"),
            (lambda: dlf.disk(V, F, outer_loop=2), "^outer_loop 2: mesh has 1 border loop"),
            (lambda: dlf.disk(V, F, band=0.1), "^band applies to regions only$"),
            (lambda: dlf.atlas(V, F, gutter=0.7), r"^gutter must be in \[0, 0.5\)$"),
            (lambda: dlf.atlas(V, F, border="free"), "^invalid value 'free' for border"),
    ):
        with pytest.raises(ValueError, match=message) as e:
            call()
        assert "--" not in str(e.value), str(e.value)
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
    # Found by test_properties.py: each once raised RuntimeError or an empty message.
    with pytest.raises(TypeError, match="border must be a string, got float"):
        dlf.disk(V, F, border=-0.5)
    with pytest.raises(ValueError, match="max_iterations is out of range: 10{30}"):
        dlf.sphere(V, F, max_iterations=10 ** 30)
    with pytest.raises(TypeError, match="callback must be callable"):
        dlf.disk(V, F, callback=0)
    for f in (dlf.disk, dlf.sphere, dlf.atlas, dlf.info):
        with pytest.raises(ValueError, match="name must not contain a NUL character"):
            f(V, F, name="a\x00b")
    with pytest.raises(TypeError, match="density must hold real numbers, got dtype <U"):
        dlf.disk(V, F, density=["high"] * len(F))
    with pytest.raises(TypeError, match="density must be an array, not str"):
        dlf.disk(V, F, density="high")
    with pytest.raises(TypeError, match="regions must be a list of dicts, got str"):
        dlf.disk(V, F, regions="nose")
    with pytest.raises(TypeError, match=r"regions\[0\]\['factor'\] must be a number, got str"):
        dlf.disk(V, F, regions=[{"faces": [0, 1], "factor": "4"}])
    with pytest.raises(ValueError, match=r"regions\[0\]\['faces'\]: face 9999 does not exist \(the mesh has 562 faces\)"):
        dlf.disk(V, F, regions=[{"faces": [0, 9999], "factor": 4}])
    with pytest.raises(ValueError, match=r"regions\[0\] needs one of 'faces' and 'ball'"):
        dlf.disk(V, F, regions=[{"factor": 4}])
    with pytest.raises(ValueError, match="density and regions exclude each other"):
        dlf.disk(V, F, density=np.ones(len(F)), regions=[{"faces": [0], "factor": 2}])
    with pytest.raises(ValueError, match=r"^regions\[0\]: no face has its centroid in this ball$"):
        dlf.disk(V, F, regions=[{"ball": (1e3, 0, 0, 1), "factor": 2}])
    with pytest.raises(TypeError, match="seam must hold vertex indices"):
        dlf.disk(V, F, seam=np.zeros((2, 2)))
    with pytest.raises(ValueError, match=r"seam must have shape \(k, 2\)"):
        dlf.disk(V, F, seam=[1, 2, 3])
    with pytest.raises(TypeError, match="tips must be an integer, got float"):
        dlf.atlas(V, F, tips=2.5)
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
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # stopped by the caller: not warned as a shortfall
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
    # While the flow computes between two callbacks, another Python thread
    # runs: it sees the flow's thread in the wrapper's frame (in C++, not in
    # the callback), and a later callback proves the flow was still running.
    # With the GIL held between callbacks the main thread could only run
    # during a callback or after the flow, and the flow would run to its
    # iteration cap. No clock is read. A mesh whose iterations are long
    # (tens of milliseconds) leaves the other thread ample room.
    V, F = read_off(mesh_path("mannequin-devil.off"))
    seen_after = []      # the number of callbacks made when the flow was seen computing
    calls = [0]
    result = {}

    def callback(it):
        calls[0] += 1
        return not (seen_after and calls[0] > seen_after[0])

    def run():
        result["out"] = dlf.disk(V, F, tolerance=1e-12, max_iterations=100000, callback=callback)

    t = threading.Thread(target=run)
    t.start()
    while t.is_alive() and not seen_after:
        frame = sys._current_frames().get(t.ident)
        n = calls[0]
        if frame is not None and frame.f_code is dlf.disk.__code__ and n >= 1:
            seen_after.append(n)
    t.join()
    uv, report = result["out"]
    assert seen_after, "the flow's thread was never seen computing"
    assert report["stop_reason"] == "interrupted" and calls[0] > seen_after[0]
    assert np.isfinite(uv).all()


# --- the module's surface ---------------------------------------------------------

def test_dir_lists_the_api_only():
    public = [n for n in dir(dlf) if not n.startswith("_")]
    assert public == sorted(n for n in dlf.__all__ if not n.startswith("_"))
    for name in ("Any", "Callable", "Dict", "Optional", "Tuple", "os", "warnings"):
        assert not hasattr(dlf, name), name
    for name in dlf.__all__:
        assert hasattr(dlf, name), name


def test_type_stubs_match_the_functions():
    stubs = ast.parse(open(os.path.join(os.path.dirname(dlf.__file__), "__init__.pyi")).read())
    stubbed = {f.name: f for f in stubs.body if isinstance(f, ast.FunctionDef)}
    functions = [n for n in dlf.__all__ if inspect.isfunction(getattr(dlf, n))]
    assert sorted(stubbed) == sorted(functions)
    for name in functions:
        a = stubbed[name].args
        in_stub = [x.arg for x in a.posonlyargs + a.args] + ["*"] * bool(a.kwonlyargs) + [x.arg for x in a.kwonlyargs]
        params = inspect.signature(getattr(dlf, name)).parameters.values()
        in_code = [p.name for p in params if p.kind != p.KEYWORD_ONLY]
        keywords = [p.name for p in params if p.kind == p.KEYWORD_ONLY]
        assert in_stub == in_code + ["*"] * bool(keywords) + keywords, name


def test_read_mesh(tmp_path, nefertiti):
    V, F = dlf.read_mesh(mesh_path("nefertiti.off"))
    assert V.dtype == np.float64 and F.dtype == np.int64
    assert np.array_equal(V, nefertiti[0]) and np.array_equal(F, nefertiti[1])
    import pathlib
    V2, F2 = dlf.read_mesh(pathlib.Path(mesh_path("nefertiti.off")))
    assert np.array_equal(V2, V) and np.array_equal(F2, F)
    with pytest.raises(FileNotFoundError):
        dlf.read_mesh(str(tmp_path / "missing.off"))
    with pytest.raises(TypeError, match="path must be a str or os.PathLike, got NoneType"):
        dlf.read_mesh(None)
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2 3\n")
    with pytest.raises(ValueError):
        dlf.read_mesh(str(bad))


# --- measure control and seams as keywords ------------------------------------------

def test_regions_match_tool(tmp_path, nefertiti):
    V, F = nefertiti
    centre = V.mean(axis=0)
    radius = 0.3 * float(np.linalg.norm(V.max(axis=0) - V.min(axis=0)))
    uv, report = dlf.disk(V, F, regions=[{"ball": tuple(centre) + (radius,), "factor": 4}], band=0.05)
    ball = [repr(float(x)) for x in centre] + [repr(radius)]
    run_tool("disk", mesh_path("nefertiti.off"), "--roi-ball", *ball, "--factor", "4", "--band", "0.05",
             "-o", str(tmp_path / "m.obj"), "--report", str(tmp_path / "r.json"), "-q")
    assert np.array_equal(uv, read_obj(tmp_path / "m.obj", "vt"))
    tool = json.loads((tmp_path / "r.json").read_text())
    assert [r["faces"] for r in report["regions"]] == [r["faces"] for r in tool["regions"]]
    assert report["regions"][0]["name"] == "regions[0]"
    assert report["regions"][0]["achieved_fraction"] == tool["regions"][0]["achieved_fraction"]
    assert report["options"]["tolerance"] == 5e-4  # as the tool's default with a region


def test_face_region_is_the_density_it_stands_for(nefertiti):
    V, F = nefertiti
    faces = np.arange(0, len(F), 3)
    rho = np.ones(len(F))
    rho[faces] = 4.0
    uv_region, report = dlf.disk(V, F, regions=[{"faces": faces, "factor": 4.0, "name": "every third"}])
    uv_density, _ = dlf.disk(V, F, density=rho)
    assert np.array_equal(uv_region, uv_density)
    r = report["regions"][0]
    assert r["name"] == "every third" and r["faces"] == len(faces)
    # The achieved share, recomputed from the map.
    tri = uv_region[F]
    area = 0.5 * np.abs((tri[:, 1, 0] - tri[:, 0, 0]) * (tri[:, 2, 1] - tri[:, 0, 1])
                        - (tri[:, 1, 1] - tri[:, 0, 1]) * (tri[:, 2, 0] - tri[:, 0, 0]))
    assert abs(area[faces].sum() / area.sum() - r["achieved_fraction"]) < 1e-9


def read_selection_edges(path):
    with open(path) as f:
        lines = f.read().split("\n")
    ints = [int(w) for w in lines[2].split()]
    return np.array(ints, dtype=np.int64).reshape(-1, 2)


def test_seam_matches_tool(tmp_path):
    V, F = read_off(mesh_path("blob.off"))
    selection = os.path.join(SEAMS, "blob.selection.txt")
    uv, report = dlf.disk(V, F, seam=read_selection_edges(selection))
    run_tool("disk", mesh_path("blob.off"), "--seam", selection, "-o", str(tmp_path / "m.obj"), "-q")
    vt = read_obj(tmp_path / "m.obj", "vt")
    with open(tmp_path / "m.obj") as f:
        corners = [[int(w.split("/")[1]) - 1 for w in line.split()[1:]] for line in f if line.startswith("f ")]
    assert uv.shape == (len(F), 3, 2)
    assert np.array_equal(uv, vt[np.array(corners)])
    assert report["seam"]["edges"] == len(read_selection_edges(selection)) and report["status"] == "ok"
    with pytest.raises(ValueError, match=r"seam: edge 0 \(0 0\): not an edge"):
        dlf.disk(V, F, seam=[[0, 0]])


# --- maps that fall short: warned, or raised with strict=True --------------------

def test_not_converged_warns_or_raises_when_strict(nefertiti):
    V, F = nefertiti
    with pytest.warns(UserWarning, match="mesh: did not converge") as caught:
        uv, report = dlf.disk(V, F, max_iterations=0)
    assert report["status"] == "not_converged" and np.isfinite(uv).all()
    assert report["message"] in str(caught[0].message)
    assert "short of d_area " in str(caught[0].message)  # the goal missed, with its value
    assert caught[0].filename == __file__  # pointed at the caller's line
    with pytest.raises(dlf.FlowError, match="did not converge") as e:
        dlf.disk(V, F, max_iterations=0, strict=True)
    assert e.value.report["status"] == "not_converged"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _, report = dlf.disk(V, F)  # converged: silent
        assert report["status"] == "ok"
        dlf.disk(V, F, strict=True)


def test_inverted_input_triangles_warn(nefertiti):
    # The literal mode inverts one of nefertiti's triangles (its flowing
    # triangulation is certified, the caller's triangles are not).
    V, F = nefertiti
    with pytest.warns(UserWarning) as caught:
        _, report = dlf.disk(V, F, mode="literal")
    inverted = report["caller_inverted_faces"]
    assert inverted >= 1
    words = " ".join(str(w.message) for w in caught)
    assert len(caught) == 1 and f"{inverted} of the input's triangles" in words and report["message"] in words
    # A converged map that inverts input triangles (the paper mode's flips can): said from the count alone.
    said = dlf._shortfall({"status": "ok", "message": "Success", "caller_inverted_faces": 3, "mode": "paper"})
    assert said == ("3 of the input's triangles are inverted (only the flowing triangulation is certified in "
                    "mode 'paper'; the certified mode never inverts them)")
    with pytest.raises(dlf.FlowError, match="of the input's triangles") as e:
        dlf.disk(V, F, mode="literal", strict=True)
    assert e.value.report["caller_inverted_faces"] == inverted


# --- the atlas, checked without the library --------------------------------------

def atlas_check(V, F, uv, report):
    """Recomputes in NumPy what the atlas promises: every corner in the unit
    square, every face's uv area positive, and the global D_area of the uv
    area shares against the 3D area shares."""
    V, F = np.asarray(V, dtype=float), np.asarray(F)
    assert uv.shape == (len(F), 3, 2) and uv.dtype == np.float64 and np.isfinite(uv).all()
    assert uv.min() >= 0 and uv.max() <= 1
    a, b, c = uv[:, 0], uv[:, 1], uv[:, 2]
    uv_area = 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))
    assert (uv_area > 0).all(), f"{int((uv_area <= 0).sum())} faces not positive"
    p, q, r = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(q - p, r - p), axis=1)
    share, uv_share = area / area.sum(), uv_area / uv_area.sum()
    ratio = uv_share / share
    d_area = float(np.sum(share * (ratio + 1 / ratio)))
    assert abs(d_area - report["d_area"]) <= 1e-9 * d_area, (d_area, report["d_area"])
    assert abs(float(np.abs(np.log(ratio)).max()) - report["log_area_max_abs"]) <= 1e-6
    assert report["valid"] and report["inverted_faces"] == 0 and report["overlapping_chart_pairs"] == 0
    assert abs(uv_area.sum() - report["packing_efficiency"]) <= 1e-9
    return d_area


def test_sphere_not_converged_warning_names_the_missed_goal():
    V, F = read_off(mesh_path("sphere.off"))
    with pytest.warns(UserWarning, match=r"mesh: did not converge: not converged: stopped \(plateau\) after .* "
                                         r"short of mean \|log area ratio\| [0-9.e-]+ > 1e-09") as caught:
        _, report = dlf.sphere(V, F, log_area_tolerance=1e-9, max_iterations=20)
    assert report["status"] == "not_converged" and report["message"] in str(caught[0].message)


def test_atlas_not_converged_warning_names_the_missed_goal(monkeypatch):
    V, F = read_off(mesh_path("knot1.off"))
    uv, report = dlf.atlas(V, F)
    assert report["status"] == "ok" and report["message"] == "Success"
    # A report as discrete_lie_flow_atlas() writes it when a chart stops short.
    short = dict(report, status="not_converged", converged=False, unconverged_charts=1,
                 message="not converged: 1 of 3 charts stopped short of their goals (a valid atlas still); the first, "
                         "chart 2 (40 faces): not converged: stopped (iteration_cap) after 150 iterations short of "
                         "d_area 2.0042 > 2.001; the map is fold-free on the input's triangles, d_area 2.0042")
    monkeypatch.setattr(dlf._core, "atlas", lambda *args, **kwargs: (uv, short))
    with pytest.warns(UserWarning, match=r"mesh: did not converge: not converged: 1 of 3 charts .* short of "
                                         r"d_area 2\.0042 > 2\.001"):
        dlf.atlas(V, F)
    with pytest.raises(dlf.FlowError, match=r"short of d_area 2\.0042 > 2\.001"):
        dlf.atlas(V, F, strict=True)


def test_atlas_of_a_closed_mesh():
    V, F = read_off(mesh_path("knot1.off"))  # closed, genus 1
    uv, report = dlf.atlas(V, F)
    assert report["closed_components"] == 1 and report["max_genus"] == 1 and report["components"] == 1
    assert report["charts"] >= 1 and report["seam_length"] > 0
    d_area = atlas_check(V, F, uv, report)
    assert d_area <= 2.02


def test_atlas_of_two_components(nefertiti):
    V1, F1 = nefertiti
    V2, F2 = read_off(mesh_path("sphere.off"))
    V = np.vstack([V1, V2 + [10.0, 0.0, 0.0]])
    F = np.vstack([F1, F2 + len(V1)])
    uv, report = dlf.atlas(V, F)
    assert report["components"] == 2 and report["closed_components"] == 1
    atlas_check(V, F, uv, report)
    # Each component gets its share of the square: the uv areas of its faces over its 3D area share.
    a, b, c = uv[:, 0], uv[:, 1], uv[:, 2]
    uv_area = 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))
    p, q, r = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(q - p, r - p), axis=1)
    first = np.arange(len(F)) < len(F1)
    assert abs(uv_area[first].sum() / uv_area.sum() - area[first].sum() / area.sum()) < 0.02


def test_atlas_bad_input():
    V, F = tetrahedron()
    with pytest.raises(ValueError, match="F: face 1 makes the mesh non-manifold or inconsistently oriented"):
        dlf.atlas(V, [[0, 1, 2], [0, 1, 3]])
    with pytest.raises(ValueError, match=r"density: 2 values; expected 4 \(one per face\)"):
        dlf.atlas(V, F, density=[1, 2])
