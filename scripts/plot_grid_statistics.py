#!/usr/bin/python3
"""Draws the stress map of a comminute grid_statistics.csv into one PNG: the mean stress and the
largest shear stress (Pa) per cell, averaged over the grid's second direction (a box: y, shown in
x–z; a cylinder: theta, shown in r–axial), and for a cylinder the mean stress over its cross-section
(r–theta, averaged along the axis). Columns are found by their headers.

usage: scripts/plot_grid_statistics.py output/grid_statistics.csv [-o grid_statistics.png]
(default output: grid_statistics.png next to the CSV)"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        sys.exit(f"{path}: no cells")
    header = rows[0]
    cols = {name: np.array([float(r[k]) for r in rows[1:] if len(r) == len(header)])
            for k, name in enumerate(header)}
    return cols


def column(cols, *names):
    for n in names:
        if n in cols:
            return cols[n]
    sys.exit(f"none of the columns {names} is in the file")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv")
    ap.add_argument("-o", "--output")
    args = ap.parse_args()
    cols = read(args.csv)
    cylinder = "centre_r [m]" in cols
    i = column(cols, "i [-]").astype(int)
    k = column(cols, "k [-]").astype(int)
    a = column(cols, "centre_r [m]", "centre_x [m]")
    c = column(cols, "centre_axial [m]", "centre_z [m]")
    ni, nk = i.max() + 1, k.max() + 1
    ax_a = np.array([a[i == m][0] for m in range(ni)])
    ax_c = np.array([c[k == m][0] for m in range(nk)])
    fig = plt.figure(figsize=(16 if cylinder else 11, 4.5))
    n = 3 if cylinder else 2
    axes = [fig.add_subplot(1, n, 1), fig.add_subplot(1, n, 2)]
    if cylinder:
        j = column(cols, "j [-]").astype(int)
        nj = j.max() + 1
        theta = np.array([column(cols, "centre_theta [rad]")[j == m][0] for m in range(nj)])
        v = column(cols, "mean_stress [Pa]")
        polar = np.array([[v[(i == m) & (j == q)].mean() for q in range(nj)] for m in range(ni)])
        ax = fig.add_subplot(1, n, 3, projection="polar")
        ax.grid(False)
        pc = ax.pcolormesh(theta, ax_a, polar, shading="nearest", cmap="coolwarm")
        fig.colorbar(pc, ax=ax)
        ax.set_title("mean stress σm over the cross-section (Pa)")
    for ax, name, title in zip(axes, ["mean_stress [Pa]", "tau_max [Pa]"],
                               ["mean stress σm (Pa, tension > 0)", "largest shear τmax (Pa)"]):
        v = column(cols, name)
        grid = np.zeros((nk, ni))
        for m in range(ni):
            for n in range(nk):
                sel = (i == m) & (k == n)
                grid[n, m] = v[sel].mean()
        pc = ax.pcolormesh(ax_a, ax_c, grid, shading="nearest",
                           cmap="viridis" if "tau" in name else "coolwarm")
        fig.colorbar(pc, ax=ax)
        ax.set_title(title)
        ax.set_xlabel("r (m)" if cylinder else "x (m)")
        ax.set_ylabel("axial (m)" if cylinder else "z (m)")
        ax.set_aspect("equal")
    fig.tight_layout()
    out = args.output or os.path.join(os.path.dirname(os.path.abspath(args.csv)),
                                      "grid_statistics.png")
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
