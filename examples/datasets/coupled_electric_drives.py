"""Coupled electric drives, PRBS record 1 (Wigren and Schoukens 2017;
data/coupled-electric-drives/SOURCE.md): u1 to z1 (the pulley speed's magnitude), estimate on the
first 250 samples (the split of the GP literature, SOURCE.md), simulate samples 251-500 after their first
10, measured (the state-initialisation window nonlinear-benchmarks 1.0.1 gives this data set, whose
loader uses another record), and score the RMS error on samples 261-500."""

import numpy as np

from benchmark import DATA, Benchmark, Test, main
from comparison import Comparison


#: docs/lab/benchmarks.md: the published figures beside bonl's (from SOURCE.md).
COMPARISONS = (Comparison(  # SOURCE.md gives no figures for this split
    test="samples 261-500", protocol="split of the GP literature (SOURCE.md); 10-sample window of "
    "nonlinear-benchmarks 1.0.1"),)


def make():
    """Coupled electric drives: every model family selected on samples 1-250, tested on 261-500."""
    data = np.genfromtxt(DATA / "coupled-electric-drives" / "drive_prbs.csv", delimiter=",", names=True)
    u, y = data["u1"], data["z1"]
    return Benchmark(
        name="coupled-electric-drives", unit="(speed magnitude)",
        estimation=[(u[:250], y[:250])],
        tests=[Test("samples 261-500", u[250:], y[250:], window=10)],
        orders=dict(na=[1, 2, 3, 4], nb=[0, 1, 2, 3], nk=[0, 1, 2], r=[1, 2, 3], r1=[2, 3]),
        published=[])  # SOURCE.md names the split, no figures


if __name__ == "__main__":
    main(make)
