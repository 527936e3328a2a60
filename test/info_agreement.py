#!/usr/bin/env python3
# `dlf info` on every mesh of a folder (CGAL's data set): the text and the
# JSON report of one run agree field by field (every text line is read, every
# report field compared or derived), n/a in the text exactly where the report
# has null, and the per-component numbers add up to the mesh's.
#
#   python3 test/info_agreement.py DLF MESHES_DIR
import json
import math
import os
import re
import subprocess
import sys
import tempfile

DLF, MESHES = sys.argv[1], sys.argv[2]
NUM = r"(-?[0-9.]+(?:e[-+]?[0-9]+)?|-?inf|nan)"


def close(text_value, json_value, what):
    """A number printed with 6 significant digits against the report's."""
    a = float(text_value)
    if json_value is None:
        raise AssertionError(f"{what}: text {text_value}, report null")
    b = float(json_value)
    if not (math.isclose(a, b, rel_tol=2e-5, abs_tol=1e-12) or (math.isnan(a) and math.isnan(b))):
        raise AssertionError(f"{what}: text {text_value}, report {json_value}")


def equal(text_value, json_value, what):
    if str(text_value) != str(json_value):
        raise AssertionError(f"{what}: text {text_value!r}, report {json_value!r}")


def genus_text(g):
    return "n/a" if g is None else str(g)


def check(path, text, r):
    lines = text.rstrip("\n").split("\n")
    pos = 0

    def take(pattern, what):
        nonlocal pos
        if pos >= len(lines):
            raise AssertionError(f"the text ends before its {what} line")
        m = re.fullmatch(pattern, lines[pos])
        if not m:
            raise AssertionError(f"expected the {what} line, got {lines[pos]!r}")
        pos += 1
        return m

    equal(take(r"dlf info (.*)", "title").group(1), r["mesh"], "mesh")
    m = take(r"  vertices +(\d+) \((\d+) unreferenced, (\d+) duplicate positions"
             r"(?: \((\d+) on the border: seam sides\))?, (\d+) non-finite\)", "vertices")
    equal(m.group(1), r["vertices"], "vertices")
    equal(m.group(2), r["unreferenced_vertices"], "unreferenced vertices")
    equal(m.group(3), r["duplicate_positions"], "duplicate positions")
    equal(m.group(4) or 0, r["duplicate_positions_on_border"], "duplicate positions on the border")
    equal(m.group(5), r["non_finite_vertices"], "non-finite vertices")
    m = take(r"  faces +(\d+) \((\d+) triangles\)", "faces")
    equal(m.group(1), r["faces"], "faces")
    equal(m.group(2), r["triangles"], "triangles")
    m = take(r"  edges +(\d+) \((\d+) border, (\d+) non-manifold, (\d+) inconsistently oriented\)", "edges")
    for g, key in zip(m.groups(), ("edges", "border_edges", "non_manifold_edges", "inconsistently_oriented_edges")):
        equal(g, r[key], key)
    equal(take(r"  connected components +(\d+)", "components").group(1), r["connected_components"], "components")

    parts = r["components"]
    equal(len(parts), r["connected_components"], "components listed in the report")
    listed = min(len(parts), 10) if len(parts) > 1 else 0
    for k in range(listed):
        c = parts[k]
        m = take(r"    component (\d+) +(\d+) faces?, (\d+) vertices?, (\d+) border loops?, Euler characteristic (-?\d+), "
                 r"genus (\d+|n/a(?: \((not manifold|not orientable)\))?), area " + NUM, f"component {k}")
        equal(m.group(1), k, "component index")
        equal(m.group(2), c["faces"], f"component {k} faces")
        equal(m.group(3), c["vertices"], f"component {k} vertices")
        equal(m.group(4), c["border_loops"], f"component {k} border loops")
        equal(m.group(5), c["euler_characteristic"], f"component {k} Euler characteristic")
        equal(m.group(6).split(" ")[0], genus_text(c["genus"]), f"component {k} genus")
        why = m.group(7)
        equal(why == "not manifold", not c["manifold"], f"component {k}: 'not manifold' in the text")
        equal(why == "not orientable", c["manifold"] and not c["orientable"], f"component {k}: 'not orientable' in the text")
        close(m.group(8), c["area"], f"component {k} area")
    if len(parts) > 10:
        equal(take(r"    \.\.\. and (\d+) more \(--report lists every component\)", "more components").group(1),
              len(parts) - 10, "components not listed")
    # The components make up the mesh.
    for key, total in (("faces", r["faces"]), ("vertices", r["vertices"] - r["unreferenced_vertices"]),
                       ("edges", r["edges"]), ("euler_characteristic", r["euler_characteristic"])):
        equal(sum(c[key] for c in parts), total, f"the components' {key} in all")
    close(sum(c["area"] for c in parts), r["area"], "the components' area in all")
    for c in parts:
        equal(c["euler_characteristic"], c["vertices"] - c["edges"] + c["faces"], "a component's V - E + F")
        if c["genus"] is not None:
            equal(2 - 2 * c["genus"] - c["border_loops"], c["euler_characteristic"], "a component's 2 - 2g - b")

    m = take(r"  border loops +(\d+)( \(connected sets of border edges\))?", "border loops")
    equal(m.group(1), r["border_loops"], "border loops")
    loops = r["loops"]
    for k in range(len(loops) if len(loops) > 1 else 0):
        m = take(r"    loop (\d+) +length " + NUM + r", (\d+) vertices( \(the outer loop of dlf disk unless --outer-loop\))?",
                 f"loop {k}")
        equal(m.group(1), k, "loop index")
        close(m.group(2), loops[k]["length"], f"loop {k} length")
        equal(m.group(3), loops[k]["vertices"], f"loop {k} vertices")
    equal(take(r"  Euler characteristic +(-?\d+)", "Euler characteristic").group(1), r["euler_characteristic"], "Euler")
    m = take(r"  genus +(\d+|n/a \(.*\))", "genus")
    equal(m.group(1).split(" ")[0], genus_text(r["genus"]), "genus")
    equal(r["genus"], parts[0]["genus"] if len(parts) == 1 else None, "the genus is the one component's")
    equal(take(r"  non-manifold vertices +(\d+)", "non-manifold vertices").group(1), r["non_manifold_vertices"],
          "non-manifold vertices")
    m = take(r"  degenerate faces +(\d+) zero area, (\d+) repeating a vertex", "degenerate faces")
    equal(m.group(1), r["zero_area_faces"], "zero-area faces")
    equal(m.group(2), r["faces_repeating_a_vertex"], "faces repeating a vertex")
    m = take(r"  smallest angle +(?:" + NUM + r" degrees \((\d+) faces? below 1 degree\)|(n/a) \(.*\))", "smallest angle")
    if m.group(3):
        equal(r["min_angle_degrees"], None, "smallest angle n/a")
    else:
        close(m.group(1), r["min_angle_degrees"], "smallest angle")
        equal(m.group(2), r["faces_below_1_degree"], "faces below 1 degree")
        if not 0 <= r["min_angle_degrees"] < 360:
            raise AssertionError(f"smallest angle {r['min_angle_degrees']}")
    close(take(r"  surface area +" + NUM, "surface area").group(1), r["area"], "surface area")
    m = take(r"  bounding box +\[" + NUM + ", " + NUM + r"\] x \[" + NUM + ", " + NUM + r"\] x \[" + NUM + ", " + NUM +
             r"\], diagonal " + NUM, "bounding box")
    box = r["bounding_box"]
    for k in range(3):
        close(m.group(1 + 2 * k), box["min"][k], f"bounding box min[{k}]")
        close(m.group(2 + 2 * k), box["max"][k], f"bounding box max[{k}]")
    close(m.group(7), math.dist(box["min"], box["max"]), "diagonal")
    m = take(r"  fits +(.*)", "fits")
    fits = m.group(1)
    if r["fits"] == "none":
        equal(fits, "neither dlf disk nor dlf sphere: " + r["reason"], "fits (none)")
    elif r["fits"] == "dlf disk" and r["border_loops"] > 1:
        holes = r["border_loops"] - 1
        equal(fits, f"dlf disk (a disk with {holes} hole{'s' if holes > 1 else ''}: they float)", "fits (holes)")
    else:
        equal(fits, r["fits"] + (" (a topological disk)" if r["fits"] == "dlf disk" else " (closed, genus 0)"), "fits")
        equal(r["reason"], "", "no reason when a command fits")
    m = take(r"  dlf atlas +(?:fits \((.*)\)|does not fit: (.*))", "dlf atlas")
    equal(m.group(1) is not None, r["atlas_fits"], "atlas fits")
    equal(m.group(1) if m.group(1) is not None else m.group(2), r["atlas_note"], "atlas note")
    if pos != len(lines):
        raise AssertionError(f"text lines the report does not have: {lines[pos:]}")


