#!/usr/bin/env python3
"""The paper's experiments that the `dlf` tool alone reproduces, as Markdown.

    paper_runs.py DLF MESHES {quick,full} SECTION...

Sections: paper_mode (the stabilised flow on every disk mesh), sphere_literal
(Algorithm 1 on the sphere), sphere_variants (the stabilised flow on the sphere
with one option changed at a time), table2 (Table 2, Figs. 12-13: the literal Algorithm 1, fixed steps
against the adaptive step), mu (Table 2's adaptive column for mu 0.2-0.8),
modes (Tables 3-5: the certified, paper and literal flows on the peers'
meshes, same start), sphere_starts (Figs. 8-9: the sphere from the Tutte and
the conformal start), disk_starts (Figs. 17-18's start: Tutte against a
conformal disk map), fig10, fig14, fig15_16. Every column printed is
deterministic (iterations, stop reasons, D_area to four decimals, folds): no
timing, so that `benchmark/paper.sh --quick --check` can compare the output.
Run single-threaded (paper.sh sets the thread limits).
"""
import json
import math
import os
import subprocess
import sys
import tempfile

DLF, MESHES, SIZE = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), sys.argv[3]
SECTIONS = sys.argv[4:]
QUICK = SIZE == "quick"
TMP = tempfile.mkdtemp()

# Meshes per section: the quick set runs in well under a minute on one core.
CFG = {
    "quick": {
        "table2": ["nefertiti", "patch-23", "blob"], "table2_cap": 2000,
        "steps": ["1", "0.1", "0.01", "0.001"],
        "mu": ["nefertiti", "patch-23"], "mu_cap": 2000,
        "disk": ["nefertiti", "patch-23"], "sphere": ["sphere"],
        "fig14": "nefertiti", "fig15_disk": "nefertiti", "fig15_sphere": "sphere",
        "factors": ["0.25", "1", "4", "16"], "fig10_cells": 8, "paper_mode": ["nefertiti", "patch-23"],
        "sphere_literal": ["sphere", "ellipsoid"],
    },
    "full": {
        "table2": ["nefertiti", "patch-23", "blob", "patch-30", "plane", "mushroom", "lion-head", "mannequin-devil"],
        "table2_cap": 2000,
        "steps": ["1", "0.1", "0.01", "0.001"],
        "mu": ["nefertiti", "patch-30", "plane", "mushroom", "lion-head"], "mu_cap": 2000,
        "disk": ["nefertiti", "patch-30", "plane", "three_peaks", "mushroom", "lion-head", "mannequin-devil"],
        "sphere": ["sphere", "triceratops", "cow", "homer", "bear", "armadillo"],
        "fig14": "nefertiti", "fig15_disk": "nefertiti", "fig15_sphere": "blobby",
        "factors": ["0.25", "0.5", "1", "2", "4", "8", "16"], "fig10_cells": 16, "paper_mode": None,
        "sphere_literal": ["sphere", "ellipsoid", "blobby", "cow", "bear"],
        "sphere_variants": ["sphere", "blobby", "triceratops", "cow", "bear", "armadillo"],
    },
}[SIZE]


def g(x):
    """D_area and the like: four decimals, or three significant digits when huge."""
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "—"
    return f"{x:.4f}" if abs(x) < 100 else f"{x:.3g}"


