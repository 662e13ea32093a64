#!/usr/bin/env python3
"""Draw the validation figures of doc/validation.md (the seed's Figs 4-7 and 9).

Reads the tables written by the validation program (doc/validation/*.csv) and the exact-theory
reference (../shared/reference/, never copied into the repository) and writes PNG files into
doc/figures/. Run from the worktree root, after the tables:

    fpm run --example shcontact-validate --profile release
    python3 scripts/validation_figures.py [--reference DIR] [--tables DIR] [--figures DIR]

Needs numpy and matplotlib (scripts/setup --plot). Signs: everything is drawn on CONTACT's side
(forces and tractions on the rail), as the tables hold them; the lateral coordinate is CONTACT's
contact-local y (from its weighted centre; our reference point, the geometric contact point, is at
y_geo = 2.845 mm).
"""
import argparse
import os
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

BOUNDS = ["ellipsoidal", "parabolic", "weighted", "weighted-slip", "clipped"]
BOUND_LABELS = {
    "ellipsoidal": "ellipsoidal",
    "parabolic": "parabolic",
    "weighted": "weighted W1",
    "weighted-slip": "weighted-slip W2",
    "clipped": "clipped W3",
}
SPIN_MODELS = ["additive", "uniform", "scaled", "geometric"]
COLOURS = {
    "ellipsoidal": "tab:blue",
    "parabolic": "tab:orange",
    "weighted": "tab:green",
    "weighted-slip": "tab:purple",
    "clipped": "tab:brown",
    "additive": "tab:red",
    "uniform": "tab:green",
    "scaled": "tab:olive",
    "geometric": "tab:cyan",
}
# The recommended settings (doc/validation.md); the sweep and CDF tables hold every bound and spin
# model with the recommended spin flexibility and reduction.
DEFAULT_BOUND = "weighted"
DEFAULT_SPIN = "uniform"


def read_csv(path):
    """A CSV with one header line as a dict of columns (floats where possible)."""
    with open(path, encoding="utf-8") as f:
        header = f.readline().strip().split(",")
        rows = [line.rstrip("\n").split(",") for line in f if line.strip()]
    cols = {}
    for j, name in enumerate(header):
        values = [r[j] for r in rows]
        try:
            cols[name] = np.array([float(v) for v in values])
        except ValueError:
            cols[name] = np.array(values)
    return cols


def reference_grid(path):
    """CONTACT's element grid as 2-D arrays (iy, ix) of every column."""
    g = read_csv(path)
    mx, my = int(g["ix"].max()), int(g["iy"].max())
    ix = g["ix"].astype(int) - 1
    iy = g["iy"].astype(int) - 1
    out = {}
    for name, values in g.items():
        a = np.zeros((my, mx))
        a[iy, ix] = values
        out[name] = a
    return out


def cell_edges(centres):
    """Edges of cells with the given uniformly spaced centres."""
    h = centres[1] - centres[0]
    return np.concatenate([centres - 0.5 * h, [centres[-1] + 0.5 * h]])


def strip_pressure(strips, x, y):
    """Our semi-elliptic strip pressure p0_i sqrt(1 - x^2/a_i^2) on the grid (x, y) (CONTACT's y)."""
    yc = strips["y_contact_mm"]
    dy = yc[1] - yc[0]
    i = np.floor((y - (yc[0] - 0.5 * dy)) / dy).astype(int)
    inside = (i >= 0) & (i < len(yc))
    i = np.clip(i, 0, len(yc) - 1)
    a = strips["a_mm"][i]
    p0 = strips["p0_MPa"][i]
    with np.errstate(invalid="ignore", divide="ignore"):
        t = np.where(a > 0, 1.0 - (x / np.where(a > 0, a, 1.0)) ** 2, -1.0)
    return np.where(inside & (t > 0), p0 * np.sqrt(np.clip(t, 0, None)), 0.0)


