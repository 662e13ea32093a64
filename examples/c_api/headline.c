/*
 * shcontact from C through the C API (include/shcontact.h): the profiles passed as arrays (here
 * the built-in ones, fetched from a contact created by name), a kinematic call as a vehicle code
 * makes it, the headline case with prescribed creepages and its element fields, both wheels of a
 * wheelset in one call, then five bad calls that must come back with a status and a message.
 *
 * S1002 wheel on a UIC60 rail canted 1:40 by the track, R0 = 460 mm, G = 82670 MPa, nu = 0.27,
 * mu = 0.3, FASTSIM_SH. Kinematic call: wheelset at y_ws = 4.733 mm, yaw 4 mrad, 40 m/s, pure
 * rolling on R0, vertical wheel load 64.7 kN. Headline case: normal force 64.7 kN, creepages
 * 0.58e-3, 0.061e-3, spin 2.74e-4 1/mm.
 *
 * Build:  cc headline.c $(pkg-config --cflags --libs shcontact) -o headline
 * Run:    ./headline [t_y]      (lateral wheelset shift in mm, default 4.733)
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "shcontact.h"

static int fail(shcontact_contact *contact, const char *what)
{
    char message[512];
    int status = shcontact_last_error(contact, message, (int)sizeof message);
    fprintf(stderr, "%s failed (status %d): %s\n", what, status, message);
    shcontact_destroy(contact);
    return 1;
}

/* A contact whose profiles are given as arrays: a vehicle code has its own; here they are the
 * built-in S1002 and UIC60, taken from a contact created from their names. */
static int create_from_arrays(shcontact_contact **contact, int side)
{
    shcontact_contact *by_name = NULL;
    double *wheel = NULL, *rail = NULL;
    int n_wheel = 0, n_rail = 0, status;

    status = shcontact_create(&by_name, "builtin:S1002", "builtin:UIC60", side);
    /* The counts first (no room), then the points: wheel y, z and rail y, z. */
    if (status == SHCONTACT_OK) {
        shcontact_get_profile(by_name, SHCONTACT_PROFILE_WHEEL, 0, &n_wheel, NULL, NULL);
        shcontact_get_profile(by_name, SHCONTACT_PROFILE_RAIL, 0, &n_rail, NULL, NULL);
        wheel = malloc(2 * (size_t)n_wheel * sizeof *wheel);
        rail = malloc(2 * (size_t)n_rail * sizeof *rail);
        if (!wheel || !rail)
            status = SHCONTACT_USAGE;
    }
    if (status == SHCONTACT_OK)
        status = shcontact_get_profile(by_name, SHCONTACT_PROFILE_WHEEL, n_wheel, &n_wheel, wheel,
                                       wheel + n_wheel);
    if (status == SHCONTACT_OK)
        status = shcontact_get_profile(by_name, SHCONTACT_PROFILE_RAIL, n_rail, &n_rail, rail,
                                       rail + n_rail);
    if (status != SHCONTACT_OK) {
        *contact = by_name; /* for the caller's message */
    } else {
        shcontact_destroy(by_name);
        /* mm; wheel from the field side to the flange back, rail from the track centre to the
         * field side; y towards the field side, z down. The arrays are copied. */
        status = shcontact_create_arrays(contact, n_wheel, wheel, wheel + n_wheel, n_rail, rail,
                                         rail + n_rail, side);
    }
    free(wheel);
    free(rail);
    return status;
}

/* The element fields of a patch: the tractions times the element areas add up to its forces. */
static int print_fields(shcontact_contact *contact, int patch)
{
    int nx, ny, i, n_slip = 0, status;
    double *x, *y, *area, *pn, *px, *py, *slip, sum_fx = 0.0, sum_fy = 0.0;
    int *state;

    status = shcontact_field_size(contact, patch, &nx, &ny);
    if (status != SHCONTACT_OK)
        return status;
    /* One block for the seven double arrays of nx*ny elements, element j of strip i at
     * [j + nx*i] (as double x[ny][nx]). */
    x = malloc(7 * (size_t)nx * (size_t)ny * sizeof *x);
    state = malloc((size_t)nx * (size_t)ny * sizeof *state);
    if (!x || !state) {
        free(x);
        free(state);
        return SHCONTACT_USAGE;
    }
    y = x + nx * ny;
    area = y + nx * ny;
    pn = area + nx * ny;
    px = pn + nx * ny;
    py = px + nx * ny;
    slip = py + nx * ny;
    status = shcontact_fields(contact, patch, nx, ny, x, y, area, pn, px, py, slip, state);
    if (status == SHCONTACT_OK) {
        for (i = 0; i < nx * ny; i++) {
            sum_fx += px[i] * area[i];
            sum_fy += py[i] * area[i];
            n_slip += state[i] == SHCONTACT_STATE_SLIP;
        }
        printf("field_nx %d\nfield_ny %d\nfield_slip_elements %d\n", nx, ny, n_slip);
        printf("field_sum_fx %.17e\nfield_sum_fy %.17e\n", sum_fx, sum_fy);
    }
    free(x);
    free(state);
    return status;
}

