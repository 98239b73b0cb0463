"""The measured data sets' published figures (docs/results/datasets/*.json, written by
scripts/datasets.sh from examples/datasets): every committed model re-scores its test figures, and
the quick data sets are selected again from scratch and must choose the same structures with the same
figures, to FIGURE_REL (tests/python/figures.py: the measured spread between builds and the floors
that set it)."""

import dataclasses
import json
import math
import pathlib
import sys

import numpy as np
import pytest

import bonl
from figures import FIGURE_REL

ROOT = pathlib.Path(__file__).resolve().parents[2]
RESULTS = ROOT / "docs" / "results" / "datasets"
SCRIPTS = ["hydraulic_actuator", "cascaded_tanks", "coupled_electric_drives", "bouc_wen", "emps", "silverbox",
           "wiener_hammerstein"]
QUICK = ["hydraulic_actuator", "cascaded_tanks", "coupled_electric_drives"]  # seconds each

sys.path.insert(0, str(ROOT / "examples" / "datasets"))


def _script(name):
    return __import__(name)


def _results(name):
    return json.loads((RESULTS / f"{name}.json").read_text())


@pytest.mark.parametrize("name", SCRIPTS)
def test_every_committed_model_gives_its_published_test_figures(name):
    results = _results(name)
    benchmark = _script(name).make()
    assert [t["name"] for t in results["tests"]] == [t.name for t in benchmark.tests]
    assert ({row["model"] for row in results["rows"]} | set(results.get("no_model", {}))
            == {m.__name__ for m in bonl.MODELS if benchmark.grid_of(m)})
    for row in results["rows"]:
        model = bonl.load_model(json.dumps(row["json"]))
        assert bonl.named_orders(model) == row["orders"]
        for test in benchmark.tests:
            assert test.rms(model) == pytest.approx(row["test_rms"][test.name], rel=FIGURE_REL), (row["model"], test.name)
            if test.window:
                assert test.rms(model, from_rest=True) == pytest.approx(row["test_rms_from_rest"][test.name], rel=FIGURE_REL)


def test_a_family_without_a_bounded_model_is_reported_not_chosen():
    """The Wiener-Hammerstein record's first samples (benchmark.quick) have inputs in [-0.116, 0]: a cubic
    input polynomial fitted there leaves the output's envelope on inputs a quarter beyond (oracle: the
    identified model's own free run, here). The script reports the family with bonl.select's reason and
    goes on with the others, instead of failing."""
    made = _script("benchmark").quick(_script("wiener_hammerstein").make())
    (u, y), = made.estimation
    (structure,) = bonl.grid(bonl.Hammerstein, **made.grid_of(bonl.Hammerstein))  # quick: one candidate
    model = bonl.identify(structure, u, y)
    middle, half = (y.max() + y.min()) / 2, (y.max() - y.min()) / 2
    assert np.abs(model.simulate(1.25 * u) - middle).max() > 10 * half
    results = _script("benchmark").run(made, families=[bonl.ARX, bonl.Hammerstein])
    assert [row["model"] for row in results["rows"]] == ["ARX"]
    assert "none has a finite score and a bounded free run" in results["no_model"]["Hammerstein"]
    assert "| Hammerstein | none chosen: " in _script("table").table(results)


@pytest.mark.parametrize("name", QUICK)
def test_the_quick_data_sets_select_the_same_structures_again(name):
    module = _script(name)
    committed = _results(name)
    rerun = _script("benchmark").run(module.make())
    assert [row["model"] for row in rerun["rows"]] == [row["model"] for row in committed["rows"]]
    for old, new in zip(committed["rows"], rerun["rows"]):
        assert (new["model"], new["orders"], new["identify"]) == (old["model"], old["orders"], old["identify"])
        assert new["test_rms"] == pytest.approx(old["test_rms"], rel=FIGURE_REL), new["model"]


def test_the_summary_is_the_table_of_the_results_files():
    table = _script("table")
    table_text = "\n\n".join(table.table(_results(name)) for name in SCRIPTS)
    assert (ROOT / "docs" / "results" / "datasets_summary.md").read_text() == table_text + "\n"
    page = (ROOT / "docs" / "lab" / "measured_data.md").read_text()
    assert table_text in page


