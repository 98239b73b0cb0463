"""The ``bonl identify`` and ``bonl simulate`` commands: from a data file to a model file and back.

``bonl identify DATA.csv [MORE.csv ...] --input COL --output COL --out MODEL.json`` finds a model on
the files' records and writes it as a model file. How:

- neither ``--model`` nor ``--orders``: the structure search, :func:`bonl.search` (the delay, the
  operating point, an integrator and the linear orders from the data, then every family seeded there,
  its nonlinearity swept and the best grown, scored on held-out data), within ``--budget`` seconds;
  every stage's choice is printed and saved;
- ``--model NAME --orders na=2 nb=1 ...``: :func:`bonl.select` over that family at those orders (their
  held-out last quarters score the candidates); an order given as a list (``na=1,2,3``) makes a grid,
  an order not given takes :data:`DEFAULT_GRID`'s values;
- ``--model NAME`` alone: that family over :data:`DEFAULT_GRID`.

Several data files are several records (experiments) of one system, identified together. Beside the
chosen model it always prints a linear (ARX) model's figures (the search's linear stage, or an ARX
selection on the same data), so a nonlinear model that does not beat a linear one shows. It prints the
ranking's first rows (``--scores`` writes every candidate's, with why a candidate failed or was
refused: a model whose free run is not bounded is never chosen, :func:`bonl.select`). Test records, never seen by the selection: ``--test FILE``
(the same columns), or ``--test-from K``, the samples from K on of a single data file (the whole
record simulated from rest). ``--window N`` scores the held-out parts and the test records after a
state-initialisation window of N samples, as benchmarks do. The stages go to standard error, with a
progress bar on a terminal.

``bonl simulate MODEL.json DATA.csv --input COL --out SIMULATED.csv`` writes a model's free run.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import pathlib
import sys
import warnings
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np

from . import _bonl
from ._bonl import metrics as _metrics
from .data_file import read_columns, write_columns
from .report import plot_fit, summary
from .selection import grid, named_orders, select
from .structure_search import OPERATING_POINTS, search

__all__ = ["DEFAULT_GRID", "candidates", "identify_arguments", "identify_run", "simulate_arguments", "simulate_run"]

#: With --model, the orders tried where --orders gives none, by name; each family takes the ones it has
#: (an order not named here takes its value at the model's PAPER_ORDERS).
#: Small orders, so that a family's grid runs in seconds on a few thousand samples.
DEFAULT_GRID: Dict[str, List[int]] = {
    "na": [1, 2, 3], "nb": [1, 2], "nk": [0, 1], "r": [3], "r1": [3], "ni": [0],
    "na1": [1, 2], "nb1": [1], "na2": [1, 2], "nb2": [1], "nh": [0], "nd": [1, 2], "nv": [0],
}


def _default_orders(model_class: type) -> Dict[str, List[int]]:
    """DEFAULT_GRID's values of the orders ``model_class`` has; an order it does not name takes the
    model's value at the paper's orders (``PAPER_ORDERS``: its default, or its minimum where the paper
    has none, as the plays' count np, 0 or 1 by model), so that a model's new order needs no entry."""
    paper = dict(zip(model_class.ORDERS, model_class.PAPER_ORDERS))
    return {name: DEFAULT_GRID.get(name, [paper[name]]) for name in model_class.ORDERS}


def _model_class(name: str) -> type:
    for model_class in _bonl.MODELS:
        if model_class.__name__ == name:
            return model_class
    raise ValueError(f"bonl identify: no model {name!r}; the models are "
                     + ", ".join(m.__name__ for m in _bonl.MODELS))


def _parse_orders(items: Sequence[str]) -> Dict[str, List[int]]:
    """``["na=2", "nb=1,2"]`` as ``{"na": [2], "nb": [1, 2]}``."""
    orders: Dict[str, List[int]] = {}
    for item in items:
        name, equals, values = item.partition("=")
        try:
            if not equals or not name:
                raise ValueError
            orders[name.strip()] = [int(v) for v in values.split(",")]
        except ValueError:
            raise ValueError(f"bonl identify: --orders takes NAME=VALUE or NAME=V1,V2,... (integers), got {item!r}") \
                from None
    return orders


def candidates(model: Optional[str] = None, orders: Optional[Dict[str, List[int]]] = None) -> List[Any]:
    """The structures ``bonl identify`` selects among.

    Parameters
    ----------
    model : str, optional
        A model class's name (one of ``bonl.MODELS``); None: every family (the command without
        --model runs :func:`bonl.search` instead of this grid).
    orders : dict of str to list of int, optional
        Orders by name, each one value or several; with ``model`` only. Orders not given take
        :data:`DEFAULT_GRID`'s values.

    Returns
    -------
    list
        The structures, for :func:`bonl.select`.

    Raises
    ------
    ValueError
        An unknown model, an order the model does not have, or orders without a model.
    """
    orders = dict(orders or {})
    if model is None:
        if orders:
            raise ValueError("bonl identify: --orders needs --model (which family the orders are of)")
        return [structure for model_class in _bonl.MODELS for structure in grid(model_class, **_default_orders(model_class))]
    model_class = _model_class(model)
    unknown = sorted(set(orders) - set(model_class.ORDERS))
    if unknown:
        raise ValueError(f"bonl identify: {model} has no order {', '.join(unknown)}; its orders are "
                         + ", ".join(model_class.ORDERS))
    return grid(model_class, **{**_default_orders(model_class), **orders})


def identify_arguments(parser: argparse.ArgumentParser) -> None:
    """The ``identify`` subcommand's arguments."""
    parser.add_argument("data", nargs="+",
                        help="the data file(s) identified on: one sample per row, the first row optionally the "
                             "columns' names; several files are several records (experiments) of one system")
    parser.add_argument("--input", required=True, help="the input's column: its name, or its 0-based position")
    parser.add_argument("--output", required=True, help="the output's column")
    parser.add_argument("--out", required=True, type=pathlib.Path, help="write the chosen model's file here (JSON)")
    parser.add_argument("--model", help="the family (" + ", ".join(m.__name__ for m in _bonl.MODELS)
                        + "); default: the structure search over every family (bonl.search)")
    parser.add_argument("--orders", nargs="+", default=[], metavar="NAME=VALUES",
                        help="orders of --model, each one value or a comma-separated list (a grid), "
                             "e.g. na=2 nb=1,2 nk=0; the others take the default grid's")
    parser.add_argument("--test", action="append", default=[], type=pathlib.Path, metavar="FILE",
                        help="a test record, never seen by the selection, scored after the choice (the same "
                             "columns); may be given several times")
    parser.add_argument("--test-from", type=int, metavar="K",
                        help="one data file only: keep its samples K on (0-based) out of the selection and score "
                             "them as a test")
    parser.add_argument("--window", type=int, default=0, metavar="N",
                        help="the state-initialisation window: the held-out parts and the test records are "
                             "simulated after their first N samples, which set the model's state, and scored "
                             "after them (default 0: simulated from rest)")
    parser.add_argument("--validation-fraction", type=float, default=0.25,
                        help="the last part of each record identified on that scores the candidates (default 0.25)")
    parser.add_argument("--operating-point", choices=OPERATING_POINTS,
                        help="where the model's blocks are centred: at zero, at the first sample, at the data's "
                             "means; default: the search chooses on held-out data (zero with --model)")
    parser.add_argument("--budget", type=float, default=420.0, metavar="SECONDS",
                        help="the search's time budget: its growth stops after this many seconds (default 420)")
    parser.add_argument("--delimiter", default=",", help="what separates the fields (default ',')")
    parser.add_argument("--scores", type=pathlib.Path,
                        help="also write the scores here (JSON): the chosen and the linear model's, and the "
                             "ranking of every candidate")
    parser.add_argument("--figure", type=pathlib.Path,
                        help="also draw measured against simulated output of the first data file here")
    parser.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                        help="a progress bar while the candidates are scored (default: when standard error is "
                             "a terminal)")


