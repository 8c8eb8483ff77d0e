"""frictionlab.validate (closed loop on EMPS) and frictionlab.identify_lugre from Python."""
import math
import os

import pytest

import frictionlab as fl

SRC = os.environ.get("FRICTIONLAB_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EMPS = os.path.join(SRC, "data", "emps")


def emps(name):
    d = fl.load(os.path.join(EMPS, name))
    return d, d["t"], d["qm"], d["gtau"] * d["vir"]


def test_validate_emps_closed_loop_matches_published_position_and_velocity():
    d, t, q, f = emps("DATA_EMPS.mat")
    model = fl.identify_idim(t, f, position=q, source=d)
    p, tp, qp, fp = emps("DATA_EMPS_PULSES.mat")
    r = fl.validate(model, p, os.path.join(SRC, "examples", "emps_closed_loop.yaml"), time=tp, position=qp, force=fp)
    errors = r.validation.signal_errors_percent
    # Published closed-loop errors on the pulses file (EMPS README), with the 10 % margin.
    assert errors["position"] <= 1.1 * 0.0080
    assert errors["velocity"] <= 1.1 * 0.479
    assert set(errors) == {"position", "velocity", "acceleration", "force"}


def test_validate_needs_a_simulable_law():
    d, t, q, f = emps("DATA_EMPS.mat")
    model = fl.identify_idim(t, f, position=q, terms=["inertia", "asymmetric", "stribeck"], input_delay=1)
    assert model.law is None  # negative Stribeck term: not a law
    with pytest.raises(ValueError):
        fl.validate(model, d, os.path.join(SRC, "examples", "emps_closed_loop.yaml"), time=t, position=q, force=f)


def lugre_record():
    times, values = [0.0, 2.0, 4.0], [0.0, 1.425, 0.0]
    for i in range(1, 301):
        tt = 4.0 + 0.02 * i
        times.append(round(tt, 6))
        values.append(3.0 * math.sin(math.pi * (tt - 4.0)))
    scenario = {
        "plant": {"type": "axis", "M": 1.0},
        "friction": {"law": "lugre", "sigma0": 1e5, "sigma1": math.sqrt(1e5), "sigma2": 0.4, "Fc": 1.0, "Fs": 1.5,
                     "vs": 0.001},
        "input": {"type": "table", "times": times, "values": values},
        "duration": 10.0,
        "output_rate": 1000.0,
    }
    return fl.simulate(scenario)


def test_identify_lugre_recovers_canudas_table_one():
    tr = lugre_record()
    r = fl.identify_lugre(tr["time"], tr["applied"], tr["position"], inertia=1.0)
    assert r.ok, r.message
    rel_tol = 0.05  # the acceptance bound for sigma0 and sigma1
    assert abs(r["sigma0"] - 1e5) <= rel_tol * 1e5
    assert abs(r["sigma1"] - math.sqrt(1e5)) <= rel_tol * math.sqrt(1e5)
    assert r.parameters["sigma0"].unit == "N/m"


def test_identify_lugre_refuses_a_bad_inertia():
    tr = lugre_record()
    with pytest.raises(ValueError, match="--inertia"):
        fl.identify_lugre(tr["time"], tr["applied"], tr["position"], inertia=0.0)
