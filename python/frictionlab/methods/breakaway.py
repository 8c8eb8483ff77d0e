"""The lecture's torque-mode trapezoid experiment from Python: identify_breakaway."""
from .. import _core
from .._args import _method_options, _source, _with_options_doc

__all__ = ["identify_breakaway"]


@_with_options_doc("breakaway")
def identify_breakaway(time, force, velocity, *, axis="linear", source=None, **options):
    """Torque-mode trapezoid experiment (slow ramp up, hold, ramp down): Fs, Fc, Fv (and M).

    Arrays (1-D, equal length, regular time): ``time`` (s), ``force`` (drive torque, N m, or
    force, N: Kt times current), ``velocity`` (rad/s or m/s).
    ``axis`` ("linear" default, as every method) picks the units; ``source`` (a Data from load() or a path) names
    the data in the result. ``diagnostics.groups['readoff']`` holds the lecture's read-offs.
    ``load`` (an option, N m or N, length N): the load the contact transmits; then
    mu_load_coulomb and mu_load_static (dimensionless) are fitted, Fs and Fc are the levels at
    zero load, and ``diagnostics.lists['breakaways']`` holds each start's time, load and force.
    """
    values, inputs = _method_options("breakaway", "identify_breakaway", options)
    o = _core._make_breakaway_options(values)
    o.axis = axis
    load = inputs.get("load")
    r = _core._identify_breakaway(time, force, velocity, o, load)
    r._record_options(values)
    r._stamp(*_source(source))
    r.inputs = {"time": time, "force": force, "velocity": velocity, "load": load}
    return r
