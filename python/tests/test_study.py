# Copyright (c) 2026 The Discrete Lie Flow authors.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# dlf-study on a LocalCluster of 2 workers: a small corpus of CGAL's meshes
# with a run that crashes, one that hangs past its timeout, and one the tool
# cannot read; every row checked; an interrupted study resumed; a worker
# killed in the middle of a study. The crash and the hang come from a
# wrapper around the real dlf (by mesh name), as a broken build would give.
# Environment (set by CTest): DLF_EXECUTABLE, DLF_DATA_DIR, PYTHONPATH.

import json
import os
import shutil
import signal
import sqlite3
import subprocess
import sys
import time

import psutil
import pytest

from discrete_lie_flow import study

DLF = os.path.abspath(os.environ.get("DLF_EXECUTABLE", "dlf"))
MESHES = os.path.join(os.environ.get("DLF_DATA_DIR", "build/data"), "meshes")
TIMEOUT = 10  # seconds per run; the real runs here take well under 1 s

CONFIGS = ("disk-certified", "disk-paper", "sphere", "sphere-paper")


@pytest.fixture(scope="module")
def corpus(tmp_path_factory):
    root = tmp_path_factory.mktemp("study")
    meshes = root / "corpus"
    meshes.mkdir()
    for name in ("nefertiti.off", "sphere.off"):
        src = os.path.join(MESHES, name)
        if not os.path.exists(src):
            pytest.skip(f"{src} missing (CGAL's data set)")
        shutil.copy(src, meshes / name)
    shutil.copy(meshes / "nefertiti.off", meshes / "crash.off")   # a disk: the disk runs crash
    shutil.copy(meshes / "sphere.off", meshes / "hang.off")       # a sphere: the sphere runs hang
    (meshes / "garbage.off").write_text("OFF\n3 1 0\n0 0 zero\n")  # unreadable: refused by both commands
    (meshes / "notes.txt").write_text("not a mesh\n")              # ignored
    # dlf, except that it crashes on crash.off and hangs on hang.off (not
    # in `dlf info`), and sleeps $FAKE_DELAY before every flow.
    fake = root / "fake-dlf"
    fake.write_text(f"""#!/bin/sh
if [ "$1" != info ]; then
  sleep "${{FAKE_DELAY:-0}}"
  case "$2" in
    *crash.off) echo "about to crash" >&2; kill -SEGV $$ ;;
    *hang.off) sleep 600 ;;
  esac
fi
exec "{DLF}" "$@"
""")
    fake.chmod(0o755)
    return meshes, str(fake)


def study_command(corpus_dir, db, fake, *extra):
    return [sys.executable, "-m", "discrete_lie_flow.study", "run", str(corpus_dir), "--db", str(db),
            "--workers", "2", "--timeout", str(TIMEOUT), "--dlf", fake, *extra]


def rows_of(db):
    con = sqlite3.connect(db)
    try:
        return {(r[0], r[1]): dict(zip(study.COLUMNS, r))
                for r in con.execute(f"SELECT {', '.join(study.COLUMNS)} FROM runs")}
    finally:
        con.close()


def count_rows(db):
    if not os.path.exists(db):
        return 0
    con = sqlite3.connect(db, timeout=30)
    try:
        return con.execute("SELECT count(*) FROM runs").fetchone()[0]
    except sqlite3.OperationalError:
        return 0
    finally:
        con.close()


EXPECTED_KEYS = {(m, c) for m in ("crash.off", "garbage.off", "hang.off", "nefertiti.off", "sphere.off") for c in CONFIGS}


def check_rows(rows):
    """Every (mesh, configuration) once, each with the result it must have."""
    assert set(rows) == EXPECTED_KEYS
    for (mesh, config), r in rows.items():
        disk = config.startswith("disk")
        if mesh in ("nefertiti.off", "sphere.off"):
            fits = "dlf disk" if mesh == "nefertiti.off" else "dlf sphere"
            assert r["fits"] == fits
            if disk == (fits == "dlf disk"):
                assert r["status"] in ("ok", "not_converged"), r
                assert r["exit_code"] in (0, 3) and r["exit_signal"] is None
                assert r["d_area"] >= 2 and r["inverted_faces"] == 0 and r["stop_reason"]
                assert r["faces"] == (562 if disk else 320) and r["seconds"] > 0
                report = json.loads(r["report"])
                assert report["mode"] == ("paper" if config.endswith("paper") else "certified")
                assert report["final"]["d_area"] == r["d_area"]
            else:
                assert r["status"] == "not_applicable" and r["seconds"] is None and r["exit_code"] is None
        elif mesh == "crash.off":
            if disk:
                assert r["status"] == "crash" and r["exit_signal"] == signal.SIGSEGV and r["exit_code"] is None
                assert "about to crash" in r["stderr_tail"] and r["report"] is None
            else:
                assert r["status"] == "not_applicable"
        elif mesh == "hang.off":
            if disk:
                assert r["status"] == "not_applicable"
            else:
                assert r["status"] == "timeout" and r["exit_signal"] == signal.SIGKILL
                assert TIMEOUT <= r["seconds"] < TIMEOUT + 30
        else:  # garbage.off: `dlf info` fails, so both commands run and refuse it
            assert r["fits"] == "unknown"
            assert r["status"] == "input_error" and r["exit_code"] == 1, r
            assert "cannot read" in r["error"] or "garbage.off" in r["error"]


