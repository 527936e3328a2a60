#!/usr/bin/env bash
# dlf-study over CGAL's data set (every mesh x disk-certified, disk-paper,
# sphere, sphere-paper: the configurations its topology fits run, the others
# are recorded as not applicable) on a LocalCluster of 1, then 2 workers:
# wall time of each study, its throughput (runs executed per second), the
# ratio, and a check that each database holds every (mesh, configuration)
# exactly once. Needs the Python module built (target dlf_python) and dask.
#   bash benchmark/study_throughput.sh
#   TIMEOUT=120 OUT=/tmp/t bash benchmark/study_throughput.sh
#   ORDER="2 1" bash benchmark/study_throughput.sh    # 2 workers first (load drifts on a busy machine)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR="${BUILD_DIR:-build}"
OUT="${OUT:-/tmp/dlf_study_throughput}"
TIMEOUT="${TIMEOUT:-300}"
PY=/usr/bin/python3
data="$(sed -n 's/^DLF_DATA_DIR:PATH=//p' "$BUILD_DIR/CMakeCache.txt")/meshes"
export PYTHONPATH="$PWD/$BUILD_DIR/python"
mkdir -p "$OUT"

declare -A seconds
for n in ${ORDER:-1 2}; do
  db="$OUT/workers$n.sqlite"
  rm -f "$db" "$db-wal" "$db-shm"
  echo "workers $n: load average $(cut -d' ' -f1-3 /proc/loadavg)"
  start=$(date +%s.%N)
  "$PY" -m discrete_lie_flow.study run "$data" --db "$db" --workers "$n" --timeout "$TIMEOUT" \
    --dlf "$BUILD_DIR/tools/dlf" -q
  end=$(date +%s.%N)
  seconds[$n]=$("$PY" -c "print($end - $start)")
  "$PY" - "$db" "$data" "${seconds[$n]}" <<'PYEOF'
import sqlite3, sys
from discrete_lie_flow import study
db, data, secs = sys.argv[1], sys.argv[2], float(sys.argv[3])
meshes = study.corpus_meshes([data])
expected = {(k, c) for k, _ in meshes for c in study.DEFAULT_CONFIGS}
con = sqlite3.connect(db)
rows = list(con.execute("SELECT mesh, config, status FROM runs"))
keys = [(m, c) for m, c, _ in rows]
assert len(keys) == len(set(keys)), "a duplicated row"
assert set(keys) == expected, f"missing {len(expected - set(keys))}, unexpected {len(set(keys) - expected)}"
executed = sum(s != "not_applicable" for _, _, s in rows)
counts = {}
for _, _, s in rows:
    counts[s] = counts.get(s, 0) + 1
print(f"  {len(meshes)} meshes, {len(rows)} rows (each once), {executed} runs executed in {secs:.1f} s: "
      f"{executed / secs:.3f} runs/s; " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
PYEOF
  echo "  load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
done
echo "throughput 2 workers / 1 worker: $("$PY" -c "print(f'{${seconds[1]} / ${seconds[2]}:.3f}')")"
