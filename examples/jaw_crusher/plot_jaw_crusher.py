#!/usr/bin/python3
"""Plots the jaw-crusher run: the throughput (cumulative product mass against time, with its mean
rate over the window the product flows), the jaw force along x (the bed pushes the swinging jaw
open: crusher_swing_jaw_Fx) and its power (crusher_swing_jaw_P), and the product's size
distribution (mass passing each sieve) from the outlet log, the feed's for comparison. When the
run has the bounded sampling plane "discharge" (sampling_planes.csv, sampling_log.csv), the mass
that crossed it downwards is drawn next to the product mass.

usage: examples/jaw_crusher/plot_jaw_crusher.py OUTPUT_DIR [--wall crusher] [--outlet product]
       [--from T0] [--feed A B] [--oss S] [-o jaw_crusher.png]
(defaults: window from the first product to the end; output jaw_crusher.png in OUTPUT_DIR)"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from machine_plots import column, mass_passing, read, uniform_feed_passing  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--wall", default="crusher")
    ap.add_argument("--outlet", default="product")
    ap.add_argument("--from", dest="t0", type=float)
    ap.add_argument("--feed", type=float, nargs=2, default=[0.025, 0.04],
                    help="the feed's uniform diameter range [m] (default 0.025 0.04)")
    ap.add_argument("--oss", type=float, default=0.015,
                    help="the open-side setting css + throw [m] (default 0.015)")
    ap.add_argument("-o", "--png")
    args = ap.parse_args()
    ts_path = os.path.join(args.output, "timeseries.csv")
    out_path = os.path.join(args.output, "outlets.csv")
    log_path = os.path.join(args.output, "outlet_log.csv")
    ts, outlets, log = read(ts_path), read(out_path), read(log_path)
    t = column(ts, "time [s]", ts_path)
    fx = column(ts, f"{args.wall}_swing_jaw_Fx [N]", ts_path)
    power = column(ts, f"{args.wall}_swing_jaw_P [W]", ts_path)
    to = column(outlets, "time [s]", out_path)
    mass = column(outlets, f"{args.outlet}_mass [kg]", out_path)
    log = [r for r in log if r["outlet [-]"] == args.outlet]
    if not log:
        sys.exit(f"{log_path}: nothing left through '{args.outlet}' yet (run longer)")
    t0 = args.t0 if args.t0 is not None else min(float(r["time [s]"]) for r in log)
    t1 = to[-1]
    m0 = next(m for x, m in zip(to, mass) if x >= t0)
    rate = (mass[-1] - m0) / (t1 - t0) if t1 > t0 else float("nan")
    window = [i for i, x in enumerate(t) if t0 <= x <= t1]
    mean = lambda xs: sum(xs[i] for i in window) / max(1, len(window))  # noqa: E731
    print(f"window {t0:.3f}-{t1:.3f} s: throughput {rate:.4g} kg/s, product {mass[-1]:.4g} kg "
          f"({len(log)} particles); swinging jaw: mean force along x {mean(fx):.4g} N, mean power "
          f"{mean(power):.4g} W")
    product = [(float(r["diameter [m]"]), float(r["mass [kg]"])) for r in log]
    total = sum(m for _, m in product)
    coarse = sum(m for d, m in product if d > args.oss)
    print(f"{100 * coarse / total:.3g} % of the product mass is coarser than the open-side "
          f"setting (should be 0 with pushing growth: README.md)")
    sieves = [0.002 * 2 ** (k / 4) for k in range(0, 23)]
    passing = [100 * sum(m for d, m in product if d <= s) / total for s in sieves]
    a, b = args.feed  # uniform in number on [a, b]: mass fraction (s^4 - a^4) / (b^4 - a^4)
    feed = [100 * min(1, max(0, (s**4 - a**4) / (b**4 - a**4))) for s in sieves]
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6))
    ax[0].plot(to, mass, lw=1.2, label="product mass")
    ax[0].plot([t0, t1], [m0, mass[-1]], "--k", label=f"mean rate {rate:.3g} kg/s")
    planes_path = os.path.join(args.output, "sampling_planes.csv")
    if os.path.exists(planes_path):
        planes = read(planes_path)
        crossed = column(planes, "discharge_mass_positive [kg]", planes_path)
        ax[0].plot(column(planes, "time [s]", planes_path), crossed, lw=1.0, ls=":",
                   label="down through the discharge plane")
        print(f"discharge plane: {crossed[-1]:.4g} kg crossed downwards")
    ax[0].set_ylabel("cumulative product [kg]")
    ax[1].plot(t, fx, lw=0.6, label="swinging jaw Fx [N]")
    ax[1].set_ylabel("force [N]")
    ax1b = ax[1].twinx()
    ax1b.plot(t, power, lw=0.6, color="C1", label="power [W]")
    ax1b.set_ylabel("power [W]", color="C1")
    for a_ in ax[:2]:
        a_.set_xlabel("time [s]")
        a_.legend(loc="upper left")
        a_.grid(alpha=0.3)
    mm = [1000 * s for s in sieves]
    ax[2].semilogx(mm, passing, "o-", label=f"product ({total:.3g} kg)")
    ax[2].semilogx(mm, feed, "s--", label=f"feed ({1000 * a:.0f}-{1000 * b:.0f} mm)")
    ax[2].set_xlabel("size [mm]")
    ax[2].set_ylabel("mass passing [%]")
    ax[2].set_ylim(0, 100)
    ax[2].legend()
    ax[2].grid(alpha=0.3, which="both")
    fig.suptitle(f"Jaw crusher: throughput {rate:.3g} kg/s")
    fig.tight_layout()
    out = args.png or os.path.join(args.output, "jaw_crusher.png")
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
