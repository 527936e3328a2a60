#!/usr/bin/env bash
# Robustness study: writes the hostile-input corpus (robustness_corpus
# --corpus-only) and runs every case x method through dlf-study on a dask
# LocalCluster, each run in its own process with a timeout and a 4 GiB
# address-space limit, one SQLite row per run: dlf disk (both modes) and
# dlf sphere with every map checked (--check-outputs), the DLF library API
# and CGAL's iterative authalic, ARAP and mean-value parameterizers through
# robustness_corpus --run (--runner). The tables of doc/robustness.md (between
# the GENERATED markers; the text above them is kept) are then written from
# the database. Exit status: 0 when DLF has no violation, 3 otherwise (1 when
# runs are missing: run again with RESUME=1).
#   bash benchmark/robustness.sh                     # full study (~5 min on 2 busy cores)
#   WORKERS=4 TIMEOUT=30 SCRATCH=/tmp/r bash benchmark/robustness.sh
#   RESUME=1 bash benchmark/robustness.sh            # keep SCRATCH's database, run only the missing rows
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-2}"
SCRATCH="${SCRATCH:-/tmp/dlf_robustness}"
TIMEOUT="${TIMEOUT:-60}"
WORKERS="${WORKERS:-2}"
DOC=doc/robustness.md

cmake -S . -B "$BUILD_DIR" -DDLF_BUILD_BENCHMARK=ON >/dev/null
cmake --build "$BUILD_DIR" --target robustness_corpus dlf dlf_python -j"$JOBS"
data="$(sed -n 's/^DLF_DATA_DIR:PATH=//p' "$BUILD_DIR/CMakeCache.txt")/meshes"

[[ "${RESUME:-0}" == 1 ]] || rm -rf "$SCRATCH"
mkdir -p "$SCRATCH"
rm -rf "$SCRATCH/corpus"  # deterministic: the same files again
"$BUILD_DIR/benchmark/robustness_corpus" --data "$data" --corpus-only "$SCRATCH/corpus"

start=$(date +%s)
PYTHONPATH="$PWD/$BUILD_DIR/python" /usr/bin/python3 -m discrete_lie_flow.study run "$SCRATCH/corpus" \
  --db "$SCRATCH/robustness.sqlite" --workers "$WORKERS" --timeout "$TIMEOUT" --memory-limit 4 \
  --dlf "$BUILD_DIR/tools/dlf" --runner "$BUILD_DIR/benchmark/robustness_corpus" --every-config --check-outputs \
  --config disk-certified@disk --config disk-paper@disk --config sphere@sphere --config dlf_api@api \
  --config cgal_iterative_authalic@disk --config cgal_arap@disk --config cgal_mvc@disk \
  -q || echo "robustness: dlf-study exited $? (rows not recorded are reported as missing below)"
echo "robustness: study run in $(( $(date +%s) - start )) s"

status=0
/usr/bin/python3 benchmark/robustness_report.py "$SCRATCH/robustness.sqlite" "$SCRATCH/corpus/cases.json" \
  --markdown "$SCRATCH/table.md" || status=$?

# Splice the generated tables into the document.
begin='<!-- BEGIN GENERATED (benchmark/robustness.sh) -->'
end='<!-- END GENERATED -->'
if [[ -f "$DOC" ]] && grep -qF "$begin" "$DOC"; then
  { awk -v b="$begin" '{ print } $0 == b { exit }' "$DOC"
    echo "_Generated $(date -u +%Y-%m-%d) by \`bash benchmark/robustness.sh\`; corpus files in \`corpus/\` under the scratch directory (\`SCRATCH\`), rows in \`robustness.sqlite\` there._"
    echo
    cat "$SCRATCH/table.md"
    awk -v e="$end" '$0 == e { on = 1 } on { print }' "$DOC"
  } >"$SCRATCH/doc.md"
else
  { echo "# Robustness"; echo; echo "$begin"; cat "$SCRATCH/table.md"; echo "$end"; } >"$SCRATCH/doc.md"
fi
mv "$SCRATCH/doc.md" "$DOC"
echo "robustness: tables written to $DOC (rows: $SCRATCH/robustness.sqlite); exit $status"
exit "$status"
