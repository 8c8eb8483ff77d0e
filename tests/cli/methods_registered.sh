#!/usr/bin/env bash
# The structure of an identification method (README, Layout): every `frictionlab identify`
# subcommand has its files (src/identify/NAME.cpp with NAME_method_info(), app/methods/NAME.cpp
# with NAME_method(), python/src/methods/NAME.cpp with NAME_binding(), python/frictionlab/methods/NAME.py)
# and one registration line, X(NAME) in FRICTIONLAB_METHODS; its name is written nowhere else as
# a string; and no file outside app/methods/ chooses behaviour by comparing a method's name (the
# text table, report and figures read the result).
source "$(dirname "$0")/lib.sh"

list="$src/include/frictionlab/identify/method.hpp"
# The subcommands as --help lists them (CLI11: a "Subcommands:" block, one name per line).
names=$("$exe" identify --help | awk '/^Subcommands:/{on=1; next} on && /^  [a-z]/ {print $1} on && /^[A-Z]/ {exit}')
[ "$(echo "$names" | wc -w)" -ge 5 ] || fail "identify --help lists too few methods: $names"
for m in $names validate; do
  [ "$(grep -cE "^ *X\($m\) *\\\\?$" "$list")" -eq 1 ] || fail "$m is not registered once in FRICTIONLAB_METHODS ($list)"
  f="$src/app/methods/$m.cpp"
  [ -f "$f" ] || fail "method $m has no file app/methods/$m.cpp"
  grep -q "^CliMethod ${m}_method()" "$f" || fail "$f does not define ${m}_method()"
  grep -q "^MethodInfo detail::${m}_method_info()" "$src/src/identify/$m.cpp" ||
    fail "src/identify/$m.cpp does not define detail::${m}_method_info()"
  grep -q "^PyMethod ${m}_binding()" "$src/python/src/methods/$m.cpp" ||
    fail "python/src/methods/$m.cpp does not define ${m}_binding()"
  [ -f "$src/python/frictionlab/methods/$m.py" ] || fail "method $m has no python/frictionlab/methods/$m.py"
done

# A method's name is written once: no string literal "NAME" in the code of the methods (comments
# aside), in the library, the command line or the Python bindings. The same word as something
# else is not the method's name: an option (idim's --validate), a law or model ("lugre"), the
# Python function validate and its arguments.
/usr/bin/python3 - "$src" $names validate <<'PY'
import pathlib, re, sys
src = pathlib.Path(sys.argv[1])
names = sys.argv[2:]
files = [p for d in ("src/identify", "include/frictionlab/identify", "app/methods", "python/src/methods")
         for p in sorted((src / d).glob("*.[ch]pp"))]
other = re.compile(r'(given|text)\("\w+"\)|\.name = "\w+"|s\.name == "lugre"|make_result\(MethodId::\w+, "|'
                   r'(path_arg|vector_arg)\([^)]*"validate"|same_length\("validate"|return \{"validate", bind')
hits = []
for p in files:
    for no, line in enumerate(p.read_text().splitlines(), 1):
        code = line.split("//")[0] if not line.lstrip().startswith("//") else ""
        code = other.sub("", code)
        for n in names:
            if f'"{n}"' in code:
                hits.append(f"{p.relative_to(src)}:{no}: {line.strip()}")
assert not hits, "a method's name written outside FRICTIONLAB_METHODS:\n" + "\n".join(hits)
PY

# No switch on a method's name anywhere else (a name read from a result or argument compared to
# a literal), nor a unit string searched to guess the axis.
hits=$(grep -nE '(method|\.name) *[!=]= *"(idim|sweep|breakaway|decay|lugre|validate)"' \
  "$src"/app/*.cpp "$src"/src/io/*.cpp "$src"/python/src/*.cpp || true)
[ -z "$hits" ] || fail "behaviour chosen by a method's name: $hits"
hits=$(grep -nE 'unit\.(find|rfind)\(' "$src"/app/*.cpp "$src"/app/methods/*.cpp "$src"/src/io/*.cpp || true)
[ -z "$hits" ] || fail "an axis guessed from a unit string: $hits"
echo "ok"
