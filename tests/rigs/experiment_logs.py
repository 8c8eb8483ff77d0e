#!/usr/bin/env python3
"""Logs of the experiments that are not trajectories, made without frictionlab: the truth for
tests of `identify auto` and of the method that fits each experiment.

One linear axis (SI units) whose motion is integrated here with a fine fixed step and an
explicit stick rule, independently of the library's engine, and logged as a drive logs it: time
stamps jittered around a 1 kHz grid (so `--resample` is needed), a quantised encoder, the
velocity as the encoder's difference (so it is noisiest, relative to the speed, at the slowest
speeds), the motor current with white noise and an offset (the current sensor's), no header
row, 12 columns selected by number:

  c1 t (s), c2 q (m), c3 q_ref (m), c4 v_est (m/s), c5 i (A), c6 i_cmd (A), c7..c12 status words

Experiments (`--experiment`):
  decay       a 2 kg mass on an 800 N/m spring released from 20 mm, the drive off (the current
              is its sensor's offset and noise): Fc 0.4 N, Fv 0.8 N s/m
  breakaway   a force ramped from rest to 1.6 Fs in 2 s, held 1 s, ramped back, then the same
              negative: Fs 4.5 N, Fc 3 N, Fv 20 N s/m
  presliding  LuGre bristles (sigma0 1e5 N/m, sigma1 2 sqrt(sigma0 M), Fc 3 N, Fs 4.5 N,
              vs 0.01 m/s) under a force ramped to 0.9 Fs in 6 s and held 2 s; 0.05 um encoder
  sweep       constant speeds 2 to 200 mm/s both ways, 2 s each, under a velocity loop; the
              current is what the loop drove (Fs 4.5 N, Fc 3 N, vs 0.01 m/s, Fv 20 N s/m)
`--law coulomb-viscous` (decay) or `--law static-coulomb-viscous` (breakaway) is the model the
method fits; `--law stribeck` adds a Stribeck rise at low speed that the method lacks (decay:
to 1.2 N below 0.05 m/s; breakaway: Fc + (Fs - Fc) exp(-(v/vs)^2), `--vs`) or fits (sweep). The
current offset (`--offset`, A; 0.2 A by default) enters the force of breakaway and sweep as a
constant force KT * offset, which neither method has a term for.

Usage: experiment_logs.py OUT.csv --experiment decay|breakaway|presliding|sweep [--law LAW]
       [--seed N] [--offset A] [--vs M_PER_S]
"""
import argparse
import math

import numpy as np

M = 2.0                  # kg
KT = 0.5                 # N/A
LOG_DT = 1e-3            # nominal log period, s
JITTER = 0.1e-3
ENCODER = 1e-6
CURRENT_NOISE = 0.02     # A (white), 0.01 N
FC, FS, VS, FV = 3.0, 4.5, 0.01, 20.0          # breakaway, sweep, presliding
SPRING, DECAY_FC, DECAY_FV, X0 = 800.0, 0.4, 0.8, 0.02  # decay: N/m, N, N s/m, m
DECAY_FS, DECAY_VS = 1.2, 0.05                 # decay's Stribeck rise: N, m/s
SIGMA0 = 1.0e5                                  # N/m
SIGMA1 = 2 * math.sqrt(SIGMA0 * M)              # N s/m: critically damped bristles


def stribeck(v, fc, fs, vs):
    return fc + (fs - fc) * math.exp(-(v / vs) ** 2)


def decay(law, h=2e-5, duration=4.0):
    """Spring-mass released from X0 at rest; sticks when |k x| <= static level at v = 0."""
    n = int(round(duration / h))
    q, v = X0, 0.0
    qs, fs = np.empty(n), np.zeros(n)
    static = DECAY_FS if law == "stribeck" else DECAY_FC
    for k in range(n):
        spring = -SPRING * q
        if v == 0.0 and abs(spring) <= static:
            a = 0.0
        else:
            s = math.copysign(1.0, v) if v != 0.0 else math.copysign(1.0, spring)
            level = stribeck(v, DECAY_FC, DECAY_FS, DECAY_VS) if law == "stribeck" else DECAY_FC
            a = (spring - s * level - DECAY_FV * v) / M
        v_new = v + h * a
        if v != 0.0 and (v_new > 0.0) != (v > 0.0):
            v_new = 0.0
        q += h * v_new  # symplectic Euler: no drift of the oscillation's energy
        v = v_new
        qs[k] = q
    return np.arange(n) * h, qs, fs


def breakaway(law, h=2e-5):
    """Trapezoids of force, positive then negative, from rest; stick rule at the static level."""
    ramp, hold, rest = 2.0, 1.0, 0.5
    level = 1.6 * FS
    period = 2 * ramp + hold + rest

    def force(t):
        s = 1.0 if t < period else -1.0
        t = t % period
        if t < ramp:
            return s * level * t / ramp
        if t < ramp + hold:
            return s * level
        if t < 2 * ramp + hold:
            return s * level * (1 - (t - ramp - hold) / ramp)
        return 0.0

    n = int(round(2 * period / h))
    q = v = 0.0
    qs, us = np.empty(n), np.empty(n)
    for k in range(n):
        u = force(k * h)
        if v == 0.0 and abs(u) <= FS:
            a = 0.0
        else:
            s = math.copysign(1.0, v) if v != 0.0 else math.copysign(1.0, u)
            level_v = stribeck(v, FC, FS, VS) if law == "stribeck" else FC
            a = (u - s * level_v - FV * v) / M
        v_new = v + h * a
        if v != 0.0 and (v_new > 0.0) != (v > 0.0):
            v_new = 0.0
        q += h * v_new  # symplectic Euler: no drift of the oscillation's energy
        v = v_new
        qs[k], us[k] = q, u
    return np.arange(n) * h, qs, us


