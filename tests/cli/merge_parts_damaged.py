"""Property test of `frictionlab merge` on damaged part files (docs/guarantees.md): a part that is
truncated, has its total, shard, columns, rows or header edited, is given twice, or comes from
another run is refused with exit 2 and one line naming the part file and what is wrong with it
(the field, or "duplicated"/"missing"/"foreign"); never a crash, never a merged table. Random
byte-level damage (seeded) may merge only when the part still reads as a part: never a crash
(exit 1 or a signal) and never more than one line on stderr.

Parts of two kinds: an `analyze map` (fixed columns) and an `identify` batch (grown columns).
Seeded: FRICTIONLAB_PROPERTY_SEED (default 25).

Usage: merge_parts_damaged.py PATH_TO_frictionlab SOURCE_DIR SCRATCH_DIR [SEED]
"""
import json
import os
import random
import shutil
import subprocess
import sys

exe, src, tmp = sys.argv[1], sys.argv[2], sys.argv[3]
seed = int(sys.argv[4] if len(sys.argv) > 4 else os.environ.get("FRICTIONLAB_PROPERTY_SEED", "25"))
rng = random.Random(seed)
env = dict(os.environ, FRICTIONLAB_NO_PROGRESS="1")


def run(args):
    return subprocess.run([exe] + args, capture_output=True, env=env, timeout=120)


def path(name):
    return os.path.join(tmp, name)


def setup(args):
    p = run(args)
    if p.returncode != 0:
        sys.exit(f"test setup failed: {' '.join(args)}\n{p.stderr.decode(errors='replace')}")


# Map parts (3 shards of a 2-D grid) and batch parts (2 shards of 3 logs).
pendulum = os.path.join(src, "examples/craig_pendulum_coulomb.yaml")
for k in (1, 2, 3):
    setup(["analyze", "map", pendulum, "--vary", "friction.Fs=0.2:0.3:3", "--vary", "friction.Fc=0.1:0.15:2",
           "--jobs", "1", "--shard", f"{k}/3", "-o", path(f"map{k}.json")])
setup(["analyze", "map", pendulum, "--vary", "friction.Fs=0.2:0.3:2", "--jobs", "1", "--shard", "1/3", "-o",
       path("other1.json")])
setup(["simulate", os.path.join(src, "examples/virgala_motor_sweep.yaml"), "-o", path("sweep.csv")])
os.makedirs(path("fleet"))
for day in ("2026-11-02", "2026-11-09", "2026-11-16"):
    shutil.copy(path("sweep.csv"), path(f"fleet/axis_{day}.csv"))
for k in (1, 2):
    setup(["identify", "sweep", path("fleet"), "--kt", "0.039", "--date-from", "name", "--shard", f"{k}/2",
           "--table", path(f"batch{k}.json")])
kinds = {"map": [path(f"map{k}.json") for k in (1, 2, 3)], "batch": [path(f"batch{k}.json") for k in (1, 2)]}
for parts in kinds.values():
    p = run(["merge"] + parts + ["-o", path("whole.csv"), "--overwrite"])
    assert p.returncode == 0, p.stderr

failures = []
cases = 0


def merge(parts, label, want_exit=2, must_name=(), may_merge=False):
    """Merges PARTS; checks the exit status, one stderr line naming each of MUST_NAME."""
    global cases
    cases += 1
    if os.path.exists(path("out.csv")):
        os.remove(path("out.csv"))
    p = run(["merge"] + parts + ["-o", path("out.csv")])
    err = p.stderr.decode("utf-8", "replace")
    why = []
    if may_merge and p.returncode == 0:
        return
    if p.returncode != want_exit:
        why.append(f"exit {p.returncode}, expected {want_exit}" + (" (a crash)" if p.returncode < 0 else ""))
    if err.count("\n") != 1:
        why.append("not a one-line message")
    for name in must_name:
        if name not in err:
            why.append(f"message does not name {name!r}")
    if p.returncode != 0 and os.path.exists(path("out.csv")):
        why.append("a refused merge wrote its output")
    if why:
        failures.append(f"{label}: {'; '.join(why)}\n    stderr: {err.strip()[:400]}")


class Raw:
    """An edit's result that is the file's whole text (not an edit of its JSON)."""

    def __init__(self, text):
        self.text = text


def damaged(kind, index, edit, name="damaged.json"):
    """The parts of KIND with part INDEX replaced by EDIT(its JSON) written to NAME."""
    parts = list(kinds[kind])
    j = json.load(open(parts[index]))
    out = edit(j)
    target = path(name)
    with open(target, "w") as f:
        f.write(out.text if isinstance(out, Raw) else json.dumps(j))
    parts[index] = target
    return parts, target


