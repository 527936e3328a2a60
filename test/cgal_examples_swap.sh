#!/usr/bin/env bash
# CGAL's Surface_mesh_parameterization examples (Debian's libcgal-demo) with
# CGAL's parameterizer swapped for Discrete_lie_flow_parameterizer_3 by sed
# alone: extracted, swapped, built in one CMake build of CGAL's own
# CMakeLists.txt (-O1), run on their own data, and their maps checked.
#
#   cgal_examples_swap.sh EXAMPLES_TAR_GZ DATA_DIR INCLUDE_DIR WORK_DIR
#
# DATA_DIR holds CGAL's meshes in DATA_DIR/meshes. Every program but
# orbifold must build, exit 0 and write a map whose triangles all have one
# orientation; orbifold must stop at compile time with the package's
# one-line message. A table of the results is printed.
set -euo pipefail
archive=$1 data=$2 include=$3 work=$4
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

# Inverted triangles of a uv OFF: those against the majority orientation.
inverted() {
  awk 'NR==2 { nv = $1; nf = $2; next } NR>2 && NR<=2+nv { x[NR-3] = $1; y[NR-3] = $2; next }
       NR>2+nv && $1 == 3 { a = $2; b = $3; c = $4
         s = (x[b]-x[a])*(y[c]-y[a]) - (y[b]-y[a])*(x[c]-x[a]); if(s > 0) p++; else if(s < 0) n++; else z++ }
       END { m = (p < n ? p : n); print m + z, nf }' "$1"
}

printf '%-34s %-40s %-8s %s\n' program data exit "inverted/faces"
run() { # program output data-args...
  local p=$1 out=$2; shift 2
  local dir="$work/run-$p-$(basename "${*: -1}" .txt)"
  mkdir -p "$dir"; ln -s "$src/data" "$dir/data"
  [[ -x "$work/build/$p" ]] || { grep -m5 -A3 "error" "$work/build.log" || true; die "$p: did not build"; return; }
  local code=0
  (cd "$dir" && CGAL_DATA_DIR="$data" timeout 600 "$work/build/$p" "$@" > run.log 2>&1) || code=$?
  local inv="-"
  [[ -s "$dir/$out" ]] && inv=$(inverted "$dir/$out")
  printf '%-34s %-40s %-8s %s\n' "$p" "$*" "$code" "$inv"
  [[ $code == 0 ]] || { tail -5 "$dir/run.log"; die "$p $*: exit $code"; }
  [[ "$inv" != "-" && "${inv%% *}" == 0 ]] || die "$p $*: map missing or folded ($inv)"
}
m="$data/meshes"
run discrete_authalic result.off "$m/three_peaks.off"
run iterative_authalic_parameterizer iterative_result.off "$m/nefertiti.off"
run simple_parameterization result.off "$m/nefertiti.off"
run square_border_parameterizer result.off "$m/nefertiti.off" data/square_corners.selection.txt
for s in lion lion2 lion3 lion4; do
  run lscm result.off "$m/lion.off" "data/$s.selection.txt"
  run seam_Polyhedron_3 result.off "$m/lion.off" "data/$s.selection.txt"
done
exit $fail
