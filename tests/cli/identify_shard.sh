#!/usr/bin/env bash
# identify --shard K/N and merge: three shards of a folder merged (any order) equal the unsharded
# --table byte for byte, CSV and JSON, with --date-from; a shard whose files all failed (no
# parameter columns of its own) and an empty shard still merge to the unsharded table; merge
# --drift and --plot write the unsharded batch's drift table and figure (undated parts: exit 2); exit
# status rules as without --shard; merge names a missing, duplicated or foreign part; the options
# that make no sense with --shard are refused before any work.
source "$(dirname "$0")/lib.sh"

/usr/bin/python3 "$src/examples/fleet_logs.py" "$tmp/fleet" > /dev/null
sweep=(identify sweep --resample --model coulomb-viscous)

# The whole folder (8 good logs, 3 broken files): unsharded, then 3 shards of one thread each.
expect 0 "" "${sweep[@]}" "$tmp/fleet" --date-from name --table "$tmp/whole.csv"
expect 0 "" "${sweep[@]}" "$tmp/fleet" --date-from name --table "$tmp/whole.json"
for k in 1 2 3; do
  expect 0 "" "${sweep[@]}" "$tmp/fleet" --date-from name --jobs 1 --shard "$k/3" --table "$tmp/part$k.json"
done
expect 0 "" merge "$tmp/part3.json" "$tmp/part1.json" "$tmp/part2.json" -o "$tmp/merged.csv"
grep -q "merged 3 parts, 11 rows (identify)" "$tmp/out.txt" || { cat "$tmp/out.txt"; fail "merge summary"; }
cmp "$tmp/whole.csv" "$tmp/merged.csv" || fail "merged CSV differs from the unsharded table"
expect 0 "" merge "$tmp/part1.json" "$tmp/part2.json" "$tmp/part3.json" -o "$tmp/merged.json"
cmp "$tmp/whole.json" "$tmp/merged.json" || fail "merged JSON differs from the unsharded table"
# merge --drift and --plot: the unsharded batch's drift table and figure, byte for byte (both are
# computed from the table by one function, and drawn by one).
expect 0 "" "${sweep[@]}" "$tmp/fleet" --date-from name --table "$tmp/w.csv" --drift "$tmp/wd.csv" --drift-threshold 3 \
  --plot "$tmp/wd.svg"
expect 0 "" merge "$tmp/part2.json" "$tmp/part3.json" "$tmp/part1.json" -o "$tmp/md_table.csv" --drift "$tmp/md.csv" \
  --drift-threshold 3 --plot "$tmp/md.svg"
grep -qF "drift: 1 flagged (a change beyond 3 combined std)" "$tmp/out.txt" || { cat "$tmp/out.txt"; fail "merge drift summary"; }
cmp "$tmp/w.csv" "$tmp/md_table.csv" || fail "merged table with --drift differs"
cmp "$tmp/wd.csv" "$tmp/md.csv" || fail "merged drift table differs from the unsharded batch's"
cmp "$tmp/wd.svg" "$tmp/md.svg" || fail "merged drift figure differs from the unsharded batch's"
cmp "$tmp/wd.svg.dat" "$tmp/md.svg.dat" || fail "merged drift figure data differs from the unsharded batch's"
# Parts without dates have no figure and no drift: exit 2 saying so, nothing written.
for k in 1 2; do expect 0 "" "${sweep[@]}" "$tmp/fleet" --jobs 1 --shard "$k/2" --table "$tmp/u$k.json"; done
expect_fail "--plot: the rows carry no dates (identify ran without --date-from): a batch's drift table and figure" \
  merge "$tmp/u1.json" "$tmp/u2.json" -o "$tmp/u.csv" --plot "$tmp/u.svg"
grep -qF "so these rows have no figure and no drift" "$tmp/err.txt" || fail "no-figure message: $(cat "$tmp/err.txt")"
expect_fail "--drift: the rows carry no dates" merge "$tmp/u1.json" "$tmp/u2.json" -o "$tmp/u.csv" --drift "$tmp/ud.csv"
expect_fail "--scenario: the parts are of \`frictionlab identify\`, not of a map" \
  merge "$tmp/u1.json" "$tmp/u2.json" -o "$tmp/u.csv" --scenario "$src/examples/map_pid_hunting.yaml"
