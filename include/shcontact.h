/*
 * shcontact: wheel-rail rolling contact (semi-Hertzian normal contact, FASTSIM_SH).
 * C API over the library's Fortran solver objects (src/shcontact/api/capi.f90, doc/api.md).
 *
 * Units: mm, N, N/mm^2 (MPa), rad; spin creepage in rad/mm. Creepages are those of the wheel
 * relative to the rail at the geometric contact point; forces act on the wheel.
 *
 * Every function returns a status: SHCONTACT_OK (0) or an error code; the handle keeps the
 * status and message of its last call for shcontact_last_error. Distinct handles may be used
 * from distinct threads at once; one handle must not be used by two threads at the same time.
 *
 * Link: pkg-config --cflags --libs shcontact   (libshcontact.so; see doc/api.md)
 */
#ifndef SHCONTACT_H
#define SHCONTACT_H

#ifdef __cplusplus
extern "C" {
#endif

/* Status codes (shcontact_core_error). */
#define SHCONTACT_OK 0
#define SHCONTACT_USAGE 1          /* bad handle or argument */
#define SHCONTACT_INVALID_INPUT 2  /* out-of-range or non-finite data, bad profile */
#define SHCONTACT_IO 3             /* a profile file could not be read */
#define SHCONTACT_NUMERICAL 5      /* a numerical procedure failed */
#define SHCONTACT_NO_CONTACT 6     /* the profiles do not touch, or the load cannot be carried */

/* Wheel side. */
#define SHCONTACT_RIGHT 1
#define SHCONTACT_LEFT (-1)

/* Load modes of shcontact_solve. */
#define SHCONTACT_LOAD_NORMAL_FORCE 1   /* normal force N (N) on the deepest patch */
#define SHCONTACT_LOAD_VERTICAL_FORCE 2 /* vertical wheel load (N) shared by all patches */
#define SHCONTACT_LOAD_APPROACH 3       /* approach (mm) of the deepest patch */
#define SHCONTACT_LOAD_VERTICAL_POSITION 4 /* vertical approach of the wheel (mm), all patches */
#define SHCONTACT_LOAD_SHARED_FORCE 5   /* normal force N (N) of the wheel, shared by its patches */

/* Values of one patch (shcontact_patch; also the first values of a result), 0-based (the
 * Fortran include file shcontact.fi has the same, 1-based). Side frame: for a left wheel the
 * lateral values (F_y, M_z, F_y track, gamma0, nu_y, phi, SUM_FY) are those of its mirror image;
 * multiply by the side (-1) for the track frame. Y_TRACK is the true track coordinate. */
#define SHCONTACT_FX 0             /* F_x (N), rolling direction */
#define SHCONTACT_FY 1             /* F_y (N), lateral, contact plane */
#define SHCONTACT_MZ 2             /* spin moment M_z about the reference point (N mm) */
#define SHCONTACT_FN 3             /* normal force F_n (N) */
#define SHCONTACT_FX_NORM 4        /* F_x / (mu F_n) */
#define SHCONTACT_FY_NORM 5        /* F_y / (mu F_n) */
#define SHCONTACT_FY_TRACK 6       /* lateral force, track frame (N) */
#define SHCONTACT_FZ_TRACK 7       /* vertical force, track frame, z down (N) */
#define SHCONTACT_APPROACH 8       /* approach delta (mm) */
#define SHCONTACT_AREA 9           /* contact area (mm^2) */
#define SHCONTACT_P_MAX 10         /* largest strip peak pressure (MPa) */
#define SHCONTACT_GAMMA0 11        /* contact angle at the reference point (rad, CONTACT's sign) */
#define SHCONTACT_R0 12            /* wheel rolling radius at the reference point (mm) */
#define SHCONTACT_Y_TRACK 13       /* reference point, lateral track coordinate (mm) */
#define SHCONTACT_Z_TRACK 14       /* reference point, vertical track coordinate (mm, down) */
#define SHCONTACT_COULOMB 15       /* max |p| / (mu p_n) */
#define SHCONTACT_ADHESION 16      /* adhesion area fraction */
#define SHCONTACT_PATCH_SIZE 17

/* Values of a result (shcontact_solve): the main (most loaded) patch, then: */
#define SHCONTACT_N_PATCHES 17     /* patches found */
#define SHCONTACT_N_LOADED 18      /* patches solved (1, or all for a vertical load) */
#define SHCONTACT_MAIN_PATCH 19    /* index (1-based) of the main patch */
#define SHCONTACT_SUM_FX 20        /* totals over the loaded patches, track frame (N) */
#define SHCONTACT_SUM_FY 21
#define SHCONTACT_SUM_FZ 22
#define SHCONTACT_SUM_FN 23
#define SHCONTACT_DZ 24            /* rigid vertical approach of the wheel (mm), vertical load */
#define SHCONTACT_RESULT_SIZE 25

/* Values of a kinematic result (shcontact_solve_kinematic, shcontact_patch_kinematic): the
 * result layout, then the patch's creepages and the longitudinal position of its contact point.
 * shcontact_patch_kinematic puts the patch's values at 0-16 and 25-28, the result's at 17-24. */
#define SHCONTACT_NU_X 25          /* longitudinal creepage, wheel relative to rail */
#define SHCONTACT_NU_Y 26          /* lateral creepage */
#define SHCONTACT_PHI 27           /* spin creepage (rad/mm) */
#define SHCONTACT_X_TRACK 28       /* contact point, longitudinal track coordinate (mm, forward) */
#define SHCONTACT_KIN_SIZE 29

/* Profiles of shcontact_get_profile. */
#define SHCONTACT_PROFILE_RAIL 0
#define SHCONTACT_PROFILE_WHEEL 1

/* Element states of shcontact_fields. */
#define SHCONTACT_STATE_EXTERIOR 0 /* outside the contact */
#define SHCONTACT_STATE_ADHESION 1 /* adhesion (stick) */
#define SHCONTACT_STATE_SLIP 2     /* slip */

/* Options (shcontact_set_option): key "group%variable" as in the app's case files, its default
 * and units, and its choices or range. The lines between the markers are GENERATED from the
 * registry (src/shcontact/core/ranges.f90, the option registries): `fpm run --example
 * shcontact-headers` writes them; test registry/header_option_lists checks them.
 * -- options --
 * profiles%wheel_smoothing = 0.0: 0.0 <= wheel_smoothing <= 100.0 mm
 * profiles%rail_smoothing = 0.0: 0.0 <= rail_smoothing <= 100.0 mm
 * track%gauge = 1435.0: 500.0 <= gauge <= 2000.0 mm
 * track%gauge_height = 14.0: 0.0 <= gauge_height <= 50.0 mm
 * track%inclination = 0.025 [-]: -0.2 <= inclination <= 0.2
 * track%flange_back_distance = 1360.0: 400.0 <= flange_back_distance <= 2000.0 mm
 * track%flange_back_position = -70.0: -200.0 <= flange_back_position <= 200.0 mm
 * track%nominal_radius = 460.0: 100.0 <= nominal_radius <= 2000.0 mm
 * position%t_y = 4.733: -30.0 <= t_y <= 30.0 mm
 * position%roll = 0.0: -0.1 <= roll <= 0.1 rad
 * kinematics%mode = 'off': 'off', 'on'
 * kinematics%yaw = 0.0: -0.1 <= yaw <= 0.1 rad
 * kinematics%v_forward = 30000.0: 0.0 < v_forward <= 200000.0 mm/s
 * kinematics%v_lateral = 0.0: -10000.0 <= v_lateral <= 10000.0 mm/s
 * kinematics%v_vertical = 0.0: -10000.0 <= v_vertical <= 10000.0 mm/s
 * kinematics%roll_rate = 0.0: -10.0 <= roll_rate <= 10.0 rad/s
 * kinematics%yaw_rate = 0.0: -10.0 <= yaw_rate <= 10.0 rad/s
 * kinematics%pitch_rate = pure rolling: -2000.0 <= pitch_rate < 0.0 rad/s
 * material%shear_modulus = 82670.0: 1000.0 <= shear_modulus <= 1000000.0 MPa
 * material%poisson = 0.27 [-]: 0.0 <= poisson < 0.5
 * material%friction = 0.3 [-]: 0.001 <= friction <= 10.0
 * load%mode = 'force': 'force', 'approach', 'vertical', 'shared-force'
 * load%normal_force = 64700.0: 1.0 <= normal_force <= 1.0e7 N
 * load%approach = 0.05: 0.0 < approach <= 5.0 mm
 * load%vertical_force = 64700.0: 1.0 <= vertical_force <= 1.0e7 N
 * creepage%nu_x = 0.00058 [-]: -1.0 <= nu_x <= 1.0
 * creepage%nu_y = 6.1e-5 [-]: -1.0 <= nu_y <= 1.0
 * creepage%phi = 0.000274: -0.1 <= phi <= 0.1 rad/mm
 * normal%method = 'semi-hertz': 'semi-hertz', 'hertz'
 * normal%reduction = 'coupled': 'coupled', 'local-hertz', 'constant'
 * normal%slide = 'linear': 'linear', 'exact'
 * normal%epsilon = 0.55 [-]: 0.01 <= epsilon <= 1.0
 * normal%n_strips = 100: 2 <= n_strips <= 100000
 * normal%b_min = 0.0001: 1.0e-8 <= b_min <= 1.0 1/mm
 * normal%longitudinal_curvature = 'local': 'local', 'reference'
 * normal%strip_tables = 'planar': 'planar', 'conformal'
 * normal%preset = 'default': 'default', 'vehicle'
 * tangential%method = 'fastsim-sh': 'fastsim-sh', 'fastsim'
 * tangential%bound = 'weighted': 'ellipsoidal', 'parabolic', 'weighted', 'weighted-slip',
 *     'clipped'
 * tangential%spin_model = 'uniform': 'additive', 'uniform', 'scaled', 'geometric'
 * tangential%spin_flexibility = 'longitudinal': 'longitudinal', 'spin'
 * tangential%correction = 'exact-ellipse': 'exact-ellipse', 'none'
 * tangential%contact_surface = 'wheel': 'wheel', 'interface'
 * tangential%n_elements = 50: 2 <= n_elements <= 100000
 * -- end options --
 */

/* An opaque contact (one wheel on its rail). */
typedef struct shcontact_contact shcontact_contact;

/* Create a contact from profile names ("builtin:S1002", "builtin:UIC60", "builtin:UIC60-canted"
 * or file names) with the default track (Manchester benchmark, rail canted 1:40 by the track,
 * R0 = 460 mm), material (G = 82670 MPa, nu = 0.27, mu = 0.3) and options. *handle receives a
 * handle also when the creation fails (its last error tells why); destroy it in any case. */
int shcontact_create(shcontact_contact **handle, const char *wheel, const char *rail, int side);

/* Create a contact from profiles given as arrays of points, in mm, in the right-side canonical
 * form: y towards the field side, z down; the n_wheel wheel points run from the field side to
 * the flange back (y decreasing overall; origin on the tape circle, flange back at y = -70 mm
 * as S1002's unless shcontact_set_track says otherwise), the n_rail rail points from the track
 * centre to the field side (y increasing overall). The points are checked and cleaned as a
 * profile file is (at least 4 points, finite, no duplicate consecutive points, that order, an
 * arc length of 5 to 500 mm, no loops, a running surface); a bad array gives
 * SHCONTACT_INVALID_INPUT and a message naming "wheel array" or "rail array" and the point
 * (counted from 1). The arrays are copied: free them when the call returns. Defaults and the
 * handle as shcontact_create. */
int shcontact_create_arrays(shcontact_contact **handle, int n_wheel, const double *wheel_y,
                            const double *wheel_z, int n_rail, const double *rail_y,
                            const double *rail_z, int side);

/* The points of the contact's wheel (kind SHCONTACT_PROFILE_WHEEL) or rail
 * (SHCONTACT_PROFILE_RAIL) profile as created: a file's read and cleaned, a built-in one as it is
 * (mm, the canonical form of shcontact_create_arrays: a MiniProf wheel, whose origin is at its
 * flange back, comes moved by -70 mm to the arrays' origin on the tape circle, flange back at
 * -70 mm as the default track has it). *n receives the number of points and y, z
 * (`capacity` values each) the points; when *n exceeds capacity nothing is copied and the status
 * is SHCONTACT_USAGE (call with capacity 0 and NULL arrays to ask for *n). Passing the points to
 * shcontact_create_arrays gives a contact with the same results (bit for bit; to round-off for a
 * moved MiniProf wheel). */
int shcontact_get_profile(shcontact_contact *handle, int kind, int capacity, int *n, double *y,
                          double *z);

/* Release a contact (NULL is ignored). */
int shcontact_destroy(shcontact_contact *handle);

/* Shear modulus G (MPa), Poisson's ratio, friction coefficient. */
int shcontact_set_material(shcontact_contact *handle, double shear_modulus, double poisson,
                           double friction);

/* Track: gauge, gauge-point depth (mm), rail inclination (slope, 1:40 = 0.025), rail_canted != 0
 * when the rail profile is already canted, flange-back distance, flange-back position in wheel
 * profile coordinates, nominal rolling radius (mm). Prepares the profiles again. */
int shcontact_set_track(shcontact_contact *handle, double gauge, double gauge_height,
                        double inclination, int rail_canted, double flange_back_distance,
                        double flange_back_position, double nominal_radius);

/* One option as in the app's case files: key "group%variable", value as text, as the app's
 * --set takes it (doc/api.md, "Options"). Keys: every variable of the case files but the sweep's
 * (doc/app.md); they set the track, material, smoothing, normal and tangential options, or the
 * state of shcontact_solve_state (&position, &kinematics, &load, &creepage). Profile files and
 * track%side are given at creation, the output file and the sweep are the app's (status 2).
 * The choices of each option: the "Options" block above; output%fields (all or 1: every later
 * solve keeps the element fields for shcontact_fields; none or 0, the default: no fields). */
int shcontact_set_option(shcontact_contact *handle, const char *key, const char *value);

/* Solve one contact: lateral wheelset shift t_y (mm, CONTACT's Y_WS), roll (rad), load mode and
 * value, creepages nu_x, nu_y and spin phi (rad/mm). values[SHCONTACT_RESULT_SIZE] receives the
 * result (zeros on failure). No allocation once the position repeats; nothing printed. */
int shcontact_solve(shcontact_contact *handle, double t_y, double roll, int load_mode,
                    double load, double nu_x, double nu_y, double phi, double *values);

/* values[SHCONTACT_PATCH_SIZE] of patch `patch` (1-based) of the last solve. */
int shcontact_patch(shcontact_contact *handle, int patch, double *values);

/* Solve one wheel from the wheelset's position and velocities (CONTACT module 1 meaning; track
 * frame x forward, y to the right, z down): lateral shift y_ws (mm), yaw and roll (rad), the
 * velocity of the wheelset centre v_forward (> 0), v_lateral, v_vertical (mm/s), roll_rate,
 * yaw_rate and pitch_rate (rad/s; pitch_rate < 0 rolling forward, pure rolling -v_forward/R0).
 * Every patch gets the creepages of the rigid-body motion at its own contact point. load_mode
 * SHCONTACT_LOAD_VERTICAL_FORCE is what a vehicle code wants. values[SHCONTACT_KIN_SIZE]
 * receives the result (zeros on failure). */
int shcontact_solve_kinematic(shcontact_contact *handle, double y_ws, double yaw, double roll,
                              double v_forward, double v_lateral, double v_vertical,
                              double roll_rate, double yaw_rate, double pitch_rate, int load_mode,
                              double load, double *values);

/* values[SHCONTACT_KIN_SIZE] of patch `patch` (1-based) of the last solve, kinematic layout. */
int shcontact_patch_kinematic(shcontact_contact *handle, int patch, double *values);

/* Element fields of the last solve (needs output%fields = all before it). *nx elements per
 * strip (rolling direction) and *ny strips of patch `patch` (1-based); 0 x 0 for a patch that
 * carries no load. */
int shcontact_field_size(shcontact_contact *handle, int patch, int *nx, int *ny);

/* The element fields of patch `patch`: each array holds nx*ny values (nx, ny from
 * shcontact_field_size) in Fortran order, element j (from the leading edge, 0-based) of strip i
 * at [j + nx*i]: declare them as double x[ny][nx] and read x[i][j]. In the patch's contact frame:
 * x along the rolling direction from the strip's middle, y the strip centre across the patch
 * from its reference point (mm); area the element area (mm^2; sum px*area = F_x,
 * sum py*area = F_y); pn normal pressure, px, py tractions on the wheel (MPa); slip the slip
 * magnitude (0 in adhesion); state 0 exterior, 1 adhesion, 2 slip. No array may be NULL.
 * Sizes other than the fields' give status 1 and write nothing. */
int shcontact_fields(shcontact_contact *handle, int patch, int nx, int ny, double *x, double *y,
                     double *area, double *pn, double *px, double *py, double *slip, int *state);

/* Keyed calls (doc/api.md, "Keyed calls"): inputs and outputs by name, so that a new one is a
 * new key, never a changed signature.
 *
 * A number by key: "group%variable" as in shcontact_set_option, or a variable name that only one
 * group has ("t_y", "yaw", "vertical_force", "friction", ...), in the key's units (mm, rad, mm/s,
 * rad/s, N, MPa, rad/mm; doc/api.md). Integer variables take whole numbers; text variables
 * (choices) shcontact_set_option. Goes through the same setter as shcontact_set_option. */
int shcontact_set_value(shcontact_contact *handle, const char *key, double value);

/* Solve the state set by key: position and velocities (&position, &kinematics; mode "on" gives
 * the kinematic call), the load (&load mode and value) and, in prescribed mode, the creepages
 * (&creepage); the settings are checked as the app checks a case file. Defaults: the app's
 * headline case. On a wheelset handle both wheels get the same load. */
int shcontact_solve_state(shcontact_contact *handle);

/* A numeric input by its key "group%variable", as the handle holds it now (a default, or what
 * the handle resolved: "track%flange_back_position" is 0 for a MiniProf wheel), at any time; or
 * a result value of the last solve by name: "fx", "fy", "mz", "fn", "fx_norm", "fy_norm",
 * "fy_track", "fz_track", "approach", "area", "p_max", "gamma0", "r0", "y_track", "z_track",
 * "coulomb", "adhesion", "n_patches", "n_loaded", "main_patch", "sum_fx", "sum_fy", "sum_fz",
 * "sum_fn", "dz", "nu_x", "nu_y", "phi", "x_track" (the kinematic layout's values, units as
 * there), of the main patch (patch 0, with the result's counts and totals) or of patch `patch`.
 * A wheelset handle: "wheelset%fx", "wheelset%fy", "wheelset%fz" (N), "wheelset%mz" (N mm), and
 * "right%NAME", "left%NAME" for a wheel (its side frame). *value receives it (0 on failure). */
int shcontact_get_value(shcontact_contact *handle, const char *key, int patch, double *value);

/* One element field of patch `patch` of the last solve by name: "x", "y" (mm), "area" (mm^2),
 * "pn", "px", "py" (MPa), "slip", "state" (0, 1, 2 as doubles); nx*ny values (the sizes of
 * shcontact_field_size) in the order of shcontact_fields. */
int shcontact_get_field(shcontact_contact *handle, const char *key, int patch, int nx, int ny,
                        double *field);

/* Both wheels of a wheelset (the library's wheelset_solver_type): a wheelset handle from profile
 * names, the left wheel the mirror image of the right one; default track, material and options,
 * which shcontact_set_option, shcontact_set_material and shcontact_set_track change for both
 * wheels. *handle as for shcontact_create; the one-wheel solve, patch and field calls refuse it
 * (SHCONTACT_USAGE). */
int shcontact_create_wheelset(shcontact_contact **handle, const char *wheel, const char *rail);

/* Solve both wheels for one wheelset state (the arguments of shcontact_solve_kinematic) and the
 * load of each wheel (load_mode as there; SHCONTACT_LOAD_VERTICAL_FORCE for a vehicle code).
 * totals[4] receives the forces on the wheelset in the true track frame, F_x, F_y (towards the
 * right rail's field side), F_z (z down) (N), and their moment M_z about the vertical axis
 * through the wheelset centre (N mm; the patches' spin moments not included); zeros on failure.
 * With SHCONTACT_LOAD_VERTICAL_FORCE a load below 1 N (0 or less too) lifts that wheel: no contact, its
 * values all zero (n_patches 0), the other wheel solved as usual.
 */
int shcontact_solve_wheelset(shcontact_contact *handle, double y_ws, double yaw, double roll,
                             double v_forward, double v_lateral, double v_vertical,
                             double roll_rate, double yaw_rate, double pitch_rate, int load_mode,
                             double load_right, double load_left, double *totals);

/* values[SHCONTACT_KIN_SIZE] of wheel `side` (SHCONTACT_RIGHT, SHCONTACT_LEFT) of the last
 * wheelset solve: its main patch (patch 0) or patch `patch`, with the wheel's counts and totals,
 * in its side frame (as shcontact_patch_kinematic). */
int shcontact_wheelset_wheel(shcontact_contact *handle, int side, int patch, double *values);

/* Status of the last call on handle; its message is copied to buffer (NUL-terminated, cut to
 * length - 1 characters, empty after a success). A NULL handle gives SHCONTACT_USAGE. */
int shcontact_last_error(const shcontact_contact *handle, char *buffer, int length);

/* The library version ("0.1.0") copied to buffer; returns its length. */
int shcontact_version(char *buffer, int length);

#ifdef __cplusplus
}
#endif

#endif /* SHCONTACT_H */
