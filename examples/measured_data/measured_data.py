"""ARX, Hammerstein, HammersteinWiener and PseudoHammersteinWiener on measured data: the hydraulic
actuator and the cascaded tanks.

Data (data/*/SOURCE.md; nobody on this project produced them):
- hydraulic-actuator (Sjoberg et al. 1995): u = valve opening, y = oil pressure, 1024 samples.
  Estimation: samples 1-512; validation: samples 513-1024. The model simulates the whole record
  from rest with its own output; the score is the RMS of the simulation error on 513-1024.
- cascaded-tanks (Schoukens et al. 2016): estimation record and validation record, 1024 samples
  each, Ts = 4 s. The model simulates the validation record; the score is its RMS error (V).

Selection, per data set and model, from the estimation data only (the validation data are not
read before the structure is fixed):
1. Split the estimation part: the first 75 % ("fit") and the last 25 % ("check").
2. For every candidate (orders na, nb, nk, r, r1 and data offset) identify on "fit", simulate the
   whole estimation part from rest and score the RMS simulation error on "check". Candidates whose
   identification breaks down (bonl.NumericalError) or whose simulation diverges are dropped.
3. The candidate with the lowest score wins (ties: the first in grid order); it is identified again
   on the whole estimation part, and that model is judged on the validation data.

Estimator settings (fixed, not searched): ARX by least squares (forgetting 1, P(0) = 1e6 I); the
block models by the equation-error method with the paper's settings (forgetting 0.98 for 200 samples
then 1, P(0) = 1e6 I, c(0) = 0.01, one pass, 100 Levenberg-Marquardt iterations on the free-run
simulation error).

Offsets: bonl's models simulate from rest (every past u, w, x zero). The actuator record starts at
rest (u and y within 0.007 of 0 for the first samples), so it is used as is. The tanks start at
about 5 V, so the data are shifted by constants (u0, y0) taken from the estimation record: either
its mean ("mean") or its first sample ("first"), chosen by the grid like an order. The validation
record is shifted by the same estimation constants: nothing is read from the validation record.

    python examples/measured_data/measured_data.py --out out --json out/results.json

Writes, into --out: one model file per data set and model (bonl JSON format; for the tanks the
model works on the shifted signals, see selection.json), selection.json (the chosen candidates
and their scores) and the figures (or into --plot DIR).
"""

from __future__ import annotations

import argparse
import concurrent.futures
import csv
import functools
import itertools
import json
import math
import operator
import os
import pathlib
import sys
import time

import numpy as np

import bonl

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = ROOT / "data"

# The models, each named by its class name (bonl's one spelling); their orders come from the class (ORDERS).
MODELS = (bonl.ARX, bonl.Hammerstein, bonl.HammersteinWiener, bonl.PseudoHammersteinWiener)
NAMES = tuple(model.__name__ for model in MODELS)
FIT_FRACTION = 0.75

# The grid: every combination, in this order (the order breaks ties).
GRID = {
    "na": (1, 2, 3, 4),
    "nb": (0, 1, 2, 3),
    "nk": (0, 1, 2),
    "r": (1, 2, 3),
    "r1": (2, 3),
}
# A smaller grid (the tests use it to stay fast).
SMALL_GRID = {"na": (2, 3), "nb": (1, 2), "nk": (0, 1), "r": (2, 3), "r1": (3,)}


# --------------------------------------------------------------------------------------------- data


def load_actuator(data: pathlib.Path = DATA) -> dict:
    """The actuator record: u (valve opening) and y (oil pressure), 1024 samples each."""
    with open(data / "hydraulic-actuator" / "actuator.csv", newline="") as file:
        rows = list(csv.DictReader(file))
    return {
        "u": np.array([float(row["u"]) for row in rows]),
        "y": np.array([float(row["p"]) for row in rows]),
    }


def load_cascaded_tanks(data: pathlib.Path = DATA) -> dict:
    """The tanks' estimation and validation records (V)."""
    with open(data / "cascaded-tanks" / "dataBenchmark.csv", newline="") as file:
        rows = [row for row in csv.DictReader(file) if row.get("uEst")]
    return {key: np.array([float(row[key]) for row in rows]) for key in ("uEst", "uVal", "yEst", "yVal")}


# ------------------------------------------------------------------------------------ candidates


def structure(model: type, orders: dict):
    """A model of class `model` at `orders` (its parameters are not used by identify)."""
    return model(**orders)


