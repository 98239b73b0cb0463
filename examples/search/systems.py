"""Known systems of every model family, for judging the structure search (``bonl.search``) against a
grid around each system's true structure (search_vs_grid.py). They are not the tests' known systems
(tests/data/known_systems.json): other orders, delays and nonlinearities, each a machine's kind of
nonlinearity, so that the search is judged on systems it was not written against.

Each system is a bonl model with its parameters, an input (random levels held a few samples, or a
sum of sines), and the output noise (white, a fraction of the noise-free output's standard
deviation). Estimation and test records are different realisations of the same kind of input.
"""

from __future__ import annotations

import dataclasses
from typing import Any, Callable, Dict, List, Tuple

import numpy as np

import bonl


@dataclasses.dataclass(frozen=True)
class System:
    name: str              #: what it is, in a few words
    make: Callable[[], Any]  #: the true model (a new object each call)
    amplitude: float = 1.0   #: the input's amplitude about 0
    hold: int = 5            #: random levels held this many samples
    noise: float = 0.02      #: white output noise, a fraction of the noise-free output's std

    def records(self, samples: int, seed: int) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(u, y measured, y noise-free) of one realisation."""
        rng = np.random.default_rng(seed)
        levels = rng.uniform(-self.amplitude, self.amplitude, samples // self.hold + 1)
        u = np.repeat(levels, self.hold)[:samples]
        clean = np.asarray(self.make().simulate(u), dtype=float)
        y = clean + self.noise * float(np.std(clean)) * rng.standard_normal(samples)
        return u, y, clean


def _model(model_class, orders: Dict[str, int], **params) -> Callable[[], Any]:
    def make():
        return model_class(*[orders.get(name, model_class.ORDER_DEFAULTS.get(name)) for name in model_class.ORDERS],
                           **params)
    return make


SYSTEMS: List[System] = [
    System("linear drive (ARX)",
           _model(bonl.ARX, dict(na=2, nb=1, nk=2), b=[0.3, 0.15], a=[-1.3, 0.42])),
    System("valve with an asymmetric gain (Hammerstein)",
           _model(bonl.Hammerstein, dict(na=2, nb=1, nk=3, r=3), b=[1.0, 0.6], a=[-1.4, 0.5],
                  f=[0.0, 0.08, 0.03, -0.02], p=[0.0, -0.04, -0.03, 0.01])),
    System("saturating sensor (Wiener)",
           _model(bonl.Wiener, dict(na=2, nb=1, nk=1, r1=3), b=[0.4, 0.2], a=[-1.1, 0.3], q=[1.0, 0.0, -0.25])),
    System("valve and sensor (Hammerstein-Wiener)",
           _model(bonl.HammersteinWiener, dict(na=3, nb=1, nk=2, r=2, r1=2), b=[1.0, 0.4], a=[-1.5, 0.74, -0.12],
                  f=[0.0, 0.1, 0.05], p=[0.0, -0.03, -0.08], q=[1.0, 0.3])),
    System("valve and linkage with backlash (P-H-W)",
           _model(bonl.PseudoHammersteinWiener, dict(na=2, nb=1, nk=4, r=2), b=[1.0, 0.5], a=[-1.5, 0.56],
                  f=[0.0, 0.12, 0.02], p=[0.0, -0.04, 0.0], c=0.15)),
    System("saturating amplifier between two filters (Wiener-Hammerstein)",
           _model(bonl.WienerHammerstein, dict(na1=2, nb1=1, nk=1, r=1, nh=2, na2=2, nb2=1),
                  b1=[0.3, 0.2], a1=[-1.2, 0.4], f=[1.0], knots=[-0.5, 0.4], g=[-0.8, -0.7], b2=[1.0, 0.3],
                  a2=[-0.9, 0.2])),
    System("stiffening spring (nonlinear feedback of the output)",
           _model(bonl.NonlinearFeedback, dict(na=2, nb=1, nk=1, r=3, nh=0, nd=1, nv=0),
                  b=[0.05, 0.04], a=[-1.8, 0.9], f=[0.0, -0.1], d=[1.0]), amplitude=1.0, hold=20),
    System("integrating drive with friction (velocity feedback, integrator)",
           _model(bonl.NonlinearFeedback, dict(na=1, nb=0, nk=1, r=1, nh=2, nd=1, nv=1, ni=1),
                  b=[0.02], a=[-0.9], knots=[-0.01, 0.01], g=[-0.06, -0.06], d=[1.0]), hold=25),
    System("hysteretic restoring force (play operators in the loop)",
           _model(bonl.NonlinearFeedback, dict(na=2, nb=1, nk=1, r=1, nh=0, nd=1, nv=0, np=2),
                  b=[0.1, 0.05], a=[-1.6, 0.7], thresholds=[0.3, 0.8], w=[-0.04, -0.03], d=[1.0]), hold=15),
    System("valve pilot hysteresis (Prandtl-Ishlinskii Hammerstein)",
           _model(bonl.PrandtlIshlinskiiHammerstein, dict(na=2, nb=1, nk=2, r=1, np=2), b=[1.0, 0.3],
                  a=[-1.3, 0.45], f=[0.0, 0.1], thresholds=[0.2, 0.5], g=[0.05, 0.04])),
    System("bolted joint (Bouc-Wen feedback)",
           _model(bonl.BoucWenFeedback, dict(na=2, nb=1, nk=1, nd=1), b=[0.08, 0.05], a=[-1.7, 0.8],
                  alpha=0.04, gamma=2.0, delta=0.5, d=[1.0]), hold=15),
]
