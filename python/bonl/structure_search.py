"""A structure search (``bonl.search``): the model an identification engineer would find, from the
estimation records alone, without a grid of orders given by hand.

It works in stages, as an engineer does, each scoring its candidates on held-out data with
:func:`bonl.select`'s scoring (the free-run error on held-out data, the candidate fitted on the rest;
with ``window``, after a state-initialisation window): 5-fold blocked cross-validation for records of
up to 10,000 samples together, 3-fold up to 30,000, and the last quarter of each record beyond
(:func:`scoring_scheme`), so that a short record's score does not hang on one stretch of it.

1. **linear**: the delay from an FIR fit (its first significant tap), then the operating point,
   identify's state-initialisation window and an integrator chosen on a few ARX structures, then the
   ARX orders grown from there by steepest descent;
2. **families**: every model family seeded at that linear structure (the nonlinear-feedback model in
   each of its physical variants: a stiffening spring, friction on the velocity with hinges, hysteresis
   with play operators; knots and thresholds placed from the records, :func:`place_from_data`);
   under cross-validation a family with an integrator is seeded twice, the state of its folds' fits
   measured and estimated (:func:`_fold_states`);
3. **nonlinearity**: each family's delay (:data:`SWEPT_DELAYS` beside the linear stage's), then its
   degrees, hinges and plays swept from its seed (:data:`SWEEPS`), each seed of a family on its own
   and the better kept;
4. **growth**: the ``families`` best structures grown one step at a time (each order up or down by one,
   a degree, the hinges and the plays to the next value of a ladder, an integrator in or out, with an
   integrator the folds' state measured or estimated, and with a window identify's window in or
   out), steepest
   descent while the held-out RMS error falls by more than ``tolerance``, the families in turn, until
   the time ``budget``;
5. **choice**: among the candidates whose held-out RMS error is within ``tolerance`` of the best, the
   one with the fewest parameters, refitted on all the records; where its free run there is not bounded, the next
   (:func:`bonl.select`'s bound: a model that diverges is never chosen).

Every candidate scored is in :attr:`SearchResult.table`, every stage's choice, with why, in
:attr:`SearchResult.stages`.
"""

from __future__ import annotations

import concurrent.futures
import dataclasses
import math
import sys
import time
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np
from numpy.typing import ArrayLike

from . import _bonl
from .selection import Candidate, _score_all, named_orders

__all__ = ["SearchResult", "Stage", "place_from_data", "search"]

#: The operating points the linear stage chooses between (identify's ``operating_point``; "zero" is
#: the structure's own, (0, 0)).
OPERATING_POINTS = ("zero", "mean", "initial")

#: Where the degrees, hinges and plays step to from a value: the next value up and down this ladder
#: (a polynomial's degree by one at small degrees and then by more; hinges and plays doubling).
LADDERS: Dict[str, Tuple[int, ...]] = {
    "r": (1, 2, 3, 4, 5, 7, 10, 15, 20, 25, 32),
    "r1": (2, 3, 4, 5, 7, 10),
    "nh": (0, 2, 4, 8, 12, 16, 24, 32),
    "np": (0, 2, 4, 8, 16),
}


@dataclasses.dataclass(frozen=True)
class Setting:
    """How a candidate is identified besides its structure: the operating point and identify's
    state-initialisation window; under cross-validation, also where the folds' fits take their state
    (:func:`bonl.select`'s ``fold_initial_state``)."""

    operating_point: str
    initialisation_window: int
    fold_initial_state: str = "measured"

    def options(self) -> Dict[str, Any]:
        """identify's options: those the chosen structure is refitted on all the records with."""
        options: Dict[str, Any] = {}
        if self.operating_point != "zero":
            options["operating_point"] = self.operating_point
        if self.initialisation_window:
            options["initialisation_window"] = self.initialisation_window
        return options

    def scored(self) -> Dict[str, Any]:
        """options(), and the folds' initial state where it is estimated: how a candidate was scored."""
        return {**self.options(), **({"fold_initial_state": self.fold_initial_state}
                                     if self.fold_initial_state != "measured" else {})}

    def folds_from(self, state: str) -> "Setting":
        return dataclasses.replace(self, fold_initial_state=state)


