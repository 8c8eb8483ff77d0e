"""Load, temperature and position effects on a friction law: the conditioned calls, the typed
errors of bad parameters, and a scenario run with a load and a thermal model."""
import math
import os
import sys

import numpy as np
import pytest

import frictionlab as fl

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "rigs"))
from load_sweep_log import load_sweep  # noqa: E402  (the rig made with numpy alone)

STRIBECK = {"law": "stribeck", "Fc": 1.0, "Fs": 1.5, "vs": 0.01, "Fv": 0.4}

# Sums and products of a few doubles: a few roundings at most.
REL = 1e-14


def test_load_raises_both_levels():
    law = fl.FrictionLaw({**STRIBECK, "mu_load": 0.05})
    assert law.effects == {"mu_load": 0.05}
    pos, neg = law.breakaway_at(load=-20.0)
    assert pos == pytest.approx(2.5, rel=REL) and neg == pytest.approx(2.5, rel=REL)
    F = law.sliding_at(np.array([1.0, -1.0]), load=20.0)
    np.testing.assert_allclose(F, [2.4, -2.4], rtol=REL)
    # Without conditions it is the plain law.
    assert law.sliding_at(0.3) == law.sliding(0.3)


def test_temperature_moves_viscous_and_coulomb():
    law = fl.FrictionLaw({**STRIBECK, "T_ref": 20.0, "Fv_per_K": -0.004, "Fc_per_K": -0.002})
    # 50 K above T_ref: Fv 0.4 -> 0.2, Fc 1 -> 0.9
    assert law.sliding_at(1.0, temperature=70.0) == pytest.approx(1.1, rel=1e-13)
    assert law.breakaway_at(temperature=70.0)[0] == pytest.approx(1.4, rel=1e-13)


def test_ripple_holds_a_stuck_contact_against_applied_minus_ripple():
    law = fl.FrictionLaw({**STRIBECK, "ripple_period": 0.004, "ripple_a": [0.2], "ripple_b": [0.1]})
    q = 0.0013
    r = 0.2 * math.sin(2 * math.pi * q / 0.004) + 0.1 * math.cos(2 * math.pi * q / 0.004)
    assert law.ripple(q) == pytest.approx(r, rel=REL)
    assert law.force_at(0.0, r + 1.4, position=q) == r + 1.4  # held
    assert law.force_at(0.0, r + 1.6, position=q) == pytest.approx(r + 1.5, rel=REL)  # beyond Fs
    assert fl.FrictionLaw(law.to_dict()) == law


def test_ripple_by_table_interpolates_over_one_period():
    table = {"ripple_period": 0.004, "ripple_position": [0.0, 0.001, 0.0025, 0.004], "ripple_force": [0.2, -0.3, 0.1, 0.2]}
    law = fl.FrictionLaw({**STRIBECK, **table})
    assert law.effects == table
    assert law.ripple(0.0005) == pytest.approx(-0.05, abs=1e-12)  # halfway along the first row pair
    assert law.ripple(0.0005 - 0.004 * 3) == pytest.approx(-0.05, abs=1e-12)  # periodic
    assert law.force_at(0.0, -0.05 + 1.4, position=0.0005) == pytest.approx(-0.05 + 1.4, abs=1e-12)  # held
    assert fl.FrictionLaw(law.to_dict()) == law
    with pytest.raises(fl.Error) as info:
        fl.FrictionLaw({**STRIBECK, **table, "ripple_position": [0.0, 0.001, 0.001, 0.004]})
    assert info.value.code == "law.parameter" and info.value.key == "ripple_position[2]"
    assert "strictly increasing" in str(info.value)


