#!/usr/bin/env bash
# Bad figure and report requests are refused before any work (exit 2, a one-line message naming
# the option and path): an unsupported --plot extension, an existing non-empty --report
# directory without --overwrite. A missing gnuplot names the Debian package that provides it.
# Usage: plot_bad_input.sh PATH_TO_frictionlab SOURCE_DIR
# shellcheck source=lib.sh
source "$(dirname "$0")/lib.sh"
emps="$src/data/emps/DATA_EMPS.mat"
idim=(identify idim "$emps" --time t --position qm --input vir --gain gtau)



# Unsupported extensions: refused before the data is read (a missing data file would be reported
# otherwise), and no figure, data or script file appears.
expect 2 "unsupported figure type '.jpg'" identify idim "$tmp/no-such-file.mat" --plot "$tmp/fig.jpg"
expect 2 "use .svg, .png or .pdf" "${idim[@]}" --plot "$tmp/fig.txt"
expect 2 "unsupported figure type" "${idim[@]}" --plot "$tmp/fig"
expect 2 "--plot" simulate "$tmp/no-such-scenario.yaml" --plot "$tmp/sim.gif"
expect 2 "--plot" analyze envelope "$tmp/no-such-data.csv" --plot "$tmp/env.jpeg"
ls "$tmp" | grep -q "fig\|sim\|env" && fail "a refused --plot left files: $(ls "$tmp")"

# A plot into a directory that does not exist: refused up front.
expect 2 "does not exist" "${idim[@]}" --plot "$tmp/nodir/fig.svg"

# A report directory that exists and is not empty: refused (before work) without --overwrite,
# and its contents are left alone.
mkdir "$tmp/report"
echo "keep me" > "$tmp/report/notes.txt"
expect 2 "not empty; pass --overwrite" identify idim "$tmp/no-such-file.mat" --report "$tmp/report"
expect 2 "--report" "${idim[@]}" --report "$tmp/report"
[ "$(ls "$tmp/report")" = "notes.txt" ] || fail "refused report directory was changed: $(ls "$tmp/report")"
# A report path that is a file is refused even with --overwrite.
echo x > "$tmp/afile"
expect 2 "not a directory" "${idim[@]}" --report "$tmp/afile" --overwrite
# With --overwrite the report is written next to the user's files, which stay.
"$exe" "${idim[@]}" --report "$tmp/report" --overwrite > /dev/null
[ -s "$tmp/report/report.html" ] || fail "--overwrite did not write report.html"
[ -f "$tmp/report/notes.txt" ] || fail "--overwrite removed a user file from the report directory"
# An empty existing directory is fine without --overwrite.
mkdir "$tmp/empty"
"$exe" "${idim[@]}" --report "$tmp/empty" > /dev/null
[ -s "$tmp/empty/report.html" ] || fail "report into an empty directory not written"

# gnuplot missing at run time: one line naming the Debian package, before any work; nothing written.
FRICTIONLAB_GNUPLOT="$tmp/no-gnuplot" expect 1 "install Debian package gnuplot-nox" "${idim[@]}" --plot "$tmp/g.svg"
FRICTIONLAB_GNUPLOT="$tmp/no-gnuplot" expect 1 "gnuplot-nox" "${idim[@]}" --report "$tmp/g-report"
env PATH=/nonexistent "$exe" "${idim[@]}" --plot "$tmp/g.svg" > /dev/null 2> "$tmp/err.txt" && fail "no gnuplot on PATH: succeeded"
grep -q "gnuplot not found: install Debian package gnuplot-nox" "$tmp/err.txt" || fail "no gnuplot on PATH: $(cat "$tmp/err.txt")"
[ ! -e "$tmp/g.svg" ] && [ ! -e "$tmp/g-report" ] || fail "missing gnuplot left output behind"

# Without a terminal on stderr, no progress line: stderr is empty on success with --json -.
"$exe" "${idim[@]}" --json - > /dev/null 2> "$tmp/err.txt"
! grep -q $'\r' "$tmp/err.txt" || fail "progress output on a non-terminal stderr"

echo "plot_bad_input: ok"
