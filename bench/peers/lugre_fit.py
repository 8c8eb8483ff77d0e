#!/usr/bin/python3
"""Peer: LuGre output-error fit of sigma0 and sigma1 (static part Fc, Fs, vs, delta, sigma2 given)
to 10 s of 1 kHz force and position of a unit mass with Canudas de Wit 1995 Table I friction
(common.LUGRE, the record of tests/identify/test_lugre.cpp), as frictionlab's identify_lugre
with a static law does it: the same starting values (sigma0 from the presliding, sigma1 critical
damping), the same windows (record start to the first velocity peak, then peak to peak, each
restarted from the measured position and velocity with the bristles in steady sliding), the same
residuals (simulated minus measured position, in um) over log sigma0, log sigma1.

As one writes it with scipy: each window simulated by solve_ivp (LSODA, rtol 1e-8, the force
interpolated linearly between samples) together with its forward sensitivities to log sigma0 and
log sigma1 (so one simulation gives residuals and Jacobian), analytic Jacobian of the state
equations for the stiff solver, scipy.optimize.least_squares (trf) with frictionlab's Ceres
tolerances (ftol = xtol = 1e-10, gtol = 1e-14).

Usage: lugre_fit.py [--repeat N] [--data FILE] [--rtol R]
--data FILE: CSV with columns time, applied, position (frictionlab_compare's lugre_record.csv or
`frictionlab simulate` output); without it the record is simulated here (Radau, rtol 1e-10).
Prints JSON {task, seconds (best of N), parameters {sigma0, sigma1}, nfev, njev, simulations,
iterations, accuracy (relative errors against Table I)}."""
import argparse
import csv

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import least_squares

from common import LUGRE, best_of, emit, lugre_accuracy, lugre_input_table

RESIDUAL_UNIT = 1e-6  # m: residuals in um, as frictionlab (presliding moves micrometres)


def read_record(path):
    with open(path) as f:
        r = csv.reader(f)
        names = next(r)
        data = np.array([[float(x) for x in row] for row in r])
    col = {n: data[:, i] for i, n in enumerate(names)}
    return col["time"], col["applied"], col["position"]


def simulate_record():
    """The experiment simulated with the true parameters (Radau, rtol 1e-10, restarted at each
    corner of the piecewise-linear force), sampled at 1 kHz: (t, u, x)."""
    L = LUGRE
    s0, s1, s2, Fc, Fs, vs, M = (L[k] for k in ("s0", "s1", "s2", "Fc", "Fs", "vs", "M"))
    times, values = lugre_input_table()
    t = np.linspace(0.0, L["T"], int(round(L["T"] * L["rate"])) + 1)

    def rhs(tt, y):
        x, v, z = y
        u = np.interp(tt, times, values)
        g = Fc + (Fs - Fc) * np.exp(-(v / vs) ** 2)
        dz = v - s0 * abs(v) * z / g
        return [v, (u - s0 * z - s1 * dz - s2 * v) / M, dz]

    x = np.zeros_like(t)
    y = np.zeros(3)
    for a, b in zip(times[:-1], times[1:]):
        inside = (t > a + 1e-12) & (t <= b + 1e-12)
        sol = solve_ivp(rhs, (a, b), y, method="Radau", t_eval=t[inside], rtol=1e-10,
                        atol=[1e-13, 1e-13, 1e-13 * Fc / s0])
        x[inside] = sol.y[0]
        y = sol.y[:, -1]
    return t, np.interp(t, times, values), x


