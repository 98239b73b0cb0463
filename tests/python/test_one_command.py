"""The one command on the measured data sets (docs/results/one_command.json, written by
scripts/one_command.sh from examples/datasets/one_command.py): every committed model re-scores its
figures on the data set's tests, the script's and the peer's figures are what their files give, and
the table in the docs is what the results file gives."""

import json
import math
import pathlib
import sys
import warnings

import pytest

import bonl
from figures import FIGURE_REL

ROOT = pathlib.Path(__file__).resolve().parents[2]
RESULTS = ROOT / "docs" / "results"
sys.path.insert(0, str(ROOT / "examples" / "datasets"))


def _module(name):
    return __import__(name)


def _results():
    return json.loads((RESULTS / "one_command.json").read_text())


def test_every_data_set_is_in_the_results_file_and_not_a_quick_run():
    results = _results()
    assert results["quick"] is False
    assert [d["script"] for d in results["data_sets"]] == _module("comparison").SCRIPTS


@pytest.mark.parametrize("script", _module("comparison").SCRIPTS)
def test_every_committed_model_gives_its_figures_on_the_data_sets_tests(script):
    (data_set,) = [d for d in _results()["data_sets"] if d["script"] == script]
    made = _module(script).make()
    assert data_set["window"] == made.window
    comparison = _module("comparison")
    selected = comparison.selected(json.loads((comparison.RESULTS / f"{script}.json").read_text()))
    peer = json.loads(_module("one_command").NARX_PEER.read_text())["data_sets"][script]
    assert data_set["script_test_rms"] == {test.name: selected["test_rms"][test.name] for test in made.tests}
    assert data_set["narx_peer"] == {test.name: peer.get(test.name) for test in made.tests}
    assert list(data_set["commands"]) == list(_module("one_command").VARIANTS)
    for variant, command in data_set["commands"].items():
        model = bonl.load_model(json.dumps(command["json"]))
        assert (type(model).__name__, bonl.named_orders(model)) == (command["model"], command["orders"])
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", bonl.ExtrapolationWarning)
            for test in made.tests:
                committed, rms = command["test_rms"][test.name], test.rms(model)
                if committed == "diverged":
                    assert rms == float("inf"), (variant, test.name)
                else:
                    assert rms == pytest.approx(committed, rel=FIGURE_REL), (variant, test.name)


def test_the_table_in_the_docs_is_the_results_files():
    table = _module("one_command").markdown(_results())
    assert (RESULTS / "one_command_summary.md").read_text() == table
    assert table in (ROOT / "docs" / "lab" / "benchmarks.md").read_text()


def test_the_docs_say_what_the_results_file_gives():
    """docs/lab/benchmarks.md's sentences under the table, against the results file."""
    results = _results()
    ratios, below_script, below_peer, peer_figures = {}, 0, 0, 0
    for data_set in results["data_sets"]:
        command = data_set["commands"]["default"]
        assert command["seconds"] < 600, data_set["data_set"]
        for test, script in data_set["script_test_rms"].items():
            rms = command["test_rms"][test]
            assert rms != "diverged" and math.isfinite(rms), (data_set["data_set"], test)
            ratios[data_set["data_set"], test] = rms / script
            below_script += rms < script
            peer = data_set["narx_peer"][test]
            if isinstance(peer, float):
                peer_figures += 1
                below_peer += rms < peer
    furthest = max(ratios, key=ratios.get)
    text = " ".join((ROOT / "docs" / "lab" / "benchmarks.md").read_text().split())
    assert ("On every test of every data set the command is within %.2f times the data-set script's figure (the "
            "Bouc-Wen sine sweep is the furthest) and below it on %d of %d tests;"
            % (ratios[furthest], below_script, len(ratios))) in text
    assert furthest == ("bouc-wen", "sine sweep")
    assert below_peer == peer_figures
    by_script = {d["script"]: d for d in results["data_sets"]}
    assert by_script["emps"]["narx_peer"]["pulses record"] == "diverged"
    assert "on EMPS the peer's free run diverged" in text
    for script in ("wiener_hammerstein", "silverbox", "bouc_wen", "emps"):
        selected = _module("comparison").selected(json.loads((RESULTS / "datasets" / f"{script}.json").read_text()))
        assert by_script[script]["commands"]["default"]["model"] == selected["model"], script
    actuator = json.loads((RESULTS / "datasets" / "hydraulic_actuator.json").read_text())
    assert by_script["hydraulic_actuator"]["commands"]["default"]["model"] == "PrandtlIshlinskiiHammerstein"
    assert "PrandtlIshlinskiiHammerstein" not in {row["model"] for row in actuator["rows"]}
