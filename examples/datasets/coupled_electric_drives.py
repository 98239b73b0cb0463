"""Coupled electric drives, PRBS record 1 (Wigren and Schoukens 2017;
data/coupled-electric-drives/SOURCE.md): u1 to z1 (the pulley speed's magnitude), estimate on the
first 250 samples, simulate the whole record from rest and score the RMS error on the last 250."""

import numpy as np

from benchmark import DATA, Benchmark, Test, main
from comparison import Comparison


#: docs/benchmarks.md: the published figures beside bonl's (from SOURCE.md).
COMPARISON = Comparison(test="samples 251-500")  # SOURCE.md gives no figures for this split


def make():
    """Coupled electric drives: every model family selected on samples 1-250, tested on 251-500."""
    data = np.genfromtxt(DATA / "coupled-electric-drives" / "drive_prbs.csv", delimiter=",", names=True)
    u, y = data["u1"], data["z1"]
    return Benchmark(
        name="coupled-electric-drives", unit="(speed magnitude)",
        estimation=[(u[:250], y[:250])],
        tests=[Test("samples 251-500", u, y, skip=250)],
        orders=dict(na=[1, 2, 3, 4], nb=[0, 1, 2, 3], nk=[0, 1, 2], r=[1, 2, 3], r1=[2, 3]),
        published=[])  # SOURCE.md names the split, no figures


if __name__ == "__main__":
    main(make)
