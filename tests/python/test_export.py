"""frictionlab.export_c: the C99 header of a law and a compensation, from Python."""
import ctypes
import json
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