#: How many rows of the ranking ``bonl identify`` prints (``--scores`` has them all).
PRINTED_RANKS = 10


@dataclasses.dataclass(frozen=True)
class _Record:
    """A record the command reads: where from, its samples, and where its scored part starts (a test
    split off a data file by --test-from is the whole file, scored from there)."""

    name: str
    u: np.ndarray
    y: np.ndarray
    start: int = 0


def _read(args: argparse.Namespace, path: Any) -> _Record:
    u, y = read_columns(path, [args.input, args.output], delimiter=args.delimiter)
    return _Record(str(path), u, y)


def _records(args: argparse.Namespace) -> Tuple[List[_Record], List[_Record]]:
    """The records identified on and the test records, from the files and --test-from, checked."""
    if args.window < 0:
        raise ValueError(f"bonl identify: --window must be >= 0, got {args.window}")
    fitted = [_read(args, path) for path in args.data]
    tests = [_read(args, path) for path in args.test]
    if args.test_from is not None:
        if len(fitted) > 1:
            raise ValueError("bonl identify: --test-from splits one data file; with several, give the test "
                             "records as --test FILE")
        whole = fitted[0]
        if not 1 <= args.test_from < whole.u.size:
            raise ValueError(f"bonl identify: --test-from must be in 1..{whole.u.size - 1} (the file has "
                             f"{whole.u.size} samples), got {args.test_from}")
        fitted = [_Record(whole.name, whole.u[:args.test_from], whole.y[:args.test_from])]
        tests.insert(0, _Record(f"{whole.name}, samples {args.test_from} on", whole.u, whole.y, args.test_from))
    for record in fitted:
        if float(np.ptp(record.u)) == 0.0:
            raise ValueError(f"bonl identify: the input {args.input!r} is constant over the samples identified on "
                             f"in {record.name}: nothing about the system can be learnt from it")
    for record in tests:
        if record.u.size - record.start <= args.window:
            raise ValueError(f"bonl identify: the test record {record.name} must be longer than the window "
                             f"({args.window} samples)")
    return fitted, tests


