#!/usr/bin/env bash
# The large and large irregular meshes of the sphere benchmark, timed as a
# user runs them: the default `dlf sphere MESH -o OUT.obj --report R.json`,
# whole process (wall and CPU seconds, maximum resident set, from
# /usr/bin/time), no environment variable set. The meshes are written first
# by `sphere_benchmark --write-meshes` (benchmark/irregular_meshes.h); extra
# options go to it (e.g. --irregular LIST, --large LIST).
#
#   benchmark/sphere_irregular_cli.sh [--irregular LIST] [--large LIST]
#
# BUILD_DIR (default: build) is the CMake build directory; WORK (default: a
# temporary directory) receives the meshes, outputs and reports.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR="${BUILD_DIR:-build}"
DLF="$BUILD_DIR/tools/dlf"
BENCH="$BUILD_DIR/benchmark/sphere_benchmark"
[[ -x "$DLF" && -x "$BENCH" ]] || { echo "sphere_irregular_cli: build dlf and sphere_benchmark first" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "sphere_irregular_cli: /usr/bin/time is needed (Debian package 'time')" >&2; exit 2; }
WORK="${WORK:-$(mktemp -d)}"
mkdir -p "$WORK/meshes"
"$BENCH" --write-meshes "$WORK/meshes" "$@" > "$WORK/meshes.txt"
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| mesh | faces | status | iterations | wall s | CPU s | wall s per 100K faces | max RSS MiB | final D_area | mean \\|log r\\| | inverted (report) |"
echo "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|"
while read -r path faces; do
  name="$(basename "$path" .off)"
  out="$WORK/$name.obj" report="$WORK/$name.json" timing="$WORK/$name.time"
  status=0
  env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT -u OPENBLAS_NUM_THREADS \
    /usr/bin/time -f '%e %U %S %M' -o "$timing" "$DLF" sphere "$path" -o "$out" --report "$report" -q || status=$?
  read -r wall user sys rss < <(tail -n 1 "$timing")
  python3 - "$name" "$faces" "$status" "$wall" "$user" "$sys" "$rss" "$report" <<'PY'
import json, sys
name, faces, status, wall, user, sys_, rss, report = sys.argv[1:]
faces = int(faces); wall = float(wall); cpu = float(user) + float(sys_)
try:
    r = json.load(open(report))
except Exception:
    r = {}
def get(*keys):
    x = r
    for k in keys:
        if not isinstance(x, dict) or k not in x: return None
        x = x[k]
    return x
fmt = lambda v, f: (f % v) if isinstance(v, (int, float)) else "-"
it = get("iterations")
d = get("final", "d_area")
m = get("final", "log_area_ratio", "mean_abs")
inv = get("caller_inverted_faces")
st = get("status") or ("exit %s" % status)
print(f"| {name} | {faces} | {st} | {fmt(it, '%d')} | {wall:.1f} | {cpu:.1f} | {wall * 1e5 / faces:.1f} | {int(rss) / 1024:.0f} | {fmt(d, '%.4f')} | {fmt(m, '%.4f')} | {fmt(inv, '%d')} |")
PY
done < "$WORK/meshes.txt"
echo
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
