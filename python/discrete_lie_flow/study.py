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

See doc/python.md ("Corpus studies") for the commands and the columns.
"""

from __future__ import annotations

import argparse
import json
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
  PRIMARY KEY (mesh, config)
)
"""


# ---------------------------------------------------------------------------
# The task (runs on a dask worker)
# ---------------------------------------------------------------------------


def _run_tool(argv: Sequence[str], timeout: float) -> Tuple[Optional[int], Optional[int], str, float, bool]:
    """Runs argv in its own process group; returns (exit code, signal,
    stderr, seconds, timed out). At the timeout the group is killed."""
    start = time.monotonic()
    with subprocess.Popen(
        list(argv), stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, start_new_session=True
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


def run_one(mesh_key: str, mesh_path: str, config_name: str, dlf: str, timeout: float, every_config: bool = False) -> dict:
    """One row of ``runs``: `dlf info` decides whether the configuration
    applies (a mesh that fits neither command is given to both, whose
    refusal is the result; with `every_config`, every mesh is given to
    every configuration), then the configuration runs with a timeout."""
    config = CONFIGS[config_name]
    row = {"mesh": mesh_key, "config": config_name, "worker": f"{socket.gethostname()}:{os.getpid()}"}
    with tempfile.TemporaryDirectory(prefix="dlf-study-") as scratch:
        fits = _mesh_fits(dlf, mesh_path, timeout, scratch)
        row["fits"] = fits
        if not every_config and fits in ("dlf disk", "dlf sphere") and fits != "dlf " + config.command:
            row["status"] = "not_applicable"
            return _finish(row)
        report_path = os.path.join(scratch, "report.json")
        argv = [dlf, config.command, mesh_path, *config.options, "--report", report_path, "--quiet"]
        row["command"] = " ".join(argv[1:3] + list(config.options))
        code, sig, err, seconds, timed_out = _run_tool(argv, timeout)
        row.update(exit_code=code, exit_signal=sig, seconds=seconds, stderr_tail=err[-STDERR_TAIL:])
        report = None
        if os.path.exists(report_path):
            try:
                with open(report_path, encoding="utf-8") as f:
                    report = json.load(f)
            except (OSError, ValueError):
                report = None
    if timed_out:
        row["status"] = "timeout"
    elif sig is not None:
        row["status"] = "crash"
    elif code in (0, 3):
        row["status"] = "ok" if code == 0 else "not_converged"
    elif code == 1:
        row["status"] = "input_error"
    elif code == 2:
        row["status"] = "flow_error"
    else:
        row["status"] = "error"
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
            report=json.dumps(report),
        )
        if row["status"] not in ("ok", "not_converged"):
            row["error"] = report.get("status")
    if row.get("error") is None and row["status"] in ("input_error", "flow_error", "error"):
        lines = [l for l in err.splitlines() if l.startswith("dlf: error:")]
        row["error"] = lines[-1][len("dlf: error: "):] if lines else None
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
    "finished_at",
)


