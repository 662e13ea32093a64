"""The numpy interface to the solver against the shcontact program (same library, same case):
the headline case with prescribed creepages, the kinematic case and the kinematic sweep (arrays
of cases), element fields against the result file's, and the errors."""
import os

import numpy as np
import pytest

import shcontact
from shcontact import layout
from conftest import KINEMATIC_SUMMARY, SUMMARY_OF_LAYOUT

# The app's default case (README, doc/app.md): S1002 on UIC60 1:40, t_y = 4.733 mm.
HEADLINE = dict(normal_force=64.7e3, nu_x=0.58e-3, nu_y=0.061e-3, phi=2.74e-4)
T_Y = 4.733
# examples/kinematic.nml.
KINEMATIC = dict(yaw=0.004, v_forward=30000.0, vertical_force=64700.0)

# The program and this package call the same library; a release build of one and a debug build
# of the other may differ in the last bits (doc/api.md §5), hence not bit for bit.
RTOL, ATOL = 1e-9, 1e-9


def assert_agrees(result, row, names, index=None):
    for key, column in names.items():
        value = result[key] if index is None else result[key][index]
        expected = float(row[column])
        assert value == pytest.approx(expected, rel=RTOL, abs=ATOL), (key, column)


@pytest.fixture(scope="module")
def contact():
    with shcontact.Contact("builtin:S1002", "builtin:UIC60", fields=True) as c:
        yield c


def test_headline_equals_program(contact, run_app):
    _, rows = run_app("headline")
    assert len(rows) == 1 and rows[0]["status"] == "0"
    assert float(rows[0]["t_y"]) == T_Y
    r = contact.solve(T_Y, **HEADLINE)
    assert r["status"] == 0
    assert_agrees(r, rows[0], SUMMARY_OF_LAYOUT)
    # The forces are those the README quotes for the headline case (a change shows here too).
    assert r["fx"] == pytest.approx(-5841.0, abs=0.1)


def test_kinematic_equals_program(contact, run_app):
    _, rows = run_app("kinematic", "examples/kinematic.nml")
    r = contact.solve_kinematic(4.733, **KINEMATIC)
    assert_agrees(r, rows[0], {**SUMMARY_OF_LAYOUT, **KINEMATIC_SUMMARY})
    assert r["n_loaded"] == 2  # tread and flange root


def test_wheel_values_in_results(contact, run_app):
    """The wheel's joined contact (wheel_fn, wheel_fx_norm, ...: what is compared with the exact
    theory's one patch) comes with every solve, in sweeps too, as the program's /summary has it
    (it was only reachable one call at a time through value())."""
    _, rows = run_app("ksweep", "examples/kinematic_sweep.nml")
    t_y = np.array([float(row["t_y"]) for row in rows])
    yaw = np.array([float(row["yaw"]) for row in rows])
    r = contact.solve_kinematic(t_y, yaw=yaw, v_forward=30000.0, vertical_force=64700.0)
    for key in layout.WHEEL:
        assert np.shape(r[key]) == t_y.shape, key
        for i, row in enumerate(rows):
            assert r[key][i] == pytest.approx(float(row[key]), rel=RTOL, abs=ATOL), (key, i)
    assert r["wheel_patches"].dtype.kind == "i" and r["wheel_patches"].max() >= 2
    one = contact.solve(T_Y, **HEADLINE)
    assert one["wheel_fx"] == contact.value("wheel_fx")
    assert one["wheel_fx_norm"] == pytest.approx(one["fx_norm"], rel=1e-12)


def test_kinematic_sweep_as_arrays(contact, run_app):
    """The 34 cases of examples/kinematic_sweep.nml as one vectorised call."""
    _, rows = run_app("ksweep", "examples/kinematic_sweep.nml")
    t_y = np.array([float(row["t_y"]) for row in rows])
    yaw = np.array([float(row["yaw"]) for row in rows])
    assert len(rows) == 34 and len(set(t_y)) == 17 and len(set(yaw)) == 2
    r = contact.solve_kinematic(t_y, yaw=yaw, v_forward=30000.0, vertical_force=64700.0)
    assert r["fx"].shape == (34,) and r["n_patches"].dtype.kind == "i"
    for k, row in enumerate(rows):
        assert_agrees(r, row, {**SUMMARY_OF_LAYOUT, **KINEMATIC_SUMMARY}, index=k)
    # Broadcasting: a (17, 2) grid holds the same cases.
    grid = contact.solve_kinematic(np.unique(t_y)[:, None], yaw=np.unique(yaw)[None, :],
                                   v_forward=30000.0, vertical_force=64700.0)
    assert grid["sum_fy"].shape == (17, 2)
    for k in range(34):
        i, j = np.searchsorted(np.unique(t_y), t_y[k]), np.searchsorted(np.unique(yaw), yaw[k])
        assert grid["sum_fy"][i, j] == r["sum_fy"][k]


