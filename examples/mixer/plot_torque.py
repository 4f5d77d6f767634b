#!/usr/bin/python3
"""Plots the shaft torque and power of the mixer sector runs against time, one curve per run,
for the whole vessel (the sector's blades + shaft columns <wall>_Tz [N m] and <wall>_P [W], times
the sector count n), and prints their means over the second half of each run.

usage: examples/mixer/plot_torque.py RUN/timeseries.csv [more.csv ...] [-o torque.png]
       [--walls blades shaft] [-n 3]
(default output: torque.png next to the first CSV)"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path, walls, n):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if len(rows) < 3:
        sys.exit(f"{path}: fewer than two rows")
    header = rows[0]
    cols = ["time [s]"] + [f"{w}_Tz [N m]" for w in walls] + [f"{w}_P [W]" for w in walls]
    for c in cols:
        if c not in header:
            sys.exit(f"{path}: no column '{c}'")
    idx = [header.index(c) for c in cols]
    t, torque, power = [], [], []
    k = len(walls)
    for r in rows[1:]:
        if len(r) != len(header):
            continue
        v = [float(r[i]) for i in idx]
        t.append(v[0])
        # the particles' torque on the shaft is -(drive torque): report the drive's, positive
        torque.append(-n * sum(v[1 : 1 + k]))
        power.append(n * sum(v[1 + k :]))
    return t, torque, power


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv", nargs="+")
    ap.add_argument("-o", "--output")
    ap.add_argument("--walls", nargs="+", default=["blades", "shaft"])
    ap.add_argument("-n", type=int, default=3, help="sectors in the whole vessel")
    args = ap.parse_args()
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(9, 7), sharex=True)
    for path in args.csv:
        t, torque, power = read(path, args.walls, args.n)
        label = os.path.basename(os.path.dirname(os.path.abspath(path)))
        half = [i for i, x in enumerate(t) if x >= t[-1] / 2]
        mt = sum(torque[i] for i in half) / len(half)
        mp = sum(power[i] for i in half) / len(half)
        print(f"{label}: mean over t >= {t[-1] / 2:.3g} s: torque {mt:.4g} N m, power {mp:.4g} W "
              f"(whole vessel, {len(half)} rows)")
        a1.plot(t, torque, lw=0.8, label=f"{label} (mean {mt:.3g} N m)")
        a2.plot(t, power, lw=0.8, label=f"{label} (mean {mp:.3g} W)")
    a1.set_ylabel("shaft torque, whole vessel [N m]")
    a2.set_ylabel("shaft power, whole vessel [W]")
    a2.set_xlabel("time [s]")
    for a in (a1, a2):
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.tight_layout()
    out = args.output or os.path.join(os.path.dirname(os.path.abspath(args.csv[0])), "torque.png")
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
