#!/usr/bin/env bash
# Every Catch2 test case is a ctest test: catch_discover_tests silently drops or splits a test whose
# name holds a ';' or a '[' (CMake's list separator and Catch's tag syntax), so such a test would
# never run under ctest. Compares each tests/cpp/<name>.test.cpp executable's own list with ctest's.
#   scripts/check_test_discovery.sh BUILD_DIR
set -euo pipefail
build=${1:?usage: scripts/check_test_discovery.sh BUILD_DIR}
cd "$(dirname "${BASH_SOURCE[0]}")/.."
registered=$(ctest --test-dir "$build" -N | sed -n 's/^ *Test *#[0-9]*: //p')
missing=0
for source in tests/cpp/*.test.cpp; do
  name=$(basename "$source" .test.cpp)
  exe="$build/tests/bonl_test_$name"
  [[ -x $exe ]] || { echo "check_test_discovery: $exe is not built" >&2; missing=1; continue; }
  while IFS= read -r test; do
    [[ -z $test ]] && continue
    if ! grep -qxF -- "$name/$test" <<<"$registered"; then
      echo "not registered with ctest (rename it without ';' or '['): $name/$test" >&2
      missing=1
    fi
  done < <("$exe" --list-test-names-only)
done
exit $missing
