"""Inverse models (docs/how-to/control.md): :class:`InverseModel` gives, per sample, the command that makes an
identified model follow a reference output, and :meth:`InverseModel.commands` the commands for a whole
reference; :class:`InverseStatus` says where a command cannot (saturation, dead band, out of range);
:class:`AdaptiveInverse` runs the online estimator beside the inverse and derives it again as the
estimate changes, keeping the last good one when the estimate is not trusted. Spelled as in C++
(``bonl::control``).

Examples
--------
>>> import numpy as np, bonl
>>> model = bonl.ARX(2, 1, 2, b=[0.5, 0.2], a=[-1.2, 0.35])
>>> r = np.r_[np.zeros(5), np.sin(np.arange(95) / 10)]
>>> run = bonl.control.InverseModel(model).commands(r)
>>> bool(np.allclose(model.simulate(run.command)[2:], r[2:]))
True
"""

from ._bonl.control import AdaptiveInverse, AdaptiveInverseHealth, InverseModel, InverseRun, InverseStatus, InverseStep

__all__ = ["AdaptiveInverse", "AdaptiveInverseHealth", "InverseModel", "InverseRun", "InverseStatus", "InverseStep"]
