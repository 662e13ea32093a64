"""Reading the HDF5 result files of ``shcontact run`` into numpy arrays or xarray Datasets.

The layout is README's "The HDF5 output" (doc/app.md): ``/summary`` one row per case,
``/cases/NNNNNN/patch_K/{geometry,normal,tangential}`` the per-case fields, ``/failures`` the
failed cases. Every dimension of a table has its HDF5 dimension scale (``summary/case``, the
strip centres ``y``, the element index ``element``), which name the dimensions here and let
``xarray.open_dataset(path, group=..., engine="h5netcdf")`` open the groups as well.

    >>> f = shcontact.ResultFile("build/headline.h5")
    >>> f.summary()["fx"]                  # numpy array, one value per case (N)
    >>> f.fields(case=1, patch=1)["px"]    # (n_strips, n_elements) traction (MPa)
    >>> f.to_xarray("summary")             # xarray.Dataset with dimension "case"

Needs h5py; :meth:`ResultFile.to_xarray` needs xarray.
"""
import os

import numpy as np

__all__ = ["ResultFile", "read_summary", "read_fields"]


def _h5py():
    try:
        import h5py
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError("shcontact: reading result files needs h5py "
                          "(pip install h5py, or pip install './python[files]')") from exc
    return h5py


def _text(value):
    """A text attribute or dataset value as str."""
    if isinstance(value, bytes):
        return value.decode()
    if isinstance(value, np.ndarray) and value.dtype.kind == "S":
        return np.char.decode(value).astype(str)
    return value


def _read(dataset):
    """A dataset as numpy (text decoded, scalars as Python/numpy scalars)."""
    value = dataset[()]
    if isinstance(value, np.ndarray) and value.dtype.kind == "S":
        return np.char.rstrip(np.char.decode(value)).astype(str)
    if isinstance(value, bytes):
        return value.decode().rstrip()
    return value


