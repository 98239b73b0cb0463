"""``python -m bonl control``: the tracking experiment (docs/how-to/control.md), as ``bonl_demo --control``
runs it. A reference joint velocity is tracked on the simulated plant by a PI loop alone, by the PI
loop plus each identified model's inverse as feedforward, and, while the plant changes mid-run, by the
PI loop plus the adaptive P-H-W feedforward. Prints the tracking RMS of each; ``--json FILE`` writes
``{"tracking_rms": {"PI": ..., model name: ...}, "plant_change": {...}, ...}`` (the same document as
``bonl_demo --control --json``) and ``--figure FILE`` the reference, the joint rates and the commands.
"""

from __future__ import annotations

import argparse
import json

from . import experiment


def report(result) -> str:
    """The two tables ``bonl_demo --control`` prints."""
    pi = result.run("PI").rms
    lines = ["%-28s %14s %14s" % ("controller", "RMS [rad/s]", "vs PI alone")]
    for run in result.runs:
        if not run.plant_changes:
            lines.append("%-28s %14.5f %13.1f%%" % (run.label, run.rms, 100.0 * (run.rms / pi - 1.0)))
    lines += ["", "under the plant change: RMS before it and 20-40 s after it",
              "%-28s %14s %14s %10s" % ("controller", "before", "after", "ratio")]
    for run in result.runs:
        if run.plant_changes:
            lines.append("%-28s %14.5f %14.5f %10.2f" % (run.label, run.rms_before_change,
                                                         run.rms_after_change,
                                                         run.rms_after_change / run.rms_before_change))
    return "\n".join(lines)


def results(result) -> dict:
    """The --json document (bonl_demo --control --json's)."""
    adaptive = result.runs[-1]
    return {
        "tracking_rms": result.tracking_rms,
        "plant_change": {run.controller: {"before": run.rms_before_change, "after": run.rms_after_change}
                         for run in result.runs if run.plant_changes},
        "pi": {"proportional_gain": result.proportional_gain, "integral_time": result.integral_time},
        "adaptive": {"rederivations": adaptive.rederivations, "refused": adaptive.refused},
    }


def figure(result, path: str) -> None:
    """Reference and joint rates (PI alone, PI + P-H-W), then the commands; the adaptive run under the change."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = result.time
    fig, axes = plt.subplots(3, 1, figsize=(10, 9), sharex=True)
    axes[0].plot(t, result.reference, "k", lw=1.5, label="reference")
    for name, colour in (("PI", "tab:orange"), ("PseudoHammersteinWiener", "tab:blue")):
        axes[0].plot(t, result.run(name).joint_rate, colour, lw=0.8, label=result.run(name).label)
    axes[0].set_ylabel("joint rate [rad/s]")
    axes[0].set_title("Tracking on the plant (no change)")
    axes[0].legend(loc="upper right", fontsize=8)
    for name, colour in (("PI", "tab:orange"), ("PseudoHammersteinWiener", "tab:blue")):
        axes[1].plot(t, result.run(name).command, colour, lw=0.8, label=result.run(name).label)
    axes[1].set_ylabel("command V [V]")
    axes[1].legend(loc="upper right", fontsize=8)
    change = result.runs[-1]
    fixed = result.run("PseudoHammersteinWiener", True)
    axes[2].plot(t, result.reference - fixed.joint_rate, "tab:red", lw=0.6, label=fixed.label)
    axes[2].plot(t, result.reference - change.joint_rate, "tab:green", lw=0.6, label=change.label)
    axes[2].axvline(40.0, color="k", ls="--", lw=1)
    axes[2].set_ylabel("tracking error [rad/s]")
    axes[2].set_xlabel("time [s]")
    axes[2].set_title("The plant changes at 40 s (dashed): fixed and adaptive P-H-W feedforward")
    axes[2].legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--method", choices=("paper", "output_error"), default="paper",
                        help="which method's identified models feed forward (default: paper)")
    parser.add_argument("--json", metavar="FILE", help="write the tracking RMS of every controller as JSON")
    parser.add_argument("--figure", metavar="FILE", help="write the figure (PNG or SVG, by its extension)")


def run(args: argparse.Namespace) -> int:
    result = experiment.run_tracking_experiment(method=args.method)
    print("PI by SIMC from the ARX model: Kc = %.4g V/(rad/s), tau_I = %.4g s" % (result.proportional_gain,
                                                                                 result.integral_time))
    print(report(result))
    if args.json:
        with open(args.json, "w") as out:
            json.dump(dict(results(result), method=args.method), out, indent=1)
            out.write("\n")
    if args.figure:
        figure(result, args.figure)
    return 0
