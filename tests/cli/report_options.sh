#!/usr/bin/env bash
# The report's Options table lists the options that applied to the run (docs/identify.md): every
# option given, and the defaults the run used. Without --iv, idim's IV options (--kp,
# --iv-iterations, --iv-tolerance) are not listed, nor the Stribeck term's --vs and --delta, nor
# outputs not asked for (--plot), the batch options, and the column defaults the run did not read
# (--velocity when it read the position; --force, --current: the force is --input times --gain);
# with --iv they are. A column default the run read is listed with the column taken (breakaway's
# --velocity 'velocity', --current 'current'). Every row has its unit on the run's axis, in a column
# of its own. validate's report follows the same rules. The result's recorded options (MODEL.json
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

# Least squares: the options given, the defaults used; not the IV, Stribeck, ripple or output ones.
expect 0 "" "${idim[@]}" --delay 1 --report "$tmp/ls" --json "$tmp/ls.json"
options_of "$tmp/ls"
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
expect 0 "" "${idim[@]}" --iv --reference qg --controller emps-pd --kp 160.18 --kv 243.45 --report "$tmp/iv"
options_of "$tmp/iv"
has --iv true
has --controller emps-pd
has --kp 160.18 "N/m or 1/s"
has --kv 243.45 "V s/m"
has --reference qg m
grep -q "^--iv-iterations	[0-9]* (default)	$" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "--iv-iterations' default is not listed"; }
grep -q "^--iv-tolerance	.* (default)	$" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "--iv-tolerance's default is not listed"; }
lacks --kd
lacks --vs

# The Stribeck term: its --vs and --delta defaults apply.
expect 0 "" "${idim[@]}" --terms inertia,viscous,coulomb,offset,stribeck --report "$tmp/stribeck"
options_of "$tmp/stribeck"
has --terms "inertia,viscous,coulomb,offset,stribeck"
grep -q "^--vs	.* (default)	m/s$" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "--vs' default is not listed"; }
grep -q "^--delta	.* (default)	$" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "--delta's default is not listed"; }
lacks --kp

# The column defaults a run read, with the column taken and its unit: breakaway reads velocity (not
# the position) and, with --kt, the current; on a rotary axis.
expect 0 "" simulate "$src/examples/craig_motor_trapezoid.yaml" -o "$tmp/trapezoid.csv"
expect 0 "" identify breakaway "$tmp/trapezoid.csv" --kt 0.0141 --axis rotary --report "$tmp/breakaway"
options_of "$tmp/breakaway"
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
has MODEL "$tmp/model.json"
has --scenario "$src/examples/emps_closed_loop.yaml"
has --time t s
has --position qm m
has --gain gtau "N per unit of --input"
has --axis "linear (default)"
for name in --velocity --force --current --x --y --x-force --y-force; do
  lacks "$name"
done
echo ok
