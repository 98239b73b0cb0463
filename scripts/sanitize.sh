#!/usr/bin/env bash
# The C++ tests once more under AddressSanitizer + UndefinedBehaviorSanitizer (a separate build in
# build/asan). Any finding stops the test that made it (-fno-sanitize-recover=all) and fails the run.
# Warnings are not errors here: GCC 12's -Wmaybe-uninitialized misfires inside libstdc++ under the
# sanitizers; the main build (scripts/test.sh) keeps -Werror. -Og -g1 (line tables for the reports'
# stack traces) builds in half the time of -O1 -g, and the tests run as fast (docs/lab/performance.md).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_ensure_deps

flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
step "configure (build/asan): ASan + UBSan"
cmake -S . -B build/asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-Og -g1" \
  -DBONL_BUILD_TESTS=ON -DBONL_BUILD_BENCH=OFF -DBONL_BUILD_DEMO=OFF -DBONL_BUILD_EXAMPLES=OFF \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined"

step "build (sanitized)"
cmake --build build/asan -j2

step "ctest under ASan + UBSan"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build/asan --output-on-failure --no-tests=error -j2
