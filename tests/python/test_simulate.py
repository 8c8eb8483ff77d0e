"""simulate() from a YAML file, a dict and a Scenario; the Trajectory; reference figures; errors."""
import numpy as np
import pytest

import frictionlab as fl

AXIS = {"plant": {"type": "axis", "M": 1.0}, "friction": {"law": "coulomb", "Fc": 1.0},
        "input": {"type": "constant", "value": 2.0}, "duration": 1.0, "output_rate": 100}


def test_dict_scenario_exact_solution():
    # M a = 2 - 1: x = t^2 / 2 exactly (hybrid stick/slip engine, sliding from the first instant).
    tr = fl.simulate(AXIS)
    assert isinstance(tr, fl.Trajectory) and len(tr) == 101
    np.testing.assert_allclose(tr["position"], tr["time"] ** 2 / 2, rtol=0, atol=1e-9)  # CVODE rtol 1e-8 (scenario default)
    np.testing.assert_allclose(tr["friction"][1:], 1.0, rtol=1e-12)
    assert list(tr) == ["time", "position", "velocity", "friction", "applied", "current", "voltage", "reference",
                        "stuck"]
    d = fl.simulate(AXIS, as_dict=True)
    assert isinstance(d, dict) and set(d) == set(tr.keys()) and np.array_equal(d["velocity"], tr["velocity"])
    assert dict(tr).keys() == d.keys()
    assert tr.to_csv().startswith("time,position,velocity,friction,applied,current,voltage,reference,stuck\n")


def test_overrides_and_scenario_object():
    sc = fl.Scenario(AXIS)
    assert (sc.plant, sc.law.name, sc.duration) == ("axis", "coulomb", 1.0)
    # The plant says how it moves (the units of its results and figures); a pendulum turns.
    assert sc.axis == "linear"
    assert fl.Scenario(dict(AXIS, plant={"type": "pendulum", "m": 1.0, "l": 0.5})).axis == "rotary"
    tr = fl.simulate(sc, law={"law": "coulomb", "Fc": 0.5}, duration=2.0, output_rate=10)
    assert len(tr) == 21 and tr["velocity"][-1] == pytest.approx(1.5 * 2.0, rel=1e-9)
    assert sc.law.name == "coulomb" and sc.law.parameters["Fc"] == 1.0  # the passed scenario is not changed
    # Applied force below the breakaway level: it never moves.
    still = fl.simulate(sc, law=fl.FrictionLaw({"law": "coulomb", "Fc": 3.0}))
    assert np.all(still["position"] == 0) and np.all(still["stuck"] == 1)


def test_craig_trapezoid_switch_times(example):
    # examples/craig_motor_trapezoid.yaml: breakaway when Kt i = Fs on the 0.003 A/s ramp (35.46 s; docs/reference-results.md
    # rounds to 35.47), stop at 102.0 s (docs/reference-results.md).
    tr = fl.simulate(example("craig_motor_trapezoid"))
    kinds = [s["kind"] for s in tr.switches]
    assert kinds == ["breakaway", "stick"]
    assert tr.switches[0]["time"] == pytest.approx(0.0015 / 0.0141 / 0.003, rel=1e-6)
    assert tr.switches[1]["time"] == pytest.approx(102.0, abs=0.05)
    assert tr.stats["solver"] == "hybrid"
    assert tr.stats["jacobian_rhs_evaluations"] > 0  # the hybrid engine's Newton matrices: difference quotients
    assert tr.law_state.shape == (0, len(tr))


def test_canudas_stick_slip_lugre(example):
    # docs/reference-results.md (tight LSODA run): period 6.36 s, peak slip velocity 0.370 m/s.
    tr = fl.simulate(example("canudas_stick_slip"))
    assert tr.law_state.shape == (1, len(tr))
    # The stiff engine on the spring-base plant's analytic Jacobian: no difference quotients.
    assert tr.stats["solver"] == "stiff" and tr.stats["jacobian_rhs_evaluations"] == 0
    assert tr.stats["rhs_evaluations"] > tr.stats["steps"] > 0
    s = fl.detect_stick_slip(tr)
    assert s.period == pytest.approx(6.36, abs=0.01)
    assert s.peak_slip_velocity == pytest.approx(0.370, abs=0.001)


def test_scenario_errors(tmp_path, example):
    with pytest.raises(ValueError, match="scenario: missing 'duration'"):
        fl.simulate({k: v for k, v in AXIS.items() if k != "duration"})
    with pytest.raises(ValueError, match=r"scenario: duration: -1 must be > 0 \(s\)"):
        fl.simulate(dict(AXIS, duration=-1))
    with pytest.raises(ValueError, match="unknown plant type 'rocket'"):
        fl.simulate(dict(AXIS, plant={"type": "rocket"}))
    with pytest.raises(ValueError, match="coulomb: Fc = -1 must be >= 0"):
        fl.simulate(AXIS, law={"law": "coulomb", "Fc": -1})
    with pytest.raises(ValueError, match="nowhere.yaml: cannot open the scenario file"):
        fl.simulate(tmp_path / "nowhere.yaml")
    bad = tmp_path / "bad.yaml"
    bad.write_text("plant: [unclosed\n")
    with pytest.raises(ValueError, match="bad.yaml: not valid YAML at line"):
        fl.simulate(bad)
    with pytest.raises(ValueError, match="scenario: expected a scenario file path, a dict or a Scenario, got int"):
        fl.simulate(3)
    with pytest.raises(ValueError, match="expected a number, text, list or dict, got object"):
        fl.simulate(dict(AXIS, duration=object()))
    with pytest.raises(KeyError, match="no column 'speed'"):
        fl.simulate(AXIS)["speed"]


def test_backlash_impact_from_a_dict():
    # The motor (0.5 kg, 2 N) crosses half the 20 mm play in sqrt(0.005) s and strikes the stuck
    # load (1.5 kg): a plastic impact, reported as a plant event and an `impact` switch.
    sc = dict(AXIS, plant={"type": "axis", "M": 1.5, "backlash": {"width": 0.02, "motor_inertia": 0.5}},
              friction={"law": "static-coulomb-viscous", "Fs": 1.2, "Fc": 1.0, "Fv": 0.0})
    tr = fl.simulate(sc)
    t1 = np.sqrt(0.005)
    assert [e["index"] for e in tr.plant_events] == [0]
    assert tr.plant_events[0]["time"] == pytest.approx(t1, rel=1e-7)  # CVODE's root finder at rtol 1e-8
    assert [s["kind"] for s in tr.switches] == ["impact"]
    with pytest.raises(ValueError, match="backlash.width = -1 must be > 0"):
        fl.simulate(dict(sc, plant={"type": "axis", "M": 1.5, "backlash": {"width": -1, "motor_inertia": 0.5}}))
