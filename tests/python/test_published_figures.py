"""Published figures stay true: every copy of a generated table in the docs is the table the
committed results file gives (docs/results/*_summary.md, written with the results by their script),
between its markers. The results themselves are re-computed by ctest (examples/online_accuracy_quick)."""

import json
import pathlib

import pytest

import bonl
from conftest import load_measured_data_example

ROOT = pathlib.Path(__file__).resolve().parents[2]

QUOTES = [
    ("online_accuracy_summary", ROOT / "docs" / "results" / "online_accuracy_summary.md",
     [ROOT / "docs" / "explanation" / "estimation_methods.md", ROOT / "docs" / "algorithm.md"]),
    ("plant_experiment_summary", ROOT / "docs" / "results" / "plant_experiment_summary.md",
     [ROOT / "README.md", ROOT / "docs" / "explanation" / "paper_experiment.md"]),
    ("measured_data_summary", ROOT / "docs" / "results" / "measured_data_summary.md",
     [ROOT / "docs" / "measured_data.md"]),
    ("tracking_summary", ROOT / "docs" / "results" / "tracking_summary.md",
     [ROOT / "docs" / "control.md"]),
    ("benchmarks_summary", ROOT / "docs" / "results" / "benchmarks_summary.md", [ROOT / "docs" / "benchmarks.md"]),
    ("joint_angle_summary", ROOT / "docs" / "results" / "joint_angle_summary.md", [ROOT / "docs" / "plant.md"]),
    ("bench_summary", ROOT / "docs" / "results" / "bench_summary.md",
     [ROOT / "docs" / "performance.md"]),
]


def quoted_block(text, marker):
    begin, end = "<!-- %s: begin" % marker, "<!-- %s: end" % marker
    assert text.count(begin) == 1 and text.count(end) == 1, "one %s block expected" % marker
    block = text.split(begin, 1)[1].split("\n", 1)[1]
    return block.split(end, 1)[0]


@pytest.mark.parametrize("marker, source, pages", QUOTES, ids=[q[0] for q in QUOTES])
def test_quoted_tables_match_their_results(marker, source, pages):
    table = source.read_text()
    for page in pages:
        assert quoted_block(page.read_text(), marker) == table, (
            "%s quotes an old %s: run the script that writes %s" % (page.name, marker, source.name))


def test_the_plant_experiment_gives_its_committed_figures():
    """docs/results/plant_experiment.json (bonl_demo --json, scripts/plant_experiment.sh) is what the
    experiment gives today: every validation MSE, identified and online, to 1e-9 relative."""
    committed = json.loads((ROOT / "docs" / "results" / "plant_experiment.json").read_text())
    result = bonl.experiment.run_paper_experiment()
    for method, entry in committed["methods"].items():
        assert set(entry["mse"]) == set(result.model_names), method
        for model, mse in entry["mse"].items():
            assert result.method(method).mse[model] == pytest.approx(mse, rel=1e-9), (method, model)
    for method, entry in committed["online"].items():
        for model, mse in entry.items():
            assert result.method(method).online_mse[model] == pytest.approx(mse, rel=1e-9), ("online", method, model)


def test_the_measured_data_give_their_committed_figures():
    """docs/results/measured_data.json (scripts/measured_data.sh) holds the structure chosen for each
    model on each data set; identified again on the estimation data, each gives its committed
    validation RMS to 1e-9 relative (the selection itself is re-run by test_measured_data.py)."""
    md = load_measured_data_example()
    committed = json.loads((ROOT / "docs" / "results" / "measured_data.json").read_text())
    act, tanks = md.load_actuator(), md.load_cascaded_tanks()
    cases = {
        "actuator": (act["u"][:512], act["y"][:512], act["u"], act["y"], 512),
        "cascaded_tanks": (tanks["uEst"], tanks["yEst"], tanks["uVal"], tanks["yVal"], 0),
    }
    classes = {model.__name__: model for model in md.MODELS}
    assert set(committed) == set(cases)
    for case, (u_est, y_est, u_sim, y_sim, score_from) in cases.items():
        assert set(committed[case]) == set(md.NAMES), case
        for name, chosen in committed[case].items():
            u0, y0 = md.offset_constants(chosen["offset"], u_est, y_est)
            structure = md.structure(classes[name], chosen["orders"])
            model = bonl.identify(structure, u_est - u0, y_est - y0, **md.settings(classes[name]))
            simulated = md.simulate(model, u_sim - u0, y0)
            assert simulated is not None, (case, name)
            rms = md.rms(simulated[score_from:] - y_sim[score_from:])
            assert rms == pytest.approx(chosen["validation_rms"], rel=1e-9), (case, name)


def test_the_benchmark_summary_is_the_committed_full_run():
    """docs/results/bench_summary.md is what bench/report.py makes of the committed full run's figures
    (bench/RESULTS.json, written by the same bench/run as bench/RESULTS.md): a quoted speed cannot
    drift from the run it names. (The speeds themselves are measured by bench/run, never in a test.)"""
    import importlib.util

    spec = importlib.util.spec_from_file_location("bench_report", ROOT / "bench" / "report.py")
    report = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(report)
    flat = json.loads((ROOT / "bench" / "RESULTS.json").read_text())
    assert report.summary(flat) == (ROOT / "docs" / "results" / "bench_summary.md").read_text()
    results_md = (ROOT / "bench" / "RESULTS.md").read_text()
    assert "(commit %s)" % flat["machine"]["git"] in results_md, "bench/RESULTS.md and RESULTS.json are of different runs"


def test_the_joint_angle_models_give_their_committed_figures():
    """docs/results/joint_angle.json (examples/joint_angle/joint_angle.py): the paper's four models on
    the simulated joint's angle, without and with an integrator, recomputed to 1e-9 relative; the table
    docs/plant.md quotes is the one the results give."""
    import importlib.util
    spec = importlib.util.spec_from_file_location("joint_angle", ROOT / "examples" / "joint_angle" / "joint_angle.py")
    joint_angle = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(joint_angle)
    committed = json.loads((ROOT / "docs" / "results" / "joint_angle.json").read_text())
    results = joint_angle.run()
    assert [(r["model"], r["ni"]) for r in results["rows"]] == [(r["model"], r["ni"]) for r in committed["rows"]]
    for new, old in zip(results["rows"], committed["rows"]):
        assert new["validation_rms"] == pytest.approx(old["validation_rms"], rel=1e-9), (new["model"], new["ni"])
        assert new["json"]["orders"].get("ni", 0) == new["ni"]
    assert joint_angle.table(committed) == (ROOT / "docs" / "results" / "joint_angle_summary.md").read_text()
