#!/usr/bin/env bash
# Tests of the `dlf` command-line tool: outputs, report, score, error paths.
#
#   bash test/cli_tests.sh PATH/TO/dlf MESHES_DIR
#
# Exits non-zero if any check fails. Needs only bash, awk and coreutils
# (reports are read with awk: the tool pretty-prints them, one field a line).
set -u

DLF=${1:?usage: cli_tests.sh PATH/TO/dlf MESHES_DIR}
MESHES=${2:?usage: cli_tests.sh PATH/TO/dlf MESHES_DIR}
# Absolute paths: the tests run in a scratch directory.
DLF=$(readlink -f "$DLF"); MESHES=$(readlink -f "$MESHES")
WORK=$(mktemp -d "${TMPDIR:-/tmp}/dlf_cli_tests.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1

failures=0
checks=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
check() { # check DESCRIPTION COMMAND...: passes when COMMAND succeeds
  local what=$1; shift
  checks=$((checks + 1))
  if "$@"; then echo "ok: $what"; else fail "$what"; fi
}

# json_get FILE BLOCK KEY: the value of "KEY" at top level (BLOCK empty) or
# inside the top-level object "BLOCK"; quotes and trailing comma removed.
json_get() {
  awk -v block="$2" -v key="$3" '
    function value(line) { sub(/^ *"[^"]*": */, "", line); sub(/,$/, "", line); gsub(/"/, "", line); return line }
    block == "" && $0 ~ "^  \"" key "\": " { print value($0); exit }
    block != "" && $0 ~ "^  \"" block "\": \\{" { inside = 1; next }
    inside && /^  [}]/ { inside = 0 }
    inside && $0 ~ "^    \"" key "\": " { print value($0); exit }
  ' "$1"
}
equals() { [ "$1" = "$2" ] || { echo "  expected '$2', got '$1'"; return 1; }; }
# relatively_equal A B TOL
relatively_equal() {
  awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if(d < 0) d = -d; m = (a < 0 ? -a : a); exit !(a != "" && d <= t * m) }' ||
    { echo "  $1 and $2 differ by more than $3 (relative)"; return 1; }
}
no_temporaries() { ! ls -A | grep -q '\.dlf-.*\.tmp$'; }
count_lines() { grep -c "^$2" "$1"; }

NEF="$MESHES/nefertiti.off"
[ -r "$NEF" ] || { echo "FAIL: $NEF not found"; exit 1; }

# --- square border with an ear (CGAL's default corners flatten it) -------------
"$DLF" disk "$MESHES/three_peaks.off" --border square --quiet --report sq.json
check "square border on three_peaks exits 0" equals "$?" 0
check "square border on three_peaks: status ok" equals "$(json_get sq.json "" status)" ok
check "square border on three_peaks: 0 inverted faces" equals "$(json_get sq.json final inverted_faces)" 0

# --- sphere -------------------------------------------------------------------
"$DLF" sphere "$MESHES/sphere.off" -o sph.obj --report sph.json > sph.out 2> sph.err
check "sphere run exits 0" equals "$?" 0
check "sphere report: status ok" equals "$(json_get sph.json "" status)" ok
check "sphere report: 0 inverted faces" equals "$(json_get sph.json final inverted_faces)" 0
check "sphere OBJ: one v per input vertex" equals "$(count_lines sph.obj 'v ')" 162
check "sphere OBJ: points on the unit sphere" awk '/^v / { r = sqrt($2*$2 + $3*$3 + $4*$4); if(r < 1 - 1e-12 || r > 1 + 1e-12) bad = 1 } END { exit bad }' sph.obj

# --- help --------------------------------------------------------------------
check "dlf --help" bash -c "'$DLF' --help | grep -q 'dlf disk'"
check "dlf disk --help has examples" bash -c "'$DLF' disk --help | grep -q 'Examples'"
check "dlf score --help" bash -c "'$DLF' score --help | grep -q 'Usage: dlf score'"

