"""`python -m bonl identify` and `simulate`: from a CSV file to a model file and back, their errors, and
the Python calls behind what they print and draw (bonl.read_columns, bonl.summary, bonl.plot_fit)."""

import json
import math

import numpy as np
import pytest

import bonl
from bonl.__main__ import main
from conftest import known_models, random_levels


def _csv(path, columns, header=True):
    names = list(columns)
    rows = np.column_stack([columns[n] for n in names])
    with open(path, "w") as handle:
        if header:
            handle.write(",".join(names) + "\n")
        for row in rows:
            handle.write(",".join(repr(float(x)) for x in row) + "\n")
    return path


@pytest.fixture
def hammerstein_file(tmp_path):
    """A record of the small known Hammerstein system (noise-free), and the system."""
    truth = known_models("small")["Hammerstein"]
    u = random_levels(3000, 5, 1.0, 3)
    return _csv(tmp_path / "record.csv", {"time": np.arange(u.size) * 0.01, "valve": u, "speed": truth.simulate(u)}), truth


def test_identify_at_given_orders_recovers_the_system_and_writes_a_model_that_loads(hammerstein_file, tmp_path, capsys):
    path, truth = hammerstein_file
    orders = [f"{name}={value}" for name, value in bonl.named_orders(truth).items()]
    status = main(["identify", str(path), "--input", "valve", "--output", "speed", "--out", str(tmp_path / "m.json"),
                   "--model", "Hammerstein", "--orders", *orders, "--scores", str(tmp_path / "s.json")])
    assert status == 0
    model = bonl.load_model((tmp_path / "m.json").read_text())
    assert isinstance(model, bonl.Hammerstein) and model.orders == truth.orders
    fresh = random_levels(2000, 5, 0.95, 99)
    assert bonl.metrics.nrmse(truth.simulate(fresh), model.simulate(fresh)) <= 1e-6
    printed = capsys.readouterr().out
    assert "Hammerstein (" in printed and "linear model beside it: ARX" in printed
    scores = json.loads((tmp_path / "s.json").read_text())
    assert scores["candidates"] == 1 and scores["model"] == "Hammerstein"


def test_identify_scores_are_what_the_model_file_and_select_give(hammerstein_file, tmp_path):
    """The scores file's figures computed again from outside: the model file's free run on the test part,
    and the linear model's held-out score from bonl.select over the same ARX grid."""
    path, truth = hammerstein_file
    status = main(["identify", str(path), "--input", "1", "--output", "speed", "--out", str(tmp_path / "m.json"),
                   "--model", "Hammerstein", "--orders", "na=1,2", "nb=1", "nk=2", "r=2",
                   "--test-from", "2000", "--scores", str(tmp_path / "s.json"), "--figure", str(tmp_path / "fit.png")])
    assert status == 0
    scores = json.loads((tmp_path / "s.json").read_text())
    assert scores["candidates"] == 2
    u, y = bonl.read_columns(path, ["valve", "speed"])
    model = bonl.load_model((tmp_path / "m.json").read_text())
    test_rms = math.sqrt(float(np.mean((y[2000:] - model.simulate(u)[2000:]) ** 2)))
    [test] = scores["tests"]
    assert test["name"].endswith("samples 2000 on") and test["rms"] == pytest.approx(test_rms, rel=1e-12)
    linear = bonl.select(bonl.grid(bonl.ARX, na=[1, 2, 3], nb=[1, 2], nk=[0, 1]), u[:2000], y[:2000], progress=False)
    assert scores["linear"]["held_out_rms"] == pytest.approx(math.sqrt(linear.table[0].score), rel=1e-12)
    assert test["rms"] < 1e-3 * scores["linear"]["tests"][0]["rms"]
    assert (tmp_path / "fit.png").stat().st_size > 10_000


