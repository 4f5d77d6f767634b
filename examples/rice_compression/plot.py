#!/usr/bin/python3
"""Plots of the rice confined-compression rig (examples/rice_compression).

Usage: /usr/bin/python3 plot.py OUTPUT_DIR   (the run's [output] directory)
Reads wall_control.csv, bed.csv, grains.csv, grain_breakage.csv, bonds.csv and fragments.csv by
column name, prints the breakage probability per layer at 2, 3, 4, 5 and 6 MPa and writes
rice_compression.png into OUTPUT_DIR. Columns are found by header name. A grain counts as broken at stress S when it broke before
the piston stress first reached S (the load only grows, so a run stopped at S is this run up to
that moment).
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LEVELS = [2e6, 3e6, 4e6, 5e6, 6e6]  # Pa


def read(path):
    """Columns of a CSV file by header name (the unit in brackets dropped)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    names = [h.split(" [")[0] for h in rows[0]]
    cols = {n: [] for n in names}
    for r in rows[1:]:
        if len(r) != len(names):
            continue
        for n, v in zip(names, r):
            try:
                cols[n].append(float(v))
            except ValueError:
                cols[n].append(v)
    return cols


def first_time_at(times, stress, level):
    for t, s in zip(times, stress):
        if s >= level:
            return t
    return None


def main(out):
    wc = read(os.path.join(out, "wall_control.csv"))
    bed = read(os.path.join(out, "bed.csv"))
    grains = read(os.path.join(out, "grains.csv"))
    events = read(os.path.join(out, "grain_breakage.csv"))
    bonds = read(os.path.join(out, "bonds.csv"))
    frags = read(os.path.join(out, "fragments.csv"))
    layers = sorted(set(int(v) for v in grains["layer"]))
    per_layer = {l: sum(1 for v in grains["layer"] if int(v) == l) for l in layers}

    fig, ax = plt.subplots(2, 3, figsize=(15, 9))
    a = ax[0][0]
    # from first contact (force above 1 N): the approach before it carries no force
    d0 = next((d for d, f in zip(wc["piston_displacement"], wc["piston_force"]) if f > 1.0), 0.0)
    pts = [(1e3 * (d - d0), f) for d, f in zip(wc["piston_displacement"], wc["piston_force"]) if d >= d0]
    a.plot([p for p, _ in pts], [f for _, f in pts], lw=1)
    a.set_xlabel("piston displacement from first contact [mm]")
    a.set_ylabel("piston force [N]")
    a.set_title("force-displacement")

    a = ax[0][1]
    print("breakage probability per layer (layer 1 at the bottom)")
    print("stress [MPa]  " + "  ".join(f"layer{l}" for l in layers) + "  all   void_ratio")
    for level in LEVELS:
        # bed.csv's stress is |F| / area, the quantity the [[stop]] condition compares
        t = first_time_at(bed["time"], bed["axial_stress"], level)
        if t is None:
            continue
        p = []
        for l in layers:
            n = sum(1 for tt, ll in zip(events["time"], events["layer"]) if int(ll) == l and tt <= t)
            p.append(n / per_layer[l])
        total = sum(1 for tt in events["time"] if tt <= t) / len(grains["grain"])
        e = bed["void_ratio"][bed["time"].index(t)]
        print(f"{level / 1e6:12.0f}  " + "  ".join(f"{v:6.2f}" for v in p) + f"  {total:.2f}  {e:.3f}")
        a.plot(p, layers, "o-", label=f"{level / 1e6:.0f} MPa")
    a.set_xlabel("breakage probability [-]")
    a.set_ylabel("layer (1 = bottom)")
    a.set_xlim(0, 1)
    a.legend()
    a.set_title("breakage per layer")

    a = ax[0][2]
    modes = ["end_chipping", "central", "split"]
    width = 0.25
    for k, m in enumerate(modes):
        counts = [sum(1 for mm, ll in zip(events["mode"], events["layer"]) if mm == m and int(ll) == l)
                  for l in layers]
        a.bar([l + (k - 1) * width for l in layers], counts, width, label=m)
    a.set_xlabel("layer")
    a.set_ylabel("broken grains [-]")
    a.legend()
    a.set_title("breakage modes (end of run)")

    a = ax[1][0]
    t, share = [], []
    for tt, nt, ns in zip(bonds["time"], bonds["failed_tensile"], bonds["failed_shear"]):
        if nt + ns > 0:
            t.append(1e3 * tt)
            share.append(nt / (nt + ns))
    a.plot(t, share, label="tensile")
    a.plot(t, [1 - s for s in share], label="shear")
    a.set_ylim(0, 1)
    a.set_xlabel("time [ms]")
    a.set_ylabel("share of failed bonds [-]")
    a.legend()
    a.set_title("tensile / shear failures")

    a = ax[1][1]
    s = [(st, e) for st, e in zip(bed["axial_stress"], bed["void_ratio"]) if st > 1e4]
    a.semilogx([st / 1e6 for st, _ in s], [e for _, e in s], ".-")
    a.set_xlabel("axial stress [MPa]")
    a.set_ylabel("void ratio [-]")
    a.set_title("normal compression line")

    a = ax[1][2]
    d = sorted(1e3 * v for v in frags["equivalent_diameter"])
    m = [v for _, v in sorted(zip(frags["equivalent_diameter"], frags["mass"]))]
    total, acc, cum = sum(m), 0.0, []
    for v in m:
        acc += v
        cum.append(acc / total)
    a.step(d, cum, where="post")
    a.set_xlabel("fragment equivalent diameter [mm]")
    a.set_ylabel("cumulative mass fraction [-]")
    a.set_title("fragment sizes (end of run)")

    fig.tight_layout()
    png = os.path.join(out, "rice_compression.png")
    fig.savefig(png, dpi=100)
    print("wrote", png)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "output")