# --- success: certified, all outputs -------------------------------------------
"$DLF" disk "$NEF" -o nef.obj --report nef.json --svg nef.svg --domain-mesh nef_domain.obj --history > nef.out 2> nef.err
rc=$?
check "certified run exits 0" equals "$rc" 0
check "certified run: nothing on stderr" test ! -s nef.err
for f in nef.obj nef.json nef.svg nef_domain.obj; do check "certified run writes $f" test -s "$f"; done
check "no temporaries left" no_temporaries
check "summary names the outputs" grep -q "wrote nef.obj" nef.out
if [ -s nef.json ]; then
  V=$(json_get nef.json "" vertices); F=$(json_get nef.json "" faces)
  check "report: status ok" equals "$(json_get nef.json "" status)" ok
  check "report: mode certified" equals "$(json_get nef.json "" mode)" certified
  check "report: 0 inverted faces (final metrics)" equals "$(json_get nef.json final inverted_faces)" 0
  check "report: 0 caller inverted faces" equals "$(json_get nef.json "" caller_inverted_faces)" 0
  check "report: initial metrics present" test -n "$(json_get nef.json initial d_area)"
  check "report: seconds.total present" test -n "$(json_get nef.json seconds total)"
  check "report: history present" grep -q '"history": \[' nef.json
  check "report: final d_area below initial" awk -v a="$(json_get nef.json final d_area)" \
    -v b="$(json_get nef.json initial d_area)" 'BEGIN { exit !(a < b && a >= 2) }'
  check "OBJ: one v per vertex" equals "$(count_lines nef.obj 'v ')" "$V"
  check "OBJ: one vt per vertex" equals "$(count_lines nef.obj 'vt ')" "$V"
  check "OBJ: one f per face" equals "$(count_lines nef.obj 'f ')" "$F"
  check "OBJ: faces a/a b/b c/c" bash -c "grep '^f ' nef.obj | head -1 | grep -Eq '^f ([0-9]+)/\\1 ([0-9]+)/\\2 ([0-9]+)/\\3\$'"
  check "OBJ: v are the input positions" equals \
    "$(grep '^v ' nef.obj | head -1 | awk '{ printf "%.9g %.9g %.9g", $2, $3, $4 }')" \
    "$(awk '!/^#/ && NF' "$NEF" | sed -n 3p | awk '{ printf "%.9g %.9g %.9g", $1, $2, $3 }')"
  check "certified domain mesh has the input faces" equals "$(grep '^f ' nef_domain.obj | md5sum)" "$(grep '^f ' nef.obj | md5sum)"
  check "SVG is complete" bash -c "head -1 nef.svg | grep -q '<?xml' && tail -1 nef.svg | grep -q '</svg>'"

  # --- score reproduces the report ----------------------------------------------
  "$DLF" score "$NEF" nef.obj --report score.json > score.out 2>&1
  check "score exits 0" equals "$?" 0
  check "score: d_area equals the report's final d_area (1e-9 relative)" \
    relatively_equal "$(json_get score.json metrics d_area)" "$(json_get nef.json final d_area)" 1e-9
  check "score: inverted faces equal" equals "$(json_get score.json metrics inverted_faces)" "$(json_get nef.json final inverted_faces)"
  # a flat OBJ (v = uv, z = 0, no vt) is read too
  awk '/^vt / { print "v", $2, $3, 0 }' nef.obj > flat.obj
  "$DLF" score "$NEF" flat.obj --report flat.json > /dev/null 2>&1
  check "score of a flat OBJ equals score of vt" equals "$(json_get flat.json metrics d_area)" "$(json_get score.json metrics d_area)"
fi

# --- other modes and borders --------------------------------------------------
"$DLF" disk "$NEF" --mode paper --report paper.json --domain-mesh paper_domain.obj -q
check "paper mode exits 0" equals "$?" 0
"$DLF" disk "$NEF" --verbose --max-iterations 2 > verbose.out 2>&1
check "--verbose prints one line per iteration" equals "$(grep -c '^  iteration ' verbose.out)" \
  "$(grep '^  iterations ' verbose.out | awk '{ print $2 }')"
