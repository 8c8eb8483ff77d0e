#!/usr/bin/env bash
# frictionlab plan end to end: the seed's trapezoid planned on the seed's motor (profile CSV with
# units, JSON with the predicted std of Fs, Fc, Fv and the read-offs), a sweep whose limits leave
# vs undetermined (std null, warning), and bad input: exit 2 with a one-line message naming the
# limit, key or file; no output file left behind.
source "$(dirname "$0")/lib.sh"
export FRICTIONLAB_NO_PROGRESS=1
prior="$src/examples/plan/craig_motor_prior.json"
motor="$src/examples/craig_motor_trapezoid.yaml"

"$exe" plan breakaway --prior "$prior" --scenario "$motor" --noise current=2e-4,velocity=0.5 --runs 5 \
  -o "$tmp/ramp.csv" --json "$tmp/plan.json" > "$tmp/text.txt"
[ "$(head -1 "$tmp/ramp.csv")" = "time_s,current_A" ] || fail "profile header: $(head -1 "$tmp/ramp.csv")"
grep -q "predicted std (5 of 5 Monte Carlo runs" "$tmp/text.txt" || fail "text lacks the prediction"
/usr/bin/python3 - "$tmp/plan.json" "$tmp/ramp.csv" <<'PY'
import csv, json, sys
j = json.load(open(sys.argv[1]))
assert j["status"] == "ok" and j["method"] == "breakaway", j["method"]
p = j["prediction"]["parameters"]
for name in ("Fs", "Fc", "Fv"):
    assert p[name]["std"] > 0 and p[name]["std"] < 0.05 * p[name]["prior"], (name, p[name])
    assert p[name]["std_fisher"] is None and p[name]["std_a_priori"] is None
assert set(j["prediction"]["readoff"]) == {"Fs", "Fc", "Fv"}
d = j["profile"]["design"]
assert abs(d["peak"]["value"] - 1.4 * 0.0015 / 0.0141) < 1e-12 and d["peak"]["unit"] == "A"
assert d["ramp_rate"]["unit"] == "A/s"
rows = list(csv.reader(open(sys.argv[2])))[1:]
assert len(rows) == j["profile"]["samples"], (len(rows), j["profile"]["samples"])
assert max(float(r[1]) for r in rows) == d["peak"]["value"]
PY

# --json -: one JSON object on stdout, the text on stderr.
"$exe" plan breakaway --prior "$prior" --scenario "$motor" --runs 2 -o "$tmp/ramp2.csv" --json - > "$tmp/out.json" 2> "$tmp/err.txt"
/usr/bin/python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); assert j["status"]=="ok"' "$tmp/out.json"
grep -q "frictionlab plan breakaway" "$tmp/err.txt" || fail "--json -: text not on stderr"

# vs undetermined: no speed below it.
"$exe" plan sweep --prior "$src/examples/plan/virgala_motor_prior.json" --scenario "$src/examples/virgala_motor_sweep.yaml" \
  --limits speed=300,min_speed=6 --speeds 5 --noise current=1e-3 --runs 2 -o "$tmp/sweep.csv" --json "$tmp/sweep.json" > /dev/null
[ "$(head -1 "$tmp/sweep.csv")" = "time_s,velocity_rad_s" ] || fail "sweep header"
/usr/bin/python3 - "$tmp/sweep.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert sorted(j["undetermined"]) == ["Fs", "delta", "vs"], j["undetermined"]  # Fs: singular information
assert j["prediction"]["parameters"]["vs"]["std"] is None
assert j["prediction"]["parameters"]["vs"]["std_a_priori"] is None
fc = j["prediction"]["parameters"]["Fc"]
assert fc["std_a_priori"] > 0 and fc["std_a_priori"] < 0.05 * fc["prior"], fc
assert any("below the prior's vs" in w for w in j["warnings"])
PY

# Bad input.
expect_fail "--limits current = 0.1 A (Kt i = 0.00141 N m) is below 1.1 Fs" \
  plan breakaway --prior "$prior" --scenario "$motor" --limits current=0.1 -o "$tmp/x.csv"