def fig_normal(ref_dir, tables, out):
    """Seed Fig. 4: the pressure of the exact solution and of our normal solutions, same scale,
    plus the lateral load distribution q(y) = integral of p over x."""
    g = reference_grid(os.path.join(ref_dir, "grid_module3_exact_nonhertz.csv"))
    xr, yr = g["x_mm"][0, :], g["y_mm"][:, 0]
    variants = [
        ("semi-hertz_local-hertz", "shcontact semi-Hertz, local-Hertz"),
        ("semi-hertz_constant", "shcontact semi-Hertz, constant ε = 0.55"),
        ("hertz", "shcontact Hertz ellipse at the geometric point"),
    ]
    x = np.linspace(-5.5, 5.5, 221)
    y = np.linspace(-12.5, 13.5, 521)
    X, Y = np.meshgrid(x, y)
    summary = read_csv(os.path.join(tables, "normal_summary.csv"))
    vmax = 950.0
    fig, axes = plt.subplots(5, 1, figsize=(10, 16), constrained_layout=True)
    s = summary["source"].tolist().index("contact-exact")
    im = axes[0].pcolormesh(cell_edges(yr), cell_edges(xr), g["pn_MPa"].T, cmap="viridis",
                            vmin=0, vmax=vmax, shading="flat")
    axes[0].set_title("CONTACT exact (0.2 mm grid): p_max %.0f MPa, area %.1f mm²"
                      % (summary["p_max_MPa"][s], summary["area_mm2"][s]), fontsize=10)
    q_ref = g["pn_MPa"].sum(axis=1) * (xr[1] - xr[0])
    curves = [("CONTACT exact", yr, q_ref, "k", "-")]
    styles = ["tab:green", "tab:orange", "tab:blue"]
    for ax, (name, title), colour in zip(axes[1:4], variants, styles):
        strips = read_csv(os.path.join(tables, "normal_strips_%s.csv" % name))
        p = strip_pressure(strips, X, Y)
        ax.pcolormesh(y, x, p.T, cmap="viridis", vmin=0, vmax=vmax, shading="nearest")
        k = summary["source"].tolist().index("shcontact_" + name)
        ax.set_title("%s: p_max %.0f MPa, area %.1f mm²" % (title, summary["p_max_MPa"][k],
                                                           summary["area_mm2"][k]), fontsize=10)
        curves.append((title.replace("shcontact ", ""), strips["y_contact_mm"],
                       strips["q_N_per_mm"], colour, "--"))
    for ax in axes[:4]:
        ax.set_xlim(-12.5, 13.5)
        ax.set_ylim(-5.5, 5.5)
        ax.set_aspect("equal")
        ax.set_xlabel("y (mm, CONTACT's contact-local lateral axis, field side +)")
        ax.set_ylabel("x (mm, rolling)")
        ax.axvline(2.845, color="w", lw=0.6, ls=":")
        ax.set_facecolor(plt.cm.viridis(0.0))
    fig.colorbar(im, ax=axes[:4], label="normal pressure p_n (MPa)", shrink=0.5, aspect=30)
    ax = axes[4]
    for label, yy, q, colour, ls in curves:
        ax.plot(yy, q, color=colour, ls=ls, label=label)
    ax.axvline(2.845, color="grey", lw=0.6, ls=":", label="geometric contact point")
    ax.set_xlim(-12.5, 13.5)
    ax.set_xlabel("y (mm, CONTACT's contact-local lateral axis)")
    ax.set_ylabel("q(y) = ∫ p_n dx (N/mm)")
    ax.set_title("Lateral load distribution (total 64.7 kN)")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.suptitle("Normal contact, S1002 on UIC60 1:40, Y_WS = 0, F_n = 64.7 kN")
    fig.savefig(os.path.join(out, "fig4_normal_pressure.png"), dpi=110)
    plt.close(fig)


def resample_fields(fields, bound, x, y):
    """Our element fields of one bound on a regular grid (x, y) (CONTACT's y): px, py, state.
    Each grid point takes the element of the nearest strip that contains it."""
    strips = np.unique(fields["strip"].astype(int))
    nx = int(fields["element"].max())
    yc = np.array([fields["y_contact_mm"][fields["strip"] == s][0] for s in strips])
    dy = np.median(np.diff(yc))
    nearest = np.argmin(np.abs(y[..., None] - yc[None, None, :]), axis=-1)
    inside = (y >= yc[0] - 0.5 * dy) & (y <= yc[-1] + 0.5 * dy)
    px = np.zeros(x.shape)
    py = np.zeros(x.shape)
    st = np.zeros(x.shape)
    for k, s in enumerate(strips):
        sel = fields["strip"] == s
        order = np.argsort(fields["element"][sel])
        xs = fields["x_mm"][sel][order]
        a = xs[0] / (1.0 - 1.0 / nx)  # first centre at a (1 - 1/nx)
        j = np.floor((a - x) / (2.0 * a / nx)).astype(int)
        ok = inside & (nearest == k) & (j >= 0) & (j < nx)
        jj = np.clip(j, 0, nx - 1)
        for name, target in (("px_", px), ("py_", py), ("state_", st)):
            v = fields[name + bound][sel][order]
            target[ok] = v[jj[ok]]
    return px, py, st


