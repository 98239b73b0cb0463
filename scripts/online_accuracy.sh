#!/usr/bin/env bash
# The online estimator's accuracy figures (docs/results/online_accuracy.json and .md): builds
# bonl_online_accuracy and runs it over the known systems of tests/data/online_systems.json (about
# two minutes on two cores). ctest checks a quick part of the committed results
# (examples/online_accuracy_quick); re-run this and commit both files when the estimator changes.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_ensure_deps

step "configure (build/examples)"
cmake -S . -B build/examples -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DBONL_BUILD_TESTS=OFF -DBONL_BUILD_BENCH=OFF -DBONL_BUILD_DEMO=OFF -DBONL_BUILD_EXAMPLES=ON

step "build bonl_online_accuracy"
cmake --build build/examples -j2 --target bonl_online_accuracy

mkdir -p docs/results
step "run bonl_online_accuracy"
./build/examples/examples/online_accuracy/bonl_online_accuracy \
  --json docs/results/online_accuracy.json --markdown docs/results/online_accuracy.md "$@"
step "wrote docs/results/online_accuracy.json and docs/results/online_accuracy.md"

# The summary table, spliced into every page that quotes it (between the online_accuracy_summary
# markers); tests/python/test_published_figures.py checks that the copies match.
for page in README.md docs/algorithm.md; do
  awk -v summary=docs/results/online_accuracy_summary.md '
    /<!-- online_accuracy_summary: begin/ { print; while ((getline line < summary) > 0) print line; skip = 1; next }
    /<!-- online_accuracy_summary: end/ { skip = 0 }
    !skip { print }' "$page" > "$page.tmp" && mv "$page.tmp" "$page"
done
step "updated the summary in README.md and docs/algorithm.md"
