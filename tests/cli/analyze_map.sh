#!/usr/bin/env bash
# frictionlab analyze map and merge: a 1-D PID hunting map classifies Fs = Fc as converged and
# stiction as hunting; three shards merged equal the unsharded CSV and JSON byte for byte, and
# merge --plot draws the figure the unsharded --plot draws, byte for byte (the scenario file found
# again, or given with --scenario, checked by its SHA-256); merge names a missing, duplicated or
# foreign part; --contact classifies another contact of a two-axis table (its own classes, its
# name in the table and JSON; an unknown one lists the contacts); unknown keys and bad grids exit
# 2 naming them.
source "$(dirname "$0")/lib.sh"
pid="$src/examples/map_pid_hunting.yaml"
vary=(--vary friction.Fs=1:2:3 --vary controller.Kp=3:4:2)  # 6 points

"$exe" analyze map "$pid" "${vary[@]}" --jobs 2 -o "$tmp/whole.csv" --json "$tmp/whole.json" --plot "$tmp/whole.svg" \
  > "$tmp/text.txt"
grep -q "transient: the first half of each run (120 s here) discarded" "$tmp/text.txt" || fail "no transient note: $(cat "$tmp/text.txt")"
grep -q "theory (pid-hunting)" "$tmp/text.txt" || fail "no theory line: $(cat "$tmp/text.txt")"
/usr/bin/python3 - "$tmp/whole.csv" "$tmp/whole.json" <<'PY'
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 6, rows
for r in rows:
    want = "converged" if float(r["friction.Fs"]) == 1.0 else "hunting"
    assert r["class"] == want, r
    assert r["theory"] == want, r
j = json.load(open(sys.argv[2]))
assert j["status"] == "ok" and j["method"] == "map", j
assert j["result"]["grid"] == ["friction.Fs=1:2:3", "controller.Kp=3:4:2"], j["result"]["grid"]
assert [r["class"] for r in j["result"]["rows"]] == [r["class"] for r in rows]
assert j["data"]["sha256"], j["data"]
PY

# Shards (one thread each, as separate array tasks would run), merged in any order.
for k in 1 2 3; do
  "$exe" analyze map "$pid" "${vary[@]}" --jobs 1 --shard "$k/3" -o "$tmp/part$k.json" > /dev/null
done
"$exe" merge "$tmp/part3.json" "$tmp/part1.json" "$tmp/part2.json" -o "$tmp/merged.csv" > /dev/null
cmp "$tmp/whole.csv" "$tmp/merged.csv" || fail "merged CSV differs from the unsharded run"
"$exe" merge "$tmp/part1.json" "$tmp/part2.json" "$tmp/part3.json" -o "$tmp/merged.json" > /dev/null
cmp "$tmp/whole.json" "$tmp/merged.json" || fail "merged JSON differs from the unsharded run"
# merge --plot draws the merged map with analyze map's own figure code: the same figure and data.
expect 0 "" merge "$tmp/part2.json" "$tmp/part3.json" "$tmp/part1.json" -o "$tmp/merged2.csv" --plot "$tmp/merged.svg"
grep -qF "merged 3 parts, 6 rows (analyze map) -> $tmp/merged2.csv; figure $tmp/merged.svg" "$tmp/out.txt" ||
  fail "merge --plot summary: $(cat "$tmp/out.txt")"
cmp "$tmp/whole.svg" "$tmp/merged.svg" || fail "merged map figure differs from the unsharded run's"
cmp "$tmp/whole.svg.dat" "$tmp/merged.svg.dat" || fail "merged map figure data differs from the unsharded run's"
grep -q "<svg" "$tmp/merged.svg" && grep -q "hunting" "$tmp/merged.svg.dat" || fail "merged figure lacks the classes"

