"""Hydraulic actuator (Sjöberg et al. 1995; data/hydraulic-actuator/SOURCE.md): estimate on samples
1-512, simulate the whole record from rest, score the RMS error on samples 513-1024."""

import numpy as np

from benchmark import DATA, Benchmark, Test, main
from comparison import Comparison


#: docs/lab/benchmarks.md: the published figures beside bonl's (from SOURCE.md).
COMPARISONS = (Comparison(
    test="samples 513-1024", protocol="SOURCE.md: from rest over the whole record",
    best=("one-hidden-layer neural network", 0.47),
    note="about; SOURCE.md quotes the paper from memory"),)


def make():
    """Hydraulic actuator: every model family selected on samples 1-512, tested on 513-1024."""
    data = np.genfromtxt(DATA / "hydraulic-actuator" / "actuator.csv", delimiter=",", names=True)
    u, y = data["u"], data["p"]
    return Benchmark(
        name="hydraulic-actuator", unit="(scaled pressure)",
        estimation=[(u[:512], y[:512])],
        tests=[Test("samples 513-1024", u, y, skip=512)],
        orders=dict(na=[1, 2, 3, 4], nb=[0, 1, 2, 3], nk=[0, 1, 2], r=[1, 2, 3], r1=[2, 3]),
        published=[("linear ARX(3,2,1), from memory of the paper", "about 0.99"),
                   ("one-hidden-layer neural network, from memory of the paper", "about 0.47")])


if __name__ == "__main__":
    main(make)
