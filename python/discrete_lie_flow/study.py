# Copyright (c) 2026 The Discrete Lie Flow authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""``dlf-study``: run configurations of the ``dlf`` tool over a corpus of
meshes on dask.distributed and keep the results in SQLite.

Every (mesh, configuration) is one dask task that runs ``dlf`` in a child
process with a timeout, so that a crash or a hang of one run costs that run
only. The client writes a row per finished task, in its own transaction, to
the table ``runs``, whose primary key is (mesh, config): a study that is
interrupted (Ctrl-C, a killed worker, a lost client) and run again skips the
rows it has and runs the others, so that no row is lost or written twice.

Besides the ``dlf`` tool, a study can run an external runner (``--runner``),
one case per process, for methods that are not commands of the tool
(robustness studies of the library API and of CGAL's parameterizers:
benchmark/robustness.sh), and can check every map the tool writes
(``--check-outputs``).

See doc/python.md ("Corpus studies") for the commands and the columns.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import shutil
import signal
import socket
import sqlite3
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Dict, Iterable, List, Optional, Sequence, Tuple

MESH_SUFFIXES = (".off", ".obj", ".ply", ".stl", ".ts", ".vtp")
STDERR_TAIL = 2000  # characters of stderr kept per run


@dataclass(frozen=True)
class Config:
    """A named configuration: the ``dlf`` command and its options."""

    name: str
    command: str  # "disk" or "sphere"
    options: Tuple[str, ...]
    description: str


CONFIGS: Dict[str, Config] = {
    c.name: c
    for c in (
        Config("disk-certified", "disk", ("--mode", "certified"), "dlf disk (certified mode, Tutte on a circle)"),
        Config("disk-paper", "disk", ("--mode", "paper"), "dlf disk --mode paper"),
        Config("disk-square", "disk", ("--border", "square"), "dlf disk --border square"),
        Config("disk-free", "disk", ("--init", "arap"), "dlf disk --init arap (free border)"),
        Config("sphere", "sphere", ("--mode", "certified"), "dlf sphere (certified mode)"),
        Config("sphere-paper", "sphere", ("--mode", "paper"), "dlf sphere --mode paper"),
    )
}
DEFAULT_CONFIGS = ("disk-certified", "disk-paper", "sphere", "sphere-paper")

# Statuses of a row. ok and not_converged are valid maps (exit 0 and 3);
# input_error (exit 1) and flow_error (exit 2) are refusals the tool words
# itself; crash, timeout and error (any other exit) are the tool's failures.
STATUSES = ("ok", "not_converged", "input_error", "flow_error", "crash", "timeout", "error", "not_applicable")

SCHEMA = """
CREATE TABLE IF NOT EXISTS runs (
  mesh           TEXT NOT NULL,     -- the mesh file, relative to its corpus folder
  config         TEXT NOT NULL,     -- a name of CONFIGS
  status         TEXT NOT NULL,     -- one of STATUSES
  stop_reason    TEXT,              -- the report's stop_reason (converged, plateau, ...)
  d_area         REAL,              -- the report's final d_area (optimum 2)
  inverted_faces INTEGER,           -- the report's final inverted_faces
  seconds        REAL,              -- wall time of the dlf process (null: not run)
  vertices       INTEGER,
  faces          INTEGER,
  iterations     INTEGER,
  fits           TEXT,              -- what `dlf info` says the mesh fits: dlf disk, dlf sphere, none
  error          TEXT,              -- the report's status name, or the tool's error line
  exit_code      INTEGER,           -- of dlf (null: killed by a signal or not run)
  exit_signal    INTEGER,           -- the signal that ended dlf (a crash, or SIGKILL at the timeout)
  stderr_tail    TEXT,              -- the end of dlf's stderr
  report         TEXT,              -- the JSON report, without its history
  command        TEXT,              -- the command line that was run
  worker         TEXT,              -- host and process of the dask worker
  finished_at    TEXT NOT NULL,     -- UTC, ISO 8601
  checked_inverted   INTEGER,       -- faces of the written map that are not positive (exact predicate; runner: against the majority)
  checked_degenerate INTEGER,       -- faces of the written map with orientation zero
  nonfinite      INTEGER,           -- 1: a NaN or infinite value in the written map
  stray_output   INTEGER,           -- 1: a map file left by a run that failed
  exit_mismatch  INTEGER,           -- 1: the exit code disagrees with the report's status
  rejected_by_exact_check INTEGER,  -- the report's trial steps refused by the exact predicate alone
  violation      TEXT,              -- a broken promise, when checked (--check-outputs, runners): see VIOLATIONS
  map_d_area     REAL,              -- --check-outputs, disk maps: d_area of the written uv against the 3D triangles
  PRIMARY KEY (mesh, config)
)
"""

# Columns added after the first version of the table, added to an older
# database when it is opened (a resumed study keeps its rows).
ADDED_COLUMNS = (
    ("checked_inverted", "INTEGER"), ("checked_degenerate", "INTEGER"), ("nonfinite", "INTEGER"),
    ("stray_output", "INTEGER"), ("exit_mismatch", "INTEGER"), ("rejected_by_exact_check", "INTEGER"),
    ("violation", "TEXT"), ("map_d_area", "REAL"),
)


# ---------------------------------------------------------------------------
# The task (runs on a dask worker)
# ---------------------------------------------------------------------------


def _child_setup(nbytes: Optional[int]):
    """What the child does before it execs: at most `nbytes` of address
    space (if given), and SIGKILL when the thread that started it dies (its
    worker: a worker that is stopped or killed takes its runs with it, even
    though each run has a process group of its own; Linux only)."""
    # Imported here, in the parent: the child (forked from a threaded
    # worker) must not take the import lock before it execs.
    import ctypes
    import resource

    setrlimit, which = resource.setrlimit, resource.RLIMIT_AS
    try:
        prctl = ctypes.CDLL(None, use_errno=True).prctl
    except (OSError, AttributeError):
        prctl = None
    PR_SET_PDEATHSIG, kill = 1, int(signal.SIGKILL)

    def apply():  # in the child, before exec
        if prctl is not None:
            prctl(PR_SET_PDEATHSIG, kill, 0, 0, 0)
        if nbytes:
            setrlimit(which, (nbytes, nbytes))

    return apply


