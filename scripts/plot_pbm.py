#!/usr/bin/python3
"""Plots of `comminute pbm` and `comminute calibrate` outputs (matplotlib, Debian python3).

usage: plot_pbm.py pbm DIR        -> DIR/distributions.png, DIR/models.png
       plot_pbm.py calibrate DIR  -> DIR/fit.png
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    return {k: [float(r[k]) for r in rows] for k in rows[0]} if rows else {}


def by(col, key):
    groups = {}
    for i, v in enumerate(col[key]):
        groups.setdefault(v, []).append(i)
    return groups


def plot_pbm(d):
    t = read(f"{d}/distributions.csv")
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
    groups = by(t, "time [s]")
    cmap = plt.get_cmap("viridis")
    for n, (time, idx) in enumerate(sorted(groups.items())):
        c = cmap(n / max(1, len(groups) - 1))
        up = [t["size_upper [m]"][i] * 1e6 for i in idx]
        lo = [max(t["size_lower [m]"][i], 1e-300) for i in idx]
        a1.plot(up, [100 * t["cumulative_mass [-]"][i] for i in idx], color=c, label=f"{time:g} s")
        # mass density per unit ln d: q3,ln = mass fraction / ln(d_upper/d_lower)
        q3 = [t["mass_fraction [-]"][i] / math.log(t["size_upper [m]"][i] / lo[k])
              if t["size_lower [m]"][i] > 0 else float("nan") for k, i in enumerate(idx)]
        a2.plot([t["size_pivot [m]"][i] * 1e6 for i in idx], q3, color=c, label=f"{time:g} s")
    a1.set(xscale="log", xlabel="particle size (µm)", ylabel="cumulative mass passing (%)",
           title="Cumulative size distribution", ylim=(0, 100))
    a2.set(xscale="log", xlabel="particle size (µm)", ylabel="mass density per ln d (–)",
           title="Density distribution (mass)")
    for a in (a1, a2):
        a.grid(True, which="both", alpha=0.3)
    a1.legend(title="time", fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{d}/distributions.png", dpi=120)

    r = read(f"{d}/rates.csv")
    b = read(f"{d}/breakage_function.csv")
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
    pos = [i for i, v in enumerate(r["rate [1/s]"]) if v > 0]  # log axis: unbreakable classes left out
    a1.plot([r["size [m]"][i] * 1e6 for i in pos], [r["rate [1/s]"][i] for i in pos], "o-", ms=3)
    a1.set(xscale="log", yscale="log", xlabel="particle size (µm)",
           ylabel="breakage rate S (1/s)", title="Breakage rate")
    for parent, idx in sorted(by(b, "parent_size [m]").items(), reverse=True):
        a2.plot([b["size_ratio [-]"][i] for i in idx],
                [max(b["cumulative_mass_passing [-]"][i], 1e-12) for i in idx],
                label=f"parent {parent * 1e6:.3g} µm")
    a2.set(xscale="log", yscale="log", xlabel="fragment size / parent size d/D",
           ylabel="cumulative mass passing B", title="Breakage function", ylim=(1e-4, 1.5))
    a2.legend(fontsize=8)
    for a in (a1, a2):
        a.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(f"{d}/models.png", dpi=120)

    if os.path.exists(f"{d}/fracture_energy.csv"):  # UFRJ: weakening by damage
        fe = read(f"{d}/fracture_energy.csv")
        fig, ax = plt.subplots(figsize=(7, 4.2))
        groups = by(fe, "time [s]")
        for n, (time, idx) in enumerate(sorted(groups.items())):
            ax.plot([fe["size_pivot [m]"][i] * 1e6 for i in idx],
                    [fe["median_fracture_energy [J/kg]"][i] for i in idx],
                    color=cmap(n / max(1, len(groups) - 1)), label=f"{time:g} s")
        ax.set(xscale="log", yscale="log", xlabel="particle size (µm)",
               ylabel="median fracture energy (J/kg)",
               title="Fracture energy of the unbroken material")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(title="time", fontsize=8)
        fig.tight_layout()
        fig.savefig(f"{d}/fracture_energy.png", dpi=120)

    if os.path.exists(f"{d}/fracture_energy_distribution.csv"):  # UFRJ: the whole distribution
        fd = read(f"{d}/fracture_energy_distribution.csv")
        classes = sorted(set(fd["class [-]"]))
        picks = [classes[-1], classes[len(classes) // 2]]
        fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
        for ax, c in zip(axes, picks):
            rows = [i for i in range(len(fd["class [-]"])) if fd["class [-]"][i] == c]
            times = sorted({fd["time [s]"][i] for i in rows})
            for n, time in enumerate(times):
                idx = [i for i in rows if fd["time [s]"][i] == time]
                ax.plot([fd["energy_upper [J/kg]"][i] for i in idx],
                        [fd["cumulative_fraction [-]"][i] for i in idx],
                        color=cmap(n / max(1, len(times) - 1)), label=f"{time:g} s")
            size = fd["size_pivot [m]"][rows[0]] * 1e6
            ax.set(xscale="log", xlabel="fracture energy E (J/kg)", ylabel="fraction with E' ≤ E",
                   title=f"class {int(c)} ({size:.3g} µm), unbroken material")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(title="time", fontsize=8)
        fig.tight_layout()
        fig.savefig(f"{d}/fracture_energy_distribution.png", dpi=120)


def plot_calibrate(d):
    t = read(f"{d}/fit.csv")
    fig, ax = plt.subplots(figsize=(7, 4.5))
    cmap = plt.get_cmap("tab10")
    for n, (key, idx) in enumerate(sorted(by(t, "dataset [-]").items())):
        c = cmap(n % 10)
        time = t["time [s]"][idx[0]]
        x = [t["size [m]"][i] * 1e6 for i in idx]
        ax.plot(x, [100 * t["measured [-]"][i] for i in idx], "o", color=c,
                label=f"measured, set {int(key)}, {time:g} s")
        ax.plot(x, [100 * t["simulated [-]"][i] for i in idx], "-", color=c, label="fitted")
    ax.set(xscale="log", xlabel="particle size (µm)", ylabel="cumulative passing (%)",
           title="Calibration: fitted vs measured", ylim=(0, 100))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"{d}/fit.png", dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in ("pbm", "calibrate"):
        sys.exit(__doc__)
    {"pbm": plot_pbm, "calibrate": plot_calibrate}[sys.argv[1]](sys.argv[2])
