#!/usr/bin/env bash
# A torque-sensor log at low speed, sampled irregularly (steps from 1 to 8 ms, median 2 ms), as a
# data logger on a slow serial link writes it: constant-velocity levels from 0.1 vs to 10 vs in
# both directions, velocity noise 2 % of the slowest level. Without --resample it is refused
# naming --resample; with it, identify sweep finds every level and Fc, Fs within 5 %.
source "$(dirname "$0")/lib.sh"

/usr/bin/python3 - "$tmp/slow.csv" <<'PY'
import sys
import numpy as np
Fc, Fs, vs, Fv = 0.5, 0.8, 0.01, 2.0          # N m, N m, rad/s, N m s/rad
rng = np.random.default_rng(11)
speeds = vs * np.array([0.1, 0.2, 0.4, 0.8, 1.5, 3.0, 6.0, 10.0])
levels = np.concatenate([[0.0], speeds, [0.0], -speeds])
hold, tau = 4.0, 0.05                          # s per level, s velocity-loop time constant
# Logger steps: mostly about 2 ms, a quarter of them anywhere from 1 to 8 ms.
n = int(len(levels) * hold / 1.5e-3)
steps = np.where(rng.random(n) < 0.75, rng.uniform(1.8e-3, 2.2e-3, n), rng.uniform(1e-3, 8e-3, n))
t = np.concatenate([[0.0], np.cumsum(steps)])
t = t[t < len(levels) * hold]
ref = levels[np.minimum((t // hold).astype(int), len(levels) - 1)]
v = np.zeros_like(t)
for k in range(1, len(t)):                     # first-order velocity loop, exact step
    a = np.exp(-(t[k] - t[k - 1]) / tau)
    v[k] = ref[k] + (v[k - 1] - ref[k]) * a
friction = np.sign(v) * (Fc + (Fs - Fc) * np.exp(-(np.abs(v) / vs) ** 2)) + Fv * v
torque = np.where(np.abs(v) < 1e-12, 0.0, friction) + 0.005 * rng.standard_normal(len(t))
vm = v + 0.02 * speeds[0] * rng.standard_normal(len(t))
np.savetxt(sys.argv[1], np.column_stack([t, vm, torque]), delimiter=",", header="time,velocity,torque",
           comments="", fmt="%.9g")
steps = np.diff(t)
assert 1e-3 <= steps.min() and steps.max() <= 8e-3 and abs(np.median(steps) - 2e-3) < 2e-4
PY
args=(identify sweep "$tmp/slow.csv" --force torque --axis rotary --model stribeck)

set +e
"$exe" "${args[@]}" > /dev/null 2> "$tmp/err.txt"
code=$?
set -e
[ "$code" -eq 2 ] || { echo "FAIL: irregular log without --resample: exit $code, expected 2"; cat "$tmp/err.txt"; exit 1; }
grep -qF -- "--resample" "$tmp/err.txt" || { echo "FAIL: the refusal does not name --resample"; cat "$tmp/err.txt"; exit 1; }

"$exe" "${args[@]}" --resample --json "$tmp/r.json" > "$tmp/r.txt"
/usr/bin/python3 - "$tmp/r.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["status"] == "ok", j["message"]
levels = j["diagnostics"]["levels"]
assert len(levels) == 16, [round(l["speed"], 5) for l in levels]        # 8 speeds, both directions
assert min(abs(l["speed"]) for l in levels) < 0.0011, levels           # the slowest, 0.1 vs, found
r = j["diagnostics"]["resampling"]
assert abs(r["dt_median"] - 2e-3) < 2e-4 and r["dt_max"] <= 8e-3 + 1e-9, r
p = {k: v["value"] for k, v in j["parameters"].items()}
# 5 %: the issue's acceptance for Fc and Fs on rig-like records; the torque noise (5 mN m) over
# thousands of samples per level leaves far less than that.
kRelTol = 0.05
for k, v in {"Fc": 0.5, "Fs": 0.8}.items():
    assert abs(p[k] - v) <= kRelTol * v, (k, p[k], v)
# vs: within 25 % (the issue's LuGre tolerance for it), or reported as undetermined, never a
# confident wrong number.
s = j["parameters"]["vs"]
assert abs(s["value"] - 0.01) <= 0.25 * 0.01 or s["std"] is None, s
PY
echo ok
