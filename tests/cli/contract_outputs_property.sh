#!/usr/bin/env bash
# The one rule for outputs as a property over every command (tests/cli/outputs_never_inputs.py):
# every output option the tool lists (`frictionlab help --commands`), pointed at every input of a
# run, at a hard link and a symbolic link to one, with and without --overwrite, is exit 2 naming
# both and leaves the input as it was. Seeded: FRICTIONLAB_PROPERTY_SEED (default 25).
# Usage: contract_outputs_property.sh PATH_TO_frictionlab SOURCE_DIR
source "$(dirname "$0")/lib.sh"
# shellcheck source=lib.sh
/usr/bin/python3 "$src/tests/cli/outputs_never_inputs.py" "$exe" "$src" "$tmp"
