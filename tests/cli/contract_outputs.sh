#!/usr/bin/env bash
# Output files on bad paths (docs/guarantees.md): every output path is checked before any work;
# a directory is refused naming the option (exit 2); two outputs that are one file are refused;
# a run that fails on its second output has not written its first; a device node or FIFO is
# written through (as `cat >` would), never replaced by a regular file, with or without
# --overwrite. /dev/null itself is not used (as root a regression would replace it): a private
# character device (mknod, when root) and a FIFO stand in for it.
# Usage: contract_outputs.sh PATH_TO_frictionlab SOURCE_DIR
source "$(dirname "$0")/lib.sh"
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2> /dev/null || true; done
  rm -rf "$tmp"
}
trap cleanup EXIT
# shellcheck source=lib.sh
. "$(dirname "$0")/lib.sh"
emps="$src/data/emps/DATA_EMPS.mat"
scenario="$src/examples/craig_pendulum_coulomb.yaml"
idim=(identify idim "$emps" --time t --position qm --input vir --gain gtau)



# An output path that is a directory: exit 2 naming the option, with or without --overwrite.
mkdir "$tmp/dir"
expect 2 "-o $tmp/dir is a directory" simulate "$scenario" -o "$tmp/dir"
expect 2 "-o $tmp/dir is a directory" simulate "$scenario" -o "$tmp/dir" --overwrite
expect 2 "--json $tmp/dir is a directory" "${idim[@]}" --json "$tmp/dir"
expect 2 "--json $tmp/dir is a directory" "${idim[@]}" --json "$tmp/dir" --overwrite
expect 2 "--json $tmp/dir is a directory" analyze envelope "$tmp/no-such.csv" --json "$tmp/dir"
mkdir "$tmp/fig.svg"
expect 2 "--plot $tmp/fig.svg is a directory" "${idim[@]}" --plot "$tmp/fig.svg" --overwrite
[ -d "$tmp/dir" ] && [ -z "$(ls "$tmp/dir")" ] && [ -d "$tmp/fig.svg" ] || fail "a refused directory was changed"

# A run that fails on its second output writes nothing: --plot exists (checked before work),
# two outputs that are one file, a figure that gnuplot fails to draw (drawn before the JSON).
touch "$tmp/exists.svg"
expect 2 "exists.svg exists" "${idim[@]}" --json "$tmp/a.json" --plot "$tmp/exists.svg"
[ ! -e "$tmp/a.json" ] || fail "--json written although --plot was refused"
expect 2 "is also the" "${idim[@]}" --json "$tmp/same.svg" --plot "$tmp/same.svg"
expect 2 "is also the" "${idim[@]}" --json "$tmp/same.svg.dat" --plot "$tmp/same.svg"
expect 2 "is also the" analyze envelope "$tmp/no-such.csv" --json "$tmp/same.svg.gp" --plot "$tmp/same.svg"
expect 2 "is also the" simulate "$scenario" -o "$tmp/same.svg" --plot "$tmp/same.svg"
ls "$tmp" | grep -q "^same" && fail "refused duplicate outputs left files: $(ls "$tmp")"
printf '#!/bin/sh\necho "gnuplot: broken on purpose" >&2\nexit 3\n' > "$tmp/bad-gnuplot"
chmod +x "$tmp/bad-gnuplot"
set +e
FRICTIONLAB_GNUPLOT="$tmp/bad-gnuplot" "$exe" "${idim[@]}" --json "$tmp/b.json" --plot "$tmp/b.svg" > /dev/null 2> "$tmp/err.txt"
code=$?
set -e
[ "$code" -eq 1 ] || fail "failing gnuplot: exit $code, expected 1"
[ ! -e "$tmp/b.svg" ] || fail "failing gnuplot left a figure"
[ ! -e "$tmp/b.json" ] || fail "--json written although the figure failed: $(cat "$tmp/b.json")"

# Devices and FIFOs are written through, never replaced.
if [ "$(id -u)" -eq 0 ] && mknod "$tmp/null" c 1 3 2> /dev/null; then
  for extra in "" "--overwrite"; do
    "$exe" simulate "$scenario" -o "$tmp/null" $extra > /dev/null 2>&1 || fail "simulate -o char device $extra failed"
    [ -c "$tmp/null" ] || fail "simulate -o $extra replaced the character device by a regular file"
    "$exe" "${idim[@]}" --json "$tmp/null" $extra > /dev/null 2>&1 || fail "--json char device $extra failed"
    [ -c "$tmp/null" ] || fail "--json $extra replaced the character device"
  done
else
  echo "note: not root or mknod refused: the character device case is skipped (the FIFO case runs)"
fi
read_fifo() {  # FIFO OUT: a reader in the background
  cat "$1" > "$2" &
  pids+=($!)
}
mkfifo "$tmp/fifo"
for extra in "" "--overwrite"; do
  read_fifo "$tmp/fifo" "$tmp/fifo.csv"
  timeout 120 "$exe" simulate "$scenario" -o "$tmp/fifo" $extra > /dev/null 2> "$tmp/err.txt" \
    || { cat "$tmp/err.txt"; fail "simulate -o FIFO $extra failed"; }
  wait "${pids[-1]}"
  [ -p "$tmp/fifo" ] || fail "simulate -o $extra replaced the FIFO"
  head -1 "$tmp/fifo.csv" | grep -q '^time,position,velocity' || fail "the CSV did not go through the FIFO"
  read_fifo "$tmp/fifo" "$tmp/fifo.json"
  timeout 120 "$exe" "${idim[@]}" --json "$tmp/fifo" $extra > /dev/null 2> "$tmp/err.txt" \
    || { cat "$tmp/err.txt"; fail "--json FIFO $extra failed"; }
  wait "${pids[-1]}"
  [ -p "$tmp/fifo" ] || fail "--json $extra replaced the FIFO"
  /usr/bin/python3 -c "import json,sys; assert json.load(open(sys.argv[1]))['status']=='ok'" "$tmp/fifo.json" \
    || fail "the JSON did not go through the FIFO"
done
# This process's stdout by name: appended to (after the table), the link untouched.
"$exe" "${idim[@]}" --json /dev/stdout > "$tmp/stdout.txt" 2> /dev/null || fail "--json /dev/stdout failed"
[ -L /dev/stdout ] || [ -c /dev/stdout ] || fail "/dev/stdout was replaced"
grep -q '"status": "ok"' "$tmp/stdout.txt" || fail "--json /dev/stdout: no JSON in $(cat "$tmp/stdout.txt")"
grep -q 'relative error' "$tmp/stdout.txt" || fail "--json /dev/stdout: the table was lost"

# A regular file is still replaced atomically with --overwrite, and refused without.
echo old > "$tmp/model.json"
expect 2 "exists; pass --overwrite" "${idim[@]}" --json "$tmp/model.json"
[ "$(cat "$tmp/model.json")" = old ] || fail "refused --json changed the file"
"$exe" "${idim[@]}" --json "$tmp/model.json" --overwrite > /dev/null 2>&1 || fail "--overwrite failed"
grep -q '"status": "ok"' "$tmp/model.json" || fail "--overwrite did not replace the file"
echo "contract_outputs: ok"
