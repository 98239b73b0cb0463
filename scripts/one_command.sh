#!/usr/bin/env bash
# The one command (`python -m bonl identify`, no model, no orders) on every measured data set's
# estimation records, scored by each data set's protocol beside the data-set script's hand-made grids
# and the NARX peer (examples/datasets/one_command.py). Writes docs/results/one_command.json and
# one_command_summary.md, spliced into docs/lab/benchmarks.md. Needs `pip install .` (scripts/test.sh
# makes build/venv) and the data-set scripts' committed results (scripts/datasets.sh); each data set
# takes up to a few minutes on 2 cores. tests/python/test_one_command.py checks the committed figures.
#
#   bash scripts/one_command.sh [--quick]
#
# --quick (the CI's smoke run): the search with a 2-second budget on the estimation records' first samples, into a
# temporary folder; nothing committed is touched and the figures are not judged.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_results_script one_command examples/datasets/one_command.py docs/lab/benchmarks.md "$@"
