#!/usr/bin/env bash
# The golden table: what every flow does on CGAL's data set, to 12
# significant digits, so that a change meant to keep the numerics (a
# refactoring, a faster kernel) can prove it did.
#
# Rows: every disk mesh of the data set with at least 100 faces (both modes,
# circle and square border; a mesh with holes: certified only) and every
# closed genus-0 mesh with at least 200 faces (both spherical modes), run by
# the default `dlf` command with one thread (the results depend on the BLAS
# thread count at rounding level).
# Columns: status, stop reason, iterations, the flow's final D_area on its
# domain triangulation, and D_area on the caller's triangles.
#
#   benchmark/golden.sh                 # compare with benchmark/golden_table.txt
#   benchmark/golden.sh --record        # write benchmark/golden_table.txt
#
# DLF (default build/tools/dlf) and MESHES (default build/data/meshes).
# Exit status 1 when a row differs; the differing rows are printed.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
DLF="${DLF:-build/tools/dlf}"
MESHES="${MESHES:-build/data/meshes}"
GOLDEN=benchmark/golden_table.txt
[[ -x "$DLF" ]] || { echo "golden: $DLF not built" >&2; exit 2; }
[[ -d "$MESHES" ]] || { echo "golden: no meshes in $MESHES" >&2; exit 2; }
command -v python3 >/dev/null || { echo "golden: python3 is needed" >&2; exit 2; }
export OMP_THREAD_LIMIT=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
out="$tmp/table.txt"

# One row from a report: mesh, command, options, then the report's fields.
row() {
  python3 - "$@" <<'EOF'
import json, sys
name, what, report = sys.argv[1], sys.argv[2], sys.argv[3]
try:
    r = json.load(open(report))
except Exception:
    print(f"{name:28s} {what:24s} no-report"); sys.exit()
g = lambda x: "-" if x is None else f"{x:.12g}"
final = (r.get("final") or {}).get("d_area")
print(f"{name:28s} {what:24s} {r['status']:24s} {r['stop_reason']:14s} {r['iterations']:4d} "
      f"{g(r.get('domain_d_area'))} {g(final)}")
EOF
}

start=$(date +%s)
for mesh in "$MESHES"/*.off; do
  name="$(basename "$mesh")"
  "$DLF" info "$mesh" -q --report "$tmp/info.json" || continue
  read -r fits faces loops < <(python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); print(j["fits"].replace(" ", "_"), j["faces"], j["border_loops"])' "$tmp/info.json")
  if [[ "$fits" == dlf_disk && "$faces" -ge 100 ]]; then
    modes="certified paper"
    [[ "$loops" -gt 1 ]] && modes=certified # holes: the paper mode takes disks only
    for mode in $modes; do
      for border in circle square; do
        rm -f "$tmp/r.json"
        "$DLF" disk "$mesh" --mode "$mode" --border "$border" -q --report "$tmp/r.json" >/dev/null 2>&1 || true
        row "$name" "disk-$mode-$border" "$tmp/r.json" >>"$out"
      done
    done
  elif [[ "$fits" == dlf_sphere && "$faces" -ge 200 ]]; then
    for mode in certified paper; do
      rm -f "$tmp/r.json"
      "$DLF" sphere "$mesh" --mode "$mode" -q --report "$tmp/r.json" >/dev/null 2>&1 || true
      row "$name" "sphere-$mode" "$tmp/r.json" >>"$out"
    done
  fi
done
echo "golden: $(wc -l <"$out") rows in $(( $(date +%s) - start )) s"

if [[ "${1:-}" == "--record" ]]; then
  cp "$out" "$GOLDEN"
  echo "golden: recorded $GOLDEN"
  exit 0
fi
same=$(comm -12 <(sort "$GOLDEN") <(sort "$out") | wc -l)
echo "golden: $same of $(wc -l <"$GOLDEN") rows identical"
if ! diff -u "$GOLDEN" "$out"; then exit 1; fi
