"""frictionlab.Error: bad input with a stable code raises a ValueError subclass carrying .code and
the fields that locate the fault (file, row, column, key, option, value; None when they do not
apply)."""
import re

import pytest

import frictionlab as fl


def test_error_is_a_value_error():
    assert issubclass(fl.Error, ValueError)


def test_csv_text_cell_code_and_fields(tmp_path):
    p = tmp_path / "d.csv"
    p.write_text("time,position\n0,0\n0.001,abc\n")
    with pytest.raises(fl.Error) as info:
        fl.load(str(p))
    e = info.value
    assert e.code == "data.not_a_number"
    assert e.file == str(p)
    assert e.row == 3
    assert e.column == "position"
    assert e.value == "abc"
    assert e.key is None and e.option is None
    assert "line 3" in str(e)  # the message is unchanged


def test_missing_file_is_still_a_value_error(tmp_path):
    with pytest.raises(ValueError) as info:
        fl.load(str(tmp_path / "none.csv"))
    assert isinstance(info.value, fl.Error)
    assert info.value.code == "data.file_unreadable"


def test_scenario_unknown_key(tmp_path):
    p = tmp_path / "s.yaml"
    p.write_text("plant: {type: pendulum, m: 1, l: 1, colour: red}\nfriction: {law: coulomb, Fc: 0.1}\nduration: 1\n")
    with pytest.raises(fl.Error) as info:
        fl.Scenario.load(str(p))
    assert info.value.code == "scenario.key_unknown"
    assert info.value.key == "plant.colour"
    assert info.value.file == str(p)


def test_law_file_value(tmp_path):
    p = tmp_path / "law.json"
    p.write_text('{"law": "coulomb", "Fc": "one"}')
    with pytest.raises(fl.Error) as info:
        fl.load_law(str(p))
    assert info.value.code == "scenario.value"
    assert info.value.key == "Fc"


def test_not_utf8_message_does_not_break_the_exception(tmp_path):
    p = tmp_path / "d.csv"
    p.write_bytes(b"time,pos\xe9\n0,0\n0.001,abc\n")
    with pytest.raises(fl.Error) as info:
        fl.load(str(p))
    assert info.value.code == "data.not_a_number"
    assert info.value.row == 3


# Numbers or an error, never both (docs/guarantees.md): figures beyond double precision raise
# frictionlab.Error with code output.not_finite in every identify_* (the library's
# finite_or_error, identify/finite_result.hpp), never a result with inf in it. The scales are
# those the command line found (a torque scaled by 2e158: std(Fc) = inf; a stiffness of 1e157:
# residual_std = inf; a force offset of 1e167: std(M) = inf); a few around each, at least one
# refused, every other one finite.
def _finite_figures(r):
    import math
    for p in r.parameters.values():
        assert math.isfinite(p.value) and not math.isinf(p.std), (r.method, p)
    assert math.isfinite(r.fit.rmse), r.fit.rmse


def _answers_or_not_finite(calls, must_refuse=True):
    refused = []
    for call in calls:
        try:
            r = call()
        except fl.Error as e:
            assert e.code == "output.not_finite", (e.code, str(e))
            assert "is not a finite number" in str(e)
            refused.append(str(e))
            continue
        if r.ok:
            _finite_figures(r)
        else:
            assert "not a finite number (values or scales" not in r.message, r.message
    assert refused or not must_refuse, "none refused as not finite"
    return refused


def test_figures_beyond_double_precision_raise_output_not_finite():
    import os
    import numpy as np
    from conftest import SOURCE_DIR
    examples = os.path.join(SOURCE_DIR, "examples")
    tr = fl.simulate(os.path.join(examples, "craig_motor_trapezoid.yaml"))
    _answers_or_not_finite([lambda s=s: fl.identify_breakaway(tr["time"], s * tr["applied"], tr["velocity"])
                            for s in (1.5e158, 2e158, 2.5e158)])
    pend = fl.simulate(os.path.join(examples, "craig_pendulum_combined.yaml"))
    _answers_or_not_finite([lambda k=k: fl.identify_decay(pend["time"], pend["position"], stiffness=k, inertia=1.0)
                            for k in (1e156, 1e157, 1e158)])
    t = np.arange(2001) * 1e-3
    lugre = fl.simulate({"plant": {"type": "axis", "M": 1.0},
                         "friction": {"law": "lugre", "sigma0": 1e5, "sigma1": 316.22776601683796, "sigma2": 0.4,
                                      "Fc": 1.0, "Fs": 1.5, "vs": 0.001},
                         "input": {"type": "sine", "amplitude": 3.0, "omega": 3.14159},
                         "duration": 2, "output_rate": 1000})
    assert len(lugre["time"]) == len(t)
    _answers_or_not_finite([lambda s=s: fl.identify_lugre(lugre["time"], s * lugre["applied"], lugre["position"], inertia=s)
                            for s in (1e156, 1e160, 1e200)])
    # idim and sweep: a force offset of 1e167 on constant-speed steps (tests/cli/contract_finite.sh).
    rng = np.random.default_rng(3)
    levels = [0.05, 0.2, -0.05, 0.1, -0.2, 0.08, -0.08, 0.15]
    ts = np.arange(8000) * 1e-3
    v = np.repeat(levels, 1000) + 1e-4 * rng.standard_normal(8000)
    f = np.sign(v) * (1 + 0.5 * np.exp(-(v / 0.02) ** 2)) + 0.4 * v + 0.01 * rng.standard_normal(8000)
    q = np.cumsum(v) * 1e-3
    _answers_or_not_finite([lambda o=o: fl.identify_idim(ts, f + o, position=q) for o in (1e166, 1.1746487914836065e167, 1e168)],
                           must_refuse=False)


