"""docs/gallery.md and its images: every kind of figure frictionlab draws, made from the bundled
data and examples by tests/figures/make_figures.py (the figures the geometry test measures), each
with the command that draws it.

The command line's figures are drawn again from their own .gp scripts as PNG (gnuplot pngcairo,
the SVG's size scaled to GALLERY_WIDTH), the Python package's with matplotlib at the same width,
so that the committed images stay small (docs/gallery/*.png).

Usage: python3 scripts/gallery.py BUILD_DIR [SOURCE_DIR]   (make gallery)
"""
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

GALLERY_WIDTH = 760  # px: a documentation page's column
PALETTE = 48  # colours of each image (shrink)

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests" / "figures"))
import make_figures  # noqa: E402

WHAT = {  # a line on what each figure shows, by name
    "simulate-trapezoid": "A simulated DC motor under a current trapezoid: position, velocity, friction, with exact stick.",
    "simulate-stick-slip": "The LuGre stick-slip rig of Canudas de Wit et al. (1995), simulated.",
    "simulate-xy-circle": "A two-axis table's circular test, simulated: the path, the tracking errors and the polar "
                          "radial error with its dashed rings.",
    "identify-idim": "idim on the EMPS benchmark: the drive force measured and modelled, and their difference.",
    "identify-idim:fit": "The report's force fit (identify --report).",
    "identify-idim:friction-map": "The report's friction map: friction against velocity with the identified law.",
    "identify-idim:cross-test": "The report's cross-test on the second EMPS file (identify --validate).",
    "identify-breakaway": "A breakaway ramp: the applied torque with Fs and the Coulomb level, and the velocity.",
    "identify-sweep": "A speed sweep: steady friction at each speed with its std and the fitted law.",
    "identify-decay": "A free decay of a pendulum: the oscillation with its turning points and the fitted envelope.",
    "analyze-envelope": "The decay envelope of the same pendulum (analyze envelope).",
    "analyze-stick-slip": "Stick-slip cycles found in the simulated rig (analyze stick-slip).",
    "analyze-contour": "The circular test analysed: polar radial error (magnified) and the error against the angle.",
    "analyze-map-1d": "Where PID hunting appears as static friction grows: amplitude against Fs, with the "
                      "describing function's prediction.",
    "analyze-map-2d": "A spring-block stick-slip map over the drive speed (logarithmic axis) and the damping, with "
                      "the linear stability boundary.",
    "validate-emps": "The identified EMPS model in the closed loop against the second measurement (validate).",
    "identify-drift": "A fleet's drift: each parameter with its std against the log's date, the flagged change marked.",
    "plot.sweep": "fl.plot.sweep: the same sweep in Python (matplotlib).",
    "plot.idim": "fl.plot.idim: measured and reconstructed force, and the residual.",
    "plot.simulation": "fl.plot.simulation: a simulation's columns against time.",
    "plot.decay": "fl.plot.decay: a free decay with its envelope.",
    "plot.breakaway": "fl.plot.breakaway: the applied torque of a breakaway ramp with Fs and the Coulomb level.",
    "plot.contour": "fl.plot.contour: a circular test's radial error against the angle, quadrant glitches marked.",
    "plot.map": "fl.plot.map: a stick-slip map over two scenario keys, one on a logarithmic axis.",
    "identify-idim-conditions": "The report's friction map against velocity and load (idim with the load term).",
    "identify-idim-conditions:ripple": "The report's position ripple over one period (idim with the ripple term).",
    "identify-idim-conditions:temperature": "The report's temperature drift: the logged temperature and the viscous "
                                            "coefficient it gives (idim with the temperature term).",
    "plot.load_map": "fl.plot.load_map: friction against velocity in three bands of |load|, each with its law.",
    "plot.ripple": "fl.plot.ripple: the position ripple over one period, samples and the identified ripple.",
    "plot.temperature": "fl.plot.temperature: the logged temperature and the viscous coefficient it gives.",
}


