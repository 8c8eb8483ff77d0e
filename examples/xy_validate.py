"""Validate a two-axis machine's identified models on a circular test, as

    frictionlab validate x=model_x.json,y=model_y.json circle_log.csv --scenario examples/xy_circle.yaml

The "machine" is examples/xy_circle.yaml with x's friction 10 % higher and its carriage 1 kg
heavier; its circular-test log has 0.2 um encoder noise and 0.5 um steps. Each axis is identified
from the log (IDIM: inertia, Coulomb, offset), then the models run in the scenario's loops and
the measured and simulated contours are compared: the Coulomb models have no static friction
peak, so they under-predict the quadrant glitches.
Usage: python3 examples/xy_validate.py [OUTPUT_DIR]
"""
import pathlib
import sys
import tempfile

import numpy as np

import frictionlab as fl

here = pathlib.Path(__file__).resolve().parent
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else None
scenario = here / "xy_circle.yaml"

text = scenario.read_text()
machine = text.replace("Fc: 25, Fs: 40, vs: 0.002, delta: 2, Fv: 150", "Fc: 27.5, Fs: 44, vs: 0.002, delta: 2, Fv: 165")
machine = machine.replace("mass: 15 ", "mass: 16 ")
with tempfile.TemporaryDirectory() as tmp:
    path = pathlib.Path(tmp) / "machine.yaml"
    path.write_text(machine)
    tr = fl.simulate(path)
rng = np.random.default_rng(1)
encoder = lambda q: 0.5e-6 * np.round((q + rng.normal(0, 0.2e-6, q.size)) / 0.5e-6)  # noqa: E731  m
t, x, y = tr["time"], encoder(tr["x.position"]), encoder(tr["y.position"])
fx, fy = tr["x.drive"], tr["y.drive"]  # N: the drives' commands, as the controller logs them

# A circle at 20 mm/s holds too little viscous information for an Fv (it would come out
# negative): inertia, Coulomb level and offset.
terms = ["inertia", "coulomb", "offset"]
models = {"x": fl.identify_idim(t, fx, position=x, terms=terms), "y": fl.identify_idim(t, fy, position=y, terms=terms)}
for axis, m in models.items():
    print(f"{axis}: M {m['M']:.2f} kg, Fc {m['Fc']:.2f} N, offset {m['offset']:.3f} N")
r, measured, simulated = fl.validate_xy(models, scenario, time=t, x=x, y=y, x_force=fx, y_force=fy)
for key, e in r.validation.signal_errors_percent.items():
    print(f"  {key:15s} {e:8.4f} %")
c = r.validation.sections["contour"]
um = 1e6
print(f"largest quadrant glitch: measured {c['measured']['max_quadrant_glitch_m'] * um:.1f} um, "
      f"simulated {c['simulated']['max_quadrant_glitch_m'] * um:.1f} um")
print(f"roundness: measured {measured.roundness_m * um:.1f} um, simulated {simulated.roundness_m * um:.1f} um")
# The loop holds the path whatever the model (< 0.1 % of the 10 mm radius); the Coulomb models
# have no breakaway peak: their glitch is lower than the machine's.
assert r.validation.signal_errors_percent["x.position"] < 0.1
assert c["simulated"]["max_quadrant_glitch_m"] < c["measured"]["max_quadrant_glitch_m"]

if out:
    out.mkdir(parents=True, exist_ok=True)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(measured.angle_deg, measured.radial_error * um, ".", ms=1, label="measured")
    ax.plot(simulated.angle_deg, simulated.radial_error * um, ".", ms=1, label="simulated")
    ax.set_xlabel("angle (deg)")
    ax.set_ylabel("radial error r - R (um)")
    ax.legend()
    fig.savefig(out / "xy_validate.png", dpi=100)