def open_db(path: str) -> sqlite3.Connection:
    db = sqlite3.connect(path, timeout=60)
    db.execute("PRAGMA journal_mode=WAL")
    db.execute(SCHEMA)
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
    from distributed import Client, LocalCluster, as_completed  # late: `report` needs no dask

    configs = args.config or list(DEFAULT_CONFIGS)
    for c in configs:
        if c not in CONFIGS:
            raise SystemExit(f"dlf-study: error: unknown configuration {c!r} (known: {', '.join(CONFIGS)})")
    if not args.timeout > 0:
        raise SystemExit("dlf-study: error: --timeout must be > 0")
    dlf = find_dlf(args.dlf)
    meshes = corpus_meshes(args.corpus)
    db = open_db(args.db)
    done = done_keys(db)
    todo = [(key, path, c) for key, path in meshes for c in dict.fromkeys(configs) if (key, c) not in done]
    # Largest files first (dask runs tasks about in submission order): the
    # longest runs start early instead of leaving one worker busy at the end.
    todo.sort(key=lambda t: -os.path.getsize(t[1]))
    total = len(meshes) * len(dict.fromkeys(configs))
    log = (lambda *a: None) if args.quiet else (lambda *a: print(*a, file=sys.stderr, flush=True))
    log(f"dlf-study: {len(meshes)} meshes x {len(set(configs))} configurations = {total} runs; "
        f"{total - len(todo)} already in {args.db}, {len(todo)} to run")
    if not todo:
        return 0

    cluster = None
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                               dashboard_address=":0")
        client = Client(cluster)
    written = 0
    start = time.monotonic()
    futures = []
    try:
        futures = [
            client.submit(run_one, key, path, c, dlf, args.timeout, args.every_config,
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
        log(f"\ndlf-study: interrupted; {written} runs written this time, {len(done_keys(db))} of {total} "
            f"in {args.db}; run the same command again to resume")
        return 130
    finally:
        for f in futures:
            f.release()
        client.close()
        if cluster is not None:
            cluster.close()
        db.close()


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
    out += ["", "Valid maps (ok or not_converged): D_area (optimum 2), inverted faces, seconds of the whole `dlf` process.",
            "", "| configuration | maps | converged | D_area median | D_area max | inverted faces | seconds median | seconds total |",
            "|---|---|---|---|---|---|---|---|"]
    for c in configs:
        mine = [r for r in rows if r["config"] == c and r["status"] in ("ok", "not_converged")]
        d = [r["d_area"] for r in mine if r["d_area"] is not None]
        t = [r["seconds"] for r in mine if r["seconds"] is not None]
        inv = sum(r["inverted_faces"] or 0 for r in mine)
        out.append(f"| {c} | {len(mine)} | {sum(r['status'] == 'ok' for r in mine)} | {_fmt(_median(d))} | "
                   f"{_fmt(max(d) if d else None)} | {inv} | {_fmt(_median(t), 3)} | {_fmt(sum(t), 4)} |")
    bad = [r for r in rows if r["status"] in ("crash", "timeout", "error")]
    out += ["", f"Crashes, timeouts and other failures of the tool: {len(bad)}.", ""]
    if bad:
        out += ["| mesh | configuration | status | signal | stderr (end) |", "|---|---|---|---|---|"]
        for r in bad:
            tail = (r["stderr_tail"] or "").strip().splitlines()[-1:] or [""]
            out.append(f"| {r['mesh']} | {r['config']} | {r['status']} | {_fmt(r['exit_signal'])} | "
                       f"{tail[0].replace('|', '/')[:160]} |")
    refused = [r for r in rows if r["status"] in ("input_error", "flow_error")]
    if refused:
        out += ["", "Inputs the tool refused, and why:", "", "| mesh | configuration | status | error |", "|---|---|---|---|"]
        for r in refused:
            out.append(f"| {r['mesh']} | {r['config']} | {r['status']} | {(r['error'] or '').replace('|', '/')[:200]} |")
    return "\n".join(out) + "\n"


def write_plots(db: sqlite3.Connection, outdir: Path) -> List[str]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = list(db.execute("SELECT config, d_area, seconds, faces FROM runs WHERE status IN ('ok', 'not_converged')"))
    configs = [c for c in CONFIGS if any(r[0] == c for r in rows)] + sorted(
        {r[0] for r in rows} - set(CONFIGS))
    written = []
    fig, ax = plt.subplots(figsize=(7, 4))
    data = [[max(r[1] - 2, 1e-16) for r in rows if r[0] == c and r[1] is not None] for c in configs]
    if any(data):
        ax.boxplot(data, labels=configs, whis=(0, 100))
        ax.set_yscale("log")
    ax.set_ylabel("D_area - 2 (log)")
    ax.set_title("Area distortion of the valid maps, per configuration")
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
    if not os.path.isfile(args.db):
        raise SystemExit(f"dlf-study: error: {args.db}: no such database")
    db = sqlite3.connect(f"file:{args.db}?mode=ro", uri=True)
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
    r.add_argument("--config", action="append", metavar="NAME",
                   help="a configuration (repeatable; default: " + ", ".join(DEFAULT_CONFIGS) + "); known: "
                   + ", ".join(CONFIGS))
    r.add_argument("--every-config", action="store_true",
                   help="give every mesh to every configuration, whatever its topology (robustness studies: "
                        "the tool's refusal is the result)")
    r.add_argument("--dlf", metavar="PATH", help="the dlf executable (default: $DLF_EXECUTABLE, or dlf on PATH)")
    r.add_argument("--retries", type=int, default=0, metavar="K",
                   help="re-run a task whose worker died K more times (dask also reschedules the tasks of a "
                        "lost worker by itself)")
    r.add_argument("--quiet", "-q", action="store_true", help="no progress lines")
    g = sub.add_parser("report", help="summary tables and plots of a study")
    g.add_argument("db", metavar="STUDY.sqlite")
    g.add_argument("-o", "--output", metavar="DIR", help="write DIR/summary.md, DIR/d_area.png, DIR/time_vs_faces.png "
                                                         "(default: the summary on stdout)")
    sub.add_parser("configs", help="list the configurations")
    return p


def main(argv: Optional[Sequence[str]] = None) -> int:
    args = parser().parse_args(argv)
    if args.command == "run":
        if args.workers is not None and args.workers < 1:
            raise SystemExit("dlf-study: error: --workers must be >= 1")
        return run_study(args)
    if args.command == "report":
        return report_study(args)
    for c in CONFIGS.values():
        command = " ".join(("dlf", c.command) + c.options)
        print(f"{c.name:16} {command:30} {c.description}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
