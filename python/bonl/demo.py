"""``python -m bonl demo``: the paper's experiment on the simulated excavator dipper joint.

Runs :func:`bonl.plant.experiment` (what the C++ ``bonl_demo`` runs: identification on the
paper's multi-sine, validation by free-run simulation on a smooth random signal, the output-error
method (bonl's default) and the paper's), prints Table 1 (identified parameters) and Table 2
(validation MSE of the velocity) in the paper's layout for both methods, the online estimates'
validation MSE, and with ``--out DIR`` writes

- ``DIR/fig11_velocity.png``: measured and predicted validation velocity of the four models (the
  paper's Fig. 11), over the whole record and zoomed;
- ``DIR/fig12_residuals.png``: the residuals, measured - predicted, one panel per model (Fig. 12);
- ``DIR/tables.txt``: the printed tables;
- ``DIR/results.json``: ``{"mse": {"ARX", "Hammerstein", "HW", "PHW"}, "params": {...},
  "method": ..., "methods": {"output_error": {...}, "paper": {...}}, "online": {...}, ...}`` as
  ``bonl_demo --json``.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
from typing import Any, Dict, List, Optional, Sequence

#: The four models in the paper's column order (Tables 1 and 2), with their display names.
MODELS = (("PHW", "P-H-W"), ("HW", "H-W"), ("Hammerstein", "Hammerstein"), ("ARX", "ARX"))
#: Line colours shared by both figures (the same as bonl_demo's sweep chart).
COLOURS = {"PHW": "#d62728", "HW": "#ff7f0e", "Hammerstein": "#2ca02c", "ARX": "#1f77b4"}


def _cell(value: Optional[float]) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return " %12s" % ""
    return " %12.4g" % value


def format_tables(method: str, params: Dict[str, Dict[str, Any]], mse: Dict[str, float]) -> str:
    """Table 1 and Table 2 of one method, in the paper's layout (as ``bonl_demo`` prints them).

    Parameters
    ----------
    method : str
        ``"output_error"`` or ``"paper"``, for the title.
    params : dict
        ``{"ARX": {"b", "a"}, "Hammerstein": {"f", "p", "b", "a"}, "HW": {..., "q"},
        "PHW": {..., "c"}}``, as :func:`bonl.plant.experiment` returns them under ``params``.
    mse : dict
        Validation MSE by model, ``{"ARX", "Hammerstein", "HW", "PHW"}`` [(rad/s)^2].

    Returns
    -------
    str
        The two tables, newline-terminated.
    """
    lines: List[str] = []
    lines.append("")
    lines.append("Table 1. Identification results (method: %s)" % method)
    lines.append("%-10s %12s %12s %12s %12s" % ("Parameter", "P-H-W", "H-W", "Hammerstein", "ARX"))

    def value(model: str, name: str, index: Optional[int]) -> Optional[float]:
        entry = params[model].get(name)
        if entry is None:
            return None
        if index is None:
            return float(entry)
        return float(entry[index]) if index < len(entry) else None

    def row(label: str, name: str, index: Optional[int]) -> None:
        lines.append("%-10s" % label + "".join(_cell(value(key, name, index)) for key, _ in MODELS))

    for i in range(3):
        row("b%d" % i, "b", i)
    for j in range(3):
        row("a%d" % (j + 1), "a", j)
    for name in ("f", "p"):
        for i in range(4):
            row("%s%d" % (name, i), name, i)
    for j in range(3):
        row("q%d" % (j + 1), "q", j)
    row("c", "c", None)

    lines.append("")
    lines.append("Table 2. MSE of the identified models (validation velocity, free-run simulation)")
    lines.append("%-10s %12s %12s %12s %12s" % ("Error", "P-H-W", "H-W", "Hammerstein", "ARX"))
    lines.append("%-10s" % "MSE" + "".join(" %12.4e" % mse[key] for key, _ in MODELS) + "   (rad/s)^2")

    def lower(other: float) -> float:
        return 100.0 * (1.0 - mse["PHW"] / other)

    lines.append(
        "P-H-W's MSE is %.0f%%, %.0f%% and %.0f%% lower than H-W's, Hammerstein's and ARX's "
        "(paper: 14%%, 30%%, 75%%)" % (lower(mse["HW"]), lower(mse["Hammerstein"]), lower(mse["ARX"]))
    )
    return "\n".join(lines) + "\n"


def format_report(result: Dict[str, Any]) -> str:
    """Everything ``python -m bonl demo`` prints: the plant's runs, then both methods' tables.

    Parameters
    ----------
    result : dict
        What :func:`bonl.plant.experiment` returned.

    Returns
    -------
    str
    """
    parameters = result["parameters"]
    out = [
        "Plant: 20 t excavator dipper joint (docs/plant.md), pilot hysteresis %.0f%%, pin backlash %.1f mrad."
        % (100 * parameters.pilot_hysteresis, 1000 * parameters.joint_backlash),
        "Records: 50 s at 100 Hz, 10 repeats averaged, 10 Hz low-pass, differentiated. Identification: "
        "paper's multi-sine; validation: smooth random signal (1 Hz band).",
    ]
    for name in ("identification", "validation"):
        run = result[name]["run"]
        out.append(
            "  %-14s: piston %.3f-%.3f m of %.2f m%s, CVODE %d steps"
            % (
                name,
                run["min_position"],
                run["max_position"],
                parameters.stroke,
                " (REACHED AN END STOP)" if run["reached_end_stop"] else "",
                run["steps"],
            )
        )
    out.append("  plant simulation and processing: %.2f s" % result["seconds"]["plant"])
    text = "\n".join(out) + "\n"
    # The paper's method first, then bonl's, as bonl_demo prints them.
    for method in ("paper", "output_error"):
        entry = result["methods"][method]
        text += format_tables(method, entry["params"], entry["mse"])
    text += format_online(result["online"], result["methods"]["output_error"]["mse"])
    text += "\nidentification and validation: %.2f s\n" % result["seconds"]["identification"]
    if "robustness" in result:
        text += format_robustness(result["robustness"])
    return text


def format_online(online: Dict[str, Dict[str, float]], identified: Dict[str, float]) -> str:
    """The online table: each method's recursive estimate alone, beside ``identify()``'s, as ``bonl_demo`` prints it.

    Parameters
    ----------
    online : dict
        ``{"output_error": mse, "paper": mse}``, validation MSE by model of the online estimates.
    identified : dict
        Validation MSE by model of ``identify()`` (the output-error estimate refined).

    Returns
    -------
    str
    """
    lines = [
        "",
        "Online: the recursive estimator alone after one pass (no refinement), validation MSE",
        "%-13s %12s %12s %12s %12s" % ("method", "P-H-W", "H-W", "Hammerstein", "ARX"),
    ]
    for method in ("output_error", "paper"):
        e = online[method]
        lines.append(
            "%-13s %12.4e %12.4e %12.4e %12.4e   (rad/s)^2" % (method, e["PHW"], e["HW"], e["Hammerstein"], e["ARX"])
        )
    e = identified
    lines.append(
        "%-13s %12.4e %12.4e %12.4e %12.4e   (identify(): recursive estimate refined)"
        % ("identify()", e["PHW"], e["HW"], e["Hammerstein"], e["ARX"])
    )
    return "\n".join(lines) + "\n"


def format_robustness(rows: Sequence[Dict[str, Dict[str, float]]]) -> str:
    """The robustness table: validation MSE on the further trajectories, as ``bonl_demo`` prints it.

    Parameters
    ----------
    rows : sequence of dict
        One ``{"output_error": mse, "paper": mse}`` per trajectory.

    Returns
    -------
    str
    """
    lines = [
        "",
        "Robustness: validation MSE on %d further trajectories (smooth random x4, other multi-sines x4)" % len(rows),
        "%-4s %-12s %11s %11s %11s %11s" % ("", "method", "P-H-W", "H-W", "Hammerstein", "ARX"),
    ]
    counts = {"output_error": [0, 0, 0], "paper": [0, 0, 0]}
    for i, row in enumerate(rows):
        for method in ("output_error", "paper"):
            e = row[method]
            phw_best, h_over_arx = e["PHW"] < e["Hammerstein"], e["Hammerstein"] < e["ARX"]
            c = counts[method]
            c[0] += phw_best
            c[1] += h_over_arx
            c[2] += phw_best and h_over_arx
            lines.append(
                "%-4d %-12s %11.3e %11.3e %11.3e %11.3e" % (i + 1, method, e["PHW"], e["HW"], e["Hammerstein"], e["ARX"])
            )
    n = len(rows)
    for method in ("output_error", "paper"):
        c = counts[method]
        lines.append(
            "%s method: P-H-W < Hammerstein on %d/%d, Hammerstein < ARX on %d/%d, both on %d/%d"
            % (method, c[0], n, c[1], n, c[2], n)
        )
    return "\n".join(lines) + "\n"


def _finite_or_none(value: Any) -> Any:
    """JSON has no inf or nan: they become null (an unstable model's MSE is infinite)."""
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {k: _finite_or_none(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite_or_none(v) for v in value]
    return value


def results_json(result: Dict[str, Any]) -> Dict[str, Any]:
    """The JSON-ready summary of an experiment (the layout of ``bonl_demo --json``).

    Parameters
    ----------
    result : dict
        What :func:`bonl.plant.experiment` returned.

    Returns
    -------
    dict
        ``mse``, ``params`` and ``method`` of the chosen method; ``methods``: both methods' ``mse``
        and ``params``; ``runs``: the plant runs' ranges and CVODE steps; ``plant_parameters``;
        ``seconds``; and ``robustness`` when it was run. Non-finite numbers become null.
    """
    summary: Dict[str, Any] = {
        "mse": dict(result["mse"]),
        "params": result["params"],
        "method": result["method"],
        "methods": {m: {"mse": dict(e["mse"]), "params": e["params"]} for m, e in result["methods"].items()},
        "online": {m: dict(e) for m, e in result["online"].items()},
        "runs": {name: dict(result[name]["run"]) for name in ("identification", "validation")},
        "plant_parameters": result["parameters"].to_dict(),
        "seconds": dict(result["seconds"]),
    }
    if "robustness" in result:
        summary["robustness"] = result["robustness"]
    return _finite_or_none(summary)


def plot_figures(result: Dict[str, Any], out_dir: str) -> List[str]:
    """Write the paper's Fig. 11 (velocity) and Fig. 12 (residuals) for the chosen method.

    Parameters
    ----------
    result : dict
        What :func:`bonl.plant.experiment` returned.
    out_dir : str
        Existing directory to write ``fig11_velocity.png`` and ``fig12_residuals.png`` into.

    Returns
    -------
    list of str
        The paths written.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    method = result["method"]
    validation = result["validation"]
    t = np.asarray(validation["time"])
    y = np.asarray(validation["velocity"])
    simulated = validation["simulated"][method]
    mse = result["mse"]

    # Fig. 11: measured and predicted velocity; the lower panel zooms on 10 s so the curves separate.
    fig, axes = plt.subplots(2, 1, figsize=(11, 8), constrained_layout=True)
    zoom = (20.0, 30.0)
    for ax, window in zip(axes, (None, zoom)):
        mask = np.ones_like(t, dtype=bool) if window is None else (t >= window[0]) & (t <= window[1])
        ax.plot(t[mask], y[mask], color="black", linewidth=1.6, label="measured")
        for key, name in MODELS:
            ax.plot(
                t[mask],
                np.asarray(simulated[key])[mask],
                color=COLOURS[key],
                linewidth=1.0,
                label="%s (MSE %.3g)" % (name, mse[key]),
            )
        ax.set_xlabel("time [s]")
        ax.set_ylabel("angular velocity [rad/s]")
        ax.grid(True, alpha=0.3)
        if window is None:
            ax.set_title("Validation: measured and predicted joint velocity (free-run simulation, %s method)" % method)
            ax.axvspan(zoom[0], zoom[1], color="grey", alpha=0.12)
            ax.legend(loc="upper right", fontsize=8, ncol=5)
        else:
            ax.set_title("Zoom on %g-%g s" % window)
    velocity_path = os.path.join(out_dir, "fig11_velocity.png")
    fig.savefig(velocity_path, dpi=110)
    plt.close(fig)

    # Fig. 12: residuals measured - predicted, one panel per model, shared axes.
    fig, axes = plt.subplots(4, 1, figsize=(11, 9), sharex=True, sharey=True, constrained_layout=True)
    for ax, (key, name) in zip(axes, MODELS):
        residual = y - np.asarray(simulated[key])
        ax.plot(t, residual, color=COLOURS[key], linewidth=0.8, label="%s (MSE %.3g (rad/s)^2)" % (name, mse[key]))
        ax.axhline(0.0, color="black", linewidth=0.6)
        ax.set_ylabel("residual [rad/s]")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="upper right", fontsize=8)
    axes[-1].set_xlabel("time [s]")
    axes[0].set_title("Validation residuals, measured - predicted velocity (%s method)" % method)
    residuals_path = os.path.join(out_dir, "fig12_residuals.png")
    fig.savefig(residuals_path, dpi=110)
    plt.close(fig)
    return [velocity_path, residuals_path]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The ``demo`` subcommand's options.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The subcommand's parser.
    """
    parser.add_argument(
        "--out",
        metavar="DIR",
        help="write fig11_velocity.png, fig12_residuals.png, tables.txt and results.json into DIR "
        "(created if missing); without it only the tables are printed",
    )
    parser.add_argument(
        "--method",
        choices=("output_error", "paper"),
        default="output_error",
        help="estimator method whose models the figures and the top level of results.json show "
        "(default: %(default)s); the tables show both",
    )
    parser.add_argument(
        "--robustness",
        action="store_true",
        help="also validate on the eight further trajectories of bonl_demo's robustness check (about 3 s more)",
    )


def run(args: argparse.Namespace) -> int:
    """Run the demo for parsed arguments (``--out``, ``--method``, ``--robustness``).

    Parameters
    ----------
    args : argparse.Namespace

    Returns
    -------
    int
        The exit status: 0, or 1 when an output could not be written.
    """
    from . import plant

    result = plant.experiment(method=args.method, robustness=args.robustness)
    report = format_report(result)
    sys.stdout.write(report)
    if not args.out:
        sys.stdout.write("\n(use --out DIR to write the figures, tables.txt and results.json)\n")
        return 0

    os.makedirs(args.out, exist_ok=True)
    tables_path = os.path.join(args.out, "tables.txt")
    with open(tables_path, "w", encoding="utf-8") as f:
        f.write(report)
    results_path = os.path.join(args.out, "results.json")
    with open(results_path, "w", encoding="utf-8") as f:
        json.dump(results_json(result), f, indent=1, allow_nan=False)
        f.write("\n")
    written = [tables_path, results_path]
    status = 0
    try:
        written += plot_figures(result, args.out)
    except ImportError as error:
        sys.stderr.write("bonl demo: cannot draw the figures (%s); pip install 'bonl[plot]'\n" % error)
        status = 1
    sys.stdout.write("\nwrote %s\n" % ", ".join(written))
    return status


def main(argv: Optional[Sequence[str]] = None) -> int:
    """``python -m bonl.demo``: the same as ``python -m bonl demo``.

    Parameters
    ----------
    argv : sequence of str, optional
        The arguments; None: ``sys.argv[1:]``.

    Returns
    -------
    int
        The exit status.
    """
    parser = argparse.ArgumentParser(prog="python -m bonl demo", description=__doc__.split("\n\n")[0])
    add_arguments(parser)
    return run(parser.parse_args(argv))


if __name__ == "__main__":
    sys.exit(main())
