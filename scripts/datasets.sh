#!/usr/bin/env bash
# Every measured data set in data/ by its SOURCE.md protocol (examples/datasets, one short script
# each, public API only): bonl.select per model family on the estimation data, then the test data.
# Writes docs/results/datasets/<data set>.json and the tables (docs/results/datasets_summary.md),
# spliced into docs/lab/measured_data.md, and the comparison with the literature (docs/lab/benchmarks.md); then the tanks' figures again with the training output
# perturbed in its last digits (docs/results/datasets/perturbation.json and its table).
# Needs `pip install .` (scripts/test.sh makes build/venv). About 15 minutes on 2 cores;
# tests/python/test_datasets.py checks the committed figures.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
python=${PYTHON:-build/venv/bin/python}

scripts=(hydraulic_actuator cascaded_tanks coupled_electric_drives bouc_wen emps silverbox wiener_hammerstein)
results=()
mkdir -p docs/results/datasets
for script in "${scripts[@]}"; do
  step "examples/datasets/$script.py"
  model=()
  # The Wiener-Hammerstein circuit's Wiener-Hammerstein model, also as a model file of its own.
  [[ $script == wiener_hammerstein ]] && model=(--model WienerHammerstein docs/results/datasets/wiener_hammerstein_model.json)
  # The Silverbox's nonlinear-feedback model, likewise.
  [[ $script == silverbox ]] && model=(--model NonlinearFeedback docs/results/datasets/silverbox_model.json)
  # The Bouc-Wen's Bouc-Wen feedback model, likewise.
  [[ $script == bouc_wen ]] && model=(--model BoucWenFeedback docs/results/datasets/bouc_wen_model.json)
  # The EMPS's nonlinear-feedback model with its integrator, likewise.
  [[ $script == emps ]] && model=(--model NonlinearFeedback docs/results/datasets/emps_model.json)
  "$python" "examples/datasets/$script.py" --json "docs/results/datasets/$script.json" "${model[@]}"
  results+=("docs/results/datasets/$script.json")
done
step "examples/datasets/bouc_wen_law.py (the benchmark's own law on its records)"
"$python" examples/datasets/bouc_wen_law.py --json docs/results/datasets/bouc_wen_law.json
"$python" examples/datasets/table.py "${results[@]}" > docs/results/datasets_summary.md
bonl_splice_summary datasets_summary docs/results/datasets_summary.md docs/lab/measured_data.md
"$python" examples/datasets/comparison.py > docs/results/benchmarks_summary.md
bonl_splice_summary benchmarks_summary docs/results/benchmarks_summary.md docs/lab/benchmarks.md
step "examples/datasets/perturbation.py --select (the tanks with 1e-9 V more on the training output)"
"$python" examples/datasets/perturbation.py --select --json docs/results/datasets/perturbation.json \
  --table docs/results/perturbation_summary.md
bonl_splice_summary perturbation_summary docs/results/perturbation_summary.md docs/lab/measured_data.md
step "wrote docs/results/datasets/*.json, datasets_summary.md and benchmarks_summary.md, updated docs/lab/measured_data.md and docs/lab/benchmarks.md"
