"""The reader of result files, and xarray on them: every group opens, every dimension named."""
import numpy as np
import pytest

import shcontact
from conftest import SUMMARY_OF_LAYOUT


def test_summary_equals_csv(run_app):
    path, rows = run_app("ksweep", "examples/kinematic_sweep.nml", "--set", "output%fields=all")
    f = shcontact.ResultFile(path)
    s = f.summary()
    assert list(s["case"]) == list(range(1, 35))
    for column in list(SUMMARY_OF_LAYOUT.values()) + ["t_y", "yaw", "x_track", "nu_x"]:
        np.testing.assert_array_equal(s[column], [float(row[column]) for row in rows],
                                      err_msg=column)
    assert f.units()["fx"] == "N" and f.units()["phi"] == "rad/mm"
    # Counts are integers, the joined contact's patch count as n_loaded.
    for column in ("status", "n_patches", "n_loaded", "main_patch", "wheel_patches"):
        assert np.issubdtype(s[column].dtype, np.integer), column
    assert set(s["wheel_patches"]) <= {1, 2}
    assert f.attrs["software"] == "shcontact" and int(f.attrs["n_cases"]) == 34
    assert "&kinematics" in f.namelist
    # Every text is declared UTF-8 (the namelist's comments hold a few non-ASCII characters,
    # which an ASCII declaration made h5py's and xarray's string readers fail on).
    import h5py
    with h5py.File(path) as raw:
        assert "§" in raw["input/namelist"].asstr()[()]
        assert raw["input/namelist"].id.get_type().get_cset() == h5py.h5t.CSET_UTF8
    assert f.failures()["case"].size == 0
    assert f.cases() == list(range(1, 35))
    profiles = f.profiles()
    assert set(profiles) == {"wheel", "rail"} and profiles["rail"].shape[1] == 2


def test_fields_of_a_case(run_app):
    path, rows = run_app("ksweep", "examples/kinematic_sweep.nml", "--set", "output%fields=all")
    f = shcontact.ResultFile(path)
    # Cases with two loaded patches, both carrying a load (a loaded patch may carry none: then
    # it has forces but no fields).
    cases = [k for k, row in enumerate(rows, 1) if row["n_loaded"] == "2"]
    both = [k for k in cases if all("px" in f.fields(k, p) for p in (1, 2))]
    assert len(both) >= 1 and all(f.patches(k) == [1, 2] for k in cases)
    for patch in (1, 2):
        t = f.fields(both[0], patch)
        area = t["dx"][:, None] * t["dy"]
        assert t["px"].shape == (t["y"].size, t["element"].size)
        assert np.sum(t["px"] * area) == pytest.approx(t["fx"], rel=1e-9)
        assert np.sum(t["py"] * area) == pytest.approx(t["fy"], rel=1e-9)
    with pytest.raises(KeyError, match="no group of case 99"):
        f.fields(99, 1)
    with pytest.raises(KeyError, match=f"case {both[0]} has no patch 5"):
        f.fields(both[0], 5)


def test_to_xarray(run_app):
    pytest.importorskip("xarray")
    path, rows = run_app("ksweep", "examples/kinematic_sweep.nml", "--set", "output%fields=all")
    f = shcontact.ResultFile(path)
    s = f.to_xarray("summary")
    assert dict(s.sizes) == {"case": 34} and s["fx"].attrs["units"] == "N"
    t = f.to_xarray(f.group(1, 1, "tangential"))
    assert t["px"].dims == ("y", "element") and t["xy"].dims == ("y", "element", "component")
    assert list(t["component"].values) == ["x", "y"]
    assert list(t["element"].values) == list(range(t.sizes["element"]))
    assert t["dx"].dims == ("y",)
    n = f.to_xarray(f.group(1, 1, "normal"))
    assert n["p0"].dims == ("y",)
    # No case failed: an empty failure table, as failures() gives (it was a raw h5py KeyError).
    assert f.to_xarray("failures").sizes.get("case", 0) == 0