check "paper mode: status ok" equals "$(json_get paper.json "" status)" ok
check "paper mode: flips counted" test -n "$(json_get paper.json "" flips)"
"$DLF" disk "$NEF" --border square -o square.obj --report square.json -q
check "square border exits 0" equals "$?" 0
check "square border: report says square" equals "$(json_get square.json "" border)" square
check "square border: 0 inverted faces" equals "$(json_get square.json final inverted_faces)" 0

# Every initial map: exit 0 with status ok and an OBJ, or exit 2 with the
# error's name in the report and no OBJ (a flow error writes only the report).
for init in tutte mvc dcp lscm arap; do
  "$DLF" disk "$NEF" --init "$init" -o "init_$init.obj" --report "init_$init.json" -q 2> "init_$init.err"
  rc=$?
  status=$(json_get "init_$init.json" "" status)
  if [ "$rc" = 0 ]; then
    check "--init $init: ok, OBJ written" bash -c "[ '$status' = ok ] && [ -s init_$init.obj ]"
  else
    check "--init $init: exit 2, error in report, no OBJ" bash -c \
      "[ $rc = 2 ] && [ '$status' != ok ] && [ -n '$status' ] && [ ! -e init_$init.obj ] && [ \$(wc -l < init_$init.err) = 1 ]"
  fi
done
check "no temporaries left" no_temporaries

# --- measure control: densities and regions of interest ----------------------
read -r NV NF _ < <(awk '!/^#/ && NF' "$NEF" | sed -n 2p)
# json_region_values FILE KEY: the values of KEY in the "regions" array, one a line.
json_region_values() { awk -v key="$2" '/^  "regions": \[/ { inside = 1; next } inside && /^  \]/ { inside = 0 }
  inside && $0 ~ "^      \"" key "\": " { sub(/^ *"[^"]*": */, ""); sub(/,$/, ""); gsub(/"/, ""); print }' "$1"; }
within_one_percent() { awk -v e="$1" 'BEGIN { exit !(e != "" && e <= 0.01 && e >= -0.01) }' || { echo "  relative error $1"; return 1; }; }
# a ball around vertex 100 of nefertiti (negative coordinates must parse)
"$DLF" disk "$NEF" --roi-ball -0.215988 -0.081660 0.215680 1 --factor 4 --band 0.3 -o roi.obj --report roi.json \
  --svg roi.svg > roi.out 2> roi.err
check "--roi-ball exits 0" equals "$?" 0
check "--roi-ball: nothing on stderr" test ! -s roi.err
check "--roi-ball: status ok" equals "$(json_get roi.json "" status)" ok
check "--roi-ball: density from regions" equals "$(json_get roi.json density source)" regions
check "--roi-ball: the density tolerance is used" equals "$(json_get roi.json options tolerance)" 0.0005
check "--roi-ball: 0 inverted faces" equals "$(json_get roi.json final inverted_faces)" 0
check "--roi-ball: one region, factor 4" equals "$(json_region_values roi.json factor)" 4.0
check "--roi-ball: share within 1%" within_one_percent "$(json_region_values roi.json relative_error)"
check "--roi-ball: region reached" equals "$(json_region_values roi.json reached)" true
check "--roi-ball: summary shows the region" grep -q "region roi-ball -0.215988 -0.08166 0.21568 1: factor 4" roi.out
check "--roi-ball: SVG outlines the region" grep -q "region of interest" roi.svg
check "--tolerance given wins over the density tolerance" bash -c \
  "'$DLF' disk '$NEF' --roi-ball 0 0 0 1 --factor 2 --tolerance 0.01 --report tol.json -q && grep -q '\"tolerance\": 0.01' tol.json"
