#!/usr/bin/env bash
# The work and memory budget (docs/guarantees.md): input that would run without end or past the
# memory is refused at once, exit 2, naming the key, option or file and the size, before any
# work: a character device named .csv, a pipe that goes on past the budget, a YAML alias bomb, a
# fixed step or a controller sample period that gives more steps than the budget, --runs
# 2147483647, a million-point map, --substeps 1000000, a LuGre plan at --rate 1e9, a long run, a
# table input reaching 1e308 s, a part whose total is edited to 1e18.
# Pipes holding a finite input are read as streams. --budget FACTOR raises or lowers the budget;
# each refusal here ends within seconds (the script's time is the check that nothing ran).
source "$(dirname "$0")/lib.sh"
pendulum="$src/examples/craig_pendulum_coulomb.yaml"
start=$SECONDS

# A character device (a link to /dev/zero named .csv): refused before a byte is read.
ln -s /dev/zero "$tmp/zero.csv"
expect_fail "zero.csv is a character device; expected the CSV file as a regular file or a pipe" \
  identify sweep "$tmp/zero.csv"
ln -s /dev/zero "$tmp/zero.yaml"
expect_fail "zero.yaml is a character device" simulate "$tmp/zero.yaml" -o "$tmp/out.csv"
ln -s /dev/zero "$tmp/zero.json"  # a law or model file read as JSON (once read without this check)
expect_fail "zero.json is a character device" export "$tmp/zero.json" --c "$tmp/zero.h"

# A pipe that goes on (yes): read as a stream until the budget, then refused naming the file.
mkfifo "$tmp/endless.csv"
(timeout 60 sh -c "yes 1,2 > \"$tmp/endless.csv\"" 2> /dev/null &)
expect_fail "endless.csv: the CSV file (" --budget 1e-6 identify sweep "$tmp/endless.csv"
grep -qF "read from a pipe so far) and the numbers read from it: that needs" "$tmp/err.txt" || fail "$(cat "$tmp/err.txt")"
# A pipe with a finite scenario: read once, as a stream, and run.
mkfifo "$tmp/pipe.yaml"
(timeout 60 sh -c "cat \"$pendulum\" > \"$tmp/pipe.yaml\"" &)
expect 0 "" simulate "$tmp/pipe.yaml" -o "$tmp/pipe_run.csv"
[ -s "$tmp/pipe_run.csv" ] || fail "the piped scenario wrote nothing"

# A YAML alias bomb (1 kB, 9^8 nodes once expanded): refused by its expansion, not walked.
/usr/bin/python3 - "$pendulum" "$tmp/bomb.yaml" <<'PY'
import sys
lines = ['a0: &a0 [x, x, x, x, x, x, x, x, x]']
for k in range(1, 9):
    lines.append(f'a{k}: &a{k} [' + ', '.join([f'*a{k-1}'] * 9) + ']')
open(sys.argv[2], 'w').write(open(sys.argv[1]).read() + 'bomb:\n' + ''.join('  ' + l + '\n' for l in lines))
PY
expect_fail "bomb.yaml: the document expands to more than 1000000 nodes with its aliases" simulate "$tmp/bomb.yaml" -o "$tmp/out.csv"

# Steps: a fixed step of 1e-12 s over 20 s, a sampled table at Ts = 1e-10 s (its circle takes 3.1 s).
sed 's/^duration: 20/duration: 20\nsolver: {mode: fixed-step, dt: 1.0e-12}/' "$pendulum" > "$tmp/fine.yaml"
expect_fail "dt = 1e-12 s: that is 2e+13 fixed steps; the work budget is 1e+09 work units" simulate "$tmp/fine.yaml" -o "$tmp/out.csv"
sed 's/^\(\s*\)Ts: 2.5e-4.*/\1Ts: 1.0e-10/' "$src/examples/xy_circle.yaml" > "$tmp/xy_fast.yaml"
grep -q "Ts: 1.0e-10" "$tmp/xy_fast.yaml" || fail "xy_circle.yaml has no Ts to edit"
expect_fail "controller samples; the work budget is" simulate "$tmp/xy_fast.yaml" -o "$tmp/out.csv"
# The same file within a raised budget passes the check (and is not run here: only refused ones are).
expect_fail "--budget = 0 must be a finite factor >= 1e-6" --budget 0 simulate "$pendulum" -o "$tmp/out.csv"
expect_fail "--budget = 1e-09 must be a finite factor >= 1e-6" simulate "$pendulum" --budget 1e-9 -o "$tmp/out.csv"

