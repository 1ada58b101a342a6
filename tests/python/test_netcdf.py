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


def read_trajectory(path):
    """A trajectory CSV as a (samples, columns) float array and its column names and units."""
    cols, schema = read_csv(path)
    names = [f["name"] for f in schema["fields"]]
    return np.column_stack([cols[n] for n in names]), names, [f["unit"] for f in schema["fields"]]


def test_grid_trajectories_in_netcdf(tmp_path):
    """--trajectories with a .nc: one variable `trajectory` over the grid's axes, `time` (the
    samples) and `column`, each point's CSV trajectory bit for bit, NaN after its last sample."""
    grid = ["fig3_18", "--set", "surface.law=coulomb", "--set", "solver.samples=21", "--vary", "surface.mu=0.05,0.1,0.2",
            "--vary", "push.yn=0,2e-8", "--quiet", "--jobs", "2"]
    sweep(tmp_path, *grid, "--out", "g.nc", "--trajectories", "tr")
    ds = xr.open_dataset(tmp_path / "g.nc")
    assert ds.trajectory.dims == ("surface_mu", "push_yn", "time", "column")
    assert ds.samples.dims == ("surface_mu", "push_yn")
    first, names, units = read_trajectory(tmp_path / "tr" / "point_0.csv")
    assert list(ds.column.values) == names and list(ds.column_units.values) == units
    assert ds.sizes["column"] == len(names)
    for i in range(6):  # point i is (mu index i // 2, yn index i % 2): the last axis fastest
        tr, _, _ = read_trajectory(tmp_path / "tr" / f"point_{i}.csv")
        n = int(ds.samples.values[i // 2, i % 2])
        assert n == tr.shape[0]
        cell = ds.trajectory.values[i // 2, i % 2]
        assert same_bits(cell[:n], tr)
        assert np.isnan(cell[n:]).all()
    # xarray's labels reach a trajectory by its point's values.
    x = ds.trajectory.sel(surface_mu=0.1, push_yn=2e-8, column="x").values
    tr3, _, _ = read_trajectory(tmp_path / "tr" / "point_3.csv")
    assert same_bits(x[:tr3.shape[0]], tr3[:, names.index("x")])


def test_run_out_netcdf(tmp_path):
    """`nanopush run --out FILE.nc`: the trajectory over a dimension `t` (its coordinate), each
    column a variable with units, the CSV's values bit for bit; nothing else left beside it."""
    p = subprocess.run([CLI, "run", "fig3_17", "--out", "r.csv", "--quiet"], capture_output=True, text=True, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    p = subprocess.run([CLI, "run", "fig3_17", "--out", "r.nc", "--quiet"], capture_output=True, text=True, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert sorted(q.name for q in tmp_path.iterdir()) == ["r.csv", "r.nc", "r.schema.json"]
    cols, schema = read_csv(tmp_path / "r.csv")
    ds = xr.open_dataset(tmp_path / "r.nc")
    assert list(ds.sizes) == ["t"]
    assert same_bits(ds.t.values, cols["t"])
    for field in schema["fields"]:
        assert same_bits(ds[field["name"]].values, cols[field["name"]]), field["name"]
        assert ds[field["name"]].attrs["units"] == field["unit"]
    assert ds.attrs["run_outcome"] == "ok" and ds.attrs["run_engine"]


def test_icor_table_out_netcdf(tmp_path):
    """Every table written by a command's --out FILE takes FILE.nc (here `icor formulas`): the
    CSV's columns over `point`, bit for bit; an unknown extension is refused, nothing written."""
    for out in ("f.csv", "f.nc"):
        p = subprocess.run([CLI, "icor", "formulas", "--n", "7", "--out", out], capture_output=True, text=True,
                           cwd=tmp_path)
        assert p.returncode == 0, p.stderr
    assert sorted(q.name for q in tmp_path.iterdir()) == ["f.csv", "f.nc", "f.schema.json"]
    cols, schema = read_csv(tmp_path / "f.csv")
    ds = xr.open_dataset(tmp_path / "f.nc")
    assert list(ds.sizes) == ["point"] and ds.sizes["point"] == 7
    for field in schema["fields"]:
        if field["type"] == "number":
            assert same_bits(ds[field["name"]].values, cols[field["name"]]), field["name"]
            assert ds[field["name"]].attrs["units"] == field["unit"]
    p = subprocess.run([CLI, "icor", "formulas", "--out", "f.parquet"], capture_output=True, text=True, cwd=tmp_path)
    assert p.returncode == 2 and "unknown extension '.parquet'" in p.stderr
    assert not (tmp_path / "f.parquet").exists()


def test_result_to_xarray_is_run_netcdf(tmp_path):
    """nanopush.Result.to_xarray(): the dataset `nanopush run --out FILE.nc` writes, over `t`,
    the same values bit for bit and the same units."""
    import nanopush

    p = subprocess.run([CLI, "run", "fig3_17", "--out", "r.nc", "--quiet"], capture_output=True, text=True, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    ds = nanopush.run("fig3_17").to_xarray()
    nc = xr.open_dataset(tmp_path / "r.nc")
    assert ds.x.dims == ("t",) and list(ds.data_vars) == list(nc.data_vars)
    assert same_bits(ds.t.values, nc.t.values) and ds.t.attrs["units"] == nc.t.attrs["units"] == "s"
    for name in nc.data_vars:
        assert same_bits(ds[name].values, nc[name].values), name
        assert ds[name].attrs["units"] == nc[name].attrs["units"], name


def test_convert_table_of_a_directory(tmp_path):
    """`nanopush convert TABLE.csv`: any finished table (here fit-icor's) into TABLE.nc beside it,
    every column over `point` bit for bit with its units; the CSV and its sidecar stay."""
    (tmp_path / "pushes.csv").write_text("F,sigma_F,yn,sigma_yn\n8.505610578323183e-07,1.7e-08,5e-08,2e-9\n"
                                         "5.33822956537572e-07,1.1e-08,2e-07,2e-9\n")
    p = subprocess.run([CLI, "fit-icor", "pushes.csv", "--pressure", "known", "--out", "fi"], capture_output=True,
                       text=True, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    p = subprocess.run([CLI, "convert", "fi/fit_icor.csv"], capture_output=True, text=True, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert {"fit_icor.csv", "fit_icor.schema.json", "fit_icor.nc"} <= {q.name for q in (tmp_path / "fi").iterdir()}
    cols, schema = read_csv(tmp_path / "fi" / "fit_icor.csv")
    ds = xr.open_dataset(tmp_path / "fi" / "fit_icor.nc")
    assert list(ds.sizes) == ["point"] and ds.sizes["point"] == 2
    for field in schema["fields"]:
        if field["type"] == "number":
            assert same_bits(ds[field["name"]].values, cols[field["name"]]), field["name"]
            assert ds[field["name"]].attrs["units"] == field["unit"]
        elif field["type"] == "string":
            assert list(ds[field["name"]].values) == list(cols[field["name"]]), field["name"]
    assert ds.attrs["command"] == schema["nanopush"]["command"] and ds.attrs["source_table"] == "fit_icor.csv"
