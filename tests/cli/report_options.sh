#!/usr/bin/env bash
# The report's Options table lists the options that applied to the run (docs/identify.md): every
# option given, and the defaults the run used. Without --iv, idim's IV options (--kp,
# --iv-iterations, --iv-tolerance) are not listed, nor the Stribeck term's --vs and --delta, nor
# outputs not asked for (--plot), the batch options, and the column defaults the run did not read
# (--velocity when it read the position; --force, --current: the force is --input times --gain);
# with --iv they are. A column default the run read is listed with the column taken (breakaway's
# --velocity 'velocity', --current 'current'). Every row has its unit on the run's axis, in a column
# of its own, the unit of this run: an option whose unit another option decides (--kp, --control-limit:
# the controller's type) shows the one the run's choice gives (1/s with --controller emps-pd, also
# when the --scenario gave the controller), never "X or Y"; MODEL.json's "options" say the same.
# validate's report follows the same rules. The result's recorded options (MODEL.json
# "options") still hold every option of the table.
source "$(dirname "$0")/lib.sh"
emps="$src/data/emps/DATA_EMPS.mat"
idim=(identify idim "$emps" --time t --position qm --input vir --gain gtau)

# options_of REPORT_DIR: the Options table as "NAME<TAB>VALUE<TAB>UNIT" lines in $tmp/options.txt.
options_of() {
  /usr/bin/python3 - "$1/report.html" > "$tmp/options.txt" <<'PY'
import html, re, sys
page = open(sys.argv[1], encoding="utf-8").read()
section = page.split('<h2 id="options">Options</h2>', 1)[1].split("</table>", 1)[0]
assert "<th>option</th><th>value</th><th>unit</th>" in section, section[:200]
for row in re.findall(r"<tr><td><code>(.*?)</code></td><td>(.*?)</td><td>(.*?)</td></tr>", section):
    print("\t".join(html.unescape(x) for x in row))
PY
}
# has NAME VALUE [UNIT]: the table lists NAME with exactly VALUE (and UNIT; none when UNIT is not
# given); lacks NAME: it does not list NAME.
has() { grep -qxF -- "$1	$2	${3:-}" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "the Options table lacks '$1 $2 ${3:-}'"; }; }
lacks() { ! grep -q -- "^$1	" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "the Options table lists $1"; }; }
# no_either_unit: no unit cell reads "X or Y" (every run below decides its units).
no_either_unit() {
  ! cut -f3 "$tmp/options.txt" | grep -q " or " || { cat "$tmp/options.txt"; fail "a unit cell names two units: the run decides which"; }
}

# Least squares: the options given, the defaults used; not the IV, Stribeck, ripple or output ones.
expect 0 "" "${idim[@]}" --delay 1 --report "$tmp/ls" --json "$tmp/ls.json"
options_of "$tmp/ls"
no_either_unit
has --time t s
has --position qm m
has --input vir
has --gain gtau "N per unit of --input"
has --delay 1 samples
has --json "$tmp/ls.json"
has --filter-order "4 (default)"
has --skip-end "0 (default)"
has --exclude-below "0 (default)" m/s
has --iv "false (default)"
has --terms "inertia,viscous,coulomb,offset (default)"
for name in --kp --kv --controller --iv-iterations --iv-tolerance --control-delay --vs --delta --ripple-harmonics \
  --plot --jobs --drift-threshold --table --force --current --velocity; do
  lacks "$name"
done
# The recorded options are every option of the table, as before.
/usr/bin/python3 - "$tmp/ls.json" <<'PY'
import json, sys
o = json.load(open(sys.argv[1]))["options"]
assert o["iv-iterations"]["given"] is False and o["iv-iterations"]["value"] == 20, o["iv-iterations"]
assert o["kp"]["value"] is None and o["vs"]["given"] is False, (o["kp"], o["vs"])
PY

# IDIM-IV (tests/cli/identify_iv.sh): its options given and its defaults are listed.
expect 0 "" "${idim[@]}" --iv --reference qg --controller emps-pd --kp 160.18 --kv 243.45 --report "$tmp/iv" \
  --json "$tmp/iv.json"
