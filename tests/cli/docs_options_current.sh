#!/usr/bin/env bash
# docs/options.md is the options reference that `frictionlab help --markdown` makes from the
# methods' option tables: the committed page must be what the tables say now (regenerate it with
# `build/app/frictionlab help --markdown > docs/options.md` after changing an option).
source "$(dirname "$0")/lib.sh"
"$exe" help --markdown > "$tmp/options.md"
diff -u "$src/docs/options.md" "$tmp/options.md" || fail "docs/options.md differs from the option tables (regenerate it)"
echo "PASS docs_options_current"
