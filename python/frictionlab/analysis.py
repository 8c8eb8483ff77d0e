"""Analyses of motion records: decay envelope of a free oscillation, stick-slip detection; maps of
scenarios over grids of their parameters."""
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


def analyze_map(scenario, vary=None, *, transient=None, tolerance=0.01, jobs=0, shard=None, contact=None):
    """Map of a scenario file over a grid of its keys, as ``frictionlab analyze map``: each grid
    point simulated and classified after a transient.

    ``scenario``: the scenario YAML file (str or path). ``vary``: a "KEY=START:STOP:N" string
    ("KEY=log:START:STOP:N" for log spacing), or a list of them (2-D and more), a key being a
    dotted path into the file (``plant.k``, ``controller.Kp``, ``friction.Fs``); or a dict
    ``{key: (start, stop, n)}``. ``transient``: seconds discarded from the start of each run (None:
    half of each run). ``tolerance``: a velocity oscillation below this fraction of the run's
    largest |v| counts as none (0.01). ``jobs``: threads (0: all cores). ``shard``: "K/N" to run
    only the points i with i % N == K - 1. ``contact``: the contact whose motion is classified, a
    name (``"x"``, ``"y"`` of an xy-table) or an index from 0 (None: the first, the one contact of
    a 1-DOF plant).

    Returns a list of dicts, one per grid point in grid order (the first key varying slowest),
    with the same columns as the CLI's table: the varied keys, ``class`` ('converged',
    'steady-sliding', 'stick-slip', 'hunting', 'oscillating', 'failed'), ``amplitude`` (m),
    ``period`` (s), ``mean_velocity``, ``velocity_amplitude`` (m/s), ``stuck_fraction``,
    ``transient`` (s), ``theory`` (the class theory predicts, '' where none applies),
    ``theory_margin`` (N s/m), ``theory_amplitude`` (m), ``theory_period`` (s), ``message``,
    ``contact`` (the classified contact's name, '' for a 1-DOF plant's one contact) and ``index``
    (the point's global index). Numbers that do not exist are NaN.
    Raises ValueError naming an unknown key, a bad grid or a contact the plant does not have (listing
    its contacts).
    """
    import math
    import os

    if not isinstance(scenario, (str, os.PathLike)):
        raise _core.ArgumentTypeError(
            f"analyze_map: argument scenario: expected the path of a scenario file; got {type(scenario).__name__}")
    if isinstance(vary, str):
        vary = [vary]
    elif isinstance(vary, dict):
        vary = [f"{k}={float(a)!r}:{float(b)!r}:{int(n)}" for k, (a, b, n) in vary.items()]
    elif not isinstance(vary, (list, tuple)) or not all(isinstance(v, str) for v in vary):
        raise _core.ArgumentTypeError(
            f"analyze_map: argument vary: expected 'KEY=START:STOP:N', a list of them or a dict "
            f"{{key: (start, stop, n)}}; got {type(vary).__name__}")
    if contact is None:
        contact = ""
    elif isinstance(contact, bool) or not isinstance(contact, (str, int)):
        raise _core.ArgumentTypeError(
            f"analyze_map: argument contact: expected a contact's name or an index from 0; got {type(contact).__name__}")
    elif isinstance(contact, int) and contact < 0:
        raise ValueError(f"analyze_map: contact {contact}: expected an index from 0 (or a contact's name)")
    out = _core._analyze_map(os.fspath(scenario), list(vary), math.nan if transient is None else float(transient),
                             float(tolerance), int(jobs), "" if shard is None else str(shard), str(contact))
    return out["rows"]
