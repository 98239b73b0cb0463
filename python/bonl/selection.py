"""Order and structure selection (``bonl.select``, ``bonl.grid``): :func:`select` fits every candidate
of a grid and ranks them.

- :func:`grid`: the structures of one model class over lists of orders,
  ``grid(bonl.HammersteinWiener, na=[1, 2, 3], nb=[0, 1], nk=[0], r=[2, 3], r1=[2, 3])``;
- :func:`select`: identifies each candidate and scores it. ``criterion="validation"`` (the default)
  fits on the first part of every record (the last ``validation_fraction`` of its samples, rounded
  half away from zero, held out) and scores the free-run simulation error on the held-out last part
  (each record simulated whole, from rest, and scored on its tail only; or, with ``window=n``, the
  tail simulated after its first n samples as a test record with a state-initialisation window is);
  ``criterion="cross_validation"`` (blocked cross-validation, for records too short for one held-out
  part to say much) cuts every record into ``folds`` consecutive blocks, holds each out once (the
  candidate fitted on the rest) and scores the free-run error over all of them;
  ``criterion="aic"`` or ``"bic"`` fits on all the data and scores ``N log(mse) + 2 p`` or
  ``N log(mse) + p log(N)`` of the free-run simulation. The best candidate is refitted on all the
  data. A model whose free run is not bounded is never chosen: from rest on every record's input, and
  on it stretched 1.25 times about the model's input operating point, its output must stay within
  10 half-ranges of the measured output's middle; a candidate that fails it is ranked last with the
  reason, and where the best fails it once refitted, the next is refitted. Each candidate is scored
  by C++'s ``bonl::score_candidate`` (``include/bonl/estimator/select.hpp``, the scoring C++'s
  ``bonl::select`` runs too), which releases the GIL; Python runs the candidates in
  parallel: on the local cores by default, or on any :class:`concurrent.futures.Executor`, such as a
  Dask cluster's (``distributed.Client(...).get_executor()``).

Examples
--------
>>> import numpy as np, bonl
>>> truth = bonl.Hammerstein(2, 1, 2, 2, b=[1, 0.5], a=[-0.6, 0.1], f=[0, 1, 0.3], p=[0, 0, -0.2])
>>> u = np.repeat(np.random.default_rng(1).uniform(-1, 1, 400), 5)
>>> y = truth.simulate(u)
>>> result = bonl.select(bonl.grid(bonl.Hammerstein, na=[2], nb=[1], nk=[1, 2, 3], r=[2]), u, y)
>>> result.best.nk
2
"""

from __future__ import annotations

import concurrent.futures
import dataclasses
import itertools
import math
import os
import sys
import time
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple

from numpy.typing import ArrayLike

from . import _bonl

__all__ = ["Candidate", "Selection", "grid", "select"]

@dataclasses.dataclass(frozen=True)
class Candidate:
    """One row of a selection's ranked table."""

    name: str                       #: the model's class name
    orders: Dict[str, int]          #: its orders by name
    num_params: int
    score: float                    #: the criterion (lower is better; inf when the fit failed or was refused)
    fit_mse: float                  #: free-run simulation MSE on the data it was fitted on, run as fitted
    validation_mse: Optional[float]  #: on the held-out parts (criteria "validation", "cross_validation"), else None
    seconds: float                  #: wall time of its identification
    error: Optional[str]            #: why the fit failed or was refused, None when it was not
    model: Any                      #: the identified model (None when the fit failed; kept when refused)
    #: criterion "cross_validation": each fold's held-out MSE (their spread says how far two scores
    #: differ by chance); else None
    fold_mse: Optional[List[float]] = None


@dataclasses.dataclass(frozen=True)
class Selection:
    """What :func:`select` found: the ranked table and the best candidate refitted on all the data."""

    criterion: str
    table: List[Candidate]          #: best first
    best: Any                       #: the best structure identified on all the data

    def __str__(self) -> str:
        lines = [f"{'rank':>4}  {'model':<24} {'orders':<32} {'params':>6} {'score':>12}"]
        for rank, row in enumerate(self.table, 1):
            orders = ", ".join(f"{k}={v}" for k, v in row.orders.items())
            score = f"{row.score:.4e}" if math.isfinite(row.score) else ("failed" if row.error else "inf")
            lines.append(f"{rank:>4}  {row.name:<24} {orders:<32} {row.num_params:>6} {score:>12}")
        return "\n".join(lines)


