#!/usr/bin/env bash
# The volumetric flow's certified start beside a peer build: for every
# tetrahedral mesh given, `dlf volume` of BASE and then of DLF (defaults,
# whole process timed by /usr/bin/time, one right after the other so that
# both see the same load), and a Markdown table of the start (Tutte's
# folds, the untangling's iterations and seconds, border + interior +
# untangling seconds), the flow's iterations, D_vol, the stop and the whole
# process's seconds, before (BASE) and after (DLF).
#
#   BASE=old/dlf DLF=build/tools/dlf bash benchmark/volume_start.sh A.mesh B.mesh ...
#
# VOLUME_ARGS adds options to both runs (e.g. "--max-iterations 0": the
# start alone). The .mesh files: `dlf tetrahedralize` (benchmark/volume.sh
# keeps its meshes in its WORK directory).
set -u
BASE=${BASE:?the peer build of dlf}
DLF=${DLF:-build/tools/dlf}
WORK=${WORK:-volume-start-work}
mkdir -p "$WORK"
echo "| mesh | tets | Tutte folds | untangle it. before | after | untangle s before | after | start s before | after | flow it. before | after | D_vol before | after | stop before | after | whole process s before | after |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for mesh in "$@"; do
  name=$(basename "$mesh" .mesh)
  for side in before after; do
    if [ $side = before ]; then bin=$BASE; else bin=$DLF; fi
    rm -f "$WORK/$name-$side.json" # a failed run leaves none
    # shellcheck disable=SC2086
    /usr/bin/time -f "%e" -o "$WORK/$name-$side.time" "$bin" volume "$mesh" -o "$WORK/$name-$side-ball.mesh" \
      --report "$WORK/$name-$side.json" -q ${VOLUME_ARGS:-} 2> "$WORK/$name-$side.err"
  done
  /usr/bin/python3 - "$WORK" "$name" <<'PY'
import json, os, sys
work, name = sys.argv[1], sys.argv[2]
def load(side):
    p = os.path.join(work, "%s-%s.json" % (name, side))
    if not os.path.exists(p) or os.path.getsize(p) == 0:
        return None
    return json.load(open(p))
a, b = load("before"), load("after")
secs = [open(os.path.join(work, "%s-%s.time" % (name, s))).read().split()[-1] for s in ("before", "after")]
if a is None or b is None:
    print("| %s | error (see %s/%s-*.err) | | | | | | | | | | | | | | %s | %s |" % (name, work, name, secs[0], secs[1]))
    sys.exit(0)
start = lambda r: r["seconds"]["border"] + r["seconds"]["interior"] + r["seconds"]["untangle"]
print("| %s | %s | %d | %s | %s | %.2f | %.2f | %.2f | %.2f | %d | %d | %.4f | %.4f | %s | %s | %s | %s |" % (
    name, format(a["tets"], ","), a["start"]["tutte_negative_tets"] + a["start"]["tutte_flat_tets"],
    format(a["start"]["untangle_iterations"], ","), format(b["start"]["untangle_iterations"], ","),
    a["seconds"]["untangle"], b["seconds"]["untangle"], start(a), start(b), a["iterations"], b["iterations"],
    a["final"]["d_vol"], b["final"]["d_vol"], a["stop_reason"], b["stop_reason"], secs[0], secs[1]))
PY
done
