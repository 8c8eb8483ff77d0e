#!/usr/bin/env python3
"""A seeded property over the C export (docs/guarantees.md, "Numbers or an error, never both").

Each case draws a law file (every static and dynamic law with an export), puts one to three of its
parameters, or of its compensation's (--band, --dead-band, --gain, --bandwidth, --inertia), at an
extreme finite value (sign * 10^U(-300, 300), the largest double, 1e308, the edges of float's
range, float's smallest subnormal and below it), chooses --float half the time, and runs
`frictionlab export LAW.json --c H.h`. Then either
  - the export was refused: exit 2, one line on stderr, no header; or
  - exit 0 and the header compiles alone with the system C compiler (`cc -std=c99 -Wall -Werror
    -c`, -Wextra -pedantic too) and in a program that evaluates it: the friction, the friction with
    stiction and the breakaway levels (static laws), a fixed-step run (dynamic laws), the
    feedforward or feedback over a velocity grid and the observers' update. Each value is finite
    wherever the library's own (the Python module's FrictionLaw.sliding, .breakaway and .step,
    in double) is finite and, for a --float header, within float's range; the feedforward and
    feedback are held to that wherever the law's own values are.
Anything else (another exit status, a header that does not compile, an inf or NaN where the
library has a number) fails, printing the case's law, options and header.
Usage: c_export_property.py FRICTIONLAB SOURCE_DIR SCRATCH [CASES [SEED]]
  CASES defaults to FRICTIONLAB_C_EXPORT_CASES or 40 (make test; make fuzz runs more), SEED to
  FRICTIONLAB_PROPERTY_SEED or 25, as the other command-line property tests.
"""
import json
import math
import os
import random
import subprocess
import sys

FLOAT_MAX = 3.4028234663852886e38
# A --float value must stay below float's largest by more than float's rounding of a literal.
FLOAT_SAFE = FLOAT_MAX * (1 - 1e-6)

# Nominal laws: each exports as it stands.
LAWS = [
    {"law": "coulomb", "Fc": 1.0},
    {"law": "viscous", "Fv": 0.4},
    {"law": "coulomb-viscous", "Fc": 1.0, "Fv": 0.4},
    {"law": "static-coulomb-viscous", "Fs": 1.5, "Fc": 1.0, "Fv": 0.4},
    {"law": "stribeck", "Fc": 1.0, "Fs": 1.5, "vs": 0.01, "Fv": 0.4, "delta": 2.0},
    {"law": "karnopp", "Fs": 1.5, "Fc": 1.0, "Fv": 0.4, "dv": 0.001},
    {"law": "smooth", "Fc": 1.0, "Fs": 1.5, "vs": 0.01, "Fv": 0.4, "vt": 0.001},
    {"law": "coulomb-viscous-asymmetric", "Fc_pos": 0.7, "Fv_pos": 0.21, "Fc_neg": 0.9, "Fv_neg": 0.19},
    {"law": "stribeck-asymmetric", "Fc_pos": 1.1, "Fs_pos": 1.6, "vs_pos": 0.002, "delta_pos": 2.0, "Fv_pos": 0.35,
     "Fc_neg": 0.8, "Fs_neg": 1.3, "vs_neg": 0.001, "delta_neg": 1.5, "Fv_neg": 0.45},
    {"law": "table", "velocity": [-1.0, -0.01, 0.01, 1.0], "force": [-1.4, -1.0, 1.0, 1.4]},
    {"law": "lugre", "sigma0": 1e5, "sigma1": 316.2, "sigma2": 0.4, "Fc": 1.0, "Fs": 1.5, "vs": 0.001},
    {"law": "dahl", "sigma0": 1e5, "Fc": 1.0, "alpha": 1.0},
    {"law": "elastoplastic", "sigma0": 1e5, "sigma1": 316.2, "sigma2": 0.4, "Fc": 1.0, "Fs": 1.5, "vs": 0.001,
     "zba": 5e-6},
    {"law": "gms", "Fc": 1.0, "Fs": 1.5, "vs": 0.001, "delta": 2.0, "C": 20.0, "sigma2": 0.4,
     "k": [5e4, 1e5], "alpha": [0.5, 0.5]},
]
DYNAMIC = {"lugre", "dahl", "elastoplastic", "gms"}
# Compensations: option -> nominal value.
COMPENSATIONS = [
    ("", {}),
    ("feedforward", {"--band": 0.002}),
    ("feedback", {"--dead-band": 0.0005}),
    ("lugre-observer", {"--gain": 0.05}),
    ("disturbance-observer", {"--bandwidth": 50.0, "--inertia": 2.5}),
]
VELOCITIES = [0.0, 1e-6, -1e-6, 1e-3, -1e-3, 0.1, -0.1, 1.0, -1.0, 10.0, -10.0]


