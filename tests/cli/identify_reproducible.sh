#!/usr/bin/env bash
# Reproducible results: MODEL.json records the frictionlab version and every option that shaped
# the result (from the method's option table: name, value, unit, given); the same inputs and
# options give byte-identical JSON however often they run, and whatever --jobs is (a batch).
source "$(dirname "$0")/lib.sh"
emps="$src/data/emps/DATA_EMPS.mat"
idim=(identify idim "$emps" --time t --position qm --input vir --gain gtau --terms inertia,asymmetric,stribeck --delay 1)

# The same run twice: the same bytes.
expect 0 "" "${idim[@]}" --json "$tmp/a.json"
expect 0 "" "${idim[@]}" --json "$tmp/b.json"
cmp "$tmp/a.json" "$tmp/b.json" || fail "idim: two runs of the same inputs differ"
version=$("$exe" --version | awk '{print $2}')
/usr/bin/python3 - "$tmp/a.json" "$version" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["frictionlab"]["version"] == sys.argv[2], j["frictionlab"]
o = j["options"]
# Every option of idim's table (sorted by name, as every JSON object), with the value that shaped the result.
assert list(o) == ["control-delay", "control-limit", "controller", "cutoff", "decimate", "delay", "delta",
                   "drive-gain", "exclude-below", "feedforward", "filter-order", "from", "iv", "iv-iterations",
                   "iv-tolerance", "kd", "ki", "kp", "kv", "load", "max-condition", "min-velocity", "padlen",
                   "reference", "ripple-harmonics", "ripple-period", "scenario", "skip", "skip-end", "temperature",
                   "temperature-ref", "terms", "validate", "vs"], list(o)
assert o["terms"] == {"value": ["inertia", "asymmetric", "stribeck"], "unit": "", "given": True}, o["terms"]
assert o["delay"] == {"value": 1, "unit": "samples", "given": True}, o["delay"]
assert o["vs"] == {"value": 0.01, "unit": "m/s", "given": False}, o["vs"]
assert o["exclude-below"] == {"value": 0, "unit": "m/s", "given": False}, o["exclude-below"]
# Taken from the sample rate: null here, the value used is in diagnostics.defaults.
assert o["cutoff"]["value"] is None and o["cutoff"]["given"] is False and o["cutoff"]["unit"] == "Hz", o["cutoff"]
assert j["diagnostics"]["defaults"]["cutoff_hz"] == 100, j["diagnostics"]["defaults"]
PY

# A LuGre fit (iterative, multi-start) on a simulated Table I axis with a given static part:
# twice, the same bytes; no run time in the JSON.
/usr/bin/python3 - "$tmp/lugre.yaml" "$tmp/static.json" <<'PY'
import json, math, sys
times = [0.0, 1.0, 2.0] + [round(2.0 + 0.02 * i, 6) for i in range(1, 101)]
values = [0.0, 1.425, 0.0] + [3.0 * math.sin(math.pi * (t - 2.0)) for t in times[3:]]
with open(sys.argv[1], "w") as f:
    f.write("plant:\n  type: axis\n  M: 1.0\n")
    f.write("friction:\n  law: lugre\n  sigma0: 1.0e5\n  sigma1: 316.22776601683796\n  sigma2: 0.4\n"
            "  Fc: 1.0\n  Fs: 1.5\n  vs: 0.001\n")
    f.write("input:\n  type: table\n  times: [%s]\n  values: [%s]\n" %
            (", ".join(repr(t) for t in times), ", ".join(repr(v) for v in values)))
    f.write("duration: 4\noutput_rate: 1000\n")
json.dump({"schema": 1, "status": "ok", "law": {"law": "stribeck", "Fc": 1.0, "Fs": 1.5, "vs": 0.001, "delta": 2.0,
                                                "Fv": 0.4}}, open(sys.argv[2], "w"))
PY
"$exe" simulate "$tmp/lugre.yaml" -o "$tmp/lugre.csv" > /dev/null
lugre=(identify lugre "$tmp/lugre.csv" --force applied --inertia 1 --static "$tmp/static.json" --max-iterations 10)
expect 0 "" "${lugre[@]}" --json "$tmp/l1.json"
expect 0 "" "${lugre[@]}" --json "$tmp/l2.json"
cmp "$tmp/l1.json" "$tmp/l2.json" || fail "lugre: two runs of the same inputs differ"
grep -q '"fit_seconds"' "$tmp/l1.json" && fail "lugre JSON holds a run time"
grep -q '"max-iterations": {' "$tmp/l1.json" || fail "lugre JSON lacks its options"

# A batch: --jobs 1 and --jobs 2 give the same table and the same bytes run after run.
/usr/bin/python3 "$src/examples/fleet_logs.py" "$tmp/fleet" > /dev/null
sweep=(identify sweep "$tmp/fleet" --resample --model coulomb-viscous --date-from name)
expect 0 "" "${sweep[@]}" --jobs 1 --table "$tmp/j1.json"
expect 0 "" "${sweep[@]}" --jobs 2 --table "$tmp/j2.json"
expect 0 "" "${sweep[@]}" --jobs 2 --table "$tmp/j2b.json"
cmp "$tmp/j1.json" "$tmp/j2.json" || fail "sweep batch: --jobs 1 and --jobs 2 differ"
cmp "$tmp/j2.json" "$tmp/j2b.json" || fail "sweep batch: two runs with --jobs 2 differ"
# One file of the batch alone, twice: the same MODEL.json bytes, its options recorded.
one=$(ls "$tmp/fleet"/*.csv | head -1)
expect 0 "" identify sweep "$one" --resample --model coulomb-viscous --json "$tmp/s1.json"
expect 0 "" identify sweep "$one" --resample --model coulomb-viscous --json "$tmp/s2.json"
cmp "$tmp/s1.json" "$tmp/s2.json" || fail "sweep: two runs of the same inputs differ"
/usr/bin/python3 - "$tmp/s1.json" <<'PY'
import json, sys
o = json.load(open(sys.argv[1]))["options"]
assert o["model"] == {"value": "coulomb-viscous", "unit": "", "given": True}, o["model"]
assert o["min-duration"] == {"value": 0.5, "unit": "s", "given": False}, o["min-duration"]
assert o["velocity-tolerance"]["unit"] == "m/s", o  # every method's default axis is linear
assert o["min-speed"]["value"] is None, o["min-speed"]  # computed from the data
PY

# analyze map runs on threads: --jobs 1 and 2 give the same bytes.
if "$exe" analyze map --help > /dev/null 2>&1; then
  scen="$src/examples/map_pid_hunting.yaml"
  expect 0 "" analyze map "$scen" --vary friction.Fs=1:2:3 --jobs 1 --json "$tmp/m1.json"
  expect 0 "" analyze map "$scen" --vary friction.Fs=1:2:3 --jobs 2 --json "$tmp/m2.json"
  cmp "$tmp/m1.json" "$tmp/m2.json" || fail "analyze map: --jobs 1 and --jobs 2 differ"
fi
echo "identify_reproducible: ok"
