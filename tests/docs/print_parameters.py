#!/usr/bin/env python3
"""print_parameters.py NAME ...: prints the named parameters of an identification's JSON (stdin,
`frictionlab identify ... --json -`) in the order given, one line each: NAME VALUE STD UNIT, to the
digits the JSON holds (the text output rounds std to three digits). The pages of docs/ mark their
parameter tables with it (`<!-- numbers in column 2: frictionlab identify ... --json - | python3
tests/docs/print_parameters.py M Fv Fc offset -->`, tests/docs/doc_commands.py). Exit 1 naming
the status and message for a run without an answer, or a name the result lacks."""
import json
import sys


def main():
    j = json.load(sys.stdin)
    if j.get("status") != "ok":
        print(f"status {j.get('status')}: {j.get('message')}", file=sys.stderr)
        return 1
    p = j["parameters"]
    for n in sys.argv[1:]:
        if n not in p:
            print(f"no parameter '{n}'; the result has {', '.join(p)}", file=sys.stderr)
            return 1
        print(n, repr(p[n]["value"]), repr(p[n].get("std")), p[n].get("unit", ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