[ ! -e "$tmp/u.csv" ] && [ ! -e "$tmp/u.svg" ] && [ ! -e "$tmp/ud.csv" ] || fail "a refused merge wrote a file"
"$exe" "${sweep[@]}" "$tmp/fleet" --date-from name --jobs 1 --shard 2/3 --table "$tmp/p2.json" --overwrite 2> "$tmp/err.txt"
grep -qF "shard 2/3: 4 of 11 files: 3 ok, 1 failed; part $tmp/p2.json" "$tmp/err.txt" || { cat "$tmp/err.txt"; fail "shard summary"; }
# A part holds its own files' rows only, with their global index.
/usr/bin/python3 - "$tmp/part2.json" "$tmp/whole.json" <<'PY'
import json, sys
p, w = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert p["frictionlab_part"] == 1 and p["command"] == "identify" and p["shard"] == "2/3" and p["total"] == 11, p
assert [r[0] for r in p["rows"]] == [1, 4, 7, 10], [r[0] for r in p["rows"]]
assert w["kind"] == "identify" and w["columns"][:9] == ["index", "file", "date", "status", "message", "method", "model",
                                                       "axis", "Fc"], w["columns"]
assert [r["index"] for r in w["rows"]] == list(range(11)) and w["rows"][0]["samples"] == 10  # integers, not 1.0
assert w["rows"][10]["status"] == "error" and w["rows"][10]["Fc"] is None and w["rows"][10]["samples"] is None
PY

# Shards whose files all failed (no parameter columns of their own) and an empty shard: the
# parameter columns come from the other parts, in the unsharded order. Shard 1 of 3 gets the two
# good logs, shards 2 and 3 only broken files; exit 2 for those (every file failed), parts written.
f="$tmp/fleet"
mixed=("$f/axis3_2026-11-01.csv" "$f/axis3_2026-11-20_no_force.csv" "$f/axis3_2026-11-21_text.csv"
       "$f/axis3_2026-11-02.csv" "$f/axis3_2026-11-22_empty.csv" "$f/missing.csv")
expect 0 "" "${sweep[@]}" "${mixed[@]}" --table "$tmp/mixed.csv"
expect 0 "" "${sweep[@]}" "${mixed[@]}" --table "$tmp/mixed.json"
expect 0 "" "${sweep[@]}" "${mixed[@]}" --shard 1/3 --table "$tmp/m1.json"
expect_fail "every file failed (shard 2/3: 2 of 6 files; part $tmp/m2.json); the first: $f/axis3_2026-11-20_no_force.csv" \
  "${sweep[@]}" "${mixed[@]}" --shard 2/3 --table "$tmp/m2.json"
expect_fail "every file failed (shard 3/3: 2 of 6 files; part $tmp/m3.json)" \
  "${sweep[@]}" "${mixed[@]}" --shard 3/3 --table "$tmp/m3.json"
/usr/bin/python3 - "$tmp/m2.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))
assert "Fc" not in p["columns"] and p["grown"]["first"] == [], p["columns"]  # this shard alone has no parameters
PY
expect 0 "" merge "$tmp/m2.json" "$tmp/m3.json" "$tmp/m1.json" -o "$tmp/mm.csv"
cmp "$tmp/mixed.csv" "$tmp/mm.csv" || fail "merged CSV with all-failed shards differs from the unsharded table"
expect 0 "" merge "$tmp/m1.json" "$tmp/m2.json" "$tmp/m3.json" -o "$tmp/mm.json"
cmp "$tmp/mixed.json" "$tmp/mm.json" || fail "merged JSON with all-failed shards differs from the unsharded table"
# More shards than files: the shard without files writes an empty part and exits 0.
two=("$f/axis3_2026-11-01.csv" "$f/axis3_2026-11-02.csv")
expect 0 "" "${sweep[@]}" "${two[@]}" --table "$tmp/two.csv"
for k in 1 2 3; do expect 0 "" "${sweep[@]}" "${two[@]}" --shard "$k/3" --table "$tmp/e$k.json"; done
expect 0 "" merge "$tmp/e1.json" "$tmp/e2.json" "$tmp/e3.json" -o "$tmp/e.csv"
cmp "$tmp/two.csv" "$tmp/e.csv" || fail "merge with an empty shard differs from the unsharded table"

