"""The Bouc-Wen benchmark's own law run on its records, to see how its test records were made.

The benchmark (Noël and Schoukens 2016, data/bouc-wen/SOURCE.md) simulates
    m y'' + c y' + k y + z = u,    z' = alpha y' - beta (gamma |y'| z + delta y' |z|)    (nu = 1)
with m = 2 kg, c = 10 N s/m, k = 5e4 N/m, alpha = 5e4 N/m, beta = 1e3 1/m, gamma = 0.8, delta = -1.1,
at 20 times the 750 Hz sampling rate, the multisine generated at that rate. Here the same law is
integrated with the classical Runge-Kutta method at that rate, the input between the samples being the
band-limited periodic multisine the samples come from (its spectrum zero-padded), from rest:
- on the training record's first two periods it reproduces the measured output to a few 1e-6 m;
- on the validation multisine it is far off from rest and within 1e-6 m one period later: that record
  is one period of the periodic steady state, not a response from rest. Scored from rest, even the law
  that made it is that far off, so the benchmark's test simulates the input twice and scores the second
  period (examples/datasets/bouc_wen.py, ``periods=2``).

    python examples/datasets/bouc_wen_law.py --json docs/results/datasets/bouc_wen_law.json

tests/python/test_datasets.py runs it again and checks the committed figures."""

import argparse
import json
import math
import pathlib

import numpy as np

from bouc_wen import multisines

SAMPLE_RATE = 750.0  # Hz
UPSAMPLING = 20  # integration steps per sample, as the benchmark's own integrator
PERIOD = 8192  # samples per multisine period
MASS, DAMPING, STIFFNESS = 2.0, 10.0, 5e4
ALPHA, BETA, GAMMA, DELTA = 5e4, 1e3, 0.8, -1.1


def _fine_input(period):
    """The multisine between its samples: one period's spectrum zero-padded to the integration rate."""
    spectrum = np.fft.rfft(period)
    fine = np.zeros(period.size * UPSAMPLING // 2 + 1, complex)
    fine[:spectrum.size] = spectrum
    return np.fft.irfft(fine, period.size * UPSAMPLING) * UPSAMPLING


def simulate(period, periods):
    """The law's displacement at the samples over ``periods`` repetitions of one input period, from rest."""
    fine = np.tile(_fine_input(period), periods)
    h = 1.0 / (SAMPLE_RATE * UPSAMPLING)

    def rate(y, v, z, u):
        return v, (u - DAMPING * v - STIFFNESS * y - z) / MASS, ALPHA * v - BETA * (GAMMA * abs(v) * z + DELTA * v * abs(z))

    y = v = z = 0.0
    out = np.empty(period.size * periods)
    for i, u0 in enumerate(fine):
        if i % UPSAMPLING == 0:
            out[i // UPSAMPLING] = y
        u1 = fine[(i + 1) % fine.size]
        um = 0.5 * (u0 + u1)
        a = rate(y, v, z, u0)
        b = rate(y + 0.5 * h * a[0], v + 0.5 * h * a[1], z + 0.5 * h * a[2], um)
        c = rate(y + 0.5 * h * b[0], v + 0.5 * h * b[1], z + 0.5 * h * b[2], um)
        d = rate(y + h * c[0], v + h * c[1], z + h * c[2], u1)
        y += h / 6 * (a[0] + 2 * b[0] + 2 * c[0] + d[0])
        v += h / 6 * (a[1] + 2 * b[1] + 2 * c[1] + d[1])
        z += h / 6 * (a[2] + 2 * b[2] + 2 * c[2] + d[2])
    return out


def _rms(error):
    return float(math.sqrt(np.mean(error ** 2)))


def run(period=PERIOD):
    """The three figures; ``period`` < PERIOD (--quick, scripts/datasets.sh's smoke run) takes each
    multisine's first ``period`` samples for its period: the same computation at a fraction of the
    cost, its figures meaningless."""
    train, test = multisines()
    assert np.array_equal(train["u"][:PERIOD], train["u"][PERIOD:2 * PERIOD]), "the training input repeats one period"
    law_train = simulate(train["u"][:period], 2)
    law_test = simulate(test["u"][:period], 2)
    return {
        "training_first_two_periods": _rms(train["y"][:2 * period] - law_train),
        "validation_multisine_from_rest": _rms(test["y"][:period] - law_test[:period]),
        "validation_multisine_second_period": _rms(test["y"][:period] - law_test[period:]),
    }


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", type=pathlib.Path, help="write the figures here")
    parser.add_argument("--quick", action="store_true", help="a 512-sample period (a smoke run: see run)")
    args = parser.parse_args()
    figures = run(512 if args.quick else PERIOD)
    print(json.dumps(figures, indent=1))
    if args.json:
        args.json.write_text(json.dumps(figures, indent=1) + "\n")
