#!/usr/bin/env bash
# The structure search against a grid around the true structure on known systems of every model
# family (examples/search/search_vs_grid.py). Writes docs/results/search_vs_grid.json and
# search_vs_grid_summary.md, spliced into docs/lab/benchmarks.md. Needs `pip install .` (scripts/test.sh
# makes build/venv); about 11 minutes on 2 cores. tests/python/test_search_vs_grid.py checks the
# committed figures.
#
#   bash scripts/search_vs_grid.sh [--quick]
#
# --quick (the CI's smoke run): two systems on short records with a 20-second budget, into a
# temporary folder; nothing committed is touched and the figures are not judged.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_results_script search_vs_grid examples/search/search_vs_grid.py docs/lab/benchmarks.md "$@"
