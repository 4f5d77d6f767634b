#!/usr/bin/env bash
# The mixer chain of examples/mixer_pbm at the study's three tip speeds (issue 13, point 6),
# shortened: the coarse-grained one-third sector with the study's Table 1 materials runs at
# 6.25, 9.5 and 13 m/s (800 particles, 0.2 s, grid statistics over 0.12-0.2 s), each grid's
# stress-frequency spectrum feeds the carbon-black population balance with KNOWN rate
# parameters, whose distributions after 10 s and 60 s become noise-free synthetic "measured"
# data (make_synthetic_measured.py --noise 0), and `comminute calibrate` fits λ and σ∞ jointly
# over the three speeds (calibrate_three_speeds.toml: one parameter set, the speed only in the
# spectra). Asserts:
#  - physics of this shallow bed: faster blades throw it up and dilate it — the mass centre of
#    the bed in the grid rises and the spectrum's mean particle pressure falls with tip speed
#    (the contact frequency per particle does not change measurably: examples/mixer_pbm/README.md);
#  - the chain: the joint fit finds the known λ and σ∞ again.
# Every case is the example's own, changed only by the sed lines below (checked).
# usage: test_mixer_three_speeds_cli.sh <comminute> <source-dir>
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
cp "$src"/examples/mixer_pbm/*.toml "$src"/examples/mixer_pbm/*.py .

# Shortened sector: 800 particles instead of 1200, 0.2 s instead of 0.3 s, the grid averaged over
# 0.12-0.2 s (the bed has landed and the blades are at speed by 0.1 s); Table 1 materials, grid,
# coarse graining and fill region unchanged.
for tag in 6p25 9p5 13; do
  f=mixer_sector_$tag.toml
  sed -i -e 's|^end_time = 0.3 |end_time = 0.2 |' -e 's|^count = 1200$|count = 800|' \
      -e 's|^start = 0.2 |start = 0.12 |' -e 's|^particles_interval = 0.02 |particles_interval = 0.1 |' "$f"
  for want in '^end_time = 0.2 ' '^count = 800$' '^start = 0.12 ' '^particles_interval = 0.1 '; do
    grep -q "$want" "$f" || { echo "examples/mixer_pbm/$f changed ($want): edit this test"; exit 1; }
  done
  "$bin" run "$f" --threads 1 > "run_$tag.log" 2>&1 || { tail -20 "run_$tag.log"; exit 1; }
done

# physics: the bed is thrown higher and dilated at a higher tip speed
/usr/bin/python3 plot_three_speeds.py output --no-plot --window-start 0.12 > summary.csv
cat summary.csv
/usr/bin/python3 - summary.csv <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
v = [float(r["tip_speed [m/s]"]) for r in rows]
h = [float(r["bed_height [m]"]) for r in rows]
p = [float(r["mean_particle_pressure [Pa]"]) for r in rows]
assert v == [6.25, 9.5, 13.0], v
# Measured with this shortened case, seeds 3 and 4: height 24.2/23.8, 26.4/26.5, 27.4/27.7 mm,
# mean particle pressure 4.56/5.07, 3.70/3.78, 3.20/3.32 kPa; the full example (1200
# particles, 0.3 s): 23.9, 25.3, 26.8 mm and 4.10, 3.82, 2.77 kPa. The spread between seeds is
# ≤ 0.3 mm and ≤ 10 % per speed, each step of the trend ≥ 1.0 mm and ≥ 7 %: every step must go
# the right way, and 6.25 → 13 m/s by more than 1.5 mm and 15 % (about half the smallest rise,
# 2.9 mm and 30 %, seen in the three runs).
for k in range(2):
    assert h[k + 1] > h[k], ("the bed does not rise with tip speed", v, h)
    assert p[k + 1] < p[k], ("the mean particle pressure does not fall with tip speed", v, p)
assert h[2] - h[0] > 1.5e-3, ("bed rise 6.25 -> 13 m/s too small", h)
assert p[2] < 0.85 * p[0], ("pressure fall 6.25 -> 13 m/s too small", p)
print("ok: bed height", h, "m; mean particle pressure", p, "Pa")
PY

# the known model at each speed -> noise-free synthetic data -> joint calibration
for tag in 6p25 9p5 13; do
  sed -i 's|^times = \[0, 10, 30, 60, 120, 300\]|times = [0, 10, 60]|' carbon_black_$tag.toml
  "$bin" pbm carbon_black_$tag.toml --no-plots > "pbm_$tag.log" 2>&1 || { cat "pbm_$tag.log"; exit 1; }
  /usr/bin/python3 make_synthetic_measured.py output/pbm_$tag/distributions.csv output/measured \
      $tag --noise 0 > /dev/null
done
sed -i -e 's|^starts = 8$|starts = 3|' calibrate_three_speeds.toml
grep -q '^starts = 3$' calibrate_three_speeds.toml || { echo "calibrate_three_speeds.toml changed: edit this test"; exit 1; }
"$bin" calibrate calibrate_three_speeds.toml --no-plots > calibrate.log 2>&1 || { cat calibrate.log; exit 1; }
/usr/bin/python3 - output/calibration <<'PY'
import csv, sys
best = {r["key [-]"]: float(r["value [case]"]) for r in csv.DictReader(open(f"{sys.argv[1]}/best_parameters.csv"))}
fit = list(csv.DictReader(open(f"{sys.argv[1]}/fit.csv")))
assert sorted({int(float(r["dataset [-]"])) for r in fit}) == [0, 1, 2, 3, 4, 5], "six data sets"
# Noise-free data made by the same model (rounded to 6 decimals): the known values are the exact
# minimum. Nelder–Mead stops when the simplex is within x_tolerance = 1e-4 of the unit box, on a
# log scale: 1e-4 × ln(100) = 5e-4 relative for λ, 1e-4 × ln(20) = 3e-4 for σ∞; 0.5 % leaves
# room for a flat valley and the rounding, while a fit that ignored a speed's spectrum (one
# parameter set cannot match three different spectra with the wrong one) is off by far more.
for key, truth in (("rate.lambda", 0.002), ("rate.sigma_inf", 2.0e4)):
    assert abs(best[key] / truth - 1) < 5e-3, (key, best[key], truth)
print(f"ok: λ = {best['rate.lambda']:.6g} (known 0.002), σ∞ = {best['rate.sigma_inf']:.6g} Pa (known 2e4)")
PY
