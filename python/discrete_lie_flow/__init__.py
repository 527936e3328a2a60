# Copyright (c) 2026 The Discrete Lie Flow authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Discrete Lie Flow: area-preserving and measure-controlled parameterization
of triangle meshes, from NumPy arrays.

    import discrete_lie_flow as dlf
    uv, report = dlf.disk(V, F)           # a disk onto the unit disk
    points, report = dlf.sphere(V, F)     # a closed genus-0 mesh onto the unit sphere
    metrics = dlf.score(V, F, uv)         # distortion of any map
    dlf.info(V, F)                        # topology, degeneracies, what the mesh fits

``V`` is an (n, 3) array of vertex positions and ``F`` an (m, 3) array of
vertex indices (any real, resp. integer, dtype and any strides; the arrays
are read, never modified). The functions run the same code as the ``dlf``
command-line tool: the maps are those of ``dlf disk -o`` / ``dlf sphere -o``
bit for bit, and the report dicts have the fields of ``--report``
(doc/design.md). Keyword options are the tool's options (``tolerance`` is
``--tolerance``), and error messages name them as the tool does.

Errors: ``ValueError`` for input the tool refuses (bad arrays, a mesh that
is not a disk, a bad option), :class:`FlowError` when the flow fails on a
valid input. The flow runs without the GIL; a ``callback`` is called after
every iteration with a dict (iteration, step, critical_step, limiting_face,
d_area, residual, backtracks, flips, seconds) and stops the flow by
returning ``False`` (the map so far is returned, its report says
``stop_reason == "interrupted"``); an exception raised by the callback
stops the flow and propagates.
"""

from typing import Any, Callable, Dict, Optional, Tuple

from . import _core
from ._core import FlowError, __version__

__all__ = ["disk", "sphere", "score", "info", "FlowError", "__version__"]


def disk(V, F, *, mode: str = "certified", border: Optional[str] = None, init: str = "tutte", density=None,
         tolerance: Optional[float] = None, init_uv=None, max_iterations: Optional[int] = None,
         mu: Optional[float] = None, share_tolerance: Optional[float] = None, fixed_step: Optional[float] = None,
         threshold: Optional[float] = None, outer_loop: int = 0, literal_targets: bool = False,
         delaunay_flips: bool = True, history: bool = False,
         callback: Optional[Callable[[Dict[str, Any]], Optional[bool]]] = None,
         name: str = "mesh") -> Tuple[Any, Dict[str, Any]]:
    """Maps a disk-topology mesh (or a disk with holes, which float) onto the
    plane, area-preserving; returns ``(uv, report)``.

    uv: (n, 2) float64 array, the map of vertex i in row i; in the
    certified mode (the default) every triangle positively oriented (exact
    predicate); in the paper and literal modes only the flowing
    triangulation is certified and ``report["caller_inverted_faces"]`` counts
    the input's triangles it inverts. report: the dict of ``dlf disk --report``.

    mode: "certified" (never folds the input triangles), "paper" (the
    paper's flow with edge flips, stabilised; disks without holes only) or
    "literal" (the paper's Algorithm 1 as printed, doc/paper_literal.md).
    border: "circle" or "square" (with init tutte, mvc, dcp; default circle),
    or "free" (the only choice, and the default, for lscm and arap).
    init: the initial map, "tutte", "mvc", "dcp", "lscm" or "arap".
    density: measure control, one value > 0 per face or per vertex; each
    face then gets density times its share of the area (default tolerance
    5e-4 then, as with ``--density``).
    tolerance: stop when D_area - 2 <= tolerance (default 1e-2).
    init_uv: the caller's own initial map instead of ``init`` (as
    ``--init-uv``): an (n, 2) array, one row per vertex, every triangle
    positively oriented (refused otherwise); its border is kept, the
    vertices slide along it (``border="free"``, the only choice).
    fixed_step: a fixed step instead of the adaptive one (``--fixed-step``).
    threshold: the literal mode's stop, ||h_M - h_Omega||^2 < threshold
    (``--threshold``).
    max_iterations, mu, share_tolerance, outer_loop, literal_targets,
    delaunay_flips: as the tool's options of the same names.
    history: add the per-iteration history to the report.
    callback: called after every iteration, see the module's help.
    name: the report's "input", and the prefix of messages.

    Raises ValueError for unsuitable input or options, FlowError (with the
    report as ``.report``) when the flow fails.
    """
    return _core.disk(V, F, mode=mode, border=border, init=init, density=density, tolerance=tolerance,
                      init_uv=init_uv, max_iterations=max_iterations, mu=mu, share_tolerance=share_tolerance,
                      fixed_step=fixed_step, threshold=threshold, outer_loop=outer_loop,
                      literal_targets=literal_targets, delaunay_flips=delaunay_flips, history=history,
                      callback=callback, name=name)


def sphere(V, F, *, mode: str = "certified", density=None, tolerance: Optional[float] = None,
           log_area_tolerance: Optional[float] = None, max_iterations: Optional[int] = None,
           mu: Optional[float] = None, share_tolerance: Optional[float] = None, fixed_step: Optional[float] = None,
           threshold: Optional[float] = None, literal_targets: bool = False,
           delaunay_flips: bool = True, history: bool = False, start: str = "tutte", init_map=None,
           callback: Optional[Callable[[Dict[str, Any]], Optional[bool]]] = None,
           name: str = "mesh") -> Tuple[Any, Dict[str, Any]]:
    """Maps a closed genus-0 mesh onto the unit sphere, area-preserving;
    returns ``(points, report)``.

    points: (n, 3) float64 array on the unit sphere; in the certified mode
    (the default) every triangle positively oriented (exact predicate); in
    the paper and literal modes only the flowing triangulation is certified
    and ``report["caller_inverted_faces"]`` counts the input's triangles it
    inverts. report: the dict of
    ``dlf sphere --report``. Options as for :func:`disk`, plus
    log_area_tolerance (``--log-area-tolerance``), start ("tutte" or
    "conformal", ``--start``) and init_map (an (n, 3) array: the caller's
    start, ``--init-map``; scaled onto the sphere, refused if a face folds).

    Raises ValueError for unsuitable input or options (e.g. not genus 0),
    FlowError (with ``.report``) when the flow fails.
    """
    return _core.sphere(V, F, mode=mode, density=density, tolerance=tolerance,
                        log_area_tolerance=log_area_tolerance, max_iterations=max_iterations, mu=mu,
                        share_tolerance=share_tolerance, fixed_step=fixed_step, threshold=threshold,
                        literal_targets=literal_targets,
                        delaunay_flips=delaunay_flips, history=history, start=start, init_map=init_map,
                        callback=callback, name=name)


def score(V, F, uv, *, density=None) -> Dict[str, Any]:
    """The distortion metrics of a map ``uv`` ((n, 2), one row per vertex)
    of the mesh (V, F), as ``dlf score`` reports them (doc/design.md,
    "Metrics"): d_area, arap, symmetric_dirichlet, log_area_ratio,
    inverted_faces, degenerate_faces, min_angle_degrees,
    faces_below_1_degree; density-weighted when ``density`` is given.
    """
    return _core.score(V, F, uv, density=density)


def info(V, F, *, name: str = "mesh") -> Dict[str, Any]:
    """What ``dlf info --report`` says of a mesh: counts, border loops,
    genus, degeneracies, and which command it fits ("fits": "dlf disk",
    "dlf sphere" or "none", with "reason"). Describes any mesh, even one the
    flows refuse (non-finite coordinates, non-manifold faces, ...)."""
    return _core.info(V, F, name=name)
