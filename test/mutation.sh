#!/usr/bin/env bash
# Mutation check: do the tests bite? Applies deliberate bugs to the library,
# one at a time, on a scratch copy of the working tree, rebuilds the test
# executable there (one build directory for all mutations: only what a
# mutation touches recompiles) and runs a fast subset of the tests. A
# mutation is caught when a test of the subset fails; every one must be.
#
#   bash test/mutation.sh              # all mutations
#   bash test/mutation.sh 3 5          # only mutations 3 and 5 (numbers as listed)
#
#   MUTATION_DIR   scratch directory (default: a new mktemp -d, removed at
#                  the end); an existing one is reused, build included
#   DLF_DATA_DIR   CGAL's data set (default: <repo>/build/data)
#   JOBS           parallel compile jobs (default 2)
#
# Each mutation is an exact text replacement in one header; a text that does
# not occur exactly once is an error (the library changed: update the
# mutation), never a silent pass. Exit 0 only when every selected mutation
# applied and was caught. Not part of every CI run (a rebuild per mutation:
# about 2 minutes each on 2 cores).
set -euo pipefail
REPO=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
DATA_DIR=${DLF_DATA_DIR:-$REPO/build/data}
JOBS=${JOBS:-2}
[[ -d "$DATA_DIR/meshes" ]] || { echo "mutation: no meshes in $DATA_DIR/meshes (run .ci/install-deps)" >&2; exit 1; }

INC=include/CGAL/Surface_mesh_parameterization
DLF=$INC/internal/discrete_lie_flow
# name | header | text | replacement
MUTATIONS=(
  "critical root of the quadratic with the wrong sign|$DLF/core/critical_step.h|take(q / a);|take(-q / a);"
  "linear term of the signed-area quadratic with a wrong sign|$DLF/core/critical_step.h|ex * hy - ey * hx + gx * fy - gy * fx|ex * hy - ey * hx - gx * fy + gy * fx"
  "exact certification dropped (every triangle counted positive)|$DLF/core/certification.h|if(o == CGAL::POSITIVE) continue;|continue;"
  "area lumping skips a corner of every face|$DLF/core/area_elements.h|for(int k = 0; k < 3; ++k) out[faces[f][k]] += value[f] / 3;|for(int k = 0; k < 2; ++k) out[faces[f][k]] += value[f] / 3;"
  "report's target areas lumped from the domain's areas instead of the targets|$DLF/disk/disk_flow.h|lump_on_vertices(p.size(), out.domain_faces, out.domain_target, R.target_area);|lump_on_vertices(p.size(), out.domain_faces, u, R.target_area);"
  "plateau test the wrong way round (every run stops early)|$DLF/flow/flow_driver.h|back(m_rules.plateau_window) - x < m_rules.plateau_tolerance * (x - 1)|back(m_rules.plateau_window) - x > m_rules.plateau_tolerance * (x - 1)"
  "paper mode keeps the targets of flipped faces (no retargeting)|$DLF/disk/planar_paper_flow.h|m_target[std::size_t(f)] = m_targets(m_tri.faces[std::size_t(f)]); }|(void)f; }"
  "density ignored (targets are the surface areas)|$INC/Discrete_lie_flow_parameterizer_3.h|P.target[f] = rho * a;|P.target[f] = a;"
  "share error relative to the larger side (too lenient)|$DLF/core/density_levels.h|/ (std::min)(p, 1 - p);|/ (std::max)(p, 1 - p);"
  "circle fitted 0.01% too large (border off the circle)|$DLF/disk/boundary_curve.h|radius = r / double(pts.size());|radius = 1.0001 * r / double(pts.size());"
  "inverted faces never counted in the metrics|$DLF/core/distortion.h|if(inverted) ++m.inverted_faces;|if(false) ++m.inverted_faces;"
  "holes: the fill's targets almost nil (the holes shrink to nothing)|$DLF/disk/disk_holes.h|P.target.push_back(rho * (std::max)(area, hole_fill_floor * area_g));|P.target.push_back(rho * 1e-6 * area_g);"
  "holes: the fill oriented against the caller's faces|$DLF/disk/disk_holes.h|P.faces.push_back(Face{{ a, b, c }});|P.faces.push_back(Face{{ b, a, c }});"
  "holes: the caller's start kept (no Tutte embedding of the filled disk)|$INC/Discrete_lie_flow_parameterizer_3.h|if(!D::filled_disk_tutte<|if(false && !D::filled_disk_tutte<"
  "holes: the report counts the fill's faces|$DLF/disk/disk_flow.h|R.faces = P.caller_faces();|R.faces = P.faces.size();"
  "literal mode: the full critical step (no μ)|$DLF/flow/literal_rules.h|: step_fraction(opt, literal_default_mu) * critical;|: critical;"
  "literal mode: a folding step taken (no exact check)|$DLF/disk/planar_literal_flow.h|count_orientations_2(m_trial, m_tri.faces);|count_orientations_2(m_trial, std::vector<Face>());"
  "floating border slides on its outline instead|$DLF/disk/planar_dofs.h|if(curve.kind() == Discrete_lie_flow_border::FLOATING) {|if(false) {"
  "holes: a hole no point sees whole is never triangulated|$DLF/disk/loop_triangulation.h|  if(!T.add_loop(uv, loop)) return false;|  return false;"
)

