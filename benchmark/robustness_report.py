#!/usr/bin/python3
# Copyright (c) 2026 The Discrete Lie Flow authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The tables of doc/robustness.md ("Results"), from the SQLite database of
the robustness study (benchmark/robustness.sh runs it through dlf-study):

    robustness_report.py STUDY.sqlite CORPUS/cases.json --markdown table.md

cases.json (written by `robustness_corpus --corpus-only CORPUS`) gives the
cases in corpus order with their class, name and kind; the rows of the
database are keyed by the case's file below CORPUS. Prints the counts; exit
status 0, 3 when DLF has a violation, 1 when runs are missing.
"""

import argparse
import json
import re
import signal
import sqlite3
import sys

# The study's configurations, by the methods' names in the tables.
METHODS = {
    "disk-certified": "dlf_disk", "disk-paper": "dlf_disk_paper", "sphere": "dlf_sphere", "dlf_api": "dlf_api",
    "cgal_iterative_authalic": "cgal_iterative_authalic", "cgal_arap": "cgal_arap", "cgal_mvc": "cgal_mvc",
}
ORDER = list(METHODS.values())
# Which methods a case of each kind is given to.
KIND_METHODS = {
    "disk": ("dlf_disk", "dlf_disk_paper", "cgal_iterative_authalic", "cgal_arap", "cgal_mvc"),
    "sphere": ("dlf_sphere",),
    "api": ("dlf_api",),
}
COLUMNS = ("mesh", "config", "status", "d_area", "seconds", "error", "exit_code", "exit_signal", "stderr_tail",
           "report", "checked_inverted", "checked_degenerate", "nonfinite", "rejected_by_exact_check", "violation", "map_d_area")


def signal_name(number):
    try:
        return signal.Signals(number).name
    except (ValueError, TypeError):
        return str(number)


def shown_status(r):
    """The status as the table shows it: the report's status name (or the
    runner's), `cli_error` for an input the tool refused before its
    parameterizer ran (no report), crash(SIGNAL), hang."""
    if r["status"] == "crash":
        return f"crash({signal_name(r['exit_signal'])})"
    if r["status"] == "timeout":
        return "hang"
    report = json.loads(r["report"]) if r["report"] else None
    if r["method"].startswith("cgal") or r["method"] == "dlf_api":
        return report["status"] if report else "runner error"
    if report is not None:
        return f"{report.get('status', '?')} ({r['exit_code']})"
    return f"{'cli_error' if r['exit_code'] == 1 else 'exit'} ({r['exit_code']})"


def message(r, path):
    report = json.loads(r["report"]) if r["report"] else None
    text = report.get("message", "") if report else ""
    if not text and r["stderr_tail"]:
        lines = [l for l in r["stderr_tail"].splitlines() if l.strip()]
        text = lines[0] if lines else ""
    text = re.sub(r"[^\s'\"]*" + re.escape(path), "INPUT", text).replace("|", "/")
    return text if len(text) <= 110 else text[:107] + "..."


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("db")
    p.add_argument("cases")
    p.add_argument("--markdown", metavar="OUT.md")
    args = p.parse_args(argv)

    with open(args.cases, encoding="utf-8") as f:
        cases = json.load(f)
    by_file = {c["file"]: c for c in cases}
    db = sqlite3.connect(f"file:{args.db}?mode=ro", uri=True)
    rows = {}
    for values in db.execute(f"SELECT {', '.join(COLUMNS)} FROM runs"):
        r = dict(zip(COLUMNS, values))
        r["method"] = METHODS.get(r["config"], r["config"])
        rows[(r["mesh"], r["method"])] = r
    db.close()

    runs, missing, violations = [], [], []
    for c in cases:
        for m in KIND_METHODS[c["kind"]]:
            r = rows.get((c["file"], m))
            if r is None:
                missing.append(f"{m} on {c['file']}")
                continue
            r["case"] = c
            runs.append(r)
    extra = len(rows) - len(runs)
    dlf_runs = [r for r in runs if r["method"].startswith("dlf")]
    dlf_ok = sum(r["status"] == "ok" for r in dlf_runs)
    rejected = sum(r["rejected_by_exact_check"] or 0 for r in dlf_runs)
    for r in dlf_runs:
        if r["violation"]:
            c = r["case"]
            violations.append(f"{r['method']} on {c['class']}/{c['case']} (`{c['file']}`): {r['violation']} "
                              f"[{shown_status(r)}]")

    md = [f"Corpus: {len(cases)} cases; {len(runs)} runs; {len(dlf_runs)} DLF runs, {dlf_ok} ok."
          + (f" **Missing runs: {len(missing)}.**" if missing else ""), ""]
    md += ["**DLF violations (crash, hang, NaN output, folds in an ok result, exception, stray output file, exit code "
           f"vs report): {len(violations)}**", ""]
    md += [f"- {v}" for v in violations]
    md += ["", "Ablation: trial steps that the double-precision test accepted and the exact predicate refused, summed "
           f"over all DLF runs (`rejected_by_exact_check`): **{rejected}**", ""]

    md += ["### Per class and method", "",
           "Each cell: ok runs / runs; then `inv` = runs with inverted or degenerate faces in the output (counted for "
           "every output, also from CGAL's methods that return OK), `NaN`, `crash`/`hang`, and the distinct error "
           "statuses.", ""]
    md += ["| class | " + " | ".join(ORDER) + " |", "|---|" + "---|" * len(ORDER)]
    classes = list(dict.fromkeys(c["class"] for c in cases))
    for cl in classes:
        cells = []
        for m in ORDER:
            mine = [r for r in runs if r["case"]["class"] == cl and r["method"] == m]
            if not mine:
                cells.append("")
                continue
            ok = sum(r["status"] == "ok" for r in mine)
            inv = sum((r["checked_inverted"] or 0) > 0 or (r["checked_degenerate"] or 0) > 0 for r in mine)
            nan = sum(bool(r["nonfinite"]) for r in mine)
            crash = sum(r["status"] == "crash" for r in mine)
            hang = sum(r["status"] == "timeout" for r in mine)
            errs = sorted({shown_status(r).split(" (")[0] for r in mine
                           if r["status"] not in ("ok", "crash", "timeout")} - {"skipped"})
            cell = f"{ok}/{len(mine)}"
            for n, what in ((inv, "inv"), (nan, "NaN"), (crash, "crash"), (hang, "hang")):
                if n:
                    cell += f", **{what} {n}**"
            cells.append(cell + "".join(", " + e for e in errs))
        md.append(f"| {cl} | " + " | ".join(cells) + " |")

    md += ["", "### Per case", "",
           "status (exit code for the CLI) · inverted+degenerate faces of the output (exact predicate) · d_area of the "
           "output (optimum 2; computed from the written map alike for all planar methods, by `dlf-study "
           "--check-outputs` for `dlf disk` and by the runner for the others; from the report for the sphere) · "
           "seconds of the whole process. `skipped`: CGAL cannot load the file as a mesh with a border.", "",
           "| class | case | kind | method | status | inv | d_area | s | message |", "|---|---|---|---|---|---|---|---|---|"]
    for r in runs:
        c = r["case"]
        st = shown_status(r)
        if r["violation"]:
            st = f"**{st}: {r['violation']}**"
        inv = ""
        if r["checked_inverted"] is not None:
            inv = str(r["checked_inverted"] + (r["checked_degenerate"] or 0))
        d_area = r["map_d_area"] if r["method"] in ("dlf_disk", "dlf_disk_paper") else r["d_area"]
        d = f"{d_area:.4f}" if d_area is not None and r["status"] in ("ok", "not_converged") else ""
        s = f"{r['seconds']:.3f}" if r["seconds"] is not None else ""
        md.append(f"| {c['class']} | {c['case']} | {c['kind']} | {r['method']} | {st} | {inv} | {d} | {s} | "
                  f"{message(r, c['file'].split('/')[-1])} |")
    text = "\n".join(md) + "\n"
    if args.markdown:
        with open(args.markdown, "w", encoding="utf-8") as f:
            f.write(text)
    print(f"runs {len(runs)}, DLF runs {len(dlf_runs)} (ok {dlf_ok}), DLF violations {len(violations)}, "
          f"rejected_by_exact_check total {rejected}" + (f", missing {len(missing)}" if missing else "")
          + (f", rows not in the corpus {extra}" if extra else ""))
    for v in violations:
        print("  " + v)
    for m in missing[:20]:
        print("  missing: " + m)
    if violations:
        return 3
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
