#!/usr/bin/env bash
# IDIM-IV on the command line (docs/identify.md): EMPS in its PD loop converges near IDIM-LS with
# the IV diagnostics in the JSON; --iv without the controller or the reference, a reference column
# the file lacks, controller options without --iv, and an iteration that does not converge are
# exit status 2 with one line naming what to give.
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
