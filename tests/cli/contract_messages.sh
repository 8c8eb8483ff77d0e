#!/usr/bin/env bash
# Messages of hostile options and values (docs/guarantees.md): each names the option or key and
# what was expected, in one short line, and nothing is run or written: --jobs -1 (once a
# 309-digit bound), a law parameter given as a list (once "missing parameter"), a newline in a
# --plot name (once "gnuplot failed (exit 0)"), an empty --shard (once: no sharding at all), a
# part file named .csv (once: JSON written into it).
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
echo ok
