#!/usr/bin/env bash
# Builds and runs paper_tables (DLF against a semi-discrete optimal transport
# map on the disk: the paper's Tables 3, 4, 6 and Figs. 17-18; the spherical
# DLF's Area_total: Table 5), then writes its tables into
# doc/paper_experiments.md (between the GENERATED markers; the text around
# them is kept) and all the numbers into doc/paper_experiments.json.
#
#   benchmark/paper_tables.sh                                # every default mesh (about 20 min on a busy 2-core machine)
#   benchmark/paper_tables.sh --meshes blob.off --sphere-meshes bear.off
#   BUILD_DIR=build build/benchmark/paper_tables --check     # checks of the OT solver only
#
# BUILD_DIR (default: build) is the CMake build directory; DATA_DIR (default:
# the build's DLF_DATA_DIR) holds CGAL's data set (meshes in $DATA_DIR/meshes).
set -euo pipefail
source "$(dirname "$0")/generated_doc.sh"
run_into_doc paper_tables paper_experiments "The paper's experiments: DLF against optimal transport, and the sphere's Area_total" benchmark/paper_tables.sh "$@"
