"""The package's constants against the C header, and its version against the library's."""
import os
import re

import pytest

import shcontact
from shcontact import layout


def header_constants(repo):
    path = os.path.join(repo, "include", "shcontact.h")
    if not os.path.exists(path):
        pytest.skip("include/shcontact.h not found (tests run outside the repository)")
    with open(path) as f:
        return {m.group(1): int(m.group(2)) for m in
                re.finditer(r"^#define SHCONTACT_(\w+) +\(?(-?\d+)\)?", f.read(), re.M)}


def test_value_layouts_match_header(repo):
    h = header_constants(repo)
    for i, name in enumerate(layout.KINEMATIC):
        assert h[name.upper()] == i, name
    assert h["PATCH_SIZE"] == len(layout.PATCH)
    assert h["RESULT_SIZE"] == len(layout.RESULT)
    assert h["KIN_SIZE"] == len(layout.KINEMATIC)
    assert set(layout.UNITS) == set(layout.KINEMATIC + layout.WHEEL + layout.FLAGS)


def test_codes_match_header(repo):
    h = header_constants(repo)
    for name, mode in layout.LOAD_MODES.items():
        assert h["LOAD_" + name.upper()] == mode
    for name, code in layout.STATUS.items():
        assert h[name.upper()] == code
    assert (h["STATE_EXTERIOR"], h["STATE_ADHESION"], h["STATE_SLIP"]) == (
        layout.STATE_EXTERIOR, layout.STATE_ADHESION, layout.STATE_SLIP)
    assert (h["RIGHT"], h["LEFT"]) == (layout.SIDES["right"], layout.SIDES["left"])
    assert (h["PROFILE_RAIL"], h["PROFILE_WHEEL"]) == (layout.PROFILE_KINDS["rail"],
                                                       layout.PROFILE_KINDS["wheel"])


def test_versions_agree(repo):
    with open(os.path.join(repo, "fpm.toml")) as f:
        fpm_version = re.search(r'^version *= *"([^"]+)"', f.read(), re.M).group(1)
    with open(os.path.join(repo, "python", "pyproject.toml")) as f:
        py_version = re.search(r'^version *= *"([^"]+)"', f.read(), re.M).group(1)
    assert shcontact.__version__ == fpm_version == py_version
    assert shcontact.Contact().library_version == fpm_version


def test_library_found_by_variable(monkeypatch, tmp_path):
    found = shcontact.find_library()  # as the other tests find it
    monkeypatch.setenv("SHCONTACT_LIB", str(tmp_path / "missing.so"))
    with pytest.raises(shcontact.LibraryNotFoundError, match="SHCONTACT_LIB.*missing.so"):
        shcontact.find_library()
    if os.path.isabs(found):
        # The directory holding the library is accepted as well as the file.
        monkeypatch.setenv("SHCONTACT_LIB", os.path.dirname(found))
        assert os.path.samefile(shcontact.find_library(), found)
