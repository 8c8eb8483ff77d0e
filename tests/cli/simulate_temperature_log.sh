#!/usr/bin/env bash
# A log's temperature column replayed by simulate: environment: {temperature: {type: data, column: T}}
# gives the law its temperature at each instant (the run's temperature column is the log's, the
# viscous friction the one at that temperature); a column the log lacks is exit 2 naming it.
source "$(dirname "$0")/lib.sh"
/usr/bin/python3 - "$tmp/log.csv" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("time,T\n")
    for k in range(201):
        f.write(f"{k * 0.01:.2f},{20 + 10 * k * 0.01:.6f}\n")  # 20 to 40 degC over 2 s
PY
cat > "$tmp/warm.yaml" <<'YAML'
data: log.csv
plant: {type: axis, M: 1.0}
friction: {law: viscous, Fv: 1, T_ref: 20, Fv_per_K: -0.01, T_max: 80}
input: {type: constant, value: 0}
initial: {velocity: 1}
duration: 2
output_rate: 100
environment: {temperature: {type: data, column: T}}
YAML
expect 0 "" simulate "$tmp/warm.yaml" -o "$tmp/run.csv"
/usr/bin/python3 - "$tmp/run.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 201, len(rows)
for r in rows:
    t, T = float(r["time"]), float(r["temperature"])
    assert abs(T - (20 + 10 * t)) <= 1e-9 * T, (t, T)   # the log, linear between its rows
    Fv = 1 - 0.01 * (T - 20)
    v, f = float(r["velocity"]), float(r["friction"])
    assert abs(f - Fv * v) <= 1e-9 * abs(Fv * v), (t, f, Fv * v)   # the law at the logged temperature
PY
sed -i 's/column: T}/column: temp}/' "$tmp/warm.yaml"
expect_fail "temp" simulate "$tmp/warm.yaml" -o "$tmp/bad.csv"
[ ! -e "$tmp/bad.csv" ] || fail "a refused run left its output"
echo "PASS simulate_temperature_log"
