"""Plan the lecture's trapezoid for the lecture's DC motor and set the predicted std of its
read-offs next to the errors of the lecture's own read-offs, as

    frictionlab plan breakaway --prior examples/plan/craig_motor_prior.json \\
        --scenario examples/craig_motor_trapezoid.yaml --noise current=2e-4,velocity=0.5 -o ramp.csv

(the README's table uses --runs 200). Usage: python3 examples/plan_craig_motor.py [OUTPUT_DIR]
"""
import pathlib
import sys

import frictionlab as fl

here = pathlib.Path(__file__).resolve().parent
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else None
if out:
    out.mkdir(parents=True, exist_ok=True)

plan = fl.plan("breakaway", here / "plan" / "craig_motor_prior.json", here / "craig_motor_trapezoid.yaml",
               noise={"current": 2e-4, "velocity": 0.5}, runs=40,
               output=out / "ramp.csv" if out else None, overwrite=True)
design = plan["profile"]["design"]
print(f"ramp {design['ramp_rate']['value']:.5f} A/s to {design['peak']['value']:.4f} A, "
      f"hold {design['hold']['value']:.2f} s, {plan['profile']['duration_s']:.1f} s in all "
      "(the lecture: 0.003 A/s to 0.15 A, hold 30 s)")

KT = 0.0141  # N m/A
lecture = {"Fs": KT * 0.1062, "Fc": KT * 0.0828}
lecture["Fv"] = (KT * 0.15 - lecture["Fc"]) / 320.8
readoff = plan["prediction"]["readoff"]
dynamic = plan["prediction"]["parameters"]
print(f"{'':4} {'lecture error %':>16} {'plan read-off std %':>20} {'plan fit std %':>15}")
for name, value in lecture.items():
    prior = readoff[name]["prior"]
    print(f"{name:4} {100 * (value / prior - 1):16.2f} {readoff[name]['relative_std_percent']:20.3f} "
          f"{dynamic[name]['relative_std_percent']:15.3f}")
    # The plan reads off each parameter to well under the lecture's own error (a bias of its
    # faster ramp and its model's lag), and the fit to a fraction of a percent.
    assert readoff[name]["relative_std_percent"] < 1.0, (name, readoff[name])
    assert dynamic[name]["relative_std_percent"] < 0.5, (name, dynamic[name])