def test_xarray_opens_every_group(run_app):
    """Every dimension has its HDF5 dimension scale, so xarray (h5netcdf) opens every group of
    the file with named dimensions: the tangential groups used to fail with "mixing of labeled
    and unlabeled dimensions", the profiles got phony dimensions."""
    xr = pytest.importorskip("xarray")
    pytest.importorskip("h5netcdf")
    import h5py
    path, _ = run_app("ksweep", "examples/kinematic_sweep.nml", "--set", "output%fields=all")
    groups = []
    with h5py.File(path) as f:
        f.visititems(lambda name, obj: groups.append(name) if isinstance(obj, h5py.Group)
                     else None)
        # Every dimension of every dataset has a scale.
        unscaled = []
        f.visititems(lambda name, obj: unscaled.extend(
            f"{name}[{k}]" for k, dim in enumerate(obj.dims) if len(dim) == 0)
            if isinstance(obj, h5py.Dataset) and obj.attrs.get("CLASS") != b"DIMENSION_SCALE"
            else None)
    assert unscaled == []
    # Opening is slow (~0.4 s a group): the groups outside /cases, and those of two cases, one
    # of them with two loaded patches (cases 19 to 22 of this sweep).
    groups = [g for g in groups if not g.startswith("cases/")
              or g.startswith(("cases/000001", "cases/000021"))]
    assert sum(g.endswith("tangential") for g in groups) == 3
    for group in groups:
        with xr.open_dataset(path, group=group, engine="h5netcdf") as ds:
            if group.endswith("tangential") and "px" in ds:
                assert ds["px"].dims == ("y", "element")
                assert ds["state"].dims == ("y", "element")
            if group == "summary":
                assert ds["fx"].dims == ("case",)
            if group == "input/profiles":
                assert ds["wheel"].dims == ("wheel_point", "column")


def test_not_a_result_file(run_app, tmp_path):
    """A file that is not HDF5 gave h5py's raw OSError ("file signature not found"), a group
    that is not there its raw KeyError: now messages that name the file (user trial, stop 46)."""
    text = tmp_path / "notes.txt"
    text.write_text("not HDF5\n")
    with pytest.raises(ValueError, match="is not an HDF5 file"):
        shcontact.ResultFile(str(text))
    with pytest.raises(ValueError, match="is not an HDF5 file"):
        shcontact.read_summary(str(text))
    path, _ = run_app("plain", "--set", "position%t_y=4.733")
    with pytest.raises(KeyError, match="has no group 'nope'"):
        shcontact.ResultFile(path).units("nope")


def test_older_files_are_not_read_as_zeros(app, tmp_path):
    """A result file lacking a /summary column of this version (an older version's) is not
    merged nor taken as a finished run by --resume: its missing column would read as 0."""
    import subprocess
    import h5py

    def run(*args):
        return subprocess.run([app, *args], capture_output=True, text=True, cwd=tmp_path)

    sweep = ["run", "--set", "sweep%nu_x=0,0.001", "-q"]
    for k in (1, 2):
        assert run(*sweep, "-o", "s.h5", "--shard", f"{k}/2").returncode == 0
    assert run(*sweep, "-o", "full.h5").returncode == 0
    for name in ("s-shard1of2.h5", "full.h5"):
        with h5py.File(tmp_path / name, "r+") as f:
            del f["summary/climbing"]
    merged = run("merge", "m.h5", "s-shard1of2.h5", "s-shard2of2.h5")
    assert merged.returncode == 2 and "has no /summary/climbing" in merged.stderr
    assert not (tmp_path / "m.h5").exists()
    resumed = run(*sweep, "-o", "full.h5", "--resume")
    assert resumed.returncode == 2 and "it has no /summary/climbing" in resumed.stderr


def test_older_checkpoint_refused_at_the_start(app, tmp_path):
    """A checkpoint whose blocks lack a /summary column of this version (made by an older
    version) is refused when --resume starts, not at the final merge after solving the rest."""
    import os
    import subprocess
    import h5py

    (tmp_path / "s.nml").write_text("&sweep nu_x = 0.0, 1.0e-3, 2.0e-3, 3.0e-3 /\n"
                                    "&output fields = 'all', checkpoint_cases = 1 /\n"
                                    "&normal n_strips = 20 /\n&tangential n_elements = 10 /\n")
    env = dict(os.environ, SHCONTACT_TEST_ABORT_AFTER_BLOCKS="2")
    killed = subprocess.run([app, "run", "s.nml", "-q", "-o", "out.h5"], capture_output=True,
                            text=True, cwd=tmp_path, env=env)
    assert killed.returncode != 0
    blocks = sorted((tmp_path / "out.h5.partial").glob("block_*.h5"))
    assert blocks
    with h5py.File(blocks[0], "r+") as f:
        del f["summary/climbing"]
    resumed = subprocess.run([app, "run", "s.nml", "-q", "-o", "out.h5", "--resume"],
                             capture_output=True, text=True, cwd=tmp_path)
    assert resumed.returncode == 2, resumed.stderr
    assert "made by an older version" in resumed.stderr and "climbing" in resumed.stderr
    assert not (tmp_path / "out.h5").exists()
