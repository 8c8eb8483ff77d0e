#!/usr/bin/env bash
# Runs the libFuzzer targets of tests/fuzz for a bounded time each, after replaying every kept
# regression input, and prints one PASS/FAIL line per target; exits 1 if any target failed.
# Usage: tests/fuzz/run.sh BUILD_DIR SECONDS JOBS [keep]
#   BUILD_DIR  the Clang build holding tests/fuzz/fuzz_* (make fuzz-build)
#   SECONDS    fuzzing time per target (-max_total_time)
#   JOBS       targets run at once (one core each)
#   keep       (make fuzz) copy each crashing input into tests/fuzz/regressions/<target>/ to be
#              committed; without it (make test) the source tree is left as it is.
# Each target mutates with the tokens of tests/fuzz/<target>.dict. Inputs found on the way go to BUILD_DIR/fuzz/corpus/<target> (not committed; make fuzz-merge
# minimises them into tests/fuzz/corpus/<target>).
set -uo pipefail

build=$1 seconds=$2 jobs=${3:-1} keep=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
targets=(fuzz_csv fuzz_mat fuzz_scenario fuzz_law fuzz_merge fuzz_simulate)
out="$build/fuzz"
mkdir -p "$out"

# Extra libFuzzer options per target. fuzz_mat: matio's header reader callocs by a header's
# declared size before any check of ours can run (4.7 GB for one 971-byte file, kept as
# regressions/fuzz_mat/header_dims_4GB_calloc.mat); the pages are never touched, so outside ASan
# it costs nothing (0.3 s, 21 MB resident). Such requests pass up to 8 GB; -rss_limit_mb (2 GB)
# still catches memory actually used.
target_options() {
  case $1 in
    fuzz_mat) echo "-malloc_limit_mb=8192" ;;
  esac
}

# make test (no `keep`) replays the regressions and the committed corpus, then fuzzes a short fixed
# sequence: seed 1 and a set number of new inputs per target (about 4 s each on the development
# machine, SECONDS still caps it), so a commit's run passes or fails the same way every time, and a
# new finding turns up in make fuzz, not as a CI that fails by chance. make fuzz (`keep`) draws a
# new seed every run and fuzzes for SECONDS.
fixed_runs() {
  case $1 in
    fuzz_csv) echo 6000 ;;
    fuzz_mat) echo 2000 ;;
    fuzz_scenario) echo 4000 ;;
    fuzz_law) echo 3500 ;;
    fuzz_merge) echo 3000 ;;
    fuzz_simulate) echo 1500 ;;
  esac
}

# One target: replay its regressions, then fuzz from the committed corpus. Writes a summary line
# to $out/<target>.result.
run_target() {
  local t=$1 bin="$build/tests/fuzz/$1"
  local corpus="$out/corpus/$t" findings="$out/findings/$t" log="$out/$t.log"
  local regressions=("$here/regressions/$t"/*)
  mkdir -p "$corpus" "$findings"
  [[ -e "${regressions[0]}" ]] || regressions=()
  local start=$SECONDS
  local options
  read -r -a options <<<"$(target_options "$t")"
  local fixed=()
  [[ -n "$keep" ]] || fixed=(-seed=1 -runs="$(fixed_runs "$t")")
  if ((${#regressions[@]})) && ! "$bin" -timeout=25 "${options[@]}" "${regressions[@]}" >"$out/$t.regressions.log" 2>&1; then
    echo "FAIL  $t: a kept regression input fails again (log: $out/$t.regressions.log)" >"$out/$t.result"
    return
  fi
  "$bin" -max_total_time="$seconds" -timeout=25 "${options[@]}" "${fixed[@]}" -print_final_stats=1 -artifact_prefix="$findings/" \
    -dict="$here/$t.dict" "$corpus" "$here/corpus/$t" >"$log" 2>&1
  local rc=$? elapsed=$((SECONDS - start))
  local runs
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  if ((rc == 0)); then
    echo "PASS  $t: ${elapsed} s, ${runs:-?} inputs run, ${#regressions[@]} regression inputs replayed" >"$out/$t.result"
    return
  fi
  local found
  found=$(ls -t "$findings" 2>/dev/null | head -1)
  local what
  what=$(grep -m1 -E 'ERROR: (AddressSanitizer|libFuzzer|UndefinedBehaviorSanitizer)|runtime error:|terminate called' "$log" || true)
  local msg="FAIL  $t: ${what:-exit status $rc} (log: $log)"
  if [[ -n "$found" ]]; then
    msg+="; input: $findings/$found"
    if [[ -n "$keep" ]]; then
      mkdir -p "$here/regressions/$t"
      cp "$findings/$found" "$here/regressions/$t/"
      msg+=" (kept in tests/fuzz/regressions/$t/: commit it with the fix)"
    else
      msg+=" (keep it in tests/fuzz/regressions/$t/ once fixed)"
    fi
  fi
  echo "$msg" >"$out/$t.result"
}
export -f run_target target_options fixed_runs
export build seconds keep here out

rm -f "$out"/*.result
printf '%s\n' "${targets[@]}" | xargs -P "$jobs" -I{} bash -c 'run_target {}'
status=0 passed=0 failed=0
for t in "${targets[@]}"; do
  if [[ -f "$out/$t.result" ]]; then
    echo "fuzz: $(cat "$out/$t.result")"
    if grep -q '^PASS' "$out/$t.result"; then passed=$((passed + 1)); else failed=$((failed + 1)) status=1; fi
  else
    echo "fuzz: FAIL  $t: did not run"
    failed=$((failed + 1)) status=1
  fi
done
echo "fuzz: $passed passed, $failed failed"
exit $status