def grid(model_class: type, **orders: Iterable[int]) -> List[Any]:
    """Every structure of ``model_class`` over the lists of orders given by name.

    Parameters
    ----------
    model_class : type
        One of ``bonl.MODELS``.
    **orders : int or iterable of int
        One value or a list per order; every order of ``model_class.ORDERS`` must be given but those
        of ``model_class.ORDER_DEFAULTS``, the integrators ``ni``, which take their default.
        ValueError for an order unknown or missing.

    Returns
    -------
    list
        The structures, every combination of the orders, to pass to :func:`select`.
    """
    if model_class not in _bonl.MODELS:
        raise ValueError(f"bonl: grid: model_class must be one of bonl.MODELS, got {model_class!r}")
    names = model_class.ORDERS
    orders = {**model_class.ORDER_DEFAULTS, **orders}
    unknown = sorted(set(orders) - set(names))
    missing = [n for n in names if n not in orders]
    if unknown or missing:
        raise ValueError(f"bonl: grid: {model_class.__name__} takes the orders {', '.join(names)}"
                         + (f"; unknown: {', '.join(unknown)}" if unknown else "")
                         + (f"; missing: {', '.join(missing)}" if missing else ""))
    values = [list(orders[n]) if isinstance(orders[n], Iterable) else [orders[n]] for n in names]
    return [model_class(*combination) for combination in itertools.product(*values)]


def named_orders(structure: Any) -> Dict[str, int]:
    """The structure's orders by name, as its model file writes them.

    Parameters
    ----------
    structure : bonl model
        The model whose orders are read.

    Returns
    -------
    dict
        Name to order; an order at its default (``ORDER_DEFAULTS``, the integrators ``ni = 0``) is
        left out.
    """
    defaults = type(structure).ORDER_DEFAULTS
    return {name: value for name, value in zip(type(structure).ORDERS, structure.orders)
            if defaults.get(name) != value}


def _failed(structure: Any, error: str, seconds: float) -> Candidate:
    """The row of a candidate that has no model: score inf, with why."""
    return Candidate(type(structure).__name__, named_orders(structure), structure.num_params, math.inf, math.inf, None,
                     seconds, error, None)


def _score(structure: Any, data: Any) -> Candidate:
    """Identifies one candidate and scores it, C++'s bonl::score_candidate on the checked data (runs
    where the executor puts it: keep it top-level)."""
    t0 = time.perf_counter()
    score, fit_mse, validation_mse, error, model, fold_mse = _bonl._score_candidate(structure, data)
    return Candidate(type(structure).__name__, named_orders(structure), structure.num_params, score, fit_mse,
                     validation_mse, time.perf_counter() - t0, error, model, fold_mse)


def _progress(total: int, progress: Optional[bool]):
    show = sys.stderr.isatty() if progress is None else progress
    if not show:
        return None
    try:
        from tqdm.auto import tqdm
    except ImportError:
        if progress:
            raise ValueError("bonl: select: progress=True needs tqdm (pip install tqdm)") from None
        return None
    return tqdm(total=total, desc="bonl.select", unit="model")


def _score_all(structures: Sequence[Any], data: Any, executor: Optional[concurrent.futures.Executor] = None,
               progress: Optional[bool] = None) -> List[Candidate]:
    """Scores each structure on ``data`` (``_bonl._selection_data``): the candidates' rows, in their order.

    Parameters
    ----------
    structures : sequence of bonl models
        The candidates.
    data : the checked records and options they are scored on
    executor : concurrent.futures.Executor, optional
        Where they run; default: threads on the local cores.
    progress : bool, optional
        A tqdm progress bar; default: when standard error is a terminal.

    Returns
    -------
    list of Candidate
        One row per structure, in their order (one the executor lost: its row says so).
    """
    own = executor is None
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) if own else executor
    bar = _progress(len(structures), progress)
    try:
        futures = [pool.submit(_score, structure, data) for structure in structures]
        index = {future: i for i, future in enumerate(futures)}
        rows: List[Optional[Candidate]] = [None] * len(futures)
        for future in concurrent.futures.as_completed(futures):
            i = index[future]
            try:
                rows[i] = future.result()
            except Exception as error:  # the executor lost this candidate: report it, keep the rest
                rows[i] = _failed(structures[i], f"executor: {type(error).__name__}: {error}", math.nan)
            if bar is not None:
                bar.update(1)
    finally:
        if own:
            pool.shutdown()
        if bar is not None:
            bar.close()
    return rows


def _refit_best(table: List[Candidate], structures: Sequence[Any], data: Any) -> Tuple[List[Candidate], Any]:
    """The best of a ranked table refitted on all of ``data``'s records, as bonl::select does it
    (bonl::refit): where that one's free run there is not bounded, the next, its row given the reason.

    Parameters
    ----------
    table : list of Candidate
        Best first.
    structures : sequence of bonl models
        The structure of each row, in the table's order.
    data : the checked records and options (``_bonl._selection_data``) to refit on

    Returns
    -------
    (list of Candidate, model)
        The table again, refused refits moved down with the failed rows (by score, stably), and the
        model.

    Raises
    ------
    NumericalError
        No row has a finite score and a bounded free run.
    """
    table = list(table)
    best = None
    for position, row in enumerate(table):
        if row.error is not None or not row.score < math.inf:
            break  # the rest are worse
        best, why = _bonl._refit(structures[position], data)
        if best is not None:
            break
        table[position] = dataclasses.replace(row, score=math.inf, error="refitted on all the records: " + why)
    if best is None:
        raise _bonl.NumericalError("bonl: select: every candidate failed: none has a finite score and a bounded "
                                   "free run; the first: " + (table[0].error or "its score is infinite"))
    table.sort(key=lambda row: row.score)  # stable: refused refits go down with the failed rows
    return table, best


