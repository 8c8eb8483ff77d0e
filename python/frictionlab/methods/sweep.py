"""Constant-velocity tests from Python: identify_sweep and sweep_points."""
from .. import _core
from .._args import _source

__all__ = ["identify_sweep", "sweep_points"]


def _sweep_options(model="stribeck", fixed_delta=None, velocity_tolerance=0.0, relative_tolerance=0.01,
                   min_duration=0.5, settle_fraction=0.2, min_speed=None, windows=None, min_segments=None,
                   axis="rotary"):
    o = _core.SweepOptions()
    fit = o.fit
    fit.model = model
    fit.fixed_delta = 0.0 if fixed_delta is None else float(fixed_delta)
    o.fit = fit
    o.velocity_tolerance = velocity_tolerance
    o.relative_tolerance = relative_tolerance
    o.min_duration = min_duration
    o.settle_fraction = settle_fraction
    o.min_speed = -1.0 if min_speed is None else float(min_speed)
    o.windows = [] if windows is None else [tuple(map(float, w)) for w in windows]
    o.min_segments = -1 if min_segments is None else int(min_segments)
    o.axis = axis
    return o


def identify_sweep(time, force, velocity, *, model="stribeck", fixed_delta=None, velocity_tolerance=0.0,
                   relative_tolerance=0.01, min_duration=0.5, settle_fraction=0.2, min_speed=None, windows=None,
                   min_segments=None, axis="rotary", source=None):
    """Constant-velocity tests: one friction-velocity point per steady segment, then a fitted law.

    Arrays (1-D, equal length): ``time`` (s), ``force`` (drive torque N m or force N),
    ``velocity`` (rad/s or m/s).
    Options: ``model`` ("coulomb-viscous", "coulomb-viscous-asymmetric", "stribeck",
    "stribeck-asymmetric"), ``fixed_delta`` (hold the Stribeck exponent; default fitted),
    ``velocity_tolerance`` (absolute steady band, rad/s or m/s, 0), ``relative_tolerance``
    (0.01), ``min_duration`` (shortest steady segment, s, 0.5), ``settle_fraction`` (part of a
    segment dropped at its start, 0.2), ``min_speed`` (slower segments are standstill; default
    1e-3 max |v|), ``windows`` ([(t_begin, t_end), ...] in s instead of detection),
    ``min_segments`` (default parameters + 1), ``axis`` ("rotary" default).
    The points are in ``result.diagnostics.lists['points']``; the fitted law in ``result.law``.
    """
    o = _sweep_options(model, fixed_delta, velocity_tolerance, relative_tolerance, min_duration, settle_fraction,
                       min_speed, windows, min_segments, axis)
    r = _core._identify_sweep(time, force, velocity, o)
    r._stamp(*_source(source))
    r.inputs = {"time": time, "force": force, "velocity": velocity}
    return r


def sweep_points(time, force, velocity, **options):
    """The steady-segment points of a sweep, as a dict of numpy arrays: ``velocity``,
    ``velocity_std`` (rad/s or m/s), ``force``, ``force_std`` (N m or N), ``t_begin``,
    ``t_end`` (s), ``samples``. Options as identify_sweep (the fit options are unused)."""
    options.pop("source", None)
    return _core._sweep_points(time, force, velocity, _sweep_options(**options))
