#!/usr/bin/env bash
# examples/ball_mill/ball_size_sweep/sweep.py with given spectra (no DEM: speed): it writes
# ball_size_rates.csv with one row per ball size and class, the total rate is the sum of the
# ball-ball and ball-liner rates (one mill with both spectra against two mills: the rate is a
# sum over collisions; 1e-10: round-off plus the CSV's 17 significant digits), and the ball size reaches the rates (the same spectrum with
# other balls gives other captured masses, so other rates).
#   usage: test_ball_size_sweep.sh <comminute> <source-dir>
set -uo pipefail
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for mm in 25 40; do
  mkdir -p "$work/spectra/d$mm"
  cp "$src/examples/pbm/ball_mill_spectrum.csv" "$work/spectra/d$mm/collision_spectrum_ball-ball.csv"
  cp "$src/examples/pbm/ball_mill_spectrum.csv" "$work/spectra/d$mm/collision_spectrum_ball-wall_mill.csv"
done
/usr/bin/python3 "$src/examples/ball_mill/ball_size_sweep/sweep.py" --comminute "$bin" \
  --balls 25,40 --spectra "$work/spectra" --out "$work/out" || { echo "FAIL: sweep.py"; exit 1; }
/usr/bin/python3 - "$work/out/ball_size_rates.csv" <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 40, len(rows)  # 2 ball sizes x 20 classes
for r in rows:
    s = float(r["rate [1/s]"]); a = float(r["rate_ball_ball [1/s]"]); b = float(r["rate_ball_liner [1/s]"])
    assert abs(s - (a + b)) <= 1e-10 * max(s, 1e-300), r  # one mill with both spectra
    assert a >= 0 and b >= 0, r
top = {r["ball_diameter [m]"]: float(r["rate [1/s]"]) for r in rows if r["class [-]"] == "19"}
assert top["0.04"] > 0 and top["0.025"] > 0 and abs(top["0.04"] / top["0.025"] - 1) > 1e-3, top
prod = list(csv.DictReader(open(sys.argv[1].replace("rates", "product"))))
assert len(prod) == 2 * 5 * 20, len(prod)  # 2 balls x 5 times x 20 classes
print("ok: ball-size sweep", top)
PY