def test_the_comparison_with_the_literature_is_what_the_results_files_give():
    """docs/results/benchmarks_summary.md (docs/lab/benchmarks.md) from the committed results and each script's
    COMPARISONS; every data set has a row, each compared test is one the script scores, and the Silverbox
    compares all three tests of its protocol."""
    comparison = _script("comparison")
    assert sorted(comparison.SCRIPTS) == sorted(SCRIPTS)
    assert (ROOT / "docs" / "results" / "benchmarks_summary.md").read_text() == comparison.table() + "\n"
    for name in SCRIPTS:
        compared = [c.test for c in _script(name).COMPARISONS]
        assert compared and set(compared) <= {t["name"] for t in _results(name)["tests"]}, name
    assert [c.test for c in _script("silverbox").COMPARISONS] == [t["name"] for t in _results("silverbox")["tests"]]


def test_the_headline_is_the_selection_on_the_estimation_data_not_the_best_test_figure():
    """The comparison's figure for a data set is the family with the best held-out estimation score
    (what bonl.select across every family picks), computed here independently from the rows; and the
    linear baseline is the ARX family's row."""
    comparison = _script("comparison")
    for name in SCRIPTS:
        results = _results(name)
        scores = {row["model"]: row["check_rms"] for row in results["rows"]}
        best = min(scores, key=scores.get)
        assert comparison.selected(results)["model"] == best, name
        assert comparison.linear(results)["model"] == "ARX", name
        for c in _script(name).COMPARISONS:
            row_text = next(line for line in comparison.rows(name) if f"({c.test};" in line)
            chosen = next(row for row in results["rows"] if row["model"] == best)
            assert f"({best})" in row_text and comparison._figure(chosen["test_rms"][c.test]) in row_text, name


def test_the_committed_cluster_run_ranked_64_candidates_identically():
    """The committed run of the 64-candidate grid locally and on a Dask cluster
    (examples/datasets/wiener_hammerstein_on_dask.py): its two tables, compared here row by row (the
    file's own flags are not trusted), rank the same candidates in the same order with the same
    scores, none failed. tests/python/test_select.py runs a grid on a live cluster."""
    run = json.loads((ROOT / "docs" / "results" / "select_on_dask.json").read_text())
    local, cluster = run["local"], run["local_cluster"]
    assert len(local) == len(cluster) == run["candidates"] == 64
    assert [row["orders"] for row in local] == [row["orders"] for row in cluster]
    assert [row["score"] for row in local] == [row["score"] for row in cluster]
    assert [row["score"] for row in local] == sorted(row["score"] for row in local)
    assert len({json.dumps(row["orders"], sort_keys=True) for row in local}) == 64
    assert all(row["error"] is None for row in local + cluster)


def test_the_chosen_tanks_structures_give_their_committed_figures_on_perturbed_records():
    """Each chosen structure identified again on the 10 perturbed records gives the committed figures,
    and the P-H-W's validation RMS moves by less than 5% (issue 18's acceptance)."""
    perturbation = _script("perturbation")
    committed = json.loads((RESULTS / "perturbation.json").read_text())
    rerun = perturbation.structures(_script("cascaded_tanks").make(), _results("cascaded_tanks"))
    assert rerun.keys() == committed["structure"].keys()
    for model, row in rerun.items():
        old = committed["structure"][model]
        assert (row["orders"], row["identify"]) == (old["orders"], old["identify"])
        assert [row["unperturbed"], *row["perturbed"]] == pytest.approx([old["unperturbed"], *old["perturbed"]],
                                                                        rel=FIGURE_REL), model
    assert rerun["PseudoHammersteinWiener"]["spread"] < 0.05
    page = (ROOT / "docs" / "lab" / "measured_data.md").read_text()
    assert perturbation.table(committed) in page
    assert (ROOT / "docs" / "results" / "perturbation_summary.md").read_text() == perturbation.table(committed) + "\n"


def _swings(x, delta):
    """How often x turns back by more than delta from its last extreme (a zig-zag count)."""
    count, direction, extreme = 0, 0.0, x[0]
    for value in x[1:]:
        if (value - extreme) * direction > 0:  # on in the same direction
            extreme = value
        elif abs(value - extreme) > delta:
            count += direction != 0
            direction = 1.0 if value > extreme else -1.0
            extreme = value
    return count


def _tanks_validation(model, test):
    return model.simulate(test.u[test.window:], initial=(test.u[:test.window], test.y[:test.window]))


