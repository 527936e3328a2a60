#!/usr/bin/env bash
# Builds the libFuzzer target fuzz/dlf_fuzz.cpp (clang, ASan + UBSan) into
# build-fuzz/ and runs it in one mode (DLF_FUZZ_MODE: mesh, the default,
# ply, stl, ts, literal, selection, density, uv, medit; fuzz/dlf_fuzz.cpp
# says what each reads) for SECONDS on one core at the lowest priority
# (FUZZ_NICE: the nice level, 19 by default), starting from
# fuzz/seeds/MODE (the literal mode: fuzz/seeds/mesh) and the corpus kept
# in build-fuzz/corpus/MODE.
# Crashes, timeouts and leaks land in build-fuzz/artifacts/MODE-*; replay one with
#   DLF_FUZZ_MODE=MODE build-fuzz/dlf_fuzz build-fuzz/artifacts/MODE-crash-...
#   bash fuzz/run.sh 600          # ten minutes of the mesh mode
#   DLF_FUZZ_MODE=medit bash fuzz/run.sh 600
#   bash fuzz/run.sh 0            # build only
#   FUZZ_RUNS=80000 bash fuzz/run.sh   # 80,000 inputs, seed 1, the same on every machine (CI: .ci/fuzz, every mode)
# Needs clang and libclang-rt (Debian: apt-get install clang libclang-rt-14-dev).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

SECONDS_TO_RUN="${1:-60}"
BUILD_DIR="${FUZZ_BUILD_DIR:-build-fuzz}"
CXX="${FUZZ_CXX:-$(command -v clang++ || command -v clang++-14)}"
export DLF_FUZZ_MODE="${DLF_FUZZ_MODE:-mesh}"
MODE=$DLF_FUZZ_MODE
SEEDS=fuzz/seeds/$MODE
[[ "$MODE" == literal ]] && SEEDS=fuzz/seeds/mesh
[[ -d "$SEEDS" ]] || { echo "fuzz: unknown mode '$MODE' (no $SEEDS)" >&2; exit 2; }
mkdir -p "$BUILD_DIR/obj" "$BUILD_DIR/corpus/$MODE" "$BUILD_DIR/artifacts" "$BUILD_DIR/tmp"

# CGAL and Eigen keep their assertions (no NDEBUG): a violated precondition
# is a finding too. Undefined behaviour aborts (halt_on_error), except what
# fuzz/ubsan.supp lists in third-party headers, which needs the check to be
# recoverable. The default SPD solver (Eigen's) avoids linking CHOLMOD.
# Line tables only (-gline-tables-only): a finding's stack trace names file
# and line as with -g, and the six sources compile in two thirds of the time.
flags=(-std=c++17 -O1 -gline-tables-only -fno-omit-frame-pointer
       -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all
       -fsanitize-recover=float-cast-overflow
       -Iinclude -Itools/dlf -isystem /usr/include/eigen3 -DCGAL_EIGEN3_ENABLED)
sources=(fuzz/dlf_fuzz.cpp tools/dlf/mesh_input.cpp tools/dlf/seam_input.cpp tools/dlf/density_input.cpp
         tools/dlf/obj_io.cpp tools/dlf/arguments.cpp)
