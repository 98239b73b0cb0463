#!/usr/bin/env bash
# Issue 6's example on measured data (the hydraulic actuator, the cascaded tanks): builds the C++
# example and runs it; writes the models as JSON, results.json and the simulated outputs into
# out/measured_data. The Python example (examples/measured_data/measured_data.py) runs the same
# procedure and also draws the figures; it needs `pip install .` first.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_ensure_deps

step "configure (build/examples)"
cmake -S . -B build/examples -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DBONL_BUILD_TESTS=OFF -DBONL_BUILD_BENCH=OFF -DBONL_BUILD_DEMO=OFF -DBONL_BUILD_EXAMPLES=ON

step "build bonl_measured_data"
cmake --build build/examples -j2 --target bonl_measured_data

mkdir -p out/measured_data
step "run bonl_measured_data"
./build/examples/examples/measured_data/bonl_measured_data --out out/measured_data \
  --json out/measured_data/results.json "$@"