def select(candidates: Iterable[Any], u: Optional[ArrayLike] = None, y: Optional[ArrayLike] = None, *,
           records: Optional[Sequence[Tuple[ArrayLike, ArrayLike]]] = None, criterion: str = "validation",
           validation_fraction: float = 0.25, window: int = 0, folds: int = 5,
           fold_initial_state: str = "measured",
           executor: Optional[concurrent.futures.Executor] = None, progress: Optional[bool] = None,
           **identify_options: Any) -> Selection:
    """Fits every candidate structure, ranks them by ``criterion`` and refits the best on all the data.

    Parameters
    ----------
    candidates : iterable of bonl models
        The structures (their orders; parameter values are not used), e.g. from :func:`grid`.
    u, y : array_like, shape (n,)
        The estimation data: one record.
    records : sequence of (u, y) pairs, keyword only
        Several records in place of u and y: ``select(candidates, records=[(u1, y1), (u2, y2)])``.
    criterion : {'validation', 'cross_validation', 'aic', 'bic'}
        'validation' (default): the free-run simulation MSE on the last ``validation_fraction`` of every
        record (its samples times the fraction, rounded half away from zero, at least 1), the candidate
        fitted on the rest. 'cross_validation': every record cut into ``folds`` consecutive blocks of
        equal length (the edges at round(f n / folds)); fold f holds out block f of every record, is
        fitted on the parts before and after it (each after identify's initialisation window of at
        least 10 samples, as a part after a block does not start at rest) and scored by the free-run
        MSE on the block (the record simulated from rest up to the block's end, or with ``window``,
        the block after its first samples); the score is the MSE over every block, each fold's is in
        the row's ``fold_mse`` and the row's model is the last fold's; with ``window`` the best is
        refitted after that window too, as its folds were. 'aic', 'bic': information criteria of the free-run simulation error on all
        the data. Every candidate is scored by C++'s ``bonl::score_candidate``, as ``bonl::select``
        scores it; one that cannot be fitted (more parameters than its fit part has samples, or an
        identification that fails), or whose free run is not bounded (the module's docstring), is
        ranked last with the reason.
    validation_fraction : float, default 0.25
        criterion 'validation': the held-out last part of every record, in (0, 1).
    window : int, default 0
        criteria 'validation' and 'cross_validation': each held-out part is scored the way a test record with a
        state-initialisation window of this many samples is: simulated after its first ``window``
        samples, which set the model's state (``Model.simulate(u, initial=...)``), instead of as the
        continuation of the whole record simulated from rest. Give the window of the test protocol
        the model will be judged by; it must be shorter than every held-out part.
    folds : int, default 5
        criterion 'cross_validation': the blocks every record is cut into, >= 2.
    fold_initial_state : {'measured', 'estimated'}, default 'measured'
        criterion 'cross_validation': where each fold's fit parts take their state at the end of their
        initialisation window: the window's measured outputs, or estimated beside the parameters. A
        part after a held-out block starts in motion, and an integrating model's state there is its
        position, which a few noisy outputs set poorly. The refit on all the records is unaffected.
    executor : concurrent.futures.Executor, optional
        Where the candidates run; default: threads on the local cores. A Dask cluster's
        ``client.get_executor()`` spreads a large grid over many machines.
    progress : bool, optional
        A tqdm progress bar; default: when standard error is a terminal.
    **identify_options
        Passed to :func:`bonl.identify` (method, passes, refine_iterations, ...).

    Returns
    -------
    Selection
        ``table``: the candidates best first (failed and refused fits last, with their error);
        ``best``: the best structure identified on all the data whose free run there is bounded.
        NumericalError where no candidate has a finite score and a bounded free run.
    """
    structures = list(candidates)
    if not structures:
        raise ValueError("bonl: select: candidates is empty")
    for i, structure in enumerate(structures):
        if type(structure) not in _bonl.MODELS:
            raise ValueError(f"bonl: select: candidates[{i}] must be a bonl model, got {type(structure).__name__}")
    # The records and options checked once, in C++ (ValueError naming the bad one).
    data = _bonl._selection_data(u, y, records=records, criterion=criterion, validation_fraction=validation_fraction,
                                 window=window, folds=folds, fold_initial_state=fold_initial_state,
                                 **identify_options)

    rows = _score_all(structures, data, executor, progress)
    # Best first; ties (and failures, all inf) keep the candidates' order, as bonl::select ranks them.
    order = sorted(range(len(rows)), key=lambda i: rows[i].score)
    table, best = _refit_best([rows[i] for i in order], [structures[i] for i in order], data)
    return Selection(criterion, table, best)
