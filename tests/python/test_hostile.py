"""Every public function of the package on hostile arguments: empty arrays, None, NaN and inf,
wrong dtypes (object, str, complex, bool), 2-D arrays, unequal lengths, non-numbers. Each must
raise ValueError or TypeError whose message names the argument (never crash, never answer).
Non-contiguous arrays are accepted (copied) and give the same answer as contiguous ones.

The public names are enumerated from frictionlab.__all__: a new one that is in none of the tables
below fails test_every_public_name_is_covered until its hostile calls are added here.
"""
import inspect
import os
import math
import re

import numpy as np
import pytest

import frictionlab as fl

N = 400  # samples of the valid arrays: enough for every method's minimum
T = np.arange(N) * 1e-3
WAVE = np.sin(2 * np.pi * 5 * T)


def _idim_result(emps):
    return fl.identify_idim(emps["t"], emps["gtau"] * emps["vir"], position=emps["qm"], source=emps)


@pytest.fixture(scope="module")
def idim_ok(emps):
    r = _idim_result(emps)
    assert r.ok, r.message
    return r


# name -> (call(**arrays), {array argument: valid value}, arguments that may be None)
def array_calls(idim_ok, emps, source_dir):
    scenario = source_dir / "examples" / "emps_closed_loop.yaml"
    data = source_dir / "data" / "emps" / "DATA_EMPS_PULSES.mat"
    tfp = {"time": T, "force": WAVE, "position": WAVE}
    tfv = {"time": T, "force": WAVE, "velocity": WAVE}
    return {
        "identify_idim": (fl.identify_idim, tfp, {"position"}),
        "idim_regression": (fl.idim_regression, tfp, {"position"}),
        "cross_test": (lambda **a: fl.cross_test(idim_ok, **a), tfp, {"position"}),
        "idim_reconstruction": (lambda **a: fl.idim_reconstruction(idim_ok, **a), tfp, {"time", "position"}),
        "identify_breakaway": (fl.identify_breakaway, tfv, set()),
        "identify_auto": (fl.identify_auto, tfp, {"position"}),
        "identify_sweep": (fl.identify_sweep, tfv, set()),
        "sweep_points": (fl.sweep_points, tfv, set()),
        "identify_decay": (fl.identify_decay, {"time": T, "position": WAVE}, set()),
        "identify_lugre": (lambda **a: fl.identify_lugre(**a, inertia=1.0), tfp, set()),
        "fit_static_law": (fl.fit_static_law, {"velocity": WAVE + 2.0, "force": WAVE}, set()),
        "decay_envelope": (fl.decay_envelope, {"t": T, "x": WAVE}, set()),
        "detect_stick_slip": (fl.detect_stick_slip, {"t": T, "v": WAVE, "force": WAVE}, {"force"}),
        "analyze_contour": (fl.analyze_contour, {"t": T, "x": np.cos(2 * np.pi * 5 * T), "y": WAVE,
                                                 "xr": np.cos(2 * np.pi * 5 * T), "yr": WAVE.copy()}, {"xr", "yr"}),
        "validate": (lambda **a: fl.validate(idim_ok, data, scenario, **a),
                     {"time": T, "position": WAVE, "force": WAVE}, set()),
        "validate_xy": (lambda **a: fl.validate_xy({"x": idim_ok}, source_dir / "examples" / "xy_circle.yaml", **a),
                        {"time": T, "x": WAVE, "y": WAVE, "x_force": WAVE, "y_force": WAVE}, {"x_force", "y_force"}),
        "FrictionLaw.sliding": (lambda **a: fl.FrictionLaw({"law": "coulomb", "Fc": 1.0}).sliding(**a),
                                {"v": WAVE}, set()),
        "FrictionLaw.force": (lambda **a: fl.FrictionLaw({"law": "coulomb", "Fc": 1.0}).force(**a),
                              {"v": WAVE, "applied": WAVE}, set()),
        "FrictionLaw.step": (lambda **a: fl.FrictionLaw({"law": "dahl", "sigma0": 1e5, "Fc": 1.0}).step(**a, dt=1e-3),
                             {"v": WAVE}, set()),
        "FrictionLaw.sliding_at": (lambda **a: fl.FrictionLaw({"law": "coulomb", "Fc": 1.0, "mu_load": 0.1}).sliding_at(**a, load=2.0),
                                   {"v": WAVE}, set()),
        "FrictionLaw.ripple": (lambda **a: fl.FrictionLaw({"law": "coulomb", "Fc": 1.0, "ripple_period": 1.0, "ripple_a": [0.1]}).ripple(**a),
                               {"q": WAVE}, set()),
        "FrictionLaw.force_at": (lambda **a: fl.FrictionLaw({"law": "coulomb", "Fc": 1.0, "ripple_period": 1.0, "ripple_a": [0.1]}).force_at(**a),
                                 {"v": WAVE, "applied": WAVE, "position": WAVE}, set()),
    }


