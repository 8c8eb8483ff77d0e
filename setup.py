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
    """Puts the compiled extension and the shared library it needs into the package (found there
    through the extension's $ORIGIN rpath).

    With FRICTIONLAB_BUILD_DIR naming a configured and built CMake build tree of this checkout
    (`make build`), the package takes what that tree compiled: nothing is compiled again. Without
    it, the `frictionlab_python` target is configured and built in setuptools' temporary folder.
    Either way the files come from `cmake --install` into a staging prefix, so they carry their
    installed rpath and no path of the build tree."""

    def build_extension(self, ext):
        out = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve().parent
        tmp = pathlib.Path(self.build_temp).resolve() / "cmake"
        build = os.environ.get("FRICTIONLAB_BUILD_DIR")
        if build:
            build = pathlib.Path(build).resolve()
            if not (build / "CMakeCache.txt").exists() or not list((build / "python" / "frictionlab").glob("_core*.so")):
                sys.exit(f"FRICTIONLAB_BUILD_DIR={build}: no built Python module there (run `make build` first)")
            # Brings the tree up to date if a source changed since (a no-op otherwise).
            subprocess.check_call(["cmake", "--build", str(build), "--target", "frictionlab_python"])
        else:
            build = tmp
            subprocess.check_call(["cmake", "-S", str(ROOT), "-B", str(tmp), "-DCMAKE_BUILD_TYPE=Release",
                                   f"-DPython_EXECUTABLE={sys.executable}", "-DFRICTIONLAB_BUILD_TESTS=OFF",
                                   "-DFRICTIONLAB_BUILD_APP=OFF"])
            subprocess.check_call(["cmake", "--build", str(tmp), "-j", str(os.cpu_count() or 2),
                                   "--target", "frictionlab_python"])
        stage = pathlib.Path(self.build_temp).resolve() / "stage"
        shutil.rmtree(stage, ignore_errors=True)
        subprocess.check_call(["cmake", "--install", str(build), "--prefix", str(stage)], stdout=subprocess.DEVNULL)
        out.mkdir(parents=True, exist_ok=True)
        for f in stage.rglob("frictionlab/_core*.so"):
            shutil.copy2(f, out / f.name)
        # The library under its soname (libfrictionlab.so.0), the one name the extension asks for.
        for f in stage.rglob("libfrictionlab.so.*"):
            if re.fullmatch(r"libfrictionlab\.so\.[0-9]+", f.name):
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
