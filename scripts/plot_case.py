#!/usr/bin/env python3
"""Plot a shcontact result file (HDF5): the figures of the seed paper for one case or a sweep,
and comparisons of two runs.

    python3 scripts/plot_case.py OUT.h5 [--case N] [--patch K] [-o DIR] [--prefix NAME]
        [--x AXIS] [--fix AXIS=VALUE ...] [--curves AXIS] [--abs] [--compare OTHER.h5]

Writes into DIR (-o/--outdir; default: the folder of OUT.h5), when the file holds what they
need:

    NAME_pressure.png   normal pressure on the patch and the strip table (seed Fig. 4)
    NAME_traction.png   tangential tractions on the wheel as arrows (with a scale key), adhesion
                        and slip areas and the stick/slip boundary (seed Fig. 5)
    NAME_numbers.csv    the numbers the two figures above print in their titles, each with
                        its full value and the half unit of its last printed digit (so that a
                        test can check that a committed figure still shows the current numbers)
    NAME_geometry.png   gap and lateral relative curvature B(y) of the patch (seed Fig. 3)
    NAME_creep.png      normalised creep forces f_x, f_y (signed; --abs for |f|) against a
                        swept input (--x, default the innermost), one curve per bound / spin
                        model or per value of --curves; every other swept input held at the
                        value --fix gives (nearest swept value; default its first value)
    NAME_vs_OTHER_forces.png     with --compare: F_x, F_y, M_z of the cases of both files
                                 against each other (seed Fig. 8)
    NAME_vs_OTHER_error_cdf.png  with --compare: distribution (CDF) of the differences of the
                                 normalised forces over the cases (seed Fig. 9)

The field figures name the case's position, creepages, load and traction bound in their titles.
NAME defaults to the file name without .h5. The field figures need a case stored with its
fields (the default for a single case; `&output fields = 'all'` in a sweep).
Needs h5py, numpy and matplotlib: `scripts/setup --plot` installs them (without them the script
says so and exits with status 1). doc/plots.md shows every figure.
"""
import argparse
import csv
import os
import re
import sys

try:
    import h5py
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    from matplotlib.collections import PolyCollection
    from matplotlib.patches import Patch
except ImportError as missing:  # one clear line instead of a traceback
    sys.stderr.write(f"plot_case: needs h5py, numpy and matplotlib, and Python cannot import "
                     f"'{missing.name}'; install them with `scripts/setup --plot` (or "
                     f"`python3 -m pip install h5py numpy matplotlib`)\n")
    sys.exit(1)

#: Swept inputs a /summary table can have, in the program's loop order.
SWEEP_AXES = ["t_y", "roll", "yaw", "normal_force", "approach", "vertical_force", "friction",
              "bound", "spin_model", "v_forward", "v_lateral", "v_vertical", "roll_rate",
              "yaw_rate", "pitch_rate", "nu_x", "nu_y", "phi"]
#: In a kinematic run (&kinematics mode = 'on') nu_x, nu_y, phi are results, and the wheelset
#: inputs are columns whether swept or not.
KINEMATIC_RESULTS = ("nu_x", "nu_y", "phi")
#: Inputs that choose the model or the material rather than the case: --compare sets solutions
#: that differ in them against each other.
MODEL_INPUTS = ("friction", "bound", "spin_model")
#: How to show a swept input: (label, scale).
AXIS_DISPLAY = {
    "nu_x": (r"$\nu_x$ [‰]", 1e3), "nu_y": (r"$\nu_y$ [‰]", 1e3),
    "phi": (r"$\varphi$ [1/m]", 1e3), "t_y": (r"$t_y$ [mm]", 1.0),
    "roll": ("roll [rad]", 1.0), "normal_force": ("N [kN]", 1e-3),
    "vertical_force": ("$F_z$ [kN]", 1e-3), "approach": (r"$\delta$ [mm]", 1.0),
    "friction": (r"$\mu$", 1.0), "yaw": (r"yaw $\psi$ [mrad]", 1e3),
    "v_forward": ("V [m/s]", 1e-3), "v_lateral": ("$v_y$ [m/s]", 1e-3),
}


