"""Identification methods over numpy arrays: idim, breakaway, sweep, decay, static law fit, and
the table of every method the library has (methods()).

Every method returns a :class:`frictionlab.Result` (values, std, units, fit figures,
diagnostics, status and message). Data that cannot give an answer (no motion, too few
segments, rank-deficient regressors) gives ``status == 'error'`` with a message, not an
exception; bad input (unequal lengths, NaN, irregular time, unknown option value) raises
ValueError with the library's message.
"""
import collections
import math
import os

import numpy as np

from . import _core

_IDIM_DEFAULT_TERMS = ("inertia", "viscous", "coulomb", "offset")

Method = collections.namedtuple("Method", "name summary fit_signal fit_units function")
Method.__doc__ = """One identification method of the library (frictionlab/identify/method.hpp).

    name        the method's name: Result.method, ``frictionlab identify NAME`` (validate: its own command)
    summary     one line on what it does
    fit_signal  the signal its fit figures are computed on, in words ("drive force"); "" when none
    fit_units   the unit of that signal (the fit's rmse) by axis, {"linear": "N", "rotary": "N m"};
                {} when there is no single fitted signal (validate reports per-signal errors)
    function    name of the frictionlab function running it ("identify_idim"), None when it has no
                Python binding
"""


def methods():
    """Every identification method of the library, in its order, as Method tuples (name, summary,
    fit_signal, fit_units, function). The table is the library's; ``function`` comes from the
    module's registration (python/src/methods/), so a method without a binding shows None."""
    return [Method(**m) for m in _core._methods()]


def _source(source):
    """(file, sha256) from a Data (load()), a path, or None."""
    if source is None:
        return "", ""
    if isinstance(source, (str, os.PathLike)):
        path = os.fspath(source)
        return path, _core.sha256_file(path)
    return getattr(source, "file", ""), getattr(source, "sha256", "")


def _nan(function, name, x):
    """An optional number option: None gives NaN (the library's "not given"); anything else must be
    a finite real number, or ArgumentTypeError / ValueError naming the argument."""
    if x is None:
        return math.nan
    if isinstance(x, (bool, str, bytes)) or not isinstance(x, (int, float, np.integer, np.floating)):
        raise _core.ArgumentTypeError(f"{function}: argument {name}: expected a number or None, got {type(x).__name__}")
    if not math.isfinite(x):
        raise ValueError(f"{function}: argument {name} is {x}; expected a finite number (or None)")
    return float(x)


def _idim_options(terms=_IDIM_DEFAULT_TERMS, cutoff_hz=100.0, filter_order=4, padlen=12, input_delay=0, skip=49,
                  skip_end=0, decimation=10, stribeck_vs=0.01, stribeck_delta=2.0, min_velocity=0.0,
                  max_condition=1e8, axis="linear"):
    o = _core.IdimOptions()
    if isinstance(terms, str):
        terms = [t.strip() for t in terms.split(",") if t.strip()]
    o.terms = list(terms)
    o.cutoff_hz = cutoff_hz
    o.filter_order = filter_order
    o.padlen = padlen
    o.input_delay = input_delay
    o.skip = skip
    o.skip_end = skip_end
    o.decimation = decimation
    if isinstance(stribeck_vs, str):
        if stribeck_vs != "search":
            raise ValueError(f"stribeck_vs '{stribeck_vs}': expected a Stribeck velocity (m/s or rad/s) or 'search'")
        o.search_stribeck_vs = True
    else:
        o.stribeck_vs = float(stribeck_vs)
    o.stribeck_delta = stribeck_delta
    o.min_velocity = min_velocity
    o.max_condition = max_condition
    o.axis = axis
    return o


def _rate_defaults(time, cutoff_hz, skip, decimation):
    """cutoff_hz, skip and decimation with each None replaced by its idim_rate_defaults value for
    the mean sample rate of ``time``, and the set of names so replaced."""
    chosen = {k for k, v in (("cutoff_hz", cutoff_hz), ("skip", skip), ("decimation", decimation)) if v is None}
    if not chosen:
        return cutoff_hz, skip, decimation, chosen
    try:
        t = np.asarray(time, dtype=float) if time is not None else np.empty(0)
    except (TypeError, ValueError):
        t = np.empty(0)  # the argument checks of the call itself name the problem with time
    if t.ndim != 1 or t.size < 2 or not np.isfinite(t[[0, -1]]).all() or not t[-1] > t[0]:
        # The argument checks of the call itself name the problem with time.
        return (100.0 if cutoff_hz is None else cutoff_hz, 49 if skip is None else skip,
                10 if decimation is None else decimation, set())
    d = _core.idim_rate_defaults((t.size - 1) / (t[-1] - t[0]))
    return (d["cutoff_hz"] if cutoff_hz is None else cutoff_hz, d["skip"] if skip is None else skip,
            d["decimation"] if decimation is None else decimation, chosen)


