"""IDIM-LS from Python: identify_idim, its cross-test, regression and reconstruction."""
import os

import numpy as np

from .. import _core
from .._args import _method_options, _source, _with_options_doc

__all__ = ["identify_idim", "cross_test", "idim_regression", "idim_reconstruction"]

# IDIM-IV's gains that may name a scalar of the data file (kp="kp" on a MAT file's log).
_SCALAR_GAINS = ("kp", "kd", "ki", "kv", "drive_gain", "control_limit")


def _scalars_of(source):
    """(file name, {name: value}) of the scalars of ``source``: a Data (load()) or a path."""
    if source is None:
        return "", None
    if isinstance(source, (str, os.PathLike)):
        from ..data import load
        d = load(source)
        return os.fspath(source), d.scalars
    return getattr(source, "file", ""), getattr(source, "scalars", None)


def _with_file_scalars(function, options, source):
    """The options with each gain given as a scalar's name replaced by its value in ``source``, and
    {option name: where it came from} for the IDIM-IV diagnostics. ValueError naming the file and
    listing its scalars for a name it lacks."""
    options, sources, scalars = dict(options), {}, None
    for keyword in _SCALAR_GAINS:
        name = options.get(keyword)
        if not isinstance(name, str):
            continue
        if scalars is None:
            file, scalars = _scalars_of(source)
            if scalars is None:
                raise ValueError(f"{function}: {keyword}='{name}' names a scalar of the data file, but no source= "
                                 f"gives one (pass source=the Data from load(), or the file's path), or give a number")
        if name not in scalars:
            raise ValueError(f"{function}: {keyword}='{name}': {file or 'the data'} has no scalar '{name}'; expected a "
                             f"number or the name of a scalar in the file; scalars: "
                             f"{', '.join(sorted(scalars)) or 'none'}")
        options[keyword] = float(scalars[name])
        sources[keyword.replace("_", "-")] = f"{keyword}='{name}': scalar of {os.path.basename(file) or 'the data'}"
    return options, sources


def _idim_options(function, options, time=None, source=None):
    """(values, IdimOptions, inputs) from keyword options checked against idim's option table;
    ``axis`` among them picks the units. With ``time``, cutoff, decimate and skip not given are
    taken from its sample rate (idim_rate_defaults), and marked so in the result. Gains given as
    a scalar's name are read from ``source`` (a Data or a path); ``scenario`` (a path or a
    Scenario) gives IDIM-IV's controller under the options."""
    options = dict(options)
    axis = options.pop("axis", "linear")
    options, sources = _with_file_scalars(function, options, source)
    values, inputs = _method_options("idim", function, options, stacklevel=4)
    scenario = inputs.get("scenario")
    scenario = None if scenario is None else _core._idim_iv_scenario(scenario, axis)
    o = _core._make_idim_options(values, scenario)
    if sources and o.iv_sources:  # filled when iv=True
        merged = dict(o.iv_sources)
        merged.update(sources)
        o.iv_sources = merged
    o.axis = axis
    given = {k: values.given(k) for k in ("cutoff", "skip", "decimate")}
    cutoff, skip, decimation, chosen = _rate_defaults(time, None if not given["cutoff"] else o.cutoff_hz,
                                                      None if not given["skip"] else o.skip,
                                                      None if not given["decimate"] else o.decimation)
    o.cutoff_hz, o.skip, o.decimation = cutoff, skip, decimation
    # The values taken from the sample rate are listed as such in diagnostics["defaults"].
    o.auto_cutoff, o.auto_decimation, o.auto_skip = (k in chosen for k in ("cutoff_hz", "decimation", "skip"))
    return values, o, inputs


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