options_of "$tmp/iv"
no_either_unit
has --iv true
has --controller emps-pd
has --kp 160.18 1/s
has --kv 243.45 "V s/m"
has --reference qg m
grep -q "^--iv-iterations	[0-9]* (default)	$" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "--iv-iterations' default is not listed"; }
grep -q "^--iv-tolerance	.* (default)	$" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "--iv-tolerance's default is not listed"; }
lacks --kd
lacks --vs
/usr/bin/python3 - "$tmp/iv.json" <<'PY'
import json, sys
o = json.load(open(sys.argv[1]))["options"]
assert o["kp"]["unit"] == "1/s" and o["control-limit"]["unit"] == "V", (o["kp"], o["control-limit"])
# Only the temperature column's unit stays open: no option of a run decides degC or K.
either = [(k, v["unit"]) for k, v in o.items() if " or " in v["unit"]]
assert either == [("temperature", "degC or K"), ("temperature-ref", "degC or K")], either
PY
# The report's diagnostics give their figures' units too: the controller the IV simulated in its
# options' units as the run decided them, the rate defaults' cutoff in Hz.
grep -q '<tr><td>kp</td><td class="num">160.18</td><td>1/s</td></tr>' "$tmp/iv/report.html" ||
  fail "the report's iv_controller table lacks kp's unit 1/s"
grep -q '<tr><td>cutoff_hz</td><td class="num">100</td><td>Hz</td></tr>' "$tmp/iv/report.html" ||
  fail "the report's defaults table lacks the cutoff's unit Hz"
# The controller from the scenario (no --controller): its type decides --kp's unit, in the report
# and in MODEL.json.
expect 0 "" "${idim[@]}" --iv --reference qg --scenario "$src/examples/emps_closed_loop.yaml" --kp 160.18 \
  --report "$tmp/iv_scenario" --json "$tmp/iv_scenario.json"
options_of "$tmp/iv_scenario"
no_either_unit
has --kp 160.18 1/s
lacks --controller
/usr/bin/python3 - "$tmp/iv_scenario.json" <<'PY'
import json, sys
o = json.load(open(sys.argv[1]))["options"]
assert o["kp"]["unit"] == "1/s" and o["control-limit"]["unit"] == "V", (o["kp"], o["control-limit"])
PY

# The Stribeck term: its --vs and --delta defaults apply.
expect 0 "" "${idim[@]}" --terms inertia,viscous,coulomb,offset,stribeck --report "$tmp/stribeck"
options_of "$tmp/stribeck"
no_either_unit
has --terms "inertia,viscous,coulomb,offset,stribeck"
grep -q "^--vs	.* (default)	m/s$" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "--vs' default is not listed"; }
grep -q "^--delta	.* (default)	$" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "--delta's default is not listed"; }
lacks --kp

# The column defaults a run read, with the column taken and its unit: breakaway reads velocity (not
# the position) and, with --kt, the current; on a rotary axis.
expect 0 "" simulate "$src/examples/craig_motor_trapezoid.yaml" -o "$tmp/trapezoid.csv"
expect 0 "" identify breakaway "$tmp/trapezoid.csv" --kt 0.0141 --axis rotary --report "$tmp/breakaway"
options_of "$tmp/breakaway"
no_either_unit
has --time "time (default)" s
has --velocity "velocity (default)" rad/s
has --current "current (default)" A
has --kt 0.0141 "N m/A"
has --axis rotary
has --edge-samples "2 (default)"
lacks --position
lacks --force
lacks --input

# validate writes the same report: the options that applied, with units; the column it did not
# read (--velocity: it compares positions) and the two-axis plant's columns are not listed.
expect 0 "" identify idim "$emps" --time t --position qm --input vir --gain gtau --json "$tmp/model.json"
expect 0 "" validate "$tmp/model.json" "$src/data/emps/DATA_EMPS_PULSES.mat" --scenario "$src/examples/emps_closed_loop.yaml" \
  --time t --position qm --input vir --gain gtau --report "$tmp/validate"
grep -q "relative error" "$tmp/validate/report.html" || fail "validate's report lacks the relative errors"
options_of "$tmp/validate"
no_either_unit
has MODEL "$tmp/model.json"
has --scenario "$src/examples/emps_closed_loop.yaml"
has --time t s
has --position qm m
has --gain gtau "N per unit of --input"
has --axis "linear (default)"
for name in --velocity --force --current --x --y --x-force --y-force; do
  lacks "$name"
done
# --resample without DT: the step the run took (the median step), not an empty cell.
/usr/bin/python3 "$src/examples/robot_joint_log.py" "$tmp/joints.csv"
expect 0 "" identify idim "$tmp/joints.csv" --names t,q1,q2,q3,q4,q5,q6,v1,v2,v3,v4,v5,v6,i1,i2 --time t --position q2 \
  --current i2 --kt 0.5 --axis rotary --resample --report "$tmp/joints"
options_of "$tmp/joints"
no_either_unit
has --resample "0.011001 (the median step)" s
has --position q2 rad
echo ok