@dataclasses.dataclass(frozen=True)
class Stage:
    """One stage of the search: what it tried, what it chose and why."""

    name: str
    choice: str
    why: str
    candidates: int
    seconds: float


@dataclasses.dataclass(frozen=True)
class SearchResult:
    """What :func:`search` found."""

    best: Any                        #: the chosen structure identified on all the records
    linear: Any                      #: the linear stage's ARX structure identified on all the records (None: unbounded)
    setting: Dict[str, Any]          #: identify's options it was identified with (operating point, window)
    held_out_rms: float              #: its held-out RMS error
    linear_held_out_rms: float       #: the linear stage's ARX structure's
    linear_setting: Dict[str, Any]   #: identify's options of the linear stage's
    held_out: str                    #: how data were held out ("5-fold blocked cross-validation", ...)
    table: List[Candidate]           #: every candidate scored, best first (failed and refused last)
    settings: List[Dict[str, Any]]   #: each table row's identify options (Setting.scored: and its folds' state)
    stages: List[Stage]              #: the stages, in order
    budget_exhausted: bool           #: the growth stopped at the time budget, not at a local minimum
    seconds: float

    def __str__(self) -> str:
        lines = [f"{stage.name}: {stage.choice} ({stage.why}; {stage.candidates} candidates, {stage.seconds:.0f} s)"
                 for stage in self.stages]
        return "\n".join(lines)


#: The samples of the least-squares slope that stands for the velocity in :func:`place_from_data`.
VELOCITY_SPAN = 21


def _velocity(y: np.ndarray) -> np.ndarray:
    """The output's velocity per sample: the slope of a straight line fitted by least squares to each
    VELOCITY_SPAN consecutive samples (its first difference where the record is shorter). A first
    difference of a measured position is mostly its noise, whose spread is not the motion's."""
    if y.size < VELOCITY_SPAN:
        return np.diff(y)
    offsets = np.arange(VELOCITY_SPAN) - (VELOCITY_SPAN - 1) / 2
    return np.convolve(y, offsets[::-1] / float(offsets @ offsets), mode="valid")


def _velocity_or_output(records: Sequence[Tuple[np.ndarray, np.ndarray]], nv: int, y0: float) -> np.ndarray:
    """What a feedback model's nonlinearity sees, over every record: the output's deviation from the
    operating point (nv = 0) or its velocity (nv = 1, :func:`_velocity`)."""
    if nv:
        return np.concatenate([_velocity(y) for _, y in records])
    return np.concatenate([y for _, y in records]) - y0


def place_from_data(structure: Any, records: Sequence[Tuple[np.ndarray, np.ndarray]], y0: float = 0.0) -> Any:
    """A feedback structure's knots and plays' thresholds placed from the records (the rules of the
    data-set scripts, written once): for a nonlinear-feedback model, whose nonlinearity sees s (the
    output's deviation from ``y0``, or for nv = 1 its velocity, a least-squares slope over
    :data:`VELOCITY_SPAN` samples), with spread sigma the standard deviation of s,

    - hinges: nh / 2 knots on each side of 0, at 0.25, 1, 2, 3, ... sigma (where Coulomb friction and a
      stop change the slope);
    - plays: thresholds i / (np + 1) sigma, i = 1..np, so that the loops the records make reach past
      most of them.

    Every other structure is returned as it is (the Wiener-Hammerstein model places its knots in its
    own start, the Prandtl-Ishlinskii model its thresholds).

    Parameters
    ----------
    structure : model
        The structure to place (changed in place for a nonlinear-feedback model).
    records : sequence of (u, y) pairs
        The identification records whose output (or its first difference) sets the spread.
    y0 : float
        The output's operating point, subtracted before the spread is taken.

    Returns
    -------
    model
        ``structure``, its knots and thresholds placed; unchanged where the records have no spread.
    """
    if type(structure) is not _bonl.NonlinearFeedback:
        return structure
    spread = float(np.std(_velocity_or_output(records, structure.nv, y0)))
    if not spread > 0.0:
        return structure
    if structure.nh:
        side = structure.nh // 2
        scales = [0.25] + [float(j) for j in range(1, structure.nh)]
        right = [spread * s for s in scales[:structure.nh - side]]
        left = [-spread * s for s in scales[:side]]
        structure.knots = np.array(sorted(left + right))
    if structure.np:
        structure.thresholds = spread * np.arange(1, structure.np + 1) / (structure.np + 1)
    return structure


