"""The paper's experiment with the joint angle as the output: what a position controller needs.

The records of ``bonl.experiment.run_paper_experiment()`` (the simulated dipper joint, docs/explanation/plant.md)
carry the measured angle beside the velocity the paper's models are fitted on. Here the paper's four
models, at the paper's orders (na = 3, nb = 2, nk = 8, r = r1 = 3), are identified on the
identification record's angle, once without and once with an integrator (``ni = 1``: the angle
integrates the joint's velocity), each with identify()'s defaults; each is then simulated from rest
on the validation record's input and scored by the RMS of its angle error. Writes a results file and
the table docs/explanation/plant.md quotes (tests/python/test_published_figures.py recomputes both).

    python examples/joint_angle/joint_angle.py --json docs/results/joint_angle.json \\
        --markdown docs/results/joint_angle_summary.md
"""

from __future__ import annotations

import argparse
import json
import math
import pathlib
import warnings

import numpy as np

import bonl
from bonl import experiment

MODELS = ("ARX", "Hammerstein", "HammersteinWiener", "PseudoHammersteinWiener")
PAPER_ORDERS = dict(na=3, nb=2, nk=8, r=3, r1=3)


def structure(name: str, ni: int):
    """The model `name` at the paper's orders with `ni` integrators."""
    family = getattr(bonl, name)
    return family(**{order: PAPER_ORDERS[order] for order in family.ORDERS if order != "ni"}, ni=ni)


def run() -> dict:
    records = experiment.run_paper_experiment()
    fit, check = records.identification, records.validation
    rows = []
    for name in MODELS:
        for ni in (0, 1):
            # The validation input leaves the identification range on 146 samples (as for the velocity
            # models); a pole near 1 is what an angle has. Neither is news per model.
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", bonl.StabilityWarning)
                warnings.simplefilter("ignore", bonl.ExtrapolationWarning)
                model = bonl.identify(structure(name, ni), fit.input, fit.angle)
                try:
                    error = check.angle - model.simulate(check.input)
                    rms = float(np.sqrt(np.mean(error ** 2)))
                except bonl.NumericalError:
                    rms = math.inf
            rows.append({"model": name, "ni": ni, "validation_rms": rms, "pole_radius": model.pole_radius,
                         "json": json.loads(model.to_json())})
    return {"orders": PAPER_ORDERS, "samples": int(fit.angle.size), "angle_rms": float(np.sqrt(np.mean(check.angle ** 2))),
            "rows": rows}


def table(results: dict) -> str:
    lines = ["| model | without an integrator (rad) | with one, ni = 1 (rad) |", "|---|---|---|"]
    by = {(row["model"], row["ni"]): row["validation_rms"] for row in results["rows"]}
    for name in MODELS:
        lines.append(f"| {name} | {by[(name, 0)]:.3g} | {by[(name, 1)]:.3g} |")
    lines.append("")
    lines.append(f"Validation record: the angle's own RMS is {results['angle_rms']:.3g} rad; every model "
                 f"simulated from rest at the paper's orders.")
    return "\n".join(lines) + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", type=pathlib.Path)
    parser.add_argument("--markdown", type=pathlib.Path)
    args = parser.parse_args()
    results = run()
    if args.json:
        args.json.write_text(json.dumps(results, indent=1) + "\n")
    text = table(results)
    if args.markdown:
        args.markdown.write_text(text)
    print(text)


if __name__ == "__main__":
    main()
