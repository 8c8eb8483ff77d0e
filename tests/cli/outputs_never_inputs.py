"""Property test of the one rule for outputs (docs/guarantees.md): no output of any command ever
replaces one of the run's inputs.

The commands and their output options come from the tool itself (`frictionlab help --commands`:
every option declared with output_option in app/), so a new output option is covered without
touching this file; a new command fails here until it has a run below. For every command, every
output option is pointed at each input of a run of it (the data, the scenario, the file its
`data:` names, MODEL, a law file, a prior, a part, a method's own input file), at a hard link and
a symbolic link to an input (chosen by the seed), with and without --overwrite (the identify
methods share their output code: one of them, by the seed, gets every case, the others a sample). Each run must exit
2 with one line on stderr naming the output path and the input, and leave every input byte for
byte as it was (a symbolic link still a link).

Usage: outputs_never_inputs.py PATH_TO_frictionlab SOURCE_DIR SCRATCH_DIR [SEED]
(SEED also from FRICTIONLAB_PROPERTY_SEED; default 25).
"""
import concurrent.futures
import hashlib
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


def run(args, check=True):
    p = subprocess.run([exe] + args, capture_output=True, env=env, timeout=120)
    if check and p.returncode != 0:
        sys.exit(f"test setup failed: {' '.join(args)}: exit {p.returncode}\n{p.stderr.decode(errors='replace')}")
    return p


def path(name):
    return os.path.join(tmp, name)


# The run's files, made once.
emps_src = os.path.join(src, "data/emps/DATA_EMPS.mat")
shutil.copy(emps_src, path("DATA_EMPS.mat"))
with open(path("law.json"), "w") as f:
    f.write('{"law": "coulomb-viscous", "Fc": 20.0, "Fv": 200.0}\n')
with open(os.path.join(src, "examples/emps_closed_loop_compensated.yaml")) as f:
    text = f.read()
lines = []
for line in text.splitlines():
    if line.startswith("data: "):
        line = "data: DATA_EMPS.mat"
    lines.append(line)
    if line == "    type: feedforward":
        lines.append("    model: law.json")
with open(path("emps.yaml"), "w") as f:
    f.write("\n".join(lines) + "\n")
assert "model: law.json" in open(path("emps.yaml")).read(), "test setup: no compensation model line"
shutil.copy(os.path.join(src, "examples/craig_pendulum_coulomb.yaml"), path("pendulum.yaml"))
run(["simulate", os.path.join(src, "examples/virgala_motor_sweep.yaml"), "-o", path("sweep.csv")])
run(["identify", "sweep", path("sweep.csv"), "--kt", "0.039", "--json", path("static.json")])
cols = ["--time", "t", "--position", "qm", "--input", "vir", "--gain", "gtau"]
shutil.copy(emps_src, path("P.mat"))
run(["identify", "idim", path("DATA_EMPS.mat")] + cols + ["--json", path("model.json")])
with open(os.path.join(src, "examples/emps_closed_loop.yaml")) as f:
    loop = "\n".join("data: DATA_EMPS.mat" if l.startswith("data: ") else l for l in f.read().splitlines())
with open(path("loop.yaml"), "w") as f:
    f.write(loop + "\n")
shutil.copy(os.path.join(src, "examples/plan/craig_motor_prior.json"), path("prior.json"))
shutil.copy(os.path.join(src, "examples/craig_motor_trapezoid.yaml"), path("motor.yaml"))
for k in (1, 2):
    run(["analyze", "map", path("pendulum.yaml"), "--vary", "friction.Fs=0.2:0.3:2", "--jobs", "1", "--shard",
         f"{k}/2", "-o", path(f"part{k}.json")])
os.makedirs(path("fleet"))
for day in ("2026-11-02", "2026-11-09"):
    shutil.copy(path("sweep.csv"), path(f"fleet/axis_{day}.csv"))

# A run of every command: its arguments (the output options left out), its inputs, the output
# options it cannot take (tested in another run of the command) and those it needs (a fresh file
# unless tested). Method-specific inputs: idim --validate, lugre --static.
ident_cols = {
    "idim": cols, "breakaway": ["--kt", "0.039"], "sweep": ["--kt", "0.039"], "decay": ["--kt", "0.039"],
    "lugre": ["--kt", "0.039", "--inertia", "1e-5"], "auto": ["--kt", "0.039"],
}
RUNS = {
    "simulate": [
        {"args": [path("pendulum.yaml")], "inputs": [path("pendulum.yaml")]},
        {"args": [path("emps.yaml")], "inputs": [path("emps.yaml"), path("DATA_EMPS.mat"), path("law.json")]},
    ],
    "validate": [
        {"args": [path("model.json"), emps_src, "--scenario", path("loop.yaml")] + cols,
         "inputs": [path("model.json"), path("loop.yaml"), path("DATA_EMPS.mat")]},
    ],
    "analyze": [
        {"args": ["map", path("pendulum.yaml"), "--vary", "friction.Fs=0.2:0.3:2", "--jobs", "1"],
         "inputs": [path("pendulum.yaml")], "needs": ["--output"]},
        {"args": ["stick-slip", path("sweep.csv")], "inputs": [path("sweep.csv")], "without": ["--output"]},
    ],
    "export": [
        {"args": [path("law.json")], "inputs": [path("law.json")], "needs": ["--c"], "without": ["--mjcf", "--json"]},
        {"args": [path("model.json")], "inputs": [path("model.json")], "needs": ["--mjcf"], "without": ["--c"]},
    ],
    "plan": [
        {"args": ["breakaway", "--prior", path("prior.json"), "--scenario", path("motor.yaml"), "--runs", "2"],
         "inputs": [path("prior.json"), path("motor.yaml")], "needs": ["--output"]},
    ],
    "merge": [
        {"args": [path("part1.json"), path("part2.json"), "--scenario", path("pendulum.yaml")],
         "inputs": [path("part1.json"), path("part2.json"), path("pendulum.yaml")], "needs": ["--output"]},
    ],
    "help": [{"args": [], "inputs": []}],  # reads nothing: no input to protect
}
for method, extra in ident_cols.items():
    data = path("DATA_EMPS.mat") if method == "idim" else path("sweep.csv")
    own = {"idim": ["--validate", path("P.mat")], "lugre": ["--static", path("static.json")]}.get(method, [])
    RUNS["identify " + method] = [
        {"args": [data] + extra + own, "inputs": [data] + own[1:]},
        {"args": [path("fleet"), "--date-from", "name"] + extra + own,
         "inputs": [path("fleet/axis_2026-11-02.csv"), path("fleet/axis_2026-11-09.csv")] + own[1:]},
    ]