def _key(structure: Any, setting: Setting) -> tuple:
    return (type(structure).__name__, tuple(structure.orders), setting)


def _fir_delay(records: Sequence[Tuple[np.ndarray, np.ndarray]], taps: int, significance: float) -> Tuple[int, int]:
    """Two readings of the input's delay from an equation-error fit with two poles and ``taps``
    numerator taps (least squares, the input and output less their means): the first tap whose
    t-statistic exceeds ``significance``, and the first tap of the fit's impulse response at a fifth
    of its peak. (0, 0) where the records are too short for the fit."""
    na = 2
    rows, targets = [], []
    for u, y in records:
        u = u - np.mean(u)
        y = y - np.mean(y)
        n = u.size
        if n - taps < 4 * (taps + na):
            continue
        rows.append(np.column_stack([y[taps - j:n - j] for j in range(1, na + 1)]
                                    + [u[taps - i:n - i] for i in range(taps)]))
        targets.append(y[taps:])
    if not rows:
        return 0, 0
    regressors, target = np.vstack(rows), np.concatenate(targets)
    theta, *_ = np.linalg.lstsq(regressors, target, rcond=None)
    residual = target - regressors @ theta
    variance = float(residual @ residual) / max(1, target.size - theta.size)
    deviations = np.sqrt(np.maximum(variance * np.diag(np.linalg.pinv(regressors.T @ regressors)), 1e-300))
    t = np.abs(theta[na:]) / deviations[na:]
    significant = np.nonzero(t > significance)[0]
    a, b = theta[:na], theta[na:]
    h = np.zeros(taps)
    for k in range(taps):  # the impulse response of B / (1 - a1 q^-1 - a2 q^-2)
        h[k] = b[k] + sum(a[j] * h[k - 1 - j] for j in range(na) if k - 1 - j >= 0)
    peak = float(np.max(np.abs(h)))
    rise = int(np.argmax(np.abs(h) >= 0.2 * peak)) if peak > 0 else 0
    return (int(significant[0]) if significant.size else 0), rise


def _delay(records: Sequence[Tuple[np.ndarray, np.ndarray]], taps: int = 30) -> int:
    """The input's delay in samples: the first significant tap of an FIR-like fit (t > 3), but no later
    than its impulse response's rise to a fifth of the peak (where the first taps are small against
    the noise and the nonlinearity, the significance test alone reads a delay that is not there)."""
    significant, rise = _fir_delay(records, taps, 3.0)
    return min(significant, rise)


#: How the search holds data out, by the records' length together (samples): blocked
#: cross-validation where several fits per candidate are affordable and one held-out part would say
#: little, the last quarter of each record above (bonl.select's criteria).
CROSS_VALIDATION = ((10_000, 5), (30_000, 3))


def scoring_scheme(records: Sequence[Tuple[np.ndarray, np.ndarray]]) -> Dict[str, Any]:
    """The held-out scheme the search scores with on these records: ``{"criterion": "cross_validation",
    "folds": K}`` (5 folds up to 10,000 samples together, 3 up to 30,000) or ``{"criterion":
    "validation"}``."""
    samples = sum(u.size for u, _ in records)
    for limit, folds in CROSS_VALIDATION:
        if samples <= limit:
            return {"criterion": "cross_validation", "folds": folds}
    return {"criterion": "validation"}


