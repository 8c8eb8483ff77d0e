"""Simulation of a scenario (a YAML file or a dict of the same form)."""
import copy
import os

from . import _core


def simulate(scenario, *, law=None, duration=None, output_rate=None, as_dict=False):
    """Simulates a scenario: a path to a scenario YAML file, a dict of the same form
    (``{"plant": {...}, "friction": {"law": ...}, "input": {...}, "duration": s, ...}``),
    or a :class:`Scenario`.

    Overrides: ``law`` (a FrictionLaw or its dict, e.g. an identified ``result.law``),
    ``duration`` (s), ``output_rate`` (Hz).

    Returns a :class:`Trajectory` (a read-only mapping of column -> numpy array: time s,
    position m or rad, velocity m/s or rad/s, friction and applied N or N m, current A,
    voltage V, reference, stuck; plus ``switches``, ``stats``, ``law_state``), or with
    ``as_dict=True`` a plain dict of the columns.
    Raises ValueError naming the file, key and value for a bad scenario; RuntimeError when the
    integrator fails.
    """
    if isinstance(scenario, _core.Scenario):
        sc = copy.copy(scenario)
    elif isinstance(scenario, dict):
        sc = _core.Scenario(scenario)
    elif isinstance(scenario, (str, os.PathLike)):
        sc = _core.Scenario.load(scenario)
    else:
        raise ValueError("scenario: expected a scenario file path, a dict or a Scenario, got "
                         + type(scenario).__name__)
    if law is not None:
        sc.law = law
    if duration is not None:
        sc.duration = duration
    if output_rate is not None:
        sc.output_rate = output_rate
    tr = _core._simulate(sc)
    return tr.to_dict() if as_dict else tr
