#!/usr/bin/env bash
# Real rigs' logs on the command line: a robot controller's joint log with no header row, 31
# columns and time stamps 10 to 12 ms apart is identified with --names and --resample; the bad
# cases (irregular time without --resample, a gap, wrong --names, a number out of range, a MAT
# file with a damaged compressed variable) exit 2 with a message naming what is wrong.
source "$(dirname "$0")/lib.sh"
# shellcheck source=lib.sh

# The log: joint 1 moves (a sum of sines), the drive reports current (A) with noise and an offset;
# torque = kt * current = M qdd + Fv qd + Fc sign(qd) + offset. Seeded.
/usr/bin/python3 - "$tmp" <<'PY'
import math, random, sys
tmp = sys.argv[1]
rng = random.Random(31)
M, Fv, Fc, off, kt = 0.8, 1.5, 2.0, 0.3, 0.5       # kg m^2, N m s/rad, N m, N m, N m/A
def motion(t):
    q = qd = qdd = 0.0
    for a, w in ((0.6, 2.1), (0.25, 5.3), (0.1, 9.7)):  # rad, rad/s
        q += a * math.sin(w * t); qd += a * w * math.cos(w * t); qdd -= a * w * w * math.sin(w * t)
    return q, qd, qdd
def write(name, rows, hole_after=None):
    t = 12.345
    with open(f"{tmp}/{name}", "w") as f:
        f.write("# exported by the joint controller\n")  # a comment line before the data
        for k in range(rows):
            if k:
                t += rng.uniform(0.010, 0.012)
            if hole_after is not None and k == hole_after:
                t += 0.5
            q, qd, qdd = motion(t)
            tau = M * qdd + Fv * qd + Fc * (1 if qd > 0 else -1) + off
            cur = tau / kt + rng.gauss(0, 0.02)
            qq = round(q / 4.8e-5) * 4.8e-5                 # encoder quantisation
            cells = [f"{t:.6f}", f"{qq:.7f}"] + ["0.1"] * 5 + [f"{qd:.6f}"] + ["0"] * 5
            cells += [f"{cur:.5f}"] + [f"{0.1 * j:.2f}" for j in range(5)] + [str(40 + j) for j in range(12)]
            assert len(cells) == 31
            f.write(",".join(cells) + "\n")
write("joints.csv", 3000)
write("hole.csv", 1500, hole_after=700)
PY

names="t,q1,q2,q3,q4,q5,q6,v1,v2,v3,v4,v5,v6,i1"  # 14 of 31 columns named; the rest stay c15..c31
idim_args=(--time t --position q1 --current i1 --kt 0.5 --axis rotary --cutoff 8 --decimate 3 --skip 20)

# The good case: exit 0, parameters near the truth, the resampling reported in diagnostics.
"$exe" identify idim "$tmp/joints.csv" --names "$names" "${idim_args[@]}" --resample --json "$tmp/idim.json" > "$tmp/idim.txt"
grep -q "resampling" "$tmp/idim.txt" || { echo "FAIL: text output lacks the resampling figures"; cat "$tmp/idim.txt"; exit 1; }
/usr/bin/python3 - "$tmp/idim.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
assert j["status"] == "ok", j["message"]
p = {k: v["value"] for k, v in j["parameters"].items()}
truth = {"M": 0.8, "Fv": 1.5, "Fc": 2.0}
for k, v in truth.items():  # 5 %: noise, quantisation and interpolation of a 91 Hz log
    assert abs(p[k] - v) <= 0.05 * v, (k, p[k], v)
r = j["diagnostics"]["resampling"]
assert 0.010 - 1e-6 <= r["dt_min"] <= r["dt_median"] <= r["dt_max"] <= 0.012 + 1e-6, r  # stamps printed to 1 us
assert r["dt"] == r["dt_median"] and r["samples_in"] == 3000, r
assert abs(r["samples_out"] - 3000) < 100, r
PY