def test_arrays_equal_single_calls(contact):
    """Each element of a vectorised call is the call made alone (no history)."""
    t_y = np.linspace(0.0, 6.0, 7)
    nu_x = np.array([0.0, 0.5e-3, 1e-3])[:, None]
    r = contact.solve(t_y, nu_x=nu_x, normal_force=64.7e3, nu_y=0.061e-3, phi=2.74e-4)
    assert r["fx"].shape == (3, 7) and r["status"].shape == (3, 7)
    with shcontact.Contact() as fresh:
        for i in range(3):
            for j in range(7):
                one = fresh.solve(t_y[j], nu_x=nu_x[i, 0], normal_force=64.7e3,
                                  nu_y=0.061e-3, phi=2.74e-4)
                for key in layout.RESULT:
                    assert r[key][i, j] == one[key], key
    # F_n as prescribed; F_x grows with nu_x.
    assert np.allclose(r["fn"], 64.7e3, rtol=1e-12) and np.all(np.diff(r["fx"], axis=0) < 0)


def test_fields_sum_to_forces_and_equal_file(contact, run_app):
    path, _ = run_app("headline")
    r = contact.solve(T_Y, **HEADLINE)
    f = contact.fields()
    ny, nx = f["pn"].shape
    assert all(f[key].shape == (ny, nx) for key in f) and nx > 10 and ny > 10
    assert np.sum(f["px"] * f["area"]) == pytest.approx(r["fx"], rel=1e-12)
    assert np.sum(f["py"] * f["area"]) == pytest.approx(r["fy"], rel=1e-12)
    # The pressure at the element centres integrates to F_n to the discretisation's accuracy.
    assert np.sum(f["pn"] * f["area"]) == pytest.approx(r["fn"], rel=2e-3)
    assert set(np.unique(f["state"])) <= {0, 1, 2}
    assert np.all((f["state"] == layout.STATE_SLIP) == (f["slip"] > 0))
    # The same fields as the program's result file (case 1, the main patch).
    g = shcontact.read_fields(path, case=1, patch=int(r["main_patch"]))
    for key in ("pn", "px", "py", "slip", "x"):
        np.testing.assert_allclose(f[key], g[key], rtol=RTOL, atol=1e-9, err_msg=key)
    np.testing.assert_array_equal(f["state"], g["state"])
    np.testing.assert_allclose(f["y"][:, 0], g["y"], rtol=RTOL, atol=1e-12)


def test_patches_and_kinematic_patch(contact):
    r = contact.solve_kinematic(4.733, **KINEMATIC)
    patches = [contact.patch(k) for k in range(1, int(r["n_loaded"]) + 1)]
    assert sum(p["fz_track"] for p in patches) == pytest.approx(r["sum_fz"], rel=1e-12)
    main = patches[int(r["main_patch"]) - 1]
    for key in ("fx", "fy", "fn", "nu_x", "nu_y", "phi", "x_track"):
        assert main[key] == r[key], key


def test_profiles_as_arrays_give_same_results(contact):
    wheel, rail = contact.profile("wheel"), contact.profile("rail")
    with shcontact.Contact.from_arrays(*wheel, *rail) as c:
        a = c.solve(T_Y, **HEADLINE)
    b = contact.solve(T_Y, **HEADLINE)
    for key in layout.RESULT:
        assert a[key] == b[key], key


