"""pyproject.toml with NANOPUSH_BUILD_TREE = this build tree: pip builds a wheel offline without
compiling anything (no compiler or build tool in the verbose build log, well within a time
bound), the wheel is platform-specific, installs into a scratch directory and imports from
there, giving the numbers of the build tree's package. A tree that cannot serve is refused
with the reason."""

import os
import pathlib
import re
import subprocess
import sys
import time
import zipfile

import nanopush

from conftest import assert_installed_package_works

SOURCE = pathlib.Path(os.environ["NANOPUSH_SOURCE_DIR"])
BUILD = pathlib.Path(os.environ["NANOPUSH_BUILD_DIR"])
# What a compile or a CMake build would print in pip's verbose log.
COMPILING = re.compile(r"(^|[\s/])(c\+\+|g\+\+|gcc|cc|gfortran|ninja|make)(\s|$)|Building CXX|Linking CXX|"
                       r"-- Configuring|cmake --build", re.M)


def pip(*args, tree, cwd):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PIP_REQUIRE_VIRTUALENV")}
    env["NANOPUSH_BUILD_TREE"] = str(tree)
    env["PIP_NO_INDEX"] = "1"  # offline: nothing may be downloaded
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    return subprocess.run([sys.executable, "-m", "pip", *args], capture_output=True, text=True, env=env, cwd=cwd)


def test_wheel_from_build_tree(tmp_path):
    t0 = time.monotonic()
    p = pip("wheel", "-v", "--no-build-isolation", "--no-deps", "--no-cache-dir", "-w", str(tmp_path / "dist"),
            str(SOURCE), tree=BUILD, cwd=tmp_path)
    seconds = time.monotonic() - t0
    log = p.stdout + p.stderr
    assert p.returncode == 0, log
    hits = [m.group(0) for m in COMPILING.finditer(log)]
    assert not hits, f"the wheel build compiled: {hits}\n{log}"
    assert "nanopush: copying " in log, log
    assert seconds < 120, f"{seconds:.0f} s for a build that copies files"
    wheels = list((tmp_path / "dist").glob("nanopush-*.whl"))
    assert len(wheels) == 1, wheels
    tag = f"cp{sys.version_info.major}{sys.version_info.minor}"
    assert re.match(rf"nanopush-{re.escape(nanopush.__version__)}-{tag}-{tag}-linux_\w+\.whl$", wheels[0].name), \
        wheels[0].name
    names = zipfile.ZipFile(wheels[0]).namelist()
    assert any(re.match(r"nanopush/_nanopush\..*\.so$", n) for n in names), names
    assert "nanopush/scenes/thesis/fig3_6a.toml" in names
    assert any(n.endswith(".dist-info/LICENSE") for n in names), names

    target = tmp_path / "site"
    q = pip("install", "--no-deps", "--no-cache-dir", "--target", str(target), str(wheels[0]), tree=BUILD, cwd=tmp_path)
    assert q.returncode == 0, q.stdout + q.stderr
    assert_installed_package_works(target, tmp_path)


def test_unusable_tree_refused(tmp_path):
    p = pip("wheel", "--no-build-isolation", "--no-deps", "--no-cache-dir", "-w", str(tmp_path / "dist"),
            str(SOURCE), tree=tmp_path, cwd=tmp_path)
    assert p.returncode != 0
    assert f"NANOPUSH_BUILD_TREE = {tmp_path}: not a CMake build tree (no CMakeCache.txt)" in p.stdout + p.stderr
    assert not list(tmp_path.glob("dist/*.whl"))
