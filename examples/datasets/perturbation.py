"""Does a result move when the data change in their last digit? The cascaded tanks (issue 18's
acceptance): the training output perturbed by Gaussian noise of 1e-9 V, seeds 0-9.

- ``structure``: every family's chosen structure (docs/results/datasets/cascaded_tanks.json)
  identified again on each perturbed record and scored on the validation record;
- ``selection`` (with ``--select``): the whole selection run again on each perturbed record, as
  cascaded_tanks.py runs it (about a minute per family).

The spread of a list of figures is (max - min) / the unperturbed figure.
"""

import argparse
import json
import pathlib
import warnings

import numpy as np

import bonl

import benchmark
import cascaded_tanks

NOISE = 1e-9
SEEDS = range(10)
RESULTS = pathlib.Path(__file__).resolve().parents[2] / "docs" / "results" / "datasets"


def perturbed(records, seed):
    """The records with noise of NOISE on the output, from numpy's default generator with this seed."""
    rng = np.random.default_rng(seed)
    return [(u, y + NOISE * rng.standard_normal(y.size)) for u, y in records]


def spread(figures):
    return (max(figures) - min(figures)) / figures[0]


def structures(tanks, chosen, seeds=SEEDS):
    """Each chosen structure identified on each perturbed record: the validation RMS per seed."""
    test = tanks.tests[0]
    rows = {}
    for row in chosen["rows"]:
        family = getattr(bonl, row["model"])
        structure = family(**row["orders"])
        figures = [test.rms(bonl.identify(structure, records=records, **row["identify"]))
                   for records in [tanks.estimation] + [perturbed(tanks.estimation, s) for s in seeds]]
        rows[row["model"]] = {"orders": row["orders"], "identify": row["identify"], "unperturbed": figures[0],
                              "perturbed": figures[1:], "spread": spread(figures)}
    return rows


def selections(tanks, chosen, seeds=SEEDS):
    """The whole selection on each perturbed record: the chosen structure and its validation RMS (the
    unperturbed run is the committed one, `chosen`)."""
    rows = {}
    unperturbed = {row["model"]: row for row in chosen["rows"]}
    for family in bonl.MODELS:
        if family.__name__ not in unperturbed:  # not run on this data set (Benchmark.grid_of)
            continue
        runs = [unperturbed[family.__name__]]
        for seed in seeds:
            again = benchmark.Benchmark(**{**tanks.__dict__, "estimation": perturbed(tanks.estimation, seed)})
            runs.append(benchmark.run(again, [family])["rows"][0])
        figures = [run["test_rms"]["validation record"] for run in runs]
        rows[family.__name__] = {"chosen": [{"orders": run["orders"], "identify": run["identify"]} for run in runs],
                                 "unperturbed": figures[0], "perturbed": figures[1:], "spread": spread(figures)}
    return rows


def table(results) -> str:
    """The Markdown table of a results file: the validation RMS unperturbed, its range over the seeds
    and the spread, per family, for the chosen structures and (where run) the whole selection."""
    lines = [f"| cascaded tanks, validation RMS [V] | structure | unperturbed | {len(results['seeds'])} perturbed "
             "records | spread |",
             "|---|---|---|---|---|"]
    for part, what in (("structure", "chosen structure identified again"), ("selection", "selection run again")):
        for model, row in results.get(part, {}).items():
            orders = " ".join(f"{k}={v}" for k, v in row["orders"].items()) if part == "structure" else (
                f"{len({json.dumps(c, sort_keys=True) for c in row['chosen']})} different chosen")
            lines.append(f"| {model}, {what} | {orders} | {row['unperturbed']:.4g} | "
                         f"{min(row['perturbed']):.4g} to {max(row['perturbed']):.4g} | {100 * row['spread']:.1f}% |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", type=pathlib.Path, help="write the results here")
    parser.add_argument("--select", action="store_true", help="also run the whole selection again per seed")
    parser.add_argument("--table", type=pathlib.Path, help="write the Markdown table here")
    parser.add_argument("--results", type=pathlib.Path, default=RESULTS,
                        help="the folder of cascaded_tanks.json (default: docs/results/datasets)")
    parser.add_argument("--quick", action="store_true",
                        help="two seeds and the selection of cascaded_tanks.py --quick (a smoke run: benchmark.quick)")
    args = parser.parse_args()
    tanks = benchmark.quick(cascaded_tanks.make()) if args.quick else cascaded_tanks.make()
    seeds = SEEDS[:2] if args.quick else SEEDS
    chosen = json.loads((args.results / "cascaded_tanks.json").read_text())
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bonl.ExtrapolationWarning)
        results = {"data_set": "cascaded-tanks", "noise": NOISE, "seeds": list(seeds),
                   "structure": structures(tanks, chosen, seeds)}
        if args.select:
            results["selection"] = selections(tanks, chosen, seeds)
    print(table(results))
    if args.json:
        args.json.write_text(json.dumps(results, indent=1) + "\n")
    if args.table:
        args.table.write_text(table(results) + "\n")


if __name__ == "__main__":
    main()
