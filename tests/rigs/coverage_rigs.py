#!/usr/bin/env python3
"""Synthetic drive logs with known friction, made with numpy alone: the truth for the coverage of
idim's standard deviations. Independent of frictionlab's simulator (as servo_log.py).

A linear axis of mass M with friction F(v) and a constant offset force moves along a smooth
multisine (random phases per seed, 0.1 to 1.5 Hz, peak speed about 0.15 m/s). The log is what a
drive records at the rate `fs`: the applied force (gain times current) with noise, and the
position of a 1 um encoder or a velocity with white noise.

- open loop: the axis follows the trajectory exactly; the force is the inverse dynamics
  M qdd + F(qd) + offset, the noise is on the recorded current only (a measurement error);
- closed loop: a PD position loop with velocity feedforward, sampled at fs, drives the axis
  (explicit stick rule at v = 0, four integration steps per sample); the noise is a force that
  acts on the axis and is not recorded (current ripple, a disturbance), so the loop reacts to it
  and the recorded force is correlated with the motion's errors: least squares is biased there.
  The closed loop's log also holds what IDIM-IV needs to simulate it: the reference position
  ("reference", m) and the drive's feedforward ("feedforward", N: the model-based feedforward plus
  KD times the reference velocity), so that the force is u = feedforward + KP (reference - q) -
  KD v, a PD on the position with Kp = KP, Kd = KD.
  Timing (timing="centre", the default): at t_k the drive reads the encoder and the velocity, and
  applies u_k at once, held until t_{k+1}: the sampled PID with no delay that IDIM-IV simulates
  (--controller pid, control delay 0). The log's position is latched at the centre of the hold,
  t_k + 1/(2 fs): the second difference that IDIM takes there weighs the held forces 1/8, 3/4,
  1/8 around u_k, so the recorded force and the acceleration are not shifted against each other.
  timing="end" is the earlier rig: the position recorded at the hold's end (t_{k+1}, half a sample
  after the force's centre) and the velocity feedback from the encoder's backward difference; its
  recorded force and acceleration are half a sample apart, which biases M by about -2 %
  (docs/coverage.md).

Noise: white, or AR(1) with a correlation time of 20 ms (whatever the rate: coefficient
exp(-1/(fs 0.02))), standard deviation NOISE_STD either way.

Friction kinds: "coulomb-viscous" (Fc sign(v) + Fv v), "stribeck" (Fc + (Fs - Fc) exp(-(v/vs)^2),
plus Fv v), "asymmetric" (Fc_pos, Fv_pos for v > 0; Fc_neg, Fv_neg for v < 0). The truth of each
kind is named as idim names its parameters (truth()).
"""
import math

import numpy as np

M = 2.0             # kg
FC, FV = 3.0, 20.0  # N, N s/m
FS, VS = 4.5, 0.01  # N, m/s (stribeck)
FC_POS, FV_POS, FC_NEG, FV_NEG = 3.0, 20.0, 2.2, 26.0
OFFSET = 0.5        # N (not in the asymmetric model: idim's asymmetric terms absorb it)
NOISE_STD = 0.3     # N, the force noise (about 5 % of the force's rms)
NOISE_TAU = 0.02    # s, correlation time of the AR(1) noise
ENCODER = 1e-6      # m per count
VELOCITY_NOISE = 2e-4  # m/s, std of a velocity sensor's white noise (a good tachometer: 0.13 % of the peak speed)
DURATION = 12.0     # s
KP, KD = 4.0e4, 400.0  # N/m, N s/m: the closed loop's PD (about 20 Hz)


def truth(kind):
    """The parameters idim reports for `kind`, by name (SI)."""
    if kind == "coulomb-viscous":
        return {"M": M, "Fv": FV, "Fc": FC, "offset": OFFSET}
    if kind == "stribeck":
        return {"M": M, "Fv": FV, "Fc": FC, "offset": OFFSET, "Fs_minus_Fc": FS - FC}
    if kind == "asymmetric":
        return {"M": M, "Fv_pos": FV_POS, "Fc_pos": FC_POS, "Fv_neg": FV_NEG, "Fc_neg": FC_NEG}
    raise ValueError(f"unknown kind {kind!r}")


def friction(kind, v):
    """Friction force (N) against the velocity v (m/s), elementwise; sign(0) = 0."""
    s = np.sign(v)
    if kind == "coulomb-viscous":
        return FC * s + FV * v
    if kind == "stribeck":
        return (FC + (FS - FC) * np.exp(-(v / VS) ** 2)) * s + FV * v
    if kind == "asymmetric":
        return np.where(v > 0, FC_POS + FV_POS * v, 0.0) + np.where(v < 0, -FC_NEG + FV_NEG * v, 0.0)
    raise ValueError(f"unknown kind {kind!r}")


def static_level(kind):
    """The force (N) a stuck axis holds before it breaks away (closed loop's stick rule)."""
    return FS if kind == "stribeck" else FC_POS if kind == "asymmetric" else FC


