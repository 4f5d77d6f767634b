#!/usr/bin/env python3
"""Ball-size sweep: UFRJ breakage rates of virgin material vs particle size and vs ball size.

For each ball diameter (default 25, 30, 40 mm) it needs two collision energy spectra, ball-ball
and ball-liner, in the format `comminute pbm` reads (energy_J, frequency_per_s). Either

  --dem            runs the Bond-mill rig examples/ball_mill/ball_mill.toml once per ball size
                   (same mill, 30 % filling, 70 % critical speed; N = 490 (25 mm/d)^3 balls) and
                   takes output/collision_spectrum_ball-ball.csv and ..._ball-wall_mill.csv, or
  --spectra DIR    reads DIR/d<mm>/collision_spectrum_ball-ball.csv and
                   DIR/d<mm>/collision_spectrum_ball-wall_mill.csv (or DIR/d<mm>/output/..., the
                   folders of an earlier --dem run).

Then for each ball size it runs `comminute pbm --no-plots` on the UFRJ case
examples/pbm/ball_mill_ufrj.toml twice, with the ball-ball spectrum (capture = "ball_ball") and
with the ball-liner spectrum (capture = "ball_wall"), and adds the two rates.csv columns: the
virgin rate S_i = sum over collisions of lambda_k m*_i/H F_i(e_ik) is linear in the list of
collisions (docs/models.md eq. U5), so the rate of the two contact types together is the sum.

A third run per ball size puts both spectra in one mill (wall_spectrum_file) and grinds the
example's feed for 600 s. Writes OUT/ball_size_rates.csv (ball_diameter [m], class [-], size [m],
rate_ball_ball [1/s], rate_ball_liner [1/s], rate [1/s] of the mill with both spectra),
OUT/ball_size_product.csv (ball_diameter [m], time [s], size_upper [m], cumulative_mass [-]) and
OUT/ball_size_sweep.png (rate vs size for each ball; rate vs ball size for a few particle sizes;
product size distribution per ball size). Run from the repository root:

  /usr/bin/python3 examples/ball_mill/ball_size_sweep/sweep.py --dem --out sweep_out
"""
import argparse
import csv
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def sub(text, pattern, repl):
    new, n = re.subn(pattern, repl, text, flags=re.M)
    if n == 0:
        sys.exit(f"sweep.py: the template changed, pattern not found: {pattern}")
    return new


def dem_case(d):
    """examples/ball_mill/ball_mill.toml for balls of diameter d (m): the same charge volume."""
    text = open(os.path.join(ROOT, "examples/ball_mill/ball_mill.toml")).read()
    r = d / 2
    n = round(490 * (0.025 / d) ** 3)  # J = 0.3: N = 0.6 J V_mill / (pi d^3/6)
    fill = round(n * 350 / 490)  # the example's split: 5/7 placed at the start, the rest poured
    text = sub(text, r"^ball_diameter = 0\.025", f"ball_diameter = {d!r}")
    text = sub(text, r"diameter = 0\.025 \}", f"diameter = {d!r} }}")
    text = sub(text, r"^count = 350", f"count = {fill}")
    text = sub(text, r"^count = 140", f"count = {n - fill}")
    # fill inside the lifter tips (0.1525 - 0.015 m) and the end liners, with a 1 mm margin
    text = sub(text, r"radius = 0\.124, length = 0\.28",
               f"radius = {0.1365 - r:.4f}, length = {0.305 - 2 * r:.4f}")
    text = sub(text, r"lo = \[-0\.08, -0\.14, 0\.0\], hi = \[0\.08, 0\.14, 0\.09\]",
               f"lo = [-0.08, {-(0.1515 - r):.4f}, 0.0], hi = [0.08, {0.1515 - r:.4f}, "
               f"{0.09 - 2 * (r - 0.0125):.4f}]")
    return text


