#!/usr/bin/env bash
# The structure search against a grid around the true structure on known systems of every model
# family (examples/search/search_vs_grid.py). Writes docs/results/search_vs_grid.json and
# search_vs_grid_summary.md, spliced into docs/lab/benchmarks.md. Needs `pip install .` (scripts/test.sh
# makes build/venv); about 15 minutes on 2 cores. tests/python/test_search_vs_grid.py checks the
# committed figures.
#
#   bash scripts/search_vs_grid.sh [--quick]
#
# --quick (the CI's smoke run): two systems on short records with a 20-second budget, into a
# temporary folder; nothing committed is touched and the figures are not judged.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
python=${PYTHON:-build/venv/bin/python}

quick=()
results=docs/results page=docs/lab/benchmarks.md
case ${1:-} in
  --quick)
    quick=(--quick)
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    results=$tmp
    cp docs/lab/benchmarks.md "$tmp/benchmarks.md"
    page=$tmp/benchmarks.md ;;
  "") ;;
  *) echo "usage: bash scripts/search_vs_grid.sh [--quick]" >&2; exit 2 ;;
esac

step "examples/search/search_vs_grid.py ${quick[*]}"
"$python" examples/search/search_vs_grid.py --json "$results/search_vs_grid.json" \
  --markdown "$results/search_vs_grid_summary.md" "${quick[@]}"
bonl_splice_summary search_vs_grid_summary "$results/search_vs_grid_summary.md" "$page"
"$python" -c 'import sys; sys.exit(open(sys.argv[1]).read() not in open(sys.argv[2]).read())' \
  "$results/search_vs_grid_summary.md" "$page" ||
  { echo "search_vs_grid.sh: the table was not spliced into $page" >&2; exit 1; }
step "wrote $results/search_vs_grid.json and search_vs_grid_summary.md, updated $page"
