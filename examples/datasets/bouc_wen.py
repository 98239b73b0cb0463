"""Bouc-Wen hysteretic benchmark, simulated data (Noël and Schoukens 2016; data/bouc-wen/SOURCE.md):
estimate on the training multisine (40 960 samples), simulate the two validation records and score
their RMS errors [m]: the multisine (8 192 samples), which is one period of the periodic steady state
(bouc_wen_law.py: the benchmark's own law is 4.6e-5 m off it from rest), simulated over two periods
and scored on the second, and also from rest; and the sine sweep (153 000 samples) from rest."""

import numpy as np
import scipy.io

from benchmark import DATA, Benchmark, Test, main
from comparison import Comparison


#: docs/lab/benchmarks.md: the published figures beside bonl's (from SOURCE.md).
COMPARISONS = (Comparison(test="validation multisine",
                          protocol="the benchmark's own (SOURCE.md): periodic steady state (bouc_wen_law.py)",
                          best=("decoupled PNLSS, Esfahani et al. 2017", 1.87e-5)),)


def _plays(y):
    """The plays' thresholds from the estimation output: r_i = i / (np + 1) of the standard deviation
    of s (the displacement, or its first difference for nv = 1), so that the loops the multisine makes
    reach past most of them."""
    spread = {0: float(np.std(y)), 1: float(np.std(np.diff(y)))}

    def prepare(structure):
        if structure.np:
            structure.thresholds = spread[structure.nv] * np.arange(1, structure.np + 1) / (structure.np + 1)
    return prepare


def _record(name):
    """One of the benchmark's validation records as its .mat files hold it (uval_<name>, yval_<name>)."""
    return tuple(scipy.io.loadmat(DATA / "bouc-wen" / f"{side}val_{name}.mat")[f"{side}val_{name}"].ravel()
                 .astype(float) for side in "uy")


def multisines():
    """The training and the validation multisine, each a structured array with fields u and y."""
    return tuple(np.genfromtxt(DATA / "bouc-wen" / f"{name}_multisine.csv", delimiter=",", names=True)
                 for name in ("train", "val"))


def make():
    """Bouc-Wen: every model family selected on the training multisine, tested on the validation multisine."""
    train, test = multisines()
    return Benchmark(
        name="bouc-wen", unit="m",
        estimation=[(train["u"], train["y"])],
        tests=[Test("validation multisine", test["u"], test["y"], periods=2),
               Test("validation multisine, from rest", test["u"], test["y"]),
               Test("sine sweep", *_record("sinesweep"))],
        orders=dict(na=[2, 4, 6], nb=[1, 3, 5], nk=[0, 1], r=[3], r1=[3]),
        # The nonlinear-feedback model: the restoring force fed back as a cubic of the displacement or of
        # the velocity, and with np = 8 a Prandtl-Ishlinskii operator of it (the hysteresis, rate-
        # independent in the benchmark's Bouc-Wen law with nu = 1), its thresholds spread over one
        # standard deviation of what the plays see in the estimation record (_plays).
        # The Bouc-Wen feedback model: the benchmark's law itself in the loop, with one to three taps of
        # the force's block D.
        family_orders={"NonlinearFeedback": dict(nh=[0], nd=[1, 2], nv=[0, 1], np=[0, 8]),
                       "BoucWenFeedback": dict(nd=[1, 2, 3])},
        prepare={"NonlinearFeedback": _plays(train["y"])},
        published=[("NFIR local model network (Belz et al. 2017)", "1.63e-4"),
                   ("dynoNet (Forgione and Piga 2021)", "4.52e-5"),
                   ("decoupled PNLSS (Esfahani et al. 2017)", "1.87e-5")])


if __name__ == "__main__":
    main(make)
