"""shcontact for Python: wheel-rail rolling contact (semi-Hertzian normal contact, FASTSIM_SH).

* :class:`Contact`: the solver of the shared library libshcontact.so through its C API, with a
  numpy interface (prescribed creepages and kinematic calls over arrays of cases, results as
  dicts of arrays, element fields of a patch); :class:`Wheelset`: both wheels of a wheelset in
  one call (the vehicle code's call: totals on the wheelset and each wheel's values);
* :class:`ResultFile`, :func:`read_summary`, :func:`read_fields`: the HDF5 result files of the
  ``shcontact`` program as numpy arrays or xarray Datasets.

Units: mm, N, MPa, rad (spin creepage rad/mm). Documentation: doc/python.md.
"""
from . import layout
from ._library import LibraryNotFoundError, find_library, load_library
from .results import ResultFile, read_fields, read_summary
from .solver import Contact, ShcontactError, Wheelset

__version__ = "0.1.0"

__all__ = ["Contact", "Wheelset", "ShcontactError", "ResultFile", "read_summary", "read_fields",
           "LibraryNotFoundError", "find_library", "load_library", "layout", "__version__"]