def test_identify_without_a_model_searches_and_finds_a_known_system(tmp_path):
    """No --model: the structure search (bonl.search); on a short, noise-free record of a Wiener system
    its choice simulates a fresh record of it to rounding, and every stage is printed and saved."""
    u = random_levels(600, 5, 1.0, 5)
    truth = known_models("small")["Wiener"]
    path = _csv(tmp_path / "w.csv", {"u": u, "y": truth.simulate(u)})
    assert main(["identify", str(path), "--input", "u", "--output", "y", "--out", str(tmp_path / "m.json"),
                 "--scores", str(tmp_path / "s.json")]) == 0
    scores = json.loads((tmp_path / "s.json").read_text())
    assert [stage["name"] for stage in scores["search"]] == [
        "held-out data", "delay", "operating point and integrator", "linear orders", "families", "nonlinearity",
        "growth", "choice"]
    assert scores["held_out"] == "5-fold blocked cross-validation"
    assert scores["candidates"] == len(scores["ranking"]) > 50
    model = bonl.load_model((tmp_path / "m.json").read_text())
    fresh = random_levels(600, 5, 0.9, 6)
    assert np.max(np.abs(model.simulate(fresh) - truth.simulate(fresh))) < 1e-8 * np.std(truth.simulate(fresh))


@pytest.mark.parametrize("arguments, content, message", [
    (["--input", "u", "--output", "y"], None, "no such file"),
    (["--input", "u", "--output", "pressure"], "u,y\n1,2\n3,4\n", "no column 'pressure'; its columns are 'u', 'y'"),
    (["--input", "u", "--output", "y"], "u,y\n1,2\n3,abc\n", "row 3, column 'y': 'abc' is not a number"),
    (["--input", "u", "--output", "y"], "u,y\n1,2\n3,nan\n", "row 3, column 'y': 'nan' is not a finite number"),
    (["--input", "u", "--output", "y"], "u,y\n1,2\n3\n", "row 3, column 'y': the row has only 1 fields"),
    (["--input", "u", "--output", "y"], "u,y\n", "no samples, only its header"),
    (["--input", "5", "--output", "y"], "u,y\n1,2\n", "no column 5: the file has 2"),
    (["--input", "u", "--output", "y"], "u,y\n" + "1,2\n" * 50, "is constant over the samples identified on"),
    (["--input", "u", "--output", "y", "--model", "Nope"], "u,y\n1,2\n2,3\n", "no model 'Nope'"),
    (["--input", "u", "--output", "y", "--model", "ARX", "--orders", "r=3"], "u,y\n1,2\n2,3\n", "ARX has no order r"),
    (["--input", "u", "--output", "y", "--orders", "na=2"], "u,y\n1,2\n2,3\n", "--orders needs --model"),
    (["--input", "u", "--output", "y", "--model", "ARX", "--orders", "na:2"], "u,y\n1,2\n2,3\n", "NAME=VALUE"),
    (["--input", "u", "--output", "y", "--test-from", "7"], "u,y\n1,2\n2,3\n", "--test-from must be in 1..1"),
    (["--input", "u", "--output", "y", "--window", "-1"], "u,y\n1,2\n2,3\n", "--window must be >= 0, got -1"),
    (["--input", "u", "--output", "y", "--test", "DATA", "--window", "2"], "u,y\n1,2\n2,3\n",
     "must be longer than the window (2 samples)"),
    (["--input", "u", "--output", "y", "--test", "missing.csv"], "u,y\n1,2\n2,3\n", "missing.csv: no such file"),
])
def test_identify_says_what_is_wrong_with_its_input(tmp_path, capsys, arguments, content, message):
    path = tmp_path / "data.csv"
    if content is not None:
        path.write_text(content)
    arguments = [str(path) if a == "DATA" else a for a in arguments]
    assert main(["identify", str(path), *arguments, "--out", str(tmp_path / "m.json")]) == 1
    assert message in capsys.readouterr().err
    assert not (tmp_path / "m.json").exists()


