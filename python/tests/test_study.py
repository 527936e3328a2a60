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
import tempfile
import time
from pathlib import Path

import psutil
import pytest
from strict import missing_mesh

from discrete_lie_flow import study

DLF = os.path.abspath(os.environ.get("DLF_EXECUTABLE", "dlf"))
MESHES = os.path.join(os.environ.get("DLF_DATA_DIR", "build/data"), "meshes")
TIMEOUT = 10  # seconds per run; the real runs here take well under 1 s

CONFIGS = ("disk-certified", "disk-paper", "sphere", "sphere-paper")


def copy_meshes(folder):
    """nefertiti.off (a disk) and sphere.off (a sphere) of CGAL's data set into `folder`."""
    for name in ("nefertiti.off", "sphere.off"):
        src = os.path.join(MESHES, name)
        if not os.path.exists(src):
            missing_mesh(src)
        shutil.copy(src, folder / name)


@pytest.fixture(scope="module")
def corpus(tmp_path_factory):
    root = tmp_path_factory.mktemp("study")
    meshes = root / "corpus"
    meshes.mkdir()
    copy_meshes(meshes)
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
    *hang.off) exec sleep 600 ;;
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


def start_study(command, delay, **popen):
    """`command` started in the background, each run of the fake tools
    delayed by `delay` seconds (FAKE_DELAY); its stdout discarded, its
    stderr kept as text unless `popen` says otherwise."""
    popen = dict(dict(stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True), **popen)
    return subprocess.Popen(command, env=dict(os.environ, FAKE_DELAY=delay), **popen)


def wait_for_rows(p, db, n, pause=0.1):
    """Waits until the study `p` has written `n` rows into `db`, or has
    ended, or 120 s have passed; returns that deadline."""
    deadline = time.time() + 120
    while count_rows(db) < n and time.time() < deadline and p.poll() is None:
        time.sleep(pause)
    return deadline


def interrupt(p):
    """Ctrl-C to the study `p`, which must exit with 130; returns its stderr."""
    p.send_signal(signal.SIGINT)
    _, err = p.communicate(timeout=120)
    assert p.returncode == 130, err
    return err


def resume(command, db, first, check):
    """Runs `command` to its end after a study stopped with the rows `first`
    in `db`: it succeeds, `check` passes on every row, and the first rows
    are kept as they were. Returns the finished process and the rows."""
    p = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    rows = rows_of(db)
    check(rows)
    for key, row in first.items():
        assert rows[key] == row
    return p, rows


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
    p = start_study(study_command(meshes, db, fake), "0.5")
    wait_for_rows(p, db, 4)
    assert "interrupted" in interrupt(p)
    first = rows_of(db)
    assert 4 <= len(first) < len(EXPECTED_KEYS)
    p, _ = resume(study_command(meshes, db, fake), db, first, check_rows)
    assert f"{len(first)} already in" in p.stderr


def test_killed_worker_loses_no_run(corpus, tmp_path):
    meshes, fake = corpus
    db = tmp_path / "study.sqlite"
    p = start_study(study_command(meshes, db, fake), "0.5")
    deadline = wait_for_rows(p, db, 3)
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


def runs_left(corpus_dir, wait=10.0):
    """The processes still running a flow on the corpus (dlf, the fake, its
    sleep), after up to `wait` seconds for them to go."""
    deadline = time.time() + wait
    while True:
        left = []
        for proc in psutil.process_iter(["cmdline"]):
            try:
                cmd = " ".join(proc.info["cmdline"] or [])
            except (psutil.NoSuchProcess, psutil.AccessDenied):
                continue
            if str(corpus_dir) in cmd and "discrete_lie_flow.study" not in cmd:
                left.append(cmd)
        if not left or time.time() > deadline:
            return left
        time.sleep(0.2)


def scratch_folders():
    return set(Path(tempfile.gettempdir()).glob("dlf-study-*"))


