"""Constant-velocity tests from Python: identify_sweep and sweep_points."""
import numpy as np

from .. import _core
from .._args import _method_options, _source, _with_options_doc

__all__ = ["identify_sweep", "sweep_points"]


def _segments(windows):
    """[(t_begin, t_end), ...] (s) as the table's T_BEGIN:T_END words (exact: repr reads back)."""
    if windows is None or isinstance(windows, str):
        return windows
    return [w if isinstance(w, str) else f"{float(w[0])!r}:{float(w[1])!r}" for w in windows]


def _sweep_options(function, axis, options):
    options = {k: (_segments(v) if k in ("segment", "windows") else v) for k, v in options.items()}
    values, inputs = _method_options("sweep", function, options, stacklevel=4)
    o = _core._make_sweep_options(values)
    if inputs.get("reference") is not None:
        o.reference = np.asarray(inputs["reference"], dtype=float)
    o.axis = axis
    return values, o, inputs.get("load")


@_with_options_doc("sweep")
def identify_sweep(time, force, velocity, *, axis="linear", source=None, **options):
    """Constant-velocity tests: one friction-velocity point per steady segment, then a fitted law.

    Arrays (1-D, equal length, regular time): ``time`` (s), ``force`` (drive torque N m or force
    N), ``velocity`` (rad/s or m/s); ``reference`` (an option) the commanded velocity.
    ``axis`` ("linear" default, as every method) picks the units. ``load`` (an option, N or N m,
    length N): the load the contact transmits; mu_load (dimensionless) is then fitted from the
    points' mean |load| and the law's levels are those at zero load.
    The points are in ``result.diagnostics.lists['points']``; the fitted law in ``result.law``.
    """
    values, o, load = _sweep_options("identify_sweep", axis, options)
    r = _core._identify_sweep(time, force, velocity, o, load)
    r._record_options(values)
    r._stamp(*_source(source))
    r.inputs = {"time": time, "force": force, "velocity": velocity, "load": load}
    return r


def sweep_points(time, force, velocity, *, axis="linear", source=None, **options):
    """The steady-segment points of a sweep, as a dict of numpy arrays: ``velocity``,
    ``velocity_std`` (rad/s or m/s), ``force``, ``force_std`` (N m or N), ``t_begin``,
    ``t_end`` (s), ``samples``; with the option ``load``, ``load`` (mean |load|, N m or N).
    Options as identify_sweep (the fit options are unused)."""
    _, o, load = _sweep_options("sweep_points", axis, options)
    return _core._sweep_points(time, force, velocity, o, load)
