"""The lecture's torque-mode trapezoid experiment from Python: identify_breakaway."""
from .. import _core
from .._args import _nan, _source

__all__ = ["identify_breakaway"]


def identify_breakaway(time, force, velocity, *, inertia=None, velocity_threshold=None, edge_samples=2,
                       axis="rotary", source=None):
    """Torque-mode trapezoid experiment (slow ramp up, hold, ramp down): Fs, Fc, Fv (and M).

    Arrays (1-D, equal length, regular time): ``time`` (s), ``force`` (drive torque, N m, or
    force, N: Kt times current), ``velocity`` (rad/s or m/s).
    Options: ``inertia`` (kg m^2 or kg; held fixed when given, else estimated as M),
    ``velocity_threshold`` (|v| above which the axis moves, rad/s or m/s; default 1 % of max),
    ``edge_samples`` (samples skipped at the ends of a sliding interval, 2), ``axis``
    ("rotary" default). ``diagnostics.groups['readoff']`` holds the lecture's read-offs.
    """
    o = _core.BreakawayOptions()
    o.inertia = _nan("identify_breakaway", "inertia", inertia)
    o.velocity_threshold = _nan("identify_breakaway", "velocity_threshold", velocity_threshold)
    o.edge_samples = edge_samples
    o.axis = axis
    r = _core._identify_breakaway(time, force, velocity, o)
    r._stamp(*_source(source))
    r.inputs = {"time": time, "force": force, "velocity": velocity}
    return r