class _Scorer:
    """Scores candidates (structure, setting) on the held-out data, each once (a cache), and keeps
    every row."""

    def __init__(self, records, window, scheme, executor, identify_options):
        self.records = records
        self.window = window
        self.scheme = scheme
        self.executor = executor
        self.identify_options = identify_options
        self._data: Dict[Setting, Any] = {}
        self.rows: Dict[tuple, Tuple[Candidate, Any, Setting]] = {}

    def data(self, setting: Setting):
        if setting not in self._data:
            self._data[setting] = _bonl._selection_data(records=self.records, window=self.window, **self.scheme,
                                                        fold_initial_state=setting.fold_initial_state,
                                                        **{**self.identify_options, **setting.options()})
        return self._data[setting]

    def score(self, pairs: Sequence[Tuple[Any, Setting]]) -> List[Candidate]:
        """The rows of the pairs, scoring those not scored yet (in parallel, on the executor)."""
        todo: Dict[Setting, Dict[tuple, Any]] = {}
        for structure, setting in pairs:
            key = _key(structure, setting)
            if key not in self.rows:
                todo.setdefault(setting, {})[key] = structure
        for setting, unique in todo.items():
            structures = list(unique.values())
            for structure, row in zip(structures, _score_all(structures, self.data(setting), self.executor, False)):
                self.rows[_key(structure, setting)] = (row, structure, setting)
        return [self.rows[_key(structure, setting)][0] for structure, setting in pairs]


def _mse_rms(mse: float) -> float:
    return math.sqrt(mse) if math.isfinite(mse) else math.inf


def _rms(row: Candidate) -> float:
    return _mse_rms(row.score) if row.error is None else math.inf


def _better_step(scorer: _Scorer, pairs: List[Tuple[Any, Setting]], mse: float,
                 tolerance: float) -> Optional[Tuple[Tuple[Any, Setting], Candidate]]:
    """The best of the pairs (structure, setting) where its held-out RMS error is more than
    ``tolerance`` below that of ``mse``, else None: one step of a steepest descent."""
    best = min(zip(pairs, scorer.score(pairs)), key=lambda entry: entry[1].score, default=None)
    return best if best is not None and _rms(best[1]) < _mse_rms(mse) * (1 - tolerance) else None


def _make(model_class: type, orders: Dict[str, int]) -> Optional[Any]:
    try:
        return model_class(*[orders[name] for name in model_class.ORDERS])
    except (ValueError, TypeError):
        return None


def _orders(structure: Any) -> Dict[str, int]:
    return dict(zip(type(structure).ORDERS, structure.orders))


def _neighbours(structure: Any) -> List[Any]:
    """The structures one step from ``structure``: each order up and down by one (the linear orders,
    the delay, the feedback taps), a degree, hinges or plays to the next value of its ladder, the
    integrator and a feedback model's nv toggled."""
    model_class = type(structure)
    orders = _orders(structure)
    out = []
    for name, value in orders.items():
        if name in LADDERS:
            ladder = LADDERS[name]
            below = [v for v in ladder if v < value]
            above = [v for v in ladder if v > value]
            steps = ([below[-1]] if below else []) + ([above[0]] if above else [])
        elif name in ("ni", "nv"):
            steps = [1 - value] if value in (0, 1) else []
        else:
            steps = [value - 1, value + 1]
        for step in steps:
            made = _make(model_class, {**orders, name: step})
            if made is not None:
                out.append(made)
    return out


#: Each family's nonlinearity swept from its seed (one order at a time, the others at the seed's):
#: the degrees, hinges and plays an engineer would try before growing the linear orders around them.
SWEEPS: Dict[Tuple[str, int], Dict[str, Tuple[int, ...]]] = {
    # (family, nv for the nonlinear-feedback model's variants, else 0): order -> values
    ("Hammerstein", 0): {"r": (2, 5, 7, 10)},
    ("Wiener", 0): {"r1": (2, 5, 7)},
    ("HammersteinWiener", 0): {"r": (2, 5, 7), "r1": (2, 5)},
    ("PseudoHammersteinWiener", 0): {"r": (2, 5, 7)},
    ("WienerHammerstein", 0): {"r": (2, 5, 7, 10, 15), "nh": (4, 8, 16)},
    ("NonlinearFeedback", 0): {"r": (2, 5, 7), "nh": (2, 4, 8), "np": (2, 8, 16)},
    ("NonlinearFeedback", 1): {"r": (3,), "nh": (4, 8)},
    ("PrandtlIshlinskiiHammerstein", 0): {"r": (3,), "np": (2, 8)},
    ("BoucWenFeedback", 0): {"nd": (2, 3)},
}


#: The delays every family tries beside the linear stage's: a delay read off a linear model can hold a
#: slow rise of the response that a block before a static map needs (a Wiener-Hammerstein chain's
#: first filter), and a sampled system without dead time has 0 or 1.
SWEPT_DELAYS = (0, 1)


