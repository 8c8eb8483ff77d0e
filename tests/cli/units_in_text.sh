#!/usr/bin/env bash
# The text outputs carry their units: simulate's summary (final and peak position, velocity and
# friction, the switches' position and applied force, in the plant's units: m, m/s, N on a linear
# axis; rad, rad/s, N m on a pendulum or a motor), and
# analyze envelope and stick-slip (--axis linear or rotary, linear by default), and identify's
# diagnostics lines.
source "$(dirname "$0")/lib.sh"
cd "$tmp"

# The summary goes to stderr (stdout may carry the CSV).
"$exe" simulate "$src/examples/canudas_stick_slip.yaml" -o stick_slip.csv 2> sim.txt
grep -E '^final +position [-0-9.e+]+ m, velocity [-0-9.e+]+ m/s$' sim.txt || { cat sim.txt; fail "simulate: final line without m and m/s"; }
grep -E '^peak +\|velocity\| [-0-9.e+]+ m/s, \|friction\| [-0-9.e+]+ N$' sim.txt || { cat sim.txt; fail "simulate: peak line without m/s and N"; }

# The stick/slip switches: position and applied force with their units (rad and N m on a motor).
"$exe" simulate "$src/examples/craig_motor_trapezoid.yaml" -o trapezoid.csv 2> motor.txt
grep -Eq '^  t = [0-9.e+-]+ s  breakaway  at position [-0-9.e+]+ rad, applied [-0-9.e+]+ N m$' motor.txt ||
  { cat motor.txt; fail "simulate: a switch line without rad and N m"; }
"$exe" simulate "$src/examples/xy_circle.yaml" -o circle.csv 2> xy.txt
grep -Eq '^  t = [0-9.e+-]+ s  x: breakaway  at position [-0-9.e+]+ m, applied [-0-9.e+]+ N$' xy.txt ||
  { cat xy.txt; fail "simulate: an xy-table's switch line without m and N"; }

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

# identify's diagnostics lines: a figure with a unit carries it (the read-offs in their
# parameters' units, the residual in the fit's, times in s, the cutoff in Hz, the controller
# IDIM-IV simulated in its options' units as the run decided them: emps-pd's kp in 1/s).
"$exe" simulate "$src/examples/craig_motor_trapezoid.yaml" -o trapezoid2.csv 2> /dev/null
"$exe" identify breakaway trapezoid2.csv --kt 0.0141 --axis rotary > ba.txt
grep -Eq '^readoff: Fc = [-0-9.e+]+ N m Fs = [-0-9.e+]+ N m Fv = [-0-9.e+]+ N m s/rad$' ba.txt ||
  { cat ba.txt; fail "breakaway: the read-offs without their units"; }
grep -Eq '^adequacy: .* residual_std = [-0-9.e+]+ N m .*standstill_speed = [-0-9.e+]+ rad/s$' ba.txt ||
  { cat ba.txt; fail "breakaway: the residual checks' figures without units"; }
"$exe" identify idim "$src/data/emps/DATA_EMPS.mat" --time t --position qm --input vir --gain gtau --iv --reference qg \
  --controller emps-pd --kp 160.18 --kv 243.45 > iv.txt
grep -Eq '^defaults: cutoff_hz = 100 Hz decimation = 10 skip = 49 samples$' iv.txt || { cat iv.txt; fail "idim: defaults without units"; }
grep -Eq '^iv_controller: control_delay = 1 samples control_limit = 10 V drive_gain = [0-9.]+ N/V kp = 160.18 1/s kv = 243.45 V s/m sample_period = 0.001 s$' iv.txt ||
  { cat iv.txt; fail "idim --iv: the controller's values without their units"; }
grep -Eq '^iv_instrument_correlation: Fc = [0-9.e+-]+ Fv = [0-9.e+-]+ M = [0-9.e+-]+ offset = [0-9.e+-]+$' iv.txt ||
  { cat iv.txt; fail "idim --iv: a correlation given a unit"; }
grep -Eq '^ls_estimate: Fc = [-0-9.e+]+ N Fv = [-0-9.e+]+ N s/m M = [-0-9.e+]+ kg offset = [-0-9.e+]+ N$' iv.txt ||
  { cat iv.txt; fail "idim --iv: the least-squares estimates without units"; }
echo "PASS units_in_text"