# two regions from CGAL selection files: a face line, and a vertex line only
{ echo; seq -s ' ' 0 99; echo; } > faces.selection.txt
{ seq -s ' ' 200 298; echo; echo; } > vertices.selection.txt
VSEL_FACES=$(awk '!/^#/ && NF' "$NEF" | awk -v nv="$NV" 'NR > 2 + nv && $2 >= 200 && $3 >= 200 && $4 >= 200' | wc -l)
"$DLF" disk "$NEF" --roi faces.selection.txt --factor 0.5 --roi vertices.selection.txt --factor 2 --report sel.json -q
check "--roi selection files exit 0" equals "$?" 0
check "--roi: face line gives 100 faces, vertex line the faces of its vertices" equals \
  "$(json_region_values sel.json faces | tr '\n' ' ')" "100 $VSEL_FACES "
check "--roi: the k-th --factor belongs to the k-th region" equals "$(json_region_values sel.json factor | tr '\n' ' ')" "0.5 2.0 "
# a density file per face and per vertex
awk -v nf="$NF" 'BEGIN { print "# density per face"; for(f = 0; f < nf; ++f) print (f < nf / 2 ? 1 : 3) }' > face.rho
awk -v nv="$NV" 'BEGIN { for(v = 0; v < nv; ++v) printf "%s%s", (v % 3 ? 1 : 2), (v % 10 == 9 ? "\n" : " ") }' > vertex.rho
"$DLF" disk "$NEF" --density face.rho --report face_rho.json -q
check "--density per face exits 0" equals "$?" 0
check "--density per face: source face" equals "$(json_get face_rho.json density source)" face
check "--density per face: density-weighted d_area reaches the tolerance" awk -v d="$(json_get face_rho.json final d_area)" \
  'BEGIN { exit !(d >= 2 && d <= 2.0006) }'
"$DLF" disk "$NEF" --density vertex.rho --report vertex_rho.json -q
check "--density per vertex: source vertex" equals "$(json_get vertex_rho.json density source)" vertex
check "--density per vertex: 0 inverted faces" equals "$(json_get vertex_rho.json final inverted_faces)" 0
# error values for the density files
head -n 10 face.rho > short.rho
{ sed -n '1,5p' face.rho; echo 0; sed -n '7,$p' face.rho; } > zero.rho
{ sed -n '1,5p' face.rho; echo -2; sed -n '7,$p' face.rho; } > negative.rho
{ sed -n '1,5p' face.rho; echo nan; sed -n '7,$p' face.rho; } > nan.rho
{ sed -n '1,5p' face.rho; echo 1,5; sed -n '7,$p' face.rho; } > garbage.rho
check "no temporaries left" no_temporaries

# --- error paths: non-zero exit, one line on stderr, no output file -----------
echo "this is not a mesh" > garbage.off
head -c 2000 /dev/zero | tr '\0' 'x' > garbage.obj
cp "$NEF" input.off
expect_error() { # expect_error DESCRIPTION EXPECTED_CODE MESSAGE_PATTERN ARGS...
  local what=$1 code=$2 pattern=$3; shift 3
  rm -rf out; mkdir out
  local outputs=(-o out/o.obj --report out/r.json --svg out/l.svg --domain-mesh out/d.obj)
  [ "$1" = sphere ] && outputs=(-o out/o.obj --report out/r.json)
  "$DLF" "$@" "${outputs[@]}" > out.txt 2> err.txt
  local rc=$?
  checks=$((checks + 1))
  if [ "$rc" = 0 ]; then fail "$what: exit 0"; return; fi
  if [ -n "$code" ] && [ "$rc" != "$code" ]; then fail "$what: exit $rc, expected $code"; return; fi
  if [ "$(wc -l < err.txt)" != 1 ] || ! grep -q '^dlf: error: ' err.txt; then
    fail "$what: expected one 'dlf: error:' line on stderr, got: $(cat err.txt)"; return
  fi
  if ! grep -q -- "$pattern" err.txt; then fail "$what: message does not say '$pattern': $(cat err.txt)"; return; fi
  if [ -n "$(ls -A out)" ]; then fail "$what: left output files: $(ls -A out)"; return; fi
  echo "ok: $what ($(cat err.txt))"
}
expect_error "missing file" 1 "cannot open" disk no_such_mesh.off
expect_error "garbage OFF" 1 "cannot read" disk garbage.off
expect_error "garbage OBJ" 1 "cannot read" disk garbage.obj
expect_error "closed mesh (not a disk)" 1 "0 border loops" disk "$MESHES/sphere.off"
expect_error "torus (not a disk)" 1 "genus 1" disk "$MESHES/pipe.off"
expect_error "non-triangle faces" 1 "not triangles" disk "$MESHES/quad.off"
expect_error "unknown option" 1 "frobnicate" disk input.off --frobnicate
expect_error "bad --mode value" 1 "'fast' for --mode" disk input.off --mode fast
expect_error "bad --init value" 1 "'magic' for --init" disk input.off --init magic
expect_error "--border square with lscm" 1 "fixed-border" disk input.off --init lscm --border square
expect_error "--mu out of range" 1 "--mu" disk input.off --mu 1.5
expect_error "missing INPUT" 1 "missing INPUT" disk
expect_error "unknown command" 1 "unknown command" frobnicate input.off
expect_error "sphere: torus refused" 1 "genus" sphere "$MESHES/pipe.off"
expect_error "sphere: open mesh refused" 1 "ERROR_NOT_GENUS_0" sphere "$NEF"

