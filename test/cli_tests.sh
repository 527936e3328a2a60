#!/usr/bin/env bash
# Tests of the `dlf` command-line tool: outputs, report, score, error paths.
#
#   bash test/cli_tests.sh PATH/TO/dlf MESHES_DIR
#
# DLF_TETRAHEDRALIZE=0: the tool was configured with
# DLF_WITH_TETRAHEDRALIZE=OFF (CTest sets it from the build).
# Exits non-zero if any check fails. Needs bash, awk, coreutils and python3
# (reports are read with awk: the tool pretty-prints them, one field a line;
# shares, XML and PNG are checked with python3); the check of in-place
# progress needs `script`.
set -u
command -v python3 > /dev/null || { echo "FAIL: python3 not found (.ci/install-deps installs it)"; exit 1; }

DLF=${1:?usage: cli_tests.sh PATH/TO/dlf MESHES_DIR}
MESHES=${2:?usage: cli_tests.sh PATH/TO/dlf MESHES_DIR}
# Absolute paths: the tests run in a scratch directory.
DLF=$(readlink -f "$DLF"); MESHES=$(readlink -f "$MESHES")
TEST_DATA=$(readlink -f "$(dirname "${BASH_SOURCE[0]}")/data")
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
# number_is A OP B: a numeric comparison that fails when A or B is not a number.
number_is() {
  awk -v a="$1" -v op="$2" -v b="$3" 'BEGIN {
    num = "^[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$"
    if(a !~ num || b !~ num) exit 1
    a += 0; b += 0
    exit !((op == "<" && a < b) || (op == "<=" && a <= b) || (op == ">" && a > b) || (op == ">=" && a >= b) || (op == "==" && a == b))
  }' || { echo "  not: '$1' $2 '$3'"; return 1; }
}
# shares_within MESH MAP CX CY CZ R FACTOR TOLERANCE: the faces whose centroid
# lies in the ball, with density FACTOR (1 elsewhere), and the rest: each
# share of the map's area within TOLERANCE (relative) of its prescribed one,
# recomputed from the input OFF and the output OBJ (uv from vt on a disk,
# the sphere's flat triangles from v on a sphere).
shares_within() { python3 - "$@" <<'PY'
import math, sys
mesh, obj, cx, cy, cz, r, factor, tol = sys.argv[1], sys.argv[2], *map(float, sys.argv[3:9])
tokens = [l.split('#')[0].split() for l in open(mesh)]
tokens = [t for t in tokens if t]
assert tokens[0][0] == "OFF"
nv, nf = int(tokens[1][0]), int(tokens[1][1])
xyz = [tuple(map(float, t[:3])) for t in tokens[2:2 + nv]]
faces = [tuple(map(int, t[1:4])) for t in tokens[2 + nv:2 + nv + nf]]
v = [tuple(map(float, l.split()[1:4])) for l in open(obj) if l.startswith("v ")]
vt = [tuple(map(float, l.split()[1:3])) for l in open(obj) if l.startswith("vt ")]
def area3(a, b, c):
    u = [b[i] - a[i] for i in range(3)]; w = [c[i] - a[i] for i in range(3)]
    x = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    return 0.5 * math.sqrt(sum(q * q for q in x))
def area2(a, b, c): return 0.5 * abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
assert len(v) == nv and (not vt or len(vt) == nv), "OBJ does not have one v (and vt) per vertex"
t_in = t_all = m_in = m_all = 0.0
inside = 0
for f in faces:
    g = [sum(xyz[i][k] for i in f) / 3 for k in range(3)]
    is_in = (g[0] - cx) ** 2 + (g[1] - cy) ** 2 + (g[2] - cz) ** 2 <= r * r
    a = area3(*(xyz[i] for i in f))
    m = area2(*(vt[i] for i in f)) if vt else area3(*(v[i] for i in f))
    t = a * (factor if is_in else 1)
    t_all += t; m_all += m
    if is_in: t_in += t; m_in += m; inside += 1
p, q = t_in / t_all, m_in / m_all
e = max(abs(q - p) / p, abs(q - p) / (1 - p))
print("  %d faces in the ball; share %.6f prescribed, %.6f achieved: error %.5f (at most %g)" % (inside, p, q, e, tol))
sys.exit(not (inside > 0 and e <= tol))
PY
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
check "sphere: converged (d_area and mean |log r| reached)" equals "$(json_get sph.json "" stop_reason)" converged
check "sphere: mean |log area ratio| <= the default 0.02" python3 -c \
  "import json, sys; sys.exit(not json.load(open('sph.json'))['final']['log_area_ratio']['mean_abs'] <= 0.02)"
check "sphere report: the log-area tolerance" equals "$(json_get sph.json options log_area_tolerance)" 0.02
# measure control on the sphere: a region's share of the sphere's area
# Coarse to fine (the threshold lowered to reach the data set): the levels in the report and the summary.
"$DLF" sphere "$MESHES/homer.off" --coarse-to-fine-faces 8000 -o sph_c2f.obj --report sph_c2f.json > sph_c2f.out
check "sphere coarse to fine: exit 0, converged, 0 inverted" equals \
  "$? $(json_get sph_c2f.json "" stop_reason) $(json_get sph_c2f.json final inverted_faces)" "0 converged 0"
check "sphere coarse to fine: the levels grow to the mesh, the coarsest flowed, none refused" python3 -c "
import json; r = json.load(open('sph_c2f.json')); L = r['levels']
assert len(L) >= 2 and L[-1]['faces'] == r['faces'] and L[0]['iterations'] > 0, L
assert all(a['faces'] < b['faces'] for a, b in zip(L, L[1:])) and r['levels_refused'] is None, r['levels_refused']"
check "sphere coarse to fine: the summary names the levels" grep -q "coarse to fine: " sph_c2f.out
check "sphere by default: no levels" equals "$(python3 -c "import json; r = json.load(open('sph.json')); print(len(r['levels']), r['levels_refused'])")" "0 None"
"$DLF" sphere "$MESHES/sphere.off" --roi-ball 0 0 1 0.8 --factor 4 -o sph_roi.obj --report sph_roi.json -q 2> sph_roi.err
check "sphere --roi-ball: exit 0" equals "$?" 0
check "sphere --roi-ball: no warning" equals "$(wc -c < sph_roi.err)" 0
check "sphere --roi-ball: converged" equals "$(json_get sph_roi.json "" stop_reason)" converged
check "sphere --roi-ball: region and rest within 0.5% of their shares (recomputed)" \
  shares_within "$MESHES/sphere.off" sph_roi.obj 0 0 1 0.8 4 0.005
awk '!/^#/ && NF' "$MESHES/sphere.off" | sed -n 2p | awk '{ for(i = 0; i < $2; ++i) print (i % 2 ? 1 : 3) }' > sph_rho.txt
"$DLF" sphere "$MESHES/sphere.off" --density sph_rho.txt --max-iterations 3 --report sph_rho.json -q 2> sph_rho.err
# Alternating densities 1 and 3 on the faces of a coarse sphere, stopped after
# 3 iterations: exit 3, "not_converged", a valid map, and a warning that
# names the goal it missed with its value.
check "sphere --density per face, 3 iterations: exit 3, not_converged" equals "$? $(json_get sph_rho.json "" status)" "3 not_converged"
check "sphere --density per face: the warning names the missed goal and its value" \
  grep -Eq 'dlf: warning: not converged: stopped \(iteration_cap\) after 3 iterations short of (d_area|share error|mean \|log area ratio\|) [0-9.e-]+ > [0-9.e-]+' sph_rho.err
check "sphere --density per face: density in the report" equals "$(json_get sph_rho.json density max)" 3.0
"$DLF" sphere "$MESHES/sphere.off" --log-area-tolerance 0 --report sph0.json -q
check "sphere --log-area-tolerance 0: exit 0, converged" equals "$? $(json_get sph0.json "" stop_reason)" "0 converged"
check "sphere --log-area-tolerance 0: in the report" number_is "$(json_get sph0.json options log_area_tolerance)" "==" 0
# On blobby the default run goes on after D_area <= 2.01 until the mean
# |log area ratio| is <= 0.02 (13 iterations); with the goal off, D_area
# alone decides: fewer iterations (12), which an ignored option would not give.
"$DLF" sphere "$MESHES/blobby.off" --report blobby_default.json -q
"$DLF" sphere "$MESHES/blobby.off" --log-area-tolerance 0 --report blobby_0.json -q
check "sphere: --log-area-tolerance 0 lets d_area alone decide (fewer iterations on blobby, both converged)" equals \
  "$(json_get blobby_default.json "" stop_reason) $(json_get blobby_0.json "" stop_reason) $(python3 -c "
import json; print(json.load(open('blobby_0.json'))['iterations'] < json.load(open('blobby_default.json'))['iterations'])")" \
  "converged converged True"
# An unreachable mean |log r| (1e-9) is a goal the run misses and names: the
# option is read (ignored, the default 0.02 would converge as above).
"$DLF" sphere "$MESHES/sphere.off" --log-area-tolerance 1e-9 --max-iterations 20 --report sph9.json -q 2> sph9.err
check "sphere --log-area-tolerance 1e-9: exit 3, not converged" equals "$? $(json_get sph9.json "" status)" "3 not_converged"
check "sphere --log-area-tolerance 1e-9: the warning names the mean |log area ratio| it missed" \
  grep -Eq 'short of mean \|log area ratio\| [0-9.e-]+ > 1e-09' sph9.err
# the start: the conformal one, and the caller's own (an earlier result)
"$DLF" sphere "$MESHES/ellipe0.003.off" --start conformal -o sph_conf.obj --report sph_conf.json -q
check "sphere --start conformal: exit 0, converged, reported" equals \
  "$? $(json_get sph_conf.json "" stop_reason) $(json_get sph_conf.json "" start)" "0 converged conformal"
"$DLF" sphere "$MESHES/ellipe0.003.off" --start mean-value --report sph_mv.json -q
check "sphere --start mean-value: exit 0, converged, reported" equals \
  "$? $(json_get sph_mv.json "" stop_reason) $(json_get sph_mv.json "" start) $(json_get sph_mv.json "" split_vertices_removed)" "0 converged mean-value 0"
"$DLF" sphere "$MESHES/ellipe0.003.off" --init-map sph_conf.obj --report sph_given.json -q
check "sphere --init-map: exit 0, started from the given map" equals "$? $(json_get sph_given.json "" start)" "0 given"
check "sphere --init-map: an earlier result has nothing left to do" number_is "$(json_get sph_given.json "" iterations)" "<=" 1
check "sphere --init-map: its initial d_area is the earlier final one" python3 -c \
  "import sys; sys.exit(abs($(json_get sph_given.json initial d_area) - $(json_get sph_conf.json final d_area)) > 1e-9)"
awk '/^v / && ++n == 1 { first = $0; next } /^v / && n == 2 { print; print first; next } { print }' sph.obj > sph_folded.obj

# --- help --------------------------------------------------------------------
check "dlf --help" bash -c "'$DLF' --help | grep -q 'dlf disk'"
check "dlf disk --help has examples" bash -c "'$DLF' disk --help | grep -q 'Examples'"
check "dlf score --help" bash -c "'$DLF' score --help | grep -q 'Usage: dlf score'"
for cmd in disk sphere volume atlas score info tetrahedralize; do
  # Defaults as written in the docs (0.005, not 0.0050000000000000001), and a
  # name for every value (OUT.obj, not boost's bare 'arg').
  check "dlf $cmd --help: no 17-digit default, no bare 'arg'" \
    bash -c "! '$DLF' $cmd --help 2>&1 | grep -E '[0-9]\.[0-9]{9,}|\] arg\b'"
done

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
  check "report: initial d_area above the final one" number_is "$(json_get nef.json initial d_area)" ">" "$(json_get nef.json final d_area)"
  check "report: final d_area within the tolerance" number_is "$(json_get nef.json final d_area)" "<=" 2.01
  check "report: converged" equals "$(json_get nef.json "" stop_reason)" converged
  check "report: seconds.total positive" number_is "$(json_get nef.json seconds total)" ">" 0
  check "report: history present" grep -q '"history": \[' nef.json
  check "report: final d_area at least 2" number_is "$(json_get nef.json final d_area)" ">=" 2
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
  check "score: 0 inverted faces, as the report" equals "$(json_get score.json metrics inverted_faces) $(json_get nef.json final inverted_faces)" "0 0"
  check "score: the Table 1 Wasserstein distance equals the report's (1e-9 relative)" \
    relatively_equal "$(json_get score.json metrics wasserstein_table1)" "$(json_get nef.json final wasserstein_table1)" 1e-9
  # Σ w|r − 1| ≤ (Σ w (r − 1)²/r · Σ w r)^½ = (D_area − 2)^½ (Cauchy–Schwarz, Σ w r = 1).
  check "score: Area_total is reported and within (D_area - 2)^1/2" number_is "$(json_get score.json metrics area_total)" "<=" \
    "$(python3 -c "import math, sys; print(math.sqrt(float(sys.argv[1]) - 2))" "$(json_get score.json metrics d_area)")"
  check "score: Area_total is positive" number_is "$(json_get score.json metrics area_total)" ">" 0
  check "score: the Beltrami block is reported" bash -c "python3 -c \"import json,sys; b=json.load(open('score.json'))['metrics']['beltrami']; sys.exit(not (0 <= b['mean'] <= b['max'] and 0 <= b['weighted_mean'] <= b['max']))\""
  # a flat OBJ (v = uv, z = 0, no vt) is read too
  awk '/^vt / { print "v", $2, $3, 0 }' nef.obj > flat.obj
  "$DLF" score "$NEF" flat.obj --report flat.json > /dev/null 2>&1
  check "score of a flat OBJ: exit 0" equals "$?" 0
  check "score of a flat OBJ equals score of vt" bash -c "[ -n '$(json_get score.json metrics d_area)' ] && [ '$(json_get flat.json metrics d_area)' = '$(json_get score.json metrics d_area)' ]"
fi

# --- other modes and borders --------------------------------------------------
"$DLF" disk "$NEF" --mode paper --report paper.json --domain-mesh paper_domain.obj -q
check "paper mode exits 0" equals "$?" 0
# --- --init-uv: the caller's own initial map (here the previous result) -----
"$DLF" disk "$NEF" --init-uv nef.obj --report inituv.json -q
check "--init-uv: exit 0 from a converged map, border free" equals \
  "$? $(json_get inituv.json "" init) $(json_get inituv.json "" border)" "0 uv free"
check "--init-uv: the start is the given map (its d_area)" relatively_equal \
  "$(json_get inituv.json initial d_area)" "$(json_get nef.json final d_area)" 1e-9

# --- literal mode: Algorithm 1 as printed; its collapse is reported, exit 3 ---
"$DLF" disk "$NEF" --mode literal --report literal.json --domain-mesh literal_domain.obj -q 2> literal.err
check "literal mode on nefertiti: exit 3 (collapsed: not converged)" equals "$?" 3
check "literal mode: status not_converged, stop reason collapsed" equals \
  "$(json_get literal.json "" status) $(json_get literal.json "" stop_reason)" "not_converged collapsed"
check "literal mode: no folded flowing face returned" equals "$(json_get literal.json "" flowing_inverted_faces)" 0
check "literal mode: the warning says collapsed" grep -q "collapsed" literal.err
"$DLF" disk "$NEF" --mode literal --fixed-step 0.01 --max-iterations 5 --history --report literal_fixed.json -q 2> /dev/null
check "literal mode, fixed step: 5 iterations of exactly 0.01" python3 -c \
  'import json,sys; h=json.load(open("literal_fixed.json"))["history"]; sys.exit(not (len(h) == 5 and all(x["step"] == 0.01 for x in h)))'
"$DLF" sphere "$MESHES/sphere.off" --mode literal --max-iterations 3 --report literal_sph.json -q 2> /dev/null
check "literal mode on the sphere: 3 iterations, no folded flowing face" equals \
  "$(json_get literal_sph.json "" iterations) $(json_get literal_sph.json "" flowing_inverted_faces)" "3 0"
"$DLF" disk "$NEF" --verbose --max-iterations 2 > verbose.out 2>&1
check "--verbose prints one line per iteration" equals "$(grep -c '^  iteration ' verbose.out)" \
  "$(grep '^  iterations ' verbose.out | awk '{ print $2 }')"
check "paper mode: status ok" equals "$(json_get paper.json "" status)" ok
# Stopped short of the targets: not "Success", yet every output is written.
"$DLF" disk "$MESHES/lion-head.off" --max-iterations 2 -o cap.obj --report cap.json -q 2> cap.err
check "--max-iterations 2: exit 3, status not_converged, the map written" bash -c \
  "[ $? = 3 ] && [ -s cap.obj ] && grep -q '\"status\": \"not_converged\"' cap.json && grep -q '\"stop_reason\": \"iteration_cap\"' cap.json"
check "--max-iterations 2: the warning says where it stopped and what to try" bash -c \
  "grep -q 'not converged.*iteration_cap.*after 2 iterations' cap.err && grep -q -- '--max-iterations' cap.err"
check "--max-iterations 2: the warning names the goal it missed, d_area against 2 + tolerance, with the value reached" python3 -c "
import json, re, sys
m = re.search(r'short of d_area ([0-9.e+-]+) > 2\.01; ', open('cap.err').read())
sys.exit(not (m and abs(float(m.group(1)) / json.load(open('cap.json'))['final']['d_area'] - 1) < 1e-5))"
check "--max-iterations 2: the written map scores as reported" bash -c \
  "'$DLF' score '$MESHES/lion-head.off' cap.obj --report cap_score.json -q && python3 -c \"import json,sys; a=json.load(open('cap.json'))['final']['d_area']; b=json.load(open('cap_score.json'))['metrics']['d_area']; sys.exit(abs(a-b) > 1e-9*a)\""
check "paper mode: flips counted" number_is "$(json_get paper.json "" flips)" ">" 0
"$DLF" disk "$NEF" --border square -o square.obj --report square.json -q
check "square border exits 0" equals "$?" 0
check "square border: report says square" equals "$(json_get square.json "" border)" square
check "square border: 0 inverted faces" equals "$(json_get square.json final inverted_faces)" 0

# Every initial map, on a mesh where each start is far from area-preserving
# (the flow moves the free border of LSCM and ARAP): exit 0, converged after
# some iterations, an OBJ whose score is the report's.
MUSHROOM="$MESHES/mushroom.off"
for init in tutte mvc dcp lscm arap; do
  "$DLF" disk "$MUSHROOM" --init "$init" -o "init_$init.obj" --report "init_$init.json" -q 2> "init_$init.err"
  check "--init $init: exit 0, ok, converged" equals "$? $(json_get "init_$init.json" "" status) $(json_get "init_$init.json" "" stop_reason)" "0 ok converged"
  check "--init $init: the flow iterated" number_is "$(json_get "init_$init.json" "" iterations)" ">" 0
  check "--init $init: the start is above 2.02" number_is "$(json_get "init_$init.json" initial d_area)" ">" 2.02
  check "--init $init: d_area at most 2.01" number_is "$(json_get "init_$init.json" final d_area)" "<=" 2.01
  "$DLF" score "$MUSHROOM" "init_$init.obj" --report "init_${init}_score.json" -q
  check "--init $init: score of the OBJ is the report's d_area" \
    relatively_equal "$(json_get "init_${init}_score.json" metrics d_area)" "$(json_get "init_$init.json" final d_area)" 1e-9
  case $init in lscm|arap) expected=free ;; *) expected=circle ;; esac
  check "--init $init: border $expected" equals "$(json_get "init_$init.json" "" border)" "$expected"
