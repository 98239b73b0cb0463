#!/usr/bin/env bash
# The C++ tests built with clang-14 (build/clang, Release, -Wall -Wextra -Wpedantic -Werror) and run
# with ctest: the main build (scripts/test.sh) is GCC's, and the two compilers warn about different
# things and may round differently.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_ensure_deps
bonl_ensure_packages "${BONL_CLANG_APT_PACKAGES[@]}"

step "configure (build/clang): clang-14"
cmake -S . -B build/clang -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=clang++-14 \
  -DBONL_BUILD_TESTS=ON -DBONL_BUILD_BENCH=OFF -DBONL_BUILD_DEMO=OFF -DBONL_BUILD_EXAMPLES=OFF \
  -DBONL_WARNINGS_AS_ERRORS=ON

step "build (clang)"
cmake --build build/clang -j2

step "ctest (clang)"
ctest --test-dir build/clang --output-on-failure --no-tests=error -j2
