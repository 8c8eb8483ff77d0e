#!/usr/bin/env bash
# --plot on simulate, identify (idim, breakaway, sweep, decay) and analyze (envelope, stick-slip):
# each writes a non-empty figure of the type its extension asks for (SVG text, PNG and PDF magic
# bytes), with the data (FILE.dat) and the gnuplot script (FILE.gp) next to it, and the script
# redraws the figure; identify --report writes the friction-velocity map next to the fit figure.
# Set FRICTIONLAB_PLOT_DIR to keep the figures (CI artefacts).
# Usage: plot_outputs.sh PATH_TO_frictionlab SOURCE_DIR
source "$(dirname "$0")/lib.sh"
out="${FRICTIONLAB_PLOT_DIR:-$tmp/figures}"
mkdir -p "$out"
command -v gnuplot > /dev/null || { echo "SKIP: gnuplot not installed (Debian package gnuplot-nox)"; exit 0; }

fail() { echo "FAIL: $*"; exit 1; }

check_figure() {  # FILE: the right magic for its extension, data and script next to it
  local f="$1"
  [ -s "$f" ] || fail "$f missing or empty"
  [ -s "$f.dat" ] || fail "$f.dat missing or empty"
  [ -s "$f.gp" ] || fail "$f.gp missing or empty"
  case "$f" in
    *.svg) grep -q "<svg" "$f" || fail "$f is not SVG" ;;
    *.png) [ "$(head -c 8 "$f" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "$f is not PNG" ;;
    *.pdf) [ "$(head -c 5 "$f")" = "%PDF-" ] || fail "$f is not PDF" ;;
  esac
  # No temporaries left behind.
  ! ls "$(dirname "$f")" | grep -q '\.tmp-' || fail "temporary files left next to $f"
}

# simulate: time series of a motor trapezoid (rotary) and of a stick-slip rig (linear).
"$exe" simulate "$src/examples/craig_motor_trapezoid.yaml" -o "$tmp/trap.csv" --plot "$out/simulate_trapezoid.svg" \
  --overwrite 2> /dev/null
check_figure "$out/simulate_trapezoid.svg"
grep -q "angular\|rad/s" "$out/simulate_trapezoid.svg" || fail "rotary axis labels missing in simulate figure"
"$exe" simulate "$src/examples/canudas_stick_slip.yaml" -o "$tmp/ss.csv" --plot "$out/simulate_stick_slip.png" \
  --overwrite 2> /dev/null
check_figure "$out/simulate_stick_slip.png"

# identify: idim (PNG), breakaway (SVG), sweep (PDF and SVG), decay (SVG).
emps="$src/data/emps/DATA_EMPS.mat"
"$exe" identify idim "$emps" --time t --position qm --input vir --gain gtau --plot "$out/identify_idim.png" \
  --overwrite > /dev/null
check_figure "$out/identify_idim.png"
"$exe" identify breakaway "$tmp/trap.csv" --kt 0.0141 --axis rotary --plot "$out/identify_breakaway.svg" --overwrite > /dev/null
check_figure "$out/identify_breakaway.svg"
grep -q "N m" "$out/identify_breakaway.svg" || fail "breakaway figure lacks the torque unit"
"$exe" simulate "$src/examples/virgala_motor_sweep.yaml" -o "$tmp/sweep.csv" > /dev/null 2>&1
"$exe" identify sweep "$tmp/sweep.csv" --kt 0.039 --axis rotary --plot "$out/identify_sweep.pdf" --overwrite > /dev/null
check_figure "$out/identify_sweep.pdf"
"$exe" identify sweep "$tmp/sweep.csv" --kt 0.039 --axis rotary --plot "$out/identify_sweep.svg" --overwrite > /dev/null
check_figure "$out/identify_sweep.svg"
grep -q "steady segments" "$out/identify_sweep.svg" || fail "sweep figure lacks its legend"
"$exe" simulate "$src/examples/craig_pendulum_combined.yaml" -o "$tmp/pend.csv" > /dev/null 2>&1
"$exe" identify decay "$tmp/pend.csv" --stiffness 9.81 --pendulum --axis rotary --plot "$out/identify_decay.svg" \
  --overwrite > /dev/null
