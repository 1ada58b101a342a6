"""The examples of examples/python run as written, each drawing its figure into a temporary
folder (matplotlib, Agg)."""

import os
import subprocess
import sys

import pytest

EXAMPLES = ["push_trajectory", "friction_map", "mu_from_icor"]


@pytest.mark.parametrize("name", EXAMPLES)
def test_example(source_dir, tmp_path, name):
    script = os.path.join(source_dir, "examples", "python", name + ".py")
    env = dict(os.environ, MPLBACKEND="Agg")
    p = subprocess.run([sys.executable, script, "--out", str(tmp_path)], capture_output=True, text=True,
                       env=env, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    png = tmp_path / (name + ".png")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert str(png) in p.stdout


def test_every_example_is_tested(source_dir):
    found = sorted(f[:-3] for f in os.listdir(os.path.join(source_dir, "examples", "python")) if f.endswith(".py"))
    assert found == sorted(EXAMPLES)
