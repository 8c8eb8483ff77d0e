"""IDIM-LS from Python: identify_idim, its cross-test, regression and reconstruction."""
import numpy as np

from .. import _core
from .._args import _source

__all__ = ["identify_idim", "cross_test", "idim_regression", "idim_reconstruction"]

_IDIM_DEFAULT_TERMS = ("inertia", "viscous", "coulomb", "offset")


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