# The fast subset: unit tests of the numerics, the area and share
# bookkeeping, the public features, and flow runs on small disks.
TESTS=(
  'Critical_step.*' 'Certification.*' 'Boundary_curve.*' 'Distortion.*' 'Errors.*' 'Run_flow.*'
  'DensityRegions.*' 'DensityExactness.*'
  'Features.*' 'Area_elements.*' 'Holes.*'
  'DataSet/Certified_disk.Circle/mushroom' 'DataSet/Certified_disk.Square/nefertiti'
  'DataSet/Free_border.Lscm/mushroom' 'DataSet/Paper_disk.Circle/mushroom'
  'Errata.*' 'Literal.*' 'DropIn.LscmStartKeptOnLionSeams' 'DropIn.HoleNotStarShapedKeepsTheStart'
)
# The test files those tests live in (the others are not built here).
SOURCES=(test_numerics.cpp test_inputs.cpp test_density.cpp test_features.cpp test_disk_flow.cpp test_area_elements.cpp test_literal.cpp test_drop_in.cpp)

selected=("$@")
if ((${#selected[@]} == 0)); then selected=($(seq 1 ${#MUTATIONS[@]})); fi

start=$(date +%s)
if [[ -n "${MUTATION_DIR:-}" ]]; then
  SCRATCH=$MUTATION_DIR; mkdir -p "$SCRATCH"
else
  SCRATCH=$(mktemp -d "${TMPDIR:-/tmp}/dlf_mutation.XXXXXX")
  trap 'rm -rf "$SCRATCH"' EXIT
fi
SRC=$SCRATCH/src BUILD=$SCRATCH/build

# The working tree as it is (committed or not), without build outputs.
rm -rf "$SRC"; mkdir -p "$SRC"
(cd "$REPO" && git ls-files -co --exclude-standard -z | grep -zv '^build' | xargs -0 tar -cf -) | tar -xf - -C "$SRC"
# Not the CLI either: without its sources the test executable does not
# depend on it (and the build of dlf_tests, not dlf_tests/fast, is the one
# that tracks header dependencies).
rm -f "$SRC"/tools/dlf/*.cpp
find "$SRC/test" -maxdepth 1 -name '*.cpp' | while read -r f; do
  keep=0; for s in "${SOURCES[@]}"; do [[ "$(basename "$f")" == "$s" ]] && keep=1; done
  ((keep)) || rm "$f"
done

# -O1: a rebuild per mutation, so compile time matters more than run time.
# Without the tool's sources, nothing that runs the tool: no Python module.
cmake -S "$SRC" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" \
  -DDLF_DATA_DIR="$DATA_DIR" -DDLF_BUILD_BENCHMARK=OFF -DDLF_WITH_PYTHON=OFF > "$SCRATCH/configure.log" 2>&1 ||
  { echo "mutation: the scratch tree does not configure:"; tail -n 20 "$SCRATCH/configure.log"; exit 1; }
filter=$(IFS=:; echo "${TESTS[*]}")
run_subset() { # run_subset LOG: the subset; prints the failed tests
  (cd "$BUILD/test" && OMP_THREAD_LIMIT=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 \
     ./dlf_tests --gtest_filter="$filter" > "$1" 2>&1) || true
  sed -n 's/^\[  FAILED  \] \([A-Za-z_][^ ,]*\).*/\1/p' "$1" | sort -u
}
build() { cmake --build "$BUILD" --target dlf_tests -j"$JOBS" > "$1" 2>&1; }

echo "mutation: scratch $SCRATCH; baseline build and run"
build "$SCRATCH/build_baseline.log" || { echo "mutation: the unmutated tree does not build (see $SCRATCH/build_baseline.log)"; exit 1; }
baseline_failed=$(run_subset "$SCRATCH/run_baseline.log")
if [[ -n "$baseline_failed" ]] || ! grep -q '^\[  PASSED  \]' "$SCRATCH/run_baseline.log"; then
  echo "mutation: the unmutated tree fails the subset: $baseline_failed"; exit 1
fi
subset=$(sed -n 's/^\[==========\] \([0-9]*\) tests from .* ran\..*/\1/p' "$SCRATCH/run_baseline.log")
echo "mutation: baseline passes ($subset tests, $(( $(date +%s) - start )) s)"

caught=0 missed=0 errors=0
for i in "${selected[@]}"; do
  IFS='|' read -r name file from to <<< "${MUTATIONS[$((i - 1))]}"
  t0=$(date +%s)
  cp "$SRC/$file" "$SCRATCH/original"
  if ! FROM=$from TO=$to perl -0777 -i -pe '$n = () = /\Q$ENV{FROM}\E/g; s/\Q$ENV{FROM}\E/$ENV{TO}/; END { exit($n == 1 ? 0 : 3) }' "$SRC/$file"; then
    printf 'mutation %d: ERROR  %s: the text does not occur exactly once in %s\n' "$i" "$name" "$file"
    cp "$SCRATCH/original" "$SRC/$file"
    errors=$((errors + 1)); continue
  fi
  log=$SCRATCH/mutation_$i
  if ! build "$log.build"; then
    printf 'mutation %d: ERROR  %s: does not compile (%s.build)\n' "$i" "$name" "$log"
    errors=$((errors + 1))
  elif ! grep -q 'Building CXX object' "$log.build"; then
    printf 'mutation %d: ERROR  %s: nothing was recompiled (%s.build)\n' "$i" "$name" "$log"
    errors=$((errors + 1))
  else
    failed=$(run_subset "$log.run")
    if [[ -n "$failed" ]]; then
      caught=$((caught + 1))
      printf 'mutation %d: caught %s (%d s) by %s\n' "$i" "$name" "$(( $(date +%s) - t0 ))" "$(echo $failed | tr ' ' ',')"
    else
      missed=$((missed + 1))
      printf 'mutation %d: MISSED %s (%d s)\n' "$i" "$name" "$(( $(date +%s) - t0 ))"
    fi
  fi
  cp "$SCRATCH/original" "$SRC/$file"
done
applied=$((caught + missed))
echo "mutation: $caught of $applied caught (kill rate $(awk -v c=$caught -v n=$applied 'BEGIN { printf "%.0f%%", n ? 100 * c / n : 0 }')), $missed missed, $errors errors; $(( $(date +%s) - start )) s"
((missed == 0 && errors == 0))
