#!/usr/bin/env python3
"""The include graph of the library has no upward edge.

Each layer (a folder of include/frictionlab/ and src/) may include only the layers listed for it
below; everything else is an upward or sideways edge and fails this check, naming the file and the
include. The table is the architecture: docs/architecture.md shows the same layers. Usage:
    check_layers.py [SOURCE_DIR]
"""
import os
import re
import sys

# layer -> the layers its files may include (besides itself). "root" is the headers directly in
# include/frictionlab/ (format.hpp, version.hpp, error.hpp, export.hpp).
ALLOWED = {
    "root": set(),
    "models": {"root"},
    "core": {"root", "models"},
    "signal": {"root", "models"},
    "io": {"root", "models", "signal"},
    "control": {"root", "models", "core"},
    "plants": {"root", "models", "core"},
    "simulate": {"root", "models", "core", "plants", "control"},
    "identify": {"root", "models", "core", "signal", "io", "plants", "control", "simulate"},
    "analysis": {"root", "models", "core", "signal", "io", "plants", "control", "simulate", "identify"},
    "scenario": {"root", "models", "core", "signal", "io", "plants", "control", "simulate", "identify",
                 "analysis"},
    "report": {"root", "models", "core", "signal", "io", "identify", "analysis"},
    "export": {"root", "models", "core", "control", "io", "identify", "scenario"},
    "fleet": {"root", "models", "core", "signal", "io", "plants", "control", "simulate", "identify",
              "analysis", "scenario", "report"},
}

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def layer_of(rel):
    """The layer of a path relative to the source root, or None outside the library."""
    parts = rel.split("/")
    if parts[0] == "include" and len(parts) >= 3 and parts[1] == "frictionlab":
        parts = parts[2:]
    elif parts[0] == "src":
        parts = parts[1:]
    else:
        return None
    return parts[0] if len(parts) > 1 else "root"


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    root = os.path.abspath(root)
    problems = []
    files = 0
    for base in ("include/frictionlab", "src"):
        for folder, _, names in os.walk(os.path.join(root, base)):
            for name in sorted(names):
                if not name.endswith((".hpp", ".cpp", ".h")):
                    continue
                files += 1
                rel = os.path.relpath(os.path.join(folder, name), root)
                here = layer_of(rel)
                if here not in ALLOWED:
                    problems.append(f"{rel}: folder '{here}' is not a layer of the table in {__file__}")
                    continue
                with open(os.path.join(root, rel), encoding="utf-8") as f:
                    text = f.read()
                for m in INCLUDE.finditer(text):
                    inc = m.group(1)
                    if inc.startswith("frictionlab/"):
                        parts = inc.split("/")
                        there = parts[1] if len(parts) > 2 else "root"
                    else:  # beside the file, else from src/ (the library's private include folder)
                        beside = os.path.normpath(os.path.join(os.path.dirname(rel), inc))
                        if not os.path.exists(os.path.join(root, beside)):
                            beside = os.path.normpath(os.path.join("src", inc))
                        there = layer_of(beside)
                    if there is None or there == here:
                        continue
                    if there not in ALLOWED[here]:
                        problems.append(f"{rel}: includes \"{inc}\": layer '{here}' may not use '{there}'"
                                        f" (it may use: {', '.join(sorted(ALLOWED[here])) or 'nothing'})")
    if files == 0:
        print(f"check_layers: no source files under {root}", file=sys.stderr)
        return 1
    for p in problems:
        print(p, file=sys.stderr)
    print(f"check_layers: {files} files, {len(problems)} upward or sideways includes")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