#: The numbers the field figures print: name -> (group under patch_K, dataset, scale to the
#: printed unit, format, printed unit). NAME_numbers.csv lists them (write_numbers).
FIELD_NUMBERS = {
    "fn": ("normal", "load", 1e-3, ".2f", "kN"),
    "p_max": ("normal", "p_max", 1.0, ".0f", "MPa"),
    "fx": ("tangential", "fx", 1.0, ".0f", "N"),
    "fy": ("tangential", "fy", 1.0, ".0f", "N"),
    "fx_norm": ("tangential", "fx_norm", 1.0, ".3f", "1"),
    "fy_norm": ("tangential", "fy_norm", 1.0, ".3f", "1"),
    "adhesion_fraction": ("tangential", "adhesion_fraction", 100.0, ".0f", "%"),
}
#: Scale of the title's numbers to their printed unit (title_numbers).
TITLE_SCALES = {"t_y": 1.0, "normal_force": 1e-3, "vertical_force": 1e-3, "approach": 1.0,
                "nu_x": 1.0, "nu_y": 1.0, "phi": 1.0}


def shown(group, patch, name):
    """(value, printed text) of one of FIELD_NUMBERS for patch `patch` of a case group."""
    sub, key, scale, fmt, _ = FIELD_NUMBERS[name]
    value = float(group[f"patch_{patch}/{sub}/{key}"][()])
    return value, format(value * scale, fmt)


def half_unit(printed):
    """Half a unit of the last digit of a printed number ('-5847' -> 0.5, '0.00058' -> 5e-6)."""
    from decimal import Decimal
    return 0.5 * 10.0 ** Decimal(printed).as_tuple().exponent


def write_numbers(f, group, patch, out):
    """NAME_numbers.csv: every number the field figures of this case and patch print, as
    `quantity,value,printed,shown,tolerance`: the value (units of the result file), the text on
    the figure, that text in the value's units, and the half unit of its last printed digit in
    the value's units. Returns False when the patch has no tangential results."""
    if f"patch_{patch}/tangential/fx" not in group:
        return False
    rows, _ = title_numbers(f, group, patch)
    rows = {k: (v, t, TITLE_SCALES[k]) for k, (v, t) in rows.items()}
    for name, spec in FIELD_NUMBERS.items():
        rows[name] = shown(group, patch, name) + (spec[2],)
    with open(out, "w", newline="") as stream:
        w = csv.writer(stream, lineterminator="\n")
        w.writerow(["quantity", "value", "printed", "shown", "tolerance"])
        for name, (value, printed, scale) in rows.items():
            w.writerow([name, repr(value), printed, repr(float(printed) / scale),
                        f"{half_unit(printed) / scale:.3g}"])
    return True


def text(value):
    """An HDF5 string (bytes or numpy bytes) as str."""
    if isinstance(value, (bytes, np.bytes_)):
        return value.decode("utf-8", "replace")
    return str(value)


def namelist_values(namelist):
    """{name: value text} of the stored namelist (`&group`, `name = value  ! comment`)."""
    values, group = {}, ""
    for line in namelist.splitlines():
        line = line.split("!", 1)[0]
        if line.lstrip().startswith("&"):
            group = line.strip()[1:].split()[0].lower() if line.strip()[1:] else ""
        elif "=" in line:
            key, value = line.split("=", 1)
            values[f"{group}%{key.strip().lower()}"] = value.strip().strip("'")
            values.setdefault(key.strip().lower(), value.strip().strip("'"))
    return values


def case_inputs(f, icase):
    """{input: value} of case `icase`: the swept inputs from its /summary row, the others from
    the stored namelist."""
    values = namelist_values(text(f["input/namelist"][()]))
    inputs = {}
    for key in ("t_y", "yaw", "nu_x", "nu_y", "phi", "normal_force", "vertical_force",
                "approach", "friction", "bound", "spin_model"):
        if key in values:
            inputs[key] = values[key]
    inputs["load_mode"] = values.get("load%mode", "")
    s = f.get("summary")
    if s is not None and "case" in s:
        rows = np.nonzero(s["case"][...] == icase)[0]
        if rows.size:
            for key in SWEEP_AXES:
                if key in s:
                    v = s[key][rows[0]]
                    inputs[key] = text(v) if isinstance(v, (bytes, np.bytes_)) else float(v)
    return inputs


def number(value):
    """A namelist or summary value as a float (nan when it is not a number)."""
    try:
        return float(str(value).replace("d", "e").replace("D", "e"))
    except ValueError:
        return float("nan")


def title_numbers(f, group, patch):
    """{quantity: (value, printed text)} of the case title of the field figures: position,
    load, and the creepages of the patch drawn (its own, stored with its tangential results in a
    kinematic run or with several patches; else the case's)."""
    c = case_inputs(f, int(group.name.split("/")[-1]))
    out = {}
    if "t_y" in c:
        out["t_y"] = (number(c["t_y"]), f"{number(c['t_y']):g}")
    load = c.get("load_mode", "")
    for mode, key in (("force", "normal_force"), ("vertical", "vertical_force"),
                      ("approach", "approach")):
        if load == mode and key in c:
            scale = 1.0 if key == "approach" else 1e-3
            out[key] = (number(c[key]), f"{number(c[key]) * scale:g}")
    tan = group.get(f"patch_{patch}/tangential")
    for key in ("nu_x", "nu_y", "phi"):
        if tan is not None and key in tan:
            value = float(tan[key][()])
        elif key in c:
            value = number(c[key])
        else:
            continue
        out[key] = (value, f"{value:.3g}")
    return out, c


