"""Closed-loop validation of identified models from Python: validate (one axis), validate_xy (a two-axis table)."""
from .. import _core

__all__ = ["validate", "validate_xy"]


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


def validate_xy(models, scenario, *, time, x, y, x_force=None, y_force=None, data=None):
    """Simulates identified axis models in a two-axis table's scenario and compares with a circular test.

    models    a dict of axis name ("x", "y") to the Result of an identification of that axis (its
              law, inertia M in kg and offset in N): each replaces the scenario's law, mass and
              offset of its axis; an axis not named keeps the scenario's
    scenario  path of the scenario YAML with plant type xy-table (its controller and contour)
    time, x, y
              the measured run (s, m, m; 1-D, equal lengths, regular time): sample k is compared
              with the simulation at k dt
    x_force, y_force
              the measured drive forces (N), or None (not compared)
    data      None, or a path or the Data from load() that the scenario's data inputs read
              (a path contour's columns), as the command line's DATA
    Returns (result, measured, simulated): the Result, whose validation.signal_errors_percent has
    the relative errors (%) keyed "x.position", "x.velocity", "x.acceleration", "x.force", "y...."
    and validation.sections["contour"] the circular-test figures (m) of both paths; and the
    ContourResult of the measured and of the simulated path (None when the reference is not a
    circle of at least one turn). The command line's `frictionlab validate x=MX.json,y=MY.json`.
    Raises ValueError naming the axis, key or argument for bad input.
    """
    if not isinstance(models, dict):
        raise _core.ArgumentTypeError(f"validate_xy: argument models: expected a dict of axis name to Result "
                                      f"({{'x': ..., 'y': ...}}), got {type(models).__name__}")
    for axis in models:
        if not isinstance(axis, str):
            raise _core.ArgumentTypeError(f"validate_xy: argument models: key {axis!r}: expected an axis name, 'x' or 'y'")
    return _core._validate_xy(models, None if data is None else _path(data), scenario, time, x, y, x_force, y_force)
