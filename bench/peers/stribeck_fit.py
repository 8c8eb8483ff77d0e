#!/usr/bin/python3
"""Peer: fit of a Stribeck law F = sign(v) (Fc + (Fs - Fc) exp(-|v/vs|^delta)) + Fv v to 100 000
noisy points (common.stribeck_data, seeded) with scipy.optimize.least_squares: trust-region
reflective with bounds (Fc, Fs - Fc, Fv >= 0; vs in [1e-6, 10] max|v|; delta in [0.5, 5]),
analytic Jacobian, x_scale='jac', tolerances 1e-12 (frictionlab's Ceres settings), a start from the
data (high-speed half: linear Coulomb + viscous; slowest tenth: Fs; delta 2), as one writes it.

Usage: stribeck_fit.py [--repeat N] [--n N] [--write FILE]
--write FILE stores the points as raw float64 (v then F, little endian) for frictionlab's side.
Prints JSON {task, seconds (best of N), parameters, accuracy (relative errors against the truth)}."""
import argparse

import numpy as np
from scipy.optimize import least_squares

from common import best_of, emit, stribeck_accuracy, stribeck_data, stribeck_law


def jac(p, v, f):
    Fc, dF, vs, delta, Fv = p
    a = np.abs(v)
    s = np.sign(v)
    r = (a / vs) ** delta
    e = np.exp(-r)
    lr = np.log(np.maximum(a / vs, 1e-300))
    return np.column_stack([s, s * e, s * dF * e * r * delta / vs, -s * dF * e * r * lr, v])


def start(v, f):
    a, g = np.abs(v), f * np.sign(v)
    o = np.argsort(a)
    hi = o[len(o) // 2:]
    Fc, Fv = np.linalg.lstsq(np.column_stack([np.ones(len(hi)), a[hi]]), g[hi], rcond=None)[0]
    Fc, Fv = max(Fc, 0.0), max(Fv, 0.0)
    lo = o[: max(1, len(o) // 10)]
    Fs = np.mean(g[lo] - Fv * a[lo])
    dF = max(Fs - Fc, 1e-3 * Fc)
    ex = g[o] - Fc - Fv * a[o]
    below = np.nonzero(ex < dF / np.e)[0]
    vs = a[o][below[0]] if len(below) else a[o][len(o) // 2]
    return np.array([Fc, dF, vs, 2.0, Fv])


def fit(v, f):
    vmax = np.abs(v).max()
    lb = [0.0, 0.0, 1e-6 * vmax, 0.5, 0.0]
    ub = [np.inf, np.inf, 10 * vmax, 5.0, np.inf]
    x0 = np.clip(start(v, f), lb, ub)
    r = least_squares(lambda p: stribeck_law(p, v) - f, x0, jac=lambda p: jac(p, v, f), bounds=(lb, ub),
                      method="trf", x_scale="jac", ftol=1e-12, xtol=1e-12, gtol=1e-14)
    Fc, dF, vs, delta, Fv = r.x
    return {"Fc": Fc, "Fs": Fc + dF, "vs": vs, "delta": delta, "Fv": Fv}, r


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--n", type=int, default=100_000)
    ap.add_argument("--write", default=None)
    a = ap.parse_args()
    v, f = stribeck_data(a.n)
    if a.write:
        np.concatenate([v, f]).astype("<f8").tofile(a.write)
    sec, (params, r) = best_of(lambda: fit(v, f), a.repeat)
    emit({"task": "stribeck_fit_100k", "seconds": sec, "points": a.n, "parameters": params, "nfev": int(r.nfev),
          "status": int(r.status), "accuracy": stribeck_accuracy(params)})


if __name__ == "__main__":
    main()
