#!/usr/bin/env bash
# The seed documents' procedures end to end on the command line: simulate an experiment to CSV,
# identify from the CSV, compare with the parameters the simulation used.
source "$(dirname "$0")/lib.sh"
# Craig's trapezoid: breakaway from time, current (with --kt) and velocity.
"$exe" simulate "$src/examples/craig_motor_trapezoid.yaml" -o "$tmp/trap.csv" > /dev/null
"$exe" identify breakaway "$tmp/trap.csv" --kt 0.0141 --axis rotary --json "$tmp/b.json" > "$tmp/b.txt"
check_parameters "$tmp/b.json" "$(rel Fs 0.0015 5e-3) and $(rel Fc 0.0012 5e-3) and $(rel Fv 2.85e-6 5e-3)"
grep -q "readoff:" "$tmp/b.txt"
grep -q '"unit": "N m"' "$tmp/b.json"

# Virgala's constant speeds: sweep with the default Stribeck model.
"$exe" simulate "$src/examples/virgala_motor_sweep.yaml" -o "$tmp/sweep.csv" > /dev/null
"$exe" identify sweep "$tmp/sweep.csv" --kt 0.039 --axis rotary --json "$tmp/s.json" > /dev/null
check_parameters "$tmp/s.json" "$(rel Fc 0.002 1e-3) and $(rel Fs 0.003 1e-3) and $(rel vs 5.0 1e-2)"

# Craig's combined pendulum: decay from the angle alone.
"$exe" simulate "$src/examples/craig_pendulum_combined.yaml" -o "$tmp/pend.csv" > /dev/null
"$exe" identify decay "$tmp/pend.csv" --stiffness 9.81 --pendulum --axis rotary --json "$tmp/d.json" > /dev/null
check_parameters "$tmp/d.json" "$(rel Fc 0.16 0.02) and $(rel Fv 0.5 0.02)"
echo "identify_simulated: ok"
