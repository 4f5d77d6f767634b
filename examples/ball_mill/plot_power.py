#!/usr/bin/python3
"""Plots the shaft power of the ball-mill rig (column mill_P [W] of timeseries.csv) against time,
with its running mean over 0.25 s and the mean over the second half of the run (steady state).

usage: examples/ball_mill/plot_power.py output/timeseries.csv [-o power.png] [--wall mill]
(default output: power.png next to the CSV)"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv")
    ap.add_argument("-o", "--output")
    ap.add_argument("--wall", default="mill")
    args = ap.parse_args()
    with open(args.csv, newline="") as f:
        rows = list(csv.reader(f))
    if len(rows) < 3:
        sys.exit(f"{args.csv}: fewer than two rows")
    header = rows[0]
    col = f"{args.wall}_P [W]"
    if col not in header:
        sys.exit(f"{args.csv}: no column '{col}'")
    it, ip = header.index("time [s]"), header.index(col)
    data = [(float(r[it]), float(r[ip])) for r in rows[1:] if len(r) == len(header)]
    t = [a for a, _ in data]
    p = [b for _, b in data]
    dt = (t[-1] - t[0]) / max(1, len(t) - 1)
    k = max(1, int(round(0.25 / dt)))
    running = [sum(p[max(0, i - k + 1) : i + 1]) / (i + 1 - max(0, i - k + 1)) for i in range(len(p))]
    half = [b for a, b in data if a >= t[-1] / 2]
    mean = sum(half) / len(half)
    print(f"mean shaft power over t >= {t[-1] / 2:.3g} s: {mean:.4g} W ({len(half)} rows)")
    out = args.output or os.path.join(os.path.dirname(os.path.abspath(args.csv)), "power.png")
    fig, ax = plt.subplots(figsize=(9, 5))
    ax.plot(t, p, lw=0.6, color="0.6", label="shaft power (sampled)")
    ax.plot(t, running, lw=1.6, label="running mean, 0.25 s")
    ax.axhline(mean, ls="--", color="k", label=f"mean over second half: {mean:.3g} W")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("shaft power [W]")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
