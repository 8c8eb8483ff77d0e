#!/usr/bin/env bash
# One rule for outputs (README "Guarantees"): an output that is one of the run's own inputs (by
# device and inode: the same path, a symbolic or hard link to it, or a file the scenario or the
# model names) is refused before any work, with or without --overwrite: exit 2, a message naming
# both, error code output.is_input, and the input unchanged. A dangling link at an output path is
# not replaced without --overwrite; an unwritable output directory is found before the work;
# SIGKILL during a write leaves no temporary file behind.
# Usage: contract_inputs_kept.sh PATH_TO_frictionlab SOURCE_DIR
source "$(dirname "$0")/lib.sh"
# shellcheck source=lib.sh
emps="$src/data/emps/DATA_EMPS.mat"
cols=(--time t --position qm --input vir --gain gtau)

# kept FILE CODE ARGS...: the run exits 2 with a one-line message naming FILE, its --json -
# error (when asked for) has CODE, and FILE has the same bytes as before.
kept() {
  local file="$1" code="$2"
  shift 2
  local before
  before="$(sha256sum "$file" | cut -d' ' -f1)"
  expect 2 "$file" "$@"
  [ "$(sha256sum "$file" | cut -d' ' -f1)" = "$before" ] || fail "$*: replaced its input $file"
  grep -q "is the input\|is the model file" "$tmp/err.txt" || { cat "$tmp/err.txt"; fail "$*: message does not say which input"; }
  if [ -s "$tmp/out.txt" ]; then
    /usr/bin/python3 - "$tmp/out.txt" "$code" <<'PY'
import json, sys
j = json.loads(open(sys.argv[1]).read())
assert j["status"] == "error" and j["error"]["code"] == sys.argv[2], j
PY
  fi
}

# The run's files: a scenario with a data file and a compensation model, their copies in $tmp.
cp "$emps" "$tmp/DATA_EMPS.mat"
printf '{"law": "coulomb-viscous", "Fc": 20.0, "Fv": 200.0}\n' > "$tmp/law.json"
sed -e 's|^data: .*|data: DATA_EMPS.mat|' -e 's|^    type: feedforward|    type: feedforward\n    model: law.json|' \
  "$src/examples/emps_closed_loop_compensated.yaml" > "$tmp/emps.yaml"
grep -q "model: law.json" "$tmp/emps.yaml" || fail "test setup: no model line in the scenario"
pendulum="$tmp/pendulum.yaml"
cp "$src/examples/craig_pendulum_coulomb.yaml" "$pendulum"

# simulate: the scenario itself, its data: file, its compensation's model: file, a link to it.
for extra in "" --overwrite; do
  kept "$pendulum" output.is_input simulate "$pendulum" -o "$pendulum" $extra
  kept "$tmp/DATA_EMPS.mat" output.is_input simulate "$tmp/emps.yaml" -o "$tmp/DATA_EMPS.mat" $extra
  kept "$tmp/law.json" output.is_input simulate "$tmp/emps.yaml" -o "$tmp/law.json" $extra
done
ln -s "$pendulum" "$tmp/link.csv"
kept "$pendulum" output.is_input simulate "$pendulum" -o "$tmp/link.csv" --overwrite
ln "$pendulum" "$tmp/hard.csv"
kept "$pendulum" output.is_input simulate "$pendulum" -o "$tmp/hard.csv" --overwrite
kept "$pendulum" output.is_input simulate "$pendulum" -o "$tmp/../$(basename "$tmp")/pendulum.yaml" --overwrite

# identify: DATA, a method's own input file (--validate, --static), --json - carries the code.
"$exe" simulate "$src/examples/virgala_motor_sweep.yaml" -o "$tmp/sweep.csv" > /dev/null
"$exe" identify sweep "$tmp/sweep.csv" --kt 0.039 --json "$tmp/static.json" > /dev/null
kept "$tmp/sweep.csv" output.is_input identify sweep "$tmp/sweep.csv" --kt 0.039 --json "$tmp/sweep.csv" --overwrite
cp "$emps" "$tmp/P.mat"
kept "$tmp/P.mat" output.is_input identify idim "$emps" "${cols[@]}" --validate "$tmp/P.mat" --json "$tmp/P.mat" --overwrite
kept "$tmp/static.json" output.is_input identify lugre "$tmp/sweep.csv" --kt 0.039 --inertia 1e-5 --static "$tmp/static.json" \
  --json "$tmp/static.json" --overwrite

# identify on a folder: --table and --drift at one of its logs (--drift used to replace it while
# exiting 2).
/usr/bin/python3 "$src/examples/fleet_logs.py" "$tmp/fleet" > /dev/null
log="$(ls "$tmp"/fleet/*.csv | head -1)"
sweep=(identify sweep --resample --model coulomb-viscous "$tmp/fleet" --date-from name)
kept "$log" output.is_input "${sweep[@]}" --table "$log" --overwrite
kept "$log" output.is_input "${sweep[@]}" --drift "$log" --table "$tmp/t.csv" --overwrite
[ ! -e "$tmp/t.csv" ] || fail "a refused batch wrote its table"

