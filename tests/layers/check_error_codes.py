#!/usr/bin/env python3
"""The error codes live in one table.

Every code constant (`errc::NAME = "CODE"`) is declared in include/frictionlab/error.hpp and nowhere
else, and the table at the top of that header lists exactly those codes: a code added to the library
without a line in the table, or a table line without a constant, fails. Every constant is used
(`errc::NAME`) by the library, the command line or the Python module: a code in the table that no
error carries (output.not_finite before the refusals of numbers that are not finite used it) fails.
Usage:
    check_error_codes.py [SOURCE_DIR]
"""
import os
import re
import sys

CONSTANT = re.compile(r'inline\s+constexpr\s+const\s+char\s*\*\s*(\w+)\s*=\s*"([a-z_.]+)"')
ROW = re.compile(r"^//\s*\|\s*([a-z_]+\.[a-z_]+|internal)\s*\|", re.MULTILINE)
ERRC = re.compile(r"\bnamespace\s+errc\b")
USE = re.compile(r"\berrc::(\w+)")


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
    table_header = os.path.join("include", "frictionlab", "error.hpp")
    text = open(os.path.join(root, table_header), encoding="utf-8").read()
    constants = {code: name for name, code in CONSTANT.findall(text)}
    rows = set(ROW.findall(text))
    problems = []
    for code in sorted(set(constants) - rows):
        problems.append(f"{table_header}: code '{code}' (errc::{constants[code]}) has no line in the table")
    for code in sorted(rows - set(constants)):
        problems.append(f"{table_header}: the table lists '{code}' but no errc constant holds it")
    used = set()
    for top in ("include", "src", "app", "python"):
        for folder, _, names in os.walk(os.path.join(root, top)):
            for name in sorted(names):
                if not name.endswith((".hpp", ".cpp", ".h")):
                    continue
                rel = os.path.relpath(os.path.join(folder, name), root)
                if rel == table_header:
                    continue
                source = open(os.path.join(root, rel), encoding="utf-8", errors="replace").read()
                if ERRC.search(source):
                    problems.append(f"{rel}: opens namespace errc; error codes belong in the table of {table_header}")
                used.update(USE.findall(source))
    for code, name in sorted(constants.items()):
        if name not in used:
            problems.append(f"{table_header}: code '{code}' (errc::{name}) is used by no error of include, src, app or python")
    for p in problems:
        print(p)
    print(f"{len(constants)} codes, {len(rows)} table lines, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
