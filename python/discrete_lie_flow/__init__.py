# Copyright (c) 2026 The Discrete Lie Flow authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Discrete Lie Flow: area-preserving and measure-controlled parameterization
of triangle meshes, from NumPy arrays.

    import discrete_lie_flow as dlf
    V, F = dlf.read_mesh("face.off")      # any format CGAL reads: OFF, OBJ, PLY, STL
    uv, report = dlf.disk(V, F)           # a disk onto the unit disk
    metrics = dlf.score(V, F, uv)         # distortion of any per-vertex map
    points, report = dlf.sphere(V, F)     # a closed genus-0 mesh onto the unit sphere
    corners, report = dlf.atlas(V, F)     # any triangle mesh to an atlas in the unit square
    dlf.info(V, F)                        # topology, degeneracies, what the mesh fits

``V`` is an (n, 3) array of vertex positions and ``F`` an (m, 3) array of
vertex indices (any real, resp. integer, dtype and any strides; the arrays
are read, never modified). The functions run the same code as the ``dlf``
command-line tool: the maps are those of ``dlf disk -o`` / ``dlf sphere -o``
bit for bit, and the report dicts have the fields of ``--report``
(doc/design.md). Keyword options are the tool's options (``tolerance`` is
``--tolerance``); error messages name the keywords.

Errors: ``TypeError`` for an argument of the wrong type (None, a string or
a list of strings where an array is expected, a dtype that is not real
numbers, resp. integers); ``ValueError`` for wrong shapes and values and
for input the tool refuses (a mesh that is not a disk, a bad option);
:class:`FlowError` when the flow fails on a valid input. A map that is
returned but falls short -- the flow stopped before its targets
(``report["status"] == "not_converged"``) or, in the paper and literal
modes, input triangles left inverted (``report["caller_inverted_faces"]``)
-- issues a ``UserWarning`` that says so in the report's words, or, with
``strict=True``, raises :class:`FlowError` with the report. The flow runs
without the GIL; a ``callback`` is called after
every iteration with a dict (iteration, step, critical_step, limiting_face,
d_area, residual, backtracks, flips, seconds) and stops the flow by
returning ``False`` (the map so far is returned, its report says
``stop_reason == "interrupted"``, and no warning is issued: the caller
stopped it); an exception raised by the callback stops the flow and
propagates.
"""

import os as _os
import typing as _t
import warnings as _warnings

from . import _core
from ._core import FlowError, __version__

__all__ = ["disk", "sphere", "atlas", "score", "info", "read_mesh", "FlowError", "__version__"]

_Callback = _t.Callable[[_t.Dict[str, _t.Any]], _t.Optional[bool]]
_Region = _t.Dict[str, _t.Any]


def __dir__() -> _t.List[str]:
    return sorted(__all__)


def _shortfall(report: _t.Dict[str, _t.Any]) -> _t.Optional[str]:
    """What a returned map falls short of, in the report's words (None: nothing)."""
    if report.get("stop_reason") == "interrupted":
        return None  # the caller's callback stopped it
    words = []
    message = str(report.get("message", ""))
    if report.get("status") == "not_converged":
        words.append("did not converge: " + message)
    inverted = report.get("caller_inverted_faces") or 0
    if inverted and not (words and "inverted" in message):  # said once
        words.append(f"{inverted} of the input's triangles {'is' if inverted == 1 else 'are'} inverted (only the "
                     f"flowing triangulation is certified in mode {report.get('mode')!r}; the certified mode never "
                     f"inverts them)")
    return "; ".join(words) or None


def _checked(result: _t.Tuple[_t.Any, _t.Dict[str, _t.Any]], name: str, strict: bool,
             message: _t.Optional[str] = None):
    """``result``, once said how its run fell short (``message``, "" for
    not at all; None: what ``_shortfall`` finds in its report): a
    UserWarning at the line that called the public function or, ``strict``,
    FlowError with the report."""
    report = result[1]
    if message is None:
        what = _shortfall(report)
        message = f"{name}: {what}" if what else None
    if message:
        if strict:
            error = FlowError(message)
            error.report = report
            raise error
        _warnings.warn(message, UserWarning, stacklevel=3)
    return result