# validate: --json at the MODEL, the scenario, the scenario's data: file.
"$exe" identify idim "$emps" "${cols[@]}" --json "$tmp/model.json" > /dev/null
cp "$src/examples/emps_closed_loop.yaml" "$tmp/loop.yaml"
sed -i 's|^data: .*|data: DATA_EMPS.mat|' "$tmp/loop.yaml"
val=(validate "$tmp/model.json" "$emps" --scenario "$tmp/loop.yaml" "${cols[@]}")
kept "$tmp/model.json" output.is_input "${val[@]}" --json "$tmp/model.json" --overwrite
kept "$tmp/loop.yaml" output.is_input "${val[@]}" --json "$tmp/loop.yaml" --overwrite
kept "$tmp/DATA_EMPS.mat" output.is_input "${val[@]}" --json "$tmp/DATA_EMPS.mat" --overwrite

# plan: -o at the prior, --json at the scenario.
cp "$src/examples/plan/craig_motor_prior.json" "$tmp/prior.json"
cp "$src/examples/craig_motor_trapezoid.yaml" "$tmp/motor.yaml"
plan=(plan breakaway --prior "$tmp/prior.json" --scenario "$tmp/motor.yaml" --runs 2)
kept "$tmp/prior.json" output.is_input "${plan[@]}" -o "$tmp/prior.json" --overwrite
kept "$tmp/prior.json" output.is_input "${plan[@]}" -o "$tmp/prior.json" --json -
[ -s "$tmp/out.txt" ] || fail "plan --json -: no error JSON on stdout"
kept "$tmp/motor.yaml" output.is_input "${plan[@]}" -o "$tmp/ramp.csv" --json "$tmp/motor.yaml" --overwrite
[ ! -e "$tmp/ramp.csv" ] || fail "a refused plan wrote its profile"

# merge: -o at one of the parts.
for k in 1 2; do
  "$exe" analyze map "$pendulum" --vary friction.Fs=0.2:0.3:2 --jobs 1 --shard "$k/2" -o "$tmp/part$k.json" > /dev/null
done
kept "$tmp/part1.json" output.is_input merge "$tmp/part1.json" "$tmp/part2.json" -o "$tmp/part1.json" --overwrite

# export: the model file (refused before; still refused, now with the code).
kept "$tmp/law.json" output.is_input export "$tmp/law.json" --c "$tmp/law.json" --overwrite

# Two outputs that are one file through a link: refused naming both.
touch "$tmp/a.csv"
ln -s "$tmp/a.csv" "$tmp/b.json"
expect 2 "is also the -o output" "${plan[@]}" -o "$tmp/a.csv" --json "$tmp/b.json" --overwrite

# A dangling link at an output path is not replaced without --overwrite (then it is).
ln -s "$tmp/nowhere/target.csv" "$tmp/dangling.csv"
expect 2 "symbolic link" simulate "$pendulum" -o "$tmp/dangling.csv"
[ -L "$tmp/dangling.csv" ] || fail "the dangling link was replaced without --overwrite"
expect 0 "" simulate "$pendulum" -o "$tmp/dangling.csv" --overwrite
[ -f "$tmp/dangling.csv" ] && [ ! -L "$tmp/dangling.csv" ] || fail "--overwrite did not replace the dangling link"

# An unwritable output directory is found before the work: exit 2 naming it (root can write
# anywhere on a writable file system: a read-only one stands in where there is one).
if [ "$(id -u)" -ne 0 ]; then
  mkdir "$tmp/ro"
  chmod 555 "$tmp/ro"
  expect 2 "$tmp/ro is not writable" simulate "$pendulum" -o "$tmp/ro/out.csv"
  chmod 755 "$tmp/ro"
elif [ -d /sys ] && [ ! -w /sys ]; then
  expect 2 "is not writable" identify idim "$emps" "${cols[@]}" --json /sys/frictionlab-out.json
fi

# SIGKILL during writes leaves no NAME.tmp-XXXXXX behind.
mkdir "$tmp/kill"
for i in 1 2 3 4 5 6; do
  "$exe" simulate "$tmp/emps.yaml" -o "$tmp/kill/out.csv" --overwrite > /dev/null 2>&1 &
  pid=$!
  sleep "0.$((i * 15))"
  kill -9 "$pid" 2> /dev/null || true
  wait "$pid" 2> /dev/null || true
done
leftover="$(ls "$tmp/kill" | grep -v '^out\.csv$' || true)"
[ -z "$leftover" ] || fail "SIGKILL left temporary files: $leftover"
echo "ok"