def test_errors(contact):
    with pytest.raises(shcontact.ShcontactError, match="positive") as info:
        contact.solve(T_Y, normal_force=-1.0)
    assert info.value.status == layout.STATUS["invalid_input"]
    # errors="nan": the failed case is NaN with its status, the others are solved.
    r = contact.solve(T_Y, nu_x=[0.58e-3, np.nan, 0.58e-3], normal_force=64.7e3, errors="nan")
    assert list(r["status"]) == [0, layout.STATUS["invalid_input"], 0]
    assert np.isnan(r["fx"][1]) and r["fx"][0] == r["fx"][2] and r["n_patches"][1] == 0
    with pytest.raises(shcontact.ShcontactError) as info:
        contact.solve(T_Y, nu_x=[0.0, np.nan], normal_force=64.7e3)
    assert info.value.case == (1,)
    with pytest.raises(TypeError, match="exactly one load"):
        contact.solve(T_Y, normal_force=1.0, vertical_force=1.0)
    with pytest.raises(shcontact.ShcontactError, match="v_forward"):
        contact.solve_kinematic(4.733, v_forward=0.0, vertical_force=64.7e3)
    with pytest.raises(shcontact.ShcontactError) as info:
        shcontact.Contact("no/such/profile.txt")
    assert info.value.status == layout.STATUS["io"]
    with pytest.raises(shcontact.ShcontactError, match="fields=True"):
        shcontact.Contact().fields()
    with pytest.raises(shcontact.ShcontactError):
        contact.set_option("no%such", "option")
    # Arguments of the wrong type name the keyword and the type expected (not ctypes'
    # "argument 2: TypeError: wrong type").
    with pytest.raises(TypeError, match=r"set_track gauge = '1435': expected a number"):
        shcontact.Contact().set_track(gauge="1435")
    with pytest.raises(TypeError, match=r"patch = 1.0: expected an integer"):
        contact.patch(1.0)
    with pytest.raises(TypeError, match=r"fields patch = 1.5: expected an integer"):
        shcontact.Contact(fields=True).fields(1.5)
    # The solve calls' inputs: text and None are not numbers (numpy read "3" as 3 and None as
    # NaN, reported by the library without the keyword).
    with pytest.raises(TypeError, match=r"t_y = '4.733': expected a number"):
        contact.solve("4.733", normal_force=64.7e3)
    with pytest.raises(TypeError, match=r"nu_x = None: expected a number"):
        contact.solve(T_Y, nu_x=None, normal_force=64.7e3)
    with pytest.raises(TypeError, match=r"yaw = 'abc': expected a number"):
        contact.solve_kinematic(T_Y, yaw="abc", v_forward=30e3, vertical_force=64.7e3)
    with pytest.raises(TypeError, match=r"v_forward = '40e3': expected a number"):
        shcontact.Wheelset().solve(3.0, v_forward="40e3", load_right=64.7e3, load_left=64.7e3)
    with pytest.raises(TypeError, match=r"set_option key = 3: expected a string"):
        contact.set_option(3, "x")
    with pytest.raises(TypeError, match=r"value key = None: expected a string"):
        contact.value(None)
    with pytest.raises(TypeError, match=r"value patch = 0.5: expected an integer \(0 the main"):
        contact.value("fx", 0.5)
    with pytest.raises(TypeError, match=r"rail_canted = 'no': expected True or False"):
        shcontact.Contact().set_track(rail_canted="no")
    with pytest.raises(TypeError, match=r"set_material friction = '0.3': expected a number"):
        shcontact.Contact().set_material(friction="0.3")
    # What ctypes took before still works: numpy scalars and 0-d arrays, Decimal, 0 the main
    # patch, integers for floats, numpy's bools.
    from decimal import Decimal
    other = shcontact.Contact()
    other.set_track(gauge=np.array(1435.0), gauge_height=Decimal("14"), rail_canted=np.bool_(False),
                    nominal_radius=460)
    assert other.value("track%gauge") == 1435.0 and other.value("track%nominal_radius") == 460.0
    contact.solve(T_Y, nu_x=0.58e-3, normal_force=64.7e3)
    assert contact.value("fx", np.array(0)) == contact.value("fx", np.int64(0)) \
        == contact.value("fx") != 0.0


