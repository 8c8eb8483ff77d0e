"""Craig's torque-mode trapezoid: simulate examples/craig_motor_trapezoid.yaml, then identify
Fs, Fc, Fv and the rotor inertia from the simulated current and speed, as

    frictionlab simulate examples/craig_motor_trapezoid.yaml -o trapezoid.csv
    frictionlab identify breakaway trapezoid.csv --current current --kt 0.0141

Usage: python3 examples/craig_motor_trapezoid.py [OUTPUT_DIR]
"""
import pathlib
import sys

import frictionlab as fl

here = pathlib.Path(__file__).resolve().parent
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else None

tr = fl.simulate(here / "craig_motor_trapezoid.yaml")
for s in tr.switches:
    print(f"t = {s['time']:8.3f} s  {s['kind']}")

KT = 0.0141  # N m/A
r = fl.identify_breakaway(tr["time"], KT * tr["current"], tr["velocity"], axis="rotary")
print(r)
print("lecture read-offs:", r.diagnostics.groups["readoff"])
for name, true in {"Fs": 0.0015, "Fc": 0.0012, "Fv": 2.85e-6}.items():
    assert abs(r[name] / true - 1) < 2e-3, (name, r[name])

if out:
    out.mkdir(parents=True, exist_ok=True)
    fl.plot.simulation(tr, ("current", "velocity", "friction"), file=out / "trapezoid.png")