done
check "no temporaries left" no_temporaries

# --- measure control: densities and regions of interest ----------------------
read -r NV NF _ < <(awk '!/^#/ && NF' "$NEF" | sed -n 2p)
# json_region_values FILE KEY: the values of KEY in the "regions" array, one a line.
json_region_values() { awk -v key="$2" '/^  "regions": \[/ { inside = 1; next } inside && /^  \]/ { inside = 0 }
  inside && $0 ~ "^      \"" key "\": " { sub(/^ *"[^"]*": */, ""); sub(/,$/, ""); gsub(/"/, ""); print }' "$1"; }
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
check "--roi-ball: converged" equals "$(json_get roi.json "" stop_reason)" converged
check "--roi-ball: region reached" equals "$(json_region_values roi.json reached)" true
check "--roi-ball: summary shows the region" grep -q "region roi-ball -0.215988 -0.08166 0.21568 1: factor 4" roi.out
check "--roi-ball: SVG outlines the region" grep -q "region of interest" roi.svg
check "--roi-ball: the share tolerance is in the options" equals "$(json_get roi.json options share_tolerance)" 0.005
check "--roi-ball: the reported share error within the tolerance" number_is "$(json_get roi.json density share_error)" "<=" 0.005
# Without a band the region's density is its factor: its share and the
# rest's, recomputed from the mesh and the OBJ, within 0.5%.
"$DLF" disk "$NEF" --roi-ball -0.215988 -0.081660 0.215680 1 --factor 4 -o roi_jump.obj --report roi_jump.json -q
check "--roi-ball without band: exit 0, converged" equals "$? $(json_get roi_jump.json "" stop_reason)" "0 converged"
check "--roi-ball without band: region and rest within 0.5% of their shares (recomputed)" \
  shares_within "$NEF" roi_jump.obj -0.215988 -0.081660 0.215680 1 4 0.005
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
check "--density per vertex: exit 0, converged" equals "$? $(json_get vertex_rho.json "" stop_reason)" "0 converged"
check "--density per vertex: source vertex" equals "$(json_get vertex_rho.json density source)" vertex
check "--density per vertex: 0 inverted faces" equals "$(json_get vertex_rho.json final inverted_faces)" 0
# error values for the density files
head -n 10 face.rho > short.rho
{ sed -n '1,5p' face.rho; echo 0; sed -n '7,$p' face.rho; } > zero.rho
{ sed -n '1,5p' face.rho; echo -2; sed -n '7,$p' face.rho; } > negative.rho
{ sed -n '1,5p' face.rho; echo nan; sed -n '7,$p' face.rho; } > nan.rho
{ sed -n '1,5p' face.rho; echo 1,5; sed -n '7,$p' face.rho; } > garbage.rho
check "no temporaries left" no_temporaries

# --- pictures: layout, convergence, histograms, textured OBJ, sphere view ------
# svg_polygons FILE: the number of <polygon> elements, after parsing FILE as
# XML (fails on malformed XML).
svg_polygons() { python3 -c '
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
print(sum(1 for e in root.iter() if e.tag.split("}")[-1] == "polygon"))' "$1"; }
# png_size FILE: "WIDTH HEIGHT" of an 8-bit RGB PNG, after checking its
# signature, every chunk CRC and that its pixel data inflates to the size
# those dimensions need, with valid filter bytes.
png_size() { python3 -c '
import sys, struct, zlib
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "no PNG signature"
pos, idat, ihdr, end = 8, b"", None, False
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    assert struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])[0] == zlib.crc32(kind + body), "bad CRC"
    if kind == b"IHDR": ihdr = struct.unpack(">IIBBBBB", body)
    if kind == b"IDAT": idat += body
    if kind == b"IEND": end = True
    pos += 12 + n
w, h, depth, colour = ihdr[:4]
assert end and depth == 8 and colour == 2, "not an 8-bit RGB PNG"
raw = zlib.decompress(idat)
assert len(raw) == h * (1 + 3 * w), "pixel data of the wrong size"
assert all(raw[y * (1 + 3 * w)] <= 4 for y in range(h)), "bad filter byte"
print(w, h)' "$1"; }
{
  "$DLF" disk "$NEF" -o pic.obj --svg pic.svg --plot-convergence conv.svg --plot-histogram hist.svg \
    --texture tex.obj --texture-size 96 --report pic.json -q > pic.out 2> pic.err
  check "all pictures: exit 0" equals "$?" 0
  check "all pictures: -q prints nothing" test ! -s pic.out
  for f in pic.svg conv.svg hist.svg tex.obj tex.mtl tex.png; do check "all pictures: $f written" test -s "$f"; done
  check "no temporaries left" no_temporaries
  check "layout SVG: well-formed, one polygon per face" equals "$(svg_polygons pic.svg)" "$NF"
  check "convergence SVG: well-formed, one polyline per quantity" equals \
    "$(python3 -c 'import sys, xml.etree.ElementTree as ET; print(sum(1 for e in ET.parse(sys.argv[1]).getroot().iter() if e.tag.endswith("polyline")))' conv.svg)" 2
  check "histogram SVG: well-formed" equals "$(svg_polygons hist.svg 2>&1)" 0
  check "histogram SVG: before and after" bash -c "grep -q 'before the flow' hist.svg && grep -q 'after the flow' hist.svg"
  check "texture PNG decodes to the requested size" equals "$(png_size tex.png)" "96 96"
  check "texture OBJ names its MTL, the MTL its PNG" bash -c "grep -qx 'mtllib tex.mtl' tex.obj && grep -qx 'map_Kd tex.png' tex.mtl && grep -qx 'usemtl dlf_checker' tex.obj"
  check "texture OBJ: one v and vt per vertex, one f per face" equals \
    "$(count_lines tex.obj 'v ') $(count_lines tex.obj 'vt ') $(count_lines tex.obj 'f ')" "$NV $NV $NF"
  # The texture's vt are the map's uv moved and scaled into [0,1]^2: read
  # both OBJs back and compare to the last printed digit.
  check "texture OBJ: vt = (uv - min) / extent, in [0,1]" python3 -c '
import sys
def vt(p): return [tuple(map(float, l.split()[1:3])) for l in open(p) if l.startswith("vt ")]
uv, t = vt(sys.argv[1]), vt(sys.argv[2])
x0 = min(u for u, v in uv); y0 = min(v for u, v in uv)
e = max(max(u for u, v in uv) - x0, max(v for u, v in uv) - y0)
assert len(uv) == len(t) and all(0 <= c <= 1 for p in t for c in p)
assert all(abs((u - x0) / e - a) <= 1e-15 and abs((v - y0) / e - b) <= 1e-15 for (u, v), (a, b) in zip(uv, t))' pic.obj tex.obj
  "$DLF" score "$NEF" tex.obj --report tex_score.json -q
  check "texture OBJ re-read: the report's d_area (1e-9 relative)" \
    relatively_equal "$(json_get tex_score.json metrics d_area)" "$(json_get pic.json final d_area)" 1e-9
  check "OBJ re-read: the uv printed in full (every number reads back to the same text)" python3 -c '
import sys
for l in open(sys.argv[1]):
    if l.startswith(("v ", "vt ")):
        for tok in l.split()[1:]:
            x = float(tok); assert float(repr(x)) == x and len(tok) <= 24, tok' pic.obj
  check "report: seconds spent on pictures, measured (a positive number)" number_is "$(json_get pic.json seconds pictures)" ">" 0
  check "report: no history unless --history" bash -c "! grep -q '\"history\"' pic.json"
  "$DLF" disk "$NEF" --density face.rho --svg rho.svg -q
  check "layout SVG outlines the pieces of a piecewise-constant density" grep -q "density pieces" rho.svg
  "$DLF" sphere "$MESHES/sphere.off" --svg sph.svg --plot-convergence sph_conv.svg --plot-histogram sph_hist.svg -q
  check "sphere view: exit 0" equals "$?" 0
  check "sphere view: well-formed, one polygon per face" equals "$(svg_polygons sph.svg)" \
    "$(awk '!/^#/ && NF' "$MESHES/sphere.off" | sed -n 2p | awk '{ print $2 }')"
  check "sphere convergence plot: well-formed" equals "$(svg_polygons sph_conv.svg 2>&1)" 0
  check "sphere histogram: well-formed, the result only" bash -c \
    "python3 -c 'import sys, xml.etree.ElementTree as ET; ET.parse(sys.argv[1])' sph_hist.svg && grep -q 'after the flow' sph_hist.svg && ! grep -q 'before the flow' sph_hist.svg"
}

