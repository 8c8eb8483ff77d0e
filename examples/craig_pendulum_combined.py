"""Craig's pendulum with static, Coulomb and viscous pivot friction: simulate, classify the
decay envelope and identify Fc and Fv from the energy lost per half cycle, as

    frictionlab simulate examples/craig_pendulum_combined.yaml -o pendulum.csv
    frictionlab analyze envelope pendulum.csv
    frictionlab identify decay pendulum.csv --stiffness 9.81 --pendulum --axis rotary

Usage: python3 examples/craig_pendulum_combined.py [OUTPUT_DIR]
"""
import pathlib
import sys

import frictionlab as fl

here = pathlib.Path(__file__).resolve().parent
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else None

tr = fl.simulate(here / "craig_pendulum_combined.yaml")
env = fl.decay_envelope(tr)
print(env)
r = fl.identify_decay(tr["time"], tr["position"], stiffness=1.0 * 9.81 * 1.0, pendulum=True, axis="rotary")  # m g l
print(r)
assert abs(r["Fc"] / 0.16 - 1) < 2e-3 and abs(r["Fv"] / 0.5 - 1) < 2e-3

if out:
    out.mkdir(parents=True, exist_ok=True)
    fl.plot.decay(tr, envelope=env, file=out / "pendulum_decay.png")
