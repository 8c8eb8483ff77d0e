"""Shared fixtures of the Python tests: paths to the bundled data and examples, and the command line."""
import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("FRICTIONLAB_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


def pytest_configure(config):
    config.addinivalue_line("markers", "install: slow packaging tests (pip into a venv, cmake --install); "
                                       "run by CI as the ctest python.install")


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def emps():
    import frictionlab as fl

    return fl.load(SOURCE_DIR / "data" / "emps" / "DATA_EMPS.mat")


@pytest.fixture(scope="session")
def emps_pulses():
    import frictionlab as fl

    return fl.load(SOURCE_DIR / "data" / "emps" / "DATA_EMPS_PULSES.mat")


@pytest.fixture(scope="session")
def example():
    return lambda name: SOURCE_DIR / "examples" / f"{name}.yaml"


@pytest.fixture(scope="session")
def cli():
    """Path of the built `frictionlab` command line: $FRICTIONLAB_CLI, else
    $FRICTIONLAB_BUILD_DIR/app/frictionlab (set by ctest), else <source>/build/app/frictionlab.
    Skips the test when there is none."""
    build = pathlib.Path(os.environ.get("FRICTIONLAB_BUILD_DIR", SOURCE_DIR / "build"))
    path = pathlib.Path(os.environ.get("FRICTIONLAB_CLI", build / "app" / "frictionlab"))
    if not path.exists():
        pytest.skip(f"frictionlab CLI not found at {path} (set FRICTIONLAB_CLI)")
    return str(path)


@pytest.fixture(scope="session")
def conditions_record():
    """30 s at 1 kHz of an axis with a load, a warming grease and a position ripple (noiseless):
    (t s, force N, q m, load N, temperature degC). Truth: M 2 kg, Fv 20 - 0.25 (T - 30) N s/m,
    Fc 3 + 0.05 |load| N, the load acting with gain 1, a ripple 0.6 sin - 0.4 cos over 20 mm."""
    import numpy as np

    t = np.arange(30001) * 1e-3
    w1, w2 = 2 * np.pi * 0.5, 2 * np.pi * 1.3
    q = 0.05 * np.sin(w1 * t) + 0.01 * np.sin(w2 * t + 0.4)
    qd = 0.05 * w1 * np.cos(w1 * t) + 0.01 * w2 * np.cos(w2 * t + 0.4)
    qdd = -0.05 * w1 ** 2 * np.sin(w1 * t) - 0.01 * w2 ** 2 * np.sin(w2 * t + 0.4)
    load = 30.0 + 20.0 * np.sin(0.3 * t)
    temp = 20.0 + 0.8 * t
    k = 2 * np.pi / 0.02
    force = (2.0 * qdd + (20.0 - 0.25 * (temp - 30.0)) * qd + (3.0 + 0.05 * np.abs(load)) * np.sign(qd) + load
             + 0.6 * np.sin(k * q) - 0.4 * np.cos(k * q))
    return t, force, q, load, temp
