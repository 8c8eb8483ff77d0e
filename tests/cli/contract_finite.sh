#!/usr/bin/env bash
# Numbers or an error, never both (docs/guarantees.md): a run whose numbers would hold an inf or
# NaN is refused (exit 2, nothing written), and a fit whose solver failed never reports status
# ok. Cases: a motor whose back-EMF constant is 1e308 (once inf voltages written with exit 0), a
# LuGre fit with a static model given on a record with one force cell of 1e308 (once Ceres failed
# and the result said ok), a C header with an inf constant or a float literal beyond float's range,
# and the text and JSON of ok runs of each command family (no nan or inf in them).
source "$(dirname "$0")/lib.sh"

sed 's/^  Kb: 0.0141.*/  Kb: 1.0e308/' "$src/examples/craig_motor_trapezoid.yaml" > "$tmp/kb.yaml"
grep -q "Kb: 1.0e308" "$tmp/kb.yaml" || fail "no Kb line to edit"
expect_fail "inf at t = " simulate "$tmp/kb.yaml" -o "$tmp/kb.csv"
[ ! -e "$tmp/kb.csv" ] || fail "inf voltages written"

# A short LuGre record: a force sine on Canudas de Wit 1995 Table I's axis, one force cell 1e308.
cat > "$tmp/lugre.yaml" <<'YAML'
plant: {type: axis, M: 1.0}
friction: {law: lugre, sigma0: 1.0e5, sigma1: 316.22776601683796, sigma2: 0.4, Fc: 1.0, Fs: 1.5, vs: 0.001}
input: {type: sine, amplitude: 3.0, omega: 3.14159}
duration: 2
output_rate: 1000
YAML
"$exe" simulate "$tmp/lugre.yaml" -o "$tmp/lugre.csv" > /dev/null 2>&1
/usr/bin/python3 - "$tmp/lugre.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
col = rows[0].index("applied")
rows[1000][col] = "1e308"
csv.writer(open(sys.argv[1], "w", newline="")).writerows(rows)
PY
printf '{"law": "stribeck", "Fc": 1.0, "Fs": 1.5, "vs": 0.001, "delta": 2, "Fv": 0.4}\n' > "$tmp/static.json"
set +e
"$exe" identify lugre "$tmp/lugre.csv" --force applied --inertia 1 --static "$tmp/static.json" --json "$tmp/g.json" \
  > "$tmp/out.txt" 2> "$tmp/err.txt"
code=$?
set -e
/usr/bin/python3 - "$tmp/g.json" "$code" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["status"] == "error", (j["status"], j.get("message"))
assert sys.argv[2] != "0", "a failed fit exited 0"
PY
grep -q "WARNING: Logging before InitGoogleLogging" "$tmp/err.txt" && fail "glog lines on stderr: $(cat "$tmp/err.txt")"
# The C header: a band of 1e307 (once "= -inf;"), a --float header of a parameter beyond float's range
# (once a header that fails -Werror=overflow): refused, nothing written.
cat > "$tmp/model.json" <<'JSON'
{"law": "coulomb-viscous-asymmetric", "Fc_pos": 0.7, "Fv_pos": 0.21, "Fc_neg": 0.9, "Fv_neg": 0.19}
JSON
cat > "$tmp/huge.json" <<'JSON'
{"law": "coulomb-viscous-asymmetric", "Fc_pos": 1e39, "Fv_pos": 0.21, "Fc_neg": 0.9, "Fv_neg": 0.19}
JSON
set +e
"$exe" export "$tmp/model.json" --c "$tmp/band.h" --compensation feedforward --band 1e307 > /dev/null 2> "$tmp/err.txt"
code=$?
set -e
if [ "$code" -eq 0 ]; then
  ! grep -Eqi "= -?(inf|nan)" "$tmp/band.h" || fail "--band 1e307: a non-finite constant written with exit 0"
else
  [ "$code" -eq 2 ] && [ ! -e "$tmp/band.h" ] || fail "--band 1e307: exit $code, or a header left: $(cat "$tmp/err.txt")"
