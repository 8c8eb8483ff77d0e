"""Shared pieces of the peer benchmarks (bench/peers/*.py) and bench/compare: timing, the problem
definitions both sides solve, and the accuracy figures both sides are scored with.
Run everything with /usr/bin/python3 (Debian's numpy 1.24 and scipy 1.10)."""
import json
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.abspath(os.path.join(HERE, "..", ".."))

# ---- Canudas de Wit et al. 1995, Table I, stick-slip with a spring pulled at V0 ---------------
CANUDAS = dict(s0=1e5, s1=np.sqrt(1e5), s2=0.4, Fc=1.0, Fs=1.5, vs=0.001, m=1.0, k=2.0, V0=0.1, T=30.0, rate=1000.0)
# frictionlab's atol on a bristle state is atol * z_scale, z_scale = Fc / sigma0 (the largest
# steady deflection at 1 m/s); the peers use the same vector of absolute tolerances.
CANUDAS_ZSCALE = CANUDAS["Fc"] / CANUDAS["s0"]

# ---- Craig's DC motor, torque mode, trapezoid current (examples/craig_motor_trapezoid.yaml) -----
CRAIG = dict(J=1.06e-6, Kt=0.0141, Fs=0.0015, Fc=0.0012, B=2.85e-6, level=0.15, rate=0.003, hold=30.0, T=140.0, rate_out=100.0)

# ---- Stribeck fit data: a small DC motor's map (N m, rad/s), noisy -------------------------------
STRIBECK_TRUTH = dict(Fc=0.02, Fs=0.035, vs=0.8, delta=1.6, Fv=1.5e-4)


def best_of(fn, repeat, min_total=0.0):
    """Runs fn() `repeat` times (more while the total is below min_total s); returns (best s, last result)."""
    best, out, total, n = float("inf"), None, 0.0, 0
    while n < repeat or total < min_total:
        t0 = time.perf_counter()
        out = fn()
        dt = time.perf_counter() - t0
        best, total, n = min(best, dt), total + dt, n + 1
    return best, out


def emit(obj):
    json.dump(obj, sys.stdout, indent=1, default=float)
    sys.stdout.write("\n")


# ---- stick-slip figures ----------------------------------------------------------------------
def stick_slip_figures(t, v):
    """Period (mean spacing of velocity peaks after the first cycle, as tests/simulate/
    canudas_reference.py) and peak slip velocity."""
    t, v = np.asarray(t), np.asarray(v)
    i = np.arange(1, len(v) - 1)
    idx = i[(v[i] >= v[i - 1]) & (v[i] > v[i + 1]) & (v[i] > 0.5 * v.max())]
    peaks = t[idx]
    period = float(np.mean(np.diff(peaks[1:]))) if len(peaks) > 2 else float("nan")
    return period, float(v.max())


def trajectory_accuracy(t, x, v, ref):
    """Errors of a sampled Canudas trajectory against the reference dict (t, x, v, period, peak)."""
    assert len(t) == len(ref["t"]) and np.allclose(t, ref["t"], rtol=0, atol=1e-9), "grids differ"
    period, peak = stick_slip_figures(t, v)
    return {
        "max_abs_dv": float(np.max(np.abs(np.asarray(v) - ref["v"]))),
        "max_abs_dx": float(np.max(np.abs(np.asarray(x) - ref["x"]))),
        "period": period,
        "peak": peak,
        "period_rel_err": abs(period - ref["period"]) / ref["period"],
        "peak_rel_err": abs(peak - ref["peak"]) / ref["peak"],
    }


# ---- Craig motor: exact solution -------------------------------------------------------------
def craig_current(t):
    c = CRAIG
    t1 = c["level"] / c["rate"]
    t2 = t1 + c["hold"]
    t3 = t2 + c["level"] / c["rate"]
    t = np.asarray(t, dtype=float)
    return np.where(t < t1, c["rate"] * t, np.where(t < t2, c["level"], np.where(t < t3, c["level"] - c["rate"] * (t - t2), 0.0)))


def craig_exact():
    """Closed form of the motor: while sliding forward J w' = Kt i(t) - Fc - B w with i piecewise
    linear, so w = w_p(t) + (w(t0) - w_p(t0)) exp(-(t - t0) B / J) on each piece, w_p linear.
    Returns breakaway time, speed at the end of the hold, stop time, and w(t) as a function."""
    c = CRAIG
    J, Kt, Fs, Fc, B, r = c["J"], c["Kt"], c["Fs"], c["Fc"], c["B"], c["rate"]
    t1 = c["level"] / r
    t2 = t1 + c["hold"]
    tb = Fs / (Kt * r)
    # pieces (t_start, slope of Kt i, value of Kt i at t_start)
    pieces = [(tb, Kt * r, Kt * r * tb), (t1, 0.0, Kt * c["level"]), (t2, -Kt * r, Kt * c["level"])]

    def piece_w(t0, a1, a0, w0, t):
        # J w' = a0 + a1 (t - t0) - Fc - B w ; particular w_p = p1 (t - t0) + p0
        p1 = a1 / B
        p0 = (a0 - Fc - J * p1) / B
        return p1 * (t - t0) + p0 + (w0 - p0) * np.exp(-(t - t0) * B / J)

    w_at = [0.0]
    ends = [t1, t2, None]
    for (t0, a1, a0), te in zip(pieces[:2], ends[:2]):
        w_at.append(piece_w(t0, a1, a0, w_at[-1], te))
    from scipy.optimize import brentq

    t0, a1, a0 = pieces[2]
    ts = brentq(lambda t: piece_w(t0, a1, a0, w_at[2], t), t2 + 1e-9, t2 + c["level"] / r, xtol=1e-14, rtol=1e-15)

    def w(t):
        t = np.asarray(t, dtype=float)
        out = np.zeros_like(t)
        for k, ((p0, a1_, a0_), hi) in enumerate(zip(pieces, [t1, t2, ts])):
            m = (t >= p0) & (t < hi)
            out[m] = piece_w(p0, a1_, a0_, w_at[k], t[m])
        return out

    return {"breakaway": tb, "hold_speed": float(w_at[2]), "stop": ts, "w": w}


