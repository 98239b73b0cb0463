"""Published figures stay true: every copy of a generated table in the docs is the table the
committed results file gives (docs/results/*_summary.md, written with the results by their script),
between its markers. The results themselves are re-computed by ctest (examples/online_accuracy_quick)."""

import csv
import json
import pathlib

import pytest

import bonl
from conftest import load_measured_data_example
from figures import FIGURE_REL

ROOT = pathlib.Path(__file__).resolve().parents[2]

QUOTES = [
    ("online_accuracy_summary", ROOT / "docs" / "results" / "online_accuracy_summary.md",
     [ROOT / "docs" / "explanation" / "estimation_methods.md", ROOT / "docs" / "explanation" / "algorithm.md"]),
    ("plant_experiment_summary", ROOT / "docs" / "results" / "plant_experiment_summary.md",
     [ROOT / "README.md", ROOT / "docs" / "explanation" / "paper_experiment.md"]),
    ("sweep_summary", ROOT / "docs" / "results" / "sweep_summary.md",
     [ROOT / "docs" / "explanation" / "paper_experiment.md"]),
    ("measured_data_summary", ROOT / "docs" / "results" / "measured_data_summary.md",
     [ROOT / "docs" / "lab" / "measured_data.md"]),
    ("tracking_summary", ROOT / "docs" / "results" / "tracking_summary.md",
     [ROOT / "docs" / "how-to" / "control.md"]),
    ("benchmarks_summary", ROOT / "docs" / "results" / "benchmarks_summary.md", [ROOT / "docs" / "lab" / "benchmarks.md"]),
    ("joint_angle_summary", ROOT / "docs" / "results" / "joint_angle_summary.md", [ROOT / "docs" / "explanation" / "plant.md"]),
    ("bench_summary", ROOT / "docs" / "results" / "bench_summary.md",
     [ROOT / "docs" / "lab" / "performance.md"]),
    ("soak_summary", ROOT / "docs" / "results" / "soak_summary.md", [ROOT / "docs" / "lab" / "reliability.md"]),
]


def module_from(path, name):
    """The Python file at `path` (a script outside the package: a report, an example) as a module."""
    import importlib.util

    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


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
    experiment gives today: every validation MSE, identified and online, to FIGURE_REL."""
    committed = json.loads((ROOT / "docs" / "results" / "plant_experiment.json").read_text())
    result = bonl.experiment.run_paper_experiment()
    for method, entry in committed["methods"].items():
        assert set(entry["mse"]) == set(result.model_names), method
        for model, mse in entry["mse"].items():
            assert result.method(method).mse[model] == pytest.approx(mse, rel=FIGURE_REL), (method, model)
    for method, entry in committed["online"].items():
        for model, mse in entry.items():
            assert result.method(method).online_mse[model] == pytest.approx(mse, rel=FIGURE_REL), ("online", method, model)


def table_rows(markdown):
    """A markdown table's body rows as lists of cells, by their first cell (the header and rule skipped)."""
    lines = [line for line in markdown.splitlines() if line.startswith("|")][2:]
    return {cells[0]: cells[1:] for cells in ([c.strip() for c in line.strip("|").split("|")] for line in lines)}


def test_the_plant_experiment_summary_is_its_results_file():
    """The README's table and sentence (plant_experiment_summary.md) say what plant_experiment.json holds:
    each row's MSEs are the JSON's to three digits, and each model the paper does not report is ranked
    as the JSON ranks it."""
    committed = json.loads((ROOT / "docs" / "results" / "plant_experiment.json").read_text())
    summary = (ROOT / "docs" / "results" / "plant_experiment_summary.md").read_text()
    rows = table_rows(summary)
    scores = {
        "bonl output_error, identify()": committed["methods"]["output_error"]["mse"],
        "bonl output_error, online (one pass, the estimator's defaults)": committed["online"]["output_error"],
        "bonl paper (eqs. 21-31, with the default trace ceiling)": committed["methods"]["paper"]["mse"],
    }
    for row, mse in scores.items():
        assert sorted(rows[row][: len(mse)]) == sorted("%.3g" % v for v in mse.values()), row
    unpublished = [name for name in committed["mse"] if bonl.experiment.published_score(name) is None]
    assert unpublished == ["PrandtlIshlinskiiHammerstein"]
    ordinal = {1: "1st", 2: "2nd", 3: "3rd", 4: "4th", 5: "5th"}
    phrases = ["with bonl's output_error identify()", "online", "with the paper's method"]
    for name in unpublished:
        for phrase, mse in zip(phrases, scores.values()):
            rank = 1 + sum(v < mse[name] for v in mse.values())
            assert " %s %s" % (ordinal[rank], phrase) in summary, (name, phrase)


