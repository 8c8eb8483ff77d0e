"""Identification methods over numpy arrays: idim, breakaway, sweep, decay, static law fit, and
the table of every method the library has (methods()).

Every method returns a :class:`frictionlab.Result` (values, std, units, fit figures,
diagnostics, status and message). Data that cannot give an answer (no motion, too few
segments, rank-deficient regressors) gives ``status == 'error'`` with a message, not an
exception; bad input (unequal lengths, NaN, irregular time, unknown option value) raises
ValueError with the library's message.
"""
import collections
import importlib

from . import _core

Method = collections.namedtuple("Method", "name summary fit_signal fit_units function options")
Method.__doc__ = """One identification method of the library (frictionlab/identify/method.hpp).

    name        the method's name: Result.method, ``frictionlab identify NAME`` (validate: its own command)
    summary     one line on what it does
    fit_signal  the signal its fit figures are computed on, in words ("drive force"); "" when none
    fit_units   the unit of that signal (the fit's rmse) by axis, {"linear": "N", "rotary": "N m"};
                {} when there is no single fitted signal (validate reports per-signal errors)
    function    name of the frictionlab function running it ("identify_idim"), None when it has no
                Python binding
    options     its option table, one dict per option: name (the command line's flag without --),
                keyword (the Python keyword), type, unit, default (as text; None when computed from
                the data or absent), help, expected (the valid values in words), required,
                deprecated (former Python keywords, still accepted with a DeprecationWarning)
"""


def methods():
    """Every identification method of the library, in its order, as Method tuples (name, summary,
    fit_signal, fit_units, function). The table is the library's; ``function`` comes from the
    module's registration (python/src/methods/), so a method without a binding shows None."""
    return [Method(**m) for m in _core._methods()]


def _method_functions():
    """{public name: function} of every method module (frictionlab.methods.NAME for each method of the
    library's table), in the table's order. A method without a Python module is left out; methods()
    shows its function as None then."""
    functions = {}
    for m in _core._methods():
        try:
            module = importlib.import_module(f".methods.{m['name']}", __package__)
        except ModuleNotFoundError as e:
            if e.name != f"{__package__}.methods.{m['name']}":
                raise
            continue
        for name in module.__all__:
            functions[name] = getattr(module, name)
    return functions


METHOD_FUNCTIONS = _method_functions()
globals().update(METHOD_FUNCTIONS)
__all__ = ["methods", "fit_static_law", *METHOD_FUNCTIONS]


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
