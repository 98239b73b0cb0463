#!/usr/bin/env bash
# The tracking experiment's published figures (docs/how-to/control.md, "Tracking on the plant"): runs
# bonl_demo --control and writes docs/results/tracking.json (every tracking RMS) and
# tracking_summary.md (the tables), splices the tables into docs/how-to/control.md between their
# markers, and draws docs/results/tracking.png with `python -m bonl control` (needs the package
# installed: pip install .). tests/python/test_published_figures.py recomputes the figures and checks them.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/deps.sh

mkdir -p docs/results
bash scripts/demo.sh --control --json docs/results/tracking.json --markdown docs/results/tracking_summary.md
bonl_splice_summary tracking_summary docs/results/tracking_summary.md docs/how-to/control.md
python=${PYTHON:-build/venv/bin/python}
step "draw docs/results/tracking.png ($python -m bonl control)"
"$python" -m bonl control --figure docs/results/tracking.png > /dev/null
step "wrote docs/results/tracking.json, tracking_summary.md and tracking.png, updated docs/how-to/control.md"
