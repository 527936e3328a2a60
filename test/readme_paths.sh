#!/usr/bin/env bash
# Runs every path of README.md as written: each fenced block is extracted
# and run from a scratch folder laid out like a checkout after the README's
# two commands (build/tools, build/python, build/data, test/data), failing
# on any error:
#   - ```sh blocks: bash -e, line by line as a user pastes them;
#   - the ```cpp block: compiled from this very text by the build
#     (examples/CMakeLists.txt extracts it), run on a disk (exit 0, its line) and
#     on a closed mesh (exit 1, the report's message on stderr);
#   - ```python blocks: with PYTHONPATH=build/python, as the README says, by
#     $DLF_PYTHON (the interpreter the module was built for; default python3).
# Blocks that this test cannot run are listed in NOT_RUN with the job that
# runs them; a block that is neither run nor listed fails the test.
#
#   bash test/readme_paths.sh SOURCE_DIR BUILD_DIR DATA_DIR README_EXAMPLE COMPILED_SOURCE
set -u
SRC=${1:?usage: readme_paths.sh SOURCE_DIR BUILD_DIR DATA_DIR README_EXAMPLE COMPILED_SOURCE}
BUILD=${2:?}
DATA=${3:?}
EXAMPLE=${4:?}
COMPILED=${5:?}
README="$SRC/README.md"
WORK=$(mktemp -d "${TMPDIR:-/tmp}/dlf_readme.XXXXXX")
trap 'rm -rf "$WORK"' EXIT

failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok: $*"; }

# The checkout as the README sees it, with outputs landing in the scratch folder.
mkdir -p "$WORK/build" "$WORK/test"
ln -s "$BUILD/tools" "$WORK/build/tools"
ln -s "$DATA" "$WORK/build/data"
ln -s "$SRC/test/data" "$WORK/test/data"
[ -d "$BUILD/python" ] && ln -s "$BUILD/python" "$WORK/build/python"

# Blocks run elsewhere, by the first command of the block: that command and
# where it runs.
NOT_RUN=(
  "bash .ci/main-job|CI's own entry points; .ci/run runs .ci/test, which runs this test"
  "cmake --install build --prefix|.ci/package: install to a prefix, a project using find_package, cpack -G DEB, apt-get install, the manual"
)

# Extract the fenced blocks: block_N.LANG, in README order.
awk -v dir="$WORK" '
  /^```[a-z]+$/ && !inside { inside = 1; n++; lang = substr($0, 4); file = sprintf("%s/block_%02d.%s", dir, n, lang); printf "" > file; next }
  /^```$/ && inside { inside = 0; close(file); next }
  inside { print >> file }
' "$README"
blocks=("$WORK"/block_*)
[ -e "${blocks[0]}" ] || { echo "FAIL: no fenced block in $README"; exit 1; }

seconds() { date +%s.%N; }
run_sh() { # block: run in the scratch folder, stopping at the first failing line
  local block=$1 name start
  name=$(basename "$block")
  start=$(seconds)
  if (cd "$WORK" && bash -e -o pipefail "$block" > "$block.out" 2>&1); then
    ok "$name ($(head -n 1 "$block" | cut -c1-70)...): $(awk -v s="$start" -v e="$(seconds)" 'BEGIN { printf "%.1f s", e - s }')"
  else
    fail "$name: exit $?; its commands and output:"; sed 's/^/    | /' "$block"; tail -n 20 "$block.out" | sed 's/^/    > /'
  fi
}

