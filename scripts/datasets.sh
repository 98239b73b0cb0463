#!/usr/bin/env bash
# Every measured data set in data/ by its SOURCE.md protocol (examples/datasets, one short script
# each, public API only): bonl.select per model family on the estimation data, then the test data.
# Writes docs/results/datasets/<data set>.json and the tables (docs/results/datasets_summary.md),
# spliced into docs/lab/measured_data.md, and the comparison with the literature (docs/lab/benchmarks.md); then the tanks' figures again with the training output
# perturbed in its last digits (docs/results/datasets/perturbation.json and its table).
# Needs `pip install .` (scripts/test.sh makes build/venv). About 15 minutes on 2 cores;
# tests/python/test_datasets.py checks the committed figures.
#
#   bash scripts/datasets.sh [--quick]
#
# --quick (the CI's smoke run, seconds): every step below, the same lines, on cheap inputs
# (one candidate per model family on the estimation records' first samples, examples/datasets/
# benchmark.py's quick; the Bouc-Wen law over a short stretch; two perturbation seeds), writing into a
# temporary folder and splicing into copies of the pages there: nothing committed is touched and
# the figures are not judged, but a step that fails fails the script.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
python=${PYTHON:-build/venv/bin/python}

quick=()
results=docs/results summaries=docs/results pages=docs/lab
case ${1:-} in
  --quick)
    quick=(--quick)
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    results=$tmp/results summaries=$tmp pages=$tmp/lab
    mkdir -p "$pages"
    cp docs/lab/measured_data.md docs/lab/benchmarks.md "$pages/" ;;
  "") ;;
  *) echo "usage: bash scripts/datasets.sh [--quick]" >&2; exit 2 ;;
esac
out=$results/datasets

scripts=(hydraulic_actuator cascaded_tanks coupled_electric_drives bouc_wen emps silverbox wiener_hammerstein)
files=()
mkdir -p "$out"
for script in "${scripts[@]}"; do
  step "examples/datasets/$script.py ${quick[*]}"
  model=()
  # The Wiener-Hammerstein circuit's Wiener-Hammerstein model, also as a model file of its own.
  [[ $script == wiener_hammerstein ]] && model=(--model WienerHammerstein "$out/wiener_hammerstein_model.json")
  # The Silverbox's nonlinear-feedback model, likewise.
  [[ $script == silverbox ]] && model=(--model NonlinearFeedback "$out/silverbox_model.json")
  # The Bouc-Wen's Bouc-Wen feedback model, likewise.
  [[ $script == bouc_wen ]] && model=(--model BoucWenFeedback "$out/bouc_wen_model.json")
  # The EMPS's nonlinear-feedback model with its integrator, likewise.
  [[ $script == emps ]] && model=(--model NonlinearFeedback "$out/emps_model.json")
  "$python" "examples/datasets/$script.py" --json "$out/$script.json" "${model[@]}" "${quick[@]}"
  files+=("$out/$script.json")
done
step "examples/datasets/bouc_wen_law.py ${quick[*]} (the benchmark's own law on its records)"
"$python" examples/datasets/bouc_wen_law.py --json "$out/bouc_wen_law.json" "${quick[@]}"
"$python" examples/datasets/table.py "${files[@]}" > "$summaries/datasets_summary.md"
bonl_splice_summary datasets_summary "$summaries/datasets_summary.md" "$pages/measured_data.md"
"$python" examples/datasets/comparison.py --results "$out" > "$summaries/benchmarks_summary.md"
bonl_splice_summary benchmarks_summary "$summaries/benchmarks_summary.md" "$pages/benchmarks.md"
step "examples/datasets/perturbation.py --select ${quick[*]} (the tanks with 1e-9 V more on the training output)"
"$python" examples/datasets/perturbation.py --select --json "$out/perturbation.json" \
  --table "$summaries/perturbation_summary.md" --results "$out" "${quick[@]}"
bonl_splice_summary perturbation_summary "$summaries/perturbation_summary.md" "$pages/measured_data.md"
if ((${#quick[@]} > 0)); then
  # Each splice must have put its table into the page's copy: a page without the markers is left as
  # it was, without a word (the quick tables differ from the committed ones the copies hold).
  for pair in datasets_summary:measured_data benchmarks_summary:benchmarks perturbation_summary:measured_data; do
    "$python" -c 'import sys; sys.exit(open(sys.argv[1]).read() not in open(sys.argv[2]).read())' \
      "$summaries/${pair%%:*}.md" "$pages/${pair#*:}.md" ||
      { echo "datasets.sh: ${pair%%:*}.md was not spliced into ${pair#*:}.md" >&2; exit 1; }
  done
  step "quick run passed (results in a temporary folder, removed; nothing committed written)"
else
  step "wrote docs/results/datasets/*.json, datasets_summary.md and benchmarks_summary.md, updated docs/lab/measured_data.md and docs/lab/benchmarks.md"
fi
