"""Closed-loop validation of an identified model from Python: validate."""
from .. import _core

__all__ = ["validate"]


def _path(x):
    """A file path from a path, or the file a Data (from load()) came from."""
    file = getattr(x, "file", None)
    return file if file else x  # checked (and named) by the binding


def validate(model, data, scenario, *, time, position, force):
    """Simulates an identified model in a scenario's plant and controller and compares it with a run.

    model     the Result of an identification whose law can be simulated (result.law is set), with
              the inertia M (kg or kg m^2) among its parameters; offset (N or N m) is used when present
    data      the measured run: a path or the Data from load(); the scenario reads its reference,
              pulses and controller constants from it (see examples/emps_closed_loop.yaml)
    scenario  path of the scenario YAML (plant and controller)
    time, position, force
              the measured signals (s, m or rad, N or N m; 1-D, equal lengths), e.g. t, qm, gtau * vir
    Returns a Result whose validation.signal_errors_percent has the relative errors (%) of
    position, velocity, acceleration and force, and whose series hold measured and simulated signals.
    Raises ValueError naming the file, key or column for bad input.
    """
    if not isinstance(model, _core.Result):
        raise _core.ArgumentTypeError(f"validate: argument model: expected the Result of an identification, got "
                                      f"{type(model).__name__}")
    return _core._validate(model, _path(data), scenario, time, position, force)
