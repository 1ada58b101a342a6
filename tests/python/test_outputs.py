"""Outputs of the package only ever replace their own regular files (docs/errors.md, "Outputs";
issue 34 item 1), as on the command line: a FIFO or a directory raises OSError and is left as it
was, a symbolic link is followed (its target replaced, the link kept), a character device is
written through. Device nodes are made in the scratch directory (root); nothing is ever written
to the machine's /dev."""

import os
import stat

import pytest

import nanopush


@pytest.fixture(scope="module")
def result():
    return nanopush.run("fig3_6c")


def test_fifo_and_directory_raise_oserror(result, tmp_path):
    fifo = tmp_path / "pipe.csv"
    os.mkfifo(fifo)
    with pytest.raises(OSError, match=r"output = .*pipe\.csv: is a FIFO"):
        result.to_csv(fifo)
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    d = tmp_path / "d.csv"
    d.mkdir()
    with pytest.raises(OSError, match="is a directory"):
        result.to_csv(d)
    assert d.is_dir() and not any(d.iterdir())
    scene = nanopush.Scene.preset("fig3_20")
    with pytest.raises(OSError, match="is a FIFO"):
        nanopush.synthesize(scene, (2e-9, 0.0, 0.0), 3, path=fifo)
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    assert not [p for p in tmp_path.iterdir() if ".tmp." in p.name]


def test_symlink_is_followed(result, tmp_path):
    (tmp_path / "data").mkdir()
    (tmp_path / "links").mkdir()
    target = tmp_path / "data" / "real.csv"
    target.write_text("old\n")
    link = tmp_path / "links" / "link.csv"
    os.symlink("../data/real.csv", link)
    result.to_csv(link)
    assert link.is_symlink() and os.readlink(link) == "../data/real.csv"
    assert target.read_text().startswith("t,x,y,theta")
    assert not [p for p in tmp_path.rglob("*") if ".tmp." in p.name]


def test_device_is_written_through(result, tmp_path):
    node = tmp_path / "nul"
    try:
        os.mknod(node, 0o600 | stat.S_IFCHR, os.makedev(1, 3))
    except PermissionError:
        pytest.skip("not root: no scratch device node (the machine's /dev is never written to)")
    result.to_csv(node)
    assert stat.S_ISCHR(os.lstat(node).st_mode)
    assert not os.path.exists(str(node) + ".schema.json")
