"""Canudas de Wit et al. (1995) stick-slip: a mass on a LuGre contact pulled through a spring
(k = 2 N/m) at 0.1 m/s. Simulate and detect the stick-slip cycle, as

    frictionlab simulate examples/canudas_stick_slip.yaml -o stick_slip.csv
    frictionlab analyze stick-slip stick_slip.csv

Reference (tight-tolerance LSODA): period 6.36 s, peak slip velocity 0.370 m/s.
Usage: python3 examples/canudas_stick_slip.py [OUTPUT_DIR]
"""
import pathlib
import sys

import frictionlab as fl

here = pathlib.Path(__file__).resolve().parent
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else None

tr = fl.simulate(here / "canudas_stick_slip.yaml")
s = fl.detect_stick_slip(tr)
print(s)
print(f"period {s.period:.3f} s (reference 6.36), peak slip velocity {s.peak_slip_velocity:.4f} m/s (reference 0.370)")
assert abs(s.period - 6.36) < 0.02 and abs(s.peak_slip_velocity - 0.370) < 0.002

if out:
    out.mkdir(parents=True, exist_ok=True)
    fl.plot.simulation(tr, ("position", "velocity", "friction"), file=out / "stick_slip.png")
