"""The structure search (``bonl.search``) against a grid around the true structure, on known systems of
every model family (systems.py), the grid the data-set scripts would write for them: the true family,
its linear orders and delay each one below, at and one above the truth, its nonlinear orders at the
truth, knots and thresholds placed by the same rule (``bonl.place_from_data``), selected by
``bonl.select`` on the estimation record. Both are scored by the free-run error on a fresh record of
the same kind of input against its noise-free output (NRMSE: RMS error over the output's standard
deviation), beside the linear model the search chose on the way (its ARX stage).

    python examples/search/search_vs_grid.py [--json FILE] [--markdown FILE] [--quick]

--quick (the CI's smoke run): two systems, 600 samples, a 20-second budget; its figures are not
judged. scripts/search_vs_grid.sh writes docs/results/search_vs_grid.json and its summary;
tests/python/test_search_vs_grid.py checks them.
"""

from __future__ import annotations

import argparse
import itertools
import json
import pathlib
import sys
import time
import warnings

import numpy as np

import bonl

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from systems import SYSTEMS  # noqa: E402

#: The estimation and test records' length and seeds.
SAMPLES = 3000
ESTIMATION_SEED, TEST_SEED = 1, 2
#: The orders the grid moves one step either way (the others stay at the truth).
LINEAR_ORDERS = ("na", "nb", "nk", "na1", "nb1", "na2", "nb2", "nd")


def grid_around(truth) -> list:
    """The true family's structures with each linear order one below, at and one above the truth."""
    model_class = type(truth)
    orders = dict(zip(model_class.ORDERS, truth.orders))
    values = [[v - 1, v, v + 1] if name in LINEAR_ORDERS else [v] for name, v in orders.items()]
    out = []
    for combination in itertools.product(*values):
        try:
            out.append(model_class(*combination))
        except ValueError:
            pass
    return out


def nrmse(model, u, clean) -> float:
    """Free-run RMS error against the noise-free output, over its standard deviation (inf where it
    diverges)."""
    try:
        simulated = np.asarray(model.simulate(u), dtype=float)
    except bonl.NumericalError:
        return float("inf")
    error = float(np.sqrt(np.mean((simulated - clean) ** 2)) / np.std(clean))
    return error if np.isfinite(error) else float("inf")


def run_one(system, samples: int, budget: float) -> dict:
    u, y, _ = system.records(samples, ESTIMATION_SEED)
    u_test, _, clean_test = system.records(samples, TEST_SEED)
    truth = system.make()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bonl.ExtrapolationWarning)
        start = time.perf_counter()
        found = bonl.search(u, y, budget=budget, progress=False)
        search_seconds = time.perf_counter() - start
        candidates = [bonl.place_from_data(c, [(u, y)]) for c in grid_around(truth)]
        start = time.perf_counter()
        grid = bonl.select(candidates, u, y, progress=False).best
        grid_seconds = time.perf_counter() - start
        linear = found.linear
        figures = {"search": nrmse(found.best, u_test, clean_test), "grid": nrmse(grid, u_test, clean_test),
                   "linear": nrmse(linear, u_test, clean_test)}
    row = {"system": system.name, "truth": {"model": type(truth).__name__, "orders": bonl.named_orders(truth)},
           "search": {"model": type(found.best).__name__, "orders": bonl.named_orders(found.best),
                      "nrmse": figures["search"], "seconds": round(search_seconds, 1),
                      "json": json.loads(found.best.to_json())},
           "grid": {"candidates": len(candidates), "model": type(grid).__name__, "orders": bonl.named_orders(grid),
                    "nrmse": figures["grid"], "seconds": round(grid_seconds, 1), "json": json.loads(grid.to_json())},
           "linear": {"orders": bonl.named_orders(linear), "nrmse": figures["linear"],
                      "json": json.loads(linear.to_json())}}
    print(f"{system.name}: search {figures['search']:.4g} ({type(found.best).__name__} "
          f"{bonl.named_orders(found.best)}), grid {figures['grid']:.4g}, linear {figures['linear']:.4g} "
          f"({search_seconds:.0f} s)", flush=True)
    return row


def markdown(results: dict) -> str:
    lines = ["| system | true structure | search: model | search NRMSE | grid NRMSE | search / grid | linear (ARX) "
             "NRMSE |", "|---|---|---|---:|---:|---:|---:|"]
    for row in results["systems"]:
        truth = " ".join(f"{k}={v}" for k, v in row["truth"]["orders"].items())
        found = " ".join(f"{k}={v}" for k, v in row["search"]["orders"].items())
        ratio = row["search"]["nrmse"] / row["grid"]["nrmse"]
        lines.append(f"| {row['system']} | {row['truth']['model']} {truth} | {row['search']['model']} {found} | "
                     f"{row['search']['nrmse']:.3g} | {row['grid']['nrmse']:.3g} | {ratio:.3g} | "
                     f"{row['linear']['nrmse']:.3g} |")
    return "\n".join(lines) + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", type=pathlib.Path, help="write the results here")
    parser.add_argument("--markdown", type=pathlib.Path, help="write the table here")
    parser.add_argument("--quick", action="store_true", help="a smoke run: two systems, short records")
    args = parser.parse_args()
    systems, samples, budget = (SYSTEMS[:2], 600, 20.0) if args.quick else (SYSTEMS, SAMPLES, 420.0)
    results = {"quick": args.quick, "samples": samples,
               "systems": [run_one(system, samples, budget) for system in systems]}
    if args.json:
        args.json.write_text(json.dumps(results, indent=1) + "\n")
    if args.markdown:
        args.markdown.write_text(markdown(results))


if __name__ == "__main__":
    main()
