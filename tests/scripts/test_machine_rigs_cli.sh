#!/usr/bin/env bash
# The machine rigs examples/hpgr and examples/jaw_crusher through the command line: `comminute
# check` accepts each as it is (exit 0) and writes the generated STL files of its parts; a
# shortened run of each writes the per-roll (per-jaw) force and power columns, logs product in
# the outlet, and its plot script reads the outputs and draws the plot; the jaw crusher continued
# from a checkpoint ends bit for bit as the straight run.
# usage: test_machine_rigs_cli.sh <comminute> <source-dir>
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

for rig in hpgr jaw_crusher; do
  mkdir -p "$tmp/$rig"
  cp "$src/examples/$rig/$rig.toml" "$tmp/$rig/"
  "$bin" check "$tmp/$rig/$rig.toml" > "$tmp/$rig/check.log" 2>&1 \
    || { cat "$tmp/$rig/check.log"; echo "FAIL: check refuses examples/$rig"; exit 1; }
done
for part in roll1 roll2 chute; do
  [ -s "$tmp/hpgr/output/hpgr_$part.stl" ] || { echo "FAIL: no hpgr_$part.stl"; exit 1; }
done
for part in fixed_jaw swing_jaw side_plates; do
  [ -s "$tmp/jaw_crusher/output/jaw_$part.stl" ] || { echo "FAIL: no jaw_$part.stl"; exit 1; }
done

# shortened: up to the first product (the HPGR's reaches its outlet at about 0.39 s, the jaw
# crusher's at about 0.45 s)
sed -i -e 's/^end_time = 1.2 /end_time = 0.5 /' "$tmp/hpgr/hpgr.toml"
sed -i -e 's/^end_time = 2.0 /end_time = 0.65 /' "$tmp/jaw_crusher/jaw_crusher.toml"
grep -q '^end_time = 0.5 ' "$tmp/hpgr/hpgr.toml" || { echo "example changed: edit this test"; exit 1; }
grep -q '^end_time = 0.65 ' "$tmp/jaw_crusher/jaw_crusher.toml" \
  || { echo "example changed: edit this test"; exit 1; }
for rig in hpgr jaw_crusher; do
  printf 'particles = false\nwalls = false\n' >> "$tmp/$rig/$rig.toml"
  "$bin" run "$tmp/$rig/$rig.toml" --threads 1 > "$tmp/$rig/run.log" 2>&1 \
    || { cat "$tmp/$rig/run.log"; echo "FAIL: run examples/$rig"; exit 1; }
done
/usr/bin/python3 - "$tmp" <<'PY'
import csv, sys
d = sys.argv[1]
ts = list(csv.DictReader(open(f"{d}/hpgr/output/timeseries.csv")))
for c in ("press_roll1_Fx [N]", "press_roll2_Fx [N]", "press_roll1_P [W]", "press_roll2_P [W]"):
    assert c in ts[0], c
# the bed pushes the rolls apart along the line of centres (x): roll 1 to -x, roll 2 to +x
f1 = sum(float(r["press_roll1_Fx [N]"]) for r in ts)
f2 = sum(float(r["press_roll2_Fx [N]"]) for r in ts)
assert f1 < 0 < f2, (f1, f2)
log = list(csv.DictReader(open(f"{d}/hpgr/output/outlet_log.csv")))
assert any(r["outlet [-]"] == "product" for r in log), "no HPGR product"
ts = list(csv.DictReader(open(f"{d}/jaw_crusher/output/timeseries.csv")))
for c in ("crusher_swing_jaw_Fx [N]", "crusher_swing_jaw_P [W]", "crusher_fixed_jaw_Fx [N]"):
    assert c in ts[0], c
out = list(csv.DictReader(open(f"{d}/jaw_crusher/output/outlets.csv")))
assert float(out[-1]["product_mass [kg]"]) > 0, "no jaw-crusher product"
print(f"ok: HPGR roll forces {f1:.4g}, {f2:.4g} (sums over rows), {len(log)} leaving; jaw product "
      f"{out[-1]['product_mass [kg]']} kg")
PY
# the swinging jaw's motion (its time and pose) continues from a checkpoint bit for bit
sed -e 's/^end_time = 0.65 /end_time = 0.3 /' "$tmp/jaw_crusher/jaw_crusher.toml" \
  > "$tmp/jaw_crusher/first.toml"
"$bin" run "$tmp/jaw_crusher/first.toml" -o "$tmp/jaw_crusher/restarted" --threads 1 > /dev/null 2>&1
"$bin" run "$tmp/jaw_crusher/jaw_crusher.toml" -o "$tmp/jaw_crusher/restarted" --threads 1 \
  --restart "$tmp/jaw_crusher/restarted/checkpoint.h5" > "$tmp/jaw_crusher/restart.log" 2>&1 \
  || { cat "$tmp/jaw_crusher/restart.log"; echo "FAIL: restart of the jaw crusher"; exit 1; }
[ "$(tail -1 "$tmp/jaw_crusher/output/timeseries.csv")" = \
  "$(tail -1 "$tmp/jaw_crusher/restarted/timeseries.csv")" ] \
  || { echo "FAIL: the restarted jaw crusher differs from the straight run"; exit 1; }
echo "ok: jaw crusher restarted at 0.3 s ends bit for bit as the straight run"
/usr/bin/python3 "$src/examples/hpgr/plot_hpgr.py" "$tmp/hpgr/output"
/usr/bin/python3 "$src/examples/jaw_crusher/plot_jaw_crusher.py" "$tmp/jaw_crusher/output"
[ -s "$tmp/hpgr/output/hpgr.png" ] && [ -s "$tmp/jaw_crusher/output/jaw_crusher.png" ] \
  || { echo "FAIL: no plot"; exit 1; }
echo "ok: machine rigs checked, run shortened and plotted"
