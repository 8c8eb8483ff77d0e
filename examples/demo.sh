#!/usr/bin/env bash
# `make demo`: identify the friction of the EMPS benchmark axis (real measurements, bundled in
# data/emps) with the benchmark's recipe and with the better model of the README, cross-test each
# on the second run, and write a report for each; then check that everything was written.
# Usage: examples/demo.sh BUILD_DIR   (outputs in $FRICTIONLAB_DEMO_OUT, default out/demo)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$here/build}" && pwd)
exe="$build/app/frictionlab"
out="${FRICTIONLAB_DEMO_OUT:-$here/out/demo}"
mkdir -p "$out"
emps=("$here/data/emps/DATA_EMPS.mat" --time t --position qm --input vir --gain gtau
      --validate "$here/data/emps/DATA_EMPS_PULSES.mat")

echo "== frictionlab demo: EMPS ball-screw axis (data/emps/README.md), inverse dynamic model least squares"
"$exe" identify idim "${emps[@]}" --json "$out/emps_model.json" --report "$out/report" --overwrite
echo
echo "== the better model: one-sample drive delay, direction-dependent friction, Stribeck term"
"$exe" identify idim "${emps[@]}" --terms inertia,asymmetric,stribeck --delay 1 \
  --json "$out/emps_model_best.json" --report "$out/report_best" --overwrite
echo

# Each report has its page and the fit, friction-map and cross-test figures (with data and script).
for report in "$out/report" "$out/report_best"; do
  for f in report.html {fit,friction-map,cross-test}.svg{,.dat,.gp}; do
    [ -s "$report/$f" ] || { echo "demo: $report/$f was not written" >&2; exit 1; }
  done
done
echo "models:  $out/emps_model.json (recipe), $out/emps_model_best.json (better)"
echo "reports: $out/report/report.html (recipe), $out/report_best/report.html (better)"
