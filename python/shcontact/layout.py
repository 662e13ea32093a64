"""The value layouts of the C API (include/shcontact.h), as names in index order.

The result of a call is a dict whose keys are these names: the C header's ``SHCONTACT_<NAME>``
in lower case (``fx`` is ``values[SHCONTACT_FX]``). python/tests/test_layout.py checks every
index against the header.
"""

#: One patch (shcontact_patch), also the first values of a result.
PATCH = (
    "fx",          # F_x (N), rolling direction, on the wheel
    "fy",          # F_y (N), lateral in the contact plane (field side +)
    "mz",          # spin moment M_z about the reference point (N mm)
    "fn",          # normal force F_n (N)
    "fx_norm",     # F_x / (mu F_n)
    "fy_norm",     # F_y / (mu F_n)
    "fy_track",    # lateral force, track frame (N)
    "fz_track",    # vertical force, track frame, z down (N)
    "approach",    # approach delta (mm)
    "area",        # contact area (mm^2)
    "p_max",       # largest strip peak pressure (MPa)
    "gamma0",      # contact angle at the reference point (rad, CONTACT's sign)
    "r0",          # wheel rolling radius at the reference point (mm)
    "y_track",     # reference point, lateral track coordinate (mm)
    "z_track",     # reference point, vertical track coordinate (mm, down)
    "coulomb",     # max |p| / (mu p_n)
    "adhesion",    # adhesion area fraction
)

#: A result (shcontact_solve): the main (most loaded) patch, then these.
RESULT = PATCH + (
    "n_patches",   # patches found
    "n_loaded",    # patches solved
    "main_patch",  # index (1-based) of the main patch
    "sum_fx",      # totals over the loaded patches, track frame (N)
    "sum_fy",
    "sum_fz",
    "sum_fn",
    "dz",          # rigid vertical approach of the wheel (mm), vertical load
)

#: A kinematic result (shcontact_solve_kinematic): the result, then the main patch's creepages
#: and the longitudinal position of its contact point.
KINEMATIC = RESULT + (
    "nu_x",        # longitudinal creepage, wheel relative to rail
    "nu_y",        # lateral creepage
    "phi",         # spin creepage (rad/mm)
    "x_track",     # contact point, longitudinal track coordinate (mm, forward)
)

#: The wheel's joined contact (doc/lobes.md: its patches within 4 mm joined as the exact theory
#: joins them), read by key (shcontact_get_value) after every solve and returned with the
#: result: the numbers to set against CONTACT's one patch.
WHEEL = ("wheel_patches", "wheel_fn", "wheel_fx", "wheel_fy", "wheel_fx_norm",
         "wheel_fy_norm", "wheel_area", "wheel_p_max")

#: The wheel's flags, read by key after every solve and returned with the result (1 or 0):
#: ``climbing``, the main patch's contact on the flange beyond its steepest part (doc/api.md).
FLAGS = ("climbing",)

#: Values that are counts, indices or flags (returned as integer arrays).
INTEGER = ("n_patches", "n_loaded", "main_patch", "wheel_patches", "climbing")

#: Units of every value.
UNITS = {
    "fx": "N", "fy": "N", "mz": "N mm", "fn": "N", "fx_norm": "1", "fy_norm": "1",
    "fy_track": "N", "fz_track": "N", "approach": "mm", "area": "mm^2", "p_max": "MPa",
    "gamma0": "rad", "r0": "mm", "y_track": "mm", "z_track": "mm", "coulomb": "1",
    "adhesion": "1", "n_patches": "1", "n_loaded": "1", "main_patch": "1", "sum_fx": "N",
    "sum_fy": "N", "sum_fz": "N", "sum_fn": "N", "dz": "mm", "nu_x": "1", "nu_y": "1",
    "phi": "rad/mm", "x_track": "mm", "wheel_patches": "1", "wheel_fn": "N", "wheel_fx": "N",
    "wheel_fy": "N", "wheel_fx_norm": "1", "wheel_fy_norm": "1", "wheel_area": "mm^2",
    "wheel_p_max": "MPa", "climbing": "1",
}

#: Load modes (SHCONTACT_LOAD_*), by the keyword that gives the load to a solve.
LOAD_MODES = {"normal_force": 1, "vertical_force": 2, "approach": 3, "vertical_position": 4,
              "shared_force": 5}

#: Status codes (SHCONTACT_OK, ...).
STATUS = {"ok": 0, "usage": 1, "invalid_input": 2, "io": 3, "numerical": 5, "no_contact": 6}

#: Element states of the fields (SHCONTACT_STATE_*).
STATE_EXTERIOR, STATE_ADHESION, STATE_SLIP = 0, 1, 2

#: Wheel sides (SHCONTACT_RIGHT, SHCONTACT_LEFT) and profile kinds (SHCONTACT_PROFILE_*).
SIDES = {"right": 1, "left": -1}
PROFILE_KINDS = {"rail": 0, "wheel": 1}
