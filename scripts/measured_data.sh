#!/usr/bin/env bash
# Issue 6's example on measured data (the hydraulic actuator, the cascaded tanks): builds the C++
# example and runs it; writes the models as JSON, results.json and the simulated outputs into
# out/measured_data. The Python example (examples/measured_data/measured_data.py) runs the same
# procedure and also draws the figures; it needs `pip install .` first. Also writes the chosen
# structures and scores (docs/results/measured_data.json) and the docs' tables (measured_data_summary.md).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_ensure_deps

bonl_build_example bonl_measured_data

mkdir -p out/measured_data
step "run bonl_measured_data"
mkdir -p docs/results
./build/examples/examples/measured_data/bonl_measured_data --out out/measured_data \
  --json out/measured_data/results.json --selection docs/results/measured_data.json \
  --markdown docs/results/measured_data_summary.md "$@"
# The tables, spliced into every page that quotes them; tests/python/test_published_figures.py
# re-identifies the chosen structures and checks the committed figures.
bonl_splice_summary measured_data_summary docs/results/measured_data_summary.md docs/lab/measured_data.md
step "wrote docs/results/measured_data.json and measured_data_summary.md, updated docs/lab/measured_data.md"
