#!/usr/bin/env bash
# The online estimator's accuracy figures (docs/results/online_accuracy.json and .md): builds
# bonl_online_accuracy and runs it over the known systems of tests/data/online_systems.json (about
# two minutes on two cores). ctest checks a quick part of the committed results
# (examples/online_accuracy_quick); re-run this and commit both files when the estimator changes.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_ensure_deps

bonl_build_example bonl_online_accuracy

mkdir -p docs/results
step "run bonl_online_accuracy"
./build/examples/examples/online_accuracy/bonl_online_accuracy \
  --json docs/results/online_accuracy.json --markdown docs/results/online_accuracy.md "$@"
step "wrote docs/results/online_accuracy.json and docs/results/online_accuracy.md"

# The summary table, spliced into every page that quotes it.
bonl_splice_summary online_accuracy_summary docs/results/online_accuracy_summary.md docs/explanation/estimation_methods.md docs/explanation/algorithm.md
step "updated the summary in docs/explanation/estimation_methods.md and docs/explanation/algorithm.md"