def test_no_model_selected_on_the_tanks_oscillates_on_the_validation_record():
    # Issue 18: the P-H-W once selected there oscillated (1.548 V). Oscillation here: the simulated
    # output turns back (by more than 0.2 V, well above the sensor's steps) more often than the
    # measured level does, over the same samples.
    test = _script("cascaded_tanks").make().tests[0]
    measured = _swings(test.y[test.window:], 0.2)
    rows = _results("cascaded_tanks")["rows"]
    for row in rows:
        simulated = _tanks_validation(bonl.load_model(json.dumps(row["json"])), test)
        assert _swings(simulated, 0.2) <= measured + 3, row["model"]
    # The count does see an oscillation: the chosen P-H-W with its poles moved to radius 0.99 at the
    # angle that keeps the linear block's static gain (it rings for about 100 samples after a step).
    phw = next(row["json"] for row in rows if row["model"] == "PseudoHammersteinWiener")
    ringing = json.loads(json.dumps(phw))
    static = 1 + sum(phw["params"]["a"])
    angle = math.acos((1 + 0.99 ** 2 - static) / (2 * 0.99))
    ringing["params"]["a"] = [-2 * 0.99 * math.cos(angle), 0.99 ** 2]
    simulated = _tanks_validation(bonl.load_model(json.dumps(ringing)), test)
    assert _swings(simulated, 0.2) > measured + 10


def test_the_wiener_hammerstein_model_file_simulates_the_record_from_rest_to_its_figure():
    """docs/results/datasets/wiener_hammerstein_model.json (issue 21): load it, simulate the whole
    record from rest, score samples 101 001-188 000 as SOURCE.md says: the committed figure, below 1 mV."""
    module = _script("wiener_hammerstein")
    model = bonl.load_model((RESULTS / "wiener_hammerstein_model.json").read_text())
    assert isinstance(model, bonl.WienerHammerstein)
    u, y = module.load()
    error = (y - model.simulate(u))[101000:]
    rms = math.sqrt(float((error ** 2).mean()))
    row = next(row for row in _results("wiener_hammerstein")["rows"] if row["model"] == "WienerHammerstein")
    assert rms == pytest.approx(row["test_rms"]["samples 101 001-188 000"], rel=FIGURE_REL)
    assert rms <= 1e-3


def test_the_prose_quotes_the_wiener_hammerstein_figure_the_results_give():
    """README.md, docs/lab/measured_data.md and docs/explanation/algorithm.md quote the W-H model's test RMS in mV in
    their text (not in a generated table): it must be the committed results file's, to three decimals;
    and the prose that compares it with the published record quotes the ratio the results give."""
    row = next(row for row in _results("wiener_hammerstein")["rows"] if row["model"] == "WienerHammerstein")
    rms = row["test_rms"]["samples 101 001-188 000"]
    quoted = "%.3f mV" % (rms * 1e3)
    for page in (ROOT / "README.md", ROOT / "docs" / "lab" / "measured_data.md", ROOT / "docs" / "explanation" / "algorithm.md"):
        assert quoted in page.read_text(), f"{page.name} should quote {quoted}"
    ratio = "%.2f times" % (rms / _script("wiener_hammerstein").COMPARISONS[0].best[1])
    for page in (ROOT / "docs" / "lab" / "benchmarks.md", ROOT / "docs" / "lab" / "measured_data.md", ROOT / "docs" / "explanation" / "algorithm.md"):
        assert ratio in page.read_text(), f"{page.name} should quote {ratio} the published record"


def _rescored_model_file(name, family="NonlinearFeedback"):
    """docs/results/datasets/<name>_model.json (scripts/datasets.sh), the model of ``family`` the data
    set's selection chose, loaded from its own file: it scores the results file's figures on every
    test record, after the state-initialisation window and, where the test has one, from rest. Returns
    it and the results file's rows by family."""
    model = bonl.load_model((RESULTS / f"{name}_model.json").read_text())
    assert type(model).__name__ == family
    rows = {row["model"]: row for row in _results(name)["rows"]}
    row = rows[family]
    for test in _script(name).make().tests:
        assert test.rms(model) == pytest.approx(row["test_rms"][test.name], rel=FIGURE_REL), test.name
        if test.window:
            assert test.rms(model, from_rest=True) == pytest.approx(row["test_rms_from_rest"][test.name], rel=FIGURE_REL)
    return model, rows


