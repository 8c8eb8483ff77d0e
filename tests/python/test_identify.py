"""Identification from Python: EMPS idim against the C++ figures, breakaway / sweep / decay on
simulated experiments with known parameters, the Result API, and the error cases."""
import json
import math
import re

import numpy as np
import pytest

import frictionlab as fl
from conftest import SOURCE_DIR

# The Python module calls the same C++ code on the same doubles: only copies differ, so the
# C++ test's figures hold to rounding. 1e-6 relative leaves room for a different BLAS.
CPP_REL_TOL = 1e-6
# Parameters identified from an exact simulation of the same model: limited by the 100 Hz
# output sampling and the finite-difference velocity, not by the method.
SIM_REL_TOL = 2e-3


def emps_force(d):
    return d["gtau"] * d["vir"]  # vir is the drive input in V; gtau N/V


@pytest.fixture(scope="module")
def emps_result(emps, emps_pulses):
    p = emps_pulses
    return fl.identify_idim(emps["t"], emps_force(emps), position=emps["qm"], source=emps,
                            validate={"time": p["t"], "force": emps_force(p), "position": p["qm"], "source": p})


def test_emps_idim_matches_cpp_and_publication(emps_result):
    r = emps_result
    assert r.ok and r.status == "ok" and r.method == "idim" and r.model == "coulomb-viscous"
    # tests/identify/test_idim_emps.cpp: scipy-verified values of the C++ pipeline.
    assert r["M"] == pytest.approx(95.10074896241412, rel=CPP_REL_TOL)
    assert r["M"] == pytest.approx(95.1089, rel=5e-3)  # published IDIM-LS
    assert r.fit.relative_error_percent == pytest.approx(4.13722720504, rel=CPP_REL_TOL)
    assert r.validation.relative_error_percent == pytest.approx(6.01646924401, rel=CPP_REL_TOL)
    assert r.validation.file.endswith("DATA_EMPS_PULSES.mat")
    assert r.data_sha256 == "6cf6814ae14618795da0101aae2bb97ff0c6351b0501b5492751b02b07facf7e"
    assert list(r) == ["M", "Fv", "Fc", "offset"]
    assert r.units == {"M": "kg", "Fv": "N s/m", "Fc": "N", "offset": "N"}
    assert all(s > 0 for s in r.std.values())
    assert r.fit.samples == 2480
    assert r.diagnostics.numbers["dt"] == pytest.approx(1e-3, rel=1e-3)
    assert r.law.name == "coulomb-viscous" and r.law.parameters["Fc"] == r["Fc"]


def test_emps_std_accounts_for_correlated_residuals(emps, emps_result):
    r = emps_result
    # std_ols: the recipe's s sqrt(diag((X'X)^-1)), the scipy figures of tests/identify/test_idim_emps.cpp.
    assert r.std_ols["Fc"] == pytest.approx(0.10262646030169308, rel=CPP_REL_TOL)
    assert r.parameters["M"].std_ols == pytest.approx(0.10997334837875802, rel=CPP_REL_TOL)
    # EMPS's residual is correlated (lag-1 autocorrelation above 0.5): the std that accounts for it
    # is larger than the ordinary one for every parameter.
    assert all(r.std[k] > r.std_ols[k] for k in r.std), (r.std, r.std_ols)
    assert r.diagnostics.numbers["covariance_bandwidth"] >= 1
    j = json.loads(r.to_json())
    assert j["diagnostics"]["covariance"] == "newey-west-prewhitened"
    assert j["parameters"]["Fc"]["std_ols"] == pytest.approx(r.std_ols["Fc"], rel=1e-12)
    assert j["parameters"]["Fc"]["std"] == pytest.approx(r.std["Fc"], rel=1e-12)
    # the correlation matrix comes from the same covariance as std: unit diagonal, symmetric
    m = np.array(j["diagnostics"]["correlation"]["matrix"], dtype=float)
    np.testing.assert_allclose(np.diag(m), 1.0)
    np.testing.assert_allclose(m, m.T)