fi
expect_fail "--float: a constant of the header is 1e+39, beyond float's range (3.4e+38) (friction_Fc_pos)" export "$tmp/huge.json" --c "$tmp/f.h" --float
[ ! -e "$tmp/f.h" ] || fail "--float header written"
grep -q -- "--compensation" "$tmp/err.txt" && fail "a law's constant blamed on --compensation: $(cat "$tmp/err.txt")"
# Found by tests/cli/contract_c_export_property.sh: a --float constant below float's smallest
# magnitude (once a literal truncated to zero, -Werror=overflow), and a feedforward band whose
# interpolation overflowed float (once inf at vr = 0): refused, or finite.
cat > "$tmp/tiny.json" <<'JSON'
{"law": "coulomb-viscous", "Fc": 1e-46, "Fv": 0.4}
JSON
expect_fail "below float's smallest magnitude (1.4e-45) (friction_Fc)" export "$tmp/tiny.json" --c "$tmp/t.h" --float
[ ! -e "$tmp/t.h" ] || fail "--float header of a constant that rounds to 0 written"
# A LuGre law whose sigma0 / Fc is 2.1e38 in a float header: once -inf friction at 10 m/s.
printf '{"law": "lugre", "sigma0": 2.1488698622776785e+38, "sigma1": 316.2, "sigma2": 0.4, "Fc": 1, "Fs": 1.5, "vs": 0.001}\n' > "$tmp/stiff.json"
expect_fail "--float: sigma0 / Fc = 2.14887e+38 (1/m or 1/rad) exceeds 1e+15" export "$tmp/stiff.json" --c "$tmp/s.h" --float
printf '{"law": "viscous", "Fv": 0.4}\n' > "$tmp/viscous.json"
expect 0 "" export "$tmp/viscous.json" --c "$tmp/ff.h" --float --compensation feedforward --band 7.707630533480257e+27
printf '#include <stdio.h>\n#include "ff.h"\nint main(void) { printf("%%.9g %%.9g\\n", (double)friction_feedforward(0.0f), (double)friction_feedforward(1e27f)); return 0; }\n' > "$tmp/ff.c"
cc -std=c99 -Wall -Wextra -Werror -pedantic -o "$tmp/ff" "$tmp/ff.c" -lm || fail "feedforward header does not compile"
"$tmp/ff" | awk '{ if ($1 != 0 || $2 != $2 + 0 || $2 == "inf") { print "feedforward " $0; exit 1 } }' || fail "feedforward not finite in its band"

# analyze envelope on a free decay of amplitude 1e307: the fits' sums overflow; an error, never
# "rms inf %" or "offset -nan m" with exit 0.
/usr/bin/python3 -c "
import numpy as np
t = np.arange(0, 10, 0.001)
np.savetxt('$tmp/huge_decay.csv', np.column_stack([t, 1e307 * np.exp(-0.2 * t) * np.cos(2 * np.pi * t)]),
           delimiter=',', header='time,position', comments='')"
expect 2 "decay envelope: a figure of the fits is not a finite number" analyze envelope "$tmp/huge_decay.csv"

# analyze contour on the circular test with its coordinates scaled by 1e50 (once "the reference
# lies on a line or a point": the circle fit was not scale-invariant) and by 1e306 (figures that
# overflow): the circle, or an error; never inf or nan with exit 0.
"$exe" simulate "$src/examples/xy_circle.yaml" -o "$tmp/circle.csv" 2> /dev/null
for scale in 1e50 1e306; do
  /usr/bin/python3 - "$tmp/circle.csv" "$tmp/circle_$scale.csv" "$scale" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
cols = [i for i, n in enumerate(rows[0]) if n.endswith(("position", "reference"))]
for r in rows[1:]:
    for i in cols:
        r[i] = repr(float(r[i]) * float(sys.argv[3]))