def settings(model: type) -> dict:
    """The estimator settings (fixed; see the module docstring): ARX, a linear regression, by least squares
    (P(0) = 1e6 I in the data's units: the batch solution's regulariser)."""
    if model is bonl.ARX:
        return {"method": "equation_error", "forgetting": 1.0, "p0": 1e6, "normalise": False}
    return {"method": "equation_error"}  # the paper's forgetting, P(0), c(0), one pass; LM refinement


def candidates(model: type, grid: dict, offsets: tuple) -> list:
    """Every candidate of class `model`, in grid order: (orders, offset)."""
    keys = [key for key in model.ORDERS if key in grid]  # the integrators ni: the class's default
    result = []
    for values in itertools.product(*(grid[key] for key in keys)):
        for offset in offsets:
            result.append((dict(zip(keys, values)), offset))
    return result


def offset_constants(kind: str, u: np.ndarray, y: np.ndarray) -> tuple:
    """(u0, y0) from the estimation record: 'none', 'mean' or 'first'."""
    if kind == "none":
        return 0.0, 0.0
    if kind == "mean":  # a plain left-to-right sum, as the C++ example does, so both agree bit for bit
        return functools.reduce(operator.add, u.tolist()) / len(u), functools.reduce(operator.add, y.tolist()) / len(y)
    if kind == "first":
        return float(u[0]), float(y[0])
    raise ValueError(f"unknown offset {kind!r}")


def rms(error: np.ndarray) -> float:
    return float(np.sqrt(np.mean(np.square(error))))


def simulate(model, u: np.ndarray, y0: float) -> np.ndarray | None:
    """Free run from rest on the shifted input, shifted back; None if it diverges."""
    try:
        simulated = np.asarray(model.simulate(u)).ravel() + y0
    except bonl.NumericalError:
        return None
    return simulated if np.all(np.isfinite(simulated)) else None


def check_score(model_class: type, orders: dict, offset: str, u: np.ndarray, y: np.ndarray) -> float:
    """Score of one candidate on the estimation record alone: fit on the first 75 %, simulate the
    whole record from rest, RMS error on the last 25 %. inf if it breaks down or diverges."""
    u0, y0 = offset_constants(offset, u, y)
    n_fit = int(round(FIT_FRACTION * len(u)))
    try:
        model = bonl.identify(structure(model_class, orders), u[:n_fit] - u0, y[:n_fit] - y0, **settings(model_class))
    except bonl.NumericalError:
        return math.inf
    simulated = simulate(model, u - u0, y0)
    if simulated is None:
        return math.inf
    score = rms(simulated[n_fit:] - y[n_fit:])
    return score if math.isfinite(score) else math.inf


def select(model: type, u: np.ndarray, y: np.ndarray, grid: dict, offsets: tuple, jobs: int) -> dict:
    """The grid search of the module docstring; returns the winner and its score."""
    cands = candidates(model, grid, offsets)
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:  # identify releases the GIL
        scores = list(pool.map(lambda c: check_score(model, c[0], c[1], u, y), cands))
    best = min(range(len(cands)), key=lambda i: (scores[i], i))
    if not math.isfinite(scores[best]):
        raise RuntimeError(f"{model.__name__}: every candidate broke down")
    orders, offset = cands[best]
    return {"orders": orders, "offset": offset, "check_rms": scores[best], "candidates": len(cands)}


# ------------------------------------------------------------------------------------- pipeline


def run_case(model_class: type, u_est, y_est, u_sim, y_sim, score_from: int, grid: dict, offsets: tuple, jobs: int):
    """Select on (u_est, y_est), refit on all of it, simulate u_sim from rest, score y_sim[score_from:]."""
    chosen = select(model_class, u_est, y_est, grid, offsets, jobs)
    u0, y0 = offset_constants(chosen["offset"], u_est, y_est)
    model = bonl.identify(structure(model_class, chosen["orders"]), u_est - u0, y_est - y0, **settings(model_class))
    simulated = simulate(model, u_sim - u0, y0)
    score = math.inf if simulated is None else rms(simulated[score_from:] - y_sim[score_from:])
    chosen.update(u0=u0, y0=y0, validation_rms=score)
    return model, simulated, chosen


def run(grid: dict = GRID, jobs: int = 2, data: pathlib.Path = DATA) -> dict:
    """The whole pipeline on both data sets. Returns {data set: {model: (model, simulated, info)}}
    plus the measured signals under "_signals"."""
    act = load_actuator(data)
    tanks = load_cascaded_tanks(data)
    n_est = 512
    results = {"actuator": {}, "cascaded_tanks": {}}
    for model in MODELS:
        results["actuator"][model.__name__] = run_case(
            model, act["u"][:n_est], act["y"][:n_est], act["u"], act["y"], n_est, grid, ("none",), jobs)
        results["cascaded_tanks"][model.__name__] = run_case(
            model, tanks["uEst"], tanks["yEst"], tanks["uVal"], tanks["yVal"], 0, grid, ("mean", "first"), jobs)
    results["_signals"] = {
        "actuator": (act["u"], act["y"], n_est),
        "cascaded_tanks": (tanks["uVal"], tanks["yVal"], 0),
    }
    return results