def _run_tool(argv: Sequence[str], timeout: float, cwd: Optional[str] = None,
              memory_limit: Optional[float] = None) -> Tuple[Optional[int], Optional[int], str, float, bool]:
    """Runs argv in its own process group (in `cwd`, with at most
    `memory_limit` GiB of address space); returns (exit code, signal,
    stderr, seconds, timed out). At the timeout the group is killed."""
    start = time.monotonic()
    setup = _child_setup(int(memory_limit * (1 << 30)) if memory_limit else None)
    with subprocess.Popen(
        list(argv), stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, start_new_session=True,
        cwd=cwd, preexec_fn=setup
    ) as p:
        try:
            _, err = p.communicate(timeout=timeout)
            timed_out = False
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            _, err = p.communicate()
            timed_out = True
    seconds = time.monotonic() - start
    code = p.returncode
    text = err.decode("utf-8", "replace")
    if code is not None and code < 0:
        return None, -code, text, seconds, timed_out
    return code, None, text, seconds, timed_out


_FITS: Dict[Tuple[str, str, int, int], str] = {}  # per worker process: (dlf, mesh, size, mtime) -> fits


def _mesh_fits(dlf: str, mesh: str, timeout: float, scratch: str) -> str:
    """What `dlf info` says the mesh fits; "unknown" when info fails. Kept
    per worker process for the other configurations of the same file."""
    try:
        st = os.stat(mesh)
        key = (dlf, mesh, st.st_size, st.st_mtime_ns)
    except OSError:
        key = None
    if key in _FITS:
        return _FITS[key]
    fits = _run_info(dlf, mesh, timeout, scratch)
    if key is not None:
        _FITS[key] = fits
    return fits


def _run_info(dlf: str, mesh: str, timeout: float, scratch: str) -> str:
    out = os.path.join(scratch, "info.json")
    code, _, _, _, _ = _run_tool([dlf, "info", mesh, "--report", out, "--quiet"], timeout)
    if code != 0:
        return "unknown"
    try:
        with open(out, encoding="utf-8") as f:
            return str(json.load(f).get("fits", "unknown"))
    except (OSError, ValueError):
        return "unknown"


def runner_config(method: str) -> Config:
    """The configuration of a method of an external runner (``--runner``)."""
    return Config(method, "runner", ("--run", method), f"RUNNER --run {method} --case MESH --report OUT.json")


def config_of(name: str, runner: Optional[str] = None) -> Config:
    if name in CONFIGS:
        return CONFIGS[name]
    if runner:
        return runner_config(name)
    raise KeyError(name)


# ---------------------------------------------------------------------------
# Checks of a written map (--check-outputs)
# ---------------------------------------------------------------------------

_EPS = 2.0 ** -53
_ORIENT2D_BOUND = (3 + 16 * _EPS) * _EPS  # Shewchuk's ccwerrboundA
_ORIENT3D_BOUND = (7 + 56 * _EPS) * _EPS  # Shewchuk's o3derrboundA


def _sign(x) -> int:
    return (x > 0) - (x < 0)


def orient2d(a, b, c) -> int:
    """The exact sign of the orientation of the points a, b, c (pairs of
    floats): a floating-point filter, exact rationals when it cannot decide."""
    left = (a[0] - c[0]) * (b[1] - c[1])
    right = (a[1] - c[1]) * (b[0] - c[0])
    det = left - right
    bound = _ORIENT2D_BOUND * (abs(left) + abs(right))
    if math.isfinite(det) and abs(det) > bound and bound > 1e-280:
        return _sign(det)
    a, b, c = ([Fraction(x) for x in p] for p in (a, b, c))
    return _sign((a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]))


def orient3d_origin(a, b, c) -> int:
    """The exact sign of det[a, b, c] (CGAL::orientation(O, a, b, c)): a
    filter, exact rationals when it cannot decide."""
    m1, m2, m3 = b[1] * c[2] - b[2] * c[1], c[1] * a[2] - c[2] * a[1], a[1] * b[2] - a[2] * b[1]
    det = a[0] * m1 + b[0] * m2 + c[0] * m3
    perm = ((abs(b[1] * c[2]) + abs(b[2] * c[1])) * abs(a[0]) + (abs(c[1] * a[2]) + abs(c[2] * a[1])) * abs(b[0])
            + (abs(a[1] * b[2]) + abs(a[2] * b[1])) * abs(c[0]))
    bound = _ORIENT3D_BOUND * perm
    if math.isfinite(det) and abs(det) > bound and bound > 1e-280:
        return _sign(det)
    a, b, c = ([Fraction(x) for x in p] for p in (a, b, c))
    return _sign(a[0] * (b[1] * c[2] - b[2] * c[1]) + b[0] * (c[1] * a[2] - c[2] * a[1])
                 + c[0] * (a[1] * b[2] - a[2] * b[1]))


def read_obj_map(path: str):
    """(v, vt, faces) of an OBJ the tool writes: faces as triples of (v, vt)
    index pairs, 0-based (vt None when the face has none). Raises ValueError
    on anything it cannot read."""
    v, vt, faces = [], [], []
    with open(path, encoding="utf-8") as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] in ("v", "vt"):
                n = 3 if w[0] == "v" else 2
                if len(w) < n + 1:
                    raise ValueError(f"{path}: a short line: {line.strip()}")
                (v if n == 3 else vt).append(tuple(float(x) for x in w[1:n + 1]))
            elif w[0] == "f":
                if len(w) != 4:
                    raise ValueError(f"{path}: a face that is not a triangle: {line.strip()}")
                corners = []
                for c in w[1:]:
                    parts = c.split("/")
                    corners.append((int(parts[0]) - 1, int(parts[1]) - 1 if len(parts) > 1 and parts[1] else None))
                faces.append(corners)
    for corners in faces:
        for i, t in corners:
            if not 0 <= i < len(v) or (t is not None and not 0 <= t < len(vt)):
                raise ValueError(f"{path}: an index out of range")
    if not faces:
        raise ValueError(f"{path}: no faces")
    return v, vt, faces


