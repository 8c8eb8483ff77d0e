#!/usr/bin/env python3
"""Coverage of idim's standard deviations on synthetic rigs with known friction.

For each cell (friction kind, noise, sensor, sample rate, open or closed loop, the terms fitted)
it makes `--cases` seeded logs with coverage_rigs.py (numpy only, independent of frictionlab's
simulator), identifies each through the Python package and counts, per parameter, how often the
reported 95 % interval value +- 1.96 std holds the truth; the same for std_ols (the ordinary
least-squares figure). A cell whose model can represent the rig must cover each parameter in at
least 90 % of the cases, or else pass a one-sided binomial test at the 1 % level against the
nominal 95 % (with 100 cases: 89 hits pass, 88 fail; an honest 95 % interval fails it with
probability below 0.01). The cases are seeded, so the verdict is repeatable.
Cells where least squares is biased (a closed loop whose disturbance the loop reacts to, a
Stribeck rig fitted without the Stribeck term) are reported, not asserted: widening the std does
not fix a bias. There the adequacy checks should speak, and the table says how often they do.

The cell "effects" is the ball-screw log of effects_log.py (a 1 kHz PD loop against a measured
load, with a temperature drift and a position ripple; jittered time put on the grid as the command
line's --resample does), fitted with the terms load, temperature and ripple. Its motion does not
depend on the seed (the seed draws the time jitter and the sensors' noise), so a systematic error
of the fit (the rig's integration, the filter) is the same in every case and shows as a bias.
The cell measures that part: the fit of the same log without time jitter and sensor noise
("systematic error / std": its error over the mean reported std of the noisy cases). Parameters
whose systematic error is comparable to their std are reported, not asserted (Cell.reported):
widening the std does not fix a bias.

Usage: idim_coverage.py [--cells fast|all|effects|iv|closed] [--cases N] [--markdown OUT.md]
                        [--compare docs/coverage.md]
Exit status 1 when a cell expected to cover does not (the cell and parameter named), or with
--compare when a row made differs from the page's (coverage_table.py: the cell and column named,
with both texts; rows run with another number of cases than the page's are not compared; with
--cells all every row of the page must have been made).
Needs the frictionlab package on PYTHONPATH (build/python) and numpy/scipy.
"""
import argparse
import os
import pathlib
import platform
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import coverage_rigs as rigs  # noqa: E402
import coverage_table  # noqa: E402
import effects_log  # noqa: E402

import frictionlab as fl  # noqa: E402

REQUIRED = 0.90  # least share of cases whose 95 % interval holds the truth, per parameter ...
BINOMIAL_LEVEL = 0.01  # ... unless P(hits <= observed | 95 % coverage) is at least this
Z95 = 1.959963984540054

STRIBECK_TERMS = "inertia,viscous,coulomb,offset,stribeck"
ASYMMETRIC_TERMS = "inertia,asymmetric"
EFFECTS_TERMS = "inertia,viscous,coulomb,offset,load,temperature,ripple"
# The effects cell's options: the rig's ripple period, and samples below 2 mm/s left out (the axis
# rests at whole ripple periods, where a stuck contact's force is not the model's).
EFFECTS_OPTIONS = {"ripple_period": effects_log.P, "exclude_below": 0.002}


class Cell:
    def __init__(self, kind, noise, sensor, fs, loop="open", terms=None, options=None, expect="covers", note="",
                 velocity_noise=rigs.VELOCITY_NOISE, max_cases=None, reported=None, method="ls"):
        self.kind, self.noise, self.sensor, self.fs, self.loop = kind, noise, sensor, fs, loop
        self.method = method  # "ls" (IDIM-LS) or "iv" (IDIM-IV with the rig's controller)
        self.velocity_noise = velocity_noise
        self.terms = terms or {"stribeck": STRIBECK_TERMS, "asymmetric": ASYMMETRIC_TERMS,
                               "effects": EFFECTS_TERMS}.get(kind)
        self.max_cases = max_cases  # at most this many cases, whatever --cases says (None: no cap)
        # {parameter: why}: parameters of a "covers" cell that are reported, not asserted
        self.reported = dict(reported or {})
        self.options = dict(options or {})
        self.expect = expect  # "covers" (asserted) or "biased" (reported)
        self.note = note

    @property
    def name(self):
        if self.kind == "effects":
            return (f"effects (load, temperature, ripple), ar1 current noise, position, "
                    f"{self.fs:g} Hz resampled, {self.loop}")
        fitted = " (fit without its term)" if self.kind == "stribeck" and "stribeck" not in self.terms else ""
        extra = "".join(f" {k}={v}" for k, v in self.options.items())
        sensor = self.sensor if self.sensor == "position" else f"velocity ({1e3 * self.velocity_noise:g} mm/s noise)"
        method = " iv" if self.method == "iv" else ""
        return f"{self.kind}{fitted}, {self.noise}, {sensor}, {self.fs:g} Hz, {self.loop}{method}{extra}"


