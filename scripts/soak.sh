#!/usr/bin/env bash
# The soak figures of docs/lab/reliability.md: the full 1e8-sample soak (tests/soak/soak.cpp) on
# seeds 1 to 25, the output-error method with its defaults (the window refinement on) and its
# recursion alone, two runs at a time (about 80 minutes on two cores). Builds bonl_soak in build/soak (Release, portable),
# writes each run's figures into build/soak/runs, gathers them (tests/soak/report.py) into
# docs/results/soak.json and its table, docs/results/soak_summary.md, and splices the table into
# docs/lab/reliability.md (tests/python/test_published_figures.py checks the copy and the table).
#
#   bash scripts/soak.sh [--quick]
#
# --quick (the CI's smoke run, seconds): seeds 1 and 2 over 200,000 samples (four phases), written
# into a temporary folder and spliced into a copy of the page there: nothing committed is touched
# and the figures are not judged (a failed soak run is recorded, not fatal), but a step that fails
# fails the script.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh
bonl_ensure_deps

samples=100000000 seeds=25 results=docs/results pages=(docs/lab/reliability.md)
case ${1:-} in
  --quick)
    samples=200000 seeds=2
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' EXIT
    results=$tmp pages=("$tmp/reliability.md")
    cp docs/lab/reliability.md "$tmp/" ;;
  "") ;;
  *) echo "usage: bash scripts/soak.sh [--quick]" >&2; exit 2 ;;
esac

step "configure (build/soak)"
cmake -S . -B build/soak -G Ninja -DCMAKE_BUILD_TYPE=Release -DBONL_BUILD_TESTS=ON \
  -DBONL_BUILD_BENCH=OFF -DBONL_BUILD_DEMO=OFF -DBONL_BUILD_EXAMPLES=OFF >/dev/null
step "build bonl_soak"
cmake --build build/soak -j2 --target bonl_soak

runs=build/soak/runs
rm -rf "$runs"
mkdir -p "$runs"
step "run bonl_soak: $seeds seeds x {output_error, output_error --no-window}, $samples samples each, two at a time"
# Each run's exit status is its verdict (1: a check failed), which its JSON records; only a run
# that wrote no JSON stops the script.
# seed_S.json is the recursion alone (--no-window), seed_S_window.json the defaults (the window on),
# the names tests/soak/report.py reads.
run() {  # run SEED defaults|no-window
  local name=seed_$1 flag=(--no-window)
  [[ $2 == defaults ]] && name+=_window flag=()
  build/soak/tests/bonl_soak --samples "$samples" --seed "$1" "${flag[@]}" --json "$runs/$name.json" \
    >"$runs/$name.log" || true
}
export -f run
export samples runs
for seed in $(seq 1 "$seeds"); do echo "$seed defaults $seed no-window"; done | xargs -n 2 -P 2 bash -c 'run "$@"' run

step "gather the runs (tests/soak/report.py)"
python3 tests/soak/report.py --runs "$runs" --json "$results/soak.json" --markdown "$results/soak_summary.md" \
  --command "bash scripts/soak.sh${*:+ $*}"
bonl_splice_summary soak_summary "$results/soak_summary.md" "${pages[@]}"
step "wrote $results/soak.json and $results/soak_summary.md; updated ${pages[*]}"
