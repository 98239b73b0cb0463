"""The ``bonl identify`` and ``bonl simulate`` commands: from a data file to a model file and back.

``bonl identify DATA.csv --input COL --output COL --out MODEL.json`` selects a model on the file's
records with :func:`bonl.select` (its held-out last quarter scores the candidates) and writes the best
as a model file. Which candidates:

- ``--model NAME --orders na=2 nb=1 ...``: that family at those orders; an order given as a list
  (``na=1,2,3``) makes a grid, an order not given takes :data:`DEFAULT_GRID`'s values;
- ``--model NAME`` alone: that family over :data:`DEFAULT_GRID`;
- neither: every family over :data:`DEFAULT_GRID` (small orders, about a hundred candidates).

Beside the chosen model it always selects an ARX model on the same data and prints its figures, so a
nonlinear model that does not beat a linear one shows. ``--test-from K`` keeps the samples from K on
out of the selection and scores them as a test (the whole record simulated from rest).

``bonl simulate MODEL.json DATA.csv --input COL --out SIMULATED.csv`` writes a model's free run.
"""

from __future__ import annotations

import argparse
import json
import math
import pathlib
import sys
import warnings
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from . import _bonl
from .data_file import read_columns, write_columns
from .report import plot_fit, summary
from .selection import grid, named_orders, select

__all__ = ["DEFAULT_GRID", "candidates", "identify_arguments", "identify_run", "simulate_arguments", "simulate_run"]

#: The orders tried where the command line gives none, by name; each family takes the ones it has
#: (an order not named here takes its value at the model's PAPER_ORDERS).
#: Small orders, so that every family's grid runs in about a minute on a few thousand samples.
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
        A model class's name (one of ``bonl.MODELS``); None: every family.
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
    parser.add_argument("data", help="the data file: one sample per row, the first row optionally the columns' names")
    parser.add_argument("--input", required=True, help="the input's column: its name, or its 0-based position")
    parser.add_argument("--output", required=True, help="the output's column")
    parser.add_argument("--out", required=True, type=pathlib.Path, help="write the chosen model's file here (JSON)")
    parser.add_argument("--model", help="the family (" + ", ".join(m.__name__ for m in _bonl.MODELS)
                        + "); default: every family")
    parser.add_argument("--orders", nargs="+", default=[], metavar="NAME=VALUES",
                        help="orders of --model, each one value or a comma-separated list (a grid), "
                             "e.g. na=2 nb=1,2 nk=0; the others take the default grid's")
    parser.add_argument("--test-from", type=int, metavar="K",
                        help="keep samples K on (0-based) out of the selection and score them as a test")
    parser.add_argument("--validation-fraction", type=float, default=0.25,
                        help="the last part of the selection data that scores the candidates (default 0.25)")
    parser.add_argument("--operating-point", choices=("zero", "initial", "mean"), default="zero",
                        help="where the model's blocks are centred: at zero (default), at the first sample, "
                             "at the data's means")
    parser.add_argument("--delimiter", default=",", help="what separates the fields (default ',')")
    parser.add_argument("--scores", type=pathlib.Path, help="also write the scores here (JSON)")
    parser.add_argument("--figure", type=pathlib.Path, help="also draw measured against simulated output here")


def _scores(model: Any, u: np.ndarray, y: np.ndarray, test_from: Optional[int]) -> Dict[str, Any]:
    try:
        simulated = np.asarray(model.simulate(u), dtype=float).ravel()
    except _bonl.NumericalError:
        simulated = np.full(u.shape, math.nan)
    parts = {"fitted_on": slice(0, test_from if test_from else u.size)}
    if test_from:
        parts["test"] = slice(test_from, u.size)
    out: Dict[str, Any] = {}
    for name, part in parts.items():
        error = y[part] - simulated[part]
        rms = float(np.sqrt(np.mean(error ** 2)))
        out[name + "_rms"] = rms if math.isfinite(rms) else None
    return out


