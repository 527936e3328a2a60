#!/usr/bin/env bash
# Long thin disks: CGAL's closed meshes cut open along long zero-width seams
# through their tips (cut_to_disk), a genus-3 mesh cut along a cut graph, and
# flat block shapes (maze, comb, spiral, slit square), flattened by the
# default `dlf disk` (certified, Tutte start, circle). Generated at run time
# in a temporary directory; nothing is written to the tree.
#
#   benchmark/slits.sh            # one row per disk
#
# DLF (default build/tools/dlf), CUT (default build/benchmark/cut_to_disk)
# and MESHES (default build/data/meshes). Columns: faces, border vertices,
# min angle (3D), status, stop reason, iterations, D_area, inverted faces
# (exact predicate), whole process time.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
DLF="${DLF:-build/tools/dlf}"
CUT="${CUT:-build/benchmark/cut_to_disk}"
MESHES="${MESHES:-build/data/meshes}"
[[ -x "$DLF" ]] || { echo "slits: $DLF not built" >&2; exit 2; }
[[ -x "$CUT" ]] || { echo "slits: $CUT not built (-DDLF_BUILD_BENCHMARK=ON, target cut_to_disk)" >&2; exit 2; }
export OMP_THREAD_LIMIT=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# name and how to make it
disks=(
  "cow-6:cut $MESHES/cow.off 6"
  "cow-6-root:cut-root $MESHES/cow.off 6"
  "triceratops-7:cut $MESHES/triceratops.off 7"
  "triceratops-7-root:cut-root $MESHES/triceratops.off 7"
  "dino-6:cut $MESHES/dino.off 6"
  "dino-6-root:cut-root $MESHES/dino.off 6"
  "bull-6:cut $MESHES/bull.off 6"
  "bull-6-root:cut-root $MESHES/bull.off 6"
  "camel-6:cut $MESHES/camel.off 6"
  "camel-6-root:cut-root $MESHES/camel.off 6"
  "man-5:cut $MESHES/man.off 5"
  "man-5-root:cut-root $MESHES/man.off 5"
  "diplodocus-6:cut $MESHES/diplodocus.off 6"
  "diplodocus-6-root:cut-root $MESHES/diplodocus.off 6"
  "armadillo-6:cut $MESHES/armadillo.off 6"
  "armadillo-6-root:cut-root $MESHES/armadillo.off 6"
  "knot1-g1:cut $MESHES/knot1.off 4"
  "eight-g2:cut $MESHES/eight.off 4"
  "elephant-g3-6:cut $MESHES/elephant.off 6"
  "elephant-g3-6-root:cut-root $MESHES/elephant.off 6"
  "slits-40-5-30:slits 40 5 30"
  "comb-8-10-3:comb 8 10 3"
  "spiral-6-3:spiral 6 3"
  "maze-16-3:maze 16 3"
)
printf "%-19s %7s %6s %7s %-6s %-14s %5s %9s %4s %7s\n" disk faces border min_ang status stop it d_area inv seconds
for d in "${disks[@]}"; do
  name="${d%%:*}"
  read -r -a how <<<"${d#*:}"
  off="$tmp/$name.off"
  if [[ "${how[0]}" == cut* ]]; then
    "$CUT" "${how[0]}" "${how[1]}" "${how[2]}" "$off" >/dev/null
  else
    "$CUT" "${how[@]}" "$off" >/dev/null
  fi
  "$DLF" info "$off" -q --report "$tmp/info.json"
  start=$(date +%s.%N)
  "$DLF" disk "$off" -q --report "$tmp/r.json" >/dev/null 2>&1 || true
  end=$(date +%s.%N)
  python3 - "$name" "$tmp/info.json" "$tmp/r.json" "$start" "$end" <<'EOF'
import json, sys
name, info, report, t0, t1 = sys.argv[1:6]
i = json.load(open(info))
r = json.load(open(report))
f = r.get("final") or {}
print("%-19s %7d %6d %7.2f %-6s %-14s %5d %9.4f %4s %7.2f" % (
    name, i["faces"], i["border_edges"], i["min_angle_degrees"], r["status"], r["stop_reason"], r["iterations"],
    f.get("d_area", float("nan")), r.get("caller_inverted_faces"), float(t1) - float(t0)))
EOF
done