# Runs, points and substeps.
expect_fail "--runs 2147483647 (1000 units per run before its samples): that is 2.15e+12 work units; the work budget is 1e+09" \
  plan breakaway --prior "$src/examples/plan/craig_motor_prior.json" --scenario "$src/examples/craig_motor_trapezoid.yaml" \
  --runs 2147483647 -o "$tmp/plan.csv"
expect_fail "the map's 1000000 points (--vary) of about" \
  analyze map "$src/examples/map_pid_hunting.yaml" --vary friction.Fs=1:2:1000 --vary controller.Kp=3:4:1000 -o "$tmp/map.csv"
"$exe" simulate "$pendulum" -o "$tmp/swing.csv" 2> /dev/null
expect_fail "lugre: 4001 samples x --substeps 1000000 x (--max-iterations 50 + 1): that is 2.04e+11 simulation steps" \
  identify lugre "$tmp/swing.csv" --force applied --inertia 1 --substeps 1000000

# A LuGre plan at --rate 1e9 Hz: its sine table (1.2e10 samples) is refused before it is built (it
# once built it for minutes before the plan's own check of its runs).
expect_fail "the lugre profile of" plan lugre --prior "$src/examples/plan/canudas_prior.json" \
  --scenario "$src/examples/canudas_presliding.yaml" --limits travel=0.05 --noise position=1e-7 --rate 1e9 -o "$tmp/sines.csv"
grep -qF -- "--rate 1e+09 Hz" "$tmp/err.txt" || fail "plan lugre --rate 1e9: $(cat "$tmp/err.txt")"
[ ! -e "$tmp/sines.csv" ] || fail "a refused plan wrote its profile"
# A long run (duration: 150000 s at 200 Hz, 3e7 rows, 2.4 GB) within a lowered budget, and a table
# input whose times reach 1e308 s: refused naming the keys and the memory, before a step.
sed 's/^duration: 20/duration: 150000/' "$pendulum" > "$tmp/long.yaml"
expect_fail "long.yaml: duration and output_rate: 150000 s at 200 Hz gives 3e+07 output rows" \
  --budget 0.01 simulate "$tmp/long.yaml" -o "$tmp/out.csv"
cat > "$tmp/table.yaml" <<'YAML'
plant: {type: axis, M: 1.0}
friction: {law: coulomb-viscous, Fc: 1.0, Fv: 0.4}
input: {type: table, times: [0, 1, 1.0e308], values: [0, 1, 1]}
duration: 1.0e308
YAML
expect_fail "table.yaml: duration: 1e+308 s at 100 Hz (the default output_rate) gives inf output rows" simulate "$tmp/table.yaml" -o "$tmp/out.csv"
grep -q "needs unbounded memory;" "$tmp/err.txt" || fail "table input 1e308: $(cat "$tmp/err.txt")"
[ ! -e "$tmp/out.csv" ] || fail "a refused run wrote its output"

# A part file whose total is edited to 1e18: refused reading it, before merge allocates.
"$exe" analyze map "$src/examples/map_pid_hunting.yaml" --vary friction.Fs=1:2:2 --jobs 1 --shard 1/2 -o "$tmp/p1.json" > /dev/null
"$exe" analyze map "$src/examples/map_pid_hunting.yaml" --vary friction.Fs=1:2:2 --jobs 1 --shard 2/2 -o "$tmp/p2.json" > /dev/null
/usr/bin/python3 -c "
import json, sys
j = json.load(open(sys.argv[1])); j['total'] = 10**18; json.dump(j, open(sys.argv[1], 'w'))" "$tmp/p1.json"
expect_fail 'p1.json: "total": 1000000000000000000 jobs give shard 1/2 500000000000000000 rows, but the part holds 1' \
  merge "$tmp/p1.json" "$tmp/p2.json" -o "$tmp/merged.csv"
[ ! -e "$tmp/merged.csv" ] || fail "merge wrote its output"

elapsed=$((SECONDS - start))
[ "$elapsed" -lt 120 ] || fail "the refusals took $elapsed s; each should end at once"
echo "ok ($elapsed s)"
