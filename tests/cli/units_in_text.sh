#!/usr/bin/env bash
# The text outputs carry their units: simulate's summary (final and peak position, velocity and
# friction in the plant's units: m, m/s, N on a linear axis; rad, rad/s, N m on a pendulum), and
# analyze envelope and stick-slip (--axis linear or rotary, linear by default).
source "$(dirname "$0")/lib.sh"
cd "$tmp"

# The summary goes to stderr (stdout may carry the CSV).
"$exe" simulate "$src/examples/canudas_stick_slip.yaml" -o stick_slip.csv 2> sim.txt
grep -E '^final +position [-0-9.e+]+ m, velocity [-0-9.e+]+ m/s$' sim.txt || { cat sim.txt; fail "simulate: final line without m and m/s"; }
grep -E '^peak +\|velocity\| [-0-9.e+]+ m/s, \|friction\| [-0-9.e+]+ N$' sim.txt || { cat sim.txt; fail "simulate: peak line without m/s and N"; }

"$exe" simulate "$src/examples/craig_pendulum_combined.yaml" -o pendulum.csv 2> pend.txt
grep -E '^final +position [-0-9.e+]+ rad, velocity [-0-9.e+]+ rad/s$' pend.txt || { cat pend.txt; fail "simulate: a pendulum's final line not in rad and rad/s"; }
grep -E '\|friction\| [-0-9.e+]+ N m$' pend.txt || { cat pend.txt; fail "simulate: a pendulum's friction not in N m"; }

"$exe" analyze stick-slip stick_slip.csv > ss.txt
grep -q "(velocity unit)\|(force unit" ss.txt && { cat ss.txt; fail "stick-slip: placeholder units left"; }
grep -E '^peak slip +[-0-9.e+]+ m/s$' ss.txt || { cat ss.txt; fail "stick-slip: peak slip without m/s"; }
grep -E '^slips +[0-9]+ \(velocity threshold [-0-9.e+]+ m/s\)$' ss.txt || { cat ss.txt; fail "stick-slip: threshold without m/s"; }
grep -E '^breakaway +[-0-9.e+]+ N \(mean\)$' ss.txt || { cat ss.txt; fail "stick-slip: breakaway without N"; }
"$exe" analyze stick-slip stick_slip.csv --axis rotary > ss_rot.txt
grep -E '^peak slip +[-0-9.e+]+ rad/s$' ss_rot.txt || { cat ss_rot.txt; fail "stick-slip --axis rotary: not rad/s"; }
grep -E '^force drop +[-0-9.e+]+ N m \(mean\)$' ss_rot.txt || { cat ss_rot.txt; fail "stick-slip --axis rotary: not N m"; }

"$exe" analyze envelope pendulum.csv --axis rotary > env.txt
grep -E '^amplitude +[-0-9.e+]+ rad -> [-0-9.e+]+ rad \(lost' env.txt || { cat env.txt; fail "envelope: amplitude without rad"; }
grep -E '^linear +[-0-9.e+]+ rad per half cycle' env.txt || { cat env.txt; fail "envelope: decrement without rad"; }
expect_fail "--axis" analyze envelope pendulum.csv --axis sideways
echo "PASS units_in_text"
