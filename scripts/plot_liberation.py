#!/usr/bin/env python3
"""Plots of a textured run (PNG): liberation degree of each phase over time (100, 95, 90 %
thresholds, all sizes), liberation by size class at the last sample, the liberation spectrum of the
target phase and the ideal grade-recovery curve (target and gangue recovery against yield).

Usage: /usr/bin/python3 scripts/plot_liberation.py <output folder> [-o <png folder>]
Reads liberation.csv, liberation_spectrum.csv and grade_recovery.csv (docs/outputs.md); columns
are found by their header names.
"""
import os
import sys

from plot_breakage import plt, read  # same folder: CSV reading and the Agg backend


def finish(fig, ax, xlabel, ylabel, title, path, legend_size=None):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=legend_size)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def over_time(rows, out):
    whole = [r for r in rows if r["size_lower [m]"] == rows[0]["size_lower [m]"]
             and r["size_upper [m]"] == rows[0]["size_upper [m]"]]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for phase in sorted({r["phase [-]"] for r in whole}):
        sel = [r for r in whole if r["phase [-]"] == phase]
        t = [float(r["time [s]"]) * 1e3 for r in sel]
        for col, style in (("liberation_100 [-]", "-"), ("liberation_95 [-]", "--"),
                           ("liberation_90 [-]", ":")):
            ax.plot(t, [100 * float(r[col]) for r in sel], style,
                    label=f"{phase}, {col.split()[0].split('_')[1]} %")
    finish(fig, ax, "time (ms)", "liberation degree (%)", "Liberation over time (all sizes)",
           os.path.join(out, "liberation_time.png"), 7)


def by_size(rows, out):
    last = max(float(r["time [s]"]) for r in rows)
    sel = [r for r in rows if float(r["time [s]"]) == last]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for phase in sorted({r["phase [-]"] for r in sel}):
        pr = [r for r in sel if r["phase [-]"] == phase][1:]  # the first row is all sizes
        x = [1e3 * (float(r["size_lower [m]"]) * float(r["size_upper [m]"])) ** 0.5 for r in pr]
        ax.semilogx(x, [100 * float(r["liberation_95 [-]"]) for r in pr], marker="o", label=phase)
    finish(fig, ax, "size class (geometric mean, mm)", "liberation at 95 % (%)",
           f"Liberation by size, t = {last * 1e3:.3g} ms", os.path.join(out, "liberation_size.png"))


def spectrum(rows, out):
    if not rows:
        return
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for lo in sorted({r["size_lower [m]"] for r in rows}, key=float):
        sel = [r for r in rows if r["size_lower [m]"] == lo]
        if sum(float(r["mass [kg]"]) for r in sel) <= 0:
            continue
        ax.plot(range(len(sel)), [100 * float(r["mass_fraction [-]"]) for r in sel], marker="o",
                label=f"{float(lo) * 1e3:.3g}-{float(sel[0]['size_upper [m]']) * 1e3:.3g} mm")
    ax.set_xticks(range(12))
    ax.set_xticklabels(["0", "-10", "-20", "-30", "-40", "-50", "-60", "-70", "-80", "-90",
                        "<100", "100"], fontsize=7)
    finish(fig, ax, "target-phase volume fraction class (%)", "mass in class (%)",
           "Liberation spectrum (last sample)", os.path.join(out, "liberation_spectrum.png"), 7)


def grade_recovery(rows, out):
    if not rows:
        return
    y = [100 * float(r["yield [-]"]) for r in rows]
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4.5))
    a1.plot(y, [100 * float(r["recovery [-]"]) for r in rows], label="target")
    a1.plot(y, [100 * float(r["gangue_recovery [-]"]) for r in rows], label="gangue")
    a1.set_xlabel("yield (%)")
    a1.set_ylabel("recovery (%)")
    a1.legend()
    a1.grid(True, alpha=0.3)
    a2.plot([100 * float(r["recovery [-]"]) for r in rows],
            [100 * float(r["grade [-]"]) for r in rows])
    a2.set_xlabel("target recovery (%)")
    a2.set_ylabel("concentrate grade (%)")
    a2.grid(True, alpha=0.3)
    fig.suptitle("Ideal separation (last sample)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "grade_recovery.png"), dpi=120)
    plt.close(fig)


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if argv else 2
    folder = argv[0]
    out = argv[argv.index("-o") + 1] if "-o" in argv else folder
    os.makedirs(out, exist_ok=True)
    lib = read(os.path.join(folder, "liberation.csv"))
    if not lib:
        print(f"no liberation.csv in {folder}", file=sys.stderr)
        return 1
    over_time(lib, out)
    by_size(lib, out)
    spectrum(read(os.path.join(folder, "liberation_spectrum.csv")), out)
    grade_recovery(read(os.path.join(folder, "grade_recovery.csv")), out)
    print(f"plots written to {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
