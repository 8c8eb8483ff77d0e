#!/usr/bin/env bash
# The report's Options table lists the options that applied to the run (docs/identify.md): every
# option given, and the defaults the run used. Without --iv, idim's IV options (--kp,
# --iv-iterations, --iv-tolerance) are not listed, nor the Stribeck term's --vs and --delta, nor
# outputs not asked for (--plot), the batch options, and the other force sources' column defaults
# (--force, --current: the force is --input times --gain); with --iv they are. The result's
# recorded options (MODEL.json "options") still hold every option of the table.
source "$(dirname "$0")/lib.sh"
emps="$src/data/emps/DATA_EMPS.mat"
idim=(identify idim "$emps" --time t --position qm --input vir --gain gtau)

# options_of REPORT_DIR: the Options table as "NAME<TAB>VALUE" lines in $tmp/options.txt.
options_of() {
  /usr/bin/python3 - "$1/report.html" > "$tmp/options.txt" <<'PY'
import html, re, sys
page = open(sys.argv[1], encoding="utf-8").read()
section = page.split('<h2 id="options">Options</h2>', 1)[1].split("</table>", 1)[0]
for name, value in re.findall(r"<tr><td><code>(.*?)</code></td><td>(.*?)</td></tr>", section):
    print(html.unescape(name) + "\t" + html.unescape(value))
PY
}
# has NAME VALUE: the table lists NAME with exactly VALUE; lacks NAME: it does not list NAME.
has() { grep -qxF -- "$1	$2" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "the Options table lacks '$1 $2'"; }; }
lacks() { ! grep -q -- "^$1	" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "the Options table lists $1"; }; }

# Least squares: the options given, the defaults used; not the IV, Stribeck, ripple or output ones.
expect 0 "" "${idim[@]}" --delay 1 --report "$tmp/ls" --json "$tmp/ls.json"
options_of "$tmp/ls"
has --time t
has --gain gtau
has --delay "1 samples"
has --json "$tmp/ls.json"
has --filter-order "4 (default)"
has --skip-end "0 (default)"
has --exclude-below "0 m/s (default)"
has --iv "false (default)"
has --terms "inertia,viscous,coulomb,offset (default)"
for name in --kp --kv --controller --iv-iterations --iv-tolerance --control-delay --vs --delta --ripple-harmonics \
  --plot --jobs --drift-threshold --table --force --current; do
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
has --kp "160.18 N/m or 1/s"
has --kv "243.45 V s/m"
has --reference qg
grep -q "^--iv-iterations	[0-9]* (default)$" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "--iv-iterations' default is not listed"; }
grep -q "^--iv-tolerance	.* (default)$" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "--iv-tolerance's default is not listed"; }
lacks --kd
lacks --vs

# The Stribeck term: its --vs and --delta defaults apply.
expect 0 "" "${idim[@]}" --terms inertia,viscous,coulomb,offset,stribeck --report "$tmp/stribeck"
options_of "$tmp/stribeck"
has --terms "inertia,viscous,coulomb,offset,stribeck"
grep -q "^--vs	.* (default)$" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "--vs' default is not listed"; }
grep -q "^--delta	.* (default)$" "$tmp/options.txt" || { cat "$tmp/options.txt"; fail "--delta's default is not listed"; }
lacks --kp
echo ok