def check_map(path: str, sphere: bool) -> Dict[str, Optional[float]]:
    """Checks a map the tool wrote: every value finite; every face positive
    by the exact predicate (the uv triangle of a disk map, or det[p, q, r]
    of the sphere points). Returns nonfinite, checked_inverted (faces that
    are negative), checked_degenerate (faces of orientation zero) and, for a
    disk map, map_d_area."""
    v, vt, faces = read_obj_map(path)
    points = v if sphere else vt
    if any(not math.isfinite(x) for p in points for x in p):
        return {"nonfinite": 1, "checked_inverted": None, "checked_degenerate": None}
    if not sphere and any(t is None for corners in faces for _, t in corners):
        raise ValueError(f"{path}: a face without texture coordinates")
    neg = zero = 0
    for corners in faces:
        if sphere:
            o = orient3d_origin(*(v[i] for i, _ in corners))
        else:
            o = orient2d(*(vt[t] for _, t in corners))
        neg += o < 0
        zero += o == 0
    result = {"nonfinite": 0, "checked_inverted": neg, "checked_degenerate": zero}
    if not sphere:
        result["map_d_area"] = _map_d_area(v, vt, faces)
    return result


def _map_d_area(v, vt, faces) -> Optional[float]:
    """d_area (doc/design.md, "Metrics") of a uv map against its 3D
    triangles, without a density: sum of w_t (r_t + 1/r_t), r_t the face's
    share of the map's area over its share of the surface's; None when a
    face has no positive area in doubles."""
    a2, a3 = [], []
    for corners in faces:
        (p, q, r), (s, t, u) = ([v[i] for i, _ in corners], [vt[j] for _, j in corners])
        a2.append(0.5 * ((t[0] - s[0]) * (u[1] - s[1]) - (t[1] - s[1]) * (u[0] - s[0])))
        e1 = [q[k] - p[k] for k in range(3)]
        e2 = [r[k] - p[k] for k in range(3)]
        n = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
        a3.append(0.5 * math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2))
    s2, s3 = sum(a2), sum(a3)
    if not (s2 > 0 and s3 > 0) or min(a2) <= 0 or min(a3) <= 0:
        return None
    d = 0.0
    for x, y in zip(a2, a3):
        ratio = (x / s2) / (y / s3)
        d += (y / s3) * (ratio + 1 / ratio)
    return d if math.isfinite(d) else None


# What counts as a violation: a crash or hang of the tool or runner, an
# exception escaping the runner, a non-finite value in a map, a folded or
# flat face in a map given as valid, a map file left by a failed run, an
# exit code that disagrees with the report or is none of the tool's (0-3),
# a map that cannot be read.
VIOLATIONS = ("crash", "hang", "unexpected exit code", "runner error", "exception escaped", "NaN/Inf in output",
              "inverted/degenerate faces in an ok result", "output file left by a failed run",
              "exit code disagrees with report status", "unreadable output")


def violation_of(row: dict) -> Optional[str]:
    status = row["status"]
    if status == "crash":
        return "crash"
    if status == "timeout":
        return "hang"
    if status == "error":
        if row.get("config") in CONFIGS:
            return "unexpected exit code"
        return "exception escaped" if row.get("error") == "exception" else "runner error"
    if row.get("nonfinite"):
        return "NaN/Inf in output"
    if status in ("ok", "not_converged") and ((row.get("checked_inverted") or 0) > 0
                                            or (row.get("checked_degenerate") or 0) > 0):
        return "inverted/degenerate faces in an ok result"
    if row.get("stray_output"):
        return "output file left by a failed run"
    if row.get("exit_mismatch"):
        return "exit code disagrees with report status"
    if row.get("_unreadable"):
        return "unreadable output"
    return None


def _status_of_exit(code: Optional[int], sig: Optional[int], timed_out: bool) -> str:
    if timed_out:
        return "timeout"
    if sig is not None:
        return "crash"
    return {0: "ok", 3: "not_converged", 1: "input_error", 2: "flow_error"}.get(code, "error")


def _read_json(path: str) -> Optional[dict]:
    if not os.path.exists(path):
        return None
    try:
        with open(path, encoding="utf-8") as f:
            value = json.load(f)
        return value if isinstance(value, dict) else None
    except (OSError, ValueError):
        return None


