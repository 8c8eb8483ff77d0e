"""frictionlab.plot: every helper writes a non-empty PNG (Agg backend)."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import frictionlab as fl  # noqa: E402

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def check_png(path):
    data = path.read_bytes()
    assert data.startswith(PNG_SIGNATURE) and len(data) > 5000  # a figure with axes and lines, not a blank file


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def test_sweep_plot(tmp_path, example):
    tr = fl.simulate(example("virgala_motor_sweep"))
    r = fl.identify_sweep(tr["time"], 0.039 * tr["current"], tr["velocity"], model="coulomb-viscous", axis="rotary")
    fig = fl.plot.sweep(r, file=tmp_path / "sweep.png")
    check_png(tmp_path / "sweep.png")
    assert fig.axes[0].get_xlabel() == "velocity (rad/s)" and fig.axes[0].get_ylabel() == "friction (N m)"


def test_idim_plot(tmp_path, emps):
    r = fl.identify_idim(emps["t"], emps["gtau"] * emps["vir"], emps["qm"])
    fig = fl.plot.idim(r, file=tmp_path / "idim.png")
    check_png(tmp_path / "idim.png")
    assert len(fig.axes) == 2 and fig.axes[0].get_ylabel() == "force (N)"


def test_simulation_and_decay_plots(tmp_path, example):
    tr = fl.simulate(example("craig_pendulum_combined"))
    fl.plot.simulation(tr, file=tmp_path / "sim.png")
    check_png(tmp_path / "sim.png")
    fl.plot.decay(tr, file=tmp_path / "decay.png")
    check_png(tmp_path / "decay.png")


def test_plot_errors(emps):
    bad = fl.identify_idim(emps["t"][:2000], emps["vir"][:2000], position=0 * emps["qm"][:2000])
    with pytest.raises(ValueError, match="idim result has status error: .*no excitation"):
        fl.plot.idim(bad)
    with pytest.raises(ValueError, match=r"sweep plot: the result has no points"):
        fl.plot.sweep(fl.identify_idim(emps["t"], emps["vir"], emps["qm"]))


# --- ax=: every function draws into the caller's Axes and returns them; the new figure kinds ---

LUGRE_YAML = """description: Canudas de Wit 1995 Table I, presliding then sliding (tests/cli/identify_lugre.sh)
plant: {type: axis, M: 1.0}
friction: {law: lugre, sigma0: 1.0e5, sigma1: 316.22776601683796, sigma2: 0.4, Fc: 1.0, Fs: 1.5, vs: 0.001}
input: {type: table, times: [%s], values: [%s]}
duration: 10
output_rate: 1000
"""


def lugre_record(tmp_path):
    import math

    times, values = [0.0, 2.0, 4.0], [0.0, 1.425, 0.0]
    for i in range(1, 301):
        t = round(4.0 + 0.02 * i, 6)
        times.append(t)
        values.append(3.0 * math.sin(math.pi * (t - 4.0)))
    path = tmp_path / "lugre.yaml"
    path.write_text(LUGRE_YAML % (", ".join(map(repr, times)), ", ".join(map(repr, values))))
    return fl.simulate(path)


def unit_of(label):
    """The unit in a label's trailing parentheses ('velocity (m/s)' -> 'm/s'), or None."""
    import re

    m = re.search(r"\(([^()]+)\)\s*$", label)
    return m.group(1) if m else None


def check_drawn_into(axes, returned):
    """The function returned the caller's Axes, drew lines or markers there, and labelled both
    axes of each with a unit."""
    assert returned is axes or list(returned) == list(axes)
    for ax in ([axes] if not isinstance(axes, list) else axes):
        assert ax.lines or ax.collections, "nothing drawn into the given Axes"
        assert unit_of(ax.get_ylabel()), ax.get_ylabel()
    bottom = axes[-1] if isinstance(axes, list) else axes
    assert unit_of(bottom.get_xlabel()), bottom.get_xlabel()


def legend_outside(ax):
    """The legend's box lies right of the axes' box (drawn beside them, never over data)."""
    fig = ax.figure
    fig.canvas.draw()
    leg = ax.get_legend()
    assert leg is not None
    lb, ab = leg.get_window_extent(), ax.get_window_extent()
    assert lb.x0 >= ab.x1, (lb, ab)