# merge refuses what does not make the whole run, naming the part.
expect_fail "missing part: shard 2/3 was not given" merge "$tmp/part1.json" "$tmp/part3.json" -o "$tmp/m.csv"
expect_fail "part2b.json: duplicated part: shard 2/3 is also" merge "$tmp/part1.json" "$tmp/part2.json" \
  "$tmp/part3.json" "$(cp "$tmp/part2.json" "$tmp/part2b.json"; echo "$tmp/part2b.json")" -o "$tmp/m.csv"
"$exe" analyze map "$pid" --vary friction.Fs=1:2:4 --vary controller.Kp=3:4:2 --shard 2/3 -o "$tmp/other.json" > /dev/null
expect_fail "other.json: foreign part: its key differs" merge "$tmp/part1.json" "$tmp/other.json" "$tmp/part3.json" -o "$tmp/m.csv"
expect_fail "not a frictionlab part file" merge "$tmp/whole.json" -o "$tmp/m.csv"
expect_fail "-o $tmp/m.txt: expected a .csv or .json file" merge "$tmp/part1.json" -o "$tmp/m.txt"
expect_fail "$tmp/merged.csv" merge "$tmp/part1.json" "$tmp/part2.json" "$tmp/part3.json" -o "$tmp/merged.csv"
[ ! -e "$tmp/m.csv" ] || fail "a failed merge left $tmp/m.csv"

# The figure needs the scenario (the theory boundary): a part's path that does not resolve here is
# named, --scenario gives the file, and a different file (edited since) is refused by its SHA-256.
cp "$pid" "$tmp/moved.yaml"
for k in 1 2; do
  "$exe" analyze map "$tmp/moved.yaml" --vary friction.Fs=1:2:3 --jobs 1 --shard "$k/2" -o "$tmp/mv$k.json" > /dev/null
done
"$exe" analyze map "$tmp/moved.yaml" --vary friction.Fs=1:2:3 --jobs 1 -o "$tmp/mv.csv" --plot "$tmp/mv.svg" > /dev/null
mv "$tmp/moved.yaml" "$tmp/elsewhere.yaml"
expect_fail "--plot: the map's scenario $tmp/moved.yaml is not a file here" \
  merge "$tmp/mv1.json" "$tmp/mv2.json" -o "$tmp/m.csv" --plot "$tmp/m.svg"
[ ! -e "$tmp/m.csv" ] && [ ! -e "$tmp/m.svg" ] || fail "a refused merge --plot left outputs"
expect 0 "" merge "$tmp/mv1.json" "$tmp/mv2.json" -o "$tmp/m1d.csv" --plot "$tmp/m1d.svg" --scenario "$tmp/elsewhere.yaml"
cmp "$tmp/mv.svg" "$tmp/m1d.svg" || fail "1-D merged map figure differs from the unsharded run's"
cmp "$tmp/mv.csv" "$tmp/m1d.csv" || fail "1-D merged table differs from the unsharded run's"
echo "# edited" >> "$tmp/elsewhere.yaml"
expect_fail "--plot: the scenario $tmp/elsewhere.yaml (--scenario) is not the file the map ran on" \
  merge "$tmp/mv1.json" "$tmp/mv2.json" -o "$tmp/m.csv" --plot "$tmp/m.svg" --scenario "$tmp/elsewhere.yaml"
expect_fail "--drift: the parts are of \`frictionlab analyze map\`, not of a batch identification" \
  merge "$tmp/mv1.json" "$tmp/mv2.json" -o "$tmp/m.csv" --drift "$tmp/d.csv"
# Hostile parts: an envelope edited alike in every part (so merge accepts them) is named, not a
# crash; a map of three keys has no figure.
/usr/bin/python3 - "$tmp/mv1.json" "$tmp/mv2.json" "$tmp" <<'PY'
import json, sys
for k, path in enumerate(sys.argv[1:3], 1):
    j = json.load(open(path))
    del j["envelope"]["result"]["grid"]
    json.dump(j, open(f"{sys.argv[3]}/ed{k}.json", "w"))