def craig_accuracy(t, w, breakaway, stop):
    ex = craig_exact()
    t = np.asarray(t)
    return {
        "breakaway_abs_err_s": abs(breakaway - ex["breakaway"]),
        "stop_abs_err_s": abs(stop - ex["stop"]),
        "max_abs_dw": float(np.max(np.abs(np.asarray(w) - ex["w"](t)))),
    }


# ---- Stribeck data ---------------------------------------------------------------------------
def stribeck_law(p, v):
    Fc, dF, vs, delta, Fv = p
    a = np.abs(v)
    return np.sign(v) * (Fc + dF * np.exp(-(a / vs) ** delta)) + Fv * v


def stribeck_data(n=100_000, seed=1):
    """n points, speeds log-uniform in [0.3, 300] rad/s in both directions, noise 1 % of Fc."""
    tr = STRIBECK_TRUTH
    rng = np.random.default_rng(seed)
    v = 300.0 * 10.0 ** rng.uniform(-3.0, 0.0, n) * np.where(rng.uniform(size=n) < 0.5, -1.0, 1.0)
    p = [tr["Fc"], tr["Fs"] - tr["Fc"], tr["vs"], tr["delta"], tr["Fv"]]
    f = stribeck_law(p, v) + 0.01 * tr["Fc"] * rng.standard_normal(n)
    return v, f


def stribeck_accuracy(params):
    """Largest relative error of the fitted (Fc, Fs, vs, delta, Fv) against the truth, and each."""
    errs = {k: abs(params[k] - STRIBECK_TRUTH[k]) / abs(STRIBECK_TRUTH[k]) for k in STRIBECK_TRUTH}
    return {"max_param_rel_err_vs_truth": max(errs.values()), "param_rel_err_vs_truth": errs}


# ---- LuGre output-error fit (tests/identify/test_lugre.cpp) ----------------------------------
# Canudas de Wit 1995 Table I on a unit mass; the static part is given to both sides, the fit is
# of sigma0 and sigma1 only.
LUGRE = dict(s0=1e5, s1=np.sqrt(1e5), s2=0.4, Fc=1.0, Fs=1.5, vs=0.001, delta=2.0, M=1.0, T=10.0, rate=1000.0)


def lugre_input_table():
    """Corners (s, N) of the applied force, linear in between: a ramp to 0.95 Fs and back (0..4 s,
    presliding), then a sine of amplitude 2 Fs at 0.5 Hz with corners every 20 ms (4..10 s)."""
    Fs = LUGRE["Fs"]
    times, values = [0.0, 2.0, 4.0], [0.0, 0.95 * Fs, 0.0]
    for i in range(1, 301):
        t = 4.0 + 0.02 * i
        times.append(round(t, 6))
        values.append(2 * Fs * np.sin(np.pi * (t - 4.0)))
    return np.array(times), np.array(values)


def lugre_scenario_yaml(path):
    """The experiment as a frictionlab scenario file (for `frictionlab simulate`)."""
    L = LUGRE
    times, values = lugre_input_table()
    with open(path, "w") as f:
        f.write("description: Canudas de Wit 1995 Table I, presliding then sliding (bench lugre_fit)\n")
        f.write(f"plant:\n  type: axis\n  M: {L['M']!r}\n")
        f.write(f"friction:\n  law: lugre\n  sigma0: {L['s0']!r}\n  sigma1: {float(L['s1'])!r}\n  sigma2: {L['s2']!r}\n"
                f"  Fc: {L['Fc']!r}\n  Fs: {L['Fs']!r}\n  vs: {L['vs']!r}\n")
        f.write("input:\n  type: table\n  times: [%s]\n  values: [%s]\n" %
                (", ".join(repr(float(t)) for t in times), ", ".join(repr(float(v)) for v in values)))
        f.write(f"duration: {L['T']!r}\noutput_rate: {L['rate']!r}\n")


def lugre_accuracy(params):
    """Relative errors of the fitted sigma0, sigma1 against Table I, and the larger."""
    errs = {"sigma0": float(abs(params["sigma0"] - LUGRE["s0"]) / LUGRE["s0"]),
            "sigma1": float(abs(params["sigma1"] - LUGRE["s1"]) / LUGRE["s1"])}
    return {"max_param_rel_err_vs_truth": max(errs.values()), "param_rel_err_vs_truth": errs}