def presliding(h=1e-5):
    """LuGre with a slow force ramp: the bristles deflect, the axis never slides."""
    ramp, hold = 6.0, 2.0
    n = int(round((ramp + hold) / h))
    q = v = z = 0.0
    qs, us = np.empty(n), np.empty(n)
    for k in range(n):
        t = k * h
        u = 0.9 * FS * min(t / ramp, 1.0)
        g = stribeck(v, FC, FS, VS)
        zd = v - SIGMA0 * abs(v) / g * z
        f = SIGMA0 * z + SIGMA1 * zd + FV * v
        v += h * (u - f) / M
        q += h * v
        z += h * zd
        qs[k], us[k] = q, u
    return np.arange(n) * h, qs, us


def sweep_profile(t):
    """Velocity reference: levels 2..200 mm/s up, then the same negative, 2 s each with 0.3 s
    smooth transitions; starts and ends at rest."""
    levels = [0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2]
    seq = [0.0] + levels + [0.0] + [-x for x in levels] + [0.0]
    dur, tr = 2.0, 0.3
    i = min(int(t // dur), len(seq) - 1)
    tau = t - i * dur
    if tau < tr and i > 0:
        w = 0.5 - 0.5 * math.cos(math.pi * tau / tr)
        return seq[i - 1] + w * (seq[i] - seq[i - 1]), len(seq) * dur
    return seq[i], len(seq) * dur


def sweep(h=2e-5):
    """A PI velocity loop (1 kHz) drives the axis along the profile: its force is the log's."""
    _, duration = sweep_profile(0.0)
    n = int(round(duration / h))
    per = int(round(LOG_DT / h))
    kp, ki = 400.0, 2.0e4  # N s/m, N/m
    q = v = integ = u = 0.0
    q_prev = 0.0
    qs, us, rs = np.empty(n), np.empty(n), np.empty(n)
    for k in range(n):
        t = k * h
        r, _ = sweep_profile(t)
        if k % per == 0:
            qm = round(q / ENCODER) * ENCODER
            v_meas = (qm - q_prev) / LOG_DT if k > 0 else 0.0
            q_prev = qm
            e = r - v_meas
            integ += e * LOG_DT
            u = kp * e + ki * integ
        if v == 0.0 and abs(u) <= FS:
            a = 0.0
        else:
            s = math.copysign(1.0, v) if v != 0.0 else math.copysign(1.0, u)
            a = (u - s * stribeck(v, FC, FS, VS) - FV * v) / M
        v_new = v + h * a
        if v != 0.0 and (v_new > 0.0) != (v > 0.0):
            v_new = 0.0
        q += h * v_new  # symplectic Euler: no drift of the oscillation's energy
        v = v_new
        qs[k], us[k], rs[k] = q, u, r
    return np.arange(n) * h, qs, us, rs


def main():
    global VS
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--experiment", choices=["decay", "breakaway", "presliding", "sweep"], required=True)
    ap.add_argument("--law", choices=["coulomb-viscous", "static-coulomb-viscous", "stribeck"], default=None)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--offset", type=float, default=0.2, help="current sensor offset, A")
    ap.add_argument("--vs", type=float, default=VS, help="Stribeck velocity of breakaway, sweep and presliding, m/s")
    a = ap.parse_args()
    VS = a.vs
    rng = np.random.default_rng(a.seed)
    encoder = ENCODER
    ref = None
    if a.experiment == "decay":
        t, q, u = decay(a.law or "coulomb-viscous")
    elif a.experiment == "breakaway":
        t, q, u = breakaway(a.law or "static-coulomb-viscous")
    elif a.experiment == "presliding":
        t, q, u = presliding()
        encoder = 0.05e-6  # an interferometer: the bristles deflect some 40 um
    else:
        t, q, u, ref = sweep()
    h = t[1] - t[0]
    grid = np.arange(0.0, t[-1] - 2 * LOG_DT, LOG_DT)
    ts = grid + rng.uniform(-JITTER, JITTER, grid.size)
    ts[0] = 0.0
    idx = np.clip(np.round(ts / h).astype(int), 0, t.size - 1)
    q_log = np.round(q[idx] / encoder) * encoder
    v_est = np.gradient(q_log, ts)
    i_cmd = u[idx] / KT
    i_log = i_cmd + a.offset + rng.normal(0.0, CURRENT_NOISE, idx.size)
    q_ref = np.zeros_like(ts) if ref is None else np.cumsum(ref[idx]) * LOG_DT
    status = np.tile(np.arange(6), (idx.size, 1))
    cols = np.column_stack([ts, q_log, q_ref, v_est, i_log, i_cmd, status])
    np.savetxt(a.out, cols, delimiter=",", fmt="%.10g")


if __name__ == "__main__":
    main()
