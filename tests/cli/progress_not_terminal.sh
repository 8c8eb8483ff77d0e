#!/usr/bin/env bash
# A slow run is never silent when stderr is not a terminal (a log, a pipe, a batch job): once it
# has taken 2 s it prints a whole progress line "<task>: <stage> ... S s" (the first at 2 s, not
# 3 s: a run of 2.5 s says what it is doing), then one every 3 s, with no carriage return or
# terminal escape; FRICTIONLAB_NO_PROGRESS turns it off. The run: a Monte Carlo plan of 400 runs
# (several seconds on the development machine; the check needs it to take at least 5 s, and says
# so when the machine was faster).
source "$(dirname "$0")/lib.sh"
cd "$tmp"
plan=(plan breakaway --prior "$src/examples/plan/craig_motor_prior.json" --scenario "$src/examples/craig_motor_trapezoid.yaml"
      --noise current=2e-4,velocity=0.5 --runs 400)

SECONDS=0
"$exe" "${plan[@]}" -o ramp.csv > out.txt 2> err.txt
took=$SECONDS
echo "took $took s"
if (( took >= 5 )); then
  grep -Eq '^frictionlab plan breakaway: .* \.\.\. [0-9]+\.[0-9] s$' err.txt || { cat err.txt; fail "no progress line on stderr in $took s"; }
  # The first line at 2 s (the thread looks every 0.25 s): before 3 s.
  first=$(grep -Eo '\.\.\. [0-9]+\.[0-9] s$' err.txt | head -1 | grep -Eo '[0-9]+\.[0-9]')
  /usr/bin/python3 -c "import sys; sys.exit(not 2.0 <= float(sys.argv[1]) < 3.0)" "$first" ||
    { cat err.txt; fail "the first progress line came at $first s; expected at 2 s"; }
else
  echo "NOTE: the run took $took s (< 5 s): the progress line is not required"
fi
grep -q $'\r' err.txt && fail "carriage return in a progress line that is not on a terminal"
grep -q $'\033' err.txt && fail "terminal escape in a progress line that is not on a terminal"
grep -q "progress\|\.\.\. [0-9]" out.txt && fail "a progress line went to stdout"

FRICTIONLAB_NO_PROGRESS=1 "$exe" "${plan[@]}" -o ramp2.csv > out2.txt 2> err2.txt
grep -q '\.\.\. [0-9.]* s$' err2.txt && fail "FRICTIONLAB_NO_PROGRESS=1: progress lines printed"
echo "PASS progress_not_terminal"