# Public functions whose arguments are a path or a scenario (not arrays): name -> argument.
PATH_CALLS = {"analyze_map": "scenario", "load": "path", "load_law": "path", "sha256_file": "path", "simulate": "scenario", "export_c": "model", "export_mjcf": "model"}
# Public functions of files and keyword options, each with its own test below.
OTHER_CALLS = {"plan", "set_budget_factor"}
# Public names that take no array: result and option classes (made by the package or with no
# arguments), the version, the lists of law names and of methods. FrictionLaw's dict is tested on its own below.
NO_ARRAYS = {"ArgumentTypeError", "Error", "BreakawayOptions", "ContourResult", "DecayOptions", "Diagnostics", "EnvelopeFit", "EnvelopeOptions", "EnvelopeResult",
             "FitFigures", "IdimOptions", "Parameter", "Result", "StaticFit", "StaticFitOptions", "StickSlipOptions",
             "StickSlipResult", "SweepOptions", "Trajectory", "ValidationFigures", "__version__", "law_names", "methods", "Data", "budget_factor",
             "Scenario", "FrictionLaw"}
ARRAY_FUNCTIONS = {"identify_idim", "identify_auto", "idim_regression", "cross_test", "idim_reconstruction", "identify_breakaway",
                   "identify_sweep", "sweep_points", "identify_decay", "identify_lugre", "fit_static_law",
                   "decay_envelope", "detect_stick_slip", "validate", "validate_xy", "analyze_contour"}


def test_every_public_name_is_covered():
    missing = set(fl.__all__) - ARRAY_FUNCTIONS - set(PATH_CALLS) - NO_ARRAYS - OTHER_CALLS
    assert not missing, f"public names without hostile-input tests (add them to tests/python/test_hostile.py): {missing}"
    # Every public function with an array-like parameter is in the array table.
    for name in fl.__all__:
        obj = getattr(fl, name)
        if inspect.isfunction(obj) and name not in ARRAY_FUNCTIONS | set(PATH_CALLS) | OTHER_CALLS:
            assert not inspect.signature(obj).parameters, f"{name} takes arguments but is not tested here"
    # FrictionLaw's public methods that take arrays are covered too.
    law_methods = {m for m in dir(fl.FrictionLaw) if not m.startswith("_")
                   and callable(getattr(fl.FrictionLaw, m))}
    # breakaway_at takes two numbers (load, temperature), no arrays.
    assert law_methods <= {"sliding", "force", "step", "units", "to_dict", "sliding_at", "ripple", "force_at", "breakaway_at"}, law_methods