def all_cells():
    cells = []
    for kind in ("coulomb-viscous", "stribeck", "asymmetric"):
        for noise in ("white", "ar1"):
            for sensor in ("position", "velocity"):
                for fs in (100, 1000, 8000):
                    cells.append(Cell(kind, noise, sensor, fs))
    for fs in (100, 1000):
        cells.append(Cell("coulomb-viscous", "white", "velocity", fs, velocity_noise=2e-3, expect="biased",
                          note="noise in the regressors (errors in variables)"))
    for noise in ("white", "ar1"):
        cells.append(Cell("stribeck", noise, "position", 1000, terms="inertia,viscous,coulomb,offset",
                          expect="biased", note="model lacks the Stribeck term"))
    # A white disturbance the loop reacts to biases least squares' M (by -0.9 std on average, 89 % of
    # 100 cases: at the binomial test's edge, so reported, not asserted); an AR(1) one's wider std
    # covers it. IDIM-IV (iv_cell) removes part of it and covers.
    for noise, expect in (("white", "biased"), ("ar1", "covers")):
        cells.append(Cell("coulomb-viscous", noise, "position", 1000, loop="closed", expect=expect,
                          note="the loop reacts to the disturbance"))
        cells.append(Cell("coulomb-viscous", noise, "position", 1000, loop="closed", options={"exclude_below": 0.005},
                          expect=expect, note="the loop reacts to the disturbance"))
    cells.append(effects_cell())
    # IDIM-IV with the rig's own controller on the white cell (docs/coverage.md says what it removes).
    cells.append(iv_cell("white"))
    return cells


# The effects cell's parameters with a systematic error of the order of their std (measured on the
# noise-free log, the same in every case), reported and not asserted. Fv_per_K: the temperature
# rises with time while the speed schedule changes over the run, so any velocity-dependent error of
# the pipeline that is uneven in time (the 100 Hz filter's lag in the fast moves, the samples left
# out near standstill) is taken for a temperature effect. load_gain (and offset, which carries
# load_gain times the mean load): a systematic error of the same kind, of order 1e-4 of the load.
EFFECTS_REPORTED = {
    "Fv_per_K": "confounded with the speed schedule (the temperature rises with time)",
    "load_gain": "systematic error of the fixed motion, about 1e-4 of the load",
    "offset": "carries load_gain's error times the mean load",
}


def effects_cell(max_cases=None):
    """The load, temperature and ripple terms on effects_log.py's rig (closed loop, 1 kHz)."""
    return Cell("effects", "ar1", "position", 1000, loop="closed", options=EFFECTS_OPTIONS, max_cases=max_cases,
                reported=EFFECTS_REPORTED)


def iv_cell(noise="white"):
    """The closed-loop cell identified by IDIM-IV with the rig's controller; every parameter asserted.
    The rig's timing is the one IDIM and the IV simulation assume (coverage_rigs.py, timing
    "centre": the force applied at the sample the controller reads, the position latched at the
    centre of the hold); with the earlier rig's (the position at the hold's end) M was biased by
    -2 % whatever the estimator, and covered in 6 % of the cases (docs/coverage.md)."""
    return Cell("coulomb-viscous", noise, "position", 1000, loop="closed", method="iv", note="")


def iv_options(log):
    """identify_idim's keywords for IDIM-IV on a closed-loop log of coverage_rigs: its PD (Kp, Kd),
    reference and feedforward."""
    return {"iv": True, "controller": "pid", "kp": rigs.KP, "kd": rigs.KD, "reference": log["reference"],
            "feedforward": log["feedforward"]}


def fast_cells():
    """The subset `make test` runs: each friction kind, both noises, both sensors, the three
    rates, and 20 cases of the effects cell (its fixed motion is simulated once, about 1 s of CPU)."""
    return [Cell("coulomb-viscous", "ar1", "position", 1000), Cell("coulomb-viscous", "white", "velocity", 100),
            Cell("stribeck", "ar1", "velocity", 1000), Cell("asymmetric", "ar1", "position", 100),
            Cell("coulomb-viscous", "ar1", "position", 8000), effects_cell(max_cases=20)]


_EFFECTS_MOTION = []  # effects_log.simulate()'s output, made once (it does not depend on the seed)


