#!/usr/bin/env bash
# `make demo` (examples/demo.sh) writes both EMPS models and both reports: the recipe model's and
# the better model's, each with the fit, friction-map and cross-test figures (demo.sh checks the
# files itself and fails without them); the better model's map shows its Stribeck terms.
# Usage: demo_reports.sh PATH_TO_frictionlab SOURCE_DIR
source "$(dirname "$0")/lib.sh"
command -v gnuplot > /dev/null || { echo "SKIP: gnuplot not installed (Debian package gnuplot-nox)"; exit 0; }

FRICTIONLAB_DEMO_OUT="$tmp/demo" bash "$src/examples/demo.sh" "$(dirname "$(dirname "$exe")")" > "$tmp/log.txt" 2>&1 ||
  { cat "$tmp/log.txt"; fail "examples/demo.sh failed"; }
for r in report report_best; do
  for f in report.html {fit,friction-map,cross-test}.svg; do [ -s "$tmp/demo/$r/$f" ] || fail "demo lacks $r/$f"; done
done
grep -q "stribeck" "$tmp/demo/report_best/report.html" || fail "the better model's report does not name its Stribeck term"
grep -q "Fc_pos" "$tmp/demo/report_best/report.html" || fail "the better model's report lacks Fc_pos"
grep -q "reports: .*report_best/report.html" "$tmp/log.txt" || fail "demo does not print the better model's report"
echo "demo_reports: ok"
