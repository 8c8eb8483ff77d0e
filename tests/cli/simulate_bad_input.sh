#!/usr/bin/env bash
# frictionlab simulate with bad scenario files: exit 2, the message names the file, the key and
# lists what is valid; nothing is written.
source "$(dirname "$0")/lib.sh"

expect_refused() {  # file, text the message must contain
  set +e
  "$exe" simulate "$1" -o "$tmp/out.csv" 2> "$tmp/err.txt"
  local code=$?
  set -e
  [ "$code" -eq 2 ] || { echo "FAIL: $1: exit $code, expected 2"; cat "$tmp/err.txt"; exit 1; }
  grep -qF -- "$2" "$tmp/err.txt" || { echo "FAIL: $1: message lacks '$2':"; cat "$tmp/err.txt"; exit 1; }
  [ ! -e "$tmp/out.csv" ] || { echo "FAIL: $1: output written"; exit 1; }
}

base="$src/examples/craig_stick_slip.yaml"
sed 's/law: static-coulomb-viscous/law: sticky/' "$base" > "$tmp/law.yaml"
expect_refused "$tmp/law.yaml" "unknown friction law 'sticky'"
expect_refused "$tmp/law.yaml" "stribeck"            # the list of valid laws
expect_refused "$tmp/law.yaml" "law.yaml: friction"  # file and key

sed 's/type: spring-base/type: trolley/' "$base" > "$tmp/plant.yaml"
expect_refused "$tmp/plant.yaml" "plant.type: unknown plant type 'trolley'; valid plant types: axis, pendulum, spring-base, dc-motor"

sed 's/duration: 10/duration: -3/' "$base" > "$tmp/dur.yaml"
expect_refused "$tmp/dur.yaml" "duration: -3 must be > 0 (s)"

sed 's/  k: 100.0      # N\/m/  kk: 100.0/' "$base" > "$tmp/field.yaml"
expect_refused "$tmp/field.yaml" "plant.kk: unknown field 'kk'; valid fields: type, m, k, c, V0, x0"

grep -v '  V0:' "$base" > "$tmp/missing.yaml"
expect_refused "$tmp/missing.yaml" "plant: missing 'V0'"

printf 'plant: [unclosed\n' > "$tmp/broken.yaml"
expect_refused "$tmp/broken.yaml" "not valid YAML at line"

expect_refused "$tmp/does_not_exist.yaml" "cannot open"
echo "ok"
