#!/usr/bin/python3
"""Peer: Canudas de Wit 1995 LuGre stick-slip (Table I, spring k = 2 N/m, drive 0.1 m/s, 30 s)
with scipy.integrate.solve_ivp, LSODA and Radau, at frictionlab's tolerances (rtol 1e-8, atol
1e-10 on x and v, 1e-10 * Fc/sigma0 on z), analytic Jacobian, output at 1 kHz.

Usage: canudas_stick_slip.py [--repeat N] [--rtol R] [--cache DIR] [--methods LSODA,Radau]
Prints JSON {task, seconds (the fastest method's best of N), methods: {name: {seconds, nfev,
accuracy}}}. Accuracy is against a tight-tolerance reference (Radau, rtol 1e-12), cached in DIR
(default: bench/.cache) as canudas_reference.npz; --reference-only just makes that file."""
import argparse
import os

import numpy as np
from scipy.integrate import solve_ivp

from common import CANUDAS, CANUDAS_ZSCALE, HERE, best_of, emit, stick_slip_figures, trajectory_accuracy

P = CANUDAS
s0, s1, s2, Fc, Fs, vs, m, k, V0 = (P[n] for n in ("s0", "s1", "s2", "Fc", "Fs", "vs", "m", "k", "V0"))


def rhs(t, y):
    x, v, z = y
    g = Fc + (Fs - Fc) * np.exp(-(v / vs) ** 2)
    dz = v - s0 * abs(v) * z / g
    F = s0 * z + s1 * dz + s2 * v
    return [v, (k * (V0 * t - x) - F) / m, dz]


def jac(t, y):
    x, v, z = y
    e = np.exp(-(v / vs) ** 2)
    g = Fc + (Fs - Fc) * e
    dg = (Fs - Fc) * e * (-2.0 * v / vs**2)
    sv = np.sign(v)
    ddz_dv = 1.0 - s0 * z * (sv * g - abs(v) * dg) / g**2
    ddz_dz = -s0 * abs(v) / g
    return np.array([
        [0.0, 1.0, 0.0],
        [-k / m, -(s1 * ddz_dv + s2) / m, -(s0 + s1 * ddz_dz) / m],
        [0.0, ddz_dv, ddz_dz],
    ])


def grid():
    return np.linspace(0.0, P["T"], int(round(P["T"] * P["rate"])) + 1)


def run(method, rtol, atol=1e-10):
    t = grid()
    sol = solve_ivp(rhs, (0.0, P["T"]), [0.0, 0.0, 0.0], method=method, t_eval=t, jac=jac, rtol=rtol,
                    atol=[atol, atol, atol * CANUDAS_ZSCALE])
    if not sol.success:
        raise RuntimeError(f"{method}: {sol.message}")
    return sol


def reference(cache):
    path = os.path.join(cache, "canudas_reference.npz")
    if os.path.exists(path):
        d = np.load(path)
        return {k: d[k] for k in d.files} | {"period": float(d["period"]), "peak": float(d["peak"])}
    sol = run("Radau", 1e-12, 1e-14)
    period, peak = stick_slip_figures(sol.t, sol.y[1])
    os.makedirs(cache, exist_ok=True)
    np.savez(path, t=sol.t, x=sol.y[0], v=sol.y[1], period=period, peak=peak)
    return {"t": sol.t, "x": sol.y[0], "v": sol.y[1], "period": period, "peak": peak}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--rtol", type=float, default=1e-8)
    ap.add_argument("--cache", default=os.path.join(HERE, "..", ".cache"))
    ap.add_argument("--methods", default="LSODA,Radau")
    ap.add_argument("--reference-only", action="store_true")
    a = ap.parse_args()
    ref = reference(a.cache)
    if a.reference_only:
        emit({"reference": os.path.join(a.cache, "canudas_reference.npz"), "period": ref["period"], "peak": ref["peak"]})
        return
    methods = {}
    for name in a.methods.split(","):
        sec, sol = best_of(lambda: run(name, a.rtol), a.repeat)
        methods[name] = {"seconds": sec, "nfev": int(sol.nfev), "njev": int(sol.njev),
                         "accuracy": trajectory_accuracy(sol.t, sol.y[0], sol.y[1], ref)}
    fastest = min(methods, key=lambda n: methods[n]["seconds"])
    emit({"task": "canudas_stick_slip", "seconds": methods[fastest]["seconds"], "method": fastest,
          "accuracy": methods[fastest]["accuracy"], "methods": methods, "rtol": a.rtol,
          "reference": {"period": ref["period"], "peak": ref["peak"]}})


if __name__ == "__main__":
    main()