def png_from_gnuplot(fig, dest):
    """The figure drawn again from its .gp script with pngcairo, scaled to GALLERY_WIDTH."""
    gp = pathlib.Path(f"{fig.svg}.gp")
    script = gp.read_text()
    m = re.search(r"^set terminal svg size (\d+),(\d+) .*$", script, re.M)
    w, h = int(m.group(1)), int(m.group(2))
    scale = GALLERY_WIDTH / w
    script = script.replace(m.group(0), f"set terminal pngcairo size {GALLERY_WIDTH},{round(h * scale)} enhanced "
                                        f"font 'Sans,{max(9, round(16 * scale))}' background '#ffffff'")
    tmp = gp.with_suffix(".png.gp")
    tmp.write_text(script)
    subprocess.run(["gnuplot", "-e", f"datafile='{fig.svg}.dat'; outfile='{dest}'", str(tmp)], check=True,
                   cwd=gp.parent, capture_output=True)


def shrink(png):
    """The image with a palette of PALETTE colours (lines, markers and text on white need no more):
    about a third of the bytes, so that the committed images stay small."""
    from PIL import Image  # Debian python3-pil, which matplotlib depends on

    with Image.open(png) as im:
        small = im.convert("RGB").quantize(colors=PALETTE, method=Image.Quantize.MEDIANCUT)
    small.save(png, optimize=True)


def main():
    build = pathlib.Path(sys.argv[1]).resolve()
    src = pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else HERE.parent).resolve()
    exe = build / "app" / "frictionlab"
    sys.path.insert(0, str(build / "python"))
    images = src / "docs" / "gallery"
    with tempfile.TemporaryDirectory(prefix="fl-gallery.") as scratch:
        figures = make_figures.make_all(exe, src, pathlib.Path(scratch), png_width=GALLERY_WIDTH)
        if images.exists():
            shutil.rmtree(images)
        images.mkdir(parents=True)
        lines = ["# Gallery", "",
                 "Every kind of figure frictionlab draws, made from the bundled data and examples by `make gallery`",
                 "(`scripts/gallery.py`, from the figures `tests/figures/make_figures.py` draws; the test",
                 "`figures.geometry` measures the same figures in a headless browser: no legend over an axis or tick",
                 "label, a unit on every axis label, text readable at 800 px wide). The command line writes SVG,",
                 "PNG or PDF by the extension of `--plot`, with the figure's data (`FIG.dat`) and gnuplot script",
                 "(`FIG.gp`) next to it; the images here are PNG drawn again from those scripts at",
                 f"{GALLERY_WIDTH} px, with a palette of {PALETTE} colours to keep them small.", "",
                 "The commands run in this order from the source directory; the inputs they read come from the",
                 "commands above them, and these (`lugre.csv` is the presliding-then-sliding record that",
                 "`tests/figures/make_figures.py` simulates):", "",
                 "```sh",
                 "frictionlab simulate examples/virgala_motor_sweep.yaml -o sweep.csv",
                 "frictionlab simulate examples/craig_pendulum_combined.yaml -o pend.csv",
                 "/usr/bin/python3 examples/fleet_logs.py fleet",
                 "/usr/bin/python3 tests/rigs/servo_log.py servo.csv",
                 "/usr/bin/python3 tests/rigs/effects_log.py effects.csv --seed 4",
                 "```", ""]
        lines += ["## Command line", ""]
        python_started = False
        for fig in figures:
            if fig.name == "identify-idim:fit":  # the report's copy of identify-idim's figure
                continue
            name = fig.name.replace(":", "-")
            dest = images / f"{name}.png"
            if fig.kind == "gnuplot":
                png_from_gnuplot(fig, dest)
            else:
                if not python_started:
                    lines += ["## Python (`frictionlab.plot`)", "",
                              "Each function also takes `ax=` (draws into your Axes and returns them).", ""]
                    python_started = True
                make_figures.redraw_python(fig, dest, GALLERY_WIDTH)
            lines += [f"### {fig.name}", "", WHAT.get(fig.name, ""), "", f"```shell\n{fig.command}\n```" if fig.kind ==
                      "gnuplot" else f"```py\n{fig.command}\n```", "",
                      f"![{fig.name}](gallery/{name}.png)", ""]
    for png in images.glob("*.png"):
        shrink(png)
    (src / "docs" / "gallery.md").write_text("\n".join(lines).rstrip() + "\n")
    total = sum(p.stat().st_size for p in images.glob("*.png"))
    print(f"gallery: {len(list(images.glob('*.png')))} figures, docs/gallery.md and docs/gallery/*.png ({total / 1024:.0f} kB)")


if __name__ == "__main__":
    main()
