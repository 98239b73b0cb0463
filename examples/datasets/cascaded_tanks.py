"""Cascaded tanks (Schoukens et al. 2016; data/cascaded-tanks/SOURCE.md): estimate on (uEst, yEst),
simulate (uVal, yVal) after the benchmark's 5-sample state-initialisation window (SOURCE.md; the
earlier nonlinear-benchmarks versions' window: 1.0.1's 50 samples make the chosen P-H-W's figure move
by 15% when the training output changes in its last digits, docs/lab/benchmarks.md). Both records start
from the same state, not from rest at zero: the model's operating point is the estimation record's
first sample or the mean of the record (identify's operating_point="initial" or "mean"), chosen like
the orders."""

import numpy as np

from benchmark import DATA, Benchmark, Test, main
from comparison import Comparison


#: docs/lab/benchmarks.md: the published figures beside bonl's (from SOURCE.md).
COMPARISONS = (Comparison(test="validation record", protocol="SOURCE.md (nonlinear-benchmarks before 1.0.1): 5-sample window",
                          best=("grey box with overflow, Rogers et al. 2017", 0.18)),)


def make():
    """Cascaded tanks: every model family selected on the estimation record, tested on the validation record."""
    data = np.genfromtxt(DATA / "cascaded-tanks" / "dataBenchmark.csv", delimiter=",", names=True)
    return Benchmark(
        name="cascaded-tanks", unit="V",
        estimation=[(data["uEst"], data["yEst"])],
        tests=[Test("validation record", data["uVal"], data["yVal"], window=5)],
        orders=dict(na=[1, 2, 3, 4], nb=[0, 1, 2, 3], nk=[0, 1, 2], r=[1, 2, 3], r1=[2, 3]),
        identify=[dict(operating_point="initial"), dict(operating_point="mean")],
        published=[("best linear approximation (Relan et al. 2017)", "0.75"),
                   ("Volterra (Birpoutsoukis et al. 2018)", "0.54"),
                   ("nonlinear state space (Relan et al. 2017)", "0.34"),
                   ("grey box with overflow (Rogers et al. 2017), best", "0.18")])


if __name__ == "__main__":
    main(make)