def plant_of(parameter, value):
    """The plant of a sweep row: the default with the swept parameter (both, for both_zero) set."""
    parameters = bonl.plant.Parameters()
    if parameter in ("pilot_hysteresis", "both_zero"):
        parameters.pilot_hysteresis = value
    if parameter in ("joint_backlash", "both_zero"):
        parameters.joint_backlash = value
    return parameters


def committed_sweep():
    with open(ROOT / "docs" / "results" / "sweep.csv", newline="") as f:
        return list(csv.DictReader(f))


def test_the_sweep_gives_its_committed_figures():
    """docs/results/sweep.csv (bonl_demo --sweep docs, scripts/plant_experiment.sh; the figure docs/results/sweep.svg is
    drawn from the same run) is what the sweep gives today: every model's validation MSE for both
    methods and P-H-W's c at every point, to the file's ten digits."""
    rows = committed_sweep()
    points = {}
    for row in rows:
        points.setdefault((row["parameter"], float(row["value"])), []).append(row)
    assert len(points) == 19 and all(len(r) == 2 for r in points.values())
    for (parameter, value), method_rows in points.items():
        result = bonl.experiment.run_paper_experiment(plant_of(parameter, value))
        assert {k[len("mse_"):] for k in method_rows[0] if k.startswith("mse_")} == set(result.model_names)
        for row in method_rows:
            m = result.method(row["method"])
            for name in result.model_names:
                assert m.mse[name] == pytest.approx(float(row["mse_" + name]), rel=FIGURE_REL), (parameter, value, row["method"], name)
            c = m.models["PseudoHammersteinWiener"].params["c"]
            assert c == pytest.approx(float(row["PseudoHammersteinWiener_c"]), rel=FIGURE_REL, abs=1e-15), (parameter, value)


def test_the_sweep_summary_is_its_results_file():
    """The sweep table of docs/explanation/paper_experiment.md (sweep_summary.md) holds docs/results/sweep.csv's output-error MSEs to three digits."""
    rows = {(r["parameter"], float(r["value"])): r for r in committed_sweep() if r["method"] == "output_error"}
    table = table_rows((ROOT / "docs" / "results" / "sweep_summary.md").read_text())
    assert len(table) == 11
    for plant, cells in table.items():
        if plant == "both zero":
            key = ("both_zero", 0.0)
        elif plant.startswith("pilot hysteresis "):
            key = ("pilot_hysteresis", float(plant.split()[-1].rstrip("%")) / 100)
        else:
            key = ("joint_backlash", float(plant.split()[-2]) / 1000)
        key = min(rows, key=lambda k: (k[0] != key[0], abs(k[1] - key[1])))
        mse = [float(v) for k, v in rows[key].items() if k.startswith("mse_")]
        assert sorted(cells[: len(mse)]) == sorted("%.3g" % v for v in mse), plant


def test_the_experiment_page_says_what_the_results_say_of_p_i_h():
    """The sentences of docs/explanation/paper_experiment.md on the Prandtl-Ishlinskii Hammerstein model (P-I-H), against the committed
    results (which the tests above tie to the code): with bonl's estimator between P-H-W and Hammerstein
    in the experiment, first with the paper's; in the sweep above P-H-W at every point with bonl's
    estimator, above Hammerstein up to 4% pilot hysteresis and below it from 5%; with the paper's
    estimator below its P-H-W at every point but both at zero, where its free run diverges."""
    committed = json.loads((ROOT / "docs" / "results" / "plant_experiment.json").read_text())
    ours, paper = committed["methods"]["output_error"]["mse"], committed["methods"]["paper"]["mse"]
    pih, phw = "PrandtlIshlinskiiHammerstein", "PseudoHammersteinWiener"
    assert ours[phw] < ours[pih] < ours["Hammerstein"]
    assert paper[pih] == min(paper.values())
    rows = committed_sweep()
    for row in rows:
        mse = {k[len("mse_"):]: float(v) for k, v in row.items() if k.startswith("mse_")}
        where = (row["parameter"], row["value"], row["method"])
        if row["method"] == "output_error":
            assert mse[pih] > mse[phw], where
            if row["parameter"] == "pilot_hysteresis":
                assert (mse[pih] < mse["Hammerstein"]) == (float(row["value"]) >= 0.05), where
        elif row["parameter"] == "both_zero":
            assert mse[pih] > 10 * mse["ARX"], where  # off the figure's scale: diverged
        else:
            assert mse[pih] < mse[phw], where


