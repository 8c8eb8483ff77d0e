#!/usr/bin/env bash
# frictionlab validate on a two-axis table: a circular-test log of "the machine" (examples/xy_circle.yaml
# simulated with perturbed friction and mass, then encoder noise and quantisation, columns renamed
# as a logger names them) against one identified MODEL.json per axis (x=...,y=...): per-axis
# relative errors and the contour figures of measured and simulated in --json and text, the
# contour and polar error figures in --plot and --report, and bad input (a one-axis model on the
# table, a missing column, an unknown axis) exiting 2 naming the key or column.
source "$(dirname "$0")/lib.sh"
# shellcheck source=lib.sh
scenario="$src/examples/xy_circle.yaml"

# The real machine: x has 10 % more friction and 1 kg more; y a lower Coulomb and higher static level.
sed -e 's/Fc: 25, Fs: 40, vs: 0.002, delta: 2, Fv: 150/Fc: 27.5, Fs: 44, vs: 0.002, delta: 2, Fv: 165/' \
    -e 's/Fc: 15, Fs: 25, vs: 0.002, delta: 2, Fv: 100/Fc: 13.5, Fs: 27.5, vs: 0.002, delta: 2, Fv: 100/' \
    -e 's/mass: 15 /mass: 16 /' "$scenario" > "$tmp/machine.yaml"
! cmp -s "$scenario" "$tmp/machine.yaml" || fail "the perturbation changed nothing"
"$exe" simulate "$tmp/machine.yaml" -o "$tmp/true.csv" 2> /dev/null
# The log: 0.2 um noise, 0.5 um encoder steps, drive commands in volts (10 N/V x, 5 N/V y).
/usr/bin/python3 - "$tmp/true.csv" "$tmp/log.csv" <<'PY'
import sys
import numpy as np
d = np.genfromtxt(sys.argv[1], delimiter=",", names=True)
rng = np.random.default_rng(3)
enc = lambda q: 0.5e-6 * np.round((q + rng.normal(0, 0.2e-6, q.size)) / 0.5e-6)
cols = [d["time"], enc(d["xposition"]), enc(d["yposition"]), d["xdrive"] / 10, d["ydrive"] / 5]
np.savetxt(sys.argv[2], np.column_stack(cols), delimiter=",", header="t,X,Y,ux,uy", comments="", fmt="%.10g")
PY

model() {  # model FILE LAW_JSON M: a MODEL.json as identify --json writes it
  printf '{"schema": 1, "status": "ok", "method": "idim", "law": %s,\n "parameters": {"M": {"value": %s, "std": 0.1, "unit": "kg"}, "offset": {"value": 0, "std": 0.01, "unit": "N"}}}\n' \
    "$2" "$3" > "$1"
}
# Equivalent masses: mass + inertia (2 pi / 0.01)^2 = mass + 11.84 (x), + 7.896 (y) kg.
model "$tmp/x_true.json" '{"law": "stribeck", "Fc": 27.5, "Fs": 44, "vs": 0.002, "delta": 2, "Fv": 165}' 27.844
model "$tmp/y_true.json" '{"law": "stribeck", "Fc": 13.5, "Fs": 27.5, "vs": 0.002, "delta": 2, "Fv": 100}' 13.896
model "$tmp/x_nominal.json" '{"law": "stribeck", "Fc": 25, "Fs": 40, "vs": 0.002, "delta": 2, "Fv": 150}' 26.844
cols=(--time t --x X --y Y --x-force ux --y-force uy --scale ux=10 --scale uy=5)

"$exe" validate "x=$tmp/x_true.json,y=$tmp/y_true.json" "$tmp/log.csv" --scenario "$scenario" "${cols[@]}" \
  --json "$tmp/exact.json" --plot "$tmp/exact.svg" --report "$tmp/report" > "$tmp/exact.txt"
grep -q "largest quadrant glitch" "$tmp/exact.txt" || { cat "$tmp/exact.txt"; fail "text: no contour table"; }
grep -q "^  x.position" "$tmp/exact.txt" && grep -q "^  y.force" "$tmp/exact.txt" || { cat "$tmp/exact.txt"; fail "text: per-axis errors"; }
# The model's parameters: the '=' in one column (x.offset is longer than the 1-DOF names), a unit
# after each value that has one and no trailing blank after one that has none (delta).
/usr/bin/python3 - "$tmp/exact.txt" <<'PY' || { cat "$tmp/exact.txt"; fail "text: the parameter lines are not aligned"; }
import re, sys
lines = [l for l in open(sys.argv[1]).read().splitlines() if re.match(r"  [xy]\.\w+ +=", l)]
assert len(lines) >= 10, lines
assert len({l.index(" = ") for l in lines}) == 1, lines
assert not [l for l in lines if l != l.rstrip()], lines
PY
# The figure is the circular test with both paths; the report has the contour, the axes and the polar plots.
grep -q "<svg" "$tmp/exact.svg" && grep -q "simulated" "$tmp/exact.svg" && grep -q "nominal circle" "$tmp/exact.svg" ||
  fail "validate --plot: not the measured and simulated contour"
for f in contour axes measured-contour simulated-contour; do
  [ -s "$tmp/report/$f.svg" ] || fail "report: no $f.svg"