def test_study_records_every_run_once(corpus, tmp_path):
    meshes, fake = corpus
    db = tmp_path / "study.sqlite"
    p = subprocess.run(study_command(meshes, db, fake), capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    check_rows(rows_of(db))
    # Run again: nothing to do, nothing rewritten.
    before = rows_of(db)
    p = subprocess.run(study_command(meshes, db, fake), capture_output=True, text=True, timeout=300)
    assert p.returncode == 0 and "20 already in" in p.stderr and "0 to run" in p.stderr
    assert rows_of(db) == before
    # The report: tables and plots.
    out = tmp_path / "report"
    p = subprocess.run([sys.executable, "-m", "discrete_lie_flow.study", "report", str(db), "-o", str(out)],
                       capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    summary = (out / "summary.md").read_text()
    assert "| disk-certified | " in summary and "| crash.off | disk-paper | crash | 11 |" in summary
    assert "| hang.off | sphere | timeout | 9 |" in summary
    for png in ("d_area.png", "time_vs_faces.png"):
        assert (out / png).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_interrupted_study_resumes(corpus, tmp_path):
    meshes, fake = corpus
    db = tmp_path / "study.sqlite"
    env = dict(os.environ, FAKE_DELAY="0.5")
    p = subprocess.Popen(study_command(meshes, db, fake), env=env, stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 120
    while count_rows(db) < 4 and time.time() < deadline and p.poll() is None:
        time.sleep(0.1)
    p.send_signal(signal.SIGINT)
    _, err = p.communicate(timeout=120)
    assert p.returncode == 130, err
    assert "interrupted" in err
    first = rows_of(db)
    assert 4 <= len(first) < len(EXPECTED_KEYS)
    p = subprocess.run(study_command(meshes, db, fake), capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    assert f"{len(first)} already in" in p.stderr
    rows = rows_of(db)
    check_rows(rows)
    for key, row in first.items():  # kept as they were
        assert rows[key] == row


def test_killed_worker_loses_no_run(corpus, tmp_path):
    meshes, fake = corpus
    db = tmp_path / "study.sqlite"
    env = dict(os.environ, FAKE_DELAY="0.5")
    p = subprocess.Popen(study_command(meshes, db, fake), env=env, stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 120
    while count_rows(db) < 3 and time.time() < deadline and p.poll() is None:
        time.sleep(0.1)
    # The worker processes are the study's children that run a flow (its dlf).
    victim = None
    while victim is None and time.time() < deadline and p.poll() is None:
        for child in psutil.Process(p.pid).children():
            if any(g.name() in ("sh", "dlf", "fake-dlf", "sleep") for g in child.children(recursive=True)):
                victim = child
                break
        time.sleep(0.05)
    assert victim is not None, "no worker running a flow found"
    victim.kill()
    _, err = p.communicate(timeout=300)
    assert p.returncode == 0, err
    check_rows(rows_of(db))


def test_study_on_an_existing_scheduler(corpus, tmp_path):
    from distributed import LocalCluster

    meshes, fake = corpus
    db = tmp_path / "study.sqlite"
    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster:
        p = subprocess.run([sys.executable, "-m", "discrete_lie_flow.study", "run", str(meshes / "nefertiti.off"),
                            str(meshes / "sphere.off"), "--db", str(db), "--scheduler", cluster.scheduler_address,
                            "--config", "disk-certified", "--config", "sphere", "--every-config", "--dlf", DLF],
                           capture_output=True, text=True, timeout=300)
        assert p.returncode == 0, p.stderr
        pids = {str(nanny.process.pid) for nanny in cluster.workers.values()}
    rows = rows_of(db)
    assert set(rows) == {(m, c) for m in ("nefertiti.off", "sphere.off") for c in ("disk-certified", "sphere")}
    assert rows[("nefertiti.off", "disk-certified")]["status"] in ("ok", "not_converged")
    assert rows[("sphere.off", "sphere")]["status"] in ("ok", "not_converged")
    # --every-config: each mesh given to the other command too, which refuses it.
    for mesh, config, what in (("sphere.off", "disk-certified", "not a disk"), ("nefertiti.off", "sphere", "genus")):
        r = rows[(mesh, config)]
        assert r["status"] == "input_error" and r["exit_code"] == 1 and what in r["error"], r
    # Run by the cluster's worker, not by a LocalCluster of the study's own.
    assert len(pids) == 1
    assert {r["worker"].split(":")[-1] for r in rows.values()} == pids
