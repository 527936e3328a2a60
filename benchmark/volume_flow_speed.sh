#!/usr/bin/env bash
# The volumetric flow alone at large sizes, its preconditioner and threads
# side by side from one certified start (doc/volume.md, "Speed of the flow
# at 1M tetrahedra"): makes the start once with `dlf volume --max-iterations
# 0` (cached in WORK), then runs benchmark/volume_flow_speed.cpp on it with
# each variant, one after the other, and prints a Markdown table
# (iterations, conjugate-gradient steps, D_vol, exact inverted count, wall
# and user CPU seconds of the flow).
#
#   DLF=build/tools/dlf SPEED=build/benchmark/volume_flow_speed \
#     bash benchmark/volume_flow_speed.sh MESH.mesh
#
# MESH: a tetrahedral mesh (e.g. `dlf tetrahedralize bunny00.off --tets
# 1000000`). VARIANTS overrides the list (one per line: a label, a colon,
# the options of volume_flow_speed).
set -eu
mesh=$1
DLF=${DLF:-build/tools/dlf}
SPEED=${SPEED:-build/benchmark/volume_flow_speed}
WORK=${WORK:-volume-speed-work}
mkdir -p "$WORK"
start="$WORK/$(basename "$mesh" .mesh)-start.mesh"
if [ ! -f "$start" ]; then
  "$DLF" volume "$mesh" --max-iterations 0 -o "$start" -q || [ -s "$start" ]
fi
VARIANTS=${VARIANTS:-"default, 1 thread:--threads 1
default, 2 threads:--threads 2
blocks alone, fixed tolerance (before), 2 threads:--threads 2 --coarse 0 --no-forcing
blocks alone, forcing, 2 threads:--threads 2 --coarse 0
aggregates of 64, fixed tolerance, 2 threads:--threads 2 --no-forcing
aggregates of 32, 2 threads:--threads 2 --coarse 32
aggregates of 128, 2 threads:--threads 2 --coarse 128"}
echo "| variant | it. | CG steps | D_vol | inverted (exact) | flow wall s | flow user s |"
echo "|---|---|---|---|---|---|---|"
while IFS= read -r line; do
  [ -n "$line" ] || continue
  label=${line%%:*}
  opts=${line#*:}
  # shellcheck disable=SC2086
  out=$("$SPEED" "$mesh" "$start" $opts | tail -1)
  get() { echo "$out" | sed -n "s/.* $1 \([^ ]*\).*/\1/p"; }
  echo "| $label | $(get iterations) | $(get cg) | $(get D_vol) | $(get inverted) | $(get flow) | $(get user) |"
done <<< "$VARIANTS"
