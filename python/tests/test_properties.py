# Copyright (c) 2026 The Discrete Lie Flow authors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# A property test of every entry point of the Python module: thousands of
# malformed calls (arrays of wrong dtypes, shapes, strides and values,
# keywords of wrong types and out of range), drawn from a fixed seed so that
# every machine makes the same calls. Whatever the input, a call either
# returns a finite result of the documented shape or raises ValueError or
# TypeError with a message, or FlowError with the report (a valid input on
# which the flow failed, doc/python.md); never another exception, a crash
# or a hang.
# DLF_PROPERTY_CALLS sets the number of calls per entry point (default 1000;
# the longer local run is reported in doc/robustness.md).

import os
import warnings

import numpy as np
import pytest

import discrete_lie_flow as dlf

CALLS = int(os.environ.get("DLF_PROPERTY_CALLS", "1000"))


def grid_disk(n):
    """An n x n grid of the unit square, two triangles per cell."""
    xs = np.linspace(0, 1, n + 1)
    V = np.array([[x, y, 0.1 * x * y] for y in xs for x in xs])
    F = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            F += [[a, a + 1, a + n + 2], [a, a + n + 2, a + n + 1]]
    return V, np.array(F, dtype=np.int64)


def octahedron():
    V = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
    F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    return V, F


BASES = [grid_disk(3), grid_disk(5), octahedron()]


def odd_value(rng):
    """A value of a type or range no keyword expects."""
    choices = [None, -1, 0, 1, 3, 2.5, -0.5, 1e300, float("nan"), float("inf"), -float("inf"), True,
               "x", "", "circle", b"\x00", [1, 2], (0.1,), {"a": 1}, 1 + 2j, 10 ** 30, np.float32(0.25),
               np.int64(-7), np.array([1.0, 2.0]), object()]
    return choices[rng.integers(len(choices))]


def mutate_vertices(rng, V):
    k = rng.integers(16)
    if k == 0: return V.astype(str)
    if k == 1: return V.astype(complex)
    if k == 2: return V > 0.5
    if k == 3: return V[:, :2]
    if k == 4: return V.reshape(-1)
    if k == 5: return V[:, :, None]
    if k == 6: return np.zeros((0, 3))
    if k == 7:
        W = V.copy()
        W[rng.integers(len(W)), rng.integers(W.shape[1])] = [np.nan, np.inf, -np.inf][rng.integers(3)]
        return W
    if k == 8: return V * 1e300
    if k == 9: return np.asfortranarray(V)
    if k == 10: return np.repeat(V, 2, axis=0)[::2]           # strided, the same values
    if k == 11: return [list(r) for r in V][:-1] + [[0.0, 1.0]]  # ragged list
    if k == 12: return V.astype(np.float32)
    if k == 13: return np.zeros_like(V)                        # every face degenerate
    if k == 14: return odd_value(rng)
    return V