def test_the_measured_data_give_their_committed_figures():
    """docs/results/measured_data.json (scripts/measured_data.sh) holds the structure chosen for each
    model on each data set; identified again on the estimation data, each gives its committed
    validation RMS to FIGURE_REL (the selection itself is re-run by test_measured_data.py)."""
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
            assert rms == pytest.approx(chosen["validation_rms"], rel=FIGURE_REL), (case, name)


def test_the_benchmark_summary_is_the_committed_full_run():
    """docs/results/bench_summary.md is what bench/report.py makes of the committed full run's figures
    (bench/RESULTS.json, written by the same bench/run as bench/RESULTS.md): a quoted speed cannot
    drift from the run it names. (The speeds themselves are measured by bench/run, never in a test.)"""
    report = module_from(ROOT / "bench" / "report.py", "bench_report")
    flat = json.loads((ROOT / "bench" / "RESULTS.json").read_text())
    assert report.summary(flat) == (ROOT / "docs" / "results" / "bench_summary.md").read_text()
    results_md = (ROOT / "bench" / "RESULTS.md").read_text()
    assert "(commit %s)" % flat["machine"]["git"] in results_md, "bench/RESULTS.md and RESULTS.json are of different runs"


def test_the_soak_summary_is_the_committed_soak():
    """docs/results/soak_summary.md is what tests/soak/report.py makes of the committed soak runs
    (docs/results/soak.json, both written by scripts/soak.sh), and those are the full soak: 25 seeds
    of 1e8 samples, each configuration, each run's verdict its own checks'. (The 1e8-sample runs take
    an hour and more; ctest's soak/short and soak/short_window run the same checks on 2e6 samples.)"""
    report = module_from(ROOT / "tests" / "soak" / "report.py", "soak_report")
    committed = json.loads((ROOT / "docs" / "results" / "soak.json").read_text())
    assert report.summary(committed) == (ROOT / "docs" / "results" / "soak_summary.md").read_text()
    assert committed["samples"] == 100_000_000 and committed["seeds"] == list(range(1, 26))
    for name, _, _ in report.CONFIGURATIONS:
        for run in committed["runs"][name]:
            assert run["samples"] == committed["samples"] and run["window"] == name.endswith("_window")
            assert run["pass"] == (run["failures"] == 0), (name, run["seed"])


def test_the_soak_report_refuses_an_incomplete_set_of_runs(tmp_path):
    """A run that wrote no figures (a crash) is missing from the gathered runs: the report says so
    instead of summarising the others."""
    report = module_from(ROOT / "tests" / "soak" / "report.py", "soak_report")
    committed = json.loads((ROOT / "docs" / "results" / "soak.json").read_text())
    for seed in (1, 2):
        (tmp_path / ("seed_%d.json" % seed)).write_text(json.dumps(committed["runs"]["output_error"][seed - 1]))
    (tmp_path / "seed_1_window.json").write_text(json.dumps(committed["runs"]["output_error_window"][0]))
    with pytest.raises(ValueError, match="different numbers of seeds"):
        report.gather(tmp_path)
    (tmp_path / "seed_3_window.json").write_text(json.dumps(committed["runs"]["output_error_window"][2]))
    with pytest.raises(ValueError, match="not seeds 1..N"):
        report.gather(tmp_path)


def test_the_joint_angle_models_give_their_committed_figures():
    """docs/results/joint_angle.json (examples/joint_angle/joint_angle.py): the paper's four models on
    the simulated joint's angle, without and with an integrator, recomputed to FIGURE_REL; the table
    docs/explanation/plant.md quotes is the one the results give."""
    joint_angle = module_from(ROOT / "examples" / "joint_angle" / "joint_angle.py", "joint_angle")
    committed = json.loads((ROOT / "docs" / "results" / "joint_angle.json").read_text())
    results = joint_angle.run()
    assert [(r["model"], r["ni"]) for r in results["rows"]] == [(r["model"], r["ni"]) for r in committed["rows"]]
    for new, old in zip(results["rows"], committed["rows"]):
        assert new["validation_rms"] == pytest.approx(old["validation_rms"], rel=FIGURE_REL), (new["model"], new["ni"])
        assert new["json"]["orders"].get("ni", 0) == new["ni"]
    assert joint_angle.table(committed) == (ROOT / "docs" / "results" / "joint_angle_summary.md").read_text()


