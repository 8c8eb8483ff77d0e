#!/usr/bin/env bash
# frictionlab identify idim on the bundled EMPS data: the published figures through the command
# line, the JSON contract of docs/contract.md, atomic output and the --overwrite rule.
source "$(dirname "$0")/lib.sh"
data="$src/data/emps"
cols=(--time t --position qm --input vir --gain gtau)

"$exe" identify idim "$data/DATA_EMPS.mat" "${cols[@]}" --validate "$data/DATA_EMPS_PULSES.mat" --json "$tmp/model.json" > "$tmp/out.txt"
grep -q "M      =      95.1007" "$tmp/out.txt" || { echo "FAIL: text table"; cat "$tmp/out.txt"; exit 1; }
/usr/bin/python3 - "$tmp/model.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["schema"] == 2 and j["status"] == "ok" and j["method"] == "idim", j
p = j["parameters"]
published = {"M": 95.1089, "Fv": 203.5034, "Fc": 20.3935, "offset": -3.1648}
for name, value in published.items():
    assert abs(p[name]["value"] - value) <= 0.005 * abs(value), (name, p[name])
assert p["M"]["unit"] == "kg" and p["Fv"]["unit"] == "N s/m" and p["Fc"]["unit"] == "N"
assert abs(j["fit"]["relative_error_percent"] - 4.08) <= 0.1, j["fit"]
assert abs(j["validation"]["relative_error_percent"] - 5.98) <= 0.1, j["validation"]
assert len(j["data"]["sha256"]) == 64 and j["data"]["file"].endswith("DATA_EMPS.mat")
assert j["law"] == {"law": "coulomb-viscous", "Fc": p["Fc"]["value"], "Fv": p["Fv"]["value"]}
assert abs(j["diagnostics"]["condition_number"] - 25.99) < 0.01
PY

# --json - : one JSON object on stdout, the text on stderr.
"$exe" identify idim "$data/DATA_EMPS.mat" "${cols[@]}" --terms inertia,asymmetric --json - 2> "$tmp/err.txt" > "$tmp/stdout.json"
/usr/bin/python3 -c "import json,sys; j=json.load(open('$tmp/stdout.json')); assert j['model']=='coulomb-viscous-asymmetric' and abs(j['parameters']['Fc_neg']['value']-20.6277)<0.005*20.6277, j"
grep -q "Fv_pos" "$tmp/err.txt"

# An existing output is not replaced without --overwrite (exit 2, file unchanged), and is with it.
before=$(sha256sum "$tmp/model.json")
set +e
"$exe" identify idim "$data/DATA_EMPS.mat" "${cols[@]}" --json "$tmp/model.json" 2> "$tmp/err.txt" > /dev/null
code=$?
set -e
[ "$code" -eq 2 ] || { echo "FAIL: overwrite without --overwrite: exit $code"; exit 1; }
grep -q "pass --overwrite" "$tmp/err.txt"
[ "$before" = "$(sha256sum "$tmp/model.json")" ] || { echo "FAIL: file changed"; exit 1; }
"$exe" identify idim "$data/DATA_EMPS.mat" "${cols[@]}" --terms inertia,asymmetric --json "$tmp/model.json" --overwrite > /dev/null
grep -q "Fc_pos" "$tmp/model.json"
ls "$tmp" | grep -q "tmp-" && { echo "FAIL: temporary file left"; exit 1; }
echo "identify_emps: ok"
