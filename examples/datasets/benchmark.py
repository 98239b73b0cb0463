"""What every data-set script shares: select each model family on the estimation data with
``bonl.select`` (the held-out data scored with the tests' state-initialisation window), simulate the
test data with the chosen model and write one results file.

Public API only (``bonl.grid``, ``bonl.select``, ``Model.simulate``, ``Model.to_json``): no offsets or
scaling by hand. Each script in this folder loads its data set, states its protocol (from the data
set's ``SOURCE.md``) and the grid of orders, and calls :func:`run`.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import pathlib
import time
import warnings
from typing import Callable, Dict, List, Optional, Sequence, Tuple

import numpy as np

import bonl

DATA = pathlib.Path(__file__).resolve().parents[2] / "data"

Record = Tuple[np.ndarray, np.ndarray]


@dataclasses.dataclass(frozen=True)
class Test:
    """A test record: the model simulates ``u`` from rest, or after the state-initialisation window
    (its first ``window`` samples, measured), and is scored on samples ``skip`` onwards. A record that
    is one period of a periodic steady state (``periods`` > 1) is simulated from rest over ``periods``
    repetitions of ``u`` and scored on the last, so that the model's transient from rest is not scored
    against a system that had none."""

    name: str
    u: np.ndarray
    y: np.ndarray
    window: int = 0
    skip: int = 0
    periods: int = 1

    def rms(self, model, from_rest: bool = False) -> float:
        """The score; ``from_rest``: the same samples scored with the whole record simulated from rest
        at the operating point, to show what the initial-state window does. Infinity where the
        simulation diverges (a figure like any other: the model is reported, not dropped)."""
        try:
            return self._rms(model, from_rest)
        except bonl.NumericalError:
            return math.inf

    def _rms(self, model, from_rest: bool) -> float:
        if self.window and from_rest:
            error = (self.y - model.simulate(self.u))[self.window:]
        elif self.window:
            initial = (self.u[:self.window], self.y[:self.window])
            simulated = model.simulate(self.u[self.window:], initial=initial)
            error = self.y[self.window:] - simulated
        else:
            error = self.y - model.simulate(np.tile(self.u, self.periods))[-self.u.size:]
        error = error[max(0, self.skip - self.window):]
        return float(np.sqrt(np.mean(error ** 2)))


@dataclasses.dataclass(frozen=True)
class Benchmark:
    name: str                          #: the folder under data/
    unit: str                          #: of the output, for the table
    estimation: List[Record]           #: the records identify sees
    tests: List[Test]
    orders: Dict[str, Sequence[int]]   #: the grid, shared by every model family (each takes its own)
    published: List[Tuple[str, str]]  #: (what, figure) from SOURCE.md
    #: identify's options; several sets are candidates like the orders (each family keeps the set
    #: whose chosen structure scores best on the held-out estimation data)
    identify: List[Dict[str, object]] = dataclasses.field(default_factory=lambda: [{}])
    #: a family's own grid, by its name, where the shared one does not fit it (the Wiener-Hammerstein
    #: model's polynomial degree and its two blocks' orders); a family whose orders neither grid names
    #: is not run on this data set
    family_orders: Dict[str, Dict[str, Sequence[int]]] = dataclasses.field(default_factory=dict)
    #: a family's own identify options, by its name, where the shared ones do not fit it
    family_identify: Dict[str, List[Dict[str, object]]] = dataclasses.field(default_factory=dict)
    #: a family's structures set up before selection, by its name (knots, an operating point that is
    #: physics, not data): called on each candidate, from the estimation data only
    prepare: Dict[str, Callable[[object], None]] = dataclasses.field(default_factory=dict)
    #: bonl.select's criterion: "validation" (the held-out tail of the estimation data, scored with the
    #: tests' window) or "aic"/"bic" (the free run over the whole estimation record)
    criterion: str = "validation"
    #: identify fits each candidate's free run after the tests' state-initialisation window (identify's
    #: initialisation_window), as the tests score it, instead of from rest
    fit_after_window: bool = False

    def grid_of(self, family) -> Optional[Dict[str, Sequence[int]]]:
        """The orders ``family`` is selected over here, or None where this data set does not run it."""
        orders = {**family.ORDER_DEFAULTS, **self.orders, **self.family_orders.get(family.__name__, {})}
        if not all(name in orders for name in family.ORDERS):
            return None
        return {name: orders[name] for name in family.ORDERS}

    @property
    def window(self) -> int:
        """The tests' state-initialisation window, which select scores the held-out data with too."""
        windows = {test.window for test in self.tests}
        if len(windows) != 1:
            raise ValueError(f"{self.name}: the tests have different windows {sorted(windows)}")
        return windows.pop()


def run(benchmark: Benchmark, families: Optional[Sequence[type]] = None) -> dict:
    """Selects every family on the estimation data and scores the chosen model on each test record."""
    # Test inputs outside the estimation range are counted in the results, not warned about per model.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bonl.ExtrapolationWarning)
        return _run(benchmark, families)