# --- progress ------------------------------------------------------------------
"$DLF" disk "$NEF" > progress.out 2>&1
check "progress, not a terminal: one plain line per iteration" equals "$(grep -c '^  iteration ' progress.out)" \
  "$(grep '^  iterations ' progress.out | awk '{ print $2 }')"
check "progress line: step, residual, d_area, elapsed" \
  grep -Eq '^  iteration +1  step [0-9.e+-]+ +residual [0-9.e+-]+ +d_area [0-9.]+  elapsed [0-9.]+ s$' progress.out
check "progress, not a terminal: no carriage return" bash -c "! grep -q $'\r' progress.out"
"$DLF" disk "$NEF" -v > verbose_progress.out 2>&1
check "--verbose: details on every progress line" equals "$(grep -c '^  iteration .* critical .* backtracks ' verbose_progress.out)" \
  "$(grep '^  iterations ' verbose_progress.out | awk '{ print $2 }')"
if command -v script > /dev/null; then
  script -qec "'$DLF' disk '$NEF'" /dev/null > tty.out 2>&1
  check "progress on a terminal: rewritten in place" bash -c "grep -q $'\r\e\\[K  iteration ' tty.out && [ \$(grep -c '^  iteration ' tty.out) -le 1 ]"
fi


# --- dlf info ------------------------------------------------------------------
info_fits() { "$DLF" info "$1" | awk '/^  fits / { sub(/^  fits +/, ""); print; exit }'; }
check "info: a disk fits dlf disk" equals "$(info_fits "$NEF")" "dlf disk (a topological disk)"
check "info: a closed genus-0 mesh fits dlf sphere" equals "$(info_fits "$MESHES/sphere.off")" "dlf sphere (closed, genus 0)"
check "info: a torus fits neither, genus 1" bash -c "'$DLF' info '$MESHES/pipe.off' | grep -q 'genus 1 (cut it open'"
check "info: quads are named" bash -c "'$DLF' info '$MESHES/quad.off' | grep -q 'not a triangle (triangulate)'"
# two triangles sharing one vertex (a bow tie), a zero-area triangle apart
printf 'OFF\n8 3 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n5 5 5\n6 6 6\n7 7 7\n3 0 1 2\n3 0 3 4\n3 5 6 7\n' > bowtie.off
"$DLF" info bowtie.off --report bowtie.json > bowtie.out
check "info: exit 0 on a mesh no command takes" equals "$?" 0
check "info: the bow tie's vertex is non-manifold" equals "$(json_get bowtie.json "" non_manifold_vertices)" 1
check "info: the collinear triangle has zero area" equals "$(json_get bowtie.json "" zero_area_faces)" 1
check "info: 2 components, Euler characteristic 8 - 9 + 3" equals \
  "$(json_get bowtie.json "" connected_components) $(json_get bowtie.json "" euler_characteristic)" "2 2"
