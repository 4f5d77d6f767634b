#!/usr/bin/env python3
"""Plots of a breakage run (PNG): size distribution over time, t10 versus specific energy,
breakage probability versus specific energy against the model curve, energy ledger.

Usage: /usr/bin/python3 scripts/plot_breakage.py <output folder> [<more folders>] [-o <png folder>]
                                               [--platen NAME SPEED]
The size distribution, t10 and ledger plots use the first folder; the probability plot takes one
point per folder (drop-weight runs at different energies) against the model curve.
--platen NAME SPEED adds force_displacement.png: the force on wall NAME against its travel at
SPEED m/s (slow-compression rig).
Reads breakage_events.csv, breakage_model.csv, size_distribution.csv, breakage_ledger.csv
written by the breakage module (docs/breakage.md).
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def size_distribution(rows, out):
    if not rows:
        return
    times = sorted({float(r["time [s]"]) for r in rows})
    picks = sorted({times[0], times[len(times) // 2], times[-1]})
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for mat in sorted({r["material [-]"] for r in rows}):
        for t in picks:
            sel = [r for r in rows if r["material [-]"] == mat and float(r["time [s]"]) == t]
            x = [float(r["sieve [m]"]) * 1e3 for r in sel]
            y = [100 * float(r["fraction_passing [-]"]) for r in sel]
            ax.semilogx(x, y, marker="o", ms=3, label=f"{mat}, t = {t * 1e3:.3g} ms")
    ax.set_xlabel("sieve size (mm)")
    ax.set_ylabel("cumulative mass passing (%)")
    ax.set_title("Product size distribution")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "size_distribution.png"), dpi=120)
    plt.close(fig)


def t10_plot(events, model, out):
    broken = [r for r in events if r["broken [-]"] == "1"]
    if not broken:
        return
    # the progeny is sized at the stressing energy (default sizing_energy = "stressing")
    key = "stressing_energy [J/kg]" if "stressing_energy [J/kg]" in broken[0] else "specific_energy [J/kg]"
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.scatter([float(r[key]) for r in broken],
               [float(r["t10 [%]"]) for r in broken], s=8, alpha=0.5,
               label="breakage events")
    for mat in sorted({r["material [-]"] for r in model}):
        sel = [r for r in model if r["material [-]"] == mat]
        d = float(sel[0]["diameter [m]"]) * 1e3
        ax.plot([float(r["specific_energy [J/kg]"]) for r in sel],
                [float(r["t10 [%]"]) for r in sel], "k-",
                label=f"model A(1-exp(-b'E/E50b)), d = {d:.3g} mm\n(fragments follow the curve of their own size)")
    ax.set_xlabel("stressing energy E (J/kg)" if key.startswith("stressing")
                  else "absorbed specific energy E (J/kg)")
    ax.set_ylabel("t10 (%)")
    ax.set_title("t10 versus specific energy")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "t10_vs_energy.png"), dpi=120)
    plt.close(fig)


def probability_point(events):
    """One drop-weight run: (delivered absorbed energy, fraction broken, n) of the first events
    of the initial particles. A particle breaks during loading, so a broken particle's logged
    energy is its fracture energy, not the delivered one; the delivered energy is read from the
    particles that survived (they took the whole impact). None when all broke."""
    first = {}
    for r in events:
        if r["generation [-]"] == "0" and r["parent_id [-]"] not in first:
            first[r["parent_id [-]"]] = r
    if not first:
        return None
    survived = [float(r["specific_energy [J/kg]"]) for r in first.values() if r["broken [-]"] == "0"]
    n = len(first)
    p = sum(r["broken [-]"] == "1" for r in first.values()) / n
    if not survived:
        return None
    return sum(survived) / len(survived), p, n


def probability_plot(runs, out):
    points = [pt for pt in (probability_point(ev) for ev, _ in runs) if pt]
    # the model curve of the run that reaches the highest energy (same material and size)
    model = max((m for _, m in runs), key=lambda m: max(
        (float(r["specific_energy [J/kg]"]) for r in m), default=0.0))
    curve = [r for r in model if float(r["probability [-]"]) >= 0]
    if not points or not curve:
        return
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.errorbar([p[0] for p in points], [p[1] for p in points],
                yerr=[3 * math.sqrt(max(p[1] * (1 - p[1]), 1e-12) / p[2]) for p in points],
                fmt="o", capsize=3, label="drop-weight runs (3 sigma binomial)")
    emax = max(p[0] for p in points) * 1.5
    for mat in sorted({r["material [-]"] for r in curve}):
        sel = [r for r in curve if r["material [-]"] == mat]
        d = float(sel[0]["diameter [m]"]) * 1e3
        ax.plot([float(r["specific_energy [J/kg]"]) for r in sel],
                [float(r["probability [-]"]) for r in sel], "k-", label=f"model P(E), d = {d:.3g} mm")
        emax = max(emax, float(sel[-1]["specific_energy [J/kg]"]))
    ax.set_xlim(0, emax)
    ax.set_xlabel("absorbed specific energy E (J/kg)")
    ax.set_ylabel("breakage probability")
    ax.set_ylim(-0.05, 1.05)
    ax.set_title("Breakage probability versus specific energy")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "breakage_probability.png"), dpi=120)
    plt.close(fig)


def ledger_plot(rows, out):
    if not rows:
        return
    t = [float(r["time [s]"]) * 1e3 for r in rows]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot(t, [float(r["removed_energy_breakage [J]"]) for r in rows], label="removed by breakage (J)")
    ax.set_xlabel("time (ms)")
    ax.set_ylabel("energy (J)")
    ax2 = ax.twinx()
    ax2.plot(t, [int(r["breakages [-]"]) for r in rows], "r--", label="breakages")
    ax2.plot(t, [int(r["pending_fragments [-]"]) for r in rows], "g:", label="fragments still growing")
    ax2.set_ylabel("count")
    ax.set_title("Energy ledger and breakage count")
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = ax2.get_legend_handles_labels()
    ax.legend(h1 + h2, l1 + l2, fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "breakage_ledger.png"), dpi=120)
    plt.close(fig)


def force_displacement(rows, wall, speed, out):
    """Slow-compression rig: normal force on the platen against its travel (speed x time, from
    the first step with a force), from timeseries.csv."""
    key = next((k for k in (rows[0].keys() if rows else []) if k.startswith(wall + "_Fz")), None)
    if key is None:
        return
    t = [float(r["time [s]"]) for r in rows]
    f = [abs(float(r[key])) for r in rows]
    start = next((k for k, v in enumerate(f) if v > 0), None)
    if start is None:
        return
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.plot([(x - t[start]) * speed * 1e3 for x in t[start:]], f[start:])
    ax.set_xlabel(f"{wall} travel since first contact (mm)")
    ax.set_ylabel(f"{wall} normal force (N)")
    ax.set_title("Force-displacement")
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "force_displacement.png"), dpi=120)
    plt.close(fig)


def main():
    args = sys.argv[1:]
    if not args or args[0] in ("-h", "--help"):
        sys.exit(__doc__)
    platen = None
    if "--platen" in args:
        k = args.index("--platen")
        platen = (args[k + 1], float(args[k + 2]))
        args = args[:k] + args[k + 3:]
    out = args[0]
    if "-o" in args:
        k = args.index("-o")
        out = args[k + 1]
        args = args[:k] + args[k + 2:]
    os.makedirs(out, exist_ok=True)
    runs = [(read(os.path.join(a, "breakage_events.csv")), read(os.path.join(a, "breakage_model.csv")))
            for a in args]
    src = args[0]
    events, model = runs[0]
    size_distribution(read(os.path.join(src, "size_distribution.csv")), out)
    t10_plot(events, model, out)
    probability_plot(runs, out)
    ledger_plot(read(os.path.join(src, "breakage_ledger.csv")), out)
    if platen:
        force_displacement(read(os.path.join(src, "timeseries.csv")), platen[0], platen[1], out)
    print("plots in", out)


if __name__ == "__main__":
    main()
