#!/usr/bin/env bash
# Scenario and law files that would break the run later (docs/guarantees.md): an output larger
# than the memory there is (duration: 1e9, output_rate: 1e9) is exit 2 naming the key and the
# memory it would need, never an out-of-memory crash; a key given twice in a mapping is refused
# naming the key and its line (YAML readers keep one of the two silently); nothing is written.
# Usage: contract_scenario.sh PATH_TO_frictionlab SOURCE_DIR
source "$(dirname "$0")/lib.sh"
base="$src/examples/craig_pendulum_coulomb.yaml"

expect_refused() {  # FILE TEXT...: exit 2, each TEXT in the one-line message, no output written
  local file="$1"
  shift
  set +e
  "$exe" simulate "$file" -o "$tmp/out.csv" > /dev/null 2> "$tmp/err.txt"
  local code=$?
  set -e
  [ "$code" -eq 2 ] || { cat "$tmp/err.txt"; fail "$file: exit $code, expected 2"; }
  [ "$(wc -l < "$tmp/err.txt")" -eq 1 ] || { cat "$tmp/err.txt"; fail "$file: expected a one-line message"; }
  for want in "$@"; do
    grep -qF -- "$want" "$tmp/err.txt" || { cat "$tmp/err.txt"; fail "$file: message lacks '$want'"; }
  done
  [ ! -e "$tmp/out.csv" ] || fail "$file: output written"
}

sed 's/^duration: 20/duration: 1e9/' "$base" > "$tmp/long.yaml"
expect_refused "$tmp/long.yaml" "long.yaml: duration and output_rate: 1000000000 s at 200 Hz" "output rows (shorten duration or lower output_rate): that needs" "B of memory; the memory budget is"
grep -v '^output_rate' "$base" | sed 's/^duration: 20/duration: 1e9/' > "$tmp/long_default.yaml"
expect_refused "$tmp/long_default.yaml" "duration: 1000000000 s at 100 Hz (the default output_rate)"
sed 's/^output_rate: 200/output_rate: 1e9/' "$base" > "$tmp/rate.yaml"
expect_refused "$tmp/rate.yaml" "output_rate" "B of memory"
sed 's/^output_rate: 200/output_rate: 1e300/' "$base" > "$tmp/huge.yaml"
expect_refused "$tmp/huge.yaml" "output_rate" "B of memory"

# A key twice: at the top, in a section, in the friction law.
{ cat "$base"; echo "duration: 30"; } > "$tmp/dup_top.yaml"
expect_refused "$tmp/dup_top.yaml" "dup_top.yaml: line 22: key 'duration' given twice (first on line 17)"
sed 's/^  g: 9.81/  g: 9.81\n  g: 1.62/' "$base" > "$tmp/dup_plant.yaml"
expect_refused "$tmp/dup_plant.yaml" "key 'g' given twice" "line 12"
sed 's/^  Fc: 0.16/  Fc: 0.16\n  Fc: 0.18/' "$base" > "$tmp/dup_law.yaml"
expect_refused "$tmp/dup_law.yaml" "key 'Fc' given twice"
# A value of the wrong kind: a clear error, not an internal one.
sed 's/^  law: static-coulomb-viscous/  law: [static-coulomb-viscous]/' "$base" > "$tmp/law_list.yaml"
expect_refused "$tmp/law_list.yaml" "friction.law: expected a name"
sed 's/^  m: 1.0/  m: {value: 1.0}/' "$base" > "$tmp/map_value.yaml"
expect_refused "$tmp/map_value.yaml" "plant.m: expected a number"
# A directory as the scenario.
mkdir "$tmp/adir"
expect_refused "$tmp/adir" "adir is a directory"

# identify lugre --static takes the law files through the same reader: a key twice is refused.
printf 'law: stribeck\nFc: 1\nFs: 1.5\nvs: 0.001\nFv: 0.4\nFc: 2\n' > "$tmp/law.yaml"
printf 'time,applied,position\n0,0,0\n0.001,0.1,0\n0.002,0.2,0\n' > "$tmp/lugre.csv"
set +e
"$exe" identify lugre "$tmp/lugre.csv" --force applied --inertia 1 --static "$tmp/law.yaml" > /dev/null 2> "$tmp/err.txt"
code=$?
set -e
[ "$code" -eq 2 ] || fail "duplicate key in --static: exit $code"
grep -qF "law.yaml: line 6: key 'Fc' given twice (first on line 2)" "$tmp/err.txt" || fail "duplicate key in --static: $(cat "$tmp/err.txt")"
echo "contract_scenario: ok"
