#!/usr/bin/python3
"""Steady-state drive torque and shaft power of mixer sector runs, with standard errors from
block averages.

The mean power over a window is taken from the cumulative work of the moving walls,
`wall_work [J]` of timeseries.csv (summed every step, so it is the exact time average, not a
mean of instantaneous samples): P = n ΔW / Δt for the whole vessel (n sectors). The window
[t0, t_end] is cut into B equal blocks; the block means P_b give the mean and its standard error
s(P_b) / sqrt(B) (block averaging, Flyvbjerg & Petersen, J. Chem. Phys. 91 (1989) 461). The
torque is P / ω, ω the shaft's angular velocity, found from the samples as Σ P_i / Σ (−T_z,i)
of the `blades` and `shaft` walls (exact for a rigid rotation at constant ω). The error is shown
for B = 4, 8 and 16: when it no longer grows with the block length, the blocks are independent.

usage: examples/mixer/steady_torque.py RUN/timeseries.csv [more.csv ...] [--t0 0.2] [-n 3]
"""
import argparse
import csv
import math
import os
import sys


def column(header, name, path):
    if name not in header:
        sys.exit(f"{path}: no column '{name}'")
    return header.index(name)


def analyse(path, t0, n, walls):
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f)]
    header = rows[0]
    it = column(header, "time [s]", path)
    iw = column(header, "wall_work [J]", path)
    ip = [column(header, f"{w}_P [W]", path) for w in walls]
    iz = [column(header, f"{w}_Tz [N m]", path) for w in walls]
    data = [r for r in rows[1:] if len(r) == len(header) and float(r[it]) >= t0]
    t = [float(r[it]) for r in data]
    work = [float(r[iw]) for r in data]
    p_sum = sum(sum(float(r[i]) for i in ip) for r in data)
    t_sum = sum(sum(-float(r[i]) for i in iz) for r in data)
    omega = p_sum / t_sum
    out = {}
    for blocks in (4, 8, 16):
        edges = [t[0] + (t[-1] - t[0]) * k / blocks for k in range(blocks + 1)]
        # the sample nearest each edge
        idx = [min(range(len(t)), key=lambda i: abs(t[i] - e)) for e in edges]
        means = [n * (work[idx[k + 1]] - work[idx[k]]) / (t[idx[k + 1]] - t[idx[k]])
                 for k in range(blocks)]
        m = sum(means) / blocks
        sd = math.sqrt(sum((x - m) ** 2 for x in means) / (blocks - 1))
        out[blocks] = (m, sd / math.sqrt(blocks))
    return t[0], t[-1], omega, out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv", nargs="+")
    ap.add_argument("--t0", type=float, default=0.2, help="start of the steady window (s)")
    ap.add_argument("-n", type=int, default=3, help="sectors in the whole vessel")
    ap.add_argument("--walls", nargs="+", default=["blades", "shaft"])
    args = ap.parse_args()
    for path in args.csv:
        a, b, omega, out = analyse(path, args.t0, args.n, args.walls)
        label = os.path.basename(os.path.dirname(os.path.abspath(path)))
        p, e = out[8]
        print(f"{label}: {a:.3g}-{b:.3g} s, omega {omega:.5g} rad/s: power {p:.4g} ± {e:.2g} W, "
              f"torque {p / omega:.4g} ± {e / omega:.2g} N m (8 blocks; standard error with "
              f"4/8/16 blocks: {out[4][1] / omega:.2g}/{out[8][1] / omega:.2g}/"
              f"{out[16][1] / omega:.2g} N m)")


if __name__ == "__main__":
    main()
