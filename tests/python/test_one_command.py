"""The one command on the measured data sets (docs/results/one_command.json, written by
scripts/one_command.sh from examples/datasets/one_command.py): every committed model re-scores its
figures on the data set's tests, the script's and the peer's figures are what their files give, and
the table in the docs is what the results file gives."""

import json
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
