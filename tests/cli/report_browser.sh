#!/usr/bin/env bash
# --report in a real headless browser (Debian's chromium): identify idim on the EMPS data with a
# cross-test writes DIR/report.html; chromium loads it from file:// (no network), the rendered DOM
# holds the parameter table (M = 95.10 kg) and the inline SVG figures (fit, friction map, cross-test),
# and a screenshot is taken.
# The screenshot is kept in $FRICTIONLAB_REPORT_SCREENSHOT, else ./report_browser.png in the
# working directory (ctest runs in the build directory, so CI can keep it as an artefact).
# Usage: report_browser.sh PATH_TO_frictionlab SOURCE_DIR
source "$(dirname "$0")/lib.sh"
shot="${FRICTIONLAB_REPORT_SCREENSHOT:-$PWD/report_browser.png}"

browser=""
for b in chromium chromium-browser; do command -v "$b" > /dev/null && { browser="$b"; break; }; done
[ -n "$browser" ] || { echo "SKIP: chromium not installed (Debian package chromium; make deps installs it)"; exit 0; }

emps="$src/data/emps"
"$exe" identify idim "$emps/DATA_EMPS.mat" --time t --position qm --input vir --gain gtau \
  --validate "$emps/DATA_EMPS_PULSES.mat" --report "$tmp/report" --json "$tmp/model.json" > /dev/null
page="$tmp/report/report.html"
[ -s "$page" ] || fail "report.html missing"
# Self-contained: no external resource is referenced.
! grep -Eq '(src|href)="(https?:)?//' "$page" || fail "report.html references a network resource"
grep -q "<svg" "$page" || fail "report.html has no inline SVG figure"
# The fit, the friction map and (--validate) the cross-test, each with its data and script.
for f in {fit,friction-map,cross-test}.svg{,.dat,.gp}; do [ -s "$tmp/report/$f" ] || fail "report directory lacks $f"; done
grep -q "Cross-test" "$tmp/report/cross-test.svg" || fail "cross-test figure lacks its title"
grep -q "DATA_EMPS_PULSES.mat" "$tmp/report/cross-test.svg" || fail "cross-test figure does not name the second file"
grep -q "predicted" "$tmp/report/cross-test.svg" || fail "cross-test figure lacks the predicted force"

run_browser() {  # extra chromium arguments; a fresh profile each time, no network, no GPU
  local profile
  profile="$(mktemp -d "$tmp/profile.XXXXXX")"
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync --disable-dev-shm-usage \
    --user-data-dir="$profile" "$@" "file://$page" 2> "$tmp/browser.log"
}

run_browser --dump-dom > "$tmp/dom.html" || { cat "$tmp/browser.log"; fail "chromium --dump-dom failed"; }
grep -q 'id="parameter-table"' "$tmp/dom.html" || fail "rendered DOM lacks the parameter table"
grep -q '95\.10' "$tmp/dom.html" || fail "rendered DOM lacks M = 95.10"
grep -q '>kg<' "$tmp/dom.html" || fail "rendered DOM lacks the unit kg"
grep -q 'DATA_EMPS_PULSES.mat' "$tmp/dom.html" || fail "rendered DOM lacks the cross-test file"
grep -q '6cf6814ae14618795da0101aae2bb97ff0c6351b0501b5492751b02b07facf7e' "$tmp/dom.html" ||
  fail "rendered DOM lacks the data file's sha256"
[ "$(grep -o '<svg' "$tmp/dom.html" | wc -l)" -ge 3 ] || fail "rendered DOM lacks the three SVG figures"
[ "$(grep -o '<figcaption>' "$tmp/dom.html" | wc -l)" -ge 3 ] || fail "rendered DOM lacks the figure captions"
grep -q 'id="figure-2"' "$tmp/dom.html" && grep -q 'Friction against velocity' "$tmp/dom.html" ||
  fail "rendered DOM lacks the friction map"
grep -q 'id="figure-3"' "$tmp/dom.html" && grep -q 'Cross-test: the drive force' "$tmp/dom.html" ||
  fail "rendered DOM lacks the cross-test figure"

mkdir -p "$(dirname "$shot")"
rm -f "$shot"
run_browser --screenshot="$shot" --window-size=1280,2000 --hide-scrollbars ||
  { cat "$tmp/browser.log"; fail "chromium --screenshot failed"; }
[ -s "$shot" ] || fail "no screenshot written"
[ "$(head -c 8 "$shot" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || fail "screenshot is not a PNG"
# A blank page compresses to a few kB; the rendered report (tables, text, figure) is far larger.
[ "$(stat -c %s "$shot")" -gt 30000 ] || fail "screenshot looks blank ($(stat -c %s "$shot") bytes)"

echo "report_browser: ok (screenshot $shot)"