/* Both wheels in one call (a wheelset handle): the wheelset 5 mm to the right, yaw 2 mrad,
 * lateral velocity 10 mm/s, yaw rate 0.01 rad/s at 30 m/s; 64.7 kN on the right wheel, 60 kN on
 * the left. totals: F_x, F_y, F_z (N) on the wheelset, true track frame, and M_z (N mm). */
static int print_wheelset(void)
{
    shcontact_contact *wheelset = NULL;
    double totals[4], right[SHCONTACT_KIN_SIZE], left_sum_fy = 0.0;
    const double speed = 30.0e3;
    int status = shcontact_create_wheelset(&wheelset, "builtin:S1002", "builtin:UIC60");

    if (status == SHCONTACT_OK)
        status = shcontact_solve_wheelset(wheelset, 5.0, 2.0e-3, 0.0, speed, 10.0, 0.0, 0.0, 0.01,
                                          -speed / 460.0, SHCONTACT_LOAD_VERTICAL_FORCE, 64.7e3,
                                          60.0e3, totals);
    /* A wheel's values by name (keyed: "right%...", "left%...") or as the kinematic layout. */
    if (status == SHCONTACT_OK)
        status = shcontact_get_value(wheelset, "left%sum_fy", 0, &left_sum_fy);
    if (status == SHCONTACT_OK)
        status = shcontact_wheelset_wheel(wheelset, SHCONTACT_RIGHT, 0, right);
    if (status != SHCONTACT_OK)
        return fail(wheelset, "shcontact_solve_wheelset");
    printf("# wheelset call, C interface\n");
    printf("ws_fx %.17e\nws_fy %.17e\nws_fz %.17e\nws_mz %.17e\n", totals[0], totals[1],
           totals[2], totals[3]);
    printf("ws_right_n_loaded %.17e\n", right[SHCONTACT_N_LOADED]);
    printf("ws_left_sum_fy %.17e\n", left_sum_fy);
    shcontact_destroy(wheelset);
    return 0;
}

static void report_bad_call(const char *name, shcontact_contact *contact, int status)
{
    char message[512];
    shcontact_last_error(contact, message, (int)sizeof message);
    printf("%s %d %s\n", name, status, message);
}

