#!/usr/bin/env bash
# Runs one program of examples/ on a real mesh and checks what it printed
# (and wrote) against what the example says it does.
#
#   bash test/example_checks.sh NAME PATH/TO/EXECUTABLE MESHES_DIR
#
# Exits non-zero on a failed run or a failed check.
set -u
NAME=${1:?usage: example_checks.sh NAME EXECUTABLE MESHES_DIR}
EXE=${2:?}
MESHES=${3:?}
WORK=$(mktemp -d "${TMPDIR:-/tmp}/dlf_example.XXXXXX")
trap 'rm -rf "$WORK"' EXIT

fail() { echo "FAIL: $*"; exit 1; }

case $NAME in
area_preserving_disk)
  # "MESH: N vertices, area distortion A -> B (optimum 2) in K iterations (STOP)"
  out=$("$EXE" "$MESHES/mushroom.off") || fail "exit $?"
  echo "$out"
  echo "$out" | awk '
    / area distortion / {
      for(i = 1; i <= NF; ++i) { if($i == "distortion") { a = $(i + 1); b = $(i + 3) } if($i == "in") k = $(i + 1) }
      stop = $NF
      seen = 1
    }
    END {
      if(!seen) { print "no result line"; exit 1 }
      if(!(a + 0 > 2.01)) { print "the start is already within the tolerance: nothing was tested"; exit 1 }
      if(!(b + 0 >= 2 && b + 0 <= 2.01)) { print "final D_area " b " not in [2, 2.01]"; exit 1 }
      if(!(k + 0 > 0)) { print "no iteration"; exit 1 }
      if(stop != "(converged)") { print "stopped " stop; exit 1 }
    }' || fail "output"
  ;;
sphere_map)
  out=$("$EXE" "$MESHES/blobby.off") || fail "exit $?"
  echo "$out"
  echo "$out" | grep -q '^status: ok ' || fail "status"
  echo "$out" | grep -q '^inverted or degenerate faces: 0$' || fail "inverted or degenerate faces"
  echo "$out" | awk '
    /^flow: / {
      seen = 1
      for(i = 1; i <= NF; ++i) { if($i == "stop:") stop = $(i + 1); if($i == "d_area") d = $(i + 1); if($i == "/") mean = $(i - 1) }
      sub(/,$/, "", stop); sub(/,$/, "", d)
    }
    END {
      if(!seen) { print "no flow line"; exit 1 }
      if(stop != "converged") { print "stopped " stop; exit 1 }
      if(!(d + 0 >= 2 && d + 0 <= 2.01)) { print "D_area " d " not in [2, 2.01]"; exit 1 }
      if(!(mean + 0 <= 0.02)) { print "mean |log area ratio| " mean " above 0.02"; exit 1 }
    }' || fail "output"
  ;;
measure_controlled)
  # A ball on nefertiti; each factor's row: the region's share and the
  # rest's within 0.5% of the prescribed ones, converged, no fold; one
  # well-formed SVG per factor.
  out=$("$EXE" "$WORK" "$MESHES/nefertiti.off" -0.215988 -0.081660 0.215680 1) || fail "exit $?"
  echo "$out"
  echo "$out" | awk '
    $1 ~ /^[0-9.]+$/ && NF >= 8 {
      rows++
      p = $2 + 0; q = $3 + 0
      e = (q > p ? q - p : p - q); e = (e / p > e / (1 - p) ? e / p : e / (1 - p))
      if(e > 0.005) { print "factor " $1 ": share error " e; bad = 1 }
      if($6 != "converged") { print "factor " $1 ": stopped " $6; bad = 1 }
      if($7 != "0") { print "factor " $1 ": " $7 " inverted faces"; bad = 1 }
    }
    END { if(rows != 6) { print rows " rows, expected 6"; exit 1 } exit bad }' || fail "output"
  for f in 1 0.25 0.5 2 4 16; do
    svg="$WORK/measure_controlled_$f.svg"
    [ -s "$svg" ] || fail "$svg not written"
    python3 -c 'import sys, xml.etree.ElementTree as ET; ET.parse(sys.argv[1])' "$svg" || fail "$svg is not well-formed"
  done
  ;;
