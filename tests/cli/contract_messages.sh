#!/usr/bin/env bash
# Messages of hostile options and values (docs/guarantees.md): each names the option or key and
# what was expected, in one short line, and nothing is run or written: --jobs -1 (once a
# 309-digit bound), a law parameter given as a list (once "missing parameter"), a newline in a
# --plot name (once "gnuplot failed (exit 0)"), an empty --shard (once: no sharding at all), a
# part file named .csv (once: JSON written into it), an unterminated quote in a YAML scenario or
# law file (once "missing 'plant'": the rest of the file was read as the quoted text), positions
# near 1e308 given to lugre and breakaway (once "|velocity| > inf m/s"), a LuGre sigma0 of 1e308
# (once -inf friction at 10 m/s).
source "$(dirname "$0")/lib.sh"
pid="$src/examples/map_pid_hunting.yaml"
pendulum="$src/examples/craig_pendulum_coulomb.yaml"

expect_fail "--jobs" analyze map "$pid" --vary friction.Fs=1:2:2 --jobs -1 -o "$tmp/m.csv"
[ "$(wc -c < "$tmp/err.txt")" -lt 200 ] || fail "--jobs -1: a long message: $(cat "$tmp/err.txt")"
grep -q "[0-9]\{20\}" "$tmp/err.txt" && fail "--jobs -1: a huge number in: $(cat "$tmp/err.txt")"

sed 's/^  Fc: 0.16.*/  Fc: [0.16]/' "$pendulum" > "$tmp/list.yaml"
grep -q "Fc: \[0.16\]" "$tmp/list.yaml" || fail "no Fc line to edit"
expect_fail "parameter 'Fc' is a list of 1 numbers; expected one number" simulate "$tmp/list.yaml" -o "$tmp/out.csv"

expect_fail "--plot: the file name holds a control character (a newline)" \
  simulate "$pendulum" -o "$tmp/out.csv" --plot "$tmp/a
b.svg"
[ ! -e "$tmp/out.csv" ] || fail "--plot with a newline: the run went ahead"

expect_fail "--shard: empty; expected K/N" analyze map "$pid" --vary friction.Fs=1:2:2 --shard "" -o "$tmp/p.json"
expect_fail "-o $tmp/p.csv: --shard 1/2 writes a part file, which is JSON: expected -o PART.json" \
  analyze map "$pid" --vary friction.Fs=1:2:2 --shard 1/2 -o "$tmp/p.csv"
[ ! -e "$tmp/p.csv" ] || fail "--shard wrote a .csv"
# An unterminated quote: the file, its line and column, and what is wrong.
sed 's|^description:.*|description: "a pendulum|' "$src/examples/craig_pendulum_coulomb.yaml" > "$tmp/quote.yaml"
grep -q '^description: "a pendulum$' "$tmp/quote.yaml" || fail "no description line to edit"
line="$(grep -n '^description:' "$tmp/quote.yaml" | cut -d: -f1)"
expect_fail "$tmp/quote.yaml: line $line, column 14: unterminated quote" simulate "$tmp/quote.yaml" -o "$tmp/out.csv"
printf "friction:\n  law: coulomb\n  Fc: '1.0\n" > "$tmp/quote_law.yaml"
expect_fail "$tmp/quote_law.yaml: line 3, column 7: unterminated quote" \
  export "$tmp/quote_law.yaml" --c "$tmp/law.h"
# A quote that is closed on a later line is YAML's multi-line text, not an error; '' and \" inside
# quotes do not close them.
cat > "$tmp/multi.yaml" <<'YAML'
description: "two
  lines \" and"
plant: {type: axis, M: 1.0}
friction: {law: coulomb, Fc: 1.0}
input: {type: constant, value: 2.0}
duration: 0.1
YAML
expect 0 "" simulate "$tmp/multi.yaml"
{ echo "description: 'it''s \"one\" line'"; tail -n +3 "$tmp/multi.yaml"; } > "$tmp/single.yaml"
grep -q "^description: 'it''s" "$tmp/single.yaml" || fail "no description line"
expect 0 "" simulate "$tmp/single.yaml"

# Positions near the range of a double: their velocity overflows; said so, not "> inf".
/usr/bin/python3 - "$tmp/far.csv" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("time,position,force\n")
    for k in range(200):
        f.write(f"{k * 1e-3},{(-1) ** k * 1.5e308},{1.0}\n")
PY
for method in lugre; do
  expect_fail "exceeds the largest double" identify "$method" "$tmp/far.csv" --inertia 1
  grep -q "inf" "$tmp/err.txt" && fail "identify $method: a message with inf: $(cat "$tmp/err.txt")"
done

# breakaway on velocities near the largest double (the fit's regressors overflow): refused, and
# never "> inf" in the message.
/usr/bin/python3 - "$tmp/farv.csv" <<'PY'
import sys
with open(sys.argv[1], "w") as f:
    f.write("time,velocity,force\n")
    for k in range(200):
        f.write(f"{k * 1e-3},{0 if k < 5 or k > 190 else (-1) ** k * 1.5e308},{1.0}\n")
PY
expect_fail "farv.csv: " identify breakaway "$tmp/farv.csv"
grep -qw "inf" "$tmp/err.txt" && fail "identify breakaway: a message with inf: $(cat "$tmp/err.txt")"
# A LuGre law too stiff for a double: refused naming sigma0 (in a scenario and in a law file).
sed 's/^  sigma0: 1.0e5 .*/  sigma0: 1.0e308/' "$src/examples/canudas_stick_slip.yaml" > "$tmp/stiff.yaml"
grep -q "sigma0: 1.0e308" "$tmp/stiff.yaml" || fail "no sigma0 line to edit"
expect_fail "lugre: sigma0 = 1e+308 (N/m or N m/rad) is too stiff for Fc = 1" simulate "$tmp/stiff.yaml" -o "$tmp/stiff.csv"
[ ! -e "$tmp/stiff.csv" ] || fail "a refused LuGre law wrote its run"
printf '{"law": "lugre", "sigma0": 1e308, "sigma1": 316, "sigma2": 0.4, "Fc": 1.0, "Fs": 1.5, "vs": 0.001}\n' > "$tmp/stiff.json"
expect_fail "sigma0" export "$tmp/stiff.json" --c "$tmp/stiff.h"
echo ok
