"""numpy interface to the solver: one :class:`Contact` per wheel, vectorised over arrays of cases.

Units: mm, N, MPa (N/mm^2), rad; spin creepage rad/mm; velocities mm/s, rates rad/s. Creepages
are those of the wheel relative to the rail at the geometric contact point; forces act on the
wheel (doc/api.md, README "Units and signs").

    >>> import numpy as np, shcontact
    >>> c = shcontact.Contact("builtin:S1002", "builtin:UIC60")
    >>> r = c.solve(t_y=np.linspace(0, 6, 7), normal_force=64.7e3, nu_x=0.58e-3)
    >>> r["fx"].shape
    (7,)

Every input of :meth:`Contact.solve` and :meth:`Contact.solve_kinematic` may be an array; they
are broadcast against each other and each element is one call of the C library (a loop in
Python; the library keeps what it can between calls at the same position). The result is a dict
of arrays of the broadcast shape, keyed by the names of :mod:`shcontact.layout`, plus
``status`` (0 for a solved case).
"""
import ctypes
import functools
import operator
import os
import threading

import numpy as np

from . import layout
from ._library import load_library, library_version

__all__ = ["Contact", "ShcontactError"]

#: The defaults of the library (Manchester benchmark track, rail canted 1:40 by the track).
DEFAULT_TRACK = {
    "gauge": 1435.0, "gauge_height": 14.0, "inclination": 1.0 / 40.0, "rail_canted": False,
    "flange_back_distance": 1360.0, "flange_back_position": -70.0, "nominal_radius": 460.0,
}


class ShcontactError(RuntimeError):
    """A call of the library failed: ``status`` (the C status code), ``message`` (its text),
    ``case`` (the index of the failed case in the input arrays, or None)."""

    def __init__(self, status, message, case=None):
        if case is not None:
            case = tuple(int(i) for i in case)
        where = "" if case is None else f" (case {case})"
        super().__init__(f"shcontact: status {status}{where}: {message}")
        self.status, self.message, self.case = status, message, case

    def __reduce__(self):
        # Picklable (multiprocessing sends a worker's exception to the parent).
        return (type(self), (self.status, self.message, self.case))


def _locked(method):
    """Run a method of :class:`Contact` under the contact's lock: ctypes releases the GIL during
    a library call, and a handle must not be used by two threads at once (doc/api.md)."""
    @functools.wraps(method)
    def wrapper(self, *args, **kwargs):
        with self._lock:
            return method(self, *args, **kwargs)
    return wrapper


def _c_double_array(values):
    array = np.ascontiguousarray(values, dtype=np.float64)
    return array, array.ctypes.data_as(ctypes.POINTER(ctypes.c_double))


def _number(what, value):
    """``value`` as a float (anything ``float`` takes but text: numpy scalars and 0-d arrays,
    Decimal, Fraction), or a TypeError naming ``what`` (ctypes' own message names neither the
    keyword nor the expected type)."""
    if not isinstance(value, (str, bytes)):
        try:
            return float(value)
        except (TypeError, ValueError):
            pass
    raise TypeError(f"shcontact: {what} = {value!r}: expected a number")


def _index(what, value, main=False):
    """``value`` as a patch number (an integer, numpy's and 0-d integer arrays too), or a
    TypeError naming ``what``; ``main``: 0 names the main patch."""
    try:
        if not isinstance(value, (bool, np.bool_)):
            return operator.index(value)
    except TypeError:
        pass
    expected = "an integer (0 the main patch, else 1-based)" if main else "an integer (1-based)"
    raise TypeError(f"shcontact: {what} = {value!r}: expected {expected}")


def _flag(what, value):
    """``value`` as 0 or 1 (True, False, numpy's bools, the integers 0 and 1), or a TypeError
    naming ``what``."""
    if isinstance(value, (bool, np.bool_)):
        return int(value)
    try:
        if not isinstance(value, (str, bytes)) and operator.index(value) in (0, 1):
            return operator.index(value)
    except TypeError:
        pass
    raise TypeError(f"shcontact: {what} = {value!r}: expected True or False")