def run_one(mesh_key: str, mesh_path: str, config_name: str, dlf: Optional[str], timeout: float,
            every_config: bool = False, runner: Optional[str] = None, check_outputs: bool = False,
            memory_limit: Optional[float] = None, scratch_root: Optional[str] = None) -> dict:
    """One row of ``runs``: `dlf info` decides whether the configuration
    applies (a mesh that fits neither command is given to both, whose
    refusal is the result; with `every_config`, every mesh is given to
    every configuration), then the configuration runs with a timeout, in a
    scratch folder of its own (in `scratch_root`, the study's, where this
    worker sees it). A runner's method runs on every mesh."""
    config = config_of(config_name, runner)
    row = {"mesh": mesh_key, "config": config_name, "worker": f"{socket.gethostname()}:{os.getpid()}"}
    where = scratch_root if scratch_root and os.path.isdir(scratch_root) else None
    with tempfile.TemporaryDirectory(prefix="dlf-study-", dir=where) as scratch:
        if config.command == "runner":
            return _run_runner(row, runner, config, mesh_path, timeout, scratch, memory_limit)
        fits = _mesh_fits(dlf, mesh_path, timeout, scratch)
        row["fits"] = fits
        if not every_config and fits in ("dlf disk", "dlf sphere") and fits != "dlf " + config.command:
            row["status"] = "not_applicable"
            return _finish(row)
        report_path = os.path.join(scratch, "report.json")
        argv = [dlf, config.command, mesh_path, *config.options, "--report", report_path, "--quiet"]
        row["command"] = " ".join(argv[1:3] + list(config.options))
        maps = []
        if check_outputs:
            # The paper mode certifies its flowing (flipped) triangulation, not
            # the caller's triangles (doc/design.md): that is the map checked.
            paper = config.command == "disk" and "paper" in config.options
            maps = [os.path.join(scratch, "map.obj")] + ([os.path.join(scratch, "domain.obj")] if paper else [])
            argv += ["-o", maps[0]] + (["--domain-mesh", maps[1]] if paper else [])
        code, sig, err, seconds, timed_out = _run_tool(argv, timeout, scratch, memory_limit)
        row.update(exit_code=code, exit_signal=sig, seconds=seconds, stderr_tail=err[-STDERR_TAIL:])
        report = _read_json(report_path)
        row["status"] = _status_of_exit(code, sig, timed_out)
        if check_outputs and not timed_out and sig is None:
            _check_outputs(row, config, code, report, maps)
    if report is not None:
        report.pop("history", None)
        final = report.get("final") or {}
        row.update(
            stop_reason=report.get("stop_reason"),
            d_area=final.get("d_area"),
            inverted_faces=final.get("inverted_faces"),
            vertices=report.get("vertices"),
            faces=report.get("faces"),
            iterations=report.get("iterations"),
            rejected_by_exact_check=report.get("rejected_by_exact_check"),
            report=json.dumps(report),
        )
        if row["status"] not in ("ok", "not_converged"):
            row["error"] = report.get("status")
    if row.get("error") is None and row["status"] in ("input_error", "flow_error", "error"):
        lines = [l for l in err.splitlines() if l.startswith("dlf: error:")]
        row["error"] = lines[-1][len("dlf: error: "):] if lines else None
    if check_outputs:
        row["violation"] = violation_of(row)
    row.pop("_unreadable", None)
    return _finish(row)


def _check_outputs(row: dict, config: Config, code: Optional[int], report: Optional[dict], maps: List[str]) -> None:
    """The checks of --check-outputs on a run that exited: the exit code
    against the report's status, no map left by a failed run, and the map
    of a valid run checked face by face."""
    status = report.get("status") if report is not None else None
    row["exit_mismatch"] = int((code == 0) != (status == "ok") or (code == 3) != (status == "not_converged"))
    wrote = code in (0, 3)
    row["stray_output"] = int(not wrote and any(os.path.exists(m) for m in maps))
    if wrote:
        try:
            row.update(check_map(maps[-1], sphere=config.command == "sphere"))
        except (OSError, ValueError, UnicodeDecodeError):
            row["_unreadable"] = True


def _run_runner(row: dict, runner: str, config: Config, mesh_path: str, timeout: float, scratch: str,
                memory_limit: Optional[float]) -> dict:
    """A method of the external runner on one mesh: the runner writes a JSON
    report (status: ok, not_converged, an error name, skipped when it cannot
    load the mesh, exception; message; inverted, degenerate, nonfinite,
    d_area, iterations, rejected_by_exact_check) and exits 0."""
    report_path = os.path.join(scratch, "report.json")
    argv = [runner, *config.options, "--case", mesh_path, "--report", report_path]
    row["command"] = " ".join([os.path.basename(runner), *config.options, "--case", os.path.basename(mesh_path)])
    code, sig, err, seconds, timed_out = _run_tool(argv, timeout, scratch, memory_limit)
    row.update(exit_code=code, exit_signal=sig, seconds=seconds, stderr_tail=err[-STDERR_TAIL:])
    report = _read_json(report_path) if code == 0 and not timed_out else None
    if timed_out or sig is not None:
        row["status"] = _status_of_exit(code, sig, timed_out)
    elif report is None or not isinstance(report.get("status"), str):
        row["status"] = "error"
        lines = [l for l in err.splitlines() if l.strip()]
        row["error"] = lines[-1] if lines else f"exit {code} without a report"
    else:
        status = report["status"]
        row["status"] = {"ok": "ok", "not_converged": "not_converged", "skipped": "input_error",
                         "exception": "error"}.get(status, "flow_error")
        if row["status"] not in ("ok", "not_converged"):
            row["error"] = status
        row.update(
            d_area=report.get("d_area"),
            inverted_faces=report.get("inverted"),
            checked_inverted=report.get("inverted"),
            checked_degenerate=report.get("degenerate"),
            nonfinite=None if report.get("nonfinite") is None else int(bool(report["nonfinite"])),
            iterations=report.get("iterations"),
            rejected_by_exact_check=report.get("rejected_by_exact_check"),
            report=json.dumps(report),
        )
    row["violation"] = violation_of(row)
    return _finish(row)


def _finish(row: dict) -> dict:
    row["finished_at"] = time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())
    return row


# ---------------------------------------------------------------------------
# The database
# ---------------------------------------------------------------------------

COLUMNS = (
    "mesh", "config", "status", "stop_reason", "d_area", "inverted_faces", "seconds", "vertices", "faces",
    "iterations", "fits", "error", "exit_code", "exit_signal", "stderr_tail", "report", "command", "worker",
    "finished_at", "checked_inverted", "checked_degenerate", "nonfinite", "stray_output", "exit_mismatch",
    "rejected_by_exact_check", "violation", "map_d_area",
)


def open_db(path: str) -> sqlite3.Connection:
    db = sqlite3.connect(path, timeout=60)
    db.execute("PRAGMA journal_mode=WAL")
    db.execute(SCHEMA)
    have = {r[1] for r in db.execute("PRAGMA table_info(runs)")}
    for name, kind in ADDED_COLUMNS:
        if name not in have:
            db.execute(f"ALTER TABLE runs ADD COLUMN {name} {kind}")
    db.commit()
    return db


