#!/usr/bin/env bash
# The C++ tests once more, built by clang-14 under AddressSanitizer + UndefinedBehaviorSanitizer
# (build/asan), warnings as errors, and run with ctest. Any finding stops the test that made it
# (-fno-sanitize-recover=all) and fails the run.
#
# One build for two checks: the main build (scripts/test.sh) is GCC's, and the two compilers warn
# about different things (hence clang's -Wall -Wextra -Wpedantic -Werror here), and the sanitizers
# find what no test asserts. A separate clang Release build checked nothing this one does not: the
# warnings are the front end's, whatever the optimisation level, and without -ffast-math clang
# rounds at -O1 as at -O3. -O1 -g1 (line tables for the reports' stack traces): the tests run
# several times slower at -O0, where Eigen is not optimised (docs/lab/performance.md, "The CI's
# build time").
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_ensure_deps
bonl_ensure_packages "${BONL_CLANG_APT_PACKAGES[@]}"

flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
# A build/asan configured with another compiler (GCC's, before this build was clang's) starts over:
# CMake would delete its cache on the compiler's change and configure anew without this script's
# options.
if [[ -f build/asan/CMakeCache.txt ]] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++-14$' build/asan/CMakeCache.txt; then
  rm -rf build/asan
fi
step "configure (build/asan): clang-14, ASan + UBSan, warnings as errors"
cmake -S . -B build/asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
  -DBONL_BUILD_TESTS=ON -DBONL_BUILD_BENCH=OFF -DBONL_BUILD_DEMO=OFF -DBONL_BUILD_EXAMPLES=OFF \
  -DBONL_WARNINGS_AS_ERRORS=ON \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined"

step "build (clang, sanitized)"
cmake --build build/asan -j2

step "ctest under ASan + UBSan (clang)"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build/asan --output-on-failure --no-tests=error -j2