def _text(what, value):
    """``value`` encoded for the C API, or a TypeError naming ``what``."""
    if not isinstance(value, str):
        raise TypeError(f"shcontact: {what} = {value!r}: expected a string")
    return value.encode()


def _numbers(**values):
    """The named inputs as float64 arrays (broadcast by the caller), or a TypeError naming the
    first that is not numbers: text, None or objects, which numpy would read as numbers
    ("3") or NaN (None)."""
    arrays = []
    for name, value in values.items():
        array = None
        if value is not None and not isinstance(value, (str, bytes)):
            array = np.asarray(value)
        if array is None or array.dtype.kind not in "iuf":
            raise TypeError(f"shcontact: {name} = {value!r}: expected a number or an array of "
                            "numbers")
        arrays.append(array.astype(np.float64))
    return arrays


def _check_errors(errors):
    if errors not in ("raise", "nan"):
        raise ValueError(f"shcontact: errors='{errors}': expected 'raise' or 'nan'")


def _result_column(array, i, name):
    """Column ``i`` of a result array as returned: counts and flags as integers (a failed
    case's NaN as 0), a 0-d array as a scalar."""
    column = array[..., i]
    if name in layout.INTEGER:
        column = np.where(np.isnan(column), 0, column).astype(np.int64)
    return column[()] if column.ndim == 0 else column