def test_the_silverbox_nonlinear_feedback_model_file_gives_its_figures_on_every_test():
    """The Silverbox's model file scores its figures on the three tests of the protocol (after the
    50-sample window and from rest) and is an order of magnitude below the linear model on each."""
    _, rows = _rescored_model_file("silverbox")
    row, linear = rows["NonlinearFeedback"], rows["ARX"]
    for test in _script("silverbox").make().tests:
        assert row["test_rms"][test.name] < 0.2 * linear["test_rms"][test.name], test.name
        # docs/lab/measured_data.md: below 0.5 mV on each test.
        assert row["test_rms"][test.name] <= 0.5e-3, test.name


def test_the_emps_friction_drive_model_file_gives_its_figures_and_beats_the_linear_model():
    """The EMPS's model file, the nonlinear-feedback model with an integrator (a friction curve of the
    velocity, the position integrating it), scores its figures on the pulses record (after the 20-sample
    window and from rest), below the linear model and every other family, and below 5 mm."""
    model, rows = _rescored_model_file("emps")
    assert model.ni == 1 and model.nv == 1
    row = rows["NonlinearFeedback"]
    (test,) = _script("emps").make().tests
    assert all(row["test_rms"][test.name] < other["test_rms"][test.name] for name, other in rows.items()
               if name != "NonlinearFeedback")
    assert row["test_rms"][test.name] <= 5e-3  # docs/lab/benchmarks.md's table: below 5 mm


def test_the_emps_diagnosis_in_the_docs_is_what_the_records_and_the_model_file_give():
    """docs/lab/benchmarks.md explains the EMPS's test figure: the two records share their reference and
    their outputs nearly coincide, while the test's input carries the controller's compensation of force
    pulses the model does not see; fed the estimation record's input, the model file scores about a
    third of its test figure against the test's output. It also quotes the model file's figure on the
    estimation record after the same window, the record dynoNet's public test script loads. The quoted
    figures are computed here from the data."""
    model, rows = _rescored_model_file("emps")
    benchmark = _script("emps").make()
    ((u, y),), (test,) = benchmark.estimation, benchmark.tests
    outputs = float(np.sqrt(np.mean((test.y - y) ** 2)))
    inputs = float(np.sqrt(np.mean((test.u - u) ** 2)))
    pulse_free = dataclasses.replace(test, u=u).rms(model)
    estimation_record = dataclasses.replace(test, u=u, y=y).rms(model)  # what dynoNet's public script scores
    page = (ROOT / "docs" / "lab" / "benchmarks.md").read_text()
    for quoted in ("%.3f mm" % (outputs * 1e3), "%.2f (%.0f %% of the input's"
                   % (inputs, 100 * inputs / np.std(test.u)), "%.2f mm" % (pulse_free * 1e3),
                   "%.2f mm" % (rows["NonlinearFeedback"]["test_rms"][test.name] * 1e3),
                   "chosen model scores %.2f mm." % (estimation_record * 1e3)):
        assert quoted in page, f"docs/lab/benchmarks.md should quote {quoted}"
    # The records' outputs nearly coincide; the pulse-free figure is well below the test's.
    assert outputs < 0.1 * pulse_free < 0.05 * rows["NonlinearFeedback"]["test_rms"][test.name]


def test_the_bouc_wen_feedback_model_file_gives_its_figures_on_every_test():
    """The Bouc-Wen's model file, the Bouc-Wen feedback model that selection picks across the families,
    scores its figures on each test record, is below the linear model and the nonlinear-feedback model
    on each, and in steady state on the validation multisine below dynoNet's published figure (the best
    block-oriented one)."""
    _, rows = _rescored_model_file("bouc_wen", "BoucWenFeedback")
    row, linear, plays = rows["BoucWenFeedback"], rows["ARX"], rows["NonlinearFeedback"]
    for test in _script("bouc_wen").make().tests:
        assert row["test_rms"][test.name] < linear["test_rms"][test.name], test.name
        assert row["test_rms"][test.name] < plays["test_rms"][test.name], test.name
    assert _script("comparison").selected(_results("bouc_wen"))["model"] == "BoucWenFeedback"
    dynonet = float(dict(_script("bouc_wen").make().published)["dynoNet (Forgione and Piga 2021)"])
    assert row["test_rms"]["validation multisine"] < dynonet


