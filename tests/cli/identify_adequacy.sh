#!/usr/bin/env bash
# Model adequacy on a servo log made without frictionlab (tests/rigs/servo_log.py: a 2 kg axis in
# a 500 Hz PD loop, 1 um encoder, jittered time, current noise, no header row). With Stribeck
# friction (Fc 3 N, Fs 4.5 N, vs 0.01 m/s, Fv 20 N s/m) the idim recipe's Coulomb-viscous model
# leaves friction at low speed in the residual: the output must say so and name the remedies
# (the stribeck term, sweep). With Coulomb-viscous friction the model is right: no such warning.
source "$(dirname "$0")/lib.sh"
cd "$tmp"
cols=(--names t,q,qr,v,i,u,s1,s2,s3,s4,s5,s6 --time t --position q --current i --kt 0.5 --resample)

/usr/bin/python3 "$src/tests/rigs/servo_log.py" stribeck.csv --law stribeck --seed 1
"$exe" identify idim stribeck.csv "${cols[@]}" --json stribeck.json > stribeck.txt
grep -q "friction at low speed is higher than the model" stribeck.txt || { cat stribeck.txt; fail "no low-speed warning on the Stribeck log"; }
/usr/bin/python3 - stribeck.json <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
w = [x for x in j["diagnostics"]["warnings"] if "friction at low speed is higher" in x]
assert w and "stribeck" in w[0] and "sweep" in w[0], j["diagnostics"]["warnings"]
a = j["diagnostics"]["adequacy"]
assert a["findings"] >= 1 and 0 < a["effective_samples"] <= a["samples"], a
bins = j["diagnostics"]["residual_by_velocity"]
assert len(bins) >= 6 and all({"centre", "mean", "standard_error", "samples"} <= set(b) for b in bins), bins
PY

/usr/bin/python3 "$src/tests/rigs/servo_log.py" cv.csv --law coulomb-viscous --seed 2
"$exe" identify idim cv.csv "${cols[@]}" --json cv.json > cv.txt
if grep -q "friction at low speed\|differs by direction\|changes with velocity" cv.txt; then
  cat cv.txt; fail "a structure warning on the Coulomb-viscous log, where the model is right"
fi
# The model is right here: the recipe lands within 5 % on Fc and Fv (truth 3 N, 20 N s/m). (M comes
# out about 14 % high on this log: a third of its samples are stuck, which the recipe keeps.)
check_parameters cv.json "$(rel Fc 3.0 0.05) and $(rel Fv 20.0 0.05)"

# decay (a pendulum's free decay simulated by frictionlab, the lecture's combined pivot friction):
# the Coulomb-viscous energy balance is right, no finding; with a Stribeck pivot (Fs 0.3 N m over
# Fc 0.16, vs 0.1 rad/s) it is wrong, and the text, the JSON and the report say so.
"$exe" simulate "$src/examples/craig_pendulum_combined.yaml" -o pendulum.csv > /dev/null
sed -e 's/law: static-coulomb-viscous/law: stribeck/' -e 's/Fs: 0.2/Fs: 0.3\n  vs: 0.1/' \
  "$src/examples/craig_pendulum_combined.yaml" > dip.yaml
"$exe" simulate dip.yaml -o dip.csv > /dev/null
decay=(--time time --position position --stiffness 9.81 --pendulum --axis rotary)
"$exe" identify decay pendulum.csv "${decay[@]}" --json pendulum.json > pendulum.txt
grep -q "^adequacy: .*findings = 0" pendulum.txt || { cat pendulum.txt; fail "decay: a finding where the model is right"; }
"$exe" identify decay dip.csv "${decay[@]}" --json dip.json --report dip > dip.txt
grep -q "a rise at low speed (a Stribeck dip) biases both levels" dip.txt || { cat dip.txt; fail "decay: no Stribeck warning"; }
/usr/bin/python3 - dip.json <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["diagnostics"]["adequacy"]["findings"] >= 1, j["diagnostics"]["adequacy"]
assert len(j["diagnostics"]["residual_by_velocity"]) >= 6, j["diagnostics"]
PY
grep -q "residual_by_velocity" dip/report.html || fail "decay: the report lacks the residual against velocity"
echo "PASS identify_adequacy"