def effects_truth(temperature_ref):
    """What idim reports on effects_log.py's rig, by name (SI); Fv at temperature_ref (degC)."""
    e = effects_log
    return {"M": e.M, "Fv": e.FV + e.FV_PER_K * (temperature_ref - e.T0), "Fc": e.FC, "offset": 0.0,
            "load_gain": 1.0, "mu_load": e.MU_LOAD, "Fv_per_K": e.FV_PER_K, "ripple_sin_1": e.A1,
            "ripple_cos_1": e.B1}


def identify_effects(cell, seed, noise=True):
    """One case of the effects cell: the log written and read back as the command line reads it
    (--resample), identified; returns the result and the truth. noise=False: the log without
    time jitter and sensor noise."""
    if not _EFFECTS_MOTION:
        _EFFECTS_MOTION.append(effects_log.simulate())
    log = effects_log.make_log(seed, _EFFECTS_MOTION[0], noise=noise)
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "effects.csv")
        effects_log.write_csv(path, log)
        data = fl.load(path, resample=True)
    r = fl.identify_idim(data["time"], data["current"] * effects_log.KT, position=data["position"],
                         load=data["load"], temperature=data["temperature"], terms=cell.terms.split(","),
                         **cell.options)
    if not r.ok:
        raise RuntimeError(f"{cell.name}, seed {seed}: {r.message}")
    return r, effects_truth(r.diagnostics.numbers["temperature_ref"])


def run_cell(cell, cases, seed0=1):
    if cell.max_cases is not None:
        cases = min(cases, cell.max_cases)
    if cell.kind == "effects":
        row = run_cases(cell, cases, seed0, identify_effects)
        r, truth = identify_effects(cell, seed0, noise=False)
        row["systematic"] = {k: (r.parameters[k].value - truth[k]) / row["mean_std"][k] for k in truth}
        return row
    return run_cases(cell, cases, seed0, identify_rig)


def identify_rig(cell, seed):
    """One case of a coverage_rigs.py cell: the log made and identified; the result and the truth."""
    truth = rigs.truth(cell.kind)
    if cell.terms is not None and cell.kind == "stribeck" and "stribeck" not in cell.terms:
        truth = {k: v for k, v in truth.items() if k != "Fs_minus_Fc"}
    log, _ = rigs.make_log(cell.kind, cell.noise, cell.sensor, cell.fs, cell.loop, seed,
                           velocity_noise=cell.velocity_noise)
    # The logs end in motion: drop as many samples at the end as the rate's default skips at
    # the start (the zero-phase filter's transient and the one-sided differences there).
    opts = dict(cell.options, skip_end=fl._core.idim_rate_defaults(cell.fs)["skip"])
    if cell.terms is not None:
        opts["terms"] = cell.terms.split(",")
    if cell.method == "iv":
        opts.update(iv_options(log))
    r = fl.identify_idim(log["time"], log["force"], position=log.get("position"), velocity=log.get("velocity"),
                         **opts)
    if not r.ok:
        raise RuntimeError(f"{cell.name}, seed {seed}: {r.message}")
    return r, truth


def run_cases(cell, cases, seed0, identify):
    """Identifies `cases` seeded logs of `cell` with identify(cell, seed) -> (result, truth) and
    counts the hits of each parameter's interval."""
    hit = hit_ols = z = None
    findings = 0
    bandwidths = []
    stds = {}
    for i in range(cases):
        seed = seed0 + 1000 * i
        r, truth = identify(cell, seed)
        if hit is None:
            hit, hit_ols, z = ({k: 0 for k in truth}, {k: 0 for k in truth}, {k: [] for k in truth})
        for k in truth:
            stds.setdefault(k, []).append(r.parameters[k].std)
        for k, true in truth.items():
            p = r.parameters[k]
            hit[k] += abs(p.value - true) <= Z95 * p.std
            hit_ols[k] += abs(p.value - true) <= Z95 * p.std_ols
            z[k].append((p.value - true) / p.std)
        findings += r.diagnostics.groups.get("adequacy", {}).get("findings", 0) > 0
        bandwidths.append(r.diagnostics.numbers["covariance_bandwidth"])
    return {"cell": cell, "cases": cases, "coverage": {k: hit[k] / cases for k in truth},
            "coverage_ols": {k: hit_ols[k] / cases for k in truth},
            "bias": {k: float(np.mean(z[k])) for k in truth},
            "mean_std": {k: float(np.mean(stds[k])) for k in truth},
            "findings": findings / cases, "bandwidth": float(np.median(bandwidths))}


