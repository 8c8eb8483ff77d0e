#!/usr/bin/env bash
# ctest build.no_wide_registers: fails when the shared library has an instruction that uses an AVX
# (ymm) or AVX-512 (zmm) register. Such an instruction stops the program on an x86-64 CPU without
# that extension, and would make results depend on which CPU runs them: the library is built for
# the baseline instruction set and has no code path chosen by CPU.
# Usage: no_wide_registers.sh LIBRARY PROCESSOR. Exit status 77 (skipped) on a processor other
# than x86-64.
set -euo pipefail
library=$1 processor=$2
case "$processor" in
  x86_64 | AMD64 | amd64) ;;
  *) echo "not x86-64 ($processor): nothing to check"; exit 77 ;;
esac
command -v objdump >/dev/null || { echo "objdump (binutils) is needed for this check" >&2; exit 1; }
# One pass: count the instructions, keep the first ten that name a ymm or zmm register (AT&T
# syntax: %ymm0 .. %ymm31, %zmm0 .. %zmm31), count those.
objdump -d --no-show-raw-insn "$library" | awk -v library="$library" '
  /^ *[0-9a-f]+:\t/ { instructions++ }
  /%[yz]mm[0-9]/ { wide++; if (wide <= 10) first = first $0 "\n" }
  END {
    # A disassembly that is not the library code would pass for the wrong reason.
    if (instructions < 10000) {
      printf "objdump -d %s gave %d instructions; expected the library code\n", library, instructions > "/dev/stderr"
      exit 1
    }
    if (wide > 0) {
      printf "%s: %d instructions use ymm or zmm registers; the first:\n%s", library, wide, first > "/dev/stderr"
      exit 1
    }
    printf "%s: no ymm or zmm register in %d instructions\n", library, instructions
  }'
