#!/usr/bin/env bash
# Cut surfaces, as a texture user meets them, in one run:
#  - CGAL's own seams (test/data/*.selection.txt) through `dlf disk --seam`;
#  - closed meshes of CGAL's data set cut open into one disk along long
#    zero-width seams through their tips, and higher-genus meshes along a cut
#    graph (benchmark/cut_to_disk: the seam's two sides are separate border
#    vertices at the same positions, as exporters write them);
#  - meshes with holes (one loop to the circle, the others free).
# Each is flattened by the default `dlf disk` — the whole process, default
# options, no thread variable in the environment — with the circle and with
# the square, beside CGAL's iterative authalic, ARAP and LSCM (their
# parameterize() alone, from dlf_benchmark, on the same cut mesh, in the same
# run). Meshes are generated in a temporary directory; nothing is written to
# the tree.
#
#   benchmark/cut_surfaces.sh                     # the table on stdout
#   benchmark/cut_surfaces.sh --markdown t.md     # and as Markdown
#   CASES="cow-6 bear" benchmark/cut_surfaces.sh  # some of the cases
#
# BUILD_DIR (default build; targets dlf, dlf_benchmark and cut_to_disk, the
# last two with -DDLF_BUILD_BENCHMARK=ON) and MESHES (default
# $BUILD_DIR/data/meshes).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR="${BUILD_DIR:-build}"
DLF="$BUILD_DIR/tools/dlf"
CUT="$BUILD_DIR/benchmark/cut_to_disk"
BENCH="$BUILD_DIR/benchmark/dlf_benchmark"
MESHES="${MESHES:-$BUILD_DIR/data/meshes}"
MARKDOWN=""
[[ "${1:-}" == "--markdown" ]] && MARKDOWN="$2"
for x in "$DLF" "$BENCH"; do
  [[ -x "$x" ]] || { echo "cut_surfaces: $x not built (-DDLF_BUILD_BENCHMARK=ON)" >&2; exit 2; }
done
# As users run: whatever thread settings the caller's shell has are dropped.
unset OMP_THREAD_LIMIT OMP_NUM_THREADS OPENBLAS_NUM_THREADS GOTO_NUM_THREADS

# name:how — seam MESH SELECTION | cut|cut-root MESH TIPS | holes MESH |
# cut-loop MESH K TIPS (K Loop subdivisions, then cut)
all_cases=(
  "blob:seam blob.off test/data/blob.selection.txt"
  "bear:seam bear.off test/data/bear.selection.txt"
  "lion-seam:seam lion.off test/data/lion.selection.txt"
  "lion2-seam:seam lion.off test/data/lion2.selection.txt"
  "lion3-seam:seam lion.off test/data/lion3.selection.txt"
  "lion4-seam:seam lion.off test/data/lion4.selection.txt"
  "cow-6:cut cow.off 6"
  "bull-6:cut bull.off 6"
  "dino-6:cut dino.off 6"
  "triceratops-7:cut triceratops.off 7"
  "camel-6:cut camel.off 6"
  "man-5:cut man.off 5"
  "diplodocus-6:cut diplodocus.off 6"
  "armadillo-6:cut armadillo.off 6"
  "camel-loop1-6:cut-loop camel.off 1 6"
  "cow-loop2-6:cut-loop cow.off 2 6"
  "elephant-g3-6:cut elephant.off 6"
  "knot1-g1:cut knot1.off 4"
  "eight-g2:cut eight.off 4"
  "eight-loop1-g2:cut-loop eight.off 1 4"
  "lion-holes:holes lion.off"
  "holes:holes holes.off"
  "head:holes head.off"
  "pig:holes pig.off"
  "mech-holes-shark:holes mech-holes-shark.off"
)
selected=" ${CASES:-} "

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/data/meshes" "$tmp/runs"
names=()
for c in "${all_cases[@]}"; do
  name="${c%%:*}"
  [[ -n "${CASES:-}" && "$selected" != *" $name "* ]] && continue
  read -r -a how <<<"${c#*:}"
  cut_mesh="$tmp/data/meshes/$name.off"
  args=()
  case "${how[0]}" in
    seam)
      input="$MESHES/${how[1]}"; args=(--seam "${how[2]}")
      # CGAL's parameterizers get the same cut, with one vertex per seam side:
      # the cut-open OBJ `dlf disk --seam` writes (v: input, vt: per side).
      "$DLF" disk "$input" "${args[@]}" --max-iterations 0 -o "$tmp/cut.obj" -q 2>/dev/null || true
      python3 - "$tmp/cut.obj" "$cut_mesh" <<'EOF'
import sys
v, vt, faces = [], [], []
for line in open(sys.argv[1]):
    t = line.split()
    if not t: continue
    if t[0] == 'v': v.append(t[1:4])
    elif t[0] == 'vt': vt.append(None)
    elif t[0] == 'f': faces.append([tuple(int(x) - 1 for x in c.split('/')[:2]) for c in t[1:]])
pos = [None] * len(vt)
for f in faces:
    for a, b in f: pos[b] = v[a]
