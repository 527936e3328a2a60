#!/usr/bin/env bash
# Builds the target dlf_wrong_bindings (test/tools/wrong_bindings.cpp), which
# must fail with exactly the package's readable static_asserts, one per
# wrong use, and no other compiler error.
#   static_assert_messages.sh CMAKE BUILD_DIR
set -uo pipefail
cmake=$1 build=$2
if log=$("$cmake" --build "$build" --target dlf_wrong_bindings 2>&1); then
  echo "FAIL: the wrong uses compiled"; exit 1
fi
fail=0
for message in \
  "X must be a CGAL border parameterizer" \
  "uvmap must map vertex_descriptor to Point_2" \
  "vimap must map vertex_descriptor to an integer index" \
  "places no orbifold cones"; do
  grep -q "static.assert.*$message" <<< "$log" || { echo "FAIL: no static_assert '$message'"; fail=1; }
done
errors=$(grep -c "error:" <<< "$log")
[[ $errors == 4 ]] || { echo "FAIL: $errors compiler errors, want the 4 static_asserts only"; fail=1; }
if [[ $fail == 0 ]]; then echo "4 wrong uses, 4 one-line static_asserts"; else grep "error:" <<< "$log" | head -20; fi
exit $fail