def test_identify_on_several_files_scores_test_files_after_the_window(tmp_path, capsys):
    """Two estimation files are two records of one selection, a third file is the test: the scores file's
    figures recomputed from outside (bonl.select on the records with the same window, the model file's
    simulation after the test's window), the ranking every candidate's, best first, and printed."""
    truth = known_models("small")["Hammerstein"]
    paths = []
    for seed in (11, 12, 13):
        u = random_levels(800, 5, 1.0, seed)
        y = truth.simulate(u) + np.random.default_rng(seed).normal(0.0, 0.01, u.size)
        paths.append(_csv(tmp_path / f"r{seed}.csv", {"u": u, "y": y}))
    status = main(["identify", str(paths[0]), str(paths[1]), "--test", str(paths[2]), "--input", "u", "--output", "y",
                   "--model", "Hammerstein", "--orders", "na=1,2", "nb=1", "nk=1,2", "r=2", "--window", "10",
                   "--out", str(tmp_path / "m.json"), "--scores", str(tmp_path / "s.json"), "--no-progress"])
    assert status == 0
    scores = json.loads((tmp_path / "s.json").read_text())
    records = [tuple(bonl.read_columns(p, ["u", "y"])) for p in paths]
    expected = bonl.select(bonl.grid(bonl.Hammerstein, na=[1, 2], nb=1, nk=[1, 2], r=2), records=records[:2],
                           window=10, progress=False)
    assert [(r["model"], r["orders"]) for r in scores["ranking"]] == [(r.name, r.orders) for r in expected.table]
    assert [r["held_out_rms"] for r in scores["ranking"]] == pytest.approx(
        [math.sqrt(r.score) for r in expected.table], rel=1e-12)
    assert scores["data"] == [str(paths[0]), str(paths[1])] and scores["samples"] == [800, 800]
    model = bonl.load_model((tmp_path / "m.json").read_text())
    np.testing.assert_array_equal(model.theta, expected.best.theta)
    u, y = records[2]
    simulated = model.simulate(u[10:], initial=(u[:10], y[:10]))
    [test] = scores["tests"]
    assert test["name"] == str(paths[2])
    assert test["rms"] == pytest.approx(math.sqrt(float(np.mean((y[10:] - simulated) ** 2))), rel=1e-12)
    assert test["rms"] < 0.02 and scores["linear"]["tests"][0]["rms"] > 2 * test["rms"]
    captured = capsys.readouterr()
    assert "ranking by held-out RMS error (4 best of 4" in captured.out
    assert f"test {paths[2]}: RMS error {test['rms']:.6g}" in captured.out
    assert "bonl identify: scoring 4 candidates on 2 record(s) of 1600 samples" in captured.err
    assert main(["identify", str(paths[0]), str(paths[1]), "--input", "u", "--output", "y", "--test-from", "100",
                 "--out", str(tmp_path / "x.json")]) == 1
    assert "--test-from splits one data file" in capsys.readouterr().err


def test_simulate_writes_the_model_files_free_run(hammerstein_file, tmp_path, capsys):
    path, truth = hammerstein_file
    (tmp_path / "truth.json").write_text(truth.to_json())
    assert main(["simulate", str(tmp_path / "truth.json"), str(path), "--input", "valve", "--output", "speed",
                 "--out", str(tmp_path / "sim.csv")]) == 0
    u, simulated = bonl.read_columns(tmp_path / "sim.csv", ["u", "simulated"])
    assert np.array_equal(u, bonl.read_columns(path, ["valve"])[0])
    np.testing.assert_allclose(simulated, truth.simulate(u), rtol=0, atol=1e-15 * np.abs(simulated).max())
    assert "RMS error against 'speed'" in capsys.readouterr().out
    assert main(["simulate", str(tmp_path / "missing.json"), str(path), "--input", "valve",
                 "--out", str(tmp_path / "x.csv")]) == 1
    assert "missing.json: no such file" in capsys.readouterr().err


def test_read_columns_takes_positions_in_a_file_without_a_header(tmp_path):
    path = _csv(tmp_path / "plain.csv", {"a": np.array([1.0, 2.0, 3.0]), "b": np.array([4.0, 5.0, 6.5])}, header=False)
    b, a = bonl.read_columns(path, [1, "0"])
    assert np.array_equal(a, [1.0, 2.0, 3.0]) and np.array_equal(b, [4.0, 5.0, 6.5])


def test_summary_and_plot_fit_show_the_model_and_its_free_run(hammerstein_file):
    path, truth = hammerstein_file
    u, y = bonl.read_columns(path, ["valve", "speed"])
    text = bonl.summary(truth, u, y, test_from=2000)
    for name, values in truth.params.items():
        assert f"  {name:<6} " + " ".join(f"{v:.6g}" for v in np.atleast_1d(values)) in text
    assert f"largest pole radius {truth.pole_radius:.6g}" in text
    assert "samples not fitted on: RMS error 0," in text  # the truth simulates its own record exactly
    figure = bonl.plot_fit(truth, u, y, test_from=2000)
    top, bottom = figure.axes
    np.testing.assert_array_equal(top.lines[1].get_ydata(), truth.simulate(u))
    np.testing.assert_array_equal(bottom.lines[0].get_ydata(), y - truth.simulate(u))
    with pytest.raises(ValueError, match="give both u and y"):
        bonl.summary(truth, u)
    with pytest.raises(ValueError, match="test_from must be in"):
        bonl.plot_fit(truth, u, y, test_from=0)