def identify_idim(time, force, position=None, velocity=None, *, terms=_IDIM_DEFAULT_TERMS, cutoff_hz=None,
                  filter_order=4, padlen=12, input_delay=0, skip=None, skip_end=0, decimation=None, stribeck_vs=0.01,
                  stribeck_delta=2.0, min_velocity=0.0, max_condition=1e8, axis="linear", source=None,
                  validate=None):
    """IDIM-LS: inverse dynamic model least squares on a measured trajectory,
    ``force = M qdd + Fv qd + Fc sign(qd) + offset (+ further terms)``, by the EMPS recipe
    (zero-phase Butterworth low-pass of the position, central differences, skip, decimate, OLS).

    Arrays (1-D, equal length N): ``time`` (s, regular), ``force`` (applied force or torque,
    N or N m: gain times the drive input), and ``position`` (m or rad) or, when no position is
    given, ``velocity`` (m/s or rad/s, filtered but not differentiated).

    Options (defaults = EMPS recipe; cutoff_hz, skip and decimation follow the sample rate
    when not given, see idim_rate_defaults: exactly 100 Hz, 49, 10 at 1 kHz):
      terms           regressors in column order: "inertia" (M, kg), "viscous" (Fv, N s/m),
                      "coulomb" (Fc, N), "offset" (N), "asymmetric" (Fv_pos, Fc_pos, Fv_neg,
                      Fc_neg), each of those four alone, "stribeck" (Fs_minus_Fc, N); a list or
                      a comma-separated string
      cutoff_hz       position low-pass cut-off, Hz (100); filter_order (4); padlen, samples (12)
      input_delay     samples by which the applied force lags the recorded input (0; EMPS: 1)
      skip, skip_end  samples dropped at the start (49) and end (0)
      decimation      keep one sample in N after the anti-alias filter (10)
      stribeck_vs     Stribeck velocity of the "stribeck" term, m/s or rad/s (0.01), or
                      "search" for the value minimising the identification error
      stribeck_delta  Stribeck exponent (2)
      min_velocity    no excitation when max |qd| is not above this, m/s or rad/s (0)
      max_condition   status error above this condition number (1e8)
      axis            "linear" (N, kg, m/s) or "rotary" (N m, kg m^2, rad/s): units reported
      source          the Data from load() (or a path) the arrays came from: its file name
                      and sha256 go into the result
      validate        optional second run for a cross-test with the identified parameters:
                      a dict with "time", "force" and "position" or "velocity" (and optionally
                      "source"); sets result.validation

    Returns a Result; ``result.law`` is the identified friction law. The arrays and options
    are kept on the result (``result.inputs``, ``result.options``) for idim_reconstruction and
    frictionlab.plot.idim.
    """
    cutoff_hz, skip, decimation, chosen = _rate_defaults(time, cutoff_hz, skip, decimation)
    opts = _idim_options(terms, cutoff_hz, filter_order, padlen, input_delay, skip, skip_end, decimation,
                         stribeck_vs, stribeck_delta, min_velocity, max_condition, axis)
    # The values taken from the sample rate are listed as such in diagnostics["defaults"].
    opts.auto_cutoff, opts.auto_decimation, opts.auto_skip = (k in chosen for k in ("cutoff_hz", "decimation", "skip"))
    file, sha = _source(source)
    r = _core._identify_idim(time, force, position, velocity, opts, file, sha)
    r.inputs = {"time": time, "force": force, "position": position, "velocity": velocity}
    r.options = opts
    if validate is not None and r.ok:
        r._set_validation(cross_test(r, **validate))
    return r


def cross_test(result, time, force, position=None, velocity=None, *, source=None, **options):
    """Relative force error of an identified idim result on a second run (the same pipeline).

    Arrays as identify_idim (time s, force N or N m, position m or rad or velocity m/s or
    rad/s). Options default to those the result was identified with; keywords of
    identify_idim override them. Returns ValidationFigures (file, sha256,
    relative_error_percent, rmse in N or N m, samples). Raises ValueError when the result is
    not ok or lacks a parameter of a term, and for bad data.
    """
    opts = getattr(result, "options", None) if not options else None
    if opts is None:
        opts = _idim_options(**options)
    file, sha = _source(source)
    return _core._cross_test(result, time, force, position, velocity, opts, file, sha)


def idim_regression(time, force, position=None, velocity=None, **options):
    """The regression identify_idim solves: dict with ``X`` (decimated regressor matrix,
    n x p), ``y`` (decimated force, N or N m), ``parameters`` (the p names, column order),
    ``dt`` (mean raw sample step, s) and ``max_speed`` (m/s or rad/s). Options as identify_idim.
    """
    return _core._idim_regression(time, force, position, velocity, _idim_options(**options))


