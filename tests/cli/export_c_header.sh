#!/usr/bin/env bash
# frictionlab export MODEL.json --c FILE.h: the header compiles strictly as C99 and gives the
# identified law's values; bad model files, compensations and flags are exit 2 naming the file,
# key or flag; a failed run leaves no output, the input is never overwritten, --overwrite is needed
# to replace a header.
source "$(dirname "$0")/lib.sh"

# no_output FILE: a failed run left nothing behind (no header, no temporary).
no_output() {
  [ ! -e "$1" ] || fail "$1 written by a failed run"
  ! ls "$(dirname "$1")" | grep -q '\.tmp-' || fail "temporary file left in $(dirname "$1")"
}

# A MODEL.json as `identify idim --json` writes it, with direction-dependent Coulomb levels.
cat > "$tmp/model.json" <<'EOF'
{"schema": 1, "status": "ok", "message": "", "method": "idim", "model": "coulomb-viscous-asymmetric",
 "law": {"law": "coulomb-viscous-asymmetric", "Fc_pos": 0.7, "Fv_pos": 0.21, "Fc_neg": 0.9, "Fv_neg": 0.19},
 "parameters": {"M": {"value": 2.5, "std": 0.01, "unit": "kg"}}}
EOF
cat > "$tmp/lugre.json" <<'EOF'
{"law": "lugre", "sigma0": 1e5, "sigma1": 316.22776601683796, "sigma2": 0.4, "Fc": 1, "Fs": 1.5, "vs": 0.001}
EOF

# 1. The header compiles strictly and gives the model's values (0.7 + 0.21 * 0.5 at +0.5 m/s,
#    -(0.9 + 0.19 * 0.5) at -0.5 m/s: printed with %.17g, compared to 1e-12 by awk).
expect 0 "" export "$tmp/model.json" --c "$tmp/drive.h" --compensation feedforward --band 0.002 --prefix x_axis
grep -q '^static const double x_axis_Fc_pos = 0.69999999999999996;' "$tmp/drive.h" || fail "Fc_pos not at full precision"
grep -q 'x_axis_feedforward' "$tmp/drive.h" || fail "no feedforward function"
cat > "$tmp/main.c" <<'EOF'
#include <stdio.h>
#include "drive.h"
int main(void) {
  printf("%.17g %.17g %.17g\n", x_axis_friction(0.5), x_axis_friction(-0.5), x_axis_feedforward(0.0));
  return 0;
}
EOF
cc -std=c99 -Wall -Wextra -Werror -pedantic -o "$tmp/prog" "$tmp/main.c" -lm || fail "header does not compile strictly"
"$tmp/prog" | awk '{
  d1 = $1 - 0.805; d2 = $2 + 0.995; m = 0.5 * ((0.7 + 0.21 * 0.002) - (0.9 + 0.19 * 0.002)); d3 = $3 - m
  if (d1 < 0) d1 = -d1; if (d2 < 0) d2 = -d2; if (d3 < 0) d3 = -d3
  if (d1 > 1e-12 * 0.805 || d2 > 1e-12 * 0.995 || d3 > 1e-12) { print "values " $0; exit 1 } }' ||
  fail "header values differ from the model's"

# The disturbance observer takes M from MODEL.json; float headers compile strictly too.
expect 0 "" export "$tmp/model.json" --c "$tmp/dob.h" --compensation disturbance-observer --float
grep -q '^static const float friction_dob_inertia = 2.5f;' "$tmp/dob.h" || fail "inertia not taken from parameters.M"
expect 0 "" export "$tmp/lugre.json" --c "$tmp/obs.h" --compensation lugre-observer --gain 0.05
printf '#include "obs.h"\nint main(void) { friction_state s; friction_lugre_observer_state o; friction_init(&s);\n friction_lugre_observer_init(&o, 0.0); return friction_update(&s, 0.01, 1e-3) > 0 && friction_lugre_observer_update(&o, 0.0, 0.0, 0.0, 1e-3) == 0 ? 0 : 1; }\n' > "$tmp/obs.c"
cc -std=c99 -Wall -Wextra -Werror -pedantic -o "$tmp/obs" "$tmp/obs.c" -lm && "$tmp/obs" || fail "lugre header"

# A law with a position ripple and a compensation: PREFIX_feedforward_at(vr, q) and
# PREFIX_feedback_at(v, q) add PREFIX_ripple(q) (at the reference and at the measured position),
# inside the band as outside it, in double and float. Coulomb-viscous Fc = 1, Fv = 0.4 and the
# ripple 0.6 sin(2 pi q / 0.02) - 0.4 cos(2 pi q / 0.02): r(0.005) = 0.6, r(0.01) = 0.4, r(0) = -0.4 N.
printf '{"law": "coulomb-viscous", "Fc": 1.0, "Fv": 0.4, "ripple_period": 0.02, "ripple_a": [0.6], "ripple_b": [-0.4]}\n' \
  > "$tmp/ripple.json"