csv.writer(open(sys.argv[2], "w", newline="")).writerows(rows)
PY
  set +e
  "$exe" analyze contour "$tmp/circle_$scale.csv" > "$tmp/contour.txt" 2> "$tmp/contour.err"
  code=$?
  set -e
  if [ "$scale" = 1e50 ]; then
    [ "$code" -eq 0 ] || fail "contour scaled by 1e50: exit $code: $(cat "$tmp/contour.err")"
    grep -q "^roundness *4.5[0-9]*e+51 um" "$tmp/contour.txt" || fail "contour scaled by 1e50: $(cat "$tmp/contour.txt")"
  fi
  if [ "$code" -eq 0 ]; then
    ! grep -Eiw -- '[-+]?(nan|inf)' "$tmp/contour.txt" || fail "contour scaled by $scale: $(cat "$tmp/contour.txt")"
  else
    [ "$code" -eq 2 ] && grep -q "contour" "$tmp/contour.err" || fail "contour scaled by $scale: exit $code: $(cat "$tmp/contour.err")"
  fi
done

# No word of the text or the JSON of an ok run is a number that is not finite (app/finite_output.hpp):
# a figure that is not determined is "n/a" in the text and null in JSON, never "nan".
no_non_finite() {
  ! grep -Eiwn -- '[-+]?(nan|inf|infinity)' "$@" || fail "nan or inf in the output of an ok run: $*"
}
# identify sweep whose Stribeck part is not determined (std n/a), text and JSON.
/usr/bin/python3 - "$tmp/steps.csv" <<'PY'
import sys
import numpy as np
rng = np.random.default_rng(3)
levels = [0.05, 0.2, -0.05, 0.1, -0.2, 0.08, -0.08, 0.15]
t = np.arange(8000) * 1e-3
v = np.repeat(levels, 1000) + 1e-4 * rng.standard_normal(8000)
f = np.sign(v) * (1 + 0.5 * np.exp(-(v / 0.02) ** 2)) + 0.4 * v + 0.01 * rng.standard_normal(8000)
np.savetxt(sys.argv[1], np.column_stack([t, np.cumsum(v) * 1e-3, v, f]), delimiter=",",
           header="time,position,velocity,force", comments="")
PY
"$exe" identify sweep "$tmp/steps.csv" --json "$tmp/sweep.json" > "$tmp/sweep.txt"
grep -q "n/a" "$tmp/sweep.txt" || fail "no undetermined std in the sweep's text: $(cat "$tmp/sweep.txt")"
no_non_finite "$tmp/sweep.txt" "$tmp/sweep.json"
"$exe" identify idim "$tmp/steps.csv" --force force --json - > "$tmp/idim.json" 2> "$tmp/idim.txt"
no_non_finite "$tmp/idim.txt" "$tmp/idim.json"
# identify on a record whose force carries an offset of 1e167 (found by
# tests/identify/test_extreme_values.cpp: once status ok with std(M) = inf, "+- inf" in the text).
/usr/bin/python3 - "$tmp/steps.csv" "$tmp/offset.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
for r in rows[1:]:
    r[3] = repr(float(r[3]) + 1.1746487914836065e167)
csv.writer(open(sys.argv[2], "w", newline="")).writerows(rows)
PY
for method in idim sweep; do
  set +e
  "$exe" identify "$method" "$tmp/offset.csv" --force force --json "$tmp/o.json" > "$tmp/o.txt" 2> "$tmp/o.err"
  code=$?
  set -e
  if [ "$code" -eq 0 ]; then
    no_non_finite "$tmp/o.txt" "$tmp/o.json"
  else
    [ "$code" -eq 2 ] || fail "identify $method, offset 1e167: exit $code: $(cat "$tmp/o.err")"
    grep -q '"status": "error"' "$tmp/o.json" || fail "identify $method, offset 1e167: exit 2 without an error JSON"
    grep -q '"code": "output.not_finite"' "$tmp/o.json" || fail "identify $method, offset 1e167: no code output.not_finite: $(cat "$tmp/o.json")"
  fi