def covers(share, cases):
    """The cell's verdict for one parameter: at least REQUIRED, or not rejected by a one-sided
    binomial test at BINOMIAL_LEVEL against 95 %."""
    from scipy.stats import binom

    return share >= REQUIRED or binom.cdf(round(share * cases), cases, 0.95) >= BINOMIAL_LEVEL


def markdown(rows, cases, seconds):
    out = ["| cell | cases | coverage of value ± 1.96 std (std_ols), per parameter | mean bias / std | "
           "adequacy finding | bandwidth | verdict |", "|---|---|---|---|---|---|---|"]
    for row in rows:
        c = row["cell"]
        cov = ", ".join(f"{k} {100 * row['coverage'][k]:.0f} ({100 * row['coverage_ols'][k]:.0f})" for k in row["coverage"])
        bias = ", ".join(f"{k} {row['bias'][k]:+.1f}" for k in row["bias"])
        if "systematic" in row:
            bias += "; systematic error / std: " + ", ".join(f"{k} {v:+.1f}" for k, v in row["systematic"].items())
        asserted = {k: v for k, v in row["coverage"].items() if k not in c.reported}
        ok = all(covers(v, row["cases"]) for v in asserted.values())
        verdict = ("covers" if ok else "**fails**") if c.expect == "covers" else \
            ("covers, but reported, not asserted: " + c.note if ok else "biased: " + c.note)
        # A cell that covers only by the binomial test says so, with its lowest count.
        low = min(asserted.values(), default=1.0)
        if c.expect == "covers" and ok and low < REQUIRED:
            verdict += f" ({round(low * row['cases'])} of {row['cases']} passes the binomial test at 1 %)"
        if c.reported:
            verdict += "; reported, not asserted: " + "; ".join(f"{k} ({why})" for k, why in c.reported.items())
        out.append(f"| {c.name} | {row['cases']} | {cov} | {bias} | {100 * row['findings']:.0f} % | "
                   f"{row['bandwidth']:g} | {verdict} |")
    out.append("")
    out.append(f"{len(rows)} cells, {cases} cases each (a cell's own cap aside), {seconds:.0f} s on {os.cpu_count()} cores "
               f"({platform.machine()}), frictionlab {fl.__version__}.")
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cells", choices=["fast", "all", "effects", "iv", "closed"], default="fast",
                    help="fast: make test's subset; all: the whole table; effects, iv: that cell alone; closed: the "
                         "closed-loop cells of coverage_rigs.py (least squares and IV)")
    ap.add_argument("--cases", type=int, default=100)
    ap.add_argument("--markdown", help="write the table here (Markdown)")
    ap.add_argument("--compare", metavar="PAGE", help="compare the rows made with PAGE's table (docs/coverage.md)")
    a = ap.parse_args()
    cells = {"fast": fast_cells, "all": all_cells, "effects": lambda: [effects_cell()], "iv": lambda: [iv_cell()],
             "closed": lambda: [c for c in all_cells() if c.loop == "closed" and c.kind != "effects"]}[a.cells]()
    rows, failures = [], []
    start = time.time()
    for cell in cells:
        t0 = time.time()
        row = run_cell(cell, a.cases)
        rows.append(row)
        low = {k: v for k, v in row["coverage"].items() if not covers(v, row["cases"]) and k not in cell.reported}
        line = ", ".join(f"{k} {100 * v:.0f} % ({100 * row['coverage_ols'][k]:.0f} %)" for k, v in row["coverage"].items())
        systematic = ""
        if "systematic" in row:
            systematic = "; systematic error / std: " + ", ".join(f"{k} {v:+.1f}" for k, v in row["systematic"].items())
        print(f"{cell.name}: {row['cases']} cases: {line}; findings {100 * row['findings']:.0f} %; L {row['bandwidth']:g}"
              f"{systematic}; {time.time() - t0:.1f} s", flush=True)
        if cell.expect == "covers" and low:
            failures.append(f"{cell.name}: " + ", ".join(f"{k} covered in {100 * v:.0f} % of {row['cases']} cases, expected "
                                                         f">= {100 * REQUIRED:.0f} % (or a binomial test at the 1 % level)"
                                                         for k, v in low.items()))
    table = markdown(rows, a.cases, time.time() - start)
    if a.markdown:
        pathlib.Path(a.markdown).write_text(table)
    if a.compare:
        differ, compared, notes = coverage_table.compare(table, pathlib.Path(a.compare).read_text(encoding="utf-8"),
                                                         a.compare, complete=a.cells == "all")
        for n in notes:
            print(f"{a.compare}: {n}")
        print(f"{a.compare}: {compared} rows compared, {len(differ)} differences", flush=True)
        failures += differ
    for f in failures:
        print("FAIL", f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
