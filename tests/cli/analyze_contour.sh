#!/usr/bin/env bash
# frictionlab analyze contour on the circular test of examples/xy_circle.yaml: the JSON carries
# the four quadrant glitches (each well above the radial error away from the reversals), the
# largest radial error and the roundness; --plot draws the polar figure with its scale; bad
# input is exit 2 naming the file and column, and leaves no output behind.
source "$(dirname "$0")/lib.sh"

"$exe" simulate "$src/examples/xy_circle.yaml" -o "$tmp/run.csv" 2> /dev/null
"$exe" analyze contour "$tmp/run.csv" > "$tmp/text.txt"
grep -q '^roundness ' "$tmp/text.txt" || fail "text lacks roundness: $(cat "$tmp/text.txt")"
grep -q '^  180 deg ' "$tmp/text.txt" || fail "text lacks the 180 deg glitch: $(cat "$tmp/text.txt")"
"$exe" analyze contour "$tmp/run.csv" --json - 2> /dev/null > "$tmp/c.json"
/usr/bin/python3 - "$tmp/c.json" "$tmp/run.csv" <<'PY'
import csv, json, math, sys
j = json.load(open(sys.argv[1]))
assert j["status"] == "ok" and j["method"] == "contour", j
d = j["diagnostics"]
g = d["quadrant_glitch_m"]
assert len(g) == 4 and all(isinstance(v, float) for v in g), g
assert d["max_radial_error_m"] >= max(abs(v) for v in g) * 0.5, d
assert j["result"]["roundness_m"] >= d["max_radial_error_m"], j["result"]
assert j["result"]["centre_from"] == "reference" and abs(j["result"]["radius_m"] - 0.01) < 1e-12, j["result"]
# The radial error away from the reversals (more than 30 deg from each, past the 0.2 s start
# transient), from the CSV itself: each glitch is above 10 times it (the example's ratio is ~100).
elsewhere = 0.0
for row in csv.DictReader(open(sys.argv[2])):
    if float(row["time"]) < 0.2:
        continue
    x, y = float(row["x.position"]), float(row["y.position"])
    deg = math.degrees(math.atan2(y, x)) % 360
    if abs(math.remainder(deg, 90)) >= 30:
        elsewhere = max(elsewhere, abs(math.hypot(x, y) - 0.01))
assert elsewhere > 0
for k, v in enumerate(g):
    assert abs(v) > 10 * elsewhere, f"glitch at {90 * k} deg {v} m not above 10 x {elsewhere} m"
PY

# --plot: the polar error plot states its magnification and ring scale.
"$exe" analyze contour "$tmp/run.csv" --plot "$tmp/c.svg" > /dev/null
[ -s "$tmp/c.svg" ] || fail "no figure"
grep -q 'radial error x' "$tmp/c.svg.gp" || fail "the figure does not state its magnification"
grep -q 'dashed rings: +-' "$tmp/c.svg.gp" || fail "the figure does not state its ring scale"

# simulate --plot on the two-axis table draws the same circular test.
"$exe" simulate "$src/examples/xy_circle.yaml" --plot "$tmp/sim.svg" 2> /dev/null
grep -q 'radial error x' "$tmp/sim.svg.gp" || fail "simulate --plot on an xy-table draws no polar error plot"

# Without the reference columns: the centre and radius from a fit of the measured path.
cut -d, -f1,2,11 "$tmp/run.csv" > "$tmp/measured.csv"
"$exe" analyze contour "$tmp/measured.csv" --json - 2> /dev/null | grep -q '"centre_from":"fit"' ||
  fail "no fit without the reference"

# Bad input: a missing column (named, with its option), a NaN cell, less than one turn, a file
# that is not there; no JSON written.
expect_fail "x.reference" analyze contour "$tmp/measured.csv" --x-reference x.reference
expect_fail "run.csv" analyze contour "$tmp/run.csv" --x xpos
expect_fail "--x" analyze contour "$tmp/run.csv" --x xpos
head -1500 "$tmp/run.csv" > "$tmp/part.csv"
expect_fail "less than one turn" analyze contour "$tmp/part.csv" --json "$tmp/part.json"
[ ! -e "$tmp/part.json" ] || fail "JSON written for a failed run"
awk -F, 'NR == 50 { $2 = "nan" } 1' OFS=, "$tmp/run.csv" > "$tmp/nan.csv"
expect_fail "x.position" analyze contour "$tmp/nan.csv"
expect_fail "no-such.csv" analyze contour "$tmp/no-such.csv"
expect_fail "--radius" analyze contour "$tmp/run.csv" --radius -1
echo "analyze_contour: ok"
