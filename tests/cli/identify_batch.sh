#!/usr/bin/env bash
# identify with several files or a folder: one row per file (CSV or JSON table), failures in
# their rows, the same rows on 1 and 2 --jobs, exit 2 only when every file failed; --date-from
# name with the drift table (the wear step flagged) and figure; one file keeps its own output;
# batch options refused where they make no sense.
source "$(dirname "$0")/lib.sh"

/usr/bin/python3 "$src/examples/fleet_logs.py" "$tmp/fleet" > /dev/null
sweep=(identify sweep --resample --model coulomb-viscous --axis rotary)

# A folder: 8 good logs and 3 broken files, one row each, in name order; exit 0 (some ok).
expect 0 "" "${sweep[@]}" "$tmp/fleet" --table "$tmp/t1.csv" --jobs 1
grep -q "11 files: 8 ok, 3 failed; table $tmp/t1.csv" "$tmp/err.txt" || { cat "$tmp/err.txt"; fail "summary line"; }
expect 0 "" "${sweep[@]}" "$tmp/fleet" --table "$tmp/t2.csv" --jobs 2
cmp "$tmp/t1.csv" "$tmp/t2.csv" || fail "--jobs 2 rows differ from --jobs 1"

/usr/bin/python3 - "$tmp/t1.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 11, len(rows)
assert [r["index"] for r in rows] == [str(k) for k in range(11)]
head = list(rows[0])[:8]
assert head == ["index", "file", "status", "message", "method", "model", "axis", "Fc"], head
for r in rows[:8]:
    assert r["status"] == "ok", r
    Fc = 0.13 if r["file"].endswith(("06.csv", "07.csv", "08.csv")) else 0.10
    # Within 3 % (the Python batch test's tolerance: ten levels average the noise).
    assert abs(float(r["Fc"]) / Fc - 1) < 0.03, r
    assert r["Fc_unit"] == "N m" and float(r["Fc_std"]) > 0 and r["samples"] == "10"
bad = {r["file"].rsplit("/", 1)[1]: r for r in rows[8:]}
assert all(r["status"] == "error" and r["Fc"] == "" and r["method"] == "sweep" for r in bad.values())
assert "force" in bad["axis3_2026-11-20_no_force.csv"]["message"]
assert "axis3_2026-11-21_text.csv" in bad["axis3_2026-11-21_text.csv"]["message"]
assert "empty" in bad["axis3_2026-11-22_empty.csv"]["message"]
PY

# MAT files (matio and HDF5 read one at a time) on two threads: the rows of one thread.
idim=(identify idim --time t --position qm --input vir --gain gtau)
for jobs in 1 2; do
  expect 0 "" "${idim[@]}" "$src"/data/emps/DATA_EMPS.mat "$src"/data/emps/DATA_EMPS_PULSES.mat "$src"/data/emps/DATA_EMPS.mat \
    --jobs $jobs --table "$tmp/emps$jobs.csv"
done
cmp "$tmp/emps1.csv" "$tmp/emps2.csv" || fail "MAT files: --jobs 2 rows differ from --jobs 1"
[ "$(grep -c ',ok,' "$tmp/emps1.csv")" -eq 3 ] || fail "three EMPS rows"

# JSON by the extension; several files in the order given; --date-from name; the drift table and figure.
expect 0 "" "${sweep[@]}" "$tmp"/fleet/axis3_2026-11-0?.csv --table "$tmp/t.json" --date-from name \
  --drift "$tmp/drift.csv" --drift-threshold 3 --plot "$tmp/drift.svg"
grep -qF "drift: 1 flagged (a change beyond 3 combined std)" "$tmp/err.txt" || { cat "$tmp/err.txt"; fail "drift summary"; }
[ -s "$tmp/drift.svg" ] && [ -s "$tmp/drift.svg.dat" ] || fail "no drift figure"
# The title counts the 8 logs, not the 16 rows (2 parameters each), as fl.plot.drift does.
grep -q "over 8 logs" "$tmp/drift.svg.gp" || fail "drift figure title does not count 8 logs"
/usr/bin/python3 - "$tmp/t.json" "$tmp/drift.csv" <<'PY'
import csv, json, sys
t = json.load(open(sys.argv[1]))
assert t["schema"] == 1 and t["kind"] == "identify" and t["columns"][2] == "date"
assert [r["date"] for r in t["rows"]] == [f"2026-11-{k:02d}" for k in range(1, 9)]
d = list(csv.DictReader(open(sys.argv[2])))
flagged = [(r["parameter"], r["date"]) for r in d if r["flagged"] == "true"]
assert flagged == [("Fc", "2026-11-06")], flagged
PY

