#!/usr/bin/env bash
# idim's std accounts for correlated residuals and the ordinary figure stays as std_ols; samples
# near standstill can be left out (--exclude-below), with the count reported; a negative or
# too large threshold is refused or reported, never numbers from nothing.
source "$(dirname "$0")/lib.sh"
emps="$src/data/emps/DATA_EMPS.mat"
idim=(identify idim "$emps" --time t --position qm --input vir --gain gtau)

expect 0 "" "${idim[@]}" --json "$tmp/all.json"
expect 0 "" "${idim[@]}" --exclude-below 0.01 --json "$tmp/moving.json"
/usr/bin/python3 - "$tmp/all.json" "$tmp/moving.json" <<'PY'
import json, sys
a, m = (json.load(open(f)) for f in sys.argv[1:3])
# std_ols: the recipe's figure (tests/identify/test_idim_emps.cpp, scipy); std is larger on EMPS,
# whose residual is correlated.
assert abs(a["parameters"]["Fc"]["std_ols"] - 0.10262646030169308) < 1e-6 * 0.1026, a["parameters"]["Fc"]
for name, p in a["parameters"].items():
    assert p["std"] > p["std_ols"], (name, p)
d = a["diagnostics"]
assert d["covariance"] == "newey-west-prewhitened" and d["covariance_bandwidth"] >= 1, d
assert "excluded_samples" not in d and "exclude_below" not in d
dm = m["diagnostics"]
assert dm["exclude_below"] == 0.01 and 0 < dm["excluded_samples"] < a["fit"]["samples"], dm
assert m["fit"]["samples"] == a["fit"]["samples"] - dm["excluded_samples"], (m["fit"], dm)
assert m["options"]["exclude-below"] == {"value": 0.01, "unit": "m/s", "given": True}, m["options"]["exclude-below"]
PY
expect_fail "exclude-below" "${idim[@]}" --exclude-below -1
# Above every speed: nothing is left; a status error naming the option (exit 2, no numbers).
expect 2 "exclude_below" "${idim[@]}" --exclude-below 10
