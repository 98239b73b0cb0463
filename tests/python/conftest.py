"""Shared fixtures: the known systems (tests/data/known_systems.json, as the C++ tests), fixed seeds."""

import importlib.util
import json
import pathlib

import numpy as np
import pytest

import bonl

KNOWN_SYSTEMS = pathlib.Path(__file__).resolve().parents[1] / "data" / "known_systems.json"
MEASURED_DATA_EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "measured_data" / "measured_data.py"


def load_measured_data_example():
    """examples/measured_data/measured_data.py as a module (it is a script, not part of the package)."""
    spec = importlib.util.spec_from_file_location("measured_data_example", MEASURED_DATA_EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def known_models(set_name="paper_orders"):
    """The known systems of tests/data/known_systems.json (shared with the C++ tests), one per model of
    bonl.MODELS: 'paper_orders' (na=3, nb=2, nk=8, r=r1=3) or 'small' (na=2, nb=1, nk=2, r=2, r1=3)."""
    systems = json.loads(KNOWN_SYSTEMS.read_text())[set_name]
    return {name: bonl.load_model(json.dumps(document)) for name, document in systems.items()}


def random_levels(n, hold, amplitude, seed):
    """Levels uniform in [-amplitude, amplitude], each held `hold` samples."""
    rng = np.random.default_rng(seed)
    levels = rng.uniform(-amplitude, amplitude, size=(n + hold - 1) // hold)
    return np.repeat(levels, hold)[:n]


@pytest.fixture(params=sorted(known_models()))
def known(request):
    """(name, model) for each known system."""
    return request.param, known_models()[request.param]