def test_exclude_below_leaves_out_slow_samples(emps):
    d = emps
    full = fl.identify_idim(d["t"], emps_force(d), position=d["qm"])
    r = fl.identify_idim(d["t"], emps_force(d), position=d["qm"], exclude_below=0.01)
    n = r.diagnostics.numbers["excluded_samples"]
    assert r.diagnostics.numbers["exclude_below"] == 0.01
    assert 0 < n < full.fit.samples and r.fit.samples == full.fit.samples - n
    assert "excluded_samples" not in full.diagnostics.numbers
    # every velocity the fit kept is at least the threshold
    assert np.min(np.abs(r.series["velocity"])) >= 0.01
    with pytest.raises(ValueError, match="exclude"):
        fl.identify_idim(d["t"], emps_force(d), position=d["qm"], exclude_below=-1)
    # a threshold above every speed leaves nothing: a status error naming it, not numbers
    none = fl.identify_idim(d["t"], emps_force(d), position=d["qm"], exclude_below=10.0)
    assert not none.ok and "exclude_below" in none.message


def test_emps_cross_test_function_and_best_model(emps, emps_pulses):
    p = emps_pulses
    # tests/identify/test_idim_emps.cpp: asymmetric friction, a Stribeck term and the one-sample delay.
    r = fl.identify_idim(emps["t"], emps_force(emps), emps["qm"], terms="inertia,asymmetric,stribeck", input_delay=1)
    v = fl.cross_test(r, p["t"], emps_force(p), p["qm"])
    assert r.fit.relative_error_percent == pytest.approx(2.310, abs=5e-3)
    assert v.relative_error_percent == pytest.approx(3.118, abs=5e-3)
    assert isinstance(v, fl.ValidationFigures) and v.samples == r.fit.samples


