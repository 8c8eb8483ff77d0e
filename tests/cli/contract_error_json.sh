#!/usr/bin/env bash
# The error JSON (README "Guarantees"): a failed run with --json - prints one JSON object with
# "status": "error", "message" and "error": {"code", "message", and the fields that locate the
# fault: file, row, column, key, option, value}; bad input that has no code of its own yet is
# input.invalid. Bytes that are not UTF-8 (a CSV header, a file name) never break the JSON: the
# run still prints it, with those bytes escaped as \xNN.
# Usage: contract_error_json.sh PATH_TO_frictionlab SOURCE_DIR
source "$(dirname "$0")/lib.sh"
# shellcheck source=lib.sh

# error_json CODE PYTHON_EXPR ARGS...: the run exits 2, stdout is one JSON object whose error has
# CODE, its message equals the top-level message, and EXPR holds over e (the error object).
error_json() {
  local code="$1" check="$2"
  shift 2
  expect 2 "" "$@"
  /usr/bin/python3 - "$tmp/out.txt" "$code" "$check" <<'PY'
import json, sys
text = open(sys.argv[1], encoding="utf-8").read()
assert text.count("\n") == 1, text
j = json.loads(text)
e = j["error"]
assert j["status"] == "error" and j["schema"] == 2, j
assert e["code"] == sys.argv[2], (e, sys.argv[2])
assert e["message"] == j["message"] and e["message"], j
assert eval(sys.argv[3]), (sys.argv[3], e)
PY
}

"$exe" simulate "$src/examples/virgala_motor_sweep.yaml" -o "$tmp/sweep.csv" > /dev/null
sweep=(identify sweep "$tmp/sweep.csv" --kt 0.039)

# Data: a missing column (with its option), a text cell (its line and column), a missing file.
error_json data.column_missing "e['file'] == '$tmp/sweep.csv' and e['column'] == 'clock' and e['option'] == '--time'" \
  "${sweep[@]}" --time clock --json -
printf 'time,velocity,current\n0,1,0.1\n0.1,1,0.1\n0.2,1,0.1\n0.3,1,0.1\n0.4,abc,0.1\n' > "$tmp/text.csv"
error_json data.not_a_number "e['row'] == 6 and e['value'] == 'abc' and e['file'] == '$tmp/text.csv' and e['column'] == 'velocity'" \
  identify sweep "$tmp/text.csv" --kt 0.039 --json -
error_json data.file_unreadable "e['file'] == '$tmp/none.csv'" identify sweep "$tmp/none.csv" --kt 0.039 --json -
error_json data.file_type "e['value'] == '.log'" identify sweep "$tmp/sweep.log" --kt 0.039 --json -
error_json option.out_of_range "e['option'] == '--resample' and e['value'] == '-1'" "${sweep[@]}" --resample=-1 --json -

# Scenario: an unknown key, with the file and the dotted key.
sed 's/^  type: pendulum/  type: pendulum\n  colour: red/' "$src/examples/craig_pendulum_coulomb.yaml" > "$tmp/s.yaml"
error_json scenario.key_unknown "e['file'] == '$tmp/s.yaml' and e['key'] == 'plant.colour'" \
  analyze map "$tmp/s.yaml" --vary friction.Fs=0.2:0.3:2 --json -

# Outputs: an existing file without --overwrite.
touch "$tmp/exists.json"
error_json output.exists "e['file'] == '$tmp/exists.json' and e['option'] == '-o'" \
  analyze map "$src/examples/craig_pendulum_coulomb.yaml" --vary friction.Fs=0.2:0.3:2 -o "$tmp/exists.json" --json -

# Bad input without a code of its own yet: input.invalid.
error_json input.invalid "set(e) == {'code', 'message'}" plan breakaway --prior "$src/examples/plan/craig_motor_prior.json" \
  --scenario "$src/examples/craig_motor_trapezoid.yaml" --runs 1 -o "$tmp/p.csv" --json -

# Bytes that are not UTF-8 in a header and in the file name: a run that succeeds prints valid
# JSON; an error naming them too (the message lists the columns).
name="$(printf 'sweep\xe9.csv')"
sed '1s/$/,temp\xe9rature/; 2,$s/$/,20/' "$tmp/sweep.csv" > "$tmp/$name"
expect 0 "" identify sweep "$tmp/$name" --kt 0.039 --json -
/usr/bin/python3 - "$tmp/out.txt" <<'PY'
import json, sys
j = json.loads(open(sys.argv[1], "rb").read().decode("utf-8"))
assert j["status"] == "ok", j
assert j["data"]["file"].endswith("sweep\\xE9.csv"), j["data"]["file"]
PY
error_json data.column_missing "'temp\\\\xE9rature' in e['message'] and e['file'].endswith('sweep\\\\xE9.csv')" \
  identify sweep "$tmp/$name" --kt 0.039 --time clock --json -
echo "ok"
