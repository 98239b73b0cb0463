"""``python -m bonl demo``: the paper's experiment on the simulated excavator dipper joint.

Runs :func:`bonl.experiment.run_paper_experiment` (what the C++ ``bonl_demo`` runs: identification on
the paper's multi-sine, validation by free-run simulation on a smooth random signal, the output-error
method (bonl's default) and the paper's) and formats its result: Table 1 (identified parameters) and
Table 2 (validation MSE of the velocity) in the paper's layout for both methods, the online estimates'
validation MSE, and with ``--out DIR``

- ``DIR/fig11_velocity.png``: measured and predicted validation velocity of every model (the paper's
  Fig. 11), over the whole record and zoomed;
- ``DIR/fig12_residuals.png``: the residuals, measured - predicted, one panel per model (Fig. 12);
- ``DIR/tables.txt``: the printed tables;
- ``DIR/results.json``: ``{"mse": {model name: mse}, "params": {...}, "method": ..., "methods":
  {"output_error": {...}, "paper": {...}}, "online": {...}, ...}`` as ``bonl_demo --json``.

Models are named by their class names (``result.model_names``); the tables and figures label them as
the paper does (``ModelResult.label``) and list them in its order, the proposed model first.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
from typing import Any, Dict, List, Optional, Sequence

#: Line colours of the figures, in the paper's column order (the same as bonl_demo's sweep chart).
PALETTE = ("#d62728", "#ff7f0e", "#2ca02c", "#1f77b4", "#9467bd", "#8c564b", "#e377c2")


def columns(method_result: Any) -> List[Any]:
    """A method's models in the paper's column order: the proposed model (the last of the experiment's) first.

    Parameters
    ----------
    method_result : bonl.experiment.MethodResult

    Returns
    -------
    list of bonl.experiment.ModelResult
    """
    return list(reversed(list(method_result.models.values())))


def _cell(value: Optional[float]) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return " %12s" % ""
    return " %12.4g" % value


def _join_words(words: Sequence[str]) -> str:
    """'a, b and c'."""
    if len(words) < 2:
        return "".join(words)
    return ", ".join(words[:-1]) + " and " + words[-1]


def format_tables(method_result: Any) -> str:
    """Table 1 and Table 2 of one method, in the paper's layout (as ``bonl_demo`` prints them).

    Parameters
    ----------
    method_result : bonl.experiment.MethodResult

    Returns
    -------
    str
        The two tables, newline-terminated.
    """
    from .experiment import published_score

    cols = columns(method_result)
    header = "".join(" %12s" % c.label for c in cols)
    lines: List[str] = ["", "Table 1. Identification results (method: %s)" % method_result.method]
    lines.append("%-10s" % "Parameter" + header)
    # The rows: every parameter label, in the order the experiment's models first name them.
    tables = [dict(c.parameters) for c in cols]
    rows: List[str] = []
    for c in reversed(cols):
        rows += [label for label, _ in c.parameters if label not in rows]
    for row in rows:
        lines.append("%-10s" % row + "".join(_cell(table.get(row)) for table in tables))

    lines.append("")
    lines.append("Table 2. MSE of the identified models (validation velocity, free-run simulation)")
    lines.append("%-10s" % "Error" + header)
    lines.append("%-10s" % "MSE" + "".join(" %12.4e" % c.mse for c in cols) + "   (rad/s)^2")
    proposed, others = cols[0], cols[1:]
    lower = ["%.0f%%" % (100.0 * (1.0 - proposed.mse / c.mse)) for c in others]
    line = "%s's MSE is %s lower than %s" % (proposed.label, _join_words(lower), _join_words([c.label + "'s" for c in others]))
    published = [published_score(c.name) for c in others]
    published = ["%d%%" % p[1] for p in published if p is not None]
    if published:
        line += " (paper: %s)" % ", ".join(published)
    lines.append(line)
    return "\n".join(lines) + "\n"


def format_report(result: Any) -> str:
    """Everything ``python -m bonl demo`` prints: the plant's runs, then both methods' tables.

    Parameters
    ----------
    result : bonl.experiment.PaperExperimentResult

    Returns
    -------
    str
    """
    parameters = result.parameters
    out = [
        "Plant: 20 t excavator dipper joint (docs/explanation/plant.md), pilot hysteresis %.0f%%, pin backlash %.1f mrad."
        % (100 * parameters.pilot_hysteresis, 1000 * parameters.joint_backlash),
        "Records: 50 s at 100 Hz, 10 repeats averaged, 10 Hz low-pass, differentiated. Identification: "
        "paper's multi-sine; validation: smooth random signal (1 Hz band).",
    ]
    for name in ("identification", "validation"):
        record = getattr(result, name)
        out.append(
            "  %-14s: piston %.3f-%.3f m of %.2f m%s, CVODE %d steps"
            % (
                name,
                record.min_position,
                record.max_position,
                parameters.stroke,
                " (REACHED AN END STOP)" if record.reached_end_stop else "",
                record.steps,
            )
        )
    out.append("  plant simulation and processing: %.2f s" % result.seconds.plant)
    text = "\n".join(out) + "\n"
    # The paper's method first, then bonl's, as bonl_demo prints them.
    for method in ("paper", "output_error"):
        text += format_tables(result.method(method))
    text += format_online(result)
    text += "\nidentification and validation: %.2f s\n" % result.seconds.identification
    if result.robustness_trajectories:
        text += format_robustness(result)
    return text


def format_online(result: Any) -> str:
    """The online table: each method's recursive estimate alone, beside ``identify()``'s, as ``bonl_demo`` prints it.

    Parameters
    ----------
    result : bonl.experiment.PaperExperimentResult

    Returns
    -------
    str
    """
    identified = columns(result.method("output_error"))
    lines = [
        "",
        "Online: the recursive estimator alone after one pass (no refinement), validation MSE",
        "%-13s" % "method" + "".join(" %12s" % c.label for c in identified),
    ]
    for method, entry in result.methods.items():
        lines.append("%-13s" % method + "".join(" %12.4e" % c.online_mse for c in columns(entry)) + "   (rad/s)^2")
    lines.append(
        "%-13s" % "identify()"
        + "".join(" %12.4e" % c.mse for c in identified)
        + "   (identify(): recursive estimate refined)"
    )
    return "\n".join(lines) + "\n"


def format_robustness(result: Any) -> str:
    """The robustness table: validation MSE on the further trajectories, as ``bonl_demo`` prints it.

    The counts check the paper's ranking: the proposed model below Hammerstein, Hammerstein below ARX;
    and place each model the paper does not report against the proposed model and Hammerstein.

    Parameters
    ----------
    result : bonl.experiment.PaperExperimentResult
        Run with ``robustness=True``.

    Returns
    -------
    str
    """
    from .experiment import published_score

    n = result.robustness_trajectories
    methods = {name: columns(entry) for name, entry in result.methods.items()}
    lines = [
        "",
        "Robustness: validation MSE on %d further trajectories (smooth random x4, other multi-sines x4)" % n,
        "%-4s %-9s" % ("", "method") + "".join(" %11s" % c.label for c in next(iter(methods.values()))),
    ]
    for i in range(n):
        for method, cols in methods.items():
            lines.append("%-4d %-12s" % (i + 1, method) + "".join(" %11.3e" % c.robustness_mse[i] for c in cols))
    for method, cols in methods.items():
        by_name = {c.name: c.robustness_mse for c in cols}
        proposed, hammerstein, arx = cols[0], by_name["Hammerstein"], by_name["ARX"]
        proposed_best = [proposed.robustness_mse[i] < hammerstein[i] for i in range(n)]
        h_over_arx = [hammerstein[i] < arx[i] for i in range(n)]
        lines.append(
            "%s method: %s < Hammerstein on %d/%d, Hammerstein < ARX on %d/%d, both on %d/%d"
            % (method, proposed.label, sum(proposed_best), n, sum(h_over_arx), n,
               sum(a and b for a, b in zip(proposed_best, h_over_arx)), n)
        )
        # A model the paper does not report, against the proposed model and Hammerstein.
        for c in cols:
            if published_score(c.name) is not None:
                continue
            lines.append(
                "%s method: %s < %s on %d/%d, %s < Hammerstein on %d/%d"
                % (method, c.label, proposed.label, sum(c.robustness_mse[i] < proposed.robustness_mse[i] for i in range(n)),
                   n, c.label, sum(c.robustness_mse[i] < hammerstein[i] for i in range(n)), n)
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


def results_json(result: Any, method: str) -> Dict[str, Any]:
    """The JSON-ready summary of an experiment (the layout of ``bonl_demo --json``).

    Parameters
    ----------
    result : bonl.experiment.PaperExperimentResult
    method : str
        ``"output_error"`` or ``"paper"``: whose results go to the top-level ``mse`` and ``params``.

    Returns
    -------
    dict
        ``mse``, ``params`` and ``method`` of the chosen method; ``methods``: both methods' ``mse``
        and ``params``; ``online``: both methods' online MSE; ``runs``: the plant runs' ranges and CVODE
        steps; ``plant_parameters``; ``seconds``; and ``robustness`` (one ``{method: {model: mse}}``
        per trajectory) when it was run. Models are keyed by name; non-finite numbers become null.
    """

    def summary(entry: Any) -> Dict[str, Any]:
        return {"mse": dict(entry.mse), "params": {name: m.params for name, m in entry.models.items()}}

    chosen = summary(result.method(method))
    runs = {}
    for name in ("identification", "validation"):
        record = getattr(result, name)
        runs[name] = {key: getattr(record, key) for key in ("min_position", "max_position", "reached_end_stop", "steps")}
    out: Dict[str, Any] = {
        "mse": chosen["mse"],
        "params": chosen["params"],
        "method": method,
        "methods": {name: summary(entry) for name, entry in result.methods.items()},
        "online": {name: dict(entry.online_mse) for name, entry in result.methods.items()},
        "runs": runs,
        "plant_parameters": result.parameters.to_dict(),
        "seconds": result.seconds.to_dict(),
    }
    if result.robustness_trajectories:
        out["robustness"] = [
            {name: {m.name: m.robustness_mse[i] for m in entry.models.values()} for name, entry in result.methods.items()}
            for i in range(result.robustness_trajectories)
        ]
    return _finite_or_none(out)


def plot_figures(result: Any, method: str, out_dir: str) -> List[str]:
    """Write the paper's Fig. 11 (velocity) and Fig. 12 (residuals) for one method.

    Parameters
    ----------
    result : bonl.experiment.PaperExperimentResult
    method : str
        ``"output_error"`` or ``"paper"``.
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

    validation = result.validation
    t = validation.time
    y = validation.velocity
    cols = columns(result.method(method))
    colours = [PALETTE[i % len(PALETTE)] for i in range(len(cols))]

    # Fig. 11: measured and predicted velocity; the lower panel zooms on 10 s so the curves separate.
    fig, axes = plt.subplots(2, 1, figsize=(11, 8), constrained_layout=True)
    zoom = (20.0, 30.0)
    for ax, window in zip(axes, (None, zoom)):
        mask = np.ones_like(t, dtype=bool) if window is None else (t >= window[0]) & (t <= window[1])
        ax.plot(t[mask], y[mask], color="black", linewidth=1.6, label="measured")
        for c, colour in zip(cols, colours):
            ax.plot(t[mask], c.simulated[mask], color=colour, linewidth=1.0, label="%s (MSE %.3g)" % (c.label, c.mse))
        ax.set_xlabel("time [s]")
        ax.set_ylabel("angular velocity [rad/s]")
        ax.grid(True, alpha=0.3)
        if window is None:
            ax.set_title("Validation: measured and predicted joint velocity (free-run simulation, %s method)" % method)
            ax.axvspan(zoom[0], zoom[1], color="grey", alpha=0.12)
            ax.legend(loc="upper right", fontsize=8, ncol=len(cols) + 1)
        else:
            ax.set_title("Zoom on %g-%g s" % window)
    velocity_path = os.path.join(out_dir, "fig11_velocity.png")
    fig.savefig(velocity_path, dpi=110)
    plt.close(fig)

    # Fig. 12: residuals measured - predicted, one panel per model, shared axes.
    fig, axes = plt.subplots(len(cols), 1, figsize=(11, 9), sharex=True, sharey=True, constrained_layout=True)
    for ax, c, colour in zip(axes, cols, colours):
        ax.plot(t, y - c.simulated, color=colour, linewidth=0.8, label="%s (MSE %.3g (rad/s)^2)" % (c.label, c.mse))
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
    from .experiment import run_paper_experiment

    result = run_paper_experiment(robustness=args.robustness)
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
        json.dump(results_json(result, args.method), f, indent=1, allow_nan=False)
        f.write("\n")
    written = [tables_path, results_path]
    status = 0
    try:
        written += plot_figures(result, args.method, args.out)
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
