"""examples/measured_data: the pipeline on the measured actuator and cascaded-tanks data (small grid)."""

import importlib.util
import json
import math
import pathlib

import numpy as np
import pytest

import bonl
from conftest import load_measured_data_example

ROOT = pathlib.Path(__file__).resolve().parents[2]
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


md = load_measured_data_example()


@pytest.fixture(scope="module")
def first_run(tmp_path_factory):
    """The example's command line, small grid, once for the module."""
    out = tmp_path_factory.mktemp("measured_data")
    plot = importlib.util.find_spec("matplotlib") is not None
    argv = ["--small-grid", "--out", str(out), "--json", str(out / "results.json")] + ([] if plot else ["--no-plot"])
    assert md.main(argv) == 0
    return out, plot


def test_data_files_are_the_documented_ones():
    act = md.load_actuator()
    tanks = md.load_cascaded_tanks()
    assert act["u"].shape == act["y"].shape == (1024,)
    assert all(tanks[key].shape == (1024,) for key in ("uEst", "uVal", "yEst", "yVal"))
    assert act["u"].min() == pytest.approx(-1.4546, abs=1e-4) and act["y"].max() == pytest.approx(3.517, abs=1e-3)
    assert tanks["yEst"].max() == pytest.approx(10.0) and tanks["uEst"].min() == pytest.approx(0.409, abs=1e-3)
    for folder in ("hydraulic-actuator", "cascaded-tanks"):
        assert (ROOT / "data" / folder / "SOURCE.md").is_file()


def test_pipeline_runs_on_both_data_sets(first_run):
    out, plot = first_run
    table = json.loads((out / "results.json").read_text())
    assert set(table) == {"actuator", "cascaded_tanks"}
    for case in table:
        assert set(table[case]) == set(md.NAMES)
        for name, value in table[case].items():
            assert math.isfinite(value) and 0.0 < value < 3.0, (case, name, value)
    # Every model file loads and is the model the table was computed with.
    selection = json.loads((out / "selection.json").read_text())
    act = md.load_actuator()
    tanks = md.load_cascaded_tanks()
    signals = {"actuator": (act["u"], act["y"], 512), "cascaded_tanks": (tanks["uVal"], tanks["yVal"], 0)}
    for case, models in selection.items():
        u, y, start = signals[case]
        for name, info in models.items():
            model = bonl.load_model((out / info["model_file"]).read_text())
            simulated = np.asarray(model.simulate(u - info["u0"])).ravel() + info["y0"]
            assert md.rms(simulated[start:] - y[start:]) == table[case][name]
    if plot:
        for case in ("actuator", "cascaded_tanks"):
            assert (out / f"{case}.png").read_bytes().startswith(PNG_SIGNATURE)


def test_results_are_deterministic(first_run, tmp_path):
    out, _ = first_run
    assert md.main(["--small-grid", "--no-plot", "--jobs", "1", "--out", str(tmp_path),
                    "--json", str(tmp_path / "results.json")]) == 0
    assert (tmp_path / "results.json").read_bytes() == (out / "results.json").read_bytes()
    for path in out.glob("*.json"):
        assert (tmp_path / path.name).read_bytes() == path.read_bytes(), path.name


def batch_least_squares(u, y, na, nb, nk, p0):
    """ARX by batch least squares, regressors from rest (past u and y zero), prior theta ~ N(0, p0 I):
    theta = (Phi' Phi + I / p0)^-1 Phi' y, theta = [b_0..b_nb, a_1..a_na]."""
    n = len(u)
    phi = np.zeros((n, nb + 1 + na))
    for k in range(n):
        for i in range(nb + 1):
            j = k - nk - i
            phi[k, i] = u[j] if j >= 0 else 0.0
        for i in range(1, na + 1):
            phi[k, nb + i] = -y[k - i] if k - i >= 0 else 0.0
    return np.linalg.solve(phi.T @ phi + np.eye(nb + 1 + na) / p0, phi.T @ y)


@pytest.mark.parametrize("orders", [(3, 2, 1), (2, 3, 2), (4, 0, 0)])
def test_arx_on_the_actuator_is_batch_least_squares(orders):
    act = md.load_actuator()
    u, y = act["u"][:512], act["y"][:512]
    settings = md.settings(bonl.ARX)
    assert settings == {"method": "equation_error", "forgetting": 1.0, "p0": 1e6, "normalise": False}
    model = bonl.identify(bonl.ARX(*orders), u, y, **settings)
    expected = batch_least_squares(u, y, *orders, p0=settings["p0"])
    theta = np.asarray(model.theta).ravel()
    assert np.max(np.abs(theta - expected)) <= 1e-8 * np.max(np.abs(expected))


def test_selection_never_reads_the_validation_part():
    """Changing the validation samples changes the score, never the chosen structure or the model."""
    act = md.load_actuator()
    u, y = act["u"], act["y"].copy()
    grid = {"na": (2, 3), "nb": (1, 2), "nk": (0, 1), "r": (2,), "r1": (3,)}
    model, _, info = md.run_case(bonl.HammersteinWiener, u[:512], y[:512], u, y, 512, grid, ("none",), 2)
    y[512:] = np.random.default_rng(5).normal(size=512)
    model2, _, info2 = md.run_case(bonl.HammersteinWiener, u[:512], y[:512], u, y, 512, grid, ("none",), 2)
    assert (info2["orders"], info2["check_rms"]) == (info["orders"], info["check_rms"])
    assert model2.to_json() == model.to_json()
    assert info2["validation_rms"] != info["validation_rms"]
