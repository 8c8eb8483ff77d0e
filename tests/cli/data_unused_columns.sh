#!/usr/bin/env bash
# Logs as robots write them: a status text column and a sensor column with gaps and NaN, neither
# used by the command, do not refuse the file; the identification equals the one on the clean
# columns. A bad cell in a column the command uses is refused naming its line and column.
source "$(dirname "$0")/lib.sh"
cd "$tmp"
/usr/bin/python3 "$src/tests/rigs/servo_log.py" servo.csv --seed 5 --law coulomb-viscous
/usr/bin/python3 - servo.csv <<'PY'
import numpy as np, sys
d = np.loadtxt(sys.argv[1], delimiter=",")
with open("clean.csv", "w") as clean, open("robot.csv", "w") as robot:
    clean.write("time,position,current\n")
    robot.write("time,position,current,status,link_temp\n")
    for k, r in enumerate(d):
        cells = f"{r[0]!r},{r[1]!r},{r[4]!r}"
        clean.write(cells + "\n")
        status = "FAULT" if k % 997 == 0 else "OK"
        temp = "nan" if k == 100 else ("" if k == 200 else "31.5")
        robot.write(f"{cells},{status},{temp}\n")
# The same log with one NaN in the current, on data line 51 (file line 52).
lines = open("robot.csv").read().splitlines()
cells = lines[51].split(",")
cells[2] = "nan"
lines[51] = ",".join(cells)
open("bad_current.csv", "w").write("\n".join(lines) + "\n")
PY
opts=(--kt 0.5 --resample --exclude-below 0.002)
"$exe" identify idim clean.csv "${opts[@]}" --json clean.json > /dev/null
"$exe" identify idim robot.csv "${opts[@]}" --json robot.json > /dev/null
/usr/bin/python3 - clean.json robot.json <<'PY'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
assert a["status"] == b["status"] == "ok", (a["message"], b["message"])
# The same samples of the same columns: the parameters are the same numbers.
for k, p in a["parameters"].items():
    assert p["value"] == b["parameters"][k]["value"], (k, p["value"], b["parameters"][k]["value"])
PY
expect 2 "robot.csv: line 2, column 4 'status': expected a number, got 'FAULT'" \
  identify idim robot.csv "${opts[@]}" --terms inertia,viscous,coulomb,offset,temperature --temperature status
expect 2 "bad_current.csv: line 52, column 3 'current': 'nan'; expected a finite number (use --drop-invalid to skip such rows)" \
  identify idim bad_current.csv "${opts[@]}"
echo ok
