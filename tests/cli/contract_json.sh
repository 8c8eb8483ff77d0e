#!/usr/bin/env bash
# The --json contract on bad input (docs/contract.md, docs/guarantees.md): whatever goes wrong (the data
# file empty, a bad cell, a missing column, a truncated .mat, a directory as DATA, a bad option,
# a bad model file, data that gives no answer), `--json -` still prints one JSON object on stdout
# with "schema": 1, "status": "error" and a message, the exit status is 2, and stderr carries
# exactly one line. With --json FILE a failed run writes no file.
# Usage: contract_json.sh PATH_TO_frictionlab SOURCE_DIR
source "$(dirname "$0")/lib.sh"
emps="$src/data/emps/DATA_EMPS.mat"
scenario="$src/examples/emps_closed_loop.yaml"

# expect_json WANT_IN_MESSAGE ARGS...: exit 2, one JSON error object on stdout naming WANT, one
# line on stderr.
expect_json() {
  local want="$1"
  shift
  set +e
  "$exe" "$@" --json - > "$tmp/out.txt" 2> "$tmp/err.txt"
  local code=$?
  set -e
  [ "$code" -eq 2 ] || { cat "$tmp/err.txt"; fail "$*: exit $code, expected 2"; }
  [ "$(wc -l < "$tmp/err.txt")" -eq 1 ] || { cat "$tmp/err.txt"; fail "$*: expected exactly one line on stderr"; }
  grep -qF -- "$want" "$tmp/err.txt" || { cat "$tmp/err.txt"; fail "$*: stderr lacks '$want'"; }
  /usr/bin/python3 - "$tmp/out.txt" "$want" <<'PY' || fail "$*: stdout is not the error JSON: $(cat "$tmp/out.txt")"
import json, sys
text = open(sys.argv[1]).read()
assert text.count("\n") == 1, "expected one line of JSON"
j = json.loads(text)
assert j["schema"] == 2 and j["status"] == "error", j
assert sys.argv[2] in j["message"], j["message"]
assert isinstance(j.get("method"), str) and j["method"], j
PY
}

idim=(identify idim --time t --position qm --input vir --gain gtau)

# Reading the data.
: > "$tmp/empty.csv"
expect_json "empty.csv" identify breakaway "$tmp/empty.csv"
expect_json "empty.csv" analyze envelope "$tmp/empty.csv"
printf 'time,velocity,force\n0,0,0\n0.01,abc,0\n0.02,0,0\n' > "$tmp/cell.csv"
expect_json "line 3" identify sweep "$tmp/cell.csv"
expect_json "line 3" analyze stick-slip "$tmp/cell.csv" --velocity velocity
printf 'time,speed,force\n0,0,0\n0.01,1,0\n0.02,2,0\n' > "$tmp/column.csv"
expect_json "velocity" identify breakaway "$tmp/column.csv"
expect_json "velocity" analyze stick-slip "$tmp/column.csv"
head -c 3000 "$emps" > "$tmp/truncated.mat"
expect_json "truncated.mat" "${idim[@]}" "$tmp/truncated.mat"
mkdir "$tmp/adir"
expect_json "adir" "${idim[@]}" "$tmp/adir"
expect_json "adir" analyze envelope "$tmp/adir"
expect_json "no-such.mat" "${idim[@]}" "$tmp/no-such.mat"

# Parsing the options (CLI11's errors go the same way).
expect_json "--cutoff" "${idim[@]}" "$emps" --cutoff fast
expect_json "--vs" "${idim[@]}" "$emps" --vs fast
expect_json "--bogus" "${idim[@]}" "$emps" --bogus

# Data that gives no answer: the method's own error result, one line on stderr.
/usr/bin/python3 - "$tmp/still.csv" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("time,velocity,force\n")
    for k in range(200):
        f.write(f"{k * 0.01},0,{k * 1e-4}\n")
PY
expect_json "no motion detected" identify breakaway "$tmp/still.csv"