# A word that is a number that is not finite, as the library's non_finite_word reads one
# (identify/finite_result.hpp): inf, nan, infinity, signed or not, between separators.
_NON_FINITE_WORD = re.compile(r'(?:^|(?<=[\s,;=:()\[\]{}|<>"]))[-+]?(?:inf|infinity|nan)(?=$|[\s,;=:()\[\]{}|<>"])',
                              re.IGNORECASE)


def test_every_method_over_decades_gives_numbers_or_an_error():
    """Numbers or an error, never both, in the words too (docs/guarantees.md): every identify_*
    on records with their force (and the inertia or stiffness with it) or their motion scaled by
    10^e, e from -150 to 150 (a seeded pick of the signal), returns a result whose figures are
    finite and whose JSON holds no inf or nan (decay at a stiffness of 1e90 to 1e155 and lugre on
    a record scaled by 1e100 put "variance inflation nan" in a warning), or raises fl.Error with
    the code of a refusal. The scales that used to say nan give an answer."""
    import os
    import random
    import numpy as np
    from conftest import SOURCE_DIR
    ex = os.path.join(SOURCE_DIR, "examples")
    ramp = fl.simulate(os.path.join(ex, "craig_motor_trapezoid.yaml"))
    pend = fl.simulate(os.path.join(ex, "craig_pendulum_combined.yaml"))
    sine = fl.simulate({"plant": {"type": "axis", "M": 1.0},
                        "friction": {"law": "lugre", "sigma0": 1e5, "sigma1": 316.22776601683796, "sigma2": 0.4,
                                     "Fc": 1.0, "Fs": 1.5, "vs": 0.001},
                        "input": {"type": "sine", "amplitude": 3.0, "omega": 3.14159},
                        "duration": 2, "output_rate": 1000})
    rng = np.random.default_rng(25)
    levels = [0.01, 0.2, -0.05, 0.1, -0.2, 0.02, -0.01, 0.05]
    ts = np.arange(8000) * 1e-3
    v = np.repeat(levels, 1000) + 1e-4 * rng.standard_normal(8000)
    f = np.sign(v) * (1 + 0.5 * np.exp(-(v / 0.02) ** 2)) + 0.4 * v + 0.01 * rng.standard_normal(8000)
    q = np.cumsum(v) * 1e-3
    methods = {
        "idim": lambda sf, sx: fl.identify_idim(ts, sf * f, position=sx * q),
        "sweep": lambda sf, sx: fl.identify_sweep(ts, sf * f, sx * v),
        "auto": lambda sf, sx: fl.identify_auto(ts, sf * f, position=sx * q),
        "breakaway": lambda sf, sx: fl.identify_breakaway(ramp["time"], sf * ramp["applied"], sx * ramp["velocity"]),
        "decay": lambda sf, sx: fl.identify_decay(pend["time"], sx * pend["position"], stiffness=sf, inertia=sf),
        "lugre": lambda sf, sx: fl.identify_lugre(sine["time"], sf * sine["applied"], sx * sine["position"], inertia=sf),
    }
    pick = random.Random(25)
    seen = {m: [] for m in methods}
    for e in range(-150, 151, 30):
        for name, call in methods.items():
            if name in ("lugre", "auto") and e % 60:  # the slow ones on every other decade
                continue
            which = pick.randrange(3)  # 0: the force, 1: the motion, 2: both
            sf, sx = (10.0 ** e if which != 1 else 1.0), (10.0 ** e if which != 0 else 1.0)
            what = f"{name}, force x {sf:g}, motion x {sx:g}"
            try:
                r = call(sf, sx)
            except fl.Error as err:
                assert err.code in ("output.not_finite", "data.no_answer") or err.code.startswith(("data.", "option.", "input.")), \
                    (what, err.code, str(err))
                seen[name].append("refused")
                continue
            text = r.to_json()
            assert not _NON_FINITE_WORD.search(text), (what, _NON_FINITE_WORD.search(text), text[:2000])
            if r.ok:
                _finite_figures(r)
            seen[name].append("ok" if r.ok else "error")
    for name, outcomes in seen.items():
        assert "ok" in outcomes, (name, outcomes)
    # The scales that said nan in a warning give an answer now.
    for k in (1e90, 1e120, 1e155):
        r = fl.identify_decay(pend["time"], pend["position"], stiffness=k, inertia=1.0)
        assert r.ok and not _NON_FINITE_WORD.search(r.to_json()), r.to_json()
    r = fl.identify_lugre(sine["time"], 1e100 * sine["applied"], sine["position"], inertia=1e100)
    assert r.ok and not _NON_FINITE_WORD.search(r.to_json()), r.to_json()


