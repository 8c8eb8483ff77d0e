#!/usr/bin/env bash
# --format: a text table whose name does not say so (a robot's .log, a .dat) is read with
# --format csv and gives the same answer as the .csv; .tsv and .txt are tables by their
# extension; an unknown extension without --format names the option; a table read as mat, or a
# format that does not exist, is refused (exit 2).
source "$(dirname "$0")/lib.sh"
cd "$tmp"
/usr/bin/python3 "$src/tests/rigs/servo_log.py" servo.csv --seed 3 --law coulomb-viscous
cp servo.csv robot.log
cp servo.csv robot.txt
tr ',' '\t' < servo.csv > robot.tsv
opts=(--names time,position,q_ref,v_est,current --kt 0.5 --resample --exclude-below 0.002)
"$exe" identify idim servo.csv "${opts[@]}" --json csv.json > /dev/null
"$exe" identify idim robot.log --format csv "${opts[@]}" --json log.json > /dev/null
"$exe" identify idim robot.txt "${opts[@]}" --json txt.json > /dev/null
"$exe" identify idim robot.tsv "${opts[@]}" --json tsv.json > /dev/null
/usr/bin/python3 - csv.json log.json txt.json tsv.json <<'PY'
import json, sys
a = json.load(open(sys.argv[1]))
assert a["status"] == "ok", a["message"]
for f in sys.argv[2:]:
    b = json.load(open(f))
    # The same cells through the same reader: the same numbers, bit for bit.
    for k, p in a["parameters"].items():
        assert p["value"] == b["parameters"][k]["value"], (f, k, p["value"], b["parameters"][k]["value"])
PY
expect_fail "robot.log: unknown data file type '.log'; expected a .csv, .tsv or .txt file" identify idim robot.log "${opts[@]}"
expect_fail "(--format csv or --format mat" identify idim robot.log "${opts[@]}"
expect_fail "servo.csv" identify idim servo.csv --format mat "${opts[@]}"
expect_fail "--format" identify idim servo.csv --format xls "${opts[@]}"
