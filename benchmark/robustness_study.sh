#!/usr/bin/env bash
# The hostile-input corpus of robustness_corpus, run by dlf-study (the dlf
# tool alone: disk cases through dlf disk in both modes, sphere cases
# through dlf sphere in both modes, each case given to its commands whatever
# its topology, as the corpus intends), on a LocalCluster; the summary and
# plots in $OUT/report. The library-API cases and CGAL's parameterizers stay
# in benchmark/robustness.sh.
#   bash benchmark/robustness_study.sh
#   WORKERS=4 TIMEOUT=30 OUT=/tmp/r bash benchmark/robustness_study.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR="${BUILD_DIR:-build}"
OUT="${OUT:-/tmp/dlf_robustness_study}"
TIMEOUT="${TIMEOUT:-60}"
WORKERS="${WORKERS:-2}"
cmake --build "$BUILD_DIR" --target robustness_corpus dlf dlf_python -j2
rm -rf "$OUT"
mkdir -p "$OUT"
"$BUILD_DIR/benchmark/robustness_corpus" --corpus-only "$OUT/corpus"
export PYTHONPATH="$PWD/$BUILD_DIR/python"
study=(/usr/bin/python3 -m discrete_lie_flow.study)
common=(--db "$OUT/robustness.sqlite" --workers "$WORKERS" --timeout "$TIMEOUT" --dlf "$BUILD_DIR/examples/dlf"
        --every-config -q)
"${study[@]}" run "$OUT/corpus/disk" --config disk-certified --config disk-paper "${common[@]}"
"${study[@]}" run "$OUT/corpus/sphere" --config sphere --config sphere-paper "${common[@]}"
"${study[@]}" report "$OUT/robustness.sqlite" -o "$OUT/report"
bad=$(/usr/bin/python3 -c "import sqlite3, sys; print(sqlite3.connect(sys.argv[1]).execute(\"SELECT count(*) FROM runs WHERE status IN ('crash', 'timeout', 'error')\").fetchone()[0])" "$OUT/robustness.sqlite")
echo "robustness study: $OUT/report/summary.md; crashes, timeouts and other tool failures: $bad"
[[ "$bad" -eq 0 ]]