class ResultFile:
    """A result file of ``shcontact run`` (or ``shcontact merge``). The file is opened for each
    call, so the object can be kept while the program writes other files."""

    def __init__(self, path):
        if not os.path.isfile(path):
            raise FileNotFoundError(f"shcontact: no result file '{path}'")
        self.path = path
        try:
            f = self._open()
        except OSError as exc:
            # h5py's "file signature not found" for a file that is not HDF5; a lock or a
            # permission error stays what it is.
            if "signature" not in str(exc):
                raise
            raise ValueError(f"shcontact: '{path}' is not an HDF5 file (not a shcontact result "
                             "file)") from exc
        with f:
            if "summary" not in f:
                raise ValueError(f"shcontact: '{path}' is not a shcontact result file "
                                 "(no /summary group)")

    def _open(self):
        return _h5py().File(self.path, "r")

    @property
    def attrs(self):
        """The root attributes (software, version, units, sign_convention, n_cases, ...)."""
        with self._open() as f:
            return {key: _text(value) for key, value in f.attrs.items()}

    @property
    def namelist(self):
        """The resolved configuration of the run (namelist text, a case file)."""
        with self._open() as f:
            return _read(f["input/namelist"])

    def profiles(self):
        """{'wheel': (n, 2) array, 'rail': (n, 2) array} of (y, z) in mm, as used."""
        with self._open() as f:
            group = f.get("input/profiles", {})
            return {name: group[name][()] for name in ("wheel", "rail") if name in group}

    def summary(self):
        """The /summary table: dict of column name to a 1-D array over the cases of the file
        (text columns as str arrays). ``units()`` gives the units. A failed case's row has
        ``status`` != 0 and 0 in every result column: select ``summary["status"] == 0`` before
        averaging or plotting."""
        return self._group("summary")

    def failures(self):
        """{'case': array, 'message': array} of the failed cases (empty arrays when none)."""
        with self._open() as f:
            if "failures" not in f:
                return {"case": np.zeros(0, dtype=np.int32), "message": np.zeros(0, dtype=str)}
        return self._group("failures")

    def units(self, group="summary"):
        """{dataset name: units} of a group (``"summary"``, or a path as in :meth:`group`)."""
        with self._open() as f:
            if group not in f:
                raise KeyError(f"shcontact: '{self.path}' has no group '{group}' (groups: "
                               f"{', '.join(sorted(f))})")
            g = f[group]
            return {name: _text(g[name].attrs.get("units", b"")) for name in g
                    if isinstance(g[name], _h5py().Dataset)}

    def cases(self):
        """The case numbers (1-based) that have a per-case group (fields) in the file."""
        with self._open() as f:
            return sorted(int(name) for name in f.get("cases", {}))

    def patches(self, case):
        """The patch numbers of a case's group."""
        with self._open() as f:
            group = f[self._case_path(f, case)]
            return sorted(int(name.split("_", 1)[1]) for name in group
                          if name.startswith("patch_"))

    def group(self, case, patch, part="tangential"):
        """Path of ``part`` (geometry, normal, tangential) of a patch of a case."""
        with self._open() as f:
            path = f"{self._case_path(f, case)}/patch_{patch}"
            if path not in f:
                raise KeyError(f"shcontact: case {case} has no patch {patch} in the file "
                               f"(its patches: {self.patches(case)})")
            return f"{path}/{part}"

    def fields(self, case=1, patch=1):
        """The tangential group of a case's patch: forces (scalars, N, N mm) and the element
        fields as (n_strips, n_elements) arrays (row i a strip, column j an element from the
        leading edge): ``x``, ``pn``, ``px``, ``py``, ``slip``, ``state``; ``y`` the strip
        centres, ``dx`` the element length of each strip, ``dy`` the strip width (mm)."""
        return self._group(self.group(case, patch, "tangential"))

    def normal(self, case=1, patch=1):
        """The normal group of a case's patch: approach, load, ... and the strip table."""
        return self._group(self.group(case, patch, "normal"))

    def _group(self, path):
        with self._open() as f:
            g = f[path]
            return {name: _read(g[name]) for name in g if isinstance(g[name], _h5py().Dataset)}

    @staticmethod
    def _case_path(f, case):
        for name in f.get("cases", {}):
            if int(name) == int(case):
                return f"cases/{name}"
        raise KeyError(f"shcontact: no group of case {case} in the file (cases with fields: "
                       f"{sorted(int(n) for n in f.get('cases', {}))})")

    def to_xarray(self, group="summary"):
        """A group (``"summary"``, ``"failures"``, ``"geometry/patch_1"``, or
        :meth:`group`'s path) as an ``xarray.Dataset``: each dataset a variable, its dimensions
        named by their dimension scales, the scales as coordinates, ``units`` and ``long_name``
        as attributes."""
        import xarray as xr
        h5py = _h5py()
        with self._open() as f:
            if group not in f:
                if group == "failures":  # none failed: an empty table, as failures() gives
                    return xr.Dataset({"case": ("case", np.zeros(0, dtype=np.int32)),
                                       "message": ("case", np.zeros(0, dtype=str))})
                raise KeyError(f"shcontact: no group '{group}' in the file")
            g = f[group]
            variables, coords = {}, {}
            for name in g:
                obj = g[name]
                if not isinstance(obj, h5py.Dataset):
                    continue
                is_scale = _text(obj.attrs.get("CLASS", b"")) == "DIMENSION_SCALE"
                dims = []
                for k, dim in enumerate(obj.dims):
                    scales = list(dim.values())
                    if scales:
                        dims.append(scales[0].name.rsplit("/", 1)[-1])
                    else:  # a scale's own dimension, or one without a scale (older files)
                        dims.append(name if is_scale and obj.ndim == 1 else f"{name}_dim{k}")
                attrs = {key: _text(obj.attrs[key]) for key in ("units", "long_name")
                         if key in obj.attrs}
                data = _read(obj)
                target = coords if is_scale else variables
                target[name] = xr.Variable(tuple(dims), data, attrs=attrs)
            return xr.Dataset(variables, coords=coords)


def read_summary(path):
    """The /summary table of a result file: dict of 1-D arrays (:meth:`ResultFile.summary`)."""
    return ResultFile(path).summary()


def read_fields(path, case=1, patch=1):
    """The tangential fields of a case's patch (:meth:`ResultFile.fields`)."""
    return ResultFile(path).fields(case, patch)