def hostile_values(valid):
    """(label, value, what the message must say) for one array argument whose valid value is `valid`."""
    with_nan = valid.copy()
    with_nan[N // 2] = math.nan
    with_inf = valid.copy()
    with_inf[3] = math.inf
    return [
        ("None", None, "None"),
        ("empty", np.array([]), "empty|at least|samples"),
        ("NaN", with_nan, "NaN"),
        ("inf", with_inf, "inf"),
        ("2-D", np.stack([valid, valid]), "1-D|2-D"),
        ("object dtype", valid.astype(object), "object"),
        ("str dtype", np.array(["a"] * len(valid)), "string|str"),
        ("complex dtype", valid.astype(complex), "complex"),
        ("bool dtype", np.ones(len(valid), dtype=bool), "bool"),
        ("str", "qm", "str"),
        ("dict", {"a": 1}, "dict"),
    ]


def expect_refusal(call, kwargs, name, want):
    with pytest.raises((ValueError, TypeError)) as info:
        call(**kwargs)
    message = str(info.value)
    assert re.search(rf"\b{re.escape(name)}\b", message), f"message does not name argument {name!r}: {message}"
    assert re.search(want, message), f"message does not say {want!r}: {message}"


def test_array_arguments_are_checked(idim_ok, emps, source_dir):
    calls = array_calls(idim_ok, emps, source_dir)
    assert set(calls) >= ARRAY_FUNCTIONS
    for fname, (call, valid, may_be_none) in calls.items():
        for arg, value in valid.items():
            for label, bad, want in hostile_values(value):
                if label == "None" and arg in may_be_none:
                    continue
                if fname.startswith("FrictionLaw.") and label == "empty":
                    continue  # element-wise: an empty array gives an empty answer
                if fname in ("FrictionLaw.sliding", "FrictionLaw.force", "FrictionLaw.sliding_at", "FrictionLaw.ripple",
                             "FrictionLaw.force_at") and label == "2-D":
                    continue  # element-wise: any shape
                kwargs = dict(valid, **{arg: bad})
                try:
                    expect_refusal(call, kwargs, arg, want)
                except AssertionError as e:
                    raise AssertionError(f"{fname}({arg}={label}): {e}") from None
                except pytest.fail.Exception as e:
                    raise AssertionError(f"{fname}({arg}={label}): no error raised") from e


def test_unequal_lengths_are_refused(idim_ok, emps, source_dir):
    for fname, (call, valid, _) in array_calls(idim_ok, emps, source_dir).items():
        if fname.startswith("FrictionLaw.") or len(valid) < 2:
            continue
        arg = list(valid)[-1]
        kwargs = dict(valid, **{arg: valid[arg][:-1]})
        with pytest.raises(ValueError) as info:
            call(**kwargs)
        assert re.search(r"length|samples|points", str(info.value)), f"{fname}: {info.value}"


def test_argument_type_error_is_both_type_and_value_error():
    assert issubclass(fl.ArgumentTypeError, TypeError) and issubclass(fl.ArgumentTypeError, ValueError)
    with pytest.raises(fl.ArgumentTypeError, match="detect_stick_slip: argument v: expected a 1-D array of numbers, "
                                                   "got an array of dtype complex128"):
        fl.detect_stick_slip(T, WAVE.astype(complex))


def test_the_reported_crash_is_an_error_now():
    # Both ended the Python process with a segmentation fault.
    with pytest.raises(ValueError, match="identify_sweep: argument time is empty; expected at least 2 samples"):
        fl.identify_sweep(np.array([]), np.array([]), np.array([]))
    with pytest.raises(TypeError, match="identify_sweep: argument time: expected a 1-D array of numbers, got None"):
        fl.identify_sweep(None, None, None)


def test_non_contiguous_arrays_are_copied():
    wide = np.stack([WAVE + 2.0, np.zeros(N)], axis=1)  # columns of a 2-D array: strided views
    v = wide[:, 0]
    assert not v.flags["C_CONTIGUOUS"]
    law = fl.FrictionLaw({"law": "coulomb-viscous", "Fc": 1.0, "Fv": 0.5})
    np.testing.assert_array_equal(law.sliding(v), law.sliding(np.ascontiguousarray(v)))
    a = fl.fit_static_law(v, law.sliding(v), model="coulomb-viscous")
    b = fl.fit_static_law(np.ascontiguousarray(v), law.sliding(v), model="coulomb-viscous")
    assert a.values == b.values
    moving = ((np.arange(N) % 100) >= 50).astype(np.int64)[::-1]  # integer dtype, negative stride
    assert moving.strides[0] < 0
    got = fl.detect_stick_slip(T, moving)
    want = fl.detect_stick_slip(T, np.ascontiguousarray(moving, dtype=float))
    assert len(want.slip) >= 3
    np.testing.assert_array_equal(got.slip, want.slip)


def test_path_arguments_are_checked():
    for fname, arg in PATH_CALLS.items():
        for bad in (None, 1.5, np.array([1.0])):
            with pytest.raises((ValueError, TypeError)) as info:
                getattr(fl, fname)(bad)
            assert re.search(rf"\b{arg}\b", str(info.value)), f"{fname}({bad!r}): {info.value}"


def test_plan_arguments_name_themselves(source_dir):
    prior = source_dir / "examples" / "plan" / "craig_motor_prior.json"
    motor = source_dir / "examples" / "craig_motor_trapezoid.yaml"
    for bad in (None, 1.5, np.array([1.0])):
        for arg in ("prior", "scenario"):
            paths = {"prior": prior, "scenario": motor, arg: bad}
            with pytest.raises((ValueError, TypeError)) as info:
                fl.plan("breakaway", paths["prior"], paths["scenario"], runs=2)
            assert re.search(rf"\b{arg}\b", str(info.value)), f"{arg}={bad!r}: {info.value}"
    for key, argument in (("current", "noise"), ("speed", "limits")):
        for bad in (math.nan, "a", True, -1.0, [1.0]):
            with pytest.raises((ValueError, TypeError)) as info:
                fl.plan("breakaway", prior, motor, runs=2, **{argument: {key: bad}})
            assert key in str(info.value) and argument in str(info.value), f"{argument}[{key}]={bad!r}: {info.value}"
    for argument, bad in (("runs", math.nan), ("runs", 1), ("seed", "a"), ("speeds", 2.5), ("margin", math.inf),
                          ("rate", None), ("method", None)):
        kwargs = {"runs": 2, argument: bad} if argument != "method" else {"runs": 2}
        method = bad if argument == "method" else "breakaway"
        with pytest.raises((ValueError, TypeError)) as info:
            fl.plan(method, prior, motor, **kwargs)
        assert re.search(rf"\b{argument}\b", str(info.value)), f"{argument}={bad!r}: {info.value}"


def test_number_arguments_name_themselves(idim_ok):
    for call, name in [
        (lambda x: fl.identify_lugre(T, WAVE, WAVE, inertia=x), "inertia"),
        (lambda x: fl.identify_breakaway(T, WAVE, WAVE, inertia=x), "inertia"),
        (lambda x: fl.identify_decay(T, WAVE, stiffness=x), "stiffness"),
        (lambda x: fl.FrictionLaw({"law": "dahl", "sigma0": 1e5, "Fc": 1.0}).step(WAVE, x), "dt"),
        (lambda x: fl.FrictionLaw({"law": "coulomb", "Fc": x}), "Fc"),
    ]:
        for bad, want in ((math.nan, "NaN|nan"), (math.inf, "inf"), ("a", "number|str"), (True, "number|bool")):
            with pytest.raises((ValueError, TypeError)) as info:
                call(bad)
            message = str(info.value)
            assert re.search(rf"\b{name}\b", message) and re.search(want, message), f"{name}={bad!r}: {message}"


def test_law_parameter_that_is_text_is_not_missing():
    with pytest.raises(TypeError, match="law parameter 'Fc': expected a number or a list of numbers, got 'a'"):
        fl.FrictionLaw({"law": "coulomb", "Fc": "a"})
    with pytest.raises(ValueError, match="law parameter 'Fc' is NaN"):
        fl.FrictionLaw({"law": "coulomb", "Fc": float("nan")})
    with pytest.raises(ValueError, match=r"law parameter 'velocity' has NaN at index 1"):
        fl.FrictionLaw({"law": "table", "velocity": [0.1, float("nan")], "force": [1.0, 2.0]})


def test_a_scenario_dict_that_contains_itself_or_nests_too_deep_is_refused():
    """Used to end the interpreter with a segmentation fault (unbounded recursion in the dict's
    conversion); now a ValueError naming where, for both Scenario and simulate."""
    d = {"plant": {"type": "axis", "M": 1.0}, "law": {"law": "coulomb", "Fc": 1.0}}
    d["plant"]["self"] = d
    for call in (fl.Scenario, fl.simulate):
        with pytest.raises(ValueError, match="plant: self: the dict contains itself"):
            call(d)
    deep = {"plant": {"type": "axis", "M": 1.0}, "law": {"law": "coulomb", "Fc": 1.0}}
    node = deep
    for _ in range(10000):
        node["x"] = {}
        node = node["x"]
    for call in (fl.Scenario, fl.simulate):
        with pytest.raises(ValueError, match="nested more than 100 levels deep"):
            call(deep)
    ring = [1.0]
    ring.append(ring)
    with pytest.raises(ValueError, match="the list contains itself"):
        fl.Scenario({"plant": {"type": "axis", "M": 1.0, "v": ring}, "law": {"law": "coulomb", "Fc": 1.0}})


def test_the_documented_exception_types():
    """Arguments of the wrong shape or kind raise ValueError or TypeError naming the function and
    the argument, not pybind11's RuntimeError or an AttributeError from deep inside."""
    law = fl.FrictionLaw({"law": "coulomb", "Fc": 1.0})
    with pytest.raises(ValueError, match=r"FrictionLaw.force: the shapes of v \(2,\) and applied \(3,\) do not match"):
        law.force([1.0, 2.0], [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match=r"position \(3,\) do not match"):
        law.force_at([1.0, 2.0], [1.0, 2.0], position=[0.0, 1.0, 2.0])
    assert law.force(0.0, [0.5, 2.0]).tolist() == [0.5, 1.0]  # a scalar still broadcasts
    with pytest.raises(TypeError, match="drift: table: expected a Table"):
        fl.batch.drift("x")
    with pytest.raises(TypeError, match="idim_reconstruction: result: expected the Result of identify_idim"):
        fl.idim_reconstruction("x")
    with pytest.raises(fl.Error, match="is a directory"):
        fl.load_law(os.path.dirname(os.path.abspath(__file__)))


def test_set_budget_factor_refuses_what_is_not_a_factor():
    """NaN, inf, zero, negative and too small factors are refused naming --budget, and leave the
    factor as it was; a string or None is an ArgumentTypeError."""
    before = fl.budget_factor()
    for bad in (float("nan"), float("inf"), -1.0, 0.0, 1e-7):
        with pytest.raises(fl.Error) as info:
            fl.set_budget_factor(bad)
        assert info.value.code == "option.out_of_range" and info.value.option == "--budget", (bad, str(info.value))
        assert fl.budget_factor() == before
    for bad in ("2", None, [2.0]):
        with pytest.raises(TypeError):
            fl.set_budget_factor(bad)
