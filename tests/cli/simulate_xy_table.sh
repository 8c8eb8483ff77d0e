#!/usr/bin/env bash
# frictionlab simulate on the two-axis table: examples/xy_circle.yaml writes per-axis columns
# (x.position, ..., y.drive) and a per-axis summary; a circle or path defines the references; bad
# keys are exit 2 naming the key, and nothing is written.
source "$(dirname "$0")/lib.sh"

"$exe" simulate "$src/examples/xy_circle.yaml" -o "$tmp/run.csv" 2> "$tmp/summary.txt"
want='time'
for axis in x y; do
  for c in position velocity friction applied current voltage reference stuck drive; do want="$want,$axis.$c"; done
done
[ "$(head -1 "$tmp/run.csv")" = "$want" ] || fail "header: $(head -1 "$tmp/run.csv")"
rows=$(wc -l < "$tmp/run.csv")
[ "$rows" -eq 6285 ] || fail "expected 6285 lines (header + 6284 rows: 2 turns of 6.283 s at 1 kHz), got $rows"
grep -q '^plant      xy-table' "$tmp/summary.txt" || fail "summary: $(cat "$tmp/summary.txt")"
grep -q '^friction   x: stribeck' "$tmp/summary.txt" || fail "summary names x's law: $(cat "$tmp/summary.txt")"
grep -q '^           y: stribeck' "$tmp/summary.txt" || fail "summary names y's law: $(cat "$tmp/summary.txt")"
# The references run the circle: x.reference^2 + y.reference^2 = R^2 on every row (R = 10 mm).
# Columns: time, then x's nine (reference is the 7th: column 8), then y's (column 17).
awk -F, 'NR > 1 { r = sqrt($8 * $8 + $17 * $17); if (r < 0.01 - 1e-12 || r > 0.01 + 1e-12) bad++ }
  END { exit bad > 0 }' "$tmp/run.csv" || fail "x.reference, y.reference off the circle"

# A path from a CSV, in mm, relative to the scenario's directory.
printf 'time,x,y\n0,0,0\n0.1,2,0\n0.2,2,2\n' > "$tmp/path.csv"
sed -e '/^input:/,$d' "$src/examples/xy_circle.yaml" > "$tmp/path.yaml"
printf 'input: {type: path, file: path.csv, scale: 0.001}\noutput_rate: 100\n' >> "$tmp/path.yaml"
"$exe" simulate "$tmp/path.yaml" -o "$tmp/path_run.csv" 2> /dev/null
[ "$(wc -l < "$tmp/path_run.csv")" -eq 22 ] || fail "path: expected header + 21 rows (0.2 s at 100 Hz)"

sed 's/feed: 0.02 /speed: 0.02 /' "$src/examples/xy_circle.yaml" > "$tmp/bad.yaml"
expect_fail "bad.yaml: input.speed: unknown field 'speed'" simulate "$tmp/bad.yaml" -o "$tmp/bad.csv"
[ ! -e "$tmp/bad.csv" ] || fail "output written for a bad scenario"
sed 's/lead: 0.01 /pitch: 0.01 /' "$src/examples/xy_circle.yaml" > "$tmp/bad.yaml"
expect_fail "bad.yaml: plant.axes.x.pitch: unknown field 'pitch'" simulate "$tmp/bad.yaml" -o "$tmp/bad.csv"
sed 's/limit: 800,/limit: -800,/' "$src/examples/xy_circle.yaml" > "$tmp/bad.yaml"
expect_fail "bad.yaml: plant: xy-table: axis y: limit = -800 must be >= 0 (N" simulate "$tmp/bad.yaml" -o "$tmp/bad.csv"
echo "ok"