done
grep -q "quadrant glitches sit at the axis reversals" "$tmp/report/report.html" || fail "report: no contour caption"
# The report's validation tables: every signal's error and the contour figures, measured and simulated.
grep -q "<h2 id=\"validation\">" "$tmp/report/report.html" && grep -q "<td>y.force</td>" "$tmp/report/report.html" ||
  fail "report: no per-axis validation table"
grep -q "<td>max_quadrant_glitch_m</td>" "$tmp/report/report.html" && grep -q "<th>simulated</th>" "$tmp/report/report.html" ||
  fail "report: no contour table"
[ "$(grep -c "<svg" "$tmp/report/report.html")" -ge 4 ] || fail "report: fewer than 4 inline figures"

# Only x from the nominal model (y keeps the scenario's law): a worse fit of the glitch.
"$exe" validate "x=$tmp/x_nominal.json" "$tmp/log.csv" --scenario "$scenario" "${cols[@]}" --json - \
  2> "$tmp/nominal.txt" > "$tmp/nominal.json"
grep -q "roundness" "$tmp/nominal.txt" || fail "text goes to stderr with --json -"
/usr/bin/python3 - "$tmp/exact.json" "$tmp/nominal.json" <<'PY'
import json, sys
exact, nominal = (json.load(open(p)) for p in sys.argv[1:])
for j in (exact, nominal):
    assert j["schema"] == 2 and j["status"] == "ok" and j["method"] == "validate", j
    v = j["validation"]
    assert v["file"].endswith("log.csv") and len(v["sha256"]) == 64, v
    keys = {f"{a}.{s}" for a in "xy" for s in ("position", "velocity", "acceleration", "force")}
    assert set(v["relative_error_percent"]) == keys, v["relative_error_percent"]
    c = v["contour"]
    for side in ("measured", "simulated"):
        assert len(c[side]["quadrant_glitch_m"]) == 4 and c[side]["roundness_m"] > 0, c[side]
    assert c["measured"]["max_quadrant_glitch_m"] > 10e-6, c["measured"]  # the log shows the glitches
e = exact["validation"]
# Exact models: positions to the encoder's noise (0.2 um in 10 mm), the glitch within 5 %.
assert e["relative_error_percent"]["x.position"] < 0.01 and e["relative_error_percent"]["y.position"] < 0.01, e
gm = e["contour"]["measured"]["max_quadrant_glitch_m"]
assert abs(e["contour"]["difference"]["max_quadrant_glitch_m"]) < 0.05 * gm, e["contour"]
# The nominal x model (10 % less friction than the machine) misses the glitch by more.
n = nominal["validation"]
assert abs(n["contour"]["difference"]["max_quadrant_glitch_m"]) > 3 * abs(e["contour"]["difference"]["max_quadrant_glitch_m"]), n["contour"]
assert n["relative_error_percent"]["x.force"] > e["relative_error_percent"]["x.force"], (n, e)
assert exact["parameters"]["x.Fs"]["value"] == 44 and exact["parameters"]["y.M"]["unit"] == "kg", exact["parameters"]
assert nominal["diagnostics"]["y.model"] == "scenario", nominal["diagnostics"]
PY

# Defaults: a log with the columns simulate writes (x.position, ..., x.drive) needs no column options.
"$exe" validate "x=$tmp/x_true.json" "$tmp/true.csv" --scenario "$scenario" --json - 2> /dev/null > "$tmp/defaults.json"
/usr/bin/python3 -c 'import json,sys; e = json.load(open(sys.argv[1]))["validation"]["relative_error_percent"]; assert "y.force" in e, e' "$tmp/defaults.json"

# Bad input: exit 2, one line naming the key or column; nothing written.
expect_fail "the xy-table has two axes (x, y): a one-axis model" \
  validate "$tmp/x_true.json" "$tmp/log.csv" --scenario "$scenario" "${cols[@]}" --json "$tmp/bad.json"
expect_fail "the xy-table has no axis 'z'; expected x or y" \
  validate "z=$tmp/x_true.json" "$tmp/log.csv" --scenario "$scenario" "${cols[@]}"
expect_fail "no column 'Y_missing' (--y)" \
  validate "x=$tmp/x_true.json" "$tmp/log.csv" --scenario "$scenario" --time t --x X --y Y_missing
expect_fail "no column 'x.position' (--x)" \
  validate "x=$tmp/x_true.json" "$tmp/log.csv" --scenario "$scenario" --time t --y Y
expect_fail "no column 'vx' (--x-force)" \
  validate "x=$tmp/x_true.json" "$tmp/log.csv" --scenario "$scenario" --time t --x X --y Y --x-force vx
expect_fail "'x' is not AXIS=FILE" \
  validate "x=$tmp/x_true.json,x" "$tmp/log.csv" --scenario "$scenario" "${cols[@]}"
expect_fail "axis 'x' is given twice" \
  validate "x=$tmp/x_true.json,x=$tmp/x_nominal.json" "$tmp/log.csv" --scenario "$scenario" "${cols[@]}"
expect_fail "models named by axis (x) need a two-axis plant (xy-table)" \
  validate "x=$tmp/x_true.json" "$tmp/log.csv" --scenario "$src/examples/craig_motor_trapezoid.yaml" --time t
[ ! -e "$tmp/bad.json" ] || fail "a failed run wrote its --json file"
echo "ok"
