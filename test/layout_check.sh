#!/usr/bin/env bash
# The internal layout (doc/architecture.md): no header directly in
# internal/discrete_lie_flow/, at most 16 headers per folder, the wings
# (disk/, sphere/, volume/, atlas/) include only core/, flow/ and their own folder,
# core/ includes only core/, flow/ only core/ and flow/, and nothing under
# internal/ includes a public parameterizer header (*_3.h); doc/architecture.md
# names every internal header.
#   bash test/layout_check.sh [REPO]
set -euo pipefail
repo="${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}"
dir="$repo/include/CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow"
fail=0
bad() { echo "layout: $*"; fail=1; }

for h in "$dir"/*.h; do [[ -e "$h" ]] && bad "${h#"$repo"/} sits at the top of internal/discrete_lie_flow/: put it in a folder"; done
for folder in "$dir"/*/; do
  n=$(ls "$folder"*.h 2>/dev/null | wc -l)
  (( n <= 16 )) || bad "$(basename "$folder")/ holds $n headers (at most 16)"
done
allowed() {  # folder -> the folders it may include
  case "$1" in
    core) echo "core" ;;
    flow) echo "core flow" ;;
    disk|sphere|volume|atlas) echo "core flow $1" ;;
    *) echo "" ;;
  esac
}
for h in "$dir"/*/*.h; do
  folder=$(basename "$(dirname "$h")")
  ok=$(allowed "$folder")
  [[ -n "$ok" ]] || bad "unknown folder $folder/ (known: core flow disk sphere volume atlas)"
  while IFS= read -r inc; do
    target=${inc#*discrete_lie_flow/}
    tf=${target%%/*}
    [[ " $ok " == *" $tf "* ]] || bad "$folder/$(basename "$h") includes $target: $folder/ may include only $ok"
  done < <(grep -o '#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/[^>]*>' "$h" | sed 's/#include <//; s/>$//')
  if grep -qE '#include <CGAL/Surface_mesh_parameterization/[A-Za-z_]+_3\.h>' "$h"; then
    bad "$folder/$(basename "$h") includes a public parameterizer header: $(grep -oE 'Surface_mesh_parameterization/[A-Za-z_]+_3\.h' "$h" | head -1)"
  fi
done
# doc/architecture.md names every internal header by its folder and name.
arch="$repo/doc/architecture.md"
for h in "$dir"/*/*.h; do
  name=$(basename "$h")
  grep -q "$name" "$arch" || bad "doc/architecture.md does not name $(basename "$(dirname "$h")")/$name"
done
count=$(ls "$dir"/*/*.h | wc -l)
(( fail == 0 )) && echo "layout: $count internal headers in $(ls -d "$dir"/*/ | wc -l) folders, no include between wings"
exit "$fail"