PY
expect_fail "--plot: the parts' envelope is not a map run's (result.scenario, result.grid" \
  merge "$tmp/ed1.json" "$tmp/ed2.json" -o "$tmp/m.csv" --plot "$tmp/m.svg"
sb3=(--vary plant.V0=0.01:0.1:2 --vary plant.c=1:2:2 --vary plant.k=10:20:2)
for k in 1 2; do
  "$exe" analyze map "$src/examples/map_spring_block.yaml" "${sb3[@]}" --shard "$k/2" -o "$tmp/k3_$k.json" > /dev/null
done
expect_fail "--plot draws 1-D and 2-D maps; this one varies 3 keys" \
  merge "$tmp/k3_1.json" "$tmp/k3_2.json" -o "$tmp/m.csv" --plot "$tmp/m.svg"
[ ! -e "$tmp/m.csv" ] && [ ! -e "$tmp/m.svg" ] || fail "a refused merge left outputs"

# A two-contact plant (an xy-table, examples/map_xy_traverse.yaml): x traverses at 20 mm/s, y holds
# its place. The map classifies
# the first contact by default, --contact NAME|INDEX another; the name is in the table and JSON.
traverse="$src/examples/map_xy_traverse.yaml"
xyvary=(--vary plant.axes.x.mass=10:20:2)
"$exe" analyze map "$traverse" "${xyvary[@]}" -o "$tmp/x.csv" > /dev/null
"$exe" analyze map "$traverse" "${xyvary[@]}" --contact y -o "$tmp/y.csv" --json "$tmp/y.json" --plot "$tmp/y.svg" \
  > "$tmp/y.txt"
grep -q "map_xy_traverse.yaml, contact y" "$tmp/y.svg" || fail "the figure's title does not name the contact"
"$exe" analyze map "$traverse" "${xyvary[@]}" --contact 1 -o "$tmp/y1.csv" > /dev/null
cmp "$tmp/y.csv" "$tmp/y1.csv" || fail "--contact 1 and --contact y differ"
grep -q "contact y (index 1)" "$tmp/y.txt" || fail "text does not name the contact: $(cat "$tmp/y.txt")"
/usr/bin/python3 - "$tmp/x.csv" "$tmp/y.csv" "$tmp/y.json" <<'PY'
import csv, json, sys
x = list(csv.DictReader(open(sys.argv[1])))
y = list(csv.DictReader(open(sys.argv[2])))
assert [r["class"] for r in x] == ["steady-sliding"] * 2, x
assert [r["class"] for r in y] == ["converged"] * 2, y
assert [r["contact"] for r in x] == ["x", "x"] and [r["contact"] for r in y] == ["y", "y"], (x, y)
assert abs(float(x[0]["mean_velocity"]) - 0.02) < 0.01 * 0.02, x[0]  # the path's feed, 1 %: a ramp's lag is constant
assert float(y[0]["mean_velocity"]) == 0.0, y[0]
j = json.load(open(sys.argv[3]))
assert j["result"]["contact"] == {"index": 1, "name": "y"}, j["result"]["contact"]
PY
expect_fail "--contact 'z': the xy-table plant has no such contact; its 2 contacts: 0 x, 1 y" \
  analyze map "$traverse" "${xyvary[@]}" --contact z
expect_fail "--contact '2': the xy-table plant has no such contact" analyze map "$traverse" "${xyvary[@]}" --contact 2
expect_fail "--contact 'x': the axis plant has no such contact; its contact: 0 (unnamed)" \
  analyze map "$pid" --vary friction.Fs=1:2:2 --contact x
# Parts of another contact are another run's.
"$exe" analyze map "$traverse" "${xyvary[@]}" --contact y --shard 1/2 -o "$tmp/cy1.json" > /dev/null
"$exe" analyze map "$traverse" "${xyvary[@]}" --shard 2/2 -o "$tmp/cx2.json" > /dev/null
expect_fail "cx2.json: foreign part: its key differs" merge "$tmp/cy1.json" "$tmp/cx2.json" -o "$tmp/m.csv"

