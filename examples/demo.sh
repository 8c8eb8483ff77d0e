#!/usr/bin/env bash
# `make demo`: identify the friction of the EMPS benchmark axis (real measurements, bundled in
# data/emps) with the benchmark's recipe, cross-test it on the second run, and write a report.
# Usage: examples/demo.sh BUILD_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$here/build}" && pwd)
exe="$build/app/frictionlab"
out="$here/out/demo"
mkdir -p "$out"

echo "== frictionlab demo: EMPS ball-screw axis (data/emps/README.md), inverse dynamic model least squares"
"$exe" identify idim "$here/data/emps/DATA_EMPS.mat" --time t --position qm --input vir --gain gtau \
  --validate "$here/data/emps/DATA_EMPS_PULSES.mat" \
  --json "$out/emps_model.json" --report "$out/report" --overwrite
echo
echo "== the better model: one-sample drive delay, direction-dependent friction, Stribeck term"
"$exe" identify idim "$here/data/emps/DATA_EMPS.mat" --time t --position qm --input vir --gain gtau \
  --terms inertia,asymmetric,stribeck --delay 1 \
  --validate "$here/data/emps/DATA_EMPS_PULSES.mat" --json "$out/emps_model_best.json" --overwrite
echo
echo "model:  $out/emps_model.json"
echo "report: $out/report/report.html"
