#!/usr/bin/env bash
# The paper's Figs. 15–16 with the paper's own flow: measure control by
# `--mode paper` (the stabilised paper flow), a region of interest scaled by
# 0.25, 0.5, 1, 2, 4, 8, 16, on a disk (default nefertiti, circle) and on a
# sphere (default blobby). The region is the ball around the mesh's
# vertex centroid of radius 0.15 × the bounding-box diagonal. Prints one row
# per factor (prescribed and achieved share of the domain, D_area, stop
# reason, caller folds) and writes the layouts to
# doc/images/fig15_16_MESH_xF.svg.
#
#   benchmark/fig15_16.sh
#   DISK=mushroom SPHERE=bear FACTORS="0.25 4 16" benchmark/fig15_16.sh
#
# DLF (default build/tools/dlf) and MESHES (default build/data/meshes).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
DLF="${DLF:-build/tools/dlf}"
MESHES="${MESHES:-build/data/meshes}"
DISK="${DISK:-nefertiti}"
SPHERE="${SPHERE:-blobby}"
FACTORS="${FACTORS:-0.25 0.5 1 2 4 8 16}"
[[ -x "$DLF" ]] || { echo "fig15_16: $DLF not built" >&2; exit 2; }
export OMP_THREAD_LIMIT=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
root="$(pwd)"
dlf="$(cd "$(dirname "$DLF")" && pwd)/$(basename "$DLF")"
mkdir -p doc/images
echo "| mesh | command | factor | prescribed share | achieved share | error | D_area | stop | iterations | caller folds |"
echo "|---|---|---:|---:|---:|---:|---:|---|---:|---:|"
for spec in "disk $DISK" "sphere $SPHERE"; do
  read -r cmd mesh <<< "$spec"
  cp "$MESHES/$mesh.off" "$tmp/"
  ball=$(python3 - "$tmp/$mesh.off" <<'EOF'
import math, sys
t = [l.split("#")[0].split() for l in open(sys.argv[1])]
t = [x for x in t if x]
nv = int(t[1][0])
p = [list(map(float, x[:3])) for x in t[2:2 + nv]]
c = [sum(q[k] for q in p) / nv for k in range(3)]
d = math.sqrt(sum((max(q[k] for q in p) - min(q[k] for q in p)) ** 2 for k in range(3)))
print(c[0], c[1], c[2], 0.15 * d)
EOF
)
  for f in $FACTORS; do
    # Run where the mesh is, so that the picture's caption names no machine path.
    (cd "$tmp" && "$dlf" "$cmd" "$mesh.off" --mode paper --roi-ball $ball --factor "$f" -q \
      --svg "$root/doc/images/fig15_16_${mesh}_x$f.svg" --report "r.json" 2>/dev/null) || true
    python3 - "$tmp/r.json" "$mesh" "$cmd" "$f" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
g = (r.get("regions") or [{}])[0]
p, a = g.get("prescribed_fraction"), g.get("achieved_fraction")
e = abs(a - p) / p if p and a is not None else float("nan")
d = (r.get("final") or {}).get("d_area", float("nan"))
print(f"| {sys.argv[2]} | {sys.argv[3]} | {sys.argv[4]} | {p:.4f} | {a:.4f} | {100 * e:.2f}% | {d:.4f} | "
      f"{r['stop_reason']} | {r['iterations']} | {r.get('caller_inverted_faces')} |")
EOF
  done
done
