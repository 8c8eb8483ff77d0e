#!/usr/bin/env python3
"""A servo axis's log, made without frictionlab: the truth for tests of identification.

A linear axis (mass M) with Stribeck friction, held by a PD position loop sampled at 500 Hz,
follows moves in both directions at several speeds. The motion is integrated here with a fine
fixed step and an explicit stick rule (the axis stays at rest while the applied force is within
the static level), independently of the library's engine. The log is what a drive records: time
stamps with jitter, a 1 um encoder, the motor current with noise, no header row.

Usage: servo_log.py OUT.csv [--seed N] [--law stribeck|coulomb-viscous] [--noise white|coloured]
Columns (no header): t, q, q_ref, v_est, i, u_cmd, then six status columns.
"""
import argparse
import math

import numpy as np

# The rig (SI): 2 kg axis, Stribeck friction, motor constant kt.
M = 2.0
FC, FS, VS, FV = 3.0, 4.5, 0.01, 20.0
KT = 0.5              # N/A
KP, KD = 2.0e4, 300.0  # N/m, N s/m: about 16 Hz position bandwidth
TS = 1.0 / 500.0      # controller period, s
H = 2e-5              # integration step, s (100 per controller period)
LOG_DT = 1e-3         # nominal log period, s
ENCODER = 1e-6        # m per count


def reference(t):
    """Moves of 5 to 40 mm at 5 to 100 mm/s both ways, with rests: smooth (cosine) profiles."""
    moves = [(0.02, 0.005), (-0.03, 0.01), (0.04, 0.05), (-0.04, 0.1), (0.03, 0.02), (-0.02, 0.003),
             (0.01, 0.03), (-0.01, 0.008)]
    q, t0, out = 0.0, 0.3, np.zeros_like(t)
    for dist, speed in moves:
        dur = np.pi / 2 * abs(dist) / speed  # peak speed of a cosine move = speed
        sel = (t >= t0)
        frac = np.clip((t[sel] - t0) / dur, 0.0, 1.0)
        out[sel] = q + dist * (1 - np.cos(np.pi * frac)) / 2
        q += dist
        t0 += dur + 0.3
    return out, t0


def simulate(law):
    """The motion at every integration step: times, position, velocity, drive force."""
    _, t_end = reference(np.array([0.0]))
    n = int(round(t_end / H))
    per_ctrl = int(round(TS / H))
    r_ctrl = reference(np.arange(0, n, per_ctrl) * H)[0]  # the reference at the controller's instants
    q = v = u = q_prev_meas = 0.0
    qs, vs, us = np.empty(n), np.empty(n), np.empty(n)
    stribeck = law == "stribeck"
    for k in range(n):
        if k % per_ctrl == 0:  # the controller samples the encoder and updates the command
            q_meas = round(q / ENCODER) * ENCODER
            v_est = (q_meas - q_prev_meas) / TS
            q_prev_meas = q_meas
            u = KP * (r_ctrl[k // per_ctrl] - q_meas) - KD * v_est
        if v == 0.0:
            # stuck while the drive is within the static level; otherwise breaking away
            a = 0.0 if abs(u) <= FS else (u - math.copysign(FS, u)) / M
        else:
            f = FC + (FS - FC) * math.exp(-(v / VS) ** 2) if stribeck else FC
            a = (u - math.copysign(f, v) - FV * v) / M
        v_new = v + H * a
        if v != 0.0 and (v_new > 0.0) != (v > 0.0):  # the velocity reaches zero within the step: stop
            v_new = 0.0
        q += H * 0.5 * (v + v_new)
        v = v_new
        qs[k], vs[k], us[k] = q, v, u
    return np.arange(n) * H, qs, vs, us


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--law", choices=["stribeck", "coulomb-viscous"], default="stribeck")
    ap.add_argument("--noise", choices=["white", "coloured"], default="white")
    a = ap.parse_args()
    rng = np.random.default_rng(a.seed)
    t, q, v, u = simulate(a.law)
    # Log samples at jittered instants around a 1 ms grid.
    grid = np.arange(0.0, t[-1] - 2 * LOG_DT, LOG_DT)
    ts = grid + rng.uniform(-0.1e-3, 0.1e-3, grid.size)
    ts[0] = 0.0
    idx = np.clip(np.round(ts / H).astype(int), 0, t.size - 1)
    q_log = np.round(q[idx] / ENCODER) * ENCODER
    i_true = u[idx] / KT
    if a.noise == "white":
        i_noise = rng.normal(0.0, 0.02, idx.size)
    else:  # first-order coloured noise, correlation time about 20 samples
        e = rng.normal(0.0, 0.02, idx.size)
        i_noise = np.zeros_like(e)
        for k in range(1, e.size):
            i_noise[k] = 0.95 * i_noise[k - 1] + np.sqrt(1 - 0.95 ** 2) * e[k]
    i_log = i_true + i_noise
    r_log, _ = reference(ts)
    v_est = np.gradient(q_log, ts)
    status = np.tile(np.arange(6), (idx.size, 1))
    cols = np.column_stack([ts, q_log, r_log, v_est, i_log, u[idx], status])
    np.savetxt(a.out, cols, delimiter=",", fmt="%.9g")


if __name__ == "__main__":
    main()
