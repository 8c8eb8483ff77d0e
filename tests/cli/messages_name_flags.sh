#!/usr/bin/env bash
# The library's messages speak of its parameters (drop_invalid, names, scale, the drive gain);
# the command line says the flag that sets each (app/flag_names.hpp, app/data_options.cpp).
source "$(dirname "$0")/lib.sh"
emps="$src/data/emps/DATA_EMPS.mat"

# A force that is zero throughout (status error through the result, not an exception).
expect_fail "check the force column or the drive gain (--gain)" \
  identify idim "$emps" --time t --position qm --input vir --gain 0

# CSV readers: an empty cell names --drop-invalid, a headerless file names --names.
printf 'time,position,force\n0,0,1\n0.001,,1\n0.002,0.2,1\n' > "$tmp/hole.csv"
expect_fail "(use --drop-invalid to skip such rows)" identify idim "$tmp/hole.csv"
printf '0,0,1\n0.001,0.1,1\n0.002,0.2,1\n' > "$tmp/bare.csv"
expect_fail "unless named with --names)" identify idim "$tmp/bare.csv"

# --scale: a malformed factor and a column the file lacks.
expect_fail "--scale 'position': expected NAME=FACTOR" identify idim "$emps" --time t --position qm --input vir --gain gtau --scale position
expect_fail "(--scale 'nothere=2')" identify idim "$emps" --time t --position qm --input vir --gain gtau --scale nothere=2

echo "messages_name_flags: ok"