def done_keys(db: sqlite3.Connection) -> set:
    return set(db.execute("SELECT mesh, config FROM runs"))


def insert_row(db: sqlite3.Connection, row: dict) -> bool:
    """Writes a row in its own transaction; False if (mesh, config) was
    already there (the row is kept as it was)."""
    values = [row.get(c) for c in COLUMNS]
    with db:
        cur = db.execute(
            f"INSERT OR IGNORE INTO runs ({', '.join(COLUMNS)}) VALUES ({', '.join('?' * len(COLUMNS))})", values
        )
    return cur.rowcount == 1


# ---------------------------------------------------------------------------
# The corpus
# ---------------------------------------------------------------------------


def corpus_meshes(inputs: Iterable[str]) -> List[Tuple[str, str]]:
    """(key, absolute path) of every mesh: a folder gives its mesh files
    (recursively, sorted; the key is the path below the folder), a file
    itself (its name); two meshes with one key are an error."""
    found: Dict[str, str] = {}
    for item in inputs:
        p = Path(item)
        if p.is_dir():
            files = sorted(f for f in p.rglob("*") if f.is_file() and f.suffix.lower() in MESH_SUFFIXES)
            pairs = [(str(f.relative_to(p)), str(f.resolve())) for f in files]
        elif p.is_file():
            pairs = [(p.name, str(p.resolve()))]
        else:
            raise SystemExit(f"dlf-study: error: {item}: no such file or folder")
        for key, path in pairs:
            if key in found and found[key] != path:
                raise SystemExit(f"dlf-study: error: two meshes named {key}: {found[key]} and {path}")
            found[key] = path
    if not found:
        raise SystemExit("dlf-study: error: no mesh files (" + ", ".join(MESH_SUFFIXES) + ") in " + ", ".join(inputs))
    return sorted(found.items())


def parse_configs(items: Sequence[str], runner: Optional[str]) -> Dict[str, List[str]]:
    """NAME[@FOLDER[,FOLDER...]] items: each configuration and the folders
    (below the corpus folders) of the meshes it runs on (empty: all). A
    name that is not one of CONFIGS is a method of the runner."""
    selected: Dict[str, List[str]] = {}
    for item in items:
        name, _, where = item.partition("@")
        if name not in CONFIGS and not runner:
            raise SystemExit(f"dlf-study: error: unknown configuration {name!r} (known: {', '.join(CONFIGS)}; "
                             "or a method of --runner)")
        if not name or (item.count("@") and not where):
            raise SystemExit(f"dlf-study: error: --config {item}: expected NAME or NAME@FOLDER")
        under = [w.strip("/") for w in where.split(",")] if where else []
        if name in selected and selected[name] != under:
            raise SystemExit(f"dlf-study: error: configuration {name} given twice with different folders")
        selected[name] = under
    return selected


def find_runner(given: str) -> str:
    path = shutil.which(given) if os.sep not in given else given
    if not path or not (os.path.isfile(path) and os.access(path, os.X_OK)):
        raise SystemExit(f"dlf-study: error: --runner {given}: not an executable")
    return os.path.abspath(path)


def find_dlf(given: Optional[str]) -> str:
    for candidate in (given, os.environ.get("DLF_EXECUTABLE"), shutil.which("dlf")):
        if candidate:
            if not (os.path.isfile(candidate) and os.access(candidate, os.X_OK)):
                raise SystemExit(f"dlf-study: error: {candidate}: not an executable")
            return os.path.abspath(candidate)
    raise SystemExit("dlf-study: error: no dlf executable (--dlf PATH, DLF_EXECUTABLE, or dlf on PATH)")


# ---------------------------------------------------------------------------
# dlf-study run
# ---------------------------------------------------------------------------


def run_study(args: argparse.Namespace) -> int:
    selected = parse_configs(args.config or list(DEFAULT_CONFIGS), args.runner)
    if not args.timeout > 0:
        raise SystemExit("dlf-study: error: --timeout must be > 0")
    if args.memory_limit is not None and not args.memory_limit > 0:
        raise SystemExit("dlf-study: error: --memory-limit must be > 0")
    runner = find_runner(args.runner) if args.runner else None
    dlf = find_dlf(args.dlf) if any(c in CONFIGS for c in selected) else None
    meshes = corpus_meshes(args.corpus)
    runs = [(key, path, c) for c, under in selected.items() for key, path in meshes
            if not under or any(key.startswith(u + "/") for u in under)]
    for c, under in selected.items():
        if under and not any(r[2] == c for r in runs):
            raise SystemExit(f"dlf-study: error: --config {c}@{'/'.join(under)}: no mesh under that folder")
    lock = _lock_study(args.db)
    try:
        return _run_locked(args, client_factory(args), runs, dlf, runner, selected, meshes)
    finally:
        lock.close()


def _lock_study(db_path: str):
    """One driver per database: an exclusive lock on DB.lock, held while the
    study runs (the kernel drops it when the driver dies, even by SIGKILL).
    A second driver refuses with the first one's pid."""
    import fcntl

    f = open(db_path + ".lock", "a+")
    try:
        fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        f.seek(0)
        pid = f.read().strip() or "?"
        f.close()
        raise SystemExit(f"dlf-study: error: another dlf-study (pid {pid}) is running on {db_path}; "
                         "wait for it to finish, or give another --db")
    f.seek(0)
    f.truncate()
    f.write(str(os.getpid()))
    f.flush()
    return f