def _rms(y: np.ndarray, simulated: np.ndarray) -> Optional[float]:
    """RMS error, None where it overflows."""
    rms = _metrics.rmse(y, simulated)
    return rms if math.isfinite(rms) else None


def _free_run_rms(model: Any, record: _Record, window: int) -> Optional[float]:
    """The RMS free-run error on a record's samples from ``record.start`` on: with a window, those
    samples simulated after their first ``window``, which set the state; otherwise the whole record
    simulated from rest (the part before ``start`` is the data fitted on). None where the simulation
    diverges."""
    u, y = record.u[record.start:], record.y[record.start:]
    try:
        if window:
            return _rms(y[window:], model.simulate(u[window:], initial=(u[:window], y[:window])))
        simulated = np.asarray(model.simulate(record.u), dtype=float).ravel()
    except _bonl.NumericalError:
        return None
    return _rms(y, simulated[record.start:])


def _fitted_rms(model: Any, records: List[_Record]) -> Optional[float]:
    """The RMS free-run error over the records identified on, each simulated whole from rest."""
    squares = 0.0
    for record in records:
        rms = _free_run_rms(model, record, 0)
        if rms is None:
            return None
        squares += rms ** 2 * record.u.size
    return math.sqrt(squares / sum(record.u.size for record in records))


def _held_out_rms(row: Any) -> Optional[float]:
    return math.sqrt(row.score) if row.error is None and math.isfinite(row.score) else None


@dataclasses.dataclass(frozen=True)
class _Outcome:
    """What the search or the selection found: the model, its held-out RMS error, every candidate's
    row for the ranking (best first), the stages (the search's), how it held data out."""

    model: Any
    held_out_rms: Optional[float]
    ranking: List[Dict[str, Any]]
    held_out: str
    identify: Dict[str, Any]  #: identify's options the model was identified with
    stages: List[Dict[str, Any]] = dataclasses.field(default_factory=list)


def _ranking(table: Sequence[Any], settings: Optional[Sequence[Dict[str, Any]]] = None) -> List[Dict[str, Any]]:
    return [{"rank": rank, "model": row.name, "orders": row.orders, "params": row.num_params,
             "held_out_rms": _held_out_rms(row), **({"identify": settings[rank - 1]} if settings else {}),
             **({"error": row.error} if row.error is not None else {})}
            for rank, row in enumerate(table, 1)]