@_with_options_doc("idim")
def identify_idim(time, force, position=None, velocity=None, *, axis="linear", source=None, **options):
    """IDIM-LS: inverse dynamic model least squares on a measured trajectory,
    ``force = M qdd + Fv qd + Fc sign(qd) + offset (+ further terms)``, by the EMPS recipe
    (zero-phase Butterworth low-pass of the position, central differences, skip, decimate, OLS).

    Arrays (1-D, equal length N): ``time`` (s, regular), ``force`` (applied force or torque,
    N or N m: gain times the drive input), and ``position`` (m or rad) or, when no position is
    given, ``velocity`` (m/s or rad/s, filtered but not differentiated).

    Defaults are the EMPS recipe; cutoff, skip and decimate follow the sample rate when not
    given (idim_rate_defaults: exactly 100 Hz, 49, 10 at 1 kHz). ``axis``: "linear" (N, kg,
    m/s) or "rotary" (N m, kg m^2, rad/s); ``source``: the Data from load() (or a path) the
    arrays came from, its file name and sha256 go into the result; ``validate``: a second run
    for a cross-test, a dict with "time", "force" and "position" or "velocity" (and optionally
    "source"; "load" and "temperature" for those terms); sets result.validation. ``load`` (N or N m)
    and ``temperature`` (degC or K): arrays of length N for the terms "load" and "temperature".
    ``iv=True``: IDIM-IV for a record taken in a closed loop (docs/identify.md): give the
    controller (``controller="pid"`` with ``kp`` N/m, ``kd`` N s/m, optional ``ki``, or
    ``controller="emps-pd"`` with ``kp`` 1/s, ``kv`` V s/m and ``drive_gain`` N/V, or
    ``scenario=`` a scenario file's path or a Scenario whose controller section gives them, the
    keywords given overriding its values) and ``reference`` (array, m or rad), optionally
    ``feedforward`` (array, N or N m). A gain may name a scalar of the data file (``kp="kp"``),
    read from ``source`` (a Data from load(), or the file's path). The result's diagnostics
    ``iv_controller`` and ``iv_source_*`` say which values the simulation used and where each
    came from.

    Returns a Result; ``result.law`` is the identified friction law. The arrays are kept on the
    result (``result.inputs``) for idim_reconstruction and frictionlab.plot.idim;
    ``result.options`` is the options the fit used, by the command line's names, each a dict
    of ``value``, ``unit`` and ``given`` (as MODEL.json's "options").
    """
    values, opts, inputs = _idim_options("identify_idim", dict(options, axis=axis), time, source)
    file, sha = _source(source)
    load, temperature = inputs.get("load"), inputs.get("temperature")
    r = _core._identify_idim(time, force, position, velocity, load, temperature, opts, file, sha,
                             inputs.get("reference"), inputs.get("feedforward"))
    r._record_options(values)
    r.inputs = {"time": time, "force": force, "position": position, "velocity": velocity, "load": load,
                "temperature": temperature}
    r._idim_options = opts  # the library's form, for cross_test and idim_reconstruction
    r.options = r.to_dict()["options"]
    validate = inputs.get("validate")
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
    options = dict(options)
    load, temperature = options.pop("load", None), options.pop("temperature", None)
    opts = getattr(result, "_idim_options", None) if not options else None
    if opts is None:
        _, opts, _ = _idim_options("cross_test", options)
    file, sha = _source(source)
    return _core._cross_test(result, time, force, position, velocity, load, temperature, opts, file, sha)


def idim_regression(time, force, position=None, velocity=None, **options):
    """The regression identify_idim solves: dict with ``X`` (decimated regressor matrix,
    n x p), ``y`` (decimated force, N or N m), ``parameters`` (the p names, column order),
    ``dt`` (mean raw sample step, s) and ``max_speed`` (m/s or rad/s). Options as identify_idim.
    """
    _, opts, inputs = _idim_options("idim_regression", options)
    return _core._idim_regression(time, force, position, velocity, inputs.get("load"), inputs.get("temperature"), opts)


def idim_reconstruction(result, time=None, force=None, position=None, velocity=None, load=None, temperature=None):
    """Measured and reconstructed force of an idim result (for plots): dict with ``time`` (s,
    the decimated sample times), ``measured`` and ``reconstructed`` (N or N m) and ``residual``.
    Uses the result's own data and options unless arrays are given (load and temperature, N or N m
    and degC or K, for results with those terms).
    """
    if not hasattr(result, "ok") or getattr(result, "method", None) != "idim":
        raise TypeError(f"idim_reconstruction: result: expected the Result of identify_idim, got "
                        f"{type(result).__name__}")
    if not result.ok:
        raise ValueError(f"idim result has status error: {result.message}")
    opts = getattr(result, "_idim_options", None) or _idim_options("idim_reconstruction", {})[1]
    if time is None:
        inputs = getattr(result, "inputs", None)
        if inputs is None:
            raise ValueError("idim_reconstruction: the result carries no data; pass time, force and position")
        time, force, position, velocity = (inputs[k] for k in ("time", "force", "position", "velocity"))
        load, temperature = inputs.get("load"), inputs.get("temperature")
    reg = _core._idim_regression(time, force, position, velocity, load, temperature, opts)
    theta = np.array([result.value(name) for name in reg["parameters"]])
    t = np.asarray(time, dtype=float)
    t = t[opts.skip:len(t) - opts.skip_end][::opts.decimation]
    fitted = reg["X"] @ theta
    return {"time": t, "measured": reg["y"], "reconstructed": fitted, "residual": reg["y"] - fitted}
