"""`nanopush sweep --out FILE.nc` (docs/data.md) read back with the netCDF library
(netCDF4-python) and xarray: a grid's dimensions named after its axes, a --points sweep over
`point`, every value the CSV table's bit for bit, CF units and long_name, provenance."""

import csv
import json
import os
import subprocess

import netCDF4
import numpy as np
import xarray as xr

CLI = os.environ["NANOPUSH_CLI"]
GRID = ["fig3_18", "--set", "surface.law=coulomb", "--vary", "surface.mu=0.02:0.2:5", "--vary", "push.yn=0:45e-9:4",
        "--quiet", "--jobs", "2"]


def sweep(tmp_path, *args):
    p = subprocess.run([CLI, "sweep", *args], capture_output=True, text=True, cwd=tmp_path)
    assert p.returncode in (0,) or 64 < p.returncode < 128, p.stderr  # failed points still give a table
    return p


def read_csv(path):
    """Columns of the CSV as the sidecar types them: floats (NaN for the empty cell), ints, text."""
    schema = json.loads(path.with_name(path.stem + ".schema.json").read_text())
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    cols = {}
    for i, field in enumerate(schema["fields"]):
        assert header[i] == field["name"]
        cells = [r[i] for r in body]
        if field["type"] == "number":
            cols[field["name"]] = np.array([float(c) if c else np.nan for c in cells])
        elif field["type"] == "integer":
            cols[field["name"]] = np.array([int(c) for c in cells]) if all(cells) else cells
        else:
            cols[field["name"]] = np.array(cells, dtype=object)
    return cols, schema


def same_bits(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and np.array_equal(np.isnan(a), np.isnan(b)) and \
        np.array_equal(a[~np.isnan(a)].view(np.uint64), b[~np.isnan(b)].view(np.uint64))


def test_grid_netcdf_equals_csv(tmp_path):
    sweep(tmp_path, *GRID, "--out", "g.csv")
    sweep(tmp_path, *GRID, "--out", "g.nc")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["g.csv", "g.nc", "g.schema.json"]
    cols, schema = read_csv(tmp_path / "g.csv")
    shape = (5, 4)

    with netCDF4.Dataset(tmp_path / "g.nc") as nc:  # the netCDF C library
        assert nc.data_model == "NETCDF4"
        assert list(nc.dimensions) == ["surface_mu", "push_yn"]
        assert [len(d) for d in nc.dimensions.values()] == list(shape)
        nc.set_auto_mask(False)
        for field in schema["fields"]:
            v = nc.variables[field["name"]]
            name = field["name"]
            if name in ("surface_mu", "push_yn"):
                assert v.dimensions == (name,)
                step = 4 if name == "surface_mu" else 1
                assert same_bits(v[:], cols[name][::step][:shape[0 if name == "surface_mu" else 1]])
                continue
            assert v.dimensions == ("surface_mu", "push_yn"), name
            if field["type"] == "number":
                assert same_bits(v[:].ravel(), cols[name]), name
                assert v.units == field["unit"], name
            elif field["type"] == "integer" and isinstance(cols[name], np.ndarray):
                assert np.array_equal(v[:].ravel(), cols[name]), name
            elif field["type"] == "string":
                assert list(v[:].ravel()) == list(cols[name]), name
            assert v.long_name == field["description"], name
        assert nc.Conventions == "CF-1.8"
        assert nc.nanopush_version == schema["nanopush"]["version"]
        assert "sweep" in nc.command

    ds = xr.open_dataset(tmp_path / "g.nc")  # a labelled 2-d array
    assert ds.x_final.dims == ("surface_mu", "push_yn")
    mu, yn = cols["surface_mu"][6], cols["push_yn"][6]  # row 6: mu index 1, yn index 2
    assert same_bits(ds.x_final.sel(surface_mu=mu, push_yn=yn).values, cols["x_final"][6])
    assert ds.x_final.attrs["units"] == "m"


def test_points_netcdf_over_point(tmp_path):
    (tmp_path / "pts.csv").write_text("surface.mu,push.yn\n0.05,0\n0.1,2e-8\n0.15,1e-8\n")
    args = ["fig3_18", "--points", "pts.csv", "--quiet", "--jobs", "1"]
    sweep(tmp_path, *args, "--out", "p.csv")
    sweep(tmp_path, *args, "--out", "p.nc")
    cols, schema = read_csv(tmp_path / "p.csv")
    ds = xr.open_dataset(tmp_path / "p.nc")
    assert dict(ds.sizes) == {"point": 3}
    for field in schema["fields"]:
        if field["type"] == "number":
            assert same_bits(ds[field["name"]].values, cols[field["name"]]), field["name"]