def disk(V, F, *, mode: str = "certified", border: _t.Optional[str] = None, init: str = "tutte", density=None,
         regions: _t.Optional[_t.Sequence[_Region]] = None, band: _t.Optional[float] = None, seam=None,
         tolerance: _t.Optional[float] = None, init_uv=None, max_iterations: _t.Optional[int] = None,
         mu: _t.Optional[float] = None, share_tolerance: _t.Optional[float] = None,
         fixed_step: _t.Optional[float] = None, threshold: _t.Optional[float] = None, outer_loop: int = 0,
         literal_targets: bool = False, delaunay_flips: bool = True, history: bool = False,
         callback: _t.Optional[_Callback] = None, name: str = "mesh",
         strict: bool = False) -> _t.Tuple[_t.Any, _t.Dict[str, _t.Any]]:
    """Maps a disk-topology mesh (or a disk with holes, which float) onto the
    plane, area-preserving; returns ``(uv, report)``.

    uv: (n, 2) float64 array, the map of vertex i in row i; with ``seam``,
    (m, 3, 2): the uv of each corner of each face (a vertex on a seam has
    one uv per side). In the certified mode (the default) every triangle is
    positively oriented (exact predicate); in the paper and literal modes
    only the flowing triangulation is certified and
    ``report["caller_inverted_faces"]`` counts the input's triangles it
    inverts (a ``UserWarning`` then). report: the dict of
    ``dlf disk --report``.

    mode: "certified" (never folds the input triangles), "paper" (the
    paper's flow with edge flips, stabilised; disks without holes only) or
    "literal" (the paper's Algorithm 1 as printed, doc/paper_literal.md).
    border: "circle" or "square" (with init tutte, mvc, dcp; default circle),
    or "free" (the only choice, and the default, for lscm and arap).
    init: the initial map, "tutte", "mvc", "dcp", "lscm" or "arap".
    density: measure control, one value > 0 per face or per vertex; each
    face then gets density times its share of the area (default tolerance
    5e-4 then, as with ``--density``).
    regions: measure control by regions of interest (as ``--roi`` /
    ``--roi-ball`` with ``--factor``): a list of dicts, each with
    ``"faces"`` (face indices) or ``"ball"`` ((x, y, z, radius): the faces
    whose centroid lies in it), ``"factor"`` (its density: 4 gives it 4
    times its share of the domain) and optionally ``"name"``; overlapping
    regions multiply; ``report["regions"]`` gives each one's prescribed and
    achieved share. band: the width (3D length) of a transition from each
    region's factor to 1 (``--band``).
    seam: an (k, 2) integer array of interior edges (vertex pairs) to cut
    the mesh open along (as ``--seam``; CGAL's ``Seam_mesh``); the cut
    surface must be a disk.
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
    strict: raise :class:`FlowError` (with ``.report``) instead of the
    ``UserWarning`` when the map falls short.

    Raises TypeError for arguments of the wrong type, ValueError for
    unsuitable input or options, FlowError (with the report as
    ``.report``) when the flow fails.
    """
    return _checked(_core.disk(V, F, mode=mode, border=border, init=init, density=density, regions=regions, band=band,
                               seam=seam, tolerance=tolerance, init_uv=init_uv, max_iterations=max_iterations, mu=mu,
                               share_tolerance=share_tolerance, fixed_step=fixed_step, threshold=threshold,
                               outer_loop=outer_loop, literal_targets=literal_targets, delaunay_flips=delaunay_flips,
                               history=history, callback=callback, name=name), name, strict)


def sphere(V, F, *, mode: str = "certified", density=None, regions: _t.Optional[_t.Sequence[_Region]] = None,
           band: _t.Optional[float] = None, tolerance: _t.Optional[float] = None,
           log_area_tolerance: _t.Optional[float] = None, max_iterations: _t.Optional[int] = None,
           mu: _t.Optional[float] = None, share_tolerance: _t.Optional[float] = None,
           fixed_step: _t.Optional[float] = None, threshold: _t.Optional[float] = None, literal_targets: bool = False,
           delaunay_flips: bool = True, history: bool = False, start: str = "tutte", init_map=None,
           callback: _t.Optional[_Callback] = None, name: str = "mesh",
           strict: bool = False) -> _t.Tuple[_t.Any, _t.Dict[str, _t.Any]]:
    """Maps a closed genus-0 mesh onto the unit sphere, area-preserving;
    returns ``(points, report)``.

    points: (n, 3) float64 array on the unit sphere; in the certified mode
    (the default) every triangle positively oriented (exact predicate); in
    the paper and literal modes only the flowing triangulation is certified
    and ``report["caller_inverted_faces"]`` counts the input's triangles it
    inverts (a ``UserWarning`` then, or FlowError with ``strict=True``).
    report: the dict of ``dlf sphere --report``. Options as for
    :func:`disk` (density, regions and band included; no seam), plus
    log_area_tolerance (``--log-area-tolerance``), start ("tutte",
    "conformal" or "mean-value", ``--start``) and init_map (an (n, 3)
    array: the caller's start, ``--init-map``; scaled onto the sphere,
    refused if a face folds).

    Raises TypeError, ValueError for unsuitable input or options (e.g. not
    genus 0), FlowError (with ``.report``) when the flow fails.
    """
    return _checked(_core.sphere(V, F, mode=mode, density=density, regions=regions, band=band, tolerance=tolerance,
                                 log_area_tolerance=log_area_tolerance, max_iterations=max_iterations, mu=mu,
                                 share_tolerance=share_tolerance, fixed_step=fixed_step, threshold=threshold,
                                 literal_targets=literal_targets, delaunay_flips=delaunay_flips, history=history,
                                 start=start, init_map=init_map, callback=callback, name=name), name, strict)


