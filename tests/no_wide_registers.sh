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
listing=$(objdump -d --no-show-raw-insn "$library")
instructions=$(grep -c $'^ *[0-9a-f]*:\t' <<<"$listing" || true)
# A disassembly that is not the library's code would pass for the wrong reason.
if ((instructions < 10000)); then
  echo "objdump -d $library gave $instructions instructions; expected the library's whole code" >&2
  exit 1
fi
# AT&T syntax names the registers %ymm0 .. %ymm31 and %zmm0 .. %zmm31.
wide=$(grep -E '%[yz]mm[0-9]+' <<<"$listing" || true)
if [[ -n "$wide" ]]; then
  echo "$library: $(wc -l <<<"$wide") instructions use ymm or zmm registers; the first:" >&2
  head -n 10 <<<"$wide" >&2
  exit 1
fi
echo "$library: no ymm or zmm register in $instructions instructions"