class Contact:
    """One wheel on its rail: a handle of the C API (``shcontact_create``).

    ``wheel``, ``rail``: profile names (``builtin:S1002``, ``builtin:UIC60``,
    ``builtin:UIC60-canted``) or file names. ``side``: ``"right"`` or ``"left"``.
    ``material``: dict of ``shear_modulus`` (MPa), ``poisson``, ``friction``; ``track``: dict of
    the keywords of :meth:`set_track`; ``options``: dict of option keys (``"tangential%method"``,
    ... as in doc/api.md) to values; ``fields=True`` keeps the element fields of every solve for
    :meth:`fields`. ``library``: path of libshcontact.so (else found as
    :mod:`shcontact._library` says).

    One contact may be shared by threads: its calls take turns (a lock); contacts of their own
    solve in parallel. A contact cannot be copied (it holds a C handle): create another one.
    """

    def __init__(self, wheel="builtin:S1002", rail="builtin:UIC60", side="right", *,
                 material=None, track=None, options=None, fields=False, library=None):
        self._start(library)
        self._check(self._lib.shcontact_create(ctypes.byref(self._handle), os.fsencode(wheel),
                                               os.fsencode(rail), self._side(side)))
        self._track_defaults = self._resolved_track_defaults()
        self._configure(material, track, options, fields)

    @classmethod
    def from_arrays(cls, wheel_y, wheel_z, rail_y, rail_z, side="right", *, material=None,
                    track=None, options=None, fields=False, library=None):
        """A contact from profiles given as arrays of points (mm; the right-side canonical form
        of ``shcontact_create_arrays``: y towards the field side, z down; the wheel from the field
        side to the flange back, the rail from the track centre to the field side)."""
        self = cls.__new__(cls)
        self._start(library)
        wy, pwy = _c_double_array(wheel_y)
        wz, pwz = _c_double_array(wheel_z)
        ry, pry = _c_double_array(rail_y)
        rz, prz = _c_double_array(rail_z)
        if wy.shape != wz.shape or ry.shape != rz.shape or wy.ndim != 1 or ry.ndim != 1:
            raise ValueError("shcontact: wheel_y/wheel_z and rail_y/rail_z must be 1-D arrays of "
                             "equal length each")
        self._check(self._lib.shcontact_create_arrays(ctypes.byref(self._handle), wy.size, pwy,
                                                      pwz, ry.size, pry, prz, cls._side(side)))
        self._track_defaults = self._resolved_track_defaults()
        self._configure(material, track, options, fields)
        return self

    # --- set-up --------------------------------------------------------------------------------

    def _start(self, library):
        self._lock = threading.RLock()
        self._lib = load_library(library)
        self._handle = ctypes.c_void_p()
        self._fields = False
        self._track_defaults = dict(DEFAULT_TRACK)

    def _resolved_track_defaults(self):
        # The library's defaults for this wheel: a MiniProf wheel has its origin at its flange
        # back, so its flange-back position is 0, not S1002's -70 mm (doc/app.md, "&track").
        return dict(DEFAULT_TRACK,
                    flange_back_position=self.value("track%flange_back_position"))

    @staticmethod
    def _side(side):
        if side not in layout.SIDES:
            raise ValueError(f"shcontact: side '{side}': expected 'right' or 'left'")
        return layout.SIDES[side]

    def _configure(self, material, track, options, fields):
        if material:
            self.set_material(**material)
        if track:
            self.set_track(**track)
        for key, value in (options or {}).items():
            self.set_option(key, value)
        if fields:
            self.set_option("output%fields", "all")

    @_locked
    def set_material(self, shear_modulus=None, poisson=None, friction=None):
        """Shear modulus G (MPa), Poisson's ratio, friction coefficient; those not given keep the
        values the contact holds now."""
        now = {name: self.value("material%" + name) if given is None else given
               for name, given in (("shear_modulus", shear_modulus), ("poisson", poisson),
                                   ("friction", friction))}
        now = {name: _number(f"set_material {name}", value) for name, value in now.items()}
        self._check(self._lib.shcontact_set_material(self._ptr(), now["shear_modulus"],
                                                     now["poisson"], now["friction"]))

    @_locked
    def set_track(self, **track):
        """Track: ``gauge``, ``gauge_height`` (mm), ``inclination`` (slope, 1:40 = 0.025),
        ``rail_canted`` (the rail profile is already canted), ``flange_back_distance``,
        ``flange_back_position``, ``nominal_radius`` (mm); those not given keep the library's
        defaults (:data:`DEFAULT_TRACK`, with the flange-back position the library took for this
        wheel: 0 for a MiniProf wheel), not earlier calls' values."""
        unknown = set(track) - set(DEFAULT_TRACK)
        if unknown:
            raise TypeError(f"shcontact: set_track: unknown keyword(s) {sorted(unknown)}; "
                            f"expected {sorted(DEFAULT_TRACK)}")
        t = dict(self._track_defaults, **track)
        for name in t:
            if name != "rail_canted":
                t[name] = _number(f"set_track {name}", t[name])
        self._check(self._lib.shcontact_set_track(
            self._ptr(), t["gauge"], t["gauge_height"], t["inclination"],
            _flag("set_track rail_canted", t["rail_canted"]), t["flange_back_distance"],
            t["flange_back_position"], t["nominal_radius"]))

    @_locked
    def set_option(self, key, value):
        """One option as in the app's case files (``"tangential%bound"``, ``"clipped"``)."""
        self._check(self._lib.shcontact_set_option(self._ptr(), _text("set_option key", key),
                                                   str(value).encode()))
        if key.strip().lower() == "output%fields":
            self._fields = str(value).strip().strip("'\"").strip().lower() in (
                "all", "1", "true", ".true.")

    @_locked
    def value(self, key, patch=0):
        """One number by key (``shcontact_get_value``): a numeric input ``group%variable`` as
        the handle holds it now (``"track%flange_back_position"``, ``"material%friction"``, ...),
        or a result value of the last solve by name (``"fx"``, ``"p_max"``, ...; ``patch`` 0 the
        main patch, else 1-based)."""
        x = ctypes.c_double()
        self._check(self._lib.shcontact_get_value(self._ptr(), _text("value key", key),
                                                  _index("value patch", patch, main=True),
                                                  ctypes.byref(x)))
        return x.value

    @_locked
    def profile(self, kind):
        """The points (y, z) in mm of the contact's ``"wheel"`` or ``"rail"`` profile, as created
        (the form :meth:`from_arrays` takes)."""
        if kind not in layout.PROFILE_KINDS:
            raise ValueError(f"shcontact: profile '{kind}': expected 'wheel' or 'rail'")
        n = ctypes.c_int()
        self._lib.shcontact_get_profile(self._ptr(), layout.PROFILE_KINDS[kind], 0,
                                        ctypes.byref(n), None, None)
        y, py = _c_double_array(np.zeros(n.value))
        z, pz = _c_double_array(np.zeros(n.value))
        self._check(self._lib.shcontact_get_profile(self._ptr(), layout.PROFILE_KINDS[kind],
                                                    n.value, ctypes.byref(n), py, pz))
        return y, z

    @property
    def library_version(self):
        """The version the loaded library reports."""
        return library_version(self._lib)

    # --- solving -------------------------------------------------------------------------------

    def solve(self, t_y, *, nu_x=0.0, nu_y=0.0, phi=0.0, roll=0.0, normal_force=None,
              vertical_force=None, approach=None, vertical_position=None, shared_force=None,
              errors="raise"):
        """Contact with prescribed creepages (``shcontact_solve``): lateral wheelset shift
        ``t_y`` (mm, CONTACT's Y_WS), creepages ``nu_x``, ``nu_y``, spin ``phi`` (rad/mm), wheelset
        ``roll`` (rad), and exactly one load: ``normal_force`` (N, on the deepest patch),
        ``vertical_force`` (N, the wheel load shared by the patches), ``approach`` (mm, of the
        deepest patch), ``vertical_position`` (mm, of the wheel) or ``shared_force`` (N, the
        normal force of the wheel's contact, shared by its patches; doc/lobes.md). The creepages
        are those at the deepest patch's reference point; other loaded patches get the rigid
        slip at their own. Arrays broadcast.

        ``errors="raise"`` raises :class:`ShcontactError` at the first failed case;
        ``errors="nan"`` gives NaN values (0 counts) and the status in ``status``."""
        mode, load = self._load(normal_force, vertical_force, approach, vertical_position,
                                shared_force)
        inputs = np.broadcast_arrays(*_numbers(t_y=t_y, roll=roll, load=load, nu_x=nu_x,
                                               nu_y=nu_y, phi=phi))
        function = self._lib.shcontact_solve

        def call(handle, values, t_y, roll, load, nu_x, nu_y, phi):
            return function(handle, t_y, roll, mode, load, nu_x, nu_y, phi, values)

        return self._loop(call, inputs, layout.RESULT, errors)

    def _state_inputs(self, y_ws, yaw, roll, v_forward, v_lateral, v_vertical, roll_rate,
                      yaw_rate, pitch_rate, **loads):
        """The wheelset state and the loads as broadcast float64 arrays (TypeError naming a
        keyword that is not numbers); pitch_rate None is pure rolling at the nominal radius the
        handle holds now (set by set_track or by option key)."""
        if pitch_rate is None:
            pitch_rate = (-_numbers(v_forward=v_forward)[0]
                          / self.value("track%nominal_radius"))
        return np.broadcast_arrays(*_numbers(
            y_ws=y_ws, yaw=yaw, roll=roll, v_forward=v_forward, v_lateral=v_lateral,
            v_vertical=v_vertical, roll_rate=roll_rate, yaw_rate=yaw_rate,
            pitch_rate=pitch_rate, **loads))

    def solve_kinematic(self, y_ws, *, v_forward, yaw=0.0, roll=0.0, v_lateral=0.0,
                        v_vertical=0.0, roll_rate=0.0, yaw_rate=0.0, pitch_rate=None,
                        vertical_force=None, normal_force=None, approach=None,
                        vertical_position=None, shared_force=None, errors="raise"):
        """One wheel from the wheelset's position and velocities (``shcontact_solve_kinematic``,
        CONTACT's module 1; track frame x forward, y to the right, z down): ``y_ws`` (mm),
        ``yaw``, ``roll`` (rad), ``v_forward`` (> 0), ``v_lateral``, ``v_vertical`` (mm/s),
        ``roll_rate``, ``yaw_rate``, ``pitch_rate`` (rad/s; default pure rolling,
        -v_forward / nominal_radius) and one load (``vertical_force``, N, is what a vehicle code
        gives). The result adds the main patch's creepages ``nu_x``, ``nu_y``, ``phi`` and
        ``x_track``. Arrays broadcast; ``errors`` as in :meth:`solve`."""
        mode, load = self._load(normal_force, vertical_force, approach, vertical_position,
                                shared_force)
        inputs = self._state_inputs(y_ws, yaw, roll, v_forward, v_lateral, v_vertical,
                                    roll_rate, yaw_rate, pitch_rate, load=load)
        function = self._lib.shcontact_solve_kinematic

        def call(handle, values, *state):
            return function(handle, *state[:9], mode, state[9], values)

        return self._loop(call, inputs, layout.KINEMATIC, errors)

    @_locked
    def patch(self, patch):
        """The values of patch ``patch`` (1-based) of the last solve, as a dict of floats
        (:data:`layout.PATCH`; after :meth:`solve_kinematic` with the creepages and x_track)."""
        values = (ctypes.c_double * len(layout.KINEMATIC))()
        patch = _index("patch", patch)
        if self._last_kinematic:
            self._check(self._lib.shcontact_patch_kinematic(self._ptr(), patch, values))
            names = layout.PATCH + layout.KINEMATIC[len(layout.RESULT):]
            offsets = list(range(len(layout.PATCH))) + list(range(len(layout.RESULT),
                                                                  len(layout.KINEMATIC)))
        else:
            self._check(self._lib.shcontact_patch(self._ptr(), patch, values))
            names, offsets = layout.PATCH, range(len(layout.PATCH))
        return {name: values[i] for name, i in zip(names, offsets)}

    @_locked
    def fields(self, patch=None):
        """The element fields of patch ``patch`` (1-based; default the main patch) of the last
        solve, which must have been made with fields on (``Contact(..., fields=True)``): a dict of
        (n_strips, n_elements) arrays, row i a strip, column j an element from the leading
        edge, in the patch's contact frame: ``x`` (rolling direction, mm), ``y`` (strip centre,
        mm), ``area`` (mm^2), ``pn`` (pressure, MPa), ``px``, ``py`` (tractions on the wheel,
        MPa), ``slip`` (slip magnitude, 0 in adhesion), ``state`` (0 exterior, 1 adhesion,
        2 slip). Sum(px * area) is the patch's F_x."""
        if not self._fields:
            raise ShcontactError(layout.STATUS["usage"], "no element fields: create the contact "
                                 "with fields=True (option output%fields = all) before the solve")
        if patch is None:
            patch = self._main_patch
        patch = _index("fields patch", patch)
        nx, ny = ctypes.c_int(), ctypes.c_int()
        self._check(self._lib.shcontact_field_size(self._ptr(), patch, ctypes.byref(nx),
                                                   ctypes.byref(ny)))
        shape = (ny.value, nx.value)
        arrays = {name: np.zeros(shape) for name in ("x", "y", "area", "pn", "px", "py", "slip")}
        state = np.zeros(shape, dtype=np.intc)
        pointers = [arrays[name].ctypes.data_as(ctypes.POINTER(ctypes.c_double))
                    for name in ("x", "y", "area", "pn", "px", "py", "slip")]
        self._check(self._lib.shcontact_fields(
            self._ptr(), patch, nx.value, ny.value, *pointers,
            state.ctypes.data_as(ctypes.POINTER(ctypes.c_int))))
        arrays["state"] = state.astype(np.int8)
        return arrays

    # --- internals -----------------------------------------------------------------------------

    _last_kinematic = False
    _main_patch = 1

    @staticmethod
    def _load(normal_force, vertical_force, approach, vertical_position, shared_force=None):
        given = {name: value for name, value in (
            ("normal_force", normal_force), ("vertical_force", vertical_force),
            ("approach", approach), ("vertical_position", vertical_position),
            ("shared_force", shared_force)) if value is not None}
        if len(given) != 1:
            raise TypeError("shcontact: give exactly one load: normal_force, vertical_force, "
                            "approach, vertical_position or shared_force "
                            f"(got {sorted(given) or 'none'})")
        (name, value), = given.items()
        return layout.LOAD_MODES[name], value

    @_locked
    def _loop(self, call, inputs, names, errors):
        _check_errors(errors)
        shape = inputs[0].shape
        keyed = layout.WHEEL + layout.FLAGS
        out = np.full(shape + (len(names) + len(keyed),), np.nan)
        status = np.zeros(shape, dtype=np.int32)
        values = (ctypes.c_double * len(names))()
        value = ctypes.c_double()
        handle = self._ptr()
        flat = [a.ravel() for a in inputs]
        stat = None
        out_flat = out.reshape(-1, len(names) + len(keyed))
        status_flat = status.reshape(-1)
        for k in range(out_flat.shape[0]):
            stat = call(handle, values, *[float(a[k]) for a in flat])
            if stat == 0:
                out_flat[k, :len(names)] = values[:]
                # The wheel's joined contact, by key (not in the flat layout).
                for j, key in enumerate(keyed):
                    self._check(self._lib.shcontact_get_value(handle, key.encode(), 0,
                                                              ctypes.byref(value)))
                    out_flat[k, len(names) + j] = value.value
            else:
                status_flat[k] = stat
                if errors == "raise":
                    case = np.unravel_index(k, shape) if shape else None
                    raise ShcontactError(stat, self._message(), case)
        self._last_kinematic = len(names) == len(layout.KINEMATIC)
        self._main_patch = int(values[names.index("main_patch")]) if stat == 0 else 1
        result = {name: _result_column(out, i, name) for i, name in enumerate(names + keyed)}
        result["status"] = status[()] if status.ndim == 0 else status
        return result

    def _ptr(self):
        if not self._handle:
            raise ShcontactError(layout.STATUS["usage"], "the contact was closed")
        return self._handle

    def _message(self):
        buffer = ctypes.create_string_buffer(1024)
        self._lib.shcontact_last_error(self._handle, buffer, len(buffer))
        return buffer.value.decode(errors="replace")

    def _check(self, stat):
        if stat != 0:
            raise ShcontactError(stat, self._message())

    @_locked
    def close(self):
        """Release the handle (also done when the object is collected)."""
        if getattr(self, "_handle", None):
            self._lib.shcontact_destroy(self._handle)
            self._handle = ctypes.c_void_p()

    def __copy__(self):
        raise TypeError("shcontact: a Contact holds a C handle and cannot be copied; create "
                        "another Contact (the same arguments, or Contact.from_arrays with "
                        "this one's profile('wheel') and profile('rail'))")

    def __deepcopy__(self, memo):
        return self.__copy__()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:  # interpreter shutdown
            pass


