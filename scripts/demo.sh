#!/usr/bin/env bash
# The main job: builds bonl_demo and runs the paper's experiment on the simulated excavator arm.
# Extra arguments go to bonl_demo (e.g. --json out.json --csv out.csv, or --sweep DIR).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_ensure_deps

step "configure (build/demo)"
cmake -S . -B build/demo -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DBONL_BUILD_TESTS=OFF -DBONL_BUILD_BENCH=OFF -DBONL_BUILD_EXAMPLES=OFF

step "build bonl_demo"
cmake --build build/demo -j2 --target bonl_demo

step "run bonl_demo $*"
./build/demo/examples/demo/bonl_demo "$@"