def draw_traction(ax, x, y, px, py, st, title, vmax):
    """|p| as colour, a coarse arrow field, and the adhesion/slip boundary."""
    contact = st > 0
    mag = np.ma.masked_where(~contact, np.hypot(px, py))
    cmap = plt.get_cmap("magma_r").copy()
    cmap.set_bad("white")
    ax.pcolormesh(y[:, 0], x[0, :], mag.T, cmap=cmap, vmin=0, vmax=vmax, shading="nearest")
    ax.contour(y[:, 0], x[0, :], (st == 1).astype(float).T, levels=[0.5], colors="c",
               linewidths=1.2)
    step_y, step_x = max(1, y.shape[0] // 26), max(1, x.shape[1] // 10)
    sub = (slice(None, None, step_y), slice(None, None, step_x))
    m = contact[sub]
    ax.quiver(y[sub][m], x[sub][m], py[sub][m], px[sub][m], color="k", scale=6000,
              width=0.003)
    ax.set_title(title, fontsize=9)
    ax.set_xlim(-12.5, 13.5)
    ax.set_ylim(-5.5, 5.5)
    ax.set_aspect("equal")
    ax.set_xlabel("y (mm, CONTACT's contact-local)")
    ax.set_ylabel("x (mm, rolling)")


def exact_value(err, column):
    """The contact-exact row's value of a column of errors.csv."""
    return err[column][err["method"].tolist().index("contact-exact")]


def fig_tractions(ref_dir, tables, out):
    """Seed Fig. 5: traction magnitude, directions and stick/slip boundary of the headline case,
    the exact solution and FASTSIM_SH with each bound (recommended spin model and flexibility)."""
    g = reference_grid(os.path.join(ref_dir, "grid_module3_exact_nonhertz.csv"))
    fields = read_csv(os.path.join(tables, "fields_headline.csv"))
    err = read_csv(os.path.join(tables, "errors.csv"))
    vmax = 0.3 * 950.0
    fig, axes = plt.subplots(3, 2, figsize=(13, 11), constrained_layout=True)
    axes = axes.ravel()
    draw_traction(axes[0], g["x_mm"], g["y_mm"], g["px_MPa"], g["py_MPa"], g["igs"],
                  "CONTACT exact: f_x = %.3f, f_y = %.3f, adhesion %.0f %%"
                  % (exact_value(err, "headline_fx"), exact_value(err, "headline_fy"),
                     100 * exact_value(err, "headline_adhesion")), vmax)
    x = np.linspace(-5.5, 5.5, 221)
    y = np.linspace(-12.5, 13.5, 261)
    Y, X = np.meshgrid(y, x, indexing="ij")
    for ax, bound in zip(axes[1:], BOUNDS):
        px, py, st = resample_fields(fields, bound, X, Y)
        k = [i for i in range(len(err["method"]))
             if err["method"][i] == "fastsim-sh" and err["normal"][i] == "local-hertz"
             and err["bound"][i] == bound and err["spin_model"][i] == DEFAULT_SPIN
             and err["spin_flexibility"][i] == "longitudinal"][0]
        draw_traction(ax, X, Y, px, py, st,
                      "FASTSIM_SH %s: f_x = %.3f, f_y = %.3f, adhesion %.0f %%"
                      % (BOUND_LABELS[bound], err["headline_fx"][k], err["headline_fy"][k],
                         100 * err["headline_adhesion"][k]), vmax)
    sm = plt.cm.ScalarMappable(cmap="magma_r", norm=plt.Normalize(0, vmax))
    fig.colorbar(sm, ax=axes, label="|p_t| (MPa), tractions on the rail", shrink=0.5)
    fig.suptitle("Headline case: ξ = 0.58 ‰, η = 0.061 ‰, φ = 0.274 1/m at the geometric point "
                 "(y = 2.845 mm); FASTSIM_SH with spin model uniform, spin flexibility "
                 "longitudinal, local-Hertz normal\narrows: tangential traction on the rail; "
                 "cyan line: adhesion/slip boundary (adhesion towards the leading edge, +x)",
                 fontsize=10)
    fig.savefig(os.path.join(out, "fig5_tractions.png"), dpi=100)
    plt.close(fig)


def sweep_axes(ax, xs, sweep, ref_hertz, comp, show_bounds=True):
    """One panel of a sweep: exact, FASTSIM_SH per bound (recommended spin model), classical
    FASTSIM on the Hertz ellipse, CONTACT's FASTSIM."""
    ax.plot(xs, sweep[comp + "_exact"], "ko-", ms=3, lw=1.5, label="CONTACT exact (non-Hertzian)")
    if show_bounds:
        for b in BOUNDS:
            key = "%s_%s_%s" % (comp, b, DEFAULT_SPIN)
            lw = 2.2 if b == DEFAULT_BOUND else 1.0
            ax.plot(xs, sweep[key], color=COLOURS[b], lw=lw,
                    label="FASTSIM_SH %s, %s" % (BOUND_LABELS[b], DEFAULT_SPIN))
    ax.plot(xs, sweep[comp + "_fastsim_ellipsoidal"], color="grey", ls="--", lw=1.2,
            label="FASTSIM, Hertz ellipse (ellipsoidal)")
    ax.plot(xs, sweep[comp + "_fastsim_parabolic"], color="grey", ls="-.", lw=1.0,
            label="FASTSIM, Hertz ellipse (parabolic)")
    ax.plot(xs, sweep[comp + "_contact_fastsim_nonhertz"], color="k", ls=":", lw=1.0,
            label="CONTACT FASTSIM, exact pressure")
    if ref_hertz is not None:
        ax.plot(xs, ref_hertz[comp], color="silver", ls="-", lw=3, alpha=0.6, zorder=0,
                label="CONTACT exact on the Hertz ellipse")
    ax.grid(alpha=0.3)
    ax.set_ylabel("%s = F_%s/(μ F_n), on the rail" % ("f_" + comp[1], comp[1]))


def fig_spin(ref_dir, tables, out):
    """Seed Fig. 6: pure spin (xi = eta = 0)."""
    fig, axes = plt.subplots(2, 2, figsize=(13, 9), constrained_layout=True)
    for col, name in enumerate(["sweep_spin_0to2", "sweep_spin_0to5"]):
        sweep = read_csv(os.path.join(tables, name + ".csv"))
        hertz = read_csv(os.path.join(ref_dir, name + "_exact_hertz.csv"))
        for row, comp in enumerate(["fx", "fy"]):
            ax = axes[row, col]
            sweep_axes(ax, sweep["phi_1_per_m"], sweep, hertz, comp)
            ax.set_xlabel("spin φ (1/m), spin centre at the geometric point")
    axes[0, 0].legend(fontsize=7, loc="center right")
    fig.suptitle("Pure spin, S1002/UIC60 1:40, Y_WS = 0, F_n = 64.7 kN, μ = 0.3")
    fig.savefig(os.path.join(out, "fig6_spin_sweeps.png"), dpi=100)
    plt.close(fig)


def fig_creep(ref_dir, tables, out):
    """Seed Fig. 7: pure creepage (xi = eta, phi = 0)."""
    sweep = read_csv(os.path.join(tables, "sweep_creep_0to2permille.csv"))
    hertz = read_csv(os.path.join(ref_dir, "sweep_creep_0to2permille_exact_hertz.csv"))
    fig, axes = plt.subplots(1, 2, figsize=(13, 5), constrained_layout=True)
    for ax, comp in zip(axes, ["fx", "fy"]):
        sweep_axes(ax, 1e3 * sweep["nux"], sweep, hertz, comp)
        ax.set_xlabel("creepage ξ = η (‰), φ = 0")
    axes[0].legend(fontsize=7, loc="upper right")
    fig.suptitle("Pure creepage, S1002/UIC60 1:40, Y_WS = 0, F_n = 64.7 kN, μ = 0.3")
    fig.savefig(os.path.join(out, "fig7_creep_sweep.png"), dpi=100)
    plt.close(fig)


def fig_cdf(tables, out):
    """Seed Fig. 9: cumulative distribution of |Δf_x|, |Δf_y| over the 10³ DOE."""
    cdf = read_csv(os.path.join(tables, "doe_cdf.csv"))
    q = cdf["q"]
    fig, axes = plt.subplots(2, 2, figsize=(13, 9), constrained_layout=True)
    for col, comp in enumerate(["dfx", "dfy"]):
        ax = axes[0, col]
        for b in BOUNDS:
            lw = 2.2 if b == DEFAULT_BOUND else 1.0
            ax.step(cdf["%s_%s_%s" % (comp, b, DEFAULT_SPIN)], q, where="post",
                    color=COLOURS[b], lw=lw, label="%s, %s" % (BOUND_LABELS[b], DEFAULT_SPIN))
        ax.set_title("|Δ%s| per traction bound (spin model %s)" % (comp[1:], DEFAULT_SPIN))
        ax = axes[1, col]
        for s in SPIN_MODELS:
            lw = 2.2 if s == DEFAULT_SPIN else 1.0
            ax.step(cdf["%s_%s_%s" % (comp, DEFAULT_BOUND, s)], q, where="post",
                    color=COLOURS[s], lw=lw, label="%s, %s" % (BOUND_LABELS[DEFAULT_BOUND], s))
        ax.set_title("|Δ%s| per spin model (bound %s)" % (comp[1:], BOUND_LABELS[DEFAULT_BOUND]))
        for ax in axes[:, col]:
            ax.step(cdf[comp + "_fastsim_ellipsoidal"], q, where="post", color="grey", ls="--",
                    label="FASTSIM, Hertz ellipse (ellipsoidal)")
            ax.step(cdf[comp + "_contact_fastsim_nonhertz"], q, where="post", color="k", ls=":",
                    label="CONTACT FASTSIM, exact pressure")
            ax.axvline(0.04, color="r", lw=0.8, ls="--")
            ax.axvline(0.1, color="r", lw=0.8)
            ax.axhline(0.8, color="r", lw=0.6, ls=":")
            ax.set_xlim(0, 0.32)
            ax.set_ylim(0, 1.01)
            ax.set_xlabel("|Δf_%s| = |f_%s − f_%s,exact| (absolute, μF_n-normalised)"
                          % (comp[2], comp[2], comp[2]))
            ax.set_ylabel("fraction of the 1000 DOE cases")
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7, loc="lower right")
    fig.suptitle("DOE 10×10×10 (ξ, η ∈ [0, 2] ‰, φ ∈ [0, 2] 1/m), errors against CONTACT exact; "
                 "red: 0.04, 0.1 and the 80th percentile")
    fig.savefig(os.path.join(out, "fig9_doe_cdf.png"), dpi=100)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    data = os.environ.get("SHCONTACT_EXTERNAL_DATA") or "../shared"
    parser.add_argument("--reference", default=os.path.join(data, "reference"),
                        help="exact-theory reference folder (default $SHCONTACT_EXTERNAL_DATA/"
                        "reference, ../shared/reference without it; doc/install.md)")
    parser.add_argument("--tables", default="doc/validation",
                        help="tables of the validation program (default doc/validation)")
    parser.add_argument("--figures", default="doc/figures",
                        help="output folder for the PNG files (default doc/figures)")
    args = parser.parse_args()
    ref_dir = os.path.join(args.reference, "ty0_literal")
    if not os.path.isfile(os.path.join(ref_dir, "summary.csv")):
        print("validation_figures: the reference %s is absent; no figures drawn" % ref_dir)
        return 0
    if not os.path.isfile(os.path.join(args.tables, "errors.csv")):
        print("validation_figures: no tables in %s; run `fpm run --example shcontact-validate "
              "--profile release` first" % args.tables)
        return 1
    os.makedirs(args.figures, exist_ok=True)
    fig_normal(ref_dir, args.tables, args.figures)
    fig_tractions(ref_dir, args.tables, args.figures)
    fig_spin(ref_dir, args.tables, args.figures)
    fig_creep(ref_dir, args.tables, args.figures)
    fig_cdf(args.tables, args.figures)
    print("validation_figures: figures written to %s" % args.figures)
    return 0


if __name__ == "__main__":
    sys.exit(main())
