"""frictionlab.export_c (the C99 header of a law and a compensation) and export_mjcf (the MuJoCo model), from Python."""
import ctypes
import json
import math
import shutil
import subprocess

import numpy as np
import pytest

import frictionlab as fl

# Double: the header runs the library's formulas in its order; 1e-12 leaves room for a compiler's
# contraction of a multiply-add and nothing more.
REL_TOL = 1e-12

STRIBECK_ASYM = {"law": "stribeck-asymmetric", "Fc_pos": 1.1, "Fs_pos": 1.6, "vs_pos": 0.002, "Fv_pos": 0.35,
                 "Fc_neg": 0.8, "Fs_neg": 1.3, "vs_neg": 0.001, "Fv_neg": 0.45}


def test_header_text_has_the_parameters_at_full_precision():
    text = fl.export_c(fl.FrictionLaw(STRIBECK_ASYM), compensation={"type": "feedforward", "band": 0.002},
                       prefix="x_axis")
    assert "static const double x_axis_Fc_pos = 1.1000000000000001;" in text
    assert "static const double x_axis_ff_band = 0.002;" in text
    assert "x_axis_feedforward(double vr)" in text
    assert text.count("#include") == 1 and "#include <math.h>" in text
    single = fl.export_c(STRIBECK_ASYM, float=True)
    assert "static const float friction_Fs_neg = 1.3f;" in single and "double" not in single


@pytest.mark.skipif(shutil.which("cc") is None, reason="needs a C compiler")
def test_compiled_header_matches_the_law(tmp_path):
    # A shared object built from the header, called through ctypes over a seeded noisy grid.
    law = fl.FrictionLaw(STRIBECK_ASYM)
    (tmp_path / "law.h").write_text(fl.export_c(law))
    (tmp_path / "lib.c").write_text('#include "law.h"\ndouble f(double v) { return friction_friction(v); }\n')
    subprocess.run(["cc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2", "-shared", "-fPIC",
                    "-o", str(tmp_path / "lib.so"), str(tmp_path / "lib.c"), "-lm"], check=True)
    lib = ctypes.CDLL(str(tmp_path / "lib.so"))
    lib.f.restype = ctypes.c_double
    lib.f.argtypes = [ctypes.c_double]
    rng = np.random.default_rng(5)
    v = np.concatenate([np.linspace(-0.05, 0.05, 201), rng.normal(0, 0.01, 300), [0.0, 1e-9, -1e-9]])
    # Scalar calls: the array form may run vector kernels, themselves within 1e-12 of the scalar law.
    want = np.array([law.sliding(float(x)) for x in v])
    got = np.array([lib.f(float(x)) for x in v])
    assert np.all(np.abs(got - want) <= REL_TOL * np.abs(want)), np.max(np.abs(got - want))
    assert got[-3] == 0.0 and got[-2] > 1.0 and got[-1] < -0.7  # rest, and each direction's own level


def test_model_file_path_and_inertia_from_model(tmp_path):
    model = tmp_path / "model.json"
    model.write_text(json.dumps({"status": "ok", "law": {"law": "coulomb-viscous", "Fc": 0.7, "Fv": 0.2},
                                 "parameters": {"M": {"value": 2.5, "std": 0.01, "unit": "kg"}}}))
    out = tmp_path / "drive.h"
    text = fl.export_c(model, compensation="disturbance-observer", path=out)
    assert out.read_text() == text
    assert "static const double friction_dob_inertia = 2.5;" in text
    with pytest.raises(ValueError, match="export_c: argument path: .*exists; pass overwrite=True"):
        fl.export_c(model, path=out)
    assert out.read_text() == text  # untouched
    fl.export_c(model, path=out, overwrite=True)
    assert "friction_dob_inertia" not in out.read_text()


def test_bad_compensations_name_the_argument():
    with pytest.raises(ValueError, match="lugre-observer: law = stribeck-asymmetric must be lugre"):
        fl.export_c(STRIBECK_ASYM, compensation="lugre-observer")
    with pytest.raises(ValueError, match="compensation 'observer' is not known; valid types: feedforward"):
        fl.export_c(STRIBECK_ASYM, compensation="observer")
    with pytest.raises(ValueError, match="compensation feedback has no parameter 'band'; it has dead_band"):
        fl.export_c(STRIBECK_ASYM, compensation={"type": "feedback", "band": 0.1})
    with pytest.raises(ValueError, match="disturbance-observer: inertia = 0 must be > 0"):
        fl.export_c(STRIBECK_ASYM, compensation="disturbance-observer")
    with pytest.raises(ValueError, match="missing 'type'"):
        fl.export_c(STRIBECK_ASYM, compensation={"band": 0.1})
    with pytest.raises(ValueError, match="prefix 'a-b' is not a C identifier"):
        fl.export_c(STRIBECK_ASYM, prefix="a-b")
    with pytest.raises(TypeError, match="export_c: argument model"):
        fl.export_c(3.0)