def _delays(structure: Any) -> List[Any]:
    """The seed at the delays of SWEPT_DELAYS it does not have."""
    orders = _orders(structure)
    return [made for nk in SWEPT_DELAYS if nk != orders["nk"]
            and (made := _make(type(structure), {**orders, "nk": nk})) is not None]


def _sweep(structure: Any) -> List[Any]:
    """The structures of the seed's sweep (SWEEPS)."""
    orders = _orders(structure)
    key = (type(structure).__name__, orders.get("nv", 0))
    out = []
    for name, values in SWEEPS.get(key, {}).items():
        for value in values:
            made = _make(type(structure), {**orders, name: value})
            if made is not None:
                out.append(made)
    return out


def _seeds(linear: Any) -> List[Any]:
    """Every nonlinear family seeded at the linear structure's orders (na, nb, nk, ni): the polynomial
    blocks at degree 3, the Wiener-Hammerstein model with the linear orders in each of its blocks (a
    linear fit of a chain whose nonlinearity dominates shows the dominant poles only),
    the nonlinear-feedback model as a stiffening spring, as friction on the velocity (two hinges) and
    with hysteresis (four plays), the Bouc-Wen feedback model with one tap."""
    na, nb, nk, ni = linear.na, linear.nb, linear.nk, linear.ni
    wanted = [
        (_bonl.Hammerstein, dict(na=na, nb=nb, nk=nk, r=3, ni=ni)),
        (_bonl.Wiener, dict(na=na, nb=nb, nk=nk, r1=3, ni=ni)),
        (_bonl.HammersteinWiener, dict(na=na, nb=nb, nk=nk, r=3, r1=3, ni=ni)),
        (_bonl.PseudoHammersteinWiener, dict(na=na, nb=nb, nk=nk, r=3, ni=ni)),
        (_bonl.WienerHammerstein, dict(na1=na, nb1=nb, nk=nk, r=3, nh=0, na2=na, nb2=nb, ni=ni)),
        (_bonl.NonlinearFeedback, dict(na=na, nb=nb, nk=nk, r=3, nh=0, nd=1, nv=0, np=0, ni=ni)),
        (_bonl.NonlinearFeedback, dict(na=na, nb=nb, nk=nk, r=1, nh=2, nd=1, nv=1, np=0, ni=ni)),
        (_bonl.PrandtlIshlinskiiHammerstein, dict(na=na, nb=nb, nk=nk, r=1, np=4, ni=ni)),
        (_bonl.BoucWenFeedback, dict(na=na, nb=nb, nk=nk, nd=1, ni=ni)),
    ]
    return [made for model_class, orders in wanted if (made := _make(model_class, orders)) is not None]


def _describe(structure: Any) -> str:
    return f"{type(structure).__name__} " + " ".join(f"{k}={v}" for k, v in named_orders(structure).items())


def _fold_note(setting: Setting) -> str:
    return ", folds' state estimated" if setting.fold_initial_state != "measured" else ""


def _fold_states(structure: Any, cross_validation: bool) -> Tuple[str, ...]:
    """The folds' initial states a structure is scored with. A fold's fit part after its held-out block
    starts in motion; an integrator's state there is a position that its first samples' noisy
    outputs set poorly, and the error stays in every later sample. So under cross-validation a
    structure with an integrator (ni = 1) is scored with the folds' state measured and estimated
    (:func:`bonl.select`'s ``fold_initial_state``); without one, the error of a measured state decays,
    and the estimated state's extra freedom only fits the fold's noise."""
    return ("measured", "estimated") if cross_validation and _orders(structure).get("ni", 0) == 1 else ("measured",)


