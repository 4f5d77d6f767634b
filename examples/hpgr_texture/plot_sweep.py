#!/usr/bin/python3
"""Plots the HPGR texture study (sweep.py) with all cases on one figure each:
product_size.png (mass passing of the product, outlet "product", from outlet_log.csv),
liberation_matrix.png (degree of liberation of the matrix in the product vs time, all sizes,
from liberation.csv) and recovery.png (recovery of the target against recovery of the gangue
under ideal separation of the product, from grade_recovery.csv, latest sample). Prints per case
the product mass, its median size and the final liberation of the matrix.

usage: examples/hpgr_texture/plot_sweep.py OUT [--outlet product] [--matrix matrix]
       [--threshold 95] (OUT: the folder of sweep.py; figures written there)"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from machine_plots import column, mass_passing, read  # noqa: E402


def case_folders(out):
    """Case name -> output folder, in the order the sweep writes them (frel by value, controls)."""
    names = [n for n in os.listdir(out) if os.path.isdir(os.path.join(out, n, "output"))]
    key = lambda n: (n.startswith("homogeneous"), float(n.split("_")[1]))  # noqa: E731
    return [(n, os.path.join(out, n, "output")) for n in sorted(names, key=key)]


def product(folder, outlet):
    path = os.path.join(folder, "outlet_log.csv")
    if not os.path.exists(path):
        return []
    rows = [r for r in read(path) if r["outlet [-]"] == outlet]
    return list(zip(column(rows, "diameter [m]", path), column(rows, "mass [kg]", path))) \
        if rows else []


def matrix_liberation(folder, phase, threshold):
    """(times, degree) of the all-sizes rows of phase `phase` (the widest size span per time)."""
    path = os.path.join(folder, "liberation.csv")
    if not os.path.exists(path):
        return [], []
    best = {}
    for r in read(path):
        if r["phase [-]"] != phase:
            continue
        t = float(r["time [s]"])
        span = float(r["size_upper [m]"]) - float(r["size_lower [m]"])
        if t not in best or span > best[t][0]:
            best[t] = (span, float(r[f"liberation_{threshold} [-]"]))
    times = sorted(best)
    return times, [best[t][1] for t in times]


def recovery(folder):
    """(gangue recovery, target recovery) of the latest grade-recovery curve."""
    path = os.path.join(folder, "grade_recovery.csv")
    if not os.path.exists(path):
        return [], []
    rows = read(path)
    if not rows:
        return [], []
    y = column(rows, "yield [-]", path)
    g = column(rows, "grade [-]", path)
    rec = column(rows, "recovery [-]", path)
    feed = g[y.index(max(y))]  # grade of the whole stream (yield 1)
    gangue = [yi * (1 - gi) / (1 - feed) for yi, gi in zip(y, g)] if feed < 1 else y
    return [0.0] + gangue, [0.0] + rec


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--outlet", default="product")
    ap.add_argument("--matrix", default="matrix", help="name of the matrix phase")
    ap.add_argument("--threshold", default="95", choices=["100", "95", "90"])
    args = ap.parse_args()
    cases = case_folders(args.out)
    if not cases:
        sys.exit(f"{args.out}: no case outputs (run sweep.py first)")
    sieves = [0.006 * 2 ** (k / 4) for k in range(0, 15)]
    figs = {k: plt.subplots(figsize=(7, 5)) for k in ("size", "lib", "rec")}
    for name, folder in cases:
        style = dict(ls="--" if name.startswith("homogeneous") else "-", lw=1.3, label=name)
        prod = product(folder, args.outlet)
        if prod:
            figs["size"][1].plot([1000 * s for s in sieves], mass_passing(prod, sieves), **style)
        t, lib = matrix_liberation(folder, args.matrix, args.threshold)
        if t:
            figs["lib"][1].plot(t, [100 * x for x in lib], **style)
        gangue, target = recovery(folder)
        if gangue:
            figs["rec"][1].plot([100 * x for x in gangue], [100 * x for x in target], **style)
        mass = sum(m for _, m in prod)
        d50 = next((s for s, p in zip(sieves, mass_passing(prod, sieves)) if p >= 50), float("nan")) \
            if prod else float("nan")
        print(f"{name}: product {len(prod)} particles, {mass:.4g} kg, d50 <= {1000 * d50:.3g} mm; "
              f"matrix liberation ({args.threshold} %) at the end "
              f"{100 * lib[-1] if lib else float('nan'):.3g} %")
    ax = figs["size"][1]
    ax.set_xscale("log")
    ax.set_xlabel("size [mm]")
    ax.set_ylabel("product mass passing [%]")
    ax = figs["lib"][1]
    ax.set_xlabel("time [s]")
    ax.set_ylabel(f"liberation of the {args.matrix} in the product ({args.threshold} %) [%]")
    ax = figs["rec"][1]
    ax.plot([0, 100], [0, 100], color="0.6", lw=0.8, label="no separation")
    ax.set_xlabel("recovery of gangue [%]")
    ax.set_ylabel("recovery of target [%]")
    for key, fname in (("size", "product_size.png"), ("lib", "liberation_matrix.png"),
                       ("rec", "recovery.png")):
        fig, ax = figs[key]
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(args.out, fname), dpi=120)
        print(f"wrote {os.path.join(args.out, fname)}")


if __name__ == "__main__":
    main()