def test_the_experiment_page_quotes_the_robustness_check():
    """docs/explanation/paper_experiment.md's robustness counts: on how many of the further validation
    trajectories one model's MSE is below another's, per method, as the experiment gives them."""
    result = bonl.experiment.run_paper_experiment(robustness=True)
    counts = {}
    for method in ("output_error", "paper"):
        mse = {name: result.method(method).models[name].robustness_mse for name in result.model_names}
        n = result.robustness_trajectories
        assert n == 8 and all(len(v) == n for v in mse.values())
        counts[method] = {(a, b): sum(x < y for x, y in zip(mse[a], mse[b])) for a in mse for b in mse}
    ours, paper = counts["output_error"], counts["paper"]
    phw, pih = "PseudoHammersteinWiener", "PrandtlIshlinskiiHammerstein"
    text = " ".join((ROOT / "docs" / "explanation" / "paper_experiment.md").read_text().split())
    assert ("bonl's P-H-W beats its Hammerstein on %d of 8, but Hammerstein beats ARX on only %d of 8; with the "
            "paper's estimator on %d of 8 and %d of 8." % (ours[phw, "Hammerstein"], ours["Hammerstein", "ARX"],
                                                           paper[phw, "Hammerstein"], paper["Hammerstein", "ARX"])) in text
    assert ("P-I-H beats P-H-W on %d of 8 and Hammerstein on %d of 8 with bonl's estimator, on %d of 8 and %d of 8 "
            "with the paper's." % (ours[pih, phw], ours[pih, "Hammerstein"], paper[pih, phw],
                                   paper[pih, "Hammerstein"])) in text


def test_the_measured_data_page_quotes_the_committed_check_scores_and_blocks():
    """docs/lab/measured_data.md, "Where we stand": the check scores it quotes are
    docs/results/measured_data.json's to three digits, and the actuator's H-W, identified again on the
    estimation data at its chosen structure, has the output polynomial the page writes out."""
    md = load_measured_data_example()
    committed = json.loads((ROOT / "docs" / "results" / "measured_data.json").read_text())
    text = " ".join((ROOT / "docs" / "lab" / "measured_data.md").read_text().split())
    act = {name: "%.3f" % row["check_rms"] for name, row in committed["actuator"].items()}
    assert float(act["Hammerstein"]) <= float(act["HammersteinWiener"]) < float(act["PseudoHammersteinWiener"])
    assert ("fits the check part as well as H-W does (%s against %s, P-H-W %s;"
            % (act["Hammerstein"], act["HammersteinWiener"], act["PseudoHammersteinWiener"])) in text
    assert "H-W wins on check (%.3f)" % committed["cascaded_tanks"]["HammersteinWiener"]["check_rms"] in text
    chosen = committed["actuator"]["HammersteinWiener"]
    actuator = md.load_actuator()
    model = bonl.identify(md.structure(bonl.HammersteinWiener, chosen["orders"]), actuator["u"][:512],
                          actuator["y"][:512], **md.settings(bonl.HammersteinWiener))
    q = model.q
    assert q[0] == 1.0 and len(q) == 2 and q[1] > 0
    assert "`y = x + %.3f x²`" % q[1] in text


def test_the_experiment_page_says_what_the_sweep_gives_without_hysteresis_or_backlash():
    """docs/explanation/paper_experiment.md: with neither pilot hysteresis nor pin backlash the paper's
    estimator gives a P-H-W worse than its Hammerstein, with c well away from 0 (above its start c0 =
    0.01), while bonl's estimator finds c at 0 (docs/results/sweep.csv, which the tests above tie to the code)."""
    rows = {row["method"]: row for row in committed_sweep() if row["parameter"] == "both_zero"}
    paper, ours = rows["paper"], rows["output_error"]
    assert float(paper["mse_PseudoHammersteinWiener"]) > float(paper["mse_Hammerstein"])
    assert float(paper["PseudoHammersteinWiener_c"]) > 0.01
    assert abs(float(ours["PseudoHammersteinWiener_c"])) < 1e-9
    text = " ".join((ROOT / "docs" / "explanation" / "paper_experiment.md").read_text().split())
    assert ("the paper's P-H-W is worse than its Hammerstein and ends with a backlash c well away from 0, "
            "while bonl's estimator finds c at 0 there") in text
