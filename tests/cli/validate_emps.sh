#!/usr/bin/env bash
# frictionlab validate on the bundled EMPS data: identify idim --json, then the closed-loop
# validation of examples/emps_closed_loop.yaml on both files (JSON contract of docs/contract.md,
# published figures within the acceptance band), and bad input exiting 2 with a message that
# names the file or column.
source "$(dirname "$0")/lib.sh"
# shellcheck source=lib.sh
data="$src/data/emps"
scenario="$src/examples/emps_closed_loop.yaml"
cols=(--time t --position qm --input vir --gain gtau)

"$exe" identify idim "$data/DATA_EMPS.mat" "${cols[@]}" --json "$tmp/model.json" > /dev/null

# Identification file, JSON to a file; pulses file, JSON on stdout (text on stderr).
"$exe" validate "$tmp/model.json" "$data/DATA_EMPS.mat" --scenario "$scenario" "${cols[@]}" --json "$tmp/val.json" \
  --plot "$tmp/val.svg" --report "$tmp/report" > "$tmp/out.txt"
# The figure (measured versus simulated position, velocity, force) and the report come out.
grep -q "<svg" "$tmp/val.svg" && grep -q "position" "$tmp/val.svg" || { echo "FAIL: validate --plot"; exit 1; }
grep -q "relative error" "$tmp/report/report.html" && grep -q "<svg" "$tmp/report/report.html" || {
  echo "FAIL: validate --report"; exit 1; }
grep -q "velocity" "$tmp/out.txt" || { echo "FAIL: text"; cat "$tmp/out.txt"; exit 1; }
"$exe" validate "$tmp/model.json" "$data/DATA_EMPS_PULSES.mat" --scenario "$scenario" "${cols[@]}" --json - \
  2> "$tmp/err.txt" > "$tmp/val_pulses.json"
grep -q "acceleration" "$tmp/err.txt"
/usr/bin/python3 - "$tmp/val.json" "$tmp/val_pulses.json" <<'PY'
import json, sys
# published closed-loop errors (position, velocity, acceleration, force), %; position and
# velocity must be within 1.1 x published, acceleration and force within 3 x (loose check).
published = [(0.0138, 0.229, 8.60, 5.85), (0.0080, 0.479, 19.8, 8.94)]
for path, pub, name in zip(sys.argv[1:], published, ["DATA_EMPS.mat", "DATA_EMPS_PULSES.mat"]):
    j = json.load(open(path))
    assert j["schema"] == 2 and j["status"] == "ok" and j["method"] == "validate", j
    v = j["validation"]
    assert v["file"].endswith(name) and len(v["sha256"]) == 64, v
    e = v["relative_error_percent"]
    assert set(e) == {"position", "velocity", "acceleration", "force"}, e
    assert e["position"] <= 1.1 * pub[0] and e["velocity"] <= 1.1 * pub[1], (name, e)
    assert e["acceleration"] <= 3 * pub[2] and e["force"] <= 3 * pub[3], (name, e)
    assert j["data"]["file"].endswith("DATA_EMPS.mat"), j["data"]
    assert abs(j["parameters"]["M"]["value"] - 95.1) < 0.5, j["parameters"]
PY

# An existing output is not replaced without --overwrite.
set +e
"$exe" validate "$tmp/model.json" "$data/DATA_EMPS.mat" --scenario "$scenario" "${cols[@]}" --json "$tmp/val.json" 2> "$tmp/err.txt" > /dev/null
code=$?
set -e
[ "$code" -eq 2 ] && grep -q "pass --overwrite" "$tmp/err.txt" || { echo "FAIL: overwrite rule: exit $code"; exit 1; }

# Bad input: exit 2 and a message naming the file or column.
expect_fail "$tmp/missing.yaml" validate "$tmp/model.json" "$data/DATA_EMPS.mat" --scenario "$tmp/missing.yaml" "${cols[@]}"
/usr/bin/python3 -c "import json,sys; j=json.load(open('$tmp/model.json')); del j['law']; json.dump(j, open('$tmp/nolaw.json','w'))"
expect_fail "nolaw.json: no 'law'" validate "$tmp/nolaw.json" "$data/DATA_EMPS.mat" --scenario "$scenario" "${cols[@]}"
# A law with a load or a temperature effect needs those conditions; EMPS's scenario gives neither.
/usr/bin/python3 -c "import json; j=json.load(open('$tmp/model.json')); j['law']['mu_load'] = 0.01; json.dump(j, open('$tmp/loaded.json','w'))"
expect_fail "loaded.json: the law's load effect (mu_load) needs the load the measured run worked at" \
  validate "$tmp/loaded.json" "$data/DATA_EMPS.mat" --scenario "$scenario" "${cols[@]}"
/usr/bin/python3 -c "import json; j=json.load(open('$tmp/model.json')); j['law'].update(T_ref=30, Fv_per_K=-0.5); json.dump(j, open('$tmp/warm.json','w'))"
expect_fail "warm.json: the law's temperature effect (T_ref, Fv_per_K) needs the temperature" \
  validate "$tmp/warm.json" "$data/DATA_EMPS.mat" --scenario "$scenario" "${cols[@]}"
# A CSV without the reference column qg.
/usr/bin/python3 - "$data/DATA_EMPS.mat" "$tmp/noref.csv" <<'PY'
import sys, scipy.io as sio
d = sio.loadmat(sys.argv[1])
with open(sys.argv[2], "w") as f:
    f.write("t,qm,vir\n")
    for t, q, v in zip(d["t"].ravel()[:2000], d["qm"].ravel()[:2000], d["vir"].ravel()[:2000]):
        f.write(f"{t!r},{q!r},{v!r}\n")
PY
expect_fail "no column 'qg'" validate "$tmp/model.json" "$tmp/noref.csv" --scenario "$scenario" --time t --position qm --input vir --gain 35.15
echo "validate_emps: ok"
