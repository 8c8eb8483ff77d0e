#!/usr/bin/env bash
# Each method's options are declared once, in its option table: `frictionlab identify METHOD
# --help` lists a flag for each, `frictionlab help --markdown` (the options reference) a row for
# each with the same flags, and a bad value exits 2 with a message naming the flag, the value
# and what was expected.
source "$(dirname "$0")/lib.sh"

expect 0 "" help --markdown
cp "$tmp/out.txt" "$tmp/ref.md"
grep -q '^# Options of the identification methods' "$tmp/ref.md" || fail "reference lacks its title"
for m in idim breakaway sweep decay lugre; do
  "$exe" identify "$m" --help > "$tmp/help.txt"
  # The method's section of the reference: from its heading to the next.
  awk -v m="## $m" '$0 == m {on=1; next} on && /^## / {exit} on' "$tmp/ref.md" > "$tmp/sec.md"
  flags=$(grep -o '^| `--[a-z-]*`' "$tmp/sec.md" | sed 's/^| `//; s/`$//')
  [ -n "$flags" ] || fail "$m: no options in the reference"
  for f in $flags; do
    grep -qE -- "(^| |,)$f( |=|$)" "$tmp/help.txt" || fail "$m: $f of the reference is not in identify $m --help"
  done
done
grep -qF '| `--min-speed` | `min_speed` | number | m/s or rad/s | computed |' "$tmp/ref.md" || fail "sweep --min-speed row"
grep -qF '| `--delay` | `delay` | integer | samples | `0` |' "$tmp/ref.md" || fail "idim --delay row"
"$exe" identify sweep --help > "$tmp/help.txt"
# The help text comes from the table too: unit, default, range and when the option applies (its
# table's conditions; in the reference too).
grep -q "Shortest steady segment kept (s; default 0.5; > 0; applies without --segment)" "$tmp/help.txt" ||
  fail "sweep --min-duration help"
"$exe" identify idim --help > "$tmp/help.txt"
grep -qE -- "--kp .*applies with --iv\)" "$tmp/help.txt" || fail "idim --kp help does not say it applies with --iv"
grep -qE -- "--vs .*applies when --terms holds stribeck\)" "$tmp/help.txt" || fail "idim --vs help does not say when it applies"
grep -F '| `--kp` |' "$tmp/ref.md" | grep -qF '(applies with `--iv`) |' || fail "the reference does not say idim --kp applies with --iv"
# Written to a file: refused when it exists, replaced with --overwrite.
expect 0 "" help --markdown -o "$tmp/options.md"
cmp "$tmp/ref.md" "$tmp/options.md" || fail "help -o differs from stdout"
expect_fail "--output" help --markdown -o "$tmp/options.md"
expect 0 "" help --markdown -o "$tmp/options.md" --overwrite

# Checks from the table: the flag, the value and what was expected; exit 2.
printf 'time,velocity,force\n0,0,0\n0.01,0,0\n0.02,0,0\n' > "$tmp/d.csv"
expect_fail "--min-duration = -1 must be > 0 (s)" identify sweep "$tmp/d.csv" --min-duration -1
expect_fail "--vs 'fast': expected a Stribeck velocity (m/s or rad/s) or 'search'" identify idim "$tmp/d.csv" --vs fast
expect_fail "--decimate = 0 must be >= 1" identify idim "$tmp/d.csv" --decimate 0
expect_fail "--substeps = 0 must be >= 1" identify lugre "$tmp/d.csv" --inertia 1 --substeps 0
expect_fail "--from 'force': expected position or velocity" identify idim "$tmp/d.csv" --from force
expect_fail "--inertia" identify lugre "$tmp/d.csv"
echo "options_reference: ok"