class Problem:
    """The output error of one record: windows, start, and residuals with their Jacobian."""

    def __init__(self, t, u, x, rtol=1e-8):
        L = LUGRE
        self.t, self.u, self.x = t, u, x
        self.dt = t[1] - t[0]
        self.M, self.s2, self.Fc, self.Fs, self.vs, self.delta = L["M"], L["s2"], L["Fc"], L["Fs"], L["vs"], L["delta"]
        self.rtol = rtol
        self.vel = np.gradient(x, self.dt)
        vmax = np.abs(self.vel).max()
        self.threshold = 0.01 * vmax
        self.windows = self._windows(max(0.1 * vmax, 3.0 * self.vs), abs(self.vel[0]) <= self.threshold)
        self.simulations = 0
        self._cache_p, self._cache = None, None

    def g(self, v):
        return self.Fc + (self.Fs - self.Fc) * np.exp(-(abs(v) / self.vs) ** self.delta)

    def _windows(self, peak_speed, start_at_rest):
        v = self.vel
        n = len(v)
        sign = np.sign(v)
        # runs of one sign; each run's largest |v| is a peak when above peak_speed
        edges = np.flatnonzero(np.diff(sign)) + 1
        peaks = []
        for a, b in zip(np.r_[0, edges], np.r_[edges, n]):
            if sign[a] == 0:
                continue
            best = a + int(np.argmax(np.abs(v[a:b])))
            if abs(v[best]) > peak_speed and 0 < best < n - 1:
                peaks.append(best)
        windows, begin, rest = [], 0, start_at_rest
        for p in peaks:
            if p - begin >= 2:
                windows.append((begin, p, rest))
                begin, rest = p, False
        if n - 1 - begin >= 1:
            windows.append((begin, n - 1, rest))
        return windows

    def start(self):
        """sigma0 from the presliding (quasi-static loading from rest: x - x0 = -(Fs / sigma0)
        ln(1 - u / Fs), least-squares slope on |u| < Fs / 2 before the first sliding sample),
        sigma1 critical damping 2 sqrt(sigma0 M). Returns [log sigma0, log sigma1]."""
        a = np.abs(self.vel) > self.threshold
        ok = np.array([a[k - 2:k + 3].all() for k in range(2, len(a) - 2)])
        first = 2 + int(np.argmax(ok)) if ok.any() else len(a)
        u, dx = self.u[1:first], self.x[1:first] - self.x[0]
        stop = np.flatnonzero(np.abs(u) > 0.5 * self.Fs)
        if len(stop):
            u, dx = u[:stop[0]], dx[:stop[0]]
        y = -np.sign(u) * self.Fs * np.log1p(-np.abs(u) / self.Fs)
        s0 = np.dot(y, dx) / np.dot(dx, dx)
        return np.log([s0, 2.0 * np.sqrt(s0 * self.M)])

    def _window(self, p, w):
        """Simulates window w = (begin, end, at_rest) with sensitivities: returns residuals (um)
        for samples begin+1..end and their Jacobian to (log sigma0, log sigma1)."""
        b, e, rest = w
        s0, s1 = np.exp(p)
        M, s2, Fs, Fc, vs, dl = self.M, self.s2, self.Fs, self.Fc, self.vs, self.delta
        t, u = self.t[b:e + 1], self.u[b:e + 1]
        t0, du = t[0], np.diff(u) / self.dt

        def parts(tt, y):
            x, v, z = y[0], y[1], y[2]
            k = min(int((tt - t0) / self.dt), len(du) - 1)
            uu = u[k] + du[k] * (tt - t[k])
            av = abs(v)
            ex = np.exp(-(av / vs) ** dl)
            g = Fc + (Fs - Fc) * ex
            dg = -(Fs - Fc) * ex * dl * (av / vs) ** (dl - 1) * np.sign(v) / vs
            dz = v - s0 * av * z / g
            dz_dv = 1.0 - s0 * z * (np.sign(v) * g - av * dg) / g**2
            dz_dz = -s0 * av / g
            F = s0 * z + s1 * dz + s2 * v
            A = np.array([[0.0, 1.0, 0.0],
                          [0.0, -(s1 * dz_dv + s2) / M, -(s0 + s1 * dz_dz) / M],
                          [0.0, dz_dv, dz_dz]])
            dz_dq0 = -s0 * av * z / g
            fq = np.array([[0.0, 0.0],
                           [-(s0 * z + s1 * dz_dq0) / M, -s1 * dz / M],
                           [dz_dq0, 0.0]])
            return np.array([v, (uu - F) / M, dz]), A, fq

        def rhs(tt, y):
            f, A, fq = parts(tt, y)
            S = y[3:].reshape(3, 2, order="F")
            return np.concatenate([f, (A @ S + fq).ravel(order="F")])

        def jac(tt, y):
            # block diagonal: the sensitivities' own coupling to the state is left out (it only
            # slows the Newton iterations of the stiff solver, never changes the solution)
            _, A, _ = parts(tt, y)
            J = np.zeros((9, 9))
            for i in range(3):
                J[3 * i:3 * i + 3, 3 * i:3 * i + 3] = A
            return J

        v0 = 0.0 if rest else self.vel[b]
        z0 = 0.0 if v0 == 0.0 else np.sign(v0) * self.g(v0) / s0
        y0 = np.zeros(9)
        y0[:3] = [self.x[b], v0, z0]
        y0[5] = -z0  # d z0 / d log sigma0
        zs = self.Fc / s0
        atol = np.array([1e-10, 1e-10, 1e-10 * zs] * 3)
        sol = solve_ivp(rhs, (t[0], t[-1]), y0, method="LSODA", t_eval=t[1:], jac=jac, rtol=self.rtol, atol=atol)
        self.simulations += 1
        if not sol.success:
            raise RuntimeError(sol.message)
        r = (sol.y[0] - self.x[b + 1:e + 1]) / RESIDUAL_UNIT
        J = np.column_stack([sol.y[3], sol.y[6]]) / RESIDUAL_UNIT
        return r, J

    def _eval(self, p):
        if self._cache_p is None or not np.array_equal(p, self._cache_p):
            out = [self._window(p, w) for w in self.windows]
            self._cache_p = np.array(p, copy=True)
            self._cache = (np.concatenate([o[0] for o in out]), np.vstack([o[1] for o in out]))
        return self._cache

    def residuals(self, p):
        return self._eval(p)[0]

    def jacobian(self, p):
        return self._eval(p)[1]


def fit(t, u, x, rtol=1e-8, start=None, tol=1e-10):
    """Fits log sigma0, log sigma1. start: [sigma0, sigma1] or None (from the record); tol: ftol
    and xtol of least_squares (default frictionlab's Ceres settings).
    Returns ({sigma0, sigma1}, least_squares result, Problem)."""
    pr = Problem(t, u, x, rtol)
    p0 = pr.start() if start is None else np.log(start)
    r = least_squares(pr.residuals, p0, jac=pr.jacobian, method="trf", x_scale="jac", ftol=tol, xtol=tol,
                      gtol=1e-14)
    s0, s1 = np.exp(r.x)
    return {"sigma0": s0, "sigma1": s1}, r, pr


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--data", default=None)
    ap.add_argument("--rtol", type=float, default=1e-8)
    a = ap.parse_args()
    t, u, x = read_record(a.data) if a.data else simulate_record()
    sec, (params, r, pr) = best_of(lambda: fit(t, u, x, a.rtol), a.repeat)
    emit({"task": "lugre_fit", "seconds": sec, "parameters": params, "nfev": int(r.nfev), "njev": int(r.njev),
          "simulations": pr.simulations, "windows": len(pr.windows), "status": int(r.status), "rtol": a.rtol,
          "accuracy": lugre_accuracy(params)})


if __name__ == "__main__":
    main()
