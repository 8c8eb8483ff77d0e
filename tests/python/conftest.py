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