def test_ax_keyword_every_function(example, emps, tmp_path):
    sw = fl.simulate(example("virgala_motor_sweep"))
    r = fl.identify_sweep(sw["time"], 0.039 * sw["current"], sw["velocity"], model="coulomb-viscous", axis="rotary")
    fig, ax = plt.subplots()
    check_drawn_into(ax, fl.plot.sweep(r, ax=ax))
    legend_outside(ax)
    assert ax.get_xlabel() == "velocity (rad/s)" and ax.get_ylabel() == "friction (N m)"
    with pytest.raises(ValueError, match="breakaway plot: the result has no 'time' and 'force'"):
        fl.plot.breakaway(r)  # a sweep's result: no record over time

    ri = fl.identify_idim(emps["t"], emps["gtau"] * emps["vir"], emps["qm"])
    fig, axes = plt.subplots(2, 1)
    check_drawn_into(list(axes), fl.plot.idim(ri, ax=axes))
    with pytest.raises(ValueError, match="this figure has 2 panels; got 1 Axes"):
        fl.plot.idim(ri, ax=axes[0])

    pend = fl.simulate(example("craig_pendulum_combined"))
    fig, axes = plt.subplots(3, 1)
    check_drawn_into(list(axes), fl.plot.simulation(pend, axis="rotary", ax=list(axes)))
    assert [a.get_ylabel() for a in axes] == ["position (rad)", "velocity (rad/s)", "friction (N m)"]
    fig, axes = plt.subplots(2, 1)
    check_drawn_into(list(axes), fl.plot.decay(pend, axis="rotary", ax=list(axes)))
    assert axes[1].get_ylabel() == "amplitude (rad)"


def test_breakaway_plot(example):
    tr = fl.simulate(example("craig_motor_trapezoid"))
    r = fl.identify_breakaway(tr["time"], 0.0141 * tr["current"], tr["velocity"], axis="rotary")
    fig, ax = plt.subplots()
    check_drawn_into(ax, fl.plot.breakaway(r, ax=ax))
    assert ax.get_ylabel() == "applied torque (N m)"
    # The breakaway marker sits at (breakaway time, Fs) of the result.
    marker = next(line for line in ax.lines if line.get_label() == "breakaway Fs")
    assert marker.get_ydata()[0] == r["Fs"] and marker.get_xdata()[0] == r.diagnostics.numbers["breakaway_time"]
    assert isinstance(fl.plot.breakaway(r), matplotlib.figure.Figure)


def test_lugre_plot(tmp_path):
    tr = lugre_record(tmp_path)
    r = fl.identify_lugre(tr["time"], tr["applied"], tr["position"], inertia=1.0)
    fig, ax = plt.subplots()
    check_drawn_into(ax, fl.plot.lugre(r, ax=ax, vmax=0.01))
    curve = ax.lines[1]  # v > 0 branch: the law's steady friction, Fc + (Fs - Fc) at v -> 0+
    # Within 2 % of Fs (identified within the CLI test's 2 % on Fc; the curve starts 1e-11 m/s from 0).
    fs_rel = 0.02
    assert curve.get_ydata()[0] == pytest.approx(r["Fs"], rel=fs_rel)
    assert ax.get_xlim()[1] >= 0.01


def test_contour_plot():
    R = 0.01  # m
    t = np.arange(0, 2 * np.pi * R / 0.02 * 1.05, 1e-3)
    a = np.pi / 4 + 0.02 / R * t
    e = 10e-6 * np.exp(-0.5 * (np.remainder(np.degrees(a) + 180, 360) - 180) ** 2 / 4.0)  # one glitch at 0 deg
    r = fl.analyze_contour(t, (R + e) * np.cos(a), (R + e) * np.sin(a), R * np.cos(a), R * np.sin(a))
    fig, ax = plt.subplots()
    check_drawn_into(ax, fl.plot.contour(r, ax=ax))
    assert ax.get_xlabel() == "angle (deg)" and unit_of(ax.get_ylabel()) == "um"
    # The radial error is drawn in um: its peak is the 10 um glitch.
    assert max(ax.lines[0].get_ydata()) == pytest.approx(r.max_radial_error_m * 1e6)


