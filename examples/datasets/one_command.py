"""The one command on every measured data set: ``python -m bonl identify`` with no model and no orders
(the structure search, ``bonl.search``; ``VARIANTS``: as it comes), on each data set's estimation records (written as CSV files, one per
record, with the tests' state-initialisation window as ``--window``), its chosen model scored on the
data set's tests by the data set's own protocol (``benchmark.Test.rms``), beside the figure of the
data-set script's hand-made grids (the family it selects on the estimation data,
``comparison.selected``) and the NARX peer's (``narx_peer.json``). The command never sees a test
record.

    python examples/datasets/one_command.py [--json FILE] [--markdown FILE] [--quick]

--quick (the CI's smoke run): the estimation records' first samples and a search budget of
QUICK_BUDGET seconds, so that the plumbing cannot rot; its figures are not judged.
scripts/one_command.sh writes docs/results/one_command.json and one_command_summary.md;
tests/python/test_one_command.py checks them.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import json
import pathlib
import sys
import tempfile
import time
import warnings

import numpy as np

import bonl
from bonl.__main__ import main as bonl_main

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import benchmark  # noqa: E402
import comparison  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
#: The NARX peer's test figures on the same protocols (SysIdentPy 0.9, as the project's issue tracker
#: reports them; "diverged" where it did).
NARX_PEER = pathlib.Path(__file__).resolve().parent / "narx_peer.json"


def _write_csv(path: pathlib.Path, u: np.ndarray, y: np.ndarray) -> pathlib.Path:
    np.savetxt(path, np.column_stack([u, y]), delimiter=",", header="u,y", comments="", fmt="%.17g")
    return path


#: The command's variants by name: their extra arguments (the default: none).
VARIANTS = {"default": []}
#: --quick: the search's budget (seconds), which its sweep and growth stop at.
QUICK_BUDGET = 2


def _command(made: benchmark.Benchmark, variant: str, quick: bool) -> dict:
    """One variant of the command on the data set's estimation records: its model, scored on the tests."""
    with tempfile.TemporaryDirectory() as folder:
        folder = pathlib.Path(folder)
        files = [str(_write_csv(folder / f"estimation_{i}.csv", u, y)) for i, (u, y) in enumerate(made.estimation)]
        arguments = ["identify", *files, "--input", "u", "--output", "y", "--window", str(made.window),
                     "--out", str(folder / "model.json"), "--scores", str(folder / "scores.json"), "--no-progress"]
        arguments += VARIANTS[variant]
        if quick:  # the smoke run: the search cut short
            arguments += ["--budget", str(QUICK_BUDGET)]
        start = time.perf_counter()
        with contextlib.redirect_stdout(io.StringIO()):
            status = bonl_main(arguments)
        seconds = time.perf_counter() - start
        if status != 0:
            raise RuntimeError(f"{made.name}: bonl identify {' '.join(VARIANTS[variant])} exited with {status}")
        model = bonl.load_model((folder / "model.json").read_text())
        scores = json.loads((folder / "scores.json").read_text())
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bonl.ExtrapolationWarning)
        figures = {test.name: _number(test.rms(model)) for test in made.tests}
    print(f"{made.name}, {variant}: {type(model).__name__} {bonl.named_orders(model)}: "
          + ", ".join(f"{name} {_figure(value)}" for name, value in figures.items()) + f" ({seconds:.0f} s)",
          flush=True)
    return {"model": type(model).__name__, "orders": bonl.named_orders(model),
            "identify": scores["identify"],
            "search": [{k: stage[k] for k in ("name", "choice")} for stage in scores.get("search", [])],
            "candidates": scores["candidates"],
            "refused": sum(1 for row in scores["ranking"] if "error" in row), "seconds": round(seconds, 1),
            "test_rms": figures, "json": json.loads(model.to_json())}


def run_one(script: str, quick: bool) -> dict:
    """Both variants of the command on one data set, beside the script's and the peer's figures."""
    made = __import__(script).make()
    if quick:
        made = benchmark.quick(made)
    script_results = json.loads((comparison.RESULTS / f"{script}.json").read_text())
    peer = json.loads(NARX_PEER.read_text())["data_sets"].get(script, {})
    return {"data_set": made.name, "script": script, "unit": made.unit, "window": made.window,
            "commands": {variant: _command(made, variant, quick) for variant in VARIANTS},
            "script_test_rms": {test.name: comparison.selected(script_results)["test_rms"][test.name]
                                for test in made.tests},
            "narx_peer": {test.name: peer.get(test.name) for test in made.tests}}


def _number(value: float):
    """A figure for the JSON file: the number, or "diverged" (JSON has no infinity)."""
    return value if np.isfinite(value) else "diverged"


def _figure(value) -> str:
    """A test RMS: None (no figure) as "-"; a diverged run as "diverged"."""
    if value is None:
        return "-"
    if value == "diverged" or not np.isfinite(value):
        return "diverged"
    return f"{value:.3g}"


def _ratio(value, reference) -> str:
    both = all(isinstance(v, float) for v in (value, reference))
    return f"{value / reference:.3g}" if both else "-"


def markdown(results: dict) -> str:
    """The table: per data set and test, each variant's figure (its chosen model) and its ratio to the
    script's figure, the script's and the peer's figures, and each variant's seconds."""
    header = ["data set (test; unit)"]
    for variant in VARIANTS:
        header += [f"the command, {variant} (chosen model)", "/ script"]
    header += ["the data-set script", "NARX peer", "seconds (" + ", ".join(VARIANTS) + ")"]
    lines = ["| " + " | ".join(header) + " |", "|---|" + "---|---:|" * len(VARIANTS) + "---:|---:|---:|"]
    for data_set in results["data_sets"]:
        for name, script in data_set["script_test_rms"].items():
            cells = [f"{data_set['data_set']} ({name}; {data_set['unit']})"]
            for variant in VARIANTS:
                command = data_set["commands"][variant]
                cells += [f"{_figure(command['test_rms'][name])} ({command['model']})",
                          _ratio(command["test_rms"][name], script)]
            cells += [_figure(script), _figure(data_set["narx_peer"][name]),
                      ", ".join(f"{data_set['commands'][v]['seconds']:.0f}" for v in VARIANTS)]
            lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", type=pathlib.Path, help="write the results here")
    parser.add_argument("--markdown", type=pathlib.Path, help="write the table here")
    parser.add_argument("--quick", action="store_true",
                        help="a smoke run: the search with a short budget on the first samples")
    args = parser.parse_args()
    results = {"quick": args.quick, "data_sets": [run_one(script, args.quick) for script in comparison.SCRIPTS]}
    if args.json:
        args.json.write_text(json.dumps(results, indent=1) + "\n")
    if args.markdown:
        args.markdown.write_text(markdown(results))


if __name__ == "__main__":
    main()
