#!/usr/bin/env bash
# Builds and runs the identification example (examples/identify).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_ensure_deps

step "configure (build/demo)"
cmake -S . -B build/demo -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DBONL_BUILD_TESTS=OFF -DBONL_BUILD_BENCH=OFF -DBONL_BUILD_EXAMPLES=ON

step "build bonl_identify_example"
cmake --build build/demo -j2 --target bonl_identify_example

step "run bonl_identify_example"
./build/demo/examples/identify/bonl_identify_example