for block in "${blocks[@]}"; do
  name=$(basename "$block")
  first=$(grep -m 1 -v '^\s*\(#.*\)\?$' "$block")
  case $block in
  *.sh)
    skipped=""
    for entry in "${NOT_RUN[@]}"; do
      [[ "$first" == "${entry%%|*}"* ]] && skipped="${entry#*|}"
    done
    if [ -n "$skipped" ]; then echo "not run here: $name ($first ...): $skipped"; continue; fi
    if grep -q 'build/python/' "$block" && [ ! -d "$BUILD/python/discrete_lie_flow" ]; then
      [ "${DLF_REQUIRE_ALL:-0}" = 1 ] && fail "$name: no Python module in $BUILD/python" || echo "skipped: $name (no Python module)"
      continue
    fi
    run_sh "$block"
    ;;
  *.cpp)
    # The program the build compiled is this block, byte for byte.
    if ! cmp -s "$block" "$COMPILED"; then
      fail "$name: the README's C++ example differs from the compiled one ($COMPILED): configure again"
      continue
    fi
    if out=$("$EXAMPLE" "$DATA/meshes/lion-head.off" 2> "$WORK/cpp.err"); then
      if [[ "$out" =~ ^converged,\ d_area\ 2\.0[01] ]]; then ok "$name on lion-head.off: $out"
      else fail "$name on lion-head.off printed '$out'"; fi
    else
      fail "$name on lion-head.off: exit $? ($(cat "$WORK/cpp.err"))"
    fi
    # A closed mesh has no border: the error branch prints the report's code and message.
    "$EXAMPLE" "$DATA/meshes/sphere.off" > "$WORK/cpp.out" 2> "$WORK/cpp.err"
    rc=$?
    if [ "$rc" = 1 ] && grep -q '^ERROR_NO_TOPOLOGICAL_DISC: .*border' "$WORK/cpp.err" && [ ! -s "$WORK/cpp.out" ]; then
      ok "$name on a closed mesh: exit 1, $(cat "$WORK/cpp.err")"
    else
      fail "$name on a closed mesh: exit $rc, stderr '$(cat "$WORK/cpp.err")', stdout '$(cat "$WORK/cpp.out")'"
    fi
    "$EXAMPLE" > /dev/null 2> "$WORK/cpp.err"
    rc=$?
    [ "$rc" = 1 ] && grep -q '^usage: ' "$WORK/cpp.err" && ok "$name without a mesh: exit 1, usage" ||
      fail "$name without a mesh: exit $rc, '$(cat "$WORK/cpp.err")'"
    ;;
  *.python)
    if [ ! -d "$BUILD/python/discrete_lie_flow" ]; then
      [ "${DLF_REQUIRE_ALL:-0}" = 1 ] && fail "$name: no Python module in $BUILD/python" || echo "skipped: $name (no Python module)"
      continue
    fi
    start=$(seconds)
    if (cd "$WORK" && PYTHONPATH=build/python "${DLF_PYTHON:-python3}" "$block" > "$block.out" 2>&1); then
      ok "$name (Python): $(awk -v s="$start" -v e="$(seconds)" 'BEGIN { printf "%.1f s", e - s }'); $(tail -n 1 "$block.out")"
    else
      fail "$name (Python): exit $?"; tail -n 20 "$block.out" | sed 's/^/    > /'
    fi
    ;;
  *)
    fail "$name: a block of unknown language ($(basename "${block##*.}")): run it here or list it in NOT_RUN"
    ;;
  esac
done

# What the blocks say they make, made.
made=(lion.obj lion.json lion.svg)
[ -d "$BUILD/python/discrete_lie_flow" ] && made+=(study/summary.md)
for f in "${made[@]}"; do
  [ -s "$WORK/$f" ] && ok "made $f" || fail "the README's commands did not make $f"
done
# The study: every run recorded, none failed by the tool.
if [ ! -d "$BUILD/python/discrete_lie_flow" ]; then
  :
elif [ -f "$WORK/study.sqlite" ]; then
  "${DLF_PYTHON:-python3}" - "$WORK/study.sqlite" <<'PY' || fail "the study's database"
import sqlite3, sys
rows = sqlite3.connect(sys.argv[1]).execute("select status, count(*) from runs group by status").fetchall()
print("ok: study runs by status:", dict(rows))
bad = {s: n for s, n in rows if s not in ("ok", "not_converged", "not_applicable", "input_error")}
sys.exit(1 if bad or not rows else 0)
PY
else
  fail "the README's study made no study.sqlite"
fi

[ "$failures" = 0 ] || { echo "readme_paths: $failures failed"; exit 1; }
echo "readme_paths: every block of README.md ran as written"
