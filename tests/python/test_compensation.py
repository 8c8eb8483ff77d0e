"""The `compensation` block in scenario dicts (the same as in scenario files): what it builds, the
lecture's hunting case settled by the LuGre observer, model files relative to base_dir, errors."""
import json

import numpy as np
import pytest

import frictionlab as fl

LUGRE = {"law": "lugre", "sigma0": 1.0e5, "sigma1": 316.22776601683796, "sigma2": 0.4, "Fc": 1.0, "Fs": 1.5,
         "vs": 0.001}


def hunting(compensation=None):
    """examples/canudas_pid_hunting.yaml as a dict, with an optional compensation block."""
    controller = {"loop": "position", "Kp": 3.0, "Ki": 4.0, "Kd": 6.0}
    if compensation is not None:
        controller["compensation"] = compensation
    return {"plant": {"type": "axis", "M": 1.0}, "friction": dict(LUGRE), "controller": controller,
            "input": {"type": "step", "value": 1.0}, "duration": 100, "output_rate": 100,
            "solver": {"max_step": 1e-3}}


def late_error(tr):
    return np.max(np.abs(tr["position"][tr["time"] >= 50.0] - 1.0))  # m, target 1 m


def test_lugre_observer_dict_ends_the_hunting():
    sc = fl.Scenario(hunting({"type": "lugre-observer", "gain": 0.01}))
    assert sc.compensation == "lugre-observer"
    assert fl.Scenario(hunting()).compensation is None
    # Plain: slips of centimetres keep coming; compensated: ~1e-14 m measured with steps <= 1 ms;
    # the bound leaves room for other solver versions, six decades below the hunting.
    assert late_error(fl.simulate(hunting())) > 3e-2
    assert late_error(fl.simulate(sc)) < 1e-8


def test_model_file_relative_to_base_dir(tmp_path):
    (tmp_path / "model.json").write_text(json.dumps(LUGRE))
    spec = hunting({"type": "feedforward", "model": "model.json", "band": 0.002})
    assert fl.Scenario(spec, base_dir=tmp_path).compensation == "feedforward"
    with pytest.raises(ValueError, match=r"controller\.compensation\.model: .*model\.json"):
        fl.Scenario(spec, base_dir=tmp_path / "elsewhere")


def test_xy_table_per_axis():
    axis = {"mass": 10, "friction": {"law": "coulomb", "Fc": 5}}
    spec = {"plant": {"type": "xy-table", "compensation": {"type": "feedforward"},
                      "axes": {"x": dict(axis), "y": dict(axis, compensation="none")},
                      "controller": {"Kp": 2e5, "Ki": 1e6, "Kd": 1500}},
            "input": {"type": "circle", "radius": 0.01, "feed": 0.02}}
    assert fl.Scenario(spec).compensation == {"x": "feedforward", "y": None}


def test_bad_blocks_name_the_key():
    with pytest.raises(ValueError, match=r"scenario: controller\.compensation\.friction: lugre-observer"):
        fl.Scenario(hunting({"type": "lugre-observer", "friction": {"law": "coulomb", "Fc": 1.0}}))
    with pytest.raises(ValueError, match=r"controller\.compensation\.type: unknown compensation type 'lugre'"):
        fl.Scenario(hunting({"type": "lugre"}))
    with pytest.raises(ValueError, match=r"controller\.compensation: .*'dead_band'"):
        fl.Scenario(hunting({"type": "feedforward", "dead_band": 0.001}))


def test_emps_loop_compensation_read_and_set(example):
    compensated = fl.Scenario.load(example("emps_closed_loop_compensated"))
    plain = fl.Scenario.load(example("emps_closed_loop"))
    assert compensated.compensation == "feedforward"
    assert plain.compensation is None
    # The file's block set from Python (the scenario's own law, the same band): the same loop, so
    # the same trajectory to the last bit (one code path builds both).
    plain.compensation = {"type": "feedforward", "band": 0.001}
    assert plain.compensation == "feedforward"
    a = fl.simulate(compensated, duration=2.0)
    b = fl.simulate(plain, duration=2.0)
    np.testing.assert_array_equal(a["position"], b["position"])
    np.testing.assert_array_equal(a["voltage"], b["voltage"])
    # Removed again: the plain loop's trajectory, which the compensation changes.
    plain.compensation = None
    assert plain.compensation is None
    c = fl.simulate(plain, duration=2.0)
    np.testing.assert_array_equal(c["position"], fl.simulate(fl.Scenario.load(example("emps_closed_loop")),
                                                             duration=2.0)["position"])
    assert np.any(c["position"] != a["position"])


def test_compensation_set_checks_its_value():
    sc = fl.Scenario(hunting())
    with pytest.raises(ValueError, match=r"Scenario\.compensation: compensation feedforward has no parameter 'gain'"):
        sc.compensation = {"type": "feedforward", "gain": 1.0}
    with pytest.raises(ValueError, match=r"Scenario\.compensation: feedforward: band = -1 must be > 0"):
        sc.compensation = {"type": "feedforward", "band": -1.0}
    with pytest.raises(ValueError, match=r"Scenario\.compensation: lugre-observer: law = coulomb must be lugre"):
        fl.Scenario(dict(hunting(), friction={"law": "coulomb", "Fc": 1.0})).compensation = "lugre-observer"
    assert sc.compensation is None  # a refused value changes nothing
    sc.compensation = "lugre-observer"
    assert sc.compensation == "lugre-observer"
    axis = {"plant": {"type": "axis", "M": 1.0}, "friction": {"law": "coulomb", "Fc": 0.5},
            "input": {"type": "constant", "value": 1.0}, "duration": 1.0,
            "output_rate": 10}
    with pytest.raises(ValueError, match=r"Scenario\.compensation: plant 'axis' has no controller"):
        fl.Scenario(axis).compensation = "feedforward"


def test_xy_table_compensation_set_per_axis():
    axis = {"mass": 10, "friction": {"law": "coulomb", "Fc": 5}}
    spec = {"plant": {"type": "xy-table", "axes": {"x": dict(axis), "y": dict(axis)},
                      "controller": {"Kp": 2e5, "Ki": 1e6, "Kd": 1500}},
            "input": {"type": "circle", "radius": 0.01, "feed": 0.02}}
    sc = fl.Scenario(spec)
    assert sc.compensation == {"x": None, "y": None}
    sc.compensation = "feedforward"
    assert sc.compensation == {"x": "feedforward", "y": "feedforward"}
    sc.compensation = {"y": None}
    assert sc.compensation == {"x": "feedforward", "y": None}
