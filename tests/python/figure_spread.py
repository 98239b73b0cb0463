"""How far the committed figures move from one build of the extension to another (figures.py's FIGURE_REL
is a multiple of it). Recomputes, through the same calls as the committed-figure tests, every figure
they compare with a committed results file, and writes them by family:

    python tests/python/figure_spread.py --json FILE [--families F,G]     (the installed bonl's figures)
    python tests/python/figure_spread.py --compare A.json B.json [--max M] (largest relative difference)

scripts/figure_spread.sh runs it with a gcc and a clang-14 build of the extension and compares."""

import argparse
import csv
import importlib.util
import json
import pathlib
import sys
import warnings

import bonl

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(ROOT / "examples" / "datasets"))
sys.path.insert(0, str(HERE))


def _module(path, name):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def datasets():
    """test_datasets.py: every committed data-set model rescored on its tests (and from rest)."""
    import test_datasets

    figures = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bonl.ExtrapolationWarning)
        for name in test_datasets.SCRIPTS:
            benchmark = __import__(name).make()
            for row in test_datasets._results(name)["rows"]:
                model = bonl.load_model(json.dumps(row["json"]))
                for test in benchmark.tests:
                    figures[f"{name} {row['model']} {test.name}"] = test.rms(model)
                    if test.window:
                        figures[f"{name} {row['model']} {test.name} from rest"] = test.rms(model, from_rest=True)
    return figures


def datasets_selection():
    """test_datasets.py: the quick data sets selected again from scratch."""
    import test_datasets

    figures = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bonl.ExtrapolationWarning)
        for name in test_datasets.QUICK:
            for row in __import__("benchmark").run(__import__(name).make())["rows"]:
                for test, rms in row["test_rms"].items():
                    figures[f"{name} {row['model']} {json.dumps(row['orders'])} {test}"] = rms
    return figures


def perturbation():
    """test_datasets.py: the tanks' chosen structures identified on the perturbed records."""
    import test_datasets

    rerun = __import__("perturbation").structures(__import__("cascaded_tanks").make(),
                                                  test_datasets._results("cascaded_tanks"))
    return {f"{model} seed {i - 1}": figure for model, row in rerun.items()
            for i, figure in enumerate([row["unperturbed"], *row["perturbed"]])}


def _experiment_figures(result, prefix=""):
    figures = {}
    for method in ("output_error", "paper"):
        entry = result.method(method)
        for name in result.model_names:
            figures[f"{prefix}{method} {name} mse"] = entry.mse[name]
            figures[f"{prefix}{method} {name} online mse"] = entry.online_mse[name]
        figures[f"{prefix}{method} P-H-W c"] = entry.models["PseudoHammersteinWiener"].params["c"]
    return figures


def plant_experiment():
    """test_published_figures.py: the paper experiment's validation MSEs, identified and online."""
    return _experiment_figures(bonl.experiment.run_paper_experiment())


def sweep():
    """test_published_figures.py: the experiment at each point of docs/results/sweep.csv."""
    published = _module(HERE / "test_published_figures.py", "published_figures")
    with open(ROOT / "docs" / "results" / "sweep.csv", newline="") as f:
        points = sorted({(row["parameter"], float(row["value"])) for row in csv.DictReader(f)})
    figures = {}
    for parameter, value in points:
        result = bonl.experiment.run_paper_experiment(published.plant_of(parameter, value))
        figures.update(_experiment_figures(result, f"{parameter}={value} "))
    return figures


def measured_data():
    """test_published_figures.py: the structures of docs/results/measured_data.json identified again."""
    from conftest import load_measured_data_example

    md = load_measured_data_example()
    committed = json.loads((ROOT / "docs" / "results" / "measured_data.json").read_text())
    act, tanks = md.load_actuator(), md.load_cascaded_tanks()
    cases = {"actuator": (act["u"][:512], act["y"][:512], act["u"], act["y"], 512),
             "cascaded_tanks": (tanks["uEst"], tanks["yEst"], tanks["uVal"], tanks["yVal"], 0)}
    classes = {model.__name__: model for model in md.MODELS}
    figures = {}
    for case, (u_est, y_est, u_sim, y_sim, score_from) in cases.items():
        for name, chosen in committed[case].items():
            u0, y0 = md.offset_constants(chosen["offset"], u_est, y_est)
            model = bonl.identify(md.structure(classes[name], chosen["orders"]), u_est - u0, y_est - y0,
                                  **md.settings(classes[name]))
            simulated = md.simulate(model, u_sim - u0, y0)
            figures[f"{case} {name}"] = md.rms(simulated[score_from:] - y_sim[score_from:])
    return figures