def _selected(structures: List[Any], records: List[Tuple[np.ndarray, np.ndarray]], args: argparse.Namespace,
              progress: bool) -> _Outcome:
    """bonl.select over the structures (the command with --model)."""
    options: Dict[str, Any] = ({} if args.operating_point in (None, "zero")
                               else {"operating_point": args.operating_point})
    selection = select(structures, records=records, validation_fraction=args.validation_fraction,
                       window=args.window, progress=progress, **options)
    return _Outcome(selection.best, _held_out_rms(selection.table[0]), _ranking(selection.table),
                    f"the last {args.validation_fraction:g} of each record", options)


def identify_run(args: argparse.Namespace) -> int:
    """Runs ``bonl identify``; prints the stages, the ranking, the chosen model and the linear model's
    figures."""
    fitted, tests = _records(args)
    orders = _parse_orders(args.orders)
    records = [(record.u, record.y) for record in fitted]
    samples = sum(record.u.size for record in fitted)
    progress = sys.stderr.isatty() if args.progress is None else args.progress
    with warnings.catch_warnings():
        # The test records' extrapolation is counted below, not warned about per candidate.
        warnings.simplefilter("ignore", _bonl.ExtrapolationWarning)
        if args.model is None and not orders:
            _say(f"searching a structure on {len(fitted)} record(s) of {samples} samples (budget {args.budget:g} s)")
            found = search(records=records, window=args.window, budget=args.budget, progress=progress,
                           operating_points=OPERATING_POINTS if args.operating_point is None
                           else (args.operating_point,))
            chosen = _Outcome(found.best, found.held_out_rms, _ranking(found.table, found.settings), found.held_out,
                              found.setting, [dataclasses.asdict(stage) for stage in found.stages])
            linear = (_Outcome(found.linear, found.linear_held_out_rms, [], found.held_out, found.linear_setting)
                      if found.linear is not None else None)
        else:
            structures = candidates(args.model, orders)
            _say(f"scoring {len(structures)} candidates on {len(fitted)} record(s) of {samples} samples, the last "
                 f"{args.validation_fraction:g} of each held out"
                 + (f", after a {args.window}-sample window" if args.window else ""))
            chosen = _selected(structures, records, args, progress)
            _say("scoring the linear (ARX) candidates beside it")
            linear = _selected(candidates("ARX"), records, args, progress)
    args.out.write_text(chosen.model.to_json() + "\n")
    with warnings.catch_warnings():
        # Said once below, with the count, instead of at each simulation of the record.
        warnings.simplefilter("ignore", _bonl.ExtrapolationWarning)
        _report(args, fitted, tests, chosen, linear)
    return 0


def _say(text: str) -> None:
    """A stage of a long run, on standard error (standard output has the results)."""
    sys.stderr.write(f"bonl identify: {text}\n")
    sys.stderr.flush()


def _model_report(args: argparse.Namespace, outcome: _Outcome, fitted: List[_Record],
                  tests: List[_Record]) -> Dict[str, Any]:
    model = outcome.model
    return {
        "orders": named_orders(model),
        "held_out_rms": outcome.held_out_rms,
        "fitted_on_rms": _fitted_rms(model, fitted),
        "tests": [{"name": record.name, "rms": _free_run_rms(model, record, args.window),
                   "inputs_outside_range": int(model.extrapolated_samples(record.u[record.start:]))}
                  for record in tests],
    }


