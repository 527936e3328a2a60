#!/usr/bin/env bash
# The paper's experiments, every page, by one command.
#
#   benchmark/paper.sh                    # every page (about an hour on a busy 2-core machine)
#   benchmark/paper.sh --quick            # small meshes only: doc/paper_quick.md (about 10 s)
#   benchmark/paper.sh --quick --check    # exit 1 when doc/paper_quick.md no longer matches the code
#   benchmark/paper.sh --parts tables,figures   # some parts of the full run only
#                                         # (literal, tables, paper_mode, pictures, figures, sphere, quick;
#                                         # or one part of figures: table2, mu, modes, sphere_starts, ...)
#
# The full run regenerates, with no manual step:
#   doc/paper_literal.md      Table 2 with the literal Algorithm 1 (benchmark/literal.sh)
#   doc/paper_experiments.md  Tables 3, 4, 5, 6 and Figs. 17-18 against the OT peer (benchmark/paper_tables.sh)
#   doc/paper_mode.md         the stabilised flow on every disk mesh (benchmark/paper_runs.py)
#   doc/paper_figures.md      Table 2 again with μ 0.2-0.8 and Figs. 12-13's steps, Tables 3-5's three
#                             flows, Figs. 8-9's and 17-18's starts, Figs. 10, 14, 15-16 (benchmark/paper_runs.py)
#   doc/paper_sphere.md       the paper mode on every closed genus-0 mesh (benchmark/sphere_paper.sh)
#                             and the literal Algorithm 1 on the sphere (benchmark/paper_runs.py)
#   doc/sphere_paper_mode.md  the paper mode on the sphere, one option changed at a time (benchmark/paper_runs.py)
#   doc/images/fig10_*.svg, fig14_*.svg, fig15_16_*.svg (benchmark/fig10.sh, fig14.sh, fig15_16.sh)
# Each generated part starts with the command, the commit, the processor, the
# compiler and the versions of CGAL, Eigen, SuiteSparse and OpenBLAS (and
# the OpenBLAS kernel in use). --check compares only the deterministic
# columns (iterations, stop reasons, D_area to four decimals, folds): the
# quick page has no timing column.
#
# BUILD_DIR (default build) is the CMake build directory; DLF (default
# BUILD_DIR/tools/dlf) the tool; DATA_DIR (default: the build's
# DLF_DATA_DIR) holds CGAL's data set (meshes in DATA_DIR/meshes). --check
# builds nothing: it needs only the `dlf` tool of the default build.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
args="$*"
quick=0 check=0 parts=literal,tables,paper_mode,pictures,figures,sphere,quick
while [[ $# -gt 0 ]]; do
  case $1 in
    --quick) quick=1 ;;
    --check) check=1 ;;
    --parts) parts=${2:?--parts needs a list}; shift ;;
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) echo "paper.sh: unknown option $1 (--quick, --check, --parts)" >&2; exit 2 ;;
  esac
  shift
done
part() { [[ ,$parts, == *,$1,* ]]; }
[[ $check == 1 && $quick == 0 ]] && { echo "paper.sh: --check compares the quick page: use --quick --check" >&2; exit 2; }