def extreme(rng):
    sign = -1.0 if rng.random() < 0.5 else 1.0
    pick = rng.random()
    edges = [1.7976931348623157e308, 1e308, FLOAT_MAX, 3.5e38, 1.1754943508222875e-38, 1.401298464324817e-45,
             1e-46, 5e-324, 0.0]
    if pick < 0.35:
        return sign * rng.choice(edges)
    if pick < 0.55:  # near float's range, where --float headers once overflowed
        return sign * 10.0 ** rng.uniform(30, 45)
    return sign * 10.0 ** rng.uniform(-300, 300)


def draw(rng):
    law = json.loads(json.dumps(rng.choice(LAWS)))
    comps = [c for c in COMPENSATIONS if c[0] != "lugre-observer" or law["law"] == "lugre"]
    # Dynamic laws export the observers; feedforward/feedback fit any law.
    comp, opts = rng.choice(comps)
    opts = dict(opts)
    leaves = [("law", k) for k, v in law.items() if k != "law" and not isinstance(v, list)]
    leaves += [("law-list", k) for k, v in law.items() if isinstance(v, list)]
    leaves += [("option", k) for k in opts]
    # Half the draws keep a value's sign and scale it (the laws' rules ask for positive values: a
    # refused sign tests less), half are any extreme value.
    def draw_value(old):
        if old != 0 and rng.random() < 0.5:
            return old * 10.0 ** rng.uniform(-300, 300)
        return extreme(rng)
    for _ in range(rng.randint(1, 3)):
        kind, key = rng.choice(leaves)
        if kind == "law":
            law[key] = draw_value(law[key])
        elif kind == "law-list":
            k = rng.randrange(len(law[key]))
            law[key][k] = draw_value(law[key][k])
        else:
            opts[key] = draw_value(opts[key])
    single = rng.random() < 0.5
    return law, comp, opts, single


def library_values(law_file, single, dynamic):
    """The library's values (double) at the grid, its breakaway levels and a fixed-step run, or
    None when the Python module refuses the law (it reads it as the export does)."""
    import numpy as np

    import frictionlab as fl

    try:
        law = fl.load_law(law_file)
    except ValueError:
        return None
    v = np.array(VELOCITIES)
    out = {"sliding": [float(x) for x in law.sliding(v)]}
    if dynamic:
        forces, _ = law.step(np.full(50, 0.01), 1e-3)
        out["update"] = [float(forces[-1])]
    else:
        pos, neg = law.breakaway
        out["breakaway"] = [float(pos), float(neg)]
    return out


def representable(x, single):
    return math.isfinite(x) and (not single or abs(x) <= FLOAT_SAFE)


def c_program(law, comp, single):
    real = "float" if single else "double"
    grid = ", ".join(repr(v) for v in VELOCITIES)
    lines = ["#include <stdio.h>", '#include "h.h"', "static const double vg[] = {%s};" % grid,
             "int main(void) {", "  unsigned i;"]
    lines.append("  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"sliding %%.17g\\n\", (double)friction_friction((%s)vg[i]));" % real)
    if law["law"] in DYNAMIC:
        lines += ["  { friction_state s; %s f = 0; friction_init(&s);" % real,
                  "    for (i = 0; i < 50; ++i) f = friction_update(&s, (%s)0.01, (%s)1e-3);" % (real, real),
                  "    printf(\"update %.17g\\n\", (double)f); }"]
    else:
        lines += ["  printf(\"breakaway %.17g\\n\", (double)friction_breakaway_pos());",
                  "  printf(\"breakaway %.17g\\n\", (double)friction_breakaway_neg());",
                  "  printf(\"stuck %%.17g\\n\", (double)friction_friction_stuck((%s)0, (%s)0));" % (real, real)]
    if comp in ("feedforward", "feedback"):
        lines.append("  for (i = 0; i < sizeof vg / sizeof vg[0]; ++i) printf(\"%s %%.17g\\n\", (double)friction_%s((%s)vg[i]));"
                     % (comp, comp, real))
    elif comp == "lugre-observer":
        lines += ["  { friction_lugre_observer_state o; %s f = 0; friction_lugre_observer_init(&o, (%s)0);" % (real, real),
                  "    for (i = 0; i < 50; ++i) f = friction_lugre_observer_update(&o, (%s)(1e-5 * i), (%s)0.01, (%s)0, (%s)1e-3);"
                  % (real, real, real, real),
                  "    printf(\"observer %.17g\\n\", (double)f); }"]
    elif comp == "disturbance-observer":
        lines += ["  { friction_disturbance_observer_state o; %s f = 0; friction_disturbance_observer_init(&o, (%s)0);" % (real, real),
                  "    for (i = 0; i < 50; ++i) f = friction_disturbance_observer_update(&o, (%s)0.01, (%s)1, (%s)1e-3);"
                  % (real, real, real),
                  "    printf(\"observer %.17g\\n\", (double)f); }"]
    lines += ["  return 0;", "}"]
    return "\n".join(lines) + "\n"


