#!/usr/bin/env bash
# Machines through `comminute run`: (1) the discharge example, shortened: every particle the
# outlet removed is one row of outlet_log.csv, the last row of outlets.csv counts them, and the
# particles that remain plus those removed are the ones inserted; (2) a [[stop]] condition ends a
# run early with exit status 0 (docs/case-file.md, "[[stop]]"), a log line and one row of
# stop.csv, and the servo piston it watches writes wall_control.csv; a restart from its checkpoint
# stops again at once.
# usage: test_machines_cli.sh <comminute> <source-dir>
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# 1. discharge to 0.1 s: the bottom layers have left through the outlet, the top ones not yet
sed -e 's/^end_time = 0.15 /end_time = 0.1 /' "$src/examples/machines/discharge.toml" \
  > "$tmp/discharge.toml"
grep -q '^end_time = 0.1 ' "$tmp/discharge.toml" || { echo "example changed: edit this test"; exit 1; }
printf 'directory = "out"\nparticles = false\n' >> "$tmp/discharge.toml"
"$bin" run "$tmp/discharge.toml" --threads 1 2> "$tmp/log" || { cat "$tmp/log"; exit 1; }
/usr/bin/python3 - "$tmp/out" <<'PY'
import csv, sys
d = sys.argv[1]
log = list(csv.DictReader(open(f"{d}/outlet_log.csv")))
tot = list(csv.DictReader(open(f"{d}/outlets.csv")))
ts = list(csv.DictReader(open(f"{d}/timeseries.csv")))
planes = list(csv.DictReader(open(f"{d}/sampling_planes.csv")))
ids = [r["id [-]"] for r in log]
assert len(ids) == len(set(ids)), "a particle logged twice"
assert 0 < len(log) < 600, f"{len(log)} removed: the test no longer catches a partial discharge"
assert int(tot[-1]["product_count [-]"]) == len(log), (tot[-1], len(log))
assert abs(float(tot[-1]["product_mass [kg]"]) - sum(float(r["mass [kg]"]) for r in log)) <= 1e-12
remaining = int(ts[-1]["particles [-]"])
assert remaining + len(log) == 600, (remaining, len(log))
# every removed particle passed the sampling plane above the outlet, downwards, once
assert int(planes[-1]["below_bin_crossings_positive [-]"]) >= len(log)
assert int(planes[-1]["below_bin_crossings_negative [-]"]) == 0
print(f"ok: {len(log)} removed and logged once, {remaining} remain, "
      f"{planes[-1]['below_bin_crossings_positive [-]']} crossed the sampling plane")
PY

# 2. a sphere pressed by a servo piston (target 3 N, at most 0.05 m/s); stop at 2 N on the piston
cat > "$tmp/stop.toml" <<'TOML'
[simulation]
end_time = 1.0
time_step = 2.0e-6
gravity = [0.0, 0.0, 0.0]
[contact]
model = "hertz_mindlin"
[materials.glass]
density = 2500.0
youngs_modulus = 1.0e8
poisson_ratio = 0.3
[[walls]]
name = "floor"
type = "plane"
point = [0.0, 0.0, 0.0]
material = "glass"
[[walls]]
name = "piston"
type = "plane"
point = [0.0, 0.0, 0.00205]
normal = [0.0, 0.0, -1.0]
material = "glass"
control = { mode = "servo", target_force = 3.0, gain = 0.02, max_speed = 0.05 }
[[insert]]
type = "fill"
material = "glass"
count = 1
region = { shape = "box", lo = [-0.001, -0.001, 0.0], hi = [0.001, 0.001, 0.002] }
size = { distribution = "fixed", diameter = 0.002 }
[[stop]]
wall = "piston"
force = 2.0
[output]
directory = "stopped"
particles = false
TOML
rc=0; "$bin" run "$tmp/stop.toml" --threads 1 2> "$tmp/log2" || rc=$?
cat "$tmp/log2"
[ "$rc" -eq 0 ] || { echo "FAIL: exit status $rc, expected 0"; exit 1; }
grep -q "stop condition reached, stop\[0\]: wall 'piston' force = " "$tmp/log2" \
  || { echo "FAIL: no stop line"; exit 1; }
[ "$(wc -l < "$tmp/stopped/stop.csv")" -eq 2 ] || { echo "FAIL: stop.csv"; cat "$tmp/stopped/stop.csv"; exit 1; }
/usr/bin/python3 - "$tmp/stopped" <<'PY'
import csv, sys
d = sys.argv[1]
row = list(csv.DictReader(open(f"{d}/stop.csv")))[0]
ts = list(csv.DictReader(open(f"{d}/timeseries.csv")))
assert float(row["quantity [N or Pa]"]) >= 2.0, row
assert float(row["time [s]"]) < 1.0, row
assert abs(float(ts[-1]["time [s]"]) - float(row["time [s]"])) == 0, (ts[-1]["time [s]"], row)
wc = list(csv.DictReader(open(f"{d}/wall_control.csv")))
assert float(wc[0]["piston_velocity [m/s]"]) == 0.0, wc[0]
assert float(wc[-1]["piston_force [N]"]) >= 2.0, wc[-1]
assert float(wc[-1]["piston_displacement [m]"]) > 5e-5, wc[-1]  # it reached the sphere
print(f"ok: stopped at t = {row['time [s]']} s, step {row['step [-]']}, F = {row['quantity [N or Pa]']} N")
PY
# a restart from the stop's checkpoint has nothing to do but stop again
rc=0; "$bin" run "$tmp/stop.toml" --threads 1 --restart "$tmp/stopped/checkpoint.h5" \
  2> "$tmp/log3" || rc=$?
[ "$rc" -eq 0 ] && grep -q "stop condition reached" "$tmp/log3" \
  || { cat "$tmp/log3"; echo "FAIL: restart after a stop (exit $rc)"; exit 1; }
echo "ok: [[stop]] ends the run with exit 0"
