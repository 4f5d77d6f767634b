#!/usr/bin/env bash
# The collision log through `comminute run` (issue 13, point 1): a small drum with [collisions]
# writes its tables; the ball-ball spectrum is read by `comminute pbm` (UFRJ mill); the same case
# run twice writes the same files, byte for byte (same seed, same outputs); a run continued from
# a checkpoint writes the same collision tables as a straight run; a bad [collisions] key is an
# input error (exit 2) for `comminute check`.
# usage: test_collisions_cli.sh <comminute> <source-dir>
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cp "$src/tests/scripts/small_drum.toml" "$tmp/drum.toml"
cd "$tmp"
for run in a b; do
  sed -e "s|^\[output\]|[output]\ndirectory = \"$run\"|" drum.toml > "$run.toml"
  "$bin" run "$run.toml" --threads 1 2> "$run.log" || { cat "$run.log"; exit 1; }
done
for f in a/collisions.csv a/collision_distributions.csv a/collision_spectrum_all.csv \
         a/collision_spectrum_ball-ball.csv a/collision_spectrum_ball-wall_shell.csv \
         a/collision_specific_energy_all.csv; do
  test -s "$f" || { echo "missing $f"; ls a; exit 1; }
  cmp "$f" "b/${f#a/}" || { echo "not deterministic: $f"; exit 1; }
done
/usr/bin/python3 - a <<'PY'
import csv, sys
d = sys.argv[1]
rows = {r["contact_type [-]"]: r for r in csv.DictReader(open(f"{d}/collisions.csv"))}
assert set(rows) == {"ball-ball", "ball-wall_shell", "all"}, set(rows)
for k, r in rows.items():
    # the run ends at the last step before end_time (a step is 0.12 ms)
    assert abs(float(r["window_length [s]"]) - 0.4) < 2e-4, r
    assert int(r["events [-]"]) > 0, (k, r)
assert int(rows["all"]["events [-]"]) == int(rows["ball-ball"]["events [-]"]) + int(rows["ball-wall_shell"]["events [-]"])
spec = list(csv.DictReader(open(f"{d}/collision_spectrum_ball-ball.csv")))
rate = sum(float(r["frequency_per_s"]) for r in spec)
below = int(rows["ball-ball"]["events_below_energy_min [-]"]) + int(rows["ball-ball"]["events_above_energy_max [-]"])
window = float(rows["ball-ball"]["window_length [s]"])
assert abs(rate - (int(rows["ball-ball"]["events [-]"]) - below) / window) <= 1e-9 * rate, rate
print(f"ok: {rows['all']['events [-]']} events in the window, {rate:.4g} ball-ball per second")
PY

# the ball-ball spectrum feeds the UFRJ mill of `comminute pbm`
sed -e 's|^spectrum_file = .*|spectrum_file = "a/collision_spectrum_ball-ball.csv"|' \
    -e 's|^directory = .*|directory = "pbm_out"|' \
    "$src/examples/ball_mill/ufrj_from_dem.toml" > pbm.toml
grep -q 'a/collision_spectrum_ball-ball.csv' pbm.toml || { echo "example changed: edit this test"; exit 1; }
"$bin" pbm pbm.toml 2> pbm.log || { cat pbm.log; exit 1; }
test -s pbm_out/distributions.csv || { echo "pbm wrote no distributions"; exit 1; }

# restart: stop at 0.4 s (checkpoint), continue to 0.6 s; the collision tables match the straight run
sed -e 's|^end_time = 0.6|end_time = 0.4|' -e "s|^\[output\]|[output]\ndirectory = \"c\"|" drum.toml > c1.toml
sed -e "s|^\[output\]|[output]\ndirectory = \"c\"|" drum.toml > c2.toml
"$bin" run c1.toml --threads 1 2> c1.log || { cat c1.log; exit 1; }
"$bin" run c2.toml --threads 1 --restart c/checkpoint.h5 2> c2.log || { cat c2.log; exit 1; }
for f in collisions.csv collision_distributions.csv collision_spectrum_all.csv; do
  cmp "a/$f" "c/$f" || { echo "restart changed $f"; diff "a/$f" "c/$f" | head; exit 1; }
done

# a bad key is refused by check
printf '[simulation]\nend_time = 0.1\n' > /dev/null
sed -e 's|^bins = 80|bins = 0|' drum.toml > bad.toml
set +e
"$bin" check bad.toml 2> bad.log
rc=$?
set -e
[ "$rc" -eq 2 ] || { echo "check exited $rc on bins = 0"; cat bad.log; exit 1; }
grep -q "collisions.bins" bad.log || { cat bad.log; exit 1; }
echo "ok: collision log deterministic, restart-exact, read by comminute pbm"