def atlas(V, F, *, border: str = "square", tips: _t.Optional[int] = None, gutter: _t.Optional[float] = None,
          stretch: bool = True, density=None, name: str = "mesh",
          strict: bool = False) -> _t.Tuple[_t.Any, _t.Dict[str, _t.Any]]:
    """Any triangle mesh (several components, any genus, holes) to an
    area-preserving atlas in the unit square; returns ``(uv, report)``.

    uv: (m, 3, 2) float64 array, the uv of corner c of face f in
    ``uv[f, c]`` (the corner at vertex ``F[f, c]``): a vertex on a seam has
    one uv per chart side. Every face's uv area is its share of the surface
    area (times the density, if given); charts do not overlap and no face
    is inverted (both checked exactly: ``report["valid"]``). report: the
    fields of ``dlf atlas --report`` (charts, seam_length,
    packing_efficiency, d_area, inverted_faces, overlapping_chart_pairs,
    chart_list, ...) but the file's repairs; ``status`` is "ok" or
    "not_converged" (a chart's flow stopped short: a ``UserWarning``, or
    FlowError with ``strict=True``).

    border: each chart's border, "square" (fills its cell; the default) or
    "circle". tips: how many tips a closed component's seam runs through
    (default 2). gutter: space around each chart, in uv units (default
    1/1024). stretch: fill treemap cells by area-preserving stretches
    (True) or keep the charts' shapes (shelf packing). density: one value >
    0 per face. The mesh must be manifold and consistently oriented (the
    ``dlf atlas`` tool repairs files that are not); isolated vertices are
    ignored and counted.

    Raises TypeError, ValueError for unsuitable input, FlowError when no
    valid atlas is made.
    """
    uv, report = _core.atlas(V, F, border=border, tips=tips, gutter=gutter, stretch=stretch, density=density,
                             name=name)
    message = f"{name}: did not converge: {report['message']}" if not report["converged"] else ""
    return _checked((uv, report), name, strict, message)


def score(V, F, uv, *, density=None) -> _t.Dict[str, _t.Any]:
    """The distortion metrics of a map ``uv`` ((n, 2), one row per vertex)
    of the mesh (V, F), as ``dlf score`` reports them (doc/design.md,
    "Metrics"): d_area, arap, symmetric_dirichlet, log_area_ratio,
    inverted_faces, degenerate_faces, min_angle_degrees,
    faces_below_1_degree; density-weighted when ``density`` is given.
    """
    return _core.score(V, F, uv, density=density)


def info(V, F, *, name: str = "mesh") -> _t.Dict[str, _t.Any]:
    """What ``dlf info --report`` says of a mesh: counts, border loops,
    genus, degeneracies, and which command it fits ("fits": "dlf disk",
    "dlf sphere" or "none", with "reason"). Describes any mesh, even one the
    flows refuse (non-finite coordinates, non-manifold faces, ...)."""
    return _core.info(V, F, name=name)


def read_mesh(path: _t.Union[str, "_os.PathLike[str]"]) -> _t.Tuple[_t.Any, _t.Any]:
    """Reads a triangle mesh file (any format CGAL reads: OFF, OBJ, PLY,
    STL) with the ``dlf`` tool's reader; returns ``(V, F)``, an (n, 3)
    float64 array of positions and an (m, 3) int64 array of vertex indices,
    in the file's order. Raises TypeError for a path that is no str or
    os.PathLike, FileNotFoundError for a missing file, ValueError for a file
    the tool refuses (unreadable, polygons, non-manifold, unreferenced
    vertices: the same checks as ``dlf disk``)."""
    if not isinstance(path, (str, _os.PathLike)):
        raise TypeError(f"path must be a str or os.PathLike, got {type(path).__name__}")
    path = _os.fspath(path)
    if not isinstance(path, str):
        raise TypeError(f"path must name a file as str, got {type(path).__name__}")
    if not _os.path.isfile(path):
        raise FileNotFoundError(2, "No such file", path)
    return _core.read_mesh(path)