def joint_angle():
    """test_published_figures.py: examples/joint_angle's four models, without and with an integrator."""
    results = _module(ROOT / "examples" / "joint_angle" / "joint_angle.py", "joint_angle").run()
    return {f"{row['model']} ni={row['ni']}": row["validation_rms"] for row in results["rows"]}


def tracking():
    """test_tracking.py: the tracking RMS of every controller, before and after the plant changes."""
    result = bonl.experiment.run_tracking_experiment()
    figures = dict(result.tracking_rms)
    for name in json.loads((ROOT / "docs" / "results" / "tracking.json").read_text())["plant_change"]:
        run = result.run(name, True)
        figures[f"{name} before change"] = run.rms_before_change
        figures[f"{name} after change"] = run.rms_after_change
    figures["PI proportional gain"] = result.proportional_gain
    return figures


FAMILIES = {f.__name__: f for f in (datasets, datasets_selection, perturbation, plant_experiment, sweep,
                                     measured_data, joint_angle, tracking)}
#: Below this magnitude a figure is zero for the comparison (P-H-W's c where the estimator puts it at
#: 0: a relative difference of two roundings of zero says nothing; the tests compare it absolutely).
ZERO = 1e-12
#: The key a family's figures hold instead when its pipeline raised.
ERROR = "error"


def relative(a, b):
    if max(abs(a), abs(b)) < ZERO:
        return 0.0
    return abs(a - b) / max(abs(a), abs(b))


def compare(a, b):
    """Per family: the largest relative difference, the figure where it is, and how many figures."""
    spread = {}
    for family in a.keys() & b.keys():
        errors = [side[family][ERROR] for side in (a, b) if ERROR in side[family]]
        if errors:  # the pipeline itself failed in a build: no figures to compare
            spread[family] = {"max_relative": float("inf"), "error": "failed in a build: " + " / ".join(errors)}
            continue
        if a[family].keys() != b[family].keys():  # a selection chose other structures
            only = sorted(a[family].keys() ^ b[family].keys())
            spread[family] = {"max_relative": float("inf"), "error": f"different figures, e.g. {only[0]}"}
            continue
        worst = max(a[family], key=lambda key: relative(a[family][key], b[family][key]))
        zeros = [abs(a[family][k] - b[family][k]) for k in a[family]
                 if max(abs(a[family][k]), abs(b[family][k])) < ZERO]
        spread[family] = {"max_relative": relative(a[family][worst], b[family][worst]), "at": worst,
                          "figures": len(a[family]),
                          "equal": sum(a[family][k] == b[family][k] for k in a[family]),
                          "zeros": len(zeros), "max_absolute_at_zero": max(zeros, default=0.0)}
    return spread


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", type=pathlib.Path, help="write the installed bonl's figures here")
    parser.add_argument("--families", default=",".join(FAMILIES), help="comma-separated (default: all)")
    parser.add_argument("--compare", nargs=2, type=pathlib.Path, metavar=("A", "B"),
                        help="print the largest relative difference per family between two such files")
    parser.add_argument("--max", type=float, help="with --compare: fail when the largest difference exceeds this")
    args = parser.parse_args()
    if args.compare:
        a, b = (json.loads(p.read_text()) for p in args.compare)
        spread = compare(a, b)
        for family, s in sorted(spread.items()):
            if "error" in s:
                print(f"{family:20s} {s['error']}")
                continue
            print(f"{family:20s} {s['max_relative']:.2e} ({s['equal']}/{s['figures']} figures bit-equal;"
                  f" largest at {s['at']}" + (f"; {s['zeros']} at zero, apart by {s['max_absolute_at_zero']:.1e}"
                                              if s["zeros"] else "") + ")")
        largest = max(s["max_relative"] for s in spread.values())
        print(f"{'all':20s} {largest:.2e}")
        if args.max is not None and not largest <= args.max:
            sys.exit(f"figure_spread.py: the figures differ by {largest:.2e}, more than {args.max:.2e}")
        return
    figures = {}
    for name in args.families.split(","):
        try:
            figures[name] = FAMILIES[name]()
        except Exception as error:  # recorded: a build where a pipeline throws is part of the spread
            figures[name] = {ERROR: f"{type(error).__name__}: {error}"}
        print(f"{name}: {len(figures[name])} figures", flush=True)
    if args.json:
        args.json.write_text(json.dumps(figures, indent=1) + "\n")


if __name__ == "__main__":
    main()