# merge names what does not make the whole run.
expect_fail "missing part: shard 2/3 was not given" merge "$tmp/part1.json" "$tmp/part3.json" -o "$tmp/x.csv"
expect_fail "p2.json: duplicated part: shard 2/3 is also $tmp/part2.json" \
  merge "$tmp/part1.json" "$tmp/part2.json" "$tmp/p2.json" "$tmp/part3.json" -o "$tmp/x.csv"
# Another option (the model), another file list, another date rule: another run's key.
expect 0 "" "${sweep[@]/coulomb-viscous/stribeck}" "$tmp/fleet" --date-from name --shard 2/3 --table "$tmp/model.json"
expect_fail "model.json: foreign part: its key differs from $tmp/part1.json's" \
  merge "$tmp/part1.json" "$tmp/model.json" "$tmp/part3.json" -o "$tmp/x.csv"
expect 0 "" "${sweep[@]}" "$tmp/fleet" --shard 2/3 --table "$tmp/nodate.json"
expect_fail "nodate.json: foreign part" merge "$tmp/part1.json" "$tmp/nodate.json" "$tmp/part3.json" -o "$tmp/x.csv"
expect 0 "" "${sweep[@]}" "$tmp"/fleet/axis3_2026-11-0?.csv --date-from name --shard 2/3 --table "$tmp/files.json"
expect_fail "files.json: foreign part" merge "$tmp/part1.json" "$tmp/files.json" "$tmp/part3.json" -o "$tmp/x.csv"
# The threads and the output options do not change the key.
expect 0 "" "${sweep[@]}" "$tmp/fleet" --date-from name --jobs 2 --shard 2/3 --table "$tmp/jobs2.json" --overwrite
expect 0 "" merge "$tmp/part1.json" "$tmp/jobs2.json" "$tmp/part3.json" -o "$tmp/j.csv"
cmp "$tmp/whole.csv" "$tmp/j.csv" || fail "--jobs 2 shard differs"
# A part of analyze map is another command.
"$exe" analyze map "$src/examples/map_pid_hunting.yaml" --vary friction.Fs=1:2:3 --shard 2/3 -o "$tmp/map2.json" > /dev/null
expect_fail "map2.json: foreign part: its command (analyze map against identify)" \
  merge "$tmp/part1.json" "$tmp/map2.json" "$tmp/part3.json" -o "$tmp/x.csv"
[ ! -e "$tmp/x.csv" ] || fail "a refused merge wrote its output"

# Refused before any work (exit 2, one line).
expect_fail "--shard 1/3 writes a part file: give --table PART.json" "${sweep[@]}" "$tmp/fleet" --shard 1/3
expect_fail "--shard 1/3 writes a part file: give --table PART.json" "${sweep[@]}" "$tmp/fleet" --shard 1/3 --table "$tmp/s.csv"
expect_fail "--shard '4/3': K = 4 must be <= N = 3" "${sweep[@]}" "$tmp/fleet" --shard 4/3 --table "$tmp/s.json"
expect_fail "--drift with --shard 1/3: the drift compares consecutive logs, so it needs every file's row; merge the parts with --drift" \
  "${sweep[@]}" "$tmp/fleet" --date-from name --shard 1/3 --table "$tmp/s.json" --drift "$tmp/d.csv"
expect_fail "--plot with --shard 1/3" "${sweep[@]}" "$tmp/fleet" --date-from name --shard 1/3 --table "$tmp/s.json" --plot "$tmp/d.svg"
[ ! -e "$tmp/s.json" ] && [ ! -e "$tmp/s.csv" ] && [ ! -e "$tmp/d.csv" ] || fail "a refused run wrote a file"
# One file with --shard is a batch of one (a part), not the single-file command.
expect 0 "" "${sweep[@]}" "$f/axis3_2026-11-01.csv" --shard 1/1 --table "$tmp/one.json"
expect 0 "" merge "$tmp/one.json" -o "$tmp/one.csv"
[ "$(wc -l < "$tmp/one.csv")" -eq 2 ] || fail "one file, one shard: a one-row table"

echo "identify shard: ok"
