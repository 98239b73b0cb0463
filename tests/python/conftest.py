"""Shared fixtures: the known systems of the C++ tests (tests/cpp/test_support.hpp), fixed seeds."""

import numpy as np
import pytest

import bonl

FRONT = dict(
    f=[0.002, 0.06, 0.02, -0.01],
    p=[-0.003, -0.02, -0.03, 0.015],
    b=[1.0, 0.5, 0.2],
    a=[-1.7, 1.04, -0.238],
)


def known_models():
    """The four known systems at the paper's orders (na=3, nb=2, nk=8, r=r1=3)."""
    return {
        "ARX": bonl.ARX(3, 2, 8, b=[0.05, 0.03, 0.02], a=FRONT["a"]),
        "Hammerstein": bonl.Hammerstein(3, 2, 8, 3, **FRONT),
        "HammersteinWiener": bonl.HammersteinWiener(3, 2, 8, 3, 3, q=[1.0, 0.2, 0.05], **FRONT),
        "PseudoHammersteinWiener": bonl.PseudoHammersteinWiener(3, 2, 8, 3, c=0.1, **FRONT),
    }


def random_levels(n, hold, amplitude, seed):
    """Levels uniform in [-amplitude, amplitude], each held `hold` samples."""
    rng = np.random.default_rng(seed)
    levels = rng.uniform(-amplitude, amplitude, size=(n + hold - 1) // hold)
    return np.repeat(levels, hold)[:n]


@pytest.fixture(params=sorted(known_models()))
def known(request):
    """(name, model) for each known system."""
    return request.param, known_models()[request.param]
