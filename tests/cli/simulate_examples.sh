#!/usr/bin/env bash
# frictionlab simulate: every example runs; -o writes the CSV with the documented header;
# an existing file is refused without --overwrite (exit 2) and replaced with it.
source "$(dirname "$0")/lib.sh"

for f in "$src"/examples/*.yaml; do
  "$exe" simulate "$f" > "$tmp/summary.txt" || { echo "FAIL: simulate $f"; exit 1; }
  grep -q '^solver' "$tmp/summary.txt" || { echo "FAIL: no summary for $f"; exit 1; }
done

"$exe" simulate "$src/examples/craig_motor_trapezoid.yaml" -o "$tmp/out.csv" 2> /dev/null
head -1 "$tmp/out.csv" | grep -qx 'time,position,velocity,friction,applied,current,voltage,reference,stuck' \
  || { echo "FAIL: header: $(head -1 "$tmp/out.csv")"; exit 1; }
rows=$(wc -l < "$tmp/out.csv")
[ "$rows" -eq 14002 ] || { echo "FAIL: expected 14002 lines (header + 14001 rows), got $rows"; exit 1; }

set +e
"$exe" simulate "$src/examples/craig_motor_trapezoid.yaml" -o "$tmp/out.csv" 2> "$tmp/err.txt"
code=$?
set -e
[ "$code" -eq 2 ] || { echo "FAIL: overwrite without --overwrite gave exit $code"; exit 1; }
grep -q -- '--overwrite' "$tmp/err.txt" || { echo "FAIL: message: $(cat "$tmp/err.txt")"; exit 1; }
"$exe" simulate "$src/examples/craig_stick_slip.yaml" -o "$tmp/out.csv" --overwrite 2> /dev/null
rows=$(wc -l < "$tmp/out.csv")
[ "$rows" -eq 10002 ] || { echo "FAIL: --overwrite did not replace the file ($rows lines)"; exit 1; }
ls "$tmp" | grep -q tmp && { echo "FAIL: temporary file left behind"; exit 1; }
echo "ok"