class Wheelset(Contact):
    """Both wheels of a wheelset: a wheelset handle of the C API (``shcontact_create_wheelset``;
    the library's ``wheelset_solver_type``), the left wheel the mirror image of the right one.

    ``wheel``, ``rail``, ``material``, ``track``, ``options``, ``library`` as for
    :class:`Contact`; :meth:`set_material`, :meth:`set_track`, :meth:`set_option` and
    :meth:`value` (inputs) act on both wheels. Solve with :meth:`solve`; the one-wheel calls
    (``solve_kinematic``, ``patch``, ``fields``) are refused (status 1).
    """

    def __init__(self, wheel="builtin:S1002", rail="builtin:UIC60", *, material=None,
                 track=None, options=None, library=None):
        self._start(library)
        self._check(self._lib.shcontact_create_wheelset(ctypes.byref(self._handle),
                                                        os.fsencode(wheel), os.fsencode(rail)))
        self._track_defaults = self._resolved_track_defaults()
        self._configure(material, track, options, False)

    def solve(self, y_ws, *, v_forward, load_right, load_left, yaw=0.0, roll=0.0,
              v_lateral=0.0, v_vertical=0.0, roll_rate=0.0, yaw_rate=0.0, pitch_rate=None,
              load="vertical_force", errors="raise"):
        """Both wheels for the wheelset state (``shcontact_solve_wheelset``; the arguments of
        :meth:`Contact.solve_kinematic`, track frame x forward, y to the right, z down) and the
        load of each wheel, ``load_right``, ``load_left`` (N for the default
        ``load="vertical_force"``, each wheel's vertical load; below 1 N, 0 included, that wheel
        is lifted: no contact, its values zero). Arrays broadcast.

        Returns a dict: ``fx``, ``fy``, ``fz`` (N; the forces on the wheelset in the true track
        frame, ``fy`` towards the right rail's field side, ``fz`` down: -(Q_right + Q_left) when
        balanced), ``mz`` (N mm, their
        moment about the vertical axis through the wheelset centre), ``status``, and ``right``,
        ``left``: each wheel's main patch, counts and totals in its side frame (dicts of
        :data:`layout.KINEMATIC` arrays, as :meth:`Contact.solve_kinematic` gives for one
        wheel, and its ``climbing`` flag). ``errors`` as in :meth:`Contact.solve`."""
        if load not in layout.LOAD_MODES:
            raise ValueError(f"shcontact: load '{load}': expected one of "
                             f"{sorted(layout.LOAD_MODES)}")
        mode = layout.LOAD_MODES[load]
        inputs = self._state_inputs(y_ws, yaw, roll, v_forward, v_lateral, v_vertical,
                                    roll_rate, yaw_rate, pitch_rate, load_right=load_right,
                                    load_left=load_left)
        return self._wheelset_loop(mode, inputs, errors)

    def solve_kinematic(self, *args, **kwargs):
        raise ShcontactError(layout.STATUS["usage"], "a Wheelset solves both wheels: use "
                             "Wheelset.solve (Contact.solve_kinematic is the one-wheel call)")

    def patch(self, *args, **kwargs):
        raise ShcontactError(layout.STATUS["usage"], "a Wheelset returns each wheel's main "
                             "patch in Wheelset.solve's 'right' and 'left'; for every patch or "
                             "the element fields, use a Contact per wheel")

    def fields(self, *args, **kwargs):
        self.patch()

    @_locked
    def _wheelset_loop(self, mode, inputs, errors):
        _check_errors(errors)
        shape = inputs[0].shape
        names = layout.KINEMATIC + layout.FLAGS
        totals_names = ("fx", "fy", "fz", "mz")
        totals = np.full(shape + (4,), np.nan)
        wheels = {side: np.full(shape + (len(names),), np.nan) for side in layout.SIDES}
        status = np.zeros(shape, dtype=np.int32)
        out_totals = (ctypes.c_double * 4)()
        values = (ctypes.c_double * len(layout.KINEMATIC))()
        flag = ctypes.c_double()
        handle = self._ptr()
        flat = [a.ravel() for a in inputs]
        totals_flat = totals.reshape(-1, 4)
        wheels_flat = {side: w.reshape(-1, len(names)) for side, w in wheels.items()}
        status_flat = status.reshape(-1)
        for k in range(totals_flat.shape[0]):
            state = [float(a[k]) for a in flat]
            stat = self._lib.shcontact_solve_wheelset(handle, *state[:9], mode, state[9],
                                                      state[10], out_totals)
            for side, code in layout.SIDES.items():
                if stat == 0:
                    stat = self._lib.shcontact_wheelset_wheel(handle, code, 0, values)
                if stat == 0:
                    wheels_flat[side][k, :len(layout.KINEMATIC)] = values[:]
                    for j, key in enumerate(layout.FLAGS):
                        self._check(self._lib.shcontact_get_value(
                            handle, f"{side}%{key}".encode(), 0, ctypes.byref(flag)))
                        wheels_flat[side][k, len(layout.KINEMATIC) + j] = flag.value
            if stat == 0:
                totals_flat[k, :] = out_totals[:]
            else:
                status_flat[k] = stat
                if errors == "raise":
                    case = np.unravel_index(k, shape) if shape else None
                    raise ShcontactError(stat, self._message(), case)

        result = {name: _result_column(totals, i, name) for i, name in enumerate(totals_names)}
        for side in layout.SIDES:
            result[side] = {name: _result_column(wheels[side], i, name)
                            for i, name in enumerate(names)}
        result["status"] = status[()] if status.ndim == 0 else status
        return result