atlas)
  # "MESH: F faces, genus G, C charts, seam S, packing P, D_area D, I inverted, O overlapping, converged"
  out=$("$EXE" "$MESHES/elephant.off") || fail "exit $?"
  echo "$out"
  echo "$out" | awk '
    / charts, / {
      seen = 1
      for(i = 1; i <= NF; ++i) {
        if($i == "genus") g = $(i + 1); if($i == "D_area") d = $(i + 1); if($i == "inverted,") inv = $(i - 1)
        if($i == "overlapping,") ovl = $(i - 1); if($i == "packing") p = $(i + 1)
      }
      sub(/,$/, "", g); sub(/,$/, "", d); sub(/,$/, "", p); last = $NF
    }
    END {
      if(!seen) { print "no result line"; exit 1 }
      if(g != "3") { print "genus " g ", expected 3"; exit 1 }
      if(!(d + 0 >= 2 && d + 0 <= 2.02)) { print "D_area " d " not in [2, 2.02]"; exit 1 }
      if(inv != "0" || ovl != "0") { print inv " inverted, " ovl " overlapping"; exit 1 }
      if(!(p + 0 > 0.5)) { print "packing " p; exit 1 }
      if(last != "converged") { print "ended " last; exit 1 }
    }' || fail "output"
  ;;
seams)
  # lion cut along CGAL's seam selection: a disk with holes, converged to
  # D_area <= 2.01; the map measured independently agrees and has no fold.
  out=$("$EXE" "$MESHES/lion.off" "$(dirname "$0")/data/lion.selection.txt") || fail "exit $?"
  echo "$out"
  echo "$out" | grep -q '^status: ok ' || fail "status"
  echo "$out" | awk '
    /^flow: / { seen = 1; for(i = 1; i <= NF; ++i) if($i == "stop:") stop = $(i + 1); d = $NF; sub(/,$/, "", stop) }
    /^measured: / { m = $3; sub(/,$/, "", m); folds = $NF }
    / holes$/ { holes = $(NF - 1) }
    END {
      if(!seen) { print "no flow line"; exit 1 }
      if(stop != "converged") { print "stopped " stop; exit 1 }
      if(!(d + 0 >= 2 && d + 0 <= 2.01)) { print "D_area " d " not in [2, 2.01]"; exit 1 }
      if(m == "" || (m - d > 1e-6 || d - m > 1e-6)) { print "measured D_area " m " differs from the report'"'"'s " d; exit 1 }
      if(folds != "0") { print folds " inverted or degenerate faces"; exit 1 }
      if(!(holes + 0 > 0)) { print "no hole: the seams did not cut the lion open as expected"; exit 1 }
    }' || fail "output"
  ;;
volume_map)
  # The Mesh_3 sphere kept in test/data: converged to D_vol <= 2.01, no
  # inverted or flat tet, every border face facing out, inside the ball.
  out=$("$EXE" "$(dirname "$0")/data/sphere_tets.mesh") || fail "exit $?"
  echo "$out"
  echo "$out" | grep -q '^status: ok ' || fail "status"
  echo "$out" | grep -q '^inverted or flat tets: 0, border faces not facing out: 0$' || fail "inverted tets"
  echo "$out" | awk '
    /^flow: / { seen = 1; for(i = 1; i <= NF; ++i) { if($i == "stop:") stop = $(i + 1); if($i == "->") d = $(i + 1) } sub(/,$/, "", stop); sub(/,$/, "", d) }
    /^largest \|x\| / { r = $NF }
    END {
      if(!seen) { print "no flow line"; exit 1 }
      if(stop != "converged") { print "stopped " stop; exit 1 }
      if(!(d + 0 >= 2 && d + 0 <= 2.01)) { print "D_vol " d " not in [2, 2.01]"; exit 1 }
      if(!(r + 0 > 0.9 && r + 0 <= 1 + 1e-12)) { print "largest |x| " r; exit 1 }
    }' || fail "output"
  ;;
*)
  fail "no check for example '$NAME' (add one here)"
  ;;
esac
echo "ok: $NAME"