# Changed flags rebuild everything.
if [[ "$(cat "$BUILD_DIR/flags" 2>/dev/null)" != "$CXX ${flags[*]}" ]]; then
  rm -f "$BUILD_DIR"/obj/*.o
  echo "$CXX ${flags[*]}" >"$BUILD_DIR/flags"
fi
objects=()
compiling=()
for src in "${sources[@]}"; do
  obj="$BUILD_DIR/obj/$(basename "$src" .cpp).o"
  objects+=("$obj")
  # Rebuild when the source or any project header is newer than the object.
  if [[ ! -f "$obj" || -n "$(find "$src" include tools/dlf -newer "$obj" \( -name '*.h' -o -path "$src" \) | head -1)" ]]; then
    echo "fuzz: compiling $src"
    # FUZZ_JOBS compiles at a time (2 by default); the largest source first.
    while (( $(jobs -rp | wc -l) >= ${FUZZ_JOBS:-2} )); do wait -n; done
    nice -n "${FUZZ_NICE:-19}" "$CXX" "${flags[@]}" -c "$src" -o "$obj" &
    compiling+=($!)
  fi
done
for pid in "${compiling[@]}"; do wait "$pid"; done
if [[ ! -x "$BUILD_DIR/dlf_fuzz" || -n "$(find "${objects[@]}" -newer "$BUILD_DIR/dlf_fuzz" | head -1)" ]]; then
  "$CXX" "${flags[@]}" "${objects[@]}" -lboost_program_options -lgmp -lmpfr -o "$BUILD_DIR/dlf_fuzz"
fi
[[ "$SECONDS_TO_RUN" -gt 0 || -n "${FUZZ_RUNS:-}" ]] || exit 0

export TMPDIR="$(cd "$BUILD_DIR" && pwd)/tmp"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1:suppressions=$PWD/fuzz/ubsan.supp}"
set +e
if [[ -n "${FUZZ_RUNS:-}" ]]; then
  # Reproducible: FUZZ_RUNS inputs from the seeds alone, in one process,
  # with a fixed random seed, so that any machine explores the same inputs
  # (CI runs this; a finding stops the run and is written to artifacts/).
  rm -rf "$BUILD_DIR/fixed-corpus/$MODE"
  mkdir -p "$BUILD_DIR/fixed-corpus/$MODE"
  nice -n "${FUZZ_NICE:-19}" "$BUILD_DIR/dlf_fuzz" -seed="${FUZZ_SEED:-1}" -runs="$FUZZ_RUNS" -timeout=20 -rss_limit_mb=2048 \
    -max_len=8192 -dict=fuzz/mesh.dict -artifact_prefix="$BUILD_DIR/artifacts/$MODE-" -print_final_stats=1 \
    "$BUILD_DIR/fixed-corpus/$MODE" "$SEEDS" 2>&1 | tee "$BUILD_DIR/last_run_$MODE.log" | grep -E '^#[0-9]+.*(pulse|DONE)|ERROR|SUMMARY|Test unit written|Done [0-9]+ runs'
  status=${PIPESTATUS[0]}
  set -e
  echo "fuzz: $MODE: exit $status after $FUZZ_RUNS runs (seed ${FUZZ_SEED:-1}); log $BUILD_DIR/last_run_$MODE.log; $(ls "$BUILD_DIR/artifacts" | wc -l) artifacts in $BUILD_DIR/artifacts/"
  exit "$status"
fi
# Exploratory: one fuzzing process at a time (-fork=1: a child that dies is
# replaced and its input kept in artifacts/, so one run reports every
# finding) for SECONDS, from the kept corpus; the machines this runs on are
# shared.
nice -n "${FUZZ_NICE:-19}" "$BUILD_DIR/dlf_fuzz" -max_total_time="$SECONDS_TO_RUN" -timeout=20 -rss_limit_mb=2048 \
  -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
  -max_len=8192 -dict=fuzz/mesh.dict -artifact_prefix="$BUILD_DIR/artifacts/$MODE-" -print_final_stats=1 \
  "$BUILD_DIR/corpus/$MODE" "$SEEDS" 2>&1 | tee "$BUILD_DIR/last_run_$MODE.log" | grep -E '^#[0-9]+: |crash|ERROR|SUMMARY|Test unit written|INFO: exiting'
status=${PIPESTATUS[0]}
set -e
echo "fuzz: $MODE: exit $status; log $BUILD_DIR/last_run_$MODE.log; $(ls "$BUILD_DIR/artifacts" | wc -l) artifacts in $BUILD_DIR/artifacts/"
exit "$status"