def test_material_track_and_options():
    """The set-up calls reach the library: the defaults given again change nothing, other
    values change what they should."""
    with shcontact.Contact() as c:
        base = c.solve(T_Y, **HEADLINE)
        c.set_material()
        c.set_track()
        again = c.solve(T_Y, **HEADLINE)
        assert all(again[key] == base[key] for key in layout.RESULT)
        c.set_material(friction=0.2)
        # Friction bounds the traction: |f| <= 1 relative to mu F_n with the new mu.
        low = c.solve(T_Y, **HEADLINE)
        assert abs(low["fx"]) < abs(base["fx"])
        assert np.hypot(low["fx"], low["fy"]) <= 0.2 * low["fn"] * (1 + 1e-12)
        c.set_track(inclination=1.0 / 20.0)
        assert c.solve(T_Y, **HEADLINE)["gamma0"] != low["gamma0"]
    with shcontact.Contact(options={"tangential%bound": "clipped"}) as c:
        assert c.solve(T_Y, **HEADLINE)["fx"] != base["fx"]
    with pytest.raises(TypeError, match="unknown keyword"):
        shcontact.Contact(track={"gage": 1435.0})


def test_value_reads_inputs_and_results():
    """``Contact.value``: a numeric input as the handle holds it, a result of the last solve."""
    with shcontact.Contact() as c:
        assert c.value("track%flange_back_position") == -70.0
        assert c.value("material%friction") == 0.3
        with pytest.raises(shcontact.ShcontactError, match="no result yet"):
            c.value("fx")
        with pytest.raises(shcontact.ShcontactError, match="not a number"):
            c.value("normal%method")
        r = c.solve(T_Y, **HEADLINE)
        assert c.value("fx") == r["fx"]
        # The grid as the vehicle preset resolves it (doc/kinematics.md, "The vehicle preset").
        assert (c.value("normal%n_strips"), c.value("tangential%n_elements")) == (100, 50)
        c.set_option("normal%preset", "vehicle")
        assert (c.value("normal%n_strips"), c.value("tangential%n_elements")) == (60, 40)


def test_pitch_rate_of_nominal_radius_by_option():
    """Pure rolling's pitch rate comes from the nominal radius the handle holds, however it
    was set (set_track or the option key): the same creepages both ways (it used a radius cached
    by set_track only, so an option key gave nu_x = +2.06e-2 instead of -1.33e-3)."""
    state = dict(v_forward=30000.0, yaw=0.002, vertical_force=64.7e3)
    with shcontact.Contact(track={"nominal_radius": 450.0}) as a, \
            shcontact.Contact(options={"track%nominal_radius": 450}) as b:
        ra, rb = a.solve_kinematic(2.0, **state), b.solve_kinematic(2.0, **state)
        assert ra["nu_x"] == rb["nu_x"] and ra["fx"] == rb["fx"]
        assert abs(ra["nu_x"]) < 2e-3


def test_track_keeps_miniprof_origin():
    """A MiniProf wheel has its origin at its flange back, so the library's flange-back
    position for it is 0 (doc/app.md, "&track"); ``track={...}`` without that keyword keeps 0
    (it sent S1002's -70 mm before, and the wheel moved by 70 mm: centred rolling radius 479.2
    instead of 459.9 mm). Needs the external data's measured wheel (SHCONTACT_EXTERNAL_DATA)."""
    folder = os.environ.get("SHCONTACT_EXTERNAL_DATA")
    if not folder:
        pytest.skip("SHCONTACT_EXTERNAL_DATA is not set")
    wheel = os.path.join(folder, "profiles", "Car7216_0001r.whl")
    with shcontact.Contact(wheel, "builtin:UIC60") as plain, \
            shcontact.Contact(wheel, "builtin:UIC60", track={"gauge": 1435.0}) as tracked:
        assert tracked.value("track%flange_back_position") == 0.0
        a = plain.solve_kinematic(0.0, v_forward=30000.0, vertical_force=64.7e3)
        b = tracked.solve_kinematic(0.0, v_forward=30000.0, vertical_force=64.7e3)
        assert a["status"] == 0 and b["r0"] == a["r0"] and b["fy"] == a["fy"]
        assert abs(a["r0"] - 460.0) < 5.0


def test_preset_option():
    """The vehicle preset is one option key (doc/kinematics.md, "The vehicle preset"): it
    changes the kinematic forces (fewer strips and elements) by little; an unknown preset names
    the option and the choices."""
    with shcontact.Contact() as d, shcontact.Contact(options={"normal%preset": "vehicle"}) as v:
        a = d.solve_kinematic(4.733, **KINEMATIC)
        b = v.solve_kinematic(4.733, **KINEMATIC)
        assert a["status"] == 0 and b["status"] == 0
        assert b["fx"] != a["fx"]
        assert abs(b["fx_norm"] - a["fx_norm"]) <= 0.01 and abs(b["fy_norm"] - a["fy_norm"]) <= 0.01
        with pytest.raises(shcontact.ShcontactError, match="normal%preset.*'default', 'vehicle'") as info:
            v.set_option("normal%preset", "fast")
        assert info.value.status == layout.STATUS["invalid_input"]


