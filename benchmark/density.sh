#!/usr/bin/env bash
# Builds and runs the measure-control benchmark (what a density costs against
# the area-preserving run), then writes its tables into
# doc/density_benchmark.md (between the GENERATED markers; the text around
# them is kept) and all the numbers into doc/density_benchmark.json.
#
#   benchmark/density.sh                          # main, band and refined sections (3-4 min on 2 cores)
#   benchmark/density.sh --bands "" --refined ""  # extra options go to density_benchmark
#
# BUILD_DIR (default: build) is the CMake build directory; DATA_DIR (default:
# the build's DLF_DATA_DIR) holds CGAL's data set (meshes in $DATA_DIR/meshes).
set -euo pipefail
source "$(dirname "$0")/generated_doc.sh"
run_into_doc density_benchmark density_benchmark "Measure control: benchmark" benchmark/density.sh "$@"