for kind, parts in kinds.items():
    n = len(parts)
    # Given twice, one missing, from another run, only one.
    i = rng.randrange(n)
    twice = list(parts)
    twice[(i + 1) % n] = parts[i]
    merge(twice, f"{kind}: a part given twice", must_name=[parts[i], "duplicated"])
    merge(parts[:-1], f"{kind}: a part missing", must_name=["missing", f"{n}/{n}"])
    if kind == "map":
        merge([path("other1.json")] + parts[1:], "map: a part of another run", must_name=["foreign"])
    # A part that claims a billion shards (its own total and rows consistent): refused as
    # incomplete, not a slot allocated per shard (once 32 GB).
    def billion(j):
        j["shard"] = "1/999999999"
        j["total"] = 1
        j["rows"] = j["rows"][:1]
    one, target = damaged(kind, 0, billion)
    merge(one[:1], f"{kind}: a part of shard 1/999999999", must_name=["missing", "2/999999999"])
    # Field edits, each naming the part and the field.
    i = rng.randrange(n)
    edits = [
        ("total", lambda j: j.__setitem__("total", j["total"] + 1), ["total"]),
        ("total", lambda j: j.__setitem__("total", max(0, j["total"] - 1)), ["total"]),
        ("total", lambda j: j.__setitem__("total", 10**18), ["total"]),
        ("total", lambda j: j.__setitem__("total", -3), ["total"]),
        ("total", lambda j: j.__setitem__("total", "7"), ["total"]),
        ("total", lambda j: j.__setitem__("total", 2.5), ["total"]),
        ("total", lambda j: j.pop("total"), ["total"]),
        ("shard", lambda j: j.__setitem__("shard", f"{n + 1}/{n}"), ["shard"]),
        ("shard", lambda j: j.__setitem__("shard", f"1/{n + 1}"), ["shard"]),
        ("shard", lambda j: j.__setitem__("shard", "0/0"), ["shard"]),
        ("columns", lambda j: j["columns"].pop(), ["row"]),
        ("columns", lambda j: j["columns"].__setitem__(0, j["columns"][0] + "_x"), ["columns"]),
        ("columns", lambda j: j.__setitem__("columns", "time"), ["columns"]),
        ("rows", lambda j: j["rows"].pop(), ["total"]),
        ("rows", lambda j: j["rows"].append(j["rows"][0]), ["total"]),
        ("rows", lambda j: j["rows"][0].pop(), ["row 1"]),
        ("rows", lambda j: j["rows"][0].__setitem__(0, j["rows"][0][0] + 1), ["shard"]),
        ("rows", lambda j: j["rows"][0].__setitem__(0, -1), ["row 1"]),
        ("rows", lambda j: j["rows"][0].__setitem__(1, {"x": 1}), ["row 1"]),
        ("key", lambda j: j.__setitem__("key", j["key"] + "x"), ["foreign", "key"]),
        ("command", lambda j: j.__setitem__("command", "simulate"), ["foreign", "command"]),
        ("envelope", lambda j: j["envelope"].__setitem__("extra", 1), ["foreign", "envelope"]),
        ("rows_at", lambda j: j.__setitem__("rows_at", "/elsewhere"), ["foreign"]),
        ("frictionlab_part", lambda j: j.__setitem__("frictionlab_part", 99), ["part format"]),
        ("frictionlab_part", lambda j: j.pop("frictionlab_part"), ["frictionlab_part"]),
        ("not an object", lambda j: Raw("[1, 2, 3]"), ["not a frictionlab part"]),
        # A number beyond a double (once exit 1, "internal error: number overflow"; fuzz_merge).
        ("a number", lambda j: Raw(json.dumps(j).replace('"total": ', '"x": 1e400, "total": ', 1)),
         ["not a part file", "1e400"]),
        ("empty", lambda j: Raw(""), ["not a part file"]),
    ]
    if kind == "batch":
        edits += [
            ("grown", lambda j: j["grown"].__setitem__("end", len(j["columns"]) + 1), ["grown"]),
            ("grown", lambda j: j["grown"]["first"].append(0), ["grown"]),
            ("grown", lambda j: j.pop("grown"), ["foreign", "columns"]),
        ]
    for what, edit, names in edits:
        # Only the first part is compared with the others as "foreign": damage a later one.
        k = i if what not in ("key", "command", "envelope", "rows_at", "grown") else n - 1
        if what == "grown" and "grown" not in json.load(open(parts[k])):
            continue
        damaged_parts, target = damaged(kind, k, edit)
        merge(damaged_parts, f"{kind}: part {k + 1} with {what} edited", must_name=[target] + names)
    # Truncated at a random point inside the text (not its trailing newline).
    text = open(parts[i], "rb").read()
    for _ in range(8):
        cut = rng.randrange(1, len(text.rstrip()))
        damaged_parts, target = damaged(kind, i, lambda j: Raw(text[:cut].decode("utf-8", "ignore")))
        merge(damaged_parts, f"{kind}: part {i + 1} cut at byte {cut}", must_name=[target])
    # Random byte damage: never a crash; a merge only when the part still reads.
    for _ in range(12):
        raw = bytearray(text)
        for _ in range(rng.randint(1, 4)):
            pos = rng.randrange(len(raw))
            op = rng.randrange(3)
            if op == 0:
                raw[pos] = rng.randrange(256)
            elif op == 1:
                del raw[pos]
            else:
                raw.insert(pos, rng.choice(b'{}[]",:0123456789-e.'))
        target = path("bytes.json")
        open(target, "wb").write(bytes(raw))
        damaged_parts = list(parts)
        damaged_parts[i] = target
        merge(damaged_parts, f"{kind}: part {i + 1} with damaged bytes", must_name=[target], may_merge=True)

print(f"seed {seed}: {cases} merges")
if failures:
    print(f"FAIL: {len(failures)} merges")
    print("\n".join(failures))
    sys.exit(1)
print("ok")
