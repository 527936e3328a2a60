#!/usr/bin/env bash
# The paper's Fig. 10: DLF on a non-convex domain. An L-shaped grid (the
# square [0, 2]² less its upper right quarter, 16 cells a unit) lifted by a
# bump z = 1.5 exp(−|p − (0.5, 0.5)|² / 0.08) is mapped from its own flat
# projection (`--init-uv`, a flip-free map onto the L) in the three modes,
# the border sliding along the L. Writes doc/images/fig10_MODE.svg and
# prints one line per mode (stop reason, iterations, D_area, folds).
#
#   benchmark/fig10.sh
#
# DLF (default build/tools/dlf).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
DLF="${DLF:-build/tools/dlf}"
[[ -x "$DLF" ]] || { echo "fig10: $DLF not built" >&2; exit 2; }
export OMP_THREAD_LIMIT=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
python3 - "$tmp/L.off" "$tmp/L_uv.obj" <<'EOF'
import math, sys
n = 16  # cells per unit
idx, pts = {}, []
for j in range(2 * n + 1):
    for i in range(2 * n + 1):
        x, y = i / n, j / n
        if x > 1 and y > 1: continue
        idx[(i, j)] = len(pts); pts.append((x, y))
faces = []
for j in range(2 * n):
    for i in range(2 * n):
        c = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
        if not all(k in idx for k in c) or (i + 0.5) / n > 1 and (j + 0.5) / n > 1: continue
        a, b, cc, d = (idx[k] for k in c)
        faces += [(a, b, cc), (a, cc, d)] if (i + j) % 2 == 0 else [(a, b, d), (b, cc, d)]
z = lambda x, y: 1.5 * math.exp(-((x - 0.5) ** 2 + (y - 0.5) ** 2) / 0.08)
with open(sys.argv[1], "w") as f:
    f.write(f"OFF\n{len(pts)} {len(faces)} 0\n")
    for x, y in pts: f.write(f"{x} {y} {z(x, y)}\n")
    for t in faces: f.write("3 %d %d %d\n" % t)
with open(sys.argv[2], "w") as f:
    for x, y in pts: f.write(f"v {x} {y} {z(x, y)}\nvt {x} {y}\n")
    for t in faces: f.write("f %d/%d %d/%d %d/%d\n" % (t[0] + 1, t[0] + 1, t[1] + 1, t[1] + 1, t[2] + 1, t[2] + 1))
EOF
mkdir -p doc/images
root="$(pwd)"
dlf="$(cd "$(dirname "$DLF")" && pwd)/$(basename "$DLF")"
for mode in certified paper literal; do
  # Run where the mesh is, so that the picture's caption names no machine path.
  (cd "$tmp" && "$dlf" disk L.off --init-uv L_uv.obj --mode "$mode" -q --svg "$root/doc/images/fig10_$mode.svg" \
    --report "$mode.json" 2>/dev/null) || true
  python3 - "$tmp/$mode.json" "$mode" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
f = r.get("final") or {}
print(f"{sys.argv[2]:9s} {r['status']:14s} {r['stop_reason']:10s} {r['iterations']:4d} it.  "
      f"D_area {r['initial']['d_area']:.4f} -> {f.get('d_area', float('nan')):.4f}  caller folds {r['caller_inverted_faces']}")
EOF
done
