#!/usr/bin/env python3
"""SYNTHETIC "measured" size distributions for the mixer chain (issue 13, point 6).

No measured NCM distributions are available to this repository, so the data the calibration is
fitted to are made here, from the population balance run with KNOWN rate parameters
(carbon_black_<tag>.toml, λ = 0.002, σ∞ = 20 kPa, fed by the DEM spectrum of that tip speed):
the cumulative mass passing at 18 sieve sizes (4 µm · √2^j, j = 0..17) after each time, plus
Gaussian noise of standard deviation `--noise` (absolute, in passing fraction). Values are
clipped to [0, 1] and sorted (a cumulative passing cannot decrease with size). Every file says
in its first line that it is synthetic and how it was made.

The passing at a sieve size is interpolated linearly in ln d between class edges, as
`comminute calibrate` does (analysis/size_distribution.cpp), so noise-free data are met
exactly by the known parameters.

usage: make_synthetic_measured.py DISTRIBUTIONS_CSV OUT_DIR TAG [--times 10 60]
                                  [--noise 0.01] [--seed 1]
writes OUT_DIR/measured_<TAG>_<t>s.csv (columns size_m, cumulative_passing)
"""
import argparse
import csv
import math
import os
import random

SIEVES = [4e-6 * math.sqrt(2.0) ** j for j in range(18)]


def passing_at(rows, size):
    """Cumulative mass passing at `size` from one time's rows of distributions.csv."""
    edges = [float(rows[0]["size_lower [m]"])] + [float(r["size_upper [m]"]) for r in rows]
    cum = [0.0] + [float(r["cumulative_mass [-]"]) for r in rows]
    if size <= edges[0]:
        return 0.0
    if size >= edges[-1]:
        return 1.0
    i = max(k for k in range(len(edges) - 1) if edges[k] <= size)
    w = math.log(size / edges[i]) / math.log(edges[i + 1] / edges[i])
    return cum[i] + w * (cum[i + 1] - cum[i])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("distributions")
    ap.add_argument("out_dir")
    ap.add_argument("tag")
    ap.add_argument("--times", type=float, nargs="+", default=[10.0, 60.0])
    ap.add_argument("--noise", type=float, default=0.01)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    rows = list(csv.DictReader(open(a.distributions)))
    os.makedirs(a.out_dir, exist_ok=True)
    # one stream per (seed, tag): the three speeds get independent noise
    rng = random.Random(f"{a.seed}:{a.tag}")
    for t in a.times:
        at = sorted((r for r in rows if abs(float(r["time [s]"]) - t) < 1e-9),
                    key=lambda r: float(r["size_upper [m]"]))
        if not at:
            raise SystemExit(f"{a.distributions}: no rows at time {t} s")
        values = sorted(min(1.0, max(0.0, passing_at(at, d) + rng.gauss(0.0, a.noise)))
                        for d in SIEVES)
        name = os.path.join(a.out_dir, f"measured_{a.tag}_{t:g}s.csv")
        with open(name, "w") as f:
            f.write(f"# SYNTHETIC measurement: {a.distributions} (known parameters) at {t:g} s, "
                    f"+ N(0, {a.noise:g}) noise (seed {a.seed}), clipped and sorted\n")
            f.write("size_m,cumulative_passing\n")
            for d, v in zip(SIEVES, values):
                f.write(f"{d:.6e},{v:.6f}\n")
        print(f"wrote {name}")


if __name__ == "__main__":
    main()
