#!/usr/bin/python3
"""Plots the HPGR slice run: the separating force of each roll (the force along the line of
centres, -press_roll1_Fx and press_roll2_Fx), the power of each roll (press_roll1_P, press_roll2_P)
and the product's size distribution (mass passing each sieve) from the outlet log, the feed's for
comparison; prints the mean force, power and throughput over the window the product flows.

usage: examples/hpgr/plot_hpgr.py OUTPUT_DIR [--wall press] [--outlet product] [--from T0]
       [--feed A B] [--gap G] [-o hpgr.png]
(defaults: window from the first product to the end; output hpgr.png in OUTPUT_DIR)"""
import argparse
import math
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
    ap.add_argument("--wall", default="press")
    ap.add_argument("--from", dest="t0", type=float)
    ap.add_argument("--outlet", default="product")
    ap.add_argument("--feed", type=float, nargs=2, default=[0.045, 0.075],
                    help="the feed's uniform diameter range [m] (default 0.045 0.075)")
    ap.add_argument("--gap", type=float, default=0.06, help="the gap [m] (default 0.06)")
    ap.add_argument("-o", "--png")
    args = ap.parse_args()
    ts_path = os.path.join(args.output, "timeseries.csv")
    log_path = os.path.join(args.output, "outlet_log.csv")
    ts = read(ts_path)
    log = read(log_path) if os.path.exists(log_path) else []
    t = column(ts, "time [s]", ts_path)
    f1 = [-x for x in column(ts, f"{args.wall}_roll1_Fx [N]", ts_path)]
    f2 = column(ts, f"{args.wall}_roll2_Fx [N]", ts_path)
    p1 = column(ts, f"{args.wall}_roll1_P [W]", ts_path)
    p2 = column(ts, f"{args.wall}_roll2_P [W]", ts_path)
    if not log:
        sys.exit(f"{log_path}: no product yet (run longer)")
    times = [float(r["time [s]"]) for r in log if r["outlet [-]"] == args.outlet] or [t[-1]]
    t0 = args.t0 if args.t0 is not None else min(times)
    t1 = t[-1]
    window = [i for i, x in enumerate(t) if t0 <= x <= t1]
    spilled = sum(1 for r in log if r["outlet [-]"] != args.outlet)
    log = [r for r in log if r["outlet [-]"] == args.outlet]
    if not log:
        sys.exit(f"{log_path}: nothing left through the outlet '{args.outlet}' yet")
    product = [(float(r["diameter [m]"]), float(r["mass [kg]"])) for r in log
               if t0 < float(r["time [s]"]) <= t1]
    mean = lambda xs: sum(xs[i] for i in window) / max(1, len(window))  # noqa: E731
    mass = sum(m for _, m in product)
    rate = mass / (t1 - t0) if t1 > t0 else float("nan")
    print(f"window {t0:.3f}-{t1:.3f} s: separating force roll1 {mean(f1):.4g} N, roll2 "
          f"{mean(f2):.4g} N; power roll1 {mean(p1):.4g} W, roll2 {mean(p2):.4g} W")
    print(f"product: {len(product)} particles, {mass:.4g} kg, throughput {rate:.4g} kg/s "
          f"(slice), generations {sorted(set(int(r['generation [-]']) for r in log))}; "
          f"{spilled} particles left through other outlets")
    coarse = sum(m for d, m in product if d > args.gap)
    print(f"{100 * coarse / mass:.3g} % of the product mass is coarser than the gap "
          f"(README.md, 'Fragments coarser than the gap')")
    sieves = [0.004 * 2 ** (k / 4) for k in range(0, 19)]
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6))
    ax[0].plot(t, f1, lw=0.8, label="roll 1: −Fx")
    ax[0].plot(t, f2, lw=0.8, label="roll 2: Fx")
    ax[0].set_ylabel("separating force [N]")
    ax[1].plot(t, p1, lw=0.8, label="roll 1")
    ax[1].plot(t, p2, lw=0.8, label="roll 2")
    ax[1].set_ylabel("roll power [W]")
    for a in ax[:2]:
        a.set_xlabel("time [s]")
        a.axvspan(t0, t1, color="0.92", label="product window")
        a.legend()
        a.grid(alpha=0.3)
    mm = [1000 * s for s in sieves]
    ax[2].semilogx(mm, mass_passing(product, sieves), "o-", label=f"product ({mass:.3g} kg)")
    a, b = args.feed
    feed = uniform_feed_passing(sieves, a, b)
    ax[2].semilogx(mm, feed, "s--", label=f"feed ({1000 * a:.0f}-{1000 * b:.0f} mm)")
    ax[2].set_xlabel("size [mm]")
    ax[2].set_ylabel("mass passing [%]")
    ax[2].set_ylim(0, 100)
    ax[2].legend()
    ax[2].grid(alpha=0.3, which="both")
    fig.suptitle(f"HPGR slice: throughput {rate:.3g} kg/s")
    fig.tight_layout()
    out = args.png or os.path.join(args.output, "hpgr.png")
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")
    if not all(math.isfinite(x) for x in f1 + f2 + p1 + p2):
        sys.exit("non-finite force or power")


if __name__ == "__main__":
    main()
