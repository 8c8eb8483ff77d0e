"""Every kind of figure frictionlab draws, made from the bundled data and examples in a scratch
directory: the command line's --plot and --report figures (gnuplot SVG, each with its .gp script
next to it) and the Python package's frictionlab.plot figures (matplotlib SVG, text kept as text).

Used by check_figures.py (the geometry test, ctest figures.geometry) and by scripts/gallery.py
(docs/gallery.md). make_all(exe, src, out) returns a list of Figure records in drawing order.

Run alone:  python3 tests/figures/make_figures.py build/app/frictionlab . OUT_DIR
"""
import dataclasses
import os
import pathlib
import subprocess
import sys


@dataclasses.dataclass
class Figure:
    name: str           # short name, unique: "identify-idim", "plot.sweep", ...
    svg: pathlib.Path   # the SVG file
    command: str        # the command (or Python call) that drew it, as a reader would type it
    kind: str           # "gnuplot" (command line) or "matplotlib" (frictionlab.plot)
    labels: list = dataclasses.field(default_factory=list)  # axis labels as written (gnuplot: from the .gp)


def _run(args, cwd):
    done = subprocess.run(args, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        raise RuntimeError("figure command failed (exit %d): %s\n%s" % (done.returncode, " ".join(map(str, args)),
                                                                      done.stderr[-2000:]))


def gnuplot_labels(script):
    """The axis labels a gnuplot script sets (set xlabel "..." / set ylabel "..."), in order."""
    import re

    labels = []
    for line in pathlib.Path(script).read_text().splitlines():
        m = re.match(r'set ([xy])label "((?:[^"\\]|\\.)*)"', line) or re.match(r"set ([xy])label '([^']*)'", line)
        if m and m.group(2):
            labels.append(m.group(2).replace('\\"', '"'))
    return labels


# The command-line figures: (stage, name, what goes after the executable, the SVG files it writes,
# relative to the scratch directory). {src} is the source tree. Stage 0 makes the inputs stage 1
# reads; the commands of a stage run side by side.
def _cli_jobs(src):
    emps = f"{src}/data/emps"
    ex = f"{src}/examples"
    cols = "--time t --position qm --input vir --gain gtau"
    return [
        (0, "simulate-trapezoid", f"simulate {ex}/craig_motor_trapezoid.yaml -o trap.csv --plot simulate-trapezoid.svg",
         ["simulate-trapezoid.svg"]),
        (0, "simulate-stick-slip", f"simulate {ex}/canudas_stick_slip.yaml -o ss.csv --plot simulate-stick-slip.svg",
         ["simulate-stick-slip.svg"]),
        (0, "simulate-xy-circle", f"simulate {ex}/xy_circle.yaml -o circle.csv --plot simulate-xy-circle.svg",
         ["simulate-xy-circle.svg"]),
        (0, None, f"simulate {ex}/virgala_motor_sweep.yaml -o sweep.csv", []),
        (0, None, f"simulate {ex}/craig_pendulum_combined.yaml -o pend.csv", []),
        (0, "identify-idim", f"identify idim {emps}/DATA_EMPS.mat {cols} --validate {emps}/DATA_EMPS_PULSES.mat "
                             f"--json model.json --plot identify-idim.svg --report report-idim",
         ["identify-idim.svg", "report-idim/fit.svg", "report-idim/friction-map.svg", "report-idim/cross-test.svg"]),
        (0, "identify-idim-conditions", "identify idim effects.csv --current current --kt 0.5 --resample "
                                        "--terms inertia,viscous,coulomb,offset,load,temperature,ripple --load load "
                                        "--temperature temperature --ripple-period 0.02 --exclude-below 0.002 "
                                        "--report report-conditions",
         ["report-conditions/load-map.svg", "report-conditions/ripple.svg", "report-conditions/temperature.svg"]),
        (0, "analyze-map-1d", f"analyze map {ex}/map_pid_hunting.yaml --vary friction.Fs=1:2:6 -o map1.csv "
                              f"--plot analyze-map-1d.svg", ["analyze-map-1d.svg"]),
        (0, "analyze-map-2d", f"analyze map {ex}/map_spring_block.yaml --vary plant.V0=log:0.004:0.2:6 "
                              f"--vary plant.c=0:8:4 -o map2.csv --plot analyze-map-2d.svg", ["analyze-map-2d.svg"]),
        (0, "identify-drift", "identify sweep --resample --axis rotary --model coulomb-viscous fleet/axis3_2026-11-0?.csv "
                              "--date-from name --table fleet.csv --drift drift.csv --drift-threshold 3 "
                              "--plot identify-drift.svg", ["identify-drift.svg"]),
        (0, "identify-lugre", "identify lugre lugre.csv --force applied --inertia 1 --plot identify-lugre.svg",
         ["identify-lugre.svg"]),
        (0, "identify-auto", "identify auto servo.csv --names time,position,q_ref,v_est,current --kt 0.5 --resample "
                             "--plot identify-auto.svg", ["identify-auto.svg"]),
        (1, "identify-breakaway", "identify breakaway trap.csv --kt 0.0141 --axis rotary --plot identify-breakaway.svg",
         ["identify-breakaway.svg"]),
        (1, "identify-sweep", "identify sweep sweep.csv --kt 0.039 --axis rotary --plot identify-sweep.svg", ["identify-sweep.svg"]),
        (1, "identify-decay", "identify decay pend.csv --stiffness 9.81 --pendulum --axis rotary "
                              "--plot identify-decay.svg", ["identify-decay.svg"]),
        (1, "analyze-envelope", "analyze envelope pend.csv --plot analyze-envelope.svg", ["analyze-envelope.svg"]),
        (1, "analyze-stick-slip", "analyze stick-slip ss.csv --plot analyze-stick-slip.svg", ["analyze-stick-slip.svg"]),
        (1, "analyze-contour", "analyze contour circle.csv --plot analyze-contour.svg", ["analyze-contour.svg"]),
        (1, "validate-emps", f"validate model.json {emps}/DATA_EMPS_PULSES.mat --scenario {ex}/emps_closed_loop.yaml "
                             f"{cols} --plot validate-emps.svg", ["validate-emps.svg"]),
    ]


def _write_lugre_record(exe, out):
    """lugre.csv: Canudas de Wit et al. 1995 Table I on a unit mass, a presliding force ramp to
    0.95 Fs and back, then a force sine of amplitude 2 Fs (the record identify lugre's test uses)."""
    import math

    times, values = [0.0, 2.0, 4.0], [0.0, 1.425, 0.0]
    for i in range(1, 301):
        t = 4.0 + 0.02 * i
        times.append(round(t, 6))
        values.append(3.0 * math.sin(math.pi * (t - 4.0)))
    scenario = out / "lugre.yaml"
    scenario.write_text(
        "description: Canudas de Wit 1995 Table I, presliding then sliding\n"
        "plant:\n  type: axis\n  M: 1.0\n"
        "friction:\n  law: lugre\n  sigma0: 1.0e5\n  sigma1: 316.22776601683796\n  sigma2: 0.4\n"
        "  Fc: 1.0\n  Fs: 1.5\n  vs: 0.001\n"
        "input:\n  type: table\n  times: [%s]\n  values: [%s]\n" % (", ".join(map(repr, times)), ", ".join(map(repr, values)))
        + "duration: 10\noutput_rate: 1000\n")
    _run([os.path.abspath(exe), "simulate", str(scenario), "-o", str(out / "lugre.csv"), "--overwrite"], out)


JOBS = 3  # commands side by side: the slowest (the EMPS validation, a map) bound the time


def make_cli(exe, src, out):
    import concurrent.futures
    import glob
    import shlex

    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    _run([sys.executable, f"{src}/examples/fleet_logs.py", str(out / "fleet")], out)
    _run([sys.executable, f"{src}/tests/rigs/servo_log.py", str(out / "servo.csv")], out)
    _run([sys.executable, f"{src}/tests/rigs/effects_log.py", str(out / "effects.csv"), "--seed", "4"], out)
    _write_lugre_record(exe, out)

    def argv(args):
        words = [str(exe)]
        for word in shlex.split(args):
            matched = sorted(glob.glob(str(out / word))) if "?" in word else []
            words += [os.path.relpath(m, out) for m in matched] if matched else [word]
        return words + ["--overwrite"]

    jobs = _cli_jobs(src)
    with concurrent.futures.ThreadPoolExecutor(JOBS) as pool:
        for stage in (0, 1):
            for f in [pool.submit(_run, argv(args), out) for st, _, args, _ in jobs if st == stage]:
                f.result()
    figures = []
    for _, name, args, svgs in jobs:
        for svg in svgs:
            path = out / svg
            figures.append(Figure(name if svg == svgs[0] else f"{name}:{pathlib.Path(svg).stem}", path,
                                  "frictionlab " + args.replace(f"{src}/", ""), "gnuplot", gnuplot_labels(f"{path}.gp")))
    return figures


def make_python(src, out, png_width=None, records=None):
    """frictionlab.plot's figures as SVG with text kept as text (svg.fonttype 'none'); with
    png_width (px) also as PNG of that width next to each SVG (the gallery's images)."""
    import matplotlib

    matplotlib.use("Agg")
    matplotlib.rcParams["svg.fonttype"] = "none"
    import matplotlib.pyplot as plt

    import frictionlab as fl

    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    figures = []

    def save(name, fig, call):
        path = out / f"{name}.svg"
        label_gids(fig)
        fig.savefig(path)
        if png_width:
            fig.savefig(path.with_suffix(".png"), dpi=png_width / fig.get_figwidth())
        labels = [a.get_xlabel() for a in fig.axes if a.get_xlabel()] + [a.get_ylabel() for a in fig.axes if a.get_ylabel()]
        figures.append(Figure(name, path, call, "matplotlib", labels))
        plt.close(fig)

    ex = pathlib.Path(src) / "examples"
    # The records the command line simulated (make_cli), read back; else simulated here.
    rec = (lambda csv, yaml: fl.load(str(pathlib.Path(records) / csv))) if records else \
        (lambda csv, yaml: fl.simulate(str(ex / yaml)))
    sw = rec("sweep.csv", "virgala_motor_sweep.yaml")
    r = fl.identify_sweep(sw["time"], 0.039 * sw["current"], sw["velocity"], model="coulomb-viscous", axis="rotary")
    save("plot.sweep", fl.plot.sweep(r), "fl.plot.sweep(fl.identify_sweep(...))")
    emps = fl.load(str(pathlib.Path(src) / "data/emps/DATA_EMPS.mat"))
    ri = fl.identify_idim(emps["t"], emps["gtau"] * emps["vir"], position=emps["qm"], source=emps)
    save("plot.idim", fl.plot.idim(ri), "fl.plot.idim(fl.identify_idim(...))")
    pend = rec("pend.csv", "craig_pendulum_combined.yaml")
    save("plot.simulation", fl.plot.simulation(pend), "fl.plot.simulation(fl.simulate(...))")
    save("plot.decay", fl.plot.decay(pend), "fl.plot.decay(fl.simulate(...))")
    tr = rec("trap.csv", "craig_motor_trapezoid.yaml")
    rb = fl.identify_breakaway(tr["time"], 0.0141 * tr["current"], tr["velocity"], axis="rotary")
    save("plot.breakaway", fl.plot.breakaway(rb), "fl.plot.breakaway(fl.identify_breakaway(...))")
    c = rec("circle.csv", "xy_circle.yaml")
    rc = fl.analyze_contour(c["time"], c["x.position"], c["y.position"], c["x.reference"], c["y.reference"])
    save("plot.contour", fl.plot.contour(rc), "fl.plot.contour(fl.analyze_contour(...))")
    rows = fl.analyze_map(str(ex / "map_spring_block.yaml"), ["plant.V0=log:0.004:0.2:4", "plant.c=0:8:3"],
                          jobs=2)
    save("plot.map", fl.plot.map(rows, units={"plant.V0": "m/s", "plant.c": "N s/m"}),
         "fl.plot.map(fl.analyze_map('examples/map_spring_block.yaml', ['plant.V0=log:0.004:0.2:4', "
         "'plant.c=0:8:3']), units={'plant.V0': 'm/s', 'plant.c': 'N s/m'})")
    # The condition terms' figures: idim on the ball-screw log with load, temperature and ripple
    # (tests/rigs/effects_log.py), the record the command line's identify-idim-conditions reads.
    effects = pathlib.Path(records) / "effects.csv" if records else out / "effects.csv"
    if not records:
        _run([sys.executable, f"{src}/tests/rigs/effects_log.py", str(effects), "--seed", "4"], out)
    e = fl.load(str(effects), resample=True)
    rt = fl.identify_idim(e["time"], 0.5 * e["current"], position=e["position"], load=e["load"],
                          temperature=e["temperature"], ripple_period=0.02, exclude_below=0.002,
                          terms=["inertia", "viscous", "coulomb", "offset", "load", "temperature", "ripple"])
    call = "fl.identify_idim(..., terms=[..., 'load', 'temperature', 'ripple'], load=..., temperature=..., ripple_period=0.02)"
    save("plot.load_map", fl.plot.load_map(rt), f"fl.plot.load_map({call})")
    save("plot.ripple", fl.plot.ripple(rt), f"fl.plot.ripple({call})")
    save("plot.temperature", fl.plot.temperature(rt), f"fl.plot.temperature({call})")
    return figures


def label_gids(fig):
    """Ids on what the geometry test measures (legend, axis labels, tick labels), so that the
    rendered SVG names them: fl-legend-A, fl-xlabel-A, fl-ylabel-A, fl-tick-A-N (A: axes index)."""
    for a, ax in enumerate(fig.axes):
        ax.xaxis.label.set_gid(f"fl-xlabel-{a}")
        ax.yaxis.label.set_gid(f"fl-ylabel-{a}")
        if ax.get_legend() is not None:
            ax.get_legend().set_gid(f"fl-legend-{a}")
        n = 0
        for t in list(ax.get_xticklabels()) + list(ax.get_yticklabels()):
            if t.get_text():
                t.set_gid(f"fl-tick-{a}-{n}")
                n += 1
    for k, leg in enumerate(fig.legends):
        leg.set_gid(f"fl-legend-f{k}")


def make_all(exe, src, out, python=True, png_width=None):
    out = pathlib.Path(out)
    figures = make_cli(exe, src, out / "cli")
    if python:
        figures += make_python(src, out / "python", png_width, records=out / "cli")
    return figures


def redraw_python(fig, dest, width):
    """The PNG make_python wrote next to a matplotlib figure's SVG (make_all(png_width=width))."""
    import shutil

    shutil.copyfile(fig.svg.with_suffix(".png"), dest)


if __name__ == "__main__":
    for f in make_all(sys.argv[1], sys.argv[2], sys.argv[3]):
        print(f.name, f.svg, f.labels)
