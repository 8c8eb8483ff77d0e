"""Analyses of motion records: decay envelope of a free oscillation, stick-slip detection."""
from . import _core


def _columns(function, t, names, second):
    # A Trajectory or a dict of columns in place of the arrays.
    if t is None or isinstance(t, (str, bytes)) or not (hasattr(t, "keys") and hasattr(t, "__getitem__")):
        if t is not None and not isinstance(t, (str, bytes)):
            raise _core.ArgumentTypeError(
                f"{function}: argument {second} is None; expected a 1-D array of numbers (or pass a Trajectory / "
                f"dict with columns {', '.join(names)} as t)")
        raise _core.ArgumentTypeError(
            f"{function}: argument t: expected a 1-D array of times, or a Trajectory / dict with columns "
            f"{', '.join(names)}; got {type(t).__name__}")
    return [t[n] if n in t else None for n in names] if names[-1] == "friction" else [t[n] for n in names]


def decay_envelope(t, x=None, *, none_tolerance=0.02, mixed_gain=0.5, fit_tolerance=0.01,
                   min_relative_amplitude=1e-3):
    """Envelope of a free oscillation x(t): the half swing of each half cycle and the law it
    decays by ('linear' = Coulomb, 'exponential' = viscous, 'mixed', or 'none').

    ``t`` (s, increasing) and ``x`` (m or rad), or a Trajectory / dict with time and position
    columns as ``t``. Options: ``none_tolerance`` (relative loss below which the kind is 'none',
    0.02), ``mixed_gain`` (0.5), ``fit_tolerance`` (0.01), ``min_relative_amplitude`` (1e-3).
    Returns an EnvelopeResult (peak_times s, amplitudes, half_period s, kind, linear /
    exponential / mixed fits, decrement_per_half_cycle, log_decrement, decay_fraction).
    Raises ValueError when fewer than 4 extremes are found.
    """
    if x is None:
        t, x = _columns("decay_envelope", t, ("time", "position"), "x")
    o = _core.EnvelopeOptions()
    o.none_tolerance = none_tolerance
    o.mixed_gain = mixed_gain
    o.fit_tolerance = fit_tolerance
    o.min_relative_amplitude = min_relative_amplitude
    return _core._decay_envelope(t, x, o)


def detect_stick_slip(t, v=None, force=None, *, velocity_threshold=0.0, min_slip_duration=0.0):
    """Stick and slip intervals of a record: ``t`` (s), ``v`` (m/s or rad/s), optional
    ``force`` (friction force, N or N m), or a Trajectory / dict (time, velocity, friction) as
    ``t``. ``velocity_threshold``: |v| at or below is stuck (0 = automatic: exact zeros, or 1 %
    of max |v|); ``min_slip_duration`` (s). Returns a StickSlipResult (stick, slip as (n, 2)
    arrays in s, period s, peak_slip_velocity, breakaway / re-stick forces, mean_force_drop).
    """
    if v is None:
        t, v, force = _columns("detect_stick_slip", t, ("time", "velocity", "friction"), "v")
    o = _core.StickSlipOptions()
    o.velocity_threshold = velocity_threshold
    o.min_slip_duration = min_slip_duration
    return _core._detect_stick_slip(t, v, force, o)