def run_case(exe, scratch, i, seed):
    rng = random.Random(seed * 1000003 + i)
    law, comp, opts, single = draw(rng)
    d = os.path.join(scratch, "case%d" % i)
    os.makedirs(d, exist_ok=True)
    law_file, header = os.path.join(d, "law.json"), os.path.join(d, "h.h")
    with open(law_file, "w") as f:
        json.dump(law, f)
    args = [exe, "export", law_file, "--c", header]
    if comp:
        args += ["--compensation", comp]
    for k, v in opts.items():
        args += [k, repr(v)]
    if single:
        args.append("--float")
    what = "case %d (seed %d): %s %s" % (i, seed, json.dumps(law), " ".join(args[5:]))
    p = subprocess.run(args, capture_output=True, text=True, env=dict(os.environ, FRICTIONLAB_NO_PROGRESS="1"),
                       timeout=60)
    if p.returncode == 2:
        lines = p.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith("frictionlab: error: "), (what, p.stderr)
        assert not os.path.exists(header), (what, "a refused export left its header")
        if os.environ.get("FRICTIONLAB_PROPERTY_VERBOSE"):
            print("refused:", p.stderr.strip())
        return "refused"
    assert p.returncode == 0, (what, "exit %d" % p.returncode, p.stderr)
    text = open(header).read()
    cc = ["cc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]
    c = subprocess.run(cc + ["-x", "c", "-c", header, "-o", os.path.join(d, "h.o")], capture_output=True, text=True)
    assert c.returncode == 0, (what, "the header does not compile", c.stderr, text)
    with open(os.path.join(d, "main.c"), "w") as f:
        f.write(c_program(law, comp, single))
    prog = os.path.join(d, "prog")
    c = subprocess.run(cc + ["-O1", "-o", prog, os.path.join(d, "main.c"), "-lm"], capture_output=True, text=True, cwd=d)
    assert c.returncode == 0, (what, "the program does not compile", c.stderr, text)
    r = subprocess.run([prog], capture_output=True, text=True, timeout=30)
    assert r.returncode == 0, (what, "the program failed", r.returncode, r.stderr)
    got = {}
    for line in r.stdout.splitlines():
        name, value = line.split()
        got.setdefault(name, []).append(float(value))
    lib = library_values(law_file, single, law["law"] in DYNAMIC)
    assert lib is not None, (what, "exported a law the library refuses")
    law_ok = all(representable(x, single) for x in lib["sliding"] + lib.get("breakaway", []))
    for name, values in got.items():
        for k, x in enumerate(values):
            if name in lib:
                expected_finite = representable(lib[name][k], single)
            elif name in ("feedforward", "feedback"):
                expected_finite = law_ok and representable(lib["sliding"][k], single)
            elif name == "stuck":
                expected_finite = law_ok
            else:  # an observer's 50 steps at an extreme gain may legitimately diverge
                expected_finite = False
            assert math.isfinite(x) or not expected_finite, (
                what, "%s[%d] = %r where the library has %r" % (name, k, x, lib.get(name, lib["sliding"])[k]), text)
    return "exported"


def main():
    exe, src, scratch = sys.argv[1], sys.argv[2], sys.argv[3]
    cases = int(sys.argv[4]) if len(sys.argv) > 4 else int(os.environ.get("FRICTIONLAB_C_EXPORT_CASES", "40"))
    seed = int(sys.argv[5]) if len(sys.argv) > 5 else int(os.environ.get("FRICTIONLAB_PROPERTY_SEED", "25"))
    # The Python module of the same build: the tool is BUILD/app/frictionlab.
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(exe))), "python"))
    counts = {"refused": 0, "exported": 0}
    failures = []
    for i in range(cases):
        try:
            counts[run_case(exe, scratch, i, seed)] += 1
        except AssertionError as e:
            failures.append(e)
            print("FAIL:", *(str(x)[:3000] for x in (e.args[0] if e.args and isinstance(e.args[0], tuple) else e.args)),
                  sep="\n  ")
    print("c export property: %d cases (seed %d): %d exported and compiled, %d refused, %d failed"
          % (cases, seed, counts["exported"], counts["refused"], len(failures)))
    assert not failures, "%d cases failed (above)" % len(failures)
    # The draw must reach both outcomes, or it tests less than it says.
    assert cases < 20 or (counts["exported"] >= cases // 10 and counts["refused"] >= cases // 10), counts


if __name__ == "__main__":
    main()
