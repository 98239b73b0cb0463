"""Published figures stay true: every copy of a generated table in the docs is the table the
committed results file gives (docs/results/*_summary.md, written with the results by their script),
between its markers. The results themselves are re-computed by ctest (examples/online_accuracy_quick)."""

import json
import pathlib

import pytest

import bonl

ROOT = pathlib.Path(__file__).resolve().parents[2]

QUOTES = [
    ("online_accuracy_summary", ROOT / "docs" / "results" / "online_accuracy_summary.md",
     [ROOT / "README.md", ROOT / "docs" / "algorithm.md"]),
    ("plant_experiment_summary", ROOT / "docs" / "results" / "plant_experiment_summary.md", [ROOT / "README.md"]),
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
