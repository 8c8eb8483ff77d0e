#!/usr/bin/env bash
# The structure of an identification method (README, Layout): every `frictionlab identify`
# subcommand has its file app/methods/NAME.cpp defining NAME_method(), one line in cli_methods()
# and one in the library's identification_methods(); and no file outside app/methods/ chooses
# behaviour by comparing a method's name (the text table, report and figures read the result).
source "$(dirname "$0")/lib.sh"

# The subcommands as --help lists them (CLI11: a "Subcommands:" block, one name per line).
names=$("$exe" identify --help | awk '/^Subcommands:/{on=1; next} on && /^  [a-z]/ {print $1} on && /^[A-Z]/ {exit}')
[ "$(echo "$names" | wc -w)" -ge 5 ] || fail "identify --help lists too few methods: $names"
for m in $names; do
  f="$src/app/methods/$m.cpp"
  [ -f "$f" ] || fail "identify $m has no file app/methods/$m.cpp"
  grep -q "^CliMethod ${m}_method()" "$f" || fail "$f does not define ${m}_method()"
  [ "$(grep -c "^ *${m}_method()," "$src/app/methods/methods.cpp")" -eq 1 ] ||
    fail "${m}_method() is not listed once in app/methods/methods.cpp"
  [ "$(grep -c "^ *{\"$m\"," "$src/src/identify/method.cpp")" -eq 1 ] ||
    fail "$m is not described once in src/identify/method.cpp"
done
# validate registers its figure and caption the same way, without an identify subcommand.
grep -q "^ *validate_method()," "$src/app/methods/methods.cpp" || fail "validate is not registered"

# No switch on a method's name anywhere else (a name read from a result or argument compared to
# a literal), nor a unit string searched to guess the axis.
hits=$(grep -nE '(method|\.name) *[!=]= *"(idim|sweep|breakaway|decay|lugre|validate)"' \
  "$src"/app/*.cpp "$src"/src/io/*.cpp "$src"/python/src/*.cpp || true)
[ -z "$hits" ] || fail "behaviour chosen by a method's name: $hits"
hits=$(grep -nE 'unit\.(find|rfind)\(' "$src"/app/*.cpp "$src"/app/methods/*.cpp "$src"/src/io/*.cpp || true)
[ -z "$hits" ] || fail "an axis guessed from a unit string: $hits"
echo "ok"