def case_title(f, group, patch, base):
    """Title of a field figure: file, case, patch, position, load, creepages of that patch,
    traction bound."""
    icase = int(group.name.split("/")[-1])
    numbers, c = title_numbers(f, group, patch)
    parts = [f"{base}, case {icase}, patch {patch}"]
    if "t_y" in numbers:
        parts.append(f"$t_y$ = {numbers['t_y'][1]} mm")
    for key, label, unit in (("normal_force", "N", "kN"), ("vertical_force", "$F_z$", "kN"),
                             ("approach", r"$\delta$", "mm")):
        if key in numbers:
            parts.append(f"{label} = {numbers[key][1]} {unit}")
    line2 = []
    for key, label in (("nu_x", r"$\nu_x$"), ("nu_y", r"$\nu_y$"), ("phi", r"$\varphi$")):
        if key in numbers:
            line2.append(f"{label} = {numbers[key][1]}" + (" rad/mm" if key == "phi" else ""))
    if "friction" in c:
        line2.append(rf"$\mu$ = {number(c['friction']):g}")
    if "bound" in c:
        line2.append(f"bound {c['bound']}")
    if "spin_model" in c:
        line2.append(f"spin model {c['spin_model']}")
    return ", ".join(parts) + "\n" + ", ".join(line2)


def nice_number(value):
    """1, 2 or 5 times a power of ten, at most `value`."""
    if value <= 0:
        return 1.0
    exp = np.floor(np.log10(value))
    for m in (5.0, 2.0, 1.0):
        if m * 10 ** exp <= value:
            return m * 10 ** exp
    return 10 ** exp


def element_rectangles(x, y, dx, dy):
    """Corner lists of the elements: x (ny, nx) centres, y (ny,) strip centres."""
    ny, nx = x.shape
    half_x = np.repeat(0.5 * dx[:, None], nx, axis=1)
    yc = np.repeat(y[:, None], nx, axis=1)
    x0, x1 = x - half_x, x + half_x
    y0, y1 = yc - 0.5 * dy, yc + 0.5 * dy
    return np.stack([np.stack([x0, y0], -1), np.stack([x1, y0], -1),
                     np.stack([x1, y1], -1), np.stack([x0, y1], -1)], axis=-2).reshape(-1, 4, 2)


def pick_case(f, case):
    """The group of the requested case, or of the first case with fields."""
    if "cases" not in f:
        return None
    names = sorted(f["cases"].keys())
    if case is not None:
        for name in names:
            if int(name) == case:
                return f["cases"][name]
        sys.exit(f"plot_case: case {case} has no fields in the file (cases with fields: "
                 f"{', '.join(str(int(n)) for n in names[:10])} ...)")
    return f["cases"][names[0]] if names else None


def plot_pressure(group, patch, title, out):
    """Seed Fig. 4: p_n on the element grid, and the strip peak pressure and half-length."""
    tan = group[f"patch_{patch}/tangential"]
    nor = group[f"patch_{patch}/normal"]
    if "pn" not in tan or "x" not in tan:
        return False
    x, y, dx, dy, pn = (tan["x"][...], tan["y"][...], tan["dx"][...], tan["dy"][()],
                        tan["pn"][...])
    inside = pn.ravel() > 0
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(12, 5), gridspec_kw={"width_ratios": [3, 2]})
    rects = element_rectangles(x, y, dx, dy)[inside]
    coll = PolyCollection(rects, array=pn.ravel()[inside], cmap="viridis", edgecolors="none")
    ax.add_collection(coll)
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_xlabel("x, rolling direction [mm]")
    ax.set_ylabel("y, lateral (field side +) [mm]")
    ax.set_title("normal pressure $p_n$")
    fig.colorbar(coll, ax=ax, label="$p_n$ [MPa]")
    if "p0" in nor:
        ys, p0, a = nor["y"][...], nor["p0"][...], nor["a"][...]
        ax2.plot(ys, p0, color="C0", label=r"strip peak pressure $p_{0,i}$")
        ax2.set_xlabel("y [mm]")
        ax2.set_ylabel("$p_{0,i}$ [MPa]", color="C0")
        ax3 = ax2.twinx()
        ax3.plot(ys, a, color="C1", label="half-length $a_i$")
        ax3.set_ylabel("$a_i$ [mm]", color="C1")
        ax2.set_title(f"strips: N = {shown(group, patch, 'fn')[1]} kN, "
                      f"$p_{{max}}$ = {shown(group, patch, 'p_max')[1]} MPa")
        ax2.grid(alpha=0.3)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)
    return True


