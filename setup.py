"""Builds the frictionlab Python package with CMake (the version comes from CMakeLists.txt)."""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
VERSION = re.search(r"project\(frictionlab VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)


class CMakeBuild(build_ext):
    """Configures and builds the `frictionlab_python` target, then copies the extension and
    the shared library it needs into the package (found there through an $ORIGIN rpath)."""

    def build_extension(self, ext):
        out = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve().parent
        tmp = pathlib.Path(self.build_temp).resolve() / "cmake"
        subprocess.check_call(["cmake", "-S", str(ROOT), "-B", str(tmp), "-DCMAKE_BUILD_TYPE=Release",
                               f"-DPython_EXECUTABLE={sys.executable}", "-DFRICTIONLAB_BUILD_TESTS=OFF",
                               "-DFRICTIONLAB_BUILD_APP=OFF"])
        subprocess.check_call(["cmake", "--build", str(tmp), "-j", str(os.cpu_count() or 2),
                               "--target", "frictionlab_python"])
        out.mkdir(parents=True, exist_ok=True)
        for f in (tmp / "python" / "frictionlab").glob("_core*.so"):
            shutil.copy2(f, out / f.name)
        for f in tmp.glob("libfrictionlab.so*"):
            shutil.copy2(f, out / f.name, follow_symlinks=True)


setup(
    name="frictionlab",
    version=VERSION,
    description="Model, simulate and identify friction in motion systems",
    packages=["frictionlab", "frictionlab.methods"],
    package_dir={"frictionlab": "python/frictionlab"},
    ext_modules=[Extension("frictionlab._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.9",
    install_requires=["numpy"],
)
