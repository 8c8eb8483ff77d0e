#!/usr/bin/env bash
# frictionlab identify with bad input: exit 2, a message naming the file, row, column or option
# and what was expected; no output file is left behind.
source "$(dirname "$0")/lib.sh"
# shellcheck source=lib.sh
emps="$src/data/emps/DATA_EMPS.mat"

expect_identify_fail() {  # text the message must contain, then the identify arguments
  local want="$1"
  shift
  expect_fail "$want" identify "$@" --json "$tmp/out.json"
}

# A missing variable is named and the file's variables are listed.
expect_identify_fail "no column 'qx'" idim "$emps" --time t --position qx --input vir --gain gtau
expect_identify_fail "qm" idim "$emps" --time t --position qx --input vir --gain gtau
# A gain that is neither a number nor a scalar of the file.
expect_identify_fail "--gain" idim "$emps" --time t --position qm --input vir --gain gtaux
# CSV: a NaN cell names its line and column; non-increasing time names its line.
printf 'time,velocity,force\n0,0,0\n0.01,0,nan\n0.02,0,0.1\n' > "$tmp/nan.csv"
expect_identify_fail "line 3" breakaway "$tmp/nan.csv"
printf 'time,velocity,force\n0,0,0\n0.01,0,0\n0.01,0,0.1\n0.03,0,0.2\n' > "$tmp/time.csv"
expect_identify_fail "line 4" breakaway "$tmp/time.csv"
# A corrupt .mat file is an error naming the file, never a crash.
head -c 300 "$emps" > "$tmp/broken.mat"
expect_identify_fail "broken.mat" idim "$tmp/broken.mat" --time t --position qm --input vir --gain gtau
# No motion: a diagnostic, with the JSON still written with status error.
python3 - "$tmp/still.csv" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("time,velocity,force\n")
    for k in range(200):
        f.write(f"{k*0.01},0,{k*1e-4}\n")
PY
expect_identify_fail "no motion detected" breakaway "$tmp/still.csv"
grep -q '"status": "error"' "$tmp/out.json" || { echo "FAIL: error JSON not written"; exit 1; }
rm -f "$tmp/out.json"
# Unknown sweep model lists the valid ones.
expect_identify_fail "expected coulomb-viscous, coulomb-viscous-asymmetric, stribeck or stribeck-asymmetric" sweep "$tmp/still.csv" --model lugre
# A decay without stiffness or natural frequency.
expect_identify_fail "give --stiffness" decay "$tmp/still.csv" --position velocity
# An unknown method.
set +e
"$exe" identify magic "$emps" > /dev/null 2>&1
code=$?
set -e
[ "$code" -eq 2 ] || { echo "FAIL: unknown method: exit $code"; exit 1; }
echo "identify_bad_input: ok"
