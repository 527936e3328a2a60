#!/usr/bin/env bash
# CGAL's Surface_mesh_parameterization examples (Debian's libcgal-demo) with
# CGAL's parameterizer swapped for Discrete_lie_flow_parameterizer_3 by sed
# alone: extracted, swapped, built in one CMake build of CGAL's own
# CMakeLists.txt (-O1), run on their own data, and their maps checked.
#
#   cgal_examples_swap.sh EXAMPLES_TAR_GZ DATA_DIR INCLUDE_DIR SCORER WORK_DIR
#
# DATA_DIR holds CGAL's meshes in DATA_DIR/meshes; SCORER is
# dlf_cgal_map_score (test/tools/cgal_map_score.cpp). Every program but
# orbifold must build, exit 0 and write a map of its disk or seamed disk
# with 0 inverted faces and D_area <= 2.01; orbifold must stop at compile
# time with the package's one-line message. A table of the results is printed.
set -euo pipefail
archive=$1 data=$2 include=$3 scorer=$4 work=$5
fail=0
die() { echo "FAIL: $*"; fail=1; }

rm -rf "$work"
mkdir -p "$work"
tar xzf "$archive" -C "$work" examples/Surface_mesh_parameterization
src="$work/examples/Surface_mesh_parameterization"

# The one-word swap: CGAL's class name becomes ours, template and
# constructor arguments untouched (the #include follows the name).
swap() {
  sed -i "s/\b$2\b/Discrete_lie_flow_parameterizer_3/g" "$src/$1.cpp"
  grep -q Discrete_lie_flow_parameterizer_3 "$src/$1.cpp" || die "$1: nothing swapped"
}
swap discrete_authalic Discrete_authalic_parameterizer_3
swap iterative_authalic_parameterizer Iterative_authalic_parameterizer_3
swap lscm LSCM_parameterizer_3
swap square_border_parameterizer Discrete_conformal_map_parameterizer_3
swap orbifold Orbifold_Tutte_parameterizer_3
# CGAL's default parameterizer has no name in these two: the swap names ours.
for p in simple_parameterization seam_Polyhedron_3; do
  sed -i -e 's|^#include <CGAL/Surface_mesh_parameterization/parameterize.h>|&\n#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>|' \
         -e 's/SMP::parameterize(\([a-z_]*\), bhd, \([a-z_]*\));/SMP::parameterize(\1, SMP::Discrete_lie_flow_parameterizer_3<decltype(\1)>(), bhd, \2);/' \
         "$src/$p.cpp"
  grep -q "Discrete_lie_flow_parameterizer_3<decltype" "$src/$p.cpp" || die "$p: nothing swapped"
done

# One build of all programs; -k: orbifold is expected to stop.
cmake -S "$src" -B "$work/build" -DCMAKE_BUILD_TYPE= -DCMAKE_CXX_FLAGS="-O1 -DNDEBUG -I$include" > "$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; die "configure"; exit 1; }
cmake --build "$work/build" -j"${JOBS:-2}" -- -k > "$work/build.log" 2>&1 || true

if [[ -x "$work/build/orbifold" ]]; then die "orbifold: built, but cones are not supported"
elif grep -q "places no orbifold cones" "$work/build.log"; then echo "orbifold: refused at compile time: $(grep -o 'Discrete_lie_flow_parameterizer_3 places no orbifold cones[^"]*' "$work/build.log" | head -1)"
else grep -m5 error "$work/build.log"; die "orbifold: no readable compile-time message"
fi

printf '%-34s %-36s %-5s %s\n' program data exit "map written (scored)"
run() { # program output mesh-kind mesh [selection file: seams, or the square's corners]
  local p=$1 out=$2 kind=$3 mesh=$4 seams=${5:-}
  local dir="$work/run-$p-$(basename "${seams:-$mesh}" .txt)"
  mkdir -p "$dir"; ln -s "$src/data" "$dir/data"
  [[ -x "$work/build/$p" ]] || { grep -m5 -A3 "error" "$work/build.log" || true; die "$p: did not build"; return; }
  local code=0
  (cd "$dir" && CGAL_DATA_DIR="$data" timeout 600 "$work/build/$p" "$data/meshes/$mesh" ${seams:+"data/$seams"} > run.log 2>&1) || code=$?
  local score="no map"
  local seam_file=""  # the second argument is a seam file for seamed meshes, corners for the square
  [[ $kind == seam_* ]] && seam_file="$src/data/$seams"
  [[ -s "$dir/$out" ]] && score=$("$scorer" "$kind" "$data/meshes/$mesh" ${seam_file:+"$seam_file"} "$dir/$out" 2>&1) || true
  printf '%-34s %-36s %-5s %s\n' "$p" "$mesh${seams:+ $seams}" "$code" "$score"
  [[ $code == 0 ]] || { tail -5 "$dir/run.log"; die "$p $mesh $seams: exit $code"; }
  awk '$1 == "faces" && $4 == 0 && $6 == 0 { ok = 1 } END { exit !ok }' <<< "$score" ||
    die "$p $mesh $seams: want a map with 0 inverted and 0 degenerate faces"
  awk '$8 <= 2.01 { ok = 1 } END { exit !ok }' <<< "$score" || die "$p $mesh $seams: want D_area <= 2.01"
}
run discrete_authalic result.off surface_mesh three_peaks.off
run iterative_authalic_parameterizer iterative_result.off surface_mesh nefertiti.off
run simple_parameterization result.off surface_mesh nefertiti.off
run square_border_parameterizer result.off polyhedron nefertiti.off square_corners.selection.txt
for s in lion lion2 lion3 lion4; do
  run lscm result.off seam_surface_mesh lion.off "$s.selection.txt"
  run seam_Polyhedron_3 result.off seam_polyhedron lion.off "$s.selection.txt"
done
exit $fail
