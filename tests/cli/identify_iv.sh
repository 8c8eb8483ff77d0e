#!/usr/bin/env bash
# IDIM-IV on the command line (docs/identify.md): EMPS in its PD loop converges near IDIM-LS with
# the IV diagnostics in the JSON; --iv without the controller or the reference, a reference column
# the file lacks, controller options without --iv, and an iteration that does not converge are
# exit status 2 with one line naming what to give. The controller from a scenario (--scenario) and
# the gains named as the MAT file's scalars (--kp kp) give the result of the numbers typed; a name
# the file lacks, a --controller against the scenario's, a rotary --axis against its linear plant
# and a velocity loop are exit status 2 naming the file and key.
source "$(dirname "$0")/lib.sh"
emps="$src/data/emps/DATA_EMPS.mat"
idim=(identify idim "$emps" --time t --position qm --input vir --gain gtau)
loop=(--iv --reference qg --controller emps-pd --kp 160.18 --kv 243.45)

expect 0 "" "${idim[@]}" "${loop[@]}" --json "$tmp/iv.json"
/usr/bin/python3 - "$tmp/iv.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["status"] == "ok", j["message"]
d = j["diagnostics"]
assert d["estimator"] == "idim-iv", d
assert 1 <= d["iv_iterations"] <= 10 and d["iv_relative_change"] <= 1e-4, d
assert 0.9 < d["iv_min_canonical_correlation"] <= 1 + 1e-12, d
ls = d["ls_estimate"]
for name in ("M", "Fv", "Fc"):
    p = j["parameters"][name]
    # IV and LS agree within 0.5 % on EMPS (tests/identify/test_idim_iv.cpp says why).
    assert abs(p["value"] - ls[name]) <= 0.005 * abs(ls[name]), (name, p, ls)
    assert p["std"] > 0 and p["std_ols"] > 0, (name, p)
assert j["options"]["iv"]["value"] is True and j["options"]["controller"]["value"] == "emps-pd", j["options"]
PY

# What to give, named.
expect_fail "--controller pid with --kp" "${idim[@]}" --iv --reference qg
expect_fail "--reference COLUMN" "${idim[@]}" --iv --controller emps-pd --kp 160.18 --kv 243.45
expect_fail "--controller emps-pd needs --kp (1/s) and --kv" "${idim[@]}" --iv --reference qg --controller emps-pd --kp 160.18
expect_fail "--controller pid needs --kp" "${idim[@]}" --iv --reference qg --controller pid --kd 10
expect_fail "qgg" "${idim[@]}" --iv --reference qgg --controller emps-pd --kp 160.18 --kv 243.45
expect_fail "but --iv is not given" "${idim[@]}" --kp 160.18
expect_fail "belongs to --controller emps-pd" "${idim[@]}" --iv --reference qg --controller pid --kp 1e4 --kv 3
expect_fail "controller" "${idim[@]}" --iv --reference qg --controller lqr --kp 1
# Not converged: exit 2, the message names the option, no numbers.
expect 2 "did not converge in 1 iterations (--iv-iterations)" "${idim[@]}" "${loop[@]}" --iv-iterations 1 --iv-tolerance 1e-15

# The controller from a scenario (--scenario, the EMPS example: emps-pd with the file's scalars
# kp, kv, gtau): the same controller as the numbers typed, so the same result; its values and
# where each came from are in the JSON. An option given overrides the scenario's value.
scenario="$src/examples/emps_closed_loop.yaml"
expect 0 "" "${idim[@]}" --iv --reference qg --scenario "$scenario" --json "$tmp/iv_scenario.json"
expect 0 "iv_source_kp: --kp" "${idim[@]}" --iv --reference qg --scenario "$scenario" --kp 150 --iv-iterations 40 \
  --json "$tmp/iv_scenario_kp.json"
grep -q "iv_source_kv: scenario $scenario: controller.kv" "$tmp/out.txt" || fail "text lacks the kv's source: $(cat "$tmp/out.txt")"
# The gains as the names of the MAT file's scalars (--kp kp --kv kv): the numbers typed above.
expect 0 "" "${idim[@]}" --iv --reference qg --controller emps-pd --kp kp --kv kv --json "$tmp/iv_names.json"
/usr/bin/python3 - "$tmp/iv.json" "$tmp/iv_scenario.json" "$tmp/iv_names.json" "$tmp/iv_scenario_kp.json" "$scenario" <<'PY'
import json, sys
typed, scen, names, kp = (json.load(open(f)) for f in sys.argv[1:5])
for j in (scen, names, kp):
    assert j["status"] == "ok", j["message"]
# The same controller and simulation: the same numbers, to the last digit the JSON holds.
for j in (scen, names):
    for name, p in typed["parameters"].items():
        assert j["parameters"][name]["value"] == p["value"] and j["parameters"][name]["std"] == p["std"], (name, j["parameters"][name], p)
d = scen["diagnostics"]
assert d["iv_controller_type"] == "emps-pd" and d["iv_source_controller"] == f"scenario {sys.argv[5]}: controller.type", d
assert d["iv_source_kp"] == f"scenario {sys.argv[5]}: controller.kp", d
assert d["iv_source_drive_gain"] == f"scenario {sys.argv[5]}: controller.gtau", d
assert d["iv_controller"]["kv"] == 243.45 and d["iv_controller"]["control_delay"] == 1, d["iv_controller"]
n = names["diagnostics"]
assert n["iv_source_kp"] == "--kp kp: scalar of DATA_EMPS.mat" and n["iv_source_kv"] == "--kv kv: scalar of DATA_EMPS.mat", n
assert n["iv_source_drive_gain"] == "--gain gtau", n
assert typed["diagnostics"]["iv_source_kp"] == "--kp", typed["diagnostics"]
k = kp["diagnostics"]
assert k["iv_source_kp"] == "--kp" and k["iv_source_kv"] == f"scenario {sys.argv[5]}: controller.kv", k
PY

# A name the file lacks: exit 2 naming the file and listing its scalars.
expect_fail "DATA_EMPS.mat: --kp = 'Kp': expected a number or the name of a scalar in the file; scalars: gtau, kp, kv" \
  "${idim[@]}" --iv --reference qg --controller emps-pd --kp Kp --kv kv
# Conflicts with the scenario: exit 2 naming the file and key.
expect_fail "contradicts the scenario $scenario: its controller.type is emps-pd" \
  "${idim[@]}" --iv --reference qg --scenario "$scenario" --controller pid --kp 1e4
expect_fail "$scenario: plant.type: the axis plant moves linear (m, N), but the identification is rotary" \
  "${idim[@]}" --iv --reference qg --scenario "$scenario" --axis rotary
cat > "$tmp/velocity_loop.yaml" <<'YAML'
plant: {type: axis, M: 95}
friction: {law: coulomb, Fc: 20}
input: {type: constant, value: 0}
duration: 1
controller: {loop: velocity, Kp: 100}
YAML
expect_fail "$tmp/velocity_loop.yaml: controller.loop: a velocity loop" "${idim[@]}" --iv --reference qg --scenario "$tmp/velocity_loop.yaml"
expect_fail "--scenario describes the controller for IDIM-IV, but --iv is not given" "${idim[@]}" --scenario "$scenario"
