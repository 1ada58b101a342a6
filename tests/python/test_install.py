"""`cmake --install BUILD --component python --prefix P` installs a package that imports from
P with PYTHONPATH alone (outside the build and source trees), with its preset scenes, and
gives the numbers of the build tree's package."""

import os
import subprocess

from conftest import assert_installed_package_works


def test_installed_package(tmp_path):
    build = os.environ["NANOPUSH_BUILD_DIR"]
    prefix = tmp_path / "prefix"
    p = subprocess.run([os.environ["NANOPUSH_CMAKE"], "--install", build, "--component", "python",
                        "--prefix", str(prefix)], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    inits = list(prefix.rglob("nanopush/__init__.py"))
    assert len(inits) == 1, inits
    site = inits[0].parent.parent
    assert site.name == "site-packages"
    assert_installed_package_works(site, tmp_path)
