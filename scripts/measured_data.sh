#!/usr/bin/env bash
# Issue 6's example on measured data (the hydraulic actuator, the cascaded tanks): builds the C++
# example and runs it; writes the models as JSON, results.json and the simulated outputs into
# out/measured_data. The Python example (examples/measured_data/measured_data.py) runs the same
# procedure and also draws the figures; it needs `pip install .` first.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_ensure_deps

bonl_build_example bonl_measured_data

mkdir -p out/measured_data
step "run bonl_measured_data"
./build/examples/examples/measured_data/bonl_measured_data --out out/measured_data \
  --json out/measured_data/results.json "$@"
