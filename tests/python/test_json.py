"""The JSON model format, one format for C++ and Python: round trips within Python and across
languages (a model saved from Python simulates the same in C++ to 1e-12, and back)."""

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import bonl
from conftest import known_models, random_levels

DATA = pathlib.Path(__file__).resolve().parents[1] / "data"


def _tool():
    path = os.environ.get("BONL_MODEL_TOOL")
    if not path:
        pytest.fail("BONL_MODEL_TOOL is not set: build the C++ tests and point it at bonl_model_tool")
    return path


def test_round_trip_in_python(known):
    name, model = known
    text = model.to_json()
    document = json.loads(text)
    assert document["format"] == "bonl-model" and document["version"] == 2
    assert document["model"] == name
    assert document["operating_point"] == {"u0": 0.0, "y0": 0.0}
    loaded = bonl.load_model(text)
    assert type(loaded) is type(model)
    np.testing.assert_array_equal(loaded.theta, model.theta)
    model.operating_point = (0.1 + 0.2, -1.0 / 3.0)
    assert bonl.load_model(model.to_json()).operating_point == (0.1 + 0.2, -1.0 / 3.0)


def test_version_1_files_load_at_operating_point_zero(known):
    """Files written before the operating point (version 1) still load; the known systems are such files."""
    name, model = known
    document = json.loads(model.to_json())
    del document["operating_point"], document["input_range"]
    document["version"] = 1
    loaded = bonl.load_model(json.dumps(document))
    assert loaded.operating_point == (0.0, 0.0)
    assert loaded.input_range == (-np.inf, np.inf)
    np.testing.assert_array_equal(loaded.theta, model.theta)


def test_bad_json_is_a_value_error():
    with pytest.raises(ValueError):
        bonl.load_model("{not json")
    text = json.loads(known_models()["PseudoHammersteinWiener"].to_json())
    text["params"]["f"] = [1.0, 2.0]
    with pytest.raises(ValueError, match="params.f"):
        bonl.load_model(json.dumps(text))


def test_python_model_simulates_the_same_in_cpp(tmp_path, known):
    name, model = known
    u = random_levels(1000, 5, 1.0, 9)
    fitted = bonl.identify(model, u, model.simulate(u) + 0.001 * np.sin(np.arange(u.size)))
    (tmp_path / "model.json").write_text(fitted.to_json())
    np.savetxt(tmp_path / "u.txt", u, fmt="%.17g")
    out = subprocess.run([_tool(), "simulate", str(tmp_path / "model.json"), str(tmp_path / "u.txt")],
                         check=True, capture_output=True, text=True).stdout
    np.testing.assert_allclose(np.array(out.split(), dtype=float), fitted.simulate(u), rtol=0, atol=1e-12)


def test_cpp_model_simulates_the_same_in_python(tmp_path):
    subprocess.run([_tool(), "identify", str(tmp_path / "cpp.json")], check=True)
    model = bonl.load_model((tmp_path / "cpp.json").read_text())
    assert type(model) is bonl.PseudoHammersteinWiener
    u = random_levels(800, 4, 1.0, 11)
    np.savetxt(tmp_path / "u.txt", u, fmt="%.17g")
    out = subprocess.run([_tool(), "simulate", str(tmp_path / "cpp.json"), str(tmp_path / "u.txt")],
                         check=True, capture_output=True, text=True).stdout
    np.testing.assert_allclose(model.simulate(u), np.array(out.split(), dtype=float), rtol=0, atol=1e-12)


def test_committed_fixture_loads():
    model = bonl.load_model((DATA / "phw_model.json").read_text())
    assert type(model) is bonl.PseudoHammersteinWiener