def stick_slip_boundary(x, state, dx):
    """Per strip: x between the last adhesion element and the first slip element after it
    (elements run from the leading edge), or nan."""
    xb = np.full(x.shape[0], np.nan)
    for i in range(x.shape[0]):
        s = state[i]
        for j in range(len(s) - 1):
            if s[j] == 1 and s[j + 1] == 2:
                xb[i] = 0.5 * (x[i, j] + x[i, j + 1])
                break
    return xb


def plot_traction(group, patch, title, out):
    """Seed Fig. 5: traction arrows on the wheel, adhesion and slip areas, their boundary."""
    tan = group[f"patch_{patch}/tangential"]
    if "px" not in tan or "state" not in tan:
        return False
    x, y, dx, dy = tan["x"][...], tan["y"][...], tan["dx"][...], tan["dy"][()]
    px, py, state = tan["px"][...], tan["py"][...], tan["state"][...]
    inside = state.ravel() > 0
    # Constrained layout and a tight bounding box keep the titles, the key above the axes and
    # the x label inside the image whatever the patch's shape (a tall patch cut the label off).
    # The height follows the patch's aspect (equal axes), so a flat patch gets no empty band.
    ny_in = state > 0
    xc = x[ny_in]
    half = np.repeat(0.5 * dx[:, None], x.shape[1], axis=1)[ny_in]
    yc = np.repeat(y[:, None], x.shape[1], axis=1)[ny_in]
    aspect = (np.ptp(yc) + dy) / max(np.ptp(xc) + 2 * half.max(), 1e-9)
    fig, ax = plt.subplots(figsize=(9, min(9.0, max(3.5, 2.5 + 6.5 * aspect))),
                           constrained_layout=True)
    colours = np.where(state.ravel() == 1, 0.0, 1.0)[inside]
    coll = PolyCollection(element_rectangles(x, y, dx, dy)[inside], array=colours,
                          cmap=matplotlib.colors.ListedColormap(["#cfe3f7", "#f9d9b8"]),
                          edgecolors="none")
    coll.set_clim(0, 1)
    ax.add_collection(coll)
    ny, nx = x.shape
    sj, si = max(1, nx // 20), max(1, ny // 30)
    sel = (slice(None, None, si), slice(None, None, sj))
    mask = state[sel] > 0
    mag = np.hypot(px, py)
    scale = mag.max() / (2.0 * max(dx.max() * sj, dy * si)) if mag.max() > 0 else 1.0
    arrows = ax.quiver(x[sel][mask], np.repeat(y[:, None], nx, axis=1)[sel][mask],
                       px[sel][mask], py[sel][mask], angles="xy", scale_units="xy", scale=scale,
                       width=0.0025, color="k")
    # Scale key: an arrow of a round traction near the largest one.
    key = nice_number(0.8 * mag.max()) if mag.max() > 0 else 1.0
    ax.quiverkey(arrows, 0.12, 1.02, key, f"{key:g} MPa", labelpos="E", coordinates="axes",
                 fontproperties={"size": 9})
    xb = stick_slip_boundary(x, state, dx)
    ax.plot(xb, y, color="C3", lw=2, label="stick/slip boundary")
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_xlabel("x, rolling direction [mm] (leading edge at +x)")
    ax.set_ylabel("y, lateral (field side +) [mm]")
    value = {name: shown(group, patch, name)[1] for name in FIELD_NUMBERS}
    forces = (f"$F_x$ = {value['fx']} N, $F_y$ = {value['fy']} N, "
              f"$f_x$ = {value['fx_norm']}, $f_y$ = {value['fy_norm']}, "
              f"adhesion {value['adhesion_fraction']} %")
    ax.set_title("tangential tractions on the wheel\n" + forces, fontsize=10, pad=22)
    ax.legend(handles=[Patch(color="#cfe3f7", label="adhesion"),
                       Patch(color="#f9d9b8", label="slip"),
                       plt.Line2D([], [], color="C3", lw=2, label="stick/slip boundary")],
              loc="upper right", fontsize=9)
    fig.suptitle(title)
    fig.savefig(out, dpi=130, bbox_inches="tight")
    plt.close(fig)
    return True


def plot_geometry(f, group, patch, title, out):
    """Seed Fig. 3: gap and lateral relative curvature of the patch, with the profiles."""
    g = None
    if group is not None and f"patch_{patch}/geometry" in group:
        g = group[f"patch_{patch}/geometry"]
        title += f", case {int(group.name.split('/')[-1])}, patch {patch}"
    elif f"geometry/patch_{patch}" in f:
        g = f[f"geometry/patch_{patch}"]
        title += f", patch {patch} (the geometry every case shares)"
    if g is None or "y" not in g:
        return False
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    if "input/profiles/wheel" in f and "input/profiles/rail" in f:
        for name, colour in (("rail", "C0"), ("wheel", "C1")):
            yz = f[f"input/profiles/{name}"][...]
            axes[0].plot(yz[:, 0], yz[:, 1], color=colour,
                         label=f"{name}: {text(f['input/profiles/' + name].attrs['source'])}")
        axes[0].invert_yaxis()
        axes[0].set_aspect("equal")
        axes[0].set_xlabel("y [mm]")
        axes[0].set_ylabel("z (down) [mm]")
        axes[0].set_title("profiles (own coordinates)")
        axes[0].legend(fontsize=8)
    y = g["y"][...]
    axes[1].plot(y, g["gap"][...], color="C2")
    axes[1].set_xlabel("y from the reference point [mm]")
    axes[1].set_ylabel("gap g(y) [mm]")
    axes[1].set_yscale("symlog", linthresh=1e-3)
    axes[1].set_title(r"gap, $\gamma_0$ = %.4f rad" % g["gamma0"][()])
    axes[2].plot(y, g["curv_b"][...], label="B(y)")
    axes[2].plot(y, g["curv_a"][...], label="A(y)")
    axes[2].set_xlabel("y from the reference point [mm]")
    axes[2].set_ylabel("relative curvature [1/mm]")
    axes[2].set_title("lateral B(y) and longitudinal A(y)")
    axes[2].legend()
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)
    return True


