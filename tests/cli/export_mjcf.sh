#!/usr/bin/env bash
# frictionlab export MODEL.json --mjcf FILE.xml: the MuJoCo model of the axis, its values and what
# it leaves out (in the file, the text and --json); bad input is exit 2 naming the file, key or
# flag; a failed run leaves no output; the input is never overwritten. (tests/export/mujoco/
# loads the files in MuJoCo itself.)
source "$(dirname "$0")/lib.sh"

no_output() {
  [ ! -e "$1" ] || fail "$1 written by a failed run"
  ! ls "$(dirname "$1")" | grep -q '\.tmp-' || fail "temporary file left in $(dirname "$1")"
}

# A MODEL.json as `identify idim --json --terms` writes it: Stribeck terms, an offset, M.
cat > "$tmp/model.json" <<'EOF'
{"schema": 1, "status": "ok", "message": "", "method": "idim", "model": "stribeck", "axis": "linear",
 "law": {"law": "stribeck", "Fc": 1.25, "Fs": 1.5, "vs": 0.001, "Fv": 0.4},
 "parameters": {"M": {"value": 2.5, "std": 0.01, "unit": "kg"}, "offset": {"value": 0.3, "std": 0.01, "unit": "N"}}}
EOF
cat > "$tmp/rotary.json" <<'EOF'
{"schema": 1, "status": "ok", "message": "", "method": "idim", "model": "coulomb-viscous", "axis": "rotary",
 "law": {"law": "coulomb-viscous", "Fc": 0.5, "Fv": 0.02},
 "parameters": {"M": {"value": 0.8, "std": 0.01, "unit": "kg m^2"}}}
EOF

# 1. Happy path: the values at full precision, what is left out in the file, on stdout and in the JSON.
expect 0 "" export "$tmp/model.json" --mjcf "$tmp/axis.xml" --json "$tmp/axis.json"
grep -q 'type="slide" axis="1 0 0" frictionloss="1.25" damping="0.4" armature="0"' "$tmp/axis.xml" || fail "joint values"
grep -q 'mass="2.5"' "$tmp/axis.xml" || fail "the body's mass is not M"
grep -q '<motor name="drive" joint="axis"' "$tmp/axis.xml" || fail "no actuator"
grep -q 'timestep="0.002" integrator="Euler"' "$tmp/axis.xml" || fail "timestep and integrator not written"
for term in "Fs = 1.5 N" "vs = 0.001 m/s" "offset = 0.3 N"; do
  grep -qF "$term" "$tmp/axis.xml" || fail "the file's comment lacks '$term'"
  grep -qF "$term" "$tmp/out.txt" || fail "the output lacks '$term'"
done
grep -q "wrote $tmp/axis.xml (MJCF, slide joint): frictionloss = Fc = 1.25 N, damping = 0.4 N s/m, mass = 2.5 kg" "$tmp/out.txt" ||
  { cat "$tmp/out.txt"; fail "the summary line"; }
/usr/bin/python3 - "$tmp/axis.json" <<'PY' || fail "JSON"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["status"] == "ok" and j["method"] == "export" and j["axis"] == "linear", j
m = j["mjcf"]
assert m["joint"] == "slide" and m["frictionloss"] == {"value": 1.25, "unit": "N"}, m
assert m["damping"] == {"value": 0.4, "unit": "N s/m"} and m["body_mass"] == {"value": 2.5, "unit": "kg"}, m
names = [x["name"] for x in j["left_out"]]
assert names == ["Fs", "vs", "delta", "offset"], names
assert j["left_out"][0]["unit"] == "N" and j["left_out"][0]["value"] == 1.5 and j["left_out"][0]["reason"]
PY

# The command's own file loads in MuJoCo (its C library through ctypes; libmujoco-dev is installed by
# scripts/setup.sh, and tests/export/mujoco/ checks the values and the motion).
mujoco_loads() {
  /usr/bin/python3 - "$1" <<'PY'
import ctypes, sys
lib = ctypes.CDLL("libmujoco.so")
lib.mj_loadXML.restype = ctypes.c_void_p
lib.mj_loadXML.argtypes = [ctypes.c_char_p, ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int]
lib.mj_deleteModel.argtypes = [ctypes.c_void_p]
error = ctypes.create_string_buffer(1000)
m = lib.mj_loadXML(sys.argv[1].encode(), None, error, len(error))
assert m, error.value.decode()
lib.mj_deleteModel(m)
PY
}
mujoco_loads "$tmp/axis.xml" || fail "MuJoCo does not load the file"

# A rotary axis gives a hinge with the inertia about its axis, a share of it as armature; --json -
# prints the JSON on stdout and the text on stderr; --mjcf - prints the XML.
expect 0 "" export "$tmp/rotary.json" --mjcf "$tmp/hinge.xml" --armature 0.2 --timestep 0.001 --json -
grep -q 'type="hinge" axis="0 0 1" frictionloss="0.5" damping="0.02" armature="0.2"' "$tmp/hinge.xml" || fail "hinge"
grep -q 'diaginertia="0.6000000000000001 ' "$tmp/hinge.xml" || grep -q 'diaginertia="0.6 ' "$tmp/hinge.xml" || fail "hinge inertia"
grep -q 'timestep="0.001"' "$tmp/hinge.xml" || fail "--timestep"
mujoco_loads "$tmp/hinge.xml" || fail "MuJoCo does not load the hinge"
/usr/bin/python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); assert j["mjcf"]["joint"]=="hinge" and j["left_out"]==[], j' \
  "$tmp/out.txt" || fail "--json - on stdout"