build=${BUILD_DIR:-build}
case $build in /*) ;; *) build=$root/$build ;; esac
if [[ -z ${DATA_DIR:-} && -f $build/CMakeCache.txt ]]; then
  DATA_DIR=$(sed -n 's/^DLF_DATA_DIR:PATH=//p' "$build/CMakeCache.txt")
fi
DATA_DIR=${DATA_DIR:-$build/data}
MESHES=$DATA_DIR/meshes
DLF=${DLF:-$build/tools/dlf}
case $DLF in /*) ;; *) DLF=$root/$DLF ;; esac
[[ -d $MESHES ]] || { echo "paper.sh: no meshes in DATA_DIR/meshes" >&2; exit 2; }
command -v python3 > /dev/null || { echo "paper.sh: python3 is needed" >&2; exit 2; }
if [[ $check == 0 ]]; then
  cmake -S "$root" -B "$build" > /dev/null
  cmake --build "$build" --target dlf -j2 > /dev/null
fi
[[ -x $DLF ]] || { echo "paper.sh: the dlf tool is not built ($DLF)" >&2; exit 2; }

# Single-threaded (OMP_THREAD_LIMIT binds CHOLMOD's OpenMP regions; see benchmark/run.sh).
export OMP_THREAD_LIMIT=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The header of every generated part: what was run, where, with what.
version() { # the preprocessor's expansion of $1 after #include <$2>
  printf '#include <%s>\n%s\n' "$2" "$1" |
    "$cxx" -E -P -x c++ ${eigen:+-I"$eigen"} ${suitesparse:+-I"$suitesparse"} - 2> /dev/null |
    tail -n 1 | tr -d ' '
}
if [[ $check == 0 ]]; then
  cxx=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt" 2> /dev/null || true)
  cxx=${cxx:-c++}
  eigen=$(sed -n 's/^EIGEN3_INCLUDE_DIR:[A-Z]*=//p' "$build/CMakeCache.txt" 2> /dev/null || true)
  suitesparse=$(sed -n 's/^CHOLMOD_INCLUDE_DIR:[A-Z]*=//p' "$build/CMakeCache.txt" 2> /dev/null || true)
  commit=$(git rev-parse --short HEAD 2> /dev/null || echo unknown)
  dirty=$(git status --porcelain -- include tools benchmark 2> /dev/null | wc -l)
  cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2> /dev/null | head -n 1)
  compiler=$("$cxx" --version 2> /dev/null | head -n 1)
  cgal=$(version CGAL_VERSION CGAL/version.h)
  eig=$(version 'EIGEN_WORLD_VERSION.EIGEN_MAJOR_VERSION.EIGEN_MINOR_VERSION' Eigen/Core)
  ss=$(version 'SUITESPARSE_MAIN_VERSION.SUITESPARSE_SUB_VERSION.SUITESPARSE_SUBSUB_VERSION' SuiteSparse_config.h)
  core=$(OPENBLAS_VERBOSE=2 "$DLF" info "$MESHES/nefertiti.off" -q 2>&1 > /dev/null | sed -n 's/^Core: //p' | head -n 1)
  openblas=$(python3 -c 'import ctypes; c = ctypes.CDLL("libopenblas.so.0"); c.openblas_get_config.restype = ctypes.c_char_p; print(c.openblas_get_config().decode().split()[1])' 2> /dev/null || echo "?")
fi
command_line="benchmark/paper.sh${args:+ $args}"
command_line=${command_line/ --check/}
header() { # $1: the part's own command
  echo "Generated by \`$command_line\` (this part: \`$1\`) at commit $commit$([[ $dirty -gt 0 ]] && echo " + $dirty uncommitted file(s) under include/, tools/, benchmark/")."
  echo "Machine: ${cpu:-unknown processor}, $(getconf _NPROCESSORS_ONLN) cores; $compiler; CGAL ${cgal:-?}, Eigen ${eig:-?}, SuiteSparse ${ss:-?}, OpenBLAS $openblas (kernel ${core:-not reported}); single-threaded."
  echo
}

# Replaces the part NAME of doc page PAGE (created with TITLE if missing) by the file BODY.
write_part() { # PAGE NAME TITLE BODY
  local page=doc/$1.md name=$2 title=$3 body=$4
  local begin="<!-- BEGIN GENERATED by benchmark/paper.sh $name: do not edit by hand -->" end='<!-- END GENERATED -->'
  if [[ ! -f $page ]] || ! grep -qF -- "$begin" "$page"; then
    [[ -f $page ]] || printf '# %s\n\nProduced by `benchmark/paper.sh`: do not edit the generated parts by hand.\n' "$title" > "$page"
    printf '\n%s\n%s\n' "$begin" "$end" >> "$page"
  fi
  awk -v b="$begin" -v e="$end" -v body="$body" '
    $0 == b { print; while((getline line < body) > 0) print line; skip = 1; next }
    skip && $0 == e { skip = 0 }
    !skip { print }
  ' "$page" > "$tmp/page.md"
  cp "$tmp/page.md" "$page"
  echo "paper.sh: wrote $page ($name)" >&2
}

runs() { # SIZE SECTION...: paper_runs.py's Markdown
  python3 benchmark/paper_runs.py "$DLF" "$MESHES" "$@"
}

quick_sections=(paper_mode sphere_literal table2 mu modes sphere_starts disk_starts fig10 fig14 fig15_16)
# The quick page is made and checked under OpenBLAS's generic kernel, which
# every x86-64 processor runs: the paper's and the literal flows amplify the
# last bits of a factorization (the same run plateaus at iteration 106 under
# one kernel and 76 under another, a collapse comes a step earlier), so the
# check pins the arithmetic as it pins the threads above.
quick_runs() { OPENBLAS_CORETYPE=Prescott runs quick "${quick_sections[@]}"; }
quick_header() { local core="Prescott, pinned for this page"; header "benchmark/paper_runs.py quick ${quick_sections[*]}"; }

if [[ $quick == 1 ]]; then
  t0=$(date +%s)
  quick_runs > "$tmp/body.md"
  if [[ $check == 1 ]]; then
    begin='<!-- BEGIN GENERATED by benchmark/paper.sh quick: do not edit by hand -->'
    [[ -f doc/paper_quick.md ]] || { echo "paper.sh --check: doc/paper_quick.md is missing" >&2; exit 1; }
    awk -v b="$begin" '$0 == b { on = 1; next } on && $0 == "<!-- END GENERATED -->" { on = 0 } on' doc/paper_quick.md |
      sed -n '/^### /,$p' > "$tmp/page.md" # the header (command, commit, machine) is not compared
    if diff -u "$tmp/page.md" "$tmp/body.md" > "$tmp/diff.txt"; then
      echo "paper.sh --check: doc/paper_quick.md matches the code ($(($(date +%s) - t0)) s)"
      exit 0
    fi
    cat "$tmp/diff.txt"
    echo "paper.sh --check: doc/paper_quick.md is stale: run benchmark/paper.sh --quick" >&2
    exit 1
  fi
  { quick_header; cat "$tmp/body.md"; } > "$tmp/part.md"
  write_part paper_quick quick "The paper's experiments on small meshes: the staleness check" "$tmp/part.md"
  exit 0
fi

# The full run. The older scripts write their own parts; PAPER_HEADER_FILE heads them.
export PAPER_HEADER_FILE=$tmp/header.md
if part literal; then
  header "benchmark/literal.sh" > "$PAPER_HEADER_FILE"
  # literal.sh's own defaults (cap 500, steps 0.1, 0.01, 0.001), which its page's prose reads;
  # the cap of 2000 and the step 1 are in paper_figures.md (part table2).
  DLF=$DLF MESHES=$MESHES benchmark/literal.sh > /dev/null
fi
if part tables; then
  header "benchmark/paper_tables.sh" > "$PAPER_HEADER_FILE"
  BUILD_DIR=$build DATA_DIR=$DATA_DIR benchmark/paper_tables.sh
fi
unset PAPER_HEADER_FILE
if part pictures; then
  DLF=$DLF benchmark/fig10.sh > /dev/null
  DLF=$DLF MESHES=$MESHES benchmark/fig14.sh > /dev/null
  DLF=$DLF MESHES=$MESHES benchmark/fig15_16.sh > /dev/null
fi
if part paper_mode; then
  { header "benchmark/paper_runs.py full paper_mode"; runs full paper_mode; } > "$tmp/part.md"
  write_part paper_mode paper_mode "Paper mode" "$tmp/part.md"
fi
for s in table2 mu modes sphere_starts disk_starts fig10 fig14 fig15_16; do
  if part figures || part "$s"; then
    { header "benchmark/paper_runs.py full $s"; runs full "$s"; } > "$tmp/part.md"
    write_part paper_figures "$s" "The paper's figures and Table 2's variants, with the dlf tool" "$tmp/part.md"
  fi
done
if part sphere; then
  { header "benchmark/sphere_paper.sh"; benchmark/sphere_paper.sh "$DLF" "$MESHES" | sed "s|$root/||g"; echo; } > "$tmp/part.md"
  write_part paper_sphere sphere_paper "The paper's flow on CGAL's closed genus-0 meshes" "$tmp/part.md"
  { header "benchmark/paper_runs.py full sphere_literal"; runs full sphere_literal; } > "$tmp/part.md"
  write_part paper_sphere sphere_literal "The paper's flow on CGAL's closed genus-0 meshes" "$tmp/part.md"
  { header "benchmark/paper_runs.py full sphere_variants"; runs full sphere_variants; } > "$tmp/part.md"
  write_part sphere_paper_mode sphere_variants "The paper mode on the sphere" "$tmp/part.md"
fi
if part quick; then
  quick_runs > "$tmp/body.md"
  { quick_header; cat "$tmp/body.md"; } > "$tmp/part.md"
  write_part paper_quick quick "The paper's experiments on small meshes: the staleness check" "$tmp/part.md"
fi
