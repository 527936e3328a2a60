#!/usr/bin/env bash
# Builds and runs the spherical DLF benchmark, then writes its tables into
# doc/sphere_benchmark.md (between the GENERATED markers; the text around them
# is kept) and all the numbers into doc/sphere_benchmark.json.
#
#   benchmark/sphere.sh                                  # every closed genus-0 mesh + the large section
#   benchmark/sphere.sh --meshes sphere.off --no-large   # extra options go to sphere_benchmark
#   benchmark/sphere.sh --check                          # and exit 3 when a goal the page states is missed
#
# BUILD_DIR (default: build) is the CMake build directory; DATA_DIR (default:
# the build's DLF_DATA_DIR) holds CGAL's data set (meshes in $DATA_DIR/meshes).
set -euo pipefail
source "$(dirname "$0")/generated_doc.sh"
run_into_doc sphere_benchmark sphere_benchmark "Spherical Discrete Lie Flow: benchmark" benchmark/sphere.sh "$@"
