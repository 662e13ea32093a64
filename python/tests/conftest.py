"""Fixtures of the Python package's tests: the repository, the shcontact program, scratch runs.

The library is found as the package finds it ($SHCONTACT_LIB, pkg-config, ...); the program
from $SHCONTACT_APP or `shcontact` on PATH (tests that need it are skipped without it).
scripts/test_python sets both to this checkout's build.
"""
import csv
import io
import os
import shutil
import subprocess

import pytest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

#: The /summary (and CSV) column of each value of the C layout they share.
SUMMARY_OF_LAYOUT = {
    "fn": "fn", "fx": "fx", "fy": "fy", "mz": "mz", "fx_norm": "fx_norm",
    "fy_norm": "fy_norm", "coulomb": "coulomb_ratio", "adhesion": "adhesion_fraction",
    "approach": "delta", "area": "area", "p_max": "p_max", "gamma0": "gamma0", "r0": "r0",
    "y_track": "y_track", "sum_fn": "fn_total", "sum_fx": "fx_total", "sum_fy": "fy_total",
    "sum_fz": "fz_total", "n_patches": "n_patches", "n_loaded": "n_loaded",
}
KINEMATIC_SUMMARY = {"x_track": "x_track", "nu_x": "nu_x", "nu_y": "nu_y", "phi": "phi"}


@pytest.fixture(scope="session")
def repo():
    return REPO


@pytest.fixture(scope="session")
def app():
    path = os.environ.get("SHCONTACT_APP") or shutil.which("shcontact")
    if not path:
        pytest.skip("no shcontact program: set SHCONTACT_APP or put shcontact on PATH")
    return path


@pytest.fixture(scope="session")
def run_app(app, tmp_path_factory):
    """run_app(name, *args) runs `shcontact run ARGS -o DIR/name.h5 -q --format csv` and gives
    (path of the result file, list of CSV rows as dicts of str)."""
    cache = {}

    def run(name, *args):
        if (name, args) not in cache:
            out = tmp_path_factory.mktemp(name) / f"{name}.h5"
            done = subprocess.run([app, "run", *args, "-o", str(out), "-q", "--format", "csv"],
                                  capture_output=True, text=True, cwd=REPO)
            assert done.returncode == 0, done.stderr
            rows = list(csv.DictReader(io.StringIO(done.stdout)))
            cache[(name, args)] = (str(out), rows)
        return cache[(name, args)]

    return run