def test_map_plot_log_axis(example):
    rows = fl.analyze_map(example("map_spring_block"), ["plant.V0=log:0.004:0.2:3", "plant.c=0:8:2"],
                          jobs=2)
    fig, ax = plt.subplots()
    check_drawn_into(ax, fl.plot.map(rows, units={"plant.V0": "m/s", "plant.c": "N s/m"}, ax=ax))
    # A log-spaced key on a true logarithmic axis (tick values are speeds, not their log10).
    assert ax.get_xscale() == "log" and ax.get_yscale() == "linear"
    assert ax.get_xlabel() == "plant.V0 (m/s)" and ax.get_ylabel() == "plant.c (N s/m)"
    legend_outside(ax)
    one = fl.analyze_map(example("map_pid_hunting"), "friction.Fs=1:2:3", jobs=2)
    fig, ax = plt.subplots()
    fl.plot.map(one, ax=ax)
    assert ax.get_xscale() == "linear" and ax.get_ylabel() == "amplitude (m or rad)"
    with pytest.raises(ValueError, match="map plot: no rows"):
        fl.plot.map([])


def test_drift_title_counts_logs(tmp_path, source_dir):
    import subprocess
    import sys

    subprocess.run([sys.executable, str(source_dir / "examples" / "fleet_logs.py"), str(tmp_path)], check=True,
                   capture_output=True)
    files = sorted(tmp_path.glob("axis3_2026-11-0?.csv"))
    table = fl.batch.identify([str(f) for f in files], "sweep", client=None, model="coulomb-viscous",
                              load={"resample": True}, date_from="name")
    fig = fl.plot.drift(table)
    # One row per parameter and log: the title counts the logs, not the rows.
    assert fig.axes[0].get_title() == f"drift over {len(files)} logs"
    fig, axes = plt.subplots(2, 1)
    check_drawn_into(list(axes), fl.plot.drift(table, ["Fc", "Fv"], ax=list(axes)))


# --- the condition terms' figures (load map, ripple, temperature drift), as the report draws them ---

def test_condition_term_plots(conditions_record, emps, tmp_path):
    t, force, q, load, temp = conditions_record
    r = fl.identify_idim(t, force, q, load=load, temperature=temp, temperature_ref=30.0, skip_end=49,
                         terms=["inertia", "viscous", "coulomb", "offset", "load", "temperature", "ripple"],
                         ripple_period=0.02)
    assert r.ok, r.message
    fig = fl.plot.load_map(r, file=tmp_path / "load_map.png")
    check_png(tmp_path / "load_map.png")
    a = fig.axes[0]
    assert a.get_xlabel() == "velocity (m/s)" and a.get_ylabel() == "friction (N)"
    legend_outside(a)
    # Three |load| bands (10 to 50 N), each with the law at its mean |load|.
    labels = [line.get_label() for line in a.lines if not line.get_label().startswith("_")]
    assert sum(lab.startswith("|load| ") for lab in labels) == 3, labels
    assert sum(lab.startswith("law at |load| ") for lab in labels) == 3, labels

    fig, ax = plt.subplots()
    check_drawn_into(ax, fl.plot.ripple(r, ax=ax))
    assert ax.get_xlabel() == "position within the ripple period (m)" and ax.get_ylabel() == "ripple force (N)"
    # The identified ripple's amplitude is the truth's, sqrt(0.6^2 + 0.4^2) N: its curve's extremes.
    curve = next(line for line in ax.lines if line.get_label() == "identified ripple")
    kAmplitudeRel = 1e-2  # the fit's 1e-3 on each harmonic, and the curve's 200 points per period
    assert np.max(np.abs(curve.get_ydata())) == pytest.approx(np.hypot(0.6, 0.4), rel=kAmplitudeRel)

    fig, axes = plt.subplots(2, 1)
    check_drawn_into(list(axes), fl.plot.temperature(r, ax=list(axes)))
    assert axes[1].get_ylabel() == "viscous coefficient (N s/m)"
    # The viscous coefficient falls by 0.25 N s/m per K over the log's 24 K rise.
    fv = axes[1].lines[0].get_ydata()
    assert fv[0] - fv[-1] == pytest.approx(0.25 * (temp[-1] - temp[0]), rel=2e-2)

    # A fit without the terms: each figure names the term to fit.
    plain = fl.identify_idim(emps["t"], emps["gtau"] * emps["vir"], emps["qm"])
    for draw, term in ((fl.plot.load_map, "load"), (fl.plot.ripple, "ripple"), (fl.plot.temperature, "temperature")):
        with pytest.raises(ValueError, match=f"fit identify_idim with the '{term}' term"):
            draw(plain)
