"""The ``bonl`` command line (``python -m bonl`` or the ``bonl`` console script).

Subcommands
-----------
demo
    The paper's experiment on the simulated excavator dipper joint: Tables 1 and 2 for both
    estimator methods, and with ``--out DIR`` the paper's Figs. 11 and 12, tables.txt and
    results.json (see :mod:`bonl.demo`).
identify
    From a data file (CSV) to a model file: a structure search, or selection over a grid, the
    chosen model's summary beside a linear model's, its scores and figure (see
    :mod:`bonl.identify_command`).
simulate
    A model file's free run over a data file's input, written as CSV.
control
    The tracking experiment: PI, PI plus each identified model's inverse as feedforward, and the
    adaptive P-H-W feedforward while the plant changes (see :mod:`bonl.tracking`).
"""

from __future__ import annotations

import argparse
import importlib
import sys
from typing import Callable, Optional, Sequence


def _lazy(module: str, function: str) -> Callable:
    """``module.function`` of this package, imported at the first call: ``bonl --help`` and one
    subcommand do not import every other subcommand's dependencies (matplotlib, the plant)."""

    def call(*args):
        return getattr(importlib.import_module("." + module, __package__), function)(*args)

    return call


#: The subcommands: (name, one-line help, description, add_arguments(parser), run(args) -> int).
#: A new subcommand is one more entry here.
COMMANDS: Sequence[tuple] = (
    (
        "demo",
        "run the paper's experiment on the simulated excavator (Tables 1-2, Figs. 11-12)",
        "Identify ARX, Hammerstein, H-W and P-H-W with the paper's orders on the simulated 20 t "
        "excavator's dipper joint (docs/explanation/plant.md), validate them by free-run simulation, print "
        "Table 1 (parameters) and Table 2 (validation MSE of the velocity) for both estimator "
        "methods, and with --out DIR write fig11_velocity.png, fig12_residuals.png, tables.txt and "
        "results.json.",
        _lazy("demo", "add_arguments"),
        _lazy("demo", "run"),
    ),
    (
        "identify",
        "identify a model from a data file (CSV) and write its model file",
        "Find a model on the input and output columns of a data file (bonl.search: a structure search "
        "over every family, scored on held-out data, within --budget seconds), write it as a model file, "
        "and print every stage's choice and its summary beside the linear (ARX) model. --model and --orders "
        "select over a grid instead (bonl.select; an order with several comma-separated values is a grid); "
        "--test-from K "
        "keeps samples K on for a test; --scores and --figure write the scores (JSON) and the fit.",
        _lazy("identify_command", "identify_arguments"),
        _lazy("identify_command", "identify_run"),
    ),
    (
        "simulate",
        "simulate a model file over a data file's input (free run from rest) and write it as CSV",
        "Load a bonl model file, simulate it from rest over the input column of a data file and write the "
        "input and the simulated output as CSV; with --output COL also print the RMS error against it.",
        _lazy("identify_command", "simulate_arguments"),
        _lazy("identify_command", "simulate_run"),
    ),
    (
        "control",
        "track a reference velocity with PI and the identified models' inverses as feedforward",
        "On the simulated excavator's dipper joint, track a reference joint velocity with a PI loop alone, "
        "with each identified model's inverse as feedforward, and with the adaptive P-H-W feedforward while "
        "the plant changes (pilot hysteresis x2, bulk modulus -30%); print the tracking RMS of each, with "
        "--json FILE write them ({\"tracking_rms\": {...}}), with --figure FILE plot them (docs/how-to/control.md).",
        _lazy("tracking", "add_arguments"),
        _lazy("tracking", "run"),
    ),
)


def build_parser() -> argparse.ArgumentParser:
    """The ``bonl`` argument parser, one subparser per entry of :data:`COMMANDS`.

    Returns
    -------
    argparse.ArgumentParser
    """
    from ._bonl import __version__

    parser = argparse.ArgumentParser(
        prog="bonl",
        description="bonl: identification of block-oriented nonlinear models (ARX, Hammerstein, H-W, P-H-W) "
        "of electro-hydraulic machines, and a CVODE excavator-arm plant.",
    )
    parser.add_argument("--version", action="version", version="bonl " + str(__version__))
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name, short_help, description, add_arguments, run in COMMANDS:
        sub = subparsers.add_parser(name, help=short_help, description=description)
        add_arguments(sub)
        sub.set_defaults(run=run)
    return parser


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Entry point of the ``bonl`` console script and of ``python -m bonl``.

    Parameters
    ----------
    argv : sequence of str, optional
        The arguments; None: ``sys.argv[1:]``.

    Returns
    -------
    int
        The exit status: 0 on success, 1 on an error, 2 on a usage error.
    """
    parser = build_parser()
    args = parser.parse_args(argv)
    run: Optional[Callable[[argparse.Namespace], int]] = getattr(args, "run", None)
    if run is None:
        parser.print_help()
        return 2
    try:
        return int(run(args) or 0)
    except (ValueError, ArithmeticError, RuntimeError, OSError) as error:
        sys.stderr.write("bonl %s: %s\n" % (args.command, error))
        return 1


if __name__ == "__main__":
    sys.exit(main())
