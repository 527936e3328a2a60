#!/usr/bin/env bash
# What the OpenMP regions inside the sparse solver cost a whole `dlf`
# process: the same command run alternately as it is and with every OpenMP
# region executed inline on the calling thread (a preloaded GOMP_parallel
# that just calls the region's function; a measurement only, never how the
# library runs). CHOLMOD (Debian 12) opens a region per step of its
# supernodal factorization, guarded by an `if` on the step's size, and
# libgomp builds and frees a one-thread team even when the guard is false.
# The two runs must agree on every reported number (the regions only
# split loops); the script says so, then prints wall and CPU seconds
# (user + sys, /usr/bin/time) of each run and their ratios.
#
#   benchmark/openmp_region_cost.sh [ROUNDS] -- dlf sphere MESH.off
#
# BUILD_DIR (default: build): `dlf` is run from $BUILD_DIR/examples.
# Needs a C compiler (cc), /usr/bin/time and python3. Results:
# doc/sphere.md, "Where the time goes, and cheaper directions that did not pay".
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BUILD_DIR="${BUILD_DIR:-build}"
rounds=2
if [[ $# -gt 0 && "$1" != "--" ]]; then rounds="$1"; shift; fi
[[ "${1:-}" == "--" ]] && shift
[[ "${1:-}" == "dlf" ]] || { echo "usage: $0 [ROUNDS] -- dlf COMMAND ARGS..." >&2; exit 2; }
shift
DLF="$BUILD_DIR/tools/dlf"
[[ -x "$DLF" ]] || { echo "openmp_region_cost: build dlf first" >&2; exit 2; }
command -v cc >/dev/null || { echo "openmp_region_cost: a C compiler (cc) is needed" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "openmp_region_cost: /usr/bin/time is needed (Debian package 'time')" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cat > "$work/inline_regions.c" <<'EOF'
/* Runs an OpenMP parallel region on the calling thread alone. */
void GOMP_parallel(void (*fn)(void *), void *data, unsigned num_threads, unsigned flags)
{
  (void)num_threads;
  (void)flags;
  fn(data);
}
EOF
cc -O2 -shared -fPIC -o "$work/inline_regions.so" "$work/inline_regions.c"

echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
for ((k = 1; k <= rounds; ++k)); do
  for variant in as_built inline; do
    preload=""
    [[ $variant == inline ]] && preload="$work/inline_regions.so"
    LD_PRELOAD="$preload" /usr/bin/time -f '%e %U %S' -o "$work/$variant.$k.time" \
      "$DLF" "$@" -q --report "$work/$variant.$k.json" -o "$work/$variant.$k.out"
  done
done
python3 - "$work" "$rounds" <<'PY'
import json, sys
work, rounds = sys.argv[1], int(sys.argv[2])
def load(variant, k):
    r = json.load(open(f"{work}/{variant}.{k}.json"))
    wall, user, sys_ = map(float, open(f"{work}/{variant}.{k}.time").read().split()[-3:])
    for key in ("seconds",):
        r.pop(key, None)
    return r, wall, user + sys_
same = True
print("| round | as built: wall s | CPU s | inline regions: wall s | CPU s | CPU ratio |")
print("|---:|---:|---:|---:|---:|---:|")
for k in range(1, rounds + 1):
    a, wa, ca = load("as_built", k)
    b, wb, cb = load("inline", k)
    same = same and a == b
    print(f"| {k} | {wa:.2f} | {ca:.2f} | {wb:.2f} | {cb:.2f} | {cb / ca:.3f} |")
print("reports identical (seconds aside):", "yes" if same else "NO")
sys.exit(0 if same else 1)
PY
