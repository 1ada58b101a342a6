"""pip install . : the Python package nanopush, built by the project's CMake (docs/python.md).

Offline on a machine with the Debian packages of .ci/setup (g++, gfortran, cmake, Eigen,
LAPACK, toml++, SUNDIALS, python3-numpy, python3-pybind11): nothing is downloaded. With a
pip that builds in isolation, add --no-build-isolation (setuptools and pybind11 then come
from the system):

    /usr/bin/python3 -m venv --system-site-packages ~/venv-nanopush
    ~/venv-nanopush/bin/pip install --no-build-isolation .

The libraries are linked statically into the extension; the wheel holds nanopush/
(__init__.py, icor.py, _nanopush.*.so) and the preset scenes (nanopush/scenes). CMake's
build tree is build/pip/cmake; NANOPUSH_PIP_JOBS sets the build's parallelism (default 2).
"""

import os
import pathlib
import re
import shutil
import subprocess
import sys

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
        built = build / "python" / "nanopush"
        dest = pathlib.Path(self.get_ext_fullpath(ext.name)).parent
        dest.mkdir(parents=True, exist_ok=True)
        module = next(built.glob("_nanopush*.so"))
        shutil.copy2(module, pathlib.Path(self.get_ext_fullpath(ext.name)))
        shutil.rmtree(dest / "scenes", ignore_errors=True)
        shutil.copytree(ROOT / "drivers" / "scenes", dest / "scenes")


setup(
    name="nanopush",
    version=VERSION,
    description="Mechanics of pushing nano-objects (AFM manipulation): friction, iCOR, Bulirsch-Stoer",
    long_description=(ROOT / "docs" / "python.md").read_text() if (ROOT / "docs" / "python.md").exists() else "",
    long_description_content_type="text/markdown",
    packages=["nanopush"],
    package_dir={"nanopush": "python/nanopush"},
    ext_modules=[CMakeExtension("nanopush._nanopush")],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.9",
    install_requires=["numpy"],
    zip_safe=False,
    options={"build": {"build_base": "build/pip"}, "egg_info": {"egg_base": "build/pip"}},
)
