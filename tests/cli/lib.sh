# Shared by the CLI test scripts, sourced first: `source "$(dirname "$0")/lib.sh"`. ctest runs
# each script as `bash SCRIPT PATH_TO_frictionlab SOURCE_DIR` (tests/CMakeLists.txt); sourced
# without arguments, this file sees the script's. It sets the scripts' common start: strict mode,
# `exe` (the tool), `src` (the source tree), a scratch directory `tmp` removed on exit (a script
# that needs more cleanup sets its own EXIT trap, removing "$tmp" too); and the helpers below, to
# run the tool and check its exit status and its one-line message.
set -euo pipefail
exe="$1"
src="$2"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

fail() { echo "FAIL: $*"; exit 1; }

# expect EXIT_CODE TEXT ARGS...: runs "$exe" ARGS (stdout to $tmp/out.txt, stderr to
# $tmp/err.txt) and fails unless it exits with EXIT_CODE and, when EXIT_CODE is not 0, stderr is
# one line (docs/guarantees.md) containing TEXT.
expect() {
  local want_code="$1" want="$2"
  shift 2
  set +e
  # No progress lines: a slow run's stderr would hold them besides the one-line message.
  FRICTIONLAB_NO_PROGRESS=1 "$exe" "$@" > "$tmp/out.txt" 2> "$tmp/err.txt"
  local code=$?
  set -e
  [ "$code" -eq "$want_code" ] || { cat "$tmp/err.txt"; fail "$*: exit $code, expected $want_code"; }
  [ "$want_code" -eq 0 ] && return 0
  grep -qF -- "$want" "$tmp/err.txt" || { cat "$tmp/err.txt"; fail "$*: message lacks '$want'"; }
  [ "$(wc -l < "$tmp/err.txt")" -eq 1 ] || { cat "$tmp/err.txt"; fail "$*: expected a one-line message"; }
}

# expect_fail TEXT ARGS...: bad input, exit status 2 with a one-line message containing TEXT.
expect_fail() {
  local want="$1"
  shift
  expect 2 "$want" "$@"
}

# check_parameters JSON EXPR: the result in JSON (a --json file) is ok and the Python expression
# EXPR holds over p, its parameters by name -> value; `rel NAME VALUE TOL` writes the expression
# "p[NAME] is within the relative tolerance TOL of VALUE" for it.
check_parameters() {
  /usr/bin/python3 - "$1" "$2" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
p = {k: v["value"] for k, v in j["parameters"].items()}
assert j["status"] == "ok", j["message"]
assert eval(sys.argv[2]), (sys.argv[2], p)
PY
}
rel() { echo "abs(p['$1'] - $2) <= $3 * abs($2)"; }
