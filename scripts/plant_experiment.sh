#!/usr/bin/env bash
# The paper's experiment's published figures: runs bonl_demo (as scripts/demo.sh does) and writes
# docs/results/plant_experiment.json (every MSE and parameter) and plant_experiment_summary.md (the
# README's table), and the sweep (docs/results/sweep.csv, docs/results/sweep.svg, docs/results/sweep_summary.md), then
# splices the tables into README.md and docs/explanation/paper_experiment.md between their markers.
# tests/python/test_published_figures.py recomputes the figures and checks both.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_ensure_deps

step "configure and build bonl_demo (build/demo)"
cmake -S . -B build/demo -G Ninja -DCMAKE_BUILD_TYPE=Release -DBONL_BUILD_TESTS=OFF -DBONL_BUILD_BENCH=OFF
cmake --build build/demo -j2 --target bonl_demo

mkdir -p docs/results
step "run bonl_demo"
./build/demo/examples/demo/bonl_demo --json docs/results/plant_experiment.json \
  --markdown docs/results/plant_experiment_summary.md > /dev/null
bonl_splice_summary plant_experiment_summary docs/results/plant_experiment_summary.md README.md docs/explanation/paper_experiment.md
step "wrote docs/results/plant_experiment.json and plant_experiment_summary.md, updated README.md and docs/explanation/paper_experiment.md"

# The sweep of the pilot hysteresis and the pin backlash: the figure, its data and its table.
step "run bonl_demo --sweep docs/results"
./build/demo/examples/demo/bonl_demo --sweep docs/results --markdown docs/results/sweep_summary.md > /dev/null
bonl_splice_summary sweep_summary docs/results/sweep_summary.md docs/explanation/paper_experiment.md
step "wrote docs/results/sweep.csv, docs/results/sweep.svg and docs/results/sweep_summary.md, updated docs/explanation/paper_experiment.md"

# The same experiment with the joint angle as the output, without and with an integrator (docs/explanation/plant.md).
# Needs `pip install .` (scripts/test.sh makes build/venv).
python=${PYTHON:-build/venv/bin/python}
step "examples/joint_angle/joint_angle.py"
"$python" examples/joint_angle/joint_angle.py --json docs/results/joint_angle.json \
  --markdown docs/results/joint_angle_summary.md > /dev/null
bonl_splice_summary joint_angle_summary docs/results/joint_angle_summary.md docs/explanation/plant.md
step "wrote docs/results/joint_angle.json and joint_angle_summary.md, updated docs/explanation/plant.md"