def dlf(cmd, mesh, *args, cwd=None):
    """Runs `dlf CMD MESH ARGS --report` and returns the report (or None)."""
    rep = os.path.join(TMP, "r.json")
    if os.path.exists(rep):
        os.remove(rep)
    subprocess.run([DLF, cmd, mesh, *args, "-q", "--report", rep], cwd=cwd,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        return json.load(open(rep))
    except (OSError, ValueError):
        return None


def off(name):
    return os.path.join(MESHES, name + ".off")


def outcome(r, cap):
    """Table 2's cell: iterations, C (collapse after k steps) or >cap."""
    if r is None:
        return "error"
    s = r["stop_reason"]
    if s == "converged":
        return str(r["iterations"])
    if s == "collapsed":
        return f"C ({r['iterations']})"
    if s == "iteration_cap":
        return f">{cap}"
    return f"{s} ({r['iterations']})"


def best(r):
    h = [(x["d_area"], x["iteration"]) for x in r.get("history", [])] + [(r["initial_domain_d_area"], 0)]
    return min(h)


def folds(r):
    return r.get("caller_inverted_faces", "—")


def literal_row(m, cap, variants):
    """One table row: the literal flow on disk mesh m (circle, Tutte) once per list of extra options."""
    cells, faces = [], ""
    for extra in variants:
        r = dlf("disk", off(m), "--mode", "literal", "--border", "circle", "--max-iterations", str(cap), "--history", *extra)
        if r is None:
            cells.append("error")
            continue
        faces = f"{r['faces']:,}"
        cells.append(f"{outcome(r, cap)} [{g(best(r)[0])}]")
    return f"| {m} | {faces} | " + " | ".join(cells) + " |"


def table2():
    cap = CFG["table2_cap"]
    steps = CFG["steps"]
    out = ["### Table 2, Figs. 12-13: literal Algorithm 1, fixed steps against the adaptive step", "",
           f"`dlf disk MESH --mode literal --border circle [--fixed-step X] --max-iterations {cap} --history`, Tutte start. "
           "Cell: iterations to the stop rule ‖h_M − h_Ω‖² < 1e-3; `C (k)`: collapsed after k accepted steps (the paper's C); "
           f"`>{cap}`: the cap. In brackets: the lowest D_area along the run.", "",
           "| mesh | faces | " + " | ".join(steps) + " | adaptive (μ 0.8) |",
           "|---|---:|" + "---|" * (len(steps) + 1)]
    for m in CFG["table2"]:
        out.append(literal_row(m, cap, [["--fixed-step", x] for x in steps] + [[]]))
    out += ["", "The paper (Table 2, 11K–470K faces): 0.1 collapses on all 11 models; 0.01 takes 369–681 iterations "
            "or collapses (4 of 11); 0.001 takes more than 2000 (3975 on Chinese lion, 4050 on Bodhisattva) or "
            "collapses (Dragon head, Horse); adaptive 13–133. Fig. 12 (David): the adaptive step takes 25 iterations "
            "against 548; Fig. 13 (Totoro): 37.", ""]
    return out


def mu():
    cap = CFG["mu_cap"]
    mus = ["0.2", "0.4", "0.6", "0.8"]
    out = ["### Table 2's adaptive column for μ 0.2–0.8 (§5.4's range)", "",
           f"`dlf disk MESH --mode literal --border circle --mu M --max-iterations {cap} --history`, Tutte start. "
           "Cell as in Table 2 above; in brackets the lowest D_area along the run.", "",
           "| mesh | faces | " + " | ".join(f"μ {m}" for m in mus) + " |", "|---|---:|" + "---|" * len(mus)]
    for m in CFG["mu"]:
        out.append(literal_row(m, cap, [["--mu", u] for u in mus]))
    out += ["", "The paper: adaptive 13–133 iterations with μ in 0.2–0.8 (§5.4; it does not say which μ Table 2 used).", ""]
    return out


def mode_row(r):
    if r is None:
        return "error | | | |"
    if r["stop_reason"] == "not_run":  # the start refused, e.g. ERROR_INITIAL_MAP_FOLDED
        return f"not run: {r['status']} | | | |"
    d = (r.get("final") or {}).get("d_area")
    return f"{r['stop_reason']} | {r['iterations']} | {g(d)} | {folds(r)}"


def modes():
    out = ["### Tables 3–5: the three flows from the same start", "",
           "`dlf disk MESH --border circle --mode M` (Tutte start) and `dlf sphere MESH --mode M` (the library's start): "
           "the literal Algorithm 1 (`literal`), the stabilised paper flow (`paper`) and the default (`certified`). "
           "D_area and folds on the caller's triangles. The optimal-transport peer's columns are in "
           "`paper_experiments.md` (`benchmark/paper_tables.sh`).", "",
           "| mesh | domain | faces | start D_area | mode | stop | iterations | D_area | caller folds |",
           "|---|---|---:|---:|---|---|---:|---:|---:|"]
    for cmd, meshes in (("disk", CFG["disk"]), ("sphere", CFG["sphere"])):
        for m in meshes:
            for mode in ("literal", "paper", "certified"):
                args = ["--mode", mode] + (["--border", "circle"] if cmd == "disk" else [])
                r = dlf(cmd, off(m), *args)
                faces = f"{r['faces']:,}" if r else ""
                start = g((r.get("initial") or {}).get("d_area")) if r else ""
                out.append(f"| {m} | {cmd} | {faces} | {start} | {mode} | {mode_row(r)} |")
    out += ["", "The paper: Table 4, D_area of DLFC 2.02–2.09, DLFS 2.01–2.24, OMT 2.04–3.19; Table 5 (sphere), "
            "DLF D_area 2.01–2.18, Area_total 0.06–0.21.", ""]
    return out


def starts(cmd):
    if cmd == "sphere":
        title = "### Figs. 8–9: the sphere from the Tutte and the conformal start"
        how = "`dlf sphere MESH --mode M --start S`"
        meshes, variants = CFG["sphere"], [("tutte", ["--start", "tutte"]), ("conformal", ["--start", "conformal"])]
    else:
        title = "### Figs. 17–18's start: Tutte against a conformal disk map"
        how = "`dlf disk MESH --border circle --mode M --init I` (I: `tutte`, or `dcp`, the discrete conformal map onto the circle)"
        meshes, variants = CFG["disk"], [("tutte", ["--init", "tutte", "--border", "circle"]),
                                         ("conformal", ["--init", "dcp", "--border", "circle"])]
    out = [title, "", how + ". D_area and folds on the caller's triangles.", "",
           "| mesh | faces | start | start D_area | mode | stop | iterations | D_area | caller folds |",
           "|---|---:|---|---:|---|---|---:|---:|---:|"]
    for m in meshes:
        for sname, sargs in variants:
            for mode in ("literal", "paper", "certified"):
                r = dlf(cmd, off(m), "--mode", mode, *sargs)
                faces = f"{r['faces']:,}" if r else ""
                start = g((r.get("initial") or {}).get("d_area")) if r else ""
                out.append(f"| {m} | {faces} | {sname} | {start} | {mode} | {mode_row(r)} |")
    out.append("")
    return out


def fig10():
    n = CFG["fig10_cells"]
    idx, pts = {}, []
    for j in range(2 * n + 1):
        for i in range(2 * n + 1):
            x, y = i / n, j / n
            if x > 1 and y > 1:
                continue
            idx[(i, j)] = len(pts)
            pts.append((x, y))
    faces = []
    for j in range(2 * n):
        for i in range(2 * n):
            c = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            if not all(k in idx for k in c) or (i + 0.5) / n > 1 and (j + 0.5) / n > 1:
                continue
            a, b, cc, d = (idx[k] for k in c)
            faces += [(a, b, cc), (a, cc, d)] if (i + j) % 2 == 0 else [(a, b, d), (b, cc, d)]
    z = lambda x, y: 1.5 * math.exp(-((x - 0.5) ** 2 + (y - 0.5) ** 2) / 0.08)
    with open(os.path.join(TMP, "L.off"), "w") as f:
        f.write(f"OFF\n{len(pts)} {len(faces)} 0\n")
        for x, y in pts:
            f.write(f"{x} {y} {z(x, y)}\n")
        for t in faces:
            f.write("3 %d %d %d\n" % t)
    with open(os.path.join(TMP, "L_uv.obj"), "w") as f:
        for x, y in pts:
            f.write(f"v {x} {y} {z(x, y)}\nvt {x} {y}\n")
        for t in faces:
            f.write("f %d/%d %d/%d %d/%d\n" % (t[0] + 1, t[0] + 1, t[1] + 1, t[1] + 1, t[2] + 1, t[2] + 1))
    out = ["### Fig. 10: a non-convex domain", "",
           f"The L-shaped grid of `benchmark/fig10.sh` ({n} cells a unit, {len(faces):,} triangles), from its own flat "
           "projection (`dlf disk L.off --init-uv L_uv.obj --mode M`), the border sliding along the L.", "",
           "| mode | stop | iterations | D_area start | D_area | caller folds |", "|---|---|---:|---:|---:|---:|"]
    for mode in ("literal", "paper", "certified"):
        r = dlf("disk", "L.off", "--init-uv", "L_uv.obj", "--mode", mode, cwd=TMP)
        if r is None:
            out.append(f"| {mode} | error | | | | |")
            continue
        out.append(f"| {mode} | {r['stop_reason']} | {r['iterations']} | {g(r['initial']['d_area'])} | "
                   f"{g((r.get('final') or {}).get('d_area'))} | {folds(r)} |")
    out.append("")
    return out


def fig14():
    m = CFG["fig14"]
    out = ["### Fig. 14: D_area along the iterations, adaptive against fixed 0.01", "",
           f"`dlf disk {m}.off --border circle --max-iterations 500 --history` (Tutte start); the plot is "
           "`benchmark/fig14.sh`'s. D_area − 2 on the flowing mesh every 5 iterations.", "",
           "| run | stop | iterations | D_area start → returned | lowest (iteration) | D_area − 2 at 5, 10, 20, 50, 100, 200 |",
           "|---|---|---:|---|---|---|"]
    for label, args in (("literal, adaptive (Eq. 5, μ 0.8)", ["--mode", "literal"]),
                        ("literal, fixed 0.01", ["--mode", "literal", "--fixed-step", "0.01"]),
                        ("paper mode", ["--mode", "paper"])):
        r = dlf("disk", off(m), "--border", "circle", "--max-iterations", "500", "--history", *args)
        if r is None:
            out.append(f"| {label} | error | | | | |")
            continue
        h = {x["iteration"]: x["d_area"] for x in r.get("history", [])}
        at = ", ".join(f"{h[k] - 2:.2g}" if k in h else "—" for k in (5, 10, 20, 50, 100, 200))
        b = best(r)
        out.append(f"| {label} | {r['stop_reason']} | {r['iterations']} | {g(r['initial_domain_d_area'])} → "
                   f"{g(r['domain_d_area'])} | {g(b[0])} ({b[1]}) | {at} |")
    out += ["", "The paper's Fig. 14: the adaptive step's D_area falls with a much steeper slope than the fixed 0.01's.", ""]
    return out


def fig15_16():
    out = ["### Figs. 15–16: a region scaled by a factor, paper mode", "",
           "`dlf disk|sphere MESH --mode paper --roi-ball X Y Z R --factor F` with the ball of `benchmark/fig15_16.sh` "
           "(the vertices' centroid, radius 0.15 × the bounding-box diagonal; on a mesh with no vertex in that ball, "
           "the ball around its highest vertex).", "",
           "| mesh | domain | factor | prescribed share | achieved share | D_area | stop | iterations | caller folds |",
           "|---|---|---:|---:|---:|---:|---|---:|---:|"]
    for cmd, m in (("disk", CFG["fig15_disk"]), ("sphere", CFG["fig15_sphere"])):
        t = [l.split("#")[0].split() for l in open(off(m))]
        t = [x for x in t if x]
        nv = int(t[1][0])
        p = [list(map(float, x[:3])) for x in t[2:2 + nv]]
        c = [sum(q[k] for q in p) / nv for k in range(3)]
        d = math.sqrt(sum((max(q[k] for q in p) - min(q[k] for q in p)) ** 2 for k in range(3)))
        r = 0.15 * d
        if not any(sum((q[k] - c[k]) ** 2 for k in range(3)) <= r * r for q in p):
            c = max(p, key=lambda q: q[2])  # a convex mesh: the ball around its top vertex instead
        ball = [repr(c[0]), repr(c[1]), repr(c[2]), repr(r)]
        for f in CFG["factors"]:
            r = dlf(cmd, off(m), "--mode", "paper", "--roi-ball", *ball, "--factor", f)
            if r is None:
                out.append(f"| {m} | {cmd} | {f} | error | | | | | |")
                continue
            reg = (r.get("regions") or [{}])[0]
            out.append(f"| {m} | {cmd} | {f} | {g(reg.get('prescribed_fraction'))} | {g(reg.get('achieved_fraction'))} | "
                       f"{g((r.get('final') or {}).get('d_area'))} | {r['stop_reason']} | {r['iterations']} | {folds(r)} |")
    out.append("")
    return out


def disk_meshes():
    """Every disk mesh of the data set with one border loop and at least 100 faces."""
    names = []
    for f in sorted(os.listdir(MESHES)):
        if not f.endswith(".off"):
            continue
        rep = os.path.join(TMP, "info.json")
        if subprocess.run([DLF, "info", os.path.join(MESHES, f), "-q", "--report", rep],
                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode != 0:
            continue
        j = json.load(open(rep))
        if j["fits"] == "dlf disk" and j["faces"] >= 100 and j["border_loops"] == 1:
            names.append(f[:-4])
    return names


def paper_mode():
    meshes = CFG["paper_mode"] or disk_meshes()
    out = ["### The paper mode on the disk meshes, both borders and both starts", "",
           "`dlf disk MESH --mode paper --border circle|square --init tutte|mvc`, default settings. D_area of the "
           "flowing triangulation, start → returned; caller folds: the input triangles inverted or degenerate at the "
           "final positions (exact); flips: edge flips in total.", "",
           "| mesh | faces | border | start | stop | iterations | D_area start → returned | caller folds | flips |",
           "|---|---:|---|---|---|---:|---|---:|---:|"]
    for m in meshes:
        for border in ("circle", "square"):
            for init, label in (("tutte", "Tutte"), ("mvc", "mean value")):
                r = dlf("disk", off(m), "--mode", "paper", "--border", border, "--init", init)
                if r is None:
                    out.append(f"| {m} | | {border} | {label} | error | | | | |")
                    continue
                out.append(f"| {m} | {r['faces']:,} | {border} | {label} | {r['stop_reason']} | {r['iterations']} | "
                           f"{g(r['initial_domain_d_area'])} → {g(r['domain_d_area'])} | {folds(r)} | {r.get('flips', '—')} |")
    out.append("")
    return out


def sphere_literal():
    out = ["### The literal Algorithm 1 on the sphere", "",
           "`dlf sphere MESH --mode literal --history` (μ 0.8, threshold 1e-3, cap 500; the library's start). "
           "\"Lowest D_area\" is the lowest of the iterates (iteration 0: the start); the literal mode returns the last one.", "",
           "| mesh | faces | stop | iterations | D_area start → returned | lowest D_area (iteration) | caller folds | collapse: folded faces |",
           "|---|---:|---|---:|---|---|---:|---:|"]
    for m in CFG["sphere_literal"]:
        r = dlf("sphere", off(m), "--mode", "literal", "--history")
        if r is None:
            out.append(f"| {m} | | error | | | | | |")
            continue
        b = best(r)
        out.append(f"| {m} | {r['faces']:,} | {r['stop_reason']} | {r['iterations']} | {g(r['initial_domain_d_area'])} → "
                   f"{g(r['domain_d_area'])} | {g(b[0])} ({b[1]}) | {folds(r)} | "
                   f"{r.get('collapse_faces', '—') if r['stop_reason'] == 'collapsed' else '-'} |")
    out.append("")
    return out


def sphere_variants():
    """The paper mode on the sphere with one stabiliser changed at a time."""
    meshes = CFG.get("sphere_variants", CFG["sphere"])
    variants = [("default (μ 0.8, targets lumped on flowing faces)", []), ("`--mu 0.5`", ["--mu", "0.5"]),
                ("`--literal-targets`", ["--literal-targets"]), ("`--no-flips`", ["--no-flips"]),
                ("`--log-area-tolerance 0`", ["--log-area-tolerance", "0"])]
    out = ["### The paper mode on the sphere, one option changed at a time", "",
           "`dlf sphere MESH --mode paper OPTION`. Each cell: D_area of the flowing triangulation returned / "
           "iterations / caller folds (the input triangles inverted or degenerate, exact); the stop reason when "
           "it is not a plateau.", "",
           "| variant | " + " | ".join(meshes) + " |", "|---|" + "---|" * len(meshes)]
    for label, extra in variants:
        cells = []
        for m in meshes:
            r = dlf("sphere", off(m), "--mode", "paper", *extra)
            if r is None:
                cells.append("error")
                continue
            stop = "" if r["stop_reason"] == "plateau" else f" ({r['stop_reason']})"
            cells.append(f"{g(r['domain_d_area'])} / {r['iterations']} / {folds(r)}{stop}")
        out.append(f"| {label} | " + " | ".join(cells) + " |")
    out.append("")
    return out


RUN = {"sphere_literal": sphere_literal, "sphere_variants": sphere_variants, "paper_mode": paper_mode, "table2": table2, "mu": mu, "modes": modes, "sphere_starts": lambda: starts("sphere"),
       "disk_starts": lambda: starts("disk"), "fig10": fig10, "fig14": fig14, "fig15_16": fig15_16}
for s in SECTIONS:
    if s not in RUN:
        sys.exit(f"paper_runs: unknown section {s}")
    print("\n".join(RUN[s]()))
    sys.stdout.flush()