def search(u: Optional[ArrayLike] = None, y: Optional[ArrayLike] = None, *,
           records: Optional[Sequence[Tuple[ArrayLike, ArrayLike]]] = None, window: int = 0,
           budget: float = 420.0, tolerance: float = 0.01, families: int = 3,
           operating_points: Sequence[str] = OPERATING_POINTS,
           executor: Optional[concurrent.futures.Executor] = None, progress: Optional[bool] = None,
           **identify_options: Any) -> SearchResult:
    """Finds a model structure and identifies it, from the estimation records alone (the module's
    docstring says how).

    Parameters
    ----------
    u, y : array_like, shape (n,)
        The estimation data: one record.
    records : sequence of (u, y) pairs, keyword only
        Several records in place of u and y.
    window : int, default 0
        The state-initialisation window the model will be used with: the held-out data are scored
        after their first ``window`` samples, and identify's own window (fitting after it) is one of
        the linear stage's choices.
    budget : float, default 420
        Seconds after which the sweep and the growth stop (the choice still runs).
    tolerance : float, default 0.01
        A step is taken where it lowers the held-out RMS error by more than this fraction.
    families : int, default 3
        How many of the families' best structures after the sweep are grown.
    operating_points : sequence of {'zero', 'mean', 'initial'}
        The operating points the linear stage chooses between (identify's ``operating_point``; "zero":
        the structure's own (0, 0)); default all three.
    executor, progress
        As :func:`bonl.select`'s: where the candidates run; the stages on standard error (default:
        when it is a terminal).
    **identify_options
        Passed to :func:`bonl.identify` (method, passes, refine_iterations, ...).

    Returns
    -------
    SearchResult

    Raises
    ------
    ValueError
        Bad records or options (as :func:`bonl.select` says them).
    NumericalError
        No candidate could be fitted, scored and bounded.
    """
    start = time.perf_counter()
    if records is None:
        if u is None or y is None:
            raise ValueError("bonl: search: give u and y for one record, or records=[(u1, y1), ...]")
        records = [(u, y)]
    elif u is not None or y is not None:
        raise ValueError("bonl: search: give u and y, or records, not both")
    records = [(np.asarray(a, dtype=float).ravel(), np.asarray(b, dtype=float).ravel()) for a, b in records]
    if not (isinstance(budget, (int, float)) and budget > 0):
        raise ValueError(f"bonl: search: budget must be a number of seconds > 0, got {budget!r}")
    if not (isinstance(tolerance, (int, float)) and 0 <= tolerance < 1):
        raise ValueError(f"bonl: search: tolerance must be in [0, 1), got {tolerance!r}")
    if not (isinstance(families, int) and families >= 1):
        raise ValueError(f"bonl: search: families must be an integer >= 1, got {families!r}")
    operating_points = tuple(operating_points)
    if not operating_points or any(op not in OPERATING_POINTS for op in operating_points):
        raise ValueError(f"bonl: search: operating_points must be some of {', '.join(OPERATING_POINTS)}, got "
                         f"{operating_points!r}")
    show = sys.stderr.isatty() if progress is None else bool(progress)
    deadline = start + budget
    scheme = scoring_scheme(records)
    scorer = _Scorer(records, window, scheme, executor, identify_options)
    scorer.data(Setting("zero", 0))  # the records and options checked before any work (ValueError)
    stages: List[Stage] = []

    def stage(name, choice, why, count, t0):
        stages.append(Stage(name, choice, why, count, time.perf_counter() - t0))
        _say(show, f"{name}: {choice} ({why})")

    held_out = (f"{scheme['folds']}-fold blocked cross-validation" if scheme["criterion"] == "cross_validation"
                else "the last quarter of each record") + (f", after a {window}-sample window" if window else "")
    stage("held-out data", held_out, f"{sum(r[0].size for r in records)} samples in {len(records)} record(s)", 0, start)

    # 1. The linear structure: delay, operating point, identify's window, integrator, orders.
    t0 = time.perf_counter()
    nk = _delay(records)
    stage("delay", f"nk = {nk}", "the first significant tap of an FIR fit (t > 3), at most its impulse "
          "response's rise to a fifth of the peak", 0, t0)

    t0 = time.perf_counter()
    # Under cross-validation the folds, and the refit, are fitted after the window anyway.
    windows = [window] if scheme["criterion"] == "cross_validation" else sorted({0, window})
    settings = [Setting(op, w) for op in operating_points for w in windows]
    probes = [(_bonl.ARX(na, nb, nk, ni), s) for s in settings for ni in (0, 1) for na, nb in ((1, 0), (2, 1), (4, 2))]
    rows = scorer.score(probes)
    finite = [(row, structure, s) for (structure, s), row in zip(probes, rows) if math.isfinite(_rms(row))]
    if not finite:
        raise _bonl.NumericalError("bonl: search: no linear (ARX) model could be fitted, scored and bounded on these "
                                   "records; the first: " + (rows[0].error or "its score is infinite"))
    best_row, best_probe, setting = min(finite, key=lambda entry: entry[0].score)
    ni = best_probe.ni
    stage("operating point and integrator", f"operating point {setting.operating_point}, identify's window "
          f"{setting.initialisation_window}, ni = {ni}", f"the best of {len(probes)} ARX probes, held-out RMS "
          f"{_rms(best_row):.4g}", len(probes), t0)

    t0 = time.perf_counter()
    linear, count = _climb(scorer, _bonl.ARX(2, 1, nk, ni), setting, tolerance, deadline)
    linear_setting = setting
    linear_rms = _rms(scorer.score([(linear, setting)])[0])
    stage("linear orders", _describe(linear), f"steepest descent from ARX na=2 nb=1 nk={nk}, held-out RMS "
          f"{linear_rms:.4g}", count, t0)

    # 2. Every family seeded at the linear structure, at its operating point and at zero (a two-segment
    # polynomial switches at u0: at the mean input, a valve's kink at zero is lost), and its
    # nonlinearity swept.
    t0 = time.perf_counter()
    y_all = np.concatenate([y for _, y in records])
    output_point = {"zero": 0.0, "mean": float(np.mean(y_all)), "initial": float(records[0][1][0])}

    cross_validation = scheme["criterion"] == "cross_validation"

    def placed(structures, at: Setting):
        """The structures placed from the records, each with ``at`` (its folds' state measured where
        the structure cannot have it estimated: :func:`_fold_states`)."""
        return [(place_from_data(structure, records, output_point[at.operating_point]),
                 at if at.fold_initial_state in _fold_states(structure, cross_validation) else at.folds_from("measured"))
                for structure in structures]

    seed_settings = [setting] + ([Setting("zero", setting.initialisation_window)]
                                 if setting.operating_point != "zero" and "zero" in operating_points else [])
    seeds = []  # each family's seed at each of its folds' states: [((structure, setting), row), ...]
    count = 0
    for structure in _seeds(linear):
        per_state = []
        for state in _fold_states(structure, cross_validation):
            pairs = [pair for at in seed_settings for pair in placed([structure], at.folds_from(state))]
            rows = scorer.score(pairs)
            count += len(pairs)
            per_state.append(min(zip(pairs, rows), key=lambda entry: entry[1].score))
        seeds.append(per_state)
    stage("families", ", ".join(f"{_describe(pair[0])} ({pair[1].operating_point}{_fold_note(pair[1])}) {_rms(row):.4g}"
                                for pair, row in (min(per_state, key=lambda e: e[1].score) for per_state in seeds)),
          "each family seeded at the linear orders, at the linear model's operating point and at zero"
          + (", an integrator's with the folds' state measured and estimated" if cross_validation else "")
          + ", held-out RMS", count, t0)

    t0 = time.perf_counter()
    lineages = []  # [structure, setting, held-out MSE, done]
    count = 0
    for per_state in seeds:
        swept_states = []  # each folds' state swept on its own: the better is kept after the sweep
        for (seed, at), seed_row in per_state:
            structure, row = seed, seed_row
            for sweep in (_delays, _sweep):  # the delay first, then the nonlinearity at the best delay
                swept = placed(sweep(structure), at) if time.perf_counter() < deadline else []
                swept_rows = scorer.score(swept)
                count += len(swept)
                (structure, at), row = min(zip([(structure, at)] + swept, [row] + swept_rows),
                                           key=lambda e: e[1].score)
            swept_states.append([structure, at, row.score, False])
        lineages.append(min(swept_states, key=lambda lineage: lineage[2]))
    lineages.sort(key=lambda lineage: lineage[2])
    stage("nonlinearity", ", ".join(f"{_describe(s)}{_fold_note(at)} {_mse_rms(m):.4g}" for s, at, m, _ in lineages),
          "each family's delay (0, 1 or the linear one), then its degrees, hinges and plays swept from its seed"
          + (" (with each of its folds' states, the better kept)" if cross_validation else "") + ", held-out RMS"
          + (", cut short at the budget" if time.perf_counter() > deadline else ""), count, t0)

    # 3. The best families grown in turn, within the budget.
    t0 = time.perf_counter()
    lineages = [lineage for lineage in lineages[:families] if math.isfinite(lineage[2])]
    exhausted = False
    count = 0
    while any(not lineage[3] for lineage in lineages):
        for lineage in lineages:
            if lineage[3]:
                continue
            if time.perf_counter() > deadline:
                exhausted = True
                break
            neighbours = placed(_neighbours(lineage[0]), lineage[1])
            if len(windows) > 1:  # identify's window in or out, as the integrator is
                other = dataclasses.replace(lineage[1], initialisation_window=0 if lineage[1].initialisation_window
                                            else window)
                neighbours += placed([lineage[0]], other)
            # the folds' state measured or estimated, as the integrator is in or out
            neighbours += [(lineage[0], lineage[1].folds_from(state))
                           for state in _fold_states(lineage[0], cross_validation)
                           if state != lineage[1].fold_initial_state]
            count += len(neighbours)
            best = _better_step(scorer, neighbours, lineage[2], tolerance)
            if best is not None:
                (lineage[0], lineage[1]), lineage[2] = best[0], best[1].score
                _say(show, f"growth: {_describe(lineage[0])}{_fold_note(lineage[1])} {_mse_rms(lineage[2]):.4g}")
            else:
                lineage[3] = True
        if exhausted:
            break
    stage("growth", ", ".join(f"{_describe(s)}{_fold_note(at)} {_mse_rms(m):.4g}" for s, at, m, _ in lineages),
          "steepest descent from each of the best families" + (", stopped at the budget" if exhausted else ""),
          count, t0)

    # 4. The choice.
    t0 = time.perf_counter()
    entries = sorted(scorer.rows.values(), key=lambda entry: entry[0].score)
    best_row = entries[0][0]
    limit = best_row.score * (1 + tolerance) ** 2
    near = sorted((e for e in entries if e[0].score <= limit), key=lambda e: (e[0].num_params, e[0].score))
    rule = f"the fewest parameters within {tolerance:g} of the best held-out RMS {_rms(best_row):.4g}"
    chosen_ids = {id(e) for e in near}
    order = near + [e for e in entries if id(e) not in chosen_ids]
    model, chosen, refused = None, None, []
    for row, structure, s in order:
        if row.error is not None or not math.isfinite(row.score):
            break
        fitted, why = _bonl._refit(structure, scorer.data(s))
        if fitted is not None:
            model, chosen, setting = fitted, row, s
            break
        refused.append(f"{_describe(structure)}: refitted on all the records: {why}")
    if model is None:
        raise _bonl.NumericalError("bonl: search: no candidate has a finite held-out score and a bounded free run"
                                   + (f"; {refused[0]}" if refused else ""))
    stage("choice", f"{_describe(model)}, {setting.operating_point} operating point{_fold_note(setting)}, held-out RMS "
          f"{_rms(chosen):.4g}",
          rule + (f"; {len(refused)} refused once refitted" if refused else ""), len(entries), t0)
    linear_model, _ = _bonl._refit(linear, scorer.data(linear_setting))
    return SearchResult(model, linear_model, setting.options(), _rms(chosen), linear_rms, linear_setting.options(),
                        held_out, [e[0] for e in entries], [e[2].scored() for e in entries], stages,
                        exhausted, time.perf_counter() - start)


def _say(progress: bool, text: str) -> None:
    if progress:
        sys.stderr.write(f"bonl.search: {text}\n")
        sys.stderr.flush()


def _climb(scorer: _Scorer, structure: Any, setting: Setting, tolerance: float, deadline: float) -> Tuple[Any, int]:
    """Steepest descent over the structure's neighbours (:func:`_neighbours`) while a step lowers the
    held-out RMS error by more than ``tolerance``, until ``deadline``. Returns the structure and the
    candidates scored."""
    current = scorer.score([(structure, setting)])[0].score
    count = 1
    while time.perf_counter() < deadline:
        neighbours = [(n, setting) for n in _neighbours(structure)]
        count += len(neighbours)
        best = _better_step(scorer, neighbours, current, tolerance)
        if best is None:
            break
        (structure, _), current = best[0], best[1].score
    return structure, count