def client_factory(args: argparse.Namespace):
    """A function that connects to the scheduler, or starts a local cluster,
    and keeps the client and the cluster in `state` as soon as each exists
    (so that an interrupt at any moment can close them). The local cluster's
    processes start with SIGINT ignored (an ignored signal stays ignored
    across exec): Ctrl-C reaches the whole foreground process group, and the
    driver alone then stops the study, in order. The price: a Ctrl-C during
    the cluster's start (about a second) is ignored by the driver too."""
    def connect(state: dict) -> None:
        from distributed import Client, LocalCluster

        if args.scheduler:
            state["client"] = Client(args.scheduler)
            return
        before = signal.signal(signal.SIGINT, signal.SIG_IGN)
        try:
            state["cluster"] = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                                            dashboard_address=":0")
        finally:
            signal.signal(signal.SIGINT, before)
        state["client"] = Client(state["cluster"])
    return connect


def _run_locked(args, connect, runs, dlf, runner, selected, meshes) -> int:
    from distributed import as_completed

    db = open_db(args.db)
    done = done_keys(db)
    todo = [(key, path, c) for key, path, c in runs if (key, c) not in done]
    # Largest files first (dask runs tasks about in submission order): the
    # longest runs start early instead of leaving one worker busy at the end.
    todo.sort(key=lambda t: -os.path.getsize(t[1]))
    total = len(runs)
    log = (lambda *a: None) if args.quiet else (lambda *a: print(*a, file=sys.stderr, flush=True))
    log(f"dlf-study: {len(meshes)} meshes, {len(selected)} configurations: {total} runs; "
        f"{total - len(todo)} already in {args.db}, {len(todo)} to run")
    # The runs' scratch folders, in one folder beside the database: removed
    # when the study ends however it ends, and, left by a driver that was
    # killed, when the next one starts.
    scratch_root = os.path.abspath(args.db) + ".scratch"
    shutil.rmtree(scratch_root, ignore_errors=True)
    if not todo:
        db.close()
        return 0
    os.makedirs(scratch_root)
    state: Dict[str, object] = {}
    written = 0
    start = time.monotonic()
    futures = []
    try:
        connect(state)
        client = state["client"]
        futures = [
            client.submit(run_one, key, path, c, dlf, args.timeout, args.every_config, runner,
                          args.check_outputs, args.memory_limit, scratch_root,
                          key=f"dlf-study-{c}-{key}-{args.db}",
                          pure=False, retries=args.retries)
            for key, path, c in todo
        ]
        lost = 0
        for future in as_completed(futures):
            try:
                row = future.result()
            except Exception as e:  # a task whose workers kept dying (KilledWorker), or a bug
                lost += 1
                log(f"dlf-study: {future.key}: not recorded: {type(e).__name__}: {e}")
                continue
            if insert_row(db, row):
                written += 1
            log(f"[{total - len(todo) + written}/{total}] {row['mesh']} {row['config']}: {row['status']}"
                + (f" ({row['seconds']:.2f} s)" if row.get("seconds") is not None else ""))
        log(f"dlf-study: {written} runs written in {time.monotonic() - start:.1f} s; "
            f"{len(done_keys(db))} of {total} in {args.db}")
        if lost:
            log(f"dlf-study: {lost} runs not recorded; run the same command again to retry them")
            return 1
        return 0
    except KeyboardInterrupt:
        _quiet_shutdown()
        log(f"\ndlf-study: interrupted; {written} runs written this time, {len(done_keys(db))} of {total} "
            f"in {args.db}; run the same command again to resume")
        return 130
    finally:
        # A second Ctrl-C (or SIGTERM) during the shutdown would leave runs behind: ignored.
        before = signal.signal(signal.SIGINT, signal.SIG_IGN)
        before_term = signal.signal(signal.SIGTERM, signal.SIG_IGN)
        try:
            for f in futures:
                f.release()
            if "client" in state:
                state["client"].close()
            if "cluster" in state:
                state["cluster"].close()  # the workers stop; their runs die with them
            db.close()
            shutil.rmtree(scratch_root, ignore_errors=True)
        finally:
            signal.signal(signal.SIGINT, before)
            signal.signal(signal.SIGTERM, before_term)


def _quiet_shutdown() -> None:
    """No warnings from dask while an interrupted study stops its workers
    (they are stopped on purpose)."""
    import logging

    for name in ("distributed", "distributed.nanny", "distributed.worker", "distributed.scheduler",
                 "distributed.core", "distributed.client", "tornado"):
        logging.getLogger(name).setLevel(logging.CRITICAL)


# ---------------------------------------------------------------------------
# dlf-study report
# ---------------------------------------------------------------------------


