#!/usr/bin/env bash
# Builds and runs the DLF benchmark, then writes its tables into doc/benchmark.md
# (between the GENERATED markers; the text around them is kept) and all the
# numbers into doc/benchmark.json.
#
#   benchmark/run.sh                 # everything (15-20 min on an idle 2-core machine, an hour under load)
#   benchmark/run.sh --meshes lion-head.off --table2 ""   # extra options go to dlf_benchmark
#
# BUILD_DIR (default: build) is the CMake build directory; DATA_DIR (default:
# the build's DLF_DATA_DIR) holds CGAL's data set (meshes in $DATA_DIR/meshes).
set -euo pipefail
source "$(dirname "$0")/generated_doc.sh"
run_into_doc dlf_benchmark benchmark Benchmark benchmark/run.sh "$@"
