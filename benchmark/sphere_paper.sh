#!/usr/bin/env bash
# Runs `dlf sphere --mode paper` (the paper's flow on the sphere) on the closed
# genus-0 meshes of CGAL's data set and prints one markdown row per mesh:
# the table of doc/sphere_paper_mode.md.
#
#   benchmark/sphere_paper.sh PATH/TO/dlf MESHES_DIR [MESH.off ...] [-- EXTRA dlf OPTIONS]
#
# Without mesh names: every mesh of MESHES_DIR that `dlf info` finds fit for
# `dlf sphere` and has at least 200 faces. Needs python3 (reads the reports).
set -euo pipefail

dlf=${1:?usage: sphere_paper.sh PATH/TO/dlf MESHES_DIR [MESH.off ...] [-- OPTIONS]}
meshes=${2:?usage: sphere_paper.sh PATH/TO/dlf MESHES_DIR [MESH.off ...] [-- OPTIONS]}
shift 2
names=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do names+=("$1"); shift; done
[ $# -gt 0 ] && shift # the rest goes to dlf
if [ ${#names[@]} -eq 0 ]; then
  for f in "$meshes"/*.off; do
    fits=$("$dlf" info "$f" 2> /dev/null | awk '/^  fits / { sub(/^  fits +/, ""); print; exit }') || true
    faces=$(awk '!/^#/ && NF' "$f" | sed -n 2p | awk '{ print $2 }')
    [ "$fits" = "dlf sphere (closed, genus 0)" ] && [ "${faces:-0}" -ge 200 ] && names+=("$(basename "$f")")
  done
fi

# Single-threaded (OMP_THREAD_LIMIT binds CHOLMOD's OpenMP regions; see benchmark/run.sh).
export OMP_THREAD_LIMIT=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| mesh | faces | stop | iterations | D_area flowing: start → best | D_area input faces | mean \\|log r\\| input faces | caller folds | flips | non-Delaunay edges | seconds |"
echo "|---|---:|---|---:|---|---:|---:|---:|---:|---:|---:|"
for name in "${names[@]}"; do
  report=$tmp/r.json
  # Exit code 3: not converged (a plateau), the report written: a row like the others.
  rc=0
  "$dlf" sphere "$meshes/$name" --mode paper --report "$report" -q "$@" 2> "$tmp/err.txt" || rc=$?
  if [ "$rc" -ne 0 ] && [ "$rc" -ne 3 ]; then
    echo "| $name | | error: $(sed "s|$meshes/||g" "$tmp/err.txt" | head -c 200 | tr '\n|' '  ') | | | | | | | | |"
    continue
  fi
  python3 - "$name" "$report" << 'EOF'
import json, sys
name, path = sys.argv[1], sys.argv[2]
r = json.load(open(path))
def g(x):
    return f"{x:.4f}" if x < 100 else f"{x:.4g}" if x < 1e5 else f"{x:.3g}"
print(f"| {name} | {r['faces']} | {r['stop_reason']} | {r['iterations']} | {g(r['initial_domain_d_area'])} → {g(r['domain_d_area'])} | "
      f"{g(r['final']['d_area'])} | {r['final']['log_area_ratio']['mean_abs']:.4f} | {r['caller_inverted_faces']} | {r['flips']} | "
      f"{r['flowing_non_delaunay_edges']} | {r['seconds']['total']:.3g} |")
EOF
done