def test_idim_regression_and_reconstruction(emps, emps_result):
    reg = fl.idim_regression(emps["t"], emps_force(emps), emps["qm"])
    assert reg["X"].shape == (2480, 4) and reg["parameters"] == ["M", "Fv", "Fc", "offset"]
    rec = fl.idim_reconstruction(emps_result)
    rel = 100 * np.linalg.norm(rec["residual"]) / np.linalg.norm(rec["measured"])
    assert rel == pytest.approx(emps_result.fit.relative_error_percent, rel=1e-9)
    assert rec["time"][0] == pytest.approx(emps["t"][49]) and len(rec["time"]) == 2480
    # The library's own series agree with the reconstruction from the regression.
    np.testing.assert_allclose(emps_result.series["force_model"], rec["reconstructed"], rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(emps_result.series["time"], rec["time"], rtol=1e-12)


def test_result_api(emps_result, tmp_path):
    r = emps_result
    text = repr(r)
    lines = text.splitlines()
    assert lines[0].startswith("<frictionlab.Result method='idim' model='coulomb-viscous' status='ok'")
    # Aligned table: the '=' and the '±' of every parameter line sit in the same column.
    rows = [ln for ln in lines if "±" in ln]
    assert len(rows) == 4 and len({ln.index("=") for ln in rows}) == 1 and len({ln.index("±") for ln in rows}) == 1
    assert "95.1007" in rows[0] and rows[0].rstrip().endswith("kg")
    # The fit's rmse carries the fitted signal's unit (EMPS: the drive force, N).
    assert re.search(r"^  fit: relative error [0-9.]+ %, rmse [0-9.]+ N, [0-9]+ samples$", text, re.M), text
    assert "unit='N'" in repr(r.fit), repr(r.fit)
    p = r.parameters["Fv"]
    assert (p.name, p.unit) == ("Fv", "N s/m") and tuple(p)[0] == p.value
    assert "Fc" in r and "Fs" not in r and len(r) == 4
    with pytest.raises(KeyError, match="no parameter 'Fs'"):
        r["Fs"]
    with pytest.raises(ValueError, match="no parameter 'Fs'"):
        r.value("Fs")
    d = r.to_dict()
    assert d["schema"] == 2 and d["parameters"]["M"]["unit"] == "kg" and d["parameters"]["M"]["value"] == r["M"]
    assert json.loads(r.to_json(indent=None)) == d
    path = tmp_path / "model.json"
    r.save(path)
    assert fl.load_law(path) == r.law
    with pytest.raises(ValueError, match="exists; pass --overwrite"):
        r.save(path)
    r.save(path, overwrite=True)


def test_idim_status_error_without_motion():
    t = np.arange(2000) * 1e-3
    r = fl.identify_idim(t, np.ones_like(t), position=np.zeros_like(t))
    assert not r.ok and r.status == "error"
    assert "no excitation" in r.message
    assert "error: " + r.message in repr(r)


def test_idim_bad_input_raises_value_error(emps):
    t = emps["t"]
    with pytest.raises(ValueError, match="unknown.*'bogus'"):
        fl.identify_idim(t, emps_force(emps), emps["qm"], terms=["inertia", "bogus"])
    with pytest.raises(ValueError, match="neither position nor velocity"):
        fl.identify_idim(t, emps_force(emps))
    with pytest.raises(ValueError, match=r"stribeck_vs 'fast': expected a Stribeck velocity"):
        fl.identify_idim(t, emps_force(emps), emps["qm"], stribeck_vs="fast")
    with pytest.raises(ValueError, match="position: expected a 1-D array of numbers"):
        fl.identify_idim(t, emps_force(emps), np.zeros((3, 2)))
    with pytest.raises(ValueError, match="position: expected a 1-D array of numbers, got str"):
        fl.identify_idim(t, emps_force(emps), "qm")
    with pytest.raises(ValueError, match="idim: decimation = 0 must be >= 1"):
        fl.identify_idim(t, emps_force(emps), emps["qm"], decimation=0)
    with pytest.raises(ValueError, match="axis"):
        fl.identify_idim(t, emps_force(emps), emps["qm"], axis="diagonal")
    bad = fl.identify_idim(np.arange(2000) * 1e-3, np.ones(2000), position=np.zeros(2000))
    with pytest.raises(ValueError):
        fl.cross_test(bad, emps["t"], emps_force(emps), emps["qm"])


@pytest.fixture(scope="module")
def trapezoid(example):
    return fl.simulate(example("craig_motor_trapezoid"))


def test_breakaway_on_craig_trapezoid(trapezoid):
    tr = trapezoid
    kt = 0.0141  # N m/A, examples/craig_motor_trapezoid.yaml
    r = fl.identify_breakaway(tr["time"], kt * tr["current"], tr["velocity"], axis="rotary")
    assert r.ok and r.method == "breakaway"
    assert r["Fs"] == pytest.approx(0.0015, rel=SIM_REL_TOL)
    assert r["Fc"] == pytest.approx(0.0012, rel=SIM_REL_TOL)
    assert r["Fv"] == pytest.approx(2.85e-6, rel=SIM_REL_TOL)
    assert r["M"] == pytest.approx(1.06e-6, rel=SIM_REL_TOL)
    assert r.units["Fv"] == "N m s/rad"
    assert set(r.diagnostics.groups["readoff"]) >= {"Fs", "Fc", "Fv"}
    fixed = fl.identify_breakaway(tr["time"], kt * tr["current"], tr["velocity"], inertia=1.06e-6, axis="rotary")
    assert "M" not in fixed and fixed["Fc"] == pytest.approx(0.0012, rel=SIM_REL_TOL)


def test_breakaway_errors(trapezoid):
    t = trapezoid["time"]
    r = fl.identify_breakaway(t, np.zeros_like(t), np.zeros_like(t))
    assert not r.ok and r.message
    with pytest.raises(ValueError, match="length|samples"):
        fl.identify_breakaway(t, t[:-1], t)


@pytest.fixture(scope="module")
def virgala(example):
    return fl.simulate(example("virgala_motor_sweep"))


VIRGALA_LAW = {"Fc": 0.002, "Fs": 0.003, "vs": 5.0, "delta": 2.0, "Fv": 1e-5}  # examples/virgala_motor_sweep.yaml


def test_sweep_on_virgala_motor(virgala):
    tr = virgala
    km = 0.039  # N m/A, examples/virgala_motor_sweep.yaml
    r = fl.identify_sweep(tr["time"], km * tr["current"], tr["velocity"], axis="rotary")
    assert r.ok and r.method == "sweep" and r.model == "stribeck"
    pts = r.diagnostics.lists["points"]
    assert len(pts) == 15
    # As tests/identify/test_identify_simulated.cpp: every true value inside the 2-sigma interval.
    for name, true in VIRGALA_LAW.items():
        assert abs(r[name] - true) <= 2 * r.std[name], (name, r[name], r.std[name])
        assert r[name] == pytest.approx(true, rel=1e-3)
    assert r.units == {"Fc": "N m", "Fs": "N m", "vs": "rad/s", "delta": "", "Fv": "N m s/rad"}
    np.testing.assert_allclose(r.series["velocity"], [q["velocity"] for q in pts], rtol=1e-12)
    p = fl.sweep_points(tr["time"], km * tr["current"], tr["velocity"])
    np.testing.assert_allclose(p["velocity"], [q["velocity"] for q in pts], rtol=1e-12)
    np.testing.assert_allclose(p["velocity"][:3], [1, 2, 3], rtol=1e-3)
    law = fl.FrictionLaw(dict(law="stribeck", **VIRGALA_LAW))
    np.testing.assert_allclose(p["force"], law.sliding(p["velocity"]), rtol=1e-3)
    w = fl.identify_sweep(tr["time"], km * tr["current"], tr["velocity"], model="coulomb-viscous",
                          windows=[(1, 1.9), (5, 5.9), (9, 9.9), (19, 19.9)])
    assert w.ok and len(w.diagnostics.lists["points"]) == 4 and w.model == "coulomb-viscous"


def test_sweep_errors(virgala):
    tr = virgala
    with pytest.raises(ValueError, match="model 'quadratic' cannot be fitted to a friction-velocity map; expected coulomb-viscous, "
                                         "coulomb-viscous-asymmetric, stribeck or stribeck-asymmetric"):
        fl.identify_sweep(tr["time"], tr["current"], tr["velocity"], model="quadratic")
    few = fl.identify_sweep(tr["time"], tr["current"], tr["velocity"], windows=[(1, 1.9)])
    assert not few.ok and "segment" in few.message


def test_decay_on_craig_pendulum(example):
    tr = fl.simulate(example("craig_pendulum_combined"))
    r = fl.identify_decay(tr["time"], tr["position"], stiffness=9.81, pendulum=True, axis="rotary")
    assert r.ok and r.method == "decay"
    assert r["Fc"] == pytest.approx(0.16, rel=SIM_REL_TOL)
    assert r["Fv"] == pytest.approx(0.5, rel=SIM_REL_TOL)
    assert r.units["Fc"] == "N m"
    with pytest.raises(ValueError, match="stiffness"):
        fl.identify_decay(tr["time"], tr["position"])


def test_fit_static_law_exact_and_errors():
    v = np.concatenate([-np.linspace(0.1, 2, 20), np.linspace(0.1, 2, 20)])
    f = np.sign(v) * 1.5 + 0.3 * v
    fit = fl.fit_static_law(v, f, model="coulomb-viscous")
    assert fit["Fc"] == pytest.approx(1.5, rel=1e-9) and fit.values["Fv"] == pytest.approx(0.3, rel=1e-9)
    assert fit.law.name == "coulomb-viscous" and fit.samples == 40
    assert fit.parameters("rotary")["Fv"].unit == "N m s/rad"
    assert "StaticFit law='coulomb-viscous'" in repr(fit)
    law = fl.FrictionLaw({"law": "stribeck", "Fc": 1.0, "Fs": 1.5, "vs": 0.1, "delta": 2.0, "Fv": 0.4})
    s = fl.fit_static_law(v, law.sliding(v), fixed_delta=2)
    assert s.converged and s["Fs"] == pytest.approx(1.5, rel=1e-6) and s["vs"] == pytest.approx(0.1, rel=1e-6)
    with pytest.raises(ValueError, match="friction fit: velocity has 40 points but force has 39; they must be equal"):
        fl.fit_static_law(v, f[:-1])
    with pytest.raises(ValueError, match="model 'nope'"):
        fl.fit_static_law(v, f, model="nope")


def test_idim_load_temperature_and_ripple_terms(conditions_record):
    # Noiseless data from the model itself: the filtered, decimated pipeline gives the truth back
    # within 1e-3 (see tests/identify/test_idim_conditions.cpp for why).
    t, force, q, load, temp = conditions_record
    r = fl.identify_idim(t, force, q, load=load, temperature=temp, temperature_ref=30.0, skip_end=49,
                         terms=["inertia", "viscous", "coulomb", "offset", "load", "temperature", "ripple"],
                         ripple_period=0.02)
    assert r.ok, r.message
    for name, truth in {"M": 2.0, "Fv": 20.0, "Fc": 3.0, "load_gain": 1.0, "mu_load": 0.05, "Fv_per_K": -0.25,
                        "ripple_sin_1": 0.6, "ripple_cos_1": -0.4}.items():
        assert r.value(name) == pytest.approx(truth, rel=1e-3), name
    assert r.parameters["Fv_per_K"].unit == "N s/m/K"
    # The result keeps its conditions for the reconstruction, whose residual is then tiny.
    rec = fl.idim_reconstruction(r)
    assert np.abs(rec["residual"]).max() < 1e-2 * np.abs(rec["measured"]).max()
    # A term without its column names the column and how to give it.
    with pytest.raises(ValueError, match="the 'load' term needs the load column"):
        fl.identify_idim(t, force, q, terms=["inertia", "viscous", "coulomb", "load"])
    with pytest.raises(ValueError, match=r"time \(30001 samples\) and load \(10 samples\) differ in length"):
        fl.identify_idim(t, force, q, load=load[:10], terms=["inertia", "load"])


# identify_auto on a Coulomb-viscous trajectory without noise but for a 10 mN force quantum:
# the model is right, so the estimates land within what the filtering and decimation leave
# (tenths of a percent); 2 % flags a wrong choice or a wrong fit.
AUTO_REL_TOL = 2e-2


def test_identify_auto_chooses_by_held_out_error():
    t = np.arange(0, 20, 1e-3)
    w = 2 * np.pi * np.array([0.3, 0.7, 1.3])
    q = 0.02 * (np.sin(w[0] * t) + 0.5 * np.sin(w[1] * t) + 0.3 * np.sin(w[2] * t))
    v = 0.02 * (w[0] * np.cos(w[0] * t) + 0.5 * w[1] * np.cos(w[1] * t) + 0.3 * w[2] * np.cos(w[2] * t))
    a = -0.02 * (w[0] ** 2 * np.sin(w[0] * t) + 0.5 * w[1] ** 2 * np.sin(w[1] * t) + 0.3 * w[2] ** 2 * np.sin(w[2] * t))
    force = np.round((2.0 * a + 3.0 * np.sign(v) + 20.0 * v) / 0.01) * 0.01
    r = fl.identify_auto(t, force, position=q, folds=4)
    assert r.ok, r.message
    j = json.loads(r.to_json())
    assert j["method"] == "auto"
    chosen = [c for c in r.selection if c["status"] == "chosen"]
    assert len(chosen) == 1 and len(r.selection) >= 3, r.selection
    assert math.isclose(r.value("Fc" if "Fc" in j["parameters"] else "Fc_pos"), 3.0, rel_tol=AUTO_REL_TOL)
    assert math.isclose(r.value("Fv" if "Fv" in j["parameters"] else "Fv_pos"), 20.0, rel_tol=AUTO_REL_TOL)
    with pytest.raises(ValueError, match="folds"):
        fl.identify_auto(t, force, position=q, folds=1)


# A free decay found by identify_auto: with ``stiffness`` (decay's keyword, N/m) Fc and Fv in N,
# without it Fc_over_k and zeta. An exact spring-mass (2 kg, 800 N/m, Fc 0.4 N, Fv 0.8 N s/m)
# integrated with a 10 us symplectic step, read at 1 kHz: 1 % is ten times what the sampling leaves.
def test_identify_auto_stiffness_gives_a_decay_in_force_units():
    h, per = 1e-5, 100
    x, v, xs = 0.02, 0.0, []
    for k in range(4000 * per):
        if k % per == 0:
            xs.append(x)
        spring = -800.0 * x
        if v != 0.0 or abs(spring) > 0.4:
            s = math.copysign(1.0, v) if v != 0.0 else math.copysign(1.0, spring)
            vn = v + h * (spring - 0.4 * s - 0.8 * v) / 2.0
            v = 0.0 if v != 0.0 and (vn > 0) != (v > 0) else vn
        x += h * v
    t = np.arange(len(xs)) * 1e-3
    q = np.array(xs)
    r = fl.identify_auto(t, np.zeros_like(t), position=q, stiffness=800.0)
    assert r.ok, r.message
    assert math.isclose(r.value("Fc"), 0.4, rel_tol=0.01) and math.isclose(r.value("Fv"), 0.8, rel_tol=0.01)
    assert r.selection[0]["status"] == "chosen" and len(r.selection) == 5, r.selection
    assert all(c["reason"].startswith("not run: ") for c in r.selection[1:]), r.selection
    plain = fl.identify_auto(t, np.zeros_like(t), position=q)
    assert math.isclose(plain.value("Fc_over_k"), 0.4 / 800.0, rel_tol=0.01)
    with pytest.raises(ValueError, match="stiffness"):
        fl.identify_auto(t, np.zeros_like(t), position=q, stiffness=-1.0)


def test_idim_iv_on_emps_with_the_benchmark_controller(emps, emps_result):
    """IDIM-IV with the same keywords as the command line (docs/identify.md): converges, close to
    IDIM-LS on EMPS (0.5 %, tests/identify/test_idim_iv.cpp says why), IV diagnostics present."""
    r = fl.identify_idim(emps["t"], emps_force(emps), position=emps["qm"], iv=True, reference=emps["qg"],
                         controller="emps-pd", kp=float(emps["kp"]), kv=float(emps["kv"]),
                         drive_gain=float(emps["gtau"]))
    assert r.ok, r.message
    d = r.diagnostics
    assert set(d.groups["ls_estimate"]) == {"M", "Fv", "Fc", "offset"}
    assert 1 <= d.numbers["iv_iterations"] <= 10
    for name in ("M", "Fv", "Fc"):
        assert abs(r.parameters[name].value - emps_result.parameters[name].value) <= 5e-3 * abs(
            emps_result.parameters[name].value), name


def test_idim_iv_without_the_controller_names_what_to_give(emps):
    t, f, q = emps["t"], emps_force(emps), emps["qm"]
    with pytest.raises(fl.Error, match="--controller pid with --kp"):
        fl.identify_idim(t, f, position=q, iv=True, reference=emps["qg"])
    with pytest.raises(fl.Error, match="--reference COLUMN"):
        fl.identify_idim(t, f, position=q, iv=True, controller="emps-pd", kp=160.18, kv=243.45, drive_gain=35.15)
    with pytest.raises(fl.Error, match="drive-gain"):
        fl.identify_idim(t, f, position=q, iv=True, reference=emps["qg"], controller="emps-pd", kp=160.18, kv=243.45)
    with pytest.raises(ValueError, match="reference"):
        fl.identify_idim(t, f, position=q, iv=True, reference=emps["qg"][:-1], controller="emps-pd", kp=160.18,
                         kv=243.45, drive_gain=35.15)


def test_idim_iv_controller_from_a_scenario_and_from_the_file_scalars(emps):
    """The controller of a scenario (a path, read with its own data file, or a Scenario) and the
    gains named as the MAT file's scalars give the result of the numbers typed; keywords given
    override the scenario's values, and the diagnostics say where each value came from."""
    t, f, q = emps["t"], emps_force(emps), emps["qm"]
    typed = fl.identify_idim(t, f, position=q, iv=True, reference=emps["qg"], controller="emps-pd",
                             kp=float(emps["kp"]), kv=float(emps["kv"]), drive_gain=float(emps["gtau"]))
    path = str(SOURCE_DIR / "examples" / "emps_closed_loop.yaml")
    by_path = fl.identify_idim(t, f, position=q, iv=True, reference=emps["qg"], scenario=path)
    by_object = fl.identify_idim(t, f, position=q, iv=True, reference=emps["qg"], scenario=fl.Scenario.load(path))
    by_names = fl.identify_idim(t, f, position=q, iv=True, reference=emps["qg"], controller="emps-pd", kp="kp",
                                kv="kv", drive_gain="gtau", source=emps)
    for r in (typed, by_path, by_object, by_names):
        assert r.ok, r.message
    for r in (by_path, by_object, by_names):
        for name in ("M", "Fv", "Fc", "offset"):
            # The same controller and simulation: the same numbers to the bit.
            assert r.parameters[name].value == typed.parameters[name].value, name
    assert by_path.diagnostics.texts["iv_source_kv"] == f"scenario {path}: controller.kv"
    assert by_object.diagnostics.texts["iv_source_kv"] == "scenario Scenario: controller.kv"
    assert by_names.diagnostics.texts["iv_source_kp"] == "kp='kp': scalar of DATA_EMPS.mat"
    assert by_names.diagnostics.groups["iv_controller"]["drive_gain"] == float(emps["gtau"])
    over = fl.identify_idim(t, f, position=q, iv=True, reference=emps["qg"], scenario=path, kv=200.0,
                            iv_iterations=40)
    assert over.ok, over.message
    assert over.diagnostics.groups["iv_controller"]["kv"] == 200.0
    assert over.diagnostics.texts["iv_source_kv"] == "--kv"
    assert over.diagnostics.texts["iv_source_kp"] == f"scenario {path}: controller.kp"


def test_idim_iv_scenario_and_scalar_name_refusals(emps):
    t, f, q = emps["t"], emps_force(emps), emps["qm"]
    path = str(SOURCE_DIR / "examples" / "emps_closed_loop.yaml")
    with pytest.raises(ValueError, match="contradicts the scenario .*controller.type is emps-pd"):
        fl.identify_idim(t, f, position=q, iv=True, reference=emps["qg"], scenario=path, controller="pid", kp=1e4)
    with pytest.raises(ValueError, match="plant.type: the axis plant moves linear"):
        fl.identify_idim(t, f, position=q, iv=True, reference=emps["qg"], scenario=path, axis="rotary")
    with pytest.raises(ValueError, match="iv=True is not given"):
        fl.identify_idim(t, f, position=q, scenario=path)
    with pytest.raises(ValueError, match="has no scalar 'Kp'.*scalars: gtau, kp, kv"):
        fl.identify_idim(t, f, position=q, iv=True, reference=emps["qg"], controller="emps-pd", kp="Kp", kv="kv",
                         drive_gain="gtau", source=emps)
    with pytest.raises(ValueError, match="no source= gives one"):
        fl.identify_idim(t, f, position=q, iv=True, reference=emps["qg"], controller="emps-pd", kp="kp", kv=243.45,
                         drive_gain=35.15)