def _median(xs: List[float]) -> Optional[float]:
    if not xs:
        return None
    s = sorted(xs)
    n = len(s)
    return s[n // 2] if n % 2 else 0.5 * (s[n // 2 - 1] + s[n // 2])


def _fmt(x, digits=4) -> str:
    if x is None:
        return "–"
    if isinstance(x, float):
        return f"{x:.{digits}g}"
    return str(x)


def _cell(text: Optional[str]) -> str:
    """A whole message as one Markdown table cell: never cut, its line breaks
    and pipes (which would end the cell) replaced."""
    return " ".join((text or "").split()).replace("|", "/")


def is_valid_map(row: dict) -> bool:
    """A map the tool wrote whose input triangles are all positive: ok or
    not_converged, no inverted face in the report nor, when checked, in the
    written map. The paper and literal modes certify only the flowing
    triangulation and may leave input triangles inverted: not valid."""
    return (row["status"] in ("ok", "not_converged") and not (row["inverted_faces"] or 0)
            and not (row.get("checked_inverted") or 0))


def summary_markdown(db: sqlite3.Connection) -> str:
    rows = [dict(zip(COLUMNS, r)) for r in db.execute(f"SELECT {', '.join(COLUMNS)} FROM runs ORDER BY config, mesh")]
    configs = sorted({r["config"] for r in rows}, key=lambda c: list(CONFIGS).index(c) if c in CONFIGS else 99)
    meshes = sorted({r["mesh"] for r in rows})
    out = [f"{len(rows)} runs: {len(meshes)} meshes, {len(configs)} configurations.", ""]
    out += ["| configuration | " + " | ".join(STATUSES) + " | runs |", "|---" * (len(STATUSES) + 2) + "|"]
    for c in configs:
        mine = [r for r in rows if r["config"] == c]
        counts = [sum(r["status"] == s for r in mine) for s in STATUSES]
        out.append(f"| {c} | " + " | ".join(str(n) for n in counts) + f" | {len(mine)} |")
    out += ["", "Valid maps (ok or not_converged, no inverted input triangle): D_area (optimum 2), seconds of the whole "
            "`dlf` process.",
            "", "| configuration | maps | converged | D_area median | D_area max | seconds median | seconds total |",
            "|---|---|---|---|---|---|---|"]
    for c in configs:
        mine = [r for r in rows if r["config"] == c and is_valid_map(r)]
        d = [r["d_area"] for r in mine if r["d_area"] is not None]
        t = [r["seconds"] for r in mine if r["seconds"] is not None]
        out.append(f"| {c} | {len(mine)} | {sum(r['status'] == 'ok' for r in mine)} | {_fmt(_median(d))} | "
                   f"{_fmt(max(d) if d else None)} | {_fmt(_median(t), 3)} | {_fmt(sum(t), 4)} |")
    folded = [r for r in rows if r["status"] in ("ok", "not_converged") and not is_valid_map(r)]
    if folded:
        out += ["", f"Maps written with inverted input triangles ({len(folded)}; the paper and literal modes certify "
                "only the flowing triangulation): not valid maps.", "",
                "| mesh | configuration | status | inverted faces | D_area |", "|---|---|---|---|---|"]
        for r in folded:
            inverted = max(r["inverted_faces"] or 0, r.get("checked_inverted") or 0)
            out.append(f"| {r['mesh']} | {r['config']} | {r['status']} | {inverted} | {_fmt(r['d_area'])} |")
    bad = [r for r in rows if r["status"] in ("crash", "timeout", "error")]
    out += ["", f"Crashes, timeouts and other failures of the tool: {len(bad)}.", ""]
    if bad:
        out += ["| mesh | configuration | status | signal | stderr (end) |", "|---|---|---|---|---|"]
        for r in bad:
            tail = (r["stderr_tail"] or "").strip().splitlines()[-1:] or [""]
            out.append(f"| {r['mesh']} | {r['config']} | {r['status']} | {_fmt(r['exit_signal'])} | {_cell(tail[0])} |")
    checked = [r for r in rows if r["violation"] is not None or r["exit_mismatch"] is not None
               or r["checked_inverted"] is not None]
    if checked:
        broken = [r for r in rows if r["violation"]]
        out += [f"Violations among the checked runs ({len(checked)}): {len(broken)}.", ""]
        if broken:
            out += ["| mesh | configuration | status | violation |", "|---|---|---|---|"]
            out += [f"| {r['mesh']} | {r['config']} | {r['status']} | {r['violation']} |" for r in broken]
            out.append("")
    refused = [r for r in rows if r["status"] in ("input_error", "flow_error")]
    if refused:
        out += ["", "Inputs the tool refused, and why:", "", "| mesh | configuration | status | error |", "|---|---|---|---|"]
        for r in refused:
            out.append(f"| {r['mesh']} | {r['config']} | {r['status']} | {_cell(r['error'])} |")
    return "\n".join(out) + "\n"


def box_labels(configs: Sequence[str], data: Sequence[Sequence[float]]) -> List[str]:
    """The box plot's labels: each configuration with the number of maps its box is drawn from."""
    return [f"{c}\nn = {len(values)}" for c, values in zip(configs, data)]


EXPORT_COLUMNS = tuple(c for c in COLUMNS if c != "report")


def export_csv(db: sqlite3.Connection, out) -> int:
    """Writes the runs as CSV to the text stream `out`: a header of the
    table's column names (all but the JSON `report`) and one row per run,
    ordered by configuration and mesh; null is an empty cell. Returns the
    number of rows."""
    import csv

    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(EXPORT_COLUMNS)
    n = 0
    for row in db.execute(f"SELECT {', '.join(EXPORT_COLUMNS)} FROM runs ORDER BY config, mesh"):
        writer.writerow(["" if v is None else v for v in row])
        n += 1
    return n


def _open_read_only(path: str) -> sqlite3.Connection:
    """The study's database at `path`, read only; an error exit when there is none."""
    if not os.path.isfile(path):
        raise SystemExit(f"dlf-study: error: {path}: no such database")
    return sqlite3.connect(f"file:{path}?mode=ro", uri=True)


def export_study(args: argparse.Namespace) -> int:
    db = _open_read_only(args.db)
    try:
        if args.csv == "-":
            export_csv(db, sys.stdout)
            return 0
        target = Path(args.csv)
        if not target.parent.is_dir():
            raise SystemExit(f"dlf-study: error: --csv {args.csv}: directory '{target.parent}' does not exist")
        # All or nothing: a temporary beside the target, renamed once complete.
        tmp = target.parent / f".{target.name}.dlf-study-{os.getpid()}.tmp"
        try:
            with open(tmp, "w", encoding="utf-8", newline="") as f:
                n = export_csv(db, f)
            os.replace(tmp, target)
        finally:
            if tmp.exists():
                tmp.unlink()
        print(f"wrote {target} ({n} runs)")
        return 0
    finally:
        db.close()


def write_plots(db: sqlite3.Connection, outdir: Path) -> List[str]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    valid = [r for r in (dict(zip(COLUMNS, x)) for x in db.execute(f"SELECT {', '.join(COLUMNS)} FROM runs"))
             if is_valid_map(r)]
    rows = [(r["config"], r["d_area"], r["seconds"], r["faces"]) for r in valid]
    configs = [c for c in CONFIGS if any(r[0] == c for r in rows)] + sorted(
        {r[0] for r in rows} - set(CONFIGS))
    written = []
    fig, ax = plt.subplots(figsize=(7, 4))
    data = [[max(r[1] - 2, 1e-16) for r in rows if r[0] == c and r[1] is not None] for c in configs]
    if any(data):
        ax.boxplot(data, labels=box_labels(configs, data), whis=(0, 100))
        # Every map as a point: a box drawn from a few maps shows them all.
        for k, values in enumerate(data):
            ax.plot([k + 1] * len(values), values, ".", color="black", alpha=0.5, markersize=3)
        ax.set_yscale("log")
    ax.set_ylabel("D_area - 2 (log)")
    ax.set_title("Area distortion of the valid maps, per configuration (n: maps)")
    fig.tight_layout()
    fig.savefig(outdir / "d_area.png", dpi=110)
    plt.close(fig)
    written.append(str(outdir / "d_area.png"))

    fig, ax = plt.subplots(figsize=(7, 4))
    for c in configs:
        pts = [(r[3], r[2]) for r in rows if r[0] == c and r[2] is not None and r[3]]
        if pts:
            ax.scatter([p[0] for p in pts], [p[1] for p in pts], s=12, label=c)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("faces")
    ax.set_ylabel("seconds (whole dlf process)")
    ax.set_title("Time against mesh size")
    if configs:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(outdir / "time_vs_faces.png", dpi=110)
    plt.close(fig)
    written.append(str(outdir / "time_vs_faces.png"))
    return written


def report_study(args: argparse.Namespace) -> int:
    db = _open_read_only(args.db)
    try:
        text = summary_markdown(db)
        if args.output is None:
            sys.stdout.write(text)
            return 0
        outdir = Path(args.output)
        outdir.mkdir(parents=True, exist_ok=True)
        (outdir / "summary.md").write_text(text, encoding="utf-8")
        files = [str(outdir / "summary.md")] + write_plots(db, outdir)
        for f in files:
            print(f"wrote {f}")
        return 0
    finally:
        db.close()


# ---------------------------------------------------------------------------
# Command line
# ---------------------------------------------------------------------------


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="dlf-study",
        description="Run dlf configurations over a corpus of meshes on dask.distributed; results in SQLite.")
    sub = p.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run", help="run (or resume) a study")
    r.add_argument("corpus", nargs="+", metavar="CORPUS", help="a folder of meshes, or mesh files")
    r.add_argument("--db", required=True, metavar="STUDY.sqlite", help="the results database (created if missing)")
    where = r.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, default=2, metavar="N",
                       help="a LocalCluster of N worker processes on this machine (default 2)")
    where.add_argument("--scheduler", metavar="ADDRESS", help="an existing dask scheduler, e.g. tcp://host:8786")
    r.add_argument("--timeout", type=float, default=300, metavar="SECONDS",
                   help="a run taking longer is killed and recorded as timeout (default 300)")
    r.add_argument("--config", action="append", metavar="NAME[@FOLDER]",
                   help="a configuration, NAME or NAME@FOLDER[,FOLDER] to run it only on the meshes under those "
                        "folders of the corpus (repeatable; default: " + ", ".join(DEFAULT_CONFIGS) + "); known: "
                   + ", ".join(CONFIGS) + "; any other NAME is a method of --runner")
    r.add_argument("--every-config", action="store_true",
                   help="give every mesh to every configuration, whatever its topology (robustness studies: "
                        "the tool's refusal is the result)")
    r.add_argument("--dlf", metavar="PATH", help="the dlf executable (default: $DLF_EXECUTABLE, or dlf on PATH)")
    r.add_argument("--runner", metavar="PATH",
                   help="an external runner: a configuration NAME that is not the tool's runs "
                        "`PATH --run NAME --case MESH --report OUT.json` (doc/python.md, \"Runners\")")
    r.add_argument("--check-outputs", action="store_true",
                   help="have dlf write each map and check it: every face positive (exact predicate), finite "
                        "values, no map left by a failed run, exit code as the report's status; fills `violation`")
    r.add_argument("--memory-limit", type=float, metavar="GIB",
                   help="address-space limit of each run (RLIMIT_AS), in GiB (default: none)")
    r.add_argument("--retries", type=int, default=0, metavar="K",
                   help="re-run a task whose worker died K more times (dask also reschedules the tasks of a "
                        "lost worker by itself)")
    r.add_argument("--quiet", "-q", action="store_true", help="no progress lines")
    g = sub.add_parser("report", help="summary tables and plots of a study")
    g.add_argument("db", metavar="STUDY.sqlite")
    g.add_argument("-o", "--output", metavar="DIR", help="write DIR/summary.md, DIR/d_area.png, DIR/time_vs_faces.png "
                                                         "(default: the summary on stdout)")
    e = sub.add_parser("export", help="the runs of a study as a table")
    e.add_argument("db", metavar="STUDY.sqlite")
    e.add_argument("--csv", required=True, metavar="FILE",
                   help="write the runs as CSV, one row per run, the columns of the database but the JSON report "
                        "('-': stdout)")
    sub.add_parser("configs", help="list the configurations")
    return p


def _interrupt(signum, frame):
    raise KeyboardInterrupt


def main(argv: Optional[Sequence[str]] = None) -> int:
    args = parser().parse_args(argv)
    if args.command == "run":
        if args.workers is not None and args.workers < 1:
            raise SystemExit("dlf-study: error: --workers must be >= 1")
        signal.signal(signal.SIGTERM, _interrupt)  # SIGTERM stops a study as Ctrl-C does
        try:
            return run_study(args)
        except KeyboardInterrupt:  # before the runs started: nothing to stop
            print(f"\ndlf-study: interrupted before any run; run the same command again to start", file=sys.stderr)
            return 130
    if args.command == "report":
        return report_study(args)
    if args.command == "export":
        return export_study(args)
    for c in CONFIGS.values():
        command = " ".join(("dlf", c.command) + c.options)
        print(f"{c.name:16} {command:30} {c.description}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
