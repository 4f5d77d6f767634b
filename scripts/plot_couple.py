#!/usr/bin/python3
"""Plots of a `comminute couple` chain (matplotlib, Debian python3). Columns are found by header.

usage: plot_couple.py COUPLE_DIR DEM_DIR PBM_DIR
writes into COUPLE_DIR:
  power.png          wall power (every `<wall>_P [W]`) and kinetic energy against time, the
                     collision log's steady-state window shaded (from couple.csv)
  spectra.png        cumulative collision frequency above an energy, per contact type
                     (DEM_DIR/collision_spectrum_<type>.csv), when the DEM case has [collisions]
  stress_map.png     the grid statistics' stress map (scripts/plot_grid_statistics.py), when the
                     DEM case has [grid_statistics]
  distributions.png  cumulative mass passing against size at each output time (PBM_DIR)
  fit.png            measured against simulated cumulative passing, when the pbm case was
                     calibrated (PBM_DIR/fit.csv)
"""
import csv
import glob
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return {k: [r[k] for r in rows] for k in rows[0]} if rows else {}


def numbers(col):
    return [float(v) for v in col]


def save(fig, ax, xlabel, ylabel, title, path):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def window(couple_dir):
    path = os.path.join(couple_dir, "couple.csv")
    if not os.path.exists(path):
        return None
    t = read(path)
    q = dict(zip(t["quantity [-]"], t["value [-]"]))
    start, length = float(q.get("window_start", -1)), float(q.get("window_length", 0))
    return (start, start + length) if start >= 0 else None


def plot_power(couple_dir, dem_dir):
    path = os.path.join(dem_dir, "timeseries.csv")
    if not os.path.exists(path):
        return
    t = read(path)
    time = numbers(t["time [s]"])
    fig, a1 = plt.subplots(figsize=(8, 4.2))
    for name in t:
        if name.endswith("_P [W]"):
            a1.plot(time, numbers(t[name]), label=name.replace(" [W]", ""))
    a1.set_xlabel("time (s)")
    a1.set_ylabel("power (W)")
    if "kinetic_translational [J]" in t:
        a2 = a1.twinx()
        ke = [a + b for a, b in zip(numbers(t["kinetic_translational [J]"]),
                                    numbers(t.get("kinetic_rotational [J]", ["0"] * len(time))))]
        a2.plot(time, ke, color="0.5", ls="--", label="kinetic energy")
        a2.set_ylabel("kinetic energy (J)")
        a2.legend(loc="lower right")
    w = window(couple_dir)
    if w:
        a1.axvspan(w[0], w[1], color="tab:green", alpha=0.15, label="steady-state window")
    a1.legend(loc="upper left")
    a1.set_title("DEM stage: power and kinetic energy")
    fig.tight_layout()
    fig.savefig(os.path.join(couple_dir, "power.png"), dpi=120)
    plt.close(fig)


def plot_spectra(couple_dir, dem_dir):
    files = sorted(glob.glob(os.path.join(dem_dir, "collision_spectrum_*.csv")))
    if not files:
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for path in files:
        name = os.path.basename(path)[len("collision_spectrum_"):-len(".csv")]
        t = read(path)
        if not t:
            continue
        e, f = numbers(t["energy_J"]), numbers(t["frequency_per_s"])
        above, cum = 0.0, []
        for v in reversed(f):  # collisions per second with an energy at least e
            above += v
            cum.append(above)
        cum.reverse()
        pts = [(a, b) for a, b in zip(e, cum) if b > 0]
        if pts:
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], label=name)
    save(fig, ax, "collision energy E (J)", "collisions per second with energy ≥ E (1/s)",
         "collision spectra by contact type (steady-state window)",
         os.path.join(couple_dir, "spectra.png"))


def plot_stress_map(couple_dir, dem_dir):
    grid = os.path.join(dem_dir, "grid_statistics.csv")
    if os.path.exists(grid):
        script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "plot_grid_statistics.py")
        subprocess.run([sys.executable, script, grid, "-o", os.path.join(couple_dir, "stress_map.png")],
                       check=True)


def plot_distributions(couple_dir, pbm_dir):
    path = os.path.join(pbm_dir, "distributions.csv")
    if not os.path.exists(path):
        return
    t = read(path)
    time, up, cum = numbers(t["time [s]"]), numbers(t["size_upper [m]"]), numbers(t["cumulative_mass [-]"])
    times = sorted(set(time))
    cmap = plt.get_cmap("viridis")
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for n, tt in enumerate(times):
        idx = [i for i, v in enumerate(time) if v == tt]
        ax.semilogx([up[i] * 1e6 for i in idx], [100 * cum[i] for i in idx],
                    color=cmap(n / max(1, len(times) - 1)), label=f"{tt:g} s")
    save(fig, ax, "size (µm)", "cumulative mass passing (%)",
         "population balance: size distribution against time",
         os.path.join(couple_dir, "distributions.png"))


def plot_fit(couple_dir, pbm_dir):
    path = os.path.join(pbm_dir, "fit.csv")
    if not os.path.exists(path):
        return
    t = read(path)
    ds, time = numbers(t["dataset [-]"]), numbers(t["time [s]"])
    size, meas, sim = numbers(t["size [m]"]), numbers(t["measured [-]"]), numbers(t["simulated [-]"])
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for n, d in enumerate(sorted(set(ds))):
        idx = [i for i, v in enumerate(ds) if v == d]
        c = plt.get_cmap("tab10")(n % 10)
        ax.semilogx([size[i] * 1e6 for i in idx], [100 * meas[i] for i in idx], "o", color=c,
                    label=f"measured, {time[idx[0]]:g} s")
        ax.semilogx([size[i] * 1e6 for i in idx], [100 * sim[i] for i in idx], "-", color=c,
                    label=f"fit, {time[idx[0]]:g} s")
    save(fig, ax, "size (µm)", "cumulative passing (%)", "calibration: fit against data",
         os.path.join(couple_dir, "fit.png"))


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    couple_dir, dem_dir, pbm_dir = sys.argv[1:]
    plot_power(couple_dir, dem_dir)
    plot_spectra(couple_dir, dem_dir)
    plot_stress_map(couple_dir, dem_dir)
    plot_distributions(couple_dir, pbm_dir)
    plot_fit(couple_dir, pbm_dir)


if __name__ == "__main__":
    main()
