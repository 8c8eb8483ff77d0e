"""Free decay from Python: identify_decay."""
from .. import _core
from .._args import _nan, _source

__all__ = ["identify_decay"]


def identify_decay(time, position, *, stiffness=None, inertia=None, natural_frequency=None, pendulum=False,
                   stop_threshold=None, axis="linear", source=None):
    """Coulomb and viscous friction from a free decay (pendulum or spring-mass), by the energy
    lost per half cycle.

    Arrays: ``time`` (s, regular), ``position`` (m or rad, from the equilibrium).
    Options: ``stiffness`` (N/m or N m/rad; a pendulum's m g l), or ``natural_frequency``
    (sqrt(k/M), rad/s) with ``inertia`` (kg or kg m^2) for force units (without inertia: Fc/k
    and the damping ratio), ``pendulum`` (restoring k sin(x)), ``stop_threshold`` (|v| at which
    the motion stopped; default 1e-6 max |v|), ``axis`` ("linear" default).
    """
    o = _core.DecayOptions()
    o.stiffness = _nan("identify_decay", "stiffness", stiffness)
    o.inertia = _nan("identify_decay", "inertia", inertia)
    o.natural_frequency = _nan("identify_decay", "natural_frequency", natural_frequency)
    o.pendulum = bool(pendulum)
    o.stop_threshold = _nan("identify_decay", "stop_threshold", stop_threshold)
    o.axis = axis
    r = _core._identify_decay(time, position, o)
    r._stamp(*_source(source))
    r.inputs = {"time": time, "position": position}
    return r
