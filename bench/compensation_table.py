#!/usr/bin/env python3
"""The README's compensation table: the largest quadrant glitch of examples/xy_circle.yaml for each
compensation type, with the exact model and with every friction parameter 20 % high and 20 % low.

    python3 bench/compensation_table.py [build/app/frictionlab]

Each case is examples/xy_circle.yaml with a `compensation:` block on each axis built from that
axis's own law with its parameters multiplied by f = 1, 1.2 or 0.8, simulated with the CLI. The
glitch is the largest radial error |r - R| within 15 degrees of an axis reversal (0, 90, 180, 270
degrees) after the first 0.2 s, as tests/plants/test_compensation_scenario.cpp measures it.

What "every friction parameter" means per type:
  feedforward, feedback: the axis's Stribeck law with Fc, Fs, vs, Fv times f (delta, the
    exponent of the Stribeck curve's shape, stays 2);
  lugre-observer: needs a LuGre law, so it gets the LuGre law whose steady state is the axis's
    Stribeck curve (g(v) = Fc + (Fs - Fc) exp(-(v/vs)^2), sigma2 = Fv: the same curve, delta 2),
    with bristle stiffness sigma0 = 1e7 N/m (2.5 um of presliding at Fc = 25 N) and damping
    sigma1 = 100 N s/m, observer gain k = 100 1/s; every one of sigma0, sigma1, sigma2, Fc, Fs, vs times f;
  disturbance-observer (bandwidth 2000 rad/s): uses no friction law; its model parameter, the nominal inertia (the
    axis's equivalent mass), times f.
"""
import csv
import math
import os
import subprocess
import sys
import tempfile


HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples")
EXE = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "build", "app", "frictionlab")

# The axes' laws and equivalent masses in examples/xy_circle.yaml (N, m/s, N s/m; kg).
AXES = {
    "x": {"Fc": 25.0, "Fs": 40.0, "vs": 0.002, "Fv": 150.0, "mass": 15 + 3.0e-5 * (2 * math.pi / 0.01) ** 2},
    "y": {"Fc": 15.0, "Fs": 25.0, "vs": 0.002, "Fv": 100.0, "mass": 6 + 2.0e-5 * (2 * math.pi / 0.01) ** 2},
}
TYPES = ["none", "feedforward", "feedback", "lugre-observer", "disturbance-observer"]
FACTORS = [1.0, 1.2, 0.8]
R, T_FROM, NEAR_DEG = 0.01, 0.2, 15.0  # m, s, degrees


def block(kind, axis, f):
    a = AXES[axis]
    if kind == "feedforward":
        return (f"{{type: feedforward, band: 1.0e-4, friction: {{law: stribeck, Fc: {a['Fc'] * f}, Fs: {a['Fs'] * f}, "
                f"vs: {a['vs'] * f}, delta: 2, Fv: {a['Fv'] * f}}}}}")
    if kind == "feedback":
        return (f"{{type: feedback, dead_band: 1.0e-4, friction: {{law: stribeck, Fc: {a['Fc'] * f}, Fs: {a['Fs'] * f}, "
                f"vs: {a['vs'] * f}, delta: 2, Fv: {a['Fv'] * f}}}}}")
    if kind == "lugre-observer":
        return (f"{{type: lugre-observer, gain: 100, friction: {{law: lugre, sigma0: {1e7 * f}, sigma1: {100 * f}, "
                f"sigma2: {a['Fv'] * f}, Fc: {a['Fc'] * f}, Fs: {a['Fs'] * f}, vs: {a['vs'] * f}}}}}")
    return f"{{type: disturbance-observer, bandwidth: 2000, inertia: {a['mass'] * f}}}"


def scenario(kind, f):
    lines = open(os.path.join(HERE, "xy_circle.yaml")).read().splitlines()
    out, axis = [], None
    for line in lines:
        out.append(line)
        stripped = line.strip()
        if stripped in ("x:", "y:"):
            axis = stripped[0]
        if kind != "none" and stripped.startswith("drive:") and axis:
            out.append(" " * (len(line) - len(line.lstrip())) + "compensation: " + block(kind, axis, f))
    return "\n".join(out) + "\n"


def largest_glitch(path):
    worst = 0.0
    with open(path) as f:
        for row in csv.DictReader(f):
            if float(row["time"]) < T_FROM:
                continue
            x, y = float(row["x.position"]), float(row["y.position"])
            deg = math.degrees(math.atan2(y, x)) % 360.0
            k = round(deg / 90.0) % 4  # nearest reversal
            if abs(math.remainder(deg - 90.0 * k, 360.0)) <= NEAR_DEG:
                worst = max(worst, abs(math.hypot(x, y) - R))
    return worst


def main():
    rows = {}
    with tempfile.TemporaryDirectory() as tmp:
        for kind in TYPES:
            for f in FACTORS if kind != "none" else [1.0]:
                path = os.path.join(tmp, "s.yaml")
                open(path, "w").write(scenario(kind, f))
                out = os.path.join(tmp, "run.csv")
                subprocess.run([EXE, "simulate", path, "-o", out], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                rows.setdefault(kind, []).append(largest_glitch(out))
                os.remove(out)
    print("| compensation | exact model | parameters +20 % | parameters -20 % |")
    print("| --- | --- | --- | --- |")
    for kind in TYPES:
        cells = [f"{1e6 * g:.2g} um" for g in rows[kind]]
        cells += ["(no model)"] * (3 - len(cells))
        print(f"| {kind} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
