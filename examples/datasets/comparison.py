"""bonl against the literature on every measured data set (docs/benchmarks.md): for each data set,
bonl's best test RMS by the data set's protocol (the best of the model families, from its committed
results file, docs/results/datasets/<script>.json), the best published result and the best published
block-oriented result beside it (each script's ``COMPARISON``, from the data set's SOURCE.md or the
issue that cites it), and the ratios.

    python examples/datasets/comparison.py > docs/results/benchmarks_summary.md

scripts/datasets.sh writes it after the results files; tests/python/test_datasets.py checks it."""

from __future__ import annotations

import dataclasses
import importlib
import json
import pathlib
import sys
from typing import Optional, Tuple

ROOT = pathlib.Path(__file__).resolve().parents[2]
RESULTS = ROOT / "docs" / "results" / "datasets"
#: The data-set scripts, in the order of the table.
SCRIPTS = ["wiener_hammerstein", "silverbox", "bouc_wen", "cascaded_tanks", "emps", "hydraulic_actuator",
           "coupled_electric_drives"]


@dataclasses.dataclass(frozen=True)
class Comparison:
    """The published figures a data set's bonl result is put beside."""

    test: str  #: the test (of the script's) whose protocol the published figures follow
    best: Optional[Tuple[str, float]] = None  #: (who, test RMS): the best published result
    block_oriented: Optional[Tuple[str, float]] = None  #: the best published block-oriented result
    note: str = ""  #: how far the best published figure can be trusted, where it matters


def _figure(value: float) -> str:
    return f"{value:.3g}"


def row(script: str) -> str:
    """One data set's line of the table."""
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
    comparison = importlib.import_module(script).COMPARISON
    results = json.loads((RESULTS / f"{script}.json").read_text())
    best = min(results["rows"], key=lambda r: r["test_rms"][comparison.test])
    ours = best["test_rms"][comparison.test]
    cells = [f"{results['data_set']} ({comparison.test}; {results['unit']})",
             f"{_figure(ours)} ({best['model']})"]
    for published, note in ((comparison.best, comparison.note), (comparison.block_oriented, "")):
        if published is None:
            cells += ["none in SOURCE.md", ""]
        else:
            who = published[0] + (f"; {note}" if note else "")
            cells += [f"{_figure(published[1])} ({who})", f"{ours / published[1]:.3g}"]
    return "| " + " | ".join(cells) + " |"


def table() -> str:
    lines = ["| data set (test; unit) | bonl's best (model) | best published | bonl / best | "
             "best published block-oriented | bonl / block-oriented |",
             "|---|---|---|---:|---|---:|"]
    return "\n".join(lines + [row(script) for script in SCRIPTS])


if __name__ == "__main__":
    print(table())
