#!/usr/bin/python3
"""Plots a comminute time series (timeseries.csv) into one PNG with three panels:
energies (J) against time, contact and particle counts, and the force on every wall (N).

usage: scripts/plot_timeseries.py output/timeseries.csv [-o timeseries.png]
(default output: timeseries.png next to the CSV)"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        sys.exit(f"{path}: empty file")
    header = rows[0]
    data = {name: [] for name in header}
    for r in rows[1:]:
        if len(r) != len(header):  # a run killed mid-row leaves a partial last line
            continue
        for name, value in zip(header, r):
            data[name].append(float(value))
    return header, data


def walls(header):
    """Wall names, from the '<name>_Fx [N]' columns, in file order."""
    return [h[: -len("_Fx [N]")] for h in header if h.endswith("_Fx [N]")]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv")
    ap.add_argument("-o", "--output")
    args = ap.parse_args()
    header, d = read(args.csv)
    out = args.output or os.path.join(os.path.dirname(os.path.abspath(args.csv)), "timeseries.png")
    t = d["time [s]"]
    if not t:
        sys.exit(f"{args.csv}: no rows yet")

    names = walls(header)
    fig, axes = plt.subplots(3 if names else 2, 1, figsize=(10, 11 if names else 7.5), sharex=True)
    ax = axes[0]
    pot0 = d["potential_gravity [J]"][0]
    bal0 = d["energy_balance [J]"][0]
    curves = [
        ("kinetic_translational [J]", "kinetic, translational", "-"),
        ("kinetic_rotational [J]", "kinetic, rotational", "-"),
        ("elastic [J]", "elastic (in contacts)", "-"),
        ("dissipated_damping [J]", "dissipated by damping (cumulative)", "--"),
        ("dissipated_friction [J]", "dissipated by friction (cumulative)", "--"),
        ("energy_removed [J]", "removed by modules (cumulative)", ":"),
        ("wall_work [J]", "work of moving walls (cumulative)", ":"),
    ]
    for col, label, style in curves:
        if any(v != 0 for v in d[col]):
            ax.plot(t, d[col], style, label=label)
    ax.plot(t, [p - pot0 for p in d["potential_gravity [J]"]], "-", label="potential (change since start)")
    ax.plot(t, [b - bal0 for b in d["energy_balance [J]"]], "k-", lw=2.5, alpha=0.5,
            label="energy balance drift (0 = all energy accounted)")
    ax.set_ylabel("energy [J]")
    ax.set_title(f"Energies — {os.path.basename(args.csv)}")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="best")

    ax = axes[1]
    ax.plot(t, d["contacts [-]"], label="particle–particle contacts")
    ax.plot(t, d["wall_contacts [-]"], label="particle–wall contacts")
    ax.set_ylabel("contacts [-]")
    ax2 = ax.twinx()
    ax2.plot(t, d["particles [-]"], "k:", label="particles (right axis)")
    ax2.set_ylabel("particles [-]")
    ax2.set_ylim(bottom=0)
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, fontsize=8, loc="center right")
    ax.grid(alpha=0.3)
    ax.set_title("Contacts and particles")

    if names:
        ax = axes[2]
        colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
        for k, w in enumerate(names):
            c = colours[k % len(colours)]
            for axis, style in (("z", "-"), ("x", "--"), ("y", ":")):
                ax.plot(t, d[f"{w}_F{axis} [N]"], style, color=c, label=f"{w} F{axis}")
        ax.set_ylabel("force on wall [N]")
        ax.set_title("Forces exerted by the particles on the walls")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, ncol=max(1, len(names)), loc="best")
    axes[-1].set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(out)


if __name__ == "__main__":
    main()