listing = json.loads(run(["help", "--commands"]).stdout)
assert listing["schema"] == 1, listing
commands = {c["command"]: c for c in listing["commands"]}
missing = sorted(set(commands) - set(RUNS))
if missing:
    sys.exit(f"FAIL: no run of {missing} in {__file__}: add one so their outputs are checked")

def digest(p):
    with open(p, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def stat_key(p):
    st = os.lstat(p)
    return (st.st_ino, st.st_size, st.st_mtime_ns, st.st_mode)


# The cases. Every output option of every command is pointed at every input of every run of the
# command, at a hard link and at a symbolic link to an input the seed picks; --overwrite alternates
# from a seeded start, so each option meets both. Of the identify methods (one code path for their
# outputs) one, picked by the seed, gets every case; the others each option at one target the seed
# picks, with or without --overwrite: the whole matrix stays under a minute.
os.makedirs(path("out"))
links = path("links")
os.makedirs(links)
methods = sorted(n for n in commands if n.startswith("identify "))
full_method = rng.choice(methods)
cases = []  # (label args, command, the run's inputs, target, named input, symbolic link or None)
for name, command in sorted(commands.items()):
    outputs = [o["name"] for o in command["options"] if "output" in o]
    for r in RUNS[name]:
        if not r["inputs"]:
            continue
        for opt in outputs:
            if opt in r.get("without", []):
                continue
            hard = os.path.join(links, f"hard{len(os.listdir(links))}.csv")
            os.link(rng.choice(r["inputs"]), hard)
            soft = os.path.join(links, f"soft{len(os.listdir(links))}.json")
            soft_to = rng.choice(r["inputs"])
            os.symlink(soft_to, soft)
            targets = [(p, p, None) for p in r["inputs"]] + [(hard, None, None), (soft, soft_to, (soft, soft_to))]
            if name.startswith("identify ") and name != full_method:
                targets = [rng.choice(targets)]
            overwrite = rng.random() < 0.5
            for target, named_input, link in targets:
                overwrite = not overwrite
                args = name.split() + r["args"]
                for need in r.get("needs", []):
                    if need != opt:
                        args += [need, path(f"out/{len(cases)}" + {"--c": ".h", "--mjcf": ".xml"}.get(need, ".json"))]
                args += [opt, target] + (["--overwrite"] if overwrite else [])
                cases.append((args, name, opt, r["inputs"], target, named_input, link))

all_inputs = sorted({p for c in cases for p in c[3]})
before = {p: digest(p) for p in all_inputs}
stats = {p: stat_key(p) for p in all_inputs}


def one(case):
    args, name, opt, inputs, target, named_input, link = case
    p = run(args, check=False)
    err = p.stderr.decode(errors="replace")
    why = []
    if p.returncode != 2:
        why.append(f"exit {p.returncode}, expected 2")
    if err.count("\n") != 1:
        why.append("not a one-line message")
    if target not in err:
        why.append(f"message does not name the output {target}")
    if named_input is not None and named_input not in err and os.path.realpath(named_input) not in err:
        why.append(f"message does not name the input {named_input}")
    if named_input is None and not any(i in err for i in inputs):  # a hard link: any name of its file
        why.append("message does not name the input the hard link is")
    for q in inputs:
        if not os.path.exists(q) or stat_key(q) != stats[q]:
            why.append(f"input {q} changed")
    if link and (not os.path.islink(link[0]) or os.readlink(link[0]) != link[1]):
        why.append(f"the symbolic link {link[0]} was replaced")
    return f"{' '.join(args)}: {'; '.join(why)}\n    stderr: {err.strip()}" if why else None


# Two at a time: each run is a process start and a few stat calls.
with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
    failures = [f for f in pool.map(one, cases) if f]
for q, h in before.items():
    if digest(q) != h:
        failures.append(f"input {q}: its bytes changed")

# Every output option of every command that reads a file was reached.
covered = {(c[1], c[2]) for c in cases}
for name, command in commands.items():
    if not any(r["inputs"] for r in RUNS[name]):
        continue
    for o in command["options"]:
        if "output" in o and (name, o["name"]) not in covered:
            failures.append(f"{name} {o['name']}: no case reached this output option")

print(f"seed {seed}: {len(cases)} cases over {len(commands)} commands (every case of {full_method})")
if failures:
    print(f"FAIL: {len(failures)} cases")
    print("\n".join(failures))
    sys.exit(1)
print("ok")
