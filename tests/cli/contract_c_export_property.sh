#!/usr/bin/env bash
# The C export as a seeded property (docs/guarantees.md, "Numbers or an error, never both"): laws
# and compensations with parameters across double's and float's ranges, double and --float headers;
# each export is refused with exit 2 and no header, or its header compiles with the system C
# compiler (cc -std=c99 -Wall -Wextra -Werror -pedantic) and evaluates to finite numbers wherever
# the library's own values are (tests/cli/c_export_property.py). make test runs 40 cases; make fuzz
# runs FRICTIONLAB_C_EXPORT_CASES of them with a new seed.
source "$(dirname "$0")/lib.sh"
/usr/bin/python3 "$src/tests/cli/c_export_property.py" "$exe" "$src" "$tmp"
echo ok
