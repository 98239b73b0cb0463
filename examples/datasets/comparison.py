"""bonl against the literature on every measured data set (docs/lab/benchmarks.md). For each data set and
each test its script compares (``COMPARISONS``):

- bonl's figure: the model ``bonl.select`` would pick across every model family on the estimation data
  alone (the family whose chosen structure scores best on the held-out part of the estimation data,
  ``check_rms`` in the results file), never the best test figure;
- bonl's own linear model (the ARX family, estimated by output error and selected the same way), so
  that a nonlinear model that does not beat linear shows at a glance;
- the best published result and the best published block-oriented one (from the data set's
  SOURCE.md or the issue that cites it), and the ratios; and which protocol the row follows.

    python examples/datasets/comparison.py > docs/results/benchmarks_summary.md

scripts/datasets.sh writes it after the results files; tests/python/test_datasets.py checks it."""

from __future__ import annotations

import argparse
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
    """The published figures a data set's bonl result is put beside, on one of its tests."""

    test: str  #: the test (of the script's) whose protocol the published figures follow
    protocol: str  #: which protocol (and version) the test follows
    best: Optional[Tuple[str, float]] = None  #: (who, test RMS): the best published result
    block_oriented: Optional[Tuple[str, float]] = None  #: the best published block-oriented result
    note: str = ""  #: how far the best published figure can be trusted, where it matters


def selected(results: dict) -> dict:
    """The row ``bonl.select`` would pick across every family: the best held-out estimation score."""
    return min(results["rows"], key=lambda r: r["check_rms"])


def linear(results: dict) -> dict:
    """bonl's own linear model: the ARX family's row."""
    return next(r for r in results["rows"] if r["model"] == "ARX")


def _figure(value: float) -> str:
    return f"{value:.3g}"


def rows(script: str, results_dir: pathlib.Path = RESULTS) -> list:
    """One data set's lines of the table, one per compared test, from its results file in ``results_dir``."""
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
    comparisons = importlib.import_module(script).COMPARISONS
    results = json.loads((results_dir / f"{script}.json").read_text())
    chosen, baseline = selected(results), linear(results)
    lines = []
    for comparison in comparisons:
        ours = chosen["test_rms"][comparison.test]
        ours_linear = baseline["test_rms"][comparison.test]
        cells = [f"{results['data_set']} ({comparison.test}; {results['unit']})", comparison.protocol,
                 f"{_figure(ours)} ({chosen['model']})", _figure(ours_linear), f"{ours / ours_linear:.3g}"]
        for published, note in ((comparison.best, comparison.note), (comparison.block_oriented, "")):
            if published is None:
                cells += ["none in SOURCE.md", ""]
            else:
                who = published[0] + (f"; {note}" if note else "")
                cells += [f"{_figure(published[1])} ({who})", f"{ours / published[1]:.3g}"]
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def table(results_dir: pathlib.Path = RESULTS) -> str:
    lines = ["| data set (test; unit) | protocol | bonl, selected on the estimation data (model) | bonl's linear model "
             "(ARX) | bonl / linear | best published | bonl / best | best published block-oriented | "
             "bonl / block-oriented |",
             "|---|---|---|---:|---:|---|---:|---|---:|"]
    return "\n".join(lines + [line for script in SCRIPTS for line in rows(script, results_dir)])


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", type=pathlib.Path, default=RESULTS,
                        help="the folder of the results files (default: docs/results/datasets)")
    print(table(parser.parse_args().results))