def idim_reconstruction(result, time=None, force=None, position=None, velocity=None):
    """Measured and reconstructed force of an idim result (for plots): dict with ``time`` (s,
    the decimated sample times), ``measured`` and ``reconstructed`` (N or N m) and ``residual``.
    Uses the result's own data and options unless arrays are given.
    """
    if not result.ok:
        raise ValueError(f"idim result has status error: {result.message}")
    opts = getattr(result, "options", None) or _idim_options()
    if time is None:
        inputs = getattr(result, "inputs", None)
        if inputs is None:
            raise ValueError("idim_reconstruction: the result carries no data; pass time, force and position")
        time, force, position, velocity = (inputs[k] for k in ("time", "force", "position", "velocity"))
    reg = _core._idim_regression(time, force, position, velocity, opts)
    theta = np.array([result.value(name) for name in reg["parameters"]])
    t = np.asarray(time, dtype=float)
    t = t[opts.skip:len(t) - opts.skip_end][::opts.decimation]
    fitted = reg["X"] @ theta
    return {"time": t, "measured": reg["y"], "reconstructed": fitted, "residual": reg["y"] - fitted}


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


def _sweep_options(model="stribeck", fixed_delta=None, velocity_tolerance=0.0, relative_tolerance=0.01,
                   min_duration=0.5, settle_fraction=0.2, min_speed=None, windows=None, min_segments=None,
                   axis="rotary"):
    o = _core.SweepOptions()
    fit = o.fit
    fit.model = model
    fit.fixed_delta = 0.0 if fixed_delta is None else float(fixed_delta)
    o.fit = fit
    o.velocity_tolerance = velocity_tolerance
    o.relative_tolerance = relative_tolerance
    o.min_duration = min_duration
    o.settle_fraction = settle_fraction
    o.min_speed = -1.0 if min_speed is None else float(min_speed)
    o.windows = [] if windows is None else [tuple(map(float, w)) for w in windows]
    o.min_segments = -1 if min_segments is None else int(min_segments)
    o.axis = axis
    return o


def identify_sweep(time, force, velocity, *, model="stribeck", fixed_delta=None, velocity_tolerance=0.0,
                   relative_tolerance=0.01, min_duration=0.5, settle_fraction=0.2, min_speed=None, windows=None,
                   min_segments=None, axis="rotary", source=None):
    """Constant-velocity tests: one friction-velocity point per steady segment, then a fitted law.

    Arrays (1-D, equal length): ``time`` (s), ``force`` (drive torque N m or force N),
    ``velocity`` (rad/s or m/s).
    Options: ``model`` ("coulomb-viscous", "coulomb-viscous-asymmetric", "stribeck",
    "stribeck-asymmetric"), ``fixed_delta`` (hold the Stribeck exponent; default fitted),
    ``velocity_tolerance`` (absolute steady band, rad/s or m/s, 0), ``relative_tolerance``
    (0.01), ``min_duration`` (shortest steady segment, s, 0.5), ``settle_fraction`` (part of a
    segment dropped at its start, 0.2), ``min_speed`` (slower segments are standstill; default
    1e-3 max |v|), ``windows`` ([(t_begin, t_end), ...] in s instead of detection),
    ``min_segments`` (default parameters + 1), ``axis`` ("rotary" default).
    The points are in ``result.diagnostics.lists['points']``; the fitted law in ``result.law``.
    """
    o = _sweep_options(model, fixed_delta, velocity_tolerance, relative_tolerance, min_duration, settle_fraction,
                       min_speed, windows, min_segments, axis)
    r = _core._identify_sweep(time, force, velocity, o)
    r._stamp(*_source(source))
    r.inputs = {"time": time, "force": force, "velocity": velocity}
    return r


def sweep_points(time, force, velocity, **options):
    """The steady-segment points of a sweep, as a dict of numpy arrays: ``velocity``,
    ``velocity_std`` (rad/s or m/s), ``force``, ``force_std`` (N m or N), ``t_begin``,
    ``t_end`` (s), ``samples``. Options as identify_sweep (the fit options are unused)."""
    options.pop("source", None)
    return _core._sweep_points(time, force, velocity, _sweep_options(**options))


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


def fit_static_law(velocity, force, *, model="stribeck", fixed_delta=None, delta_min=0.5, delta_max=5.0,
                   max_iterations=200, num_threads=2):
    """Least-squares fit of a static law to friction-velocity points (v in m/s or rad/s,
    F in N or N m, friction with the sign of v; no zero velocities).

    ``model``: "coulomb-viscous" (linear, exact), "coulomb-viscous-asymmetric", "stribeck",
    "stribeck-asymmetric" (Ceres, data-driven start). ``fixed_delta`` holds the Stribeck
    exponent (default: fitted within [delta_min, delta_max]).
    Returns a StaticFit: ``law`` (FrictionLaw), ``values``, ``std``, ``parameters(axis)``,
    ``relative_error_percent``, ``rmse`` (N or N m), ``samples``, ``converged``, ``warnings``.
    """
    o = _core.StaticFitOptions()
    o.model = model
    o.fixed_delta = 0.0 if fixed_delta is None else float(fixed_delta)
    o.delta_min = delta_min
    o.delta_max = delta_max
    o.max_iterations = max_iterations
    o.num_threads = num_threads
    return _core._fit_static_law(velocity, force, o)