check "info: fits none, with the reasons" grep -q 'neither dlf disk nor dlf sphere: not manifold (repair it); 1 zero-area face' bowtie.out
check "info: report says fits none" equals "$(json_get bowtie.json "" fits)" none
"$DLF" info "$MESHES/lion-head.off" --report lion_info.json -q
check "info: lion-head's numbers" equals "$(json_get lion_info.json "" faces) $(json_get lion_info.json "" border_loops) $(json_get lion_info.json "" genus)" "16674 1 0"
check "info --help" bash -c "'$DLF' info --help | grep -q 'Usage: dlf info'"
# Polygons: area, angles and genus computed on the polygons themselves.
# jpath FILE EXPR: a value of the report (Python expression on r).
jpath() { python3 -c 'import json, sys; r = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$1" "$2"; }
"$DLF" info "$MESHES/cube_quad.off" --report cube_quad.json > cube_quad.out
check "info on quads (the cube of side 2): genus 0, area 24, smallest angle 90, 1 component" equals \
  "$(jpath cube_quad.json '[r["genus"], r["area"], r["min_angle_degrees"], r["connected_components"], r["components"][0]["genus"]]')" \
  "[0, 24.0, 90.0, 1, 0]"
check "info on quads: the text says the same" bash -c "grep -q '^  genus                 0$' cube_quad.out &&
  grep -q '^  surface area          24$' cube_quad.out && grep -q '^  smallest angle        90 degrees' cube_quad.out"
check "info on quads: dlf atlas fits, triangulating" grep -q '^  dlf atlas             fits (polygons triangulated' cube_quad.out
# One flat heptagon with a slit: its reflex corner (356 degrees) is not a
# 4-degree angle; area 16 less the slit's 0.3.
printf 'OFF\n7 1 0\n0 0 0\n4 0 0\n4 4 0\n2.1 4 0\n2 1 0\n1.9 4 0\n0 4 0\n7 0 1 2 3 4 5 6\n' > slit.off
"$DLF" info slit.off --report slit.json > slit.out
check "info on a non-convex polygon: area 15.7, smallest angle 90 (the reflex corner counted as reflex)" equals \
  "$(jpath slit.json '[round(r["area"], 9), round(r["min_angle_degrees"], 9), r["genus"]]')" "[15.7, 90.0, 0]"
# A Möbius strip of three quads: one border loop, not orientable, so no genus.
printf 'OFF\n6 3 0\n0 0 0\n1 0 1\n2 0 0\n0 1 0\n1 1 1\n2 1 0\n4 0 1 4 3\n4 1 2 5 4\n4 2 3 0 5\n' > moebius.off
"$DLF" info moebius.off --report moebius.json > moebius.out
check "info: a Moebius strip is not orientable, its genus null, n/a in the text" bash -c \
  "[ '$(jpath moebius.json '[r["components"][0]["orientable"], r["genus"], r["border_loops"]]')' = '[False, None, 1]' ] &&
   grep -q '^  genus                 n/a (not orientable)$' moebius.out"
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 3 2\n' > reversed.off
check "info: a disk with one face reversed is orientable, genus 0" equals \
  "$("$DLF" info reversed.off --report reversed.json -q; jpath reversed.json '[r["components"][0]["orientable"], r["genus"], r["inconsistently_oriented_edges"]]')" \
  "[True, 0, 1]"
# Three components: each listed, text and report, with its genus.
"$DLF" info "$MESHES/blobby_3cc.off" --report b3cc.json > b3cc.out
check "info on 3 components: each with its genus, none for the mesh" bash -c \
  "[ '$(jpath b3cc.json '[r["connected_components"], len(r["components"]), r["genus"], all(c["genus"] == 0 for c in r["components"])]')' = '[3, 3, None, True]' ] &&
   [ \$(grep -c '^    component [0-2] .*, genus 0, area ' b3cc.out) = 3 ] && grep -q '^  genus                 n/a (3 components: each below)$' b3cc.out &&
   grep -q '^  dlf atlas             fits (each of the 3 components' b3cc.out"

# --- meshes with holes (genus 0, several border loops) --------------------------
# The longest loop is the outer one by default, the others float; the library
# fills them for the flow, so the map is injective as well as fold-free.
"$DLF" info "$MESHES/head.off" --report head_info.json > head_info.out
check "info: head has 3 loops, fits dlf disk with 2 holes" bash -c \
  "[ '$(json_get head_info.json "" border_loops) $(json_get head_info.json "" fits)' = '3 dlf disk' ] && grep -q 'a disk with 2 holes' head_info.out"
check "info: loops listed longest first" bash -c \
  "grep -q '^    loop 0  *length 25.10.*, 38 vertices (the outer loop' head_info.out && grep -q '^    loop 2  *length 4.22.*, 10 vertices' head_info.out"
for mesh in pig holes; do
  "$DLF" disk "$MESHES/$mesh.off" -o "$mesh.obj" --report "$mesh.json" > "$mesh.out"
  check "$mesh (holes): exit 0, ok, converged" equals "$? $(json_get "$mesh.json" "" status) $(json_get "$mesh.json" "" stop_reason)" "0 ok converged"
  check "$mesh (holes): 6 holes float, loop 0 outer" equals "$(json_get "$mesh.json" "" holes) $(json_get "$mesh.json" outer_loop index)" "6 0"
  check "$mesh (holes): the summary says which loop is outer and what the start was" bash -c \
    "grep -q 'loop 0 is outer.*6 holes float' $mesh.out && grep -q 'start is Tutte' $mesh.out"
  "$DLF" score "$MESHES/$mesh.off" "$mesh.obj" --report "${mesh}_score.json" -q
  check "$mesh (holes): rescored d_area <= 2.01" number_is "$(json_get "${mesh}_score.json" metrics d_area)" "<=" 2.01
  check "$mesh (holes): rescored, 0 inverted faces" equals "$(json_get "${mesh}_score.json" metrics inverted_faces)" 0
  check "$mesh (holes): at most 200 iterations" number_is "$(json_get "$mesh.json" "" iterations)" "<=" 200
done
"$DLF" disk "$MESHES/head.off" --outer-loop 1 --max-iterations 20 --report head1.json -q
# 20 iterations are too few from a 10-vertex outer loop: a valid map, not converged (exit 3).
check "head --outer-loop 1: exit 3, an eye outer (10 vertices), 2 holes" equals \
  "$? $(json_get head1.json outer_loop index) $(json_get head1.json outer_loop vertices) $(json_get head1.json "" holes)" "3 1 10 2"
check "head --outer-loop 1: not_converged, and the message still says what the holes became" bash -c \
  "grep -q '\"status\": \"not_converged\"' head1.json && grep -q 'not converged.*2 holes filled for the flow' head1.json"
check "head --outer-loop 1: 0 inverted faces" equals "$(json_get head1.json final inverted_faces)" 0

# --- error paths: non-zero exit, one line on stderr, no output file -----------
echo "this is not a mesh" > garbage.off
head -c 2000 /dev/zero | tr '\0' 'x' > garbage.obj
cp "$NEF" input.off
expect_error() { # expect_error DESCRIPTION EXPECTED_CODE MESSAGE_PATTERN ARGS...
  local what=$1 code=$2 pattern=$3; shift 3
  rm -rf out; mkdir out
  local outputs=(-o out/o.obj --report out/r.json --svg out/l.svg --domain-mesh out/d.obj
                 --plot-convergence out/c.svg --plot-histogram out/h.svg --texture out/t.obj)
  [ "$1" = sphere ] && outputs=(-o out/o.obj --report out/r.json --svg out/s.svg --plot-convergence out/c.svg
                                --plot-histogram out/h.svg)
  [ "$1" = info ] && outputs=(--report out/r.json)
  # OUTPUTS="...": these outputs instead (for errors about the outputs themselves)
  [ -n "${OUTPUTS+set}" ] && read -r -a outputs <<< "$OUTPUTS"
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
# A PLY header with a property before any element (CGAL's reader would index an empty list).
printf 'ply\nformat ascii 1.0\nproperty float x\nelement vertex 3\nend_header\n0\n1\n2\n' > property_first.ply
expect_error "PLY property before any element" 1 "property_first.ply', line 3: a PLY 'property' before any 'element'" \
  disk property_first.ply
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty uint16 z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' > integer_coordinate.ply
expect_error "PLY integer coordinate" 1 "integer_coordinate.ply', line 6: vertex coordinate 'z' declared as 'uint16'" \
  disk integer_coordinate.ply
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nelement halfedge 1\nproperty float source\nproperty uint target\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n0 1\n' > float_halfedge.ply
expect_error "PLY float halfedge source" 1 "float_halfedge.ply', line 10: halfedge 'source' declared as 'float'" \
  disk float_halfedge.ply
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list char int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n' > negative_list.ply
expect_error "PLY negative list count" 1 "negative_list.ply': cannot read as a mesh (the reader failed: " disk negative_list.ply
# A property of no PLY type, and counts the file cannot hold (CGAL's reader
# would read the items from nothing, one default point per announced vertex).
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty doubl x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n' > unknown_type.ply
expect_error "PLY unknown property type" 1 "unknown_type.ply', line 4: a property of type 'doubl' (not a PLY type" disk unknown_type.ply
printf 'ply\nformat ascii 1.0\nelement vertex 21474836476\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' > huge_count.ply
expect_error "PLY count beyond the file" 1 "huge_count.ply', line 3: element 'vertex' announces 21474836476 items, more than the 26 bytes after the header can hold" disk huge_count.ply
printf 'ply\nformat ascii 1.0\nelement vertex -3\nproperty float x\nend_header\n0\n' > negative_count.ply
expect_error "PLY negative element count" 1 "negative_count.ply', line 3: element 'vertex' has the count '-3'" disk negative_count.ply
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n0 0 0\n1 0 0\n0 1 0\n' > no_end_header.ply
expect_error "PLY header without end_header" 1 "no_end_header.ply': the PLY header has no 'end_header' line" disk no_end_header.ply
# dlf info and dlf atlas read through the same checks.
expect_error "info: PLY count beyond the file" 1 "huge_count.ply', line 3: element 'vertex' announces 21474836476 items" info huge_count.ply
OUTPUTS="-o out/o.obj" expect_error "atlas: PLY unknown property type" 1 "unknown_type.ply', line 4: a property of type 'doubl'" atlas unknown_type.ply
printf 'OFF\n2000000000 2000000000 0\n0 0 0\n' > huge_counts.off
expect_error "info: OFF counts beyond the file" 1 "more than the file's" info huge_counts.off
expect_error "closed mesh (not a disk): the reason first, dlf sphere named" 1 \
  "not a disk: a closed surface (no border loop) of genus 0 (Euler characteristic 2); dlf disk needs a border: 'dlf sphere' maps it" \
  disk "$MESHES/sphere.off"
expect_error "torus (not a disk): the reason first, dlf atlas named" 1 \
  "not a disk: a closed surface (no border loop) of genus 1 (Euler characteristic 0); dlf disk needs a border: cut it open, or 'dlf atlas'" \
  disk "$MESHES/pipe.off"
expect_error "three components (not a disk): the reason first, dlf atlas named" 1 \
  "not a disk: 3 connected components (dlf disk maps one), [0-9]* border loops in all, .*; 'dlf atlas' maps every component" \
  disk "$MESHES/blobby_3cc.off"
expect_error "non-triangle faces" 1 "faces are not triangles (first: face .*); triangulate the mesh first, or 'dlf atlas'" \
  disk "$MESHES/quad.off"
expect_error "genus 3 with holes" 1 "not a disk: genus 3 with 106 border loops (Euler characteristic -110); dlf disk takes genus 0" \
  disk "$MESHES/elephant-with-holes.off"
# Two triangles joined at one vertex (a bow tie): one face each side, but two fans at the vertex.
printf 'OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n' > bowtie_disk.off
expect_error "two fans at a vertex (not manifold)" 1 "the mesh is not manifold .*; 'dlf atlas' splits" disk bowtie_disk.off
# The reader's refusals, each with its own message: a face that repeats a
# vertex (whichever two corners), an index one past the last vertex, counts
# the file cannot hold, a vertex of no face.
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 1\n' > repeat_last.off
expect_error "reader: a face whose third corner repeats its first" 1 "face 1 uses vertex 1 twice" disk repeat_last.off
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 2 1 3\n' > repeat_none.off
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 2 1 4\n' > index_past_end.off
expect_error "reader: a face index equal to the vertex count" 1 "cannot read as a mesh" disk index_past_end.off
printf 'OFF\n2000000 1000000 0\n0 0 0\n' > huge_header.off
expect_error "reader: counts the file cannot hold, refused before reading" 1 \
  "the header announces 2000000 vertices and 1000000 faces, more than the file's [0-9]* bytes can hold" disk huge_header.off
printf 'OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n5 5 5\n3 0 1 2\n3 2 1 3\n' > unused_vertex.off
expect_error "reader: a vertex of no face" 1 "1 vertex is not used by any face (first: vertex 4); remove them first" disk unused_vertex.off
"$DLF" disk repeat_none.off -o repeat_none.obj -q
check "reader: the same mesh without the repeat is read and mapped" equals "$?" 0
# A hexagon fan, once plain, once with signs, exponents, comments, colours
# and one face reversed (oriented on reading): the same map.
printf 'OFF\n7 6 0\n0 0 0\n1 0 0\n0.5 0.866 0\n-0.5 0.866 0\n-1 0 0\n-0.5 -0.866 0\n0.5 -0.866 0\n3 0 1 2\n3 0 2 3\n3 0 3 4\n3 0 4 5\n3 0 5 6\n3 0 6 1\n' > hexagon.off
printf 'OFF # a comment\n7 6 0\n+0 -0 0.0e0\n1 0 0 # x\n+0.5 0.866 0\n-0.5 8.66e-1 0\n-1 0 +0\n-0.5 -0.866 0\n0.5 -0.866 0 1 1 1\n3 0 1 2\n3 0 2 3 255 0 0\n3 0 4 3\n3 0 4 5\n3 0 5 6\n3 0 6 1\n' > hexagon_noisy.off
"$DLF" disk hexagon.off -o hexagon.obj -q
"$DLF" disk hexagon_noisy.off -o hexagon_noisy.obj -q
check "OFF numbers with signs, exponents, comments and colours, a reversed face: the plain file's map" \
  equals "$(grep -c '^vt ' hexagon_noisy.obj) $(grep '^vt ' hexagon.obj | md5sum)" "7 $(grep '^vt ' hexagon_noisy.obj | md5sum)"
expect_error "--outer-loop out of range" 1 "has 3 border loops (0 to 2" disk "$MESHES/head.off" --outer-loop 3
expect_error "--outer-loop negative" 1 "--outer-loop must be >= 0" disk "$MESHES/head.off" --outer-loop -1
expect_error "--init-uv with --init" 1 "--init-uv and --init exclude each other" disk "$NEF" --init-uv nef.obj --init mvc
expect_error "--init-uv with another border" 1 "--border free only" disk "$NEF" --init-uv nef.obj --border circle
expect_error "--init-uv: wrong vertex count" 1 "expected one uv per vertex" disk "$MESHES/mushroom.off" --init-uv nef.obj
expect_error "--threshold outside literal mode" 1 "--threshold applies to --mode literal only" disk "$NEF" --threshold 0.1
expect_error "--threshold not positive" 1 "--threshold must be a number > 0" disk "$NEF" --mode literal --threshold 0
expect_error "--fixed-step not positive" 1 "--fixed-step must be a number > 0" disk "$NEF" --fixed-step -1
expect_error "sphere --mode unknown" 1 "expected certified, paper or literal" sphere "$MESHES/sphere.off" --mode literall
expect_error "sphere --start unknown" 1 "expected tutte, conformal or mean-value" sphere "$MESHES/sphere.off" --start harmonic
expect_error "sphere --init-map with --start" 1 "--init-map and --start exclude each other" sphere "$MESHES/sphere.off" \
  --init-map sph.obj --start conformal
expect_error "sphere --init-map of another mesh" 1 "expected the input's faces" sphere "$MESHES/sphere.off" --init-map sph_conf.obj
expect_error "sphere --init-map folded" "" "ERROR_INITIAL_MAP_FOLDED: the given initial map has .* inverted" sphere \
  "$MESHES/sphere.off" --init-map sph_folded.obj
expect_error "paper mode refuses holes" 1 "--mode paper takes disks only: .* has 6 holes" disk "$MESHES/pig.off" --mode paper
expect_error "unknown option" 1 "frobnicate" disk input.off --frobnicate
expect_error "bad --mode value" 1 "'fast' for --mode" disk input.off --mode fast
expect_error "bad --init value" 1 "'magic' for --init" disk input.off --init magic
expect_error "--border square with lscm" 1 "fixed-border" disk input.off --init lscm --border square
expect_error "--mu out of range" 1 "--mu" disk input.off --mu 1.5
expect_error "missing INPUT" 1 "missing INPUT" disk
expect_error "unknown command" 1 "unknown command" frobnicate input.off
expect_error "sphere: torus refused, the genus first" 1 \
  "ERROR_NOT_GENUS_0: not a closed genus-0 surface: a closed surface of genus 1 (Euler characteristic 0); .*'dlf atlas' maps any mesh" \
  sphere "$MESHES/pipe.off"
# Three components with borders: they are the reason, not the Euler
# characteristic (which is a sphere's, 2, for these three disks with holes).
expect_error "sphere: 3 components refused, the components and borders first" 1 \
  "ERROR_NOT_GENUS_0: not a closed genus-0 surface: 3 components and [1-9][0-9]* border edges; a spherical map needs one closed, manifold component (this mesh: Euler characteristic 2); 'dlf atlas' maps any mesh" \
  sphere "$MESHES/blobby_3cc.off"
expect_error "sphere: polygons refused, dlf atlas named" 1 "not triangles .*; triangulate the mesh first, or 'dlf atlas' triangulates it" \
  sphere "$MESHES/cube_quad.off"
expect_error "sphere: negative --log-area-tolerance" 1 "log-area-tolerance" sphere "$MESHES/sphere.off" --log-area-tolerance -1
expect_error "sphere: --roi-ball without --factor" 1 "factor" sphere "$MESHES/sphere.off" --roi-ball 0 0 1 0.8
expect_error "sphere: --density and --roi exclude each other" 1 "exclude" sphere "$MESHES/sphere.off" --density sph_rho.txt --roi-ball 0 0 1 0.8 --factor 2
expect_error "sphere: --band without a region" 1 "band" sphere "$MESHES/sphere.off" --band 0.1
expect_error "sphere: negative --share-tolerance" 1 "share-tolerance" sphere "$MESHES/sphere.off" --share-tolerance -1
expect_error "sphere: open mesh refused, the border first" 1 "ERROR_NOT_GENUS_0: not a closed genus-0 surface: [1-9][0-9]* border edges;" sphere "$NEF"

OUTPUTS="-o out/o.obj --svg out/l.svg" expect_error "--texture not an .obj" 1 "ending in .obj" disk input.off --texture out/t.png
expect_error "--texture-size too small" 1 "--texture-size must be in" disk input.off --texture-size 8
OUTPUTS="-o out/o.obj --svg out/l.svg" expect_error "--texture-size without --texture" 1 "applies to --texture only" \
  disk input.off --texture-size 64
OUTPUTS="-o out/o.obj" expect_error "--texture PNG and --plot-histogram into one file" 1 "name the same file" \
  disk input.off --texture out/x.obj --plot-histogram out/x.png
expect_error "info: missing file" 1 "cannot open" info no_such_mesh.off
expect_error "info: garbage" 1 "cannot read" info garbage.off
expect_error "info: two meshes" 1 "exactly one MESH" info input.off input.off
expect_error "sphere: --svg on a torus" 1 "genus" sphere "$MESHES/pipe.off"
# a disk with a zero-area triangle: the parameterizer refuses it
printf 'OFF\n4 3 0\n0 0 0\n1 0 0\n2 0 0\n1 1 0\n3 0 1 3\n3 1 2 3\n3 0 2 1\n' > degenerate.off
OUTPUTS="-o out/o.obj --svg out/l.svg --domain-mesh out/d.obj --plot-convergence out/c.svg --plot-histogram out/h.svg --texture out/t.obj" \
  expect_error "parameterizer error: no picture" 1 "ERROR_DEGENERATE_INPUT" disk degenerate.off
"$DLF" disk degenerate.off --svg degenerate.svg --texture degenerate_tex.obj --report degenerate.json > /dev/null 2>&1
check "parameterizer error: only the report is written" bash -c "[ -s degenerate.json ] && [ ! -e degenerate.svg ] && ! ls degenerate_tex.* > /dev/null 2>&1"
check "info names the zero-area face" bash -c "'$DLF' info degenerate.off | grep -q '1 zero-area face (the flow refuses them)'"

expect_error "--density: wrong count" 1 "9 values; expected $NF (one per face) or $NV (one per vertex)" disk input.off --density short.rho
expect_error "--density: zero" 1 "line 6: the density of face 4 is 0" disk input.off --density zero.rho
expect_error "--density: negative" 1 "the density of face 4 is -2" disk input.off --density negative.rho
expect_error "--share-tolerance: negative" 1 "share-tolerance must be a number >= 0" disk input.off --share-tolerance -0.1
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

# --- sphere, paper mode --------------------------------------------------------
unit_points() { awk '/^v / { r = sqrt($2*$2 + $3*$3 + $4*$4); if(r < 1 - 1e-12 || r > 1 + 1e-12) bad = 1 } END { exit bad }' "$1"; }
"$DLF" sphere "$MESHES/ellipsoid.off" --mode paper -o sphp.obj --report sphp.json --domain-mesh sphp_flow.obj --history -q 2> sphp.err
# The paper's flow stops on a plateau here, D_area within the goal but the
# mean |log area ratio| above 0.02 (0.033): exit 3, "not_converged", a
# warning that names that goal, every output written all the same.
check "sphere --mode paper on ellipsoid: exit 3, not_converged on a plateau" equals \
  "$? $(json_get sphp.json "" status) $(json_get sphp.json "" stop_reason)" "3 not_converged plateau"
check "sphere --mode paper on ellipsoid: the warning names the mean |log area ratio| it missed, and only that" \
  grep -Eq '^dlf: warning: not converged: stopped \(plateau\) after [0-9]+ iterations short of mean \|log area ratio\| 0\.0[0-9]+ > 0\.02; the map' sphp.err
check "sphere --mode paper: mode in the report" equals "$(json_get sphp.json "" mode)" "paper"
check "sphere --mode paper: a stop reason" grep -Eq '"stop_reason": "(converged|plateau|stalled|iteration_cap)"' sphp.json
check "sphere --mode paper: flips counted" awk -v f="$(json_get sphp.json "" flips)" 'BEGIN { exit !(f > 0) }'
check "sphere --mode paper: flowing triangulation never folded, Delaunay" equals \
  "$(json_get sphp.json "" flowing_inverted_faces) $(json_get sphp.json "" flowing_non_delaunay_edges)" "0 0"
# The message claims fold-free input triangles exactly when the report counts none.
check "sphere --mode paper: caller folds reported, and the message says the same" python3 -c "
import json, sys
r = json.load(open('sphp.json')); n = r['caller_inverted_faces']; m = r['message']
claims = 'fold-free on the input' in m
ok = (n == 0 and (m == 'Success' or claims)) or (n > 0 and not claims and (str(n) + ' of the input') in m)
sys.exit(not ok)"
check "sphere --mode paper: d_area on the flowing triangulation decreased" awk \
  -v a="$(json_get sphp.json "" initial_domain_d_area)" -v b="$(json_get sphp.json "" domain_d_area)" 'BEGIN { exit !(b < a && b >= 2) }'
check "sphere --mode paper: the history's flips add up to the report's" python3 -c "
import json, sys; r = json.load(open('sphp.json'))
sys.exit(not (len(r['history']) == r['iterations'] and sum(h['flips'] for h in r['history']) == r['flips'] > 0))"
check "sphere --mode paper: OBJ has the input faces" equals "$(count_lines sphp.obj 'f ')" \
  "$(awk '!/^#/ && NF' "$MESHES/ellipsoid.off" | sed -n 2p | awk '{ print $2 }')"
check "sphere --mode paper: --domain-mesh has as many faces" equals "$(count_lines sphp_flow.obj 'f ')" "$(count_lines sphp.obj 'f ')"
check "sphere --mode paper: --domain-mesh points on the unit sphere" unit_points sphp_flow.obj
check "sphere --mode paper: the flowing triangulation is not the input's" bash -c "! cmp -s <(grep '^f ' sphp.obj) <(grep '^f ' sphp_flow.obj)"
"$DLF" sphere "$MESHES/ellipsoid.off" --mode paper --no-flips --report sphp_nf.json -q
check "sphere --mode paper --no-flips: no flips, no caller folds" equals \
  "$(json_get sphp_nf.json "" flips) $(json_get sphp_nf.json "" caller_inverted_faces) $(json_get sphp_nf.json options delaunay_flips)" "0 0 false"
"$DLF" sphere "$MESHES/sphere.off" -o sphc.obj --report sphc.json --domain-mesh sphc_flow.obj -q
check "sphere certified: exit 0, status ok" equals "$? $(json_get sphc.json "" status)" "0 ok"
check "sphere certified: mode in the report, no flips" equals "$(json_get sphc.json "" mode) $(json_get sphc.json "" flips)" "certified 0"
check "sphere certified: --domain-mesh has the input faces" bash -c \
  "[ \$(grep -c '^f ' sphc.obj) = 320 ] && cmp -s <(grep '^f ' sphc.obj) <(grep '^f ' sphc_flow.obj)"
expect_error "sphere --mode: unknown value" 1 "invalid value 'fast' for --mode" sphere "$MESHES/sphere.off" --mode fast
expect_error "sphere --no-flips needs paper mode" 1 "--no-flips applies to --mode paper only" sphere "$MESHES/sphere.off" --no-flips
expect_error "sphere --literal-targets needs paper mode" 1 "--literal-targets applies to --mode paper only" sphere "$MESHES/sphere.off" --literal-targets
expect_error "sphere --mode paper: a torus is refused" 1 "ERROR_NOT_GENUS_0" sphere "$MESHES/pipe.off" --mode paper
check "no temporaries left (sphere paper)" no_temporaries

# --- seams: CGAL's selection files (test/data), cut through Seam_mesh ----------
SEAMDATA=$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/data
# seam_obj_check OBJ INPUT_EDGES_PLUS_SEAMS_MINUS_FACES: every face is f v/vt,
# the vt faces form a disk (V - E + F = 1) with one vt per Seam_mesh vertex
# (a disk cut from the input has 1 + E + seams - F of them), and the seam
# shows: some corner's vt is not its v.
seam_obj_check() { python3 - "$@" <<'PY'
import sys
obj, expected = sys.argv[1], int(sys.argv[2])
nvt = sum(1 for l in open(obj) if l.startswith("vt "))
faces = [l.split()[1:] for l in open(obj) if l.startswith("f ")]
assert all(len(f) == 3 and all(c.count("/") == 1 for c in f) for f in faces), "a face is not f v/vt v/vt v/vt"
v = [[int(c.split("/")[0]) for c in f] for f in faces]
t = [[int(c.split("/")[1]) for c in f] for f in faces]
edges = {tuple(sorted((f[k], f[(k + 1) % 3]))) for f in t for k in range(3)}
used = {i for f in t for i in f}
chi = len(used) - len(edges) + len(faces)
differ = sum(1 for a, b in zip(v, t) for x, y in zip(a, b) if x != y)
print("  %d vt (%d used, %d expected), vt faces: Euler characteristic %d, %d corners with vt != v" % (nvt, len(used), expected, chi, differ))
sys.exit(not (nvt == len(used) == expected and chi == 1 and differ > 0))
PY
}
# input_e_minus_f MESH.off: edges minus faces of an OFF triangle mesh.
input_e_minus_f() { python3 -c '
import sys
t = [l.split("#")[0].split() for l in open(sys.argv[1])]; t = [x for x in t if x]
nv, nf = int(t[1][0]), int(t[1][1])
f = [list(map(int, x[1:4])) for x in t[2 + nv:2 + nv + nf]]
print(len({tuple(sorted((a[k], a[(k + 1) % 3]))) for a in f for k in range(3)}) - nf)' "$1"; }
seam_case() { # seam_case NAME MESH SELECTION: a seamed run, its OBJ scored back
  local name=$1 mesh=$MESHES/$2 sel=$SEAMDATA/$3
  "$DLF" disk "$mesh" --seam "$sel" -o "seam_$name.obj" --report "seam_$name.json" --svg "seam_$name.svg" \
    --texture "seam_${name}_tex.obj" --domain-mesh "seam_${name}_dom.obj" -q
  check "--seam $name: exit 0" equals "$?" 0
  check "--seam $name: status ok, converged" equals \
    "$(json_get "seam_$name.json" "" status) $(json_get "seam_$name.json" "" stop_reason)" "ok converged"
  "$DLF" score "seam_$name.obj" --report "seam_${name}_score.json" -q
  check "--seam $name: dlf score of the OBJ alone exits 0, per-corner uv" equals \
    "$? $(json_get "seam_${name}_score.json" "" uv)" "0 per_corner"
  check "--seam $name: d_area <= 2.01 recomputed from the OBJ" number_is "$(json_get "seam_${name}_score.json" metrics d_area)" "<=" 2.01
  check "--seam $name: the OBJ's d_area is the report's (1e-9 relative)" \
    relatively_equal "$(json_get "seam_${name}_score.json" metrics d_area)" "$(json_get "seam_$name.json" final d_area)" 1e-9
  check "--seam $name: 0 inverted faces in the OBJ" equals "$(json_get "seam_${name}_score.json" metrics inverted_faces)" 0
  "$DLF" score "$mesh" "seam_$name.obj" --report "seam_${name}_score2.json" -q
  check "--seam $name: dlf score MESH OBJ agrees" equals "$(json_get "seam_${name}_score2.json" metrics d_area)" \
    "$(json_get "seam_${name}_score.json" metrics d_area)"
  check "--seam $name: one v per input vertex" equals "$(count_lines "seam_$name.obj" 'v ')" "$(json_get "seam_$name.json" "" vertices)"
  local seams; seams=$(json_get "seam_$name.json" seam edges)
  check "--seam $name: one vt per Seam_mesh vertex, f v/vt, a disk" \
    seam_obj_check "seam_$name.obj" "$((1 + $(input_e_minus_f "$mesh") + seams))"
  check "--seam $name: the report's cut has as many vertices" equals "$(json_get "seam_$name.json" seam cut_vertices)" \
    "$(count_lines "seam_$name.obj" 'vt ')"
  check "--seam $name: textured OBJ and domain mesh have the same faces" bash -c \
    "cmp -s <(grep '^f ' seam_$name.obj) <(grep '^f ' seam_${name}_tex.obj) && cmp -s <(grep '^f ' seam_$name.obj) <(grep '^f ' seam_${name}_dom.obj)"
  check "--seam $name: the layout draws every face" equals "$(grep -c '<polygon' "seam_$name.svg")" \
    "$(count_lines "seam_$name.obj" 'f ')"
}
seam_case blob blob.off blob.selection.txt
# bear.selection.txt has no edges: its line 1 (3 cones) is joined by shortest paths
seam_case bear bear.off bear.selection.txt
check "--seam bear: the cones were joined" equals "$(json_get seam_bear.json seam joined_vertices)" 3
# --- coarse to fine (the threshold lowered to reach the data set), on a seam --
"$DLF" disk "$MESHES/bear.off" --seam "$SEAMDATA/bear.selection.txt" --coarse-to-fine-faces 1000 -o c2f.obj \
  --report c2f.json > c2f.out
check "coarse to fine on bear's seam: exit 0, converged" equals "$? $(json_get c2f.json "" stop_reason)" "0 converged"
check "coarse to fine: the report's levels grow to the mesh, the coarsest flowed, none refused" python3 -c "
import json; r = json.load(open('c2f.json')); L = r['levels']
assert len(L) >= 2 and L[-1]['faces'] == r['faces'] and L[0]['iterations'] > 0, L
assert all(a['faces'] < b['faces'] for a, b in zip(L, L[1:])) and r['levels_refused'] is None, r['levels_refused']"
check "coarse to fine: the summary names the levels" grep -q "coarse to fine: " c2f.out
"$DLF" score c2f.obj --report c2f_score.json -q
check "coarse to fine: 0 inverted faces and d_area <= 2.01 in the OBJ" equals \
  "$(json_get c2f_score.json metrics inverted_faces) $(python3 -c "import json; print(json.load(open('c2f_score.json'))['metrics']['d_area'] <= 2.01)")" "0 True"
"$DLF" disk "$MESHES/bear.off" --seam "$SEAMDATA/bear.selection.txt" --coarse-to-fine-faces 0 --report plain.json -q
check "--coarse-to-fine-faces 0: the flow on the mesh alone, no levels" equals \
  "$(python3 -c "import json; r = json.load(open('plain.json')); print(len(r['levels']), r['levels_refused'])")" "0 None"
"$DLF" disk "$MESHES/blob.off" --seam "$SEAMDATA/blob.selection.txt" --init lscm --mode paper --report seam_lscm.json -q 2> seam_lscm.err
# The paper mode from LSCM's free border on the circle plateaus just above
# the goal (D_area 2.0102 > 2.01), 2 of the caller's triangles folded (the
# paper mode certifies its flowing triangulation only): exit 3, said so.
check "--seam with --init lscm --mode paper: exit 3, not_converged on a plateau" equals \
  "$? $(json_get seam_lscm.json "" status) $(json_get seam_lscm.json "" stop_reason)" "3 not_converged plateau"
check "--seam with --init lscm --mode paper: the warning names d_area against 2.01 and the caller's folds" \
  grep -Eq 'short of d_area 2\.01[0-9]* > 2\.01; the map is [0-9]+ of the input.s triangles inverted' seam_lscm.err
"$DLF" disk "$MESHES/blob.off" --seam "$SEAMDATA/blob.selection.txt" --border square --report seam_sq.json -q
check "--seam with --border square: exit 0, status ok" equals "$? $(json_get seam_sq.json "" status)" "0 ok"
# CGAL's lion seams leave 4 or 5 border loops (genus 0): the longest goes to
# the circle, the others are holes that float. Per selection: its holes.
for row in lion:4 lion2:4 lion3:3 lion4:3; do
  sel=${row%%:*} holes=${row##*:}
  "$DLF" disk "$MESHES/lion.off" --seam "$SEAMDATA/$sel.selection.txt" -o "seam_$sel.obj" --report "seam_$sel.json" -q
  check "--seam $sel.selection.txt on lion.off: exit 0, ok, converged, $holes holes" equals \
    "$? $(json_get "seam_$sel.json" "" status) $(json_get "seam_$sel.json" "" stop_reason) $(json_get "seam_$sel.json" "" holes)" \
    "0 ok converged $holes"
  "$DLF" score "seam_$sel.obj" --report "seam_${sel}_score.json" -q
  check "--seam $sel.selection.txt on lion.off: d_area <= 2.01 and 0 inverted faces, recomputed from the OBJ" bash -c \
    "awk -v d='$(json_get "seam_${sel}_score.json" metrics d_area)' 'BEGIN { exit !(d != \"\" && d <= 2.01) }' && [ '$(json_get "seam_${sel}_score.json" metrics inverted_faces)' = 0 ]"
done
cp "$MESHES/blob.off" blob.off
printf '\n\n95 114 114 101 101 95\n' > ring.selection.txt
expect_error "--seam: a seam loop cuts off a piece" 1 "not a disk: 2 connected components" disk blob.off --seam ring.selection.txt
# A square has 4 corners; an ear away from one would be flattened: the error says so.
OUTPUTS="-o out/o.obj" expect_error "--border square with more than 4 ears on the border: named" 2 \
  "ERROR_BORDER_TOO_SHORT: .*the outer loop has [0-9]* ears, triangles with two border edges, at vertices [0-9]" \
  disk "$MESHES/mech-holes-shark.off" --border square
printf '\n\n0 99999\n' > s1.selection.txt
expect_error "--seam: vertex out of range" 1 "line 3, pair 1 (0 99999): vertex 99999 does not exist (the mesh has 138 vertices)" disk blob.off --seam s1.selection.txt
printf '\n\n95 114 0 1\n' > s2.selection.txt
expect_error "--seam: not an edge" 1 "line 3, pair 2 (0 1): no edge of the mesh joins these vertices" disk blob.off --seam s2.selection.txt
printf '\n\n95 114 0 x1\n' > s3.selection.txt
expect_error "--seam: not a number" 1 "line 3: 'x1' is not a vertex index" disk blob.off --seam s3.selection.txt
printf '\n\n95 114 0\n' > s4.selection.txt
expect_error "--seam: odd count" 1 "line 3 has 3 indices, an odd number" disk blob.off --seam s4.selection.txt
printf '\n\n1 5\n' > s5.selection.txt
expect_error "--seam: border edge" 1 "pair 1 (1 5): a border edge" disk blob.off --seam s5.selection.txt
printf '\n\n7 7\n' > s6.selection.txt
expect_error "--seam: same vertex twice" 1 "pair 1 (7 7): not an edge" disk blob.off --seam s6.selection.txt
printf '3\n\n\n' > s7.selection.txt
expect_error "--seam: nothing to cut along" 1 "no seam edges (line 3 is empty)" disk blob.off --seam s7.selection.txt
printf '3 -4\n\n\n' > s8.selection.txt
expect_error "--seam: negative index" 1 "line 1: '-4' is not a vertex index" disk blob.off --seam s8.selection.txt
expect_error "--seam: missing file" 1 "cannot open" disk blob.off --seam no_such.selection.txt
# A mesh already cut open (duplicate positions along the seam, as exporters
# write it) is a disk like any other: nothing merged, nothing refused.
python3 - seam_blob.obj cut_open.off cut_open.obj <<'PY'
import sys
lines = open(sys.argv[1]).read().split("\n")
v = [l.split()[1:4] for l in lines if l.startswith("v ")]
f = [[c.split("/") for c in l.split()[1:]] for l in lines if l.startswith("f ")]
xyz = {}
for face in f:
    for a, t in face: xyz[int(t) - 1] = v[int(a) - 1]
with open(sys.argv[2], "w") as off:
    off.write("OFF\n%d %d 0\n" % (len(xyz), len(f)))
    for i in range(len(xyz)): off.write(" ".join(xyz[i]) + "\n")
    for face in f: off.write("3 " + " ".join(str(int(t) - 1) for a, t in face) + "\n")
with open(sys.argv[3], "w") as obj:
    for i in range(len(xyz)): obj.write("v " + " ".join(xyz[i]) + "\n")
    for face in f: obj.write("f " + " ".join(t for a, t in face) + "\n")
PY
check "cut-open mesh: dlf info finds the 6 duplicate positions on the border" bash -c \
  "'$DLF' info cut_open.off | grep -q '6 duplicate positions (6 on the border: seam sides)'"
check "cut-open mesh: dlf info says it fits dlf disk" equals "$(info_fits cut_open.off)" "dlf disk (a topological disk)"
for ext in off obj; do
  "$DLF" disk "cut_open.$ext" -o "cut_open_uv_$ext.obj" --report "cut_open_$ext.json" -q
  check "cut-open mesh (.$ext): exit 0, status ok, converged, as many vertices as the seamed run's vt" equals \
    "$? $(json_get "cut_open_$ext.json" "" status) $(json_get "cut_open_$ext.json" "" stop_reason) $(json_get "cut_open_$ext.json" "" vertices)" \
    "0 ok converged $(count_lines seam_blob.obj 'vt ')"
  "$DLF" score "cut_open.$ext" "cut_open_uv_$ext.obj" --report "cut_open_score_$ext.json" -q
  check "cut-open mesh (.$ext): d_area <= 2.01" number_is "$(json_get "cut_open_score_$ext.json" metrics d_area)" "<=" 2.01
  check "cut-open mesh (.$ext): 0 inverted faces" equals "$(json_get "cut_open_score_$ext.json" metrics inverted_faces)" 0
done
check "no temporaries left (seams)" no_temporaries

# --- volume --------------------------------------------------------------------
# DLF_TETRAHEDRALIZE=0 (a tool built without Mesh_3, as under the sanitizers):
# the volume tests start from the same Mesh_3 sphere kept in test/data.
if [ "${DLF_TETRAHEDRALIZE:-1}" = 0 ]; then
  "$DLF" tetrahedralize "$MESHES/sphere.off" -o vol_sphere.mesh --tets 3000 -q 2> vol_tet.err
  check "tetrahedralize without Mesh_3: exit 2, says so, writes nothing" equals \
    "$? $(grep -c 'built without CGAL.s Mesh_3' vol_tet.err) $(ls vol_sphere.mesh 2> /dev/null | wc -l)" "2 1 0"
  cp "$TEST_DATA/sphere_tets.mesh" vol_sphere.mesh
else
  "$DLF" tetrahedralize "$MESHES/sphere.off" -o vol_sphere.mesh --tets 6000 -q
  check "tetrahedralize sphere.off: exit 0" equals "$?" 0
  check "tetrahedralize: a Tetrahedra section" grep -q '^Tetrahedra' vol_sphere.mesh
fi
"$DLF" volume vol_sphere.mesh -o vol_ball.mesh --report vol.json --svg vol.svg -q 2> vol.err
check "volume: exit 0" equals "$?" 0
check "volume report: status ok, converged, start certified, 0 inverted tets" equals \
  "$(json_get vol.json "" status) $(json_get vol.json "" stop_reason) $(json_get vol.json start certified) $(json_get vol.json final inverted_tets)" \
  "ok converged true 0"
check "volume: d_vol <= 2.01" number_is "$(json_get vol.json final d_vol)" "<=" 2.01
check "volume: the output keeps the tetrahedra" equals "$(sed -n '/^Tetrahedra/{n;p}' vol_ball.mesh)" "$(sed -n '/^Tetrahedra/{n;p}' vol_sphere.mesh)"
check "volume: border vertices on the unit sphere, all inside the ball (recomputed)" /usr/bin/python3 - vol_ball.mesh <<'PY'
import math, sys
t = [l.split() for l in open(sys.argv[1])]
i = next(k for k, l in enumerate(t) if l == ["Vertices"]); n = int(t[i + 1][0])
p = [tuple(map(float, l[:3])) for l in t[i + 2:i + 2 + n]]
j = next(k for k, l in enumerate(t) if l == ["Triangles"]); m = int(t[j + 1][0])
border = {int(v) - 1 for l in t[j + 2:j + 2 + m] for v in l[:3]}
r = [math.sqrt(sum(c * c for c in q)) for q in p]
sys.exit(not (all(abs(r[v] - 1) < 1e-12 for v in border) and all(x <= 1 + 1e-12 for x in r) and len(border) > 0))
PY
check "volume --svg: an SVG picture" grep -q '<svg' vol.svg
"$DLF" volume vol_sphere.mesh --roi-ball 0 0 0.5 0.5 --factor 4 --report vol_roi.json -q
check "volume --roi-ball x4: exit 0, region within 1% of its share" equals \
  "$? $(/usr/bin/python3 -c "import json; r = json.load(open('vol_roi.json'))['roi']; print(abs(r['relative_error']) <= 0.01)")" "0 True"
"$DLF" volume vol_sphere.mesh --border-start conformal --border-max-iterations 0 --report vol_conformal.json -q
check "volume --border-start conformal --border-max-iterations 0: converged from the conformal border alone, as reported" equals \
  "$? $(json_get vol_conformal.json "" stop_reason) $(json_get vol_conformal.json start border_stop_reason) $(json_get vol_conformal.json options border_start) $(json_get vol_conformal.json options border_max_iterations)" \
  "0 converged iteration_cap conformal 0"
check "volume --border-start conformal: the border's D_area is the conformal start's, above the flow's" \
  number_is "$(json_get vol_conformal.json start border_d_area)" ">" "$(json_get vol.json start border_d_area)"
"$DLF" volume vol_sphere.mesh -v --report vol_verbose.json > vol_verbose.out
check "volume -v: a line per flow iteration, as many as reported" equals \
  "$(grep -c '^flow ' vol_verbose.out)" "$(json_get vol_verbose.json "" iterations)"
"$DLF" volume vol_sphere.mesh --cholesky-every 1 --report vol_chol.json -q
check "volume --cholesky-every 1: converged, one conjugate-gradient step per iteration (the factorisation is the matrix solved)" \
  equals "$(json_get vol_chol.json "" stop_reason) $(json_get vol_chol.json counters cg_iterations)" \
  "converged $(json_get vol_chol.json "" iterations)"
# A tolerance no two iterations reach (the ball takes 1 to 3 iterations to D_vol 2.01).
"$DLF" volume vol_sphere.mesh --max-iterations 2 --tolerance 1e-9 --report vol_cap.json -q 2> vol_cap.err
check "volume stopped after 2 iterations: exit 3 and status not_converged, as disk and sphere" equals \
  "$? $(json_get vol_cap.json "" status) $(json_get vol_cap.json "" stop_reason)" "3 not_converged iteration_cap"
check "volume stopped short: the warning names the goal it missed, D_vol against 2 + tolerance, with its value" \
  grep -Eq '^dlf: warning: not converged: stopped \(iteration_cap\) after 2 iterations short of D_vol [0-9.e+-]+ > 2[;.]' vol_cap.err
check "volume stopped short: the report's message is the warning's" \
  grep -Fq "$(json_get vol_cap.json "" message)" vol_cap.err
"$DLF" volume vol_sphere.mesh --mode paper -o vol_paper.mesh --report vol_paper.json -q
check "volume --mode paper: status ok, 0 inverted tets, the mode reported, no conjugate gradients" equals \
  "$(json_get vol_paper.json "" status) $(json_get vol_paper.json final inverted_tets) $(json_get vol_paper.json options mode) $(json_get vol_paper.json counters cg_iterations)" \
  "ok 0 paper 0"
check "volume --mode paper: D_vol below the certified start's" \
  number_is "$(json_get vol_paper.json final d_vol)" "<" "$(json_get vol_paper.json start d_vol)"
"$DLF" volume vol_sphere.mesh --mode literal 2> vol_mode.err
check "volume --mode literal: exit 1, named" equals "$? $(grep -c 'mode takes certified or paper' vol_mode.err)" "1 1"
"$DLF" volume vol_sphere.mesh --threads 1 -o vol_t1.mesh -q && "$DLF" volume vol_sphere.mesh --threads 2 -o vol_t2.mesh -q
check "volume --threads 1 and --threads 2: the same points, bit for bit" cmp -s vol_t1.mesh vol_t2.mesh

# --- tables: --csv beside --report, one seconds layout -------------------------
# csv_matches_json R.csv R.json: a header and one row, the columns the JSON
# report's keys flattened (objects and lists joined by '.', history and
# chart_list left out), each cell the JSON value (null: empty).
csv_matches_json() { python3 - "$@" <<'PY'
import csv, json, sys
rows = list(csv.reader(open(sys.argv[1], newline="")))
report = json.load(open(sys.argv[2]))
cells = []
def flatten(j, name):
    if isinstance(j, dict) and j:
        for k, v in j.items():
            if not (name == "" and k in ("history", "chart_list")):
                flatten(v, k if name == "" else name + "." + k)
    elif isinstance(j, list) and j:
        for k, v in enumerate(j):
            flatten(v, f"{name}.{k}")
    else:
        cells.append((name, j))
flatten(report, "")
assert len(rows) == 2, f"{len(rows)} lines, expected a header and one row"
assert rows[0] == [c[0] for c in cells], f"columns {rows[0][:8]}... differ from the report's keys {[c[0] for c in cells][:8]}..."
for (name, value), text in zip(cells, rows[1]):
    if value is None or value == [] or value == {}:
        ok = text == ""
    elif isinstance(value, bool):
        ok = text == ("true" if value else "false")
    elif isinstance(value, (int, float)):
        ok = float(text) == float(value)
    else:
        ok = text == value
    assert ok, f"{name}: CSV '{text}', JSON {value!r}"
assert len(rows[1]) == len(cells)
PY
}
# seconds_layout R.json: "seconds" begins with read check initial flow write pictures total, in this order.
seconds_layout() { python3 -c '
import json, sys
s = json.load(open(sys.argv[1]))["seconds"]
keys = list(s)[:7]
assert keys == ["read", "check", "initial", "flow", "write", "pictures", "total"], keys
assert all(isinstance(s[k], (int, float)) and s[k] >= 0 for k in keys), s
' "$1"; }
"$DLF" disk "$NEF" --roi-ball 0 0 0 1 --factor 2 -o tab.obj --report tab.json --csv tab.csv -q
check "disk --csv: exit 0, one row, the report's flattened keys and values (regions by index)" csv_matches_json tab.csv tab.json
check "disk --csv: the region's achieved share is a column" grep -q 'regions.0.achieved_fraction' tab.csv
check "disk: seconds read, check, initial, flow, write, pictures, total" seconds_layout tab.json
check "disk: seconds.read and seconds.write measured" number_is "$(json_get tab.json seconds read)" ">" 0
"$DLF" disk "$NEF" --max-iterations 0 --history --csv tab_cap.csv -q 2> /dev/null
check "disk --csv on a run stopped short: status not_converged in its column (a message with commas, quoted), no history columns" python3 -c '
import csv, sys
h, r = list(csv.reader(open(sys.argv[1])))
assert dict(zip(h, r))["status"] == "not_converged" and not any(c.startswith("history") for c in h), h' tab_cap.csv
"$DLF" sphere "$MESHES/sphere.off" --report tab_sph.json --csv tab_sph.csv -o tab_sph.obj -q
check "sphere --csv: the report's flattened keys and values" csv_matches_json tab_sph.csv tab_sph.json
check "sphere: the seconds layout of disk" seconds_layout tab_sph.json
check "sphere: seconds.read and seconds.write measured" number_is "$(json_get tab_sph.json seconds write)" ">" 0
"$DLF" volume vol_sphere.mesh --max-iterations 2 --report tab_vol.json --csv tab_vol.csv -o tab_vol.mesh -q
check "volume --csv: the report's flattened keys and values" csv_matches_json tab_vol.csv tab_vol.json
check "volume: the seconds layout of disk, the start's parts after it" seconds_layout tab_vol.json
check "volume: seconds.initial is its border, interior and untangling" python3 -c '
import json, sys
s = json.load(open(sys.argv[1]))["seconds"]
assert abs(s["initial"] - (s["border"] + s["interior"] + s["untangle"])) <= 1e-12 * max(1, s["initial"]), s' tab_vol.json
"$DLF" score "$NEF" tab.obj --report tab_score.json --csv tab_score.csv -q
check "score --csv: the report's flattened keys and values" csv_matches_json tab_score.csv tab_score.json
"$DLF" atlas "$NEF" -o tab_atlas.obj --report tab_atlas.json --csv tab_atlas.csv --quiet
check "atlas --csv: the report's keys and values, chart_list left out" csv_matches_json tab_atlas.csv tab_atlas.json
"$DLF" disk "$NEF" -o tab_bad.obj --csv no_such_dir/t.csv -q 2> tab_bad.err
check "disk --csv into a missing directory: exit 1 before any work, nothing written" equals \
  "$? $(grep -c "csv 'no_such_dir/t.csv': directory 'no_such_dir' does not exist" tab_bad.err) $(test -e tab_bad.obj; echo $?)" "1 1 1"
check "volume: the report names the flow's threads and preconditioner (automatic: one thread on a small mesh)" equals \
  "$(json_get vol.json options threads) $(json_get vol.json options threads_used) $(json_get vol.json options coarse_aggregate) $(json_get vol.json options cg_forcing)" \
  "0 1 64 true"
"$DLF" volume vol_sphere.mesh --threads -1 2> vol_threads.err
check "volume --threads -1: exit 1, named" equals "$? $(grep -c 'threads must be' vol_threads.err)" "1 1"
"$DLF" volume vol_sphere.mesh --border-start foo 2> vol_border_start.err
check "volume --border-start foo: exit 1, named" equals "$? $(grep -c 'border-start takes tutte or conformal' vol_border_start.err)" "1 1"
printf 'MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\nTetrahedra\n1\n1 2 4 3 1\nEnd\n' > vol_inverted.mesh
"$DLF" volume vol_inverted.mesh 2> vol_inverted.err
check "volume: an inverted tet is bad input (exit 1), named" equals \
  "$? $(grep -c 'tetrahedron 0 is inverted' vol_inverted.err)" "1 1"
printf 'MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\nTetrahedra\n1\n1 2 3 9 1\nEnd\n' > vol_range.mesh
"$DLF" volume vol_range.mesh 2> vol_range.err
check "volume: a parse error names the line (exit 1)" equals "$? $(grep -c 'line 11: tetrahedron 1 of 1 refers to vertex 9' vol_range.err)" "1 1"
if [ "${DLF_TETRAHEDRALIZE:-1}" != 0 ]; then
  "$DLF" tetrahedralize "$MESHES/elk.off" -o vol_torus.mesh 2> vol_torus.err
  check "tetrahedralize: a surface of genus 1 is refused (exit 1)" equals "$? $(grep -c 'Euler characteristic 0' vol_torus.err)" "1 1"
  "$DLF" tetrahedralize "$MESHES/sphere.off" -o vol_ratio.mesh --facet-ratio 0.5 2> vol_ratio.err
  check "tetrahedralize --facet-ratio 0.5: refused (exit 1), named, nothing written" equals \
    "$? $(grep -c 'facet-ratio must lie in' vol_ratio.err) $(ls vol_ratio.mesh 2> /dev/null | wc -l)" "1 1 0"
  check "tetrahedralize --tets 6000: between 3000 and 12000 tetrahedra" /usr/bin/python3 - vol_sphere.mesh <<'PY'
import sys
w = open(sys.argv[1]).read().split()
sys.exit(0 if 3000 <= int(w[w.index("Tetrahedra") + 1]) <= 12000 else 1)
PY
  # A shape with thin legs: border triangles 3 times the tetrahedra's size
  # (the default) leave far fewer vertices on the border than Mesh_3's
  # uniform sizing (--facet-ratio 1), and those bound how low D_vol gets.
  "$DLF" tetrahedralize "$MESHES/tripod.off" -o vol_tripod.mesh --tets 3000 -q
  "$DLF" tetrahedralize "$MESHES/tripod.off" -o vol_tripod_uniform.mesh --tets 3000 --facet-ratio 1 -q
  check "tetrahedralize tripod: the default's border vertices a smaller fraction than --facet-ratio 1's, by 0.1 at least" \
    /usr/bin/python3 - vol_tripod.mesh vol_tripod_uniform.mesh <<'PY'
import collections, sys
def border_fraction(path):
    w = open(path).read().split()
    k = w.index("Tetrahedra"); n = int(w[k + 1])
    tets = [w[k + 2 + 5 * i:k + 6 + 5 * i] for i in range(n)]
    faces = collections.Counter(tuple(sorted(t[:j] + t[j + 1:])) for t in tets for j in range(4))
    border = {v for f, c in faces.items() if c == 1 for v in f}
    return len(border) / len({v for t in tets for v in t})
a, b = border_fraction(sys.argv[1]), border_fraction(sys.argv[2])
print(a, b)
sys.exit(0 if a < b - 0.1 else 1)
PY
fi
check "no temporaries left (volume)" no_temporaries

# --- atlas ----------------------------------------------------------------------
# A closed genus-1 mesh: a valid atlas (exact checks), per-corner vt, the
# file's v lines in order.
"$DLF" atlas "$MESHES/knot1.off" -o knot_atlas.obj --report knot_atlas.json --svg knot_atlas.svg --quiet > atlas.out 2> atlas.err
check "atlas knot1 exits 0" equals "$?" 0
check "atlas knot1: no stderr with --quiet" equals "$(wc -c < atlas.err)" 0
check "atlas knot1 report: valid" equals "$(json_get knot_atlas.json "" valid)" true
check "atlas knot1 report: converged" equals "$(json_get knot_atlas.json "" converged)" true
check "atlas knot1 report: 0 inverted faces" equals "$(json_get knot_atlas.json "" inverted_faces)" 0
check "atlas knot1 report: 0 overlapping charts" equals "$(json_get knot_atlas.json "" overlapping_chart_pairs)" 0
check "atlas knot1 report: genus 1" equals "$(json_get knot_atlas.json "" max_genus)" 1
check "atlas knot1 report: D_area <= 2.02" number_is "$(json_get knot_atlas.json "" d_area)" "<=" 2.02
check "atlas knot1 OBJ: the file's v lines, in order" equals \
  "$(awk '/^v / { printf "%.12g %.12g %.12g\n", $2, $3, $4 }' knot_atlas.obj | md5sum)" \
  "$(awk '!/^#/ && NF' "$MESHES/knot1.off" | awk 'NR == 2 { n = $1 } NR > 2 && NR <= 2 + n { printf "%.12g %.12g %.12g\n", $1, $2, $3 }' | md5sum)"
check "atlas knot1 OBJ: 6400 faces f v/vt" equals "$(grep -c '^f [0-9]*/[0-9]* [0-9]*/[0-9]* [0-9]*/[0-9]*$' knot_atlas.obj)" 6400
check "atlas knot1 OBJ: vt in the unit square" awk '/^vt / { if($2 < 0 || $2 > 1 || $3 < 0 || $3 > 1) bad = 1 } END { exit bad }' knot_atlas.obj
check "atlas knot1 --svg: one polygon per face" equals "$(grep -c '^<polygon ' knot_atlas.svg)" 6400
check "atlas knot1 --svg: a whole SVG" equals "$(tail -1 knot_atlas.svg)" "</svg>"
# dlf score on the atlas (its own v lines are the mesh): the same D_area,
# as many charts, no fold and no overlapping uv triangles (exact).
"$DLF" score knot_atlas.obj knot_atlas.obj --report knot_score.json > knot_score.out 2>&1
check "score of an atlas exits 0" equals "$?" 0
check "score of an atlas: D_area equals the atlas report's (1e-9 relative)" \
  relatively_equal "$(json_get knot_score.json atlas d_area)" "$(json_get knot_atlas.json "" d_area)" 1e-9
check "score of an atlas: its charts" equals "$(json_get knot_score.json atlas charts)" "$(json_get knot_atlas.json "" charts)"
check "score of an atlas: 0 inverted, 0 overlapping uv triangle pairs" equals \
  "$(json_get knot_score.json atlas inverted_faces) $(json_get knot_score.json atlas overlapping_face_pairs)" "0 0"
check "score of an atlas: says so" grep -q "overlapping uv triangle pairs" knot_score.out
# Polygons: triangulated, said on stderr and in the report.
"$DLF" atlas "$MESHES/double-torus-example.off" -o dt.obj --report dt.json > dt.out 2> dt.err
check "atlas on polygons exits 0" equals "$?" 0
check "atlas on polygons: one stderr line says so" grep -q "polygons triangulated" dt.err
check "atlas on polygons: report field" number_is "$(json_get dt.json repairs polygons_triangulated)" ">" 0
# --texture: the atlas's own uv (the unit square, area-preserving, so the
# checkerboard's squares are equal in surface area) in a textured OBJ with
# its material and PNG; -q as --quiet.
"$DLF" atlas "$MESHES/knot1.off" -o knot_tex_uv.obj --texture knot_tex.obj --texture-size 64 -q > tex.out 2> tex.err
check "atlas --texture exits 0" equals "$?" 0
check "atlas -q: nothing on stdout or stderr" equals "$(cat tex.out tex.err | wc -c)" 0
check "atlas --texture: the OBJ names its material" grep -q '^mtllib knot_tex.mtl$' knot_tex.obj
check "atlas --texture: the material names the PNG" grep -q '^map_Kd knot_tex.png$' knot_tex.mtl
check "atlas --texture: a PNG of 64 x 64 pixels" equals \
  "$(python3 -c "import struct,sys; d=open('knot_tex.png','rb').read(24); print(d[:8]==b'\\x89PNG\\r\\n\\x1a\\n', *struct.unpack('>II', d[16:24]))")" "True 64 64"
check "atlas --texture: the atlas's v, vt and f lines" equals \
  "$(grep -E '^(v|vt|f) ' knot_tex.obj | md5sum)" "$(grep -E '^(v|vt|f) ' knot_tex_uv.obj | md5sum)"
expect_atlas_error() { # expect_atlas_error DESCRIPTION PATTERN ARGS...: exit 1, one line, nothing written
  local what=$1 pattern=$2; shift 2
  rm -f bad_atlas.obj
  "$DLF" atlas "$@" > bad_atlas.out 2> bad_atlas.err
  check "$what: exits 1" equals "$?" 1
  check "$what: says so" grep -q "$pattern" bad_atlas.err
  check "$what: nothing written" test ! -e bad_atlas.obj
}
expect_atlas_error "atlas --texture not .obj" "texture expects a file name ending in .obj" \
  "$MESHES/knot1.off" -o bad_atlas.obj --texture knot_tex.png
expect_atlas_error "atlas --texture-size alone" "texture-size applies to --texture only" \
  "$MESHES/knot1.off" -o bad_atlas.obj --texture-size 64
# A polygon soup (boeing.off: 2,741 vertices at 1,264 positions, its pieces
# repeating the vertices of their shared edges): merged, said on one line
# and in the report; one component, not 122. --keep-duplicates keeps them.
"$DLF" atlas "$MESHES/boeing.off" -o boeing_atlas.obj --report boeing_atlas.json > boeing.out 2> boeing.err
check "atlas boeing exits 0" equals "$?" 0
check "atlas boeing: one line says the duplicates were merged" equals \
  "$(grep -c '1477 duplicate vertices merged (a polygon soup' boeing.err)" 1
check "atlas boeing: report field" equals "$(json_get boeing_atlas.json repairs duplicate_vertices_merged)" 1477
check "atlas boeing: one component" equals "$(json_get boeing_atlas.json "" components)" 1
check "atlas boeing: valid" equals "$(json_get boeing_atlas.json "" valid)" true
check "atlas boeing: merged copies are not counted isolated" equals "$(json_get boeing_atlas.json repairs isolated_vertices)" 0
check "atlas boeing: the file's 2741 v lines" equals "$(grep -c '^v ' boeing_atlas.obj)" 2741
"$DLF" atlas "$MESHES/boeing.off" -o boeing_kept.obj --report boeing_kept.json --keep-duplicates -q
check "atlas boeing --keep-duplicates: 122 components" equals "$(json_get boeing_kept.json "" components)" 122
check "atlas boeing --keep-duplicates: nothing merged" equals "$(json_get boeing_kept.json repairs duplicate_vertices_merged)" 0
# knot1 has no duplicates: nothing merged, the repair line absent.
check "atlas knot1: no duplicates merged" equals "$(json_get knot_atlas.json repairs duplicate_vertices_merged)" 0

# Several components: each handled.
"$DLF" atlas "$MESHES/blobby_3cc.off" -o b3.obj --report b3.json --quiet
check "atlas blobby_3cc exits 0" equals "$?" 0
check "atlas blobby_3cc: 3 components" equals "$(json_get b3.json "" components)" 3
# Bad input: one line, exit 1, no output file.
: > empty.off
printf 'OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n' > cloud.off
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n3 0 1 2\n3 0 2 3\n' > flat.off
for bad in empty cloud flat; do
  # Output names of their own: an earlier check writes flat.obj.
  rm -f "atlas_$bad.obj"
  "$DLF" atlas "$bad.off" -o "atlas_$bad.obj" > "$bad.out" 2> "$bad.err"
  check "atlas on $bad input exits 1" equals "$?" 1
  check "atlas on $bad input: one stderr line" equals "$(wc -l < "$bad.err")" 1
  check "atlas on $bad input: no output file" test ! -e "atlas_$bad.obj"
done
check "atlas on a point cloud says so" grep -q "point cloud" cloud.err
check "atlas on all-degenerate faces says so" grep -q "all 2 faces are degenerate" flat.err

# --- pictures of measure control: raw colours, fitted scales, face budget ------
# svg_facts FILE: after parsing FILE as XML, one "key value" a line: the
# colour bar's scale (scale_max, scale_min) and top label (top_label), the
# polygons and images drawn, the region shade's opacity (shade, none if
# absent), and the mean of red - blue over the fills of the region's faces
# (region_red) and of the others (rest_red): about 0 for white, > 0 red.
svg_facts() { python3 - "$1" <<'PY'
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
name = lambda e: e.tag.split("}")[-1]
bar = next(e for e in root.iter() if e.get("id") == "colour-bar")
print("scale_max", bar.get("data-scale-max")); print("scale_min", bar.get("data-scale-min"))
print("top_label", [t.text for t in bar.iter() if name(t) == "text"][0])
print("polygons", sum(1 for e in root.iter() if name(e) == "polygon"))
print("images", sum(1 for e in root.iter() if name(e) == "image"))
shade = [e for e in root.iter() if e.get("id") == "region-shade"]
print("shade", shade[0].get("fill-opacity") if shade else "none")
def red(group):
    fills = [e.get("fill") for e in group.iter() if name(e) == "polygon"]
    return sum(int(f[1:3], 16) - int(f[5:7], 16) for f in fills) / max(1, len(fills))
region = [e for e in root.iter() if e.get("id") == "region-faces"]
rest = [e for e in root.iter() if name(e) == "g" and e.get("stroke-width") == "0.3" and e.get("id") is None]
print("region_red", red(region[0]) if region else "none")
print("rest_red", red(rest[0]) if rest else "none")
PY
}
fact() { svg_facts "$1" | awk -v k="$2" '$1 == k { print $2 }'; }
# raw_ratio_range MESH MAP CX CY CZ R FACTOR: the largest domain / surface
# ratio or its inverse over the faces, recomputed as the picture defines it:
# density FACTOR on the faces whose centroid lies in the ball, 1 elsewhere,
# the domain scaled to the area sum of density x area.
raw_ratio_range() { python3 - "$@" <<'PY'
import math, sys
mesh, obj, cx, cy, cz, r, factor = sys.argv[1], sys.argv[2], *map(float, sys.argv[3:8])
tokens = [t for t in (l.split('#')[0].split() for l in open(mesh)) if t]
nv, nf = int(tokens[1][0]), int(tokens[1][1])
xyz = [tuple(map(float, t[:3])) for t in tokens[2:2 + nv]]
faces = [tuple(map(int, t[1:4])) for t in tokens[2 + nv:2 + nv + nf]]
vt = [tuple(map(float, l.split()[1:3])) for l in open(obj) if l.startswith("vt ")]
def area3(a, b, c):
    u = [b[i] - a[i] for i in range(3)]; w = [c[i] - a[i] for i in range(3)]
    return 0.5 * math.sqrt((u[1] * w[2] - u[2] * w[1]) ** 2 + (u[2] * w[0] - u[0] * w[2]) ** 2 + (u[0] * w[1] - u[1] * w[0]) ** 2)
def area2(a, b, c): return 0.5 * abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
rho = [factor if sum((sum(xyz[i][k] for i in f) / 3 - (cx, cy, cz)[k]) ** 2 for k in range(3)) <= r * r else 1 for f in faces]
a3 = [area3(*(xyz[i] for i in f)) for f in faces]
a2 = [area2(*(vt[i] for i in f)) for f in faces]
scale = sum(p * a for p, a in zip(rho, a3)) / sum(a2)
print(math.exp(max(abs(math.log(b * scale / a)) for a, b in zip(a3, a2))))
PY
}
BALL="-0.215988 -0.081660 0.215680 1"
"$DLF" disk "$NEF" --roi-ball $BALL --factor 4 -o mag.obj --report mag.json --svg mag.svg > mag.out
check "4x region: exit 0" equals "$?" 0
check "4x region: magnification within 1% of 4" python3 -c \
  "import json, sys; r = json.load(open('mag.json'))['regions'][0]; sys.exit(not (abs(r['magnification'] - 4) <= 0.04 and r['prescribed_magnification'] == 4))"
check "4x region: magnification = achieved / prescribed share x factor, surface share < prescribed share" python3 -c \
  "import json, sys; r = json.load(open('mag.json'))['regions'][0]; sys.exit(not (abs(r['magnification'] - r['achieved_fraction'] / r['prescribed_fraction'] * 4) < 1e-9 and 0 < r['surface_fraction'] < r['prescribed_fraction']))"
check "4x region: surface share recomputed" python3 - "$NEF" mag.json <<'PY'
import json, math, sys
tokens = [t for t in (l.split('#')[0].split() for l in open(sys.argv[1])) if t]
nv, nf = int(tokens[1][0]), int(tokens[1][1])
xyz = [tuple(map(float, t[:3])) for t in tokens[2:2 + nv]]
faces = [tuple(map(int, t[1:4])) for t in tokens[2 + nv:2 + nv + nf]]
c, r = (-0.215988, -0.081660, 0.215680), 1
def area3(a, b, d):
    u = [b[i] - a[i] for i in range(3)]; w = [d[i] - a[i] for i in range(3)]
    return 0.5 * math.sqrt((u[1] * w[2] - u[2] * w[1]) ** 2 + (u[2] * w[0] - u[0] * w[2]) ** 2 + (u[0] * w[1] - u[1] * w[0]) ** 2)
inside = total = 0
for f in faces:
    a = area3(*(xyz[i] for i in f)); total += a
    if sum((sum(xyz[i][k] for i in f) / 3 - c[k]) ** 2 for k in range(3)) <= r * r: inside += a
got = json.load(open(sys.argv[2]))['regions'][0]['surface_fraction']
sys.exit(not abs(got - inside / total) <= 1e-9)
PY
check "4x region: the summary gives the surface share and the magnification" \
  grep -Eq "region roi-ball .*: factor 4, [0-9]+ faces, 0\.[0-9]+ of the surface; .*magnification (3\.9[6-9]|4\.0[0-4]|4)[0-9]* \(prescribed 4\)" mag.out
check "4x region SVG: raw colours by default, the region red, the rest about white" python3 -c "
import sys; f = dict(l.split() for l in sys.stdin)
sys.exit(not (float(f['region_red']) > 100 and abs(float(f['rest_red'])) < 20))" < <(svg_facts mag.svg)
check "4x region SVG: the region is shaded (filled), not only outlined" equals "$(fact mag.svg shade)" 0.15
MAG_RANGE=$(raw_ratio_range "$NEF" mag.obj $BALL 4)
check "4x region SVG: the fitted scale spans the run's range, rounded up to 2 digits" python3 -c "
import sys; e, m = float(sys.argv[1]), float(sys.argv[2]); lo = float(sys.argv[3])
sys.exit(not (m >= 3.9 and m <= e <= 1.1 * m + 1e-9 and abs(lo * e - 1) < 1e-12))" \
  "$(fact mag.svg scale_max)" "$MAG_RANGE" "$(fact mag.svg scale_min)"
check "4x region SVG: the colour bar's top label is the scale's end" \
  equals "$(fact mag.svg top_label)" "$(python3 -c "import sys; print('%.3g' % float(sys.argv[1]))" "$(fact mag.svg scale_max)")"
"$DLF" disk "$NEF" --roi-ball $BALL --factor 4 --svg mag_p.svg --svg-colour prescribed --svg-scale fixed -q
check "--svg-colour prescribed: the converged region about white like the rest" python3 -c "
import sys; f = dict(l.split() for l in sys.stdin)
sys.exit(not (abs(float(f['region_red'])) < 20 and abs(float(f['rest_red'])) < 20))" < <(svg_facts mag_p.svg)
check "--svg-scale fixed: 1/4 to 4" equals "$(fact mag_p.svg scale_min) $(fact mag_p.svg scale_max) $(fact mag_p.svg top_label)" "0.25 4 4"
"$DLF" disk "$NEF" --svg plain.svg -q
check "no density: the fitted scale of a converged map has its floor (1.1 or more)" \
  number_is "$(fact plain.svg scale_max)" ">=" 1.1
check "no density: the bar names domain / surface" grep -q ">domain / surface<" plain.svg
"$DLF" sphere "$MESHES/sphere.off" --roi-ball 0 0 1 0.8 --factor 4 --report sph_mag.json --svg sph_mag.svg > sph_mag.out
check "sphere 4x region: magnification within 1% of 4" python3 -c \
  "import json, sys; r = json.load(open('sph_mag.json'))['regions'][0]; sys.exit(not (abs(r['magnification'] - 4) <= 0.04 and 0 < r['surface_fraction'] < r['prescribed_fraction']))"
check "sphere 4x region SVG: the region red, the rest about white, shaded" python3 -c "
import sys; f = dict(l.split() for l in sys.stdin)
sys.exit(not (float(f['region_red']) > 100 and abs(float(f['rest_red'])) < 20 and f['shade'] == '0.15' and float(f['scale_max']) >= 3.9))" < <(svg_facts sph_mag.svg)
check "sphere 4x region: the summary gives the magnification" grep -q "magnification .* (prescribed 4)" sph_mag.out
# The face budget: beyond it, one embedded PNG and no polygon.
"$DLF" disk "$NEF" --roi-ball $BALL --factor 4 --svg budget.svg --svg-max-faces 100 -q
check "--svg-max-faces below the faces: one image, no polygon" \
  equals "$(fact budget.svg images) $(fact budget.svg polygons)" "1 0"
check "--svg-max-faces: the image is a PNG of the picture's triangles (region red, rest white)" python3 - budget.svg <<'PY'
import base64, re, struct, sys, zlib
href = re.search(r'href="data:image/png;base64,([^"]*)"', open(sys.argv[1]).read()).group(1)
data = base64.b64decode(href)
assert data[:8] == b"\x89PNG\r\n\x1a\n"
pos, idat = 8, b""
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    if kind == b"IHDR": w, h, depth, colour = struct.unpack(">IIBB", data[pos + 8:pos + 18])
    if kind == b"IDAT": idat += data[pos + 8:pos + 8 + n]
    pos += 12 + n
assert depth == 8 and colour == 6
raw, stride = zlib.decompress(idat), 1 + 4 * w
assert len(raw) == h * stride
# Undo the filters, count opaque red and opaque near-white pixels.
prev, red, white = bytearray(4 * w), 0, 0
for y in range(h):
    kind, line = raw[y * stride], bytearray(raw[y * stride + 1:(y + 1) * stride])
    for i in range(len(line)):
        a, b = line[i - 4] if i >= 4 else 0, prev[i]
        c = prev[i - 4] if i >= 4 else 0
        p = a + b - c
        pred = [0, a, b, (a + b) // 2, a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else b if abs(p - b) <= abs(p - c) else c][kind]
        line[i] = (line[i] + pred) & 255
    for x in range(0, len(line), 4):
        r, g, bl, al = line[x:x + 4]
        if al == 255 and r - bl > 100: red += 1
        if al == 255 and abs(r - bl) < 20 and r > 200: white += 1
    prev = line
sys.exit(not (red > 10000 and white > 10000))
PY
# A mesh above the default budget (50,000 faces): a 160 x 160 grid, 51,200 triangles.
python3 -c "
n = 160
print('OFF'); print((n + 1) ** 2, 2 * n * n, 0)
for j in range(n + 1):
    for i in range(n + 1): print(i / n, j / n, 0.1 * (i / n) ** 2)
for j in range(n):
    for i in range(n):
        a = j * (n + 1) + i
        print(3, a, a + 1, a + n + 2); print(3, a, a + n + 2, a + n + 1)" > grid.off
"$DLF" disk grid.off --svg grid.svg -q
check "51,200 faces: exit 0" equals "$?" 0
check "51,200 faces: rasterised (one image, no polygon)" equals "$(fact grid.svg images) $(fact grid.svg polygons)" "1 0"
check "51,200 faces: the SVG under 3 MB" number_is "$(wc -c < grid.svg)" "<" 3000000
# Bad values: one line, exit 1.
for bad in "--svg-colour blue" "--svg-scale wide" "--svg-max-faces 0"; do
  "$DLF" disk "$NEF" --svg bad.svg $bad > bad.out 2> bad.err
  check "$bad: exit 1, one stderr line" equals "$? $(wc -l < bad.err)" "1 1"
done
"$DLF" disk "$NEF" --svg-scale fixed -o x.obj > bad.out 2> bad.err
check "--svg-scale without --svg: refused" equals "$? $(cat bad.err)" "1 dlf: error: --svg-scale applies to --svg only"

echo
if [ "$failures" -ne 0 ]; then
  echo "$failures of $checks checks FAILED"
  exit 1
fi
echo "all $checks checks passed"
