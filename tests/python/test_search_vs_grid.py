"""The structure search against a grid around the true structure (docs/results/search_vs_grid.json,
written by scripts/search_vs_grid.sh from examples/search/search_vs_grid.py): every committed model
re-scores its figure on the regenerated test record, the table in the docs is the results file's,
and on every system the search is within 1.5 times the grid's error."""

import json
import pathlib
import re
import sys
import warnings

import numpy as np
import pytest

import bonl
from figures import FIGURE_REL

ROOT = pathlib.Path(__file__).resolve().parents[2]
RESULTS = ROOT / "docs" / "results" / "search_vs_grid.json"
sys.path.insert(0, str(ROOT / "examples" / "search"))
import search_vs_grid  # noqa: E402
from systems import SYSTEMS  # noqa: E402


def _results():
    return json.loads(RESULTS.read_text())


def test_every_system_is_in_the_results_file_and_not_a_quick_run():
    results = _results()
    assert results["quick"] is False and results["samples"] == search_vs_grid.SAMPLES
    assert [row["system"] for row in results["systems"]] == [system.name for system in SYSTEMS]


@pytest.mark.parametrize("system", SYSTEMS, ids=[s.name for s in SYSTEMS])
def test_every_committed_model_gives_its_figure_and_the_search_is_within_1_5_of_the_grid(system):
    (row,) = [r for r in _results()["systems"] if r["system"] == system.name]
    u, _, clean = system.records(search_vs_grid.SAMPLES, search_vs_grid.TEST_SEED)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bonl.ExtrapolationWarning)
        for part in ("search", "grid", "linear"):
            model = bonl.load_model(json.dumps(row[part]["json"]))
            assert search_vs_grid.nrmse(model, u, clean) == pytest.approx(row[part]["nrmse"], rel=FIGURE_REL), part
    if system.name not in SHORT_OF_THE_GRID:
        assert row["search"]["nrmse"] <= 1.5 * row["grid"]["nrmse"]


#: Where the docs say the search is more than 1.5 times the grid's error (docs/lab/benchmarks.md).
SHORT_OF_THE_GRID = ("integrating drive with friction (velocity feedback, integrator)",)


def test_the_docs_say_where_the_search_is_short_of_the_grid():
    rows = _results()["systems"]
    ratio = {row["system"]: row["search"]["nrmse"] / row["grid"]["nrmse"] for row in rows}
    assert tuple(name for name in ratio if ratio[name] > 1.5) == SHORT_OF_THE_GRID
    (short,) = SHORT_OF_THE_GRID
    row = next(r for r in rows if r["system"] == short)
    assert row["search"]["nrmse"] > row["linear"]["nrmse"] and row["search"]["model"] == "Hammerstein"
    text = " ".join((ROOT / "docs" / "lab" / "benchmarks.md").read_text().split())
    assert ("The search is within 1.5 times the grid's error on %d of the %d systems, below it on %d."
            % (sum(r <= 1.5 for r in ratio.values()), len(ratio), sum(r < 1 for r in ratio.values()))) in text
    assert "on the integrating drive with friction (%.2f times the grid's error, above its own linear" % ratio[short] in text


def test_the_table_in_the_docs_is_the_results_files():
    table = search_vs_grid.markdown(_results())
    assert (ROOT / "docs" / "results" / "search_vs_grid_summary.md").read_text() == table
    assert table in (ROOT / "docs" / "lab" / "benchmarks.md").read_text()


def test_the_docs_say_why_the_search_is_short_of_the_grid_on_the_integrating_drive():
    """The pole pair and the two cross-validated scores the docs quote, computed again: the chosen
    structure's and the true structure's (knots placed by the search's rule) on the estimation record."""
    (short,) = SHORT_OF_THE_GRID
    row = next(r for r in _results()["systems"] if r["system"] == short)
    system = next(s for s in SYSTEMS if s.name == short)
    chosen = bonl.load_model(json.dumps(row["search"]["json"]))
    radii = sorted(abs(np.roots(np.r_[1.0, chosen.a])))
    assert radii[-1] == pytest.approx(radii[-2], rel=1e-9)
    u, y, _ = system.records(search_vs_grid.SAMPLES, search_vs_grid.ESTIMATION_SEED)
    truth = system.make()
    structures = [type(chosen)(**row["search"]["orders"]),
                  bonl.place_from_data(type(truth)(**row["truth"]["orders"]), [(u, y)])]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bonl.ExtrapolationWarning)
        table = bonl.select(structures, u, y, criterion="cross_validation", folds=5, progress=False).table
    held_out = {row.name: float(np.sqrt(row.score)) for row in table}
    text = " ".join((ROOT / "docs" / "lab" / "benchmarks.md").read_text().split())
    assert "a pole pair of radius %.3f," % radii[-1] in text
    # These two are identified again here, not read from the results file, and an identification
    # amplifies the last-bit differences between machines (tests/python/figures.py): the same code
    # gave the chosen structure's score as 0.13863 on one machine and 0.13833 on another, either side
    # of the docs' rounding. The docs' figures are held to 1 % instead of to their last digit.
    chosen_quoted = quoted_number(text, "so its score (", ", at the noise floor)")
    truth_quoted = quoted_number(text, "the true structure's folds fit worse there (", ")")
    assert chosen_quoted == pytest.approx(held_out["Hammerstein"], rel=1e-2)
    assert truth_quoted == pytest.approx(held_out["NonlinearFeedback"], rel=1e-2)


def quoted_number(text, before, after):
    """The decimal number the text quotes between `before` and `after` (plain text, not patterns)."""
    match = re.search(re.escape(before) + r"([0-9]+\.[0-9]+)" + re.escape(after), text)
    assert match, "the docs no longer say " + before + "..." + after
    return float(match.group(1))