# validate: the model file (trailing garbage, a failed identification, a bad value blamed on the
# model, not on the scenario), and the data.
model='{"schema": 1, "status": "ok", "method": "idim", "law": {"law": "coulomb-viscous", "Fc": 20, "Fv": 200}, "parameters": {"M": {"value": 95.1, "std": 0.1, "unit": "kg"}}}'
echo "$model" > "$tmp/model.json"
{ echo "$model"; echo "trailing text"; } > "$tmp/garbage.json"
expect_json "garbage.json" validate "$tmp/garbage.json" "$emps" --scenario "$scenario" --time t --position qm --input vir --gain gtau
echo '{"schema": 1, "status": "error", "message": "no excitation", "method": "idim"}' > "$tmp/failed.json"
expect_json "the identification failed" validate "$tmp/failed.json" "$emps" --scenario "$scenario" --time t --position qm --input vir --gain gtau
echo "${model/\"schema\": 1/\"schema\": 7}" > "$tmp/future.json"
expect_json "future.json: schema: 7 is not a MODEL.json schema this frictionlab reads (1 or 2)" validate "$tmp/future.json" "$emps" --scenario "$scenario" --time t --position qm --input vir --gain gtau
echo "${model/95.1/-3}" > "$tmp/negative.json"
expect_json "negative.json: parameters.M" validate "$tmp/negative.json" "$emps" --scenario "$scenario" --time t --position qm --input vir --gain gtau
grep -qF "$scenario" "$tmp/err.txt" && fail "a bad value of MODEL.json blamed on the scenario: $(cat "$tmp/err.txt")"
# MODEL.json schema 2 and its strict reader. A schema-1 file of the previous release (auto's
# candidates at the top level) is still read; so is the schema-2 file this build writes.
cat > "$tmp/schema1.json" <<'EOF'
{"schema": 1, "status": "ok", "message": "", "method": "auto", "model": "coulomb-viscous", "axis": "linear",
 "parameters": {"M": {"value": 95.1, "std": 0.1, "unit": "kg"}, "Fc": {"value": 20, "std": 0.1, "unit": "N"},
                "Fv": {"value": 200, "std": 1, "unit": "N s/m"}},
 "law": {"law": "coulomb-viscous", "Fc": 20, "Fv": 200},
 "fit": {"relative_error_percent": 4.1, "rmse": 1.2, "samples": 2480},
 "diagnostics": {"selection": [{"candidate": 1, "chosen": 1}], "warnings": []},
 "selection": [{"name": "idim coulomb-viscous", "status": "chosen", "heldout_error_percent": 4.2}]}
EOF
expect 0 "" export "$tmp/schema1.json" --c "$tmp/schema1.h"
grep -q "20" "$tmp/schema1.h" || fail "the schema-1 model's Fc is not in the exported header"
"$exe" identify idim "$emps" --time t --position qm --input vir --gain gtau --json "$tmp/schema2.json" > /dev/null
/usr/bin/python3 - "$tmp/schema2.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["schema"] == 2 and j["axis"] == "linear", j
assert "selection" not in j, "schema 2 has no top-level selection"
assert j["diagnostics"]["covariance"].startswith("newey-west"), j["diagnostics"]
assert all(p["std_ols"] is not None for p in j["parameters"].values()), j["parameters"]
PY
expect 0 "" export "$tmp/schema2.json" --c "$tmp/schema2.h"
# Refused naming the key: a key given twice, a text where a number belongs, no status, an axis
# that is neither linear nor rotary.
echo '{"schema": 2, "status": "ok", "law": {"law": "coulomb", "Fc": 1, "Fc": 2}, "parameters": {"M": 1}}' > "$tmp/twice.json"
expect_fail "twice.json: law.Fc: the key is given twice" export "$tmp/twice.json" --c "$tmp/x.h"
echo "${model/\"value\": 95.1/\"value\": \"95.1\"}" > "$tmp/text.json"
expect_fail "text.json: parameters.M.value: expected a number" export "$tmp/text.json" --c "$tmp/x.h"
echo "${model/\"status\": \"ok\", /}" > "$tmp/nostatus.json"
expect_fail "nostatus.json: missing 'status'" export "$tmp/nostatus.json" --c "$tmp/x.h"
echo "${model/\"method\"/\"axis\": \"diagonal\", \"method\"}" > "$tmp/diagonal.json"
expect_fail "diagonal.json: axis: expected \"linear\" or \"rotary\", got \"diagonal\"" export "$tmp/diagonal.json" --c "$tmp/x.h"
# A rotary model on the EMPS scenario's linear plant: exit 2 naming both axes.
echo "${model/\"method\"/\"axis\": \"rotary\", \"method\"}" > "$tmp/rotary.json"
expect_json "rotary.json: axis: a rotary model on the linear plant" validate "$tmp/rotary.json" "$emps" --scenario "$scenario" --time t --position qm --input vir --gain gtau
expect_json "adir" validate "$tmp/model.json" "$tmp/adir" --scenario "$scenario" --time t --position qm --input vir --gain gtau
# identify lugre --static reads the model the same way.
/usr/bin/python3 - "$tmp/lugre.csv" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("time,applied,position\n")
    for k in range(100):
        f.write(f"{k * 0.001},{k * 0.01},0\n")
PY
expect_json "garbage.json" identify lugre "$tmp/lugre.csv" --force applied --inertia 1 --static "$tmp/garbage.json"
expect_json "the identification failed" identify lugre "$tmp/lugre.csv" --force applied --inertia 1 --static "$tmp/failed.json"

# --json FILE: a run that failed writes no file (the message is on stderr), whether it failed on
# the data or on another output (--plot exists).
set +e
"$exe" identify breakaway "$tmp/cell.csv" --json "$tmp/never.json" > /dev/null 2> "$tmp/err.txt"
code=$?
set -e
[ "$code" -eq 2 ] || fail "bad cell with --json FILE: exit $code"
[ ! -e "$tmp/never.json" ] || fail "a run that failed on its data wrote --json"
touch "$tmp/exists.svg"
set +e
"$exe" identify breakaway "$tmp/cell.csv" --json "$tmp/never.json" --plot "$tmp/exists.svg" > /dev/null 2> "$tmp/err.txt"
code=$?
set -e
[ "$code" -eq 2 ] || fail "existing --plot: exit $code"
[ ! -e "$tmp/never.json" ] || fail "a refused output still wrote --json"
echo "contract_json: ok"