def test_data_without_an_answer_is_still_a_result():
    # Only figures beyond double precision raise; no motion stays status 'error' (docs/python.md).
    import numpy as np
    t = np.arange(200) * 0.01
    r = fl.identify_breakaway(t, t * 1e-4, np.zeros(200))
    assert not r.ok and "no motion" in r.message


def test_work_beyond_the_budget_is_refused_before_it_starts():
    """The sizes of the Ctrl-C findings (plan(runs=10**9), a 10**6-point map, identify_lugre on
    10**7 samples) are refused by the work budget before any run, with code budget.work
    (tests/python/test_cancellation.py interrupts the sizes within it)."""
    import os
    import numpy as np
    from conftest import SOURCE_DIR
    ex = os.path.join(SOURCE_DIR, "examples")
    t = np.arange(10**7) * 1e-3
    calls = [lambda: fl.plan("breakaway", os.path.join(ex, "plan", "craig_motor_prior.json"),
                             os.path.join(ex, "craig_motor_trapezoid.yaml"), runs=10**9),
             lambda: fl.analyze_map(os.path.join(ex, "map_pid_hunting.yaml"),
                                    {"friction.Fs": (1.5, 2.5, 1000), "controller.Kp": (3.0, 4.0, 1000)}),
             lambda: fl.identify_lugre(t, np.sin(t), 0.01 * np.sin(t - 0.3), inertia=1.0)]
    for call in calls:
        with pytest.raises(fl.Error) as info:
            call()
        assert info.value.code == "budget.work", str(info.value)


def test_lugre_on_ten_million_samples_is_refused_before_its_arrays_are_read():
    """identify_lugre's work budget comes from the arrays' lengths before they are converted and
    checked (their copies took seconds; the refusal came only after them): a NaN in the last
    sample, which the check of the arrays names, is not reached; the refusal names the samples,
    the steps, the budget and how to raise it."""
    import numpy as np
    n = 10**7
    t = np.arange(n) * 1e-3
    force = np.sin(t)
    force[-1] = np.nan
    with pytest.raises(fl.Error) as info:
        fl.identify_lugre(t, force, 0.01 * np.sin(t - 0.3), inertia=1.0)
    message = str(info.value)
    assert info.value.code == "budget.work", message
    assert "10000000 samples" in message and "2.04e+09 simulation steps" in message, message
    assert "--budget FACTOR" in message and "frictionlab.set_budget_factor(FACTOR)" in message, message
    assert info.value.option == "--substeps", message


def test_set_budget_factor_raises_and_lowers_the_budget_as_the_command_lines_budget():
    """fl.set_budget_factor is the command line's --budget: a small LuGre record that the default
    budget takes is refused at a factor of 1e-6 (its 1000 work units per sample exceed 1e3 units),
    and taken again at 1; a factor out of range is refused naming --budget."""
    import numpy as np
    t = np.arange(2000) * 1e-3
    assert fl.budget_factor() == 1.0
    try:
        fl.set_budget_factor(1e-6)
        assert fl.budget_factor() == 1e-6
        with pytest.raises(fl.Error) as info:
            fl.identify_lugre(t, np.sin(t), 0.01 * np.sin(t - 0.3), inertia=1.0)
        assert info.value.code == "budget.work", str(info.value)
    finally:
        fl.set_budget_factor(1.0)
    with pytest.raises(fl.Error) as info:
        fl.set_budget_factor(0.0)
    assert info.value.code == "option.out_of_range" and info.value.option == "--budget", str(info.value)
