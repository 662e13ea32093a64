#!/usr/bin/env python3
"""Plot a run of examples/vehicle/wheelset.f: lateral shift, yaw angle and lateral contact forces.

    python3 examples/vehicle/plot_wheelset.py wheelset.csv [-o wheelset.png] [--title TEXT]

Needs numpy and matplotlib (scripts/setup --plot).
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", help="the CSV written by the vehicle example")
    parser.add_argument("-o", "--output", default="wheelset.png", help="PNG file")
    parser.add_argument("--title", default="", help="figure title")
    args = parser.parse_args()

    data = np.genfromtxt(args.csv, delimiter=",", names=True)
    t = data["t_s"]
    fig, axes = plt.subplots(3, 1, figsize=(9, 8), sharex=True)
    axes[0].plot(t, data["y_mm"], lw=0.8)
    axes[0].set_ylabel("lateral shift y (mm)")
    axes[1].plot(t, data["yaw_mrad"], lw=0.8, color="tab:orange")
    axes[1].set_ylabel("yaw angle (mrad)")
    axes[2].plot(t, data["fy_right_N"] / 1e3, lw=0.8, label="right wheel")
    axes[2].plot(t, data["fy_left_N"] / 1e3, lw=0.8, label="left wheel")
    axes[2].plot(t, data["fy_total_N"] / 1e3, lw=0.8, color="k", label="total")
    axes[2].set_ylabel("lateral force on wheel,\ntrack frame (kN)")
    axes[2].set_xlabel("time (s)")
    axes[2].legend(loc="upper right", fontsize=8)
    for ax in axes:
        ax.grid(True, lw=0.3)
    if args.title:
        fig.suptitle(args.title, fontsize=10)
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
