#!/usr/bin/env python3
"""shcontact from Python through ctypes: a kinematic call as a vehicle code makes it, the headline
case with prescribed creepages, then four bad calls that must come back with a status and a
message.

S1002 wheel on a UIC60 rail canted 1:40 by the track, R0 = 460 mm, G = 82670 MPa, nu = 0.27,
mu = 0.3, FASTSIM_SH. Kinematic call: wheelset at y_ws = 4.733 mm, yaw 4 mrad, 40 m/s, pure
rolling on R0, vertical wheel load 64.7 kN. Headline case: normal force 64.7 kN, creepages
0.58e-3, 0.061e-3, spin 2.74e-4 1/mm.

    python3 headline.py [--lib PATH/libshcontact.so] [--t-y MM]

The library is found from --lib, else $SHCONTACT_LIB, else pkg-config (the libdir of an
installed shcontact.pc: PKG_CONFIG_PATH=PREFIX/lib/pkgconfig), else the system's library path.
"""
import argparse
import ctypes
import ctypes.util
import os
import shutil
import subprocess
import sys

# Result layout of include/shcontact.h (0-based).
FX, FY, MZ, FN, FX_NORM, FY_NORM = 0, 1, 2, 3, 4, 5
GAMMA0, N_PATCHES, SUM_FX, SUM_FY, SUM_FZ = 11, 17, 20, 21, 22
NU_X, NU_Y, PHI, X_TRACK = 25, 26, 27, 28
RESULT_SIZE, KIN_SIZE = 25, 29
LOAD_NORMAL_FORCE, LOAD_VERTICAL_FORCE = 1, 2
RIGHT = 1


class Shcontact:
    """The few C API calls this script needs, with their argument types."""

    def __init__(self, path):
        lib = ctypes.CDLL(path)
        handle = ctypes.c_void_p
        dbl, cint, text = ctypes.c_double, ctypes.c_int, ctypes.c_char_p
        signatures = {
            "shcontact_create": [ctypes.POINTER(handle), text, text, cint],
            "shcontact_destroy": [handle],
            "shcontact_set_material": [handle, dbl, dbl, dbl],
            "shcontact_set_option": [handle, text, text],
            "shcontact_solve": [handle, dbl, dbl, cint, dbl, dbl, dbl, dbl,
                                ctypes.POINTER(dbl)],
            "shcontact_solve_kinematic": [handle] + [dbl] * 9 + [cint, dbl,
                                                                 ctypes.POINTER(dbl)],
            "shcontact_last_error": [handle, ctypes.c_char_p, cint],
        }
        for name, argtypes in signatures.items():
            function = getattr(lib, name)
            function.argtypes = argtypes
            function.restype = cint
        self.lib = lib

    def last_error(self, contact):
        buffer = ctypes.create_string_buffer(512)
        status = self.lib.shcontact_last_error(contact, buffer, len(buffer))
        return status, buffer.value.decode()


def pkg_config_library():
    """libshcontact.so in `pkg-config --variable=libdir shcontact`, or None."""
    if not shutil.which("pkg-config"):
        return None
    try:
        libdir = subprocess.run(["pkg-config", "--variable=libdir", "shcontact"],
                                capture_output=True, text=True, check=True).stdout.strip()
    except subprocess.CalledProcessError:
        return None
    path = os.path.join(libdir, "libshcontact.so")
    return path if libdir and os.path.exists(path) else None


