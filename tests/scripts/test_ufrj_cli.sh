#!/usr/bin/env bash
# The UFRJ mill from the command line (issue 13 point 5): the example writes the whole
# fracture-energy distribution; bad UFRJ keys fail with exit code 2 naming key and line; and
# examples/ball_mill/ball_size_sweep/sweep.py with given spectra (no DEM: speed): it writes
# ball_size_rates.csv with one row per ball size and class, the total rate is the sum of the
# ball-ball and ball-liner rates (one mill with both spectra against two mills: the rate is a
# sum over collisions; 1e-10: round-off plus the CSV's 17 significant digits), and the ball size reaches the rates (the same spectrum with
# other balls gives other captured masses, so other rates).
#   usage: test_ufrj_cli.sh <comminute> <source-dir>
set -uo pipefail
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
check() {  # check <description> <condition...>
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; fail=1; fi
}
cp "$src/examples/pbm/ball_mill_ufrj.toml" "$src/examples/pbm/ball_mill_spectrum.csv" "$work/"
(cd "$work" && "$bin" pbm --no-plots ball_mill_ufrj.toml > /dev/null)
check "the example runs" test $? -eq 0
header=$(head -1 "$work/ball_mill_ufrj_out/fracture_energy_distribution.csv")
check "fracture_energy_distribution.csv header ($header)" test "$header" = \
  "time [s],class [-],size_pivot [m],bin [-],energy_lower [J/kg],energy_upper [J/kg],mass [kg],fraction [-],cumulative_fraction [-]"
# 5 times x 20 classes x 60 bins, plus the header
check "fracture_energy_distribution.csv rows" test "$(wc -l < "$work/ball_mill_ufrj_out/fracture_energy_distribution.csv")" -eq 6001
expect_error() {  # expect_error <description> <sed expression> <line pattern> <text>
  sed -e "$2" "$work/ball_mill_ufrj.toml" > "$work/bad.toml"
  local line
  line=$(grep -n -- "$3" "$work/bad.toml" | cut -d: -f1)
  out=$("$bin" pbm --no-plots "$work/bad.toml" 2>&1)
  rc=$?
  check "$1: exit code 2 (got $rc)" test $rc -eq 2
  check "$1: message names line and key ($out)" grep -qF -- "bad.toml:$line: $4" <<<"$out"
}
expect_error "unknown capture" 's/^ball_diameter = .*/ball_diameter = 0.025\ncapture = "ball_box"/' \
  '^capture' "key 'mill.capture'"
expect_error "sigma table lengths differ" 's/^sigma = 0.8/sigma = 0.8\nsigma_sizes = [1e-4, 1e-3]\nsigma_values = [0.8]/' \
  '^sigma_values' "key 'mill.fracture_energy.sigma_values'"
expect_error "sigma sizes not increasing" 's/^sigma = 0.8/sigma = 0.8\nsigma_sizes = [1e-3, 1e-4]\nsigma_values = [0.8, 0.7]/' \
  '^sigma_sizes' "key 'mill.fracture_energy.sigma_sizes'"
expect_error "missing wall spectrum" 's/^holdup = 0.5 .*/holdup = 0.5\nwall_spectrum_file = "none.csv"/' \
  '^wall_spectrum_file' "key 'mill.wall_spectrum_file'"

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
exit $fail