done
# The refusal's code is output.not_finite (include/frictionlab/error.hpp), exit status 2 as for any
# data that cannot give an answer: breakaway on the Craig motor's record with the torque scaled by
# 2e158 (std(Fc) = inf; the library refuses it, identify/finite_result.hpp), the envelope above.
"$exe" simulate "$src/examples/craig_motor_trapezoid.yaml" -o "$tmp/craig.csv" 2> /dev/null
set +e
"$exe" identify breakaway "$tmp/craig.csv" --force "applied * 2e158" --json - > "$tmp/b.json" 2> "$tmp/b.err"
code=$?
"$exe" analyze envelope "$tmp/huge_decay.csv" --json - > "$tmp/e.json" 2> /dev/null
ecode=$?
set -e
[ "$code" -eq 2 ] || fail "breakaway, torque scaled by 2e158: exit $code: $(cat "$tmp/b.err")"
[ "$ecode" -eq 2 ] || fail "envelope of 1e307: exit $ecode"
/usr/bin/python3 - "$tmp/b.json" "$tmp/e.json" <<'PY'
import json, sys
for path in sys.argv[1:]:
    j = json.load(open(path))
    assert j["status"] == "error" and j["error"]["code"] == "output.not_finite", (path, j.get("error"), j["message"])
    assert "not a finite number" in j["error"]["message"], j["error"]
PY

# validate: a measured force beyond what double's squares hold (the EMPS drive gain scaled to
# 1e300 N/V: the validation's rmse overflows) is an error with exit 2, never an ok run with inf or
# nan; an ok run of validate has neither in its text or JSON.
emps="$src/data/emps/DATA_EMPS.mat"
printf '{"schema": 2, "status": "ok", "method": "idim", "law": {"law": "coulomb-viscous", "Fc": 20, "Fv": 200}, "parameters": {"M": {"value": 95.1, "std": 0.1, "unit": "kg"}}}\n' > "$tmp/emps_model.json"
validate_emps() {
  "$exe" validate "$tmp/emps_model.json" "$emps" --scenario "$src/examples/emps_closed_loop.yaml" --time t --position qm \
    --input vir "$@"
}
set +e
FRICTIONLAB_NO_PROGRESS=1 validate_emps --gain 1e300 --json - > "$tmp/v.json" 2> "$tmp/v.err"
code=$?
set -e
[ "$code" -eq 2 ] || fail "validate, gain 1e300: exit $code, expected 2: $(cat "$tmp/v.err")"
[ "$(wc -l < "$tmp/v.err")" -eq 1 ] || fail "validate, gain 1e300: expected one line on stderr: $(cat "$tmp/v.err")"
grep -q "is not a finite number" "$tmp/v.err" || fail "validate, gain 1e300: $(cat "$tmp/v.err")"
/usr/bin/python3 - "$tmp/v.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["status"] == "error" and j["error"]["code"] == "output.not_finite", (j["status"], j.get("error"), j["message"])
PY
validate_emps --gain gtau --json "$tmp/v_ok.json" > "$tmp/v_ok.txt"
grep -q '"status": "ok"' "$tmp/v_ok.json" || fail "validate, EMPS: not ok"
no_non_finite "$tmp/v_ok.txt" "$tmp/v_ok.json"
# simulate (CSV and summary), plan (text, profile, JSON), analyze (text; validate writes through the
# same emit() as identify and analyze).
"$exe" simulate "$src/examples/craig_pendulum_combined.yaml" -o "$tmp/p.csv" 2> "$tmp/sim.txt"
no_non_finite "$tmp/p.csv" "$tmp/sim.txt"
FRICTIONLAB_NO_PROGRESS=1 "$exe" plan sweep --prior "$src/examples/plan/virgala_motor_prior.json" \
  --scenario "$src/examples/virgala_motor_sweep.yaml" --limits speed=300,min_speed=6 --speeds 5 --noise current=1e-3 \
  --runs 2 -o "$tmp/plan.csv" --json "$tmp/plan.json" > "$tmp/plan.txt"
no_non_finite "$tmp/plan.txt" "$tmp/plan.csv" "$tmp/plan.json"
/usr/bin/python3 -c "
import numpy as np
t = np.arange(0, 10, 0.001)
np.savetxt('$tmp/decay.csv', np.column_stack([t, 0.01 * np.exp(-0.2 * t) * np.cos(2 * np.pi * t)]),
           delimiter=',', header='time,position', comments='')"
"$exe" analyze envelope "$tmp/decay.csv" > "$tmp/env.txt"
no_non_finite "$tmp/env.txt"
echo ok