def tangential_label(namelist):
    """'fastsim-sh, weighted' from the &tangential group of the stored namelist."""
    group = namelist.split("&tangential", 1)[-1].split("\n/", 1)[0]
    values = {}
    for line in group.splitlines():
        if "=" in line:
            key, value = line.split("!", 1)[0].split("=", 1)
            values[key.strip()] = value.strip().strip("'")
    return ", ".join(v for v in (values.get("method"), values.get("bound")) if v)


def swept_axes(f):
    """The swept inputs of a /summary table (in a kinematic run, the wheelset inputs that
    vary)."""
    s = f["summary"]
    namelist = text(f["input/namelist"][()])
    if re.search(r"&kinematics\s+mode\s*=\s*'on'", namelist):
        return [a for a in SWEEP_AXES if a in s and a not in KINEMATIC_RESULTS
                and len(np.unique(s[a][...])) > 1]
    return [a for a in SWEEP_AXES if a in s]


def parse_fixes(fixes):
    """{axis: value} from ['nu_y=1e-3', ...]."""
    out = {}
    for item in fixes or []:
        if "=" not in item:
            sys.exit(f"plot_case: --fix takes AXIS=VALUE, not '{item}'")
        key, value = item.split("=", 1)
        out[key.strip()] = value.strip()
    return out