# export_mjcf: the MuJoCo model (tests/export/mujoco/ loads the same text in MuJoCo itself).

def test_export_mjcf_maps_the_model_and_lists_what_is_left_out(tmp_path):
    model = tmp_path / "model.json"
    model.write_text(json.dumps({"status": "ok", "axis": "linear",
                                 "law": {"law": "stribeck", "Fc": 1.25, "Fs": 1.5, "vs": 0.001, "Fv": 0.4},
                                 "parameters": {"M": {"value": 2.5, "std": 0.01, "unit": "kg"},
                                                "offset": {"value": 0.3, "std": 0.01, "unit": "N"}}}))
    out = tmp_path / "axis.xml"
    r = fl.export_mjcf(model, out)
    assert out.read_text() == r["xml"]
    assert r["joint"] == "slide" and r["frictionloss"] == 1.25 and r["damping"] == 0.4 and r["body_inertia"] == 2.5
    assert 'frictionloss="1.25" damping="0.4"' in r["xml"] and 'mass="2.5"' in r["xml"]
    assert [x["name"] for x in r["left_out"]] == ["Fs", "vs", "delta", "offset"]
    assert r["left_out"][0] == {"name": "Fs", "value": 1.5, "unit": "N", "reason": r["left_out"][0]["reason"]}
    assert "Fs = 1.5 N" in r["xml"]
    with pytest.raises(ValueError, match="export_mjcf: argument path: .*exists; pass overwrite=True"):
        fl.export_mjcf(model, out)
    # The same text as the command line's for the same file (one writer).
    assert fl.export_mjcf(model, out, overwrite=True)["xml"] == r["xml"]


def test_export_mjcf_of_a_law_needs_the_inertia_and_takes_the_axis():
    law = {"law": "coulomb-viscous", "Fc": 0.5, "Fv": 0.02}
    with pytest.raises(ValueError, match="export_mjcf: argument inertia: missing"):
        fl.export_mjcf(law)
    r = fl.export_mjcf(law, inertia=0.8, armature=0.2, axis="rotary", timestep=0.001)
    assert r["joint"] == "hinge" and r["armature"] == 0.2 and abs(r["body_inertia"] - 0.6) <= 1e-15
    assert 'type="hinge"' in r["xml"] and 'timestep="0.001"' in r["xml"] and r["left_out"] == []


def test_export_mjcf_bad_input_names_the_argument():
    with pytest.raises(ValueError, match="law viscous has no Fc"):
        fl.export_mjcf({"law": "viscous", "Fv": 1.0}, inertia=1.0)
    with pytest.raises(ValueError, match=r"export_mjcf: argument inertia = -1 must be > 0 \(kg or kg m\^2\)"):
        fl.export_mjcf({"law": "coulomb", "Fc": 1.0}, inertia=-1.0)
    with pytest.raises(ValueError, match="export_mjcf: argument armature = 1 must be >= 0 and < the inertia 1"):
        fl.export_mjcf({"law": "coulomb", "Fc": 1.0}, inertia=1.0, armature=1.0)
    with pytest.raises(ValueError, match="export_mjcf: argument timestep = 0 must be > 0"):
        fl.export_mjcf({"law": "coulomb", "Fc": 1.0}, inertia=1.0, timestep=0.0)
    with pytest.raises(ValueError, match="export_mjcf: argument axis"):
        fl.export_mjcf({"law": "coulomb", "Fc": 1.0}, inertia=1.0, axis="diagonal")
    with pytest.raises(ValueError, match="export_mjcf: argument inertia = nan must be > 0"):
        fl.export_mjcf({"law": "coulomb", "Fc": 1.0}, inertia=math.nan)
    with pytest.raises(TypeError, match="inertia"):
        fl.export_mjcf({"law": "coulomb", "Fc": 1.0}, inertia="heavy")
    with pytest.raises(TypeError, match="export_mjcf: argument model"):
        fl.export_mjcf(3.0)


def test_export_mjcf_of_an_identification_result(emps):
    # The EMPS axis identified in Python: M, Fc, Fv and the offset come from the Result itself.
    r = fl.identify_idim(emps["t"], emps["gtau"] * emps["vir"], position=emps["qm"], source=emps)
    p = {name: x.value for name, x in r.parameters.items()}
    out = fl.export_mjcf(r)
    assert out["joint"] == ("hinge" if r.axis == "rotary" else "slide")
    assert out["frictionloss"] == p["Fc"] and out["damping"] == p["Fv"] and out["body_inertia"] == p["M"]
    offset = [x for x in out["left_out"] if x["name"] == "offset"]
    assert len(offset) == 1 and offset[0]["value"] == pytest.approx(p["offset"], rel=1e-15)
