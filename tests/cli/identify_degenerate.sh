#!/usr/bin/env bash
# Data that cannot give an answer is exit 2 with status "error" and a message, never exit 0 with
# NaN figures: a zero drive gain on EMPS (force zero throughout), a record that never slips for
# analyze stick-slip. And idim's rate-dependent defaults are reported as such.
source "$(dirname "$0")/lib.sh"
data="$src/data/emps"

# --gain 0: zero drive force.
set +e
"$exe" identify idim "$data/DATA_EMPS.mat" --time t --position qm --input vir --gain 0 --json - \
  > "$tmp/gain0.json" 2> "$tmp/gain0.txt"
code=$?
set -e
[ "$code" -eq 2 ] || { echo "FAIL: --gain 0 exit $code, expected 2"; cat "$tmp/gain0.txt"; exit 1; }
grep -q "force is zero throughout" "$tmp/gain0.txt" || { echo "FAIL: --gain 0 message"; cat "$tmp/gain0.txt"; exit 1; }
if grep -qi "nan" "$tmp/gain0.txt"; then echo "FAIL: NaN printed"; cat "$tmp/gain0.txt"; exit 1; fi
/usr/bin/python3 - "$tmp/gain0.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["status"] == "error" and "zero" in j["message"], j
# every error JSON carries a stable code (docs/contract.md); data without an answer: data.no_answer
assert j.get("error", {}).get("code") == "data.no_answer", j.get("error")
assert j["parameters"] == {}, j["parameters"]
PY

# EMPS at 1 kHz with no --cutoff/--decimate/--skip: the EMPS recipe, reported as defaults;
# the correlation matrix is carried.
"$exe" identify idim "$data/DATA_EMPS.mat" --time t --position qm --input vir --gain gtau --json - \
  > "$tmp/emps.json" 2> "$tmp/emps.txt"
grep -q "defaults: cutoff_hz = 100 Hz decimation = 10 skip = 49 samples" "$tmp/emps.txt" || { echo "FAIL: defaults line"; cat "$tmp/emps.txt"; exit 1; }
grep -q "regressors_from: position" "$tmp/emps.txt" || { echo "FAIL: regressors_from line"; cat "$tmp/emps.txt"; exit 1; }
/usr/bin/python3 - "$tmp/emps.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
d = j["diagnostics"]
assert d["defaults"] == {"cutoff_hz": 100, "decimation": 10, "skip": 49}, d["defaults"]
assert abs(j["parameters"]["M"]["value"] - 95.1089) <= 0.005 * 95.1089, j["parameters"]
c = d["correlation"]
assert c["names"] == ["M", "Fv", "Fc", "offset"], c
m = c["matrix"]
for i in range(4):
    assert m[i][i] == 1.0
    for k in range(4):
        assert m[i][k] == m[k][i] and abs(m[i][k]) <= 1.0
assert d["undetermined"] == [] and d["at_bound"] == []
PY

# Given explicitly, they are not defaults.
"$exe" identify idim "$data/DATA_EMPS.mat" --time t --position qm --input vir --gain gtau --cutoff 80 --json - \
  2> /dev/null > "$tmp/cut.json"
/usr/bin/python3 -c "
import json; d = json.load(open('$tmp/cut.json'))['diagnostics']
assert d['cutoff_hz'] == 80 and d['defaults'] == {'decimation': 10, 'skip': 49}, d"

# A record that never slips: analyze stick-slip exits 2 naming the threshold.
/usr/bin/python3 - "$tmp/still.csv" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("time,velocity,force\n")
    for k in range(500):
        f.write(f"{k * 0.01:.2f},0,{0.001 * k:.3f}\n")
PY
set +e
"$exe" analyze stick-slip "$tmp/still.csv" --json - > "$tmp/still.json" 2> "$tmp/still.txt"
code=$?
set -e
[ "$code" -eq 2 ] || { echo "FAIL: never-slipping record exit $code, expected 2"; cat "$tmp/still.txt"; exit 1; }
grep -q "no slip found: velocity never exceeded" "$tmp/still.txt" || { echo "FAIL: message"; cat "$tmp/still.txt"; exit 1; }
if grep -q "period" "$tmp/still.txt"; then echo "FAIL: a period was printed"; cat "$tmp/still.txt"; exit 1; fi
/usr/bin/python3 -c "
import json; j = json.load(open('$tmp/still.json'))
assert j['status'] == 'error' and 'no slip found' in j['message'], j"
echo ok