def plot_creep(f, title, out, xname=None, fixes=None, curves=None, magnitude=False):
    """Seed Figs 6-7: f_x and f_y against a swept real input; one curve per combination of the
    choice inputs (bound, spin model) or per value of `curves`; the other swept inputs of a
    grid held at the values of `fixes` (nearest swept value) or at their first value."""
    s = f["summary"]
    swept = swept_axes(f)
    real_axes = [a for a in swept if a not in ("bound", "spin_model")]
    if not real_axes or len(s["case"]) < 2:
        return False
    fixes = parse_fixes(fixes)
    for a in list(fixes) + [xname, curves]:
        if a is not None and a not in swept:
            sys.exit(f"plot_case: '{a}' is not a swept input of this file "
                     f"(swept: {', '.join(swept)})")
    ok = s["status"][...] == 0
    if not ok.all():
        print(f"plot_case: {int((~ok).sum())} of {ok.size} case(s) failed and are left out "
              f"of the creep-force figures (their messages: /failures)", file=sys.stderr)
    xname = xname or real_axes[-1]
    list_mode = "mode = 'list'" in text(f["input/namelist"][()])
    keep = ok.copy()
    held, together = [], []
    for a in real_axes:
        if a in (xname, curves):
            continue
        v = s[a][...]
        if list_mode and a not in fixes:
            together.append(a)  # the i-th values go together
            continue
        values = np.unique(v)
        target = number(fixes[a]) if a in fixes else v[0]
        pick = values[np.argmin(np.abs(values - target))]
        keep &= v == pick
        label, scale = AXIS_DISPLAY.get(a, (a, 1.0))
        held.append(f"{label} = {pick * scale:.4g}")
    for a in ("bound", "spin_model"):
        if a in fixes:
            keep &= np.array([text(t) == fixes[a] for t in s[a][...]])
            held.append(f"{a} {fixes[a]}")
    labels = [a for a in swept if a in ("bound", "spin_model") and a not in fixes]
    if curves is not None:
        cv = s[curves][...]
        values = np.unique(cv[keep])
        if len(values) > 8:  # at most 8 curves, evenly spread
            values = values[np.round(np.linspace(0, len(values) - 1, 8)).astype(int)]
        clabel, cscale = AXIS_DISPLAY.get(curves, (curves, 1.0))
        groups = [(f"{clabel} = {v * cscale:.3g}", keep & (cv == v)) for v in values]
    else:
        keys = [tuple(text(s[a][i]) for a in labels) for i in range(len(ok))]
        default_label = tangential_label(text(f["input/namelist"][()]))
        groups = [(", ".join(key) if key else default_label,
                   keep & np.array([k == key for k in keys])) for key in sorted(set(keys))]
    label, scale = AXIS_DISPLAY.get(xname, (xname, 1.0))
    if together:
        label = " = ".join([AXIS_DISPLAY.get(a, (a, 1))[0] for a in together] + [label])
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8), sharex=True)
    for name, rows in groups:
        if not rows.any():
            continue
        xv = s[xname][...][rows] * scale
        order = np.argsort(xv)
        for ax, comp in zip(axes, ("fx_norm", "fy_norm")):
            yv = s[comp][...][rows]
            ax.plot(xv[order], (np.abs(yv) if magnitude else yv)[order], "o-", ms=3,
                    label=name)
    for ax, comp in zip(axes, ("x", "y")):
        ax.set_xlabel(label)
        if magnitude:
            ax.set_ylabel(rf"$|f_{comp}| = |F_{comp}|/(\mu F_n)$")
            ax.set_ylim(bottom=0)
        else:
            ax.set_ylabel(rf"$f_{comp} = F_{comp}/(\mu F_n)$ (on the wheel)")
            ax.axhline(0.0, color="0.5", lw=0.8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    # The inputs that are not swept, so the figure says what it shows.
    values = namelist_values(text(f["input/namelist"][()]))
    if not re.search(r"&kinematics\s+mode\s*=\s*'on'", text(f["input/namelist"][()])):
        for a in ("t_y", "nu_x", "nu_y", "phi"):
            if a not in swept and a in values:
                alabel, ascale = AXIS_DISPLAY.get(a, (a, 1.0))
                held.append(f"{alabel} = {number(values[a]) * ascale:.4g}")
    if held:
        title += "\n" + ", ".join(held)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)
    return True


def open_result(path, what="file"):
    """The HDF5 result file `path` opened for reading, or a one-line exit naming it."""
    if not os.path.isfile(path):
        sys.exit(f"plot_case: {path}: no such file")
    try:
        f = h5py.File(path, "r")
    except OSError as exc:
        if "signature" in str(exc):
            sys.exit(f"plot_case: {path} is not an HDF5 file (not a shcontact result file)")
        sys.exit(f"plot_case: cannot open {path}: {exc}")
    if text(f.attrs.get("software", b"")) != "shcontact" or "summary" not in f:
        f.close()
        sys.exit(f"plot_case: {path} is not a shcontact result file")
    return f


def is_kinematic(f):
    """True for a kinematic run (&kinematics mode = 'on')."""
    return re.search(r"&kinematics\s+mode\s*=\s*'on'", text(f["input/namelist"][()])) is not None


def input_columns(f, rows):
    """{input: values of the cases at `rows`} of a result file: the /summary column where there
    is one, else the stored namelist's value for every case (creepages are results in a
    kinematic run and are left out)."""
    values = namelist_values(text(f["input/namelist"][()]))
    s = f["summary"]
    columns = {}
    for key in SWEEP_AXES:
        if (is_kinematic(f) and key in KINEMATIC_RESULTS) or key in MODEL_INPUTS:
            continue
        if key in s:
            column = s[key][...][rows]
            columns[key] = [text(v) for v in column] if column.dtype.kind in "SO" else column
        elif key in values:
            columns[key] = [values[key]] * len(rows)
    return columns


