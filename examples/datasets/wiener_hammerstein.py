"""Wiener-Hammerstein benchmark, SYSID 2009 (Schoukens, Suykens and Ljung 2009;
data/wiener-hammerstein-2009/SOURCE.md), by its original protocol: estimate on samples 1-100 000,
simulate 100 001-188 000 from rest and score the RMS error without the first 1 000 of them [V]."""

import numpy as np

from benchmark import DATA, Benchmark, Test, main
from comparison import Comparison


def load():
    data = np.genfromtxt(DATA / "wiener-hammerstein-2009" / "WienerHammerBenchmark.csv", delimiter=",", names=True)
    return data["uBenchMark"], data["yBenchMark"]


#: docs/lab/benchmarks.md: the published figures beside bonl's (from SOURCE.md).
COMPARISONS = (Comparison(
    test="samples 101 001-188 000",
    protocol="the benchmark's own (SOURCE.md): from rest, the first 1 000 samples not scored",
    best=("M. Schoukens, Pintelon and Rolain 2014", 2.8e-4),
    block_oriented=("M. Schoukens, Pintelon and Rolain 2014", 2.8e-4)),)


def make():
    """Wiener-Hammerstein: every model family selected on samples 1-100 000, tested on 101 001-188 000."""
    u, y = load()
    return Benchmark(
        name="wiener-hammerstein-2009", unit="V",
        estimation=[(u[:100000], y[:100000])],
        tests=[Test("samples 101 001-188 000", u[100000:], y[100000:], skip=1000)],
        orders=dict(na=[2, 4, 6], nb=[1, 3, 5], nk=[0, 1], r=[3], r1=[3]),
        # The circuit's two filters are third order (SOURCE.md): G1 and G2 with three poles each; the
        # diode network saturates, which a polynomial follows only at a high degree, hinges (a
        # piecewise-linear nonlinearity, r = 1) with a knot every few percent of the samples.
        family_orders={"WienerHammerstein": dict(na1=[3], nb1=[2], nk=[0, 1], r=[1, 10, 15, 20], nh=[0, 10, 20],
                                                 na2=[3], nb2=[2])},
        published=[("polynomial NARX (SysIdentPy), nonlinear_benchmarks split", "1.52e-2"),
                   ("dynoNet (Forgione and Piga 2021)", "1.2e-3"),
                   ("block-oriented, best published (M. Schoukens et al. 2014)", "2.8e-4")])


if __name__ == "__main__":
    main(make)