def test_interrupt_leaves_no_run_and_no_scratch(corpus, tmp_path):
    # Ctrl-C reaches the whole foreground process group (driver and dask's
    # processes): sent the same way here, once the runs have started (a
    # Ctrl-C during the local cluster's start is ignored, doc/python.md), at
    # five moments drawn once.
    meshes, fake = corpus
    before = scratch_folders()
    for i, delay in enumerate((0.3, 1.9, 0.0, 2.7, 1.2)):
        db = tmp_path / f"study{i}.sqlite"
        p = start_study(study_command(meshes, db, fake), "0.5", start_new_session=True)
        deadline = time.time() + 120
        while not os.path.isdir(str(db) + ".scratch") or not any(Path(str(db) + ".scratch").iterdir()):
            assert time.time() < deadline and p.poll() is None, "no run started"
            time.sleep(0.02)
        time.sleep(delay)
        os.killpg(p.pid, signal.SIGINT)
        _, err = p.communicate(timeout=120)
        assert p.returncode == 130, err
        assert "Traceback" not in err and "still alive" not in err, err
        assert err.strip().splitlines()[-1].endswith("run the same command again to resume") or \
            "interrupted before any run" in err, err
        assert runs_left(meshes) == [], f"runs left behind after Ctrl-C at {delay} s"
        assert not os.path.exists(str(db) + ".scratch")
    assert scratch_folders() == before


def test_killed_study_resumes_with_every_row_once(corpus, tmp_path):
    # The whole study (driver and workers) killed by SIGKILL: its runs die
    # with their workers, and the next study keeps every finished row as it
    # was, runs the others once, and removes the dead one's scratch folder.
    meshes, fake = corpus
    db = tmp_path / "study.sqlite"
    p = start_study(study_command(meshes, db, fake), "0.5", stderr=subprocess.DEVNULL, text=False,
                    start_new_session=True)
    wait_for_rows(p, db, 3)
    os.killpg(p.pid, signal.SIGKILL)
    p.wait(timeout=60)
    assert runs_left(meshes) == []
    first = rows_of(db)
    assert 3 <= len(first) < len(EXPECTED_KEYS)
    assert os.path.isdir(str(db) + ".scratch")  # left by the killed driver
    p, _ = resume(study_command(meshes, db, fake), db, first, check_rows)
    assert f"{len(first)} already in" in p.stderr
    assert not os.path.exists(str(db) + ".scratch")


def test_second_driver_on_one_database_refuses(corpus, tmp_path):
    meshes, fake = corpus
    db = tmp_path / "study.sqlite"
    first = start_study(study_command(meshes, db, fake), "0.5")
    wait_for_rows(first, db, 1)
    second = subprocess.run(study_command(meshes, db, fake), capture_output=True, text=True, timeout=120)
    assert second.returncode == 1
    assert f"another dlf-study (pid {first.pid}) is running on {db}" in second.stderr, second.stderr
    _, err = first.communicate(timeout=300)
    assert first.returncode == 0, err
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


# ---------------------------------------------------------------------------
# Runners (--runner) and the checks of the written maps (--check-outputs)
# ---------------------------------------------------------------------------

RUNNER_CONFIGS = ("alpha@disk", "beta@api", "gamma")