def table(results: dict) -> dict:
    """{"actuator": {"ARX": rms, ...}, "cascaded_tanks": {...}}."""
    return {case: {name: results[case][name][2]["validation_rms"] for name in NAMES}
            for case in ("actuator", "cascaded_tanks")}


def describe(info: dict) -> str:
    orders = " ".join(f"{key}={value}" for key, value in info["orders"].items())
    return f"{orders}" + ("" if info["offset"] == "none" else f", offset {info['offset']}")


def print_table(results: dict) -> None:
    titles = {"actuator": "Hydraulic actuator: simulation RMS on samples 513-1024",
              "cascaded_tanks": "Cascaded tanks: simulation RMS on the validation record (V)"}
    for case, title in titles.items():
        print(title)
        print(f"  {'model':<24} {'validation':>10} {'check':>8}  chosen (from estimation data only)")
        for name in NAMES:
            info = results[case][name][2]
            print(f"  {name:<24} {info['validation_rms']:>10.4f} {info['check_rms']:>8.4f}  {describe(info)}")


def plot(results: dict, directory: pathlib.Path) -> list:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    written = []
    labels = {"actuator": ("Hydraulic actuator (Sjoberg et al. 1995)", "sample", "oil pressure (scaled)"),
              "cascaded_tanks": ("Cascaded tanks, validation record", "time (s)", "water level (V)")}
    for case, (title, xlabel, ylabel) in labels.items():
        _, y, split = results["_signals"][case]
        t = np.arange(len(y)) * (4.0 if case == "cascaded_tanks" else 1.0)
        fig, axes = plt.subplots(len(MODELS), 1, figsize=(10, 9), sharex=True)
        for ax, name in zip(axes, NAMES):
            _, simulated, info = results[case][name]
            ax.plot(t, y, color="black", linewidth=1.0, label="measured")
            if simulated is not None:
                ax.plot(t, simulated, color="tab:red", linewidth=1.0,
                        label=f"{name} simulated ({describe(info)}), RMS {info['validation_rms']:.3f}")
            if split:
                ax.axvline(t[split], color="gray", linestyle="--", linewidth=0.8)
                ax.text(t[split], ax.get_ylim()[1], " validation ->", va="top", fontsize=8, color="gray")
            ax.set_ylabel(ylabel)
            ax.legend(loc="lower left", fontsize=8)
            ax.grid(alpha=0.3)
        axes[-1].set_xlabel(xlabel)
        fig.suptitle(f"{title}: measured vs free-run simulation from rest")
        fig.tight_layout()
        path = directory / f"{case}.png"
        fig.savefig(path, dpi=110)
        plt.close(fig)
        written.append(path)
    return written


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("measured_data_out"),
                        help="directory for the model files, selection.json and (without --plot) the figures")
    parser.add_argument("--json", type=pathlib.Path, help="write the table of validation RMS here")
    parser.add_argument("--plot", type=pathlib.Path, help="directory for the figures (default: --out)")
    parser.add_argument("--no-plot", action="store_true", help="skip the figures")
    parser.add_argument("--small-grid", action="store_true", help="the tests' small grid (fast)")
    parser.add_argument("--jobs", type=int, default=min(2, os.cpu_count() or 1), help="threads for the grid")
    args = parser.parse_args(argv)

    start = time.perf_counter()
    results = run(SMALL_GRID if args.small_grid else GRID, args.jobs)
    print_table(results)

    args.out.mkdir(parents=True, exist_ok=True)
    selection = {}
    for case in ("actuator", "cascaded_tanks"):
        selection[case] = {}
        for name in NAMES:
            model, _, info = results[case][name]
            path = args.out / f"{case}_{name}.json"
            path.write_text(model.to_json(2) + "\n")
            selection[case][name] = dict(info, model_file=path.name)
    (args.out / "selection.json").write_text(json.dumps(selection, indent=2) + "\n")
    if args.json:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(json.dumps(table(results), indent=2) + "\n")
    if not args.no_plot:
        directory = args.plot or args.out
        directory.mkdir(parents=True, exist_ok=True)
        for path in plot(results, directory):
            print(f"wrote {path}")
    print(f"models and selection.json in {args.out}; {time.perf_counter() - start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