def test_the_bouc_wen_law_shows_the_validation_multisine_is_a_steady_state():
    """examples/datasets/bouc_wen_law.py: the benchmark's own law reproduces the training output, and
    the validation multisine one period after rest, not from rest; the committed figures are what it
    gives again, docs/lab/benchmarks.md quotes them, and the Bouc-Wen script scores that record over
    two periods."""
    figures = _script("bouc_wen_law").run()
    committed = json.loads((RESULTS / "bouc_wen_law.json").read_text())
    assert figures == pytest.approx(committed, rel=1e-6)
    assert figures["validation_multisine_second_period"] < 1e-6 < figures["training_first_two_periods"] < 1e-5
    assert figures["validation_multisine_from_rest"] > 40 * figures["validation_multisine_second_period"]
    page = " ".join((ROOT / "docs" / "lab" / "benchmarks.md").read_text().split())
    for key in ("training_first_two_periods", "validation_multisine_second_period", "validation_multisine_from_rest"):
        assert "%.1e m" % figures[key] in page, key
    (steady, from_rest, _) = _script("bouc_wen").make().tests
    assert (steady.periods, from_rest.periods) == (2, 1) and np.array_equal(steady.u, from_rest.u)


FEED_FORWARD = ("ARX", "Hammerstein", "HammersteinWiener", "PseudoHammersteinWiener", "Wiener")


def test_the_measured_data_page_says_what_the_results_files_give():
    """The sentences of docs/lab/measured_data.md that read the tables: the feed-forward chains within 4 %
    of ARX on the Bouc-Wen multisine and the Silverbox, within 6 % on the Bouc-Wen sine sweep; the
    nonlinear-feedback model an order of magnitude below ARX on every Silverbox test, 0.4 to 0.55 of it
    on the Bouc-Wen multisine and a quarter on the sweep; the one-linear-block models on the
    Wiener-Hammerstein circuit at 21 mV and more; the EMPS's test input outside the estimation range on
    172 samples and its H-W kilometres off; its block models without an integrator several times
    dynoNet's figure."""
    text = " ".join((ROOT / "docs" / "lab" / "measured_data.md").read_text().split())

    def rows(name):
        return {row["model"]: row for row in _results(name)["rows"]}

    worst = {}  # the feed-forward chains' largest distance from ARX, per test
    loop = {}  # the nonlinear-feedback model's error over ARX's, per test
    for name in ("bouc_wen", "silverbox"):
        by_model = rows(name)
        for test, linear in by_model["ARX"]["test_rms"].items():
            worst[name, test] = max(abs(by_model[m]["test_rms"][test] / linear - 1) for m in FEED_FORWARD)
            loop[name, test] = by_model["NonlinearFeedback"]["test_rms"][test] / linear
    sweep = ("bouc_wen", "sine sweep")
    assert max(v for k, v in worst.items() if k != sweep) < 0.04 and "within 4 % of ARX" in text
    assert 0.04 <= worst[sweep] < 0.06 and "(within 6 % on the Bouc-Wen sine sweep)" in text
    assert all(v < 0.1 for (name, _), v in loop.items() if name == "silverbox")
    multisine = [v for (name, test), v in loop.items() if name == "bouc_wen" and test.startswith("validation")]
    assert len(multisine) == 2 and all(0.4 < v < 0.55 for v in multisine) and 0.2 < loop[sweep] < 0.3
    assert ("an order of magnitude below ARX on every Silverbox test, 0.4 to 0.55 of ARX on the Bouc-Wen "
            "multisine (in steady state and from rest) and a quarter of it on the sine sweep") in text

    one_block = min(row["test_rms"]["samples 101 001-188 000"] for model, row in rows("wiener_hammerstein").items()
                    if model != "WienerHammerstein")
    assert "stay at %d mV and more" % math.floor(one_block * 1e3) in text

    emps = rows("emps")
    outside = {n for row in emps.values() for n in row["test_inputs_outside_range"].values()}
    assert outside == {172} and "(172 samples outside the range `identify` saw" in text
    assert "still scores %.3f m" % emps["HammersteinWiener"]["test_rms"]["pulses record"] in text
    dynonet = _script("emps").COMPARISONS[0].best[1]
    assert all(emps[m]["test_rms"]["pulses record"] > 3 * dynonet for m in FEED_FORWARD if m != "ARX")
    assert "several times dynoNet's figure and more" in text
    # docs/lab/benchmarks.md: the Bouc-Wen selection's loop has eight play operators.
    assert rows("bouc_wen")["NonlinearFeedback"]["orders"]["np"] == 8
    assert "the loop with eight play operators" in (ROOT / "docs" / "lab" / "benchmarks.md").read_text()