def _report(args: argparse.Namespace, fitted: List[_Record], tests: List[_Record], chosen: _Outcome,
            linear: Optional[_Outcome]) -> None:
    """Prints the stages, the ranking, the chosen model's summary and the linear model's figures;
    writes the scores and the figure."""
    best = chosen.model
    count = len(chosen.ranking)
    report = {
        "data": [record.name for record in fitted],
        "samples": [int(record.u.size) for record in fitted],
        "window": args.window,
        "held_out": chosen.held_out,
        "model": type(best).__name__,
        "identify": chosen.identify,
        "candidates": count,
        **_model_report(args, chosen, fitted, tests),
        "linear": _model_report(args, linear, fitted, tests) if linear is not None else None,
        **({"search": chosen.stages} if chosen.stages else {}),
        "ranking": chosen.ranking,
    }
    for stage in chosen.stages:
        print(f"{stage['name']}: {stage['choice']} ({stage['why']})")
    ranking = report["ranking"]
    print(f"ranking by held-out RMS error ({min(PRINTED_RANKS, count)} best of {count}; --scores has them all):")
    for row in ranking[:PRINTED_RANKS]:
        orders = ", ".join(f"{k}={v}" for k, v in row["orders"].items())
        score = f"{row['held_out_rms']:.6g}" if row["held_out_rms"] is not None else row.get("error", "diverged")
        print(f"  {row['rank']:>4}  {row['model']:<28} {orders:<40} {row['params']:>4} params  {score}")
    refused = [row for row in ranking if "error" in row]
    if refused:
        print(f"  {len(refused)} candidate(s) failed or were refused, e.g. {refused[0]['model']}: {refused[0]['error']}")
    # The first data file whole (with --test-from, its test part marked).
    whole = tests[0] if args.test_from is not None else fitted[0]
    print(summary(best, whole.u, whole.y, test_from=args.test_from) if len(fitted) == 1 else summary(best))
    if len(fitted) > 1:
        print(f"  free run from rest over the {len(fitted)} records: RMS error {_format(report['fitted_on_rms'])}")
    for test in report["tests"]:
        print(f"  test {test['name']}: RMS error {_format(test['rms'])}")
        if test["inputs_outside_range"]:
            print(f"    {test['inputs_outside_range']} of its inputs lie outside the range identified on: "
                  "the model extrapolates there")
    print(f"  chosen among {count} candidates, {chosen.held_out} held out: RMS error there "
          f"{_format(report['held_out_rms'])}")
    if linear is not None:
        linear_orders = ", ".join(f"{k}={v}" for k, v in report["linear"]["orders"].items())
        print(f"linear model beside it: ARX ({linear_orders}), held-out RMS error "
              f"{_format(report['linear']['held_out_rms'])}"
              + "".join(f", test {t['name']} {_format(t['rms'])}" for t in report["linear"]["tests"]))
    else:
        print("linear model beside it: none (the linear stage's ARX model is not bounded on all the records)")
    print(f"wrote {args.out}")
    if args.scores:
        args.scores.write_text(json.dumps(report, indent=1) + "\n")
        print(f"wrote {args.scores}")
    if args.figure:
        plot_fit(best, whole.u, whole.y, test_from=args.test_from, path=args.figure,
                 title=f"{type(best).__name__} on {pathlib.Path(whole.name).name}")
        print(f"wrote {args.figure}")


def _format(value: Optional[float]) -> str:
    return f"{value:.6g}" if value is not None else "diverged"


def simulate_arguments(parser: argparse.ArgumentParser) -> None:
    """The ``simulate`` subcommand's arguments."""
    parser.add_argument("model", type=pathlib.Path, help="a bonl model file (JSON)")
    parser.add_argument("data", help="the data file holding the input")
    parser.add_argument("--input", required=True, help="the input's column: its name, or its 0-based position")
    parser.add_argument("--output", help="a measured output's column: also print the RMS error against it")
    parser.add_argument("--out", required=True, type=pathlib.Path,
                        help="write the input and the simulated output here (CSV, columns u and simulated)")
    parser.add_argument("--delimiter", default=",", help="what separates the fields (default ',')")


def simulate_run(args: argparse.Namespace) -> int:
    """Runs ``bonl simulate``: the model's free run from rest over the file's input."""
    if not args.model.is_file():
        raise ValueError(f"bonl simulate: {args.model}: no such file")
    model = _bonl.load_model(args.model.read_text())
    columns = [args.input] + ([args.output] if args.output else [])
    data = read_columns(args.data, columns, delimiter=args.delimiter)
    u = data[0]
    simulated = np.asarray(model.simulate(u), dtype=float).ravel()
    write_columns(args.out, [("u", u), ("simulated", simulated)])
    if args.output:
        rms = float(np.sqrt(np.mean((data[1] - simulated) ** 2)))
        print(f"RMS error against {args.output!r}: {rms:.6g}")
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit("run it as `python -m bonl identify` or `python -m bonl simulate`")
