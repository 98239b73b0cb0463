"""What to look at after identifying a model: its summary in words and the figure of its fit.

:func:`summary` gives a model's structure, parameters by block, poles, operating point and input
range, and, given data, its free-run scores on them; :func:`plot_fit` draws the measured against the
simulated output and the residuals, with the part the model was not fitted on marked.
"""

from __future__ import annotations

import math
from typing import Any, Optional

import numpy as np

from . import _bonl
from ._bonl import metrics as _metrics
from .selection import named_orders

__all__ = ["plot_fit", "summary"]


def _free_run(model: Any, u: np.ndarray) -> np.ndarray:
    try:
        return np.asarray(model.simulate(u), dtype=float).ravel()
    except _bonl.NumericalError:
        return np.full(np.shape(u), math.nan)


def _checked_record(caller: str, u: Any, y: Any, test_from: Optional[int]):
    """u and y as 1-D float arrays of one length, and test_from inside them; otherwise ValueError."""
    u = np.asarray(u, dtype=float).ravel()
    y = np.asarray(y, dtype=float).ravel()
    if u.size != y.size:
        raise ValueError(f"bonl: {caller}: u and y must have the same length, got {u.size} and {y.size}")
    if test_from is not None and not 0 < test_from < u.size:
        raise ValueError(f"bonl: {caller}: test_from must be in 1..{u.size - 1}, got {test_from}")
    return u, y


def summary(model: Any, u: Any = None, y: Any = None, test_from: Optional[int] = None) -> str:
    """A model in words: its class and orders, its parameters by block, the largest pole radius, the
    operating point and the input range it was identified on; given data, its free-run scores.

    Parameters
    ----------
    model : a bonl model
        Identified (or set by hand).
    u, y : array_like, optional
        A record to score the model on: simulated from rest over all of it.
    test_from : int, optional
        With data: the samples from this index on are scored apart, as data the model was not
        fitted on (the whole record is still simulated from rest).

    Returns
    -------
    str
        Several lines of text, the same the ``bonl identify`` command prints.

    Raises
    ------
    ValueError
        ``model`` is not a bonl model, only one of ``u`` and ``y`` is given, or ``test_from`` is
        outside the record.
    """
    if type(model) not in _bonl.MODELS:
        raise ValueError(f"bonl: summary: model must be a bonl model, got {type(model).__name__}")
    if (u is None) != (y is None):
        raise ValueError("bonl: summary: give both u and y to score the model, or neither")
    orders = ", ".join(f"{name}={value}" for name, value in named_orders(model).items())
    lines = [f"{type(model).__name__} ({orders}), {model.num_params} parameters"]
    for name, values in model.params.items():
        values = np.atleast_1d(np.asarray(values, dtype=float))
        lines.append(f"  {name:<6} " + " ".join(f"{v:.6g}" for v in values) if values.size else f"  {name:<6} (none)")
    lines.append(f"  largest pole radius {model.pole_radius:.6g}"
                 + ("" if model.pole_radius < 1 else " (not inside the unit circle: the free run may drift)"))
    u0, y0 = model.operating_point
    lines.append(f"  operating point u0 = {u0:.6g}, y0 = {y0:.6g}")
    low, high = model.input_range
    if math.isfinite(low) or math.isfinite(high):
        lines.append(f"  identified on inputs from {low:.6g} to {high:.6g}")
    if u is None:
        return "\n".join(lines)
    u, y = _checked_record("summary", u, y, test_from)
    simulated = _free_run(model, u)
    parts = [("the whole record", slice(0, u.size))]
    if test_from is not None:
        parts = [("samples fitted on", slice(0, test_from)), ("samples not fitted on", slice(test_from, u.size))]
    lines.append("  free run from rest:")
    for label, part in parts:
        if np.all(np.isfinite(simulated[part])):
            lines.append(f"    {label}: RMS error {_metrics.rmse(y[part], simulated[part]):.6g}, "
                         f"fit {_metrics.fit_percent(y[part], simulated[part]):.2f} %")
        else:
            lines.append(f"    {label}: the simulation diverged")
    return "\n".join(lines)


def plot_fit(model: Any, u: Any, y: Any, test_from: Optional[int] = None, path: Any = None, title: str = ""):
    """The figure of a model's fit: measured and simulated output (free run from rest) above, the
    residual below, the samples from ``test_from`` on (not fitted on) shaded.

    Parameters
    ----------
    model : a bonl model
    u, y : array_like
        The record: input and measured output.
    test_from : int, optional
        Where the part the model was not fitted on begins.
    path : str or path-like, optional
        Save the figure there (the format from the extension, e.g. ``.png``, ``.pdf``).
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
        The figure (two axes sharing the sample axis).

    Raises
    ------
    ValueError
        ``model`` is not a bonl model, u and y differ in length, or ``test_from`` is outside the record.
    """
    if type(model) not in _bonl.MODELS:
        raise ValueError(f"bonl: plot_fit: model must be a bonl model, got {type(model).__name__}")
    u, y = _checked_record("plot_fit", u, y, test_from)
    import matplotlib

    if path is not None:
        matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    simulated = _free_run(model, u)
    samples = np.arange(u.size)
    figure, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(9, 5.5), gridspec_kw={"height_ratios": [2, 1]})
    top.plot(samples, y, color="black", linewidth=1.0, label="measured")
    top.plot(samples, simulated, color="tab:red", linewidth=1.0, label=f"{type(model).__name__}, free run")
    bottom.plot(samples, y - simulated, color="tab:red", linewidth=0.8)
    bottom.axhline(0.0, color="black", linewidth=0.5)
    for axes in (top, bottom):
        if test_from is not None:
            axes.axvspan(test_from, u.size - 1, color="0.9", zorder=0)
        axes.grid(True, linewidth=0.3)
    if test_from is not None:
        top.text(test_from, 0.98, " not fitted on", transform=top.get_xaxis_transform(), va="top", fontsize=8)
    top.set_ylabel("output")
    top.legend(loc="upper left", fontsize=8)
    bottom.set_ylabel("residual")
    bottom.set_xlabel("sample")
    if title:
        top.set_title(title)
    figure.tight_layout()
    if path is not None:
        figure.savefig(path, dpi=120)
    return figure
