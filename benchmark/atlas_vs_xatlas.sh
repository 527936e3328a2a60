#!/usr/bin/env bash
# `dlf atlas` and xatlas side by side, on the same meshes in the same run:
# charts, seam length over √area, packing efficiency, global D_area,
# inverted uv triangles and overlapping uv triangle pairs (both atlases
# scored by the same exact scorer, build/benchmark/atlas_score), whole-process
# seconds (wall and CPU) and peak memory of each program.
#
# xatlas is npm's WebAssembly build `xatlas-web` 0.1.0 with its default chart
# and pack options, run under node by benchmark/xatlas_run.cjs (a two-global
# shim: the build targets browsers). It is installed under the build dir,
# never committed:
#
#   mkdir -p build/xatlas-npm && (cd build/xatlas-npm && npm init -y && npm install xatlas-web@0.1.0)
#   cmake -S . -B build -DDLF_BUILD_BENCHMARK=ON && cmake --build build --target dlf atlas_score
#   benchmark/atlas_vs_xatlas.sh MESH...      # OFF/OBJ triangle meshes; table on stdout
#
# xatlas-web reads 16-bit indices: meshes of more than 65,535 vertices are
# skipped (benchmark/loop_subdivide.cjs makes 100K-face meshes within that).
# Environment: BUILD (default build), DLF (default BUILD/tools/dlf), OUT
# (default BUILD/atlas_vs_xatlas), PICTURE (a mesh's name, e.g. cow: both
# atlases of it side by side in OUT/NAME.png, benchmark/atlas_picture.py;
# doc/images/atlas_vs_xatlas_cow.png is PICTURE=cow).
set -u
here=$(cd "$(dirname "$0")" && pwd)
BUILD=${BUILD:-$here/../build}
OUT=${OUT:-$BUILD/atlas_vs_xatlas}
DLF=${DLF:-$BUILD/tools/dlf}
SCORE=$BUILD/benchmark/atlas_score
NODE_MODULES=$BUILD/xatlas-npm/node_modules
for need in "$DLF" "$SCORE" "$NODE_MODULES/xatlas-web/dist/xatlas-web.wasm"; do
  [ -e "$need" ] || { echo "atlas_vs_xatlas: missing $need (see the header of $0)" >&2; exit 1; }
done
[ $# -gt 0 ] || { echo "usage: $0 MESH..." >&2; exit 1; }
mkdir -p "$OUT"
rows=$OUT/rows.jsonl
: > "$rows"
for mesh in "$@"; do
  name=$(basename "${mesh%.*}")
  # Each program once, timed as a whole process: wall s, user+sys s, max RSS KiB.
  /usr/bin/time -f '%e %U %S %M' -o "$OUT/$name.dlf.time" \
    "$DLF" atlas "$mesh" -o "$OUT/$name.dlf.obj" --report "$OUT/$name.dlf.json" --quiet
  dlf_status=$?
  NODE_PATH=$NODE_MODULES /usr/bin/time -f '%e %U %S %M' -o "$OUT/$name.xatlas.time" \
    node "$here/xatlas_run.cjs" "$mesh" "$OUT/$name.xatlas.obj" > "$OUT/$name.xatlas.log" 2>&1
  xatlas_status=$?
  dlf_score='null'; xatlas_score='null'
  [ -s "$OUT/$name.dlf.obj" ] && [ $dlf_status -ne 1 ] && [ $dlf_status -ne 2 ] && dlf_score=$("$SCORE" "$OUT/$name.dlf.obj")
  [ $xatlas_status -eq 0 ] && xatlas_score=$("$SCORE" "$OUT/$name.xatlas.obj")
  [ $xatlas_status -eq 0 ] || echo "atlas_vs_xatlas: $name: xatlas: $(tail -1 "$OUT/$name.xatlas.log")" >&2
  echo "{\"mesh\": \"$name\", \"dlf_status\": $dlf_status, \"xatlas_status\": $xatlas_status," \
       "\"dlf_time\": [$(tr ' ' , < "$OUT/$name.dlf.time" | tail -1)], \"xatlas_time\": [$(tr ' ' , < "$OUT/$name.xatlas.time" | tail -1)]," \
       "\"dlf\": $dlf_score, \"xatlas\": $xatlas_score}" >> "$rows"
  echo "atlas_vs_xatlas: $name done" >&2
done
if [ -n "${PICTURE:-}" ] && [ -s "$OUT/$PICTURE.dlf.obj" ] && [ -s "$OUT/$PICTURE.xatlas.obj" ]; then
  python3 "$here/atlas_picture.py" "$OUT/$PICTURE.png" "dlf atlas" "$OUT/$PICTURE.dlf.obj" xatlas "$OUT/$PICTURE.xatlas.obj"
fi
python3 - "$rows" <<'PY'
import json, sys, statistics
rows = [json.loads(l) for l in open(sys.argv[1])]
print("| mesh | faces | charts dlf / xatlas | seam/√A dlf / xatlas | packing dlf / xatlas | D_area dlf / xatlas | inverted dlf / xatlas | overlaps dlf / xatlas | CPU s dlf / xatlas | wall s dlf / xatlas | CPU ratio | MiB dlf / xatlas |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
pack_d, pack_x, ratios, ratios_big, lower = [], [], [], [], 0
both = 0
for r in rows:
    d, x = r["dlf"], r["xatlas"]
    if d is None or x is None:
        print(f"| {r['mesh']} | – | dlf exit {r['dlf_status']}, xatlas exit {r['xatlas_status']} |||||||||||")
        continue
    both += 1
    dt, xt = r["dlf_time"], r["xatlas_time"]
    dc, xc = dt[1] + dt[2], xt[1] + xt[2]
    ratio = xc / dc if dc > 0 else float("inf")
    ratios.append(ratio)
    if d["faces"] >= 75000: ratios_big.append(ratio)
    pack_d.append(d["packing_efficiency"]); pack_x.append(x["packing_efficiency"])
    lower += d["d_area"] < x["d_area"]
    print(f"| {r['mesh']} | {d['faces']} | {d['charts']} / {x['charts']} | {d['seam_over_sqrt_area']:.2f} / {x['seam_over_sqrt_area']:.2f} "
          f"| {d['packing_efficiency']:.3f} / {x['packing_efficiency']:.3f} | {d['d_area']:.4f} / {x['d_area']:.4f} "
          f"| {d['inverted'] + d['degenerate']} / {x['inverted'] + x['degenerate']} "
          f"| {d['overlapping_face_pairs']} / {x['overlapping_face_pairs']} ({x['overlapping_pairs_in_a_chart']} in a chart) "
          f"| {dc:.2f} / {xc:.2f} | {dt[0]:.2f} / {xt[0]:.2f} | {ratio:.1f}× | {dt[3] / 1024:.0f} / {xt[3] / 1024:.0f} |")
if both:
    print()
    print(f"meshes scored for both: {both}; median packing efficiency dlf {statistics.median(pack_d):.3f}, xatlas {statistics.median(pack_x):.3f}; "
          f"D_area lower for dlf on {lower} of {both}; median CPU ratio xatlas / dlf {statistics.median(ratios):.1f}×"
          + (f", from 75K faces {statistics.median(ratios_big):.1f}× ({len(ratios_big)} meshes)" if ratios_big else ""))
PY