check_figure "$out/identify_decay.svg"
grep -q "envelope" "$out/identify_decay.svg" || fail "decay figure lacks the fitted envelope"

# identify --report: the fit figure and the friction-velocity map (no cross-test without --validate).
map_check() {  # REPORT_DIR UNIT_LABEL...: the map's files and its axis labels with units
  local dir="$1"; shift
  check_figure "$dir/friction-map.svg"
  grep -q "Friction map" "$dir/friction-map.svg" || fail "$dir/friction-map.svg lacks its title"
  for l in "$@"; do grep -q "$l" "$dir/friction-map.svg" || fail "$dir/friction-map.svg lacks the label '$l'"; done
  grep -q "friction-map.svg" "$dir/report.html" && grep -q "Friction against velocity\|Applied force against velocity" \
    "$dir/report.html" || fail "$dir/report.html lacks the friction map's caption"
  [ ! -e "$dir/cross-test.svg" ] || fail "$dir has a cross-test figure without --validate"
}
"$exe" identify idim "$emps" --time t --position qm --input vir --gain gtau --report "$out/report_idim" \
  --overwrite > /dev/null
check_figure "$out/report_idim/fit.svg"
map_check "$out/report_idim" "velocity (m/s)" "friction force (N)" "per velocity bin" "identified law"
# The binned means carry finite, positive error bars (the third column of their data block), on
# both sides of zero velocity.
awk '/series .mean \+- std per velocity bin/ {b = 1; next} /^# index/ {b = 0} b && NF == 3 {
       n++; if ($3 > 0 && $3 < 1e9) ok++; if ($1 < 0) neg++; if ($1 > 0) pos++ }
     END { exit !(n >= 10 && ok == n && neg >= 5 && pos >= 5) }' "$out/report_idim/friction-map.svg.dat" ||
  fail "friction map: binned means without error bars on both sides of v = 0"
"$exe" identify breakaway "$tmp/trap.csv" --kt 0.0141 --axis rotary --report "$out/report_breakaway" --overwrite > /dev/null
map_check "$out/report_breakaway" "velocity (rad/s)" "applied torque (N m)" "breakaway Fs"

# With --json -, stdout stays pure JSON (the figure note goes to stderr).
"$exe" identify decay "$tmp/pend.csv" --stiffness 9.81 --pendulum --axis rotary --plot "$tmp/d2.svg" --json - \
  2> /dev/null | python3 -c 'import json,sys; json.load(sys.stdin)' || fail "--plot spoils --json - output"

# analyze: envelope and stick-slip.
"$exe" analyze envelope "$tmp/pend.csv" --plot "$out/analyze_envelope.svg" --overwrite > /dev/null
check_figure "$out/analyze_envelope.svg"
"$exe" analyze stick-slip "$tmp/ss.csv" --plot "$out/analyze_stick_slip.png" --overwrite > /dev/null
check_figure "$out/analyze_stick_slip.png"

# The script written next to a figure redraws it (in its directory, as its comment says).
rm "$out/identify_decay.svg"
(cd "$out" && gnuplot identify_decay.svg.gp 2> /dev/null)
check_figure "$out/identify_decay.svg"

# An existing figure is not replaced without --overwrite (exit 2, nothing changed).
before=$(md5sum < "$out/identify_sweep.svg")
set +e
"$exe" identify sweep "$tmp/sweep.csv" --kt 0.039 --axis rotary --plot "$out/identify_sweep.svg" > /dev/null 2> "$tmp/err.txt"
code=$?
set -e
[ "$code" -eq 2 ] || fail "existing --plot file: exit $code, expected 2"
grep -q -- "--overwrite" "$tmp/err.txt" || fail "existing --plot file: message lacks --overwrite: $(cat "$tmp/err.txt")"
[ "$(md5sum < "$out/identify_sweep.svg")" = "$before" ] || fail "existing figure was changed"

echo "plot_outputs: ok (figures in $out)"