def main():
    meshes = sorted(f for f in os.listdir(MESHES) if os.path.isfile(os.path.join(MESHES, f)))
    failures, read, refused = [], 0, []
    with tempfile.TemporaryDirectory() as tmp:
        report = os.path.join(tmp, "info.json")
        for name in meshes:
            path = os.path.join(MESHES, name)
            if os.path.exists(report):
                os.remove(report)
            p = subprocess.run([DLF, "info", path, "--report", report], capture_output=True, text=True)
            if p.returncode != 0:
                # A file the reader refuses: one error line, no report.
                if p.returncode != 1 or not p.stderr.startswith("dlf: error: ") or os.path.exists(report):
                    failures.append(f"{name}: exit {p.returncode}: {p.stderr.strip()}")
                refused.append(name)
                continue
            read += 1
            try:
                with open(report) as f:
                    r = json.load(f)
                check(path, p.stdout.replace("  wrote " + report + "\n", ""), r)
            except (AssertionError, KeyError, TypeError, ValueError) as e:
                failures.append(f"{name}: {type(e).__name__}: {e}")
    for f in failures:
        print("FAIL:", f)
    print(f"info_agreement: {read} meshes read, text and report compared; {len(refused)} refused by the reader "
          f"({', '.join(refused) or 'none'}); {len(failures)} failed")
    if read == 0:
        print("FAIL: no mesh in", MESHES)
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
