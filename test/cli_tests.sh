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
