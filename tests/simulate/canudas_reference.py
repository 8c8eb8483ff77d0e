#!/usr/bin/python3
"""Reference figures of the Canudas de Wit et al. (1995) LuGre stick-slip case, computed with
scipy's LSODA at tight tolerance (rtol 1e-10, atol 1e-12). Run with /usr/bin/python3 (scipy).

Plant: unit mass, spring k = 2 N/m pulled at 0.1 m/s (spring relaxed at x = 0, t = 0), 30 s.
LuGre Table I: sigma0 = 1e5, sigma1 = sqrt(1e5), sigma2 = 0.4, Fc = 1, Fs = 1.5, vs = 0.001.

Prints the stick-slip period (mean time between successive velocity peaks after the first cycle)
and the peak slip velocity; tests/simulate/test_examples.cpp compares frictionlab with them
(period 6.36 s, peak 0.370 m/s as recorded in docs/reference-results.md)."""
import numpy as np
from scipy.integrate import solve_ivp

s0, s1, s2, Fc, Fs, vs = 1e5, np.sqrt(1e5), 0.4, 1.0, 1.5, 0.001
m, k, V0 = 1.0, 2.0, 0.1


def rhs(t, y):
    x, v, z = y
    g = Fc + (Fs - Fc) * np.exp(-(v / vs) ** 2)
    dz = v - s0 * abs(v) * z / g
    F = s0 * z + s1 * dz + s2 * v
    return [v, (k * (V0 * t - x) - F) / m, dz]


t = np.linspace(0.0, 30.0, 300001)
sol = solve_ivp(rhs, (0.0, 30.0), [0.0, 0.0, 0.0], method="LSODA", t_eval=t, rtol=1e-10, atol=1e-12)
v = sol.y[1]
# velocity peaks: local maxima above half the global maximum
idx = [i for i in range(1, len(v) - 1) if v[i] >= v[i - 1] and v[i] > v[i + 1] and v[i] > 0.5 * v.max()]
peaks = t[idx]
print(f"peak times: {np.array2string(peaks, precision=4)}")
print(f"period: {np.mean(np.diff(peaks[1:])):.4f} s")
print(f"peak slip velocity: {v.max():.4f} m/s")
