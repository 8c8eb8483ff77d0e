"""FrictionLaw.sliding on numpy arrays: one batch call (the law's formula in a loop) that equals
the float form value by value, keeps v's shape, and accepts any array-like of numbers."""
import math

import numpy as np
import pytest

import frictionlab as fl

LAWS = [
    {"law": "stribeck", "Fc": 1.0, "Fs": 1.5, "vs": 1e-3, "delta": 1.5, "Fv": 0.4},
    {"law": "stribeck", "Fc": 1.0, "Fs": 1.5, "vs": 1e-3, "Fv": 0.4},
    {"law": "smooth", "Fc": 1.0, "Fs": 1.5, "vs": 1e-3, "Fv": 0.2, "vt": 1e-3, "shape": "tanh"},
    {"law": "smooth", "Fc": 1.0, "Fs": 1.5, "vs": 1e-3, "delta": 0.7, "Fv": 0.2, "vt": 1e-3, "shape": "atan"},
    {"law": "smooth", "Fc": 1.0, "vt": 1e-3},
    {"law": "stribeck-asymmetric", "Fc_pos": 1.0, "Fs_pos": 1.5, "vs_pos": 1e-3, "delta_pos": 1.5, "Fv_pos": 0.4,
     "Fc_neg": 0.8, "Fs_neg": 1.1, "vs_neg": 2e-3, "delta_neg": 2.0, "Fv_neg": 0.3},
    {"law": "coulomb-viscous", "Fc": 2.0, "Fv": 0.5},
    {"law": "table", "velocity": [-1.0, -0.1, 0.1, 1.0], "force": [-1.4, -1.0, 1.0, 1.4]},
    {"law": "lugre", "sigma0": 1e5, "sigma1": 316.2, "sigma2": 0.4, "Fc": 1.0, "Fs": 1.5, "vs": 1e-3},
]


def velocities():
    rng = np.random.default_rng(20261123)
    v = np.sign(rng.uniform(-1, 1, 1001)) * 10.0 ** rng.uniform(-8, 2, 1001)
    v[:6] = [0.0, -0.0, 1e-300, -5e-324, 1e6, -1e-3]
    return v


@pytest.mark.parametrize("spec", LAWS, ids=lambda s: s["law"] + ("-" + s["shape"] if "shape" in s else ""))
def test_array_equals_the_float_form(spec):
    law = fl.FrictionLaw(spec)
    v = velocities()
    F = law.sliding(v)
    assert isinstance(F, np.ndarray) and F.dtype == np.float64 and F.shape == v.shape
    expected = np.array([law.sliding(float(x)) for x in v])
    # The batch call runs the scalar formula (FrictionLaw::sliding(v, F) in friction_law.hpp): equal
    # to the bit, on every CPU.
    np.testing.assert_array_equal(F, expected)
    # v = 0 gives the float form's value exactly, sign of zero included.
    assert [math.copysign(1, f) for f in F[:2]] == [math.copysign(1, f) for f in expected[:2]]
    np.testing.assert_array_equal(F[:2], expected[:2])
    np.testing.assert_array_equal(law(v), F)


def test_shapes_and_array_likes():
    law = fl.FrictionLaw({"law": "stribeck", "Fc": 1.0, "Fs": 1.5, "vs": 1e-3, "delta": 1.5, "Fv": 0.4})
    grid = np.linspace(-0.01, 0.01, 12).reshape(3, 4)
    F = law.sliding(grid)
    assert F.shape == (3, 4)
    np.testing.assert_allclose(F.ravel(), law.sliding(grid.ravel()), rtol=0, atol=0)
    # Non-contiguous, other dtypes and lists are copied to float64 first.
    np.testing.assert_array_equal(law.sliding(grid[:, ::2]), F[:, ::2])
    as_float32 = grid.astype(np.float32)
    np.testing.assert_array_equal(law.sliding(as_float32), law.sliding(as_float32.astype(float)))
    np.testing.assert_array_equal(law.sliding([0.001, -0.002]), law.sliding(np.array([0.001, -0.002])))
    assert law.sliding(np.array([])).shape == (0,)
    # Numbers, numpy scalars and 0-d arrays give a float.
    for x in (0.002, 2, np.float32(0.002), np.array(0.002)):
        assert isinstance(law.sliding(x), float)
    assert law.sliding(np.array(0.002)) == law.sliding(0.002)


def test_not_a_number_array_is_a_value_error():
    law = fl.FrictionLaw({"law": "coulomb", "Fc": 1.0})
    for bad in ("fast", None, object()):
        with pytest.raises(ValueError, match=r"v: expected a number or an array of numbers \(m/s or rad/s\)"):
            law.sliding(bad)