# stdout without --table; the same table as --table - .
expect 0 "" "${sweep[@]}" "$tmp"/fleet/axis3_2026-11-01.csv "$tmp"/fleet/axis3_2026-11-02.csv
head -1 "$tmp/out.txt" | grep -q "^index,file,status," || fail "table on stdout"
[ "$(wc -l < "$tmp/out.txt")" -eq 3 ] || fail "two rows on stdout"

# Every file failed: exit 2, the table still written with the reasons.
expect_fail "every file failed (3 files; table $tmp/bad.csv); the first: $tmp/fleet/axis3_2026-11-20_no_force.csv" \
  "${sweep[@]}" "$tmp"/fleet/axis3_2026-11-2*.csv --table "$tmp/bad.csv"
[ "$(grep -c ',error,' "$tmp/bad.csv")" -eq 3 ] || fail "three error rows"

# One file: the single-file command as before (result text, no table).
expect 0 "" "${sweep[@]}" "$tmp/fleet/axis3_2026-11-01.csv"
grep -q "^frictionlab identify sweep: $tmp/fleet/axis3_2026-11-01.csv" "$tmp/out.txt" || { cat "$tmp/out.txt"; fail "one-file text"; }
# One file with --table: a one-row table.
expect 0 "" "${sweep[@]}" "$tmp/fleet/axis3_2026-11-01.csv" --table -
[ "$(wc -l < "$tmp/out.txt")" -eq 2 ] || fail "one-row table"

# Refused before any work (exit 2, one line naming the option).
expect_fail "--json writes one file's result" "${sweep[@]}" "$tmp/fleet" --json "$tmp/x.json"
expect_fail "--report is for one file" "${sweep[@]}" "$tmp/fleet" --report "$tmp/rep"
expect_fail "--drift needs --date-from" "${sweep[@]}" "$tmp/fleet" --drift "$tmp/d.csv"
expect_fail "--plot with several files draws the drift figure" "${sweep[@]}" "$tmp/fleet" --plot "$tmp/d.svg"
expect_fail "--date-from 'day': expected name or column:NAME" "${sweep[@]}" "$tmp/fleet" --date-from day
expect_fail "--table $tmp/t1.csv exists" "${sweep[@]}" "$tmp/fleet" --table "$tmp/t1.csv"
mkdir "$tmp/none"
expect_fail "folder has no .csv or .mat file" "${sweep[@]}" "$tmp/none"
expect_fail "--jobs" "${sweep[@]}" "$tmp/fleet" --jobs 0
[ ! -e "$tmp/x.json" ] && [ ! -e "$tmp/d.csv" ] || fail "a refused run wrote a file"

# A log without a date in its name is its row's error with --date-from name.
cp "$tmp/fleet/axis3_2026-11-01.csv" "$tmp/nodate.csv"
expect 0 "" "${sweep[@]}" "$tmp/nodate.csv" "$tmp/fleet/axis3_2026-11-02.csv" --date-from name --table "$tmp/nd.csv"
grep -q "nodate.csv: no date in the file's name" "$tmp/nd.csv" || fail "no-date row"

# --date-from column:NAME: POSIX time in the first sample (here the logger's time column + an epoch).
/usr/bin/python3 - "$tmp" <<'PY'
import sys
src, out = f"{sys.argv[1]}/fleet/axis3_2026-11-01.csv", f"{sys.argv[1]}/stamped.csv"
lines = open(src).read().splitlines()
with open(out, "w") as f:
    f.write(lines[0] + ",stamp\n")
    for line in lines[1:]:
        f.write(f"{line},{1793577600 + float(line.split(',')[0]):.3f}\n")
PY
expect 0 "" "${sweep[@]}" "$tmp/stamped.csv" --date-from column:stamp --table "$tmp/st.csv"
grep -q ",2026-11-02T00:16:40," "$tmp/st.csv" || { cat "$tmp/st.csv"; fail "date from column"; }
echo "identify batch: ok"
