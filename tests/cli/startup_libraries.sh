#!/usr/bin/env bash
# Start-up cost: commands that read no MAT file do not load matio (nor HDF5, curl, GnuTLS, ...,
# about 30 shared libraries through it); a MAT file loads it on first use. The dynamic loader's own
# record (LD_DEBUG=files) tells which libraries a run opened.
source "$(dirname "$0")/lib.sh"

opened() { LD_DEBUG=files "$@" 2>&1 >/dev/null | grep -E 'file=[^ ]+ \[0\];  (needed|dynamically loaded)' || true; }

opened "$exe" --version > "$tmp/version.txt"
grep -q "file=libfrictionlab" "$tmp/version.txt" || fail "LD_DEBUG=files shows no libfrictionlab: the check below would pass for the wrong reason"
! grep -qE "libmatio|libhdf5|libcurl" "$tmp/version.txt" || { cat "$tmp/version.txt"; fail "--version loads matio or HDF5"; }

"$exe" simulate "$src/examples/canudas_stick_slip.yaml" -o "$tmp/run.csv" > /dev/null
opened "$exe" analyze stick-slip "$tmp/run.csv" > "$tmp/csv.txt"
! grep -qE "libmatio|libhdf5" "$tmp/csv.txt" || { cat "$tmp/csv.txt"; fail "reading a CSV file loads matio"; }

opened "$exe" identify idim "$src/data/emps/DATA_EMPS.mat" --time t --position qm --input vir --gain gtau > "$tmp/mat.txt"
grep -q "file=libmatio.*dynamically loaded" "$tmp/mat.txt" || { cat "$tmp/mat.txt"; fail "a MAT file did not load matio on demand"; }
echo "startup_libraries: ok"
