#!/usr/bin/env bash
# The JSON contract as a property (tests/cli/json_envelope.py): bytes that are not UTF-8 in file
# names, CSV headers, MAT variable names and option values never break `--json -`: stdout is one
# valid JSON object with the documented envelope, for runs that succeed and runs that fail.
# Seeded: FRICTIONLAB_PROPERTY_SEED (default 25).
# Usage: contract_json_envelope.sh PATH_TO_frictionlab SOURCE_DIR
source "$(dirname "$0")/lib.sh"
# shellcheck source=lib.sh
/usr/bin/python3 "$src/tests/cli/json_envelope.py" "$exe" "$src" "$tmp"