@pytest.fixture(scope="module")
def runner_corpus(tmp_path_factory):
    """disk/{plain,crash,hang,folds,broken,exc}.off and api/{plain,exc}.off,
    and a runner that, by the case's name, writes a valid report, crashes,
    hangs, reports folds, exits 1 without a report or reports an escaped
    exception; it sleeps $FAKE_DELAY first."""
    root = tmp_path_factory.mktemp("runner")
    corpus = root / "corpus"
    for sub, names in (("disk", ("plain", "crash", "hang", "folds", "broken", "exc")), ("api", ("plain", "exc"))):
        (corpus / sub).mkdir(parents=True)
        for n in names:
            (corpus / sub / f"{n}.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    runner = root / "runner"
    runner.write_text("""#!/bin/sh
# runner --run METHOD --case FILE --report OUT
sleep "${FAKE_DELAY:-0}"
method=$2; case=$4; out=$6
inv=0; status=ok
case "$case" in
  *crash.off) echo "runner about to crash" >&2; kill -SEGV $$ ;;
  *hang.off) sleep 600 ;;
  *folds.off) inv=2 ;;
  *broken.off) echo "runner: cannot load $case" >&2; exit 1 ;;
  *exc.off) status=exception ;;
esac
printf '{"status": "%s", "message": "%s on %s", "inverted": %s, "degenerate": 0, "nonfinite": false, "d_area": 2.5, "iterations": 7}\\n' \
  "$status" "$method" "$(basename "$case")" "$inv" > "$out"
""")
    runner.chmod(0o755)
    return corpus, str(runner)


def runner_command(corpus, db, runner, *extra):
    return [sys.executable, "-m", "discrete_lie_flow.study", "run", str(corpus), "--db", str(db), "--workers", "2",
            "--timeout", "3", "--runner", runner, "--memory-limit", "4", "-q",
            *[a for c in RUNNER_CONFIGS for a in ("--config", c)], *extra]


RUNNER_KEYS = ({(f"disk/{n}.off", c) for n in ("plain", "crash", "hang", "folds", "broken", "exc") for c in ("alpha", "gamma")}
               | {(f"api/{n}.off", c) for n in ("plain", "exc") for c in ("beta", "gamma")})


def check_runner_rows(rows):
    assert set(rows) == RUNNER_KEYS  # every (case, method) of its folders, once
    for (mesh, config), r in rows.items():
        name = mesh.split("/")[1]
        assert r["fits"] is None and r["command"].startswith(f"runner --run {config} --case {name}")
        if name == "crash.off":
            assert r["status"] == "crash" and r["exit_signal"] == signal.SIGSEGV and r["violation"] == "crash"
            assert "about to crash" in r["stderr_tail"] and r["report"] is None
        elif name == "hang.off":
            assert r["status"] == "timeout" and r["exit_signal"] == signal.SIGKILL and r["violation"] == "hang"
        elif name == "broken.off":
            assert r["status"] == "error" and r["exit_code"] == 1 and r["violation"] == "runner error"
            assert "cannot load" in r["error"]
        elif name == "exc.off":
            assert r["status"] == "error" and r["error"] == "exception" and r["violation"] == "exception escaped"
        else:
            report = json.loads(r["report"])
            assert report["message"] == f"{config} on {name}"
            assert r["status"] == "ok" and r["d_area"] == 2.5 and r["iterations"] == 7 and r["nonfinite"] == 0
            assert r["checked_inverted"] == r["inverted_faces"] == (2 if name == "folds.off" else 0)
            assert r["violation"] == ("inverted/degenerate faces in an ok result" if name == "folds.off" else None)


def test_runner_configurations(runner_corpus, tmp_path):
    """Interrupted, resumed, run again: every row once, as it was first written."""
    corpus, runner = runner_corpus
    db = tmp_path / "study.sqlite"
    p = start_study(runner_command(corpus, db, runner), "0.3")
    wait_for_rows(p, db, 3, pause=0.05)
    interrupt(p)
    first = rows_of(db)
    assert 3 <= len(first) < len(RUNNER_KEYS)
    _, rows = resume(runner_command(corpus, db, runner), db, first, check_runner_rows)
    again = [a for a in runner_command(corpus, db, runner) if a != "-q"]  # the progress line says what is left
    p = subprocess.run(again, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0 and f"{len(RUNNER_KEYS)} already in" in p.stderr and "0 to run" in p.stderr, p.stderr
    assert rows_of(db) == rows
    summary = study.summary_markdown(sqlite3.connect(db))
    assert f"Violations among the checked runs ({len(RUNNER_KEYS)}): 12." in summary  # 6 kinds x 2
    # A folder that holds no mesh is a mistake, not an empty study.
    p = subprocess.run(runner_command(corpus, db, runner, "--config", "delta@sphere"), capture_output=True, text=True,
                       timeout=120)
    assert p.returncode == 1 and "delta@sphere: no mesh under that folder" in p.stderr


def test_exact_orientation_filters():
    """The filtered predicates against exact rationals, on triangles made
    nearly flat at the rounding level (where the filter must defer)."""
    import random
    from fractions import Fraction

    rng = random.Random(5)
    for _ in range(3000):
        a = (rng.uniform(-1, 1), rng.uniform(-1, 1))
        b = (rng.uniform(-1, 1), rng.uniform(-1, 1))
        t = rng.uniform(-2, 2)
        c = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
        if rng.random() < 0.5:
            c = (c[0] + rng.choice((-1, 1)) * rng.random() * 1e-15, c[1])
        F = [[Fraction(x) for x in p] for p in (a, b, c)]
        exact = (F[0][0] - F[2][0]) * (F[1][1] - F[2][1]) - (F[0][1] - F[2][1]) * (F[1][0] - F[2][0])
        assert study.orient2d(a, b, c) == (exact > 0) - (exact < 0)
        p3 = [tuple(rng.uniform(-1, 1) for _ in range(3)) for _ in range(2)]
        s = rng.uniform(-2, 2)
        q = tuple(p3[0][k] + s * p3[1][k] for k in range(3))  # det[a, b, a + s b] = 0 up to rounding
        G = [[Fraction(x) for x in p] for p in (p3[0], p3[1], q)]
        det = (G[0][0] * (G[1][1] * G[2][2] - G[1][2] * G[2][1]) + G[1][0] * (G[2][1] * G[0][2] - G[2][2] * G[0][1])
               + G[2][0] * (G[0][1] * G[1][2] - G[0][2] * G[1][1]))
        assert study.orient3d_origin(p3[0], p3[1], q) == (det > 0) - (det < 0)
    assert study.orient2d((0.0, 0.0), (1.0, 0.0), (2.0, 0.0)) == 0
    assert study.orient2d((0.0, 0.0), (1.0, 0.0), (0.5, 1e-300)) == 1


@pytest.fixture(scope="module")
def checked_corpus(tmp_path_factory):
    """nefertiti and sphere.off as they are, and copies on which a wrapper of
    dlf breaks a promise: a folded face in an ok map (fold), a map left by
    a failed run (stray), exit 0 with a report that says otherwise (lie), a
    face with an index out of range (garble)."""
    root = tmp_path_factory.mktemp("checked")
    corpus = root / "corpus"
    corpus.mkdir()
    copy_meshes(corpus)
    for name in ("fold", "stray", "lie", "garble"):
        shutil.copy(corpus / "nefertiti.off", corpus / f"{name}.off")
    fake = root / "fake-dlf"
    edit = root / "edit.py"
    edit.write_text("""import json, sys
what, path = sys.argv[1], sys.argv[2]
if what == "fold":  # swap two corners of the first face
    lines = open(path).read().split("\\n")
    i = next(k for k, l in enumerate(lines) if l.startswith("f "))
    w = lines[i].split()
    lines[i] = " ".join([w[0], w[2], w[1], w[3]])
    open(path, "w").write("\\n".join(lines))
else:  # the report says the flow failed
    r = json.load(open(path))
    r["status"] = "ERROR_FLOW_STALLED"
    json.dump(r, open(path, "w"))
""")
    fake = root / "fake-dlf"
    fake.write_text(f"""#!/bin/sh
"{DLF}" "$@"; code=$?
out=""; dom=""; rep=""; prev=""
for a in "$@"; do
  case "$prev" in -o) out=$a ;; --domain-mesh) dom=$a ;; --report) rep=$a ;; esac
  prev=$a
done
[ "$1" = info ] && exit $code
case "$2" in
  *fold.off) for m in $out $dom; do "{sys.executable}" "{edit}" fold "$m"; done ;;
  *stray.off) echo "dlf: error: made up" >&2; exit 1 ;;
  *lie.off) "{sys.executable}" "{edit}" report "$rep"; exit 0 ;;
  *garble.off) for m in $out $dom; do echo "f 1/1 2/2 999999/999999" >> "$m"; done ;;
esac
exit $code
""")
    fake.chmod(0o755)
    return corpus, str(fake)


def test_check_outputs(checked_corpus, tmp_path):
    corpus, fake = checked_corpus
    db = tmp_path / "study.sqlite"
    p = subprocess.run([sys.executable, "-m", "discrete_lie_flow.study", "run", str(corpus), "--db", str(db),
                        "--workers", "2", "--timeout", str(TIMEOUT), "--dlf", fake, "--check-outputs", "-q",
                        "--config", "disk-certified", "--config", "disk-paper", "--config", "sphere"],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    rows = rows_of(db)
    for config in ("disk-certified", "disk-paper"):
        r = rows[("nefertiti.off", config)]
        assert r["status"] == "ok" and r["violation"] is None, r
        assert r["checked_inverted"] == 0 and r["checked_degenerate"] == 0 and r["nonfinite"] == 0
        assert r["stray_output"] == 0 and r["exit_mismatch"] == 0 and r["rejected_by_exact_check"] == 0
        assert rows[("fold.off", config)]["violation"] == "inverted/degenerate faces in an ok result"
        assert rows[("stray.off", config)]["violation"] == "output file left by a failed run"
        assert rows[("lie.off", config)]["violation"] == "exit code disagrees with report status"
        assert rows[("garble.off", config)]["violation"] == "unreadable output"
    # The study's d_area of the written map is the report's (the certified mode's map is the caller's mesh).
    r = rows[("nefertiti.off", "disk-certified")]
    assert abs(r["map_d_area"] - r["d_area"]) < 1e-9 * r["d_area"], r
    assert rows[("nefertiti.off", "disk-paper")]["map_d_area"] >= 2
    # One face of each checked map swapped: one fold (the paper mode's check is of its flowing mesh).
    assert rows[("fold.off", "disk-certified")]["checked_inverted"] == 1
    assert rows[("fold.off", "disk-paper")]["checked_inverted"] == 1
    r = rows[("sphere.off", "sphere")]
    assert r["status"] in ("ok", "not_converged") and r["checked_inverted"] == 0 and r["violation"] is None, r
    assert rows[("nefertiti.off", "sphere")]["status"] == "not_applicable"


ROBUSTNESS_CORPUS = os.environ.get("DLF_ROBUSTNESS_CORPUS")  # set by CTest when the benchmarks are built


def test_robustness_study_slice(tmp_path):
    """Two classes of the robustness corpus (tiny: 4 disk and 1 sphere case;
    folded_initial_map: 6 library-API cases) through dlf-study with the real
    runner, as benchmark/robustness.sh runs them, and its tables. Registered
    as the test python_study_corpus where the benchmarks are built; run
    without its runner it fails (never a skip)."""
    assert ROBUSTNESS_CORPUS, "DLF_ROBUSTNESS_CORPUS is not set: build with -DDLF_BUILD_BENCHMARK=ON (ctest python_study_corpus)"
    corpus = tmp_path / "corpus"
    cases = []
    for only in ("tiny", "folded_initial_map"):
        part = tmp_path / only
        subprocess.run([ROBUSTNESS_CORPUS, "--data", MESHES, "--only", only, "--corpus-only", str(part)], check=True,
                       capture_output=True, timeout=120)
        shutil.copytree(part, corpus, dirs_exist_ok=True)
        cases += json.loads((part / "cases.json").read_text())
    (corpus / "cases.json").write_text(json.dumps(cases))
    db = tmp_path / "study.sqlite"
    configs = ("disk-certified@disk", "disk-paper@disk", "sphere@sphere", "dlf_api@api", "cgal_mvc@disk",
               "cgal_arap@disk")
    p = subprocess.run([sys.executable, "-m", "discrete_lie_flow.study", "run", str(corpus), "--db", str(db),
                        "--workers", "2", "--timeout", "60", "--memory-limit", "4", "--dlf", DLF,
                        "--runner", ROBUSTNESS_CORPUS, "--every-config", "--check-outputs", "-q",
                        *[a for c in configs for a in ("--config", c)]], capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    rows = rows_of(db)
    assert len(rows) == 4 * 4 + 1 + 6
    api = {k[0].split("__")[1]: r for k, r in rows.items() if k[1] == "dlf_api"}
    for name in ("nefertiti_mirrored.off", "nefertiti_identity_tutte.off"):
        r = api[name]
        assert r["status"] == "ok" and r["checked_inverted"] == 0 and r["checked_degenerate"] == 0, r
        assert 2 <= r["d_area"] < 2.01 and r["violation"] is None
    for name in ("nefertiti_vertex_reflected.off", "nefertiti_two_vertices_coincide.off",
                 "nefertiti_all_collapsed.off", "nefertiti_nan_uv.off"):
        r = api[name]
        assert r["status"] == "flow_error" and r["error"] == "ERROR_INITIAL_MAP_FOLDED" and r["violation"] is None, r
    r = rows[("disk/tiny__one_flat_triangle.off", "disk-certified")]
    assert r["error"] == "ERROR_DEGENERATE_INPUT" and r["violation"] is None
    r = rows[("disk/tiny__two_triangles.off", "cgal_mvc")]
    assert r["status"] == "ok" and r["checked_inverted"] == 0 and r["violation"] is None
    assert all(r["violation"] is None for k, r in rows.items() if not k[1].startswith("cgal"))
    report = Path(__file__).resolve().parents[2] / "benchmark" / "robustness_report.py"
    out = tmp_path / "table.md"
    p = subprocess.run([sys.executable, str(report), str(db), str(corpus / "cases.json"), "--markdown", str(out)],
                       capture_output=True, text=True, timeout=60)
    # CGAL's iterative authalic is not in this study: its 4 rows are missing (exit 1); no DLF violation.
    assert p.returncode == 1 and "DLF violations 0" in p.stdout and "missing 4" in p.stdout, p.stdout + p.stderr
    table = out.read_text()
    assert "| folded_initial_map |  |  |  | 2/6, ERROR_INITIAL_MAP_FOLDED |" in table
    assert "| tiny | nefertiti" not in table and "| tiny | one_quad | disk | dlf_disk | cli_error (1) |" in table


def test_memory_limit(tmp_path):
    """--memory-limit caps each run's address space: 6 GiB cannot be had
    under a 4 GiB limit, 100 MiB can."""
    code, sig, err, _, timed_out = study._run_tool([sys.executable, "-c", "bytearray(6 << 30)"], 60, str(tmp_path), 4)
    assert code == 1 and sig is None and not timed_out and "MemoryError" in err
    code, _, err, _, _ = study._run_tool([sys.executable, "-c", "bytearray(100 << 20)"], 60, str(tmp_path), 4)
    assert code == 0, err


def test_build_tree_script_is_not_shadowed_by_the_sources():
    """<build>/python/dlf-study imports the built package even when the
    source folder python/ (the same package without its compiled module)
    comes first on the path, as it does when run from a checkout, and with
    PYTHONSAFEPATH set (the script's own folder then is not on the path)."""
    build_python = Path(study.__file__).resolve().parent.parent
    script = build_python / "dlf-study"
    assert script.is_file() and os.access(script, os.X_OK), script
    sources = Path(__file__).resolve().parent.parent
    assert (sources / "discrete_lie_flow" / "__init__.py").is_file()
    env = dict(os.environ, PYTHONPATH=str(sources), PYTHONSAFEPATH="1")
    p = subprocess.run([str(script), "configs"], cwd=str(sources), env=env, capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    assert "disk-square" in p.stdout, p.stdout


# --- report and export, on a database written here (no runs) -----------------------

def table_rows():
    long_refusal = ("'x.off': not a disk: 2 connected components (keep one), 219 border edges; at least one "
                    "component is closed; 'dlf info' lists them | and this text runs on past two hundred characters "
                    "so that a cut would fall in the middle of a word such as this")
    base = dict(vertices=10, faces=16, iterations=5, finished_at="2026-01-01T00:00:00Z", command="dlf")
    return [
        dict(base, mesh="a.off", config="disk-certified", status="ok", d_area=2.004, inverted_faces=0, seconds=0.5),
        dict(base, mesh="b.off", config="disk-certified", status="not_converged", d_area=2.2, inverted_faces=0, seconds=0.7),
        dict(base, mesh="a.off", config="disk-paper", status="ok", d_area=2.001, inverted_faces=373, seconds=0.4),
        dict(base, mesh="b.off", config="disk-paper", status="ok", d_area=2.003, inverted_faces=0, seconds=0.6,
             checked_inverted=2),
        dict(base, mesh="c.off", config="disk-paper", status="ok", d_area=2.002, inverted_faces=0, seconds=0.3),
        dict(base, mesh="x.off", config="disk-certified", status="input_error", error=long_refusal,
             stderr_tail="dlf: error: " + long_refusal),
    ], long_refusal


def test_report_lists_only_fold_free_maps_as_valid(tmp_path):
    rows, long_refusal = table_rows()
    db = study.open_db(str(tmp_path / "t.sqlite"))
    for r in rows:
        study.insert_row(db, r)
    summary = study.summary_markdown(db)
    valid = summary[summary.index("Valid maps"):summary.index("Maps written with inverted")]
    assert "| disk-certified | 2 | 1 |" in valid
    assert "| disk-paper | 1 | 1 | 2.002 | 2.002 |" in valid  # c.off alone: a.off folds 373, b.off's map 2 faces
    folded = summary[summary.index("Maps written with inverted"):]
    assert "| a.off | disk-paper | ok | 373 |" in folded and "| b.off | disk-paper | ok | 2 |" in folded
    # The refusal in full, on one line, its pipe escaped.
    assert " ".join(long_refusal.split()).replace("|", "/") in summary
    assert study.box_labels(["disk-certified", "disk-paper"], [[0.1, 0.2], [0.3]]) == \
        ["disk-certified\nn = 2", "disk-paper\nn = 1"]


def test_export_csv(tmp_path):
    import csv
    rows, long_refusal = table_rows()
    path = tmp_path / "t.sqlite"
    db = study.open_db(str(path))
    for r in rows:
        study.insert_row(db, r)
    db.close()
    out = tmp_path / "runs.csv"
    p = subprocess.run([sys.executable, "-m", "discrete_lie_flow.study", "export", str(path), "--csv", str(out)],
                       capture_output=True, text=True, timeout=60)
    assert p.returncode == 0 and f"wrote {out} (6 runs)" in p.stdout, p.stderr
    table = list(csv.reader(open(out, newline="")))
    assert tuple(table[0]) == study.EXPORT_COLUMNS and "report" not in table[0]
    got = [dict(zip(table[0], r)) for r in table[1:]]
    assert [(g["config"], g["mesh"]) for g in got] == sorted((r["config"], r["mesh"]) for r in rows)
    by_key = {(g["mesh"], g["config"]): g for g in got}
    assert by_key[("a.off", "disk-paper")]["inverted_faces"] == "373"
    assert float(by_key[("a.off", "disk-certified")]["d_area"]) == 2.004
    assert by_key[("x.off", "disk-certified")]["error"] == long_refusal  # whole, with its pipe, quoted
    assert by_key[("x.off", "disk-certified")]["d_area"] == ""           # null
    # No database, or no such folder: an error, no file.
    p = subprocess.run([sys.executable, "-m", "discrete_lie_flow.study", "export", str(path), "--csv",
                        str(tmp_path / "nowhere" / "r.csv")], capture_output=True, text=True, timeout=60)
    assert p.returncode != 0 and "does not exist" in p.stderr and not (tmp_path / "nowhere").exists()
    assert not [f for f in os.listdir(tmp_path) if f.startswith(".")]  # no temporary left
