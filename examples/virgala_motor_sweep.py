"""Virgala's constant-speed identification: simulate 15 speed steps of a DC motor under a
velocity loop (examples/virgala_motor_sweep.yaml), then fit the friction-velocity map, as

    frictionlab simulate examples/virgala_motor_sweep.yaml -o sweep.csv
    frictionlab identify sweep sweep.csv --current current --kt 0.039

Usage: python3 examples/virgala_motor_sweep.py [OUTPUT_DIR]
"""
import pathlib
import sys

import frictionlab as fl

here = pathlib.Path(__file__).resolve().parent
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else None

tr = fl.simulate(here / "virgala_motor_sweep.yaml")
KM = 0.039  # N m/A: at steady speed the friction torque is Km i
r = fl.identify_sweep(tr["time"], KM * tr["current"], tr["velocity"], axis="rotary")  # Stribeck law, exponent fitted
print(r)
for p in r.diagnostics.lists["points"]:
    print(f"  {p['velocity']:8.2f} rad/s  {p['force'] * 1e3:7.4f} mN m")
assert len(r.diagnostics.lists["points"]) == 15
for name, true in {"Fc": 0.002, "Fs": 0.003, "vs": 5.0, "Fv": 1e-5}.items():  # the scenario's law
    assert abs(r[name] - true) <= 2 * r.std[name], (name, r[name], r.std[name])

if out:
    out.mkdir(parents=True, exist_ok=True)
    fl.plot.sweep(r, file=out / "sweep.png")