def pbm_case(spectrum, d, capture, out, wall_spectrum=None):
    text = open(os.path.join(ROOT, "examples/pbm/ball_mill_ufrj.toml")).read()
    extra = f'\nwall_spectrum_file = "{wall_spectrum}"' if wall_spectrum else ""
    text = sub(text, r"^spectrum_file = .*$", f'spectrum_file = "{spectrum}"{extra}')
    text = sub(text, r"^ball_diameter = .*$", f'ball_diameter = {d!r}\ncapture = "{capture}"')
    if not wall_spectrum:
        text = sub(text, r"^times = .*$", "times = [0, 60]")
    text = sub(text, r"^directory = .*$", f'directory = "{out}"')
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--comminute", default=os.path.join(ROOT, "build/bin/comminute"))
    ap.add_argument("--balls", default="25,30,40", help="ball diameters in mm")
    ap.add_argument("--dem", action="store_true", help="run the DEM rig for each ball size")
    ap.add_argument("--spectra", help="folder with d<mm>/collision_spectrum_*.csv")
    ap.add_argument("--out", default="ball_size_sweep_out")
    a = ap.parse_args()
    if not a.dem and not a.spectra:
        sys.exit("sweep.py: give --dem or --spectra DIR")
    out = os.path.abspath(a.out)
    rows, product = [], []
    for mm in [int(b) for b in a.balls.split(",")]:
        d = mm / 1000.0
        work = os.path.join(out, f"d{mm}")
        os.makedirs(work, exist_ok=True)
        if a.dem:
            case = os.path.join(work, "ball_mill.toml")
            open(case, "w").write(dem_case(d))
            print(f"sweep: DEM rig, {mm} mm balls", flush=True)
            subprocess.run([a.comminute, "run", case], check=True, stdout=subprocess.DEVNULL)
            sdir = os.path.join(work, "output")
        else:
            sdir = os.path.join(os.path.abspath(a.spectra), f"d{mm}")
            if not os.path.exists(os.path.join(sdir, "collision_spectrum_ball-ball.csv")):
                sdir = os.path.join(sdir, "output")  # the folder of an earlier --dem run
        rates = {}
        for kind, spec, capture in (("ball_ball", "ball-ball", "ball_ball"),
                                    ("ball_liner", "ball-wall_mill", "ball_wall")):
            spectrum = os.path.join(sdir, f"collision_spectrum_{spec}.csv")
            case = os.path.join(work, f"ufrj_{kind}.toml")
            open(case, "w").write(pbm_case(spectrum, d, capture, f"ufrj_{kind}"))
            subprocess.run([a.comminute, "pbm", "--no-plots", case], check=True,
                           stdout=subprocess.DEVNULL)
            rates[kind] = read(os.path.join(work, f"ufrj_{kind}", "rates.csv"))
        # both spectra in one mill: the product size distribution vs grinding time
        case = os.path.join(work, "ufrj_both.toml")
        open(case, "w").write(pbm_case(
            os.path.join(sdir, "collision_spectrum_ball-ball.csv"), d, "ball_ball", "ufrj_both",
            os.path.join(sdir, "collision_spectrum_ball-wall_mill.csv")))
        subprocess.run([a.comminute, "pbm", "--no-plots", case], check=True,
                       stdout=subprocess.DEVNULL)
        dist = read(os.path.join(work, "ufrj_both", "distributions.csv"))
        for k in range(len(dist["time [s]"])):
            product.append((d, dist["time [s]"][k], dist["size_upper [m]"][k],
                            dist["cumulative_mass [-]"][k]))
        both = read(os.path.join(work, "ufrj_both", "rates.csv"))["rate [1/s]"]
        bb, bl = rates["ball_ball"], rates["ball_liner"]
        for i in range(len(bb["rate [1/s]"])):
            s1, s2 = bb["rate [1/s]"][i], bl["rate [1/s]"][i]
            rows.append((d, int(bb["class [-]"][i]), bb["size [m]"][i], s1, s2, both[i]))
    with open(os.path.join(out, "ball_size_rates.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["ball_diameter [m]", "class [-]", "size [m]", "rate_ball_ball [1/s]",
                    "rate_ball_liner [1/s]", "rate [1/s]"])
        for r in rows:
            w.writerow([repr(v) if isinstance(v, float) else v for v in r])
    print(f"sweep: wrote {os.path.join(out, 'ball_size_rates.csv')}")
    with open(os.path.join(out, "ball_size_product.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["ball_diameter [m]", "time [s]", "size_upper [m]", "cumulative_mass [-]"])
        for r in product:
            w.writerow([repr(v) for v in r])
    print(f"sweep: wrote {os.path.join(out, 'ball_size_product.csv')}")
    plot(rows, product, os.path.join(out, "ball_size_sweep.png"))


def plot(rows, product, png):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("sweep: matplotlib missing, no PNG (the CSV is complete)")
        return
    balls = sorted({r[0] for r in rows})
    fig, ax = plt.subplots(1, 3, figsize=(16, 4.2))
    for b in balls:
        pts = [(r[2], r[5]) for r in rows if r[0] == b and r[5] > 0]
        ax[0].loglog([p[0] * 1e3 for p in pts], [p[1] for p in pts], "o-", ms=3,
                     label=f"{b * 1e3:.0f} mm balls")
    ax[0].set_xlabel("particle size (mm)")
    ax[0].set_ylabel("breakage rate of virgin material S_i (1/s)")
    ax[0].set_title("UFRJ rates vs particle size")
    ax[0].legend()
    sizes = sorted({r[2] for r in rows})
    for s in sizes[-1::-4][:4]:
        pts = [(r[0], r[5]) for r in rows if r[2] == s]
        ax[1].plot([p[0] * 1e3 for p in pts], [p[1] for p in pts], "o-", label=f"{s * 1e3:.2f} mm")
    ax[1].set_xlabel("ball diameter (mm)")
    ax[1].set_ylabel("S_i (1/s)")
    ax[1].set_yscale("log")
    ax[1].set_title("rates vs ball size")
    ax[1].legend(title="particle size")
    t_end = max(p[1] for p in product)
    for b in balls:
        pts = [(p[2], p[3]) for p in product if p[0] == b and p[1] == t_end]
        ax[2].semilogx([q[0] * 1e3 for q in pts], [q[1] for q in pts], "-", label=f"{b * 1e3:.0f} mm")
    feed = [(p[2], p[3]) for p in product if p[0] == balls[0] and p[1] == 0]
    ax[2].semilogx([q[0] * 1e3 for q in feed], [q[1] for q in feed], "k--", label="feed")
    ax[2].set_xlabel("size (mm)")
    ax[2].set_ylabel("cumulative mass passing")
    ax[2].set_title(f"product after {t_end:g} s (ball-ball + ball-liner)")
    ax[2].legend(title="balls")
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print(f"sweep: wrote {png}")


if __name__ == "__main__":
    main()