# Bad keys and grids: exit 2 naming them, before anything is simulated.
expect_fail "--vary friction.Fx: the scenario does not give it, and as a new field" \
  analyze map "$pid" --vary friction.Fx=1:2:2
expect_fail "--vary plant.spring.k: the scenario has no 'spring' under plant (it has type, M)" \
  analyze map "$pid" --vary plant.spring.k=1:2:2
expect_fail "--vary controller: names a section, not a number" analyze map "$pid" --vary controller=1:2:2
expect_fail "--vary description: the scenario gives 'PID position loop hunting on Coulomb + static friction' there, not a number" \
  analyze map "$pid" --vary description=1:2:2
expect_fail "--vary 'friction.Fs=1:2': expected START:STOP:N" analyze map "$pid" --vary friction.Fs=1:2
expect_fail "map: no --vary given" analyze map "$pid"
expect_fail "with friction.Fs=0.5: friction" analyze map "$pid" --vary friction.Fs=0.5:1:2
expect_fail "--shard '4/3': K = 4 must be <= N = 3" analyze map "$pid" --vary friction.Fs=1:2:2 --shard 4/3 -o "$tmp/p.json"
expect_fail "--shard 1/2 needs -o PART" analyze map "$pid" --vary friction.Fs=1:2:2 --shard 1/2
expect_fail "--shard writes a part file only" analyze map "$pid" --vary friction.Fs=1:2:2 --shard 1/2 -o "$tmp/p.json" --json -
expect_fail "-o $tmp/t.txt: expected a .csv or .json file" analyze map "$pid" --vary friction.Fs=1:2:2 -o "$tmp/t.txt"
expect_fail "--vary, --shard, --contact and -o belong to analyze map" analyze stick-slip "$tmp/whole.csv" -o "$tmp/x.csv"

# A 2-D spring-block map: both classes on either side of the drawn linear stability boundary.
"$exe" analyze map "$src/examples/map_spring_block.yaml" --vary plant.V0=log:0.005:0.1:4 --vary plant.c=2:6:2 \
  -o "$tmp/sb.csv" --plot "$tmp/sb.svg" > "$tmp/sb.txt"
[ -s "$tmp/sb.svg" ] || fail "no figure"
grep -q "linear stability boundary" "$tmp/sb.svg.dat" || fail "no boundary in the figure's data"
grep -q "stick-slip" "$tmp/sb.csv" && grep -q "steady-sliding" "$tmp/sb.csv" || fail "both classes expected: $(cat "$tmp/sb.csv")"
grep -q "agrees with the simulation at" "$tmp/sb.txt" || fail "no agreement line: $(cat "$tmp/sb.txt")"
expect_fail "--plot draws 1-D and 2-D maps; this one varies 3 keys" analyze map "$src/examples/map_spring_block.yaml" \
  --vary plant.V0=0.01:0.1:2 --vary plant.c=1:2:2 --vary plant.k=10:20:2 --plot "$tmp/x.svg"

# --json - prints the error JSON on a failure and the result on success.
"$exe" analyze map "$pid" --vary friction.Fs=1.5:1.5:1 --json - 2> /dev/null | /usr/bin/python3 -c '
import json, sys
j = json.loads(sys.stdin.read())
assert j["result"]["rows"][0]["class"] == "hunting", j'
set +e
"$exe" analyze map "$pid" --vary friction.Fx=1:2:2 --json - 2> /dev/null > "$tmp/err.json"
code=$?
set -e
[ "$code" -eq 2 ] || fail "unknown key with --json -: exit $code"
/usr/bin/python3 -c '
import json, sys
j = json.load(open(sys.argv[1]))
assert j["status"] == "error" and j["method"] == "map" and "friction.Fx" in j["message"], j' "$tmp/err.json"
echo "ok"
