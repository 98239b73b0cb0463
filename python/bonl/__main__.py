"""The ``bonl`` command line (``python -m bonl`` or the ``bonl`` console script).

Subcommands
-----------
demo
    The paper's experiment on the simulated excavator dipper joint: Tables 1 and 2 for both
    estimator methods, and with ``--out DIR`` the paper's Figs. 11 and 12, tables.txt and
    results.json (see :mod:`bonl.demo`).
control
    The tracking experiment: PI, PI plus each identified model's inverse as feedforward, and the
    adaptive P-H-W feedforward while the plant changes (see :mod:`bonl.tracking`).
"""

from __future__ import annotations

import argparse
import sys
from typing import Callable, Optional, Sequence


def _demo_arguments(parser: argparse.ArgumentParser) -> None:
    from . import demo

    demo.add_arguments(parser)


def _demo_run(args: argparse.Namespace) -> int:
    from . import demo

    return demo.run(args)


def _control_arguments(parser: argparse.ArgumentParser) -> None:
    from . import tracking

    tracking.add_arguments(parser)


def _control_run(args: argparse.Namespace) -> int:
    from . import tracking

    return tracking.run(args)


#: The subcommands: (name, one-line help, description, add_arguments(parser), run(args) -> int).
#: A new subcommand is one more entry here.
COMMANDS: Sequence[tuple] = (
    (
        "demo",
        "run the paper's experiment on the simulated excavator (Tables 1-2, Figs. 11-12)",
        "Identify ARX, Hammerstein, H-W and P-H-W with the paper's orders on the simulated 20 t "
        "excavator's dipper joint (docs/plant.md), validate them by free-run simulation, print "
        "Table 1 (parameters) and Table 2 (validation MSE of the velocity) for both estimator "
        "methods, and with --out DIR write fig11_velocity.png, fig12_residuals.png, tables.txt and "
        "results.json.",
        _demo_arguments,
        _demo_run,
    ),
    (
        "control",
        "track a reference velocity with PI and the identified models' inverses as feedforward",
        "On the simulated excavator's dipper joint, track a reference joint velocity with a PI loop alone, "
        "with each identified model's inverse as feedforward, and with the adaptive P-H-W feedforward while "
        "the plant changes (pilot hysteresis x2, bulk modulus -30%); print the tracking RMS of each, with "
        "--json FILE write them ({\"tracking_rms\": {...}}), with --figure FILE plot them (docs/control.md).",
        _control_arguments,
        _control_run,
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
