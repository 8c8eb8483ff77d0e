#!/usr/bin/env bash
# Numbers or an error, never both (docs/guarantees.md): a run whose numbers would hold an inf or
# NaN is refused (exit 2, nothing written), and a fit whose solver failed never reports status
# ok. Cases: a motor whose back-EMF constant is 1e308 (once inf voltages written with exit 0), a
# LuGre fit with a static model given on a record with one force cell of 1e308 (once Ceres failed
# and the result said ok), a C header with an inf constant or a float literal beyond float's range.
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
expect_fail "--float: a constant of the header is 1e+39, beyond float's range" export "$tmp/huge.json" --c "$tmp/f.h" --float
[ ! -e "$tmp/f.h" ] || fail "--float header written"

# analyze envelope on a free decay of amplitude 1e307: the fits' sums overflow; an error, never
# "rms inf %" or "offset -nan m" with exit 0.
/usr/bin/python3 -c "
import numpy as np
t = np.arange(0, 10, 0.001)
np.savetxt('$tmp/huge_decay.csv', np.column_stack([t, 1e307 * np.exp(-0.2 * t) * np.cos(2 * np.pi * t)]),
           delimiter=',', header='time,position', comments='')"
expect 2 "decay envelope: a figure of the fits is not a finite number" analyze envelope "$tmp/huge_decay.csv"
echo ok
