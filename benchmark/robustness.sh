#!/usr/bin/env bash
# Robustness study: builds the corpus runner and dlf, runs the
# hostile-input corpus through dlf disk/sphere, the DLF library API and CGAL's
# iterative authalic, ARAP and mean-value parameterizers, and writes the
# tables into doc/robustness.md (between the GENERATED markers; the policy
# text above them is kept). Exit status: 0 when DLF has no violation, 3 otherwise.
#   bash benchmark/robustness.sh                 # full study (~2-5 min on 2 cores)
#   TIMEOUT=30 SCRATCH=/tmp/r bash benchmark/robustness.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

BUILD_DIR="${BUILD_DIR:-build}"
JOBS="${JOBS:-2}"
SCRATCH="${SCRATCH:-/tmp/dlf_robustness}"
TIMEOUT="${TIMEOUT:-60}"
DOC=doc/robustness.md

cmake -S . -B "$BUILD_DIR" -DDLF_BUILD_BENCHMARK=ON >/dev/null
cmake --build "$BUILD_DIR" --target robustness_corpus dlf -j"$JOBS"
data="$(sed -n 's/^DLF_DATA_DIR:PATH=//p' "$BUILD_DIR/CMakeCache.txt")/meshes"

rm -rf "$SCRATCH"
mkdir -p "$SCRATCH"
status=0
"$BUILD_DIR/benchmark/robustness_corpus" --dlf "$BUILD_DIR/examples/dlf" --data "$data" \
  --scratch "$SCRATCH" --timeout "$TIMEOUT" --json "$SCRATCH/results.json" \
  --markdown "$SCRATCH/table.md" 2>"$SCRATCH/progress.log" || status=$?

# Splice the generated tables into the document.
begin='<!-- BEGIN GENERATED (benchmark/robustness.sh) -->'
end='<!-- END GENERATED -->'
if [[ -f "$DOC" ]] && grep -qF "$begin" "$DOC"; then
  { awk -v b="$begin" '{ print } $0 == b { exit }' "$DOC"
    echo "_Generated $(date -u +%Y-%m-%d) by \`bash benchmark/robustness.sh\`; corpus files in \`corpus/\` under the scratch directory (\`SCRATCH\`)._"
    echo
    cat "$SCRATCH/table.md"
    awk -v e="$end" '$0 == e { on = 1 } on { print }' "$DOC"
  } >"$SCRATCH/doc.md"
else
  { echo "# Robustness"; echo; echo "$begin"; cat "$SCRATCH/table.md"; echo "$end"; } >"$SCRATCH/doc.md"
fi
mv "$SCRATCH/doc.md" "$DOC"
echo "robustness: tables written to $DOC (raw results: $SCRATCH/results.json); exit $status"
exit "$status"
