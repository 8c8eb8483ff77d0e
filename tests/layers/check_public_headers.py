#!/usr/bin/env python3
"""Every public header exports what it declares.

The library is built with hidden visibility; a public header (include/frictionlab/**.hpp) opens its
namespace as `namespace frictionlab FRICTIONLAB_API {` after including frictionlab/export.hpp, or its
declarations are missing from the shared library and a consumer fails to link. (The attribute stands
after the name: GCC also takes it before, Clang only after.) Usage:
    check_public_headers.py [SOURCE_DIR]
"""
import os
import re
import sys

OPEN = re.compile(r"^namespace\s+frictionlab(\s+FRICTIONLAB_API)?\s*\{", re.MULTILINE)


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
    problems, headers = [], 0
    for folder, _, names in os.walk(os.path.join(root, "include", "frictionlab")):
        for name in sorted(names):
            if not name.endswith(".hpp"):
                continue
            headers += 1
            rel = os.path.relpath(os.path.join(folder, name), root)
            text = open(os.path.join(root, rel), encoding="utf-8").read()
            opens = OPEN.findall(text)
            if not opens:
                problems.append(f"{rel}: declares nothing in namespace frictionlab (an empty or misplaced header)")
            elif not opens[0]:
                problems.append(f"{rel}: opens 'namespace frictionlab {{' without FRICTIONLAB_API; expected"
                                f" '#include \"frictionlab/export.hpp\"' and 'namespace frictionlab FRICTIONLAB_API {{'")
            elif '#include "frictionlab/export.hpp"' not in text:
                problems.append(f"{rel}: uses FRICTIONLAB_API without including frictionlab/export.hpp")
    for p in problems:
        print(p, file=sys.stderr)
    print(f"check_public_headers: {headers} headers, {len(problems)} problems")
    return 1 if problems or headers == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
