"""`cmake --install BUILD --component python --prefix P` installs a package that imports from
P with PYTHONPATH alone (outside the build and source trees), with its preset scenes, and
gives the numbers of the build tree's package."""

import os
import pathlib
import subprocess
import sys

import nanopush


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
    code = ("import nanopush, sys; r = nanopush.run('fig3_6a'); "
            "print(nanopush.__file__); print(repr(r.theta[-1])); print(len(nanopush.presets()))")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "NANOPUSH_SCENES")}
    env["PYTHONPATH"] = str(site)
    q = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=tmp_path)
    assert q.returncode == 0, q.stderr
    where, theta, npresets = q.stdout.split()
    assert pathlib.Path(where).is_relative_to(prefix)
    assert float(theta) == nanopush.run("fig3_6a").theta[-1]
    assert int(npresets) == len(nanopush.presets())