def identify_run(args: argparse.Namespace) -> int:
    """Runs ``bonl identify``; prints the chosen model and the linear model's figures."""
    u, y = read_columns(args.data, [args.input, args.output], delimiter=args.delimiter)
    if args.test_from is not None and not 1 <= args.test_from < u.size:
        raise ValueError(f"bonl identify: --test-from must be in 1..{u.size - 1} (the file has {u.size} samples), "
                         f"got {args.test_from}")
    end = args.test_from or u.size
    structures = candidates(args.model, _parse_orders(args.orders))
    options: Dict[str, Any] = {}
    if args.operating_point != "zero":
        options["operating_point"] = args.operating_point
    u_fit, y_fit = u[:end], y[:end]
    if float(np.ptp(u_fit)) == 0.0:
        raise ValueError(f"bonl identify: the input {args.input!r} is constant over the samples identified on: "
                         "nothing about the system can be learnt from it")
    with warnings.catch_warnings():
        # The test part's extrapolation is counted below, not warned about per candidate.
        warnings.simplefilter("ignore", _bonl.ExtrapolationWarning)
        chosen = select(structures, u_fit, y_fit, validation_fraction=args.validation_fraction, progress=False,
                        **options)
        linear = select(candidates("ARX"), u_fit, y_fit, validation_fraction=args.validation_fraction,
                        progress=False, **options)
    best = chosen.best
    if chosen.table[0].error is not None or not math.isfinite(chosen.table[0].score):
        raise ValueError("bonl identify: no candidate could be identified: " + str(chosen.table[0].error))
    args.out.write_text(best.to_json() + "\n")
    with warnings.catch_warnings():
        # Said once below, with the count, instead of at each simulation of the record.
        warnings.simplefilter("ignore", _bonl.ExtrapolationWarning)
        _report(args, u, y, best, chosen, linear, len(structures), end)
    return 0


def _report(args: argparse.Namespace, u: np.ndarray, y: np.ndarray, best: Any, chosen: Any, linear: Any,
            count: int, end: int) -> None:
    """Prints the chosen model's summary and the linear model's figures; writes the scores and the figure."""
    report = {
        "data": str(args.data),
        "samples": int(u.size),
        "test_from": args.test_from,
        "model": type(best).__name__,
        "orders": named_orders(best),
        "candidates": count,
        "held_out_rms": math.sqrt(chosen.table[0].score),
        **_scores(best, u, y, args.test_from),
        "linear": {"orders": named_orders(linear.best), "held_out_rms": math.sqrt(linear.table[0].score),
                   **_scores(linear.best, u, y, args.test_from)},
    }
    print(summary(best, u, y, test_from=args.test_from))
    if args.test_from:
        report["test_inputs_outside_range"] = outside = int(best.extrapolated_samples(u[args.test_from:]))
        if outside:
            print(f"  {outside} test samples' inputs lie outside the range identified on: the model extrapolates there")
    print(f"  selected among {count} candidates on samples 0-{end - 1}, the last "
          f"{args.validation_fraction:g} of them held out: RMS error there {report['held_out_rms']:.6g}")
    linear_orders = ", ".join(f"{k}={v}" for k, v in report["linear"]["orders"].items())
    print(f"linear model beside it: ARX ({linear_orders}), held-out RMS error {report['linear']['held_out_rms']:.6g}"
          + (f", test RMS error {report['linear']['test_rms']:.6g}" if args.test_from else ""))
    print(f"wrote {args.out}")
    if args.scores:
        args.scores.write_text(json.dumps(report, indent=1) + "\n")
        print(f"wrote {args.scores}")
    if args.figure:
        plot_fit(best, u, y, test_from=args.test_from, path=args.figure,
                 title=f"{type(best).__name__} on {pathlib.Path(args.data).name}")
        print(f"wrote {args.figure}")


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
