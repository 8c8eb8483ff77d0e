"""frictionlab.plot: every helper writes a non-empty PNG (Agg backend)."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
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
