"""Every identification method of the library (frictionlab/identify/method.hpp) has a Python
binding (python/src/methods/, seen through fl.methods()) and a command (`frictionlab identify
NAME`, or `frictionlab NAME` for a method with a command of its own), in the library's order; and
a result carries the fitted signal and unit its method declares.

The command line is conftest.py's `cli` fixture."""
import re
import subprocess

import numpy as np
import pytest

import frictionlab as fl

# identify_idim on the generated rig record below: 1 % force noise, a 1 um encoder and a 10 mN
# force quantum over 20 s at 1 kHz leave the least-squares estimates of M and Fc within a few
# tenths of a percent (their std is ~0.1 %); 2 % flags a wrong fit, not noise.
IDIM_REL_TOL = 2e-2


def subcommands(cli, *args):
    """Names listed under "Subcommands:" by `frictionlab ARGS --help`, in their order."""
    text = subprocess.run([cli, *args, "--help"], stdout=subprocess.PIPE, text=True, check=True).stdout
    block = text.split("Subcommands:\n", 1)[1].split("\n\n", 1)[0]
    return [m.group(1) for m in re.finditer(r"^  (\S+)", block, re.MULTILINE)]


def test_every_library_method_has_a_python_binding():
    table = fl.methods()
    assert table, "the library lists no identification method"
    assert len({m.name for m in table}) == len(table)
    for m in table:
        assert m.function is not None, f"method '{m.name}' has no Python binding (python/src/methods/{m.name}.cpp)"
        assert m.function in fl.__all__ and callable(getattr(fl, m.function)), (m.name, m.function)
        assert m.summary, m.name
        # A fitted signal comes with its unit on both axes; none (validate) with none.
        assert (set(m.fit_units) == {"linear", "rotary"}) == bool(m.fit_signal), m


def test_every_library_method_has_a_cli_command(cli):
    identify = subcommands(cli, "identify")
    top = subcommands(cli)
    table = fl.methods()
    for m in table:
        # identify_NAME runs as `frictionlab identify NAME`; any other (validate) as its own command.
        if m.function == f"identify_{m.name}":
            assert m.name in identify, f"`frictionlab identify {m.name}` missing: {identify}"
        else:
            assert m.name in top, f"`frictionlab {m.name}` missing: {top}"
    # Nothing in the command line that the library does not list, and the same order.
    assert identify == [m.name for m in table if m.name in identify]


def test_method_fit_units_follow_the_axis():
    by_name = {m.name: m for m in fl.methods()}
    assert by_name["idim"].fit_units == {"linear": "N", "rotary": "N m"}
    assert by_name["decay"].fit_units == {"linear": "J", "rotary": "J"}  # energy: J on either axis
    assert by_name["lugre"].fit_units == {"linear": "m", "rotary": "rad"}
    assert by_name["validate"].fit_units == {} and by_name["validate"].fit_signal == ""


def rig_record(seed=15):
    """A linear axis logged at 1 kHz for 20 s: two-tone position through a 1 um encoder with an
    arbitrary zero, drive force of M = 2 kg, Fv = 8 N s/m, Fc = 3 N, offset 0.4 N with 1 % noise
    and a 10 mN quantum. Returns time, force, position and the true values."""
    rng = np.random.default_rng(seed)
    t = np.arange(20000) * 1e-3
    w1, w2 = 2 * np.pi * 0.5, 2 * np.pi * 2.1
    x = 0.05 * np.sin(w1 * t) + 0.01 * np.sin(w2 * t)
    v = 0.05 * w1 * np.cos(w1 * t) + 0.01 * w2 * np.cos(w2 * t)
    a = -0.05 * w1**2 * np.sin(w1 * t) - 0.01 * w2**2 * np.sin(w2 * t)
    true = {"M": 2.0, "Fv": 8.0, "Fc": 3.0, "offset": 0.4}
    f = true["M"] * a + true["Fv"] * v + true["Fc"] * np.sign(v) + true["offset"]
    f = np.round((f + 0.01 * np.std(f) * rng.standard_normal(t.size)) / 0.01) * 0.01
    encoder = np.round((x + 0.123) / 1e-6) * 1e-6
    return t, f, encoder, true


@pytest.mark.parametrize("axis", ["linear", "rotary"])
def test_idim_result_carries_its_methods_fit_signal_and_unit(axis):
    t, f, x, true = rig_record()
    r = fl.identify_idim(t, f, position=x, axis=axis)
    m = {m.name: m for m in fl.methods()}["idim"]
    assert r.ok, r.message
    assert r.method == m.name and r.axis == axis
    assert r.fit.quantity == m.fit_signal and r.fit.unit == m.fit_units[axis]
    assert r.to_dict()["fit"]["unit"] == m.fit_units[axis]
    for name in ("M", "Fc"):
        assert r[name] == pytest.approx(true[name], rel=IDIM_REL_TOL), name


def test_decay_result_carries_its_methods_fit_unit(example):
    tr = fl.simulate(example("craig_pendulum_combined"))
    r = fl.identify_decay(tr["time"], tr["position"], stiffness=9.81, pendulum=True, axis="rotary")
    m = {m.name: m for m in fl.methods()}["decay"]
    assert r.ok and r.method == m.name
    assert (r.fit.quantity, r.fit.unit) == (m.fit_signal, m.fit_units["rotary"])