def find_library(explicit):
    path = (explicit or os.environ.get("SHCONTACT_LIB") or pkg_config_library()
            or ctypes.util.find_library("shcontact"))
    if not path:
        sys.exit("headline.py: libshcontact.so not found; give --lib, set SHCONTACT_LIB or "
                 "PKG_CONFIG_PATH=PREFIX/lib/pkgconfig")
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lib", help="path of libshcontact.so")
    # Lateral wheelset shift Y_WS (mm): the app's default (doc/theory.md decision 13).
    parser.add_argument("--t-y", type=float, default=4.733, help="lateral shift (mm)")
    args = parser.parse_args()
    api = Shcontact(find_library(args.lib))
    lib = api.lib

    contact = ctypes.c_void_p()
    values = (ctypes.c_double * RESULT_SIZE)()
    kin = (ctypes.c_double * KIN_SIZE)()
    roll, normal_force = 0.0, 64.7e3
    nu_x, nu_y, phi = 0.58e-3, 0.061e-3, 2.74e-4
    # The wheelset of the kinematic call (mm, rad, mm/s, rad/s, N).
    y_ws, yaw, speed, wheel_load = 4.733, 4.0e-3, 40.0e3, 64.7e3
    pitch_rate = -speed / 460.0

    def solve_kinematic(handle, v_forward):
        # y_ws, yaw, roll, v_forward, v_lateral, v_vertical, roll_rate, yaw_rate, pitch_rate
        return lib.shcontact_solve_kinematic(handle, y_ws, yaw, 0.0, v_forward, 0.0, 0.0, 0.0,
                                             0.0, pitch_rate, LOAD_VERTICAL_FORCE, wheel_load,
                                             kin)

    steps = [
        ("shcontact_create", lambda: lib.shcontact_create(
            ctypes.byref(contact), b"builtin:S1002", b"builtin:UIC60", RIGHT)),
        ("shcontact_set_material", lambda: lib.shcontact_set_material(
            contact, 82670.0, 0.27, 0.3)),
        ("shcontact_set_option", lambda: lib.shcontact_set_option(
            contact, b"tangential%method", b"fastsim-sh")),
        ("shcontact_solve_kinematic", lambda: solve_kinematic(contact, speed)),
        ("shcontact_solve", lambda: lib.shcontact_solve(
            contact, args.t_y, roll, LOAD_NORMAL_FORCE, normal_force, nu_x, nu_y, phi, values)),
    ]
    for name, call in steps:
        if call() != 0:
            status, message = api.last_error(contact)
            lib.shcontact_destroy(contact)
            sys.exit(f"{name} failed (status {status}): {message}")

    print("# kinematic call, Python ctypes interface")
    for key, index in [("kin_sum_fx", SUM_FX), ("kin_sum_fy", SUM_FY), ("kin_sum_fz", SUM_FZ),
                       ("kin_fn", FN), ("kin_nu_x", NU_X), ("kin_nu_y", NU_Y),
                       ("kin_phi", PHI), ("kin_x_track", X_TRACK)]:
        print(f"{key} {kin[index]:.17e}")
    print("# headline case, Python ctypes interface")
    for key, index in [("fx", FX), ("fy", FY), ("mz", MZ), ("fn", FN), ("fx_norm", FX_NORM),
                       ("fy_norm", FY_NORM), ("gamma0", GAMMA0), ("n_patches", N_PATCHES),
                       ("sum_fz", SUM_FZ)]:
        print(f"{key} {values[index]:.17e}")
    print(f"t_y {args.t_y:.17e}")

    # Bad calls: an invalid (NULL) handle, a negative load, a NaN creepage, a wheelset that does
    # not move forward.
    bad_calls = [
        ("status_invalid_handle", None, normal_force, nu_x),
        ("status_negative_load", contact, -normal_force, nu_x),
        ("status_nan_creepage", contact, normal_force, float("nan")),
    ]
    for name, handle, load, creepage in bad_calls:
        status = lib.shcontact_solve(handle, args.t_y, roll, LOAD_NORMAL_FORCE, load, creepage,
                                     nu_y, phi, values)
        _, message = api.last_error(handle)
        print(f"{name} {status} {message}")
    status = solve_kinematic(contact, 0.0)
    print(f"status_kin_zero_speed {status} {api.last_error(contact)[1]}")

    lib.shcontact_destroy(contact)


if __name__ == "__main__":
    main()
