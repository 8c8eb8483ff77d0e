#!/usr/bin/env bash
# frictionlab analyze on simulate output: the four Craig pendulum cases classify as
# none / exponential / linear / mixed; the Canudas stick-slip period is 6.36 s; bad columns exit 2.
source "$(dirname "$0")/lib.sh"

for pair in frictionless:none viscous:exponential coulomb:linear combined:mixed; do
  case_name="${pair%%:*}"
  kind="${pair##*:}"
  "$exe" simulate "$src/examples/craig_pendulum_$case_name.yaml" -o "$tmp/$case_name.csv" 2> /dev/null
  "$exe" analyze envelope "$tmp/$case_name.csv" --json "$tmp/$case_name.json" > /dev/null
  grep -q "\"kind\": \"$kind\"" "$tmp/$case_name.json" || { echo "FAIL: $case_name is not $kind"; cat "$tmp/$case_name.json"; exit 1; }
done

"$exe" simulate "$src/examples/canudas_stick_slip.yaml" -o "$tmp/ss.csv" 2> /dev/null
"$exe" analyze stick-slip "$tmp/ss.csv" --json - 2> /dev/null > "$tmp/ss.json"
/usr/bin/python3 - "$tmp/ss.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert r["status"] == "ok", r
p = r["result"]["period"]
v = r["result"]["peak_slip_velocity"]
assert abs(p - 6.3627) < 0.02, p
assert abs(v - 0.3698) < 0.002, v
PY

set +e
"$exe" analyze stick-slip "$tmp/ss.csv" --velocity speed 2> "$tmp/err.txt"
code=$?
set -e
[ "$code" -eq 2 ] || { echo "FAIL: unknown column gave exit $code"; exit 1; }
grep -q "no column 'speed'" "$tmp/err.txt" || { echo "FAIL: message: $(cat "$tmp/err.txt")"; exit 1; }
echo "ok"
