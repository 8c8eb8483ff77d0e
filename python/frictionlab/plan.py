"""Experiment planning: design the excitation of an identification experiment from a prior
model and the rig's scenario, and predict each parameter's standard deviation before it is run
(the library's analysis/plan, the command line's ``frictionlab plan``)."""
import json
import math

from . import _core

_NOISE_KEYS = ("position", "velocity", "current", "force", "encoder")
_LIMIT_KEYS = ("current", "force", "speed", "min_speed", "travel")


def _items(argument, value, keys):
    # A dict {key: number} as the KEY=VALUE items of the command line's --noise / --limits.
    if value is None:
        return []
    if not hasattr(value, "items"):
        raise _core.ArgumentTypeError(
            f"plan: argument {argument}: expected a dict with keys among {', '.join(keys)}; got {type(value).__name__}")
    items = []
    for key, number in value.items():
        if isinstance(number, bool) or not isinstance(number, (int, float)):
            raise _core.ArgumentTypeError(
                f"plan: argument {argument}['{key}']: expected a number, got {type(number).__name__}")
        items.append(f"{key}={repr(float(number)) if math.isfinite(number) else number}")
    return [",".join(items)] if items else []


def _whole(argument, value):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value != int(value):
        raise _core.ArgumentTypeError(f"plan: argument {argument}: expected a whole number, got {value!r}")
    return int(value)


def _number(argument, value):
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise _core.ArgumentTypeError(f"plan: argument {argument}: expected a number, got {type(value).__name__}")
    if not math.isfinite(value):
        raise ValueError(f"plan: argument {argument}: expected a finite number, got {value!r}")
    return float(value)


def plan(method, prior, scenario, *, noise=None, limits=None, runs=0, seed=1, margin=0.0, lag_fraction=0.01,
         speeds=15, rate=0.0, load=0.0, warm_up=0.0, ripple_periods=4, output=None, overwrite=False):
    """Design an experiment and predict the std of each parameter.

    ``method``: 'breakaway', 'sweep', 'idim', 'lugre', or the effects' designs 'load-steps',
    'warm-up', 'ripple-scan' (identified by idim with its load, temperature or ripple term). ``prior``: MODEL.json of an
    identification (or a law file); ``scenario``: the rig's scenario YAML (axis or dc-motor, with
    a velocity loop for sweep and a position loop for idim).
    ``noise``: dict of sensor noise std, keys position (m or rad), velocity (m/s or rad/s),
    current (A), force (N or N m), encoder (quantisation step, m or rad).
    ``limits``: dict, keys current (A), force (N or N m), speed (m/s or rad/s), min_speed
    (m/s or rad/s), travel (m or rad).
    ``runs``: Monte Carlo runs (0: 40, lugre 8); ``seed``: first seed; ``margin``, ``lag_fraction``,
    ``speeds``, ``rate`` (Hz), ``load`` (load-steps: the largest load, N or N m), ``warm_up``
    (warm-up: the run's length, s; 0: 2 thermal time constants), ``ripple_periods`` (ripple-scan):
    design choices as on the command line.
    ``output``: a CSV path to write the profile to (atomically; ``overwrite`` to replace).

    Returns the plan as a dict (the JSON of ``frictionlab plan --json``), with
    ``result["profile"]["time"]`` (s) and ``result["profile"]["command"]`` (command unit) as
    numpy arrays, and for load-steps ``result["profile"]["load"]`` (N or N m). Predicted std: ``result["prediction"]["parameters"][NAME]["std"]`` (None when
    the plan cannot determine NAME, which is then listed in ``result["undetermined"]``); for sweep
    and idim also ``"std_a_priori"``, the Fisher-information std of the noise-free plan (README).
    Raises ValueError naming the limit that makes the plan impossible, or a bad key.
    """
    if not isinstance(method, str):
        raise _core.ArgumentTypeError(f"plan: argument method: expected one of breakaway, sweep, idim, lugre, "
                                      f"load-steps, warm-up, ripple-scan; "
                                      f"got {type(method).__name__}")
    text, t, u, load_samples = _core._plan(
        method, prior, scenario, _items("noise", noise, _NOISE_KEYS), _items("limits", limits, _LIMIT_KEYS),
        _whole("runs", runs), _whole("seed", seed), _number("margin", margin), _number("lag_fraction", lag_fraction),
        _whole("speeds", speeds), _number("rate", rate), _number("load", load), _number("warm_up", warm_up),
        _whole("ripple_periods", ripple_periods), output, bool(overwrite))
    result = json.loads(text)
    result["profile"]["time"] = t
    result["profile"]["command"] = u
    if load_samples is not None:
        result["profile"]["load"] = load_samples
    return result