int main(int argc, char **argv)
{
    /* Lateral wheelset shift Y_WS (mm): the app's default (doc/theory.md decision 13). */
    const double t_y = argc > 1 ? atof(argv[1]) : 4.733;
    const double roll = 0.0, normal_force = 64.7e3;
    const double nu_x = 0.58e-3, nu_y = 0.061e-3, phi = 2.74e-4;
    /* The wheelset of the kinematic call (mm, rad, mm/s, rad/s, N). */
    const double y_ws = 4.733, yaw = 4.0e-3, speed = 40.0e3, pitch_rate = -speed / 460.0;
    const double wheel_load = 64.7e3;
    double v[SHCONTACT_RESULT_SIZE], k[SHCONTACT_KIN_SIZE];
    shcontact_contact *contact = NULL;
    int status;

    if (create_from_arrays(&contact, SHCONTACT_RIGHT) != 0)
        return fail(contact, "shcontact_create_arrays");
    if (shcontact_set_material(contact, 82670.0, 0.27, 0.3) != 0)
        return fail(contact, "shcontact_set_material");
    if (shcontact_set_option(contact, "tangential%method", "fastsim-sh") != 0)
        return fail(contact, "shcontact_set_option");
    /* Keep the element fields of every solve (off by default: no cost). */
    if (shcontact_set_option(contact, "output%fields", "all") != 0)
        return fail(contact, "shcontact_set_option");

    /* The kinematic call: position, velocities, vertical wheel load. */
    if (shcontact_solve_kinematic(contact, y_ws, yaw, 0.0, speed, 0.0, 0.0, 0.0, 0.0, pitch_rate,
                                  SHCONTACT_LOAD_VERTICAL_FORCE, wheel_load, k) != 0)
        return fail(contact, "shcontact_solve_kinematic");
    printf("# kinematic call, C interface\n");
    printf("kin_sum_fx %.17e\n", k[SHCONTACT_SUM_FX]);
    printf("kin_sum_fy %.17e\n", k[SHCONTACT_SUM_FY]);
    printf("kin_sum_fz %.17e\n", k[SHCONTACT_SUM_FZ]);
    printf("kin_fn %.17e\n", k[SHCONTACT_FN]);
    printf("kin_nu_x %.17e\n", k[SHCONTACT_NU_X]);
    printf("kin_nu_y %.17e\n", k[SHCONTACT_NU_Y]);
    printf("kin_phi %.17e\n", k[SHCONTACT_PHI]);
    printf("kin_x_track %.17e\n", k[SHCONTACT_X_TRACK]);

    /* The headline case: position, normal force, creepages. */
    if (shcontact_solve(contact, t_y, roll, SHCONTACT_LOAD_NORMAL_FORCE, normal_force, nu_x, nu_y,
                        phi, v) != 0)
        return fail(contact, "shcontact_solve");

    printf("# headline case, C interface\n");
    printf("t_y %.17e\n", t_y);
    printf("fx %.17e\n", v[SHCONTACT_FX]);
    printf("fy %.17e\n", v[SHCONTACT_FY]);
    printf("mz %.17e\n", v[SHCONTACT_MZ]);
    printf("fn %.17e\n", v[SHCONTACT_FN]);
    printf("fx_norm %.17e\n", v[SHCONTACT_FX_NORM]);
    printf("fy_norm %.17e\n", v[SHCONTACT_FY_NORM]);
    printf("gamma0 %.17e\n", v[SHCONTACT_GAMMA0]);
    printf("n_patches %.17e\n", v[SHCONTACT_N_PATCHES]);
    printf("sum_fz %.17e\n", v[SHCONTACT_SUM_FZ]);
    if (print_fields(contact, (int)v[SHCONTACT_MAIN_PATCH]) != 0)
        return fail(contact, "shcontact_fields");

    if (print_wheelset() != 0) {
        shcontact_destroy(contact);
        return 1;
    }

    /* Bad calls: an invalid (NULL) handle, a negative load, a NaN creepage, a wheelset that does
     * not move forward, a wheel of one point. */
    status = shcontact_solve(NULL, t_y, roll, SHCONTACT_LOAD_NORMAL_FORCE, normal_force, nu_x,
                             nu_y, phi, v);
    report_bad_call("status_invalid_handle", NULL, status);
    status = shcontact_solve(contact, t_y, roll, SHCONTACT_LOAD_NORMAL_FORCE, -normal_force, nu_x,
                             nu_y, phi, v);
    report_bad_call("status_negative_load", contact, status);
    status = shcontact_solve(contact, t_y, roll, SHCONTACT_LOAD_NORMAL_FORCE, normal_force, NAN,
                             nu_y, phi, v);
    report_bad_call("status_nan_creepage", contact, status);
    status = shcontact_solve_kinematic(contact, y_ws, yaw, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, pitch_rate,
                                       SHCONTACT_LOAD_VERTICAL_FORCE, wheel_load, k);
    report_bad_call("status_kin_zero_speed", contact, status);
    {
        shcontact_contact *bad = NULL;
        const double one_y[1] = {0.0}, one_z[1] = {0.0}, rail_y[2] = {-30.0, 30.0},
                     rail_z[2] = {0.0, 0.0};
        status = shcontact_create_arrays(&bad, 1, one_y, one_z, 2, rail_y, rail_z,
                                         SHCONTACT_RIGHT);
        report_bad_call("status_bad_array", bad, status);
        shcontact_destroy(bad);
    }

    shcontact_destroy(contact);
    return 0;
}