expect_error "--density: wrong count" 1 "9 values; expected $NF (one per face) or $NV (one per vertex)" disk input.off --density short.rho
expect_error "--density: zero" 1 "line 6: the density of face 4 is 0" disk input.off --density zero.rho
expect_error "--density: negative" 1 "the density of face 4 is -2" disk input.off --density negative.rho
expect_error "--density: NaN" 1 "the density of face 4 is nan" disk input.off --density nan.rho
expect_error "--density: not a number" 1 "line 6: '1,5' is not a number" disk input.off --density garbage.rho
expect_error "--density: missing file" 1 "cannot open" disk input.off --density no_such.rho
expect_error "--roi without --factor" 1 "one --factor per region" disk input.off --roi faces.selection.txt
expect_error "--factor without region" 1 "one --factor per region" disk input.off --factor 2
expect_error "--factor 0" 1 "--factor must be a positive number" disk input.off --roi-ball 0 0 0 1 --factor 0
expect_error "--roi-ball with three numbers" 1 "four numbers" disk input.off --roi-ball 0 0 1
expect_error "--roi-ball: empty ball" 1 "no face has its centroid" disk input.off --roi-ball 100 100 100 1 --factor 2
expect_error "--density with --roi" 1 "exclude each other" disk input.off --density face.rho --roi faces.selection.txt --factor 2
expect_error "--band without region" 1 "--band applies" disk input.off --band 1
echo "$NF" > bad.selection.txt; echo "$NF" >> bad.selection.txt
expect_error "--roi: face out of range" 1 "face $NF does not exist" disk input.off --roi bad.selection.txt --factor 2
printf '\n\n0 1\n' > edges.selection.txt
expect_error "--roi: edges only" 1 "selects no face" disk input.off --roi edges.selection.txt --factor 2

"$DLF" disk input.off -o no_such_dir/o.obj > /dev/null 2> err.txt
check "output into a missing directory fails before the flow" bash -c "[ $? = 1 ] && grep -q 'does not exist' err.txt"
"$DLF" disk input.off -o same.obj --report ./same.obj > /dev/null 2> err.txt
check "two outputs into one file are refused" bash -c "[ $? = 1 ] && [ ! -e same.obj ]"
"$DLF" score input.off garbage.off --report score_bad.json > /dev/null 2> err.txt
check "score of a file without uv fails, no report" bash -c "[ $? = 1 ] && [ ! -e score_bad.json ]"
awk '!(/^vt / && !dropped++)' nef.obj > short.obj
"$DLF" score input.off short.obj > /dev/null 2> err.txt
check "score: too few vt is refused" bash -c "[ $? = 1 ] && grep -q 'vt' err.txt"
check "no temporaries left" no_temporaries

echo
if [ "$failures" -ne 0 ]; then
  echo "$failures of $checks checks FAILED"
  exit 1
fi
echo "all $checks checks passed"