def trajectory(t, rng):
    """Multisine position (m), velocity, acceleration at times t: five tones, random phases."""
    freqs = np.array([0.1, 0.23, 0.47, 0.83, 1.5])
    amps = 0.15 / (2 * np.pi * freqs) / len(freqs) * 1.6  # peak speed about 0.15 m/s
    ph = rng.uniform(0, 2 * np.pi, freqs.size)
    w = 2 * np.pi * freqs
    arg = np.outer(t, w) + ph
    q = (np.sin(arg) - np.sin(ph)) @ amps
    qd = np.cos(arg) @ (amps * w)
    qdd = -np.sin(arg) @ (amps * w * w)
    return q, qd, qdd


def noise(kind, n, fs, rng):
    """n samples of force noise (N) at rate fs (Hz): 'white' or 'ar1' (correlation time NOISE_TAU)."""
    e = rng.normal(0.0, NOISE_STD, n)
    if kind == "white":
        return e
    from scipy.signal import lfilter

    phi = math.exp(-1.0 / (fs * NOISE_TAU))
    # starts in the stationary distribution: y[0] = sqrt(1 - phi^2) e[0] + phi z, z ~ N(0, NOISE_STD^2)
    y, _ = lfilter([math.sqrt(1 - phi * phi)], [1.0, -phi], e, zi=[phi * rng.normal(0.0, NOISE_STD)])
    return y


def friction_scalar(kind, v):
    """friction() for one velocity (the closed loop's inner step)."""
    if v == 0.0:
        return 0.0
    s = 1.0 if v > 0 else -1.0
    if kind == "coulomb-viscous":
        return FC * s + FV * v
    if kind == "stribeck":
        return (FC + (FS - FC) * math.exp(-(v / VS) ** 2)) * s + FV * v
    return FC_POS + FV_POS * v if v > 0 else -FC_NEG + FV_NEG * v


def closed_loop(kind, t, q_ref, qd_ref, qdd_ref, disturbance, timing="centre"):
    """The PD loop with feedforward (inverse dynamics of the reference, with the true friction's
    smooth part) at the log's sampling; returns position, velocity, recorded force and the
    feedforward force (N: everything in the force that depends on the reference's derivatives).
    timing: "centre" or "end" (the module's docstring)."""
    if timing not in ("centre", "end"):
        raise ValueError(f"unknown timing {timing!r}")
    n = t.size
    dt = t[1] - t[0]
    sub = 4
    h = dt / sub
    fstat = static_level(kind)
    q = q_ref[0]
    v = 0.0
    qs, vs, us = np.empty(n), np.empty(n), np.empty(n)
    ff = M * qdd_ref + friction(kind, qd_ref) + OFFSET * (kind != "asymmetric")
    q_prev = round(q / ENCODER) * ENCODER
    for k in range(n):
        q_meas = round(q / ENCODER) * ENCODER
        v_est = (q_meas - q_prev) / dt
        q_prev = q_meas
        v_fb = v if timing == "centre" else v_est
        u = ff[k] + KP * (q_ref[k] - q_meas) + KD * (qd_ref[k] - v_fb)
        applied = u + disturbance[k] - (OFFSET if kind != "asymmetric" else 0.0)
        for j in range(sub):
            if v == 0.0:
                a = 0.0 if abs(applied) <= fstat else (applied - math.copysign(fstat, applied)) / M
            else:
                a = (applied - friction_scalar(kind, v)) / M
            v_new = v + h * a
            if v != 0.0 and (v_new > 0.0) != (v > 0.0):
                v_new = 0.0
            q += h * 0.5 * (v + v_new)
            v = v_new
            if timing == "centre" and j + 1 == sub // 2:
                qs[k], vs[k] = q, v  # latched at the centre of the hold
        if timing == "end":
            qs[k], vs[k] = q, v
        us[k] = u
    return qs, vs, us, ff + KD * qd_ref


def make_log(kind, noise_kind, sensor, fs, loop, seed, duration=DURATION, velocity_noise=VELOCITY_NOISE,
             timing="centre"):
    """One log: dict(time, force, position or velocity) and the truth (truth(kind)); a velocity
    sensor's white noise has the standard deviation `velocity_noise` (m/s); `timing`: the closed
    loop's (closed_loop)."""
    rng = np.random.default_rng(seed)
    t = np.arange(int(round(duration * fs))) / fs
    q, qd, qdd = trajectory(t, rng)
    w = noise(noise_kind, t.size, fs, rng)
    offset = OFFSET if kind != "asymmetric" else 0.0
    if loop == "open":
        force = M * qdd + friction(kind, qd) + offset + w
        pos, vel = q, qd
    elif loop == "closed":
        pos, vel, force, feedforward = closed_loop(kind, t, q, qd, qdd, w, timing)
    else:
        raise ValueError(f"unknown loop {loop!r}")
    log = {"time": t, "force": force}
    if loop == "closed":
        log["reference"], log["feedforward"] = q, feedforward
    if sensor == "position":
        log["position"] = np.round(pos / ENCODER) * ENCODER
    elif sensor == "velocity":
        log["velocity"] = vel + rng.normal(0.0, velocity_noise, t.size)
    else:
        raise ValueError(f"unknown sensor {sensor!r}")
    return log, truth(kind)
