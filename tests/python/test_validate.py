"""frictionlab.validate (closed loop on EMPS), validate_xy (a two-axis table on a circular test) and
frictionlab.identify_lugre from Python."""
import math
import os

import numpy as np
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


# ---- validate_xy: a two-axis table's models against a circular-test log -------------------------

def xy_machine_log(source_dir, tmp_path):
    """examples/xy_circle.yaml with x's friction 10 % higher and 1 kg more on its carriage, as the
    machine; its run with 0.2 um encoder noise and 0.5 um steps, as the log."""
    text = (source_dir / "examples" / "xy_circle.yaml").read_text()
    machine = text.replace("Fc: 25, Fs: 40, vs: 0.002, delta: 2, Fv: 150", "Fc: 27.5, Fs: 44, vs: 0.002, delta: 2, Fv: 165")
    machine = machine.replace("mass: 15 ", "mass: 16 ")
    assert machine != text
    path = tmp_path / "machine.yaml"
    path.write_text(machine)
    tr = fl.simulate(str(path))
    rng = np.random.default_rng(11)
    enc = lambda q: 0.5e-6 * np.round((q + rng.normal(0, 0.2e-6, q.size)) / 0.5e-6)  # noqa: E731
    return tr["time"], enc(tr["x.position"]), enc(tr["y.position"]), tr["x.drive"], tr["y.drive"]


def test_validate_xy_with_models_identified_from_the_log(source_dir, tmp_path):
    t, x, y, fx, fy = xy_machine_log(source_dir, tmp_path)
    # Each axis identified from the log itself (inertia, Coulomb, offset), as a user would: a
    # circle at 20 mm/s holds too little viscous information for an Fv (it comes out negative).
    terms = ["inertia", "coulomb", "offset"]
    models = {a: fl.identify_idim(t, f, position=q, terms=terms) for a, q, f in (("x", x, fx), ("y", y, fy))}
    for a, m in models.items():
        assert m.ok and m.law is not None, (a, m.message)
    scenario = str(source_dir / "examples" / "xy_circle.yaml")
    r, measured, simulated = fl.validate_xy(models, scenario, time=t, x=x, y=y, x_force=fx, y_force=fy)
    errors = r.validation.signal_errors_percent
    assert set(errors) == {f"{a}.{s}" for a in "xy" for s in ("position", "velocity", "acceleration", "force")}
    # Closed loop at 40 Hz: the position follows the reference whatever the friction model; the
    # identified Coulomb-viscous models miss the Stribeck breakaway, not the path (< 0.1 % of 10 mm).
    assert errors["x.position"] < 0.1 and errors["y.position"] < 0.1, errors
    contour = r.validation.sections["contour"]
    assert contour["measured"]["max_quadrant_glitch_m"] == pytest.approx(max(abs(g) for g in measured.quadrant_glitch_m))
    assert len(contour["simulated"]["quadrant_glitch_m"]) == 4
    assert measured.radius == pytest.approx(0.01, rel=1e-9) and simulated.radius == measured.radius
    # The log shows the glitches (tens of um); the difference block is simulated less measured.
    assert max(abs(g) for g in measured.quadrant_glitch_m) > 10e-6
    assert contour["difference"]["roundness_m"] == pytest.approx(simulated.roundness_m - measured.roundness_m)
    assert r["x.M"] == pytest.approx(models["x"]["M"])
    assert r.diagnostics.numbers["roundness_m"] == pytest.approx(measured.roundness_m)


@pytest.fixture(scope="module")
def idim_ok(emps):
    r = fl.identify_idim(emps["t"], emps["gtau"] * emps["vir"], position=emps["qm"], source=emps)
    assert r.ok, r.message
    return r


def test_validate_xy_bad_input(source_dir, tmp_path, idim_ok):
    t, x, y, fx, fy = xy_machine_log(source_dir, tmp_path)
    scenario = str(source_dir / "examples" / "xy_circle.yaml")
    with pytest.raises(fl.ArgumentTypeError, match="validate_xy: argument models: expected a dict"):
        fl.validate_xy(idim_ok, scenario, time=t, x=x, y=y)
    with pytest.raises(ValueError, match="the xy-table has no axis 'z'; expected x or y"):
        fl.validate_xy({"z": idim_ok}, scenario, time=t, x=x, y=y)
    with pytest.raises(fl.ArgumentTypeError, match=r"validate_xy: argument models\['x'\]: expected the Result"):
        fl.validate_xy({"x": 1.0}, scenario, time=t, x=x, y=y)
    with pytest.raises(ValueError, match="validate_xy: arguments time .6284 samples. and y_force .6283 samples. differ in length"):
        fl.validate_xy({}, scenario, time=t, x=x, y=y, y_force=fy[:-1])
    one_axis = str(source_dir / "examples" / "emps_closed_loop.yaml")
    with pytest.raises(ValueError, match=r"models named by axis \(x\) need a two-axis plant"):
        fl.validate_xy({"x": idim_ok}, one_axis, time=t, x=x, y=y)
