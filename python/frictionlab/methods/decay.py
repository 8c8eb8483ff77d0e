"""Free decay from Python: identify_decay."""
from .. import _core
from .._args import _method_options, _source, _with_options_doc

__all__ = ["identify_decay"]


@_with_options_doc("decay")
def identify_decay(time, position, *, axis="linear", source=None, **options):
    """Coulomb and viscous friction from a free decay (pendulum or spring-mass), by the energy
    lost per half cycle.

    Arrays: ``time`` (s, regular), ``position`` (m or rad, from the equilibrium).
    Give ``stiffness``, or ``natural_frequency`` with ``inertia`` for force units (without
    inertia: Fc/k and the damping ratio). ``axis`` ("linear" default) picks the units.
    """
    values, _ = _method_options("decay", "identify_decay", options)
    o = _core._make_decay_options(values)
    o.axis = axis
    r = _core._identify_decay(time, position, o)
    r._record_options(values)
    r._stamp(*_source(source))
    r.inputs = {"time": time, "position": position}
    return r