def check_same_inputs(f, g, names):
    """Exit unless the cases both files hold have the same position, load, creepages or
    wheelset motion: --compare sets two solutions of the same cases against each other (other
    options, bounds, spin models or friction), and files of other sweeps pair their cases by
    number only."""
    if is_kinematic(f) != is_kinematic(g):
        sys.exit(f"plot_case: --compare: {names[0 if is_kinematic(f) else 1]} is a kinematic run "
                 f"and {names[1 if is_kinematic(f) else 0]} is not: their cases differ")
    rf, rg = common_cases(f, g)
    if rf.size == 0:
        sys.exit(f"plot_case: --compare: {names[0]} and {names[1]} have no solved case in common")
    a, b = input_columns(f, rf), input_columns(g, rg)
    cases = f["summary/case"][...][rf]
    for key in a:
        if key not in b:
            continue
        va, vb = a[key], b[key]
        for i in range(len(cases)):
            x, y = number(va[i]), number(vb[i])
            same = (text(va[i]) == text(vb[i]) if np.isnan(x) or np.isnan(y)
                    else abs(x - y) <= 1e-9 * max(abs(x), abs(y), 1e-300))
            if not same:
                sys.exit(f"plot_case: --compare: case {cases[i]} has {key} = {text(va[i])} in "
                         f"{names[0]} and {text(vb[i])} in {names[1]}: the files hold other "
                         f"cases (compare two solutions of the same cases)")


def common_cases(f, g):
    """Rows of the solved cases both files hold: (rows in f, rows in g)."""
    cf, cg = f["summary/case"][...], g["summary/case"][...]
    both = np.intersect1d(cf[f["summary/status"][...] == 0], cg[g["summary/status"][...] == 0])
    return np.searchsorted(cf, both), np.searchsorted(cg, both)


def plot_compare_forces(f, g, names, out):
    """Seed Fig. 8: F_x, F_y, M_z of the cases of two files against each other."""
    rf, rg = common_cases(f, g)
    if rf.size == 0:
        return False
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.8))
    for ax, (key, label, scale) in zip(axes, (("fx", "$F_x$ [kN]", 1e-3),
                                              ("fy", "$F_y$ [kN]", 1e-3),
                                              ("mz", "$M_z$ [N m]", 1e-3))):
        a = f["summary/" + key][...][rf] * scale
        b = g["summary/" + key][...][rg] * scale
        # Few cases: markers that show (a single case was a dot of 1-2 pixels).
        few = rf.size < 50
        ax.plot(b, a, "o" if few else ".", ms=6 if few else 2, alpha=0.8 if few else 0.5,
                color="C0")
        lo, hi = min(a.min(), b.min()), max(a.max(), b.max())
        ax.plot([lo, hi], [lo, hi], color="C3", lw=1, label="equal")
        ax.set_xlabel(f"{label}, {names[1]}")
        ax.set_ylabel(f"{label}, {names[0]}")
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="upper left")
    fig.suptitle(f"{names[0]} against {names[1]}: {rf.size} cases (forces on the wheel)")
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)
    return True


