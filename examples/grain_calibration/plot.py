#!/usr/bin/python3
"""Plot of a single-grain compression calibration (examples/grain_calibration).

Usage: /usr/bin/python3 plot.py OUTPUT_DIR   (the calibration's [output] directory)
Reads fit.csv (measured and simulated force at the measured displacements) and compression.csv
(the whole simulated curve at the best parameters) by column name and writes fit.png into
OUTPUT_DIR.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    """Columns of a CSV file by header name (the unit in brackets dropped)."""
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]
    names = [h.split(" [")[0] for h in rows[0]]
    return {n: [float(r[k]) for r in rows[1:]] for k, n in enumerate(names)}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "output"
    fit = read(os.path.join(out, "fit.csv"))
    curve = read(os.path.join(out, "compression.csv"))
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot([x * 1e6 for x in curve["displacement"]], curve["force"], "-", lw=1,
            label="simulated, best fit")
    ax.plot([x * 1e6 for x in fit["displacement"]], fit["measured"], "o", ms=3, label="measured")
    ax.set_xlabel("platen displacement from first contact [µm]")
    ax.set_ylabel("force [N]")
    ax.legend()
    fig.tight_layout()
    path = os.path.join(out, "fit.png")
    fig.savefig(path, dpi=120)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
