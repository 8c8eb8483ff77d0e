#!/usr/bin/env bash
# merge on damaged parts as a property (tests/cli/merge_parts_damaged.py): a truncated part, an
# edited total, shard, column or row, a part given twice or from another run is exit 2 naming the
# part and what is wrong; never a crash, never a silent merge. Seeded: FRICTIONLAB_PROPERTY_SEED.
# Usage: contract_merge_parts.sh PATH_TO_frictionlab SOURCE_DIR
source "$(dirname "$0")/lib.sh"
# shellcheck source=lib.sh
/usr/bin/python3 "$src/tests/cli/merge_parts_damaged.py" "$exe" "$src" "$tmp"