def mutate_faces(rng, F, n):
    k = rng.integers(16)
    if k == 0:
        G = F.copy(); G[rng.integers(len(G)), rng.integers(3)] = -1 - int(rng.integers(3)); return G
    if k == 1:
        G = F.copy(); G[rng.integers(len(G)), rng.integers(3)] = n + int(rng.integers(3)); return G
    if k == 2: return F.astype(float) + 0.5
    if k == 3: return F.astype(float)
    if k == 4: return F[:, :2]
    if k == 5: return np.hstack([F, F[:, :1]])
    if k == 6:
        G = F.copy(); G[0, 1] = G[0, 0]; return G
    if k == 7: return F[:0]
    if k == 8: return F.astype(np.uint64) + np.uint64(2 ** 63)
    if k == 9: return F[:, ::-1].copy()                        # every face reversed
    if k == 10: return np.vstack([F, F[:1]])                   # a face twice
    if k == 11: return F[: max(1, len(F) // 2)]                # unreferenced vertices
    if k == 12: return F.astype(np.int8) if n < 100 else F
    if k == 13: return F.astype(str)
    if k == 14: return odd_value(rng)
    return F


KEYWORDS = {
    dlf.disk: ["mode", "border", "init", "density", "regions", "band", "seam", "tolerance", "init_uv",
               "max_iterations", "mu", "share_tolerance", "fixed_step", "threshold", "outer_loop",
               "literal_targets", "delaunay_flips", "history", "callback", "name"],
    dlf.sphere: ["mode", "density", "regions", "band", "tolerance", "log_area_tolerance", "max_iterations",
                 "mu", "share_tolerance", "fixed_step", "threshold", "literal_targets", "delaunay_flips",
                 "history", "start", "init_map", "callback", "name"],
    dlf.atlas: ["border", "tips", "gutter", "stretch", "density", "name"],
    dlf.info: ["name"],
    dlf.score: ["density"],
}


def keyword_value(rng, key, V, F):
    """Mostly plausible values of the keyword's kind, sometimes anything."""
    if rng.random() < 0.35:
        return odd_value(rng)
    n, m = (len(V), len(F)) if hasattr(V, "__len__") and hasattr(F, "__len__") else (3, 1)
    if key in ("density",):
        d = rng.uniform(0.5, 2, max(0, m + int(rng.integers(-1, 2))))
        if len(d) and rng.random() < 0.3: d[0] = [0.0, -1.0, np.nan][rng.integers(3)]
        return d
    if key in ("init_uv", "init_map"):
        return rng.normal(size=(max(0, n + int(rng.integers(-1, 2))), 2 if key == "init_uv" else 3))
    if key == "seam":
        return rng.integers(-1, n + 1, size=(int(rng.integers(0, 4)), 2))
    if key == "regions":
        return [{"faces": list(rng.integers(-1, m + 1, size=3)), "factor": float(rng.uniform(-1, 4))}]
    if key == "callback":
        # (A callback's own exception is the caller's and passes through.)
        return [lambda it: None, lambda it: True, lambda: None][rng.integers(3)]
    if key in ("mode", "border", "init", "start"):
        return ["certified", "paper", "literal", "circle", "square", "free", "tutte", "lscm",
                "conformal", "bogus"][rng.integers(10)]
    if key in ("max_iterations", "outer_loop", "tips"):
        return int(rng.integers(-2, 6))
    if key in ("literal_targets", "delaunay_flips", "history", "stretch"):
        return bool(rng.integers(2))
    if key == "name":
        return "mesh\x00name" if rng.random() < 0.2 else "m"
    return float(rng.choice([-1.0, 0.0, 1e-12, 1e-3, 0.3, 0.9, 1.0, 2.0, 50.0]))


def check_result(fn, result, V, F, kwargs):
    if fn in (dlf.info, dlf.score):
        assert isinstance(result, dict)
        return
    out, report = result
    assert isinstance(report, dict) and isinstance(out, np.ndarray)
    if fn is dlf.atlas or (fn is dlf.disk and kwargs.get("seam") is not None):
        assert out.shape == (len(F), 3, 2)   # per corner
    else:
        assert out.shape == (len(V), 2 if fn is dlf.disk else 3)
    assert np.isfinite(out).all()


@pytest.mark.parametrize("fn", [dlf.disk, dlf.sphere, dlf.atlas, dlf.info, dlf.score],
                         ids=["disk", "sphere", "atlas", "info", "score"])
def test_malformed_calls_raise_only_value_or_type_error(fn):
    rng = np.random.default_rng(20261128 + list(KEYWORDS).index(fn))
    outcomes = {"returned": 0, "ValueError": 0, "TypeError": 0, "FlowError": 0}
    for call in range(CALLS):
        V0, F0 = BASES[rng.integers(len(BASES))]
        V = mutate_vertices(rng, V0) if rng.random() < 0.5 else V0.copy()
        F = mutate_faces(rng, F0, len(V0)) if rng.random() < 0.5 else F0.copy()
        args = [V, F]
        if fn is dlf.score:
            uv = rng.normal(size=(len(V0), 2))
            if rng.random() < 0.4: uv = mutate_vertices(rng, uv)
            args.append(uv)
        keys = KEYWORDS[fn]
        kwargs = {k: keyword_value(rng, k, V, F) for k in rng.choice(keys, size=int(rng.integers(0, min(4, len(keys) + 1))), replace=False)}
        if fn in (dlf.disk, dlf.sphere) and "max_iterations" not in kwargs and rng.random() < 0.8:
            kwargs["max_iterations"] = 30   # keeps a call short; the default is tried too
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                result = fn(*args, **kwargs)
        except (ValueError, TypeError) as e:
            assert str(e), "%s: %s with an empty message" % (what(call, fn, args, kwargs), type(e).__name__)
            outcomes["ValueError" if isinstance(e, ValueError) else "TypeError"] += 1
            continue
        except dlf.FlowError as e:
            assert str(e) and (e.report is None or isinstance(e.report, dict)), \
                "%s: FlowError without a message" % what(call, fn, args, kwargs)
            outcomes["FlowError"] += 1
            continue
        except Exception as e:  # noqa: BLE001 - the property under test
            pytest.fail("%s raised %s: %s" % (what(call, fn, args, kwargs), type(e).__name__, e))
        check_result(fn, result, V, F, kwargs)
        outcomes["returned"] += 1
    # The draw reaches every outcome, so that a regression that turns every
    # call into an error (or none) is seen too.
    print(fn.__name__, outcomes)
    assert outcomes["returned"] > 0 and outcomes["ValueError"] > 0 and outcomes["TypeError"] > 0, outcomes


def what(call, fn, args, kwargs):
    return "call %d: %s(%s, keywords %s)" % (call, fn.__name__, ", ".join(describe(a) for a in args),
                                             {k: describe(v) for k, v in kwargs.items()})


def describe(a):
    if isinstance(a, np.ndarray):
        return "array(%s, %s)" % (a.dtype, a.shape)
    text = repr(a)
    return text if len(text) < 60 else type(a).__name__
