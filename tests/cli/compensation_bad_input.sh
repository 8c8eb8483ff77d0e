#!/usr/bin/env bash
# A scenario's `compensation:` block that does not fit (scenario/scenario.hpp): exit 2 with a one-line
# message naming the file and the key (a LuGre observer without a LuGre law, an unknown type, a
# parameter of another type, an unknown key, a model file that is not there, a model of the other
# kind of axis); nothing written.
# Usage: compensation_bad_input.sh PATH_TO_frictionlab SOURCE_DIR
source "$(dirname "$0")/lib.sh"

hunting="$src/examples/canudas_pid_hunting_compensated.yaml"
circle="$src/examples/xy_circle_compensated.yaml"

# check NAME SED_EXPR BASE TEXT...: BASE edited by SED_EXPR, simulated: exit 2, one line with each
# TEXT, no output file.
check() {
  local name="$1" expr="$2" base="$3"
  shift 3
  sed "$expr" "$base" > "$tmp/$name.yaml"
  expect_fail "$name.yaml" simulate "$tmp/$name.yaml" -o "$tmp/out.csv"
  for want in "$@"; do
    grep -qF -- "$want" "$tmp/err.txt" || { cat "$tmp/err.txt"; fail "$name: message lacks '$want'"; }
  done
  [ ! -e "$tmp/out.csv" ] || fail "$name: output written"
}

# The xy-table's axes have Stribeck laws: a LuGre observer of them is refused at the type.
check stribeck_observer 's/type: feedforward/type: lugre-observer/; /band: 1.0e-4/d' "$circle" \
  "plant.compensation.type" "lugre-observer" "lugre"
# An explicit law that is not LuGre: blamed on the friction key.
check coulomb_observer 's/    gain: 0.01 .*/    friction: {law: coulomb, Fc: 1}/' "$hunting" \
  "controller.compensation.friction" "lugre-observer"
check unknown_type 's/type: lugre-observer .*/type: observer/' "$hunting" \
  "controller.compensation.type" "unknown compensation type 'observer'" "feedforward, feedback, lugre-observer, disturbance-observer"
check foreign_key 's/    gain: 0.01 .*/    band: 0.001/' "$hunting" \
  "controller.compensation" "'band'" "gain"
check unknown_key 's/    gain: 0.01 .*/    gian: 0.01/' "$hunting" \
  "controller.compensation" "'gian'"
check missing_model 's/    gain: 0.01 .*/    model: missing_model.json/' "$hunting" \
  "controller.compensation.model" "missing_model.json"
# A model identified on a rotary axis (N m) compensating the linear rig (N): refused naming both.
echo '{"schema": 2, "status": "ok", "axis": "rotary", "law": {"law": "lugre", "sigma0": 1e5, "sigma1": 316, "sigma2": 0.4, "Fc": 1, "Fs": 1.5, "vs": 0.001}}' > "$tmp/rotary.json"
check rotary_model "s|    gain: 0.01 .*|    model: $tmp/rotary.json|" "$hunting" \
  "controller.compensation.model" "rotary.json: axis: a rotary model on a linear plant"
check bad_scale 's/    band: 1.0e-4 .*/    scale: -1/' "$circle" \
  "plant.compensation.scale" "-1" "> 0"
echo "ok"