for precision in double float; do
  flag=""; [ "$precision" = float ] && flag="--float"
  expect 0 "" export "$tmp/ripple.json" --c "$tmp/rff_$precision.h" --compensation feedforward --band 0.002 $flag
  expect 0 "" export "$tmp/ripple.json" --c "$tmp/rfb_$precision.h" --compensation feedback --dead-band 0.001 $flag
  for kind in rff rfb; do
    fn=friction_feedforward_at; [ "$kind" = rfb ] && fn=friction_feedback_at
    printf '#include <stdio.h>\n#include "%s_%s.h"\nint main(void) {\n  printf("%%.9g %%.9g %%.9g\\n", (double)%s(0.5, 0.005), (double)%s(0.0, 0.01), (double)%s(-0.5, 0.0));\n  return 0;\n}\n' \
      "$kind" "$precision" "$fn" "$fn" "$fn" > "$tmp/$kind.c"
    cc -std=c99 -Wall -Wextra -Werror -pedantic -o "$tmp/$kind" "$tmp/$kind.c" -lm ||
      fail "$kind header ($precision) does not compile strictly"
    # F(0.5) + 0.6 = 1.8; at rest F = 0 (the feedforward band's midpoint, the feedback's dead band)
    # + 0.4; F(-0.5) + r(0) = -1.2 - 0.4 = -1.6; to float's precision (1e-6 of about 1 N).
    "$tmp/$kind" | awk -v what="$kind $precision" '{
      split("1.8 0.4 -1.6", w, " ")
      for (i = 1; i <= 3; ++i) { d = $i - w[i]; if (d < 0) d = -d; if (d > 1e-6) { print what ": " $0; exit 1 } } }' ||
      fail "$kind header ($precision) does not add the ripple at the position"
  done
done

# --help names the command's units.
"$exe" export --help > "$tmp/help.txt"
grep -q 'm/s or rad/s' "$tmp/help.txt" || fail "--help lacks units"
grep -q 'kg or kg m^2' "$tmp/help.txt" || fail "--help lacks the inertia's unit"

# 2. Bad input: exit 2, one line naming the file, key or flag; nothing written.
out="$tmp/out/bad.h"
mkdir -p "$tmp/out"
expect_fail "lugre-observer: law = coulomb-viscous-asymmetric must be lugre" \
  export "$tmp/model.json" --c "$out" --compensation lugre-observer
grep -qF "$tmp/model.json: --compensation" "$tmp/err.txt" || fail "the LuGre-observer message does not name the file and flag"
no_output "$out"
expect_fail "--compensation: compensation 'observer' is not known; valid types: feedforward, feedback, lugre-observer, disturbance-observer" \
  export "$tmp/model.json" --c "$out" --compensation observer
no_output "$out"
expect_fail "--gain is a parameter of --compensation lugre-observer, not of feedforward" \
  export "$tmp/model.json" --c "$out" --compensation feedforward --gain 1
expect_fail "--band is a parameter of --compensation feedforward" export "$tmp/model.json" --c "$out" --band 0.01
expect_fail "feedforward: band = -0.01 must be > 0 (m/s or rad/s)" \
  export "$tmp/model.json" --c "$out" --compensation feedforward --band -0.01
expect_fail "--inertia: missing" export "$tmp/lugre.json" --c "$out" --compensation disturbance-observer
expect_fail "disturbance-observer: inertia = -1 must be > 0" \
  export "$tmp/model.json" --c "$out" --compensation disturbance-observer --inertia -1
expect_fail "--prefix '9axis' is not a C identifier" export "$tmp/model.json" --c "$out" --prefix 9axis
no_output "$out"

printf '{"law": "stribeck", "Fc": 1, "Fs": 0.5, "vs": 0.001, "Fv": 0.1}\n' > "$tmp/badlaw.json"
expect_fail "Fs = 0.5 must be >= Fc = 1" export "$tmp/badlaw.json" --c "$out"
printf '{"law": "stribeck", "Fc": 1,\n' > "$tmp/broken.json"
expect_fail "broken.json" export "$tmp/broken.json" --c "$out"
printf '{"status": "error", "message": "no motion detected"}\n' > "$tmp/failed.json"
expect_fail "no motion detected" export "$tmp/failed.json" --c "$out"
expect_fail "missing.json" export "$tmp/missing.json" --c "$out"
expect_fail "directory $tmp/nowhere does not exist" export "$tmp/model.json" --c "$tmp/nowhere/x.h"
no_output "$out"

# 3. The input is never overwritten, even with --overwrite; an existing header needs --overwrite.
cp "$tmp/model.json" "$tmp/model.keep"
expect_fail "is the model file" export "$tmp/model.json" --c "$tmp/model.json" --overwrite
cmp -s "$tmp/model.json" "$tmp/model.keep" || fail "the model file was changed"
expect_fail "exists; pass --overwrite" export "$tmp/model.json" --c "$tmp/drive.h"
expect 0 "" export "$tmp/lugre.json" --c "$tmp/drive.h" --overwrite
grep -q 'friction_update' "$tmp/drive.h" || fail "--overwrite did not replace the header"

# 4. An identified offset is not friction: the header leaves it out and says so on stderr, with its
#    value and unit; a model without an offset gets no such line.
cat > "$tmp/biased.json" <<'EOF'
{"schema": 1, "status": "ok", "message": "", "method": "idim", "model": "coulomb-viscous", "axis": "rotary",
 "law": {"law": "coulomb-viscous", "Fc": 1.25, "Fv": 0.4},
 "parameters": {"M": {"value": 2.5, "std": 0.01, "unit": "kg m^2"}, "offset": {"value": -3.25, "std": 0.01, "unit": "N m"}}}
EOF
"$exe" export "$tmp/biased.json" --c "$tmp/biased.h" 2> "$tmp/biased.err"
grep -qF "not in the header: parameters.offset = -3.25 N m (a constant force of the rig, not friction" "$tmp/biased.err" \
  || { cat "$tmp/biased.err"; fail "the offset was dropped without a word"; }
grep -q "offset" "$tmp/biased.h" && fail "the header carries the offset"
"$exe" export "$tmp/model.json" --c "$tmp/plain.h" 2> "$tmp/plain.err"
grep -q "offset" "$tmp/plain.err" && fail "a model without an offset got an offset line"
echo "ok"
