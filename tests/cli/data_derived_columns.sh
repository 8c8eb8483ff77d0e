#!/usr/bin/env bash
# Derived columns: a torque-sensing joint's friction formed on the command line as an expression of
# columns (`--force 'motor - link'`), evaluated after --scale, gives the same identification as
# the precomputed column; a name with spaces goes between backquotes; bad expressions exit 2
# naming the option, the expression and the place.
source "$(dirname "$0")/lib.sh"
cd "$tmp"
/usr/bin/python3 "$src/tests/rigs/servo_log.py" servo.csv --seed 3 --law coulomb-viscous
# The drive's force (kt * current) split into what a joint with a torque sensor logs: the motor's
# torque and a link torque in mN (so it needs --scale), whose difference is the drive force.
/usr/bin/python3 - servo.csv <<'PY'
import numpy as np, sys
d = np.loadtxt(sys.argv[1], delimiter=",")
t, q, i = d[:, 0], d[:, 1], d[:, 4]
force = 0.5 * i
link = 0.25 * np.sin(7.0 * t)           # N, any signal: it cancels in the difference
motor = force + link
np.savetxt("plain.csv", np.column_stack([t, q, force]), delimiter=",", header="time,position,force", comments="")
np.savetxt("joint.csv", np.column_stack([t, q, motor, link * 1e3]), delimiter=",",
           header="time,position,motor torque,link_mN", comments="")
PY
common=(--resample --exclude-below 0.002)
"$exe" identify idim plain.csv "${common[@]}" --json plain.json > /dev/null
"$exe" identify idim joint.csv "${common[@]}" --force '`motor torque` - link_mN' --scale link_mN=1e-3 --json joint.json > /dev/null
/usr/bin/python3 - plain.json joint.json <<'PY'
import json, sys
a, b = (json.load(open(f)) for f in sys.argv[1:3])
assert a["status"] == b["status"] == "ok", (a["message"], b["message"])
# The derived force differs from the precomputed one by rounding only (the CSV holds 18 digits
# of each; motor - link reproduces force to ~1e-15 relative), so the parameters agree to 1e-9.
REL = 1e-9
for k, p in a["parameters"].items():
    v, w = p["value"], b["parameters"][k]["value"]
    assert abs(v - w) <= REL * max(1.0, abs(v)), (k, v, w)
PY

# Bad expressions: exit 2, one line naming the option, the expression and what is wrong.
expect 2 "joint.csv: no column 'link' (--force 'motor - link'); the file has columns: time, position, motor torque, link_mN" \
  identify idim joint.csv --resample --force 'motor - link'
expect 2 "--force '\`motor torque\` -': ends where a column, a number or '(' was expected" \
  identify idim joint.csv --resample --force '`motor torque` -'
expect 2 "--force '\`motor torque - link_mN': the backquote at character 1 is not closed" \
  identify idim joint.csv --resample --force '`motor torque - link_mN'
expect 2 "--force '\`motor torque\` / 0' is" \
  identify idim joint.csv --resample --force '`motor torque` / 0'
echo ok
