"""pip install . : the Python package nanopush, built by the project's CMake (docs/python.md).
The package's metadata is in pyproject.toml; this file builds the extension.

Offline on a machine with the Debian packages of .ci/setup (g++, gfortran, cmake, Eigen,
LAPACK, toml++, SUNDIALS, python3-numpy, python3-pybind11): nothing is downloaded. With a
pip that builds in isolation, add --no-build-isolation (setuptools and pybind11 then come
from the system):

    /usr/bin/python3 -m venv --system-site-packages ~/venv-nanopush
    ~/venv-nanopush/bin/pip install --no-build-isolation .

The libraries are linked statically into the extension; the wheel holds nanopush/
(__init__.py, icor.py, _nanopush.*.so) and the preset scenes (nanopush/scenes). CMake's
build tree is build/pip/cmake; NANOPUSH_PIP_JOBS sets the build's parallelism (default 2).

NANOPUSH_BUILD_TREE=DIR (absolute, or relative to this directory) reuses a CMake tree of this
source tree already built with the Python package (build/release): its extension is copied and
nothing is compiled. The tree must have static nanopush libraries (the default) and an
extension for the interpreter running pip; otherwise the build stops, saying which.
"""

import os
import pathlib
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
(ROOT / "build" / "pip").mkdir(parents=True, exist_ok=True)
VERSION = re.search(r"project\(nanopush VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    """Configure the project with only the library and the Python module, build the module,
    and put it and the preset scenes beside the package's Python files."""

    def build_extension(self, ext):
        dest = pathlib.Path(self.get_ext_fullpath(ext.name))
        dest.parent.mkdir(parents=True, exist_ok=True)
        tree = os.environ.get("NANOPUSH_BUILD_TREE")
        module = reused_extension(pathlib.Path(tree)) if tree else self.cmake_extension()
        print(f"nanopush: copying {module} -> {dest}")
        shutil.copy2(module, dest)
        shutil.rmtree(dest.parent / "scenes", ignore_errors=True)
        shutil.copytree(ROOT / "drivers" / "scenes", dest.parent / "scenes")

    def cmake_extension(self):
        build = ROOT / "build" / "pip" / "cmake"
        cmake = shutil.which("cmake") or "cmake"
        cfg = [cmake, "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
               "-DNANOPUSH_PYTHON=ON", "-DNANOPUSH_TESTS=OFF", "-DNANOPUSH_DRIVERS=OFF", "-DNANOPUSH_MPI=OFF",
               f"-DPython3_EXECUTABLE={sys.executable}"]
        if shutil.which("ninja") and not (build / "CMakeCache.txt").exists():
            cfg += ["-G", "Ninja"]
        subprocess.check_call(cfg)
        jobs = os.environ.get("NANOPUSH_PIP_JOBS", "2")
        subprocess.check_call([cmake, "--build", str(build), "--target", "_nanopush", "-j", jobs])
        return next((build / "python" / "nanopush").glob("_nanopush*.so"))


def reused_extension(tree):
    """The extension of an already built CMake tree of this source tree, checked to fit this
    interpreter and to hold the libraries (static); SystemExit naming what does not fit."""
    tree = (ROOT / tree).resolve()
    cache_file = tree / "CMakeCache.txt"
    if not cache_file.is_file():
        sys.exit(f"NANOPUSH_BUILD_TREE = {tree}: not a CMake build tree (no CMakeCache.txt); "
                 "configure and build it first (cmake --preset release && cmake --build --preset release)")
    cache = dict(re.findall(r"^([A-Za-z0-9_]+):[A-Z]+=(.*)$", cache_file.read_text(), re.M))
    source = pathlib.Path(cache.get("CMAKE_HOME_DIRECTORY", "")).resolve()
    if source != ROOT:
        sys.exit(f"NANOPUSH_BUILD_TREE = {tree}: a build of {source}, not of {ROOT}")
    if cache.get("BUILD_SHARED_LIBS", "OFF").upper() in ("ON", "1", "TRUE", "YES"):
        sys.exit(f"NANOPUSH_BUILD_TREE = {tree}: BUILD_SHARED_LIBS=ON, so its extension needs that tree's "
                 "shared libraries; a wheel needs a tree with static libraries (the default)")
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    module = tree / "python" / "nanopush" / f"_nanopush{suffix}"
    if not module.is_file():
        built = sorted(p.name for p in (tree / "python" / "nanopush").glob("_nanopush*.so"))
        sys.exit(f"NANOPUSH_BUILD_TREE = {tree}: no {module.name} for this Python ({sys.executable}); the tree has "
                 f"{built or 'no extension (NANOPUSH_PYTHON=OFF, or not built yet)'} "
                 f"(built for {cache.get('Python3_EXECUTABLE', '?')})")
    return module


# Metadata: pyproject.toml. Here: the version (from CMakeLists.txt) and the extension.
setup(
    version=VERSION,
    ext_modules=[CMakeExtension("nanopush._nanopush")],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build/pip"}, "egg_info": {"egg_base": "build/pip"}},
)
