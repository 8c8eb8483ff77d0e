"""Shared fixtures of the Python tests: paths to the bundled data and examples."""
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