def test_shared_force_loads_both_lobes(contact):
    """The normal force shared by the patches (doc/lobes.md): at t_y = 5.0 mm both patches
    carry it and their normal forces add up to it; the plain normal force loads the first."""
    r = contact.solve(5.0, shared_force=64.7e3, nu_x=0.58e-3, phi=2.74e-4)
    assert r["n_loaded"] == 2 and r["sum_fn"] == pytest.approx(64.7e3, rel=1e-9)
    assert r["fn"] < 0.9 * 64.7e3
    plain = contact.solve(5.0, normal_force=64.7e3, nu_x=0.58e-3, phi=2.74e-4)
    assert plain["n_loaded"] == 1 and plain["fn"] == pytest.approx(64.7e3, rel=1e-10)


def test_shared_between_threads_equals_serial():
    """One contact used by two threads at once: its calls take turns (a lock), so every result
    equals the serial one bit for bit (a user trial found 731 of 1980 cases wrong, status 0,
    before the lock: ctypes releases the GIL during a library call)."""
    import threading
    t_y = np.linspace(-2.0, 6.0, 9)
    with shcontact.Contact() as c:
        serial = [c.solve(t_y, vertical_force=64.7e3, nu_x=k * 1e-4)["fx"] for k in range(6)]
        results = [None] * 6

        def work(first):
            for k in range(first, 6, 2):
                results[k] = c.solve(t_y, vertical_force=64.7e3, nu_x=k * 1e-4)["fx"]

        threads = [threading.Thread(target=work, args=(i,)) for i in (0, 1)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
    for k in range(6):
        np.testing.assert_array_equal(results[k], serial[k])


def test_copy_refused_and_error_picklable(tmp_path):
    """A contact cannot be copied (a shared C handle crashed the process at exit); the error
    of a failed case survives pickling (multiprocessing hung on it), with its case as ints."""
    import copy
    import pathlib
    import pickle
    with shcontact.Contact() as c:
        with pytest.raises(TypeError, match="cannot be copied"):
            copy.copy(c)
        with pytest.raises(TypeError, match="cannot be copied"):
            copy.deepcopy(c)
        with pytest.raises(shcontact.ShcontactError) as info:
            c.solve(np.array([0.0, 40.0]), normal_force=64.7e3)
    err = pickle.loads(pickle.dumps(info.value))
    assert (err.status, err.message, err.case) == (info.value.status, info.value.message, (1,))
    assert str(err) == str(info.value) and "(case (1,))" in str(err)
    # A path object names a profile file as a string does.
    wheel = pathlib.Path(__file__).resolve().parents[2] / "data" / "profiles" / "S1002.txt"
    with shcontact.Contact(wheel) as a, shcontact.Contact(str(wheel)) as b:
        assert a.solve(3.0, normal_force=64.7e3)["fx"] == b.solve(3.0, normal_force=64.7e3)["fx"]


def test_set_material_keeps_values_not_given():
    """set_material(friction=...) keeps the shear modulus and Poisson's ratio the contact holds
    (it reset them to the defaults); output%fields takes quoted values and True."""
    with shcontact.Contact(material={"shear_modulus": 80000.0, "poisson": 0.28}) as c:
        c.set_material(friction=0.2)
        assert (c.value("material%shear_modulus"), c.value("material%poisson"),
                c.value("material%friction")) == (80000.0, 0.28, 0.2)
        c.set_option("output%fields", "'all'")
        c.solve(3.0, normal_force=64.7e3)
        assert c.fields()["pn"].shape[1] > 0
        c.set_option("output%fields", False)
        c.set_option("output%fields", True)


def test_wheelset_equals_two_wheels():
    """Wheelset.solve (shcontact_solve_wheelset) against one Contact per wheel: each wheel's
    values bit for bit, the totals their sum in the track frame (the left wheel's side-frame
    lateral force turned), over arrays of states; a wheel below 1 N is lifted."""
    state = dict(yaw=np.array([0.0, 0.004, -0.003]), v_forward=30000.0, v_lateral=-20.0,
                 yaw_rate=0.05)
    y_ws = np.array([0.0, 3.0, -5.5])
    q_right, q_left = np.array([64.7e3, 60e3, 70e3]), np.array([64.7e3, 68e3, 58e3])
    with shcontact.Wheelset() as axle, shcontact.Contact(side="right") as right, \
            shcontact.Contact(side="left") as left:
        both = axle.solve(y_ws, load_right=q_right, load_left=q_left, **state)
        one = {"right": right.solve_kinematic(y_ws, vertical_force=q_right, **state),
               "left": left.solve_kinematic(y_ws, vertical_force=q_left, **state)}
        assert np.all(both["status"] == 0)
        for side in ("right", "left"):
            for name in layout.KINEMATIC + layout.FLAGS:
                assert np.array_equal(both[side][name], one[side][name]), (side, name)
        assert np.allclose(both["fx"], one["right"]["sum_fx"] + one["left"]["sum_fx"],
                           rtol=1e-12, atol=1e-9)
        assert np.allclose(both["fy"], one["right"]["sum_fy"] - one["left"]["sum_fy"],
                           rtol=1e-12, atol=1e-9)
        assert np.allclose(both["fz"], one["right"]["sum_fz"] + one["left"]["sum_fz"],
                           rtol=1e-12, atol=1e-9)
        # z down: the rails carry the loads, -(Q_right + Q_left).
        assert np.all(np.abs(both["fz"] + (q_right + q_left)) <= 1e-5 * (q_right + q_left))
        lifted = axle.solve(2.0, v_forward=30000.0, load_right=64.7e3, load_left=0.5)
        assert lifted["status"] == 0 and lifted["left"]["n_patches"] == 0
        assert lifted["left"]["fn"] == 0.0 and lifted["right"]["fn"] > 0.0
        for call in (lambda: axle.solve_kinematic(0.0, v_forward=30000.0,
                                                  vertical_force=64.7e3),
                     lambda: axle.patch(1), lambda: axle.fields()):
            with pytest.raises(shcontact.ShcontactError, match="Wheelset"):
                call()
        failed = axle.solve([0.0, 0.0], v_forward=[30000.0, -1.0], load_right=64.7e3,
                            load_left=64.7e3, errors="nan")
        assert list(failed["status"]) == [0, layout.STATUS["invalid_input"]]
        assert np.isnan(failed["fx"][1]) and np.isnan(failed["right"]["fx"][1])


def test_climbing_flag_by_key():
    """The keyed value 'climbing' (1: the main contact lies on the flange beyond its steepest
    part) through the C API: off on the tread, on at 20 mm; a wheelset's wheel by 'right%'."""
    with shcontact.Contact() as c:
        c.solve_kinematic(0.0, v_forward=30000.0, vertical_force=64.7e3)
        assert c.value("climbing") == 0.0
        c.solve_kinematic(20.0, v_forward=30000.0, vertical_force=64.7e3)
        assert c.value("climbing") == 1.0
        # With every result of an array of states, as an integer flag.
        k = c.solve_kinematic([0.0, 3.0, 20.0], v_forward=30000.0, vertical_force=64.7e3)
        assert k["climbing"].dtype.kind == "i" and list(k["climbing"]) == [0, 0, 1]
        with pytest.raises(shcontact.ShcontactError):
            c.value("climbing", patch=1)
    with shcontact.Wheelset() as axle:
        w = axle.solve(20.0, v_forward=30000.0, load_right=64.7e3, load_left=64.7e3)
        assert axle.value("right%climbing") == 1.0 and axle.value("left%climbing") == 0.0
        assert w["right"]["climbing"] == 1 and w["left"]["climbing"] == 0


def test_program_names_read_the_same_values(run_app):
    """The keyed getter takes the program's /summary names too (coulomb_ratio, delta,
    fx_total, ...): one name reads the same value in every interface (the program's CSV)."""
    _, rows = run_app("headline")
    with shcontact.Contact() as c:
        c.solve(T_Y, **HEADLINE)
        for column in SUMMARY_OF_LAYOUT.values():
            assert c.value(column) == pytest.approx(float(rows[0][column]), rel=RTOL,
                                                    abs=ATOL), column
