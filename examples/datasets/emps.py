"""EMPS, electro-mechanical positioning system (Janot et al. 2019; data/emps/SOURCE.md): u = vir,
y = qm; estimate on DATA_EMPS, simulate DATA_EMPS_PULSES after the benchmark's 20-sample
state-initialisation window and score its RMS error [m]. The data were taken in closed loop and the
plant holds an integrator. The block-model families run without one (their estimated poles inside
the unit circle); the nonlinear-feedback family is the drive's physics: a position integrating a
velocity (ni = 1) that a friction curve of the velocity acts on (nv = 1), at rest for u = 0."""

import numpy as np
import scipy.io

from benchmark import DATA, Benchmark, Test, main
from comparison import Comparison


def _record(name):
    data = scipy.io.loadmat(DATA / "emps" / name)
    return data["vir"].ravel().astype(float), data["qm"].ravel().astype(float)


#: docs/lab/benchmarks.md: the published figures beside bonl's (from SOURCE.md).
COMPARISONS = (Comparison(test="pulses record", protocol="nonlinear-benchmarks 1.0.1: 20-sample window",
                          best=("dynoNet, Forgione and Piga 2021", 2.64e-3)),)


def _friction_drive(y):
    """The nonlinear-feedback structures' setup from the estimation record: knots of the friction
    curve at +-0.25 (and +-1) standard deviations of the velocity (the position's first difference,
    where Coulomb friction changes slope), and the operating point (0, the first position): an
    integrating drive rests for zero force wherever it stands."""
    spread = float(np.std(np.diff(y)))

    def prepare(structure):
        inner = [-0.25 * spread, 0.25 * spread]
        structure.knots = np.array(inner if structure.nh == 2 else [-spread] + inner + [spread])
        structure.operating_point = (0.0, float(y[0]))
    return prepare


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
        # The first grid (nb 2, r 1, nd 1-2) chose the edge of na, nh and nd on the held-out estimation
        # data; this one adds nb 1-3, r 3 and nd 3.
        family_orders={"NonlinearFeedback": dict(na=[1, 2, 3], nb=[1, 2, 3], nk=[0, 1], r=[1, 3], nh=[2, 4],
                                                 nd=[1, 2, 3], nv=[1], ni=[1])},
        family_identify={"NonlinearFeedback": [{}]},  # the structure's operating point (_friction_drive)
        prepare={"NonlinearFeedback": _friction_drive(y)},
        # The test is a free run over the whole 25 s record of an integrating drive, where every velocity
        # error adds up; the held-out last quarter (6 s) does not measure that drift, the free run over
        # the whole estimation record does: the candidates are ranked by its BIC.
        criterion="bic",
        # The records start in motion, and the position integrates: fitted from rest, the chosen model
        # had learnt a start transient that the test's window removes, and it simulated the estimation
        # record itself twice as far off after the window as from rest (a constant offset). Fitted after
        # the window, it is used as it was fitted.
        fit_after_window=True,
        published=[("dynoNet (Forgione and Piga 2021), fit 96.8 %", "2.64e-3")])


if __name__ == "__main__":
    main(make)
