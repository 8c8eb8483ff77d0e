"""Packaging (slow, marked `install`; CI runs it as the ctest python.install):
pip install --no-build-isolation . into a --system-site-packages venv (from the build tree that
FRICTIONLAB_BUILD_DIR names, as ctest sets it, so nothing is compiled again), and cmake --install
of the build tree; each installed package must import and compute outside the source tree."""
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

SMOKE = ("import frictionlab as fl, numpy as np; "
         "assert 'site-packages' in fl.__file__ or 'dist-packages' in fl.__file__, fl.__file__; "
         "law = fl.FrictionLaw({'law': 'coulomb-viscous', 'Fc': 2, 'Fv': 0.5}); "
         "assert law.sliding(np.array([1.0]))[0] == 2.5; "
         "tr = fl.simulate({'plant': {'type': 'axis', 'M': 1}, 'friction': {'law': 'coulomb', 'Fc': 1}, "
         "'input': {'type': 'constant', 'value': 2}, 'duration': 1}); "
         "assert abs(tr['velocity'][-1] - 1) < 1e-9; print(fl.__version__)")


def clean_env():
    env = dict(os.environ)
    env.pop("PYTHONPATH", None)  # the build tree must not be what gets imported
    return env


@pytest.mark.install
def test_pip_install_into_system_site_packages_venv(tmp_path, source_dir):
    # Copy the sources so the build leaves nothing in the checkout (setup.py stages in build/).
    src = tmp_path / "src"
    shutil.copytree(source_dir, src, ignore=shutil.ignore_patterns("build*", ".git", "__pycache__", "*.egg-info"))
    venv = tmp_path / "venv"
    subprocess.run(["/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable, "-m", "venv",
                    "--system-site-packages", str(venv)], check=True)
    py = venv / "bin" / "python"
    subprocess.run([str(py), "-m", "pip", "install", "--no-build-isolation", "--no-index", "-q", str(src)],
                   check=True, env=clean_env(), cwd=tmp_path)
    out = subprocess.run([str(py), "-c", SMOKE], check=True, env=clean_env(), cwd=tmp_path, capture_output=True,
                         text=True)
    assert out.stdout.strip()
    # The package carries the library under its soname and finds it beside the extension: no
    # path of a build tree in the extension's run-time search path.
    core = list(venv.rglob("frictionlab/_core*.so"))
    assert len(core) == 1, core
    assert list(core[0].parent.glob("libfrictionlab.so.*")), list(core[0].parent.iterdir())
    dynamic = subprocess.run(["readelf", "-d", str(core[0])], check=True, capture_output=True, text=True).stdout
    runpath = [line for line in dynamic.splitlines() if "RUNPATH" in line or "RPATH" in line]
    assert runpath and "$ORIGIN" in runpath[0] and "build" not in runpath[0], runpath


@pytest.mark.install
def test_cmake_install_of_the_build_tree(tmp_path):
    build = os.environ.get("FRICTIONLAB_BUILD_DIR")
    if not build:
        pytest.skip("FRICTIONLAB_BUILD_DIR not set (ctest sets it)")
    prefix = tmp_path / "prefix"
    subprocess.run(["cmake", "--install", build, "--prefix", str(prefix)], check=True, capture_output=True)
    site = [p.parent for p in prefix.rglob("frictionlab/__init__.py")]
    assert len(site) == 1, site
    env = clean_env()
    env["PYTHONPATH"] = str(site[0].parent)
    subprocess.run([sys.executable, "-c", SMOKE], check=True, env=env, cwd=tmp_path)
    assert pathlib.Path(site[0], "plot.py").exists()
