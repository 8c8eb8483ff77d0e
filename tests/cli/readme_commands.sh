#!/usr/bin/env bash
# Every command of the README runs: the ```sh blocks in the order they stand (each block one shell
# script, stopping at its first failure), then the ```python blocks, in a scratch directory that
# sees the checkout's examples/, data/ and tests/, with the built tool first on PATH. Every fence
# has a language: sh or python (run here) or shell (shown only: the quick start and the install,
# which `make test` runs as cli.demo_reports, make install-test and python.install). The figures
# the README quotes from these commands are checked where they come out: the own-data parameters,
# to the digits shown (the paragraph's marking comment, tests/docs/doc_commands.py). The README
# stays a first hour's read: at most 300 lines.
source "$(dirname "$0")/lib.sh"
cd "$tmp"
ln -s "$src/examples" examples
ln -s "$src/data" data
ln -s "$src/tests" tests
lines=$(wc -l < "$src/README.md")
((lines <= 300)) || fail "README.md has $lines lines; at most 300 (move the detail to a page of docs/)"
export PATH="$(dirname "$exe"):$PATH"
export PYTHONPATH="$(cd "$(dirname "$exe")/../python" && pwd)${PYTHONPATH:+:$PYTHONPATH}"

/usr/bin/python3 - "$src/README.md" "$tmp" <<'PY'
import re, sys
text = open(sys.argv[1], encoding="utf-8").read()
fences = re.findall(r"^```(\S*)[^\n]*\n.*?^```", text, re.M | re.S)
unknown = [f or "(none)" for f in fences if f not in ("sh", "python", "shell", "text")]
assert not unknown, f"README.md: fences of language {unknown}: use sh or python (run) or shell (shown only)"
blocks = re.findall(r"^```(sh|python)\n(.*?)^```", text, re.M | re.S)
assert blocks, "README.md has no ```sh or ```python block"
n = {"sh": 0, "python": 0}
for kind, body in blocks:
    n[kind] += 1
    with open(f"{sys.argv[2]}/block_{kind}_{n[kind]:02d}.{'sh' if kind == 'sh' else 'py'}", "w") as f:
        f.write(("set -euo pipefail\n" if kind == "sh" else "") + body)
print(f"README: {n['sh']} shell blocks, {n['python']} Python blocks")
PY

for block in block_sh_*.sh; do
  echo "== $block"; cat "$block"
  bash "$block" > "$block.out" 2> "$block.err" || { cat "$block.out" "$block.err"; fail "README $block failed"; }
done
for block in block_python_*.py; do
  echo "== $block"
  /usr/bin/python3 "$block" > "$block.out" 2> "$block.err" || { cat "$block.out" "$block.err"; fail "README $block failed"; }
done

# The figures the README's prose quotes, to the digits shown, from the commands its comments name.
/usr/bin/python3 "$src/tests/docs/doc_commands.py" --numbers-of "$src/README.md" || fail "README's quoted figures differ"
# The own-data figures the README quotes: within 3.2 % of the truth (M 0.8, Fv 1.5, Fc 2.0).
kRelTol=0.035  # the README's "within 3.2 %", rounded up to the last digit it prints
check_parameters joint2.json "$(rel M 0.8 $kRelTol) and $(rel Fv 1.5 $kRelTol) and $(rel Fc 2.0 $kRelTol)"
[ -s joint2/report.html ] || fail "joint2/report.html was not written"
[ -s friction.h ] || fail "friction.h was not written"
grep -q "frictionloss=" axis.xml || fail "axis.xml (export --mjcf) was not written"
echo "PASS readme_commands"
