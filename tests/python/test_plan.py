"""frictionlab.plan: the seed's trapezoid on the seed's motor, the profile and the prediction as
a dict, undetermined parameters, bad input as ValueError / ArgumentTypeError naming the key."""
import math

import numpy as np
import pytest

import frictionlab as fl


def test_breakaway_plan_of_the_lectures_motor(source_dir, tmp_path):
    out = tmp_path / "ramp.csv"
    r = fl.plan("breakaway", source_dir / "examples/plan/craig_motor_prior.json",
                source_dir / "examples/craig_motor_trapezoid.yaml",
                noise={"current": 2e-4, "velocity": 0.5}, runs=4, output=out)
    assert r["status"] == "ok"
    prof = r["profile"]
    assert prof["columns"] == ["time_s", "current_A"]
    assert isinstance(prof["time"], np.ndarray) and prof["time"].shape == prof["command"].shape
    assert prof["command"].max() == pytest.approx(1.4 * 0.0015 / 0.0141, rel=1e-12)
    assert out.read_text().splitlines()[0] == "time_s,current_A"
    for name in ("Fs", "Fc", "Fv"):
        p = r["prediction"]["parameters"][name]
        assert 0 < p["std"] < 0.05 * p["prior"]
    with pytest.raises(ValueError, match="exists"):
        fl.plan("breakaway", source_dir / "examples/plan/craig_motor_prior.json",
                source_dir / "examples/craig_motor_trapezoid.yaml", runs=2, output=out)


def test_sweep_plan_names_undetermined_parameters(source_dir):
    r = fl.plan("sweep", source_dir / "examples/plan/virgala_motor_prior.json",
                source_dir / "examples/virgala_motor_sweep.yaml",
                limits={"speed": 300, "min_speed": 6}, noise={"current": 1e-3}, speeds=5, runs=2)
    # Fs with vs and delta: with vs free and no speed below it, its information is singular.
    assert sorted(r["undetermined"]) == ["Fs", "delta", "vs"]
    assert r["prediction"]["parameters"]["vs"]["std"] is None
    assert r["prediction"]["parameters"]["vs"]["std_a_priori"] is None
    assert math.isfinite(r["prediction"]["parameters"]["Fc"]["std"])
    assert 0 < r["prediction"]["parameters"]["Fc"]["std_a_priori"] < 0.05 * 0.002


def test_plan_bad_input(source_dir):
    prior = source_dir / "examples/plan/craig_motor_prior.json"
    motor = source_dir / "examples/craig_motor_trapezoid.yaml"
    with pytest.raises(ValueError, match=r"--limits|limits current = 0.1 A"):
        fl.plan("breakaway", prior, motor, limits={"current": 0.1}, runs=2)
    with pytest.raises(ValueError, match="unknown key 'amps'"):
        fl.plan("breakaway", prior, motor, limits={"amps": 1}, runs=2)
    with pytest.raises(fl.ArgumentTypeError, match="plan: argument noise"):
        fl.plan("breakaway", prior, motor, noise=[1, 2], runs=2)
    with pytest.raises(ValueError, match="expected one of breakaway, sweep, idim, lugre"):
        fl.plan("ramp", prior, motor)


def test_load_steps_plan_returns_the_load_column(source_dir, tmp_path):
    out = tmp_path / "load_steps.csv"
    r = fl.plan("load-steps", source_dir / "examples/plan/emps_effects_prior.json",
                source_dir / "examples/plan/axis_position_loop.yaml",
                limits={"travel": 0.2, "force": 1500}, noise={"force": 2}, load=200, runs=2, output=out)
    prof = r["profile"]
    assert prof["columns"] == ["time_s", "position_m", "load_N"]
    assert prof["load"].shape == prof["time"].shape
    assert sorted(set(prof["load"].tolist())) == [0.0, 100.0, 200.0]
    assert out.read_text().splitlines()[0] == "time_s,position_m,load_N"
    assert 0 < r["prediction"]["parameters"]["mu_load"]["std_a_priori"] < 0.01
    with pytest.raises(ValueError, match="--load: a load-steps plan needs the largest load"):
        fl.plan("load-steps", source_dir / "examples/plan/emps_effects_prior.json",
                source_dir / "examples/plan/axis_position_loop.yaml", runs=2)
