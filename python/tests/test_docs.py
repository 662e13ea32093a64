"""The documented examples: the README's five lines print what the README shows, and every
Python block of doc/python.md runs (in order, in one interpreter, next to the result file its
reader examples open)."""
import os
import re
import subprocess
import sys

import pytest


def blocks(text, language):
    return re.findall(r"^```" + language + r"\n(.*?)^```", text, re.M | re.S)


def run_python(code, cwd):
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=cwd)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_readme_example(repo, tmp_path):
    with open(os.path.join(repo, "README.md")) as f:
        section = f.read().split("\n## Python\n", 1)[1].split("\n## ", 1)[0]
    code = blocks(section, "python")[0]
    assert len(code.strip().splitlines()) == 5
    expected = section.split("prints", 1)[1]
    expected = blocks(expected, "")[0]
    assert run_python(code, tmp_path) == expected


def test_python_md_examples(repo, app, tmp_path):
    pytest.importorskip("xarray")
    pytest.importorskip("h5netcdf")
    (tmp_path / "build").mkdir()
    done = subprocess.run([app, "run", "examples/kinematic_sweep.nml", "-o",
                           str(tmp_path / "build" / "ksweep.h5"), "--set", "output%fields=all",
                           "-q"], capture_output=True, text=True, cwd=repo)
    assert done.returncode == 0, done.stderr
    with open(os.path.join(repo, "doc", "python.md")) as f:
        code = "\n".join(blocks(f.read(), "python"))
    assert "solve_kinematic" in code and "open_dataset" in code
    out = run_python(code, tmp_path)
    assert "('y', 'element')" in out  # xarray names the dimensions of the fields
