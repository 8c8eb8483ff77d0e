"""Property test of the JSON contract (docs/contract.md, docs/guarantees.md): whatever bytes a file
name, a CSV header or a MAT variable name holds, `--json -` prints one valid UTF-8 JSON object on
stdout with the documented envelope (schema, status, message, method; on an error the error
object with its code and the same message), for runs that succeed and runs that fail.

Seeded (FRICTIONLAB_PROPERTY_SEED, default 25): each round picks bytes that are not UTF-8 (a
lone continuation byte, a truncated sequence, an overlong form, a surrogate, 0xFE/0xFF) and puts
them in a file name, a header and a MAT variable name, then runs a set of commands on them.

Usage: json_envelope.py PATH_TO_frictionlab SOURCE_DIR SCRATCH_DIR [SEED]
"""
import csv
import json
import os
import random
import subprocess
import sys

import numpy as np
import scipy.io

exe, src, tmp = sys.argv[1], sys.argv[2], sys.argv[3]
seed = int(sys.argv[4] if len(sys.argv) > 4 else os.environ.get("FRICTIONLAB_PROPERTY_SEED", "25"))
rng = random.Random(seed)
env = dict(os.environ, FRICTIONLAB_NO_PROGRESS="1")
tmpb = os.fsencode(tmp)

BAD = [b"\x80", b"\xbf", b"\xc3", b"\xe9", b"\xc0\xaf", b"\xe0\x80\xaf", b"\xed\xa0\x80", b"\xf4\x90\x80\x80",
       b"\xf8\x88\x80\x80\x80", b"\xfe", b"\xff", b"\xe2\x82", b"a\xf0\x9f\x98"]


def run(args):
    return subprocess.run([os.fsencode(exe)] + [a if isinstance(a, bytes) else a.encode() for a in args],
                          capture_output=True, env=env, timeout=120)


p = run(["simulate", os.path.join(src, "examples/virgala_motor_sweep.yaml"), "-o", os.path.join(tmp, "sweep.csv")])
assert p.returncode == 0, p.stderr
with open(os.path.join(tmp, "sweep.csv"), newline="") as f:
    rows = list(csv.reader(f))
header, body = rows[0], np.array(rows[1:], dtype=float)

failures = []
cases = 0


def check(args, want_status):
    """Runs ARGS --json -: stdout must be one UTF-8 JSON object with the envelope."""
    global cases
    cases += 1
    p = run(args + ["--json", "-"])
    shown = b" ".join(a if isinstance(a, bytes) else a.encode() for a in args).decode("utf-8", "backslashreplace")
    why = []
    try:
        text = p.stdout.decode("utf-8")  # strict: any byte that is not UTF-8 fails here
        assert text.count("\n") == 1 and text.endswith("\n"), "not one line of JSON"
        j = json.loads(text)
        assert isinstance(j, dict), "not an object"
        assert j.get("schema") == 2, f"schema {j.get('schema')!r}"
        assert j.get("status") in ("ok", "error"), f"status {j.get('status')!r}"
        assert isinstance(j.get("message"), str), "no message"
        assert isinstance(j.get("method"), str) and j["method"], "no method"
        if j["status"] == "error":
            e = j.get("error")
            assert isinstance(e, dict) and isinstance(e.get("code"), str) and e["code"], f"error {e!r}"
            assert e.get("message") == j["message"] and j["message"], "error.message differs from message"
            for k, v in e.items():
                assert k in ("code", "message", "file", "row", "column", "key", "option", "value", "other_file",
                             "other_option"), f"unknown error field {k}"
                assert isinstance(v, int if k == "row" else str), f"error.{k} is {v!r}"
            assert p.returncode == 2, f"exit {p.returncode} with status error"
        else:
            assert p.returncode == 0, f"exit {p.returncode} with status ok"
            assert isinstance(j.get("frictionlab", {}).get("version"), str), "no frictionlab.version"
        want = {"ok": 0, "error": 2}[want_status]
        assert p.returncode == want, f"exit {p.returncode}, expected {want}"
        assert p.stderr.count(b"\n") <= 40, "stderr floods"
    except (AssertionError, UnicodeDecodeError, json.JSONDecodeError) as ex:
        why.append(str(ex))
    if why:
        failures.append(f"{shown} --json -: {'; '.join(why)}\n    stdout: {p.stdout[:300]!r}\n    stderr: "
                        f"{p.stderr[-300:]!r}")


def write_mat(path, names):
    """A MAT v5 file of the sweep's columns under NAMES (bytes; same length as the column's name):
    scipy writes ASCII names, then they are replaced in place by the bytes wanted."""
    placeholders = {}
    data = {}
    letters = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
    for col, name in zip(header, names):
        ph = "".join(rng.choice(letters) for _ in range(len(name)))
        placeholders[ph.encode()] = name
        data[ph] = body[:, header.index(col)]
    scipy.io.savemat(os.fsdecode(path), data, do_compression=False, oned_as="column")
    raw = open(path, "rb").read()
    for ph, name in placeholders.items():
        assert raw.count(ph) == 1, ph  # a placeholder that the numbers' bytes happen to hold: change the seed
        raw = raw.replace(ph, name)
    open(path, "wb").write(raw)


for round_ in range(4):
    bad = rng.choice(BAD)
    bad2 = rng.choice(BAD)
    d = os.path.join(tmpb, b"r%d" % round_)
    os.makedirs(d)
    # A CSV whose file name and extra column's name hold the bytes.
    name = os.path.join(d, b"sweep" + bad + b".csv")
    with open(name, "wb") as f:
        f.write(",".join(header).encode() + b",temp" + bad2 + b"rature\n")
        for r in body:
            f.write(",".join(repr(float(x)) for x in r).encode() + b",20\n")
    sweep = ["identify", "sweep", name, "--kt", "0.039"]
    check(sweep, "ok")
    check(sweep + ["--time", "clock"], "error")  # the message lists the columns, the bad one too
    check(sweep + [b"--velocity=vel" + bad2], "error")  # the option's value itself
    check(["analyze", "stick-slip", name], "ok")
    check(["analyze", "envelope", name, "--position", b"pos" + bad], "error")
    # The same columns in a MAT file, one variable's name holding the bytes, in a file whose name does.
    mat = os.path.join(d, b"log" + bad2 + b".mat")
    names = [h.encode() for h in header]
    extra = header.index("stuck")
    names[extra] = (b"s" + bad)[:len(names[extra])].ljust(len(names[extra]), b"x")
    write_mat(mat, names)
    check(["identify", "sweep", mat, "--kt", "0.039"], "ok")
    check(["identify", "sweep", mat, "--kt", "0.039", "--time", "clock"], "error")
    # A file that does not exist, a directory, an empty file: named with the bytes.
    check(["identify", "sweep", os.path.join(d, b"none" + bad + b".csv"), "--kt", "0.039"], "error")
    empty = os.path.join(d, b"empty" + bad + b".csv")
    open(empty, "wb").close()
    check(["identify", "sweep", empty, "--kt", "0.039"], "error")
    # A model file whose name holds the bytes: validate against it (a bad scenario path).
    check(["validate", os.path.join(d, b"model" + bad + b".json"), name, "--scenario",
           os.path.join(d, b"s" + bad2 + b".yaml")], "error")

print(f"seed {seed}: {cases} runs")
if failures:
    print(f"FAIL: {len(failures)} runs")
    print("\n".join(failures))
    sys.exit(1)
print("ok")