def plot_error_cdf(f, g, names, out):
    """Seed Fig. 9: distribution over the cases of the differences between two files: of the
    normalised forces (|delta f_x|, |delta f_y|, in units of mu F_n) and the relative
    difference of the resultant |f|."""
    rf, rg = common_cases(f, g)
    if rf.size == 0:
        return False
    fx_a, fy_a = f["summary/fx_norm"][...][rf], f["summary/fy_norm"][...][rf]
    fx_b, fy_b = g["summary/fx_norm"][...][rg], g["summary/fy_norm"][...][rg]
    res_a, res_b = np.hypot(fx_a, fy_a), np.hypot(fx_b, fy_b)
    loaded = res_b > 1e-3
    series = ((r"$|\Delta f_x|$", np.abs(fx_a - fx_b)), (r"$|\Delta f_y|$", np.abs(fy_a - fy_b)),
              (r"$|\Delta |f||\,/\,|f|$ (cases with $|f| > 10^{-3}$)",
               np.abs(res_a - res_b)[loaded] / res_b[loaded]))
    fig, ax = plt.subplots(figsize=(8, 5))
    floor = 1e-12
    for label, err in series:
        e = np.sort(np.maximum(err, floor))
        p = np.arange(1, e.size + 1) / e.size
        ax.step(e, p, where="post", marker="o" if e.size < 20 else None, ms=5,
                label=f"{label}: median {np.median(err):.2g}, 95 % {np.percentile(err, 95):.2g}, "
                      f"max {err.max():.2g}")
    ax.set_xscale("log")
    # From just below the smallest differences that are not zero (equal cases sit at the left).
    positive = np.concatenate([err[err > floor] for _, err in series])
    if positive.size:
        left = 10 ** np.floor(np.log10(np.percentile(positive, 0.5)))
        # Two decades at least, so that only the decades are labelled (a narrow range labelled
        # its minor ticks on top of each other).
        ax.set_xlim(left=left, right=max(10 ** np.ceil(np.log10(positive.max() * 1.0001)),
                                         100 * left))
    ax.set_xlabel(f"difference, {names[0]} against {names[1]} (cases with none at the left)")
    ax.set_ylabel("fraction of cases with a smaller difference")
    ax.set_ylim(0, 1.02)
    ax.grid(alpha=0.3, which="both")
    # Few cases sit at the top, where the legend of many cases goes.
    ax.legend(fontsize=8, loc="upper left" if rf.size >= 20 else "center left")
    ax.set_title(f"{names[0]} against {names[1]}: {rf.size} cases")
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("file", help="shcontact HDF5 result file")
    parser.add_argument("--case", type=int, help="case to draw the fields of (default: first "
                        "case with fields)")
    parser.add_argument("--patch", type=int, default=1, help="contact patch (default 1)")
    parser.add_argument("-o", "--outdir", help="directory for the PNGs (default: the folder "
                        "of the result file)")
    parser.add_argument("--prefix", help="file name prefix (default: the file name)")
    parser.add_argument("--x", dest="xaxis", help="swept input on the x-axis of the creep "
                        "figure (default: the innermost)")
    parser.add_argument("--fix", action="append", metavar="AXIS=VALUE",
                        help="hold a swept input at (the swept value nearest to) VALUE in the "
                        "creep figure; repeatable (default: its first value)")
    parser.add_argument("--curves", metavar="AXIS", help="one creep curve per value of this "
                        "swept input (at most 8)")
    parser.add_argument("--abs", action="store_true", help="plot |f_x|, |f_y| (seed style)")
    parser.add_argument("--compare", metavar="OTHER.h5", help="also compare the forces of the "
                        "cases with those of another result file")
    args = parser.parse_args()
    prefix = args.prefix or os.path.splitext(os.path.basename(args.file))[0]
    if args.outdir is None:
        args.outdir = os.path.dirname(args.file) or "."
    f = open_result(args.file)
    g = open_result(args.compare) if args.compare else None
    names = (os.path.basename(args.file), os.path.basename(args.compare or ""))
    if g is not None:
        check_same_inputs(f, g, names)
    if args.case is not None and "cases" not in f:
        sys.exit(f"plot_case: --case {args.case}: {args.file} holds no element fields (run "
                 f"with --set output%fields=all to store them)")
    os.makedirs(args.outdir, exist_ok=True)
    written = []
    with f:
        group = pick_case(f, args.case)
        title = os.path.basename(args.file)
        if group is not None:
            if f"patch_{args.patch}" not in group:
                have = ", ".join(k[6:] for k in group if k.startswith("patch_"))
                sys.exit(f"plot_case: case {group.name.split('/')[-1]} has no patch "
                         f"{args.patch} (it has: {have})")
            title_case = case_title(f, group, args.patch, title)
            for kind, plot in (("pressure", plot_pressure), ("traction", plot_traction)):
                out = os.path.join(args.outdir, f"{prefix}_{kind}.png")
                if plot(group, args.patch, title_case, out):
                    written.append(out)
            out = os.path.join(args.outdir, f"{prefix}_numbers.csv")
            if write_numbers(f, group, args.patch, out):
                written.append(out)
        out = os.path.join(args.outdir, f"{prefix}_geometry.png")
        if plot_geometry(f, group, args.patch, title, out):
            written.append(out)
        out = os.path.join(args.outdir, f"{prefix}_creep.png")
        if "summary" in f and plot_creep(f, title, out, args.xaxis, args.fix, args.curves,
                                         args.abs):
            written.append(out)
        if g is not None:
            other = os.path.splitext(os.path.basename(args.compare))[0]
            with g:
                out = os.path.join(args.outdir, f"{prefix}_vs_{other}_forces.png")
                if plot_compare_forces(f, g, names, out):
                    written.append(out)
                out = os.path.join(args.outdir, f"{prefix}_vs_{other}_error_cdf.png")
                if plot_error_cdf(f, g, names, out):
                    written.append(out)
    for name in written:
        print(name)
    if not written:
        sys.exit("plot_case: nothing to plot (no fields and no sweep in the file)")


if __name__ == "__main__":
    main()
