"""Finding and loading libshcontact.so, and the argument types of its C API (include/shcontact.h).

The library is looked for, in this order, at:

1. the path given to :func:`load_library` (or to ``Contact(..., library=PATH)``);
2. ``$SHCONTACT_LIB``: the library file, or the directory holding ``libshcontact.so``;
3. the ``libdir`` of pkg-config's ``shcontact.pc`` (``PKG_CONFIG_PATH=PREFIX/lib/pkgconfig``);
4. ``$HOME/.local/lib``, the default prefix of ``scripts/install``;
5. the system's library path (``ctypes.util.find_library``).
"""
import ctypes
import ctypes.util
import os
import shutil
import subprocess

__all__ = ["LibraryNotFoundError", "find_library", "load_library"]

_NAME = "libshcontact.so"


class LibraryNotFoundError(OSError):
    """libshcontact.so was not found (or could not be loaded)."""


def _pkg_config_libdir():
    if not shutil.which("pkg-config"):
        return None
    try:
        out = subprocess.run(["pkg-config", "--variable=libdir", "shcontact"],
                             capture_output=True, text=True, check=True).stdout.strip()
    except (subprocess.CalledProcessError, OSError):
        return None
    return out or None


def _in_directory(directory):
    path = os.path.join(directory, _NAME)
    return path if os.path.exists(path) else None


def find_library(path=None):
    """The path of libshcontact.so by the rules of this module; LibraryNotFoundError if none."""
    origin = "the library argument"
    if not path:
        path, origin = os.environ.get("SHCONTACT_LIB"), "SHCONTACT_LIB"
    if path:
        found = _in_directory(path) if os.path.isdir(path) else path
        if found and os.path.isfile(found):
            return found
        raise LibraryNotFoundError(
            f"shcontact: {origin} names '{path}', which is neither {_NAME} nor a directory "
            f"holding it")
    home = os.path.join(os.path.expanduser("~"), ".local", "lib")
    for directory in (_pkg_config_libdir(), home):
        found = _in_directory(directory) if directory else None
        if found:
            return found
    found = ctypes.util.find_library("shcontact")
    if found:
        return found
    raise LibraryNotFoundError(
        f"shcontact: {_NAME} not found. Install it with `scripts/install --prefix PREFIX` "
        f"(from the shcontact repository) and set SHCONTACT_LIB=PREFIX/lib (or "
        f"PKG_CONFIG_PATH=PREFIX/lib/pkgconfig); $HOME/.local/lib is searched by default")


_handle = ctypes.c_void_p
_dbl = ctypes.c_double
_int = ctypes.c_int
_text = ctypes.c_char_p
_pdbl = ctypes.POINTER(ctypes.c_double)
_pint = ctypes.POINTER(ctypes.c_int)

#: Argument types of every call of include/shcontact.h (all return an int status).
SIGNATURES = {
    "shcontact_create": [ctypes.POINTER(_handle), _text, _text, _int],
    "shcontact_create_arrays": [ctypes.POINTER(_handle), _int, _pdbl, _pdbl, _int, _pdbl, _pdbl,
                                _int],
    "shcontact_get_profile": [_handle, _int, _int, _pint, _pdbl, _pdbl],
    "shcontact_destroy": [_handle],
    "shcontact_set_material": [_handle, _dbl, _dbl, _dbl],
    "shcontact_set_track": [_handle, _dbl, _dbl, _dbl, _int, _dbl, _dbl, _dbl],
    "shcontact_set_option": [_handle, _text, _text],
    "shcontact_solve": [_handle, _dbl, _dbl, _int, _dbl, _dbl, _dbl, _dbl, _pdbl],
    "shcontact_patch": [_handle, _int, _pdbl],
    "shcontact_solve_kinematic": [_handle] + [_dbl] * 9 + [_int, _dbl, _pdbl],
    "shcontact_patch_kinematic": [_handle, _int, _pdbl],
    "shcontact_field_size": [_handle, _int, _pint, _pint],
    "shcontact_fields": [_handle, _int, _int, _int] + [_pdbl] * 7 + [_pint],
    "shcontact_last_error": [_handle, ctypes.c_char_p, _int],
    "shcontact_version": [ctypes.c_char_p, _int],
    "shcontact_set_value": [_handle, _text, _dbl],
    "shcontact_solve_state": [_handle],
    "shcontact_get_value": [_handle, _text, _int, _pdbl],
    "shcontact_get_field": [_handle, _text, _int, _int, _int, _pdbl],
    "shcontact_create_wheelset": [ctypes.POINTER(_handle), _text, _text],
    "shcontact_solve_wheelset": [_handle] + [_dbl] * 9 + [_int, _dbl, _dbl, _pdbl],
    "shcontact_wheelset_wheel": [_handle, _int, _int, _pdbl],
}

_loaded = {}


def load_library(path=None):
    """The library as a ctypes.CDLL with the argument types declared (loaded once per path)."""
    found = find_library(path)
    if found not in _loaded:
        try:
            lib = ctypes.CDLL(found)
        except OSError as exc:
            raise LibraryNotFoundError(f"shcontact: cannot load '{found}': {exc}") from exc
        for name, argtypes in SIGNATURES.items():
            function = getattr(lib, name)
            function.argtypes = argtypes
            function.restype = _int
        _loaded[found] = lib
    return _loaded[found]


def library_version(lib):
    """The version string the library reports."""
    buffer = ctypes.create_string_buffer(64)
    n = lib.shcontact_version(buffer, len(buffer))
    return buffer.value[:n].decode()
