"""A fleet of realistic constant-velocity logs of one rotary axis over days, and broken files: the
data of examples/fleet_drift.py, the README's batch section and the batch tests
(tests/python/test_batch.py, tests/cli/identify_batch.sh).

Each good log: ten speed levels (both directions, 0.2 to 4 rad/s, 1.5 s each) reached through
the axis' first-order response (time constant 0.05 s); the logged velocity has white noise
(0.01 rad/s) and the encoder's quantisation (0.002 rad/s); the torque is Fc sign(v) + Fv v +
J a + an offset of the current sensor (3 mN m) with noise (5 mN m), quantised by the ADC
(1 mN m); the logger's time starts at 1000 s and its steps jitter by +-2 % (so the files need
resampling). Fc rises by 30 % from the sixth day on (wear): the drift test's step.

Usage: python3 examples/fleet_logs.py [DIR]   writes the files into DIR (default: fleet_logs) and
                                              prints their names
"""
import os
import sys

import numpy as np

FC, FC_WORN, FV, INERTIA = 0.10, 0.13, 0.010, 2e-4  # N m, N m, N m s/rad, kg m^2
DAYS = 8
WORN_FROM_DAY = 6
BROKEN = {
    "axis3_2026-11-20_no_force.csv": "missing column",
    "axis3_2026-11-21_text.csv": "text value",
    "axis3_2026-11-22_empty.csv": "empty file",
}


def log(path, Fc, seed, jitter=0.02):
    rng = np.random.default_rng(seed)
    speeds = np.array([0.2, 0.5, 1.0, 2.0, 4.0])
    levels = np.concatenate([speeds, -speeds])
    dt, hold, tau = 0.005, 1.5, 0.05
    ref = np.repeat(levels, int(hold / dt))
    v = np.zeros_like(ref)
    for k in range(1, len(ref)):
        v[k] = v[k - 1] + dt * (ref[k] - v[k - 1]) / tau
    a = np.gradient(v, dt)
    torque = Fc * np.sign(v) + FV * v + INERTIA * a + 0.003 + 0.005 * rng.standard_normal(len(v))
    torque = np.round(torque / 1e-3) * 1e-3
    vm = np.round((v + 0.01 * rng.standard_normal(len(v))) / 2e-3) * 2e-3
    t = 1000.0 + np.cumsum(np.full(len(v), dt) * (1 + jitter * rng.uniform(-1, 1, len(v))))
    np.savetxt(path, np.column_stack([t, vm, torque]), delimiter=",", header="time,velocity,force", comments="",
               fmt="%.9g")


def write_fleet(folder):
    """Writes DAYS good logs axis3_2026-11-DD.csv and the BROKEN files into `folder`; returns
    {file name: true Fc (N m), or None for a broken file}."""
    os.makedirs(folder, exist_ok=True)
    truth = {}
    for day in range(1, DAYS + 1):
        name = f"axis3_2026-11-{day:02d}.csv"
        Fc = FC_WORN if day >= WORN_FROM_DAY else FC
        log(os.path.join(folder, name), Fc, seed=day)
        truth[name] = Fc
    names = list(BROKEN)
    log(os.path.join(folder, names[0]), FC, seed=99)
    with open(os.path.join(folder, names[0])) as f:
        lines = [",".join(line.rstrip("\n").split(",")[:2]) for line in f]
    with open(os.path.join(folder, names[0]), "w") as f:
        f.write("\n".join(lines) + "\n")
    log(os.path.join(folder, names[1]), FC, seed=98)
    with open(os.path.join(folder, names[1])) as f:
        lines = f.readlines()
    lines[40] = lines[40].split(",")[0] + ",n/a," + lines[40].split(",")[2]
    with open(os.path.join(folder, names[1]), "w") as f:
        f.writelines(lines)
    open(os.path.join(folder, names[2]), "w").close()
    truth.update({n: None for n in names})
    return truth


if __name__ == "__main__":
    for name in write_fleet(sys.argv[1] if len(sys.argv) > 1 else "fleet_logs"):
        print(name)