@pytest.mark.parametrize(
    "extra, key",
    [
        ({"mu_load": -0.1}, "mu_load"),
        ({"ripple_period": 0.0, "ripple_a": [0.1]}, "ripple_period"),
        ({"ripple_period": -2.0, "ripple_a": [0.1]}, "ripple_period"),
        ({"T_ref": 20.0, "Fv_per_K": -0.004, "T_max": 130.0}, "Fv_per_K"),
        ({"mu_load_static": 0.01, "mu_load_coulomb": 0.02}, "mu_load_static"),
    ],
)
def test_bad_effect_parameters_raise_a_typed_error_naming_them(extra, key):
    with pytest.raises(fl.Error) as info:
        fl.FrictionLaw({**STRIBECK, **extra})
    assert info.value.code == "law.parameter"
    assert info.value.key == key
    assert key in str(info.value)


def test_temperature_outside_the_range_names_the_bound_and_the_temperature():
    law = fl.FrictionLaw({**STRIBECK, "T_ref": 20.0, "Fv_per_K": -0.004, "T_max": 100.0})
    with pytest.raises(fl.Error) as info:
        law.sliding_at(1.0, temperature=101.0)
    assert info.value.key == "T_max" and "101" in str(info.value)


def test_scenario_with_a_falling_load_and_a_thermal_model(tmp_path):
    # Held by 1.5 + 0.1 (10 - t) against 2.2 N: breaks loose at t = 3 s; the contact then warms.
    p = tmp_path / "s.yaml"
    p.write_text(
        "plant: {type: axis, M: 1.0}\n"
        "friction: {law: stribeck, Fc: 1, Fs: 1.5, vs: 0.01, Fv: 0.1, mu_load: 0.1, T_ref: 20, Fv_per_K: -0.0005}\n"
        "environment:\n"
        "  load: {type: ramp, initial: 10, rate: -1}\n"
        "  thermal: {T_ambient: 20, tau: 10, R: 5}\n"
        "input: {type: constant, value: 2.2}\n"
        "duration: 5\n"
    )
    traj = fl.simulate(str(p))
    assert "load" in traj.keys() and "temperature" in traj.keys()
    t = np.asarray(traj["time"])
    stuck = np.asarray(traj["stuck"])
    assert np.all(stuck[t < 2.99] == 1.0) and np.all(stuck[t > 3.01] == 0.0)
    np.testing.assert_allclose(np.asarray(traj["load"]), 10.0 - t, rtol=0, atol=1e-12)
    T = np.asarray(traj["temperature"])
    assert np.all(T[t < 3.0] == 20.0)  # no power while stuck
    assert T[-1] > 20.5  # sliding friction heats it


def test_c_export_carries_load_terms_and_refuses_a_dynamic_law_with_them():
    # A static law's load term becomes an argument of PREFIX_friction_at (N or N m).
    text = fl.export_c({**STRIBECK, "mu_load": 0.05})
    assert "friction_friction_at(double v, double load)" in text and "`load` in N" in text
    # A dynamic law's state update runs on fixed levels: refused saying why, not dropped.
    with pytest.raises(fl.Error) as info:
        fl.export_c({"law": "lugre", "sigma0": 1e5, "sigma1": 316.2, "sigma2": 0.4, "Fc": 1, "Fs": 1.5, "vs": 0.001,
                     "mu_load": 0.05})
    assert info.value.code == "law.parameter" and "fixed levels" in str(info.value)
    assert fl.export_c(STRIBECK).startswith("/* Friction law 'stribeck'")  # the plain law still exports


def test_sweep_fits_mu_load_from_a_load_array():
    t, f, v, load = load_sweep((10.0, 40.0, 80.0), 3)
    r = fl.identify_sweep(t, f, v, model="coulomb-viscous", load=load)
    assert r.ok, r.message
    # 24 levels of 1.2 s each with 2 mN m of noise: within 1 %.
    assert r["mu_load"] == pytest.approx(0.01, rel=0.01)
    assert r["Fc"] == pytest.approx(0.1, rel=0.01)
    assert r.law.effects == {"mu_load": r["mu_load"]}
    pts = fl.sweep_points(t, f, v, load=load)
    assert len(pts["load"]) == 24 and pts["load"][0] == pytest.approx(10.0, abs=0.1)
    with pytest.raises(ValueError, match="load"):
        fl.identify_sweep(t, f, v, load=load[:-1])
