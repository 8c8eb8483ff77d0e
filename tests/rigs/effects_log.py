#!/usr/bin/env python3
"""A ball-screw axis's log with load, temperature and position ripple, made without frictionlab.

The truth for tests of the idim terms `load`, `temperature` and `ripple`. A linear axis (mass M)
works against a measured load force L(t) (it acts on the axis, like the weight on a vertical
screw) and has friction
    F = (Fc + mu_load |L|) sign(v) + (Fv + Fv_per_K (T - T0)) v + a1 sin(2 pi q / P) + b1 cos(2 pi q / P),
the last two terms a ripple that repeats with position and acts whether the axis slides or sticks.
The grease warms with time (T from 20 to about 44 degC), not with the speed schedule. A PD loop
sampled at 1 kHz follows moves of several speeds over five ripple periods. The motion is
integrated here with a fixed step and an explicit stick rule (at rest while |u - L - ripple| is
within the Coulomb level at the current load), independently of the library's engine. The log is
what a drive records: jittered time stamps, a 1 um encoder, the motor current with coloured noise,
the load cell and the temperature sensor with noise; a header row.

Usage: effects_log.py OUT.csv [--seed N]
Columns: time (s), position (m), current (A), load (N), temperature (degC).
"""
import argparse
import math

import numpy as np

# The rig (SI).
M = 2.0                 # kg
FC, MU_LOAD = 3.0, 0.05  # N, dimensionless
FV, FV_PER_K, T0 = 20.0, -0.25, 30.0  # N s/m at T0 (degC), N s/m/K
P, A1, B1 = 0.02, 0.6, -0.4  # ripple period (m) and its sine and cosine amplitudes (N)
KT = 0.5                # N/A
KP, KD = 4.0e4, 400.0   # N/m, N s/m
TS = 1e-3               # controller period, s
H = 1e-4                # integration step, s (10 per controller period)
ENCODER = 1e-6          # m per count
COLUMNS = ("time", "position", "current", "load", "temperature")


def load(t):
    """The load force on the axis, N: between 5 and 55 N, slowly varying."""
    return 30.0 + 25.0 * np.sin(2 * np.pi * t / 7.0)


def temperature(t):
    """The grease temperature, degC: warming with time, independent of the speed."""
    return 20.0 + 25.0 * (1.0 - np.exp(-t / 15.0))


def reference(t):
    """Cosine moves of 20 to 100 mm at 10 to 200 mm/s both ways, with short rests."""
    moves = [(0.1, 0.05), (-0.1, 0.1), (0.06, 0.02), (-0.08, 0.15), (0.1, 0.2), (-0.04, 0.01),
             (-0.06, 0.08), (0.05, 0.03), (0.05, 0.12), (-0.1, 0.2), (0.1, 0.06), (-0.1, 0.04)]
    q, t0, out = 0.0, 0.2, np.zeros_like(t)
    for dist, speed in moves:
        dur = np.pi / 2 * abs(dist) / speed
        sel = t >= t0
        frac = np.clip((t[sel] - t0) / dur, 0.0, 1.0)
        out[sel] = q + dist * (1 - np.cos(np.pi * frac)) / 2
        q += dist
        t0 += dur + 0.15
    return out, t0


def ripple(q):
    return A1 * math.sin(2 * math.pi * q / P) + B1 * math.cos(2 * math.pi * q / P)


def simulate():
    """The motion at every integration step: times, position, velocity, drive force."""
    _, t_end = reference(np.array([0.0]))
    n = int(round(t_end / H))
    per_ctrl = int(round(TS / H))
    r_ctrl = reference(np.arange(0, n, per_ctrl) * H)[0]
    times = np.arange(n) * H
    loads, temps = load(times), temperature(times)
    q = v = u = q_prev_meas = 0.0
    qs, vs, us = np.empty(n), np.empty(n), np.empty(n)
    for k in range(n):
        if k % per_ctrl == 0:
            q_meas = round(q / ENCODER) * ENCODER
            v_est = (q_meas - q_prev_meas) / TS
            q_prev_meas = q_meas
            u = KP * (r_ctrl[k // per_ctrl] - q_meas) - KD * v_est
        L, T = loads[k], temps[k]
        level = FC + MU_LOAD * abs(L)
        net = u - L - ripple(q)  # what the friction level must hold or what drives the slide
        if v == 0.0:
            a = 0.0 if abs(net) <= level else (net - math.copysign(level, net)) / M
        else:
            a = (net - math.copysign(level, v) - (FV + FV_PER_K * (T - T0)) * v) / M
        v_new = v + H * a
        if v != 0.0 and (v_new > 0.0) != (v > 0.0):  # the velocity reaches zero within the step
            v_new = 0.0
        q += H * 0.5 * (v + v_new)
        v = v_new
        qs[k], vs[k], us[k] = q, v, u
    return times, qs, vs, us


def make_log(seed, motion=None, noise=True):
    """The drive's log for `seed` as a dict of columns (time s, position m, current A, load N,
    temperature degC); `motion`: simulate()'s output, which does not depend on the seed (the seed
    draws only the time jitter and the sensors' noise), to reuse across seeds. noise=False: no
    time jitter and no sensor noise (the encoder's counts stay), the systematic part of a fit."""
    rng = np.random.default_rng(seed)
    scale = 1.0 if noise else 0.0
    t, q, _, u = simulate() if motion is None else motion
    grid = np.arange(0.0, t[-1] - 2e-3, 1e-3)
    ts = grid + scale * rng.uniform(-0.05e-3, 0.05e-3, grid.size)
    ts[0] = 0.0
    idx = np.clip(np.round(ts / H).astype(int), 0, t.size - 1)
    q_log = np.round(q[idx] / ENCODER) * ENCODER
    e = scale * rng.normal(0.0, 0.03, idx.size)  # A; first-order coloured, correlation time about 20 samples
    i_noise = np.zeros_like(e)
    for k in range(1, e.size):
        i_noise[k] = 0.95 * i_noise[k - 1] + math.sqrt(1 - 0.95 ** 2) * e[k]
    i_log = u[idx] / KT + i_noise
    load_log = load(t[idx]) + scale * rng.normal(0.0, 0.2, idx.size)        # N, load cell noise
    temp_log = temperature(t[idx]) + scale * rng.normal(0.0, 0.05, idx.size)  # degC, sensor noise
    return {"time": ts, "position": q_log, "current": i_log, "load": load_log, "temperature": temp_log}


def write_csv(path, log):
    """Writes make_log()'s columns with a header row."""
    cols = np.column_stack([log[k] for k in COLUMNS])
    np.savetxt(path, cols, delimiter=",", fmt="%.9g", header=",".join(COLUMNS), comments="")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    write_csv(a.out, make_log(a.seed))


if __name__ == "__main__":
    main()
