#!/usr/bin/env python3
"""Every promise of docs/guarantees.md names the tests that check it.

Each top-level bullet (`- **Promise.** ...`) must hold a `*Checked by*` sentence naming at least one
test file under tests/ (`tests/cli/contract_finite.sh`; a glob such as `tests/cli/*_bad_input.sh`
must match a file), and every test file the page names must exist. A GoogleTest name given in
parentheses after a .cpp file (`Budget.*`, `ModelFile.OneStrictReader`) must be a TEST of that file.
Usage: check_guarantees.py [SOURCE_DIR]
"""
import glob
import os
import re
import sys

PATH = re.compile(r"`(tests/[^`\s]+)`")
# A .cpp file followed by its test names in parentheses: `tests/io/x.cpp` (`A.b`, `C.*`)
CPP_TESTS = re.compile(r"`(tests/[^`\s]+\.cpp)`\s*\(([^)]*)\)")
NAME = re.compile(r"`([A-Z]\w*)\.(\w+|\*)`")


def bullets(text):
    out, current = [], None
    for line in text.splitlines():
        if line.startswith("- **"):
            current = [line]
            out.append(current)
        elif current is not None and line.startswith("  "):
            current.append(line)
        else:
            current = None
    return [" ".join(b) for b in out]


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
    text = open(os.path.join(root, "docs", "guarantees.md"), encoding="utf-8").read()
    problems = []
    promises = bullets(text)
    if not promises:
        problems.append("docs/guarantees.md: no promises found (bullets starting '- **')")
    for b in promises:
        title = re.match(r"- \*\*([^*]+)\*\*", b).group(1)
        checked = b.split("*Checked by*", 1)
        if len(checked) < 2:
            problems.append(f"promise '{title}': no '*Checked by*' naming its tests")
        elif not PATH.search(checked[1]):
            problems.append(f"promise '{title}': '*Checked by*' names no test file under tests/")
    flat = " ".join(text.split())
    for path in sorted(set(PATH.findall(flat))):
        if not glob.glob(os.path.join(root, path)):
            problems.append(f"docs/guarantees.md names {path}, which does not exist")
    for path, names in CPP_TESTS.findall(flat):
        source = os.path.join(root, path)
        if not os.path.exists(source):
            continue
        code = open(source, encoding="utf-8").read()
        for suite, test in NAME.findall(names):
            pattern = r"TEST(_F|_P)?\(\s*" + suite + r"\s*,\s*" + (r"\w+" if test == "*" else test) + r"\s*\)"
            if not re.search(pattern, code):
                problems.append(f"docs/guarantees.md names {suite}.{test} in {path}, which has no such test")
    for p in problems:
        print(p)
    print(f"{len(promises)} promises, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