def _run(benchmark, families):
    rows = []
    unbounded = {}  # families none of whose candidates has a bounded free run, and why (bonl.select)
    for family in families or bonl.MODELS:
        orders = benchmark.grid_of(family)
        if orders is None:
            continue
        candidates = bonl.grid(family, **orders)
        for candidate in candidates:
            benchmark.prepare.get(family.__name__, lambda structure: None)(candidate)
        identify = benchmark.family_identify.get(family.__name__, benchmark.identify)
        if benchmark.fit_after_window:
            identify = [{**options, "initialisation_window": benchmark.window} for options in identify]
        start = time.perf_counter()
        scoring = (dict(window=benchmark.window) if benchmark.criterion == "validation"
                   else dict(criterion=benchmark.criterion))
        selections, refused = [], []
        for options in identify:
            try:
                selections.append((bonl.select(candidates, records=benchmark.estimation, **scoring, **options),
                                   options))
            except bonl.NumericalError as error:  # every candidate failed or was refused: the reason
                refused.append(str(error))
        if not selections:
            unbounded[family.__name__] = refused[0]
            print(f"{benchmark.name}: {family.__name__}: no model chosen: {refused[0]}", flush=True)
            continue
        selection, options = min(selections, key=lambda pair: pair[0].table[0].score)
        seconds = time.perf_counter() - start
        best = selection.best
        chosen = selection.table[0]
        rows.append({
            "model": family.__name__,
            "orders": bonl.named_orders(best),
            "identify": options,
            "candidates": len(candidates) * len(identify),
            "check_rms": math.sqrt(chosen.score if benchmark.criterion == "validation" else chosen.fit_mse),
            "test_rms": {test.name: test.rms(best) for test in benchmark.tests},
            "test_rms_from_rest": {test.name: test.rms(best, from_rest=True) for test in benchmark.tests if test.window},
            "test_inputs_outside_range": {test.name: best.extrapolated_samples(test.u) for test in benchmark.tests},
            "pole_radius": best.pole_radius,
            "seconds": round(seconds, 1),
            "json": json.loads(best.to_json()),
        })
        print(f"{benchmark.name}: {family.__name__} {rows[-1]['orders']}: "
              + ", ".join(f"{k} {v:.4g}" for k, v in rows[-1]["test_rms"].items()) + f" ({seconds:.0f} s)", flush=True)
    return {
        "data_set": benchmark.name,
        "unit": benchmark.unit,
        "orders": {k: list(v) for k, v in benchmark.orders.items()},
        **({"family_orders": {family: {k: list(v) for k, v in grid.items()}
                              for family, grid in benchmark.family_orders.items()}}
           if benchmark.family_orders else {}),
        **({"family_identify": benchmark.family_identify} if benchmark.family_identify else {}),
        "identify": benchmark.identify,
        **({"criterion": benchmark.criterion} if benchmark.criterion != "validation" else {}),
        **({"fit_after_window": True} if benchmark.fit_after_window else {}),
        "tests": [{"name": t.name, "samples": int(t.u.size), "window": t.window, "skip": t.skip,
                   **({"periods": t.periods} if t.periods > 1 else {})} for t in benchmark.tests],
        "published": benchmark.published,
        "rows": rows,
        **({"no_model": unbounded} if unbounded else {}),
    }


#: --quick: the estimation records' first samples only (the tanks' whole record is 1 024)
QUICK_SAMPLES = 2000


def quick(benchmark: Benchmark) -> Benchmark:
    """The same data set at a fraction of the cost, for scripts/datasets.sh --quick (the CI's smoke
    run of the script, whose figures are not judged): one candidate per family (each order's first
    value, the first set of identify options) on the estimation records' first QUICK_SAMPLES samples;
    the tests are the whole test records, as in the full run."""
    def first(grid):
        return {name: list(values)[:1] for name, values in grid.items()}

    return dataclasses.replace(
        benchmark,
        estimation=[(u[:QUICK_SAMPLES], y[:QUICK_SAMPLES]) for u, y in benchmark.estimation],
        orders=first(benchmark.orders),
        family_orders={family: first(grid) for family, grid in benchmark.family_orders.items()},
        identify=benchmark.identify[:1],
        family_identify={family: options[:1] for family, options in benchmark.family_identify.items()})


def main(make: Callable[[], Benchmark]) -> None:
    parser = argparse.ArgumentParser(description=(make.__doc__ or "").strip())
    parser.add_argument("--json", type=pathlib.Path, help="write the results here")
    parser.add_argument("--model", nargs=2, metavar=("FAMILY", "FILE"),
                        help="also write that family's chosen model as a bonl model file")
    parser.add_argument("--quick", action="store_true",
                        help="one candidate per family on the first samples only (a smoke run: see quick)")
    args = parser.parse_args()
    results = run(quick(make()) if args.quick else make())
    if args.json:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(json.dumps(results, indent=1) + "\n")
    if args.model:
        family, path = args.model
        row = next(row for row in results["rows"] if row["model"] == family)
        pathlib.Path(path).write_text(json.dumps(row["json"], indent=1) + "\n")