# Irregular time without --resample: refused, naming a line of the file and --resample.
expect_fail "--resample" identify idim "$tmp/joints.csv" --names "$names" "${idim_args[@]}"
expect_fail "joints.csv: line " identify idim "$tmp/joints.csv" --names "$names" "${idim_args[@]}"
# Without --names the columns are c1..c31 and the message says the file has no header row.
expect_fail "no column 't' (--time)" identify idim "$tmp/joints.csv" "${idim_args[@]}" --resample
expect_fail "c31 (the file has no header row" identify idim "$tmp/joints.csv" "${idim_args[@]}" --resample
# More names than columns; an empty name.
expect_fail "--names gives 32 names but the file has 31 columns" \
  identify idim "$tmp/joints.csv" --names "$names$(printf ',x%d' $(seq 15 32))" "${idim_args[@]}" --resample
expect_fail "--names: name 2 is empty" identify idim "$tmp/joints.csv" --names "t,,q" "${idim_args[@]}" --resample
# A 0.5 s hole: an error naming its lines unless --max-gap allows it.
expect_fail "line 701 to line 702: a gap of 0.5" identify idim "$tmp/hole.csv" --names "$names" "${idim_args[@]}" --resample
expect_fail "--max-gap" identify idim "$tmp/hole.csv" --names "$names" "${idim_args[@]}" --resample
"$exe" identify idim "$tmp/hole.csv" --names "$names" "${idim_args[@]}" --resample --max-gap 0.6 --json "$tmp/hole.json" > /dev/null
# Option values: a grid step that is not a number, --max-gap without --resample.
expect_fail "--resample 'abc'" identify idim "$tmp/joints.csv" --names "$names" "${idim_args[@]}" --resample abc
expect_fail "--max-gap" identify idim "$tmp/joints.csv" --names "$names" "${idim_args[@]}" --max-gap 1
# A cell beyond the range of a double is called that, not "not a finite number".
printf 'time;x\n0;1\n0.01;1e400\n' > "$tmp/huge.csv"
expect_fail "huge.csv: line 3, column 2 'x': '1e400' is out of the range of a double" \
  analyze envelope "$tmp/huge.csv" --position x
# A MAT file whose compressed variable qm has flipped bytes: refused, naming the file and qm.
/usr/bin/python3 - "$src/data/emps/DATA_EMPS.mat" "$tmp/flipped.mat" <<'PY'
import struct, sys, zlib
b = bytearray(open(sys.argv[1], "rb").read())
at, done = 128, False
while at + 8 <= len(b):  # the v5 data elements after the 128-byte header
    typ, size = struct.unpack("<II", b[at:at + 8])
    head = zlib.decompressobj().decompress(bytes(b[at + 8:at + 8 + size]), 64) if typ == 15 else b""
    if head[44:48] == b"qm\0\0":  # the name in a small element after tag, flags and dims
        for k in range(4):
            b[at + 8 + size // 2 + 7 * k] ^= 0x5A
        done = True
    at += 8 + size
assert done
open(sys.argv[2], "wb").write(b)
PY
expect_fail "variable 'qm'" identify idim "$tmp/flipped.mat" --time t --position qm --input vir --gain gtau
expect_fail "flipped.mat" identify idim "$tmp/flipped.mat" --time t --position qm --input vir --gain gtau
# analyze reads the same way: a jittered, headerless free decay, resampled; the JSON says how.
/usr/bin/python3 - "$tmp/decay.txt" <<'PY'
import math, random, sys
rng, t = random.Random(3), 0.0
with open(sys.argv[1], "w") as f:
    for k in range(4000):
        t += rng.uniform(0.0009, 0.0011) if k else 0.0
        f.write(f"{t:.7f} {math.exp(-0.3 * t) * math.cos(2 * math.pi * t):.6f}\n")  # space separated
PY
mv "$tmp/decay.txt" "$tmp/decay.csv"
"$exe" analyze envelope "$tmp/decay.csv" --names t,x --time t --position x --resample --json - 2> /dev/null > "$tmp/env.json"
/usr/bin/python3 - "$tmp/env.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
r = j["diagnostics"]["resampling"]
assert j["status"] == "ok" and r["samples_in"] == 4000 and abs(r["dt_median"] - 0.001) < 2e-5, r
assert j["result"]["half_cycles"] >= 4, j["result"]
PY
echo "data_real_logs: all checks passed"