grep -q "left out: nothing" "$tmp/err.txt" || fail "text on stderr with --json -"
expect 0 "" export "$tmp/rotary.json" --mjcf -
grep -q '^<mujoco model="frictionlab">' "$tmp/out.txt" || fail "--mjcf - prints the XML"
# A model without M takes --inertia.
printf '{"law": "coulomb", "Fc": 1}\n' > "$tmp/law.json"
expect 0 "" export "$tmp/law.json" --mjcf "$tmp/law.xml" --inertia 3
grep -q 'mass="3"' "$tmp/law.xml" || fail "--inertia"
grep -q "linear: the model names no axis" "$tmp/out.txt" || fail "no word about the default axis"

# --help names the option and its units.
"$exe" export --help > "$tmp/help.txt"
grep -q -- '--mjcf' "$tmp/help.txt" || fail "--help lacks --mjcf"
grep -q 'frictionloss = Fc' "$tmp/help.txt" || fail "--help lacks the mapping"

# 2. Bad input: exit 2, one line naming the problem; nothing written.
mkdir -p "$tmp/out"
out="$tmp/out/bad.xml"
printf '{"law": "viscous", "Fv": 0.4}\n' > "$tmp/viscous.json"
expect_fail "$tmp/viscous.json has no Fc (law viscous): --mjcf needs a Coulomb level" export "$tmp/viscous.json" --mjcf "$out" --inertia 1
no_output "$out"
expect_fail "$tmp/law.json has no parameters.M: --mjcf needs the axis' inertia (kg)" export "$tmp/law.json" --mjcf "$out"
printf '{"status": "ok", "law": {"law": "coulomb", "Fc": 1}, "parameters": {"M": {"value": -2}}}\n' > "$tmp/negm.json"
expect_fail "$tmp/negm.json: parameters.M = -2 must be > 0 (kg)" export "$tmp/negm.json" --mjcf "$out"
printf '{"law": "coulomb", "Fc": -1}\n' > "$tmp/negfc.json"
expect_fail "Fc = -1 must be >= 0" export "$tmp/negfc.json" --mjcf "$out" --inertia 1
expect_fail "--inertia = -1 must be > 0 (kg)" export "$tmp/law.json" --mjcf "$out" --inertia -1
expect_fail "--armature = 2.5 must be >= 0 and < the inertia M = 2.5 (kg)" export "$tmp/model.json" --mjcf "$out" --armature 2.5
expect_fail "--armature = -0.1 must be >= 0" export "$tmp/model.json" --mjcf "$out" --armature -0.1
expect_fail "--timestep = 0 must be > 0 (s)" export "$tmp/model.json" --mjcf "$out" --timestep 0
printf '{"law": "coulomb", "Fc": 1, "axis": "diagonal"}\n' > "$tmp/badaxis.json"
printf '{"status": "ok", "axis": "diagonal", "law": {"law": "coulomb", "Fc": 1}, "parameters": {"M": 1}}\n' > "$tmp/badaxis.json"
expect_fail "$tmp/badaxis.json: axis: expected \"linear\" or \"rotary\", got \"diagonal\"" export "$tmp/badaxis.json" --mjcf "$out"
expect_fail "--float is an option of --c, not of --mjcf" export "$tmp/model.json" --mjcf "$out" --float
expect_fail "--compensation is an option of --c, not of --mjcf" export "$tmp/model.json" --mjcf "$out" --compensation feedforward
expect_fail "--prefix is an option of --c, not of --mjcf" export "$tmp/model.json" --mjcf "$out" --prefix x
expect_fail "--armature is an option of --mjcf, not of --c" export "$tmp/model.json" --c "$tmp/out/x.h" --armature 0.1
expect_fail "--c excludes --mjcf" export "$tmp/model.json" --mjcf "$out" --c "$tmp/out/x.h"
expect_fail "--c FILE.h or --mjcf FILE.xml: missing" export "$tmp/model.json"
expect_fail "--mass" export "$tmp/model.json" --mjcf "$out" --mass 2
expect_fail "missing.json" export "$tmp/missing.json" --mjcf "$out"
no_output "$out"
[ ! -e "$tmp/out/x.h" ] || fail "x.h written by a failed run"

# A failed run with --json - still prints the error JSON, naming the file and key.
expect_fail "has no Fc" export "$tmp/viscous.json" --mjcf "$out" --inertia 1 --json -
/usr/bin/python3 -c 'import json,sys; e=json.load(open(sys.argv[1]))["error"]; assert e["code"]=="scenario.key_missing" and e["key"]=="Fc", e' \
  "$tmp/out.txt" || fail "error JSON"

# 3. The input is never overwritten, even with --overwrite; an existing output needs --overwrite.
cp "$tmp/model.json" "$tmp/model.keep"
expect_fail "--mjcf $tmp/model.json is the model file" export "$tmp/model.json" --mjcf "$tmp/model.json" --overwrite
expect_fail "--json $tmp/model.json is the model file" export "$tmp/model.json" --mjcf "$out" --json "$tmp/model.json" --overwrite
cmp -s "$tmp/model.json" "$tmp/model.keep" || fail "the model file was changed"
no_output "$out"
expect_fail "exists; pass --overwrite" export "$tmp/model.json" --mjcf "$tmp/axis.xml"
expect_fail "is also the --mjcf output" export "$tmp/model.json" --mjcf "$tmp/out/same.xml" --json "$tmp/out/same.xml"
expect 0 "" export "$tmp/rotary.json" --mjcf "$tmp/axis.xml" --overwrite
grep -q 'type="hinge"' "$tmp/axis.xml" || fail "--overwrite did not replace the file"
echo "ok"
