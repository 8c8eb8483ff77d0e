"""fl.analyze_contour on a synthetic circular test with known quadrant glitches, and its errors."""
import numpy as np
import pytest

import frictionlab as fl


def test_analyze_contour_recovers_glitches():
    rng = np.random.default_rng(5)
    R, heights = 0.01, np.array([20e-6, 15e-6, 25e-6, 12e-6])  # m
    t = np.arange(0, 2 * np.pi * R / 0.02 * 1.05, 1e-3)  # a little over one turn at 20 mm/s
    a = np.pi / 4 + 0.02 / R * t
    deg = np.degrees(a)
    e = sum(h * np.exp(-0.5 * (np.remainder(deg - 90 * k + 180, 360) - 180) ** 2 / 2.0**2) for k, h in enumerate(heights))
    noise = 0.3e-6  # m
    x = (R + e) * np.cos(a) + rng.normal(0, noise, t.size)
    y = (R + e) * np.sin(a) + rng.normal(0, noise, t.size)
    r = fl.analyze_contour(t, x, y, R * np.cos(a), R * np.sin(a))
    assert r.centre_source == "reference"
    # The peak sample rides on the noise: up to ~3 sigma (1 um) of the smallest glitch, 12 um.
    peak_rtol = 0.1
    np.testing.assert_allclose(r.quadrant_glitch_m, heights, rtol=peak_rtol)
    assert [g.reversal_deg for g in r.glitches] == [0, 90, 180, 270]
    assert r.radial_error.shape == t.shape and r.x_error.shape == t.shape
    assert r.max_radial_error_m == pytest.approx(heights.max(), rel=peak_rtol)


def test_analyze_contour_errors():
    t = np.linspace(0, 1, 100)
    half = np.linspace(0, np.pi, 100)
    with pytest.raises(ValueError, match="less than one turn"):
        fl.analyze_contour(t, np.cos(half), np.sin(half))
    with pytest.raises(ValueError, match="differ in length"):
        fl.analyze_contour(t, np.cos(half), np.sin(half)[:-1])
    with pytest.raises(ValueError, match="at least 20 samples"):
        fl.analyze_contour(t[:10], t[:10], t[:10])
    with pytest.raises(ValueError, match=r"centre: expected \(x, y\)"):
        fl.analyze_contour(t, np.cos(half), np.sin(half), centre=[0, 0, 0])