with open(sys.argv[2], 'w') as out:
    out.write(f"OFF\n{len(pos)} {len(faces)} 0\n")
    for p in pos: out.write(" ".join(p) + "\n")
    for f in faces: out.write(f"{len(f)} " + " ".join(str(b) for _, b in f) + "\n")
EOF
      ;;
    cut|cut-root)
      [[ -x "$CUT" ]] || { echo "cut_surfaces: $CUT not built (-DDLF_BUILD_BENCHMARK=ON)" >&2; exit 2; }
      "$CUT" "${how[0]}" "$MESHES/${how[1]}" "${how[2]}" "$cut_mesh" >/dev/null
      input="$cut_mesh" ;;
    cut-loop)
      [[ -x "$CUT" ]] || { echo "cut_surfaces: $CUT not built (-DDLF_BUILD_BENCHMARK=ON)" >&2; exit 2; }
      "$CUT" subdivide "$MESHES/${how[1]}" "${how[2]}" "$tmp/fine.off" >/dev/null
      "$CUT" cut "$tmp/fine.off" "${how[3]}" "$cut_mesh" >/dev/null
      input="$cut_mesh" ;;
    holes)
      cp "$MESHES/${how[1]}" "$cut_mesh"; input="$cut_mesh" ;;
  esac
  for border in circle square; do
    # Whole process, wall clock, as a user times it.
    python3 - "$tmp/runs/$name.$border" "$DLF" disk "$input" "${args[@]}" --border "$border" \
      -o "$tmp/runs/$name.$border.obj" --report "$tmp/runs/$name.$border.json" -q <<'EOF'
import subprocess, sys, time
t = time.perf_counter()
code = subprocess.run(sys.argv[2:], stderr=subprocess.DEVNULL).returncode
open(sys.argv[1] + ".time", "w").write(f"{time.perf_counter() - t} {code}\n")
EOF
  done
  names+=("$name")
done

list=$(printf "%s.off," "${names[@]}")
"$BENCH" --data-dir "$tmp/data" --meshes "${list%,}" --methods iter_authalic_circle,arap,lscm \
  --slow-face-limit 1000000 --repeats 1 --table2 "" --json "$tmp/cgal.json" --markdown "$tmp/cgal.md" 2>"$tmp/cgal.log" ||
  { echo "cut_surfaces: dlf_benchmark failed:"; tail -5 "$tmp/cgal.log"; exit 1; }

python3 - "$tmp" "$MARKDOWN" "${names[@]}" <<'EOF'
import json, sys
tmp, md_path, names = sys.argv[1], sys.argv[2], sys.argv[3:]
cgal = {m["mesh"][:-4]: m for m in json.load(open(f"{tmp}/cgal.json"))["meshes"]}
def dlf(name, border):
    seconds, code = open(f"{tmp}/runs/{name}.{border}.time").read().split()
    try: r = json.load(open(f"{tmp}/runs/{name}.{border}.json"))
    except Exception: return None, float(seconds), int(code)
    return r, float(seconds), int(code)
def fmt_dlf(r, s, code):
    if r is None or r.get("final") is None: return f"exit {code}", "", "", "", "", f"{s:.2f}"
    f = r["final"]
    return (r["status"], r["stop_reason"], str(r["iterations"]), f"{f['d_area']:.4f}", str(f["inverted_faces"]), f"{s:.2f}")
def fmt_cgal(m, key):
    r = m["methods"].get(key, {})
    if "caller" not in r: return ("fail", "", f"{r.get('seconds', 0):.2f}")
    return (f"{r['caller']['d_area']:.4g}", str(r["caller"]["folds"]), f"{r['seconds']:.2f}")
head = ["case", "faces", "status", "stop", "it", "D_area", "inv", "s", "square: status", "it", "D_area", "inv", "s",
        "IA D_area", "folds", "s", "ARAP D_area", "folds", "s", "LSCM D_area", "folds", "s", "DLF s / IA s"]
rows = []
for n in names:
    m = cgal.get(n)
    c, sq = dlf(n, "circle"), dlf(n, "square")
    ia = fmt_cgal(m, "iter_authalic_circle") if m else ("", "", "")
    ratio = ""
    if m and "seconds" in m["methods"].get("iter_authalic_circle", {}):
        ratio = f"{c[1] / m['methods']['iter_authalic_circle']['seconds']:.3f}"
    csq = fmt_dlf(*sq)
    rows.append([n, str(m["F"]) if m else ""] + list(fmt_dlf(*c)) + [csq[0], csq[2], csq[3], csq[4], csq[5]] + list(ia) +
                list(fmt_cgal(m, "arap") if m else ("", "", "")) + list(fmt_cgal(m, "lscm") if m else ("", "", "")) + [ratio])
widths = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(head)]
print("  ".join(h.ljust(w) for h, w in zip(head, widths)))
for r in rows: print("  ".join(x.ljust(w) for x, w in zip(r, widths)))
if md_path:
    with open(md_path, "w") as out:
        out.write("| " + " | ".join(head) + " |\n|" + "---|" * len(head) + "\n")
        for r in rows: out.write("| " + " | ".join(r) + " |\n")
EOF
