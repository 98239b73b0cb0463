"""EMPS, electro-mechanical positioning system (Janot et al. 2019; data/emps/SOURCE.md): u = vir,
y = qm; estimate on DATA_EMPS, simulate DATA_EMPS_PULSES after the benchmark's 20-sample
state-initialisation window and score its RMS error [m]. The data were taken in closed loop and the
plant holds an integrator; bonl's models are open-loop and keep their poles inside the unit circle."""

import numpy as np
import scipy.io

from benchmark import DATA, Benchmark, Test, main
from comparison import Comparison


def _record(name):
    data = scipy.io.loadmat(DATA / "emps" / name)
    return data["vir"].ravel().astype(float), data["qm"].ravel().astype(float)


#: docs/benchmarks.md: the published figures beside bonl's (from SOURCE.md).
COMPARISONS = (Comparison(test="pulses record", protocol="nonlinear-benchmarks 1.0.1: 20-sample window",
                          best=("dynoNet, Forgione and Piga 2021", 2.64e-3)),)


def make():
    """EMPS: every model family selected on DATA_EMPS, tested on DATA_EMPS_PULSES."""
    u, y = _record("DATA_EMPS.mat")
    u_test, y_test = _record("DATA_EMPS_PULSES.mat")
    return Benchmark(
        name="emps", unit="m",
        estimation=[(u, y)],
        tests=[Test("pulses record", u_test, y_test, window=20)],
        orders=dict(na=[1, 2, 3], nb=[1, 2], nk=[0, 1], r=[1, 3], r1=[3]),
        identify=[dict(operating_point="initial"), dict(operating_point="mean")],
        published=[("dynoNet (Forgione and Piga 2021), fit 96.8 %", "2.64e-3")])


if __name__ == "__main__":
    main(make)
