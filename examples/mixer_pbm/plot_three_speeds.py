#!/usr/bin/env python3
"""The mixer chain at three tip speeds (issue 13, point 6): DEM spectra and the joint fit.

Reads, under OUTPUT (examples/mixer_pbm/output by default):
  sector_<tag>/grid_statistics_spectrum.csv   ṅ(σ) per primary particle (columns by header)
  sector_<tag>/grid_statistics.csv           for the height of the bed's mass centre
  sector_<tag>/timeseries.csv                 for the shaft power (optional)
  calibration/fit.csv                         measured vs simulated passing (optional)
Prints, per tip speed, the spectrum's summary — the mean contact frequency per particle
ṅ_tot = ∫ ṅ dσ, the mean particle pressure ∫ σ ṅ dσ / ṅ_tot, the frequency above 30 kPa —, the
height of the bed's mass centre in the grid (cells weighted by their mean particle volume) and
the whole-vessel shaft power (blades + shaft, × 3 sectors, mean over t ≥ WINDOW_START), as CSV.
Draws OUTPUT/three_speeds.png: ṅ(σ), the tail ∫_σ ṅ dσ (the rate b = λ × tail at σ = σ50), and
the synthetic data against the joint fit.

usage: plot_three_speeds.py [OUTPUT] [--no-plot] [--window-start 0.2]
"""
import argparse
import csv
import os

SPEEDS = [("6p25", 6.25), ("9p5", 9.5), ("13", 13.0)]
HIGH = 3e4  # Pa: "high-stress" contacts, the σ∞ scale of the carbon-black strength


def read_spectrum(path):
    rows = list(csv.DictReader(open(path)))
    s = [float(r["stress [Pa]"]) for r in rows]
    n = [float(r["primary_frequency [1/(s Pa)]"]) for r in rows]
    width = s[1] - s[0]  # equal bins, values at the centres
    return s, n, width


def summary(spectrum):
    s, n, w = spectrum
    total = sum(n) * w
    mean_p = sum(si * ni for si, ni in zip(s, n)) * w / total if total > 0 else 0.0
    high = sum(ni for si, ni in zip(s, n) if si > HIGH) * w
    return total, mean_p, high


def bed_height(path):
    rows = list(csv.DictReader(open(path)))
    m = [float(r["solid_fraction [-]"]) * float(r["volume [m3]"]) for r in rows]
    return sum(a * float(r["centre_axial [m]"]) for a, r in zip(m, rows)) / sum(m)


def shaft_power(path, start):
    if not os.path.exists(path):
        return float("nan")
    rows = [r for r in csv.DictReader(open(path)) if float(r["time [s]"]) >= start]
    if not rows:
        return float("nan")
    p = [float(r["blades_P [W]"]) + float(r["shaft_P [W]"]) for r in rows]
    return 3.0 * sum(p) / len(p)  # the walls' power on the particles (examples/mixer)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("output", nargs="?", default="examples/mixer_pbm/output")
    ap.add_argument("--no-plot", action="store_true")
    ap.add_argument("--window-start", type=float, default=0.2)
    a = ap.parse_args()
    spectra = {}
    print("tip_speed [m/s],contact_frequency [1/s],mean_particle_pressure [Pa],"
          "frequency_above_30kPa [1/s],bed_height [m],shaft_power [W]")
    for tag, v in SPEEDS:
        d = os.path.join(a.output, f"sector_{tag}")
        spectra[tag] = read_spectrum(os.path.join(d, "grid_statistics_spectrum.csv"))
        total, mean_p, high = summary(spectra[tag])
        power = shaft_power(os.path.join(d, "timeseries.csv"), a.window_start)
        height = bed_height(os.path.join(d, "grid_statistics.csv"))
        print(f"{v:g},{total:.6g},{mean_p:.6g},{high:.6g},{height:.6g},{power:.6g}")
    if a.no_plot:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
    colours = {"6p25": "tab:blue", "9p5": "tab:orange", "13": "tab:red"}
    for tag, v in SPEEDS:
        s, n, w = spectra[tag]
        c = colours[tag]
        # empty bins (no cell sample at that pressure) are left out of the log plot
        ax[0].semilogy([x / 1e3 for x, y in zip(s, n) if y > 0], [y for y in n if y > 0], ".-",
                       color=c, label=f"{v:g} m/s", ms=4, lw=0.8)
        tail, acc = [], 0.0
        for y in reversed(n):
            acc += y * w
            tail.append(acc)
        tail.reverse()
        ax[1].semilogy([(x - w / 2) / 1e3 for x, t in zip(s, tail) if t > 0],
                       [t for t in tail if t > 0], color=c, label=f"{v:g} m/s")
    ax[0].set(xlabel="particle pressure σ (kPa)", ylabel="ṅ(σ) per primary particle (1/(s Pa))",
              title="DEM stress–frequency spectra")
    ax[1].set(xlabel="σ (kPa)", ylabel="∫_σ ṅ dσ (1/s)",
              title="contacts per second above σ (b = λ × this at σ50)")
    fit = os.path.join(a.output, "calibration", "fit.csv")
    if os.path.exists(fit):
        rows = list(csv.DictReader(open(fit)))
        for k, (tag, v) in enumerate(SPEEDS):
            for ds, style in ((2 * k, "-"), (2 * k + 1, "--")):
                r = [x for x in rows if int(float(x["dataset [-]"])) == ds]
                if not r:
                    continue
                size = [float(x["size [m]"]) * 1e6 for x in r]
                t = float(r[0]["time [s]"])
                ax[2].semilogx(size, [float(x["measured [-]"]) for x in r], "o",
                               color=colours[tag], ms=4)
                ax[2].semilogx(size, [float(x["simulated [-]"]) for x in r], style,
                               color=colours[tag], label=f"{v:g} m/s, {t:g} s")
        ax[2].set(xlabel="size (µm)", ylabel="cumulative mass passing",
                  title="synthetic data (dots) and the joint fit (lines)")
        ax[2].legend(fontsize=8)
    for x in ax[:2]:
        x.legend()
    fig.tight_layout()
    out = os.path.join(a.output, "three_speeds.png")
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
