#!/usr/bin/python3
"""Peer: Craig's DC motor in torque mode under a trapezoid current (examples/
craig_motor_trapezoid.yaml), exact stick/slip the way one writes it by hand: a loop over modes,
solve_ivp (RK45, rtol 1e-8, atol 1e-10, the slip ODE is not stiff: J/B = 0.37 s) with a
terminal event w = 0 while sliding, the breakaway found by brentq on Kt i(t) = Fs while stuck,
pieces split at the corners of the input; output at 100 Hz.

Usage: craig_motor_trapezoid.py [--repeat N]
Prints JSON {task, seconds (best of N), breakaway, stop, accuracy} with the accuracy against the
closed-form solution (common.craig_exact)."""
import argparse

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from common import CRAIG, best_of, craig_accuracy, craig_current, emit

C = CRAIG
J, Kt, Fs, Fc, B = C["J"], C["Kt"], C["Fs"], C["Fc"], C["B"]
T1 = C["level"] / C["rate"]
T2 = T1 + C["hold"]
T3 = T2 + C["level"] / C["rate"]
CORNERS = [T1, T2, T3, C["T"]]


def torque(t):
    return Kt * float(craig_current(t))


def simulate(rtol=1e-8, atol=1e-10):
    t_out = np.linspace(0.0, C["T"], int(round(C["T"] * C["rate_out"])) + 1)
    w_out = np.zeros_like(t_out)
    t, w, stuck, direction = 0.0, 0.0, True, 0
    events = []
    while t < C["T"]:
        nxt = min(c for c in CORNERS if c > t + 1e-12)
        if stuck:
            # stuck until |Kt i| reaches Fs within this input piece (i is linear on it)
            g = lambda s, sgn: sgn * torque(s) - Fs
            hit = None
            for sgn in (1.0, -1.0):
                if g(nxt, sgn) >= 0 > g(t, sgn):
                    hit = (brentq(g, t, nxt, args=(sgn,), xtol=1e-13, rtol=1e-15), sgn)
            if hit is None:
                t = nxt
                continue
            t, direction = hit
            stuck = False
            events.append(("breakaway", t))
            continue

        def f(s, y, d=direction):
            return [(torque(s) - d * Fc - B * y[0]) / J]

        def stop(s, y):
            return y[0]

        stop.terminal, stop.direction = True, -direction
        mask = (t_out > t) & (t_out <= nxt)
        sol = solve_ivp(f, (t, nxt), [w], method="RK45", events=stop, rtol=rtol, atol=atol,
                        t_eval=t_out[mask], dense_output=False)
        w_out[np.searchsorted(t_out, sol.t)] = sol.y[0]
        if sol.status == 1:  # velocity reached zero
            t = float(sol.t_events[0][0])
            w = 0.0
            w_out[(t_out > t) & (t_out <= nxt)] = 0.0
            if abs(torque(t)) <= Fs:
                stuck, direction = True, 0
                events.append(("stick", t))
            else:
                direction = 1 if torque(t) > 0 else -1
                events.append(("reversal", t))
        else:
            t, w = nxt, float(sol.y[0][-1]) if sol.y.size else w
    return t_out, w_out, events


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=10)
    a = ap.parse_args()
    sec, (t, w, events) = best_of(simulate, a.repeat)
    brk = next(tt for kind, tt in events if kind == "breakaway")
    stp = next(tt for kind, tt in events if kind == "stick")
    emit({"task": "craig_motor_trapezoid", "seconds": sec, "breakaway": brk, "stop": stp,
          "hold_speed": float(np.interp(T2, t, w)), "accuracy": craig_accuracy(t, w, brk, stp)})


if __name__ == "__main__":
    main()
