#!/usr/bin/env python3
"""A sweep run at several loads, made with numpy alone (the truth for the load-column tests of
sweep): steady speeds 0.5, 1, 2, 4 rad/s each way at each load, 0.3 s at rest before each 1.5 s
level, first-order speed steps (tau 50 ms), 1 kHz; friction 0.1 + 0.01 |load| N m while sliding
plus 0.002 N m s/rad, inertia 0.005 kg m^2; 2 mN m of torque noise and 0.3 N m of load noise.

Usage: load_sweep_log.py OUT.csv [--seed N] [--loads 10,40,80]   (columns time,velocity,torque,load)
"""
import argparse
import math

import numpy as np


def load_sweep(loads=(10.0, 40.0, 80.0), seed=7):
    """(time s, torque N m, velocity rad/s, load N m) arrays of the sweep at `loads`."""
    rng = np.random.default_rng(seed)
    v, f, load = [], [], []
    vel, dt = 0.0, 1e-3
    for L in loads:
        for sgn in (1, -1):
            for speed in (0.5, 1.0, 2.0, 4.0):
                for ref, dur in ((0.0, 0.3), (sgn * speed, 1.5)):
                    for _ in range(int(dur / dt)):
                        a = (ref - vel) / 0.05
                        vel += dt * a
                        if ref == 0.0 and abs(vel) < 1e-9:
                            vel = 0.0
                        fr = 0.0 if vel == 0.0 else math.copysign(0.1 + 0.01 * L, vel) + 0.002 * vel
                        v.append(vel)
                        f.append(fr + 0.005 * a + 2e-3 * rng.standard_normal())
                        load.append(L + 0.3 * rng.standard_normal())
    return dt * np.arange(len(v)), np.array(f), np.array(v), np.array(load)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--loads", default="10,40,80", help="loads in N m, comma-separated")
    a = ap.parse_args()
    t, f, v, load = load_sweep(tuple(float(x) for x in a.loads.split(",")), a.seed)
    np.savetxt(a.out, np.column_stack([t, v, f, load]), delimiter=",", header="time,velocity,torque,load",
               comments="", fmt="%.9g")


if __name__ == "__main__":
    main()
