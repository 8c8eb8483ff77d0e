#!/usr/bin/env python3
"""Writes a robot controller's joint log as such controllers export it, for the README's
"Your own data" walk-through: no header row, 31 columns (time, six positions, six velocities, six
currents, twelve status words), a '#' comment line, time stamps 10 to 12 ms apart (100 Hz nominal),
a 17-bit encoder, current noise and a torque offset. Joint 2 moves (a sum of sines); the others
hold still. Seeded, so the file is the same every time.

    /usr/bin/python3 examples/robot_joint_log.py joints.csv      # the log alone
    /usr/bin/python3 examples/robot_joint_log.py OUT_DIR         # the log, then identified from Python

The friction of joint 2 is what `frictionlab identify idim` should find:
inertia 0.8 kg m^2, Fv 1.5 N m s/rad, Fc 2.0 N m, offset 0.3 N m, with kt = 0.5 N m/A.
"""
import math
import random
import sys

TRUTH = {"M": 0.8, "Fv": 1.5, "Fc": 2.0, "offset": 0.3}  # kg m^2, N m s/rad, N m, N m
KT = 0.5                                                  # N m/A
ENCODER_STEP = 2 * math.pi / 2**17                        # rad: a 17-bit encoder
CURRENT_NOISE = 0.02                                      # A, std of the current measurement


def motion(t):
    """Joint 2's position (rad), velocity (rad/s) and acceleration (rad/s^2) at time t (s)."""
    q = qd = qdd = 0.0
    for a, w in ((0.6, 2.1), (0.25, 5.3), (0.1, 9.7)):  # rad, rad/s
        q += a * math.sin(w * t)
        qd += a * w * math.cos(w * t)
        qdd -= a * w * w * math.sin(w * t)
    return q, qd, qdd


def write_log(path, rows=4000, seed=7):
    rng = random.Random(seed)
    t = 1732.118  # s: the controller's clock, not zero at the start of the log
    with open(path, "w") as f:
        f.write("# joint log exported by the controller, 100 Hz\n")
        for k in range(rows):
            if k:
                t += rng.uniform(0.010, 0.012)  # jittered time stamps
            q, qd, qdd = motion(t - 1732.118)
            tau = TRUTH["M"] * qdd + TRUTH["Fv"] * qd + TRUTH["Fc"] * math.copysign(1.0, qd) + TRUTH["offset"]
            positions = [0.31, round(q / ENCODER_STEP) * ENCODER_STEP, -1.2, 0.05, 0.9, 0.0]
            velocities = [0.0, qd, 0.0, 0.0, 0.0, 0.0]
            currents = [0.8 + rng.gauss(0, CURRENT_NOISE), tau / KT + rng.gauss(0, CURRENT_NOISE)]
            currents += [rng.gauss(0, CURRENT_NOISE) for _ in range(4)]
            status = [str(40 + j) for j in range(12)]
            cells = [f"{t:.6f}"] + [f"{x:.7f}" for x in positions] + [f"{x:.6f}" for x in velocities]
            cells += [f"{x:.5f}" for x in currents] + status
            assert len(cells) == 31
            f.write(",".join(cells) + "\n")


def identify_joint(path):
    """The README's walk-through from Python: load the headerless log with names, resample it,
    identify joint 2 with idim (filter settings from the sample rate) and check the result."""
    import frictionlab as fl

    d = fl.load(path, names="t,q1,q2,q3,q4,q5,q6,v1,v2,v3,v4,v5,v6,i1,i2", resample=True, time="t")
    r = fl.identify_idim(d["t"], KT * d["i2"], position=d["q2"], axis="rotary", source=d)
    print(r)
    print("resampling:", d.resampling)
    # 5 %: the acceptance for rig-like logs (current noise, a 17-bit encoder, interpolation of
    # 10-12 ms jitter onto a uniform grid); the README quotes what the command line finds.
    rel_tol = 0.05
    for name in ("M", "Fv", "Fc"):
        assert abs(r.value(name) - TRUTH[name]) <= rel_tol * TRUTH[name], (name, r.value(name), TRUTH[name])


if __name__ == "__main__":
    # OUT.csv: write the log. A directory (as `make test` passes): write the log into it, then
    # identify joint 2 from Python.
    if len(sys.argv) != 2:
        sys.exit("usage: robot_joint_log.py OUT.csv | OUT_DIR")
    out = sys.argv[1]
    if out.endswith(".csv"):
        write_log(out)
    else:
        import os

        os.makedirs(out, exist_ok=True)
        write_log(os.path.join(out, "joints.csv"))
        identify_joint(os.path.join(out, "joints.csv"))
