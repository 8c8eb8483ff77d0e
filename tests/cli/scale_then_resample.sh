#!/usr/bin/env bash
# --scale applies before --resample: a log whose time column is in ms, read with
# --scale t=0.001 --resample, is resampled in seconds, and its resampling report (dt_median, dt)
# gives the steps in s: the same figures as the same log written in seconds.
source "$(dirname "$0")/lib.sh"
cd "$tmp"
/usr/bin/python3 "$src/examples/robot_joint_log.py" joints.csv > /dev/null
# The same log with its time stamps in ms (first column), the comment line kept.
/usr/bin/python3 - <<'PY'
with open("joints.csv") as f, open("joints_ms.csv", "w") as g:
    for line in f:
        cells = line.rstrip("\n").split(",")
        try:
            cells[0] = repr(float(cells[0]) * 1000.0)
        except ValueError:
            pass
        g.write(",".join(cells) + "\n")
PY
cols=(--names t,q1,q2,q3,q4,q5,q6,v1,v2,v3,v4,v5,v6,i1,i2 --time t --position q2 --current i2 --kt 0.5 --axis rotary)
"$exe" identify idim joints.csv "${cols[@]}" --resample --json s.json > /dev/null
"$exe" identify idim joints_ms.csv "${cols[@]}" --scale t=0.001 --resample --json ms.json > /dev/null
/usr/bin/python3 - <<'PY'
import json
s = json.load(open("s.json"))["diagnostics"]
ms = json.load(open("ms.json"))["diagnostics"]
rs, rms = s["groups"]["resampling"] if "groups" in s else s["resampling"], ms["groups"]["resampling"] if "groups" in ms else ms["resampling"]
# Steps of about 11 ms: in s, not in ms. 1e-9: the ms log's stamps are the s log's times 1000
# written with 17 digits, so the steps agree to round-off.
for k in ("dt_median", "dt", "dt_min", "dt_max"):
    assert 0.005 < rms[k] < 0.02, (k, rms[k])
    assert abs(rms[k] - rs[k]) <= 1e-9 * rs[k], (k, rms[k], rs[k])
print("resampling in s:", {k: rms[k] for k in ("dt_median", "dt")})
PY
echo "PASS scale_then_resample"
