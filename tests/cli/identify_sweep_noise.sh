#!/usr/bin/env bash
# identify sweep on a Virgala-style record with velocity noise (15 speeds per direction from 0.1 vs
# to 250 vs, noise 4 % of the slowest speed): every level is found, on the measured velocity and on
# --reference; a sweep that never goes below 3 vs gives vs and delta std null, a warning, and
# "(undetermined)" in the text.
source "$(dirname "$0")/lib.sh"

/usr/bin/python3 - "$tmp" <<'PY'
import sys
import numpy as np
out = sys.argv[1]
Fc, Fs, vs, delta, Fv = 0.02, 0.035, 0.8, 2.0, 1.5e-4
def law(v):
    return np.sign(v) * (Fc + (Fs - Fc) * np.exp(-(np.abs(v) / vs) ** delta)) + Fv * v
def record(path, lo, hi, n_levels, seed):
    rng = np.random.default_rng(seed)
    speeds = lo * (hi / lo) ** (np.arange(n_levels) / (n_levels - 1))
    levels = np.concatenate([[0.0], speeds, -speeds])
    dt, hold, tau = 1e-3, 3.0, 0.05
    per = int(hold / dt)
    ref = np.repeat(levels, per)
    v = np.zeros_like(ref)
    for k in range(1, len(ref)):
        v[k] = v[k - 1] + dt * (ref[k] - v[k - 1]) / tau
    t = dt * np.arange(len(ref))
    torque = np.where(v == 0, 0.0, law(v)) + 2e-4 * rng.standard_normal(len(t))
    vm = v + 0.04 * lo * rng.standard_normal(len(t))
    np.savetxt(path, np.column_stack([t, vm, torque, ref]), delimiter=",", header="time,velocity,force,v_cmd",
               comments="", fmt="%.9g")
record(f"{out}/sweep.csv", 0.08, 200.0, 15, 1)
record(f"{out}/fast.csv", 2.4, 200.0, 10, 2)
PY

for extra in "" "--reference v_cmd"; do
  # shellcheck disable=SC2086
  "$exe" identify sweep "$tmp/sweep.csv" $extra --json - > "$tmp/r.json" 2> /dev/null
  /usr/bin/python3 - "$tmp/r.json" "$extra" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["status"] == "ok", j["message"]
levels = j["diagnostics"]["levels"]
assert len(levels) == 30, (sys.argv[2], [round(l["speed"], 3) for l in levels])
assert min(abs(l["speed"]) for l in levels) < 0.09, levels
assert j["diagnostics"]["segmented_on"] == ("reference" if sys.argv[2] else "velocity")
c = j["diagnostics"]["correlation"]
assert sorted(c["names"]) == sorted(j["parameters"]), c["names"]
for i, row in enumerate(c["matrix"]):
    assert row[i] == 1.0
PY
done

"$exe" identify sweep "$tmp/fast.csv" --json "$tmp/fast.json" > "$tmp/fast.txt"
grep -q "Stribeck part is not determined by the data" "$tmp/fast.txt" || { echo "FAIL: no warning"; cat "$tmp/fast.txt"; exit 1; }
grep -Eq "^  vs .*n/a .*\((undetermined|at bound)\)" "$tmp/fast.txt" || { echo "FAIL: vs not marked"; cat "$tmp/fast.txt"; exit 1; }
! grep -Eqiw "[-+]?(nan|inf)" "$tmp/fast.txt" || { echo "FAIL: nan or inf in the text of an ok run"; cat "$tmp/fast.txt"; exit 1; }
/usr/bin/python3 - "$tmp/fast.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
p = j["parameters"]
assert p["vs"]["std"] is None and p["delta"]["std"] is None, p
assert "vs" in j["diagnostics"]["undetermined"] + j["diagnostics"]["at_bound"], j["diagnostics"]
PY
echo ok
