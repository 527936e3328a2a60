#!/usr/bin/env bash
# Large meshes (doc/large_meshes.md): the default `dlf disk` (coarse to fine)
# on lion-head and mannequin-devil subdivided 2 to 4 times by Loop (267K to
# 6.6M faces), and on the same meshes scrambled (edges flipped, vertices
# moved: no longer subdivisions), whole process and its split, beside the
# plain flow (--coarse-to-fine-faces 0) on the same mesh in the same run.
#
#   benchmark/large_meshes.sh                  # all sizes (about 20 minutes on 2 cores)
#   benchmark/large_meshes.sh SPEC...          # some, e.g. mannequin-devil.off+loop2
#   benchmark/large_meshes.sh --big            # the two largest rows, not subdivisions, default only:
#                                              # three_peaks+loop5+scramble (3.76M faces) and
#                                              # mannequin-devil+loop5+scramble (26.5M faces, a 24 GiB machine)
#
# The benchmark frees its copy of each mesh once the OFF file is written,
# before the dlf runs: the child has the machine's memory to itself.
#
# DLF (default build/tools/dlf), BENCH (default build/benchmark/large_meshes),
# DATA (default build/data, with meshes/), WORK (default: a temporary
# directory, removed after; the subdivided meshes are written there),
# JSON (optional: every number).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
DLF="${DLF:-build/tools/dlf}"
BENCH="${BENCH:-build/benchmark/large_meshes}"
DATA="${DATA:-build/data}"
[[ -x "$DLF" ]] || { echo "large_meshes: $DLF not built" >&2; exit 2; }
[[ -x "$BENCH" ]] || { echo "large_meshes: $BENCH not built (-DDLF_BUILD_BENCHMARK=ON, target large_meshes)" >&2; exit 2; }
if [[ -z "${WORK:-}" ]]; then
  WORK="$(mktemp -d)"
  trap 'rm -rf "$WORK"' EXIT
fi
args=(--dlf "$DLF" --data-dir "$DATA" --work "$WORK")
specs=("$@")
if [[ ${#specs[@]} -gt 0 && "${specs[0]}" == "--big" ]]; then
  # The plain flow beside them would not fit: its factor of 26M faces takes more than 24 GiB.
  specs=(three_peaks.off+loop5+scramble mannequin-devil.off+loop5+scramble)
  args+=(--no-plain)
elif [[ ${#specs[@]} -eq 0 ]]; then
  specs=(lion-head.off+loop2 lion-head.off+loop3
         mannequin-devil.off+loop2 mannequin-devil.off+loop3 mannequin-devil.off+loop4
         mannequin-devil.off+loop2+scramble mannequin-devil.off+loop3+scramble mannequin-devil.off+loop4+scramble)
fi
[[ -n "${JSON:-}" ]] && args+=(--json "$JSON")
# Each mesh and its outputs are removed once measured: the largest take GBs.
exec "$BENCH" "${args[@]}" "${specs[@]}"