[ ! -e "$tmp/x.csv" ] || fail "a refused plan left its profile"
expect_fail "unknown key 'amps'" plan breakaway --prior "$prior" --scenario "$motor" --limits amps=1 -o "$tmp/x.csv"
expect_fail "plan method 'ramp': expected one of breakaway, sweep, idim, lugre" \
  plan ramp --prior "$prior" --scenario "$motor" -o "$tmp/x.csv"
expect_fail "a sweep plan needs a velocity loop" plan sweep --prior "$prior" --scenario "$motor" -o "$tmp/x.csv"
expect_fail "ramp.csv" plan breakaway --prior "$prior" --scenario "$motor" --runs 2 -o "$tmp/ramp.csv"
expect_fail "--runs 1: expected >= 2" plan breakaway --prior "$prior" --scenario "$motor" --runs 1 -o "$tmp/x.csv"
expect_fail "no-such.json" plan breakaway --prior "$tmp/no-such.json" --scenario "$motor" -o "$tmp/x.csv"
expect_fail "--noise current = 0.001 A: the scenario's plant (axis) has no motor current" \
  plan idim --prior "$src/examples/plan/emps_prior.json" --scenario "$src/examples/plan/axis_position_loop.yaml" \
  --noise current=1e-3 -o "$tmp/x.csv"
cat > "$tmp/backlash.yaml" <<'YAML'
plant: {type: axis, M: 1.5, backlash: {width: 0.002, motor_inertia: 0.5}}
controller: {loop: position, Kp: 400, Kd: 60}
input: {type: constant, value: 0}
duration: 1
YAML
expect_fail "plant.backlash: an axis with backlash is not supported by plan" \
  plan idim --prior "$src/examples/plan/emps_prior.json" --scenario "$tmp/backlash.yaml" -o "$tmp/x.csv"
# The error JSON on stdout with --json -.
set +e
"$exe" plan breakaway --prior "$prior" --scenario "$motor" --limits current=0.1 -o "$tmp/x.csv" --json - > "$tmp/err.json" 2> /dev/null
code=$?
set -e
[ "$code" -eq 2 ] || fail "error JSON run: exit $code"
/usr/bin/python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); assert j["status"]=="error" and "--limits current" in j["message"]' "$tmp/err.json"
# The help into a file first: grep -q stops reading at its match, and the help's writer would then
# fail on the closed pipe (pipefail).
"$exe" plan --help > "$tmp/help.txt"
grep -q "breakaway  trapezoid of current" "$tmp/help.txt" || fail "--help lacks the methods"
grep -q "ripple-scan slow moves" "$tmp/help.txt" || fail "--help lacks the effects' designs"
# Without --noise the predicted std are round-off (about 1e-19): a warning says so, in the text
# and the JSON; with --noise there is no such warning.
"$exe" plan sweep --prior "$src/examples/plan/virgala_motor_prior.json" --scenario "$src/examples/virgala_motor_sweep.yaml" \
  --limits speed=300,min_speed=6 --runs 4 -o "$tmp/quiet.csv" --json "$tmp/quiet.json" > "$tmp/quiet.txt"
grep -q "^warning: no --noise given: the predicted standard deviations come from round-off alone" "$tmp/quiet.txt" \
  || { cat "$tmp/quiet.txt"; fail "plan without --noise: no warning"; }
/usr/bin/python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); assert any("no --noise" in w for w in j["warnings"]), j["warnings"]' "$tmp/quiet.json"
"$exe" plan sweep --prior "$src/examples/plan/virgala_motor_prior.json" --scenario "$src/examples/virgala_motor_sweep.yaml" \
  --limits speed=300,min_speed=6 --noise current=2e-3 --runs 4 -o "$tmp/noisy.csv" > "$tmp/noisy.txt"
grep -q "no --noise" "$tmp/noisy.txt" && fail "plan with --noise: warned of no noise"
echo ok
