"""Closed-loop validation and the LuGre output-error fit (SI units throughout)."""

from . import _core


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


def identify_lugre(time, force, position, *, inertia, static_law=None, delta=2.0, stribeck_velocity=0.001,
                   substeps=4, max_iterations=50, axis="linear", vd=0.0):
    """LuGre sigma0 (N/m) and sigma1 (N s/m) by output error, with the static part (Fc, Fs, vs in
    m/s, sigma2) identified from the same record unless static_law (a FrictionLaw or its dict) is given.
    vd (m/s, >= 0): decay velocity of the damping sigma1 exp(-(v/vd)^2), held fixed; 0 = constant.
    A parameter the record cannot determine, or that ends at a bound, has std NaN and a warning.

    time (s), force (applied, N), position (m): 1-D arrays of equal length, the record starting at rest
    inertia: mass (kg, > 0). Returns a Result (parameters with std, fit of the position, law).
    Raises ValueError for a non-positive inertia or unequal lengths.
    """
    return _core._identify_lugre(time, force, position, inertia, static_law, delta, stribeck_velocity, substeps,
                                 max_iterations, axis, vd)
